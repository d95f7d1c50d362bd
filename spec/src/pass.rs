//! One thread pass, exactly: the path every threading cycle with passes
//! cuts (G76's rough and finishing passes, a G92 block), in exact decimals.
//!
//! Each pass, for each start (reading R-STARTS), follows seed 000 "执行过程"
//! (4)-(5), 988TA G76 steps ①-⑩ and 980TDi G92 steps ①-④:
//!
//! 1. rapid from A to Bn, or to the lead-in start An and a screw-in thread
//!    move to Bn (reading R-LEADIN);
//! 2. thread from Bn to the end line, X travelling the taper (seed 000
//!    (4): "本轮切削终点与螺纹切入点在 Z 轴方向的移动量为 W，X 轴方向的移动量为
//!    i", reading R-END), with the run-out K before the end (reading
//!    R-RUNOUT);
//! 3. rapid along X to E (X of A), then along Z back to A ("退尾后，先沿 X
//!    轴方向快速移动，后沿 Z 轴方向快速移动回到起点"; 980TDi G92 ③ "X 轴以快速移动
//!    速度退刀 … 返回到 X 轴绝对坐标与起点相同处", ④ "Z 轴快速移动返回到起点").
//!
//! Moves that would not move are left out (reading R-ZERO).
//!
//! Twin: `impl/src/engine/pass.rs`.

use cycleref::angle::StartAngle;
use cycleref::lead::Lead;
use cycleref::moves::{Motion, Move, Pass, Role};
use cycleref::units::Point;
use cycleref::Units;
use rust_decimal::Decimal;

use crate::exact::{quantize, to_increments};
use crate::g76::LongAxis;

/// What every pass of a cycle shares, in the manual's terms, in the frame's
/// coordinates: the first the short axis (the depth), the second the long
/// axis. They are X and Z, or Z and X for a face thread (`transposed`),
/// turned back into X and Z when a move is made.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `PassFrame`.
#[derive(Clone, Copy, Debug)]
pub struct PassFrame {
    /// A, in the frame's coordinates (X in X-word units).
    pub a: (Decimal, Decimal),
    /// The frame's first coordinate is Z and its second X (G92 P1).
    pub transposed: bool,
    /// +1 when A lies outside the thread (external), -1 inside.
    pub side: i64,
    /// Sign of W: +1 cutting towards +Z, -1 towards -Z.
    pub direction: i64,
    /// |W|, the thread's length along Z.
    pub length: Decimal,
    /// Short-axis units per radius unit (2 for X as a diameter; 1 for a
    /// radius X, and for a face thread's short axis Z).
    pub x_factor: Decimal,
    /// The long axis.
    pub long_axis: LongAxis,
    /// The run-out amounts `(J, K)`, radius, or `None`.
    pub run_out: Option<(Decimal, Decimal)>,
    /// J clamped at the retract (reading R-RUNOUT, 988TA G92 note 5);
    /// `false` under R-RUNOUT `gsk988-only` on another profile.
    pub clamp_run_out: bool,
    /// The direction of every cut line, C→D (reading R-END `parallel` and
    /// `translated`); `None`: from Bn towards the pass's end (`travel-i`,
    /// and G92's pass, which has no shift).
    pub line: Option<(Decimal, Decimal)>,
    /// The lead.
    pub lead: Lead,
    /// The cycle's units.
    pub units: Units,
}

/// A cycle's moves made a pass at a time: `next_pass` appends the moves of
/// the next pass (and start) to the buffer it is given, empty, and says
/// false when there is none. The reference's stream: its memory is that of
/// one pass, whatever the number of passes and starts.
#[derive(Clone)]
pub struct PassStream<F> {
    next_pass: F,
    buf: Vec<Move>,
    at: usize,
}

impl<F: FnMut(&mut Vec<Move>) -> bool> PassStream<F> {
    /// The stream of the passes `next_pass` makes.
    pub fn new(next_pass: F) -> PassStream<F> {
        PassStream { next_pass, buf: Vec::new(), at: 0 }
    }
}

impl<F: FnMut(&mut Vec<Move>) -> bool> Iterator for PassStream<F> {
    type Item = Move;

