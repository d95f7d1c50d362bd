//! Logarithm, exponential and powers (LinuxCNC's depth law `n^(1/R)`).

use core::cmp::Ordering;

use super::fixed::{Fixed, RoundDirection};
use super::interval::Interval;
use super::trig::MAX_TERMS;
use super::SCRATCH;

/// Most halvings of the exponential's argument: an argument below `2^127`
/// (every valid interval) falls below 1/2 after at most 128.
pub(super) const MAX_HALVINGS: u32 = 130;

/// Most steps of the integer root search of [`power`] (a binary search
/// over `[1, 2^32]`, 33 steps) and of its gcd (Euclid's on `u32`, at most
/// 47 steps).
pub(super) const MAX_ROOT_STEPS: u32 = 64;

impl<const N: usize> Fixed<N> {
    /// The number at the precision `M`: exact when `M ≥ N` (zero fraction
    /// limbs appended below), rounded by `dir` otherwise (the integer part
    /// is the same two limbs at every precision, so it never overflows).
    pub(super) fn at_precision<const M: usize>(&self, dir: RoundDirection) -> Option<Fixed<M>> {
        let (neg, mut m) = self.magnitude();
        let (from, to) = (Self::FRAC, Fixed::<M>::FRAC);
        if to >= from {
            let mut s = [0_u64; SCRATCH];
            let mut loops = crate::loop_counters::count!(REAL_LIMBS);
            for (d, x) in s.iter_mut().skip(to - from).zip(m.iter()) {
                loops.tick();
                *d = *x;
            }
            Fixed::<M>::from_magnitude(neg, &s)
        } else {
            Fixed::<M>::round_shifted(neg, &mut m, from - to, false, dir)
        }
    }
}

impl<const N: usize> Interval<N> {
    /// The same enclosure at the precision `M`: exact when `M ≥ N`, rounded
    /// outwards when `M < N` (a wider enclosure of the same value); a
    /// poisoned interval stays poisoned.
    ///
    /// ```
    /// use cycleref::engine::real::{Interval, FAST, SLOW};
    /// let third = Interval::<SLOW>::int(1).div_int(3);
    /// let fast: Interval<FAST> = third.at_precision();
    /// assert!(fast.lower().cmp_signed(fast.upper()).is_lt());
    /// assert_eq!(Interval::<FAST>::int(7).at_precision::<SLOW>(), Interval::int(7));
    /// ```
    #[must_use]
    pub fn at_precision<const M: usize>(&self) -> Interval<M> {
        Interval::of(
            self.lo.at_precision(RoundDirection::Down),
            self.hi.at_precision(RoundDirection::Up),
            self.ok,
        )
    }
}

/// `2·atanh(num/den)` enclosed at the precision `N`, for `0 ≤ num/den ≤
/// 1/3`, `num < 2^63`: `2 Σ z^(2k+1)/(2k+1)`, every term positive and
/// enclosed outwards. The series stops at the first power `z^(2k+1)` whose
/// upper end is at most 4 units of the last place; the rest of the series
/// from there on, `Σ_{j≥k} z^(2j+1)/(2j+1) ≤ z^(2k+1)/(1 − z²) ≤ (9/8)
/// z^(2k+1)`, is added to the upper end only as twice that bound. Each
/// step divides the power by at least 9, so at most `P/3` steps are needed
/// (256 at the largest precision, [`MAX_TERMS`] is the bound); poisoned
/// outside the domain or when the bound is reached.
///
/// Twin: `spec/src/real.rs`, `atanh2_scaled`.
pub(super) fn atanh2<const N: usize>(num: u64, den: u64) -> Interval<N> {
    let Ok(num_i) = i64::try_from(num) else {
        return Interval::poison();
    };
    if den == 0 || num.saturating_mul(3) > den {
        return Interval::poison();
    }
    let z = Interval::<N>::int(i128::from(num)).div_int(den);
    let (mut power, mut sum) = (z, z);
    let small = Fixed::<N>::from_ulps(4);
    let mut k: u64 = 1;
    let mut loops = crate::loop_counters::count!(REAL_LN);
    while k <= MAX_TERMS {
        loops.tick();
        // z^(2k+1) = z^(2k−1) · num² / den², each factor exact then rounded
        // outwards (num < 2^63 and the power ≤ 1: no overflow).
        power = power.mul_int(num_i).div_int(den).mul_int(num_i).div_int(den);
        if !power.ok {
            return Interval::poison();
        }
        if power.hi.cmp_signed(&small) != Ordering::Greater {
            let Some(bound) = power.hi.mul_int(2) else {
                return Interval::poison();
            };
            return sum.add(&Interval::new(Fixed::zero(), bound)).mul_int(2);
        }
        sum = sum.add(&power.div_int(2 * k + 1));
        k += 1;
    }
    Interval::poison()
}

