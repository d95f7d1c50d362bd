//! The harnesses can fail: each property's harness, run on an engine broken
//! on purpose in the way the property forbids, finds the break. The mutants
//! wrap the real engine and change its output (or its arithmetic), so they
//! stand for the bugs a vendor's engine could have.
//!
//! Every case runs the same harness twice over the same exhaustive domain,
//! within the same run budget: on the real engine (the control, which must
//! pass with every declared cover satisfied) and on the mutant, whose run
//! must fail on the assertion named in the case (its own text, not the
//! check's name, which every shim panic carries).

use std::panic::catch_unwind;

use cycleref::{CycleError, G76Cycle, Infeed, Move, PassKind, Role};
use cycleref_proofs::harness::{self, Domain};
use cycleref_proofs::shim::{self, check, Mode};

type Moves = std::vec::IntoIter<Move>;

fn real(c: &G76Cycle) -> Result<Vec<Move>, CycleError> {
    cycleref::engine::expand_g76(c).map(Iterator::collect)
}

/// The real engine through the same adapter as the mutants.
fn control(c: &G76Cycle) -> Result<Moves, CycleError> {
    real(c).map(Vec::into_iter)
}

/// Runs `body(control)` and `body(mutant)` exhaustively within `max_runs`:
/// the first must pass, the second must fail with `expected` in the failing
/// assertion's message. Returns the two run counts.
fn caught<M>(
    max_runs: u64,
    body: impl Fn(&dyn Fn(&G76Cycle) -> Result<Moves, CycleError>),
    mutant: M,
    expected: &str,
) where
    M: Fn(&G76Cycle) -> Result<Moves, CycleError>,
{
    let r = shim::caught(Mode::Exhaustive { max_runs }, || body(&control), || body(&mutant), expected);
    eprintln!("control: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
}

/// The small schedule domain of `harnesses.rs`.
const SCHEDULE: Domain = Domain::SCHEDULE;

const GEOMETRY: Domain = Domain {
    height: (6, 8),
    first_depth: (3, 4),
    allowance: (0, 1),
    tool_angle: (58, 62),
    infeed: (0, 2),
    depth_mode: (1, 1),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-45, 45),
    length: (40, 40),
    run_out_kind: (1, 3),
    run_out: (1, 3),
    lead: (1, 2),
    ..Domain::POINT
};

/// Applies `f` to every move of the real engine's output.
fn mutant(f: impl Fn(&G76Cycle, Move) -> Move) -> impl Fn(&G76Cycle) -> Result<Moves, CycleError> {
    move |c| real(c).map(|v| v.into_iter().map(|m| f(c, m)).collect::<Vec<_>>().into_iter())
}

/// An engine that cuts the first pass of the second level twice (the whole
/// pass, with its annotation: a repeated level with a consistent cut), in
/// every infeed mode (that pass is rough pass 3 in D2, 2 otherwise).
fn repeated_level(c: &G76Cycle) -> Result<Moves, CycleError> {
    real(c).map(|v| {
        let number = if c.infeed == Infeed::LeftRight { 3 } else { 2 };
        let of_pass = |m: &Move| m.pass.is_some_and(|p| p.kind == PassKind::Rough && p.number == number);
        let pass: Vec<Move> = v.iter().filter(|m| of_pass(m)).copied().collect();
        let mut out = Vec::with_capacity(v.len() + pass.len());
        let mut done = false;
        for m in v {
            if !done && !of_pass(&m) && !pass.is_empty() && out.last().is_some_and(of_pass) {
                out.extend_from_slice(&pass);
                done = true;
            }
            out.push(m);
        }
        out.into_iter()
    })
}

#[test]
fn a_repeated_level_is_caught_by_p1_in_every_mode() {
    caught(
        200_000,
        |e| harness::depth_monotonicity(&SCHEDULE, &e),
        repeated_level,
        "rough depths must strictly increase",
    );
}

#[test]
fn a_d2_left_pass_off_its_level_is_caught_by_p1() {
    // The left pass of each D2 level one increment deeper than its right pass.
    let e = mutant(|_, mut m| {
        if let Some(p) = m.pass.as_mut() {
            if p.kind == PassKind::Rough && p.flank == cycleref::Flank::Left {
                p.depth += 1;
            }
        }
        m
    });
    caught(
        200_000,
        |e| harness::depth_monotonicity(&SCHEDULE, &e),
        e,
        "a D2 left pass repeats its level's right pass",
    );
}

#[test]
fn a_repeated_level_is_caught_by_p2_in_every_mode() {
    caught(
        200_000,
        |e| harness::termination(&SCHEDULE, &e),
        repeated_level,
        "a rough level repeats or goes back",
    );
}

