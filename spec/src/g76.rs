//! The G76 multiple thread-cutting cycle, exactly as the manuals define it.
//!
//! Sources: seed 000 (GSK extended G76, the authority), manuals/gsk988ta-g76.txt,
//! manuals/gsk980tdi-g76.txt, manuals/gsk988ta-g78.txt (figures of the infeed
//! modes and the lead-in), seed 004 (FANUC teaching notes), and the decisions
//! of DOMAIN.md. Every reading chosen where the sources are silent or
//! ambiguous carries an id `R-…` and is collected, with its source and reason,
//! in `docs/INTERPRETATIONS.md`.
//!
//! Lengths here are exact decimals in mm (inch); radius amounts are radius
//! values as in the manual, and X coordinates are converted to X words
//! (diameters by default) only when a point is formed. Every rounding goes
//! to the least increment, nearest, ties away from zero (DOMAIN decision 2),
//! through [`crate::exact`] and [`crate::tan`], never through floating point.
//!
//! The points, in the manual's names:
//!
//! | point | definition |
//! |---|---|
//! | A | start point: the tool position before the cycle, where it returns |
//! | D | thread end: X(U) Z(W) of block 2 |
//! | C | thread start: Z of A, X of D plus i (radius) |
//! | B | depth reference: Z of A, X of C plus k towards A (depth 0) |
//! | Bn | start of pass n: depth Dn below B, shifted along Z |
//! | E | retract end: X of A, on the line through the end of the pass |

use cycleref::angle::StartAngle;
use cycleref::error::{CycleError, Field};
use cycleref::g76::{DepthMode, G76Cycle, Infeed, RunOut};
use cycleref::lead::{Lead, Ratio};
use cycleref::moves::{Flank, Move, Pass, PassKind};
use cycleref::readings::PassEnd;
use cycleref::units::{Length, MAX_LENGTH};
use cycleref::Units;
use rust_decimal::Decimal;

use crate::exact::{ceil_div, from_increments, quantize, round_div, round_sqrt, to_increments};
use crate::pass::{pass_path, PassFrame, PassStream};

/// Which axis is the long axis (长轴) of the thread.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LongAxis {
    /// |W| > |i|: Z is the long axis (the ordinary case).
    Z,
    /// |i| >= |W|: X is the long axis (a steep taper).
    X,
}

/// The fixed geometry of a cycle, in the manual's terms.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `Geometry`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Geometry {
    /// A, in X-word units.
    pub a: (Decimal, Decimal),
    /// D, in X-word units.
    pub d: (Decimal, Decimal),
    /// X of C (X-word units).
    pub c_x: Decimal,
    /// X of B (X-word units).
    pub b_x: Decimal,
    /// +1 when A lies outside C (external thread), -1 inside (internal).
    pub side: i64,
    /// Sign of Z(D) - Z(A): +1 cutting towards +Z, -1 towards -Z.
    pub direction: i64,
    /// The long axis.
    pub long_axis: LongAxis,
    /// X-word units per radius unit: 2 for diameter X, 1 for radius X.
    pub x_factor: Decimal,
}

/// One planned pass: the depth of its level and where it starts along Z.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlannedPass {
    /// Kind, number, depth, cut and flank (lengths in increments).
    pub pass: Pass,
    /// Shift of Bn from the Z of A, towards D (mm, inch).
    pub z_shift: Decimal,
}

fn len(v: Decimal, u: Units) -> Length {
    Length::new(to_increments(quantize(v, u), u), u)
}

/// Geometry of the cycle (seed 000, "执行过程" table of points).
///
/// * C: "Z 轴绝对坐标与 A 点相同、X 轴绝对坐标与 D 点 X 轴绝对坐标的差值为 i".
/// * B: "Z 轴绝对坐标与 A 点相同、X 轴绝对坐标与 C 点 X 轴绝对坐标的差值为 k",
///   on the side of A (reading R-SIDE: external when A is outside C,
///   internal when inside).
/// * Long axis (reading R-LONG): "C 点与 D 点 Z 轴坐标差的绝对值大于 X 轴坐标差的绝对值 (半径值,
///   等于 i 的绝对值) 时, Z 轴为长轴; 反之, X 轴为长轴".
///
/// # Errors
///
/// [`CycleError::StartInsideThread`] when A is not clear of the thread
/// (reading R-SIDE `refuse-inside`), or on the X of C (no side, under
/// either value).
///
/// Twin: `impl/src/engine/g76.rs`, `expand_g76` (the same checks in
/// integers).
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `geometry`.
pub fn geometry(c: &G76Cycle) -> Result<Geometry, CycleError> {
    let u = c.units;
    let xf = Decimal::from(c.x_mode.factor());
    let a = (from_increments(c.start.x, u), from_increments(c.start.z, u));
    let d = (from_increments(c.end.x, u), from_increments(c.end.z, u));
    let i = from_increments(c.taper, u);
    let k = from_increments(c.thread_height, u);
    let c_x = d.0 + xf * i;
    let side = match a.0.cmp(&c_x) {
        std::cmp::Ordering::Greater => 1,
        std::cmp::Ordering::Less => -1,
        std::cmp::Ordering::Equal => return Err(CycleError::StartInsideThread),
    };
    let s = Decimal::from(side);
    let b_x = c_x + s * xf * k;
    let crest_at_end = d.0 + s * xf * k;
    // Reading R-SIDE `accept`: an A inside the crest is made as written.
    let inside = s * (a.0 - b_x) < Decimal::ZERO || s * (a.0 - crest_at_end) < Decimal::ZERO;
    if inside && !c.readings.accept_start_inside {
        return Err(CycleError::StartInsideThread);
    }
    let w = d.1 - a.1;
    let direction = if w > Decimal::ZERO { 1 } else { -1 };
    // Reading R-LONG988 `table` (a 988TA G78): Z whatever the displacements.
    let long_axis =
        if w.abs() > i.abs() || c.readings.long_axis_by_table { LongAxis::Z } else { LongAxis::X };
    Ok(Geometry { a, d, c_x, b_x, side, direction, long_axis, x_factor: xf })
}

