//! Differential tests of G75.1: the fixed-point engine (`cycleref::expand_g75`)
//! against the exact reference model (`cycleref_spec::g75::expand`). For
//! every generated groove, valid or not, both must give the same alarm or the
//! same moves, move by move; and the engine gives the same with and
//! without its fast path (reading R-FASTPATH, `expand_g75_exact`).
//!
//! The default run tries 1500 grooves per strategy; the long run (50 000,
//! release) is ignored by default:
//!
//! ```text
//! cargo test -p cycleref-proofs --profile proofs --test g75_equivalence -- --ignored
//! ```

use cycleref::g75::{Corner, CornerKind, G75Cycle, PathType};
use cycleref::{CycleError, IncrementSystem, InputUnit, Move, Point, Units, XMode};
use cycleref_spec::differ::assert_same_moves;
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// Both engines agree on `c`, and the engine with its fast path
/// (R-FASTPATH) gives what it gives without (`expand_g75_exact`); the
/// engine's count of layers and plunges, made before its first move for
/// the `nc` heading, is that of the reference's moves, counted. Returns the
/// common result.
fn same(c: &G75Cycle) -> Result<Vec<Move>, CycleError> {
    let s = cycleref_spec::g75::expand(c);
    let ours = cycleref::expand_g75(c);
    if let (Ok(ours), Ok(moves)) = (&ours, &s) {
        let counted = cycleref_spec::cycles::count_plunges(moves.iter().copied());
        assert_eq!(ours.layers_and_plunges(), counted, "{c:?}");
    }
    let fast: Result<Vec<Move>, CycleError> = ours.map(Iterator::collect);
    assert_same_moves(&fast, &s, format_args!("{c:?}"));
    let exact: Result<Vec<Move>, CycleError> =
        cycleref::engine::g75::expand_g75_exact(c).map(Iterator::collect);
    assert_eq!(fast, exact, "the fast path against the intervals alone: {c:?}");
    s
}

/// Angles: mostly arbitrary 0.0001° values, often the exact ones (30, 45,
/// 60, 90) where ties and exact arithmetic matter.
fn angle(lo: u32, hi: u32) -> impl Strategy<Value = u32> {
    prop_oneof![
        3 => lo..=hi,
        1 => prop::sample::select(vec![300_000_u32, 450_000, 600_000, 900_000, 150_000, 750_000])
            .prop_filter("in range", move |a| (lo..=hi).contains(a)),
    ]
}

/// Corner sizes scaled to the groove (`max`, the largest depth and width):
/// mostly small enough to fit their edges, sometimes too large (the
/// CornerTooLarge alarms).
fn corner(max: i64) -> impl Strategy<Value = Corner> {
    (prop_oneof![2 => Just(0_i64), 3 => 1_i64..max / 50 + 2, 1 => 1_i64..max], any::<bool>()).prop_map(
        |(size, round)| Corner { size, kind: if round { CornerKind::Round } else { CornerKind::Chamfer } },
    )
}