/// `ln n` enclosed at the precision `N`, for an integer `1 ≤ n < 2^63`:
/// `e · ln 2 + ln(n / 2^e)` with `2^e ≤ n < 2^(e+1)`, each logarithm as
/// `2 atanh((y − 1)/(y + 1))`: `ln 2 = 2 atanh(1/3)` and `ln(n/2^e) = 2
/// atanh((n − 2^e)/(n + 2^e))`, `(n − 2^e)/(n + 2^e) < 1/3`. Exact (0) for
/// `n = 1`; poisoned for `n = 0` and `n ≥ 2^63`.
///
/// Twin: `spec/src/real.rs`, `ln_scaled`.
///
/// ```
/// use cycleref::engine::real::{ln, Rounding, FAST};
/// // ln 1000 = 6.907755…
/// let l = ln::<FAST>(1000).mul_int(1_000_000);
/// assert_eq!(l.round(Rounding::Floor), Some(6_907_755));
/// assert!(ln::<FAST>(1).is_point());
/// ```
#[must_use]
pub fn ln<const N: usize>(n: u64) -> Interval<N> {
    if n == 0 || n >= 1 << 63 {
        return Interval::poison();
    }
    let e = 63 - n.leading_zeros();
    let p = 1_u64 << e;
    // n < 2^63 and p ≤ n: n + p < 2^64.
    let y = atanh2::<N>(n - p, n + p);
    if e == 0 {
        return y;
    }
    atanh2::<N>(1, 3).mul_int(i64::from(e)).add(&y)
}

/// `exp(x)` enclosed at the precision `N`, for an interval `x` of
/// non-negative numbers: the argument is halved `h` times to below 1/2
/// (outwards), the Taylor series `Σ x^k/k!` summed over the interval (every
/// term is increasing in `x`, so the interval product keeps the lower end
/// at the lower argument and the upper end at the upper one) until a term's
/// upper end is at most 4 units of the last place, the rest (at most twice
/// that term, as `x/(k+1) < 1/2`) added to the upper end, and the sum
/// squared `h` times. Poisoned for a poisoned or partly negative argument,
/// and when the result reaches `2^127` (an overflow in a squaring). The
/// loops are bounded by `MAX_HALVINGS` (130), `MAX_TERMS` (400) and `h`.
///
/// Twin: `spec/src/real.rs`, `exp_scaled`.
///
/// ```
/// use cycleref::engine::real::{exp, Interval, Rounding, FAST};
/// // e = 2.718281828…, e^10 = 22026.46579…
/// let e = exp(&Interval::<FAST>::int(1)).mul_int(1_000_000_000);
/// assert_eq!(e.round(Rounding::Floor), Some(2_718_281_828));
/// assert_eq!(exp(&Interval::<FAST>::int(10)).round(Rounding::Floor), Some(22_026));
/// assert_eq!(exp(&Interval::<FAST>::int(0)), Interval::int(1));
/// ```
#[must_use]
pub fn exp<const N: usize>(x: &Interval<N>) -> Interval<N> {
    if !x.ok || x.lo.is_negative() {
        return Interval::poison();
    }
    let half = Fixed::<N>::half();
    let mut x = *x;
    let mut h = 0_u32;
    {
        let mut loops = crate::loop_counters::count!(REAL_EXP);
        while x.hi.cmp_signed(&half) != Ordering::Less {
            loops.tick();
            if h >= MAX_HALVINGS {
                return Interval::poison();
            }
            x = x.div_int(2);
            h += 1;
        }
    }
    let small = Fixed::<N>::from_ulps(4);
    let mut term = Interval::<N>::int(1);
    let mut sum = term;
    let mut k: u64 = 1;
    {
        let mut loops = crate::loop_counters::count!(REAL_EXP);
        loop {
            loops.tick();
            if k > MAX_TERMS {
                return Interval::poison();
            }
            term = term.mul(&x).div_int(k);
            if !term.ok {
                return Interval::poison();
            }
            if term.hi.cmp_signed(&small) != Ordering::Greater {
                let Some(bound) = term.hi.mul_int(2) else {
                    return Interval::poison();
                };
                sum = sum.add(&Interval::new(Fixed::zero(), bound));
                break;
            }
            sum = sum.add(&term);
            k += 1;
        }
    }
    let mut loops = crate::loop_counters::count!(REAL_EXP);
    for _ in 0..h {
        loops.tick();
        sum = sum.mul(&sum);
    }
    sum
}

