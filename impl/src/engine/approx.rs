//! The fast path of the LinuxCNC G76 and G75.1 engines (issue 33, reading
//! R-FASTPATH in `docs/INTERPRETATIONS.md`): each value an engine rounds is first
//! computed in 64-bit fixed point with a rigorous bound on its error, and
//! rounded from there when no rounding boundary lies within the bound
//! (Ziv's strategy); otherwise the caller falls back to the exact interval
//! arithmetic of [`crate::engine::real`].
//!
//! # Numbers
//!
//! An [`Approx`] is a value `v · 2^-64` (`v` an `i128`) and a bound `e`
//! (a `u128`, in the same units of `2^-64`, the "ulps" below) with the
//! invariant `|x − v·2^-64| ≤ e·2^-64` for the exact real `x` it stands
//! for. Every operation keeps the invariant: additions, subtractions and
//! products by an integer are exact and add the bounds; a product of two
//! [`Approx`] truncates once (one ulp) and adds the propagated bounds
//! (`|a|·e_b + |b|·e_a + e_a·e_b`, rounded up). An overflow makes the
//! value unknown ([`Approx::UNKNOWN`], a bound of `u128::MAX`), on which
//! every decision is undecided. Integers only: no floating point, as in
//! the rest of the engine, so each error bound is an exact integer
//! inequality.
//!
//! # Decisions
//!
//! [`Approx::round_half_away`] returns `k` only when the whole enclosure
//! `[v − e, v + e]` lies strictly inside `(k − 1/2, k + 1/2)`: then every
//! real of the enclosure, the exact value among them, rounds to `k`
//! (nearest, ties away from zero), and no tie can be inside; or when the
//! value is exact (`e = 0`), as R-LCNC-EXACT rounds it (a half increment
//! away from zero).
//! [`Approx::sign`] decides `x > 0` when `v − e > 0`, `x < 0` when `v + e
//! < 0`, and `x = 0` only for the exact zero (`v = e = 0`). These are
//! comparisons of integers, exact. Whatever they decide is the rounding
//! of the exact value, which the interval path also returns (it decides
//! the same value, and falls back to R-G75TIE only within `2^-512` of a
//! boundary, where the bound here never decides): the answers are the
//! same, and the tests compare both paths.
//!
//! # The power `n^(a/b)` ([`power`])
//!
//! `n^(a/b) = 2^k · exp(r)` with `x = (a/b)·ln n`, `k = ⌊x / ln 2⌋` and
//! `r = x − k·ln 2 ∈ [0, ln 2)`; `ln n = f·ln 2 + 2 atanh(s)`, `s = (n −
//! 2^f)/(n + 2^f)`, `f` chosen so that `n/2^f ∈ [3/4, 3/2)` and `|s| ≤
//! 1/5`. The bounds, in ulps of `2^-64` (derived in R-FASTPATH and
//! checked at their worst cases by the tests):
//!
//! * `atanh`: 14 terms `s^(2j+1)/(2j+1)`, each truncated; error below 28
//!   ulps (the rest of the series is below `2^-72`);
//! * `ln n`: `2·28 + f` (`ln 2` truncated to 64 bits, `f ≤ 63`): below
//!   119, taken as [`LN_BOUND`] = 128 (for `n <` [`LN_TABLE_LEN`] the
//!   series' value is read from a table built at compile time by the
//!   same series: the same value and bound);
//! * `x = ⌊ln n · a / b⌋`: below 129;
//! * `r`: below `129 + k ≤ 192`;
//! * `exp(r)`: 20 terms `r^i/i!`, each truncated twice; below 71 ulps of
//!   the series, plus `e^r·|Δr| ≤ 2.0001 · 192` from the error of `r`:
//!   below 456, taken as [`EXP_BOUND`] = 1024;
//! * `n^(a/b) = 2^k · exp(r)`: below `1024 · 2^k` ulps, i.e. a relative
//!   error below `2^-54`.
//!
//! # Sine and cosine ([`sin_cos`], for G75.1)
//!
//! The exact cases of `docs/G75.md` §6 exactly; above 45° from the
//! complement; for `0 < x ≤ π/4` the series `Σ ±x^(2j+s)/(2j+s)!` (j ≤ 10)
//! in integers, every step truncated, below the exact value's terms by a
//! sum under 13 ulps (taken as [`SIN_COS_BOUND`] = 16; R-FASTPATH derives
//! it, `sin_cos_bound_at_its_worst_cases` measures 3). Quotients
//! ([`Approx::div`]) give tan and cot.
//!
//! An exact power (`n = 1` or `a = b`) is an exact integer (bound 0); other
//! exact powers (`n = r^b`) are enclosed like any value, so that a depth
//! exactly on K (R-LCNC-TIE) is undecided here and decided by the
//! interval path.

use core::cmp::Ordering;

use crate::engine::linuxcnc::mul_wide;
use crate::engine::real::{Interval, Rounding, HALF_TURN, PI_FRACTION, RIGHT};

/// `⌊ln 2 · 2^64⌋`: `ln 2 = 0.B17217F7D1CF79AB C9E3…` (hexadecimal); the
/// truncation is below `ln 2` by less than one ulp (the test
/// `ln2_constant` checks it against the interval arithmetic's `ln 2`).
pub const LN2: u128 = 0xB172_17F7_D1CF_79AB;

/// The bound of `ln n`, in ulps of `2^-64` (R-FASTPATH: below 119).
pub const LN_BOUND: u128 = 128;

/// The bound of `exp(r)` computed from `r = x − k·ln 2`, in ulps of
/// `2^-64` (R-FASTPATH: below 456).
pub const EXP_BOUND: u128 = 1024;

/// Terms of the `atanh` series: `j = 0 … ATANH_TERMS − 1`.
const ATANH_TERMS: usize = 14;

/// Terms of the exponential's series: `i = 0 … EXP_TERMS − 1`.
const EXP_TERMS: usize = 20;

/// `⌊(2^64 − 1) / (2j + 1)⌋ = ⌊2^64 / (2j + 1)⌋` for `j ≥ 1` (index 0
/// unused): below `1/(2j+1)` by less than one ulp.
const INV_ODD: [u64; ATANH_TERMS] = {
    let mut t = [0_u64; ATANH_TERMS];
    let mut j = 1;
    while j < ATANH_TERMS {
        t[j] = u64::MAX / (2 * j as u64 + 1);
        j += 1;
    }
    t
};

