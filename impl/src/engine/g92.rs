//! The fixed-point G92 engine: a G92 block (`cycleref_spec::g92::expand`,
//! the exact-decimal reference, is the authority) as one pass of the
//! shared pass model (`engine::pass`), the pass a G76 cycle cuts at its
//! thread height, once per start.
//!
//! [`expand_g92`] checks the block completely before the first move (the
//! same errors, in the same order, as the reference) and returns a
//! [`G92Moves`] iterator that then cannot fail.
//!
//! # Integer widths
//!
//! `validate()` bounds A, C and R by [`MAX_LENGTH`] `< 2^30`, so X of B =
//! X of C + xf·R stays below `3·2^30`, and the pass model's bounds (module
//! docs of [`super::g76`]) hold with k = 0.
//!
//! # Work and memory
//!
//! O(1) up front; per move a bounded number of steps (at most six path
//! steps, and a binary gcd of numbers below 10^7 per start). A
//! [`G92Moves`] is a fixed-size value.

use core::cmp::Ordering;
use core::iter::FusedIterator;

use super::g76::run_out_amounts;
use super::pass::{Frame, LongAxis, Walk};
use crate::angle::{StartAngle, StartSpacing};
use crate::error::{CycleError, Field};
use crate::g92::G92Cycle;
use crate::moves::{Flank, Move, Pass, PassKind};
use crate::readings::PassEnd;
use crate::units::{Length, Point, MAX_LENGTH};

/// The moves of a G92 block, in order: an [`Iterator`] of constant size
/// made by [`expand_g92`].
#[derive(Clone, Debug)]
pub struct G92Moves {
    /// Fixed values.
    frame: Frame,
    /// The pass of the current start, streamed.
    walk: Walk,
    /// Current start, 0-based.
    start: u32,
    /// Q: the angle of the first start.
    first_angle: StartAngle,
}

