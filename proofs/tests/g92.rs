//! G92: the engine equals the reference (differential proptests), the pass
//! harness exhaustively and sampled, its loops against its unwind bound
//! (in `unwind.rs`), and engines broken on purpose that it catches.

use cycleref::lead::{Lead, LeadWord};
use cycleref::{G92Cycle, Move, Point, RunOut, StartAngle};
use cycleref_proofs::g92::g92_pass;
use cycleref_proofs::harness::units_of;
use cycleref_proofs::shim::{check, Mode};
use proptest::prelude::*;

fn cycles() -> impl Strategy<Value = G92Cycle> {
    let coord = prop_oneof![-1_000_000_000_i64..=1_000_000_000, -5_000_i64..=5_000];
    (
        (0_u8..8, coord.clone(), coord.clone(), coord.clone(), coord.clone(), coord),
        (0_u8..4, 0_i64..=3_000_000, 0_i64..=3_000_000, 0_u32..=100, 0_u32..=90),
        (1_u64..=99_999_999, 0_u32..=7, any::<bool>(), 0_u32..=1000, 0_u32..=359_999, any::<bool>()),
    )
        .prop_map(
            |((code, x0, z0, x1, z1, r), (ro, j, k, chamfer, angle), (m, scale, i, l, q, face))| G92Cycle {
                units: units_of(i64::from(code)).0,
                x_mode: units_of(i64::from(code)).1,
                start: Point::new(x0, z0),
                end: Point::new(x1, z1),
                taper: r,
                lead: Lead { word: if i { LeadWord::I } else { LeadWord::F }, mantissa: m, scale },
                run_out: match ro {
                    0 => RunOut::None,
                    1 => RunOut::Amounts { short: j, long: k },
                    2 => RunOut::Chamfer { tenths_of_lead: chamfer, angle_degrees: angle, long: None },
                    _ => RunOut::Chamfer { tenths_of_lead: chamfer, angle_degrees: angle, long: Some(k) },
                },
                starts: l.min(12),
                start_angle: StartAngle::from_millidegrees(u64::from(q)),
                face,
                readings: cycleref::CycleReadings::DEFAULT,
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// Both engines give the same moves or the same error.
    #[test]
    fn engine_equals_spec(c in cycles()) {
        let ours = cycleref::expand_g92(&c).map(Iterator::collect::<Vec<_>>);
        prop_assert_eq!(ours, cycleref_spec::g92::expand(&c));
    }

    /// Near the geometry's boundaries (A on C's X, B on A, K = |W|, a
    /// steep taper): small coordinates, where the alarms and the long
    /// axis switch.
    #[test]
    fn engine_equals_spec_near_boundaries(
        x0 in -6_i64..=6, z0 in -6_i64..=6, x1 in -6_i64..=6, z1 in -6_i64..=6, r in -6_i64..=6,
        j in 0_i64..=6, k in 0_i64..=6, code in 0_u8..8, l in 1_u32..=3, face in any::<bool>(),
    ) {
        let c = G92Cycle {
            units: units_of(i64::from(code)).0,
            x_mode: units_of(i64::from(code)).1,
            start: Point::new(x0, z0),
            end: Point::new(x1, z1),
            taper: r,
            lead: Lead { word: LeadWord::F, mantissa: 1, scale: 0 },
            run_out: if j == 0 { RunOut::None } else { RunOut::Amounts { short: j, long: k } },
            starts: l,
            start_angle: StartAngle::ZERO,
            face,
            readings: cycleref::CycleReadings::DEFAULT,
        };
        let ours = cycleref::expand_g92(&c).map(Iterator::collect::<Vec<_>>);
        prop_assert_eq!(ours, cycleref_spec::g92::expand(&c));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// Both engines agree under every value of the readings a block carries
    /// (issue 34: R-RUNOUT's clamp, R-XRUNOUT, R-LONG988's table, which
    /// also accepts the steep face thread (R-G92FACE), R-CHAMFERANGLE's
    /// axis; R-END has no effect on G92's unshifted pass, and both engines
    /// take every value),
    /// on every block size and near the boundaries, where the clamp, the
    /// long axis and the X-long run-out switch.
    #[test]
    fn engine_equals_spec_under_every_reading(
        c in cycles(), clamp in any::<bool>(), towards in any::<bool>(), table in any::<bool>(),
        end in 0..3_u8,
        x0 in -6_i64..=6, z0 in -6_i64..=6, x1 in -6_i64..=6, z1 in -6_i64..=6, r in -6_i64..=6,
        j in 0_i64..=6, k in 0_i64..=6, small in any::<bool>(), from_short in any::<bool>(),
    ) {
        let pass_end = [
            cycleref::readings::PassEnd::TravelI,
            cycleref::readings::PassEnd::Parallel,
            cycleref::readings::PassEnd::Translated,
        ][usize::from(end)];
        let readings = cycleref::CycleReadings {
            clamp_run_out: clamp,
            x_run_out_towards_start: towards,
            pass_end,
            long_axis_by_table: table,
            chamfer_from_short_axis: from_short,
            ..cycleref::CycleReadings::DEFAULT
        };
        let c = if small {
            G92Cycle {
                start: Point::new(x0, z0),
                end: Point::new(x1, z1),
                taper: r,
                run_out: if j == 0 { RunOut::None } else { RunOut::Amounts { short: j, long: k } },
                starts: 1,
                readings,
                ..c
            }
        } else {
            G92Cycle { readings, ..c }
        };
        let ours = cycleref::expand_g92(&c).map(Iterator::collect::<Vec<_>>);
        prop_assert_eq!(ours, cycleref_spec::g92::expand(&c));
    }
}

/// The harness over every block within 2 increments (all units, run-outs,
/// one and two starts).
#[test]
fn pass_harness_exhaustive() {
    let r = check("G92 pass", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        g92_pass(2, 2, 2, &cycleref::expand_g92);
    });
    eprintln!("G92 pass: {} runs, {} pruned", r.runs, r.pruned);
    assert!(r.runs > 100_000, "{} runs", r.runs);
}

#[test]
fn pass_harness_sampled() {
    let (reach, run_out, starts) = cycleref_proofs::windows::G92_WINDOW;
    check("G92 pass (window)", Mode::Sample { runs: 50_000, seed: 92 }, || {
        g92_pass(reach, run_out, starts, &cycleref::expand_g92);
    });
    check("G92 pass (full range)", Mode::Sample { runs: 20_000, seed: 93 }, || {
        g92_pass(999_999_999, 99_999_999, 999, &cycleref::expand_g92);
    });
    // The reference obeys it too.
    check("G92 pass (reference)", Mode::Sample { runs: 20_000, seed: 94 }, || {
        g92_pass(1_000_000, 100_000, 3, &|c: &G92Cycle| cycleref_spec::g92::expand(c).map(Vec::into_iter));
    });
}

/// An engine whose run-out goes into the work (J towards C's far side).
fn flipped_run_out(c: &G92Cycle) -> Result<std::vec::IntoIter<Move>, cycleref::CycleError> {
    let mut moves: Vec<Move> = cycleref::expand_g92(c)?.collect();
    for m in &mut moves {
        if m.role == cycleref::Role::RunOut {
            m.to.x = 2 * c.end.x - m.to.x;
        }
    }
    Ok(moves.into_iter())
}

/// An engine that rapids diagonally from A to B (X and Z together) after
/// moving A's Z by one increment.
fn diagonal_approach(c: &G92Cycle) -> Result<std::vec::IntoIter<Move>, cycleref::CycleError> {
    let mut moves: Vec<Move> = cycleref::expand_g92(c)?.collect();
    if let Some(m) = moves.iter_mut().find(|m| m.role == cycleref::Role::Approach) {
        m.to.z += 1;
    }
    Ok(moves.into_iter())
}

/// The real engine passes over the mutants' domain with every cover
/// satisfied (the control of the two mutant tests below).
#[test]
fn mutant_domain_control() {
    check("G92 pass (control)", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        g92_pass(2, 2, 2, &cycleref::expand_g92);
    });
}

#[test]
#[should_panic(expected = "no point beyond the cut line")]
fn a_run_out_into_the_work_is_caught() {
    check("G92 pass (flipped run-out)", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        g92_pass(2, 2, 2, &flipped_run_out);
    });
}

#[test]
#[should_panic(expected = "the approach runs along X from A to B")]
fn a_diagonal_approach_is_caught() {
    check("G92 pass (diagonal approach)", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        g92_pass(2, 2, 2, &diagonal_approach);
    });
}
