//! Any bytes as a vendor's trace, read as an expanded program (`.nc`) and
//! as a CSV, and compared with the expansion of a fixed program that has a
//! G76, a continuous G32 thread with start angles and a G75.1 groove with
//! rounds: the trace readers and the comparison return a report or an
//! error naming a line, never panic.
//!
//! `cli/src/check.rs` and `cli/src/format.rs` are compiled in as they are;
//! `Job` below is the narrow part of the command's `Job` that `check` uses
//! (the program, the machine, its name, the three expansions).
#![no_main]
#![allow(dead_code, missing_docs)]

#[path = "../../cli/src/check.rs"]
mod check;
#[path = "../../cli/src/format.rs"]
mod format;

mod plot {
    /// What `check::overlay` returns.
    pub struct Overlay {
        pub name: String,
        pub points: Vec<cycleref::Point>,
    }
}

use std::sync::OnceLock;

use cycleref::{CycleError, G32Block, G75Cycle, G76Cycle, Move};
use cycleref_spec::{read, Machine, ProfileName, Program};
use libfuzzer_sys::fuzz_target;

/// An error message, as in the command.
pub struct Failure(pub String);

/// The program `check` compares with, read and ready to expand.
pub struct Job {
    name: String,
    program: Program,
    machine: Machine,
}

impl Job {
    fn expand(&self, cycle: &G76Cycle, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = cycleref::expand_g76(cycle).map(Iterator::collect);
        r.map_err(|e| Failure(format!("{}: line {line}, G76: {e}", self.name)))
    }

    fn expand_g32(&self, block: &G32Block, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = cycleref::expand_g32(block).map(Iterator::collect);
        r.map_err(|e| Failure(format!("{}: line {line}, G32: {e}", self.name)))
    }

    fn expand_g75(&self, cycle: &G75Cycle, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = cycleref::expand_g75(cycle).map(Iterator::collect);
        r.map_err(|e| Failure(format!("{}: line {line}, G75.1: {e}", self.name)))
    }
}

/// The fixed program (also `fuzz/check_program.nc`, from which the seed
/// corpus is expanded).
pub const PROGRAM: &str = include_str!("../check_program.nc");

fn job() -> &'static Job {
    static JOB: OnceLock<Job> = OnceLock::new();
    JOB.get_or_init(|| {
        let machine = Machine::new(ProfileName::Gsk980);
        let program = read(PROGRAM, &machine).expect("the fixed program reads");
        Job { name: "check_program.nc".into(), program, machine }
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