/// `round(Δd × √n)` to the least increment (seed 000 "切深计算": "X 轴切深:
/// √n × Q(Δd)"), exactly: with `q` = Δd in increments it is the integer
/// nearest to `√(q² n)`.
///
/// Twin: `impl/src/engine/schedule.rs`, `law`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `depth_by_law`.
#[must_use]
pub fn depth_by_law(first_depth: Decimal, n: u64, u: Units) -> Decimal {
    let q = u128::try_from(to_increments(first_depth, u)).unwrap_or(0);
    let s = round_sqrt(q * q * u128::from(n));
    from_increments(i64::try_from(s).unwrap_or(i64::MAX), u)
}

/// The smallest cut the schedule allows: Δdmin, and never less than one
/// increment (DOMAIN decision 3: `max(Δdmin, 1 increment)`), so the
/// schedule always advances.
#[must_use]
pub fn effective_min_cut(min_cut: Decimal, u: Units) -> Decimal {
    min_cut.max(from_increments(1, u))
}

/// Depth of rough level `n` from the previous level's depth (reading
/// R-DEPTH, DOMAIN decision 3, seed 000 "注意 1"):
///
/// `Dn = min(k - d, max(round(Δd √n), D(n-1) + max(Δdmin, 1 increment)))`.
///
/// Seed 000: "如果 X 轴切削量小于最小切削量 … X 轴切削量 = 最小切削量 …
/// 下一刀的 X 轴切深 = 最小切削量 + 前一刀的切深 … 如果 X 轴切深 ≥ 牙高 P(k) −
/// 精车切削量 R(d) 则 X 轴切深 = 牙高 P(k) − 精车切削量 R(d)".
///
/// Twin: `impl/src/engine/schedule.rs`, `Schedule::next_level`.
///
/// G78's equal steps (等距离进刀, "等距离进刀的每次切削量为 Q(△d)", with the
/// minimum cut as for every rough cut: "当粗车切削量小于△dmin时，以△dmin作为
/// 本次粗车的切削量"): `Dn = min(k - d, D(n-1) + max(Δd, Δdmin, 1
/// increment))`.
///
/// Under reading R-DEPTH `formula` (988TA G76 step (5), 980TDi step ⑤:
/// "切深取（√n×△d）、（√(n-1)×△d+△dmin）中的较大值", on every level):
/// `Dn = min(k - d, max(round(Δd √n), round(Δd √(n-1)) + m, D(n-1) + 1
/// increment))`. The page's Δdmin is taken as `m = max(Δdmin, 1
/// increment)`, which changes nothing: with Δdmin = 0, `round(Δd √(n-1)) +
/// 1 ≤ D(n-1) + 1`, the last term, since every level is at least as deep
/// as the law.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `next_depth`.
#[must_use]
pub fn next_depth(c: &G76Cycle, n: u64, previous: Decimal) -> Decimal {
    let u = c.units;
    let last = from_increments(c.thread_height - c.finishing_allowance, u);
    let first = from_increments(c.first_depth, u);
    let min = effective_min_cut(from_increments(c.min_cut, u), u);
    match c.depth_mode {
        DepthMode::Decreasing if c.readings.depth_formula => {
            let by_formula = depth_by_law(first, n - 1, u) + min;
            last.min(depth_by_law(first, n, u).max(by_formula).max(previous + from_increments(1, u)))
        }
        DepthMode::Decreasing => last.min(depth_by_law(first, n, u).max(previous + min)),
        DepthMode::Equal => last.min(previous + first.max(min)),
    }
}

