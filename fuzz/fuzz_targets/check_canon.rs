//! Any bytes as a vendor's trace of a LinuxCNC program, read as LinuxCNC's
//! canonical output (`rs274 -g`, reading R-CHECKLCNC) and as an expanded
//! program, and compared with the expansion of
//! `examples/linuxcnc-m20-taper.ngc` (a G76 with both end tapers) on the
//! `linuxcnc` profile: the trace readers and the comparison return a report
//! or an error naming a line, never panic.
//!
//! Its seed corpus is the rs274 output of that program
//! (`spec/tests/data/lcnc-taper.canon`) and `docs/peers/*.canon`.
#![no_main]

use std::sync::OnceLock;

use cycleref_cli::check::{self, TraceFormat};
use cycleref_cli::Job;
use cycleref_spec::pipeline::Engine;
use cycleref_spec::{Machine, ProfileName};
use libfuzzer_sys::fuzz_target;

/// The fixed program.
pub const PROGRAM: &str = include_str!("../../examples/linuxcnc-m20-taper.ngc");

fn job() -> &'static Job {
    static JOB: OnceLock<Job> = OnceLock::new();
    JOB.get_or_init(|| {
        let machine = Machine::new(ProfileName::LinuxCnc);
        Job::new("linuxcnc-m20-taper.ngc", PROGRAM.as_bytes().to_vec(), machine, Engine::Impl)
    })
}

fuzz_target!(|data: &[u8]| {
    let job = job();
    // The first byte chooses the tolerance; the rest is the trace.
    let (tol, trace) = match data.split_first() {
        Some((&t, rest)) => (u64::from(t % 4), rest),
        None => (0, data),
    };
    for format in [TraceFormat::Rs274, TraceFormat::Nc] {
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
});
