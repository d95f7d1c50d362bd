//! Exact real arithmetic for the G75.1 reference model (`docs/G75.md` §6).
//!
//! The G75.1 profile is made of lengths times sines, cosines, tangents and
//! cotangents of the programmed angles. Those are irrational but for a
//! handful of angles, so a coordinate cannot be held exactly as a decimal.
//! This module holds it exactly in another way: a [`Real`] is either
//!
//! * an exact rational ([`Rational`], big integers), the value of every
//!   formula built only from the words and the trigonometric values that
//!   are rational (`docs/G75.md` §6: "the exact rational cases (sin 0, 30°,
//!   90°; cos 0, 60°, 90°; tan 0, 45°; cot 45°, 90°) are used exactly, so
//!   right-angle grooves are computed in exact rational arithmetic"), or
//! * an expression over such rationals and the trigonometric values of
//!   angles `k · 0.00005°`, which can be enclosed in an [`Interval`] as
//!   narrow as asked ("Irrational values are enclosed in intervals whose
//!   width shrinks until the rounding is decided").
//!
//! A real number is only ever *used* through a decision: its rounding to an
//! integer ([`Real::floor`], [`Real::ceil`], [`Real::nearest`]) or its sign
//! ([`Real::sign`], [`Real::compare`]). An exact rational is decided
//! exactly. Any other value is enclosed at 64 fraction bits, and the
//! precision doubles (128, 256, 512) until both ends of the interval give
//! the same answer. Every enclosure is rigorous: the true value always lies
//! in it, so a decision made this way is the decision of the exact value.
//!
//! # Values on a rounding boundary (R-G75TIE)
//!
//! Exact identities among the trigonometric values make some values
//! exactly a rounding boundary although they are computed from irrational
//! terms (`tan 30°·sin 60° = 1/2`, `tan(a/2)·sin a = 1 − cos a`, …); no
//! enclosure can decide them. `docs/G75.md` §6, R-G75TIE: "a value whose
//! enclosure at 512 fraction bits still contains exactly one rounding
//! boundary (an integer for floor and ceil, a half-integer for nearest,
//! zero for a sign) is taken to lie on it, and is then rounded by the rule
//! above (a tie goes up)". So, only after the 512-bit enclosure has failed
//! to decide (the whole ladder 64 → 128 → 256 → 512 is run first), the
//! boundaries in the closed 512-bit enclosure are counted (one strictly
//! inside or on an end counts alike):
//!
//! * exactly one integer `k`: `floor = ceil = k`;
//! * exactly one half-integer `k + 1/2`: `nearest = floor(k + 1/2 + 1/2) =
//!   k + 1`;
//! * zero in the enclosure of a sign: the sign is 0 (`Ordering::Equal`);
//! * two boundaries or more (or no enclosure at all, a divisor still
//!   enclosing 0): [`CycleError::UndecidedRounding`] ("`UndecidedRounding`
//!   remains for an enclosure that still holds two boundaries at 512
//!   bits").
//!
//! The rule is wrong only for a value within about `2⁻⁵⁰⁰` of a boundary
//! without lying on it, which `docs/G75.md` accepts; the fixed-point engine
//! applies the same rule at the same precision.
//!
//! # Trigonometry
//!
//! Angles are whole multiples `k` of 0.00005° (half the 0.0001° input unit,
//! so that half angles such as `a/2` and `(a + L)/2` are exact), with
//! `0 ≤ k ≤ 1 800 000` (0° to 90°); the angle in radians is
//! `k · π / 3 600 000`. The values are computed here, independently of the
//! engine, from first principles:
//!
//! * `π = 16 atan(1/5) − 4 atan(1/239)` (Machin's formula), each arctangent
//!   by its alternating series, every term enclosed between two integers;
//! * `sin x` and `cos x` by their Taylor series over an interval of `x`,
//!   each term's bounds taken at the ends of the interval (the terms grow
//!   with `x`), the remainder bounded by the first omitted term (the series
//!   alternate with decreasing terms for `x < 2`);
//! * `tan = sin / cos`, `cot = cos / sin` by interval division.
//!
//! All of it runs 32 guard bits beyond the requested precision and is then
//! rounded outwards.

use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::rc::Rc;

use cycleref::error::CycleError;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The first precision (fraction bits) at which a decision is tried.
pub const FIRST_PRECISION: u32 = 64;

/// The highest precision (fraction bits): a decision still open here is
/// made by the boundary rule R-G75TIE (`docs/G75.md` §6), or refused with
/// [`CycleError::UndecidedRounding`] when the enclosure holds two
/// boundaries or more.
pub const MAX_PRECISION: u32 = 512;

/// Guard bits of the trigonometric series beyond the requested precision.
pub const GUARD_BITS: u32 = 32;

/// 90° in the angle unit of this module, 0.00005°.
pub const RIGHT_ANGLE: u32 = 1_800_000;

/// 180° in the angle unit of this module, 0.00005°: the angle `k` is
/// `k · π / HALF_TURN` radians.
pub const HALF_TURN: u32 = 3_600_000;

/// `2^bits` as a big integer.
fn pow2(bits: u32) -> BigInt {
    BigInt::one() << bits
}

