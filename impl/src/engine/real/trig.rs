//! Trigonometry: π and the sine, cosine, tangent and cotangent of angles
//! `k · 0.00005°` by their Taylor series, enclosed.

use core::cmp::Ordering;

use super::fixed::Fixed;
use super::interval::Interval;
use super::{HALF_TURN, PI_FRACTION, RIGHT};

/// π enclosed at the precision `N`: `[trunc(π·2^P), trunc(π·2^P) + 1]·2^-P`
/// (exactly the truncation of the digits of [`PI_FRACTION`], which the
/// constant holds to 640 bits); poisoned beyond 640 fraction bits.
#[must_use]
pub fn pi<const N: usize>() -> Interval<N> {
    let frac = Fixed::<N>::FRAC;
    if frac > PI_FRACTION.len() {
        return Interval::poison();
    }
    let mut lo = Fixed::<N>::from_int(3);
    // Fraction limb i (most significant first) goes to limb FRAC − 1 − i.
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, w) in PI_FRACTION.iter().take(frac).enumerate() {
        loops.tick();
        if let Some(s) = lo.l.get_mut(frac - 1 - i) {
            *s = *w;
        }
    }
    Interval::of(Some(lo), lo.checked_add(&Fixed::from_ulps(1)), true)
}

/// The bound on the number of terms of a series (far more than needed: at
/// 832 fraction bits, the largest precision [`MAX_LIMBS`] allows, the terms
/// of `x < 1.6` fall below one unit after about 140 steps).
pub(super) const MAX_TERMS: u64 = 400;

/// `x = k · π / 3 600 000` and `x²`, the argument of [`series`].
pub(super) fn series_argument<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
    let x = pi::<N>().mul_int(i64::from(k)).div_int(u64::from(HALF_TURN));
    let x2 = x.mul(&x);
    (x, x2)
}

/// `sin x` (`first = x`, `first_index = 1`) or `cos x` (`first = 1`,
/// `first_index = 0`) by its Taylor series, for `x = k · π / 3 600 000`
/// with `k ≤ 1 800 000` (no exact cases: see [`sin_cos`]). Then `0 ≤ x ≤
/// π/2 < 2`: the terms `x^j/j!` decrease from `j = 1` on and the series
/// alternate, so the remainder after the last term summed is at most the
/// next term.
pub(super) fn series<const N: usize>(x2: &Interval<N>, first: Interval<N>, first_index: u64) -> Interval<N> {
    // A term whose upper bound is at most 4 units of the last place ends
    // the series: its bound is then added to both ends as the remainder.
    let small = Fixed::<N>::from_ulps(4);
    let mut sum = first;
    let mut term = first;
    let mut j: u64 = 1;
    let mut loops = crate::loop_counters::count!(REAL_SERIES);
    while j <= MAX_TERMS {
        loops.tick();
        // t_j = t_(j−1) · x² / ((f + 2j − 1)(f + 2j)), f = 1 for sin
        // (x^(2j+1)/(2j+1)!), 0 for cos (x^(2j)/(2j)!).
        let a = first_index + 2 * j - 1;
        term = term.mul(x2).div_int(a * (a + 1));
        if !term.ok {
            return Interval::poison();
        }
        if term.hi.cmp_signed(&small) != Ordering::Greater {
            let bound = Interval::new(term.hi.checked_neg().unwrap_or(term.hi), term.hi);
            return sum.add(&bound);
        }
        sum = if j % 2 == 1 { sum.sub(&term) } else { sum.add(&term) };
        j += 1;
    }
    Interval::poison()
}

/// `sin x` by its series ([`series`]).
pub(super) fn sin_series<const N: usize>(k: u32) -> Interval<N> {
    let (x, x2) = series_argument::<N>(k);
    series(&x2, x, 1)
}

/// `cos x` by its series ([`series`]).
pub(super) fn cos_series<const N: usize>(k: u32) -> Interval<N> {
    let (_, x2) = series_argument::<N>(k);
    series(&x2, Interval::int(1), 0)
}

