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
//! Contracts: each kernel states what it guarantees as
//! `#[cfg_attr(kani, kani::requires/ensures)]`, with the predicates of
//! [`contracts`](super::contracts); `cargo kani` proves them
//! (`proof_for_contract`) and the cycle harnesses use them in place of the
//! kernels (`stub_verified`). With the test-only feature `contract-checks`
//! each call checks its precondition and postcondition at run time.
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
///
/// Contract: [`sqrt_requires`](super::contracts::sqrt_requires) (`x <
/// 2^62`, the range its callers use; the function computes every `u128`'s
/// root), [`isqrt_floor_ensures`](super::contracts::isqrt_floor_ensures).
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::sqrt_requires(x)))]
#[cfg_attr(kani, kani::ensures(|s: &u128| crate::engine::contracts::isqrt_floor_ensures(x, *s)))]
pub const fn isqrt_floor(x: u128) -> u128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::sqrt_requires(x), "isqrt_floor: requires");
    let s = isqrt_floor_counted(x).0;
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::isqrt_floor_ensures(x, s), "isqrt_floor: ensures");
    s
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
///
/// Contract: [`sqrt_requires`](super::contracts::sqrt_requires),
/// [`round_sqrt_ensures`](super::contracts::round_sqrt_ensures).
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::sqrt_requires(x)))]
#[cfg_attr(kani, kani::ensures(|r: &u128| crate::engine::contracts::round_sqrt_ensures(x, *r)))]
pub const fn round_sqrt(x: u128) -> u128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::sqrt_requires(x), "round_sqrt: requires");
    let s = isqrt_floor(x);
    // s² ≤ x, so neither the product nor the difference overflows, and
    // s + 1 ≤ 2^64.
    let r = if x - s * s > s { s + 1 } else { s };
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::round_sqrt_ensures(x, r), "round_sqrt: ensures");
    r
}

/// Corrections by one that [`round_sqrt_near`] tries from its guess before
/// it takes [`round_sqrt`].
pub const NEAR_STEPS: u32 = 4;

/// `⌊√(n · 2^64)⌋ = ⌊√n · 2^32⌋` for `n` in `0..=32`: the first levels'
/// guesses of the depth law (`engine::schedule`), `Δd √n` to within
/// `Δd · 2^-32 < ¼` increment.
pub(super) const SQRT_Q32: [u64; 33] = {
    let mut t = [0_u64; 33];
    let mut n = 0;
    while n < 33 {
        // n · 2^64 < 2^70; its root is below 2^35: lossless.
        #[allow(clippy::cast_possible_truncation)]
        let root = isqrt_floor_counted((n as u128) << 64).0 as u64;
        t[n] = root;
        n += 1;
    }
    t
};

/// [`round_sqrt`] of `x` from a `guess` of it: the guess is taken when it
/// is the root, else corrected by one at a time, at most [`NEAR_STEPS`]
/// times, towards it; then, if still not there, [`round_sqrt`] (Newton's
/// method from a power of two). The guess changes only the speed, never
/// the result: a step by one needs two products and no division, where
/// Newton's method takes five to seven dependent divisions. The depth law
/// guesses each level from the one before (`engine::schedule`).
///
/// Each candidate `r` is tested with [`round_sqrt_ensures`]'s own
/// inequalities, `r(r - 1) < x ≤ r(r + 1)` (`x = 0` for `r = 0`), so a
/// returned guess is the rounded root; a candidate too large (`r(r - 1) ≥
/// x`) steps down, one too small (`r(r + 1) < x`) steps up. Candidates
/// start at most at `2^31` (`√x < 2^31` for `x < 2^62`), so every product
/// is below `2^63`.
///
/// Contract: [`sqrt_requires`](super::contracts::sqrt_requires),
/// [`round_sqrt_ensures`](super::contracts::round_sqrt_ensures) (the
/// guess is any `u128`).
///
/// [`round_sqrt_ensures`]: super::contracts::round_sqrt_ensures
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::sqrt_requires(x)))]
#[cfg_attr(kani, kani::ensures(|r: &u128| crate::engine::contracts::round_sqrt_ensures(x, *r)))]
// Inlined into the depth law (a call per root cost as much again as the
// root; the G76 up-front count and schedule take one per level).
#[inline(always)]
pub const fn round_sqrt_near(x: u128, guess: u128) -> u128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::sqrt_requires(x), "round_sqrt_near: requires");
    let r = match round_sqrt_near_steps(x, guess).0 {
        Some(r) => r,
        None => round_sqrt(x),
    };
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::round_sqrt_ensures(x, r), "round_sqrt_near: ensures");
    r
}

