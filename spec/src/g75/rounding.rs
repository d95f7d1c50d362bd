//! The roundings of `docs/G75.md` §6: nearest, ceiling and floor of an
//! exact value, decided with reading R-G75TIE.
//!
//! Twin: `impl/src/engine/g75/exact.rs`, `Evaluator` (`nearest`, `ceil`,
//! `floor`, `sign`).

use cycleref::error::CycleError;
use num_bigint::BigInt;

use crate::real::{saturating_i128, Real};

use super::*;

pub(super) fn to_i128(v: &BigInt) -> i128 {
    saturating_i128(v)
}

/// Nearest: `floor(v + 1/2)` (ties towards +u / +y).
pub(super) fn nearest(v: &Real) -> Result<i128, CycleError> {
    v.nearest().map(|b| to_i128(&b))
}

/// In, on the start side: `ceil(v)`.
pub(super) fn ceil(v: &Real) -> Result<i128, CycleError> {
    v.ceil().map(|b| to_i128(&b))
}

/// In, on the far side and for the depths: `floor(v)`.
pub(super) fn floor(v: &Real) -> Result<i128, CycleError> {
    v.floor().map(|b| to_i128(&b))
}

/// A profile point rounded to nearest (`docs/G75.md` §6: "all finishing
/// points and centres, P3").
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn round_nearest(p: &RealPoint) -> Result<LocalPoint, CycleError> {
    Ok(LocalPoint::new(nearest(&p.u)?, nearest(&p.y)?))
}