/// `ceil(n / d)` for `d > 0`.
fn div_ceil(n: &BigInt, d: &BigInt) -> BigInt {
    -((-n).div_floor(d))
}

/// An exact rational number `num / den`, in lowest terms with `den > 0`.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Rational {
    num: BigInt,
    den: BigInt,
}

impl Rational {
    /// `num / den` in lowest terms.
    ///
    /// # Panics
    ///
    /// When `den` is zero (a division by zero in the model is a bug of the
    /// model).
    #[must_use]
    pub fn new(num: impl Into<BigInt>, den: impl Into<BigInt>) -> Rational {
        let (num, den) = (num.into(), den.into());
        assert!(!den.is_zero(), "rational with denominator zero");
        let g = num.gcd(&den);
        let (mut num, mut den) = (num / &g, den / &g);
        if den.is_negative() {
            num = -num;
            den = -den;
        }
        Rational { num, den }
    }

    /// The integer `v`.
    #[must_use]
    pub fn integer(v: impl Into<BigInt>) -> Rational {
        Rational { num: v.into(), den: BigInt::one() }
    }

    /// 0.
    #[must_use]
    pub fn zero() -> Rational {
        Rational::integer(0)
    }

    /// 1.
    #[must_use]
    pub fn one() -> Rational {
        Rational::integer(1)
    }

    /// The numerator (its sign is the number's sign).
    #[must_use]
    pub fn numer(&self) -> &BigInt {
        &self.num
    }

    /// The denominator, positive.
    #[must_use]
    pub fn denom(&self) -> &BigInt {
        &self.den
    }

    /// True for 0.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// True for 1.
    #[must_use]
    pub fn is_one(&self) -> bool {
        self.num.is_one() && self.den.is_one()
    }

    /// The sign, as the ordering against 0.
    #[must_use]
    pub fn sign(&self) -> Ordering {
        self.num.sign().cmp(&num_bigint::Sign::NoSign)
    }

    /// `floor(self)`: the largest integer not above it.
    #[must_use]
    pub fn floor(&self) -> BigInt {
        self.num.div_floor(&self.den)
    }

    /// `ceil(self)`: the smallest integer not below it.
    #[must_use]
    pub fn ceil(&self) -> BigInt {
        div_ceil(&self.num, &self.den)
    }

    /// `floor(self + 1/2)`: the nearest integer, ties upwards
    /// (`docs/G75.md` §6 "nearest: `floor(v + 1/2)`").
    #[must_use]
    pub fn nearest(&self) -> BigInt {
        let twice: BigInt = &self.num * 2 + &self.den;
        twice.div_floor(&(&self.den * 2))
    }

    /// `self · 2^bits` rounded down and up: the tightest enclosure of the
    /// number at `bits` fraction bits.
    fn scaled(&self, bits: u32) -> (BigInt, BigInt) {
        let n = &self.num << bits;
        (n.div_floor(&self.den), div_ceil(&n, &self.den))
    }

    /// The number as a decimal with `digits` decimals, rounded down (for
    /// messages and tests).
    #[must_use]
    pub fn to_decimal(&self, digits: u32) -> String {
        let scaled = (&self.num * BigInt::from(10).pow(digits)).div_floor(&self.den);
        let sign = if scaled.is_negative() { "-" } else { "" };
        let text = scaled.abs().to_string();
        let digits = usize::try_from(digits).unwrap_or(usize::MAX);
        if digits == 0 {
            return format!("{sign}{text}");
        }
        let padded = format!("{text:0>width$}", width = digits + 1);
        let (int, frac) = padded.split_at(padded.len() - digits);
        format!("{sign}{int}.{frac}")
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den.is_one() {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Rational) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Rational) -> Ordering {
        (&self.num * &other.den).cmp(&(&other.num * &self.den))
    }
}

impl Add for &Rational {
    type Output = Rational;
    fn add(self, o: &Rational) -> Rational {
        Rational::new(&self.num * &o.den + &o.num * &self.den, &self.den * &o.den)
    }
}

impl Sub for &Rational {
    type Output = Rational;
    fn sub(self, o: &Rational) -> Rational {
        Rational::new(&self.num * &o.den - &o.num * &self.den, &self.den * &o.den)
    }
}

impl Mul for &Rational {
    type Output = Rational;
    fn mul(self, o: &Rational) -> Rational {
        Rational::new(&self.num * &o.num, &self.den * &o.den)
    }
}

impl Div for &Rational {
    type Output = Rational;
    /// # Panics
    ///
    /// On division by zero.
    fn div(self, o: &Rational) -> Rational {
        Rational::new(&self.num * &o.den, &self.den * &o.num)
    }
}

impl Neg for &Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational { num: -&self.num, den: self.den.clone() }
    }
}

/// A closed interval `[lo · 2^-bits, hi · 2^-bits]` that contains a real
/// number: the enclosure of a [`Real`] at `bits` fraction bits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Interval {
    lo: BigInt,
    hi: BigInt,
    bits: u32,
}

impl Interval {
    /// The lower end.
    #[must_use]
    pub fn lower(&self) -> Rational {
        Rational::new(self.lo.clone(), pow2(self.bits))
    }

    /// The upper end.
    #[must_use]
    pub fn upper(&self) -> Rational {
        Rational::new(self.hi.clone(), pow2(self.bits))
    }