/// Records the iterations of [`round_sqrt_near`]'s loop on `x` from
/// `guess` (`loop-counters`): its callers call it, since a `const fn`
/// cannot record.
#[cfg(feature = "loop-counters")]
pub fn record_isqrt_near(x: u128, guess: u128) {
    crate::loop_counters::ISQRT_NEAR.record(round_sqrt_near_steps(x, guess).1);
}

/// The steps of [`round_sqrt_near`] from `guess`: the rounded root, or
/// `None` when [`NEAR_STEPS`] corrections do not reach it (or `x ≥ 2^62`),
/// with the iterations of the loop (at most `NEAR_STEPS + 1`).
#[inline(always)]
const fn round_sqrt_near_steps(x: u128, guess: u128) -> (Option<u128>, u32) {
    if x >= super::contracts::SQRT_LIMIT {
        return (None, 0);
    }
    // Lossless: x < 2^62.
    #[allow(clippy::cast_possible_truncation)]
    let x = x as u64;
    // r ≤ 2^31 + NEAR_STEPS: r(r + 1) < 2^63.
    #[allow(clippy::cast_possible_truncation)]
    let mut r = if guess > 1 << 31 { 1 << 31 } else { guess as u64 };
    let mut step = 0;
    while step <= NEAR_STEPS {
        step += 1;
        if r > 0 && r * (r - 1) >= x {
            r -= 1;
        } else if r * (r + 1) < x {
            r += 1;
        } else {
            return (Some(r as u128), step);
        }
    }
    (None, step)
}

/// `num / den` rounded to the nearest integer, ties away from zero (the
/// reference's `Decimal` quantisation); `0` for a zero divisor, which no
/// caller passes. Twin: `spec/src/exact.rs`, `round_div`.
///
/// Contract: [`round_div_requires`](super::contracts::round_div_requires)
/// (a non-zero divisor below `2^34`, a numerator below `2^67`: the ranges
/// its callers use),
/// [`round_div_ensures`](super::contracts::round_div_ensures).
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::round_div_requires(num, den)))]
#[cfg_attr(kani, kani::ensures(|r: &i128| crate::engine::contracts::round_div_ensures(num, den, *r)))]
pub fn round_div(num: i128, den: i128) -> i128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::round_div_requires(num, den), "round_div: requires");
    let r = round_div_unchecked(num, den);
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::round_div_ensures(num, den, r), "round_div: ensures");
    r
}

/// [`round_div`] without the contract checks.
#[inline]
fn round_div_unchecked(num: i128, den: i128) -> i128 {
    // Both below 2^62 in magnitude (every caller's divisor, and most
    // numerators): the steps of `round_div_wide` in `i64`, whose division
    // is one instruction where `i128`'s is a library call. No negation,
    // product or sum below can overflow; `tests::round_div_narrow_equals_wide`
    // holds the two equal.
    const WORD: i128 = 1 << 62;
    if (-WORD..WORD).contains(&num) && (-WORD..WORD).contains(&den) && den != 0 {
        // In range: checked just above.
        #[allow(clippy::cast_possible_truncation)]
        let (n, d) = (num as i64, den as i64);
        let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
        let (q, r) = (n / d, n % d);
        let q = if r.unsigned_abs() * 2 >= d.unsigned_abs() { q + n.signum() } else { q };
        return i128::from(q);
    }
    round_div_wide(num, den)
}

