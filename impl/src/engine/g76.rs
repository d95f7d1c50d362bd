//! The fixed-point G76 engine: the cycle of `cycleref_spec::g76::expand`
//! (the exact-decimal reference model, the authority) in integers, without
//! heap, floating point, `unsafe` or panics, streamed move by move.
//!
//! [`expand_g76`] checks the cycle completely before the first move: the
//! same errors, with the same values, in the same order as the reference
//! (`validate()`, the geometry, the lead-in on an X long axis, the rough
//! pass count, the thread and run-out lengths, the coordinates). It returns
//! a [`G76Moves`] iterator that then cannot fail: it yields exactly the
//! reference's moves, one by one.
//!
//! # The depth schedule
//!
//! Rough level `n` has the depth (DOMAIN decision 3)
//!
//! ```text
//! D(n) = min(k - d, max(round(Δd √n), D(n-1) + m)),   m = max(Δdmin, 1)
//! ```
//!
//! computed level by level in O(1): `round(Δd √n)` is the exact integer
//! square root of `Δd² n` rounded to nearest, guessed from the level
//! before and checked by two products
//! ([`round_sqrt_near`](super::arith::round_sqrt_near); Newton's method,
//! [`round_sqrt`](super::arith::round_sqrt), only when the guess is more
//! than a few increments off), and once the minimum cut
//! takes over (`round(Δd √n) < D(n-1) + m`) the schedule stops taking roots
//! and adds `m` per level. That is exact:
//!
//! *Claim.* If `round(Δd √n0) < D(n0-1) + m` at the first such level `n0`,
//! then `round(Δd √n) < D(n-1) + m` for every later level `n`.
//!
//! *Proof.* Write `a(n) = Δd √n`, concave, so `a(n+1) - a(n)` decreases.
//! Before `n0` every level follows the law: `D(n0-1) = round(a(n0-1))`, so
//! `a(n0-1) ≥ D(n0-1) - ½` (for `n0 = 1`, `a(0) = D(0) = 0`). At `n0`,
//! `round(a(n0)) ≤ D(n0-1) + m - 1`, so `a(n0) < D(n0-1) + m - ½` and the
//! step `a(n0) - a(n0-1) < m`. Every later step is smaller, so
//! `a(n0+j) < D(n0-1) + (j+1) m - ½`, hence `round(a(n0+j)) ≤ D(n0-1) +
//! (j+1) m - 1 < D(n0+j-1) + m`, because `D(n0+j-1) = D(n0-1) + j m` while
//! the schedule lasts (it stops at the first level that reaches `k - d`). ∎
//!
//! The rough pass count is found up front exactly as the reference finds it
//! (`check_pass_count`, reading R-LIMIT): levels by the law until the
//! minimum cut takes over, then `ceil((k - d - D) / m)` more at once; if the
//! law alone runs past the limit the count is only known to exceed it.
//!
//! # Integer widths, and why nothing overflows
//!
//! `validate()` bounds every length word by [`MAX_LENGTH`] `= 999_999_999
//! < 2^30` in magnitude, k, Δd ≥ 1, 0 ≤ Δdmin, d ≤ k, so `0 ≤ k - d < 2^30`.
//! Lengths are `i64` (radius increments for amounts, X-word increments for
//! X coordinates; `xf` = 1 or 2):
//!
//! * X of C and B: `|X(D)| + 2|i| + 2k < 5·2^30`; a pass starts between B
//!   and C and ends between D and its crest; the lead-in adds `2E < 2^31`;
//!   run-out X ends lie between the cut line and A. All far inside `i64`.
//! * Z: `|W| = |Z(D) - Z(A)| < 2^31`; Z shifts are `round(D tan(a/2))` with
//!   `tan(49.5°) < 1.18`, so `|shift| < 2^31` and a D2 left shift
//!   `2 zc - z < 2^32` (`-z > -2^31` under R-G78LEFT `mirror-b`); lead-in length is checked against the range before
//!   any point uses it.
//! * `Δd² n` is `u128`: `Δd² < 2^60` and `n ≤ pass_limit + 1 ≤ 2^32` in the
//!   up-front count, `n ≤ k - d < 2^30` while iterating, so `Δd² n < 2^92`.
//! * Run-out start on the cut line: `round(b + Δ·(r - b')/(e - b'))` needs
//!   products of two coordinates (`< 2^33` each), so the numerator is
//!   computed in `i128` (`< 2^67`).
//! * Chamfer length and lead-in length use the exact lead ratio of
//!   [`Lead::increments_per_rev`] in `u128`: numerators are at most
//!   `99 · 2^64 · 10^5 · 2 < 2^89` and `E · den + num < 2^102`, far below
//!   `2^128`. Beyond-range values saturate exactly as the reference's
//!   `unwrap_or(i64::MAX)` does.
//! * Z shifts and the chamfer's short axis go through
//!   [`crate::tan::mul_tan_round`] (`u128`, bit-identical to the reference).
//!
//! Every other operation is checked (`checked_*`, `saturating_*`) or bounded
//! by the comments next to it; no index, `unwrap`, `expect` or division can
//! panic.
//!
//! # Work and memory
//!
//! * Up front: O(1) plus one square root per rough level in the law phase,
//!   at most `pass_limit + 1` of them, as in the reference (each guessed
//!   from the level before: no division for most levels).
//! * Per move: a bounded number of steps. Each pass is a fixed list of at
//!   most six candidate moves (approach, lead-in, cut, run-out, retract,
//!   return), of which the zero-length ones are left out once per pass,
//!   when its walk is made (every start walks the same path from A); at
//!   least one remains (the cut and the run-out go from Bn to the end line,
//!   Z of D or beyond on a Z-long thread, X of the pass end on an X-long
//!   one; the pass start Bn is A only for a pass at depth 0, R-NOROUGH
//!   `one-at-zero`, with A on B). A move is then copied out of the walk;
//!   moving on to the next pass takes at most one square root; the next
//!   start, a binary gcd
//!   of numbers below 1000 (no division unless the angle must be reduced,
//!   [`StartSpacing`]).
//! * Memory: a [`G76Moves`] is a fixed-size value (840 bytes on 64-bit
//!   targets; `proofs/tests/engine_equals_spec.rs` checks the bound),
//!   whatever the number of passes and starts.

