//! The G76 depth schedule, one rough level at a time (DOMAIN decision 3,
//! readings R-DEPTH and R-LINEAR):
//!
//! ```text
//! D(n) = min(k - d, max(round(Δd √n), D(n-1) + m)),   m = max(Δdmin, 1)
//! ```
//!
//! [`Schedule`] is the state of the levels produced so far; the G76 engine
//! ([`super::g76`]) steps it once per rough level and counts the levels up
//! front with the same `law`. Why the schedule stops taking square roots
//! once the minimum cut has taken over is proved in the module docs of
//! [`super::g76`] (and in R-LINEAR).
//!
//! It is public so that the proofs can state the schedule's properties as
//! one step from a level `n` (`cycleref-proofs`, `schedule_step`):
//! [`Schedule::resume`] makes the state at a level, [`Schedule::next_level`]
//! steps it, and the accessors read it back.

#[cfg(feature = "loop-counters")]
use super::arith::record_isqrt;
use super::arith::{round_sqrt, round_sqrt_near, SQRT_Q32};
use crate::units::MAX_LENGTH;

/// `round(Δd √n)` with `q2 = Δd²`: `q2 < 2^60`, `n < 2^33`, so the product
/// is below `2^93` and the root below `2^47`.
///
/// Twin: `spec/src/g76.rs`, `depth_by_law`.
pub(super) fn law(q2: u64, n: u64) -> i64 {
    #[cfg(feature = "loop-counters")]
    record_isqrt(u128::from(q2) * u128::from(n));
    let root = round_sqrt(u128::from(q2) * u128::from(n));
    i64::try_from(root).unwrap_or(i64::MAX)
}

/// [`law`] at level `n ≥ 1` from the level before, `previous = round(Δd
/// √(n - 1))` reached by a `step` from its own predecessor: the same value,
/// from a guess ([`round_sqrt_near`]). The guess is `Δd √n` from a table of
/// `√n` for the first 32 levels (within a quarter increment), and
/// `previous + step` beyond (the law's steps shrink by less than one
/// increment a level there, so the rounded ones by at most about one).
/// Any `previous` and `step` give the same result; only the speed differs.
/// `q = Δd < 2^30`, `q2 = Δd²`.
///
/// Twin: `spec/src/g76.rs`, `depth_by_law`.
// Inlined into the up-front count and the schedule (one call per level).
#[inline(always)]
pub(super) fn law_near(q: u64, q2: u64, n: u64, previous: i64, step: i64) -> i64 {
    let x = u128::from(q2) * u128::from(n);
    #[cfg(feature = "loop-counters")]
    record_isqrt(x);
    let guess = match usize::try_from(n).ok().and_then(|i| SQRT_Q32.get(i)) {
        // q < 2^30, √n · 2^32 < 2^35: below 2^65; rounded to nearest.
        Some(&root) => (u128::from(q) * u128::from(root) + (1 << 31)) >> 32,
        // A negative guess (not reached) is as good as any other.
        None => u128::try_from(previous.saturating_add(step)).unwrap_or(0),
    };
    #[cfg(feature = "loop-counters")]
    super::arith::record_isqrt_near(x, guess);
    let root = round_sqrt_near(x, guess);
    i64::try_from(root).unwrap_or(i64::MAX)
}

/// The rough levels, one at a time (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Schedule {
    /// Δd (< 2^30; [`Schedule::q2`] is Δd²).
    pub(super) q: u32,
    /// max(Δdmin, 1).
    pub(super) min: i64,
    /// k - d.
    pub(super) last: i64,
    /// Levels produced so far.
    pub(super) n: u64,
    /// Depth of the last level produced (0 before the first).
    pub(super) depth: i64,
    /// True once the minimum cut has taken over.
    pub(super) min_phase: bool,
    /// Reading R-NOROUGH `one-at-zero`: the first level is made even when
    /// it is already at `k - d` (= 0: d = k).
    pub(super) one_at_zero: bool,
    /// Reading R-DEPTH `formula`: every level is `max(round(Δd √n),
    /// round(Δd √(n-1)) + m, D(n-1) + 1)` ([`formula_levels`]); the
    /// minimum-cut phase is not used.
    pub(super) formula: bool,
    /// Under `formula`: `round(Δd √n)` of the last level produced (0
    /// before the first).
    pub(super) law_n: i64,
    /// The depth the last level by the law added (Δd before the first
    /// level): only the guess of the next level's root ([`law_near`]),
    /// which never changes a level (below 2^31: law levels are).
    pub(super) step: i32,
}