#[test]
fn schedule_stopping_short_is_caught_by_p2() {
    // The last rough level stops one increment short of k - d (where its
    // cut is 2 or more, so that it still goes deeper than the level before).
    let e = mutant(|c, mut m| {
        if let Some(p) = m.pass.as_mut() {
            if p.kind == PassKind::Rough && p.depth == c.thread_height - c.finishing_allowance && p.cut > 1 {
                p.depth -= 1;
            }
        }
        m
    });
    caught(200_000, |e| harness::termination(&SCHEDULE, &e), e, "the last rough depth is k - d");
}

#[test]
fn finishing_cut_repeated_is_caught_by_p3() {
    // Every finishing pass claims to remove d.
    let e = mutant(|c, mut m| {
        if let Some(p) = m.pass.as_mut() {
            if p.kind == PassKind::Finish {
                p.cut = c.finishing_allowance;
            }
        }
        m
    });
    let d = Domain { finishing: (0, 3), ..SCHEDULE };
    caught(400_000, |e| harness::finishing(&d, &e), e, "finishing cut: d, then 0");
}

#[test]
fn flipped_run_out_is_caught_by_p4() {
    // The run-out's short-axis travel goes the wrong way (into the work).
    let e = move |c: &G76Cycle| {
        real(c).map(|v| {
            let mut out = Vec::with_capacity(v.len());
            let mut at = c.start;
            for mut m in v {
                if m.role == Role::RunOut {
                    m.to.x = at.x - (m.to.x - at.x);
                }
                at = m.to;
                out.push(m);
            }
            out.into_iter()
        })
    };
    // Every run-out kind (chamfers accepted with F0.01), F and I leads; X
    // long needs |i| > |W| = 40.
    caught(
        4_000_000,
        |e| harness::run_out_direction(&GEOMETRY, &e),
        e,
        "an X-long run-out ends at X of the cut's end",
    );
}

#[test]
fn shift_past_the_flank_is_caught_by_p5() {
    // Rough passes shifted two increments too far towards D.
    let e = mutant(|c, mut m| {
        if m.role == Role::Approach && m.pass.is_some_and(|p| p.kind == PassKind::Rough) {
            m.to.z += 2 * (c.end.z - c.start.z).signum();
        }
        m
    });
    let d = Domain { run_out_kind: (0, 0), taper: (0, 0), lead: (0, 0), lead_in: (0, 1), ..GEOMETRY };
    caught(2_000_000, |e| harness::no_overcut(&d, &e), e, "a pass lies outside the final form");
}

#[test]
fn any_difference_is_caught_by_p6() {
    // Rounding the Z shift down instead of to nearest, at a = 45° only.
    let e = mutant(|c, mut m| {
        if m.role == Role::Approach && c.tool_angle == 45 {
            m.to.z -= (c.end.z - c.start.z).signum();
        }
        m
    });
    let d = Domain {
        height: (1, 10),
        first_depth: (1, 10),
        allowance: (0, 10),
        tool_angle: (44, 46),
        ..SCHEDULE
    };
    caught(400_000, |e| harness::equivalence(&d, &e), e, "engine and reference differ");
}

#[test]
fn a_panicking_engine_is_caught_by_p7() {
    // An engine that overflows on a 7-start thread.
    let e = |c: &G76Cycle| {
        let starts: u8 = u8::try_from(c.starts).unwrap();
        assert!(starts != 7, "attempt to add with overflow");
        real(c).map(Vec::into_iter)
    };
    let d = Domain { starts: (1, 9), ..Domain::POINT };
    caught(1_000, |e| harness::no_panic(&d, &e, 100), e, "attempt to add with overflow");
}

#[test]
fn a_move_out_of_range_is_caught_by_p7() {
    // An engine whose rough approach lands one increment beyond the range.
    let e = mutant(|_, mut m| {
        if m.role == Role::Approach {
            m.to.x = cycleref::units::MAX_LENGTH + 1;
        }
        m
    });
    let d = Domain { starts: (1, 2), ..Domain::POINT };
    caught(1_000, |e| harness::no_panic(&d, &e, 100), e, "a move outside the coordinate range");
}

#[test]
fn floor_sqrt_is_caught_by_p8() {
    let mode = Mode::Exhaustive { max_runs: 1 << 12 };
    check("control", mode, || harness::isqrt_rounds(0, 1 << 10, cycleref::engine::round_sqrt));
    let failure = catch_unwind(|| {
        check("mutant", mode, || harness::isqrt_rounds(0, 1 << 10, cycleref::engine::isqrt_floor))
    })
    .expect_err("a floor square root must be caught");
    let text = failure.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(text.ends_with("round(√x): the contract of round_sqrt"), "{text}");
}