/// [`round_div`] in `i128`, for every argument.
fn round_div_wide(num: i128, den: i128) -> i128 {
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
/// Contract: [`saturate_i64_ensures`](super::contracts::saturate_i64_ensures).
#[must_use]
#[cfg_attr(kani, kani::ensures(|r: &i64| crate::engine::contracts::saturate_i64_ensures(v, *r)))]
pub fn saturate_i64(v: i128) -> i64 {
    let r = i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX });
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::saturate_i64_ensures(v, r), "saturate_i64: ensures");
    r
}

/// `⌊a / b⌋` for `b > 0`. Contract:
/// [`div_requires`](super::contracts::div_requires),
/// [`floor_div_ensures`](super::contracts::floor_div_ensures).
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::div_requires(a, b)))]
#[cfg_attr(kani, kani::ensures(|q: &i128| crate::engine::contracts::floor_div_ensures(a, b, *q)))]
pub fn floor_div(a: i128, b: i128) -> i128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::div_requires(a, b), "floor_div: requires");
    let q = floor_div_unchecked(a, b);
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::floor_div_ensures(a, b, q), "floor_div: ensures");
    q
}

/// [`floor_div`] without the contract checks (`b > 0`).
fn floor_div_unchecked(a: i128, b: i128) -> i128 {
    let q = a / b;
    if a % b != 0 && a < 0 {
        q - 1
    } else {
        q
    }
}

/// `⌈a / b⌉` for `b > 0`. Contract:
/// [`div_requires`](super::contracts::div_requires),
/// [`ceil_div_ensures`](super::contracts::ceil_div_ensures).
#[must_use]
#[cfg_attr(kani, kani::requires(crate::engine::contracts::div_requires(a, b)))]
#[cfg_attr(kani, kani::ensures(|q: &i128| crate::engine::contracts::ceil_div_ensures(a, b, *q)))]
pub fn ceil_div(a: i128, b: i128) -> i128 {
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::div_requires(a, b), "ceil_div: requires");
    // |a| < 2^120: the negations cannot overflow.
    let q = -floor_div_unchecked(-a, b);
    #[cfg(feature = "contract-checks")]
    assert!(super::contracts::ceil_div_ensures(a, b, q), "ceil_div: ensures");
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `i64` steps of `round_div_unchecked` equal the `i128` ones on
    /// both sides of its range, at ties and next to them, for every sign.
    #[test]
    fn round_div_narrow_equals_wide() {
        let w: i128 = 1 << 62;
        let base = [0_i128, 1, 2, 3, 5, 7, 10, 999, 1_000, 1_001, w - 2, w - 1, w, w + 1, 1 << 34];
        let values = base.iter().flat_map(|&v| [v, -v]);
        let dens = [
            1_i128,
            2,
            3,
            4,
            7,
            10,
            1_000,
            2_001,
            (1 << 34) - 1,
            w - 1,
            w,
            -1,
            -2,
            -3,
            -7,
            -1_000,
            -(w - 1),
            -w,
            0,
        ];
        for &d in &dens {
            for n in values.clone() {
                for e in -3..=3 {
                    let n = n + e * d.abs().min(1 << 20);
                    assert_eq!(round_div_unchecked(n, d), round_div_wide(n, d), "{n} / {d}");
                }
            }
            // Ties: k·d ± d/2 for even d.
            for k in [-5_i128, -1, 0, 1, 5, 1 << 20] {
                let n = k * d + d / 2;
                assert_eq!(round_div_unchecked(n, d), round_div_wide(n, d), "{n} / {d}");
                assert_eq!(round_div_unchecked(-n, d), round_div_wide(-n, d), "{} / {d}", -n);
            }
        }
    }
}
