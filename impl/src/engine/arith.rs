//! The arithmetic kernels shared by the engines: the one rounded division
//! (`round_div`), the one saturating narrowing (`saturate_i64`), the floor
//! and ceiling divisions of the G75.1 layers and pecks (`floor_div`,
//! `ceil_div`), and the exact integer square roots of the G76 depth
//! schedule ([`isqrt_floor`], [`round_sqrt`]).
//!
//! None of them overflows or panics for the arguments its callers pass:
//! `round_div` and the square roots are total; `floor_div` and `ceil_div`
//! need a divisor `b > 0` (every caller divides by a validated step or
//! layer height of at least one increment, on values below `2^72`).
//!
//! Twins: the reference model states the same roundings in
//! `spec/src/exact.rs` (`round_div`, `round_sqrt`, `ceil_div`), written as
//! plainly as possible; `proofs/tests/engine_equals_spec.rs` checks the
//! square roots against them.

/// `floor(√x)` by Newton's method from a power of two not below the root.
///
/// From a start `g ≥ ⌊√x⌋` the iteration `g ← ⌊(g + ⌊x/g⌋)/2⌋` decreases
/// strictly while `g > ⌊√x⌋` and never goes below `⌊√x⌋` (AM-GM), so it stops
/// exactly there, after about `log2(bits)` + 1 steps (7 for `u128`).
#[must_use]
pub const fn isqrt_floor(x: u128) -> u128 {
    isqrt_floor_counted(x).0
}

/// [`isqrt_floor`], with the iterations of Newton's loop and whether it ran
/// on `u128` (`x ≥ 2^64`) rather than `u64` (for `loop-counters`).
const fn isqrt_floor_counted(x: u128) -> (u128, u32, bool) {
    if x < 2 {
        return (x, 0, false);
    }
    if x <= u64::MAX as u128 {
        // Lossless: x fits u64 (checked above); the root fits u64 as well.
        #[allow(clippy::cast_possible_truncation)]
        let (r, n) = isqrt_floor_u64(x as u64);
        return (r as u128, n, false);
    }
    // x ≥ 2^64: bits in 65..=128, g = 2^ceil(bits/2) ≤ 2^64 and g > √x.
    let bits = 128 - x.leading_zeros();
    let mut g: u128 = 1 << bits.div_ceil(2);
    let mut n = 0_u32;
    loop {
        n += 1;
        // g ≥ ⌊√x⌋ ≥ 2^32 > 0; g ≤ 2^64 and x / g < 2^64 + 3, so the sum
        // stays below 2^66.
        let y = (g + x / g) >> 1;
        if y >= g {
            return (g, n, true);
        }
        g = y;
    }
}

/// [`isqrt_floor`] on `u64`, `x ≥ 2`, with the iterations of its loop.
const fn isqrt_floor_u64(x: u64) -> (u64, u32) {
    // bits in 2..=64, g = 2^ceil(bits/2) ≤ 2^32 and g > √x.
    let bits = 64 - x.leading_zeros();
    let mut g: u64 = 1 << bits.div_ceil(2);
    // At most 64 iterations (g decreases strictly from below 2^33).
    let mut n = 0_u32;
    loop {
        n += 1;
        // 1 ≤ ⌊√x⌋ ≤ g ≤ 2^32 and x / g ≤ 2^32 + 2: no overflow.
        let y = (g + x / g) >> 1;
        if y >= g {
            return (g, n);
        }
        g = y;
    }
}

/// Records the iterations [`isqrt_floor`] makes on `x` (`loop-counters`):
/// its callers call it, since a `const fn` cannot record.
#[cfg(feature = "loop-counters")]
pub fn record_isqrt(x: u128) {
    let (_, n, wide) = isqrt_floor_counted(x);
    if wide {
        crate::loop_counters::ISQRT_U128.record(n);
    } else {
        crate::loop_counters::ISQRT_U64.record(n);
    }
}

/// The integer nearest to `√x`: the `s` with `(2s - 1)² ≤ 4x < (2s + 1)²`
/// (a tie would need an odd square equal to a multiple of 4). Twin:
/// `spec/src/exact.rs`, `round_sqrt` (bisection on the same definition).
///
/// `round(√x) = s + 1` where `s = ⌊√x⌋` exactly when `√x ≥ s + ½`, i.e.
/// `x ≥ s² + s + ¼`, i.e. `x - s² > s` for integers.
#[must_use]
pub const fn round_sqrt(x: u128) -> u128 {
    let s = isqrt_floor(x);
    // s² ≤ x, so neither the product nor the difference overflows, and
    // s + 1 ≤ 2^64.
    if x - s * s > s {
        s + 1
    } else {
        s
    }
}

/// `num / den` rounded to the nearest integer, ties away from zero (the
/// reference's `Decimal` quantisation); `0` for a zero divisor, which no
/// caller passes. Twin: `spec/src/exact.rs`, `round_div`.
pub(crate) fn round_div(num: i128, den: i128) -> i128 {
    let (n, d) = if den < 0 { (num.checked_neg(), den.checked_neg()) } else { (Some(num), Some(den)) };
    let (Some(n), Some(d)) = (n, d) else {
        return 0;
    };
    let (Some(q), Some(r)) = (n.checked_div(d), n.checked_rem(d)) else {
        return 0;
    };
    // |r| < d ≤ i128::MAX / 2 for every caller (|d| < 2^34).
    if r.unsigned_abs().saturating_mul(2) >= d.unsigned_abs() {
        q.saturating_add(n.signum())
    } else {
        q
    }
}

/// `v` as an `i64`, saturating: the one narrowing of every engine (only
/// values that a range check then refuses can lie outside, such as the
/// out-of-range error values of a G76 lead-in or a G75.1 coordinate).
pub(crate) fn saturate_i64(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

/// `⌊a / b⌋` for `b > 0`.
pub(crate) fn floor_div(a: i128, b: i128) -> i128 {
    let q = a / b;
    if a % b != 0 && a < 0 {
        q - 1
    } else {
        q
    }
}

/// `⌈a / b⌉` for `b > 0`.
pub(crate) fn ceil_div(a: i128, b: i128) -> i128 {
    -floor_div(-a, b)
}