/// Grooves over a realistic part of the ranges (sizes up to 20 mm at IS-B),
/// every feature on, valid and invalid.
fn groove(max: i64) -> impl Strategy<Value = G75Cycle> {
    let units = (0_u8..8).prop_map(|code| {
        (
            Units {
                system: if code & 1 == 0 { IncrementSystem::IsB } else { IncrementSystem::IsC },
                unit: if code & 2 == 0 { InputUnit::Metric } else { InputUnit::Inch },
            },
            if code & 4 == 0 { XMode::Diameter } else { XMode::Radius },
        )
    });
    let sizes = (
        1_i64..max,
        0_i64..max,
        prop_oneof![1_i64..max / 10 + 2, 1_i64..max],
        prop_oneof![1_i64..max / 10 + 2, 1_i64..max],
        0_i64..2_000,
        prop_oneof![Just(None), (1_i64..max).prop_map(Some)],
    );
    let allowances = (
        prop_oneof![Just(0_i64), 0_i64..max / 8 + 1],
        prop_oneof![Just(0_i64), 0_i64..max / 8 + 1],
        prop_oneof![Just(None), (0_i64..max / 2 + 1).prop_map(Some)],
    );
    let shape = (angle(1, 900_000), angle(1, 900_000), prop_oneof![Just(0_u32), angle(0, 899_999)]);
    let rest = (any::<bool>(), any::<bool>(), 0_u8..3, [corner(max), corner(max), corner(max), corner(max)]);
    // The readings of the G75.1 page (issue 34), each value as often as
    // the default: bit 0 R-G75RIDGE `as-written`, bit 1 R-G75PECK
    // `as-written`, bit 2 R-G75LAYER `equal`, bit 3 R-G75CHAMFER
    // `axial-width`, bit 4 R-G75SLOPE `falls-towards-d`.
    let readings = any::<u8>();
    (units, sizes, allowances, shape, rest, readings).prop_map(
        |(
            (units, x_mode),
            (depth, width, peck, step, retract, layer),
            (u, w, tool),
            (a, b, l),
            (sx, sz, j, corners),
            bits,
        )| {
            let sx = if sx { 1 } else { -1 };
            let sz = if sz { 1 } else { -1 };
            let start = Point::new(50_000, 1_000);
            G75Cycle {
                units,
                x_mode,
                from: Point::new(start.x - sx * 2_000, start.z - sz * 500),
                start,
                peck,
                step,
                depth: sx * depth,
                width: sz * width,
                flank_a: a,
                flank_b: b,
                slope: l,
                retract,
                layer,
                allowance_x: u,
                allowance_z: w,
                tool_width: tool,
                path: match j {
                    0 => PathType::Rough,
                    1 => PathType::RoughAndFinish,
                    _ => PathType::Finish,
                },
                corners,
                readings: cycleref::G75Readings {
                    ridges_as_written: bits & 1 != 0,
                    peck_retract_as_written: bits & 2 != 0,
                    equal_layers: bits & 4 != 0,
                    chamfer_axial_width: bits & 8 != 0,
                    slope_falls_towards_d: bits & 16 != 0,
                },
            }
        },
    )
}

fn run(cases: u32, max: i64) -> (u32, u32) {
    let mut runner = TestRunner::new(Config { cases, failure_persistence: None, ..Config::default() });
    let valid = std::cell::Cell::new(0_u32);
    let refused = std::cell::Cell::new(0_u32);
    runner
        .run(&groove(max), |c| {
            match same(&c) {
                Ok(_) => valid.set(valid.get() + 1),
                Err(_) => refused.set(refused.get() + 1),
            }
            Ok(())
        })
        .unwrap();
    (valid.get(), refused.get())
}

#[test]
fn engine_equals_reference_small() {
    let (valid, refused) = run(1_500, 200);
    eprintln!("small grooves: {valid} valid, {refused} refused");
    assert!(valid > 300, "the strategy must reach valid grooves ({valid})");
}

#[test]
fn engine_equals_reference_realistic() {
    let (valid, refused) = run(1_500, 20_000);
    eprintln!("realistic grooves: {valid} valid, {refused} refused");
    assert!(valid > 300, "the strategy must reach valid grooves ({valid})");
}

#[test]
#[ignore = "long: run with --profile proofs -- --ignored"]
fn engine_equals_reference_long() {
    let (v1, r1) = run(25_000, 300);
    let (v2, r2) = run(25_000, 30_000);
    eprintln!("long: {} valid, {} refused", v1 + v2, r1 + r2);
}

/// The two example programs with every engine-level option flipped.
#[test]
fn examples_agree() {
    for name in ["gsk980-g75-seed.nc", "gsk980-g75-square.nc", "gsk980-g75-slope.nc"] {
        let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap();
        let mut m = cycleref_spec::Machine::new(cycleref_spec::ProfileName::Gsk980);
        if name.contains("seed") {
            m.increment = IncrementSystem::IsC;
        }
        let program = cycleref_spec::read(&text, &m).unwrap();
        for call in program.grooves() {
            for path in [PathType::Rough, PathType::RoughAndFinish, PathType::Finish] {
                same(&G75Cycle { path, ..call.cycle }).unwrap_or_else(|e| panic!("{name}: {e}"));
            }
        }
    }
}
