//! Criterion benchmarks of the G75.1 groove cycle: the exact reference
//! model against the fixed-point engine.
//!
//! ```text
//! cargo bench -p cycleref-benches --bench g75
//! ```
//!
//! Groups: `g75/seed` (seed 001 with I4 and J1: exact right-angle-free
//! geometry, 3 plunges), `g75/slope` (a slope and four rounds: the geometry
//! dominates), `g75/wide` (a wide groove of thousands of plunges: the path
//! dominates; throughput in moves).

#![forbid(unsafe_code)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput};
use cycleref::G75Cycle;
use cycleref_benches::cases;

const MEASURE: Duration = Duration::from_millis(2_500);
const WARM_UP: Duration = Duration::from_millis(800);

fn group(cr: &mut Criterion, name: &str, c: &G75Cycle, reference_samples: usize) {
    let moves = cycleref::expand_g75(c).expect("valid").count() as u64;
    let reference = cycleref_spec::g75::expand(c).expect("valid");
    assert_eq!(reference.len() as u64, moves, "{name}: both engines give the same path");
    let mut g = cr.benchmark_group(format!("g75/{name}"));
    g.throughput(Throughput::Elements(moves)).warm_up_time(WARM_UP).measurement_time(MEASURE);
    g.sample_size(reference_samples);
    g.bench_function("reference", |b| {
        b.iter(|| cycleref_spec::g75::expand(black_box(c)).expect("valid").len())
    });
    g.sample_size(50);
    g.bench_function("engine", |b| b.iter(|| cycleref::expand_g75(black_box(c)).expect("valid").count()));
    g.finish();
}

/// What `criterion_group!` and `criterion_main!` would generate, written
/// out (their functions carry no docs, which the workspace lints deny).
fn main() {
    let mut cr = Criterion::default().configure_from_args();
    group(&mut cr, "seed", &cases::groove_seed(), 20);
    group(&mut cr, "slope", &cases::groove_slope(), 20);
    group(&mut cr, "wide", &cases::groove_wide(), 10);
    cr.final_summary();
}
