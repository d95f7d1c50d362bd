//! Fixed-point numbers: [`Fixed<N>`], a signed dyadic number of `N` limbs.

use core::cmp::Ordering;

use super::limbs::{
    limbs_add, limbs_cmp, limbs_div_small, limbs_divmod, limbs_inc, limbs_mul, limbs_mul_small, limbs_neg,
    limbs_sub, limbs_zero,
};
use super::{MAX_LIMBS, SCRATCH};

/// A signed dyadic number `int · 2^-P`, `P = 64·(N − 2)`: `N` limbs of two's
/// complement, little-endian; the top two limbs are the integer part (see
/// the [module documentation](super)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Fixed<const N: usize> {
    pub(super) l: [u64; N],
}

/// The former name of [`Fixed`], kept so that old paths still compile.
#[deprecated(note = "renamed `Fixed`")]
pub type Fx<const N: usize> = Fixed<N>;

/// How a result that is not representable is rounded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum RoundDirection {
    /// Towards −∞ (lower ends).
    Down,
    /// Towards +∞ (upper ends).
    Up,
}

impl<const N: usize> Fixed<N> {
    /// Compile-time check of the limb count (evaluated by every constructor).
    const LIMBS_OK: () = assert!(N >= 3 && N <= MAX_LIMBS, "Fixed needs 3..=MAX_LIMBS limbs");

    /// Number of fraction limbs, `N − 2`.
    pub(super) const FRAC: usize = N - 2;

    /// Fraction bits `P`.
    pub const FRACTION_BITS: u32 = 64 * (N as u32 - 2);

    /// Zero.
    #[must_use]
    pub const fn zero() -> Fixed<N> {
        let () = Self::LIMBS_OK;
        Fixed { l: [0; N] }
    }

    /// The integer `v`, exactly.
    #[must_use]
    pub fn from_int(v: i128) -> Fixed<N> {
        let mut x = Fixed::zero();
        let bits = v.to_le_bytes();
        let mut lo = [0_u8; 8];
        let mut hi = [0_u8; 8];
        lo.copy_from_slice(bits.get(..8).unwrap_or(&[0; 8]));
        hi.copy_from_slice(bits.get(8..).unwrap_or(&[0; 8]));
        if let Some(s) = x.l.get_mut(Self::FRAC) {
            *s = u64::from_le_bytes(lo);
        }
        if let Some(s) = x.l.get_mut(Self::FRAC + 1) {
            *s = u64::from_le_bytes(hi);
        }
        x
    }

    /// `ulps · 2^-P`.
    #[must_use]
    pub fn from_ulps(ulps: u64) -> Fixed<N> {
        let mut x = Fixed::zero();
        if let Some(s) = x.l.first_mut() {
            *s = ulps;
        }
        x
    }

    /// `2^-1`.
    pub(super) fn half() -> Fixed<N> {
        let mut x = Fixed::zero();
        if let Some(s) = x.l.get_mut(Self::FRAC - 1) {
            *s = 1 << 63;
        }
        x
    }

    /// True for a negative number.
    #[must_use]
    pub fn is_negative(&self) -> bool {
        self.l.last().is_some_and(|x| x >> 63 == 1)
    }