/// `⌊(2^64 − 1) / i⌋` for `i ≥ 2` (index 0 and 1 unused): below `1/i` by
/// at most one ulp.
const INV: [u64; EXP_TERMS] = {
    let mut t = [0_u64; EXP_TERMS];
    let mut i = 2;
    while i < EXP_TERMS {
        t[i] = u64::MAX / i as u64;
        i += 1;
    }
    t
};

/// One in ulps of `2^-64`.
const ONE: i128 = 1 << 64;

/// A value and a rigorous bound on its error, both in units of `2^-64`
/// (module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Approx {
    v: i128,
    e: u128,
}

/// `⌊a·b / 2^64⌋`, exact in one product of 64-bit words.
const fn mul_hi(a: u64, b: u64) -> u64 {
    // a·b < 2^128: the high word.
    let p = (a as u128) * (b as u128);
    (p >> 64) as u64
}

/// `⌈a·b / 2^64⌉`, saturating.
fn mul_up(a: u128, b: u128) -> u128 {
    const M: u128 = u64::MAX as u128;
    // A factor below 2^64 (every bound in practice): two 64-bit products,
    // `a·b = a₁·b·2^64 + a₀·b` with `a₁·b < 2^128`; the same value.
    let (a, b) = if a <= M { (b, a) } else { (a, b) };
    if b <= M {
        let p = (a & M) * b;
        let q = (p >> 64) + u128::from(p & M != 0);
        return ((a >> 64) * b).saturating_add(q);
    }
    let (hi, lo) = mul_wide(a, b);
    let q = (lo >> 64) + u128::from(lo & u128::from(u64::MAX) != 0);
    if hi >> 64 != 0 {
        return u128::MAX;
    }
    (hi << 64).saturating_add(q)
}

impl Approx {
    /// The unknown value: every decision on it is undecided.
    pub const UNKNOWN: Approx = Approx { v: 0, e: u128::MAX };

    /// The integer `i`, exactly.
    #[must_use]
    pub const fn int(i: i64) -> Approx {
        Approx { v: (i as i128) << 64, e: 0 }
    }

    /// The value `v·2^-64` with the bound `e·2^-64` (the caller's claim).
    #[must_use]
    pub const fn new(v: i128, e: u128) -> Approx {
        Approx { v, e }
    }

    /// The value, in units of `2^-64`.
    #[must_use]
    pub const fn value(&self) -> i128 {
        self.v
    }

    /// The bound, in units of `2^-64`.
    #[must_use]
    pub const fn bound(&self) -> u128 {
        self.e
    }

    /// True for [`Approx::UNKNOWN`] (or any value whose bound is
    /// `u128::MAX`): nothing is decided on it, and every operation on it
    /// gives it again.
    #[must_use]
    pub const fn is_unknown(&self) -> bool {
        self.e == u128::MAX
    }

    /// The integer `i` (of any `i128`): exact when `|i| < 2^63`, unknown
    /// beyond.
    #[must_use]
    pub fn int_wide(i: i128) -> Approx {
        match i64::try_from(i) {
            Ok(i) if i != i64::MIN => Approx::int(i),
            _ => Approx::UNKNOWN,
        }
    }

    /// `1/2`, exactly.
    #[must_use]
    pub const fn half() -> Approx {
        Approx { v: ONE / 2, e: 0 }
    }

    /// The enclosure `[v − e, v + e]` as its two ends (`None` when unknown
    /// or when an end overflows).
    fn ends(&self) -> Option<(i128, i128)> {
        if self.is_unknown() {
            return None;
        }
        let e = i128::try_from(self.e).ok()?;
        Some((self.v.checked_sub(e)?, self.v.checked_add(e)?))
    }

    /// The value enclosed by `[lo, hi]` (`lo ≤ hi`): `v = lo`, `e = hi − lo`.
    fn from_ends(lo: i128, hi: i128) -> Approx {
        match hi.checked_sub(lo).and_then(|d| u128::try_from(d).ok()) {
            Some(e) => Approx::of(Some(lo), e),
            None => Approx::UNKNOWN,
        }
    }

    /// `−self`, exact.
    #[must_use]
    pub fn neg(&self) -> Approx {
        if self.is_unknown() {
            return Approx::UNKNOWN;
        }
        Approx::of(self.v.checked_neg(), self.e)
    }

    /// `max(self, o)`: the enclosure `[max(lo₁, lo₂), max(hi₁, hi₂)]`
    /// (as [`Interval::max`]).
    #[must_use]
    pub fn max(&self, o: &Approx) -> Approx {
        match (self.ends(), o.ends()) {
            (Some((l1, h1)), Some((l2, h2))) => Approx::from_ends(l1.max(l2), h1.max(h2)),
            _ => Approx::UNKNOWN,
        }
    }

    /// `min(self, o)`: the enclosure `[min(lo₁, lo₂), min(hi₁, hi₂)]`
    /// (as [`Interval::min`]).
    #[must_use]
    pub fn min(&self, o: &Approx) -> Approx {
        match (self.ends(), o.ends()) {
            (Some((l1, h1)), Some((l2, h2))) => Approx::from_ends(l1.min(l2), h1.min(h2)),
            _ => Approx::UNKNOWN,
        }
    }

