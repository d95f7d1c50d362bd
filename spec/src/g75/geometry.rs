//! The exact groove (`docs/G75.md` §2–§3): the local frame's points and
//! the cycle's words as exact reals ([`Groove`], [`groove`]), the
//! programmed profile's points (P1, P2, P3, the tangent points and centres
//! of the four corners) and the corner alarms ([`check_corners`]).
//!
//! Twin: the engine evaluates the same formulas over intervals in
//! `impl/src/engine/g75/exact.rs` (`Enclosures::new`, `Enclosures::eval`).
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use std::cmp::Ordering;

use cycleref::error::{CycleError, GrooveEdge};
use cycleref::g75::{corner, CornerKind, G75Cycle};

use crate::real::Real;

/// A point of the local frame (`docs/G75.md` §2) with exact coordinates.
#[derive(Clone, Debug)]
pub struct RealPoint {
    /// Axial distance from S in the direction `sz` (Z increments).
    pub u: Real,
    /// Radial depth below S in the direction `sx` (X-word increments).
    pub y: Real,
}

impl RealPoint {
    pub(super) fn new(u: Real, y: Real) -> RealPoint {
        RealPoint { u, y }
    }
}

/// A point of the local frame rounded to whole increments.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LocalPoint {
    /// Axial distance from S in the direction `sz` (Z increments).
    pub u: i128,
    /// Radial depth below S in the direction `sx` (X-word increments).
    pub y: i128,
}

impl LocalPoint {
    /// The point `(u, y)`.
    #[must_use]
    pub const fn new(u: i128, y: i128) -> LocalPoint {
        LocalPoint { u, y }
    }

    /// The point moved `w` towards `−u`: the tool's reference corner when
    /// its far corner is at `self` (R-G75TOOL: "every position on the far
    /// side … is the position of the far corner minus w").
    #[must_use]
    pub const fn less_tool(self, w: i128) -> LocalPoint {
        LocalPoint { u: self.u - w, y: self.y }
    }
}

/// The trigonometric values of the programmed angles (shared by every
/// formula, so each is enclosed once per precision).
#[derive(Clone, Debug)]
pub struct Angles {
    /// sin a.
    pub sin_a: Real,
    /// cos a.
    pub cos_a: Real,
    /// cot a.
    pub cot_a: Real,
    /// cot(a/2), the slope of the chord of corner r3.
    pub cot_half_a: Real,
    /// sin b.
    pub sin_b: Real,
    /// cos b.
    pub cos_b: Real,
    /// cot b.
    pub cot_b: Real,
    /// cot(b/2), the slope of the chord of corner r4.
    pub cot_half_b: Real,
    /// sin L.
    pub sin_l: Real,
    /// cos L.
    pub cos_l: Real,
    /// tan L.
    pub tan_l: Real,
}

/// The cycle's words in the local frame (`docs/G75.md` §2), as integers in
/// increments, with the trigonometric values and tangent lengths.
#[derive(Clone, Debug)]
pub struct Groove {
    /// The cycle.
    pub cycle: G75Cycle,
    /// `f`: X-word increments per radius increment (2 diameter, 1 radius).
    pub f: i128,
    /// `sx`: +1 when H > 0, −1 when H < 0.
    pub sx: i128,
    /// `sz`: +1 when D ≥ 0, −1 when D < 0.
    pub sz: i128,
    /// `Y = |H|` (X-word units).
    pub depth: i128,
    /// `d = |D|` (Z units).
    pub width: i128,
    /// `w`, the tool width (0 for a pointed tool).
    pub tool: i128,
    /// `Δi` (X-word units).
    pub peck: i128,
    /// `Δk` (Z units).
    pub step: i128,
    /// `e_x = f·e` (X-word units).
    pub retract: i128,
    /// `Δv` (X-word units), if programmed.
    pub layer: Option<i128>,
    /// `Δu` (X-word units).
    pub allowance_x: i128,
    /// `Δw` (Z units).
    pub allowance_z: i128,
    /// The angles' trigonometric values.
    pub angles: Angles,
    /// `t1..t4` indexed by [`corner`] (`t[corner::R1]` is t1 …).
    pub tangents: [Real; 4],
}

pub(super) fn int(v: i128) -> Real {
    Real::int(v)
}

