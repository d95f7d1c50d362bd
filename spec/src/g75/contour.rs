//! The two contours of `docs/G75.md` §8: the rough contour of step 9 (the
//! region's vertices rounded in) and the finishing contour of step 10 (the
//! programmed profile rounded to nearest, with the rounds' centres and
//! turning senses).
//!
//! Twin: `impl/src/engine/g75/contour.rs`, `rough_vertices` and
//! `finish_profile`; the turning sense `impl/src/engine/g75/frame.rs`,
//! `Frame::clockwise`.
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use std::cmp::Ordering;

use cycleref::error::CycleError;
use cycleref::g75::corner;

use super::*;

/// `R0 = (ceil(left(y_top)), y_top)`: where the rough contour starts, on
/// the start-side boundary of the roughing region at the layer top
/// (`docs/G75.md` §8: "rapid along Z to `R0 = (ceil(left(y_top)), y_top)`").
///
/// `left` is flank A (less Δw) unless the chord of r3 (less both
/// allowances) meets it above the layer top; then the chord bounds the
/// region over the whole depth and R0 lies on it ("When the moved chord
/// meets its flank above the layer top, the chord is the boundary over the
/// whole depth: R0 (R3) lies on it and K1 (K4) is not a vertex").
/// R-G75MAXMIN: `left(y_top)` is rounded as one value.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn r0(g: &Groove, y_top: i128) -> Result<LocalPoint, CycleError> {
    // R-G75MAXMIN: ceil of max(flankA_r, chord3_r) as one value.
    Ok(LocalPoint::new(ceil(&left(g, &int(y_top)))?, y_top))
}

/// `y_K1 = floor(Y − Δu − f·t3·sin a − Δu·cos a)`: the depth where flank A
/// (less Δw) meets the chord of r3 (less both allowances), rounded towards
/// the opening.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn y_k1(g: &Groove) -> Result<i128, CycleError> {
    let (t, a) = (&g.tangents[corner::R3], &g.angles);
    let du = int(g.allowance_x);
    floor(&(int(bottom_rough(g)) - int(g.f) * t * &a.sin_a - &du * &a.cos_a))
}

/// `K1 = (ceil(flankA_r(y_K1)), y_K1)`: the end of flank A on the rough
/// contour when r3 is programmed.
///
/// R-G75K1Y: "K1's u is taken on flank A at the integer y_K1, where flank A
/// is the active boundary, then rounded in": the formula of flankA_r is
/// evaluated exactly at the depth `y_K1` that K1 has (the rounded integer,
/// at or above the exact meeting point, so on flank A's side), and only
/// then rounded up. [`rough_vertices`] makes K1 a vertex only when
/// `y_K1 > y_top`.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn k1(g: &Groove) -> Result<LocalPoint, CycleError> {
    let y = y_k1(g)?;
    // R-G75K1Y: flankA_r at the integer y_K1 (exact), then ceil.
    Ok(LocalPoint::new(ceil(&flank_a_rough(g, &int(y)))?, y))
}

/// `K2 = (ceil((Y/f)·cot a + t3 + Δw), Y − Δu)`: where the chord of r3
/// (less the allowances) meets the roughing bottom.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn k2(g: &Groove) -> Result<LocalPoint, CycleError> {
    let u = p1(g).u + &g.tangents[corner::R3] + int(g.allowance_z);
    Ok(LocalPoint::new(ceil(&u)?, bottom_rough(g)))
}

/// `K3 = (floor((Y/f)·cot a + d − t4 − Δw) − w, Y − Δu)`: where the
/// roughing bottom meets the chord of r4.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn k3(g: &Groove) -> Result<LocalPoint, CycleError> {
    let u = p2(g).u - &g.tangents[corner::R4] - int(g.allowance_z);
    Ok(LocalPoint::new(floor(&u)? - g.tool, bottom_rough(g)))
}

/// `y_K4 = floor(Y − Δu − f·t4·sin b − Δu·cos b)`: the depth where the
/// chord of r4 meets flank B (less the allowances).
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn y_k4(g: &Groove) -> Result<i128, CycleError> {
    let (t, a) = (&g.tangents[corner::R4], &g.angles);
    let du = int(g.allowance_x);
    floor(&(int(bottom_rough(g)) - int(g.f) * t * &a.sin_b - &du * &a.cos_b))
}

