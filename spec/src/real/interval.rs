//! Enclosures: an [`Interval`] of dyadic ends `lo · 2^-bits` and
//! `hi · 2^-bits`, its interval arithmetic (rounded outwards), and the
//! decisions made on it: a rounding or a sign that is the same for every
//! number inside, and the boundary rule R-G75TIE.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, Zero};

use super::rational::{div_ceil, pow2, Rational};

/// A closed interval `[lo · 2^-bits, hi · 2^-bits]` that contains a real
/// number: the enclosure of a [`Real`](super::Real) at `bits` fraction bits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Interval {
    pub(super) lo: BigInt,
    pub(super) hi: BigInt,
    pub(super) bits: u32,
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

    pub(super) fn of_rational(r: &Rational, bits: u32) -> Interval {
        let (lo, hi) = r.scaled(bits);
        Interval { lo, hi, bits }
    }

    /// Rounds the ends of an enclosure at `from` fraction bits outwards to
    /// `bits` (`bits ≤ from`).
    pub(super) fn outwards(lo: &BigInt, hi: &BigInt, from: u32, bits: u32) -> Interval {
        let d = pow2(from - bits);
        Interval { lo: lo.div_floor(&d), hi: div_ceil(hi, &d), bits }
    }

    pub(super) fn add(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo + &o.lo, hi: &self.hi + &o.hi, bits: self.bits }
    }

    pub(super) fn sub(&self, o: &Interval) -> Interval {
        Interval { lo: &self.lo - &o.hi, hi: &self.hi - &o.lo, bits: self.bits }
    }

    pub(super) fn neg(&self) -> Interval {
        Interval { lo: -&self.hi, hi: -&self.lo, bits: self.bits }
    }

    pub(super) fn mul(&self, o: &Interval) -> Interval {
        let products = [&self.lo * &o.lo, &self.lo * &o.hi, &self.hi * &o.lo, &self.hi * &o.hi];
        let min = products.iter().min().cloned().unwrap_or_default();
        let max = products.iter().max().cloned().unwrap_or_default();
        Interval::outwards(&min, &max, 2 * self.bits, self.bits)
    }

    /// `None` when the divisor's enclosure contains 0.
    pub(super) fn div(&self, o: &Interval) -> Option<Interval> {
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

    pub(super) fn max(&self, o: &Interval) -> Interval {
        Interval { lo: (&self.lo).max(&o.lo).clone(), hi: (&self.hi).max(&o.hi).clone(), bits: self.bits }
    }

    pub(super) fn min(&self, o: &Interval) -> Interval {
        Interval { lo: (&self.lo).min(&o.lo).clone(), hi: (&self.hi).min(&o.hi).clone(), bits: self.bits }
    }

    /// `floor` of every number in the interval, if it is the same for all.
    ///
    /// Twin (with `ceil`, `nearest`): `impl/src/engine/real/`,
    /// `Interval::round`.
    pub(super) fn floor(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let (a, b) = (self.lo.div_floor(&d), self.hi.div_floor(&d));
        (a == b).then_some(a)
    }

    /// `ceil` of every number in the interval, if it is the same for all.
    pub(super) fn ceil(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let (a, b) = (div_ceil(&self.lo, &d), div_ceil(&self.hi, &d));
        (a == b).then_some(a)
    }

    /// `floor(v + 1/2)` of every number `v` in the interval, if it is the
    /// same for all.
    pub(super) fn nearest(&self) -> Option<BigInt> {
        let d = pow2(self.bits);
        let half = pow2(self.bits) >> 1_u32;
        let (a, b) = ((&self.lo + &half).div_floor(&d), (&self.hi + &half).div_floor(&d));
        (a == b).then_some(a)
    }

    /// The sign of every number in the interval, if it is the same for all.
    ///
    /// Twin: `impl/src/engine/real/interval.rs`, `Interval::sign`.
    pub(super) fn sign(&self) -> Option<Ordering> {
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
    /// Twin (with `tie_nearest`): `impl/src/engine/real/`,
    /// `Interval::round_tie`.
    pub(super) fn tie_integer(&self) -> Option<BigInt> {
        self.only_integer()
    }

    /// R-G75TIE for `nearest`: a value whose enclosure holds exactly one
    /// half-integer `k + 1/2` is taken to be `k + 1/2`, and `floor(k + 1/2
    /// + 1/2) = k + 1` (a tie goes up); `None` for two half-integers or
    /// more. `k + 1/2 ∈ [lo, hi]` exactly when `k ∈ [lo − 1/2, hi − 1/2]`.
    pub(super) fn tie_nearest(&self) -> Option<BigInt> {
        let half = pow2(self.bits) >> 1_u32;
        let shifted = Interval { lo: &self.lo - &half, hi: &self.hi - &half, bits: self.bits };
        shifted.only_integer().map(|k| k + 1)
    }

    /// R-G75TIE for a sign: an enclosure that holds 0 (the only boundary
    /// of a sign) is taken to be 0; `None` when it does not hold 0 (then
    /// [`Interval::sign`] decides).
    ///
    /// Twin: `impl/src/engine/real/interval.rs`, `Interval::sign_tie`.
    pub(super) fn tie_sign(&self) -> Option<Ordering> {
        (!self.lo.is_positive() && !self.hi.is_negative()).then_some(Ordering::Equal)
    }
}
