//! The G76 harnesses over G78's modes: G78 is the same cycle with three
//! more infeed modes (centre, left flank, the 980TDi's alternating flanks)
//! and the equal-step depth mode, so P1 (depth monotonicity), P2
//! (termination), P3 (finishing), P5 (no overcut), no rapid in the thread
//! and P6 (engine = reference) run here exhaustively over every infeed
//! mode, both depth modes, and sampled over the documented ranges. Under
//! Kani the G76 windows include them (`windows::G76_WINDOW`: infeed 0..=5,
//! depth mode 0..=1).

use cycleref_proofs::harness::{self, Domain, FixedPoint};
use cycleref_proofs::shim::{self, check_and_print as check, Mode};

/// Every infeed mode of G76 and G78, both depth modes.
const MODES: Domain = Domain { infeed: (0, 5), depth_mode: (0, 1), ..Domain::SCHEDULE };

/// A smaller schedule for the geometric properties: k 1..=8, Δd 1..=8,
/// Δdmin 0..=2, d 0..=k.
const SMALL: Domain =
    Domain { height: (1, 8), first_depth: (1, 8), min_cut: (0, 2), allowance: (0, 8), ..MODES };

/// Sampling: the documented ranges, every mode.
const WIDE: Domain = Domain { infeed: (0, 5), depth_mode: (0, 1), ..Domain::WIDE };

const SAMPLE: Mode = Mode::Sample { runs: 3_000, seed: 0x6737_3878 };

#[test]
fn p1_depth_monotonicity_every_mode() {
    let r = check("G78 depth monotonicity", Mode::Exhaustive { max_runs: 1_000_000 }, || {
        harness::depth_monotonicity(&MODES, &FixedPoint);
    });
    assert!(r.runs > 250_000, "{} runs", r.runs);
    check("G78 depth monotonicity (sampled)", SAMPLE, || harness::depth_monotonicity(&WIDE, &FixedPoint));
}

#[test]
fn p2_termination_every_mode() {
    check("G78 termination", Mode::Exhaustive { max_runs: 1_000_000 }, || {
        harness::termination(&MODES, &FixedPoint);
    });
    check("G78 termination (sampled)", SAMPLE, || harness::termination(&WIDE, &FixedPoint));
}

#[test]
fn p3_finishing_every_mode() {
    let d = Domain { finishing: (0, 3), starts: (1, 2), ..SMALL };
    check("G78 finishing", Mode::Exhaustive { max_runs: 1_000_000 }, || harness::finishing(&d, &FixedPoint));
}

#[test]
fn p5_no_overcut_every_mode() {
    // Tool angles around 60° and the extremes' neighbours are in the
    // sampled run; here 29..=31 and 59..=61 by two domains.
    let d = Domain { tool_angle: (59, 61), lead_in: (0, 1), taper: (-2, 2), ..SMALL };
    let d = Domain { height: (1, 6), first_depth: (1, 6), allowance: (0, 6), ..d };
    check("G78 no overcut", Mode::Exhaustive { max_runs: 2_000_000 }, || {
        harness::no_overcut(&d, &FixedPoint)
    });
    let d = Domain { tool_angle: (29, 31), ..d };
    check("G78 no overcut (30°)", Mode::Exhaustive { max_runs: 2_000_000 }, || {
        harness::no_overcut(&d, &FixedPoint)
    });
    check("G78 no overcut (sampled)", SAMPLE, || harness::no_overcut(&WIDE, &FixedPoint));
}

#[test]
fn no_rapid_in_thread_every_mode() {
    let d = Domain {
        height: (1, 4),
        first_depth: (1, 4),
        min_cut: (0, 1),
        allowance: (0, 4),
        tool_angle: (60, 60),
        finishing: (0, 1),
        internal: (0, 1),
        positive_z: (0, 1),
        taper: (-6, 6),
        length: (5, 6),
        run_out_kind: (0, 1),
        run_out: (1, 2),
        units: (3, 3),
        lead_in: (0, 1),
        ..MODES
    };
    check("G78 no rapid in the thread", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        cycleref_proofs::thread::no_rapid_in_thread(&d, &FixedPoint);
    });
}

#[test]
fn p6_equivalence_every_mode() {
    check("G78 equivalence", Mode::Exhaustive { max_runs: 1_000_000 }, || {
        harness::equivalence(&SMALL, &FixedPoint);
    });
    check("G78 equivalence (sampled)", SAMPLE, || harness::equivalence(&WIDE, &FixedPoint));
}

/// A left flank mirrored the wrong way (`zc + right` instead of `2 zc -
/// right`: the mirror of the right flank about the centre line) puts the
/// deep left passes outside the final form: P5 catches it on its own
/// assertion text, and the real engine passes the same domain with every
/// cover (the control).
#[test]
fn a_left_flank_mirrored_wrongly_is_caught() {
    use cycleref::{Flank, G76Cycle, Move, Role};
    let d = Domain { tool_angle: (59, 61), lead_in: (0, 1), taper: (0, 0), ..SMALL };
    let d = Domain { height: (1, 6), first_depth: (1, 6), allowance: (0, 6), ..d };
    let mutant = |c: &G76Cycle| -> Result<std::vec::IntoIter<Move>, cycleref::CycleError> {
        let mut moves: Vec<Move> = cycleref::expand_g76(c)?.collect();
        let zc = cycleref_spec::tan::mul_tan_round(c.thread_height - c.finishing_allowance, c.tool_angle)
            .unwrap_or(0);
        let t = (c.end.z - c.start.z).signum();
        for m in &mut moves {
            if m.role == Role::Approach && m.pass.is_some_and(|p| p.flank == Flank::Left) {
                // shift = 2 zc - right, so right = 2 zc - shift; the mutant
                // shifts zc + right = 3 zc - shift.
                let shift = t * (m.to.z - c.start.z);
                m.to.z = c.start.z + t * (3 * zc - shift);
            }
        }
        Ok(moves.into_iter())
    };
    let r = shim::caught(
        Mode::Exhaustive { max_runs: 2_000_000 },
        || harness::no_overcut(&d, &FixedPoint),
        || harness::no_overcut(&d, &mutant),
        "a pass lies outside the final form",
    );
    eprintln!("control: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
}
