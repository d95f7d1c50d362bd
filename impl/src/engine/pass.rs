//! One thread pass, shared by every threading cycle with passes (G76's
//! rough and finishing passes, a G92 block): the path of a pass from A to
//! its start, along the thread, through the run-out and back to A, and the
//! walk that streams its moves.
//!
//! A pass, in the manuals' terms (seed 000 "执行过程", 988TA G76 steps
//! ①-⑩, 980TDi G92 steps ①-④):
//!
//! 1. rapid from A to the pass start Bn (or to the lead-in start An, then a
//!    screw-in thread move to Bn, reading R-LEADIN);
//! 2. thread from Bn to the end line, X travelling the taper (reading
//!    R-END), with the run-out K before the end (reading R-RUNOUT);
//! 3. rapid along X to E (X of A), then along Z back to A.
//!
//! Moves that would not move are left out (reading R-ZERO).
//!
//! Twin: `spec/src/pass.rs`.

use crate::angle::{StartAngle, StartSpacing};
use crate::engine::arith::{round_div, saturate_i64};
use crate::lead::Lead;
use crate::moves::{Motion, Move, Pass, Role};
use crate::readings::PassEnd;
use crate::units::Point;

/// The long axis of the thread (reading R-LONG).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum LongAxis {
    /// `|W| > |i|`.
    Z,
    /// `|i| ≥ |W|`.
    X,
}

/// The fixed values of a checked threading cycle, in the frame's
/// coordinates: `x` the short axis (the depth), `z` the long axis. For an
/// axial thread they are X and Z; for a face thread (G92 P1) they are Z and
/// X (`transposed`), and the points of a path are turned back into X and Z
/// when they are made.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    /// The cycle's lead, for the thread motions.
    pub(crate) lead: Lead,
    /// A, in the frame's coordinates.
    pub(crate) a: Point,
    /// A, in X and Z: where every pass returns.
    pub(crate) home: Point,
    /// The frame's x is Z and its z is X (a face thread).
    pub(crate) transposed: bool,
    /// D (G92: the cut end C).
    pub(crate) d: Point,
    /// X of C, the thread's start at the Z of A (G92: X of B).
    pub(crate) c_x: i64,
    /// Short-axis coordinate increments per radius increment: 2 for X as a
    /// diameter, else 1 (a face thread's short axis is Z).
    pub(crate) xf: i64,
    /// +1 external, -1 internal.
    pub(crate) side: i64,
    /// Sign of W.
    pub(crate) direction: i64,
    /// |W|.
    pub(crate) w_abs: i64,
    /// k (G92: 0, every pass is at the programmed X).
    pub(crate) k: i64,
    /// Long axis.
    pub(crate) long_axis: LongAxis,
    /// `(J, K)`, K in the long axis's coordinate increments (a face
    /// thread's K, a radius, is scaled to X's words by the caller).
    pub(crate) run_out: Option<(i64, i64)>,
    /// J clamped at the retract (reading R-RUNOUT, 988TA G92 note 5).
    pub(crate) clamp_run_out: bool,
    /// Where each pass ends (reading R-END); G92 passes have no shift, so
    /// every value gives the same path.
    pub(crate) pass_end: PassEnd,
    /// `(E, lead-in length)`.
    pub(crate) lead_in: Option<(i64, i64)>,
    /// L.
    pub(crate) starts: u32,
    /// The spacing of the starts, 360° / L.
    pub(crate) spacing: StartSpacing,
}

/// The path of one pass: the candidate moves' end points.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PassPath {
    /// End of the approach: An with a lead-in, else Bn.
    approach: Point,
    /// Bn, the end of the lead-in, if there is one.
    lead_in: Option<Point>,
    /// End of the cut: the run-out start, or the end line D–E.
    cut: Point,
    /// End of the run-out, if there is one.
    run_out: Option<Point>,
    /// E: the X of A, on the Z of the end of the pass.
    retract: Point,
}

impl Frame {
    /// C→D, the direction of a `parallel` or `translated` pass (R-END).
    #[inline(always)]
    fn c_to_d(&self) -> (i128, i128) {
        (i128::from(self.d.x) - i128::from(self.c_x), i128::from(self.d.z) - i128::from(self.a.z))
    }