/// Expands a G92 block: checks it completely, then streams its moves.
///
/// The result equals `cycleref_spec::g92::expand(cycle)` exactly: the same
/// error, or an iterator of the same moves in the same order.
///
/// # Errors
///
/// In the reference's order: [`G92Cycle::validate`],
/// [`CycleError::NoInfeed`], [`CycleError::TaperBeyondStart`],
/// [`CycleError::RunOutTooLong`], [`CycleError::RunOutIntoWork`],
/// [`CycleError::OutOfRange`] for the X of the cut start B.
///
/// # Example
///
/// The first block of the 980TDi manual's example O0012 (`G0 X65 Z5; G92
/// X58.7 Z-28 F3 J3 K1`), in IS-B mm, diameter X:
///
/// ```
/// use cycleref::{expand_g92, G92Cycle, Lead, LeadWord, Point, Role, RunOut, StartAngle, Units, XMode};
///
/// let block = G92Cycle {
///     units: Units::IS_B_METRIC,
///     x_mode: XMode::Diameter,
///     start: Point::new(65_000, 5_000),  // A: X65 Z5
///     end: Point::new(58_700, -28_000),  // C: X58.7 Z-28
///     taper: 0,
///     lead: Lead { word: LeadWord::F, mantissa: 3, scale: 0 }, // F3
///     run_out: RunOut::Amounts { short: 3_000, long: 1_000 },   // J3 K1
///     starts: 1,
///     start_angle: StartAngle::ZERO,
///     face: false,
///     readings: cycleref::CycleReadings::DEFAULT,
/// };
/// let moves: Vec<_> = expand_g92(&block)?.collect();
/// let ends: Vec<_> = moves.iter().map(|m| (m.role, m.to)).collect();
/// assert_eq!(ends, [
///     (Role::Approach, Point::new(58_700, 5_000)),  // ① to B
///     (Role::Cut, Point::new(58_700, -27_000)),     // ② K = 1 before C
///     (Role::RunOut, Point::new(64_700, -28_000)),  //    J = 3 (radius) outwards
///     (Role::Retract, Point::new(65_000, -28_000)), // ③ to the X of A
///     (Role::Return, Point::new(65_000, 5_000)),    // ④ back to A
/// ]);
/// # Ok::<(), cycleref::CycleError>(())
/// ```
///
/// Twin: `spec/src/g92.rs`, `expand`.
pub fn expand_g92(cycle: &G92Cycle) -> Result<G92Moves, CycleError> {
    let c = cycle;
    c.validate()?;
    let u = c.units;
    let len = |v: i64| Length::new(v, u);
    let xf = c.x_mode.factor();
    // The frame (`super::pass`): x the short axis, z the long axis; a face
    // thread (P1) swaps X and Z, and its long axis X counts X words (`lf`).
    let swap = |p: Point| Point::new(p.z, p.x);
    let (a, end, sf, lf) = if c.face { (swap(c.start), swap(c.end), 1, xf) } else { (c.start, c.end, xf, 1) };
    // |short(C)| + 2|R| < 3·2^30: B's short-axis coordinate.
    let b_x = end.x + sf * c.taper;
    // Reading R-G92SIDE: the side of the thread is the side of A.
    let side = match a.x.cmp(&end.x) {
        Ordering::Greater => 1,
        Ordering::Less => -1,
        Ordering::Equal => return Err(CycleError::NoInfeed),
    };
    if side * (a.x - b_x) < 0 {
        return Err(CycleError::TaperBeyondStart { taper: len(c.taper), infeed: len(end.x - a.x) });
    }
    // The long-axis travel ≠ 0 (validate), |W| < 2^31.
    let w = end.z - a.z;
    let direction = if w > 0 { 1 } else { -1 };
    let w_abs = w.abs();
    let taper_abs = c.taper.abs();
    // R-LONG for an axial thread; a face thread's long axis is X (988TA:
    // "P = 1（端面螺纹）长轴 纵轴").
    // Reading R-LONG988 `table` (988TA "P = 0（轴向螺纹）长轴：横轴"): Z
    // whatever the displacements.
    let long_axis =
        if c.face || w_abs > taper_abs || c.readings.long_axis_by_table { LongAxis::Z } else { LongAxis::X };
    // K in the long axis's coordinate increments (X words on a face thread).
    let run_out = run_out_amounts(c.run_out, c.lead, u, c.readings.chamfer_from_short_axis)
        .map(|(j, k)| (j, lf.saturating_mul(k)));
    if let Some((_, kk)) = run_out {
        let length = match long_axis {
            LongAxis::Z => w_abs,
            LongAxis::X => taper_abs,
        };
        // 988TA note 4: "当螺纹长轴方向退尾长度大于长轴的螺纹加工长度时，系统产生报警".
        if kk > length {
            return Err(CycleError::RunOutTooLong { run_out: len(kk), length: len(length) });
        }
        // Reading R-XRUNOUT: along Z towards A is into the work when the
        // cut line rises towards A (s·R > 0); `towards-start` makes it.
        if long_axis == LongAxis::X && side * c.taper > 0 && !c.readings.x_run_out_towards_start {
            return Err(CycleError::RunOutIntoWork { taper: len(c.taper) });
        }
    }
    // Reading R-RANGE: A and C are words within range, every other point
    // lies between them or on B's short-axis coordinate.
    if b_x.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
        return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value: len(b_x) });
    }
    // Reading R-RUNOUT `gsk988-only`: J as written, not clamped at the
    // retract; its end may then lie beyond the range (R-RANGE). J ≤ 57 ×
    // MAX_LENGTH (a chamfer at 89°), in i128.
    if let (Some((j, _)), false) = (run_out, c.readings.clamp_run_out) {
        let j = i128::from(j);
        let beyond = match long_axis {
            LongAxis::Z => i128::from(end.x) + i128::from(side * sf) * j,
            LongAxis::X => i128::from(end.z) - i128::from(direction) * j,
        };
        if beyond.unsigned_abs() > MAX_LENGTH.unsigned_abs().into() {
            let value = Length::new(i64::try_from(beyond).unwrap_or(i64::MAX), u);
            return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value });
        }
    }
    let frame = Frame {
        a,
        home: c.start,
        transposed: c.face,
        d: end,
        c_x: b_x,
        xf: sf,
        side,
        direction,
        w_abs,
        k: 0,
        long_axis,
        run_out,
        clamp_run_out: c.readings.clamp_run_out,
        // One pass without shift: every R-END value gives this path.
        pass_end: PassEnd::TravelI,
        lead_in: None,
        starts: c.starts,
        spacing: {
            #[cfg(feature = "loop-counters")]
            StartSpacing::record_new_gcd(c.starts);
            StartSpacing::new(c.starts)
        },
    };
    let pass = Pass { kind: PassKind::Single, number: 1, start: 1, depth: 0, cut: 0, flank: Flank::Centre };
    let walk = Walk::new(frame.path(0, 0), pass, c.lead, 0, c.start_angle, c.start);
    Ok(G92Moves { frame, walk, start: 0, first_angle: c.start_angle })
}

impl Iterator for G92Moves {
    type Item = Move;

    // Inlined across crates (see `G76Moves::next`): only the walk; the
    // next start is a call (`next_start`), once per path.
    #[inline(always)]
    fn next(&mut self) -> Option<Move> {
        let mut count = crate::loop_counters::count!(G92_NEXT);
        loop {
            count.tick();
            if let Some(m) = self.walk.next_move() {
                return Some(m);
            }
            if !self.next_start() {
                return None;
            }
        }
    }
}

impl G92Moves {
    /// The path of this start is done: the next start, if any (reading
    /// R-STARTS: each start a full pass from A); false after the last.
    #[inline(never)]
    fn next_start(&mut self) -> bool {
        let next = self.start.saturating_add(1);
        if next >= self.frame.starts {
            return false;
        }
        self.start = next;
        // next < L ≤ 999.
        let number = u16::try_from(next + 1).unwrap_or(u16::MAX);
        // The start after this one, if any, is the one expected next.
        let after = if next + 1 < self.frame.starts { next + 1 } else { next };
        let (first, spacing) = (self.first_angle, self.frame.spacing);
        self.walk.restart(number, next, after, |i| {
            #[cfg(feature = "loop-counters")]
            spacing.record_angle_gcd(i);
            first.plus(spacing.angle(i))
        });
        true
    }
}

impl FusedIterator for G92Moves {}