    /// The fraction bits of the ends.
    #[must_use]
    pub fn bits(&self) -> u32 {
        self.bits
    }

    /// The width `upper − lower`.
    #[must_use]
    pub fn width(&self) -> Rational {
        Rational::new(&self.hi - &self.lo, pow2(self.bits))
    }

    fn of_rational(r: &Rational, bits: u32) -> Interval {
        let (lo, hi) = r.scaled(bits);
        Interval { lo, hi, bits }
    }

    /// Rounds the ends of an enclosure at `from` fraction bits outwards to
    /// `bits` (`bits ≤ from`).
    fn outwards(lo: &BigInt, hi: &BigInt, from: u32, bits: u32) -> Interval {
        let d = pow2(from - bits);
        Interval { lo: lo.div_floor(&d), hi: div_ceil(hi, &d), bits }
    }

    fn add(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo + &o.lo, hi: &self.hi + &o.hi, bits: self.bits }
    }

    fn sub(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo - &o.hi, hi: &self.hi - &o.lo, bits: self.bits }
    }

    fn neg(&self) -> Interval {
        Interval { lo: -&self.hi, hi: -&self.lo, bits: self.bits }
    }

    fn mul(&self, o: &Interval) -> Interval {
        let products = [&self.lo * &o.lo, &self.lo * &o.hi, &self.hi * &o.lo, &self.hi * &o.hi];
        let min = products.iter().min().cloned().unwrap_or_default();
        let max = products.iter().max().cloned().unwrap_or_default();
        Interval::outwards(&min, &max, 2 * self.bits, self.bits)
    }

    /// `None` when the divisor's enclosure contains 0.
    fn div(&self, o: &Interval) -> Option<Interval> {
        if !(o.lo.is_positive() || o.hi.is_negative()) {
            return None;
        }
        let (a_lo, a_hi) = (&self.lo << self.bits, &self.hi << self.bits);
        let quotients_lo = [&a_lo, &a_hi].map(|a| [a.div_floor(&o.lo), a.div_floor(&o.hi)]);
        let quotients_hi = [&a_lo, &a_hi].map(|a| [div_ceil(a, &o.lo), div_ceil(a, &o.hi)]);
        let lo = quotients_lo.iter().flatten().min().cloned().unwrap_or_default();
        let hi = quotients_hi.iter().flatten().max().cloned().unwrap_or_default();
        Some(Interval { lo, hi, bits: self.bits })
    }

    fn max(&self, o: &Interval) -> Interval {
        Interval { lo: (&self.lo).max(&o.lo).clone(), hi: (&self.hi).max(&o.hi).clone(), bits: self.bits }
    }

    fn min(&self, o: &Interval) -> Interval {
        Interval { lo: (&self.lo).min(&o.lo).clone(), hi: (&self.hi).min(&o.hi).clone(), bits: self.bits }
    }

    /// `floor` of every number in the interval, if it is the same for all.
    ///
    /// Twin (with `ceil`, `nearest`): `impl/src/engine/real.rs`,
    /// `Interval::round`.
    fn floor(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let (a, b) = (self.lo.div_floor(&d), self.hi.div_floor(&d));
        (a == b).then_some(a)
    }

    /// `ceil` of every number in the interval, if it is the same for all.
    fn ceil(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let (a, b) = (div_ceil(&self.lo, &d), div_ceil(&self.hi, &d));
        (a == b).then_some(a)
    }

    /// `floor(v + 1/2)` of every number `v` in the interval, if it is the
    /// same for all.
    fn nearest(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let half = pow2(self.bits) >> 1_u32;
        let (a, b) = ((&self.lo + &half).div_floor(&d), (&self.hi + &half).div_floor(&d));
        (a == b).then_some(a)
    }

    /// The sign of every number in the interval, if it is the same for all.
    ///
    /// Twin: `impl/src/engine/real.rs`, `Interval::sign`.
    fn sign(&self) -> Option<Ordering> {
        if self.lo.is_positive() {
            Some(Ordering::Greater)
        } else if self.hi.is_negative() {
            Some(Ordering::Less)
        } else if self.lo.is_zero() && self.hi.is_zero() {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The only integer in the closed interval, if there is exactly one
    /// (R-G75TIE: one boundary, strictly inside or on an end).
    fn only_integer(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let (first, last) = (div_ceil(&self.lo, &d), self.hi.div_floor(&d));
        (first == last).then_some(first)
    }

    /// R-G75TIE for `floor` and `ceil`: a value whose enclosure holds
    /// exactly one integer `k` is taken to be `k`, and `floor(k) = ceil(k)
    /// = k`; `None` for two integers or more.
    ///
    /// Twin (with `tie_nearest`): `impl/src/engine/real.rs`,
    /// `Interval::round_tie`.
    fn tie_integer(&self) -> Option<BigInt> {
        self.only_integer()
    }

    /// R-G75TIE for `nearest`: a value whose enclosure holds exactly one
    /// half-integer `k + 1/2` is taken to be `k + 1/2`, and `floor(k + 1/2
    /// + 1/2) = k + 1` (a tie goes up); `None` for two half-integers or
    /// more. `k + 1/2 ∈ [lo, hi]` exactly when `k ∈ [lo − 1/2, hi − 1/2]`.
    fn tie_nearest(&self) -> Option<BigInt> {
        let half = pow2(self.bits) >> 1_u32;
        let shifted = Interval { lo: &self.lo - &half, hi: &self.hi - &half, bits: self.bits };
        shifted.only_integer().map(|k| k + 1)
    }

    /// R-G75TIE for a sign: an enclosure that holds 0 (the only boundary
    /// of a sign) is taken to be 0; `None` when it does not hold 0 (then
    /// [`Interval::sign`] decides).
    ///
    /// Twin: `impl/src/engine/real.rs`, `Interval::sign_tie`.
    fn tie_sign(&self) -> Option<Ordering> {
        (!self.lo.is_positive() && !self.hi.is_negative()).then_some(Ordering::Equal)
    }
}

/// A trigonometric function of an angle of 0° to 90°.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TrigFn {
    /// Sine.
    Sin,
    /// Cosine.
    Cos,
    /// Tangent (not of 90°).
    Tan,
    /// Cotangent (not of 0°).
    Cot,
}

