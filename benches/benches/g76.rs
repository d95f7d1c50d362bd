//! Criterion benchmarks of the G76 cycle: the exact-decimal reference
//! model, the fixed-point engine and the `f64` baseline.
//!
//! ```text
//! cargo bench -p cycleref-benches --bench g76            # everything, a few minutes
//! cargo bench -p cycleref-benches --bench g76 -- expand  # one group
//! ```
//!
//! Groups (see `benches/README.md`): `schedule`, `expand/m68x6`,
//! `expand/passes_1000`, `expand/8_start`, `flat`, `reader`. Throughput is
//! in pass paths ((rough + finishing) × starts) or, for `reader`, blocks.

#![forbid(unsafe_code)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, SamplingMode, Throughput};
use cycleref::engine::{expand_g76, rough_pass_count};
use cycleref::g76::G76Cycle;
use cycleref::moves::{PassKind, Role};
use cycleref_benches::cases;
use cycleref_benches::float::{FloatCycle, FloatMove};
use cycleref_spec::{Machine, ProfileName};

/// Measurement time of every benchmark; the machine is small and noisy,
/// the medians are what `track` reads.
const MEASURE: Duration = Duration::from_millis(2_500);
const WARM_UP: Duration = Duration::from_millis(800);

fn elements(n: u64) -> Throughput {
    Throughput::Elements(n)
}

/// The rough depth schedule of the 1000-pass cycle.
fn schedule(cr: &mut Criterion) {
    let c = cases::passes_1000();
    let rough = rough_pass_count(&c).expect("valid");
    assert_eq!(rough, 1_000, "the schedule case has 1000 rough passes");
    let mut g = cr.benchmark_group("schedule");
    g.throughput(elements(rough)).warm_up_time(WARM_UP).measurement_time(MEASURE);
    g.sample_size(20);
    g.bench_function("reference", |b| {
        b.iter(|| cycleref_spec::g76::rough_levels(black_box(&c)).expect("valid"));
    });
    g.sample_size(50);
    // The engine has no public schedule: iterate its moves and keep the
    // depth of every rough pass (one Approach move per pass).
    let mut depths: Vec<i64> = Vec::with_capacity(1_100);
    g.bench_function("engine", |b| {
        b.iter(|| {
            depths.clear();
            for m in expand_g76(black_box(&c)).expect("valid") {
                if m.role == Role::Approach {
                    if let Some(p) = m.pass.filter(|p| p.kind == PassKind::Rough) {
                        depths.push(p.depth);
                    }
                }
            }
            black_box(depths.len())
        });
    });
    // Only the engine's up-front pass count (law levels by square roots,
    // then the minimum-cut levels at once): a lower bound of its schedule.
    g.bench_function("engine_count", |b| b.iter(|| rough_pass_count(black_box(&c)).expect("valid")));
    let mut buf = Vec::with_capacity(1_100);
    g.bench_function("f64", |b| {
        b.iter(|| {
            let f = FloatCycle::from_cycle(black_box(&c)).expect("modelled");
            f.rough_depths(&mut buf);
            black_box(buf.len())
        });
    });
    g.finish();
}

/// One `expand/<case>` group: reference, engine, f64 (iterator) and f64
/// into a buffer.
fn expand_case(cr: &mut Criterion, name: &str, c: &G76Cycle, reference_samples: usize) {
    let passes = cases::pass_paths(c);
    // Every implementation gives the same number of moves (checked by the
    // tests of cycleref_benches::float; asserted here once more).
    let moves = expand_g76(c).expect("valid").count();
    assert_eq!(cycleref_spec::g76::expand(c).expect("valid").len(), moves, "{name}: reference moves");
    let f = FloatCycle::from_cycle(c).expect("modelled");
    assert_eq!(f.moves().count(), moves, "{name}: f64 moves");

    let mut g = cr.benchmark_group(format!("expand/{name}"));
    g.throughput(elements(passes)).warm_up_time(WARM_UP).measurement_time(MEASURE);
    g.sample_size(reference_samples);
    g.bench_function("reference", |b| b.iter(|| cycleref_spec::g76::expand(black_box(c)).expect("valid")));
    g.sample_size(50);
    g.bench_function("engine", |b| {
        b.iter(|| {
            for m in expand_g76(black_box(c)).expect("valid") {
                black_box(m);
            }
        });
    });
    g.bench_function("f64", |b| {
        b.iter(|| {
            let f = FloatCycle::from_cycle(black_box(c)).expect("modelled");
            for m in f.moves() {
                black_box(m);
            }
        });
    });
    let mut buf: Vec<FloatMove> = Vec::with_capacity(moves);
    g.bench_function("f64_buffer", |b| {
        b.iter(|| {
            let f = FloatCycle::from_cycle(black_box(c)).expect("modelled");
            black_box(f.expand_into(&mut buf));
            black_box(&buf);
        });
    });
    g.finish();
}

