//! A small driver for instruction counts and `perf stat` timings of the
//! `expand/<case>` benchmarks of `benches/g76.rs`: runs one case's engine
//! or `f64` iterator a given number of times.
//!
//! ```text
//! cargo build --release -p cycleref-benches --example g76_loop
//! valgrind --tool=callgrind target/release/examples/g76_loop m68x6 engine 1000
//! perf stat -e task-clock target/release/examples/g76_loop 8_start f64 200000
//! ```

#![forbid(unsafe_code)]

use std::hint::black_box;

use cycleref::engine::expand_g76;
use cycleref::g76::G76Cycle;
use cycleref_benches::cases;
use cycleref_benches::float::FloatCycle;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: g76_loop m68x6|passes_1000|8_start engine|f64 ITERATIONS";
    let (Some(case), Some(which), Some(n)) = (args.get(1), args.get(2), args.get(3)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let c: G76Cycle = match case.as_str() {
        "m68x6" => cases::m68x6(),
        "passes_1000" => cases::passes_1000(),
        "8_start" => cases::eight_start(),
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    };
    let n: u64 = n.parse().unwrap_or_else(|_| {
        eprintln!("{usage}");
        std::process::exit(2);
    });
    let mut moves = 0_u64;
    match which.as_str() {
        "engine" => {
            for _ in 0..n {
                for m in expand_g76(black_box(&c)).expect("valid") {
                    black_box(m);
                    moves += 1;
                }
            }
        }
        "f64" => {
            for _ in 0..n {
                let f = FloatCycle::from_cycle(black_box(&c)).expect("modelled");
                for m in f.moves() {
                    black_box(m);
                    moves += 1;
                }
            }
        }
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    }
    println!("{moves} moves");
}