impl TrigFn {
    /// The exact rational value of the function at `k · 0.00005°`, when it
    /// is one of `docs/G75.md` §6's exact cases: sin 0, 30°, 90°; cos 0,
    /// 60°, 90°; tan 0, 45°; cot 45°, 90°. (By Niven's theorem these are
    /// the only rational values at rational angles of 0° to 90°.)
    #[must_use]
    pub fn exact(self, k: u32) -> Option<Rational> {
        const DEG30: u32 = RIGHT_ANGLE / 3;
        const DEG45: u32 = RIGHT_ANGLE / 2;
        const DEG60: u32 = 2 * RIGHT_ANGLE / 3;
        match (self, k) {
            (TrigFn::Sin, 0) | (TrigFn::Cos, RIGHT_ANGLE) | (TrigFn::Tan, 0) | (TrigFn::Cot, RIGHT_ANGLE) => {
                Some(Rational::zero())
            }
            (TrigFn::Sin, DEG30) | (TrigFn::Cos, DEG60) => Some(Rational::new(1, 2)),
            (TrigFn::Sin, RIGHT_ANGLE) | (TrigFn::Cos, 0) | (TrigFn::Tan, DEG45) | (TrigFn::Cot, DEG45) => {
                Some(Rational::one())
            }
            _ => None,
        }
    }

    fn name(self) -> &'static str {
        match self {
            TrigFn::Sin => "sin",
            TrigFn::Cos => "cos",
            TrigFn::Tan => "tan",
            TrigFn::Cot => "cot",
        }
    }
}

thread_local! {
    /// π enclosures already computed, by fraction bits.
    static PI: RefCell<HashMap<u32, (BigInt, BigInt)>> = RefCell::new(HashMap::new());
}

/// `atan(1/m) · 2^bits` enclosed between two integers, by the alternating
/// series `atan(1/m) = Σ (−1)^j / ((2j + 1) m^(2j+1))`.
///
/// Each term `2^bits / ((2j + 1) m^(2j+1))` lies between its floor `t` and
/// `t + 1`; the series stops at the first term whose floor is 0, and the
/// remainder (that term and all after it) is bounded by that term, below
/// one unit (an alternating series of decreasing terms).
fn atan_inverse(m: u32, bits: u32) -> (BigInt, BigInt) {
    let one = pow2(bits);
    let m2 = BigInt::from(m) * m;
    let mut power = BigInt::from(m);
    let (mut lo, mut hi) = (BigInt::zero(), BigInt::zero());
    let mut j = 0_u32;
    loop {
        let t = one.div_floor(&(&power * (2 * j + 1)));
        if t.is_zero() {
            lo -= 1;
            hi += 1;
            return (lo, hi);
        }
        if j % 2 == 0 {
            lo += &t;
            hi += t + 1;
        } else {
            lo -= &t + 1;
            hi -= t;
        }
        power *= &m2;
        j += 1;
    }
}

/// `π · 2^bits` enclosed between two integers, by Machin's formula
/// `π = 16 atan(1/5) − 4 atan(1/239)`.
#[must_use]
pub fn pi_scaled(bits: u32) -> (BigInt, BigInt) {
    if let Some(v) = PI.with(|p| p.borrow().get(&bits).cloned()) {
        return v;
    }
    let (lo5, hi5) = atan_inverse(5, bits);
    let (lo239, hi239) = atan_inverse(239, bits);
    let v = (16 * lo5 - 4 * hi239, 16 * hi5 - 4 * lo239);
    PI.with(|p| p.borrow_mut().insert(bits, v.clone()));
    v
}

