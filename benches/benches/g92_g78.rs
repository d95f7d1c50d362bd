//! Criterion benchmarks of G92 and G78 beside G76's: the exact-decimal
//! reference model and the fixed-point engine on the same cycles.
//!
//! ```text
//! cargo bench -p cycleref-benches --bench g92_g78
//! ```
//!
//! Groups (see `benches/README.md`): `g92/o0012` (the 980TDi manual's
//! first block: one pass with a run-out), `g92/8_start` (the same block
//! with L8: eight passes), `g92/taper` (a taper whose run-out starts on
//! the cut line: one rounded division); `g78/alternating_equal` (G76's
//! 1000-pass case as a G78 with equal depth steps and the flanks in turn)
//! and `g78/centre_decreasing` (the same, centre line, G76's depths).
//! Throughput is in moves.

#![forbid(unsafe_code)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput};
use cycleref::{
    expand_g76, expand_g92, DepthMode, G76Cycle, G92Cycle, Infeed, Lead, LeadWord, Point, RunOut, StartAngle,
    Units, XMode,
};
use cycleref_benches::cases;

const MEASURE: Duration = Duration::from_millis(2_500);
const WARM_UP: Duration = Duration::from_millis(800);

/// `G0 X65 Z5; G92 X58.7 Z-28 F3 J3 K1` (IS-B, diameter), `starts` starts.
fn o0012(starts: u32) -> G92Cycle {
    G92Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(65_000, 5_000),
        end: Point::new(58_700, -28_000),
        taper: 0,
        lead: Lead { word: LeadWord::F, mantissa: 3, scale: 0 },
        run_out: RunOut::Amounts { short: 3_000, long: 1_000 },
        starts,
        start_angle: StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

fn group(cr: &mut Criterion, name: &str, c: &G92Cycle) {
    let moves = expand_g92(c).expect("valid").count();
    assert_eq!(moves, cycleref_spec::g92::expand(c).expect("valid").len());
    let mut g = cr.benchmark_group(format!("g92/{name}"));
    g.throughput(Throughput::Elements(u64::try_from(moves).unwrap_or(1)));
    g.warm_up_time(WARM_UP).measurement_time(MEASURE);
    g.bench_function("reference", |b| b.iter(|| cycleref_spec::g92::expand(black_box(c)).expect("valid")));
    g.bench_function("engine", |b| {
        b.iter(|| expand_g92(black_box(c)).expect("valid").fold(0_i64, |s, m| s.wrapping_add(m.to.x)));
    });
    g.finish();
}

fn g78_group(cr: &mut Criterion, name: &str, c: &G76Cycle) {
    let moves = expand_g76(c).expect("valid").count();
    assert_eq!(moves, cycleref_spec::g76::expand(c).expect("valid").len());
    let mut g = cr.benchmark_group(format!("g78/{name}"));
    g.throughput(Throughput::Elements(u64::try_from(moves).unwrap_or(1)));
    g.warm_up_time(WARM_UP).measurement_time(MEASURE).sample_size(20);
    g.bench_function("reference", |b| b.iter(|| cycleref_spec::g76::expand(black_box(c)).expect("valid")));
    g.bench_function("engine", |b| {
        b.iter(|| expand_g76(black_box(c)).expect("valid").fold(0_i64, |s, m| s.wrapping_add(m.to.x)));
    });
    g.finish();
}

/// The groups, run from `main` (criterion's group macros are left out:
/// their functions carry no docs, which the workspace lints deny).
fn main() {
    let mut cr = Criterion::default().configure_from_args();
    let cr = &mut cr;
    group(cr, "o0012", &o0012(1));
    group(cr, "8_start", &o0012(8));
    // G92 X40 Z-30 R-5 F2 J1 K2 from X50 Z2: the run-out starts at X39.375.
    let taper = G92Cycle {
        start: Point::new(50_000, 2_000),
        end: Point::new(40_000, -30_000),
        taper: -5_000,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: RunOut::Amounts { short: 1_000, long: 2_000 },
        ..o0012(1)
    };
    group(cr, "taper", &taper);
    let g78 = G76Cycle { infeed: Infeed::Alternating, depth_mode: DepthMode::Equal, ..cases::passes_1000() };
    g78_group(cr, "alternating_equal", &g78);
    let g78 = G76Cycle { infeed: Infeed::Centre, ..cases::passes_1000() };
    g78_group(cr, "centre_decreasing", &g78);
    cr.final_summary();
}
