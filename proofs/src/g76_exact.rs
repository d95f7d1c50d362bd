//! The G76 reference, `cycleref_spec::g76::expand`, restated in integers
//! (least increments), for the `equivalence` harness under Kani (issue 13:
//! leave `rust_decimal` out of what Kani executes symbolically).
//!
//! Every length of the reference is a whole number of increments but one:
//! the run-out start on the cut line, which the reference quantises, i.e.
//! rounds to the nearest increment with ties away from zero. So the
//! reference's decimals are integers here, and that one quotient is an
//! exact rounded division of the whole expression (`round((b·Δ + p) / Δ)`,
//! not `b + round(p / Δ)`, which differs at ties). The steps, the checks
//! and their order, and the names follow `spec/src/g76.rs` and
//! `spec/src/pass.rs` line by line; the integer kernels are the
//! reference's own (`cycleref_spec::exact::{round_div, ceil_div,
//! round_sqrt}`, `cycleref_spec::tan::mul_tan_round`: integer arithmetic,
//! no `rust_decimal`), never the engine's. The words' own decoding is the
//! shared types' (`G76Cycle::validate`, `Lead::increments_per_rev`,
//! `StartAngle::of_start`), which the reference calls too.
//!
//! Under `cargo test` the `equivalence` harness checks the engine against
//! this restatement and this restatement against the decimal reference, so
//! the restatement is held to the reference over every cycle the shim runs
//! (`proofs/tests/harnesses.rs`, `proofs/tests/g78.rs`).
//!
//! *Readings.* It restates R-LEADIN's two values and every other reading
//! at `CycleReadings::DEFAULT` only (R-END `travel-i`, R-RUNOUT clamped,
//! R-XRUNOUT `refuse`, the long axis by the displacements, left flanks
//! about zc, centre passes at zc, R-INFEED `right-first`, R-NOROUGH
//! `none`, R-DEPTH `previous-plus-min`, R-STARTS `pass-major`): the
//! harnesses build their cycles under those values
//! (`crate::harness::any_cycle`, which says why), and the other values are
//! compared engine against reference by the differential tests
//! (`proofs/tests/engine_equals_spec.rs`).

use cycleref::angle::StartAngle;
use cycleref::error::{CycleError, Field};
use cycleref::g76::{DepthMode, G76Cycle, Infeed, RunOut};
use cycleref::lead::{Lead, Ratio};
use cycleref::moves::{Flank, Motion, Move, Pass, PassKind, Role};
use cycleref::units::{Length, Point, MAX_LENGTH};
use cycleref::Units;
use cycleref_spec::exact::{ceil_div, round_div, round_sqrt};

/// Which axis is the long axis (reading R-LONG).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LongAxis {
    Z,
    X,
}

/// The geometry, X in X-word increments.
///
/// Twin: `spec/src/g76.rs`, `Geometry`.
#[derive(Clone, Copy, Debug)]
struct Geometry {
    a: (i64, i64),
    d: (i64, i64),
    c_x: i64,
    side: i64,
    direction: i64,
    long_axis: LongAxis,
    xf: i64,
}

/// A planned pass and its Z shift from A (increments).
#[derive(Clone, Copy, Debug)]
struct Planned {
    pass: Pass,
    z_shift: i64,
}

fn len(v: i64, u: Units) -> Length {
    Length::new(v, u)
}

/// Twin: `spec/src/g76.rs`, `geometry`.
fn geometry(c: &G76Cycle) -> Result<Geometry, CycleError> {
    let xf = c.x_mode.factor();
    let a = (c.start.x, c.start.z);
    let d = (c.end.x, c.end.z);
    let (i, k) = (c.taper, c.thread_height);
    let c_x = d.0 + xf * i;
    let side = match a.0.cmp(&c_x) {
        std::cmp::Ordering::Greater => 1,
        std::cmp::Ordering::Less => -1,
        std::cmp::Ordering::Equal => return Err(CycleError::StartInsideThread),
    };
    let b_x = c_x + side * xf * k;
    let crest_at_end = d.0 + side * xf * k;
    if side * (a.0 - b_x) < 0 || side * (a.0 - crest_at_end) < 0 {
        return Err(CycleError::StartInsideThread);
    }
    let w = d.1 - a.1;
    let direction = if w > 0 { 1 } else { -1 };
    let long_axis = if w.abs() > i.abs() { LongAxis::Z } else { LongAxis::X };
    Ok(Geometry { a, d, c_x, side, direction, long_axis, xf })
}

