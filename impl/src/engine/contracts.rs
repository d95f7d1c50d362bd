//! The contracts of the small exact kernels, stated once as predicates.
//!
//! Each kernel of [`arith`](super::arith) and [`crate::tan::mul_tan_round`]
//! carries `#[cfg_attr(kani, kani::requires(...))]` and
//! `#[cfg_attr(kani, kani::ensures(...))]` attributes that call these
//! predicates: `cargo kani` proves each contract with a
//! `#[kani::proof_for_contract]` harness (`proofs/src/kani_proofs.rs`) and
//! replaces the kernel by its contract (`#[kani::stub_verified]`) in the
//! harnesses of the cycles. Under `cargo test` the same predicates are
//! checked by the proofs crate (exhaustively over small domains, sampled
//! over large values: `proofs/src/contracts.rs`), and, with the test-only
//! feature `contract-checks`, at every call of a kernel: the precondition
//! on entry (what `stub_verified` asserts at each call site) and the
//! postcondition on return.
//!
//! Every postcondition determines the result uniquely for the arguments
//! its precondition admits, so replacing a kernel by its contract loses no
//! precision: a harness that holds with the kernels holds with the stubs.
//! The predicates never overflow or panic (checked or widened arithmetic).

/// The arguments `isqrt_floor`, `round_sqrt` and `round_sqrt_near` are
/// proved for: `x < 2^62`. Their one caller in the engine, the depth law
/// (`engine::schedule`), takes `round(√(Δd²·n))` only in the law's phase,
/// where `Δd·√n ≤ k − d + Δd < 2^31` (Δd and k below 10^9), so `x = Δd²·n
/// < 2^62`. The kernels compute the root of every `u128` (their Newton
/// loops on `u64` and `u128`); the contract states the range the callers
/// use, which Kani proves and the stubs assume (issue 32: a contract over
/// every `u128` leaves CBMC 128-bit products and divisions it does not
/// finish). With the feature `contract-checks`, every call checks it.
pub const SQRT_LIMIT: u128 = 1 << 62;

/// `x < 2^62` ([`SQRT_LIMIT`]).
#[must_use]
pub const fn sqrt_requires(x: u128) -> bool {
    x < SQRT_LIMIT
}

/// `isqrt_floor(x) = s`: `s² ≤ x < (s + 1)²`.
#[must_use]
pub const fn isqrt_floor_ensures(x: u128, s: u128) -> bool {
    // s² ≤ x: the square must not overflow (then it exceeds x).
    let below = match s.checked_mul(s) {
        Some(sq) => sq <= x,
        None => false,
    };
    // x < (s + 1)²: an overflowing square is above every u128.
    let above = match s.checked_add(1) {
        Some(t) => match t.checked_mul(t) {
            Some(sq) => x < sq,
            None => true,
        },
        None => true,
    };
    below && above
}

/// `round_sqrt(x) = s` (and `round_sqrt_near(x, guess) = s` for every
/// guess), the integer nearest to `√x`: `(2s - 1)² ≤ 4x <
/// (2s + 1)²` (for `s ≥ 1`; `s = 0` only for `x = 0`), stated without
/// overflow as `s(s - 1) < x ≤ s(s + 1)`. Total (no precondition).
#[must_use]
pub const fn round_sqrt_ensures(x: u128, s: u128) -> bool {
    // (2s - 1)² ≤ 4x ⟺ 4(s² - s) + 1 ≤ 4x ⟺ s(s - 1) < x for integers.
    let lower = if s == 0 {
        true
    } else {
        match s.checked_mul(s - 1) {
            Some(p) => p < x,
            None => false,
        }
    };
    // 4x < (2s + 1)² ⟺ x ≤ s² + s.
    let upper = match s.checked_add(1) {
        Some(t) => match s.checked_mul(t) {
            Some(p) => x <= p,
            None => true,
        },
        None => true,
    };
    // s = 0 needs x = 0 (the lower bound is vacuous there).
    lower && upper && (s != 0 || x == 0)
}

/// The arguments `round_div` is proved for: a non-zero divisor below
/// `2^34` and a numerator below `2^67` in magnitude. Its callers divide a
/// product of two coordinate differences (each below `2^32`: coordinates
/// within ±999 999 999 increments, doubled in diameter) by a third, plus
/// half of it: `|num| < 2^64 + 2^32 < 2^67`, `|den| < 2^32 < 2^34`
/// (`engine::pass`, the taper's X at the run-out; `engine::g32`, the
/// run-out's start). With the feature `contract-checks` every call checks
/// it; the kernel computes every quotient of `i128`s but `den = 0`.
#[must_use]
pub const fn round_div_requires(num: i128, den: i128) -> bool {
    den != 0 && num.unsigned_abs() < 1 << 67 && den.unsigned_abs() < 1 << 34
}