/// `K4 = (floor(flankB_r(y_K4)) − w, y_K4)` (R-G75K1Y as for [`k1`]: flank
/// B at the integer `y_K4`); a vertex only when `y_K4 > y_top`.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn k4(g: &Groove) -> Result<LocalPoint, CycleError> {
    let y = y_k4(g)?;
    // R-G75K1Y: flankB_r at the integer y_K4 (exact), then floor, then − w.
    Ok(LocalPoint::new(floor(&flank_b_rough(g, &int(y)))? - g.tool, y))
}

/// `Q1 = (ceil(flankA_r(Y − Δu)), Y − Δu)`: the bottom corner of the rough
/// contour on the start side without r3.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn q1(g: &Groove) -> Result<LocalPoint, CycleError> {
    let y = bottom_rough(g);
    Ok(LocalPoint::new(ceil(&flank_a_rough(g, &int(y)))?, y))
}

/// `Q2 = (floor(flankB_r(Y − Δu)) − w, Y − Δu)`: the bottom corner of the
/// rough contour on the far side without r4.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn q2(g: &Groove) -> Result<LocalPoint, CycleError> {
    let y = bottom_rough(g);
    Ok(LocalPoint::new(floor(&flank_b_rough(g, &int(y)))? - g.tool, y))
}

/// `R3 = (floor(right(y_top)) − w, y_top)`: where the rough contour ends,
/// on the far-side boundary of the roughing region at the layer top (flank
/// B less Δw, or the chord of r4 less both allowances when it meets flank
/// B above the layer top), as [`r0`]. R-G75MAXMIN: `right(y_top)` is
/// rounded as one value.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn r3(g: &Groove, y_top: i128) -> Result<LocalPoint, CycleError> {
    // R-G75MAXMIN: floor of min(flankB_r, chord4_r) as one value, then − w.
    Ok(LocalPoint::new(floor(&right(g, &int(y_top)))? - g.tool, y_top))
}

/// A vertex of the rough contour before the tool width is subtracted:
/// `far` for the vertices on the far side (K3, K4, Q2, R3), whose tool
/// position is the vertex less w (R-G75TOOL).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RoughVertex {
    /// The vertex, rounded into the region, without the tool width.
    pub at: LocalPoint,
    /// On the far side: the tool's reference corner is at `at.u − w`.
    pub far: bool,
}

/// The vertices of the roughing region that the rough contour visits
/// (`docs/G75.md` §8 step 9), in order, without the tool width: R0; K1
/// (only when t3 > 0 and `y_K1 > y_top`) and K2 when t3 > 0, or Q1; K3 and
/// K4 (only when t4 > 0 and `y_K4 > y_top`) when t4 > 0, or Q2; R3.
///
/// "feed to `K1` (only when `y_K1 > y_top`) then `K2` (or to `Q1` … when
/// t3 = 0); feed to `K3` then `K4` (only when `y_K4 > y_top`) (or `Q2` …
/// when t4 = 0)": when the moved chord meets its flank at or above the
/// layer top, the chord bounds the region down from R0 (R3) and K1 (K4)
/// is no vertex. `y_K1` (`y_K4`) is still decided, in the order of
/// R-G75DECIDE (R0, y_K1, K1, K2 or Q1, K3, y_K4, K4 or Q2, R3).
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
///
/// Twin: `impl/src/engine/g75/contour.rs`, `rough_vertices`.
pub fn rough_vertices(g: &Groove, y_top: i128) -> Result<Vec<RoughVertex>, CycleError> {
    let near = |at: LocalPoint| RoughVertex { at, far: false };
    // The far-side functions subtract w; the vertex is the point before.
    let far = |at: LocalPoint| RoughVertex { at: LocalPoint::new(at.u + g.tool, at.y), far: true };
    let mut points = vec![near(r0(g, y_top)?)];
    if has_corner(g, corner::R3) {
        // K1 is a vertex only below the layer top (docs/G75.md §8).
        if y_k1(g)? > y_top {
            points.push(near(k1(g)?));
        }
        points.push(near(k2(g)?));
    } else {
        points.push(near(q1(g)?));
    }
    if has_corner(g, corner::R4) {
        points.push(far(k3(g)?));
        // K4 is a vertex only below the layer top (docs/G75.md §8).
        if y_k4(g)? > y_top {
            points.push(far(k4(g)?));
        }
    } else {
        points.push(far(q2(g)?));
    }
    points.push(far(r3(g, y_top)?));
    Ok(points)
}