    /// The path of a pass at `depth` shifted `shift` along Z, as the
    /// reference's `pass_path` builds it.
    ///
    /// Twin: `spec/src/pass.rs`, `pass_path`.
    // Inlined into each cycle's next pass: a `PassPath` returned through
    // memory is written piece by piece and read back whole (a
    // store-forwarding stall per pass, 40 % of `next_pass` in the G76
    // benchmark).
    #[inline(always)]
    pub(crate) fn path(&self, depth: i64, shift: i64) -> PassPath {
        let (s, t, xf) = (self.side, self.direction, self.xf);
        // 0 ≤ k - depth < 2^30; X of C < 3·2^30, Z shifts < 2^32.
        let sink = s * xf * (self.k - depth);
        let bn = Point::new(self.c_x + sink, self.a.z + t * shift);
        // Reading R-END. The cut line runs from Bn along `dir`: its own
        // end for `travel-i`, C→D for the other two (exactly: the end of a
        // `parallel` pass is rounded, the line is not).
        let (end, dir) = match self.pass_end {
            PassEnd::TravelI => {
                let end = Point::new(self.d.x + sink, self.d.z);
                (end, (i128::from(end.x) - i128::from(bn.x), i128::from(end.z) - i128::from(bn.z)))
            }
            PassEnd::Parallel => {
                // X of the line at the Z of D: X(D) + sink + xf·i·shift/|W|,
                // rounded as a whole (|W| ≥ 1; every term below 2^34).
                let num = (i128::from(self.d.x) + i128::from(sink)) * i128::from(self.w_abs)
                    + (i128::from(self.c_x) - i128::from(self.d.x)) * i128::from(shift);
                let x = saturate_i64(round_div(num, i128::from(self.w_abs)));
                (Point::new(x, self.d.z), self.c_to_d())
            }
            PassEnd::Translated => (Point::new(self.d.x + sink, self.d.z + t * shift), self.c_to_d()),
        };
        let approach = match self.lead_in {
            // Only called for a planned pass, so the range check of
            // expand_g76 has bounded both coordinates of An (|lz| < 2^33).
            Some((e, lz)) => Point::new(bn.x + s * xf * e, bn.z - t * lz),
            None => bn,
        };
        let lead_in = self.lead_in.map(|_| bn);
        let (cut, run_out, last) = match self.run_out {
            None => (end, None, end),
            Some((j, kk)) => match self.long_axis {
                LongAxis::Z => {
                    // The run-out starts K before the end along Z, on the cut
                    // line: xr = round(bn.x + dir.x (zr - bn.z) / dir.z), the
                    // rounding on the whole sum. dir.z ≠ 0: t(|W| - shift)
                    // (ThreadTooShort) or W.
                    let zr = end.z - t * kk;
                    let xr = if dir.0 == 0 {
                        // A straight cut: no division (the common case).
                        bn.x
                    } else {
                        let num = i128::from(bn.x) * dir.1 + dir.0 * (i128::from(zr) - i128::from(bn.z));
                        saturate_i64(round_div(num, dir.1))
                    };
                    // J away from the work, at most to E; J may be i64::MAX.
                    // Unclamped (R-RUNOUT `gsk988-only`): J as written,
                    // range-checked by the caller.
                    let jx = xf.saturating_mul(j);
                    let jx = if self.clamp_run_out { jx.min(s * (self.a.x - end.x)) } else { jx };
                    let last = Point::new(end.x + s * jx, end.z);
                    (Point::new(xr, zr), Some(last), last)
                }
                LongAxis::X => {
                    // dir.x = -xf i ≠ 0 (or the travel-i pass's, the same)
                    // on an X long axis.
                    let sigma = if dir.0 > 0 { 1 } else { -1 };
                    let xr = end.x - sigma * xf * kk;
                    let num = i128::from(bn.z) * dir.0 + dir.1 * (i128::from(xr) - i128::from(bn.x));
                    let zr = saturate_i64(round_div(num, dir.0));
                    // At most the Z travel back to A (|W|, or |W| + shift
                    // for a translated pass).
                    let back = (end.z - self.a.z).abs();
                    let jz = if self.clamp_run_out { j.min(back) } else { j };
                    let last = Point::new(end.x, end.z - t * jz);
                    (Point::new(xr, zr), Some(last), last)
                }
            },
        };
        let path = PassPath { approach, lead_in, cut, run_out, retract: Point::new(self.a.x, last.z) };
        if self.transposed {
            let swap = |p: Point| Point::new(p.z, p.x);
            PassPath {
                approach: swap(path.approach),
                lead_in: path.lead_in.map(swap),
                cut: swap(path.cut),
                run_out: path.run_out.map(swap),
                retract: swap(path.retract),
            }
        } else {
            path
        }
    }
}

/// The moves of one pass of one start, streamed: at most six candidate
/// moves (approach, lead-in, cut, run-out, retract, return), of which the
/// zero-length ones are skipped.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Walk {
    /// The pass every move carries (its `start` is the current start).
    pub(crate) pass: Pass,
    /// The path.
    path: PassPath,
    /// Spindle angle of the start.
    angle: StartAngle,
    /// Next candidate move of the path, 0..=6 (6: path finished).
    step: u8,
    /// Tool position.
    at: Point,
    /// The path has started its synchronised run.
    sync_done: bool,
}

impl Walk {
    /// A walk of `path` from A for `pass` at spindle angle `angle`.
    pub(crate) fn new(path: PassPath, pass: Pass, angle: StartAngle, a: Point) -> Walk {
        Walk { pass, path, angle, step: 0, at: a, sync_done: false }
    }

    /// The same path again from A, for another start.
    pub(crate) fn restart(&mut self, start: u16, angle: StartAngle, a: Point) {
        self.pass.start = start;
        self.angle = angle;
        self.step = 0;
        self.at = a;
        self.sync_done = false;
    }

    /// The next move of the path, or `None` once it is back at A.
    // Inlined across crates: a call per move costs more than the move.
    #[inline]
    pub(crate) fn next_move(&mut self, frame: &Frame) -> Option<Move> {
        let mut count = crate::loop_counters::count!(PASS_WALK);
        loop {
            count.tick();
            let step = self.step;
            // (thread?, end point, role); None when the path has no such move.
            // Only the field needed is read (copying the whole path per move
            // showed in the profile).
            let candidate = match step {
                0 => Some((false, self.path.approach, Role::Approach)),
                1 => self.path.lead_in.map(|to| (true, to, Role::LeadIn)),
                2 => Some((true, self.path.cut, Role::Cut)),
                3 => self.path.run_out.map(|to| (true, to, Role::RunOut)),
                4 => Some((false, self.path.retract, Role::Retract)),
                5 => Some((false, frame.home, Role::Return)),
                _ => return None,
            };
            self.step = step.saturating_add(1);
            let Some((thread, to, role)) = candidate else {
                continue;
            };
            // Reading R-ZERO: moves that would not move are left out.
            if to == self.at {
                continue;
            }
            self.at = to;
            let motion = if thread {
                let sync = !self.sync_done;
                self.sync_done = true;
                Motion::Thread { lead: frame.lead, start_angle: self.angle, sync }
            } else {
                Motion::Rapid
            };
            return Some(Move { motion, to, role, pass: Some(self.pass) });
        }
    }
}
