//! Exact arithmetic the manual's formulas need beyond `+ - ×`: rounding to
//! the least increment, division and square root rounded to nearest.
//!
//! DOMAIN decision 2: quantisation rounds to the nearest increment, ties away
//! from zero, computed exactly. These helpers are deliberately written as
//! plainly as possible: they are the reference the engine's fast versions
//! are checked against.

use cycleref::Units;
use rust_decimal::{Decimal, RoundingStrategy};

/// `num / den` rounded to the nearest integer, ties away from zero.
/// `den` must not be zero.
///
/// Twin: `impl/src/engine/arith.rs`, `round_div` (checked, for the
/// engine).
#[must_use]
pub fn round_div(num: i128, den: i128) -> i128 {
    let (n, d) = if den < 0 { (-num, -den) } else { (num, den) };
    let q = n / d;
    let r = n % d;
    if 2 * r.abs() >= d {
        q + n.signum()
    } else {
        q
    }
}

/// `ceil(num / den)` for `num >= 0`, `den > 0`.
///
/// Twin: `impl/src/engine/arith.rs`, `ceil_div` (any sign of `num`).
#[must_use]
pub fn ceil_div(num: i128, den: i128) -> i128 {
    (num + den - 1) / den
}

/// The integer nearest to `sqrt(x)`, found by bisection on its definition:
/// the `s` with `(2s - 1)^2 <= 4x < (2s + 1)^2`. A tie is impossible: it
/// would need `4x = (2s + 1)^2`, an odd square equal to a multiple of 4.
///
/// Twin: `impl/src/engine/arith.rs`, `round_sqrt` (Newton's method on
/// the floor root).
#[must_use]
pub fn round_sqrt(x: u128) -> u128 {
    // s <= 2^64, so (2s + 1)^2 may exceed u128 for the largest inputs:
    // compare s^2 + s against x instead: (2s+1)^2 > 4x  <=>  s^2 + s >= x
    // (because 4s^2 + 4s + 1 > 4x  <=>  s^2 + s >= x for integers).
    let above = |s: u128| -> bool {
        // s*s + s >= x, without overflow.
        match s.checked_mul(s).and_then(|sq| sq.checked_add(s)) {
            Some(v) => v >= x,
            None => true,
        }
    };
    // Smallest s with s^2 + s >= x is round(sqrt(x)).
    let (mut lo, mut hi) = (0_u128, 1_u128 << 64);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if above(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// `v` rounded to the least increment of `units`, ties away from zero.
#[must_use]
pub fn quantize(v: Decimal, units: Units) -> Decimal {
    v.round_dp_with_strategy(units.decimals(), RoundingStrategy::MidpointAwayFromZero)
}

/// A length in mm (inch) from increments.
#[must_use]
pub fn from_increments(v: i64, units: Units) -> Decimal {
    Decimal::new(v, units.decimals())
}

/// Increments of a length that is already a whole number of increments.
///
/// # Panics
///
/// Never for a quantised value within the range tables; the reference model
/// only calls it on such values, so a panic here is a bug of the model.
#[must_use]
pub fn to_increments(v: Decimal, units: Units) -> i64 {
    let scaled = v * Decimal::from(units.per_unit());
    assert!(scaled.fract().is_zero(), "not a whole number of increments: {v}");
    i64::try_from(scaled).expect("length within the range tables")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_div_ties_away() {
        assert_eq!(round_div(5, 2), 3);
        assert_eq!(round_div(-5, 2), -3);
        assert_eq!(round_div(7, 3), 2);
        assert_eq!(round_div(-7, 3), -2);
        assert_eq!(round_div(8, -3), -3);
        assert_eq!(round_div(0, 7), 0);
    }

    #[test]
    fn round_sqrt_definition() {
        for x in 0_u128..20_000 {
            let s = round_sqrt(x);
            assert!((2 * s).saturating_sub(1).pow(2) <= 4 * x || s == 0, "x={x} s={s}");
            assert!(4 * x < (2 * s + 1).pow(2), "x={x} s={s}");
        }
        // sqrt(2) * 1800 = 2545.58... -> 2546
        assert_eq!(round_sqrt(1800 * 1800 * 2), 2546);
        assert_eq!(round_sqrt(u128::from(u64::MAX) * u128::from(u64::MAX)), u128::from(u64::MAX));
    }
}
