//! What the trace targets (`check_trace`, `check_canon`) share: a job made
//! once, and one run of `check` on a fuzzed trace in each of its formats.

use std::sync::OnceLock;

use cycleref_cli::check::{self, TraceFormat};
use cycleref_cli::Job;
use cycleref_spec::pipeline::Engine;
use cycleref_spec::{Machine, ProfileName};

/// The job of `program` (called `name`) on `profile`, made on first use.
pub fn job(cell: &'static OnceLock<Job>, name: &str, program: &str, profile: ProfileName) -> &'static Job {
    cell.get_or_init(|| Job::new(name, program.as_bytes().to_vec(), Machine::new(profile), Engine::Impl))
}

/// `data` as a trace in each of `formats`, against `job`: the first byte
/// chooses the tolerance, the rest is the trace. The readers and the
/// comparison give a report or an error naming a line, never a panic.
pub fn check_all(job: &Job, data: &[u8], formats: &[TraceFormat]) {
    let (tol, trace) = match data.split_first() {
        Some((&t, rest)) => (u64::from(t % 4), rest),
        None => (0, data),
    };
    for &format in formats {
        match check::check_bytes_as(job, trace, format, tol) {
            Ok(report) => {
                let _ = report.text();
                let _ = report.json();
            }
            // Every error names a line, except the one about the whole trace.
            Err(e) => assert!(
                e.contains("line ") || e.starts_with("the trace has no moves"),
                "an error without a line: {e}"
            ),
        }
    }
}