/// The cycle's words in the local frame (`docs/G75.md` §2): "`Z = Z_S +
/// sz·u`, `X = X_S + sx·y`. `f` = X-word increments per radius increment
/// … Write `Y = |H|`, `d = |D|`, `w` = tool width (0 for a pointed tool),
/// `Δu`, `Δw`, `Δi`, `Δk`, `e_x = f·e`, `Δv`."
///
/// Angles in 0.0001° become multiples of 0.00005° (`2a`, and `a` for a/2).
///
/// # Panics
///
/// On a cycle that `validate()` refuses (an angle of 0 or beyond 90°):
/// call it on validated cycles only, as [`expand`](super::expand) and [`profile`](super::profile) do.
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Geometry::new` and `Enclosures::new`.
#[must_use]
pub fn groove(c: &G75Cycle) -> Groove {
    let (a, b, l) = (c.flank_a, c.flank_b, c.slope);
    let angles = Angles {
        sin_a: Real::sin(2 * a),
        cos_a: Real::cos(2 * a),
        cot_a: Real::cot(2 * a),
        cot_half_a: Real::cot(a),
        sin_b: Real::sin(2 * b),
        cos_b: Real::cos(2 * b),
        cot_b: Real::cot(2 * b),
        cot_half_b: Real::cot(b),
        sin_l: Real::sin(2 * l),
        cos_l: Real::cos(2 * l),
        tan_l: Real::tan(2 * l),
    };
    let f = i128::from(c.x_mode.factor());
    Groove {
        cycle: *c,
        f,
        sx: i128::from(c.radial_sign()),
        sz: i128::from(c.axial_sign()),
        depth: i128::from(c.depth).abs(),
        width: i128::from(c.width).abs(),
        tool: i128::from(c.width_of_tool()).abs(),
        peck: i128::from(c.peck),
        step: i128::from(c.step),
        retract: f * i128::from(c.retract),
        layer: c.layer.map(i128::from),
        allowance_x: i128::from(c.allowance_x),
        allowance_z: i128::from(c.allowance_z),
        tangents: [corner::R1, corner::R2, corner::R3, corner::R4].map(|i| tangent_length(c, i)),
        angles,
    }
}

/// `Y/f`: the depth as a radius length.
pub(super) fn depth_radius(g: &Groove) -> Real {
    Real::ratio(g.depth, g.f)
}

/// P1, the bottom corner on the start side: `P1 = ((Y/f)·cot a, Y)`.
///
/// R-G75PROFILE: "H(h): 凹槽深度, 凹槽内底到凹槽外底的相对距离" is measured at
/// S, so the inner bottom is at `y = Y`; "A(∠a): 啮合角 1, 邻近起点的腰与内底
/// (槽底) 形成的夹角" is the angle between flank A and the bottom, so flank
/// A runs from S to P1 with `du = (dy/f)·cot a`.
#[must_use]
pub fn p1(g: &Groove) -> RealPoint {
    RealPoint::new(depth_radius(g) * &g.angles.cot_a, int(g.depth))
}

/// P2, the bottom corner on the far side: `P2 = ((Y/f)·cot a + d, Y)`
/// ("D(d): 凹槽内底宽度, 凹槽槽底宽度"; note (2): "凹槽内底宽度是未使用倒角时
/// 实际的槽底宽度", the width between the virtual sharp corners).
#[must_use]
pub fn p2(g: &Groove) -> RealPoint {
    RealPoint::new(p1(g).u + int(g.width), int(g.depth))
}

/// `u3 = ((Y/f)·cot a + d + (Y/f)·cot b) / (1 − tan L·cot b)`: where
/// flank B ("B(∠b): 啮合角 2, 与起点不相邻的腰与内底 (槽底) 形成的夹角") meets
/// the slope of the opening ("L(∠p): 斜面的角度, 斜面与底边延长线形成的夹角").
///
/// R-G75SLOPE: the opening is the line through S rising (towards −y) in
/// the direction `sz` at angle L; `validate()` has made `L < B`, so the
/// denominator is positive.
#[must_use]
pub fn u3(g: &Groove) -> Real {
    let t = &g.angles;
    let num = p2(g).u + depth_radius(g) * &t.cot_b;
    if falls(g) {
        // R-G75SLOPE `falls-towards-d`: y = +f·u·tan L meets flank B at
        // u = P2.u + ((Y − y)/f)·cot b.
        num / (int(1) + &t.tan_l * &t.cot_b)
    } else {
        num / (int(1) - &t.tan_l * &t.cot_b)
    }
}

/// True under R-G75SLOPE `falls-towards-d`: the opening falls towards +y
/// in the direction `sz`.
pub(super) fn falls(g: &Groove) -> bool {
    g.cycle.readings.slope_falls_towards_d
}

/// `y3 = −f·u3·tan L`: the depth of P3, on the slope line through S
/// (R-G75SLOPE); 0 when L = 0.
#[must_use]
pub fn y3(g: &Groove) -> Real {
    let y = int(g.f) * u3(g) * &g.angles.tan_l;
    if falls(g) {
        y
    } else {
        -y
    }
}

/// P3 = (u3, y3), the far corner of the opening (外底另一端).
#[must_use]
pub fn p3(g: &Groove) -> RealPoint {
    RealPoint::new(u3(g), y3(g))
}

/// The tangent length `t` of a corner (`docs/G75.md` §3), in radius
/// increments: its size `c` for a chamfer (R-G75CHAMFER `equal-legs`,
/// equal legs along both edges from the virtual sharp corner, as `,C` on
/// G01; under `axial-width` `c / (cos θ1 + cos θ2)`, the legs of the
/// symmetric chamfer whose extent along Z is c:
///
/// | corner | t (chamfer, `axial-width`) |
/// |---|---|
/// | r1 (A) | `c / (cos a + cos L)` |
/// | r2 (B) | `c / (cos b + cos L)` |
/// | r3 (D) | `c / (1 + cos a)` |
/// | r4 (E) | `c / (1 + cos b)` |
///
/// ), and
/// `ρ·cot(φ/2)` for a round of radius ρ tangent to both edges:
///
/// | corner | t (round) |
/// |---|---|
/// | r1 (A) "外底起点处的倒棱宽度 … 或倒圆半径" | `ρ·tan((a+L)/2)` |
/// | r2 (B) "外底另一端的倒棱宽度 … 或倒圆半径" | `ρ·tan((b−L)/2)` |
/// | r3 (D) "内底靠近起点的倒棱宽度 … 或倒圆半径" | `ρ·tan(a/2)` |
/// | r4 (E) "内底远离起点（对角）倒棱宽度 … 或倒圆半径" | `ρ·tan(b/2)` |
///
/// "倒角的类型由 P 第一位决定, P 的第一位为 0 时, 倒角为直线倒角; 为 1 时, 倒角为
/// 圆弧倒角". A size of 0 ("未输入时默认不存在倒棱或倒圆") gives 0.
///
/// The half angles are multiples of 0.00005°: `(a+L)/2` is `a + L` of
/// them. `validate()` keeps every one of them in (0°, 90°).
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Enclosures::new` (`t1` … `t4`).
#[must_use]
pub fn tangent_length(c: &G75Cycle, index: usize) -> Real {
    let size = c.corners[index].size;
    let rho = Real::int(size);
    match c.corners[index].kind {
        // R-G75CHAMFER `axial-width`: the symmetric chamfer whose extent
        // along Z ("宽度") is c: its legs t run along edges at θ1, θ2 to the
        // Z axis, so its Z extent is t·(cos θ1 + cos θ2) (r1: flank A and
        // the surface before S, r2: flank B and the surface beyond P3, r3:
        // flank A and the bottom, r4: flank B and the bottom).
        CornerKind::Chamfer if size > 0 && c.readings.chamfer_axial_width => {
            let (first, second) = match index {
                corner::R1 => (c.flank_a, c.slope),
                corner::R2 => (c.flank_b, c.slope),
                corner::R3 => (c.flank_a, 0),
                _ => (c.flank_b, 0),
            };
            &rho / &(Real::cos(2 * first) + Real::cos(2 * second))
        }
        CornerKind::Chamfer => rho,
        CornerKind::Round if size == 0 => rho,
        CornerKind::Round => {
            // R-G75SLOPE: the surface beyond r1 and r2 falls towards D under
            // `falls-towards-d`, so their angles φ are 180° − (a − L) and
            // 180° − (b + L).
            let falls = c.readings.slope_falls_towards_d;
            let half = match index {
                corner::R1 if falls => c.flank_a - c.slope,
                corner::R2 if falls => c.flank_b + c.slope,
                corner::R1 => c.flank_a + c.slope,
                corner::R2 => c.flank_b - c.slope,
                corner::R3 => c.flank_a,
                _ => c.flank_b,
            };
            rho * Real::tan(half)
        }
    }
}