use core::cmp::Ordering;
use core::iter::FusedIterator;

use super::arith::saturate_i64;
use super::pass::{Frame, LongAxis, Walk};
use super::schedule::{formula_levels, law_near, Schedule};
use crate::angle::StartSpacing;
use crate::error::{CycleError, Field};
use crate::g76::{DepthMode, G76Cycle, Infeed, RunOut};
use crate::lead::{Lead, Ratio};
use crate::moves::{Flank, Move, Pass, PassKind};
use crate::readings::PassEnd;
use crate::tan::mul_tan_round;
use crate::units::{Length, Units, MAX_LENGTH};

/// Z shift of a pass at `depth`: `round(depth × tan(a ÷ 2))`, as the
/// reference's `flank_shift` (`depth ≤ k < 2^30`, so never `None`).
///
/// Twin: `spec/src/g76.rs`, `flank_shift`.
fn flank_shift(depth: i64, tool_angle: u32) -> i64 {
    mul_tan_round(depth, tool_angle).unwrap_or(0)
}

/// The rough pass count of a validated cycle, found before any move
/// exactly as the reference's `check_pass_count` (reading R-LIMIT).
///
/// Twin: `spec/src/g76.rs`, `check_pass_count`.
// Not inlined into `expand_g76`: inlined, its square-root loop ran about
// half as slow again (the same instructions; the flat benchmark's
// up-front count 184 µs against 120 µs), the last of the per-pass
// regression since e31a431 (CHANGELOG).
#[inline(never)]
fn check_pass_count(c: &G76Cycle) -> Result<PassCount, CycleError> {
    // validate(): 0 ≤ d ≤ k < 2^30, 0 ≤ Δdmin ≤ k, 1 ≤ Δd < 2^30.
    let last = c.thread_height - c.finishing_allowance;
    let min = c.min_cut.max(1);
    // Δd < 2^30: Δd² < 2^60.
    let q = c.first_depth.unsigned_abs();
    let q2 = q * q;
    let limit = u64::from(c.pass_limit);
    let mut depth = 0_i64;
    // The last law step, the guess of the next (law_near): Δd to level 1.
    let mut step = c.first_depth;
    let mut n = 0_u64;
    let mut count = crate::loop_counters::count!(PASS_COUNT);
    // The depth of the level before the last (0 when there are fewer than
    // two levels): every level is at least one increment deep.
    let mut penultimate = 0_i64;
    let levels = if c.depth_mode == DepthMode::Equal {
        // Every level adds max(Δd, Δdmin, 1) < 2^30: ceil((k - d) / step)
        // levels, 0 ≤ k - d < 2^30, the one before the last at (levels -
        // 1)·step < k - d.
        let step = c.first_depth.max(min);
        let levels = (last + step - 1) / step;
        if levels >= 2 {
            penultimate = (levels - 1) * step;
        }
        levels.unsigned_abs()
    } else if c.readings.depth_formula {
        // Reading R-DEPTH `formula`: exact, in closed form.
        if last > 0 {
            let (levels, pen) = formula_levels(q2, min, last);
            penultimate = pen;
            levels
        } else {
            0
        }
    } else {
        loop {
            count.tick();
            if depth >= last {
                break n;
            }
            // n ≤ limit + 1 ≤ 2^32: the loop returns once n > limit.
            n += 1;
            // depth = round(Δd √(n - 1)) here, reached by `step`.
            let law = law_near(q, q2, n, depth, step);
            // depth < last < 2^30 and min < 2^30: the sum is below 2^31.
            if law < depth + min {
                // 0 < rest < 2^30, 1 ≤ min < 2^30: ceil(rest / min) < 2^30.
                let rest = last - depth;
                let more = (rest + min - 1) / min;
                // Levels D(n-1) + j·min, j = 1..more, the last at k - d:
                // the one before it at D(n-1) + (more - 1)·min < k - d
                // (D(n-1) itself when more = 1, 0 when n = 1).
                penultimate = depth + (more - 1) * min;
                break n - 1 + more.unsigned_abs();
            }
            if law >= last {
                penultimate = depth;
                break n;
            }
            // depth ≤ law < k - d < 2^30.
            step = law - depth;
            depth = law;
            if n > limit {
                return Err(CycleError::TooManyPasses { passes: limit, exact: false, limit: c.pass_limit });
            }
        }
    };
    // Reading R-NOROUGH `one-at-zero`: one level at 0 when k - d = 0 (the
    // only case with no level above).
    let levels = levels.max(u64::from(c.readings.one_rough_at_zero));
    // levels < 2^33: doubling cannot overflow.
    let passes = c.infeed.passes(levels);
    if passes > limit {
        return Err(CycleError::TooManyPasses { passes, exact: true, limit: c.pass_limit });
    }
    check_work(c, passes)?;
    Ok(PassCount { passes, penultimate })
}

