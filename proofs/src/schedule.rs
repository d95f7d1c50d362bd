//! The G76 depth schedule, one step at a time: level `n + 1` against level
//! `n`, for a symbolic `n` (`cycleref::engine::schedule::Schedule`).
//!
//! P1 and P2 ([`crate::harness`]) follow whole cycles through their moves,
//! so Kani must unroll every level of a cycle and their window stops at
//! k ≤ 6. [`schedule_step`] is an induction instead, with no loop over the
//! levels: it takes any state of the schedule that satisfies an invariant
//! ([`invariant`]), steps it once, and checks the step's properties and
//! that the invariant holds at the next level. The first state (level 0,
//! depth 0) satisfies the invariant, so by induction every state the
//! schedule reaches does, and every step of every cycle has the
//! properties, at every level `n`: under Kani over every documented input
//! (Δd, Δdmin, k - d < 2^30, any level), here exhaustively over a small
//! window and sampled at large values.
//!
//! With `a(n) = Δd √n` and `m = max(Δdmin, 1)`, the invariant of a state
//! after level `n` at depth `D < k - d` is, in integers (no square root):
//!
//! * law: `D = round(a(n))`, i.e. `(2D - 1)² ≤ 4Δd²n < (2D + 1)²`; or
//! * minimum cut: `a(n) < D - ½`, i.e. `4Δd²n < (2D - 1)²`, and the last
//!   step of the law below `m`, `a(n) - a(n-1) < m`, i.e. `Δd ≤ m` or
//!   `(Δd² - m²)² < (2mΔd)²(n - 1)`. The minimum-cut state is required once
//!   the schedule has switched to adding `m` without a root (R-LINEAR: `a`
//!   is concave, so the law stays below `D + m` from there on);
//!
//! and `n ≤ D` (every level at least one increment deeper), level 0 at
//! depth 0; a state at `D = k - d` is the end.

use cycleref::engine::schedule::Schedule;

use crate::cover;
use crate::verify::{any_bool, any_in, assume, declare};

/// The words and the state a [`schedule_step`] may choose, inclusive
/// ranges in increments; `depth` is capped at `k - d` and `level` at the
/// depth.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScheduleDomain {
    /// Δd.
    pub first_depth: (i64, i64),
    /// Δdmin.
    pub min_cut: (i64, i64),
    /// k - d.
    pub last: (i64, i64),
    /// D(n), the depth of the state's last level.
    pub depth: (i64, i64),
    /// n, the levels made so far.
    pub level: (i64, i64),
}

/// `4Δd²n`.
fn four_q2n(q: i64, n: i64) -> u128 {
    4 * u128::from(q.unsigned_abs()).pow(2) * u128::from(n.unsigned_abs())
}

/// `round(Δd √n) ≥ v`: `a(n) ≥ v - ½`, i.e. `(2v - 1)² ≤ 4Δd²n` (no tie:
/// an odd square is never a multiple of 4).
fn root_at_least(q: i64, n: i64, v: i64) -> bool {
    v <= 0 || u128::from((2 * v - 1).unsigned_abs()).pow(2) <= four_q2n(q, n)
}

/// `round(Δd √n) ≤ v` (`v ≥ 0`): `a(n) < v + ½`, i.e. `4Δd²n < (2v + 1)²`.
fn root_at_most(q: i64, n: i64, v: i64) -> bool {
    v >= 0 && four_q2n(q, n) < u128::from((2 * v + 1).unsigned_abs()).pow(2)
}

/// The minimum-cut state after level `n ≥ 1` at depth `D`: `a(n) < D - ½`
/// and `a(n) - a(n-1) < m`.
fn min_cut_state(q: i64, m: i64, n: i64, depth: i64) -> bool {
    let below = depth >= 1 && four_q2n(q, n) < u128::from((2 * depth - 1).unsigned_abs()).pow(2);
    // Δd(√n - √(n-1)) < m ⟺ Δd² - m² < 2mΔd√(n-1) ⟺ Δd ≤ m or (Δd² -
    // m²)² < (2mΔd)²(n - 1); the product may pass u128 (then it is larger).
    let (q, m) = (u128::from(q.unsigned_abs()), u128::from(m.unsigned_abs()));
    let step_below = q <= m
        || (2 * m * q)
            .pow(2)
            .checked_mul(u128::from((n - 1).unsigned_abs()))
            .is_none_or(|p| (q * q - m * m).pow(2) < p);
    n >= 1 && below && step_below
}

