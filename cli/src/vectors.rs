//! `cycleref vectors`: conformance vectors (being written).

use std::path::Path;

/// Writes `count` cases generated from `seed` into `out`.
pub fn run(_count: u32, _seed: u64, _out: &Path) -> Result<String, String> {
    Err("vectors: not available yet".into())
}