/// What [`check_pass_count`] finds: the rough pass count and the depth of
/// the level before the last (0 when there are fewer than two levels),
/// where the deepest left pass of D2 and of 交错 may lie (reading
/// R-G78LEFT `mirror-b`).
#[derive(Clone, Copy, Debug)]
struct PassCount {
    /// Rough passes.
    passes: u64,
    /// Depth of level f - 1, or 0.
    penultimate: i64,
}

/// Reading R-BUDGET: the whole cycle's pass paths, (rough + finishing) ×
/// starts, within the pass limit, before any move.
///
/// Twin: `spec/src/g76.rs`, `check_work`.
fn check_work(c: &G76Cycle, rough: u64) -> Result<(), CycleError> {
    // rough ≤ limit < 2^32, m < 2^32, starts < 2^32: saturating is exact
    // below u64::MAX, and u64::MAX is above every limit.
    let pass_paths =
        rough.saturating_add(u64::from(c.finishing_passes)).saturating_mul(u64::from(c.starts.max(1)));
    if pass_paths > u64::from(c.pass_limit) {
        return Err(CycleError::TooMuchWork { pass_paths, limit: c.pass_limit });
    }
    Ok(())
}

/// The number of rough passes of a cycle (D2 counts both flanks of a
/// level), after `validate()` and the pass limit, as the reference finds
/// it. It does not check the geometry: [`expand_g76`] does that first.
///
/// # Errors
///
/// Those of [`G76Cycle::validate`], then [`CycleError::TooManyPasses`].
pub fn rough_pass_count(cycle: &G76Cycle) -> Result<u64, CycleError> {
    cycle.validate()?;
    check_pass_count(cycle).map(|p| p.passes)
}

/// `round(num × ratio)` for `num ≥ 0`, ties away from zero, or `None` if it
/// overflows (it cannot, for any lead and factor used here: see the module
/// docs).
///
/// Twin: `spec/src/g76.rs`, `round_ratio`.
fn round_ratio(num: u128, r: Ratio) -> Option<u128> {
    let n = num.checked_mul(r.num)?;
    let twice = n.checked_mul(2)?.checked_add(r.den)?;
    twice.checked_div(r.den.checked_mul(2)?)
}

/// The run-out amounts `(J, K)` in increments, or `None` for no run-out,
/// as the reference's `run_out_amounts` (reading R-RUNOUT). `validate()`
/// has bounded the chamfer by the range table, so the saturations below
/// (to `i64::MAX`, as the reference's `unwrap_or`) are never reached for a
/// validated cycle.
///
/// Twin: `spec/src/g76.rs`, `run_out_amounts`.
pub(crate) fn run_out_amounts(
    run_out: RunOut,
    lead: Lead,
    units: Units,
    from_short_axis: bool,
) -> Option<(i64, i64)> {
    let (j, k) = match run_out {
        RunOut::None => return None,
        RunOut::Amounts { short, long } => (short, long),
        RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
            let lead = lead.increments_per_rev(units);
            // K = round(r × lead / 10): 10 × den ≤ 10 × 10 × 2^64.
            let chamfer = lead
                .den
                .checked_mul(10)
                .and_then(|den| round_ratio(u128::from(tenths_of_lead), Ratio { num: lead.num, den }))
                .and_then(|v| i64::try_from(v).ok())
                .unwrap_or(i64::MAX);
            // angle_degrees ≤ 89 (validate), so 2 × angle ≤ 178. Reading
            // R-CHAMFERANGLE: θ from the long axis, J = round(K·tan θ), or
            // from the short axis, J = round(K·tan(90° - θ)) (half degrees).
            let twice = angle_degrees.saturating_mul(2);
            let half_degrees = if from_short_axis { 180_u32.saturating_sub(twice) } else { twice };
            let short = mul_tan_round(chamfer, half_degrees).unwrap_or(i64::MAX);
            (short, long.unwrap_or(chamfer))
        }
    };
    if j == 0 {
        return None;
    }
    Some((j, k))
}

/// The long-axis length of the lead-in (reading R-LEADIN): the smallest
/// whole number `N ≥ 1` of leads with `N × lead ≥ E`, times the lead,
/// rounded to the increment; `i64::MAX` when that does not fit, as the
/// reference (`whole-leads`); 0 under `same-z`.
///
/// Twin: `spec/src/g76.rs`, `lead_in_length`.
fn lead_in_length(c: &G76Cycle) -> i64 {
    // Reading R-LEADIN `same-z`: An at the Z of Bn.
    if c.readings.lead_in_same_z {
        return 0;
    }
    let lead = c.lead.increments_per_rev(c.units);
    let e = u128::from(c.lead_in.unsigned_abs());
    // e < 2^30, den < 2^72, num < 2^81 (module docs): no overflow below.
    let leads = e
        .checked_mul(lead.den)
        .and_then(|ed| ed.checked_add(lead.num.checked_sub(1)?))
        .and_then(|v| v.checked_div(lead.num))
        .map(|v| v.max(1));
    leads.and_then(|n| round_ratio(n, lead)).and_then(|v| i64::try_from(v).ok()).unwrap_or(i64::MAX)
}

/// A pass coordinate beyond the range tables (reading R-RANGE).
///
/// Twin: `spec/src/g76.rs`, `check_coordinate`.
fn check_coordinate(v: i128, units: Units) -> Result<(), CycleError> {
    if v.unsigned_abs() > MAX_LENGTH.unsigned_abs().into() {
        return Err(CycleError::OutOfRange {
            field: Field::PassCoordinate,
            value: Length::new(saturate_i64(v), units),
        });
    }
    Ok(())
}

