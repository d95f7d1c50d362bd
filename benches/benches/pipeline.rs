//! Criterion group `pipeline`: the command's path from program text to
//! output, on a generated program of about 256 KB (`corpus::program`, GSK
//! 980TDi: G76, G32 and G75.1 cycles among turning blocks and comments).
//!
//! ```text
//! cargo bench -p cycleref-benches --bench pipeline
//! ```
//!
//! * `read`: the streaming reader alone over the program (throughput in
//!   blocks, i.e. lines);
//! * `expand_nc`, `expand_json`: `cycleref_cli::output::expand` into
//!   `std::io::sink()` (validation phase and writing phase, as the
//!   command does), throughput in moves of the cycles;
//! * `check`: `cycleref_cli::check::run` of the program against its own
//!   nc expansion (written to a temporary file once, outside the timing),
//!   throughput in moves.

#![forbid(unsafe_code)]

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, SamplingMode, Throughput};
use cycleref_benches::corpus;
use cycleref_cli::{check, output, Format, Job};
use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::reader::Reader;

/// Size of the program: large enough that per-program costs vanish, small
/// enough for a few iterations per sample.
const BYTES: usize = 256 * 1024;

fn main() {
    let mut cr = Criterion::default().configure_from_args();
    let g = corpus::program(BYTES, true);
    let machine = corpus::machine();
    let moves: u64 = Reader::new(g.text.as_bytes(), &machine)
        .filter_map(|item| {
            let item = item.expect("the program reads");
            Cycle::of(&item).map(|c| expand(c, Engine::Impl).expect("valid cycle").count() as u64)
        })
        .sum();
    let job = Job::new("bench.nc", g.text.clone().into_bytes(), machine.clone(), Engine::Impl);

    let trace = std::env::temp_dir().join(format!("cycleref-bench-pipeline-{}.nc", std::process::id()));
    let mut nc = Vec::new();
    output::expand(&job, Format::Nc, &mut nc).expect("expands");
    std::fs::write(&trace, &nc).expect("writes the trace");
    assert!(check::run(&job, &trace, 0).expect("checks").agree(), "the program agrees with its expansion");
    eprintln!(
        "pipeline: {} bytes, {} lines, {} cycles, {moves} moves, nc output {} bytes",
        g.text.len(),
        g.lines,
        g.cycles(),
        nc.len()
    );

    let mut grp = cr.benchmark_group("pipeline");
    grp.warm_up_time(Duration::from_millis(800))
        .measurement_time(Duration::from_secs(3))
        .sampling_mode(SamplingMode::Flat)
        .sample_size(10);
    grp.throughput(Throughput::Elements(g.lines as u64));
    grp.bench_function("read", |b| {
        b.iter(|| {
            let mut n = 0_usize;
            for item in Reader::new(black_box(g.text.as_bytes()), &machine) {
                black_box(item.expect("reads"));
                n += 1;
            }
            n
        });
    });
    grp.throughput(Throughput::Elements(moves));
    grp.bench_function("expand_nc", |b| {
        b.iter(|| output::expand(black_box(&job), Format::Nc, std::io::sink()).expect("expands"));
    });
    grp.bench_function("expand_json", |b| {
        b.iter(|| output::expand(black_box(&job), Format::Json, std::io::sink()).expect("expands"));
    });
    grp.bench_function("check", |b| {
        b.iter(|| check::run(black_box(&job), &trace, 0).expect("checks").agree());
    });
    grp.finish();
    let _ = std::fs::remove_file(&trace);
    cr.final_summary();
}