    /// True for zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        limbs_zero(&self.l)
    }

    /// Sign and magnitude (the magnitude as an unsigned `N`-limb number).
    pub(super) fn magnitude(&self) -> (bool, [u64; N]) {
        let neg = self.is_negative();
        let mut m = self.l;
        if neg {
            limbs_neg(&mut m);
        }
        (neg, m)
    }

    /// The number `±m` from a magnitude of any length; `None` unless
    /// `m < 2^(64N − 1)`.
    pub(super) fn from_magnitude(neg: bool, m: &[u64]) -> Option<Fixed<N>> {
        if m.iter().skip(N).any(|&x| x != 0) {
            return None;
        }
        let mut x = Fixed::zero();
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        for (d, s) in x.l.iter_mut().zip(m) {
            loops.tick();
            *d = *s;
        }
        if x.is_negative() {
            return None;
        }
        if neg {
            limbs_neg(&mut x.l);
        }
        Some(x)
    }

    /// `self + o`; `None` on overflow.
    #[must_use]
    pub fn checked_add(&self, o: &Fixed<N>) -> Option<Fixed<N>> {
        let mut r = *self;
        limbs_add(&mut r.l, &o.l);
        // Signed overflow: both operands of one sign, the result of the other.
        let (a, b, s) = (self.is_negative(), o.is_negative(), r.is_negative());
        (a != b || a == s).then_some(r)
    }

    /// `self − o`; `None` on overflow.
    #[must_use]
    pub fn checked_sub(&self, o: &Fixed<N>) -> Option<Fixed<N>> {
        let mut r = *self;
        limbs_sub(&mut r.l, &o.l);
        let (a, b, s) = (self.is_negative(), o.is_negative(), r.is_negative());
        (a == b || a == s).then_some(r)
    }

    /// `−self`; `None` for the most negative number.
    #[must_use]
    pub fn checked_neg(&self) -> Option<Fixed<N>> {
        let mut r = *self;
        limbs_neg(&mut r.l);
        (self.is_zero() || r.is_negative() != self.is_negative()).then_some(r)
    }

    /// Signed comparison.
    #[must_use]
    pub fn cmp_signed(&self, o: &Fixed<N>) -> Ordering {
        match (self.is_negative(), o.is_negative()) {
            (true, false) => Ordering::Less,
            (false, true) => Ordering::Greater,
            // Same sign: two's complement orders like unsigned.
            _ => limbs_cmp(&self.l, &o.l),
        }
    }

    /// The smaller of two numbers.
    pub(super) fn min(self, o: Fixed<N>) -> Fixed<N> {
        if self.cmp_signed(&o) == Ordering::Greater {
            o
        } else {
            self
        }
    }

    /// The larger of two numbers.
    pub(super) fn max(self, o: Fixed<N>) -> Fixed<N> {
        if self.cmp_signed(&o) == Ordering::Less {
            o
        } else {
            self
        }
    }

    /// The magnitude `m` rounded by `dir` after dropping its `drop` low limbs
    /// (`m / 2^(64·drop)`), with the sign `neg`.
    pub(super) fn round_shifted(
        neg: bool,
        m: &mut [u64],
        drop: usize,
        inexact_below: bool,
        dir: RoundDirection,
    ) -> Option<Fixed<N>> {
        let inexact = inexact_below || !limbs_zero(m.get(..drop).unwrap_or(&[]));
        let kept = m.get_mut(drop..)?;
        // Away from zero for Down on a negative and Up on a positive value.
        if inexact && ((dir == RoundDirection::Up) != neg) && limbs_inc(kept) {
            return None;
        }
        let neg = neg && !limbs_zero(kept);
        Fixed::from_magnitude(neg, kept)
    }

    /// `self · o` rounded by `dir`; `None` on overflow.
    pub(super) fn mul_round(&self, o: &Fixed<N>, dir: RoundDirection) -> Option<Fixed<N>> {
        let (na, ma) = self.magnitude();
        let (nb, mb) = o.magnitude();
        let mut p = [0_u64; SCRATCH];
        let prod = p.get_mut(..2 * N)?;
        limbs_mul(&ma, &mb, prod);
        // (A·2^-P)(B·2^-P) = (A·B·2^-P)·2^-P: drop P bits = N − 2 limbs.
        Fixed::round_shifted(na != nb, prod, Self::FRAC, false, dir)
    }

    /// `self / o` rounded by `dir`; `None` on overflow or division by zero.
    pub(super) fn div_round(&self, o: &Fixed<N>, dir: RoundDirection) -> Option<Fixed<N>> {
        if o.is_zero() {
            return None;
        }
        let (na, ma) = self.magnitude();
        let (nb, mb) = o.magnitude();
        // (A·2^-P)/(B·2^-P) = (A·2^P / B)·2^-P: the dividend is A shifted up
        // by N − 2 limbs (2N − 2 limbs in all).
        let mut num = [0_u64; SCRATCH];
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        for (d, s) in num.iter_mut().skip(Self::FRAC).zip(ma.iter()) {
            loops.tick();
            *d = *s;
        }
        let num = num.get(..2 * N - 2)?;
        let mut q = [0_u64; SCRATCH];
        let q = q.get_mut(..2 * N - 2)?;
        let mut rem = [0_u64; MAX_LIMBS + 1];
        let rem = rem.get_mut(..=N)?;
        limbs_divmod(num, &mb, q, rem);
        let inexact = !limbs_zero(rem);
        Fixed::round_shifted(na != nb, q, 0, inexact, dir)
    }

    /// `self · k`, exact; `None` on overflow.
    #[must_use]
    pub fn mul_int(&self, k: i64) -> Option<Fixed<N>> {
        let (neg, mut m) = self.magnitude();
        let carry = limbs_mul_small(&mut m, k.unsigned_abs());
        if carry != 0 {
            return None;
        }
        let neg = neg != (k < 0);
        Fixed::from_magnitude(neg && !limbs_zero(&m), &m)
    }

    /// `self / k` rounded by `dir`, `k > 0`.
    pub(super) fn div_small(&self, k: u64, dir: RoundDirection) -> Option<Fixed<N>> {
        if k == 0 {
            return None;
        }
        let (neg, mut m) = self.magnitude();
        let rem = limbs_div_small(&mut m, k);
        Fixed::round_shifted(neg, &mut m, 0, rem != 0, dir)
    }

    /// `floor(self)`: the top two limbs read as a signed integer (the
    /// arithmetic shift right by `P`).
    #[must_use]
    pub fn floor(&self) -> i128 {
        let lo = self.l.get(Self::FRAC).copied().unwrap_or(0);
        let hi = self.l.get(Self::FRAC + 1).copied().unwrap_or(0);
        let u = (u128::from(hi) << 64) | u128::from(lo);
        i128::from_le_bytes(u.to_le_bytes())
    }

    /// True when the number has a non-zero fraction.
    pub(super) fn has_fraction(&self) -> bool {
        !limbs_zero(self.l.get(..Self::FRAC).unwrap_or(&[]))
    }

    /// `ceil(self)`; `None` only at the top of the range.
    #[must_use]
    pub fn ceil(&self) -> Option<i128> {
        self.floor().checked_add(i128::from(self.has_fraction()))
    }

    /// The limbs (little-endian two's complement), for tests.
    #[must_use]
    pub const fn limbs(&self) -> &[u64; N] {
        &self.l
    }
}
