//! Exact rounding support for the G75.1 engine (`docs/G75.md` §6,
//! reading R-G75ROUND): dyadic fixed-point interval arithmetic, the sine,
//! cosine, tangent and cotangent of angles `k · 0.00005°`, and the four
//! decisions the cycle makes on a real number (floor, ceil, nearest, sign).
//!
//! # Numbers
//!
//! An [`Fixed<N>`] is a signed integer of `N` 64-bit limbs (two's complement,
//! little-endian) read as `int · 2^-P` with `P = 64·(N − 2)` fraction bits:
//! the two top limbs hold the integer part, so every value lies in
//! `(−2^127, 2^127)`. The engine uses two precisions:
//!
//! * [`FAST`] = 4 limbs, `P = 128` (the fast path);
//! * [`SLOW`] = 10 limbs, `P = 512` (the highest precision of
//!   `docs/G75.md` §6, at which reading R-G75TIE applies:
//!   [`Interval::round_tie`], [`Interval::sign_tie`]).
//!
//! An [`Interval<N>`] is a closed interval `[lo, hi]` of such numbers that contains
//! the exact real value it stands for. Every operation rounds its lower end
//! down and its upper end up, so the containment is kept. Additions and
//! subtractions are exact; a product or quotient is exact whenever the exact
//! result is representable, so an operation on point intervals (exact
//! values) gives a point interval exactly when the exact result is a dyadic
//! number with at most `P` fraction bits. All exact values of the G75.1
//! geometry are dyadic with few fraction bits (the only exact trigonometric
//! values are 0, 1/2 and 1, and the only divisors are `f` ∈ {1, 2} and
//! sines, cosines and `1 − tan L·cot b` that are 1/2 or 1 when exact), so
//! exact inputs give exact point intervals and are decided exactly.
//!
//! An operation that would overflow (a magnitude of `2^127` or more), a
//! division by an interval that contains 0 and a series that does not
//! converge within its iteration bound "poison" the interval: every decision
//! on a poisoned interval is undecided, so the engine refuses
//! ([`crate::CycleError::UndecidedRounding`]) instead of guessing. None of
//! these can happen for a validated cycle: the largest magnitude the G75.1
//! formulas reach is below `2^96` (see `engine/g75/mod.rs`).
//!
//! # Trigonometry
//!
//! `sin` and `cos` of `x = k · π / 3 600 000` (`0 ≤ k ≤ 1 800 000`, 0° to
//! 90°) by their Taylor series. Each term is enclosed by interval
//! arithmetic; the series alternate with terms that decrease in magnitude
//! (`x < 2`), so the remainder after a term is at most the next term, whose
//! upper bound is added to both ends (a rigorous truncation bound). `π`
//! comes from [`PI_FRACTION`], hard-coded. The exact cases of
//! `docs/G75.md` §6 (sin 0, 30°, 90°; cos 0, 60°, 90°; tan 0, 45°; cot 45°,
//! 90°) are returned as exact point intervals.
//!
//! No heap, no floating point, no `unsafe`, no panics: every index is
//! bounded by the const generic `N` (checked at compile time to lie in
//! `3..=MAX_LIMBS`), every arithmetic operation is checked or wrapping on
//! purpose (limb arithmetic with explicit carries).

use core::cmp::Ordering;

/// Limbs of the fast precision: 128 fraction bits.
pub const FAST: usize = 4;

/// Limbs of the slow precision: 512 fraction bits (`docs/G75.md` §6).
pub const SLOW: usize = 10;

/// Most limbs an [`Fixed`] may have (the scratch buffers are sized for it).
pub const MAX_LIMBS: usize = 14;

/// Scratch size: a full product of two numbers of [`MAX_LIMBS`] limbs.
const SCRATCH: usize = 2 * MAX_LIMBS;

/// The fraction bits of π − 3, most significant 64-bit word first: `π =
/// 3 + Σ PI_FRACTION[i] · 2^(−64(i+1)) + δ`, `0 ≤ δ < 2^-640`.
///
/// These are the well-known hexadecimal digits of π
/// (`3.243F6A8885A308D313198A2E03707344A4093822299F31D0…`, the same digits
/// that initialise Blowfish's P-array and first S-box). The test
/// `pi_matches_machin` recomputes π from Machin's formula
/// `π = 16 atan(1/5) − 4 atan(1/239)` with this module's interval
/// arithmetic at 704 fraction bits and checks every one of these 640 bits.
pub const PI_FRACTION: [u64; 10] = [
    0x243F_6A88_85A3_08D3,
    0x1319_8A2E_0370_7344,
    0xA409_3822_299F_31D0,
    0x082E_FA98_EC4E_6C89,
    0x4528_21E6_38D0_1377,
    0xBE54_66CF_34E9_0C6C,
    0xC0AC_29B7_C97C_50DD,
    0x3F84_D5B5_B547_0917,
    0x9216_D5D9_8979_FB1B,
    0xD131_0BA6_98DF_B5AC,
];

/// 90° in the angle unit of this module, 0.00005°.
pub const RIGHT: u32 = 1_800_000;

/// 180° in the angle unit of this module: the angle `k` is `k·π/HALF_TURN`.
pub const HALF_TURN: u32 = 3_600_000;

// ---------------------------------------------------------------------------
// Limb arithmetic on little-endian slices of u64.
// ---------------------------------------------------------------------------

/// True when every limb is 0.
fn limbs_zero(a: &[u64]) -> bool {
    a.iter().all(|&x| x == 0)
}

/// `a += b` over `a.len()` limbs (`b` shorter or equal, read as zero
/// beyond its end); returns the carry out of the top limb.
fn limbs_add(a: &mut [u64], b: &[u64]) -> bool {
    let mut carry = false;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, x) in a.iter_mut().enumerate() {
        loops.tick();
        let y = b.get(i).copied().unwrap_or(0);
        let (s1, c1) = x.overflowing_add(y);
        let (s2, c2) = s1.overflowing_add(u64::from(carry));
        *x = s2;
        carry = c1 || c2;
    }
    carry
}

/// `a -= b` over `a.len()` limbs; returns the borrow out of the top limb.
fn limbs_sub(a: &mut [u64], b: &[u64]) -> bool {
    let mut borrow = false;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, x) in a.iter_mut().enumerate() {
        loops.tick();
        let y = b.get(i).copied().unwrap_or(0);
        let (s1, b1) = x.overflowing_sub(y);
        let (s2, b2) = s1.overflowing_sub(u64::from(borrow));
        *x = s2;
        borrow = b1 || b2;
    }
    borrow
}