/// The reference's `depth_by_law`: `round(Δd √n)`, the integer nearest `√(Δd² n)`.
///
/// Twin: `spec/src/g76.rs`, `depth_by_law`.
fn depth_by_law(first_depth: i64, n: u64) -> i64 {
    let q = u128::try_from(first_depth).unwrap_or(0);
    i64::try_from(round_sqrt(q * q * u128::from(n))).unwrap_or(i64::MAX)
}

/// Twin: `spec/src/g76.rs`, `next_depth`.
fn next_depth(c: &G76Cycle, n: u64, previous: i64) -> i64 {
    let last = c.thread_height - c.finishing_allowance;
    let first = c.first_depth;
    let min = c.min_cut.max(1);
    match c.depth_mode {
        DepthMode::Decreasing => last.min(depth_by_law(first, n).max(previous + min)),
        DepthMode::Equal => last.min(previous + first.max(min)),
    }
}

/// The reference's `check_pass_count` (reading R-LIMIT).
///
/// Twin: `spec/src/g76.rs`, `check_pass_count`.
fn check_pass_count(c: &G76Cycle) -> Result<(), CycleError> {
    let last = c.thread_height - c.finishing_allowance;
    let min = c.min_cut.max(1);
    let first = c.first_depth;
    let limit = u64::from(c.pass_limit);
    // Restated here, not `Infeed::passes` (its twin in the shared model,
    // which the engine and the reference both call): the oracle keeps its
    // own count.
    let passes_of = |levels: u64| -> u64 {
        match c.infeed {
            Infeed::LeftRight => (2 * levels).saturating_sub(1),
            _ => levels,
        }
    };
    let mut depth = 0_i64;
    let mut n = 0_u64;
    let levels = if c.depth_mode == DepthMode::Equal {
        let step = first.max(min);
        u64::try_from(ceil_div(i128::from(last), i128::from(step))).unwrap_or(u64::MAX)
    } else {
        loop {
            if depth >= last {
                break n;
            }
            n += 1;
            let law = depth_by_law(first, n);
            if law < depth + min {
                let more =
                    u64::try_from(ceil_div(i128::from(last - depth), i128::from(min))).unwrap_or(u64::MAX);
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
    let passes = passes_of(levels);
    if passes > limit {
        return Err(CycleError::TooManyPasses { passes, exact: true, limit: c.pass_limit });
    }
    // Reading R-BUDGET: (rough + finishing) × starts, in u128 (no
    // saturation to reason about).
    let paths = (u128::from(passes) + u128::from(c.finishing_passes)) * u128::from(c.starts.max(1));
    if paths > u128::from(c.pass_limit) {
        let pass_paths = u64::try_from(paths).unwrap_or(u64::MAX);
        return Err(CycleError::TooMuchWork { pass_paths, limit: c.pass_limit });
    }
    Ok(())
}

/// Twin: `spec/src/g76.rs`, `rough_levels`.
fn rough_levels(c: &G76Cycle) -> Result<Vec<i64>, CycleError> {
    let last = c.thread_height - c.finishing_allowance;
    check_pass_count(c)?;
    let mut levels = Vec::new();
    let mut depth = 0_i64;
    let mut n = 0_u64;
    while depth < last {
        n += 1;
        depth = next_depth(c, n, depth);
        levels.push(depth);
    }
    Ok(levels)
}

/// The reference's `flank_shift`: `round(depth × tan(a ÷ 2))` by the reference's table.
///
/// Twin: `spec/src/g76.rs`, `flank_shift`.
fn flank_shift(depth: i64, tool_angle: u32) -> i64 {
    cycleref_spec::tan::mul_tan_round(depth, tool_angle).unwrap_or(0)
}

/// The reference's `planned_passes` (readings R-INFEED, R-FINISH).
///
/// Twin: `spec/src/g76.rs`, `planned_passes`.
fn planned_passes(c: &G76Cycle) -> Result<Vec<Planned>, CycleError> {
    let levels = rough_levels(c)?;
    let last = c.thread_height - c.finishing_allowance;
    let centre = flank_shift(last, c.tool_angle);
    let mut out = Vec::new();
    let mut number = 0_u32;
    let mut previous = 0_i64;
    let f = levels.len();
    let mut push = |kind, depth: i64, cut: i64, flank, z_shift, number: u32| {
        out.push(Planned { pass: Pass { kind, number, start: 1, depth, cut, flank }, z_shift });
    };
    for (index, &depth) in levels.iter().enumerate() {
        let level = index + 1;
        let cut = depth - previous;
        let right = flank_shift(depth, c.tool_angle);
        let left = centre + centre - right;
        number += 1;
        match c.infeed {
            Infeed::RightFlank => push(PassKind::Rough, depth, cut, Flank::Right, right, number),
            Infeed::RightCentre if level % 2 == 1 => {
                push(PassKind::Rough, depth, cut, Flank::Right, right, number)
            }
            Infeed::RightCentre | Infeed::Centre => {
                push(PassKind::Rough, depth, cut, Flank::Centre, centre, number);
            }
            Infeed::LeftRight => {
                push(PassKind::Rough, depth, cut, Flank::Right, right, number);
                if level < f {
                    number += 1;
                    push(PassKind::Rough, depth, cut, Flank::Left, left, number);
                }
            }
            Infeed::LeftFlank => push(PassKind::Rough, depth, cut, Flank::Left, left, number),
            Infeed::Alternating if level % 2 == 1 => {
                push(PassKind::Rough, depth, cut, Flank::Right, right, number)
            }
            Infeed::Alternating => push(PassKind::Rough, depth, cut, Flank::Left, left, number),
        }
        previous = depth;
    }
    for m in 1..=c.finishing_passes {
        let cut = if m == 1 { c.finishing_allowance } else { 0 };
        push(PassKind::Finish, c.thread_height, cut, Flank::Centre, centre, m);
    }
    Ok(out)
}

/// Twin: `spec/src/g76.rs`, `round_ratio`.
fn round_ratio(num: i128, r: Ratio) -> i128 {
    let n = i128::try_from(r.num).unwrap_or(i128::MAX);
    let d = i128::try_from(r.den).unwrap_or(1);
    round_div(num * n, d)
}

/// The reference's `run_out_amounts`: `(J, K)` in increments (radius where X).
///
/// Twin: `spec/src/g76.rs`, `run_out_amounts`.
fn run_out_amounts(run_out: RunOut, lead: Lead, u: Units, from_short_axis: bool) -> Option<(i64, i64)> {
    let (j, k) = match run_out {
        RunOut::None => return None,
        RunOut::Amounts { short, long } => (short, long),
        RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
            let lead = lead.increments_per_rev(u);
            let chamfer =
                round_ratio(i128::from(tenths_of_lead), Ratio { num: lead.num, den: lead.den * 10 });
            let chamfer = i64::try_from(chamfer).unwrap_or(i64::MAX);
            // Reading R-CHAMFERANGLE.
            let half_degrees = if from_short_axis { 180 - 2 * angle_degrees } else { 2 * angle_degrees };
            let short = cycleref_spec::tan::mul_tan_round(chamfer, half_degrees).unwrap_or(i64::MAX);
            (short, long.unwrap_or(chamfer))
        }
    };
    (j != 0).then_some((j, k))
}

/// The reference's `lead_in_length` (reading R-LEADIN): 0 under `same-z`
/// (the default), whole leads under `whole-leads`. (The other readings are
/// restated at their defaults only: the harnesses make their cycles under
/// `CycleReadings::DEFAULT`.)
///
/// Twin: `spec/src/g76.rs`, `lead_in_length`.
fn lead_in_length(c: &G76Cycle) -> i64 {
    if c.readings.lead_in_same_z {
        return 0;
    }
    let lead = c.lead.increments_per_rev(c.units);
    let e = i128::from(c.lead_in);
    let n = i128::try_from(lead.num).unwrap_or(i128::MAX);
    let d = i128::try_from(lead.den).unwrap_or(1);
    let leads = ceil_div(e * d, n).max(1);
    i64::try_from(round_div(leads * n, d)).unwrap_or(i64::MAX)
}

/// The reference's `check_coordinate` (reading R-RANGE).
///
/// Twin: `spec/src/g76.rs`, `check_coordinate`.
fn check_coordinate(v: i64, u: Units) -> Result<(), CycleError> {
    if v.abs() > MAX_LENGTH {
        return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value: len(v, u) });
    }
    Ok(())
}