/// Where the pass sequence is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    /// Rough passes; `second_pending`: the D2 pass of the current level on
    /// its second flank comes next.
    Rough {
        /// The D2 pass of the current level on its second flank (the left
        /// one, the right one under reading R-INFEED `left-first`) is
        /// still to come.
        second_pending: bool,
    },
    /// Finishing passes.
    Finish,
    /// No more passes.
    Done,
}

/// The moves of a G76 cycle, in order: an [`Iterator`] of constant size
/// (see the [module documentation](self)) made by [`expand_g76`].
#[derive(Clone, Debug)]
pub struct G76Moves {
    /// Fixed values.
    frame: Frame,
    /// Rough levels.
    schedule: Schedule,
    /// Tool angle a (degrees).
    tool_angle: u32,
    /// Infeed mode.
    infeed: Infeed,
    /// Z shift of the centre passes: the centre line of the final form,
    /// `zc = round((k - d) tan(a/2))`, or 0 for G78 r = 0 under reading
    /// R-G78CENTRE `under-b`.
    centre: i64,
    /// The line left flanks mirror the right flank about (reading
    /// R-G78LEFT): `zc`, or 0 (B) under `mirror-b`.
    mirror: i64,
    /// The flank a level of D2, r = 4 and 交错 starts on (reading
    /// R-INFEED): the right one, the left under `left-first`.
    first: Flank,
    /// Z shift of the last rough pass planned (0 before the first): where
    /// the finishing passes start ("精车 Z 轴起切点与最后一刀粗车一致").
    finish: i64,
    /// d.
    allowance: i64,
    /// m.
    finishing_passes: u32,
    /// Position in the pass sequence.
    stage: Stage,
    /// Depth of the previous rough level.
    previous: i64,
    /// Number of the last rough pass (or finishing pass, in [`Stage::Finish`]).
    number: u32,
    /// The current pass of the current start, streamed.
    walk: Walk,
    /// Current start, 0-based.
    start: u32,
    /// The number of rough passes, found before any move (reading R-LIMIT).
    rough_passes: u64,
    /// Reading R-STARTS: `None` under `pass-major`; under `start-major`,
    /// whether the schedule starts in its minimum-cut phase (G78's equal
    /// steps), to restart it for each start.
    start_major: Option<bool>,
}

/// What the up-front checks need of the planned passes: the depth of the
/// first (shallowest) pass and the smallest and largest Z shifts, or `None`
/// when the cycle has no pass at all.
#[derive(Clone, Copy, Debug)]
struct PlanExtremes {
    /// Depth of the first planned pass: D1, or k when there is no rough level.
    shallowest: i64,
    /// Smallest Z shift of a pass.
    min_shift: i64,
    /// Largest Z shift of a pass.
    max_shift: i64,
}

/// The [`PlanExtremes`] of a cycle whose pass count has been checked:
/// `count` from [`check_pass_count`], `zc` the shift of the last level,
/// `centre` the centre passes' and `mirror` the left flanks' mirror line.
fn plan_extremes(
    c: &G76Cycle,
    last: i64,
    count: PassCount,
    zc: i64,
    centre: i64,
    mirror: i64,
) -> Option<PlanExtremes> {
    if last <= 0 {
        // d = k: one rough level at depth 0 (reading R-NOROUGH
        // `one-at-zero`) or none, then the finishing passes (if any) at
        // depth k; every pass at shift 0 (zc = 0, so every mode's shift
        // and mirror line is 0).
        let rough = c.readings.one_rough_at_zero;
        return (rough || c.finishing_passes > 0).then_some(PlanExtremes {
            shallowest: if rough { 0 } else { c.thread_height },
            min_shift: 0,
            max_shift: 0,
        });
    }
    // D1 = min(k - d, max(round(Δd √1), 0 + m)), with round(Δd √1) = Δd;
    // the equal-step schedule's first level is the same, min(k - d, max(Δd,
    // m)).
    let d1 = last.min(c.first_depth.max(c.min_cut.max(1)));
    let right1 = flank_shift(d1, c.tool_angle);
    // Right shifts grow with the depth, in [right1, zc]; left shifts are
    // 2·mirror - right (mirror = zc or 0; |values| < 2^32), so they shrink
    // with the depth. D2 cuts a left pass at every level but the last (the
    // deepest at level f - 1), r = 1 at every level, the 980TDi's 交错 at
    // the even levels. The finishing passes repeat the last rough shift.
    let left = |right: i64| 2 * mirror - right;
    // Reading R-INFEED: the flanks of D2's and 交错's levels in their order;
    // each shift is monotonic in the depth, so its extremes over a run of
    // levels are at the run's ends.
    let left_first = c.readings.left_first;
    let first = |right: i64| if left_first { left(right) } else { right };
    let second = |right: i64| if left_first { right } else { left(right) };
    let two_levels = d1 < last;
    let ends = |a: i64, b: i64, c: i64, d: i64| (a.min(b).min(c).min(d), a.max(b).max(c).max(d));
    let (min_shift, max_shift) = match c.infeed {
        Infeed::LeftRight if two_levels => {
            // first at every level, second at levels 1 … f - 1.
            let pen = flank_shift(count.penultimate, c.tool_angle);
            ends(first(right1), first(zc), second(right1), second(pen))
        }
        Infeed::LeftRight => (first(zc), first(zc)),
        Infeed::RightFlank | Infeed::RightCentre => (right1, zc),
        Infeed::Centre => (centre, centre),
        Infeed::LeftFlank => (left(zc), left(right1)),
        Infeed::Alternating if two_levels => {
            let mut levels = schedule_of(c);
            let d2 = levels.next_level().and_then(|_| levels.next_level()).unwrap_or(last);
            // The deepest odd (first flank) and even (second) levels: f
            // and f - 1.
            let pen = flank_shift(count.penultimate, c.tool_angle);
            let (odd, even) = if count.passes % 2 == 1 { (zc, pen) } else { (pen, zc) };
            ends(first(right1), first(odd), second(flank_shift(d2, c.tool_angle)), second(even))
        }
        Infeed::Alternating => (first(zc), first(zc)),
    };
    Some(PlanExtremes { shallowest: d1, min_shift, max_shift })
}

