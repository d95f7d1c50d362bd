//! G75.1, the radial trapezoidal groove cycle (径向凹槽切削循环), exactly as
//! `docs/G75.md` defines it from the manual page (seed 001, GSK 980TDi
//! §3.23.8; manuals/gsk980tdi-g75.1.txt).
//!
//! "代码意义: 给定精车的起点 (X, Z), 粗车循环时的轴向和径向的进刀量, 凹槽的槽深、
//! 槽底宽度两腰与槽底形成的两个啮合角以及斜面切槽的斜面角度。给定退刀量, 安全距离,
//! 精加工余量, 刀具宽度, 加工路径类型, 倒棱宽度或倒圆半径以及倒角类型。" (seed 001)
//!
//! One function per formula of `docs/G75.md`, each with the manual's words
//! and the reading (`R-G75…`) it implements. All geometry is computed in the
//! local frame of §2 (`u` along the groove from S in the direction of D's
//! sign, `y` the depth below S in X-word units) as exact [`Real`](crate::real::Real) numbers,
//! and every coordinate is rounded to a whole increment from its own exact
//! formula, never from a rounded intermediate (R-G75ROUND), with the
//! rounding `docs/G75.md` §6 gives it:
//!
//! * nearest, `floor(v + 1/2)`: the finishing profile, round centres, P3;
//! * in (towards the inside of the roughing region): `ceil` on the start
//!   side (`left`, R0, K1, K2, Q1), `floor` on the far side (`right`, R3,
//!   K3, K4, Q2) before the tool width is subtracted, `floor` for the
//!   depths `y_K1`, `y_K4`, `y_top`.
//!
//! A rounding (or an alarm's comparison) that 512 fraction bits cannot
//! decide falls under R-G75TIE (`crate::real`): a value whose enclosure
//! still holds exactly one rounding boundary lies on it; only two
//! boundaries or more give `CycleError::UndecidedRounding`.
//!
//! Readings this model adds where `docs/G75.md` is silent are marked
//! `R-G75…:` in comments (R-G75MAXMIN, R-G75K1Y, R-G75NARROWJ, R-G75PECKJ2,
//! R-G75DECIDE, R-G75RANGE, R-G75ARCZERO, R-G75ROLES).
//!
//! # Layout
//!
//! This module is the driver, [`expand`]; the formulas are split by the
//! sections of `docs/G75.md`, and re-exported here: `geometry` (§2–§3, the
//! exact groove and the corner alarms), `region` (§5, the roughing
//! region's boundaries), `rounding` (§6), `roughing` (§7, layers, plunges
//! and pecks), `contour` (§8 steps 9 and 10), `path` (§8, the path, the
//! range check and the roughing moves), `profile` (the whole groove, for
//! tests). The fixed-point engine is split the same way
//! (`impl/src/engine/g75/`).
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use cycleref::error::CycleError;
use cycleref::g75::G75Cycle;
use cycleref::moves::{Motion, Move, Role};

mod contour;
mod geometry;
mod path;
mod profile;
mod region;
mod roughing;
mod rounding;

pub use contour::*;
pub use geometry::*;
use path::*;
pub use profile::*;
pub use region::*;
pub use roughing::*;
pub use rounding::*;