/// Reading R-DEPTH `formula`: the number of rough levels of a schedule with
/// Δd = `q`, `m = max(Δdmin, 1)` and `k - d` = `last` (increments, `last >
/// 0`), in closed form. With `N(n) = round(q √n)` (`N(0) = 0`), `E(n) =
/// max(N(n), N(n-1) + m)` and `F(n) = max(E(n), F(n-1) + 1)` (`F(0) = 0`),
/// the levels are `min(k - d, F(n))` until the first `F(n) ≥ k - d`.
///
/// * `δ(j) = q (√j - √(j-1))` decreases; `N(j) - N(j-1)` lies strictly
///   between `δ(j) - 1` and `δ(j) + 1`, so it is at least 1 while `δ(j) ≥
///   1` and at most 1 after. `δ(j) ≥ 1 ⟺ √j + √(j-1) ≤ q ⟺ j ≤ (q² + 1)² /
///   (4q²)` (square twice; both sides non-negative there), so `j1 =
///   ⌊(q² + 1)² / 4q²⌋` is the last such `j`.
/// * `E(j) - E(j-1) ≥ min(m, N(j-1) - N(j-2)) ≥ 1` for `j ≤ p = j1 + 1`
///   (`E(1) = max(q, m) ≥ 1`, `E(2) ≥ q + m ≥ E(1) + 1`), and `E(j) - E(j-1)
///   ≤ max(N(j) - N(j-1), N(j-1) - N(j-2)) ≤ 1` for `j > p`.
/// * `F(n) = max over j ≤ n of E(j) + n - j`; `E(j) - j` does not decrease
///   up to `p` and does not increase after, so `F(n) = E(n)` for `n ≤ p`
///   and `F(n) = E(p) + n - p` for `n ≥ p`.
/// * Hence the count is the first `n` with `E(n) ≥ k - d`, `min(n_N(k -
///   d), 1 + n_N(k - d - m))` with `n_N(v) = ⌈(2v - 1)² / 4q²⌉` the first
///   `n` with `N(n) ≥ v` (`round(q √n) ≥ v ⟺ 4q²n ≥ (2v - 1)²`; 0 for `v ≤
///   0`), when that is at most `p`; otherwise `p + (k - d) - E(p)`.
///
/// Held against counting the levels one by one (`spec/tests/readings.rs`,
/// `depth_formula_count_is_exact`).
///
/// Twin: `impl/src/engine/schedule.rs`, `formula_levels`.
#[must_use]
pub fn formula_level_count(q: i64, m: i64, last: i64) -> u64 {
    let q2 = u128::from(q.unsigned_abs()).pow(2);
    let law = |n: u128| i128::try_from(round_sqrt(q2 * n)).unwrap_or(i128::MAX);
    let first_at_least = |v: i64| -> u128 {
        if v <= 0 {
            return 0;
        }
        u128::from((2 * v - 1).unsigned_abs()).pow(2).div_ceil(4 * q2)
    };
    let p = (q2 + 1).pow(2) / (4 * q2) + 1;
    let by_e = first_at_least(last).min(1 + first_at_least(last - m));
    let levels = if by_e <= p {
        by_e
    } else {
        // E(p) < k - d < 2^30.
        let e_p = law(p).max(law(p - 1) + i128::from(m));
        p + u128::try_from(i128::from(last) - e_p).unwrap_or(0)
    };
    u64::try_from(levels).unwrap_or(u64::MAX)
}

/// The depths of the rough levels, in order: they strictly increase and the
/// last is exactly `k - d` (seed 000: "X 轴切深 = 牙高 P(k) − 精车切削量
/// R(d)"; 988TA note 5: "当设定第一次螺纹切削深度大于螺纹总切削深度时，只进行
/// 一次粗车"). With `d = k` (k - d = 0) the list is one level at 0 under
/// reading R-NOROUGH `one-at-zero` (steps ①-⑤ always cut a first rough
/// pass, "按切深（k-d）进刀到 Bf 点"), and empty under `none`.
///
/// # Errors
///
/// [`CycleError::TooManyPasses`] when the cycle would cut more rough passes
/// than its limit (reading R-LIMIT, which also says how the count is found).
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `rough_levels`.
pub fn rough_levels(c: &G76Cycle) -> Result<Vec<Decimal>, CycleError> {
    let u = c.units;
    let last = from_increments(c.thread_height - c.finishing_allowance, u);
    check_pass_count(c)?;
    let mut levels = Vec::new();
    let mut depth = Decimal::ZERO;
    let mut n = 0_u64;
    // Reading R-NOROUGH `one-at-zero`: the first level is cut even when it
    // is already at k - d = 0.
    while depth < last || (n == 0 && c.readings.one_rough_at_zero) {
        n += 1;
        depth = next_depth(c, n, depth);
        levels.push(depth);
    }
    Ok(levels)
}