/// Enclosures of `sin x` and `cos x` (`x = k · π / 3 600 000`, `0 < k <
/// 1 800 000`) at `bits` fraction bits, each as `(lo, hi)` scaled by
/// `2^bits`, computed with [`GUARD_BITS`] more.
fn sin_cos(k: u32, bits: u32) -> ((BigInt, BigInt), (BigInt, BigInt)) {
    let q = bits + GUARD_BITS;
    let (pi_lo, pi_hi) = pi_scaled(q);
    let x_lo = (pi_lo * k).div_floor(&BigInt::from(HALF_TURN));
    let x_hi = div_ceil(&(pi_hi * k), &BigInt::from(HALF_TURN));
    let x2_lo = &x_lo * &x_lo;
    let x2_hi = &x_hi * &x_hi;
    let unit2 = pow2(2 * q);
    // Term j of a series: t_j = t_(j−1) · x² / (c1 · c2), enclosed from
    // below with x_lo and from above with x_hi (every term grows with x).
    // The partial sums alternate; the remainder after the last term taken
    // is at most the next term (x < 2: the terms decrease).
    let series = |t_lo: BigInt, t_hi: BigInt, first: u32| -> (BigInt, BigInt) {
        let (mut t_lo, mut t_hi) = (t_lo, t_hi);
        let (mut s_lo, mut s_hi) = (t_lo.clone(), t_hi.clone());
        let mut j = 1_u32;
        loop {
            let c = BigInt::from(first + 2 * j - 1) * (first + 2 * j);
            let den = &unit2 * &c;
            t_lo = (&t_lo * &x2_lo).div_floor(&den);
            t_hi = div_ceil(&(&t_hi * &x2_hi), &den);
            if t_hi <= BigInt::one() {
                s_lo -= &t_hi;
                s_hi += &t_hi;
                return (s_lo, s_hi);
            }
            if j % 2 == 1 {
                s_lo -= &t_hi;
                s_hi -= &t_lo;
            } else {
                s_lo += &t_lo;
                s_hi += &t_hi;
            }
            j += 1;
        }
    };
    // sin x = x − x³/3! + x⁵/5! − …: t_j = t_(j−1) x² / ((2j)(2j + 1)).
    let (s_lo, s_hi) = series(x_lo.clone(), x_hi.clone(), 1);
    // cos x = 1 − x²/2! + x⁴/4! − …: t_j = t_(j−1) x² / ((2j − 1)(2j)).
    let (c_lo, c_hi) = series(pow2(q), pow2(q), 0);
    let sin = Interval::outwards(&s_lo, &s_hi, q, bits);
    let cos = Interval::outwards(&c_lo, &c_hi, q, bits);
    ((sin.lo, sin.hi), (cos.lo, cos.hi))
}

/// The enclosure of `func(k · 0.00005°)` at `bits` fraction bits; `None`
/// when a divisor's enclosure still contains 0 at this precision.
fn trig_interval(func: TrigFn, k: u32, bits: u32) -> Option<Interval> {
    if let Some(r) = func.exact(k) {
        return Some(Interval::of_rational(&r, bits));
    }
    // tan and cot are divided at the guarded precision, then rounded out.
    let q = bits + GUARD_BITS;
    let ((s_lo, s_hi), (c_lo, c_hi)) = sin_cos(k, q);
    let sin = Interval { lo: s_lo, hi: s_hi, bits: q };
    let cos = Interval { lo: c_lo, hi: c_hi, bits: q };
    let v = match func {
        TrigFn::Sin => sin,
        TrigFn::Cos => cos,
        TrigFn::Tan => sin.div(&cos)?,
        TrigFn::Cot => cos.div(&sin)?,
    };
    Some(Interval::outwards(&v.lo, &v.hi, q, bits))
}

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
/// Twin: `impl/src/engine/real.rs`, `atanh2`.
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
/// Twin: `impl/src/engine/real.rs`, `ln`.
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
/// Twin: `impl/src/engine/real.rs`, `exp`.
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
fn power_interval(n: u64, a: u32, b: u32, bits: u32) -> Interval {
    let q = bits + POWER_GUARD_BITS;
    let (l_lo, l_hi) = ln_scaled(n, q);
    let (a, b) = (BigInt::from(a), BigInt::from(b));
    let (y_lo, y_hi) = ((l_lo * &a).div_floor(&b), div_ceil(&(l_hi * &a), &b));
    let (lo, hi) = exp_scaled(&y_lo.max(BigInt::zero()), &y_hi, q);
    Interval::outwards(&lo, &hi, q, bits)
}

/// What a [`Real`] is made of.
enum Op {
    Exact(Rational),
    Trig(TrigFn, u32),
    /// `n^(a/b)`, irrational.
    Power(u64, u32, u32),
    Add(Real, Real),
    Sub(Real, Real),
    Mul(Real, Real),
    Div(Real, Real),
    Neg(Real),
    Max(Real, Real),
    Min(Real, Real),
}

struct Node {
    op: Op,
    /// Enclosures already computed, by precision.
    cache: RefCell<Vec<(u32, Option<Interval>)>>,
}

/// An exact real number: an exact [`Rational`], or an expression over
/// rationals and trigonometric values that can be enclosed as narrowly as
/// asked. Cheap to clone (shared).
///
/// Operations on two exact rationals give an exact rational; `0 · x`,
/// `x + 0`, `x − 0`, `1 · x` and `x / 1` give the exact result without an
/// expression (they are exact whatever `x` is).
#[derive(Clone)]
pub struct Real(Rc<Node>);

impl Real {
    fn node(op: Op) -> Real {
        Real(Rc::new(Node { op, cache: RefCell::new(Vec::new()) }))
    }

    /// An exact rational.
    #[must_use]
    pub fn exact(r: Rational) -> Real {
        Real::node(Op::Exact(r))
    }

