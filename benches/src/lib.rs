//! Benchmarks for cycleref.