/// The first `n ≥ 0` with `round(Δd √n) ≥ v`: 0 for `v ≤ 0`, else `⌈(2v -
/// 1)² / 4Δd²⌉` (`round(Δd √n) ≥ v ⟺ 4Δd²n ≥ (2v - 1)²`, no tie).
fn first_law_at_least(q2: u64, v: i64) -> u128 {
    if v <= 0 {
        return 0;
    }
    // v < 2^30: (2v - 1)² < 2^62; q2 ≥ 1, 4·q2 < 2^62.
    u128::from((2 * v - 1).unsigned_abs()).pow(2).div_ceil(4 * u128::from(q2))
}

/// Reading R-DEPTH `formula`: the number of rough levels of a schedule
/// with `q2 = Δd²`, `min = max(Δdmin, 1)` and `last = k - d > 0`, in
/// closed form, and the depth of the level before the last (0 when there
/// are fewer than two). The proof is at the reference's twin; in short,
/// with `E(n) = max(round(Δd √n), round(Δd √(n-1)) + m)` and `p = ⌊(Δd² +
/// 1)² / 4Δd²⌋ + 1` (after `p` the law rises by at most one increment a
/// level), the levels are `E(n)` up to `p` and `E(p) + n - p` after, so
/// the count is the first `n` with `E(n) ≥ k - d` when that is at most
/// `p`, else `p + k - d - E(p)`. No square root is taken beyond the
/// schedule's own levels (`E(n) < k - d` at every `n` it is taken for, so
/// `Δd² n < 2^62`, within the kernel's contract).
///
/// Twin: `spec/src/g76.rs`, `formula_level_count`.
pub(super) fn formula_levels(q2: u64, min: i64, last: i64) -> (u64, i64) {
    // q2 < 2^60: (q2 + 1)² < 2^121; p ≤ 2^58 + 1.
    let q2w = u128::from(q2);
    let p = u64::try_from((q2w + 1).pow(2) / (4 * q2w)).unwrap_or(u64::MAX).saturating_add(1);
    // n ≥ 1; E(n) < 2^31 at every n it is asked for (below).
    let e = |n: u64| law(q2, n).max(law(q2, n - 1) + min);
    let by_e = first_law_at_least(q2, last).min(1 + first_law_at_least(q2, last - min));
    // by_e ≤ n_N(k - d) < 2^62.
    let by_e = u64::try_from(by_e).unwrap_or(u64::MAX);
    let levels = if by_e <= p {
        by_e
    } else {
        // E(p) < k - d: p + (k - d - E(p)) < 2^59.
        p + (last - e(p)).unsigned_abs()
    };
    // The level before the last is below k - d: F(levels - 1) < k - d.
    let penultimate = match levels {
        0 | 1 => 0,
        n if n - 1 <= p => e(n - 1),
        // n - 1 - p < k - d < 2^30.
        n => e(p) + i64::try_from(n - 1 - p).unwrap_or(i64::MAX),
    };
    (levels, penultimate)
}

