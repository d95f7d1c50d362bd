//! Intervals of fixed-point numbers: [`Interval<N>`] and its decisions
//! ([`Rounding`], R-G75TIE).

use core::cmp::Ordering;

use super::fixed::{Fixed, RoundDirection};

/// A closed interval `[lo, hi]` of [`Fixed<N>`] that contains an exact real
/// value, or a poisoned interval (an overflow, a division by an interval
/// containing 0, a series that did not converge) on which every decision is
/// undecided.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Interval<const N: usize> {
    pub(super) lo: Fixed<N>,
    pub(super) hi: Fixed<N>,
    pub(super) ok: bool,
}

/// The former name of [`Interval`], kept so that old paths still compile.
#[deprecated(note = "renamed `Interval`")]
pub type Iv<const N: usize> = Interval<N>;

/// A rounding to an integer (`docs/G75.md` §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Rounding {
    /// `floor(v)`.
    Floor,
    /// `ceil(v)`.
    Ceil,
    /// `floor(v + 1/2)`: nearest, ties upwards.
    Nearest,
}

impl<const N: usize> Interval<N> {
    /// The poisoned interval.
    #[must_use]
    pub fn poison() -> Interval<N> {
        Interval { lo: Fixed::zero(), hi: Fixed::zero(), ok: false }
    }

    /// The exact value `x`.
    #[must_use]
    pub fn point(x: Fixed<N>) -> Interval<N> {
        Interval { lo: x, hi: x, ok: true }
    }

    /// The exact integer `v`.
    #[must_use]
    pub fn int(v: i128) -> Interval<N> {
        Interval::point(Fixed::from_int(v))
    }

    /// The exact value `1/2`.
    #[must_use]
    pub fn half() -> Interval<N> {
        Interval::point(Fixed::half())
    }

    /// `[lo, hi]`; poisoned when `lo > hi`.
    #[must_use]
    pub fn new(lo: Fixed<N>, hi: Fixed<N>) -> Interval<N> {
        Interval { lo, hi, ok: lo.cmp_signed(&hi) != Ordering::Greater }
    }

    /// From optional ends: poisoned if either is missing.
    pub(super) fn of(lo: Option<Fixed<N>>, hi: Option<Fixed<N>>, ok: bool) -> Interval<N> {
        match (lo, hi) {
            (Some(lo), Some(hi)) if ok => Interval { lo, hi, ok: true },
            _ => Interval::poison(),
        }
    }

    /// The lower end.
    #[must_use]
    pub const fn lower(&self) -> &Fixed<N> {
        &self.lo
    }

    /// The upper end.
    #[must_use]
    pub const fn upper(&self) -> &Fixed<N> {
        &self.hi
    }

    /// False for a poisoned interval.
    #[must_use]
    pub const fn is_valid(&self) -> bool {
        self.ok
    }

    /// True for an exact value (a valid point interval).
    #[must_use]
    pub fn is_point(&self) -> bool {
        self.ok && self.lo == self.hi
    }

    /// `self + o`, exact.
    #[must_use]
    pub fn add(&self, o: &Interval<N>) -> Interval<N> {
        Interval::of(self.lo.checked_add(&o.lo), self.hi.checked_add(&o.hi), self.ok && o.ok)
    }

    /// `self − o`, exact.
    #[must_use]
    pub fn sub(&self, o: &Interval<N>) -> Interval<N> {
        Interval::of(self.lo.checked_sub(&o.hi), self.hi.checked_sub(&o.lo), self.ok && o.ok)
    }

    /// `−self`, exact.
    #[must_use]
    pub fn neg(&self) -> Interval<N> {
        Interval::of(self.hi.checked_neg(), self.lo.checked_neg(), self.ok)
    }

    /// `self · o`, rounded outwards (exact when the product is representable).
    #[must_use]
    pub fn mul(&self, o: &Interval<N>) -> Interval<N> {
        if !(self.ok && o.ok) {
            return Interval::poison();
        }
        // Exact shortcuts (the general rule gives the same intervals).
        let one = Fixed::from_int(1);
        if self.is_point() && (self.lo.is_zero() || self.lo == one) {
            return if self.lo.is_zero() { *self } else { *o };
        }
        if o.is_point() && (o.lo.is_zero() || o.lo == one) {
            return if o.lo.is_zero() { *o } else { *self };
        }
        let nonneg = |v: &Interval<N>| !v.lo.is_negative();
        if nonneg(self) && nonneg(o) {
            // Both non-negative: the product is monotone in each end.
            return Interval::of(
                self.lo.mul_round(&o.lo, RoundDirection::Down),
                self.hi.mul_round(&o.hi, RoundDirection::Up),
                true,
            );
        }
        let pairs = [(&self.lo, &o.lo), (&self.lo, &o.hi), (&self.hi, &o.lo), (&self.hi, &o.hi)];
        let mut lo: Option<Fixed<N>> = None;
        let mut hi: Option<Fixed<N>> = None;
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        for (x, y) in pairs {
            loops.tick();
            let (Some(d), Some(u)) =
                (x.mul_round(y, RoundDirection::Down), x.mul_round(y, RoundDirection::Up))
            else {
                return Interval::poison();
            };
            lo = Some(lo.map_or(d, |l| l.min(d)));
            hi = Some(hi.map_or(u, |h| h.max(u)));
        }
        Interval::of(lo, hi, true)
    }

