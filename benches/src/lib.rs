//! Benchmarks for cycleref: the cases, the `f64` baseline and the
//! history tracking behind `cargo bench -p cycleref-benches --bench g76`
//! and `cargo run -p cycleref-benches --release --bin track`.
//!
//! See `benches/README.md` for the groups and how to read the figures.

#![forbid(unsafe_code)]

pub mod cases;
pub mod corpus;
pub mod float;
pub mod track;