/// Reading R-LIMIT (with R-LINEAR): the number of rough levels, found
/// before any move is made. Until the first level where the minimum cut takes over (`round(Δd
/// √n) < D(n-1) + Δdmin`), the levels follow the law; from that level on
/// every level adds exactly Δdmin (proved in docs/INTERPRETATIONS.md and by
/// the proof harnesses), so the count is `n - 1 + ceil((k - d - D(n-1)) /
/// Δdmin)`. If the law alone runs past the limit, the count is only known
/// to exceed it. Under reading R-DEPTH `formula` the count is in closed
/// form ([`formula_level_count`]) and always exact.
///
/// Twin: `impl/src/engine/g76.rs`, `check_pass_count`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `check_pass_count`.
fn check_pass_count(c: &G76Cycle) -> Result<(), CycleError> {
    let u = c.units;
    let last = from_increments(c.thread_height - c.finishing_allowance, u);
    let min = effective_min_cut(from_increments(c.min_cut, u), u);
    let first = from_increments(c.first_depth, u);
    let limit = u64::from(c.pass_limit);
    let passes_of = |levels: u64| c.infeed.passes(levels);
    let mut depth = Decimal::ZERO;
    let mut n = 0_u64;
    let levels = if c.depth_mode == DepthMode::Equal {
        // Equal steps of max(Δd, Δdmin, 1): ceil((k - d) / step) levels.
        let step = to_increments(first.max(min), u);
        let rest = to_increments(last, u);
        u64::try_from(ceil_div(i128::from(rest), i128::from(step))).unwrap_or(u64::MAX)
    } else if c.readings.depth_formula {
        // Reading R-DEPTH `formula`: exact, in closed form.
        let last = to_increments(last, u);
        if last > 0 {
            formula_level_count(c.first_depth, to_increments(min, u), last)
        } else {
            0
        }
    } else {
        loop {
            if depth >= last {
                break n;
            }
            n += 1;
            let law = depth_by_law(first, n, u);
            if law < depth + min {
                let rest = to_increments(last - depth, u);
                let step = to_increments(min, u);
                let more = u64::try_from(ceil_div(i128::from(rest), i128::from(step))).unwrap_or(u64::MAX);
                break n - 1 + more;
            }
            if law >= last {
                break n;
            }
            depth = law;
            if n > limit {
                return Err(CycleError::TooManyPasses { passes: limit, exact: false, limit: c.pass_limit });
            }
        }
    };
    // Reading R-NOROUGH `one-at-zero`: one level at 0 when k - d = 0 (the
    // only case with no level above).
    let levels = levels.max(u64::from(c.readings.one_rough_at_zero));
    let passes = passes_of(levels);
    if passes > limit {
        return Err(CycleError::TooManyPasses { passes, exact: true, limit: c.pass_limit });
    }
    check_work(c, passes)
}

/// Reading R-BUDGET: every pass path the cycle cuts, (rough + finishing) ×
/// starts, within the pass limit, checked before any move is made.
///
/// Twin: `impl/src/engine/g76.rs`, `check_work`.
fn check_work(c: &G76Cycle, rough: u64) -> Result<(), CycleError> {
    let paths = u128::from(rough) + u128::from(c.finishing_passes);
    let paths = paths * u128::from(c.starts.max(1));
    if paths > u128::from(c.pass_limit) {
        let pass_paths = u64::try_from(paths).unwrap_or(u64::MAX);
        return Err(CycleError::TooMuchWork { pass_paths, limit: c.pass_limit });
    }
    Ok(())
}

/// `round(depth × tan(a ÷ 2))`: the Z shift of a pass at `depth` (seed 000
/// "Z 轴起切点 = X 轴切深 × tan(P(a) ÷ 2)"; "Bn 点相对于 B 点 X 轴和 Z 轴的位移
/// 符合公式 tg(a/2) = Z 轴位移 / X 轴位移").
///
/// Twin: `impl/src/engine/g76.rs`, `flank_shift`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `flank_shift`.
#[must_use]
pub fn flank_shift(depth: Decimal, tool_angle: u32, u: Units) -> Decimal {
    let inc = to_increments(depth, u);
    let v = crate::tan::mul_tan_round(inc, tool_angle).unwrap_or(0);
    from_increments(v, u)
}