impl Schedule {
    /// The state after `level` levels, the last at `depth`, the minimum cut
    /// in force or not: Δd = `first_depth`, Δdmin = `min_cut`, k - d =
    /// `last`. `resume(Δd, Δdmin, k - d, 0, 0, false)` is the schedule of a
    /// cycle before its first level (what the G76 engine starts from).
    ///
    /// Any such state can be made, reachable or not: the proofs step every
    /// state that satisfies their invariant. `None` outside the ranges the
    /// engine works in (`validate()`'s: `1 ≤ Δd ≤ MAX_LENGTH`, `0 ≤ Δdmin`,
    /// `0 ≤ depth ≤ k - d ≤ MAX_LENGTH`, and `level ≤ MAX_LENGTH`: every
    /// level is at least one increment deeper than the one before).
    #[must_use]
    pub fn resume(
        first_depth: i64,
        min_cut: i64,
        last: i64,
        level: u64,
        depth: i64,
        min_phase: bool,
    ) -> Option<Schedule> {
        let length = 0..=MAX_LENGTH;
        let ok = (1..=MAX_LENGTH).contains(&first_depth)
            && length.contains(&min_cut)
            && length.contains(&last)
            && (0..=last).contains(&depth)
            && level <= MAX_LENGTH.unsigned_abs();
        // Δd < 2^30: Δd² < 2^60.
        // 1 ≤ Δd ≤ MAX_LENGTH < 2^30 (checked in `ok`).
        let q = u32::try_from(first_depth).unwrap_or(u32::MAX);
        ok.then_some(Schedule {
            q,
            min: min_cut.max(1),
            last,
            n: level,
            depth,
            min_phase,
            one_at_zero: false,
            formula: false,
            law_n: 0,
            step: i32::try_from(first_depth).unwrap_or(i32::MAX),
        })
    }

    /// The same words (Δd, Δdmin, k - d) at another state: `level` levels
    /// made, the last at `depth`; `None` outside the ranges of
    /// [`Schedule::resume`].
    #[must_use]
    pub fn with_state(self, level: u64, depth: i64, min_phase: bool) -> Option<Schedule> {
        let ok = (0..=self.last).contains(&depth) && level <= MAX_LENGTH.unsigned_abs();
        // Under R-DEPTH `formula` the state carries round(Δd √level) (for
        // the levels the schedule makes, within the root's contract).
        let law_n = if self.formula && level > 0 { law(self.q2(), level) } else { 0 };
        ok.then_some(Schedule { n: level, depth, min_phase, law_n, ..self })
    }

    /// The depth of the next level, or `None` after the level at `k - d`.
    ///
    /// Twin: `spec/src/g76.rs`, `next_depth` (and `rough_levels`).
    #[inline(always)]
    pub fn next_level(&mut self) -> Option<i64> {
        if self.depth >= self.last {
            // Reading R-NOROUGH `one-at-zero`: level 1 at k - d = 0.
            if self.n > 0 || !self.one_at_zero {
                return None;
            }
            self.n = 1;
            return Some(self.depth);
        }
        // At most k - d < 2^30 levels: the depth grows by at least 1.
        self.n += 1;
        // depth < last < 2^30, min < 2^30.
        let by_min = self.depth + self.min;
        let next = if self.formula {
            // Reading R-DEPTH `formula`: max(round(Δd √n), round(Δd
            // √(n-1)) + m, D(n-1) + 1); round(Δd √n) < 2^31 (it rises by
            // less than Δd + 1 from round(Δd √(n-1)) ≤ D(n-1) < k - d).
            let law = law(self.q2(), self.n);
            let next = law.max(self.law_n + self.min).max(self.depth + 1);
            self.law_n = law;
            next
        } else if self.min_phase {
            by_min
        } else {
            let law = law_near(u64::from(self.q), self.q2(), self.n, self.depth, i64::from(self.step));
            if law < by_min {
                self.min_phase = true;
                by_min
            } else {
                // depth ≤ law < 2^31 (a level by the law is below k - d).
                self.step = i32::try_from(law - self.depth).unwrap_or(i32::MAX);
                law
            }
        };
        self.depth = next.min(self.last);
        Some(self.depth)
    }

    /// Δd² (< 2^60).
    #[inline]
    fn q2(&self) -> u64 {
        let q = u64::from(self.q);
        q * q
    }

    /// The number of levels produced so far.
    #[must_use]
    pub const fn level(&self) -> u64 {
        self.n
    }

    /// The depth of the last level produced (0 before the first).
    #[must_use]
    pub const fn depth(&self) -> i64 {
        self.depth
    }

    /// True once the minimum cut has taken over (the schedule then adds `m`
    /// per level without taking square roots).
    #[must_use]
    pub const fn min_phase(&self) -> bool {
        self.min_phase
    }
}