/// True when the corner has a feature (size > 0; then `t > 0`).
pub(super) fn has_corner(g: &Groove, index: usize) -> bool {
    g.cycle.corners[index].size > 0
}

/// `ρ`, the corner's size as a real (its round's radius).
pub(super) fn rho(g: &Groove, index: usize) -> Real {
    Real::int(g.cycle.corners[index].size)
}

/// `T1s = (−t1·cos L, f·t1·sin L)`: the tangent point of r1 on the surface
/// before S (the finishing start point F0 when r1 is programmed).
#[must_use]
pub fn t1s(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R1], &g.angles);
    let y = int(g.f) * t * &a.sin_l;
    // R-G75SLOPE: the surface before S lies above S's level when the
    // opening falls towards D: T1s = (−t1·cos L, −f·t1·sin L).
    RealPoint::new(-(t * &a.cos_l), if falls(g) { -y } else { y })
}

/// `T1a = (t1·cos a, f·t1·sin a)`: the tangent point of r1 on flank A.
#[must_use]
pub fn t1a(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R1], &g.angles);
    RealPoint::new(t * &a.cos_a, int(g.f) * t * &a.sin_a)
}

/// `C1 = T1a + ρ1·(−sin a, f·cos a)`: the centre of the round r1, in the
/// material beside flank A.
#[must_use]
pub fn c1(g: &Groove) -> RealPoint {
    let (p, r, a) = (t1a(g), rho(g, corner::R1), &g.angles);
    RealPoint::new(p.u - &r * &a.sin_a, p.y + int(g.f) * &r * &a.cos_a)
}