/// The passes of the cycle in cutting order, before multi-start expansion
/// (readings R-INFEED, R-FINISH).
///
/// * D0 (右边切入): every rough pass on the right flank, shifted
///   `round(Dn tan(a/2))`.
/// * D1 (右中轮流切入): odd levels on the right flank, even levels on the
///   centre line of the final form, whose shift is that of the last rough
///   level, `zc = round((k - d) tan(a/2))`.
/// * D2 (左右等量轮流切入): every level but the last twice, first on the right
///   flank, then on the left flank mirrored about the centre line
///   (`2 zc - round(Dn tan(a/2))`); the last level once (the two flanks meet
///   at `zc`), as the 988TA figure draws Bn1, Bn2 … and a single Bf. Under
///   reading R-INFEED `left-first` each level left then right, and the
///   last level once on the left (the flank its level starts on).
/// * G78 r = 0 (中线切入): every rough pass on the centre line, `zc`
///   (reading R-G78CENTRE `form-centre`), or under B, 0 (`under-b`).
/// * G78 r = 1 (左边切入): every rough pass on the left flank, `2 zc -
///   round(Dn tan(a/2))`.
/// * G78 r = 3 on the 980TDi (交错切入, reading R-G78ALT): one pass a level,
///   odd levels on the right flank, even levels on the left (swapped
///   under R-INFEED `left-first`).
/// * Every left flank (r = 1, D2, 交错) is the right flank mirrored about
///   the line `mirror`: `2 mirror - round(Dn tan(a/2))`, `mirror` = zc
///   (reading R-G78LEFT `mirror-form-centre`) or 0, B (`mirror-b`).
/// * Finishing: m passes at depth k from the Z of the last rough pass
///   (seed 000 注意 2: "精车 Z 轴起切点与最后一刀粗车一致"), `zc` under the
///   default readings, 0 when there is no rough pass; the first removes
///   d, the others 0 (seed 000: "第一次精车切削量为 d，其后的精车切削量为 0").
///
/// # Errors
///
/// As [`rough_levels`].
///
/// Twin: `impl/src/engine/g76.rs`, `G76Moves::plan_next`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `planned_passes`.
pub fn planned_passes(c: &G76Cycle) -> Result<Vec<PlannedPass>, CycleError> {
    let u = c.units;
    let levels = rough_levels(c)?;
    let last = from_increments(c.thread_height - c.finishing_allowance, u);
    let zc = flank_shift(last, c.tool_angle, u);
    // Reading R-G78CENTRE: the shift of G78 r = 0's passes.
    let centre_line = if c.readings.centre_under_b { Decimal::ZERO } else { zc };
    // Reading R-G78LEFT: the line the right flank is mirrored about.
    let mirror = if c.readings.left_mirror_b { Decimal::ZERO } else { zc };
    let left = |right: Decimal| mirror + mirror - right;
    // Reading R-INFEED (with R-G78ALT): the flank a level of D2, r = 4 and
    // 交错 starts on, and the other one.
    let (first, second) =
        if c.readings.left_first { (Flank::Left, Flank::Right) } else { (Flank::Right, Flank::Left) };
    let shift_on = |flank: Flank, right: Decimal| if flank == Flank::Left { left(right) } else { right };
    let mut out = Vec::new();
    let mut number = 0_u32;
    let mut previous = Decimal::ZERO;
    let f = levels.len();
    let mut push = |kind, depth: Decimal, cut: Decimal, flank, z_shift, number: u32| {
        out.push(PlannedPass {
            pass: Pass {
                kind,
                number,
                start: 1,
                depth: to_increments(depth, u),
                cut: to_increments(cut, u),
                flank,
            },
            z_shift,
        });
    };
    for (index, &depth) in levels.iter().enumerate() {
        let level = index + 1;
        let cut = depth - previous;
        let right = flank_shift(depth, c.tool_angle, u);
        match c.infeed {
            Infeed::RightFlank => {
                number += 1;
                push(PassKind::Rough, depth, cut, Flank::Right, right, number);
            }
            Infeed::RightCentre => {
                number += 1;
                if level % 2 == 1 {
                    push(PassKind::Rough, depth, cut, Flank::Right, right, number);
                } else {
                    push(PassKind::Rough, depth, cut, Flank::Centre, zc, number);
                }
            }
            Infeed::LeftRight => {
                number += 1;
                push(PassKind::Rough, depth, cut, first, shift_on(first, right), number);
                if level < f {
                    number += 1;
                    push(PassKind::Rough, depth, cut, second, shift_on(second, right), number);
                }
            }
            Infeed::Centre => {
                number += 1;
                push(PassKind::Rough, depth, cut, Flank::Centre, centre_line, number);
            }
            Infeed::LeftFlank => {
                number += 1;
                push(PassKind::Rough, depth, cut, Flank::Left, left(right), number);
            }
            Infeed::Alternating => {
                number += 1;
                let flank = if level % 2 == 1 { first } else { second };
                push(PassKind::Rough, depth, cut, flank, shift_on(flank, right), number);
            }
        }
        previous = depth;
    }
    let k = from_increments(c.thread_height, u);
    let d = from_increments(c.finishing_allowance, u);
    // "精车 Z 轴起切点与最后一刀粗车一致": zc under the default readings (every
    // mode's last rough pass is at zc), 0 without a rough pass (zc = 0).
    let finish = out.last().map_or(Decimal::ZERO, |p| p.z_shift);
    for m in 1..=c.finishing_passes {
        let cut = if m == 1 { d } else { Decimal::ZERO };
        out.push(PlannedPass {
            pass: Pass {
                kind: PassKind::Finish,
                number: m,
                start: 1,
                depth: to_increments(k, u),
                cut: to_increments(cut, u),
                flank: Flank::Centre,
            },
            z_shift: finish,
        });
    }
    Ok(out)
}

/// `round(num × ratio)` in increments, exactly.
///
/// Twin: `impl/src/engine/g76.rs`, `round_ratio`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `round_ratio`.
fn round_ratio(num: i128, r: Ratio) -> i128 {
    let n = i128::try_from(r.num).unwrap_or(i128::MAX);
    let d = i128::try_from(r.den).unwrap_or(1);
    round_div(num * n, d)
}