/// `round((b·den + num) / den)`: the reference's `quantize(b + num / den)`
/// exactly (nearest, ties away from zero).
fn quantize_sum(b: i64, num: i128, den: i128) -> i64 {
    i64::try_from(round_div(i128::from(b) * den + num, den)).unwrap_or(i64::MAX)
}

/// What every pass shares (G76: never transposed).
///
/// Twin: `spec/src/pass.rs`, `PassFrame`.
struct Frame {
    a: (i64, i64),
    side: i64,
    direction: i64,
    length: i64,
    xf: i64,
    long_axis: LongAxis,
    run_out: Option<(i64, i64)>,
    lead: Lead,
}

/// The reference's `Path`: the moves of one pass, zero-length ones left out.
///
/// Twin: `spec/src/pass.rs`, `Path`.
struct Path<'a> {
    moves: &'a mut Vec<Move>,
    at: (i64, i64),
    pass: Pass,
    sync_done: bool,
    lead: Lead,
    angle: StartAngle,
}

impl Path<'_> {
    fn go(&mut self, motion: Motion, to: (i64, i64), role: Role) {
        if to == self.at {
            return;
        }
        self.at = to;
        self.moves.push(Move { motion, to: Point::new(to.0, to.1), role, pass: Some(self.pass) });
    }

    fn thread(&mut self, to: (i64, i64), role: Role) {
        if to == self.at {
            return;
        }
        let sync = !self.sync_done;
        self.sync_done = true;
        let motion = Motion::Thread { lead: self.lead, start_angle: self.angle, sync };
        self.go(motion, to, role);
    }
}

