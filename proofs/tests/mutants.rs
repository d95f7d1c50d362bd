//! The harnesses can fail: each property's harness, run on an engine broken
//! on purpose in the way the property forbids, finds the break. The mutants
//! wrap the real engine and change its output (or its arithmetic), so they
//! stand for the bugs a vendor's engine could have.

use cycleref::{CycleError, G76Cycle, Move, PassKind, Role};
use cycleref_proofs::harness::{self, Domain};
use cycleref_proofs::shim::{check, Mode};

type Moves = std::vec::IntoIter<Move>;

fn real(c: &G76Cycle) -> Result<Vec<Move>, CycleError> {
    cycleref::engine::expand_g76(c).map(Iterator::collect)
}

/// The small schedule domain of `harnesses.rs`.
const SCHEDULE: Domain = Domain::SCHEDULE;

const GEOMETRY: Domain = Domain {
    height: (6, 8),
    first_depth: (3, 4),
    allowance: (0, 1),
    tool_angle: (58, 62),
    infeed: (0, 2),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-45, 45),
    length: (40, 40),
    run_out_kind: (1, 1),
    run_out: (1, 3),
    ..Domain::POINT
};

/// Applies `f` to every move of the real engine's output.
fn mutant(f: impl Fn(&G76Cycle, Move) -> Move) -> impl Fn(&G76Cycle) -> Result<Moves, CycleError> {
    move |c| real(c).map(|v| v.into_iter().map(|m| f(c, m)).collect::<Vec<_>>().into_iter())
}

#[test]
#[should_panic(expected = "depth monotonicity")]
fn mutated_schedule_is_caught_by_p1() {
    // The third rough level repeats the second's depth (a schedule that stalls).
    let e = move |c: &G76Cycle| {
        real(c).map(|v| {
            let second = v.iter().filter_map(|m| m.pass).find(|p| p.kind == PassKind::Rough && p.number == 2);
            v.into_iter()
                .map(|mut m| {
                    if let (Some(p), Some(s)) = (m.pass.as_mut(), second) {
                        if p.kind == PassKind::Rough
                            && p.number == 3
                            && c.infeed != cycleref::Infeed::LeftRight
                        {
                            p.depth = s.depth;
                        }
                    }
                    m
                })
                .collect::<Vec<_>>()
                .into_iter()
        })
    };
    check("depth monotonicity", Mode::Exhaustive { max_runs: 200_000 }, || {
        harness::depth_monotonicity(&SCHEDULE, &e)
    });
}

#[test]
#[should_panic(expected = "termination")]
fn schedule_stopping_short_is_caught_by_p2() {
    // The last rough level stops one increment short of k - d.
    let e = mutant(|c, mut m| {
        if let Some(p) = m.pass.as_mut() {
            if p.kind == PassKind::Rough && p.depth == c.thread_height - c.finishing_allowance && p.depth > 1
            {
                p.depth -= 1;
            }
        }
        m
    });
    check("termination", Mode::Exhaustive { max_runs: 200_000 }, || harness::termination(&SCHEDULE, &e));
}

#[test]
#[should_panic(expected = "finishing")]
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
    check("finishing", Mode::Exhaustive { max_runs: 400_000 }, || harness::finishing(&d, &e));
}

#[test]
#[should_panic(expected = "run-out direction")]
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
    check("run-out direction", Mode::Exhaustive { max_runs: 4_000_000 }, || {
        harness::run_out_direction(&GEOMETRY, &e)
    });
}

#[test]
#[should_panic(expected = "no overcut")]
fn shift_past_the_flank_is_caught_by_p5() {
    // Rough passes shifted two increments too far towards D.
    let e = mutant(|c, mut m| {
        if m.role == Role::Approach && m.pass.is_some_and(|p| p.kind == PassKind::Rough) {
            m.to.z += 2 * (c.end.z - c.start.z).signum();
        }
        m
    });
    let d = Domain { run_out_kind: (0, 0), taper: (0, 0), ..GEOMETRY };
    check("no overcut", Mode::Exhaustive { max_runs: 2_000_000 }, || harness::no_overcut(&d, &e));
}

#[test]
#[should_panic(expected = "equivalence")]
fn any_difference_is_caught_by_p6() {
    // Rounding the Z shift down instead of to nearest.
    let e = mutant(|c, mut m| {
        if m.role == Role::Approach && c.tool_angle == 45 {
            m.to.z -= (c.end.z - c.start.z).signum();
        }
        m
    });
    let d = Domain { tool_angle: (0, 60), ..SCHEDULE };
    check("equivalence", Mode::Exhaustive { max_runs: 2_000_000 }, || harness::equivalence(&d, &e));
}

#[test]
#[should_panic(expected = "no panic")]
fn a_panicking_engine_is_caught_by_p7() {
    // An engine that overflows on a 7-start thread.
    let e = |c: &G76Cycle| {
        let starts: u8 = u8::try_from(c.starts).unwrap();
        assert!(starts != 7, "attempt to add with overflow");
        real(c).map(Vec::into_iter)
    };
    let d = Domain { starts: (1, 9), ..Domain::POINT };
    check("no panic", Mode::Exhaustive { max_runs: 1_000 }, || harness::no_panic(&d, &e, 100));
}

#[test]
#[should_panic(expected = "isqrt")]
fn floor_sqrt_is_caught_by_p8() {
    check("isqrt", Mode::Exhaustive { max_runs: 1 << 12 }, || {
        harness::isqrt_rounds(0, 1 << 10, cycleref::engine::isqrt_floor)
    });
}

#[test]
fn the_real_engine_passes_the_same_checks() {
    let e = |c: &G76Cycle| real(c).map(Vec::into_iter);
    check("control", Mode::Exhaustive { max_runs: 4_000_000 }, || harness::run_out_direction(&GEOMETRY, &e));
}