/// The schedule of a validated cycle before its first level: the depth law
/// with the minimum cut (G76; G78 递减式), or, from the start, equal steps
/// of `max(Δd, Δdmin, 1)` (G78 等距离), which is the minimum-cut phase with
/// that step.
fn schedule_of(c: &G76Cycle) -> Schedule {
    // 1 ≤ Δd < 2^30 (validate()): fits u32.
    let q = c.first_depth.unsigned_abs();
    let last = c.thread_height - c.finishing_allowance;
    let min = c.min_cut.max(1);
    let one_at_zero = c.readings.one_rough_at_zero;
    match c.depth_mode {
        DepthMode::Decreasing => Schedule {
            q: u32::try_from(q).unwrap_or(u32::MAX),
            min,
            last,
            n: 0,
            depth: 0,
            min_phase: false,
            one_at_zero,
            // Reading R-DEPTH.
            formula: c.readings.depth_formula,
            law_n: 0,
            step: i32::try_from(c.first_depth).unwrap_or(i32::MAX),
        },
        DepthMode::Equal => Schedule {
            q: u32::try_from(q).unwrap_or(u32::MAX),
            min: c.first_depth.max(min),
            last,
            n: 0,
            depth: 0,
            min_phase: true,
            one_at_zero,
            formula: false,
            law_n: 0,
            step: i32::try_from(c.first_depth).unwrap_or(i32::MAX),
        },
    }
}

/// Expands a G76 cycle: checks it completely, then streams its moves.
///
/// The result equals `cycleref_spec::g76::expand(cycle)` exactly: the same
/// error, or an iterator of the same moves in the same order.
///
/// # Errors
///
/// The manual's alarms, as [`CycleError`], in the reference's order:
/// [`G76Cycle::validate`], [`CycleError::StartInsideThread`],
/// [`CycleError::LeadInOnXLongAxis`], [`CycleError::TooManyPasses`],
/// [`CycleError::ThreadTooShort`], [`CycleError::RunOutTooLong`], [`CycleError::RunOutIntoWork`],
/// [`CycleError::OutOfRange`] for a pass coordinate.
///
/// Twin: `spec/src/g76.rs`, `expand` (and `geometry` for the checks).
pub fn expand_g76(cycle: &G76Cycle) -> Result<G76Moves, CycleError> {
    let c = cycle;
    let Planned { frame, centre, mirror, rough_passes, start_major } = plan(c)?;
    // Made in place as the result (a value built first and then moved
    // into it was copied whole, 840 bytes, once per cycle), with no pass
    // loaded yet: the first call of `next` finds the walk empty and
    // `advance` plans the first pass, at start 1 (`start` is the last
    // start under `pass-major`, so that `advance` moves on to the next
    // pass rather than to another start of none; the first under
    // `start-major`).
    Ok(G76Moves {
        frame,
        schedule: schedule_of(c),
        tool_angle: c.tool_angle,
        infeed: c.infeed,
        centre,
        mirror,
        first: if c.readings.left_first { Flank::Left } else { Flank::Right },
        finish: 0,
        allowance: c.finishing_allowance,
        finishing_passes: c.finishing_passes,
        stage: Stage::Rough { second_pending: false },
        previous: 0,
        number: 0,
        // Start 0's angle, 0° (`StartSpacing::angle`), in the first bank.
        walk: Walk::idle(c.lead, 0, frame.spacing.angle(0)),
        start: if start_major.is_some() { 0 } else { c.starts.saturating_sub(1) },
        rough_passes,
        start_major,
    })
}

/// Checks a G76 cycle as [`expand_g76`] checks it, without making its
/// iterator: `Ok` exactly when `expand_g76` gives the moves, else the
/// same alarm (one home for the checks, the private `plan`). The first
/// phase of a run checks every cycle before the second writes its moves
/// (issue 33: the iterator made, moved and dropped was about a third of
/// the first phase's work on a G76).
///
/// # Errors
///
/// As [`expand_g76`].
///
/// ```
/// use cycleref::engine::{check_g76, expand_g76};
/// use cycleref::examples::M68X6;
///
/// assert_eq!(check_g76(&M68X6), Ok(()));
/// let mut inside = M68X6;
/// // A at X66: inside the thread (the root at X60.64, the crest at X68 on
/// // diameter: 60.64 + 2 × 3.68), an alarm by both.
/// inside.start.x = 66_000;
/// assert_eq!(check_g76(&inside).err(), expand_g76(&inside).err());
/// assert_eq!(check_g76(&inside), Err(cycleref::CycleError::StartInsideThread));
/// ```
pub fn check_g76(cycle: &G76Cycle) -> Result<(), CycleError> {
    plan(cycle).map(drop)
}