fn expand(cr: &mut Criterion) {
    // The M68x6 example, read once with the reader, outside the timing.
    expand_case(cr, "m68x6", &cases::m68x6(), 50);
    let c = cases::passes_1000();
    assert_eq!(rough_pass_count(&c), Ok(1_000), "passes_1000 has 1000 rough passes");
    expand_case(cr, "passes_1000", &c, 10);
    let c = cases::eight_start();
    assert_eq!(c.starts, 8);
    expand_case(cr, "8_start", &c, 20);
}

/// The engine's cost per pass from 10 to 100 000 rough passes.
fn flat(cr: &mut Criterion) {
    let mut g = cr.benchmark_group("flat");
    g.warm_up_time(WARM_UP).measurement_time(MEASURE).sample_size(20);
    for n in cases::FLAT_PASSES {
        let c = cases::flat(n);
        assert_eq!(rough_pass_count(&c), Ok(n), "flat({n})");
        g.throughput(elements(cases::pass_paths(&c)));
        g.bench_with_input(BenchmarkId::new("engine", n), &c, |b, c| {
            b.iter(|| {
                for m in expand_g76(black_box(c)).expect("valid") {
                    black_box(m);
                }
            });
        });
    }
    g.finish();
}

/// The program reader on a generated 100 000-block program.
fn reader(cr: &mut Criterion) {
    let text = cases::reader_program(cases::READER_BLOCKS);
    let machine = Machine::new(ProfileName::Gsk988);
    let cycles = cycleref_spec::read(&text, &machine).expect("reads").cycles().count();
    assert!(cycles >= 900, "a G76 every ~100 blocks ({cycles})");
    let mut g = cr.benchmark_group("reader");
    // About 0.1 s per read: flat sampling, 10 samples of equal size.
    g.throughput(elements(cases::READER_BLOCKS as u64))
        .warm_up_time(WARM_UP)
        .measurement_time(Duration::from_secs(3))
        .sampling_mode(SamplingMode::Flat)
        .sample_size(10);
    g.bench_function("read_100000_blocks", |b| {
        b.iter(|| cycleref_spec::read(black_box(&text), &machine).expect("reads"));
    });
    g.finish();
}

/// G32 beside G76: one tapered block with a run-out (two moves), reference
/// against engine.
fn g32(cr: &mut Criterion) {
    use cycleref::{G32Block, G32RunOut, Lead, LeadWord, Point, StartAngle, Units, XMode};
    let b = G32Block {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(30_000, 2_000),
        end: Point::new(40_001, -48_000),
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: G32RunOut::Amounts { short: 1_000, long: 2_000 },
        start_angle: StartAngle::ZERO,
        sync: true,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    assert_eq!(cycleref::expand_g32(&b).expect("valid").count(), 2);
    let mut g = cr.benchmark_group("g32/taper_run_out");
    g.throughput(elements(1)).warm_up_time(WARM_UP).measurement_time(Duration::from_millis(2_500));
    g.bench_function("reference", |bn| bn.iter(|| cycleref_spec::g32::expand(black_box(&b)).expect("valid")));
    g.bench_function("engine", |bn| {
        bn.iter(|| {
            for m in cycleref::expand_g32(black_box(&b)).expect("valid") {
                black_box(m);
            }
        });
    });
    g.finish();
}

/// What `criterion_group!` and `criterion_main!` would generate, written
/// out (their functions carry no docs, which the workspace lints deny).
fn main() {
    let mut cr = Criterion::default().configure_from_args();
    schedule(&mut cr);
    expand(&mut cr);
    flat(&mut cr);
    reader(&mut cr);
    g32(&mut cr);
    cr.final_summary();
}