    /// The integer `v`.
    #[must_use]
    pub fn int(v: impl Into<BigInt>) -> Real {
        Real::exact(Rational::integer(v))
    }

    /// The rational `num / den`.
    ///
    /// # Panics
    ///
    /// When `den` is zero.
    #[must_use]
    pub fn ratio(num: impl Into<BigInt>, den: impl Into<BigInt>) -> Real {
        Real::exact(Rational::new(num, den))
    }

    /// `func(k · 0.00005°)`: exact for the cases of [`TrigFn::exact`].
    ///
    /// # Panics
    ///
    /// When `k > 1 800 000` (beyond 90°), for `tan 90°` and for `cot 0`:
    /// the G75.1 model never asks for them (a bug of the model otherwise).
    #[must_use]
    pub fn trig(func: TrigFn, k: u32) -> Real {
        assert!(k <= RIGHT_ANGLE, "angle beyond 90°: {k} × 0.00005°");
        assert!(!(func == TrigFn::Tan && k == RIGHT_ANGLE), "tan 90° is not defined");
        assert!(!(func == TrigFn::Cot && k == 0), "cot 0 is not defined");
        match func.exact(k) {
            Some(r) => Real::exact(r),
            None => Real::node(Op::Trig(func, k)),
        }
    }

    /// `n^(a/b)` for `n ≥ 1` and `0 < a ≤ b`: an exact integer when it is
    /// one (`n = 1`, `a = b`, or an exact root `m` with `m^b = n^a`, tested
    /// for `b ≤ 64`), otherwise enclosed through `exp(ln(n)·a/b)` as
    /// narrowly as asked (the values of LinuxCNC's depth law `n^(1/R)`).
    ///
    /// Twin: `impl/src/engine/real.rs`, `power` (which tests the exact
    /// root as `n = r^b` in integers: the same cases for `a/b` in lowest
    /// terms).
    ///
    /// # Panics
    ///
    /// When `n = 0`, `a = 0` or `a > b`.
    #[must_use]
    pub fn power(n: u64, a: u32, b: u32) -> Real {
        assert!(n >= 1 && a >= 1 && a <= b, "power {n}^({a}/{b}) outside n >= 1, 0 < a <= b");
        let g = a.gcd(&b);
        let (a, b) = (a / g, b / g);
        if n == 1 || a == b {
            return Real::int(BigInt::from(n));
        }
        if b <= 64 {
            // An exact root: m^b = n^a for the integer m nearest n^(a/b).
            let estimate = power_interval(n, a, b, FIRST_PRECISION);
            let m = estimate.lower().nearest();
            if m.is_positive()
                && num_traits::pow(m.clone(), b as usize) == num_traits::pow(BigInt::from(n), a as usize)
            {
                return Real::int(m);
            }
        }
        Real::node(Op::Power(n, a, b))
    }

    /// `sin(k · 0.00005°)`, `0 ≤ k ≤ 1 800 000`.
    #[must_use]
    pub fn sin(k: u32) -> Real {
        Real::trig(TrigFn::Sin, k)
    }

    /// `cos(k · 0.00005°)`, `0 ≤ k ≤ 1 800 000`.
    #[must_use]
    pub fn cos(k: u32) -> Real {
        Real::trig(TrigFn::Cos, k)
    }

    /// `tan(k · 0.00005°)`, `0 ≤ k < 1 800 000`.
    #[must_use]
    pub fn tan(k: u32) -> Real {
        Real::trig(TrigFn::Tan, k)
    }

    /// `cot(k · 0.00005°)`, `0 < k ≤ 1 800 000`.
    #[must_use]
    pub fn cot(k: u32) -> Real {
        Real::trig(TrigFn::Cot, k)
    }

    /// The exact rational value, when the number is held as one.
    #[must_use]
    pub fn as_exact(&self) -> Option<&Rational> {
        match &self.0.op {
            Op::Exact(r) => Some(r),
            _ => None,
        }
    }

    /// True when the number is held as an exact rational.
    #[must_use]
    pub fn is_exact(&self) -> bool {
        self.as_exact().is_some()
    }