/// `a += 1`; returns the carry out.
fn limbs_inc(a: &mut [u64]) -> bool {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        let (s, c) = x.overflowing_add(1);
        *x = s;
        if !c {
            return false;
        }
    }
    true
}

/// Two's complement negation in place.
fn limbs_neg(a: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        *x = !*x;
    }
    limbs_inc(a);
}

/// Unsigned comparison of `a` and `b` (the shorter read as zero-extended).
fn limbs_cmp(a: &[u64], b: &[u64]) -> Ordering {
    let n = a.len().max(b.len());
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for i in (0..n).rev() {
        loops.tick();
        let x = a.get(i).copied().unwrap_or(0);
        let y = b.get(i).copied().unwrap_or(0);
        match x.cmp(&y) {
            Ordering::Equal => {}
            o => return o,
        }
    }
    Ordering::Equal
}

/// `out = a · b`; `out` must be zero on entry and hold `a.len() + b.len()`
/// limbs (the product of an `m`- and an `n`-limb number fits `m + n` limbs).
fn limbs_mul(a: &[u64], b: &[u64], out: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, &x) in a.iter().enumerate() {
        loops.tick();
        if x == 0 {
            continue;
        }
        let mut carry: u64 = 0;
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        for (j, &y) in b.iter().enumerate() {
            loops.tick();
            if let Some(slot) = out.get_mut(i + j) {
                // x·y + slot + carry ≤ (2^64 − 1)^2 + 2(2^64 − 1) = 2^128 − 1.
                let t = u128::from(x) * u128::from(y) + u128::from(*slot) + u128::from(carry);
                *slot = low64(t);
                carry = high64(t);
            }
        }
        let mut k = i + b.len();
        let mut loops = crate::loop_counters::count!(REAL_LIMBS);
        while carry != 0 {
            loops.tick();
            if let Some(slot) = out.get_mut(k) {
                let (s, c) = slot.overflowing_add(carry);
                *slot = s;
                carry = u64::from(c);
                k += 1;
            } else {
                break;
            }
        }
    }
}

/// `a / d` in place for a one-limb divisor `d > 0`; returns the remainder.
fn limbs_div_small(a: &mut [u64], d: u64) -> u64 {
    let mut rem: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut().rev() {
        loops.tick();
        // rem < d, so the partial dividend is below d·2^64 and the quotient
        // digit fits a limb.
        let cur = (u128::from(rem) << 64) | u128::from(*x);
        let d128 = u128::from(d);
        *x = low64(cur / d128);
        rem = low64(cur % d128);
    }
    rem
}

/// `a · k` in place for a one-limb factor; returns the limb carried out.
fn limbs_mul_small(a: &mut [u64], k: u64) -> u64 {
    let mut carry: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for x in a.iter_mut() {
        loops.tick();
        let t = u128::from(*x) * u128::from(k) + u128::from(carry);
        *x = low64(t);
        carry = high64(t);
    }
    carry
}

/// The number of significant bits of `a` (0 for zero).
fn limbs_bits(a: &[u64]) -> usize {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for i in (0..a.len()).rev() {
        loops.tick();
        if let Some(&x) = a.get(i) {
            if x != 0 {
                return 64 * i + (64 - x.leading_zeros() as usize);
            }
        }
    }
    0
}

/// Long division `num / den` (Knuth's algorithm D, TAOCP vol. 2 §4.3.1,
/// with 64-bit digits): the quotient goes to `q` (as long as `num`, zero on
/// entry), the remainder is left in `rem` (zero on entry, one limb longer
/// than `den`). `den` must not be zero (a zero `den` leaves both zero).
///
/// One quotient limb per step, each estimated from the top two limbs of the
/// partial remainder and the top limb of the normalised divisor (at most two
/// too large after the test on the second limb, and then at most one: the
/// add-back). It replaced a bit-by-bit restoring division (kept as the
/// tests' oracle, `limbs_divmod_bits`), which took 128 + 64·k steps for a
/// quotient of a `k`-limb number and was 15 % of `expand` (benches/README).
fn limbs_divmod(num: &[u64], den: &[u64], q: &mut [u64], rem: &mut [u64]) {
    let n = limbs_bits(den).div_ceil(64);
    let m = limbs_bits(num).div_ceil(64);
    if n == 0 {
        return;
    }
    let (Some(num), Some(den)) = (num.get(..m), den.get(..n)) else { return };
    if m < n {
        limbs_copy(rem, num);
        return;
    }
    if n == 1 {
        let d = den.first().copied().unwrap_or(1);
        let mut r: u64 = 0;
        let mut loops = crate::loop_counters::count!(REAL_DIVMOD);
        for (qi, &x) in q.iter_mut().zip(num).rev() {
            loops.tick();
            // r < d, so the partial dividend is below d·2^64: the digit fits.
            let cur = (u128::from(r) << 64) | u128::from(x);
            *qi = low64(cur / u128::from(d));
            r = low64(cur % u128::from(d));
        }
        if let Some(r0) = rem.first_mut() {
            *r0 = r;
        }
        return;
    }
    // D1: normalise, so that the divisor's top limb has its top bit set.
    let shift = den.get(n - 1).map_or(0, |x| x.leading_zeros());
    let mut v = [0_u64; SCRATCH];
    let mut u = [0_u64; SCRATCH + 1];
    let (Some(v), Some(u)) = (v.get_mut(..n), u.get_mut(..=m)) else { return };
    limbs_shl_into(den, shift, v);
    limbs_shl_into(num, shift, u);
    let v_top = u128::from(v.get(n - 1).copied().unwrap_or(1));
    let v_next = u128::from(v.get(n - 2).copied().unwrap_or(0));
    let mut loops = crate::loop_counters::count!(REAL_DIVMOD);
    for j in (0..=m - n).rev() {
        loops.tick();
        let limb = |u: &[u64], i: usize| u128::from(u.get(i).copied().unwrap_or(0));
        // D3: the estimate q̂ from the top two limbs, corrected by the next.
        let top = (limb(u, j + n) << 64) | limb(u, j + n - 1);
        let mut q_hat = top / v_top;
        let mut r_hat = top % v_top;
        let mut fixes = crate::loop_counters::count!(REAL_DIVMOD);
        while q_hat > u128::from(u64::MAX) || q_hat * v_next > ((r_hat << 64) | limb(u, j + n - 2)) {
            fixes.tick();
            q_hat -= 1;
            r_hat += v_top;
            if r_hat > u128::from(u64::MAX) {
                break;
            }
        }
        // D4: u[j..=j+n] −= q̂ · v.
        let q_digit = low64(q_hat);
        let mut borrow: u64 = 0;
        let mut carry: u64 = 0;
        let mut limbs = crate::loop_counters::count!(REAL_LIMBS);
        for (i, &vi) in v.iter().enumerate() {
            limbs.tick();
            let p = u128::from(q_digit) * u128::from(vi) + u128::from(carry);
            carry = high64(p);
            if let Some(x) = u.get_mut(i + j) {
                let (d1, b1) = x.overflowing_sub(low64(p));
                let (d2, b2) = d1.overflowing_sub(borrow);
                *x = d2;
                borrow = u64::from(b1 || b2);
            }
        }
        let mut negative = false;
        if let Some(x) = u.get_mut(j + n) {
            let (d1, b1) = x.overflowing_sub(carry);
            let (d2, b2) = d1.overflowing_sub(borrow);
            *x = d2;
            negative = b1 || b2;
        }
        // D5, D6: q̂ was one too large (rare): add v back.
        let q_digit = if negative {
            let mut c = false;
            let mut limbs = crate::loop_counters::count!(REAL_LIMBS);
            for (i, &vi) in v.iter().enumerate() {
                limbs.tick();
                if let Some(x) = u.get_mut(i + j) {
                    let (s1, c1) = x.overflowing_add(vi);
                    let (s2, c2) = s1.overflowing_add(u64::from(c));
                    *x = s2;
                    c = c1 || c2;
                }
            }
            if let Some(x) = u.get_mut(j + n) {
                *x = x.wrapping_add(u64::from(c));
            }
            #[cfg(test)]
            ADD_BACKS.fetch_add(1, core::sync::atomic::Ordering::Relaxed);
            q_digit.wrapping_sub(1)
        } else {
            q_digit
        };
        if let Some(x) = q.get_mut(j) {
            *x = q_digit;
        }
    }
    // D8: the remainder is u[..n], shifted back.
    limbs_shr_into(u.get(..n).unwrap_or(&[]), shift, rem);
}