/// The integer `r` with `r^b = n`, if there is one (`b ≥ 2`): a binary
/// search for the largest `r ≤ 2^32` with `r^b ≤ n` (`r² ≤ n < 2^64`), in
/// checked arithmetic, at most 33 steps.
pub(super) fn integer_root(n: u64, b: u32) -> Option<u64> {
    let pow_le = |r: u64| r.checked_pow(b).is_some_and(|v| v <= n);
    let (mut lo, mut hi) = (1_u64, 1_u64 << 32);
    let mut steps = 0;
    let mut loops = crate::loop_counters::count!(REAL_ROOT);
    while lo < hi && steps < MAX_ROOT_STEPS {
        loops.tick();
        steps += 1;
        // lo < hi ≤ 2^32: no overflow; mid > lo.
        let mid = lo + (hi - lo).div_ceil(2);
        if pow_le(mid) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    (lo.checked_pow(b) == Some(n)).then_some(lo)
}

/// Greatest common divisor of two `u32`, `gcd(0, 0) = 1` (Euclid's
/// algorithm: at most 47 steps for `u32`, Lamé).
pub(super) fn gcd_u32(mut a: u32, mut b: u32) -> u32 {
    let mut loops = crate::loop_counters::count!(REAL_ROOT);
    let mut steps = 0;
    while b != 0 && steps < MAX_ROOT_STEPS {
        loops.tick();
        steps += 1;
        let r = a % b;
        a = b;
        b = r;
    }
    a.max(1)
}

/// `n^(a/b)` enclosed at the precision `N`, for `1 ≤ n < 2^63` and `0 < a
/// ≤ b` (LinuxCNC's depth law: `n^(1/R) = n^(10000/R')`, `R'` = R in
/// ten-thousandths). After reducing `a/b`, an exact point interval when the
/// power is an integer: `n = 1`, `a = b`, or `n = r^b` for an integer `r`
/// (then `n^(a/b) = r^a`; with `a/b` in lowest terms, `m^b = n^a` has an
/// integer solution `m` exactly when `n` is a perfect `b`-th power, so this
/// is the reference's test `m^b = n^a` in integers that cannot overflow).
/// Otherwise `exp(ln(n) · a / b)`, by [`ln`] and [`exp`], whose width at
/// `P` fraction bits is a few hundred units of `2^-P` times `n^(a/b)`
/// (callers wanting `P` good bits compute at one more limb and narrow with
/// [`Interval::at_precision`]). Poisoned outside the domain.
///
/// Twin: `spec/src/real.rs`, `Real::power` (and `power_interval`).
///
/// ```
/// use cycleref::engine::real::{power, Interval, Rounding, FAST};
/// assert_eq!(power::<FAST>(8, 2, 3), Interval::int(4));  // exact: 8^(2/3)
/// assert_eq!(power::<FAST>(9, 1, 2), Interval::int(3));  // exact: √9
/// // 2^(2/3) = ∛4 = 1.587401051968…
/// let v = power::<FAST>(2, 2, 3).mul_int(1_000_000_000_000);
/// assert_eq!(v.round(Rounding::Floor), Some(1_587_401_051_968));
/// ```
#[must_use]
pub fn power<const N: usize>(n: u64, a: u32, b: u32) -> Interval<N> {
    if n == 0 || n >= 1 << 63 || a == 0 || a > b {
        return Interval::poison();
    }
    let g = gcd_u32(a, b);
    let (a, b) = (a / g, b / g);
    if n == 1 || a == b {
        return Interval::int(i128::from(n));
    }
    if let Some(r) = integer_root(n, b) {
        // r^a ≤ r^b = n.
        if let Some(m) = r.checked_pow(a) {
            return Interval::int(i128::from(m));
        }
    }
    exp(&ln::<N>(n).mul_int(i64::from(a)).div_int(u64::from(b)))
}
