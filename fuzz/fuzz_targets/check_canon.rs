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

use cycleref_cli::check::TraceFormat;
use cycleref_cli::Job;
use cycleref_spec::ProfileName;
use libfuzzer_sys::fuzz_target;

mod trace;

/// The fixed program.
pub const PROGRAM: &str = include_str!("../../examples/linuxcnc-m20-taper.ngc");

static JOB: OnceLock<Job> = OnceLock::new();

fuzz_target!(|data: &[u8]| {
    let job = trace::job(&JOB, "linuxcnc-m20-taper.ngc", PROGRAM, ProfileName::LinuxCnc);
    trace::check_all(job, data, &[TraceFormat::Rs274, TraceFormat::Nc]);
});