    /// `self / o` for a divisor interval of positive numbers, rounded
    /// outwards; poisoned when `o` contains 0 or a negative number.
    #[must_use]
    pub fn div(&self, o: &Interval<N>) -> Interval<N> {
        if !(self.ok && o.ok) || o.lo.is_negative() || o.lo.is_zero() {
            return Interval::poison();
        }
        if o.is_point() && o.lo == Fixed::from_int(1) {
            // x / 1 = x exactly.
            return *self;
        }
        // For a positive divisor, x/y is increasing in x and, for x ≥ 0,
        // decreasing in y (increasing for x < 0).
        let lo = if self.lo.is_negative() {
            self.lo.div_round(&o.lo, RoundDirection::Down)
        } else {
            self.lo.div_round(&o.hi, RoundDirection::Down)
        };
        let hi = if self.hi.is_negative() {
            self.hi.div_round(&o.hi, RoundDirection::Up)
        } else {
            self.hi.div_round(&o.lo, RoundDirection::Up)
        };
        Interval::of(lo, hi, true)
    }

    /// `self · k` for an integer `k`, exact.
    #[must_use]
    pub fn mul_int(&self, k: i64) -> Interval<N> {
        let (a, b) = (self.lo.mul_int(k), self.hi.mul_int(k));
        if k < 0 {
            Interval::of(b, a, self.ok)
        } else {
            Interval::of(a, b, self.ok)
        }
    }

    /// `self / k` for an integer `k > 0`, rounded outwards.
    #[must_use]
    pub fn div_int(&self, k: u64) -> Interval<N> {
        Interval::of(
            self.lo.div_small(k, RoundDirection::Down),
            self.hi.div_small(k, RoundDirection::Up),
            self.ok,
        )
    }

    /// `max(self, o)`: `[max(lo₁, lo₂), max(hi₁, hi₂)]`.
    #[must_use]
    pub fn max(&self, o: &Interval<N>) -> Interval<N> {
        Interval::of(Some(self.lo.max(o.lo)), Some(self.hi.max(o.hi)), self.ok && o.ok)
    }

    /// `min(self, o)`: `[min(lo₁, lo₂), min(hi₁, hi₂)]`.
    #[must_use]
    pub fn min(&self, o: &Interval<N>) -> Interval<N> {
        Interval::of(Some(self.lo.min(o.lo)), Some(self.hi.min(o.hi)), self.ok && o.ok)
    }

    /// The rounding of every number of the interval, when it is the same
    /// for all (always for a point interval); `None` when undecided.
    ///
    /// Twin: `spec/src/real.rs`, `Interval::floor`, `Interval::ceil`,
    /// `Interval::nearest` (over big integers).
    #[must_use]
    pub fn round(&self, r: Rounding) -> Option<i128> {
        if !self.ok {
            return None;
        }
        let (a, b) = match r {
            Rounding::Floor => (Some(self.lo.floor()), Some(self.hi.floor())),
            Rounding::Ceil => (self.lo.ceil(), self.hi.ceil()),
            Rounding::Nearest => {
                let half = Fixed::half();
                (self.lo.checked_add(&half).map(|x| x.floor()), self.hi.checked_add(&half).map(|x| x.floor()))
            }
        };
        match (a, b) {
            (Some(a), Some(b)) if a == b => Some(a),
            _ => None,
        }
    }

    /// The sign of every number of the interval (its ordering against 0),
    /// when it is the same for all; `None` when undecided.
    ///
    /// Twin: `spec/src/real.rs`, `Interval::sign`.
    #[must_use]
    pub fn sign(&self) -> Option<Ordering> {
        if !self.ok {
            None
        } else if !self.lo.is_negative() && !self.lo.is_zero() {
            Some(Ordering::Greater)
        } else if self.hi.is_negative() {
            Some(Ordering::Less)
        } else if self.lo.is_zero() && self.hi.is_zero() {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The rounding of the exact value enclosed, for an enclosure at the
    /// highest precision (reading R-G75TIE, `docs/G75.md` §6): as
    /// [`Interval::round`] when that decides; otherwise, when the interval holds
    /// exactly one rounding boundary (an integer for floor and ceil, a
    /// half-integer for nearest; inside or on an end), the value is taken
    /// to lie on it: `floor(k) = ceil(k) = k`, and the nearest of `k + 1/2`
    /// is `k + 1` (ties up). `None` for a poisoned interval or one that
    /// holds two or more boundaries.
    ///
    /// Twin: `spec/src/real.rs`, `Interval::tie_integer` and
    /// `Interval::tie_nearest`.
    #[must_use]
    pub fn round_tie(&self, r: Rounding) -> Option<i128> {
        if let Some(v) = self.round(r) {
            return Some(v);
        }
        if !self.ok {
            return None;
        }
        // The boundaries, shifted to the integers: the half-integers `j − 1/2`
        // of nearest are the integers `j` of `[lo + 1/2, hi + 1/2]`, and the
        // nearest of `j − 1/2` is `j`.
        let (lo, hi) = match r {
            Rounding::Floor | Rounding::Ceil => (self.lo, self.hi),
            Rounding::Nearest => {
                let half = Fixed::half();
                (self.lo.checked_add(&half)?, self.hi.checked_add(&half)?)
            }
        };
        // The integers of [lo, hi] are ceil(lo)..=floor(hi): one exactly when
        // the two are equal.
        let first = lo.ceil()?;
        (first == hi.floor()).then_some(first)
    }

    /// The sign of the exact value enclosed, for an enclosure at the highest
    /// precision (reading R-G75TIE): as [`Interval::sign`] when that decides;
    /// otherwise the interval contains 0 (its only boundary) and the value is
    /// taken to be 0. `None` only for a poisoned interval.
    ///
    /// Twin: `spec/src/real.rs`, `Interval::tie_sign`.
    #[must_use]
    pub fn sign_tie(&self) -> Option<Ordering> {
        match self.sign() {
            Some(o) => Some(o),
            // Undecided and valid: lo ≤ 0 ≤ hi.
            None if self.ok => Some(Ordering::Equal),
            None => None,
        }
    }
}
