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
use crate::moves::{Flank, Motion, Move, Pass, PassKind, Role};
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
                // rounded as a whole (|W| ≥ 1; every term below 2^34). On
                // a straight thread (X of C = X of D, i = 0) the quotient
                // is exact, X(D) + sink: no division.
                let x = if self.c_x == self.d.x {
                    self.d.x + sink
                } else {
                    let num = (i128::from(self.d.x) + i128::from(sink)) * i128::from(self.w_abs)
                        + (i128::from(self.c_x) - i128::from(self.d.x)) * i128::from(shift);
                    saturate_i64(round_div(num, i128::from(self.w_abs)))
                };
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

/// The moves of one pass, streamed for each start: the candidate moves
/// (approach, lead-in, cut, run-out, retract, return) less the zero-length
/// ones, chosen once per pass when the walk is made. Every start walks the
/// same path from the same point (A, `frame.home`), so the moves left out
/// (reading R-ZERO) are the same for every start; a start only changes the
/// pass's start number and the spindle angle.
// The bookkeeping fields are words, not bytes, and the end points two
// arrays of `i64`: a byte stored per move and read back within a wider
// load, or a point stored as two words and read back as one 16-byte
// load, cannot be forwarded from the store buffer and stalls each move.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Walk {
    /// Next move of the current start, `0..=len`.
    next: usize,
    /// Number of moves, at most 6.
    len: usize,
    /// The pass every move carries, but for its `start`.
    pub(crate) pass: Pass,
    /// The current start (1-based), the `start` of every move's pass: kept
    /// apart, so that a new start does not write into `pass` (a 2-byte
    /// store that each start's first move read back within the pass's
    /// wider loads: a store-forwarding stall per start).
    start: u16,
    /// X (the first coordinate) of the end points of the moves that move,
    /// in order (`len` of them).
    x: [i64; SLOTS],
    /// Z of the same end points.
    z: [i64; SLOTS],
    /// Their roles.
    role: [Role; SLOTS],
    /// The motion of each move: [`RAPID`], [`SYNC`] or [`THREAD`], an
    /// index into a bank of `motions`.
    motion: [u8; SLOTS],
    /// The bank of `motions` the current start's moves take their motion
    /// from: the index of its first motion, 0 or [`BANK`] (a word: it is
    /// read per move).
    bank: usize,
    /// The start (the caller's key: G76 and G92 use the 0-based start
    /// index) whose spindle angle each bank holds; [`NO_KEY`] for none.
    keys: [u32; 2],
    /// Two banks of the three motions a move can have, each for one start:
    /// a rapid, the thread move where synchronisation starts, the thread
    /// moves after it. Copied whole into each move: a motion assembled per
    /// move was built in memory field by field and read back whole, a
    /// store-forwarding stall per move. A bank is written one start ahead
    /// of its use (see [`Walk::restart`]): a spindle angle written when
    /// its start begins was read back, within the motion's wider loads, by
    /// that start's first thread move while still in the store buffer (a
    /// stall per start).
    motions: [Motion; SLOTS],
}

/// The motions in one bank of [`Walk::motions`] (three, and one unused).
const BANK: usize = 4;
/// The length of the arrays of a [`Walk`]: at least six moves and two
/// banks of motions, a power of two so that an index taken modulo
/// `SLOTS` is visibly in bounds (no check per move; every index used is
/// already below it).
const SLOTS: usize = 8;
/// The key of a bank of [`Walk::motions`] that holds no start's angle.
const NO_KEY: u32 = u32::MAX;

/// Index in a bank of [`Walk::motions`] of a rapid.
const RAPID: u8 = 0;
/// Index in a bank of [`Walk::motions`] of the thread move where synchronisation
/// starts.
const SYNC: u8 = 1;
/// Index in a bank of [`Walk::motions`] of a later thread move of the run.
const THREAD: u8 = 2;

/// The three motions of a walk at spindle angle `angle` (see
/// [`Walk::motions`]).
fn motions(lead: Lead, angle: StartAngle) -> [Motion; 3] {
    [
        Motion::Rapid,
        Motion::Thread { lead, start_angle: angle, sync: true },
        Motion::Thread { lead, start_angle: angle, sync: false },
    ]
}

/// Sets the spindle angle of the thread motions in place (the lead, the
/// cycle's, does not change): a motion built anew is assembled in a
/// temporary and copied, which stalls on the copy.
#[inline(always)]
fn set_angle(motions: &mut [Motion], angle: StartAngle) {
    for m in motions {
        if let Motion::Thread { start_angle, .. } = m {
            *start_angle = angle;
        }
    }
}

impl Walk {
    /// A walk of `path` from `a` (A, `frame.home`: where every start
    /// begins) for `pass` at spindle angle `angle`, the angle of the start
    /// the caller calls `key` (see [`Walk::restart`]).
    pub(crate) fn new(path: PassPath, pass: Pass, lead: Lead, key: u32, angle: StartAngle, a: Point) -> Walk {
        let mut walk = Walk::idle(lead, key, angle);
        walk.load(path, pass, a);
        walk.start = pass.start;
        walk
    }