/// A point of the frame: (X in X-word increments, Z).
type At = (i64, i64);

/// The reference's `pass_path`: from A to `bn` (by `lead_in_start`), to the end line
/// at `end`, the run-out, the retract and the return.
///
/// Twin: `spec/src/pass.rs`, `pass_path`.
fn pass_path(
    moves: &mut Vec<Move>,
    f: &Frame,
    (bn, end, lead_in_start): (At, At, Option<At>),
    pass: Pass,
    angle: StartAngle,
) {
    let (s, t, xf) = (f.side, f.direction, f.xf);
    let mut path = Path { moves, at: f.a, pass, sync_done: false, lead: f.lead, angle };
    match lead_in_start {
        Some(an) => {
            path.go(Motion::Rapid, an, Role::Approach);
            path.thread(bn, Role::LeadIn);
        }
        None => path.go(Motion::Rapid, bn, Role::Approach),
    }
    let mut last = end;
    match f.run_out {
        None => path.thread(end, Role::Cut),
        Some((j, kk)) => match f.long_axis {
            LongAxis::Z => {
                let zr = end.1 - t * kk;
                // quantize(bn.x + (end.x - bn.x)(zr - bn.z)/(end.z - bn.z)).
                let num = i128::from(end.0 - bn.0) * i128::from(zr - bn.1);
                let xr = quantize_sum(bn.0, num, i128::from(end.1 - bn.1));
                path.thread((xr, zr), Role::Cut);
                let jx = (xf * j).min(s * (f.a.0 - end.0));
                last = (end.0 + s * jx, end.1);
                path.thread(last, Role::RunOut);
            }
            LongAxis::X => {
                let sigma = if end.0 > bn.0 { 1 } else { -1 };
                let xr = end.0 - sigma * xf * kk;
                let num = i128::from(end.1 - bn.1) * i128::from(xr - bn.0);
                let zr = quantize_sum(bn.1, num, i128::from(end.0 - bn.0));
                path.thread((xr, zr), Role::Cut);
                let jz = j.min(f.length);
                last = (end.0, end.1 - t * jz);
                path.thread(last, Role::RunOut);
            }
        },
    }
    path.go(Motion::Rapid, (f.a.0, last.1), Role::Retract);
    path.go(Motion::Rapid, f.a, Role::Return);
}