/// Expands a G75.1 cycle into its moves (`docs/G75.md` §8), in absolute
/// X/Z, every move with `pass: None`:
///
/// 1. `Approach`: rapid to A11 = `(A_11, y_top)` (step ① "刀具从当前起点定位到
///    粗加工起点 A11"), whatever J is;
/// 2. J0, J1 ("J: 走刀路径类型，0：只走粗加工路径；1：粗加工路径+精加工路径"): the
///    layers and plunges (`rough_moves`), then the rough contour
///    (`RoughContour`, step ⑨ "刀具沿着粗车轨迹轮廓切削，切削完回到粗车起点
///    A11"): rapid along Z to R0, feeds through [`rough_contour`], rapid
///    along Z back to A11;
/// 3. J1, J2 ("2：只走精加工路径"): the finishing contour (`FinishContour`,
///    step ⑩): rapid along Z to F0's u at `y_top`, rapid along X to F0, the
///    [`finish_contour`]; then `Return` ("切削完回到精车起点 (X,Z)"): rapid
///    along X to `min(y_top, y_end)`, along Z to `u = 0`, along X to S;
/// 4. `Return`: rapid to `from` in one move ("刀具快速返回凹槽切削前起点处，
///    G75.1 循环执行完毕").
///
/// No move ends where the tool already is (R-G75ZERO).
///
/// Errors come in the order of `docs/G75.md`: `validate()`; the corner
/// alarms (flank A, bottom, flank B); the groove narrower than the tool;
/// too many pecks; a coordinate beyond the range tables.
///
/// R-G75DECIDE: the values are decided in this order, so that an
/// undecidable one (`UndecidedRounding`) is reported where it is first
/// needed: the corner alarms, the last layer's plunge range, `y_top`, the
/// layers' plunge ranges (J0, J1; else only layer 1's), the rough contour
/// (R0, y_K1, K1 if below y_top, K2 or Q1, K3, y_K4, K4 if below y_top or
/// Q2, R3), the finishing contour in path order (each point, then a round's
/// centre, then its direction).
///
/// R-G75RANGE: the coordinates are checked after the moves are made, in
/// move order, each move's end X then Z, then an arc's centre X then Z.
///
/// # Errors
///
/// The manual's alarms, as [`CycleError`].
///
/// Twin: `impl/src/engine/g75/mod.rs`, `expand_g75`.
pub fn expand(c: &G75Cycle) -> Result<Vec<Move>, CycleError> {
    c.validate()?;
    let g = groove(c);
    // R-G75DECIDE: values are decided in this order (corners, last layer,
    // y_top, layers, rough contour, finishing contour in path order).
    check_corners(&g)?;
    check_tool_fits(&g)?;
    check_ridges(&g)?;
    let y_top = y_top(&g)?;
    let layers = if c.path.roughs() { rough_layers(&g, y_top)? } else { Vec::new() };
    let a11 = match layers.first() {
        Some(layer) => LocalPoint::new(layer.range.first, y_top),
        None => LocalPoint::new(plunge_range(&g, 1)?.first, y_top),
    };
    let mut path = Path { at: local_of(&g, c.from), moves: Vec::new() };
    path.rapid(a11, Role::Approach);
    if c.path.roughs() {
        rough_moves(&g, &mut path, &layers, a11, y_top);
        let contour = rough_contour(&g, y_top)?;
        let mut points = contour.iter();
        if let Some(r0) = points.next() {
            path.rapid_u(r0.u, Role::RoughContour);
        }
        for p in points {
            path.go(LocalMotion::Feed, *p, Role::RoughContour);
        }
        path.rapid_u(a11.u, Role::RoughContour);
    }
    if c.path.finishes() {
        let (start, moves) = finish_contour(&g)?;
        path.rapid_u(start.u, Role::FinishContour);
        path.rapid_y(start.y, Role::FinishContour);
        for m in &moves {
            path.go(m.motion, m.to, Role::FinishContour);
        }
        path.rapid_y(y_top.min(path.at.y), Role::Return);
        path.rapid_u(0, Role::Return);
        path.rapid_y(0, Role::Return);
    }
    path.rapid(local_of(&g, c.from), Role::Return);
    // R-G75RANGE: checked in move order, end point then arc centre.
    let mut out = Vec::with_capacity(path.moves.len());
    for m in &path.moves {
        let to = absolute(&g, m.to)?;
        let motion = match m.motion {
            LocalMotion::Rapid => Motion::Rapid,
            LocalMotion::Feed => Motion::Feed,
            LocalMotion::Arc { centre, clockwise } => {
                Motion::Arc { centre: absolute(&g, centre)?, clockwise }
            }
        };
        out.push(Move { motion, to, role: m.role, pass: None });
    }
    Ok(out)
}