/// `sin x` and `cos x` by their series ([`series`]), sharing `x` and `x²`.
pub(super) fn sin_cos_series<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
    let (x, x2) = series_argument::<N>(k);
    (series(&x2, x, 1), series(&x2, Interval::int(1), 0))
}

/// `sin(k·0.00005°)`, exact for 0, 30° and 90° (`docs/G75.md` §6).
#[must_use]
pub fn sin<const N: usize>(k: u32) -> Interval<N> {
    match k {
        0 => Interval::int(0),
        600_000 => Interval::half(),
        RIGHT => Interval::int(1),
        k if k > RIGHT => Interval::poison(),
        k => sin_series(k),
    }
}

/// `cos(k·0.00005°)`, exact for 0, 60° and 90° (`docs/G75.md` §6).
#[must_use]
pub fn cos<const N: usize>(k: u32) -> Interval<N> {
    match k {
        0 => Interval::int(1),
        1_200_000 => Interval::half(),
        RIGHT => Interval::int(0),
        k if k > RIGHT => Interval::poison(),
        k => cos_series(k),
    }
}

/// The sine and cosine of `k·0.00005°` together (one series evaluation for
/// both when neither is an exact case, and for 45°, whose sine is its
/// cosine).
#[must_use]
pub fn sin_cos<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
    match k {
        0 | 600_000 | 1_200_000 | RIGHT => (sin(k), cos(k)),
        900_000 => {
            // sin 45° = cos 45° = √2/2: one enclosure serves both.
            let s = sin_series(k);
            (s, s)
        }
        k if k > RIGHT => (Interval::poison(), Interval::poison()),
        k => sin_cos_series(k),
    }
}

/// `tan(k·0.00005°)` from that angle's sine and cosine: exact for 0 and
/// 45°, `s/c` otherwise; poisoned for 90° and beyond.
#[must_use]
pub fn tan_of<const N: usize>(k: u32, s: &Interval<N>, c: &Interval<N>) -> Interval<N> {
    match k {
        0 => Interval::int(0),
        900_000 => Interval::int(1),
        k if k >= RIGHT => Interval::poison(),
        _ => s.div(c),
    }
}

/// `cot(k·0.00005°)` from that angle's sine and cosine: exact for 45° and
/// 90°, `c/s` otherwise; poisoned for 0 and beyond 90°.
#[must_use]
pub fn cot_of<const N: usize>(k: u32, s: &Interval<N>, c: &Interval<N>) -> Interval<N> {
    match k {
        900_000 => Interval::int(1),
        RIGHT => Interval::int(0),
        k if k == 0 || k > RIGHT => Interval::poison(),
        _ => c.div(s),
    }
}

/// `tan(k·0.00005°)`, exact for 0 and 45° (`docs/G75.md` §6).
#[must_use]
pub fn tan<const N: usize>(k: u32) -> Interval<N> {
    match k {
        0 | 900_000 => tan_of(k, &Interval::poison(), &Interval::poison()),
        k => {
            let (s, c) = sin_cos::<N>(k);
            tan_of(k, &s, &c)
        }
    }
}

/// `cot(k·0.00005°)`, exact for 45° and 90° (`docs/G75.md` §6).
#[must_use]
pub fn cot<const N: usize>(k: u32) -> Interval<N> {
    match k {
        900_000 | RIGHT => cot_of(k, &Interval::poison(), &Interval::poison()),
        k => {
            let (s, c) = sin_cos::<N>(k);
            cot_of(k, &s, &c)
        }
    }
}

/// `tan` and `cot` of one angle together (one series evaluation), with the
/// exact cases of [`tan`] and [`cot`].
#[must_use]
pub fn tan_cot<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
    let (s, c) = sin_cos::<N>(k);
    (tan_of(k, &s, &c), cot_of(k, &s, &c))
}