/// The invariant of the module docs for the state after level `n` at
/// `depth`, the minimum cut in force (`min_phase`) or not.
#[must_use]
pub fn invariant(q: i64, m: i64, last: i64, n: i64, depth: i64, min_phase: bool) -> bool {
    if depth < 0 || depth > last || n < 0 || n > depth {
        return false;
    }
    if depth == last {
        return true;
    }
    if n == 0 {
        return depth == 0 && !min_phase;
    }
    let law = root_at_least(q, n, depth) && root_at_most(q, n, depth);
    min_cut_state(q, m, n, depth) || (!min_phase && law)
}

/// `next = min(k - d, max(round(Δd √n), previous + m))`, without a square
/// root: which of the three it is, each verified by the squares.
fn by_the_law(q: i64, n: i64, previous: i64, m: i64, last: i64, next: i64) -> bool {
    let by_min = previous + m;
    if next == last {
        by_min >= last || root_at_least(q, n, last)
    } else {
        next < last
            && (next == by_min && root_at_most(q, n, by_min)
                || next > by_min && root_at_least(q, n, next) && root_at_most(q, n, next))
    }
}

/// `ceil((k - d - D) / m)`: the levels left from depth `D` when every level
/// adds `m` (`D ≤ k - d`).
fn levels_left(last: i64, depth: i64, m: i64) -> i64 {
    (last - depth + m - 1) / m
}

/// One step of the schedule, from any state after level `n` that satisfies
/// [`invariant`], by `step` (the engine's `Schedule::next_level`, or a
/// mutant):
///
/// * at `D(n) = k - d` the schedule ends; below it there is a level `n + 1`;
/// * the depth strictly increases, never beyond `k - d`, by at least
///   `min(m, k - d - D(n))`, `m = max(Δdmin, 1)`;
/// * `D(n+1) = min(k - d, max(round(Δd √(n+1)), D(n) + m))`, the rounded
///   root verified by the squares `(2r - 1)² ≤ 4Δd²(n+1) < (2r + 1)²`;
/// * the invariant holds at level `n + 1` (the induction step);
/// * in the minimum-cut phase the levels left are `ceil((k - d - D) / m)`:
///   one fewer after each level, so the phase makes exactly that many.
pub fn schedule_step<S: Fn(&mut Schedule) -> Option<i64>>(d: &ScheduleDomain, step: &S) {
    declare(&[
        "the first level",
        "a level by the law, beyond D(n) + m",
        "the minimum cut takes over",
        "a level of the minimum-cut phase",
        "a level cut short at k - d",
        "the schedule ends at k - d",
    ]);
    let q = any_in(d.first_depth.0, d.first_depth.1);
    let min_cut = any_in(d.min_cut.0, d.min_cut.1);
    let last = any_in(d.last.0, d.last.1);
    let depth = any_in(d.depth.0.min(last), d.depth.1.min(last));
    let n = any_in(d.level.0.min(depth), d.level.1.min(depth));
    let min_phase = any_bool();
    let m = min_cut.max(1);
    assume(invariant(q, m, last, n, depth, min_phase));
    let state = Schedule::resume(q, min_cut, last, n.unsigned_abs(), depth, min_phase);
    assume(state.is_some());
    let Some(mut s) = state else { return };
    let next = step(&mut s);
    if depth == last {
        assert!(next.is_none(), "the schedule ends at k - d");
        cover!(true, "the schedule ends at k - d");
        return;
    }
    let Some(next) = next else { panic!("the schedule ends before k - d") };
    assert!(next > depth, "the depth strictly increases from level to level");
    assert!(next <= last, "no level deeper than k - d");
    assert!(
        next - depth >= m.min(last - depth),
        "every cut is at least m = max(Δdmin, 1), or what remains to k - d"
    );
    assert!(by_the_law(q, n + 1, depth, m, last, next), "D(n) = min(k - d, max(round(Δd √n), D(n-1) + m))");
    assert!(s.level() == n.unsigned_abs() + 1 && s.depth() == next, "the state is level n + 1 at its depth");
    assert!(
        invariant(q, m, last, n + 1, next, s.min_phase()),
        "the schedule's invariant holds at the next level"
    );
    if s.min_phase() {
        assert_eq!(
            levels_left(last, next, m) + 1,
            levels_left(last, depth, m),
            "the minimum-cut phase makes ceil((k - d - D) / m) more levels"
        );
    }
    cover!(n == 0, "the first level");
    cover!(next > depth + m && next < last, "a level by the law, beyond D(n) + m");
    cover!(!min_phase && s.min_phase() && next < last, "the minimum cut takes over");
    cover!(min_phase && next == depth + m && next < last, "a level of the minimum-cut phase");
    let clamped = depth + m > last || root_at_least(q, n + 1, last + 1);
    cover!(next == last && clamped, "a level cut short at k - d");
}