/// What [`plan`] found of a cycle that passed every check: the parts of
/// [`G76Moves`] that the checks compute.
struct Planned {
    frame: Frame,
    centre: i64,
    mirror: i64,
    rough_passes: u64,
    start_major: Option<bool>,
}

/// Every check of [`expand_g76`], in its order, and the frame of the
/// cycle that passes them.
#[inline(always)]
fn plan(cycle: &G76Cycle) -> Result<Planned, CycleError> {
    let c = cycle;
    c.validate()?;
    let u = c.units;
    let len = |v: i64| Length::new(v, u);
    let xf = c.x_mode.factor();
    let (a, d) = (c.start, c.end);
    // Geometry (reading R-SIDE); |X(D)| + 2|i| + 2k < 5·2^30.
    let c_x = d.x + xf * c.taper;
    let side = match a.x.cmp(&c_x) {
        Ordering::Greater => 1,
        Ordering::Less => -1,
        Ordering::Equal => return Err(CycleError::StartInsideThread),
    };
    let b_x = c_x + side * xf * c.thread_height;
    let crest_at_end = d.x + side * xf * c.thread_height;
    // Reading R-SIDE `accept`: an A inside the crest is made as written.
    let inside = side * (a.x - b_x) < 0 || side * (a.x - crest_at_end) < 0;
    if inside && !c.readings.accept_start_inside {
        return Err(CycleError::StartInsideThread);
    }
    // W ≠ 0 (validate: no face thread), |W| < 2^31.
    let w = d.z - a.z;
    let direction = if w > 0 { 1 } else { -1 };
    let w_abs = w.abs();
    let taper_abs = c.taper.abs();
    // Reading R-LONG, or R-LONG988 `table` (a 988TA G78: Z whatever the
    // displacements).
    let long_axis =
        if w_abs > taper_abs || c.readings.long_axis_by_table { LongAxis::Z } else { LongAxis::X };
    if long_axis == LongAxis::X && c.lead_in > 0 {
        return Err(CycleError::LeadInOnXLongAxis);
    }
    let count = check_pass_count(c)?;
    let rough_passes = count.passes;
    let last = c.thread_height - c.finishing_allowance;
    let zc = flank_shift(last, c.tool_angle);
    // Readings R-G78CENTRE (G78 r = 0 under B) and R-G78LEFT (left flanks
    // mirrored about B).
    let centre = if c.infeed == Infeed::Centre && c.readings.centre_under_b { 0 } else { zc };
    let mirror = if c.readings.left_mirror_b { 0 } else { zc };
    let extremes = plan_extremes(c, last, count, zc, centre, mirror);
    let max_shift = extremes.map_or(0, |p| p.max_shift);
    let run_out = run_out_amounts(c.run_out, c.lead, c.units, c.readings.chamfer_from_short_axis);
    let lead_in = if c.lead_in > 0 { Some((c.lead_in, lead_in_length(c))) } else { None };

    // Note 7 and reading R-SHORT; on either long axis a pass whose shift
    // reaches |W| would start at or beyond the end line.
    if max_shift >= w_abs {
        return Err(CycleError::ThreadTooShort { shift: len(max_shift), length: len(w_abs) });
    }
    let pass_end = c.readings.pass_end;
    match long_axis {
        LongAxis::Z => {
            if let Some((_, kk)) = run_out {
                // The shortest pass along Z: |W| less the largest shift,
                // or |W| when every pass is C→D translated (R-END).
                let length = if pass_end == PassEnd::Translated { w_abs } else { w_abs - max_shift };
                if kk > length {
                    return Err(CycleError::RunOutTooLong { run_out: len(kk), length: len(length) });
                }
            }
        }
        LongAxis::X => {
            if let Some((_, kk)) = run_out {
                // The shortest pass along X (radius): |i|, or for a
                // `parallel` pass |i| (|W| - largest shift) / |W|, floored
                // (K, an integer, exceeds it exactly when it exceeds the
                // floor). |i| < 2^31, |W| < 2^31.
                let length = if pass_end == PassEnd::Parallel {
                    let num = i128::from(taper_abs) * i128::from(w_abs - max_shift);
                    saturate_i64(num / i128::from(w_abs))
                } else {
                    taper_abs
                };
                if kk > length {
                    return Err(CycleError::RunOutTooLong { run_out: len(kk), length: len(length) });
                }
                // Reading R-XRUNOUT: along Z towards A is into the work
                // when the cut line rises towards A (s·i > 0); `towards-start`
                // makes it.
                if side * c.taper > 0 && !c.readings.x_run_out_towards_start {
                    return Err(CycleError::RunOutIntoWork { taper: len(c.taper) });
                }
            }
        }
    }
    // Reading R-RANGE: A and D are words within range and B lies between A
    // and C, so X of C and the lead-in start are the extremes. The lead-in
    // start is furthest out on the shallowest pass, and on Z at the
    // smallest shift. Sums of values below 2^33, in i128. Every pass's
    // shift is below |W| (checked above), so its Z lies between A and D,
    // or, under R-G78LEFT `mirror-b`, beyond A by at most zc (checked
    // below).
    check_coordinate(i128::from(c_x), u)?;
    // Reading R-SIDE `accept`: A may lie inside the crest, B beyond it; the
    // shallowest pass starts and ends furthest out (a `parallel` end lies
    // between the two).
    if let (true, Some(p)) = (c.readings.accept_start_inside, extremes) {
        let out = i128::from(side * xf) * i128::from(c.thread_height - p.shallowest);
        check_coordinate(i128::from(c_x) + out, u)?;
        check_coordinate(i128::from(d.x) + out, u)?;
    }
    if let (Some((e, lz)), Some(p)) = (lead_in, extremes) {
        let out = i128::from(side * xf);
        let x = i128::from(c_x) + out * i128::from(c.thread_height - p.shallowest) + out * i128::from(e);
        check_coordinate(x, u)?;
        let t = i128::from(direction);
        // lz may be i64::MAX (the reference's saturation).
        let z = i128::from(a.z) + t * i128::from(p.min_shift) - t * i128::from(lz);
        check_coordinate(z, u)?;
    }
    // Reading R-END `translated`: the passes end beyond D along Z, the
    // furthest by the largest shift.
    if pass_end == PassEnd::Translated {
        check_coordinate(i128::from(d.z) + i128::from(direction) * i128::from(max_shift), u)?;
    }
    // Reading R-G78LEFT `mirror-b`: a left pass starts beyond the Z of A,
    // furthest at the smallest (negative) shift.
    if let Some(p) = extremes.filter(|p| p.min_shift < 0) {
        check_coordinate(i128::from(a.z) + i128::from(direction) * i128::from(p.min_shift), u)?;
    }
    // Reading R-RUNOUT `gsk988-only`: J as written, not clamped at the
    // retract. Z long: furthest out at the end of the shallowest pass; X
    // long: J along Z from the end of the pass towards A (the end at the
    // smallest shift when the passes are translated). J ≤ 57 × MAX_LENGTH,
    // in i128.
    if let (Some((j, _)), Some(p), false) = (run_out, extremes, c.readings.clamp_run_out) {
        let (j, out) = (i128::from(j), i128::from(side * xf));
        let t = i128::from(direction);
        let beyond = match long_axis {
            LongAxis::Z => i128::from(d.x) + out * i128::from(c.thread_height - p.shallowest) + out * j,
            LongAxis::X if pass_end == PassEnd::Translated => {
                i128::from(d.z) + t * i128::from(p.min_shift) - t * j
            }
            LongAxis::X => i128::from(d.z) - t * j,
        };
        check_coordinate(beyond, u)?;
    }

    let frame = Frame {
        a,
        home: a,
        transposed: false,
        d,
        c_x,
        xf,
        side,
        direction,
        w_abs,
        k: c.thread_height,
        long_axis,
        run_out,
        clamp_run_out: c.readings.clamp_run_out,
        pass_end,
        lead_in,
        starts: c.starts,
        spacing: {
            #[cfg(feature = "loop-counters")]
            StartSpacing::record_new_gcd(c.starts);
            StartSpacing::new(c.starts)
        },
    };
    let start_major = c.readings.start_major.then_some(c.depth_mode == DepthMode::Equal);
    Ok(Planned { frame, centre, mirror, rough_passes, start_major })
}