    /// `max(self, other)`. Its enclosure is the interval extension of max
    /// (`[max(lo₁, lo₂), max(hi₁, hi₂)]`), so rounding it never needs the
    /// comparison of the two to be decided.
    #[must_use]
    pub fn max(&self, other: &Real) -> Real {
        match (self.as_exact(), other.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a.max(b).clone()),
            _ => Real::node(Op::Max(self.clone(), other.clone())),
        }
    }

    /// `min(self, other)`, as [`Real::max`].
    #[must_use]
    pub fn min(&self, other: &Real) -> Real {
        match (self.as_exact(), other.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a.min(b).clone()),
            _ => Real::node(Op::Min(self.clone(), other.clone())),
        }
    }

    /// An enclosure of the number at `bits` fraction bits; `None` when a
    /// divisor's enclosure contains 0 at this precision (a higher one may
    /// do).
    #[must_use]
    pub fn enclose(&self, bits: u32) -> Option<Interval> {
        if let Some((_, v)) = self.0.cache.borrow().iter().find(|(b, _)| *b == bits) {
            return v.clone();
        }
        let v = match &self.0.op {
            Op::Exact(r) => Some(Interval::of_rational(r, bits)),
            Op::Trig(func, k) => trig_interval(*func, *k, bits),
            Op::Power(n, a, b) => Some(power_interval(*n, *a, *b, bits)),
            Op::Add(a, b) => Some(a.enclose(bits)?.add(&b.enclose(bits)?)),
            Op::Sub(a, b) => Some(a.enclose(bits)?.sub(&b.enclose(bits)?)),
            Op::Mul(a, b) => Some(a.enclose(bits)?.mul(&b.enclose(bits)?)),
            Op::Div(a, b) => a.enclose(bits)?.div(&b.enclose(bits)?),
            Op::Neg(a) => Some(a.enclose(bits)?.neg()),
            Op::Max(a, b) => Some(a.enclose(bits)?.max(&b.enclose(bits)?)),
            Op::Min(a, b) => Some(a.enclose(bits)?.min(&b.enclose(bits)?)),
        };
        self.0.cache.borrow_mut().push((bits, v.clone()));
        v
    }

    /// Decides `exact(r)` or, for an expression, `interval(enclosure)` at
    /// 64, 128, 256 and 512 fraction bits, the first that decides; when
    /// none does, `tie(the 512-bit enclosure)` (R-G75TIE).
    ///
    /// R-G75TIE (`docs/G75.md` §6): the boundary rule applies only after
    /// the whole precision ladder, to the 512-bit enclosure, and only when
    /// that enclosure holds exactly one boundary (`tie` returns `None` for
    /// two or more); otherwise, and when there is no 512-bit enclosure (a
    /// divisor's still contains 0), the decision is refused.
    fn decide<T>(
        &self,
        exact: impl Fn(&Rational) -> T,
        interval: impl Fn(&Interval) -> Option<T>,
        tie: impl Fn(&Interval) -> Option<T>,
    ) -> Result<T, CycleError> {
        if let Some(r) = self.as_exact() {
            return Ok(exact(r));
        }
        let mut bits = FIRST_PRECISION;
        let mut last = None;
        while bits <= MAX_PRECISION {
            last = self.enclose(bits);
            if let Some(v) = last.as_ref().and_then(&interval) {
                return Ok(v);
            }
            bits *= 2;
        }
        // R-G75TIE: still undecided at 512 fraction bits; one boundary in
        // the enclosure: the value lies on it. Two or more: refused.
        last.as_ref().and_then(tie).ok_or(CycleError::UndecidedRounding)
    }

    /// `floor(self)`, decided exactly (`docs/G75.md` §6); a value whose
    /// 512-bit enclosure still holds exactly one integer `k` is taken to be
    /// `k` (R-G75TIE).
    ///
    /// # Errors
    ///
    /// [`CycleError::UndecidedRounding`] when the 512-bit enclosure holds
    /// two integers or more (or a divisor's enclosure still contains 0).
    pub fn floor(&self) -> Result<BigInt, CycleError> {
        self.decide(Rational::floor, Interval::floor, Interval::tie_integer)
    }

    /// `ceil(self)`, decided exactly; a value whose 512-bit enclosure still
    /// holds exactly one integer `k` is taken to be `k` (R-G75TIE).
    ///
    /// # Errors
    ///
    /// As [`Real::floor`].
    pub fn ceil(&self) -> Result<BigInt, CycleError> {
        self.decide(Rational::ceil, Interval::ceil, Interval::tie_integer)
    }

    /// `floor(self + 1/2)`, the nearest integer with ties upwards, decided
    /// exactly; a value whose 512-bit enclosure still holds exactly one
    /// half-integer `k + 1/2` is taken to be it and rounds to `k + 1`
    /// (R-G75TIE).
    ///
    /// # Errors
    ///
    /// [`CycleError::UndecidedRounding`] when the 512-bit enclosure holds
    /// two half-integers or more (or a divisor's enclosure still contains
    /// 0).
    pub fn nearest(&self) -> Result<BigInt, CycleError> {
        self.decide(Rational::nearest, Interval::nearest, Interval::tie_nearest)
    }

    /// The sign of the number (its ordering against 0), decided exactly; a
    /// value whose 512-bit enclosure still holds 0 is taken to be 0
    /// (R-G75TIE: an irrational-looking expression that is exactly 0).
    ///
    /// # Errors
    ///
    /// [`CycleError::UndecidedRounding`] only when there is no 512-bit
    /// enclosure (a divisor's enclosure still contains 0): a sign has one
    /// boundary.
    pub fn sign(&self) -> Result<Ordering, CycleError> {
        self.decide(Rational::sign, Interval::sign, Interval::tie_sign)
    }

    /// `self` against `other`, decided exactly (the sign of the difference,
    /// with R-G75TIE: equal when 512 bits cannot tell them apart).
    ///
    /// # Errors
    ///
    /// As [`Real::sign`].
    pub fn compare(&self, other: &Real) -> Result<Ordering, CycleError> {
        (self - other).sign()
    }

    /// The number as a decimal with `digits` decimals, rounded down, when
    /// 512 fraction bits decide it (for messages and tests).
    #[must_use]
    pub fn to_decimal(&self, digits: u32) -> Option<String> {
        if let Some(r) = self.as_exact() {
            return Some(r.to_decimal(digits));
        }
        let mut bits = FIRST_PRECISION;
        while bits <= MAX_PRECISION {
            if let Some(iv) = self.enclose(bits) {
                let (lo, hi) = (iv.lower().to_decimal(digits), iv.upper().to_decimal(digits));
                if lo == hi {
                    return Some(lo);
                }
            }
            bits *= 2;
        }
        None
    }
}

