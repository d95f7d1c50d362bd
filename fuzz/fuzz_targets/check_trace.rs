//! Any bytes as a vendor's trace, read as an expanded program (`.nc`) and
//! as a CSV, and compared with the expansion of a fixed program that has a
//! G76, a continuous G32 thread with start angles and a G75.1 groove with
//! rounds: the trace readers and the comparison return a report or an
//! error naming a line, never panic.
//!
//! It calls the command's library (`cycleref_cli::check::check_bytes`).
#![no_main]

use std::sync::OnceLock;

use cycleref_cli::{check, Job};
use cycleref_spec::pipeline::Engine;
use cycleref_spec::{Machine, ProfileName};
use libfuzzer_sys::fuzz_target;

/// The fixed program (also `fuzz/check_program.nc`, from which the seed
/// corpus is expanded).
pub const PROGRAM: &str = include_str!("../check_program.nc");

fn job() -> &'static Job {
    static JOB: OnceLock<Job> = OnceLock::new();
    JOB.get_or_init(|| {
        let machine = Machine::new(ProfileName::Gsk980);
        Job::new("check_program.nc", PROGRAM.as_bytes().to_vec(), machine, Engine::Impl)
    })
}

fuzz_target!(|data: &[u8]| {
    let job = job();
    // The first byte chooses the tolerance; the rest is the trace.
    let (tol, trace) = match data.split_first() {
        Some((&t, rest)) => (u64::from(t % 4), rest),
        None => (0, data),
    };
    for is_csv in [false, true] {
        match check::check_bytes(job, trace, is_csv, tol) {
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
});
