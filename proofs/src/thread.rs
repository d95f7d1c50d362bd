//! No rapid enters the thread: the thread counterpart of
//! [`crate::groove::groove_material`] for G76 and G32.
//!
//! The region a rapid must stay out of is derived from the cycle's words
//! alone (docs/INTERPRETATIONS.md R-LONG, R-SIDE, R-END, R-RUNOUT), not from
//! the engine. For a G76 cycle, with either long axis:
//!
//! * the root line runs from C = (X_D + xf·i, Z_A) to D, the crest line
//!   `s·xf·k` beyond it along X, `s` = +1 external, -1 internal (R-SIDE: A
//!   is beyond C's X on the work's outside). The depth is along X on both
//!   long axes (R-END: every pass ends on Z = Z_D at X = X_D + s·xf·(k -
//!   Dn), and starts at X_C + s·xf·(k - Dn)); R-LONG decides only which
//!   way the run-out goes;
//! * along Z the thread runs from the last pass start to D: every pass
//!   starts at Z_A shifted towards D by its flank shift (R-INFEED), at most
//!   `2·zc` on a left flank (D2, G78's r = 1 and the 980TDi's alternating
//!   r = 3: `2·zc - round(Dn·tan(a/2))`) and `zc` in D0, D1, on the centre
//!   line and in the finishing passes, `zc = round((k - d)·tan(a/2))` (the
//!   reference's tangent product, `cycleref_spec::tan`). The approach to a
//!   pass start ends on that boundary or before it;
//!
//! and the region is the open parallelogram between the two lines, from
//! `Z_S = Z_A + t·max_shift` to `Z_D` (t = the direction of Z_A → Z_D).
//! With Z long it is a long band along Z; with X long (`|i| ≥ |W|`) a
//! steep one, whose sides Z = Z_S and Z = Z_D are each `xf·k` long along
//! X. Every rapid, as the straight segment from the tool's position to its
//! end, must not meet it: the approach and a lead-in's start lie on A's
//! side of `Z_S` (X long: no lead-in, `LeadInOnXLongAxis`), the retract
//! runs along Z = Z_D to E when there is no run-out, or from beyond the
//! crest after a Z-long run-out (a thread move along X away from the work,
//! ending on Z = Z_D), and the return runs at X of A, clear of the crest
//! at both ends and so between them (R-SIDE). The cut, the screw-in of a
//! lead-in and the run-out are thread moves and cut the thread by design.
//!
//! **X long with a run-out (reading R-XRUNOUT).** R-RUNOUT moves the
//! X-long run-out along Z, by J' = min(J, |W|) towards Z_A, so it ends at
//! Z_D - t·J', inside the band's Z span, and the retract to E = (X_A,
//! Z_D - t·J') then runs along X, the long axis, across the band. With
//! `s·i > 0` the run-out would end beyond its pass's cut line, in the work (the
//! line lies `xf·|i|·J' / |W|` further out there): both engines refuse
//! such cycles (`CycleError::RunOutIntoWork`), found by this harness. With
//! `s·i < 0` the run-out ends above its pass's cut line, in the part of the
//! band that pass has cut, and the retract runs through air; the static
//! region here cannot tell, so the harness leaves that retract out,
//! asserting `s·i < 0`, and counts it under its own cover.
//!
//! A G32 block is a thread move and its run-out another one: its expansion
//! has no rapid at all, which [`g32_no_rapid`] checks.

use cycleref::{G76Cycle, Infeed, Motion, Move, Point, Role, RunOut};

use crate::cover;
use crate::harness::{any_cycle, any_g32, Domain, Engine};
use crate::verify::{assume, declare};

/// The open region of a G76 thread (see the module docs), in integers: a
/// point is inside when `t·(z - z_s) > 0`, `t·(z_d - z) > 0` and `0 <
/// s·(x·L - root(z)·L) < xf·k·L`, `L = |Z_D - Z_A|` (never 0: a face
/// thread is refused).
#[derive(Clone, Copy, Debug)]
pub struct ThreadRegion {
    s: i128,
    t: i128,
    z_a: i128,
    z_s: i128,
    z_d: i128,
    x_c: i128,
    x_d: i128,
    len: i128,
    depth: i128,
    x_long: bool,
}