    /// `self / o` for a divisor of magnitude at most 1 (`|v_o| ≤ 2^64`)
    /// that the bound keeps away from 0 (`|v_o| > e_o`); unknown otherwise
    /// (and when the quotient reaches `2^63`). The quotient `⌊|a|·2^64 /
    /// |b|⌋` with its sign (truncated, below one ulp; exact when the
    /// remainder is 0), the bound `⌈(e_a·2^64 + (|q| + 1)·e_b) / (|b| −
    /// e_b)⌉ + 1` (R-FASTPATH; 0 for an exact quotient of exact values).
    #[must_use]
    pub fn div(&self, o: &Approx) -> Approx {
        if self.is_unknown() || o.is_unknown() {
            return Approx::UNKNOWN;
        }
        let (a, b) = (self.v.unsigned_abs(), o.v.unsigned_abs());
        if b > 1 << 64 || b <= o.e {
            return Approx::UNKNOWN;
        }
        // |a|·2^64 / |b|, three 64-bit digits (b ≤ 2^64; b = 2^64 is 1).
        let (q, exact) = if b == 1 << 64 {
            (a, true)
        } else {
            let (hi, lo) = (a >> 64, a & u128::from(u64::MAX));
            let (q1, r1) = (hi / b, hi % b);
            let d2 = (r1 << 64) | lo;
            let (q2, r2) = (d2 / b, d2 % b);
            let d3 = r2 << 64;
            let (q3, r3) = (d3 / b, d3 % b);
            if q1 != 0 || q2 >> 63 != 0 {
                return Approx::UNKNOWN;
            }
            ((q2 << 64) | q3, r3 == 0)
        };
        let Ok(m) = i128::try_from(q) else {
            return Approx::UNKNOWN;
        };
        let v = if (self.v < 0) != (o.v < 0) { -m } else { m };
        if self.e == 0 && o.e == 0 {
            return Approx::of(Some(v), u128::from(!exact));
        }
        // The quotient's error: (e_a + |a/b|·e_b)/(|b| − e_b), in ulps.
        // e_a·2^64 (the shift drops bits only when e_a ≥ 2^64, refused).
        let num = (self.e < 1 << 64)
            .then_some(self.e << 64)
            .and_then(|ea| q.checked_add(1)?.checked_mul(o.e)?.checked_add(ea));
        match num {
            Some(n) => Approx::of(Some(v), n.div_ceil(b - o.e).saturating_add(1)),
            None => Approx::UNKNOWN,
        }
    }

    /// The rounding of every real of the enclosure `[v − e, v + e]`, when it
    /// is the same for all (as [`Interval::round`] decides on its ends);
    /// `None` when undecided or unknown.
    #[must_use]
    pub fn round(&self, r: Rounding) -> Option<i128> {
        let (lo, hi) = self.ends()?;
        let at = |x: i128| -> Option<i128> {
            match r {
                Rounding::Floor => Some(x >> 64),
                // ⌈x⌉ = −⌊−x⌋.
                Rounding::Ceil => Some(-(x.checked_neg()? >> 64)),
                Rounding::Nearest => Some(x.checked_add(ONE / 2)? >> 64),
            }
        };
        let (a, b) = (at(lo)?, at(hi)?);
        (a == b).then_some(a)
    }

    fn of(v: Option<i128>, e: u128) -> Approx {
        match v {
            Some(v) if e != u128::MAX => Approx { v, e },
            _ => Approx::UNKNOWN,
        }
    }

    /// `self + o`, exact.
    #[must_use]
    pub fn add(&self, o: &Approx) -> Approx {
        Approx::of(self.v.checked_add(o.v), self.e.saturating_add(o.e))
    }

    /// `self − o`, exact.
    #[must_use]
    pub fn sub(&self, o: &Approx) -> Approx {
        Approx::of(self.v.checked_sub(o.v), self.e.saturating_add(o.e))
    }

    /// `self · k`, exact.
    #[must_use]
    pub fn mul_int(&self, k: i64) -> Approx {
        if self.is_unknown() {
            return Approx::UNKNOWN;
        }
        Approx::of(self.v.checked_mul(i128::from(k)), self.e.saturating_mul(u128::from(k.unsigned_abs())))
    }

    /// `self / k` for `k > 0`: the quotient truncated (below one ulp), the
    /// bound divided and rounded up.
    #[must_use]
    pub fn div_int(&self, k: u64) -> Approx {
        if k == 0 || self.is_unknown() {
            return Approx::UNKNOWN;
        }
        if k == 1 {
            return *self;
        }
        // ξ = 2 (G7) by a shift: the floor, below one ulp as well.
        let (q, r) =
            if k == 2 { (self.v >> 1, self.v & 1) } else { (self.v / i128::from(k), self.v % i128::from(k)) };
        let e = self.e.div_ceil(u128::from(k)).saturating_add(u128::from(r != 0));
        Approx::of(Some(q), e)
    }

    /// `self · o`: the product truncated towards zero (below one ulp, and
    /// exact when no bit is cut), the bound `⌈(|a|·e_b + |b|·e_a + e_a·e_b)
    /// / 2^64⌉ + 1`, without the 1 when the product of the values is exact
    /// (so an exact 0 factor gives an exact 0).
    #[must_use]
    pub fn mul(&self, o: &Approx) -> Approx {
        if self.is_unknown() || o.is_unknown() {
            return Approx::UNKNOWN;
        }
        let (ma, mb) = (self.v.unsigned_abs(), o.v.unsigned_abs());
        let (hi, lo) = mul_wide(ma, mb);
        if hi >> 64 != 0 {
            return Approx::UNKNOWN;
        }
        let exact = lo & u128::from(u64::MAX) == 0;
        let Ok(m) = i128::try_from((hi << 64) | (lo >> 64)) else {
            return Approx::UNKNOWN;
        };
        let v = if (self.v < 0) != (o.v < 0) { -m } else { m };
        let e = if self.e == 0 && o.e == 0 {
            u128::from(!exact)
        } else {
            mul_up(ma, o.e)
                .saturating_add(mul_up(mb, self.e))
                .saturating_add(mul_up(self.e, o.e))
                .saturating_add(u128::from(!exact))
        };
        Approx::of(Some(v), e)
    }

    /// The exact value's rounding to the nearest integer, ties away from
    /// zero: for an exact value (`e = 0`), that rounding; otherwise when
    /// every real within the bound rounds alike and none is a tie, `Some(k)`
    /// only when `k − 1/2 < v − e` and `v + e < k + 1/2`.
    #[must_use]
    pub fn round_half_away(&self) -> Option<i128> {
        let half = ONE / 2;
        if self.e == 0 {
            // ⌊|v| + 1/2⌋ with the sign of v: a tie goes away from zero.
            let k = i128::try_from((self.v.unsigned_abs() + (1 << 63)) >> 64).ok()?;
            return Some(if self.v < 0 { -k } else { k });
        }
        let e = i128::try_from(self.e).ok()?;
        // k = ⌊v + 1/2⌋ (an arithmetic shift is a floor): the candidate.
        let k = self.v.checked_add(half)? >> 64;
        let centre = k.checked_mul(ONE)?;
        let (below, above) = (centre.checked_sub(half)?, centre.checked_add(half)?);
        (self.v.checked_sub(e)? > below && self.v.checked_add(e)? < above).then_some(k)
    }

