//! Exact rationals: [`Rational`], big integers in lowest terms, with the
//! roundings (`floor`, `ceil`, `nearest`) the G75.1 model decides, and the
//! two integer helpers the enclosures share (`pow2`, `div_ceil`).

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// `2^bits` as a big integer.
pub(super) fn pow2(bits: u32) -> BigInt {
    BigInt::one() << bits
}

/// `ceil(n / d)` for `d > 0`.
pub(super) fn div_ceil(n: &BigInt, d: &BigInt) -> BigInt {
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
    pub(super) fn scaled(&self, bits: u32) -> (BigInt, BigInt) {
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
}