/// `T3a = ((Y/f)·cot a − t3·cos a, Y − f·t3·sin a)`: r3's tangent point on
/// flank A.
#[must_use]
pub fn t3a(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R3], &g.angles);
    RealPoint::new(p1(g).u - t * &a.cos_a, int(g.depth) - int(g.f) * t * &a.sin_a)
}

/// `T3b = ((Y/f)·cot a + t3, Y)`: r3's tangent point on the bottom.
#[must_use]
pub fn t3b(g: &Groove) -> RealPoint {
    RealPoint::new(p1(g).u + &g.tangents[corner::R3], int(g.depth))
}

/// `C3 = ((Y/f)·cot a + t3, Y − f·ρ3)`: the centre of the round r3, above
/// the bottom.
#[must_use]
pub fn c3(g: &Groove) -> RealPoint {
    RealPoint::new(t3b(g).u, int(g.depth) - int(g.f) * rho(g, corner::R3))
}

/// `T4b = ((Y/f)·cot a + d − t4, Y)`: r4's tangent point on the bottom.
#[must_use]
pub fn t4b(g: &Groove) -> RealPoint {
    RealPoint::new(p2(g).u - &g.tangents[corner::R4], int(g.depth))
}

/// `T4c = ((Y/f)·cot a + d + t4·cos b, Y − f·t4·sin b)`: r4's tangent point
/// on flank B.
#[must_use]
pub fn t4c(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R4], &g.angles);
    RealPoint::new(p2(g).u + t * &a.cos_b, int(g.depth) - int(g.f) * t * &a.sin_b)
}

/// `C4 = ((Y/f)·cot a + d − t4, Y − f·ρ4)`: the centre of the round r4.
#[must_use]
pub fn c4(g: &Groove) -> RealPoint {
    RealPoint::new(t4b(g).u, int(g.depth) - int(g.f) * rho(g, corner::R4))
}

/// `T2b = (u3 − t2·cos b, y3 + f·t2·sin b)`: r2's tangent point on flank B.
#[must_use]
pub fn t2b(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R2], &g.angles);
    RealPoint::new(u3(g) - t * &a.cos_b, y3(g) + int(g.f) * t * &a.sin_b)
}

