//! The G92 harness: one block's pass, checked move by move against the
//! manuals' steps ①-④ and the run-out's direction, derived from the
//! block's words alone (980TDi "循环过程", notes 4-7; 988TA notes 4-5;
//! readings R-G92SIDE, R-RUNOUT, R-LONG), never from the engine.
//!
//! With A the start, C the cut end, R the taper and `xf` the X factor:
//! B = (X_C + xf·R, Z_A); `s` = +1 when A lies above C (external), -1
//! below; `t` the sign of W = Z_C - Z_A. For each start, in order:
//!
//! 1. a rapid along X only, from A to B (left out when B is A);
//! 2. the cut, a thread move, to C, or with a run-out (J > 0) to its
//!    start: K before C along the long axis (Z when |W| > |R|), on the
//!    line B–C to within half an increment (left out when K = |W|: the
//!    whole thread is run-out);
//! 3. the run-out, a thread move, away from the work: Z long, to X_C +
//!    s·min(xf·J, s·(X_A - X_C)) at Z_C; X long, to Z_C - t·min(J, |W|) at
//!    X_C;
//! 4. a rapid along X only to the X of A;
//! 5. a rapid along Z only back to A.
//!
//! The first thread move of each start synchronises at the start's spindle
//! angle `(start - 1)·360°/L` and the next does not; every point lies
//! between the X of A and the deeper end of the cut line; the starts come
//! in order, each once.

use cycleref::lead::{Lead, LeadWord};
use cycleref::{CycleError, G92Cycle, Motion, Move, PassKind, Point, Role, RunOut, StartAngle};

use crate::cover;
use crate::verify::{any_in, assume, declare};