/// The feed points of the rough contour (step ⑨: "刀具沿着粗车轨迹轮廓切削"),
/// in order, as tool positions (far-side vertices less w): R0, then K1 (if
/// `y_K1 > y_top`), K2 (or Q1 without r3), then K3, K4 (if
/// `y_K4 > y_top`) (or Q2 without r4), then R3 ([`rough_vertices`]).
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn rough_contour(g: &Groove, y_top: i128) -> Result<Vec<LocalPoint>, CycleError> {
    let vertices = rough_vertices(g, y_top)?;
    Ok(vertices.iter().map(|v| if v.far { v.at.less_tool(g.tool) } else { v.at }).collect())
}

/// How the tool moves to a point, in the local frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LocalMotion {
    /// G00.
    Rapid,
    /// G01.
    Feed,
    /// G02 (`clockwise`) or G03 around `centre`.
    Arc {
        /// The centre, rounded to nearest (less w on the far side).
        centre: LocalPoint,
        /// G02 (R-G75ARC).
        clockwise: bool,
    },
}

/// R-G75ARC: whether the round from `start` to `end` around `centre` turns
/// clockwise "seen with +Z to the right and +X up": the cross product of
/// `(start − centre)` and `(end − centre)` in (Z, X as a radius)
/// coordinates is negative. Decided from the exact geometry, not from the
/// rounded points. In the local frame `Z = sz·u`, `X = sx·y/f`, so the
/// cross product is `sz·sx/f` times the local one.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`] (never for a real round: its cross
/// product is `±ρ²` times the sine of an angle in (0°, 180°)).
///
/// Twin: `impl/src/engine/g75/frame.rs`, `Frame::clockwise`.
pub fn clockwise(
    g: &Groove,
    start: &RealPoint,
    end: &RealPoint,
    centre: &RealPoint,
) -> Result<bool, CycleError> {
    let (su, sy) = (&start.u - &centre.u, &start.y - &centre.y);
    let (eu, ey) = (&end.u - &centre.u, &end.y - &centre.y);
    let local = (su * ey - sy * eu).sign()?;
    let negative = match local {
        Ordering::Less => g.sz * g.sx > 0,
        Ordering::Greater => g.sz * g.sx < 0,
        Ordering::Equal => false,
    };
    Ok(negative)
}

/// One move of the finishing contour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ContourMove {
    /// Feed or arc.
    pub motion: LocalMotion,
    /// The end point.
    pub to: LocalPoint,
}

/// The finishing contour (step ⑩: "刀具沿着精车轨迹轮廓切削"): its start F0
/// (T1s, or S without r1) and its moves: r1 (T1s → T1a), flank A to T3a (or
/// P1), r3 (→ T3b), the bottom to T4b − w (or P2 − w), r4 (→ T4c − w),
/// flank B to T2b − w (or P3 − w), r2 (→ T2s − w). Every point and centre
/// is rounded to nearest; on the far side the tool width is then
/// subtracted (R-G75TOOL). A chamfer is a feed, a round an arc.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
///
/// Twin: `impl/src/engine/g75/contour.rs`, `finish_profile`.
pub fn finish_contour(g: &Groove) -> Result<(LocalPoint, Vec<ContourMove>), CycleError> {
    let w = g.tool;
    let mut moves = Vec::new();
    let corner_move = |index: usize, shift: i128, moves: &mut Vec<ContourMove>| -> Result<(), CycleError> {
        if let Some(feat) = feature(g, index) {
            let to = round_nearest(&feat.end)?.less_tool(shift);
            let motion = match &feat.centre {
                None => LocalMotion::Feed,
                Some(centre) => LocalMotion::Arc {
                    centre: round_nearest(centre)?.less_tool(shift),
                    clockwise: clockwise(g, &feat.start, &feat.end, centre)?,
                },
            };
            moves.push(ContourMove { motion, to });
        }
        Ok(())
    };
    let feed = |p: &RealPoint, shift: i128| -> Result<ContourMove, CycleError> {
        Ok(ContourMove { motion: LocalMotion::Feed, to: round_nearest(p)?.less_tool(shift) })
    };
    let start = if has_corner(g, corner::R1) { round_nearest(&t1s(g))? } else { LocalPoint::new(0, 0) };
    corner_move(corner::R1, 0, &mut moves)?;
    moves.push(feed(&if has_corner(g, corner::R3) { t3a(g) } else { p1(g) }, 0)?);
    corner_move(corner::R3, 0, &mut moves)?;
    moves.push(feed(&if has_corner(g, corner::R4) { t4b(g) } else { p2(g) }, w)?);
    corner_move(corner::R4, w, &mut moves)?;
    moves.push(feed(&if has_corner(g, corner::R2) { t2b(g) } else { p3(g) }, w)?);
    corner_move(corner::R2, w, &mut moves)?;
    Ok((start, moves))
}