/// `T2s = (u3 + t2·cos L, y3 − f·t2·sin L)`: r2's tangent point on the
/// surface beyond P3.
#[must_use]
pub fn t2s(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R2], &g.angles);
    let rise = int(g.f) * t * &a.sin_l;
    // R-G75SLOPE: beyond P3 the surface keeps falling when the opening
    // falls towards D: T2s = (u3 + t2·cos L, y3 + f·t2·sin L).
    RealPoint::new(u3(g) + t * &a.cos_l, if falls(g) { y3(g) + rise } else { y3(g) - rise })
}

/// `C2 = T2b + ρ2·(sin b, f·cos b)`: the centre of the round r2, in the
/// material beyond flank B.
#[must_use]
pub fn c2(g: &Groove) -> RealPoint {
    let (p, r, a) = (t2b(g), rho(g, corner::R2), &g.angles);
    RealPoint::new(p.u + &r * &a.sin_b, p.y + int(g.f) * &r * &a.cos_b)
}

/// A corner feature of the finishing profile in path order: from `start`
/// to `end`, around `centre` for a round.
#[derive(Clone, Debug)]
pub struct Feature {
    /// Chamfer or round.
    pub kind: CornerKind,
    /// Where the feature starts along the finishing path.
    pub start: RealPoint,
    /// Where it ends.
    pub end: RealPoint,
    /// The round's centre (`None` for a chamfer).
    pub centre: Option<RealPoint>,
}

/// The feature of corner `index` in the finishing path's direction (r1:
/// T1s → T1a, r3: T3a → T3b, r4: T4b → T4c, r2: T2b → T2s), or `None` for
/// a sharp corner.
#[must_use]
pub fn feature(g: &Groove, index: usize) -> Option<Feature> {
    if !has_corner(g, index) {
        return None;
    }
    let kind = g.cycle.corners[index].kind;
    let (start, end, centre) = match index {
        corner::R1 => (t1s(g), t1a(g), c1(g)),
        corner::R2 => (t2b(g), t2s(g), c2(g)),
        corner::R3 => (t3a(g), t3b(g), c3(g)),
        _ => (t4b(g), t4c(g), c4(g)),
    };
    let centre = (kind == CornerKind::Round).then_some(centre);
    Some(Feature { kind, start, end, centre })
}

/// The length of flank A from S to P1, `(Y/f)/sin a`.
#[must_use]
pub fn flank_a_length(g: &Groove) -> Real {
    depth_radius(g) / &g.angles.sin_a
}

/// The length of flank B from P2 to P3, `((Y − y3)/f)/sin b`.
#[must_use]
pub fn flank_b_length(g: &Groove) -> Real {
    (int(g.depth) - y3(g)) / int(g.f) / &g.angles.sin_b
}

/// Under R-G75SLOPE `falls-towards-d` first the opening, `y3 ≥ Y`
/// ([`CycleError::OpeningBelowBottom`]); then the corner alarms
/// (`docs/G75.md` §3), in this order:
/// `t1 + t3 > (Y/f)/sin a` (flank A), `t3 + t4 > d` (the bottom),
/// `t4 + t2 > ((Y − y3)/f)/sin b` (flank B): the corners may meet but not
/// overlap. Decided on exact values (§6).
///
/// # Errors
///
/// [`CycleError::CornerTooLarge`] with the first edge that is too short;
/// [`CycleError::UndecidedRounding`] when a comparison cannot be decided.
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Evaluator::check_corners`.
pub fn check_corners(g: &Groove) -> Result<(), CycleError> {
    // R-G75SLOPE `falls-towards-d`: the opening must meet flank B above the
    // bottom, `y3 < Y`, before the corners are measured on flank B.
    if falls(g) && y3(g).compare(&int(g.depth))? != Ordering::Less {
        return Err(CycleError::OpeningBelowBottom);
    }
    let t = &g.tangents;
    let checks = [
        (GrooveEdge::FlankA, &t[corner::R1] + &t[corner::R3], flank_a_length(g)),
        (GrooveEdge::Bottom, &t[corner::R3] + &t[corner::R4], int(g.width)),
        (GrooveEdge::FlankB, &t[corner::R4] + &t[corner::R2], flank_b_length(g)),
    ];
    for (edge, corners, length) in checks {
        if corners.compare(&length)? == Ordering::Greater {
            return Err(CycleError::CornerTooLarge { edge });
        }
    }
    Ok(())
}