impl G76Moves {
    /// The number of rough passes of the cycle, as [`rough_pass_count`]
    /// gives it: [`expand_g76`] counted them (reading R-LIMIT) before it
    /// returned.
    ///
    /// ```
    /// use cycleref::engine::rough_pass_count;
    /// use cycleref::examples::M68X6;
    /// use cycleref::expand_g76;
    ///
    /// // k − d = 3.58; the levels 1.8·√n are 1.8, 2.546, 3.118, then 3.6,
    /// // which the last level, at 3.58, takes the place of.
    /// assert_eq!(expand_g76(&M68X6)?.rough_passes(), 4);
    /// assert_eq!(rough_pass_count(&M68X6)?, 4);
    /// # Ok::<(), cycleref::CycleError>(())
    /// ```
    #[must_use]
    pub fn rough_passes(&self) -> u64 {
        self.rough_passes
    }

    /// The path of this start is done: the next start, or the next pass
    /// (reading R-STARTS `pass-major`); the next pass of this start
    /// (`start-major`).
    #[inline(never)]
    fn advance(&mut self) {
        let next = self.start.saturating_add(1);
        if self.start_major.is_none() && next < self.frame.starts {
            self.begin_start(next);
        } else {
            self.next_pass();
        }
    }

    /// Moves on to the next planned pass (at start 1, or at the current
    /// start under R-STARTS `start-major`), or to [`Stage::Done`]. Under
    /// `start-major`, after the last pass of a start the plan restarts
    /// from its first level for the next start (the schedule's state at
    /// level 0, `Schedule::with_state`): constant memory, whatever L.
    fn next_pass(&mut self) {
        let mut planned = self.plan_next();
        if let (None, Some(min_phase)) = (planned, self.start_major) {
            let next = self.start.saturating_add(1);
            if next < self.frame.starts {
                if let Some(s) = self.schedule.with_state(0, 0, min_phase) {
                    self.schedule = s;
                    self.stage = Stage::Rough { second_pending: false };
                    (self.previous, self.number, self.finish, self.start) = (0, 0, 0, next);
                    planned = self.plan_next();
                }
            }
        }
        let Some((pass, shift)) = planned else {
            self.stage = Stage::Done;
            return;
        };
        let path = self.frame.path(pass.depth, shift);
        self.walk.load(path, pass, self.frame.home);
        // start < L ≤ 999; 0 under `pass-major`.
        self.begin_start(if self.start_major.is_some() { self.start } else { 0 });
    }