/// `round_div(num, den) = r`, the integer nearest to `num / den`, ties
/// away from zero: `|2(num - r den)| ≤ |den|`, and on equality (a tie) the
/// remainder `num - r den` has the sign opposite to `num` (`|r den| >
/// |num|`).
#[must_use]
pub const fn round_div_ensures(num: i128, den: i128, r: i128) -> bool {
    let Some(p) = r.checked_mul(den) else {
        return false;
    };
    let Some(rem) = num.checked_sub(p) else {
        return false;
    };
    let Some(e) = rem.checked_mul(2) else {
        return false;
    };
    let (e, d) = (e.unsigned_abs(), den.unsigned_abs());
    e < d || (e == d && ((rem < 0 && num > 0) || (rem > 0 && num < 0)))
}

/// `saturate_i64(v) = r`: `r = v` when `v` fits `i64`, else the bound on
/// `v`'s side. Total.
#[must_use]
pub const fn saturate_i64_ensures(v: i128, r: i64) -> bool {
    if v < i64::MIN as i128 {
        r == i64::MIN
    } else if v > i64::MAX as i128 {
        r == i64::MAX
    } else {
        r as i128 == v
    }
}

/// The arguments `floor_div` and `ceil_div` are proved for: a positive
/// divisor below `2^34` and a dividend below `2^72` in magnitude. Their
/// callers (`engine::g75::roughing`) divide differences of groove depths
/// and positions (below `2^32`, scaled by at most `2^40` in the exact
/// roughing limits) by a peck Δi, a step Δk or a layer Δv, each at most
/// 99 999 999 increments doubled (`< 2^28`). With the feature
/// `contract-checks` every call checks it.
#[must_use]
pub const fn div_requires(a: i128, b: i128) -> bool {
    b > 0 && b < 1 << 34 && a.unsigned_abs() < 1 << 72
}

/// `floor_div(a, b) = q` for `b > 0`: `q b ≤ a < (q + 1) b`, i.e. `0 ≤ a -
/// q b < b`.
#[must_use]
pub const fn floor_div_ensures(a: i128, b: i128, q: i128) -> bool {
    match q.checked_mul(b) {
        Some(p) => match a.checked_sub(p) {
            Some(rem) => 0 <= rem && rem < b,
            None => false,
        },
        None => false,
    }
}

/// `ceil_div(a, b) = q` for `b > 0`: `(q - 1) b < a ≤ q b`, i.e. `0 ≤ q b -
/// a < b`.
#[must_use]
pub const fn ceil_div_ensures(a: i128, b: i128, q: i128) -> bool {
    match q.checked_mul(b) {
        Some(p) => match p.checked_sub(a) {
            Some(rem) => 0 <= rem && rem < b,
            None => false,
        },
        None => false,
    }
}

/// `mul_tan_round(value, h) = r`: `None` exactly when `|value|` exceeds
/// [`MAX_LENGTH`](crate::units::MAX_LENGTH) or `h > 179`; otherwise
/// `Some(r)`, `r` with the sign of `value` and `|r|` the integer nearest to
/// `|value| × T / 2^90` (`T` = [`tan_q90`](crate::tan::tan_q90)`(h)`), ties
/// up: `(2|r| - 1) 2^89 ≤ |value| T < (2|r| + 1) 2^89`. Total.
#[must_use]
pub const fn mul_tan_round_ensures(value: i64, half_degrees: u32, r: Option<i64>) -> bool {
    let magnitude = value.unsigned_abs();
    let t = match crate::tan::tan_q90(half_degrees) {
        Some(t) if magnitude <= crate::units::MAX_LENGTH.unsigned_abs() => t,
        _ => return r.is_none(),
    };
    let Some(r) = r else {
        return false;
    };
    // The sign of value (zero for zero), f(-v) = -f(v).
    if (value < 0 && r > 0) || (value > 0 && r < 0) {
        return false;
    }
    let Some(product) = (magnitude as u128).checked_mul(t) else {
        return false;
    };
    let half = 1_u128 << (crate::tan::TAN_FRAC_BITS - 1);
    let m = r.unsigned_abs() as u128;
    // (2m - 1) 2^89 ≤ product (vacuous for m = 0) and product < (2m + 1) 2^89.
    let lower = m == 0
        || match (2 * m - 1).checked_mul(half) {
            Some(b) => b <= product,
            None => false,
        };
    let upper = match (2 * m + 1).checked_mul(half) {
        Some(b) => product < b,
        None => true,
    };
    lower && upper
}