impl From<i64> for Real {
    fn from(v: i64) -> Real {
        Real::int(v)
    }
}

impl From<i128> for Real {
    fn from(v: i128) -> Real {
        Real::int(v)
    }
}

impl From<Rational> for Real {
    fn from(r: Rational) -> Real {
        Real::exact(r)
    }
}

impl fmt::Debug for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0.op {
            Op::Exact(r) => write!(f, "{r}"),
            Op::Trig(func, k) => write!(f, "{}({k}·0.00005°)", func.name()),
            _ => match self.enclose(128) {
                Some(iv) => write!(f, "≈{}", iv.lower().to_decimal(12)),
                None => write!(f, "≈?"),
            },
        }
    }
}

impl Add for &Real {
    type Output = Real;
    fn add(self, o: &Real) -> Real {
        match (self.as_exact(), o.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a + b),
            (Some(a), None) if a.is_zero() => o.clone(),
            (None, Some(b)) if b.is_zero() => self.clone(),
            _ => Real::node(Op::Add(self.clone(), o.clone())),
        }
    }
}

impl Sub for &Real {
    type Output = Real;
    fn sub(self, o: &Real) -> Real {
        match (self.as_exact(), o.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a - b),
            (Some(a), None) if a.is_zero() => -o,
            (None, Some(b)) if b.is_zero() => self.clone(),
            _ => Real::node(Op::Sub(self.clone(), o.clone())),
        }
    }
}

impl Mul for &Real {
    type Output = Real;
    fn mul(self, o: &Real) -> Real {
        match (self.as_exact(), o.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a * b),
            (Some(a), _) | (_, Some(a)) if a.is_zero() => Real::exact(Rational::zero()),
            (Some(a), None) if a.is_one() => o.clone(),
            (None, Some(b)) if b.is_one() => self.clone(),
            _ => Real::node(Op::Mul(self.clone(), o.clone())),
        }
    }
}

impl Div for &Real {
    type Output = Real;
    /// # Panics
    ///
    /// On division by an exact 0 (a bug of the model).
    fn div(self, o: &Real) -> Real {
        match (self.as_exact(), o.as_exact()) {
            (Some(a), Some(b)) => Real::exact(a / b),
            (Some(a), None) if a.is_zero() => self.clone(),
            (None, Some(b)) if b.is_one() => self.clone(),
            _ => Real::node(Op::Div(self.clone(), o.clone())),
        }
    }
}

impl Neg for &Real {
    type Output = Real;
    fn neg(self) -> Real {
        match self.as_exact() {
            Some(a) => Real::exact(-a),
            None => Real::node(Op::Neg(self.clone())),
        }
    }
}

impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        -&self
    }
}

/// `Real op Real`, `Real op &Real` and `&Real op Real` by the reference
/// implementations.
macro_rules! by_value {
    ($($tr:ident $method:ident),*) => {$(
        impl $tr for Real {
            type Output = Real;
            fn $method(self, o: Real) -> Real {
                (&self).$method(&o)
            }
        }
        impl $tr<&Real> for Real {
            type Output = Real;
            fn $method(self, o: &Real) -> Real {
                (&self).$method(o)
            }
        }
        impl $tr<Real> for &Real {
            type Output = Real;
            fn $method(self, o: Real) -> Real {
                self.$method(&o)
            }
        }
    )*};
}

by_value!(Add add, Sub sub, Mul mul, Div div);

/// A big integer as `i128`, saturating (the G75.1 model's rounded values
/// are far inside `i128`; saturation only guards the conversion).
#[must_use]
pub fn saturating_i128(v: &BigInt) -> i128 {
    v.to_i128().unwrap_or(if v.is_negative() { i128::MIN } else { i128::MAX })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rational_rounding() {
        let r = Rational::new(5, 2);
        assert_eq!(r.floor(), BigInt::from(2));
        assert_eq!(r.ceil(), BigInt::from(3));
        assert_eq!(r.nearest(), BigInt::from(3));
        let r = Rational::new(-5, 2);
        assert_eq!(r.floor(), BigInt::from(-3));
        assert_eq!(r.ceil(), BigInt::from(-2));
        assert_eq!(r.nearest(), BigInt::from(-2));
        assert_eq!(Rational::new(6, -4), Rational::new(-3, 2));
        assert_eq!(Rational::new(-1, 3).to_decimal(3), "-0.334");
        assert_eq!(Rational::new(1, 8).to_decimal(3), "0.125");
    }

    #[test]
    fn pi_encloses() {
        let (lo, hi) = pi_scaled(200);
        let lo = Rational::new(lo, pow2(200)).to_decimal(50);
        let hi = Rational::new(hi, pow2(200)).to_decimal(50);
        assert_eq!(&lo[..52], "3.14159265358979323846264338327950288419716939937510");
        assert_eq!(lo, hi);
    }
}
