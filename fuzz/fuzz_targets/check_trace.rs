//! Any bytes as a vendor's trace, read as an expanded program (`.nc`) and
//! as a CSV, and compared with the expansion of a fixed program that has a
//! G76, a continuous G32 thread with start angles and a G75.1 groove with
//! rounds: the trace readers and the comparison return a report or an
//! error naming a line, never panic.
//!
//! It calls the command's library (`cycleref_cli::check::check_bytes_as`).
#![no_main]

use std::sync::OnceLock;

use cycleref_cli::check::TraceFormat;
use cycleref_cli::Job;
use cycleref_spec::ProfileName;
use libfuzzer_sys::fuzz_target;

mod trace;

/// The fixed program (also `fuzz/check_program.nc`, from which the seed
/// corpus is expanded).
pub const PROGRAM: &str = include_str!("../check_program.nc");

static JOB: OnceLock<Job> = OnceLock::new();

fuzz_target!(|data: &[u8]| {
    let job = trace::job(&JOB, "check_program.nc", PROGRAM, ProfileName::Gsk980);
    trace::check_all(job, data, &[TraceFormat::Nc, TraceFormat::Csv]);
});
