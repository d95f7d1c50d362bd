//! No rapid enters the thread (`cycleref_proofs::thread`), G76 and G32:
//! exhaustively over a small window, sampled over wide ranges, and against
//! engines broken on purpose (with the real engine as their control).

use std::panic::{catch_unwind, AssertUnwindSafe};

use cycleref::{CycleError, G76Cycle, Motion, Move, Point, Role, RunOut};
use cycleref_proofs::harness::{Domain, FixedPoint, PLAIN_CYCLE};
use cycleref_proofs::shim::{self, check_and_print as check, Mode};
use cycleref_proofs::thread::{self, ThreadRegion};
use cycleref_proofs::windows::G32_WINDOW;
use cycleref_spec::differ::assert_same_moves;

/// The exhaustive window: k ≤ 4, every infeed mode, both sides and
/// directions, straight and tapered, both long axes (|W| = 5 or 6, |i| ≤
/// 6: Z long where |i| < |W|, X long where |i| ≥ |W|), every run-out kind,
/// a lead-in or none (refused on an X long axis), F and I leads, IS-C inch
/// diameter and IS-B metric radius (unit codes 3 and 4, which between
/// them have every unit); run with the tool angles 60° and 29° (the flank
/// shifts).
const THREAD: Domain = Domain {
    height: (1, 4),
    first_depth: (1, 4),
    min_cut: (0, 1),
    allowance: (0, 1),
    tool_angle: (60, 60),
    finishing: (1, 1),
    infeed: (0, 2),
    depth_mode: (1, 1),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-6, 6),
    length: (5, 6),
    run_out_kind: (0, 3),
    run_out: (1, 2),
    chamfer: (3, 3),
    chamfer_angle: (45, 45),
    units: (3, 4),
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
    depth_mode: (1, 1),
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

/// X long at large values: lengths from 1 against tapers up to 300 000, no
/// lead-in (refused on an X long axis).
#[test]
fn no_rapid_enters_an_x_long_thread() {
    let wide = Domain { length: (1, 300_000), lead_in: (0, 0), ..WIDE };
    check(
        "no rapid in the thread, X long (sampled)",
        Mode::Sample { runs: 3_000, seed: 0x0078_6c6f_6e67 },
        || {
            thread::no_rapid_in_thread(&wide, &FixedPoint);
        },
    );
}

/// An X-long G76 (radius X, IS-B): A = (115, 5), D = (100, 0), |W| = 5,
/// k = Δd = 4 (one rough pass), one finishing pass, 60°; the tests set the
/// taper i (|i| = 10 >= |W|: X long) and the run-out.
fn x_long_cycle() -> G76Cycle {
    G76Cycle {
        start: Point::new(115, 5),
        end: Point::new(100, 0),
        taper: 10,
        thread_height: 4,
        first_depth: 4,
        min_cut: 1,
        finishing_allowance: 0,
        pass_limit: 100,
        ..PLAIN_CYCLE
    }
}

/// The finding of `crate::thread`'s module docs, now refused (reading
/// R-XRUNOUT): X long, `s·i > 0` (A at X115 outside C at X110, i = +10),
/// a run-out: J along Z towards A would end in the work, and the retract
/// after it would cross the thread. Both engines refuse it; without the
/// run-out it expands.
#[test]
fn an_x_long_run_out_into_the_work_is_refused() {
    let c = G76Cycle { taper: 10, run_out: RunOut::Amounts { short: 2, long: 3 }, ..x_long_cycle() };
    let refused = Err(cycleref::CycleError::RunOutIntoWork { taper: cycleref::Length::new(10, c.units) });
    assert_eq!(cycleref::expand_g76(&c).map(Iterator::count), refused.map(|()| 0));
    assert_eq!(cycleref_spec::g76::expand(&c).map(|v| v.len()), refused.map(|()| 0));
    assert!(cycleref::expand_g76(&G76Cycle { run_out: RunOut::None, ..c }).is_ok());
}

/// The other slope (`s·i < 0`: A at X115 outside C at X90, i = -10): the
/// run-out along Z towards A ends above its pass's cut line, in the air,
/// but inside the static band between the root and crest lines (whose part
/// above the pass is already cut): the retract after it meets the region
/// and is the one rapid the harness leaves out, checking `s·i < 0`.
#[test]
fn an_x_long_run_out_away_from_the_work_expands() {
    let c = G76Cycle { taper: -10, run_out: RunOut::Amounts { short: 1, long: 3 }, ..x_long_cycle() };
    let ours: Vec<Move> = cycleref::expand_g76(&c).expect("a valid cycle").collect();
    assert_same_moves(&Ok(ours.clone()), &cycleref_spec::g76::expand(&c), "the X-long cycle");
    // C = (100 - 10, 5) = (90, 5). The pass at depth 4 = k runs from (90,
    // 5) to D = (100, 0); the run-out ends J = 1 back towards A: (100, 1),
    // where the cut line (the root) lies at X = 90 + 10·4/5 = 98 (radius,
    // below the tool: air) and the crest at 102.
    let region = ThreadRegion::of(&c).expect("not a face thread");
    assert!(region.x_long());
    let mut at = c.start;
    let mut crossing = Vec::new();
    for (i, m) in ours.iter().enumerate() {
        if m.role == Role::RunOut {
            assert_eq!(m.to, Point::new(100, 1));
        }
        if m.motion == Motion::Rapid && region.meets(at, m.to) {
            crossing.push((ours[i - 1].role, m.role, at, m.to));
        }
        at = m.to;
    }
    // The rough pass (k = Δd = 4, d = 0) and the finishing pass: each
    // retract after its run-out, through the band's cut part, and nothing
    // else.
    let expected = (Role::RunOut, Role::Retract, Point::new(100, 1), Point::new(115, 1));
    assert_eq!(crossing, vec![expected, expected]);
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
    let w = Domain { tool_angle: (60, 60), units: (3, 3), lead: (1, 1), ..THREAD };
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
