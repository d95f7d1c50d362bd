//! G32: the engine equals the reference (differential proptests), and the
//! run-out harness (property 4 for G32) exhaustively and sampled.

use cycleref::lead::{Lead, LeadWord};
use cycleref::{G32Block, G32RunOut, Point, StartAngle};
use cycleref_proofs::harness;
use cycleref_proofs::harness::units_of;
use cycleref_proofs::shim::{check, Mode};
use proptest::prelude::*;

fn blocks() -> impl Strategy<Value = G32Block> {
    let coord = prop_oneof![-1_000_000_000_i64..=1_000_000_000, -2_000_i64..=2_000];
    (
        (0_u8..8, coord.clone(), coord.clone(), coord.clone(), coord),
        (any::<bool>(), -3_000_000_i64..=3_000_000, -10_i64..=3_000_000, any::<bool>()),
        (1_u64..=99_999_999, 0_u32..=7, any::<bool>(), 0_u32..=359_999, 1_u32..=999, any::<bool>()),
    )
        .prop_map(|((code, x0, z0, x1, z1), (ro, j, k, sync), (m, scale, i, q, den, frac))| G32Block {
            units: units_of(i64::from(code)).0,
            x_mode: units_of(i64::from(code)).1,
            start: Point::new(x0, z0),
            end: Point::new(x1, z1),
            lead: Lead { word: if i { LeadWord::I } else { LeadWord::F }, mantissa: m, scale },
            run_out: if ro { G32RunOut::Amounts { short: j, long: k } } else { G32RunOut::None },
            start_angle: if frac {
                StartAngle { num: q, den }
            } else {
                StartAngle::from_millidegrees(u64::from(q))
            },
            sync,
            readings: cycleref::CycleReadings::DEFAULT,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    /// Both engines give the same moves or the same error.
    #[test]
    fn engine_equals_spec(b in blocks()) {
        let ours = cycleref::expand_g32(&b).map(Iterator::collect::<Vec<_>>);
        prop_assert_eq!(ours, cycleref_spec::g32::expand(&b));
    }

    /// Both engines agree at the tie of R-G32LONG (the X travel as a radius
    /// equal to the Z travel), under `tie-x` and `tie-z`.
    #[test]
    fn engine_equals_spec_at_the_tie(b in blocks(), tie_z in any::<bool>(), down in any::<bool>()) {
        let xf = b.x_mode.factor();
        // An X travel the factor divides, and the Z travel its radius.
        let dx = (b.end.x - b.start.x) / xf * xf;
        let dz = if down { -dx.abs() / xf } else { dx.abs() / xf };
        let b = G32Block {
            end: Point::new(b.start.x + dx, b.start.z + dz),
            readings: cycleref::CycleReadings { g32_tie_z: tie_z, ..cycleref::CycleReadings::DEFAULT },
            ..b
        };
        let ours = cycleref::expand_g32(&b).map(Iterator::collect::<Vec<_>>);
        prop_assert_eq!(ours, cycleref_spec::g32::expand(&b));
    }
}

#[test]
fn run_out_harness_exhaustive() {
    // Start and end in a 7 × 7 × 7 × 7 grid around 0, |J|, K <= 2, all units.
    let r = check("G32 run-out", Mode::Exhaustive { max_runs: 5_000_000 }, || {
        harness::g32_run_out(3, 2, &cycleref::expand_g32)
    });
    eprintln!("G32 run-out: {} runs, {} pruned", r.runs, r.pruned);
}

#[test]
fn run_out_harness_sampled() {
    check("G32 run-out (sampled)", Mode::Sample { runs: 50_000, seed: 5 }, || {
        harness::g32_run_out(999_999_999, 99_999_999, &cycleref::expand_g32)
    });
    // The reference obeys it too.
    check("G32 run-out (reference)", Mode::Sample { runs: 20_000, seed: 6 }, || {
        harness::g32_run_out(1_000_000, 100_000, &|b: &G32Block| {
            cycleref_spec::g32::expand(b).map(Vec::into_iter)
        })
    });
}

#[test]
#[should_panic(expected = "run-out end: J along")]
fn flipped_j_is_caught() {
    let mutant = |b: &G32Block| {
        let flipped = match b.run_out {
            G32RunOut::Amounts { short, long } => {
                G32Block { run_out: G32RunOut::Amounts { short: -short, long }, ..*b }
            }
            G32RunOut::None => *b,
        };
        cycleref::expand_g32(&flipped)
    };
    check("G32 run-out", Mode::Exhaustive { max_runs: 5_000_000 }, || harness::g32_run_out(3, 2, &mutant));
}