/// How many times step D6 (add back) ran: the tests check that they reach it.
#[cfg(test)]
static ADD_BACKS: core::sync::atomic::AtomicUsize = core::sync::atomic::AtomicUsize::new(0);

/// Copies `src` into the start of `dst` (as far as `dst` goes).
fn limbs_copy(dst: &mut [u64], src: &[u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (d, &s) in dst.iter_mut().zip(src) {
        loops.tick();
        *d = s;
    }
}

/// `out = a << shift` for `shift < 64`; `out` has at least `a.len()` limbs
/// (one more receives the bits shifted out of the top, when it is there).
fn limbs_shl_into(a: &[u64], shift: u32, out: &mut [u64]) {
    let mut carry: u64 = 0;
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (o, &x) in out.iter_mut().zip(a) {
        loops.tick();
        *o = (x << shift) | carry;
        carry = if shift == 0 { 0 } else { x >> (64 - shift) };
    }
    if let Some(o) = out.get_mut(a.len()) {
        *o = carry;
    }
}

/// `out = a >> shift` for `shift < 64`, `a.len()` limbs into the start of
/// `out`.
fn limbs_shr_into(a: &[u64], shift: u32, out: &mut [u64]) {
    let mut loops = crate::loop_counters::count!(REAL_LIMBS);
    for (i, o) in out.iter_mut().enumerate().take(a.len()) {
        loops.tick();
        let x = a.get(i).copied().unwrap_or(0);
        let above = a.get(i + 1).copied().unwrap_or(0);
        *o = if shift == 0 { x } else { (x >> shift) | (above << (64 - shift)) };
    }
}

/// The low 64 bits of `v`.
const fn low64(v: u128) -> u64 {
    // Truncation on purpose: the low limb.
    #[allow(clippy::cast_possible_truncation)]
    let r = v as u64;
    r
}

/// The high 64 bits of `v`.
const fn high64(v: u128) -> u64 {
    low64(v >> 64)
}

// ---------------------------------------------------------------------------
// Fixed-point numbers.
// ---------------------------------------------------------------------------

/// A signed dyadic number `int · 2^-P`, `P = 64·(N − 2)`: `N` limbs of two's
/// complement, little-endian; the top two limbs are the integer part (see
/// the [module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Fixed<const N: usize> {
    l: [u64; N],
}

/// The former name of [`Fixed`], kept so that old paths still compile.
#[deprecated(note = "renamed `Fixed`")]
pub type Fx<const N: usize> = Fixed<N>;

/// How a result that is not representable is rounded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RoundDirection {
    /// Towards −∞ (lower ends).
    Down,
    /// Towards +∞ (upper ends).
    Up,
}

impl<const N: usize> Fixed<N> {
    /// Compile-time check of the limb count (evaluated by every constructor).
    const LIMBS_OK: () = assert!(N >= 3 && N <= MAX_LIMBS, "Fixed needs 3..=MAX_LIMBS limbs");

