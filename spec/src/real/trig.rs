//! Trigonometry: [`TrigFn`] and its exact cases, `π` by Machin's formula
//! ([`pi_scaled`]), and the enclosures of `sin`, `cos`, `tan` and `cot` of
//! an angle `k · 0.00005°` by their series (see the module documentation
//! of [`crate::real`], "Trigonometry").

use std::cell::RefCell;
use std::collections::HashMap;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Zero};

use super::interval::Interval;
use super::rational::{div_ceil, pow2, Rational};

/// Guard bits of the trigonometric series beyond the requested precision.
pub const GUARD_BITS: u32 = 32;

/// 90° in the angle unit of this module, 0.00005°.
pub const RIGHT_ANGLE: u32 = 1_800_000;

/// 180° in the angle unit of this module, 0.00005°: the angle `k` is
/// `k · π / HALF_TURN` radians.
pub const HALF_TURN: u32 = 3_600_000;

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

    pub(super) fn name(self) -> &'static str {
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
pub(super) fn trig_interval(func: TrigFn, k: u32, bits: u32) -> Option<Interval> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pi_encloses() {
        let (lo, hi) = pi_scaled(200);
        let lo = Rational::new(lo, pow2(200)).to_decimal(50);
        let hi = Rational::new(hi, pow2(200)).to_decimal(50);
        assert_eq!(&lo[..52], "3.14159265358979323846264338327950288419716939937510");
        assert_eq!(lo, hi);
    }
}
