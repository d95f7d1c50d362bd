//! G32, constant-lead thread cutting, exactly as the manuals define it
//! (seed 002, manuals/gsk980tdi-g32.txt, manuals/gsk988ta-g32.txt).
//!
//! "刀具的运动轨迹是从起点到终点的一条直线, 从起点到终点位移量(X轴按半径值)较大的
//! 坐标轴称为长轴, 另一个坐标轴称为短轴, 运动过程中主轴每转一圈长轴移动一个导程"
//! (seed 002): one straight synchronised move from the current position to
//! X(U) Z(W), the lead along the long axis; with a run-out, the move stops
//! K before the end along the long axis and the run-out ends at the end's
//! long-axis coordinate displaced J along the short axis (reading R-G32RUNOUT).

use cycleref::error::CycleError;
use cycleref::g32::{G32Block, G32RunOut};
use cycleref::moves::{Motion, Move, Role};
use cycleref::units::{Length, Point};
use rust_decimal::Decimal;

use crate::exact::{from_increments, quantize, to_increments};
use crate::g76::LongAxis;

/// The long axis of a G32 move (reading R-G32LONG): Z when its displacement
/// is larger than X's as a radius, X otherwise (seed 002: "位移量(X轴按半径值)
/// 较大的坐标轴称为长轴"; an equal displacement counts for X, as G76's rule
/// "反之，X 轴为长轴"), or for Z under reading R-G32LONG `tie-z`.
#[must_use]
pub fn long_axis(b: &G32Block) -> LongAxis {
    let u = b.units;
    let xf = Decimal::from(b.x_mode.factor());
    let dx = (from_increments(b.end.x, u) - from_increments(b.start.x, u)) / xf;
    let dz = from_increments(b.end.z, u) - from_increments(b.start.z, u);
    if dz.abs() > dx.abs() || (b.readings.g32_tie_z && dz.abs() == dx.abs()) {
        LongAxis::Z
    } else {
        LongAxis::X
    }
}

/// Expands one G32 block into its thread moves.
///
/// # Errors
///
/// The block's alarm: a zero or out-of-range lead, no motion, a value
/// outside the range tables, or a run-out longer than the move along the
/// long axis (988TA G32 note 4: "当螺纹长轴方向退尾长度大于长轴的螺纹加工长度时，
/// 系统产生报警").
///
/// Twin: `impl/src/engine/g32.rs`, `expand_g32`.
pub fn expand(b: &G32Block) -> Result<Vec<Move>, CycleError> {
    b.validate()?;
    let u = b.units;
    let xf = Decimal::from(b.x_mode.factor());
    let start = (from_increments(b.start.x, u), from_increments(b.start.z, u));
    let end = (from_increments(b.end.x, u), from_increments(b.end.z, u));
    let (dx, dz) = (end.0 - start.0, end.1 - start.1);
    let axis = long_axis(b);
    let thread = |sync: bool| Motion::Thread { lead: b.lead, start_angle: b.start_angle, sync };
    let point = |x: Decimal, z: Decimal| Point::new(to_increments(x, u), to_increments(z, u));
    let mut moves = Vec::with_capacity(2);
    let mut at = start;
    let mut go = |to: (Decimal, Decimal), role: Role, moves: &mut Vec<Move>| {
        if to != at {
            let sync = b.sync && moves.is_empty();
            moves.push(Move { motion: thread(sync), to: point(to.0, to.1), role, pass: None });
            at = to;
        }
    };
    match b.run_out {
        G32RunOut::None => go(end, Role::Cut, &mut moves),
        G32RunOut::Amounts { short, long } => {
            let j = from_increments(short, u);
            let k = from_increments(long, u);
            match axis {
                LongAxis::Z => {
                    if k > dz.abs() {
                        return Err(too_long(long, to_increments(dz.abs(), u), b));
                    }
                    // The run-out starts K before the end along Z, on the line.
                    let zr = end.1 - sign(dz) * k;
                    let xr = quantize(start.0 + dx * (zr - start.1) / dz, u);
                    go((xr, zr), Role::Cut, &mut moves);
                    go((end.0 + xf * j, end.1), Role::RunOut, &mut moves);
                }
                LongAxis::X => {
                    // K is a radius when X is the long axis.
                    if xf * k > dx.abs() {
                        let length = to_increments(quantize((dx.abs() / xf).floor_to_increment(u), u), u);
                        return Err(too_long(long, length, b));
                    }
                    let xr = end.0 - sign(dx) * xf * k;
                    let zr = quantize(start.1 + dz * (xr - start.0) / dx, u);
                    go((xr, zr), Role::Cut, &mut moves);
                    go((end.0, end.1 + j), Role::RunOut, &mut moves);
                }
            }
        }
    }
    Ok(moves)
}

/// +1 or -1 (the operand is never zero where it is used).
fn sign(v: Decimal) -> Decimal {
    if v.is_sign_negative() {
        Decimal::NEGATIVE_ONE
    } else {
        Decimal::ONE
    }
}

fn too_long(run_out: i64, length: i64, b: &G32Block) -> CycleError {
    CycleError::RunOutTooLong { run_out: Length::new(run_out, b.units), length: Length::new(length, b.units) }
}

/// Rounding a radius length down to the increment, for messages.
trait FloorToIncrement {
    fn floor_to_increment(self, u: cycleref::Units) -> Decimal;
}

impl FloorToIncrement for Decimal {
    fn floor_to_increment(self, u: cycleref::Units) -> Decimal {
        self.round_dp_with_strategy(u.decimals(), rust_decimal::RoundingStrategy::ToZero)
    }
}
