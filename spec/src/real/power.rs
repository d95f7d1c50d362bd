//! Powers: the enclosure of `n^(a/b)` as `exp(ln(n) · a / b)`, the
//! logarithm by `atanh` series and the exponential by its Taylor series
//! (the values of LinuxCNC's depth law, [`Real::power`](super::Real::power)).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

use super::interval::Interval;
use super::rational::{div_ceil, pow2};

/// Guard bits of the logarithm and exponential series beyond the requested
/// precision: the exponential's argument is halved up to 6 times and the
/// result squared back, which multiplies its relative error by at most
/// 2^6, and the logarithm's error is multiplied by the exponent (below
/// 2^5 for the values the models use).
const POWER_GUARD_BITS: u32 = 64;

/// `2 · atanh(num / den)` scaled by `2^q`, enclosed (`0 ≤ num/den ≤ 1/3`):
/// `2 Σ z^(2k+1) / (2k+1)`, every term positive; the lower end sums
/// floored terms, the upper end ceiled ones plus a bound of the remainder
/// (after a term `t`, the rest is at most `t·z²/(1 − z²) ≤ t/8`).
///
/// Twin: `impl/src/engine/real/power.rs`, `atanh2`.
fn atanh2_scaled(num: &BigInt, den: &BigInt, q: u32) -> (BigInt, BigInt) {
    let one = pow2(q);
    let (n2, d2) = (num * num, den * den);
    let mut t_lo = (&one * num).div_floor(den);
    let mut t_hi = div_ceil(&(&one * num), den);
    let (mut s_lo, mut s_hi) = (t_lo.clone(), t_hi.clone());
    let mut k = 1_u32;
    while t_hi > BigInt::one() {
        t_lo = (&t_lo * &n2).div_floor(&d2);
        t_hi = div_ceil(&(&t_hi * &n2), &d2);
        let odd = BigInt::from(2 * k + 1);
        s_lo += t_lo.div_floor(&odd);
        s_hi += div_ceil(&t_hi, &odd);
        k += 1;
    }
    // The remainder after the last term is at most t_hi/8 ≤ 1/8 unit.
    s_hi += BigInt::one();
    (s_lo * 2, s_hi * 2)
}

/// `ln m` scaled by `2^q`, enclosed, for an integer `m ≥ 1`:
/// `e · ln 2 + ln(m / 2^e)` with `m / 2^e` in `[1, 2)`, each logarithm as
/// `2 atanh((y − 1)/(y + 1))` (`ln 2 = 2 atanh(1/3)`).
///
/// Twin: `impl/src/engine/real/power.rs`, `ln`.
fn ln_scaled(m: u64, q: u32) -> (BigInt, BigInt) {
    let e = 63 - m.leading_zeros();
    let p = BigInt::one() << e;
    let m = BigInt::from(m);
    let (y_lo, y_hi) = atanh2_scaled(&(&m - &p), &(&m + &p), q);
    let (l2_lo, l2_hi) = atanh2_scaled(&BigInt::one(), &BigInt::from(3), q);
    (y_lo + l2_lo * e, y_hi + l2_hi * e)
}

/// `exp(y)` scaled by `2^q`, enclosed, for `y` enclosed by `[lo, hi]`
/// (scaled by `2^q`, `0 ≤ lo ≤ hi < 2^(q+6)`): the argument is halved `h`
/// times to below 1/2, the Taylor series summed (floored terms for the
/// lower end; ceiled ones plus the remainder bound, at most the last term
/// when the argument is below 1/2, for the upper end), and the result
/// squared `h` times.
///
/// Twin: `impl/src/engine/real/power.rs`, `exp`.
fn exp_scaled(lo: &BigInt, hi: &BigInt, q: u32) -> (BigInt, BigInt) {
    let one = pow2(q);
    let half = pow2(q - 1);
    let mut h = 0_u32;
    while (hi >> h) >= half {
        h += 1;
    }
    let (x_lo, x_hi) = (lo >> h, div_ceil(hi, &pow2(h)));
    let series = |x: &BigInt, up: bool| -> BigInt {
        let mut t = one.clone();
        let mut sum = one.clone();
        let mut k = 1_u32;
        loop {
            let den = &one * k;
            t = if up { div_ceil(&(&t * x), &den) } else { (&t * x).div_floor(&den) };
            if t.is_zero() {
                return sum;
            }
            sum += &t;
            if up && t <= BigInt::one() {
                return sum + BigInt::one();
            }
            k += 1;
        }
    };
    let (mut r_lo, mut r_hi) = (series(&x_lo, false), series(&x_hi, true));
    for _ in 0..h {
        r_lo = (&r_lo * &r_lo).div_floor(&one);
        r_hi = div_ceil(&(&r_hi * &r_hi), &one);
    }
    (r_lo, r_hi)
}

/// The enclosure of `n^(a/b)` at `bits` fraction bits (`n ≥ 1`, `0 < a ≤
/// b`): `exp(ln(n) · a / b)`, computed with [`POWER_GUARD_BITS`] more and
/// rounded outwards.
pub(super) fn power_interval(n: u64, a: u32, b: u32, bits: u32) -> Interval {
    let q = bits + POWER_GUARD_BITS;
    let (l_lo, l_hi) = ln_scaled(n, q);
    let (a, b) = (BigInt::from(a), BigInt::from(b));
    let (y_lo, y_hi) = ((l_lo * &a).div_floor(&b), div_ceil(&(l_hi * &a), &b));
    let (lo, hi) = exp_scaled(&y_lo.max(BigInt::zero()), &y_hi, q);
    Interval::outwards(&lo, &hi, q, bits)
}