/// The run-out amounts `(J, K)` (short axis, long axis; radius where X),
/// or `None` for no run-out (reading R-RUNOUT).
///
/// With the chamfer r: K = `round(r × 0.1 × lead)` (seed 000 P(r): "螺纹倒角量
/// 0~99 (单位: 0.1×L, L 为螺纹螺距)") and J = `round(K × tan(θ))` with the
/// chamfer angle θ from the long axis (988TA G92: "当参数 5131 设置为零时,
/// 长轴和短轴以 45° 角退尾"). J = 0 means no run-out.
///
/// Twin: `impl/src/engine/g76.rs`, `run_out_amounts`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `run_out_amounts`.
#[must_use]
pub fn run_out_amounts(
    run_out: RunOut,
    lead: Lead,
    u: Units,
    from_short_axis: bool,
) -> Option<(Decimal, Decimal)> {
    let (j, k) = match run_out {
        RunOut::None => return None,
        RunOut::Amounts { short, long } => (short, long),
        RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
            let lead = lead.increments_per_rev(u);
            let chamfer =
                round_ratio(i128::from(tenths_of_lead), Ratio { num: lead.num, den: lead.den * 10 });
            // validate() has refused a chamfer beyond the range table.
            let chamfer = i64::try_from(chamfer).unwrap_or(i64::MAX);
            // Reading R-CHAMFERANGLE: θ from the long axis, J = round(K·tan θ),
            // or from the short axis, J = round(K·tan(90° - θ)) (half degrees).
            let half_degrees = if from_short_axis { 180 - 2 * angle_degrees } else { 2 * angle_degrees };
            let short = crate::tan::mul_tan_round(chamfer, half_degrees).unwrap_or(i64::MAX);
            (short, long.unwrap_or(chamfer))
        }
    };
    if j == 0 {
        return None;
    }
    Some((from_increments(j, u), from_increments(k, u)))
}

/// The long-axis length of the lead-in (reading R-LEADIN): the smallest whole
/// number of leads not shorter than E, rounded to the increment, so that the
/// screw-in lands on the same helix as a pass without lead-in and Z stays the
/// long axis of the screw-in move (`whole-leads`); 0 under `same-z`, the
/// lead-in start then E out along X at the Z of Bn.
///
/// Twin: `impl/src/engine/g76.rs`, `lead_in_length`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `lead_in_length`.
#[must_use]
pub fn lead_in_length(c: &G76Cycle) -> Decimal {
    let u = c.units;
    // Reading R-LEADIN `same-z`: An at the Z of Bn.
    if c.readings.lead_in_same_z {
        return Decimal::ZERO;
    }
    let lead = c.lead.increments_per_rev(u);
    let e = i128::from(c.lead_in);
    let n = i128::try_from(lead.num).unwrap_or(i128::MAX);
    let d = i128::try_from(lead.den).unwrap_or(1);
    // smallest N >= 1 with N * n / d >= e
    let leads = ceil_div(e * d, n).max(1);
    from_increments(i64::try_from(round_div(leads * n, d)).unwrap_or(i64::MAX), u)
}

///
/// Twin: `impl/src/engine/g76.rs`, `check_coordinate`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `check_coordinate`.
fn check_coordinate(v: Decimal, u: Units) -> Result<(), CycleError> {
    if to_increments(v, u).abs() > MAX_LENGTH {
        return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value: len(v, u) });
    }
    Ok(())
}

/// The end of a pass at `depth` whose start Bn is shifted `shift` along Z
/// (reading R-END):
///
/// * `travel-i`: on the line D–E (Z of D), at X of D plus the depth below
///   the crest: X travels i from Bn (seed 000 (4): "X 轴方向的移动量为 i").
/// * `parallel`: on the line through Bn parallel to C→D where it meets D–E
///   (980TDi and 988TA G76 ②: "沿平行于 C→D 的方向螺纹切削到与 D→E 相交处"):
///   X of D + s·xf·(k - depth) + xf·i·shift/|W|, rounded to the nearest
///   increment, ties away from zero.
/// * `translated`: Bn plus C→D, Z travel W and X travel i (seed 000 and
///   988TA G78 (4): "在 Z 轴方向的移动量为 W，X 轴方向的移动量为 i"): X as
///   `travel-i`, Z of D plus the shift towards D.
///
/// Twin: `impl/src/engine/pass.rs`, `Frame::path`.
fn pass_end_point(
    g: &Geometry,
    depth: Decimal,
    shift: Decimal,
    k: Decimal,
    pass_end: PassEnd,
    u: Units,
) -> (Decimal, Decimal) {
    let s = Decimal::from(g.side);
    let t = Decimal::from(g.direction);
    let x = g.d.0 + s * g.x_factor * (k - depth);
    match pass_end {
        PassEnd::TravelI => (x, g.d.1),
        PassEnd::Parallel => {
            // Exactly, in increments: (x |W| + (X(C) - X(D)) shift) / |W|.
            let w = i128::from(to_increments((g.d.1 - g.a.1).abs(), u));
            let num = i128::from(to_increments(x, u)) * w
                + i128::from(to_increments(g.c_x - g.d.0, u)) * i128::from(to_increments(shift, u));
            (from_increments(i64::try_from(round_div(num, w)).unwrap_or(i64::MAX), u), g.d.1)
        }
        PassEnd::Translated => (x, g.d.1 + t * shift),
    }
}