    /// The exact value's sign, when the bound decides it (0 only for an
    /// exact zero).
    #[must_use]
    pub fn sign(&self) -> Option<Ordering> {
        let e = i128::try_from(self.e).ok()?;
        if self.v.checked_sub(e)? > 0 {
            Some(Ordering::Greater)
        } else if self.v.checked_add(e)? < 0 {
            Some(Ordering::Less)
        } else if self.v == 0 && e == 0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// An enclosure (of 64 fraction bits or more) as an [`Approx`]: the
    /// value is the lower end truncated to 64 fraction bits (a floor), the
    /// bound the distance to the upper end rounded up.
    #[must_use]
    pub fn enclosing<const N: usize>(iv: &Interval<N>) -> Approx {
        if !iv.is_valid() {
            return Approx::UNKNOWN;
        }
        // Limbs (two's complement, little-endian), the top two the integer
        // part: the value at 64 fraction bits is the top three, ⌊·⌋ (the
        // limbs below dropped), which fits an i128 when the top limb is
        // the sign extension of the next.
        let at64 = |l: &[u64; N]| -> Option<(i128, bool)> {
            let top = N.checked_sub(3)?;
            let (f, lo, hi) = (*l.get(top)?, *l.get(top + 1)?, *l.get(top + 2)?);
            let top_ok = (hi == 0 && lo >> 63 == 0) || (hi == u64::MAX && lo >> 63 == 1);
            if !top_ok {
                return None;
            }
            let bits = (u128::from(lo) << 64) | u128::from(f);
            let cut = l.get(..top).is_some_and(|below| below.iter().any(|&x| x != 0));
            Some((i128::from_le_bytes(bits.to_le_bytes()), cut))
        };
        let (Some((lo, _)), Some((hi, hi_cut))) = (at64(iv.lower().limbs()), at64(iv.upper().limbs())) else {
            return Approx::UNKNOWN;
        };
        let hi = if hi_cut { hi.checked_add(1) } else { Some(hi) };
        match hi.and_then(|h| h.checked_sub(lo)).and_then(|d| u128::try_from(d).ok()) {
            Some(e) => Approx::of(Some(lo), e),
            None => Approx::UNKNOWN,
        }
    }
}

/// `ln n` for `2 ≤ n < 2^63`, in ulps of `2^-64`, with its error below
/// [`LN_BOUND`] (R-FASTPATH); `None` outside the domain.
///
/// The value of [`ln_series`]: read from a table (which holds that
/// series' values, computed at compile time) for `n <` [`LN_TABLE_LEN`],
/// the depth laws' usual pass numbers, and computed for any larger `n`.
#[must_use]
pub fn ln(n: u64) -> Option<i128> {
    match usize::try_from(n).ok().and_then(|i| LN_TABLE.get(i)) {
        Some(&v) if n >= 2 => Some(v),
        _ => ln_series(n),
    }
}

/// How many values [`ln`]'s table holds (`n` from 0; 0 and 1 unused).
pub const LN_TABLE_LEN: usize = 256;

/// `ln_series(n)` for `2 ≤ n <` [`LN_TABLE_LEN`] (0 at 0 and 1, which
/// [`ln`] does not read): the same values, so the same bound
/// ([`LN_BOUND`]); the test `ln_table_is_the_series` compares them.
const LN_TABLE: [i128; LN_TABLE_LEN] = {
    let mut t = [0_i128; LN_TABLE_LEN];
    let mut n = 2;
    while n < LN_TABLE_LEN {
        if let Some(v) = ln_series(n as u64) {
            t[n] = v;
        }
        n += 1;
    }
    t
};

/// `ln n` for `2 ≤ n < 2^63` by its series (the error below [`LN_BOUND`],
/// R-FASTPATH); `None` outside the domain.
///
/// `n = 2^f · m` with `m ∈ [3/4, 3/2)`, `ln m = 2 atanh(s)`, `s = (n −
/// 2^f)/(n + 2^f)`, `|s| ≤ 1/5`: the series `Σ s^(2j+1)/(2j+1)` over
/// magnitudes, every step truncated (so every partial result is below the
/// exact one), then its sign. A `const fn` (so that [`ln`]'s table is
/// built at compile time); its loop has 13 rounds (14 terms).
#[must_use]
pub const fn ln_series(n: u64) -> Option<i128> {
    if n < 2 || n >> 63 != 0 {
        return None;
    }
    let e = 63 - n.leading_zeros();
    // n ≥ 3·2^(e−1) (m ≥ 3/2): divide by 2^(e+1) instead.
    let f = if n as u128 >= 3_u128 << (e - 1) { e + 1 } else { e };
    let (n, base) = (n as u128, 1_u128 << f);
    let (num, negative) = if n >= base { (n - base, false) } else { (base - n, true) };
    // num ≤ 2^(f−1) ≤ 2^62: num·2^64 < 2^127; den < 2^65; s < 2^64/5.
    let s = (num << 64) / (n + base);
    if s > u64::MAX as u128 {
        return None;
    }
    let s = s as u64;
    let q = mul_hi(s, s);
    // Each term below s < 2^64, 14 of them: the sum stays below 2^68.
    let (mut power, mut sum) = (s, s as i128);
    let mut j = 1;
    while j < ATANH_TERMS {
        power = mul_hi(power, q);
        sum += mul_hi(power, INV_ODD[j]) as i128;
        j += 1;
    }
    // LN2 < 2^64 and f ≤ 64: f·LN2 < 2^71.
    let base_ln = (LN2 as u64) as i128 * f as i128;
    if negative {
        base_ln.checked_sub(2 * sum)
    } else {
        base_ln.checked_add(2 * sum)
    }
}

/// `exp(r)` for `0 ≤ r < ln 2` given in ulps of `2^-64` (the series `Σ
/// r^i/i!` to `i = 19`, every step truncated): below the exact value by
/// less than 71 ulps (R-FASTPATH).
fn exp_unit(r: u128) -> Option<u128> {
    let r = u64::try_from(r).ok()?;
    // Terms 0 and 1 exactly (1 and r), then ⌊⌊term·r⌋ · ⌊(2^64 − 1)/i⌋⌋.
    let (mut term, mut sum) = (r, (1_u128 << 64) + u128::from(r));
    let mut loops = crate::loop_counters::count!(REAL_EXP);
    for inv in INV.iter().skip(2) {
        loops.tick();
        term = mul_hi(mul_hi(term, r), *inv);
        sum += u128::from(term);
    }
    Some(sum)
}

/// `n^(a/b)` for `1 ≤ n < 2^63`, `0 < a ≤ b` (the depth law `n^(1/R)`),
/// with its bound (R-FASTPATH): exact for `n = 1` and `a = b`, otherwise
/// `2^k · exp(r)` with a bound of `EXP_BOUND · 2^k` ulps (a relative error
/// below `2^-54`). Unknown outside the domain.
#[must_use]
pub fn power(n: u64, a: u32, b: u32) -> Approx {
    if n == 0 || n >> 63 != 0 || a == 0 || a > b {
        return Approx::UNKNOWN;
    }
    if n == 1 || a == b {
        return i64::try_from(n).map_or(Approx::UNKNOWN, Approx::int);
    }
    power_inexact(n, a, b).unwrap_or(Approx::UNKNOWN)
}

fn power_inexact(n: u64, a: u32, b: u32) -> Option<Approx> {
    let l = u128::try_from(ln(n)?).ok()?;
    // ln n < 44: l < 2^70, a < 2^32: no overflow.
    let x = l.checked_mul(u128::from(a))? / u128::from(b);
    // k = ⌊x / LN2⌋: estimated in 64-bit words (x < 2^70), then corrected.
    let estimate = u64::try_from(x >> 8).ok()? / u64::try_from(LN2 >> 8).ok()?;
    let mut k = u128::from(estimate);
    let mut r = i128::try_from(x).ok()? - i128::try_from(k.checked_mul(LN2)?).ok()?;
    let ln2 = i128::try_from(LN2).ok()?;
    if r < 0 {
        k = k.checked_sub(1)?;
        r += ln2;
    } else if r >= ln2 {
        k += 1;
        r -= ln2;
    }
    let r = u128::try_from(r).ok().filter(|&r| r < LN2)?;
    let k = u32::try_from(k).ok().filter(|&k| k < 64)?;
    let s = exp_unit(r)?;
    // s < 2^66 (exp r < 2): s·2^k must stay below 2^127.
    if s.leading_zeros() <= k + 1 {
        return None;
    }
    let v = i128::try_from(s << k).ok()?;
    let e = EXP_BOUND << k;
    Some(Approx { v, e })
}

/// `⌊π·2^64⌋`: 3 and the first 64 fraction bits of [`PI_FRACTION`] (below
/// π by less than one ulp).
const PI: u128 = (3 << 64) | PI_FRACTION[0] as u128;

/// The bound of [`sin_cos`]'s series values, in ulps of `2^-64`
/// (R-FASTPATH: below 13).
pub const SIN_COS_BOUND: u128 = 16;

/// Terms of the sine and cosine series: `j = 0 … TRIG_TERMS − 1`.
const TRIG_TERMS: u64 = 11;

/// 45° in the angle unit of [`crate::engine::real`] (0.00005°).
const EIGHTH: u32 = RIGHT / 2;

/// `sin x` and `cos x` of `x = k·π/3 600 000` for `0 < k ≤ 900 000` (0° to
/// 45°), each below the exact value's magnitude terms by a sum the bound
/// [`SIN_COS_BOUND`] covers (R-FASTPATH: below 13 ulps).
///
/// `X = ⌊⌊π·2^64⌋·k / 3 600 000⌋` (below `x` by < 1.25 ulps), `Q =
/// ⌊X²/2^64⌋` (below `x²` by < 3), the terms `T_j = ⌊⌊T_(j−1)·Q/2^64⌋ /
/// ((2j + s − 1)(2j + s))⌋` from `T_0 = X` (sine, s = 1) or `2^64` (cosine,
/// s = 0), summed with alternating signs.
fn sin_cos_series(k: u32) -> (Approx, Approx) {
    // X < π/4 · 2^64 < 2^64: every product below fits a u128.
    let x = PI * u128::from(k) / u128::from(HALF_TURN);
    let q = (x * x) >> 64;
    let series = |first: u128, s: u64| -> Option<Approx> {
        let (mut term, mut sum) = (first, i128::try_from(first).ok()?);
        let mut loops = crate::loop_counters::count!(REAL_SERIES);
        for j in 1..TRIG_TERMS {
            loops.tick();
            let a = 2 * j + s - 1;
            // term ≤ 2^64, q < 2^64: the product fits.
            term = ((term * q) >> 64) / u128::from(a * (a + 1));
            let t = i128::try_from(term).ok()?;
            sum = if j % 2 == 1 { sum - t } else { sum + t };
        }
        Some(Approx::new(sum, SIN_COS_BOUND))
    };
    let sin = series(x, 1).unwrap_or(Approx::UNKNOWN);
    let cos = series(1 << 64, 0).unwrap_or(Approx::UNKNOWN);
    (sin, cos)
}

/// The sine and cosine of `k·0.00005°` with their bounds (R-FASTPATH), the
/// fast path's [`crate::engine::real::sin_cos`]: the same exact cases
/// (`docs/G75.md` §6: sin 0, 30°, 90°, cos 0, 60°, 90°, exact), the series
/// in integers (the module documentation) up to 45° and, beyond, `sin x =
/// cos(90° − x)` and `cos x = sin(90° − x)`. Unknown beyond 90°.
#[must_use]
pub fn sin_cos(k: u32) -> (Approx, Approx) {
    let half = Approx::half();
    match k {
        0 => (Approx::int(0), Approx::int(1)),
        600_000 => (half, sin_cos_series(k).1),
        1_200_000 => (sin_cos_series(RIGHT - k).1, half),
        RIGHT => (Approx::int(1), Approx::int(0)),
        k if k > RIGHT => (Approx::UNKNOWN, Approx::UNKNOWN),
        k if k > EIGHTH => {
            let (s, c) = sin_cos_series(RIGHT - k);
            (c, s)
        }
        k => sin_cos_series(k),
    }
}

/// `tan(k·0.00005°)` from that angle's sine and cosine, with the exact
/// cases of [`crate::engine::real::tan_of`] (0 and 45°; unknown from 90°).
#[must_use]
pub fn tan_of(k: u32, s: &Approx, c: &Approx) -> Approx {
    match k {
        0 => Approx::int(0),
        EIGHTH => Approx::int(1),
        k if k >= RIGHT => Approx::UNKNOWN,
        _ => s.div(c),
    }
}

/// `cot(k·0.00005°)` from that angle's sine and cosine, with the exact
/// cases of [`crate::engine::real::cot_of`] (45° and 90°; unknown at 0 and
/// beyond 90°).
#[must_use]
pub fn cot_of(k: u32, s: &Approx, c: &Approx) -> Approx {
    match k {
        EIGHTH => Approx::int(1),
        RIGHT => Approx::int(0),
        k if k == 0 || k > RIGHT => Approx::UNKNOWN,
        _ => c.div(s),
    }
}

/// `tan` and `cot` of one angle together ([`tan_of`], [`cot_of`]).
#[must_use]
pub fn tan_cot(k: u32) -> (Approx, Approx) {
    let (s, c) = sin_cos(k);
    (tan_of(k, &s, &c), cot_of(k, &s, &c))
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::engine::real::{self, Fixed, FAST, SLOW};

    /// The exact `x` (a narrow enclosure at 512 bits) against an
    /// [`Approx`]: the distance from `v·2^-64` to every end of the
    /// enclosure, in ulps of `2^-64` (rounded up), must be at most `e`.
    fn error_ulps(a: &Approx, exact: &Interval<SLOW>) -> u128 {
        let v = Interval::<SLOW>::point(fixed_of(a.value()));
        let d1 = v.sub(exact).mul_int(1 << 62).mul_int(4);
        let d2 = exact.sub(&v).mul_int(1 << 62).mul_int(4);
        let c1 = d1.upper().ceil().unwrap();
        let c2 = d2.upper().ceil().unwrap();
        u128::try_from(c1.max(c2).max(0)).unwrap()
    }

    /// `v·2^-64` as a fixed-point number at 512 bits.
    fn fixed_of(v: i128) -> Fixed<SLOW> {
        let hi = v >> 64;
        let lo = v & i128::from(u64::MAX);
        let lo = Interval::<SLOW>::int(lo).div_int(1 << 32).div_int(1 << 32);
        assert!(lo.is_point());
        Fixed::from_int(hi).checked_add(lo.lower()).unwrap()
    }

    /// [`mul_up`]'s short form (a factor below 2^64) gives what the full
    /// 256-bit product gives: `⌈a·b/2^64⌉`, saturated at `u128::MAX`.
    #[test]
    fn mul_up_is_the_wide_ceiling() {
        let wide = |a: u128, b: u128| -> u128 {
            let (hi, lo) = mul_wide(a, b);
            let q = (lo >> 64) + u128::from(lo & u128::from(u64::MAX) != 0);
            if hi >> 64 != 0 {
                return u128::MAX;
            }
            (hi << 64).saturating_add(q)
        };
        let vals = [
            0_u128,
            1,
            2,
            3,
            (1 << 63) - 1,
            1 << 63,
            u128::from(u64::MAX) - 1,
            u128::from(u64::MAX),
            1 << 64,
            (1 << 64) + 1,
            (1 << 64) * 3 + 12_345,
            0x1234_5678_9abc_def0_0fed_cba9_8765_4321,
            (1 << 127) - 1,
            1 << 127,
            u128::MAX - 1,
            u128::MAX,
        ];
        for &a in &vals {
            for &b in &vals {
                assert_eq!(mul_up(a, b), wide(a, b), "{a:#x} · {b:#x}");
            }
        }
    }

    #[test]
    fn ln2_constant() {
        // ⌊ln 2 · 2^64⌋ from the interval arithmetic's ln 2 at 512 bits.
        let l = real::ln::<SLOW>(2).mul_int(1 << 32).mul_int(1 << 32);
        assert_eq!(l.round(real::Rounding::Floor), Some(i128::try_from(LN2).unwrap()));
    }

    #[test]
    fn decisions() {
        let half = ONE / 2;
        // 2.5 exactly: a tie, away from zero; 2.5 − 1 ulp: 2; −2.5 + 1 ulp: −2.
        assert_eq!(Approx::new(2 * ONE + half, 0).round_half_away(), Some(3));
        assert_eq!(Approx::new(-2 * ONE - half, 0).round_half_away(), Some(-3));
        assert_eq!(Approx::new(2 * ONE + half, 1).round_half_away(), None);
        assert_eq!(Approx::new(2 * ONE + half - 1, 0).round_half_away(), Some(2));
        assert_eq!(Approx::new(2 * ONE + half + 1, 0).round_half_away(), Some(3));
        assert_eq!(Approx::new(-2 * ONE - half + 1, 0).round_half_away(), Some(-2));
        assert_eq!(Approx::new(-2 * ONE - half - 1, 0).round_half_away(), Some(-3));
        // Within the bound of the boundary: undecided; one ulp further: decided.
        assert_eq!(Approx::new(2 * ONE + half - 5, 5).round_half_away(), None);
        assert_eq!(Approx::new(2 * ONE + half - 6, 5).round_half_away(), Some(2));
        assert_eq!(Approx::new(2 * ONE - half + 5, 5).round_half_away(), None);
        assert_eq!(Approx::new(2 * ONE - half + 6, 5).round_half_away(), Some(2));
        assert_eq!(Approx::int(7).round_half_away(), Some(7));
        assert_eq!(Approx::UNKNOWN.round_half_away(), None);
        assert_eq!(Approx::int(0).sign(), Some(Ordering::Equal));
        assert_eq!(Approx::new(1, 1).sign(), None);
        assert_eq!(Approx::new(2, 1).sign(), Some(Ordering::Greater));
        assert_eq!(Approx::new(-2, 1).sign(), Some(Ordering::Less));
        assert_eq!(Approx::UNKNOWN.sign(), None);
    }

    #[test]
    fn products_keep_their_bound() {
        let third = Approx::new(ONE / 3, 1);
        let p = third.mul(&third);
        // 1/9 within the bound.
        let exact = Interval::<SLOW>::int(1).div_int(9);
        assert!(error_ulps(&p, &exact) <= p.bound(), "{p:?}");
        let m = Approx::new(-ONE / 3, 1).mul(&Approx::int(3));
        assert!(error_ulps(&m, &Interval::<SLOW>::int(-1)) <= m.bound());
        assert_eq!(Approx::int(3).mul(&Approx::int(-4)), Approx::int(-12));
        assert_eq!(Approx::int(5).div_int(2), Approx::new(5 * ONE / 2, 0));
    }

    /// [`LN_TABLE`] holds [`ln_series`]'s values: [`ln`] is the series
    /// on either side of the table's end.
    #[test]
    fn ln_table_is_the_series() {
        for n in 0..(LN_TABLE_LEN as u64 + 64) {
            assert_eq!(ln(n), ln_series(n), "{n}");
        }
        assert_eq!(ln(0), None);
        assert_eq!(ln(1), None);
        assert!(ln(2).is_some());
    }

    /// The worst cases of [`ln`]: `|s|` at its largest (`n/2^f` at 3/4 and
    /// just below 3/2), the largest `f`, and the smallest `n`; the error
    /// against the interval arithmetic's `ln` is within [`LN_BOUND`] and
    /// the derivation's 119.
    #[test]
    fn ln_bound_at_its_worst_cases() {
        let mut worst = 0;
        let cases = [
            2_u64,
            3,
            5,
            6,
            7,
            11,
            (3 << 20) - 1,
            3 << 20,
            (1 << 32) + 1,
            3 << 31,
            (3 << 31) - 1,
            (1 << 62) + (1 << 61) - 1,
            (1 << 62) + (1 << 61),
            (1 << 63) - 1,
        ];
        for n in cases {
            let a = Approx::new(ln(n).unwrap(), LN_BOUND);
            let err = error_ulps(&a, &real::ln::<SLOW>(n));
            worst = worst.max(err);
            assert!(err < 119, "ln {n}: {err} ulps");
        }
        std::println!("ln: worst error {worst} ulps (bound {LN_BOUND})");
    }

    /// The worst cases of [`power`]: the largest `k` the engine reaches
    /// (`n = 2^32 + 1`, R = 1.0001), `r` near ln 2, and the depth laws of
    /// the examples; the error against the interval arithmetic's power.
    #[test]
    fn power_bound_at_its_worst_cases() {
        let mut worst_ratio = 0.0_f64;
        let cases = [
            (2_u64, 10_000, 10_001),
            ((1 << 32) + 1, 10_000, 10_001),
            ((1 << 32) + 1, 10_000, 15_000),
            ((1 << 32) + 1, 10_000, 1_000_000),
            (9, 10_000, 15_000),
            (8, 10_000, 15_000),
            (1_000_001, 10_000, 12_345),
            (3, 10_000, 15_849),
            (1 << 40, 10_000, 10_001),
            ((1 << 62) + 12_345, 10_000, 10_001),
        ];
        for (n, a, b) in cases {
            let p = power(n, a, b);
            assert_ne!(p, Approx::UNKNOWN, "{n} {a}/{b}");
            let exact = real::power::<{ SLOW + 1 }>(n, a, b).at_precision::<SLOW>();
            let err = error_ulps(&p, &exact);
            assert!(err <= p.bound(), "{n}^({a}/{b}): {err} > {}", p.bound());
            // The bound's derivation: below 456·2^k.
            let k = 63 - p.value().leading_zeros();
            let ratio = err as f64 / 2_f64.powi(i32::try_from(k).unwrap());
            worst_ratio = worst_ratio.max(ratio);
            assert!(ratio < 456.0, "{n}^({a}/{b}): {ratio}·2^k ulps");
        }
        std::println!("power: worst error {worst_ratio:.1}·2^k ulps (bound {EXP_BOUND}·2^k)");
        assert_eq!(power(1, 2, 3), Approx::int(1));
        assert_eq!(power(17, 3, 3), Approx::int(17));
        assert_eq!(power(0, 2, 3), Approx::UNKNOWN);
        assert_eq!(power(5, 4, 3), Approx::UNKNOWN);
    }

    /// `exp` of the series at the largest `r` (just below ln 2).
    #[test]
    fn exp_bound_at_its_worst_case() {
        for r in [LN2 - 1, LN2 / 2, 1] {
            let s = exp_unit(r).unwrap();
            let x = Interval::<SLOW>::point(fixed_of(i128::try_from(r).unwrap()));
            let exact = real::exp(&x);
            let err = error_ulps(&Approx::new(i128::try_from(s).unwrap(), 0), &exact);
            assert!(err < 71, "exp {r}: {err}");
        }
    }

    /// The bound of [`sin_cos`] against the interval arithmetic's sine and
    /// cosine at 512 bits: at the ends of the series' range (the smallest
    /// angle, 45° where `x` is largest), beside the exact cases, at the
    /// reflected angles above 45°, and at a spread of angles. The
    /// derivation (R-FASTPATH) gives below 13 ulps.
    #[test]
    fn sin_cos_bound_at_its_worst_cases() {
        let mut worst = 0;
        let mut ks = std::vec![1_u32, 2, 3, 599_999, 600_000, 600_001, 899_999, 900_000, 900_001];
        ks.extend([1_199_999, 1_200_000, 1_200_001, 1_799_999, 1_800_000, 0, 450_000, 1_350_000]);
        ks.extend((0..200_u32).map(|i| i * 8_999 + 17));
        for k in ks {
            let (s, c) = sin_cos(k);
            let (es, ec) = real::sin_cos::<SLOW>(k);
            for (a, exact) in [(s, es), (c, ec)] {
                let err = error_ulps(&a, &exact);
                assert!(err <= a.bound(), "k = {k}: {err} > {}", a.bound());
                worst = worst.max(err);
                assert!(err < 13, "k = {k}: {err} ulps");
            }
        }
        std::println!("sin/cos: worst error {worst} ulps (bound {SIN_COS_BOUND})");
        // The exact cases are exact.
        assert_eq!(sin_cos(0), (Approx::int(0), Approx::int(1)));
        assert_eq!(sin_cos(600_000).0, Approx::half());
        assert_eq!(sin_cos(1_200_000).1, Approx::half());
        assert_eq!(sin_cos(RIGHT), (Approx::int(1), Approx::int(0)));
        assert_eq!(sin_cos(RIGHT + 1), (Approx::UNKNOWN, Approx::UNKNOWN));
        // tan and cot from them, against the intervals', and their exact cases.
        for k in [1_u32, 150_000, 600_000, 899_999, 1_200_000, 1_799_999] {
            let (t, c) = tan_cot(k);
            let (et, ec) = real::tan_cot::<SLOW>(k);
            assert!(error_ulps(&t, &et) <= t.bound(), "tan {k}");
            assert!(error_ulps(&c, &ec) <= c.bound(), "cot {k}");
        }
        assert_eq!(tan_cot(EIGHTH), (Approx::int(1), Approx::int(1)));
        assert_eq!(tan_cot(RIGHT).1, Approx::int(0));
        assert_eq!(tan_cot(0).0, Approx::int(0));
        assert!(tan_cot(0).1.is_unknown() && tan_cot(RIGHT).0.is_unknown());
    }

    /// Quotients keep their bound: exact ones exact, inexact ones within
    /// `⌈(e_a·2^64 + (|q| + 1)·e_b)/(|b| − e_b)⌉ + 1` of the exact value,
    /// at the divisor's extremes (1, the smallest sine of the angle unit).
    #[test]
    fn quotients_keep_their_bound() {
        assert_eq!(Approx::int(3).div(&Approx::half()), Approx::int(6));
        assert_eq!(Approx::int(-3).div(&Approx::int(1)), Approx::int(-3));
        assert_eq!(Approx::int(1).div(&Approx::int(2)), Approx::UNKNOWN);
        assert_eq!(Approx::int(1).div(&Approx::new(3, 3)), Approx::UNKNOWN);
        assert_eq!(Approx::int(1).div(&Approx::int(0)), Approx::UNKNOWN);
        let third = Approx::int(1).div(&Approx::new(3 * ONE / 4, 0));
        assert_eq!(third.bound(), 1);
        assert!(error_ulps(&third, &Interval::<SLOW>::int(4).div_int(3)) <= third.bound());
        for (ka, kb) in [(1_u32, 1_u32), (899_999, 1), (1, 899_999), (123_457, 765_431)] {
            let ((sa, ca), (sb, cb)) = (sin_cos(ka), sin_cos(kb));
            let ((esa, eca), (esb, ecb)) = (real::sin_cos::<SLOW>(ka), real::sin_cos::<SLOW>(kb));
            for (a, b, ea, eb) in [(ca, sb, eca, esb), (sa.mul_int(-7_000), cb, esa.mul_int(-7_000), ecb)] {
                let q = a.div(&b);
                assert!(!q.is_unknown(), "{ka} {kb}");
                assert!(error_ulps(&q, &ea.div(&eb)) <= q.bound(), "{ka} {kb}: {q:?}");
            }
        }
        assert!(Approx::UNKNOWN.div(&Approx::int(1)).is_unknown());
        assert!(Approx::UNKNOWN.mul_int(0).is_unknown());
        assert!(Approx::UNKNOWN.mul(&Approx::int(0)).is_unknown());
        assert!(Approx::UNKNOWN.div_int(3).is_unknown());
    }

    /// Floor, ceil and nearest (ties up) on the ends of the enclosure, as
    /// the intervals decide them; max and min of enclosures.
    #[test]
    fn roundings_on_the_ends() {
        let half = ONE / 2;
        let cases = [
            (Approx::new(2 * ONE, 0), [Some(2), Some(2), Some(2)]),
            (Approx::new(2 * ONE + half, 0), [Some(2), Some(3), Some(3)]),
            (Approx::new(-2 * ONE - half, 0), [Some(-3), Some(-2), Some(-2)]),
            (Approx::new(2 * ONE + 5, 5), [Some(2), None, Some(2)]),
            (Approx::new(2 * ONE + 4, 5), [None, None, Some(2)]),
            (Approx::new(-2 * ONE - half + 6, 5), [Some(-3), Some(-2), Some(-2)]),
            (Approx::new(-2 * ONE - half + 5, 5), [Some(-3), Some(-2), Some(-2)]),
            (Approx::new(-2 * ONE - half + 4, 5), [Some(-3), Some(-2), None]),
            (Approx::UNKNOWN, [None, None, None]),
        ];
        for (a, want) in cases {
            let got = [Rounding::Floor, Rounding::Ceil, Rounding::Nearest].map(|r| a.round(r));
            assert_eq!(got, want, "{a:?}");
            // The intervals decide the same on the same ends.
            if let Some((lo, hi)) = a.ends() {
                let iv = Interval::<SLOW>::new(fixed_of(lo), fixed_of(hi));
                let by_iv = [Rounding::Floor, Rounding::Ceil, Rounding::Nearest].map(|r| iv.round(r));
                assert_eq!(got, by_iv, "{a:?}");
            }
        }
        let (a, b) = (Approx::new(10, 3), Approx::new(12, 4));
        assert_eq!(a.max(&b), Approx::new(8, 8));
        assert_eq!(a.min(&b), Approx::new(7, 6));
        assert_eq!(Approx::int(5).neg(), Approx::int(-5));
        assert_eq!(Approx::int_wide(1 << 63), Approx::UNKNOWN);
        assert_eq!(Approx::int_wide(-(1 << 62)), Approx::int(-(1 << 62)));
    }

    #[test]
    fn enclosing_an_interval() {
        let t = real::tan::<FAST>(590_000);
        let a = Approx::enclosing(&t);
        let exact = real::tan::<SLOW>(590_000);
        assert!(error_ulps(&a, &exact) <= a.bound());
        assert!(a.bound() <= 2);
        let n = Approx::enclosing(&t.neg());
        assert!(error_ulps(&n, &exact.neg()) <= n.bound());
        // At 64 fraction bits: the ends exactly.
        let t3 = real::tan::<3>(590_000);
        let a3 = Approx::enclosing(&t3);
        assert!(error_ulps(&a3, &exact) <= a3.bound());
        assert!(a3.bound() < 1 << 12, "{a3:?}");
        std::println!("tan 29.5° at 64 bits: bound {} ulps", a3.bound());
        assert_eq!(Approx::enclosing(&Interval::<FAST>::int(0)), Approx::int(0));
        assert_eq!(Approx::enclosing(&Interval::<3>::int(-7)), Approx::int(-7));
        assert_eq!(Approx::enclosing(&Interval::<FAST>::poison()), Approx::UNKNOWN);
    }
}