/// A G92 block: A, C and R within `reach` increments of 0, J and K up to
/// `run_out` (or no run-out), 1 to `max_starts` starts, every unit code,
/// an F1.5 lead.
pub fn any_g92(reach: i64, run_out: i64, max_starts: i64) -> G92Cycle {
    let (units, x_mode) = crate::harness::units_of(any_in(0, 7));
    let start = Point::new(any_in(-reach, reach), any_in(-reach, reach));
    let end = Point::new(any_in(-reach, reach), any_in(-reach, reach));
    let taper = any_in(-reach, reach);
    let run_out = if any_in(0, 1) == 1 {
        RunOut::Amounts { short: any_in(0, run_out), long: any_in(0, run_out) }
    } else {
        RunOut::None
    };
    let starts = u32::try_from(any_in(1, max_starts)).unwrap_or(1);
    let face = any_in(0, 1) == 1;
    G92Cycle {
        units,
        x_mode,
        start,
        end,
        taper,
        lead: Lead { word: LeadWord::F, mantissa: 15, scale: 1 },
        run_out,
        starts,
        start_angle: StartAngle::ZERO,
        face,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// The G92 pass property (see the module docs) over [`any_g92`]`(reach,
/// run_out, max_starts)`, the moves checked as they stream.
pub fn g92_pass<F, I>(reach: i64, run_out: i64, max_starts: i64, engine: &F)
where
    F: Fn(&G92Cycle) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&[
        "external",
        "internal",
        "Z long with a run-out",
        "X long with a run-out",
        "R and U of opposite signs",
        "a pull-out (K = 0)",
        "two starts",
        "a face thread (P1) with a run-out",
    ]);
    let c = any_g92(reach, run_out, max_starts);
    // The reader never makes a run-out with J = 0 (every profile: none).
    assume(!matches!(c.run_out, RunOut::Amounts { short: 0, .. }));
    let Ok(moves) = engine(&c) else {
        assume(false);
        return;
    };
    // In the frame (short axis, long axis): X and Z, or Z and X for a face
    // thread (P1), whose long axis X counts X words (`lf`) and short axis
    // Z radius-like (`xf` = 1 there).
    let frame = |p: Point| if c.face { Point::new(p.z, p.x) } else { p };
    let (xf, lf) = if c.face { (1, c.x_mode.factor()) } else { (c.x_mode.factor(), 1) };
    let (a, cut_end) = (frame(c.start), frame(c.end));
    let b = Point::new(cut_end.x + xf * c.taper, a.z);
    let s = if a.x > cut_end.x { 1 } else { -1 };
    let w = cut_end.z - a.z;
    let t = w.signum();
    let z_long = c.face || w.abs() > c.taper.abs();
    let run_out = match c.run_out {
        RunOut::Amounts { short, long } => Some((short, lf * long)),
        RunOut::None | RunOut::Chamfer { .. } => None,
    };
    // The deeper end of the cut line, on the work's side.
    let deepest = if s > 0 { b.x.min(cut_end.x) } else { b.x.max(cut_end.x) };
    let mut at = a;
    let mut start = 0_u16;
    let mut stage = 0_u8;
    let mut synced = false;
    for m in moves {
        let p = m.pass.expect("a G92 move carries its pass");
        assert_eq!(p.kind, PassKind::Single, "a G92 pass is single");
        if p.start != start {
            assert_eq!(p.start, start + 1, "the starts come in order, each once");
            assert_eq!(at, a, "each start begins at A");
            start = p.start;
            stage = 0;
            synced = false;
        }
        if let Motion::Thread { sync, start_angle, .. } = m.motion {
            assert_eq!(sync, !synced, "the first thread move of a start synchronises, the next does not");
            if sync {
                // (start - 1)·360°/L, as a fraction of thousandths.
                let want = u64::from(start - 1) * 360_000 * u64::from(start_angle.den);
                assert_eq!(u64::from(start_angle.num) * u64::from(c.starts), want, "start angle");
            }
            synced = true;
        }
        let from = at;
        at = frame(m.to);
        let m = Move { to: frame(m.to), ..m };
        assert!(s * (m.to.x - a.x) <= 0, "no point beyond the X of A");
        assert!(s * (m.to.x - deepest) >= 0, "no point beyond the cut line");
        let order = match m.role {
            Role::Approach => 1,
            Role::Cut => 2,
            Role::RunOut => 3,
            Role::Retract => 4,
            Role::Return => 5,
            _ => panic!("a G92 move is an approach, cut, run-out, retract or return"),
        };
        assert!(order > stage, "steps 1-5 in order, each once");
        stage = order;
        match m.role {
            Role::Approach => {
                assert_eq!(m.motion, Motion::Rapid, "the approach is a rapid");
                assert_eq!((from, m.to), (a, b), "the approach runs along X from A to B");
            }
            Role::Cut => {
                assert!(matches!(m.motion, Motion::Thread { .. }), "the cut is a thread move");
                assert_eq!(from, b, "the cut starts at B");
                match run_out {
                    None => assert_eq!(m.to, cut_end, "without a run-out the cut ends at C"),
                    Some((_, k)) => {
                        if z_long {
                            assert_eq!(m.to.z, cut_end.z - t * k, "run-out start: K before C along Z");
                        } else {
                            let sigma = (cut_end.x - b.x).signum();
                            assert_eq!(
                                m.to.x,
                                cut_end.x - sigma * xf * k,
                                "run-out start: K before C along X"
                            );
                        }
                        // On the line B–C within half an increment along the short axis.
                        let (dx, dz) = (i128::from(cut_end.x - b.x), i128::from(cut_end.z - b.z));
                        let (px, pz) = (i128::from(m.to.x - b.x), i128::from(m.to.z - b.z));
                        let cross = px * dz - pz * dx;
                        let span = if z_long { dz.abs() } else { dx.abs() };
                        assert!(2 * cross.abs() <= span, "run-out start on the cut line");
                    }
                }
            }
            Role::RunOut => {
                assert!(matches!(m.motion, Motion::Thread { .. }), "the run-out is a thread move");
                let (j, k) = run_out.expect("a run-out move only with a run-out");
                let end = if z_long {
                    Point::new(cut_end.x + s * (xf * j).min(s * (a.x - cut_end.x)), cut_end.z)
                } else {
                    Point::new(cut_end.x, cut_end.z - t * j.min(w.abs()))
                };
                assert_eq!(m.to, end, "run-out end: J away from the work");
                cover!(z_long, "Z long with a run-out");
                cover!(!z_long, "X long with a run-out");
                cover!(k == 0, "a pull-out (K = 0)");
                cover!(c.face, "a face thread (P1) with a run-out");
            }
            Role::Retract => {
                assert_eq!(m.motion, Motion::Rapid, "the retract is a rapid");
                assert_eq!((from.z, m.to.x), (m.to.z, a.x), "the retract runs along X to the X of A");
            }
            _ => {
                assert_eq!(m.motion, Motion::Rapid, "the return is a rapid");
                assert_eq!((from.x, m.to), (a.x, a), "the return runs along Z back to A");
            }
        }
    }
    assert_eq!(u32::from(start), c.starts, "every start is cut");
    assert_eq!(at, a, "the block ends at A");
    cover!(s > 0, "external");
    cover!(s < 0, "internal");
    cover!(c.taper != 0 && (c.taper > 0) != (cut_end.x > a.x), "R and U of opposite signs");
    cover!(c.starts == 2, "two starts");
}