/// `cycleref_spec::g76::expand` in integers: the same moves, or the same
/// alarm with the same values, for every cycle.
///
/// # Errors
///
/// The reference's alarms.
pub fn expand(c: &G76Cycle) -> Result<Vec<Move>, CycleError> {
    c.validate()?;
    let u = c.units;
    let g = geometry(c)?;
    let e = c.lead_in;
    if g.long_axis == LongAxis::X && c.lead_in > 0 {
        return Err(CycleError::LeadInOnXLongAxis);
    }
    let plan = planned_passes(c)?;
    let (s, t, xf) = (g.side, g.direction, g.xf);
    let (k, i) = (c.thread_height, c.taper);
    let w = g.d.1 - g.a.1;
    let run_out = run_out_amounts(c.run_out, c.lead, u, c.readings.chamfer_from_short_axis);
    let lead_in = (c.lead_in > 0).then(|| lead_in_length(c));
    // Note 7 and reading R-SHORT.
    let max_shift = plan.iter().map(|p| p.z_shift).max().unwrap_or(0);
    if max_shift >= w.abs() {
        return Err(CycleError::ThreadTooShort { shift: len(max_shift, u), length: len(w.abs(), u) });
    }
    match (g.long_axis, run_out) {
        (_, None) => {}
        (LongAxis::Z, Some((_, kk))) => {
            if kk > w.abs() - max_shift {
                return Err(CycleError::RunOutTooLong {
                    run_out: len(kk, u),
                    length: len(w.abs() - max_shift, u),
                });
            }
        }
        (LongAxis::X, Some((_, kk))) => {
            if kk > i.abs() {
                return Err(CycleError::RunOutTooLong { run_out: len(kk, u), length: len(i.abs(), u) });
            }
            // Reading R-XRUNOUT.
            if s * i > 0 {
                return Err(CycleError::RunOutIntoWork { taper: len(i, u) });
            }
        }
    }
    // Reading R-RANGE.
    check_coordinate(g.c_x, u)?;
    if let (Some(lz), Some(first)) = (lead_in, plan.first()) {
        check_coordinate(g.c_x + s * xf * (k - first.pass.depth) + s * xf * e, u)?;
        let min_shift = plan.iter().map(|p| p.z_shift).min().unwrap_or(0);
        check_coordinate(g.a.1 + t * min_shift - t * lz, u)?;
    }
    let frame = Frame {
        a: g.a,
        side: s,
        direction: t,
        length: w.abs(),
        xf,
        long_axis: g.long_axis,
        run_out,
        lead: c.lead,
    };
    let mut moves = Vec::new();
    for planned in &plan {
        for start in 0..c.starts {
            let mut pass = planned.pass;
            pass.start = u16::try_from(start + 1).unwrap_or(u16::MAX);
            let angle = StartAngle::of_start(start, c.starts);
            let depth = pass.depth;
            let bn = (g.d.0 + xf * i + s * xf * (k - depth), g.a.1 + t * planned.z_shift);
            let end = (g.d.0 + s * xf * (k - depth), g.d.1);
            let lead_in_start = lead_in.map(|lz| (bn.0 + s * xf * e, bn.1 - t * lz));
            pass_path(&mut moves, &frame, (bn, end, lead_in_start), pass, angle);
        }
    }
    Ok(moves)
}