/// Expands a G76 cycle into moves.
///
/// Each pass, for each start (reading R-STARTS: all starts at one depth
/// before the next depth under `pass-major`, all passes of one start
/// before the next start under `start-major`), follows seed 000 "执行过程" (4)-(5) and 988TA
/// steps ①-⑩:
///
/// 1. rapid from A to Bn, X and Z together ("如果 a≠0，X 轴和 Z 轴同时移动，
///    移动方向与 A→D 的方向相同"), or to the lead-in start An and a screw-in
///    thread move to Bn (reading R-LEADIN);
/// 2. thread from Bn to the end line D–E, X travelling i (seed 000 (4): "本轮
///    切削终点与螺纹切入点在 Z 轴方向的移动量为 W，X 轴方向的移动量为 i",
///    reading R-END), with the run-out K before the end (reading R-RUNOUT);
/// 3. rapid along X to E (X of A), then along Z back to A ("退尾后，先沿 X 轴
///    方向快速移动，后沿 Z 轴方向快速移动回到起点").
///
/// Moves that would not move are left out (reading R-ZERO).
///
/// # Errors
///
/// The manual's alarms, as [`CycleError`].
///
/// Twin: `impl/src/engine/g76.rs`, `expand_g76` and `Frame::path`.
pub fn expand(c: &G76Cycle) -> Result<Vec<Move>, CycleError> {
    Ok(moves(c)?.collect())
}