    fn next(&mut self) -> Option<Move> {
        loop {
            if let Some(m) = self.buf.get(self.at) {
                self.at += 1;
                return Some(*m);
            }
            self.buf.clear();
            self.at = 0;
            if !(self.next_pass)(&mut self.buf) {
                return None;
            }
        }
    }
}

/// Appends to `moves` the moves of one pass of one start: from A to `bn`
/// (by the lead-in start `lead_in_start` when there is one), along the
/// thread to the end line at `end`, the run-out, the retract to the X of A
/// and the return to A, each carrying `pass`.
///
/// Twin: `impl/src/engine/pass.rs`, `Frame::path` and `Walk::new`.
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `pass_path`.
pub fn pass_path(
    moves: &mut Vec<Move>,
    f: &PassFrame,
    bn: (Decimal, Decimal),
    end: (Decimal, Decimal),
    lead_in_start: Option<(Decimal, Decimal)>,
    pass: Pass,
    angle: StartAngle,
) {
    let u = f.units;
    let s = Decimal::from(f.side);
    let t = Decimal::from(f.direction);
    let xf = f.x_factor;
    let mut path =
        Path { moves, at: f.a, pass, u, sync_done: false, lead: f.lead, angle, transposed: f.transposed };
    match lead_in_start {
        Some(an) => {
            path.go(Motion::Rapid, an, Role::Approach);
            path.thread(bn, Role::LeadIn);
        }
        None => path.go(Motion::Rapid, bn, Role::Approach),
    }
    let mut last = end;
    // The cut line: from Bn along `dir` (reading R-END).
    let dir = f.line.unwrap_or((end.0 - bn.0, end.1 - bn.1));
    match f.run_out {
        None => path.thread(end, Role::Cut),
        Some((j, kk)) => match f.long_axis {
            LongAxis::Z => {
                // Run-out starts K before the end along Z, on the cut line.
                let zr = end.1 - t * kk;
                let xr = quantize(bn.0 + dir.0 * (zr - bn.1) / dir.1, u);
                path.thread((xr, zr), Role::Cut);
                // Short axis: J away from the work, at most to E (reading R-RUNOUT).
                // Reading R-RUNOUT `gsk988-only`: J as written.
                let jx = if f.clamp_run_out { (xf * j).min(s * (f.a.0 - end.0)) } else { xf * j };
                last = (end.0 + s * jx, end.1);
                path.thread(last, Role::RunOut);
            }
            LongAxis::X => {
                let sigma = if dir.0 > Decimal::ZERO { Decimal::ONE } else { Decimal::NEGATIVE_ONE };
                let xr = end.0 - sigma * xf * kk;
                let zr = quantize(bn.1 + dir.1 * (xr - bn.0) / dir.0, u);
                path.thread((xr, zr), Role::Cut);
                // At most the Z travel back to A: |W|, or |W| + the shift
                // for a translated pass (R-END).
                let jz = if f.clamp_run_out { j.min((end.1 - f.a.1).abs()) } else { j };
                last = (end.0, end.1 - t * jz);
                path.thread(last, Role::RunOut);
            }
        },
    }
    path.go(Motion::Rapid, (f.a.0, last.1), Role::Retract);
    path.go(Motion::Rapid, f.a, Role::Return);
}

/// The moves of one pass, zero-length ones left out (reading R-ZERO).
///
/// Restated in integers: `proofs/src/g76_exact.rs`, `Path`.
struct Path<'a> {
    moves: &'a mut Vec<Move>,
    at: (Decimal, Decimal),
    pass: Pass,
    u: Units,
    sync_done: bool,
    lead: Lead,
    angle: StartAngle,
    transposed: bool,
}

impl Path<'_> {
    fn go(&mut self, motion: Motion, to: (Decimal, Decimal), role: Role) {
        if to == self.at {
            return;
        }
        self.at = to;
        let to = if self.transposed { (to.1, to.0) } else { to };
        let to = Point::new(to_increments(to.0, self.u), to_increments(to.1, self.u));
        self.moves.push(Move { motion, to, role, pass: Some(self.pass) });
    }

    fn thread(&mut self, to: (Decimal, Decimal), role: Role) {
        if to == self.at {
            return;
        }
        let sync = !self.sync_done;
        self.sync_done = true;
        let motion = Motion::Thread { lead: self.lead, start_angle: self.angle, sync };
        self.go(motion, to, role);
    }
}