impl ThreadRegion {
    /// The region of `c`, on either long axis; `None` for a face thread
    /// (`W = 0`, which the engines refuse).
    #[must_use]
    pub fn of(c: &G76Cycle) -> Option<ThreadRegion> {
        let xf = i128::from(c.x_mode.factor());
        let (z_a, z_d) = (i128::from(c.start.z), i128::from(c.end.z));
        let len = (z_d - z_a).abs();
        if len == 0 {
            return None;
        }
        let x_d = i128::from(c.end.x);
        let x_c = x_d + xf * i128::from(c.taper);
        let s = if i128::from(c.start.x) > x_c { 1 } else { -1 };
        let t = (z_d - z_a).signum();
        let tan =
            |depth: i64| i128::from(cycleref_spec::tan::mul_tan_round(depth, c.tool_angle).unwrap_or(0));
        let zc = tan(c.thread_height - c.finishing_allowance);
        let left = matches!(c.infeed, Infeed::LeftRight | Infeed::LeftFlank | Infeed::Alternating);
        let max_shift = if left { 2 * zc } else { zc };
        Some(ThreadRegion {
            s,
            t,
            z_a,
            z_s: z_a + t * max_shift,
            z_d,
            x_c,
            x_d,
            len,
            depth: xf * i128::from(c.thread_height) * len,
            // R-LONG: X is long when |i| ≥ |W|.
            x_long: len <= i128::from(c.taper).abs(),
        })
    }

    /// True when X is the long axis (R-LONG: `|i| ≥ |W|`).
    #[must_use]
    pub fn x_long(&self) -> bool {
        self.x_long
    }

    /// +1 for an external thread, -1 for an internal one (R-SIDE).
    #[must_use]
    pub fn side(&self) -> i128 {
        self.s
    }

    /// The four constraints at a point, each `> 0` inside: `(a, b)` with the
    /// constraint `a + b·λ` along the segment `from + λ (to - from)`.
    fn constraints(&self, from: Point, to: Point) -> [(i128, i128); 4] {
        let (px, pz) = (i128::from(from.x), i128::from(from.z));
        let (dx, dz) = (i128::from(to.x) - px, i128::from(to.z) - pz);
        // u = s·(x·L - X_C·L - (X_D - X_C)·t·(z - Z_A)), linear in λ.
        let u0 =
            self.s * (px * self.len - self.x_c * self.len - (self.x_d - self.x_c) * self.t * (pz - self.z_a));
        let u1 = self.s * (dx * self.len - (self.x_d - self.x_c) * self.t * dz);
        [
            (self.t * (pz - self.z_s), self.t * dz),
            (self.t * (self.z_d - pz), -self.t * dz),
            (u0, u1),
            (self.depth - u0, -u1),
        ]
    }

    /// True when some point of the segment `from`–`to` lies inside the
    /// open region: some `λ` in `[0, 1]` satisfies every `a + b·λ > 0`.
    #[must_use]
    pub fn meets(&self, from: Point, to: Point) -> bool {
        // The feasible λ: above lo (strictly unless it is the closed end 0)
        // and below hi (strictly unless it is the closed end 1), as
        // fractions n / d with d > 0.
        let (mut lo, mut lo_open) = ((0_i128, 1_i128), false);
        let (mut hi, mut hi_open) = ((1_i128, 1_i128), false);
        for (a, b) in self.constraints(from, to) {
            if b == 0 {
                if a <= 0 {
                    return false;
                }
            } else if b > 0 {
                // λ > -a / b.
                let bound = (-a, b);
                if cmp(bound, lo) >= 0 {
                    lo = bound;
                    lo_open = true;
                }
            } else {
                // λ < a / -b.
                let bound = (a, -b);
                if cmp(bound, hi) <= 0 {
                    hi = bound;
                    hi_open = true;
                }
            }
        }
        let order = cmp(lo, hi);
        order < 0 || (order == 0 && !lo_open && !hi_open)
    }
}

/// The sign of `a.0 / a.1 - b.0 / b.1` (positive denominators).
fn cmp(a: (i128, i128), b: (i128, i128)) -> i32 {
    match (a.0 * b.1).cmp(&(b.0 * a.1)) {
        core::cmp::Ordering::Less => -1,
        core::cmp::Ordering::Equal => 0,
        core::cmp::Ordering::Greater => 1,
    }
}

