//! Benchmarks for cycleref: the cases, the `f64` baseline, the generated
//! programs, the bytes-out floor and the history files behind `cargo bench
//! -p cycleref-benches` and the `track` and `pipeline` binaries.
//!
//! See `benches/README.md` for the groups and how to read the figures.

#![forbid(unsafe_code)]

pub mod cases;
pub mod corpus;
pub mod float;
pub mod floor;
pub mod pipeline_history;
pub mod track;