    /// Starts the path of the current pass for start `start` (0-based).
    /// The start expected next is the next one, after the last the first
    /// (`pass-major`: the next pass's; `start-major` repeats a start for
    /// each pass and then goes on to the next).
    #[inline(always)]
    fn begin_start(&mut self, start: u32) {
        self.start = start;
        // start < L ≤ 999.
        let number = u16::try_from(start + 1).unwrap_or(u16::MAX);
        let next = if start + 1 < self.frame.starts { start + 1 } else { 0 };
        let spacing = self.frame.spacing;
        self.walk.restart(number, start, next, |i| {
            #[cfg(feature = "loop-counters")]
            spacing.record_angle_gcd(i);
            spacing.angle(i)
        });
    }

    /// The next planned pass and its Z shift, as the reference's
    /// `planned_passes` (readings R-INFEED, R-FINISH), with `start` 1.
    ///
    /// Twin: `spec/src/g76.rs`, `planned_passes`.
    // Inlined into `next_pass`: a `(Pass, i64)` returned through memory
    // was written piece by piece and read back in 16-byte loads (a
    // store-forwarding stall per pass).
    #[inline(always)]
    fn plan_next(&mut self) -> Option<(Pass, i64)> {
        let mut count = crate::loop_counters::count!(PLAN_NEXT);
        loop {
            count.tick();
            match self.stage {
                Stage::Rough { second_pending: true } => {
                    self.stage = Stage::Rough { second_pending: false };
                    let depth = self.schedule.depth;
                    let right = flank_shift(depth, self.tool_angle);
                    // The rough count is at most pass_limit ≤ u32::MAX.
                    self.number = self.number.saturating_add(1);
                    let flank = self.second();
                    let pass = self.rough(depth, flank);
                    self.finish = self.shift_on(flank, right);
                    return Some((pass, self.finish));
                }
                Stage::Rough { second_pending: false } => {
                    let previous = self.schedule.depth;
                    let Some(depth) = self.schedule.next_level() else {
                        self.stage = Stage::Finish;
                        self.number = 0;
                        continue;
                    };
                    self.previous = previous;
                    self.number = self.number.saturating_add(1);
                    let right = flank_shift(depth, self.tool_angle);
                    let (flank, shift) = match self.infeed {
                        Infeed::RightFlank => (Flank::Right, right),
                        Infeed::RightCentre if self.schedule.n % 2 == 0 => (Flank::Centre, self.centre),
                        Infeed::RightCentre => (Flank::Right, right),
                        Infeed::Centre => (Flank::Centre, self.centre),
                        Infeed::LeftFlank => (Flank::Left, self.shift_on(Flank::Left, right)),
                        Infeed::Alternating if self.schedule.n % 2 == 0 => {
                            let second = self.second();
                            (second, self.shift_on(second, right))
                        }
                        Infeed::Alternating => (self.first, self.shift_on(self.first, right)),
                        Infeed::LeftRight => {
                            // Every level but the last (the one at k - d) twice.
                            self.stage = Stage::Rough { second_pending: depth < self.schedule.last };
                            (self.first, self.shift_on(self.first, right))
                        }
                    };
                    self.finish = shift;
                    return Some((self.rough(depth, flank), shift));
                }
                Stage::Finish => {
                    if self.number >= self.finishing_passes {
                        self.stage = Stage::Done;
                        return None;
                    }
                    // number < m ≤ 99.
                    self.number += 1;
                    let cut = if self.number == 1 { self.allowance } else { 0 };
                    let pass = Pass {
                        kind: PassKind::Finish,
                        number: self.number,
                        start: 1,
                        depth: self.frame.k,
                        cut,
                        flank: Flank::Centre,
                    };
                    return Some((pass, self.finish));
                }
                Stage::Done => return None,
            }
        }
    }

    /// The flank a level of D2, r = 4 and 交错 takes second (reading
    /// R-INFEED).
    fn second(&self) -> Flank {
        if self.first == Flank::Left {
            Flank::Right
        } else {
            Flank::Left
        }
    }

    /// The Z shift of a pass on `flank` whose right-flank shift is `right`:
    /// `right`, or `2 mirror - right` on the left flank (R-G78LEFT).
    fn shift_on(&self, flank: Flank, right: i64) -> i64 {
        // |mirror| < 2^31, 0 ≤ right ≤ zc < 2^31.
        if flank == Flank::Left {
            2 * self.mirror - right
        } else {
            right
        }
    }

    /// A rough pass of the current level.
    fn rough(&self, depth: i64, flank: Flank) -> Pass {
        Pass {
            kind: PassKind::Rough,
            number: self.number,
            start: 1,
            depth,
            cut: depth - self.previous,
            flank,
        }
    }
}

impl Iterator for G76Moves {
    type Item = Move;

    // Inlined across crates: a call per move costs more than the move, and
    // a `Move` returned through memory is assembled there piece by piece
    // and read back whole (a store-forwarding stall per move). Only the
    // walk is inline; the next start or pass is a call (`advance`), once
    // per path.
    #[inline(always)]
    fn next(&mut self) -> Option<Move> {
        let mut count = crate::loop_counters::count!(G76_NEXT);
        loop {
            count.tick();
            // The walk first: a cycle is done only once its last path has
            // been walked (`next_pass` ends it when the walk is at its
            // end, and nothing loads the walk after that), so a move is
            // made without looking at the stage.
            if let Some(m) = self.walk.next_move() {
                return Some(m);
            }
            if self.stage == Stage::Done {
                return None;
            }
            self.advance();
        }
    }
}

impl FusedIterator for G76Moves {}