/// No rapid enters the thread (G76, either long axis): every rapid of the
/// expansion, as a segment from the tool's position, stays out of the open
/// region between the crest and root lines from the last pass start to D
/// ([`ThreadRegion`]), but the retract after an X-long run-out, which
/// must follow a run-out above its pass's cut line (`s·i < 0`, module docs)
/// and is counted instead. The moves are
/// checked as they stream, not collected.
///
/// The cycle carries `CycleReadings::DEFAULT` (`any_cycle`), so reading
/// R-SIDE is pinned to its default `refuse-inside`: R-SIDE `accept` is
/// exempt by design, since it makes an A inside the crest as written and
/// its retract to E and return along Z then run through the thread (the
/// page's own moves, docs/INTERPRETATIONS.md R-SIDE).
pub fn no_rapid_in_thread<E: Engine>(d: &Domain, engine: &E) {
    declare(&[
        "external thread, towards -Z",
        "external thread, towards +Z",
        "internal thread, towards -Z",
        "internal thread, towards +Z",
        "X-long external thread",
        "X-long internal thread",
        "X-long thread with a run-out: the retract after it left out",
        "with a run-out",
        "without a run-out",
        "with a lead-in",
        "a rapid ending on the region's boundary",
    ]);
    // (A cycle with d = k and m = 0 has no pass and no move at all.)
    let c = any_cycle(d);
    let region = ThreadRegion::of(&c);
    assume(region.is_some());
    let Some(region) = region else { return };
    let Ok(moves) = engine.expand(&c) else {
        assume(false);
        return;
    };
    let mut at = c.start;
    let mut after_run_out = false;
    let mut touching = false;
    let mut left_out = false;
    for m in moves {
        let Move { motion, to, role, .. } = m;
        if motion == Motion::Rapid {
            // Only the retract that follows the run-out is left out: when
            // a retract of no length is dropped (R-ZERO), the next rapid
            // (the return) is checked (issue 32: no exemption by position
            // alone).
            if region.x_long && after_run_out && role == Role::Retract {
                // R-XRUNOUT: only a run-out above its pass's cut line.
                assert!(region.s * i128::from(c.taper) < 0, "an X-long run-out ends in the work");
                left_out = true;
            } else {
                assert!(!region.meets(at, to), "a rapid enters the thread");
            }
            // Ends on the boundary: the closed region would be met.
            touching |= to.z == c.end.z || i128::from(to.z) == region.z_s;
        }
        after_run_out = role == Role::RunOut;
        at = to;
    }
    let external = region.s > 0;
    let towards_plus = region.t > 0;
    let z_long = !region.x_long;
    cover!(z_long && external && !towards_plus, "external thread, towards -Z");
    cover!(z_long && external && towards_plus, "external thread, towards +Z");
    cover!(z_long && !external && !towards_plus, "internal thread, towards -Z");
    cover!(z_long && !external && towards_plus, "internal thread, towards +Z");
    cover!(region.x_long && external, "X-long external thread");
    cover!(region.x_long && !external, "X-long internal thread");
    cover!(left_out, "X-long thread with a run-out: the retract after it left out");
    cover!(!matches!(c.run_out, RunOut::None), "with a run-out");
    cover!(matches!(c.run_out, RunOut::None), "without a run-out");
    cover!(c.lead_in > 0, "with a lead-in");
    cover!(touching, "a rapid ending on the region's boundary");
}

/// No rapid in a G32 block: the block and its run-out are thread moves
/// (the rapids around a G32 thread are the program's own blocks).
pub fn g32_no_rapid<F, I>(reach: i64, run_out: i64, engine: &F)
where
    F: Fn(&cycleref::G32Block) -> Result<I, cycleref::CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&["G32 with a run-out", "G32 without a run-out"]);
    let b = any_g32(reach, run_out);
    let Ok(moves) = engine(&b) else {
        assume(false);
        return;
    };
    let mut n = 0_u32;
    for m in moves {
        n += 1;
        assert!(matches!(m.motion, Motion::Thread { .. }), "a rapid in a G32 block");
    }
    cover!(n == 2, "G32 with a run-out");
    cover!(n == 1, "G32 without a run-out");
}
