//! No rapid enters the thread (`cycleref_proofs::thread`), G76 and G32:
//! exhaustively over a small window, sampled over wide ranges, and against
//! engines broken on purpose (with the real engine as their control).

use std::panic::{catch_unwind, AssertUnwindSafe};

use cycleref::{CycleError, G76Cycle, Motion, Move, Point, Role};
use cycleref_proofs::harness::{Domain, FixedPoint};
use cycleref_proofs::shim::{self, Mode};
use cycleref_proofs::thread;
use cycleref_proofs::windows::G32_WINDOW;

fn check(name: &str, mode: Mode, body: impl Fn()) -> shim::Report {
    let r = shim::check(name, mode, body);
    eprintln!("{name}: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
    r
}

/// The exhaustive window: k ≤ 4, every infeed mode, both sides and
/// directions, straight and tapered (|i| ≤ 2, Z long), every run-out kind,
/// a lead-in or none, F and I leads, every unit code; run with the tool
/// angles 60° and 29° (the flank shifts).
const THREAD: Domain = Domain {
    height: (1, 4),
    first_depth: (1, 4),
    min_cut: (0, 1),
    allowance: (0, 1),
    tool_angle: (60, 60),
    finishing: (1, 1),
    infeed: (0, 2),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-2, 2),
    length: (20, 20),
    run_out_kind: (0, 3),
    run_out: (1, 2),
    chamfer: (3, 3),
    chamfer_angle: (45, 45),
    units: (0, 7),
    lead_in: (0, 1),
    lead: (1, 2),
    ..Domain::POINT
};

/// Wide ranges, sampled.
const WIDE: Domain = Domain {
    height: (1, 999_999),
    first_depth: (1, 999_999),
    min_cut: (0, 999_999),
    allowance: (0, 999_999),
    tool_angle: (0, 99),
    finishing: (0, 3),
    infeed: (0, 2),
    starts: (1, 3),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-300_000, 300_000),
    length: (1, 9_999_999),
    run_out_kind: (0, 3),
    run_out: (0, 9_999_999),
    chamfer: (0, 99),
    chamfer_angle: (1, 89),
    units: (0, 7),
    pass_limit: 2_000,
    lead_in: (0, 100_000),
    lead: (0, 3),
    wild_x: 2,
};

#[test]
fn no_rapid_enters_the_thread() {
    let w = Domain { tool_angle: (60, 60), ..THREAD };
    let r = check("no rapid in the thread (a = 60)", Mode::Exhaustive { max_runs: 3_000_000 }, || {
        thread::no_rapid_in_thread(&w, &FixedPoint);
    });
    assert!(r.runs > r.pruned);
    let w = Domain { tool_angle: (29, 29), ..THREAD };
    check("no rapid in the thread (a = 29)", Mode::Exhaustive { max_runs: 3_000_000 }, || {
        thread::no_rapid_in_thread(&w, &FixedPoint);
    });
    check("no rapid in the thread (sampled)", Mode::Sample { runs: 3_000, seed: 0x7468_7264 }, || {
        thread::no_rapid_in_thread(&WIDE, &FixedPoint);
    });
}

#[test]
fn no_rapid_in_g32() {
    check("G32: no rapid (within 3)", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        thread::g32_no_rapid(3, 2, &cycleref::expand_g32);
    });
    check("G32: no rapid (sampled)", Mode::Sample { runs: 20_000, seed: 32 }, || {
        thread::g32_no_rapid(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
    });
}

type Moves = std::vec::IntoIter<Move>;

/// `mutant` must be caught by "a rapid enters the thread" on the window
/// where the real engine passes.
fn caught(mutant: impl Fn(&G76Cycle) -> Result<Moves, CycleError>) {
    let w = Domain { tool_angle: (60, 60), units: (0, 0), lead: (1, 1), ..THREAD };
    let mode = Mode::Exhaustive { max_runs: 3_000_000 };
    let real = |c: &G76Cycle| cycleref::expand_g76(c).map(|m| m.collect::<Vec<_>>().into_iter());
    check("control", mode, || thread::no_rapid_in_thread(&w, &real));
    let failure = catch_unwind(AssertUnwindSafe(|| {
        shim::check("mutant", mode, || thread::no_rapid_in_thread(&w, &mutant));
    }))
    .expect_err("the mutant must be caught");
    let text = failure.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(text.ends_with("a rapid enters the thread"), "{text}");
}

fn mapped(c: &G76Cycle, f: impl Fn(&G76Cycle, Move, Point) -> Vec<Move>) -> Result<Moves, CycleError> {
    let mut at = c.start;
    let mut out = Vec::new();
    for m in cycleref::expand_g76(c)? {
        out.extend(f(c, m, at));
        at = m.to;
    }
    Ok(out.into_iter())
}

#[test]
fn a_rapid_through_the_thread_is_caught() {
    // The return to A runs inside the thread's depth, halfway between A's
    // X and D's.
    caught(|c| {
        mapped(c, |c, m, at| {
            if m.role == Role::Return {
                let mid = (c.start.x + c.end.x) / 2;
                let down = Move { to: Point::new(mid, at.z), ..m };
                let back = Move { to: Point::new(mid, c.start.z), ..m };
                vec![down, back, m]
            } else {
                vec![m]
            }
        })
    });
    // The retract goes straight back to A (diagonally through the thread).
    caught(|c| {
        mapped(
            c,
            |c, m, _| {
                if m.role == Role::Retract {
                    vec![Move { to: c.start, ..m }, m]
                } else {
                    vec![m]
                }
            },
        )
    });
    // The cut to the end of the pass is a rapid.
    caught(|c| {
        mapped(
            c,
            |_, m, _| {
                if m.role == Role::Cut {
                    vec![Move { motion: Motion::Rapid, ..m }]
                } else {
                    vec![m]
                }
            },
        )
    });
}