    /// Number of fraction limbs, `N − 2`.
    const FRAC: usize = N - 2;

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
    fn half() -> Fixed<N> {
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
    fn magnitude(&self) -> (bool, [u64; N]) {
        let neg = self.is_negative();
        let mut m = self.l;
        if neg {
            limbs_neg(&mut m);
        }
        (neg, m)
    }

    /// The number `±m` from a magnitude of any length; `None` unless
    /// `m < 2^(64N − 1)`.
    fn from_magnitude(neg: bool, m: &[u64]) -> Option<Fixed<N>> {
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
    fn min(self, o: Fixed<N>) -> Fixed<N> {
        if self.cmp_signed(&o) == Ordering::Greater {
            o
        } else {
            self
        }
    }

    /// The larger of two numbers.
    fn max(self, o: Fixed<N>) -> Fixed<N> {
        if self.cmp_signed(&o) == Ordering::Less {
            o
        } else {
            self
        }
    }

    /// The magnitude `m` rounded by `dir` after dropping its `drop` low limbs
    /// (`m / 2^(64·drop)`), with the sign `neg`.
    fn round_shifted(
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
    fn mul_round(&self, o: &Fixed<N>, dir: RoundDirection) -> Option<Fixed<N>> {
        let (na, ma) = self.magnitude();
        let (nb, mb) = o.magnitude();
        let mut p = [0_u64; SCRATCH];
        let prod = p.get_mut(..2 * N)?;
        limbs_mul(&ma, &mb, prod);
        // (A·2^-P)(B·2^-P) = (A·B·2^-P)·2^-P: drop P bits = N − 2 limbs.
        Fixed::round_shifted(na != nb, prod, Self::FRAC, false, dir)
    }

    /// `self / o` rounded by `dir`; `None` on overflow or division by zero.
    fn div_round(&self, o: &Fixed<N>, dir: RoundDirection) -> Option<Fixed<N>> {
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
    fn div_small(&self, k: u64, dir: RoundDirection) -> Option<Fixed<N>> {
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
    fn has_fraction(&self) -> bool {
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

// ---------------------------------------------------------------------------
// Intervals.
// ---------------------------------------------------------------------------

/// A closed interval `[lo, hi]` of [`Fixed<N>`] that contains an exact real
/// value, or a poisoned interval (an overflow, a division by an interval
/// containing 0, a series that did not converge) on which every decision is
/// undecided.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Interval<const N: usize> {
    lo: Fixed<N>,
    hi: Fixed<N>,
    ok: bool,
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
    fn of(lo: Option<Fixed<N>>, hi: Option<Fixed<N>>, ok: bool) -> Interval<N> {
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

// ---------------------------------------------------------------------------
// Trigonometry.
// ---------------------------------------------------------------------------

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
const MAX_TERMS: u64 = 400;

/// `x = k · π / 3 600 000` and `x²`, the argument of [`series`].
fn series_argument<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
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
fn series<const N: usize>(x2: &Interval<N>, first: Interval<N>, first_index: u64) -> Interval<N> {
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
fn sin_series<const N: usize>(k: u32) -> Interval<N> {
    let (x, x2) = series_argument::<N>(k);
    series(&x2, x, 1)
}

/// `cos x` by its series ([`series`]).
fn cos_series<const N: usize>(k: u32) -> Interval<N> {
    let (_, x2) = series_argument::<N>(k);
    series(&x2, Interval::int(1), 0)
}

/// `sin x` and `cos x` by their series ([`series`]), sharing `x` and `x²`.
fn sin_cos_series<const N: usize>(k: u32) -> (Interval<N>, Interval<N>) {
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

// ---------------------------------------------------------------------------
// Logarithm, exponential and powers (LinuxCNC's depth law `n^(1/R)`).
// ---------------------------------------------------------------------------

/// Most halvings of the exponential's argument: an argument below `2^127`
/// (every valid interval) falls below 1/2 after at most 128.
const MAX_HALVINGS: u32 = 130;

/// Most steps of the integer root search of [`power`] (a binary search
/// over `[1, 2^32]`, 33 steps) and of its gcd (Euclid's on `u32`, at most
/// 47 steps).
const MAX_ROOT_STEPS: u32 = 64;

impl<const N: usize> Fixed<N> {
    /// The number at the precision `M`: exact when `M ≥ N` (zero fraction
    /// limbs appended below), rounded by `dir` otherwise (the integer part
    /// is the same two limbs at every precision, so it never overflows).
    fn at_precision<const M: usize>(&self, dir: RoundDirection) -> Option<Fixed<M>> {
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
fn atanh2<const N: usize>(num: u64, den: u64) -> Interval<N> {
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
fn integer_root(n: u64, b: u32) -> Option<u64> {
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
fn gcd_u32(mut a: u32, mut b: u32) -> u32 {
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

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use std::string::String;
    use std::vec::Vec;

    /// `a <<= 1`; returns the bit shifted out.
    fn limbs_shl1(a: &mut [u64]) -> bool {
        let mut carry = false;
        for x in a.iter_mut() {
            let out = *x >> 63 == 1;
            *x = (*x << 1) | u64::from(carry);
            carry = out;
        }
        carry
    }

    /// Bit `i` of `a`.
    fn limbs_bit(a: &[u64], i: usize) -> bool {
        a.get(i / 64).is_some_and(|x| (x >> (i % 64)) & 1 == 1)
    }

    /// The bit-by-bit restoring division that `limbs_divmod` replaced: the
    /// oracle of `divmod_matches_the_bitwise_division`.
    fn limbs_divmod_bits(num: &[u64], den: &[u64], q: &mut [u64], rem: &mut [u64]) {
        for i in (0..limbs_bits(num)).rev() {
            limbs_shl1(rem);
            if limbs_bit(num, i) {
                rem[0] |= 1;
            }
            if limbs_cmp(rem, den) != Ordering::Less {
                limbs_sub(rem, den);
                q[i / 64] |= 1 << (i % 64);
            }
        }
    }

    /// A small deterministic generator (xorshift64*), so that the test
    /// needs no dependency.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
        }

        /// A limb that is often an edge: 0, 1, all ones, a top bit alone.
        fn limb(&mut self) -> u64 {
            match self.next() % 8 {
                0 => 0,
                1 => u64::MAX,
                2 => 1 << 63,
                3 => 1,
                4 => u64::MAX - 1,
                _ => self.next(),
            }
        }
    }

    /// Knuth's algorithm D against the restoring division, on dividends and
    /// divisors of every length up to the widest the engine divides (18
    /// and 10 limbs), with limbs drawn to hit the rare add-back step (a
    /// divisor of all-ones limbs and a top limb of 2^63) and the q̂ > 2^64
    /// case (equal top limbs).
    #[test]
    fn divmod_matches_the_bitwise_division() {
        let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
        for case in 0..40_000 {
            let m = 1 + (case % 18);
            let n = 1 + (rng.next() as usize % 11);
            let mut num = [0_u64; 18];
            let mut den = [0_u64; 10];
            for x in num.iter_mut().take(m) {
                *x = rng.limb();
            }
            for x in den.iter_mut().take(n.min(10)) {
                *x = rng.limb();
            }
            if case % 7 == 0 {
                // Equal leading limbs: q̂ from the top two limbs exceeds 2^64 − 1.
                let dn = limbs_bits(&den).div_ceil(64);
                if dn > 0 && dn <= m {
                    num[m - 1] = den[dn - 1];
                }
            }
            if limbs_bits(&den) == 0 {
                continue;
            }
            let (num, den) = (&num[..m], &den[..]);
            let (mut q1, mut r1) = ([0_u64; 18], [0_u64; 11]);
            let (mut q2, mut r2) = ([0_u64; 18], [0_u64; 11]);
            limbs_divmod(num, den, &mut q1[..m], &mut r1);
            limbs_divmod_bits(num, den, &mut q2[..m], &mut r2);
            assert_eq!((q1, r1), (q2, r2), "{num:x?} / {den:x?}");
            // q·den + r = num, and r < den, checked without the oracle.
            let mut back = [0_u64; 29];
            limbs_mul(&q1[..m], den, &mut back);
            assert!(!limbs_add(&mut back, &r1));
            assert_eq!(limbs_cmp(&back, num), Ordering::Equal);
            assert_eq!(limbs_cmp(&r1, den), Ordering::Less);
        }
    }

    /// The add-back step (D6), which random limbs almost never reach
    /// (probability about 2/2^64): the cases of Hacker's Delight's `divmnu`
    /// tests marked "add back required", with its 16-bit digits scaled to
    /// 64 bits (0x8000 → 2^63, 0x7fff → 2^63 − 1, 0xffff → 2^64 − 1,
    /// 0xfffe → 2^64 − 2), each checked against the restoring division and
    /// counted.
    #[test]
    fn divmod_add_back() {
        const H: u64 = 1 << 63;
        const M: u64 = u64::MAX;
        let cases: [(&[u64], &[u64]); 3] =
            [(&[3, 0, H], &[1, 0, H >> 2]), (&[0, 0, H, H - 1], &[1, 0, H]), (&[0, M - 1, 0, H], &[M, 0, H])];
        let before = ADD_BACKS.load(core::sync::atomic::Ordering::Relaxed);
        for (num, den) in cases {
            let (mut q1, mut r1) = ([0_u64; 4], [0_u64; 4]);
            let (mut q2, mut r2) = ([0_u64; 4], [0_u64; 4]);
            let m = num.len();
            limbs_divmod(num, den, &mut q1[..m], &mut r1[..=den.len()]);
            limbs_divmod_bits(num, den, &mut q2[..m], &mut r2[..=den.len()]);
            assert_eq!((q1, r1), (q2, r2), "{num:x?} / {den:x?}");
        }
        let after = ADD_BACKS.load(core::sync::atomic::Ordering::Relaxed);
        assert!(after > before, "no case reached the add-back step");
    }

    type F = Fixed<FAST>;
    type S = Fixed<SLOW>;

    /// The interval contains `num / 10^digits` within one unit of the last
    /// decimal, and is narrower than `10^-digits`: `lo·10^d ≤ num + 1`,
    /// `hi·10^d ≥ num`, `(hi − lo)·10^d < 1`.
    fn encloses_decimal<const N: usize>(iv: &Interval<N>, digits: &str) {
        let (int, frac) = digits.split_once('.').unwrap();
        let text: String = [int, frac].concat();
        let num: i128 = text.parse().unwrap();
        let scale = |x: &Fixed<N>| {
            let mut v = *x;
            for _ in 0..frac.len() {
                v = v.mul_int(10).unwrap();
            }
            v
        };
        let (lo, hi) = (scale(iv.lower()), scale(iv.upper()));
        assert!(lo.floor() <= num + 1, "lower end too high for {digits}");
        assert!(hi.ceil().unwrap() >= num, "upper end too low for {digits}");
        let width = hi.checked_sub(&lo).unwrap();
        assert_eq!(width.floor(), 0, "interval too wide for {digits}");
    }

    #[test]
    fn fixed_point_basics() {
        let three = F::from_int(3);
        let two = F::from_int(2);
        assert_eq!(three.checked_add(&two).unwrap().floor(), 5);
        assert_eq!(two.checked_sub(&three).unwrap().floor(), -1);
        let m = F::from_int(-7);
        assert_eq!(m.floor(), -7);
        assert_eq!(m.ceil(), Some(-7));
        assert!(m.is_negative());
        assert_eq!(m.checked_neg().unwrap(), F::from_int(7));
        // 7 / 2 = 3.5: floor 3, ceil 4, exact.
        let q = F::from_int(7).div_round(&two, RoundDirection::Down).unwrap();
        assert_eq!(q, F::from_int(7).div_round(&two, RoundDirection::Up).unwrap());
        assert_eq!((q.floor(), q.ceil()), (3, Some(4)));
        // −7 / 2 = −3.5.
        let q = m.div_round(&two, RoundDirection::Down).unwrap();
        assert_eq!((q.floor(), q.ceil()), (-4, Some(-3)));
        // 1/3 is inexact: the two roundings differ by one unit.
        let d = F::from_int(1).div_round(&three, RoundDirection::Down).unwrap();
        let u = F::from_int(1).div_round(&three, RoundDirection::Up).unwrap();
        assert_eq!(u.checked_sub(&d).unwrap(), F::from_ulps(1));
        let d = F::from_int(-1).div_round(&three, RoundDirection::Down).unwrap();
        let u = F::from_int(-1).div_round(&three, RoundDirection::Up).unwrap();
        assert_eq!(u.checked_sub(&d).unwrap(), F::from_ulps(1));
        // Products: exact for dyadic results, one unit apart otherwise.
        let h = F::half();
        assert_eq!(h.mul_round(&h, RoundDirection::Down), h.mul_round(&h, RoundDirection::Up));
        assert_eq!(
            h.mul_round(&m, RoundDirection::Down).unwrap(),
            F::from_int(-7).div_small(2, RoundDirection::Down).unwrap()
        );
        let tiny = F::from_ulps(1);
        assert_eq!(tiny.mul_round(&tiny, RoundDirection::Down).unwrap(), F::zero());
        assert_eq!(tiny.mul_round(&tiny, RoundDirection::Up).unwrap(), tiny);
        let ntiny = tiny.checked_neg().unwrap();
        assert_eq!(ntiny.mul_round(&tiny, RoundDirection::Down).unwrap(), ntiny);
        assert_eq!(ntiny.mul_round(&tiny, RoundDirection::Up).unwrap(), F::zero());
        // Overflow is reported, not wrapped.
        let big = F::from_int(i128::MAX >> 1);
        assert!(big.checked_add(&big).is_some());
        let top = F::from_int(1 << 126);
        assert!(top.checked_add(&top).is_none());
        assert!(top.checked_neg().unwrap().checked_sub(&top).is_some());
        assert!(top
            .checked_neg()
            .unwrap()
            .checked_sub(&top)
            .unwrap()
            .checked_sub(&F::from_ulps(1))
            .is_none());
        assert!(big.mul_round(&two, RoundDirection::Down).is_some());
        assert!(big.mul_round(&three, RoundDirection::Down).is_none());
        assert!(big.mul_int(4).is_none());
        assert!(F::from_int(1).div_round(&F::zero(), RoundDirection::Up).is_none());
    }

    /// Division against multiplication on pseudo-random operands: the
    /// quotient's two roundings bracket the exact one and are one unit apart
    /// or equal, and q·b reproduces a within the rounding.
    #[test]
    fn division_brackets() {
        let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..2000 {
            let mut a = F::zero();
            let mut b = F::zero();
            for i in 0..FAST - 1 {
                a.l[i] = next();
                b.l[i] = next() >> (next() % 64);
            }
            a.l[FAST - 1] = next() >> 40;
            if next() % 2 == 0 {
                a = a.checked_neg().unwrap();
            }
            if b.is_zero() {
                continue;
            }
            let (Some(d), Some(u)) =
                (a.div_round(&b, RoundDirection::Down), a.div_round(&b, RoundDirection::Up))
            else {
                continue;
            };
            let gap = u.checked_sub(&d).unwrap();
            assert!(gap == F::zero() || gap == F::from_ulps(1));
            // d·b ≤ a ≤ u·b (b > 0), checked with exact products.
            let lo = d.mul_round(&b, RoundDirection::Down).unwrap();
            let hi = u.mul_round(&b, RoundDirection::Up).unwrap();
            assert_ne!(lo.cmp_signed(&a), Ordering::Greater);
            assert_ne!(hi.cmp_signed(&a), Ordering::Less);
        }
    }

    #[test]
    fn interval_decisions() {
        let p = Interval::<FAST>::int(5).div_int(2);
        assert!(p.is_point());
        assert_eq!(p.round(Rounding::Floor), Some(2));
        assert_eq!(p.round(Rounding::Ceil), Some(3));
        // Ties go up.
        assert_eq!(p.round(Rounding::Nearest), Some(3));
        let n = p.neg();
        assert_eq!(n.round(Rounding::Nearest), Some(-2));
        assert_eq!(n.round(Rounding::Floor), Some(-3));
        assert_eq!(n.round(Rounding::Ceil), Some(-2));
        // An interval straddling an integer decides nearest but not floor.
        let s = Interval::new(F::from_int(2).checked_sub(&F::from_ulps(1)).unwrap(), F::from_int(2));
        assert_eq!(s.round(Rounding::Floor), None);
        assert_eq!(s.round(Rounding::Ceil), Some(2));
        assert_eq!(s.round(Rounding::Nearest), Some(2));
        assert_eq!(s.sign(), Some(Ordering::Greater));
        let z = Interval::new(F::from_ulps(1).checked_neg().unwrap(), F::from_ulps(1));
        assert_eq!(z.sign(), None);
        assert_eq!(Interval::<FAST>::int(0).sign(), Some(Ordering::Equal));
        assert_eq!(Interval::<FAST>::int(-3).sign(), Some(Ordering::Less));
        assert_eq!(Interval::<FAST>::poison().round(Rounding::Floor), None);
        // Exact zero times anything is an exact zero.
        let third = Interval::<FAST>::int(1).div_int(3);
        assert!(!third.is_point());
        assert!(Interval::<FAST>::int(0).mul(&third).is_point());
        assert!(third.neg().mul(&Interval::int(0)).is_point());
        // Mixed signs.
        let m = Interval::new(F::from_int(-2), F::from_int(3))
            .mul(&Interval::new(F::from_int(-5), F::from_int(4)));
        assert_eq!((m.lower().floor(), m.upper().floor()), (-15, 12));
        // Division by an interval containing 0 is poisoned.
        assert!(!third.div(&z).is_valid());
    }

    /// R-G75TIE: one boundary in the enclosure decides on it; two do not.
    #[test]
    fn tie_decisions() {
        let ulp = F::from_ulps(1);
        let around = |v: F| Interval::new(v.checked_sub(&ulp).unwrap(), v.checked_add(&ulp).unwrap());
        let two = F::from_int(2);
        // An integer inside: floor and ceil give it.
        let i = around(two);
        assert_eq!((i.round(Rounding::Floor), i.round(Rounding::Ceil)), (None, None));
        assert_eq!(i.round_tie(Rounding::Floor), Some(2));
        assert_eq!(i.round_tie(Rounding::Ceil), Some(2));
        assert_eq!(i.round_tie(Rounding::Nearest), Some(2));
        // On an end: [2 − ulp, 2] and [2, 2 + ulp].
        let below = Interval::new(two.checked_sub(&ulp).unwrap(), two);
        assert_eq!(below.round(Rounding::Floor), None);
        assert_eq!(below.round_tie(Rounding::Floor), Some(2));
        let above = Interval::new(two, two.checked_add(&ulp).unwrap());
        assert_eq!(above.round(Rounding::Ceil), None);
        assert_eq!(above.round_tie(Rounding::Ceil), Some(2));
        // A half-integer: nearest goes up, on both sides of 0.
        let h = around(*Interval::<FAST>::int(3).div_int(2).lower());
        assert_eq!(h.round(Rounding::Nearest), None);
        assert_eq!(h.round_tie(Rounding::Nearest), Some(2));
        assert_eq!(h.round_tie(Rounding::Floor), Some(1));
        let nh = around(*Interval::<FAST>::int(-5).div_int(2).lower());
        assert_eq!(nh.round_tie(Rounding::Nearest), Some(-2));
        assert_eq!(nh.round_tie(Rounding::Ceil), Some(-2));
        // Two boundaries: refused.
        let wide = Interval::new(F::from_int(1), F::from_int(2));
        assert_eq!(wide.round_tie(Rounding::Floor), None);
        assert_eq!(wide.round_tie(Rounding::Ceil), None);
        let halves = Interval::new(
            F::from_int(1).checked_sub(&F::half()).unwrap(),
            F::from_int(1).checked_add(&F::half()).unwrap(),
        );
        assert_eq!(halves.round_tie(Rounding::Nearest), None);
        assert_eq!(halves.round_tie(Rounding::Floor), Some(1));
        assert_eq!(Interval::<FAST>::poison().round_tie(Rounding::Floor), None);
        // Signs: 0 inside or on an end is 0; decided signs stay.
        assert_eq!(around(F::zero()).sign_tie(), Some(Ordering::Equal));
        assert_eq!(Interval::new(F::zero(), ulp).sign_tie(), Some(Ordering::Equal));
        assert_eq!(Interval::new(ulp, two).sign_tie(), Some(Ordering::Greater));
        assert_eq!(Interval::<FAST>::int(-1).sign_tie(), Some(Ordering::Less));
        assert_eq!(Interval::<FAST>::poison().sign_tie(), None);
        // The identity tan 30°·sin 60° = 1/2 at 512 bits.
        let t = tan::<SLOW>(600_000).mul(&sin::<SLOW>(1_200_000));
        assert_eq!(t.round(Rounding::Nearest), None);
        assert_eq!(t.mul_int(2).round(Rounding::Floor), None);
        assert_eq!(t.mul_int(2).round_tie(Rounding::Floor), Some(1));
        assert_eq!(t.round_tie(Rounding::Nearest), Some(1));
    }

    #[test]
    fn exact_trigonometric_cases() {
        assert!(sin::<FAST>(0).is_point() && sin::<FAST>(0).round(Rounding::Floor) == Some(0));
        assert_eq!(sin::<FAST>(600_000), Interval::half());
        assert_eq!(sin::<FAST>(RIGHT), Interval::int(1));
        assert_eq!(cos::<FAST>(0), Interval::int(1));
        assert_eq!(cos::<FAST>(1_200_000), Interval::half());
        assert_eq!(cos::<FAST>(RIGHT), Interval::int(0));
        assert_eq!(tan::<FAST>(0), Interval::int(0));
        assert_eq!(tan::<FAST>(900_000), Interval::int(1));
        assert_eq!(cot::<FAST>(900_000), Interval::int(1));
        assert_eq!(cot::<FAST>(RIGHT), Interval::int(0));
        assert!(!tan::<FAST>(RIGHT).is_valid());
        assert!(!cot::<FAST>(0).is_valid());
        assert_eq!(tan_cot::<SLOW>(900_000), (Interval::int(1), Interval::int(1)));
        // Non-exact values are proper intervals.
        assert!(!sin::<FAST>(1_200_000).is_point());
        assert!(!cos::<FAST>(600_000).is_point());
        assert!(!tan::<FAST>(600_000).is_point());
    }

    #[test]
    fn trigonometric_values() {
        // 1° = 20 000 units of 0.00005°.
        encloses_decimal(&sin::<FAST>(20_000), "0.017452406437283512819418978516316");
        encloses_decimal(&sin::<SLOW>(20_000), "0.017452406437283512819418978516316");
        encloses_decimal(&cos::<FAST>(900_000), "0.70710678118654752440084436210484");
        encloses_decimal(&sin::<FAST>(900_000), "0.70710678118654752440084436210484");
        encloses_decimal(&cos::<SLOW>(900_000), "0.70710678118654752440084436210484");
        // 45° together: one series for both.
        let (s, c) = sin_cos::<FAST>(900_000);
        encloses_decimal(&s, "0.70710678118654752440084436210484");
        encloses_decimal(&c, "0.70710678118654752440084436210484");
        let (s, c) = sin_cos::<SLOW>(900_000);
        encloses_decimal(&s, "0.70710678118654752440084436210484");
        encloses_decimal(&c, "0.70710678118654752440084436210484");
        // sin 60° = cos 30° = √3/2, tan 30° = 1/√3, tan 60° = √3.
        encloses_decimal(&sin::<FAST>(1_200_000), "0.86602540378443864676372317075293");
        encloses_decimal(&cos::<SLOW>(600_000), "0.86602540378443864676372317075293");
        encloses_decimal(&tan::<FAST>(600_000), "0.57735026918962576450914878050195");
        encloses_decimal(&cot::<SLOW>(600_000), "1.7320508075688772935274463415058");
        // Near the ends of the range: cot 0.0001° and tan 89.99995°.
        encloses_decimal(&cot::<FAST>(2), "572957.79513024143235064998");
        encloses_decimal(&tan::<FAST>(RIGHT - 1), "1145915.59026135552932729735");
        // sin 30° from the series agrees with the exact 1/2.
        let s = sin_cos_series::<FAST>(600_000).0;
        // ... but the series alone cannot decide its rounding: that is why
        // the exact cases exist.
        assert_eq!(s.round(Rounding::Nearest), None);
        assert!(s.lower().floor() == 0 && s.upper().ceil() == Some(1));
        // Widths: the fast path keeps more than 118 bits, the slow more than 500.
        let w = |iv: &Interval<FAST>| iv.upper().checked_sub(iv.lower()).unwrap();
        assert!(w(&sin::<FAST>(123_457)).cmp_signed(&Fixed::from_ulps(1 << 10)) == Ordering::Less);
        let ws = sin::<SLOW>(123_457);
        let ws = ws.upper().checked_sub(ws.lower()).unwrap();
        assert!(ws.cmp_signed(&Fixed::from_ulps(1 << 10)) == Ordering::Less);
        // sin² + cos² = 1 within the widths.
        for k in [1, 7, 20_000, 333_333, 900_001, 1_799_999] {
            let (s, c) = sin_cos::<FAST>(k);
            let one = s.mul(&s).add(&c.mul(&c));
            assert_eq!(one.round(Rounding::Nearest), Some(1));
            assert!(one.lower().floor() <= 1 && one.upper().ceil() >= Some(1));
        }
    }

    #[test]
    fn logarithms_and_exponentials() {
        // ln 2, ln 10, e, e^(1/2), e^20 (published constants; the helper
        // checks the enclosure holds the digits and is narrower than them).
        encloses_decimal(&ln::<FAST>(2), "0.693147180559945309417232121458");
        encloses_decimal(&ln::<SLOW>(2), "0.69314718055994530941723212145817656807");
        encloses_decimal(&ln::<FAST>(10), "2.302585092994045684017991454684");
        encloses_decimal(&ln::<SLOW>(1_000_000_007), "20.723265843946411131661923206492610601");
        encloses_decimal(&exp(&Interval::<FAST>::int(1)), "2.718281828459045235360287471352");
        encloses_decimal(&exp(&Interval::<SLOW>::half()), "1.6487212707001281468486507878141635716");
        encloses_decimal(&exp(&Interval::<FAST>::int(20)), "485165195.409790277969106830");
        assert_eq!(ln::<FAST>(1), Interval::int(0));
        assert!(!ln::<FAST>(0).is_valid() && !ln::<FAST>(1 << 63).is_valid());
        assert!(ln::<FAST>((1 << 63) - 1).is_valid());
        // exp(ln n) = n within the widths, at both precisions.
        for n in [3_u64, 1000, 4_294_967_297] {
            assert_eq!(exp(&ln::<FAST>(n)).round(Rounding::Nearest), Some(i128::from(n)));
            assert_eq!(exp(&ln::<SLOW>(n)).round(Rounding::Nearest), Some(i128::from(n)));
        }
        // Outside the domain, and too large a result: poisoned.
        assert!(!exp(&Interval::<FAST>::int(-1)).is_valid());
        assert!(!exp(&Interval::<FAST>::poison()).is_valid());
        assert!(!exp(&Interval::<FAST>::int(100)).is_valid());
        assert!(exp(&Interval::<FAST>::int(87)).is_valid());
        // The widths: the fast power of a value below 2^33 keeps about 80
        // bits, the slow one about 460.
        let w = |iv: &Interval<FAST>| iv.upper().checked_sub(iv.lower()).unwrap();
        let p = power::<FAST>(4_294_967_297, 10_000, 10_001);
        assert!(w(&p).cmp_signed(&F::from_ulps(1 << 50)) == Ordering::Less);
        let p = power::<SLOW>(4_294_967_297, 10_000, 10_001);
        let ws = p.upper().checked_sub(p.lower()).unwrap();
        assert!(ws.cmp_signed(&S::from_ulps(1 << 50)) == Ordering::Less);
    }

    #[test]
    fn integer_roots() {
        assert_eq!(integer_root(1, 2), Some(1));
        assert_eq!(integer_root(u64::MAX, 2), None);
        assert_eq!(integer_root(4_294_967_295 * 4_294_967_295, 2), Some(4_294_967_295));
        assert_eq!(integer_root(1 << 62, 62), Some(2));
        assert_eq!(integer_root(1 << 62, 63), None);
        assert_eq!(integer_root(3_486_784_401, 20), Some(3));
        assert_eq!(integer_root(3_486_784_402, 20), None);
        assert_eq!(
            (gcd_u32(10_000, 15_000), gcd_u32(0, 0), gcd_u32(7, 0), gcd_u32(u32::MAX, u32::MAX - 1)),
            (5_000, 1, 7, 1)
        );
    }

    #[test]
    fn changes_of_precision() {
        let third = Interval::<SLOW>::int(-1).div_int(3);
        let fast: Interval<FAST> = third.at_precision();
        // The narrowed enclosure holds the wider one.
        let back: Interval<SLOW> = fast.at_precision();
        assert_ne!(back.lower().cmp_signed(third.lower()), Ordering::Greater);
        assert_ne!(back.upper().cmp_signed(third.upper()), Ordering::Less);
        assert_eq!(fast, Interval::<FAST>::int(-1).div_int(3));
        // Exact values stay exact both ways; poison stays poison.
        assert_eq!(Interval::<SLOW>::int(-5).div_int(4).at_precision::<FAST>(), Interval::int(-5).div_int(4));
        assert!(!Interval::<SLOW>::poison().at_precision::<FAST>().is_valid());
        let big = Interval::<FAST>::int(i128::MAX >> 1);
        assert_eq!(big.at_precision::<SLOW>().at_precision::<FAST>(), big);
    }

    /// `atan(1/m)` enclosed by its alternating series at the precision `N`.
    fn atan_inv<const N: usize>(m: u64) -> Interval<N> {
        let m2 = m * m;
        let mut power = Interval::<N>::int(1).div_int(m); // 1/m^(2j+1)
        let mut sum = power;
        let mut j: u64 = 1;
        loop {
            power = power.div_int(m2);
            let term = power.div_int(2 * j + 1);
            if term.upper().cmp_signed(&Fixed::from_ulps(4)) != Ordering::Greater {
                let hi = *term.upper();
                return sum.add(&Interval::new(hi.checked_neg().unwrap(), hi));
            }
            sum = if j % 2 == 1 { sum.sub(&term) } else { sum.add(&term) };
            j += 1;
        }
    }

    /// The hard-coded digits of π against Machin's formula at 704 fraction
    /// bits: all 640 bits of [`PI_FRACTION`] are decided and equal.
    #[test]
    fn pi_matches_machin() {
        const N: usize = 13; // 704 fraction bits
        let machin = atan_inv::<N>(5).mul_int(16).sub(&atan_inv::<N>(239).mul_int(4));
        assert!(machin.is_valid());
        let words = |x: &Fixed<N>| -> Vec<u64> {
            // Fraction limbs 10..=1 (most significant first) hold bits 1..640.
            (0..10).map(|i| x.limbs()[Fixed::<N>::FRAC - 1 - i]).collect()
        };
        assert_eq!(machin.lower().floor(), 3);
        assert_eq!(machin.upper().floor(), 3);
        assert_eq!(words(machin.lower()), PI_FRACTION.to_vec());
        assert_eq!(words(machin.upper()), PI_FRACTION.to_vec());
        // And pi() at both engine precisions encloses it.
        let p = pi::<SLOW>();
        assert_eq!(p.upper().checked_sub(p.lower()).unwrap(), Fixed::from_ulps(1));
        assert_eq!(
            p.lower().limbs()[..8],
            [
                PI_FRACTION[7],
                PI_FRACTION[6],
                PI_FRACTION[5],
                PI_FRACTION[4],
                PI_FRACTION[3],
                PI_FRACTION[2],
                PI_FRACTION[1],
                PI_FRACTION[0]
            ]
        );
        encloses_decimal(&pi::<FAST>(), "3.14159265358979323846264338327950288");
        let _ = S::zero();
    }
}