    /// A walk with no move, for the lead `lead`, whose first bank holds
    /// the angle `angle` of the start `key`: [`Walk::load`] gives it its
    /// first path.
    pub(crate) fn idle(lead: Lead, key: u32, angle: StartAngle) -> Walk {
        // A placeholder pass, replaced by `load` before any move is made.
        let pass = Pass { kind: PassKind::Rough, number: 0, start: 1, depth: 0, cut: 0, flank: Flank::Right };
        let [r, s, t] = motions(lead, angle);
        Walk {
            next: 0,
            len: 0,
            pass,
            start: 1,
            x: [0; SLOTS],
            z: [0; SLOTS],
            role: [Role::Return; SLOTS],
            motion: [RAPID; SLOTS],
            bank: 0,
            keys: [key, NO_KEY],
            motions: [r, s, t, r, r, s, t, r],
        }
    }

    /// Makes this the walk of `path` from `a` for `pass`, in place (a walk
    /// returned by value is copied whole, once per pass), with the motions
    /// it has: [`Walk::restart`] then starts it.
    #[inline(always)]
    pub(crate) fn load(&mut self, path: PassPath, pass: Pass, a: Point) {
        self.pass = pass;
        self.len = 0;
        self.next = 0;
        // The candidates in order, each kept if it moves (the lead-in and
        // the run-out only when the path has them). Entries at `len` and
        // beyond are never read.
        let mut at = a;
        let mut sync = true;
        self.push(&mut at, &mut sync, false, path.approach, Role::Approach);
        if let Some(to) = path.lead_in {
            self.push(&mut at, &mut sync, true, to, Role::LeadIn);
        }
        self.push(&mut at, &mut sync, true, path.cut, Role::Cut);
        if let Some(to) = path.run_out {
            self.push(&mut at, &mut sync, true, to, Role::RunOut);
        }
        self.push(&mut at, &mut sync, false, path.retract, Role::Retract);
        self.push(&mut at, &mut sync, false, a, Role::Return);
    }

    /// Appends the candidate move to `to` unless the tool is already there
    /// (`at`): reading R-ZERO, moves that would not move are left out.
    #[inline(always)]
    fn push(&mut self, at: &mut Point, sync: &mut bool, thread: bool, to: Point, role: Role) {
        if to == *at {
            return;
        }
        *at = to;
        let i = self.len;
        // At most six candidates, so i < 6: the writes stay in the arrays
        // and the shift in the word.
        // The first thread move of the path starts the synchronised run.
        let motion = match (thread, *sync) {
            (false, _) => RAPID,
            (true, true) => SYNC,
            (true, false) => THREAD,
        };
        *sync &= !thread;
        if let (Some(x), Some(z), Some(r), Some(m)) =
            (self.x.get_mut(i), self.z.get_mut(i), self.role.get_mut(i), self.motion.get_mut(i))
        {
            *x = to.x;
            *z = to.z;
            *r = role;
            *m = motion;
        }
        self.len = i + 1;
    }

    /// The path from A (again) for the start numbered `start` (1-based),
    /// at the spindle angle of the start the caller calls `key`; `next`
    /// is the key of the start expected to come next (the same key when
    /// none is), and `angle` gives the angle of a key.
    ///
    /// The angle of `next` is written now, into the bank not in use, so
    /// that its moves read a bank written a whole path before; `key`'s
    /// bank is written only when neither bank holds it (the first start
    /// of a cycle, or a start that was not expected). Either way each move
    /// carries `angle(key)`: which bank holds it changes only the speed.
    #[inline(always)]
    pub(crate) fn restart(&mut self, start: u16, key: u32, next: u32, angle: impl Fn(u32) -> StartAngle) {
        self.start = start;
        self.next = 0;
        let held = usize::from(self.bank != 0);
        let mut other = held ^ 1;
        if self.keys.get(held) != Some(&key) {
            if self.keys.get(other) != Some(&key) {
                self.fill(other, key, angle(key));
            }
            self.bank = other * BANK;
            other = held;
        }
        if next != key && self.keys.get(other) != Some(&next) {
            self.fill(other, next, angle(next));
        }
    }

    /// Writes the angle of the start `key` into bank `bank` (0 or 1).
    #[inline(always)]
    fn fill(&mut self, bank: usize, key: u32, angle: StartAngle) {
        // Only the bank's two thread motions (SYNC and THREAD) have an angle.
        let first = bank * BANK + usize::from(SYNC);
        if let (Some(k), Some(motions)) = (self.keys.get_mut(bank), self.motions.get_mut(first..first + 2)) {
            *k = key;
            set_angle(motions, angle);
        }
    }

    /// The next move of the path, or `None` once it is back at A.
    // Inlined across crates: a call per move costs more than the move.
    #[inline]
    pub(crate) fn next_move(&mut self) -> Option<Move> {
        let i = self.next;
        if i >= self.len {
            return None;
        }
        // i < len ≤ 6 and m + bank ≤ 2 + BANK < SLOTS: the remainders
        // change nothing (they let the compiler see the bounds).
        let k = i % SLOTS;
        let motion = self.motions[(usize::from(self.motion[k]) + self.bank) % SLOTS];
        let (x, z, role) = (self.x[k], self.z[k], self.role[k]);
        self.next = i + 1;
        Some(Move { motion, to: Point::new(x, z), role, pass: Some(Pass { start: self.start, ..self.pass }) })
    }
}