/// The moves of [`expand`], made a pass and a start at a time (memory of
/// one pass, whatever the number of starts): every alarm is raised before
/// the first move.
///
/// # Errors
///
/// As [`expand`].
pub fn moves(c: &G76Cycle) -> Result<impl Iterator<Item = Move> + Clone + Send + Sync + 'static, CycleError> {
    c.validate()?;
    let u = c.units;
    let g = geometry(c)?;
    let e = from_increments(c.lead_in, u);
    if g.long_axis == LongAxis::X && c.lead_in > 0 {
        return Err(CycleError::LeadInOnXLongAxis);
    }
    let plan = planned_passes(c)?;
    let s = Decimal::from(g.side);
    let t = Decimal::from(g.direction);
    let xf = g.x_factor;
    let k = from_increments(c.thread_height, u);
    let i = from_increments(c.taper, u);
    let w = g.d.1 - g.a.1;
    let run_out = run_out_amounts(c.run_out, c.lead, u, c.readings.chamfer_from_short_axis);
    let lead_in = if c.lead_in > 0 { Some(lead_in_length(c)) } else { None };

    // Note 7 and reading R-SHORT: the shortest pass must be longer than the
    // flank shift and not shorter than the run-out.
    // On either long axis a pass whose shift reaches |W| would start at or
    // beyond the end line.
    let max_shift = plan.iter().map(|p| p.z_shift).max().unwrap_or(Decimal::ZERO);
    if max_shift >= w.abs() {
        return Err(CycleError::ThreadTooShort { shift: len(max_shift, u), length: len(w.abs(), u) });
    }
    let pass_end = c.readings.pass_end;
    match g.long_axis {
        LongAxis::Z => {
            if let Some((_, kk)) = run_out {
                // Reading R-END: a translated pass is |W| long whatever its
                // shift; the others end on D–E, |W| less the shift.
                let length = if pass_end == PassEnd::Translated { w.abs() } else { w.abs() - max_shift };
                if kk > length {
                    return Err(CycleError::RunOutTooLong { run_out: len(kk, u), length: len(length, u) });
                }
            }
        }
        LongAxis::X => {
            if let Some((_, kk)) = run_out {
                // Reading R-END: a parallel pass travels |i| (|W| - shift) /
                // |W| along X (radius), the least at the largest shift; K,
                // a whole number of increments, exceeds it exactly when it
                // exceeds its floor.
                let length = if pass_end == PassEnd::Parallel {
                    let num = i128::from(c.taper.abs()) * i128::from(to_increments(w.abs() - max_shift, u));
                    from_increments(
                        i64::try_from(num / i128::from(to_increments(w.abs(), u))).unwrap_or(i64::MAX),
                        u,
                    )
                } else {
                    i.abs()
                };
                if kk > length {
                    return Err(CycleError::RunOutTooLong { run_out: len(kk, u), length: len(length, u) });
                }
                // Reading R-XRUNOUT: the run-out ends at X of the pass end,
                // J along Z towards A, where the cut line lies at X of the
                // end plus xf·i·J/|W|: beyond the tool, on the work's side,
                // when s·i > 0.
                // `towards-start` makes it as written.
                if s * i > Decimal::ZERO && !c.readings.x_run_out_towards_start {
                    return Err(CycleError::RunOutIntoWork { taper: len(i, u) });
                }
            }
        }
    }
    // Coordinates beyond the range tables (reading R-RANGE): A and D are
    // words within range and B lies between A and C, so X of C (the
    // finishing passes' start) and the lead-in start are the extremes.
    check_coordinate(g.c_x, u)?;
    // Reading R-SIDE `accept`: A may lie inside the crest, B beyond it; the
    // shallowest pass (the first) starts and ends furthest out (a
    // `parallel` end lies between the two).
    if let (true, Some(first)) = (c.readings.accept_start_inside, plan.first()) {
        let shallowest = from_increments(first.pass.depth, u);
        check_coordinate(g.c_x + s * xf * (k - shallowest), u)?;
        check_coordinate(g.d.0 + s * xf * (k - shallowest), u)?;
    }
    if let (Some(lz), Some(first)) = (lead_in, plan.first()) {
        // The shallowest pass (the first) has the lead-in start furthest out.
        let shallowest = from_increments(first.pass.depth, u);
        check_coordinate(g.c_x + s * xf * (k - shallowest) + s * xf * e, u)?;
        let min_shift = plan.iter().map(|p| p.z_shift).min().unwrap_or(Decimal::ZERO);
        check_coordinate(g.a.1 + t * min_shift - t * lz, u)?;
    }
    // Reading R-END `translated`: every pass ends its shift beyond D along
    // Z, the furthest by the largest shift.
    if pass_end == PassEnd::Translated {
        check_coordinate(g.d.1 + t * max_shift, u)?;
    }
    // Reading R-G78LEFT `mirror-b`: a left pass starts beyond the Z of A,
    // furthest at the deepest left pass (within the lead-in's start, above).
    let min_shift = plan.iter().map(|p| p.z_shift).min().unwrap_or(Decimal::ZERO);
    if min_shift < Decimal::ZERO {
        check_coordinate(g.a.1 + t * min_shift, u)?;
    }
    // Reading R-RUNOUT `gsk988-only`: J as written, not clamped at the
    // retract: Z long, furthest out at the end of the shallowest pass; X
    // long, J along Z from the pass's end towards A (D, or D shifted by
    // the smallest shift for translated passes).
    if let (Some((j, _)), Some(first), false) = (run_out, plan.first(), c.readings.clamp_run_out) {
        let shallowest = from_increments(first.pass.depth, u);
        let min_shift = plan.iter().map(|p| p.z_shift).min().unwrap_or(Decimal::ZERO);
        let beyond = match g.long_axis {
            LongAxis::Z => g.d.0 + s * xf * (k - shallowest) + s * xf * j,
            LongAxis::X if pass_end == PassEnd::Translated => g.d.1 + t * min_shift - t * j,
            LongAxis::X => g.d.1 - t * j,
        };
        check_coordinate(beyond, u)?;
    }

    let frame = PassFrame {
        a: g.a,
        transposed: false,
        side: g.side,
        direction: g.direction,
        length: w.abs(),
        x_factor: xf,
        long_axis: g.long_axis,
        run_out,
        clamp_run_out: c.readings.clamp_run_out,
        line: match pass_end {
            PassEnd::TravelI => None,
            PassEnd::Parallel | PassEnd::Translated => Some((g.d.0 - g.c_x, w)),
        },
        lead: c.lead,
        units: u,
    };
    let starts = c.starts;
    // Reading R-STARTS: every pass for all starts (`pass-major`), or every
    // pass of one start before the next start (`start-major`).
    let start_major = c.readings.start_major;
    let (mut index, mut start) = (0_usize, 0_u32);
    Ok(PassStream::new(move |moves: &mut Vec<Move>| {
        if start_major && index == plan.len() {
            (index, start) = (0, start + 1);
        } else if !start_major && start == starts {
            (index, start) = (index + 1, 0);
        }
        if start >= starts {
            return false;
        }
        let Some(planned) = plan.get(index) else { return false };
        {
            let mut pass = planned.pass;
            pass.start = u16::try_from(start + 1).expect("L <= 999 (validate)");
            let angle = StartAngle::of_start(start, starts);
            let depth = from_increments(pass.depth, u);
            // Seed 000 "进刀点实际坐标位置计算": X = X 终点 + 锥度 R(i) ∓ 牙高 P(k)
            // ± X 轴切深; Z = Z 起点 ± Z 轴切深.
            let bn = (g.d.0 + xf * i + s * xf * (k - depth), g.a.1 + t * planned.z_shift);
            // Reading R-END: where the cut ends.
            let end = pass_end_point(&g, depth, planned.z_shift, k, pass_end, u);
            let lead_in_start = lead_in.map(|lz| (bn.0 + s * xf * e, bn.1 - t * lz));
            pass_path(moves, &frame, bn, end, lead_in_start, pass, angle);
        }
        if start_major {
            index += 1;
        } else {
            start += 1;
        }
        true
    }))
}
