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
//!
//! # Layout
//!
//! This file holds [`Real`] (the expression, its enclosures and its
//! decisions) and the precisions; [`Rational`] is in `real/rational.rs`,
//! [`Interval`] (its arithmetic, roundings and the R-G75TIE rules) in
//! `real/interval.rs`, [`TrigFn`], `π` and the sine and cosine series in
//! `real/trig.rs`, and the power `n^(a/b)` (`atanh2_scaled`, `ln_scaled`,
//! `exp_scaled`, `power_interval`) in `real/power.rs`: the twins that
//! `impl/src/engine/real/` names in `spec/src/real.rs` are there.

use std::cell::RefCell;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::rc::Rc;

use cycleref::error::CycleError;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive};

mod interval;
mod power;
mod rational;
mod trig;

pub use interval::Interval;
use power::power_interval;
pub use rational::Rational;
use trig::trig_interval;
pub use trig::{pi_scaled, TrigFn, GUARD_BITS, HALF_TURN, RIGHT_ANGLE};

/// The first precision (fraction bits) at which a decision is tried.
pub const FIRST_PRECISION: u32 = 64;

/// The highest precision (fraction bits): a decision still open here is
/// made by the boundary rule R-G75TIE (`docs/G75.md` §6), or refused with
/// [`CycleError::UndecidedRounding`] when the enclosure holds two
/// boundaries or more.
pub const MAX_PRECISION: u32 = 512;

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
    /// Twin: `impl/src/engine/real/`, `power` (which tests the exact
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
