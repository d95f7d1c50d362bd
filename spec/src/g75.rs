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
//! sign, `y` the depth below S in X-word units) as exact [`Real`] numbers,
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

use std::cmp::Ordering;

use cycleref::error::{CycleError, Field, GrooveEdge};
use cycleref::g75::{corner, CornerKind, G75Cycle, MAX_PECKS};
use cycleref::moves::{Motion, Move, Plunge, Role};
use cycleref::units::{Length, Point, MAX_LENGTH};
use num_bigint::BigInt;

use crate::real::{saturating_i128, Real};

/// A point of the local frame (`docs/G75.md` §2) with exact coordinates.
#[derive(Clone, Debug)]
pub struct RealPoint {
    /// Axial distance from S in the direction `sz` (Z increments).
    pub u: Real,
    /// Radial depth below S in the direction `sx` (X-word increments).
    pub y: Real,
}

impl RealPoint {
    fn new(u: Real, y: Real) -> RealPoint {
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

fn int(v: i128) -> Real {
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
/// call it on validated cycles only, as [`expand`] and [`profile`] do.
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

// ---------------------------------------------------------------------------
// §3 The programmed profile.
// ---------------------------------------------------------------------------

/// `Y/f`: the depth as a radius length.
fn depth_radius(g: &Groove) -> Real {
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
    num / (int(1) - &t.tan_l * &t.cot_b)
}

/// `y3 = −f·u3·tan L`: the depth of P3, on the slope line through S
/// (R-G75SLOPE); 0 when L = 0.
#[must_use]
pub fn y3(g: &Groove) -> Real {
    -(int(g.f) * u3(g) * &g.angles.tan_l)
}

/// P3 = (u3, y3), the far corner of the opening (外底另一端).
#[must_use]
pub fn p3(g: &Groove) -> RealPoint {
    RealPoint::new(u3(g), y3(g))
}

/// The tangent length `t` of a corner (`docs/G75.md` §3), in radius
/// increments: its size `c` for a chamfer (R-G75CHAMFER, equal legs along
/// both edges from the virtual sharp corner, as `,C` on G01), and
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
#[must_use]
pub fn tangent_length(c: &G75Cycle, index: usize) -> Real {
    let size = c.corners[index].size;
    let rho = Real::int(size);
    match c.corners[index].kind {
        CornerKind::Chamfer => rho,
        CornerKind::Round if size == 0 => rho,
        CornerKind::Round => {
            let half = match index {
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
fn has_corner(g: &Groove, index: usize) -> bool {
    g.cycle.corners[index].size > 0
}

/// `ρ`, the corner's size as a real (its round's radius).
fn rho(g: &Groove, index: usize) -> Real {
    Real::int(g.cycle.corners[index].size)
}

/// `T1s = (−t1·cos L, f·t1·sin L)`: the tangent point of r1 on the surface
/// before S (the finishing start point F0 when r1 is programmed).
#[must_use]
pub fn t1s(g: &Groove) -> RealPoint {
    let (t, a) = (&g.tangents[corner::R1], &g.angles);
    RealPoint::new(-(t * &a.cos_l), int(g.f) * t * &a.sin_l)
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
    RealPoint::new(u3(g) + t * &a.cos_l, y3(g) - int(g.f) * t * &a.sin_l)
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

/// The corner alarms (`docs/G75.md` §3), in this order:
/// `t1 + t3 > (Y/f)/sin a` (flank A), `t3 + t4 > d` (the bottom),
/// `t4 + t2 > ((Y − y3)/f)/sin b` (flank B): the corners may meet but not
/// overlap. Decided on exact values (§6).
///
/// # Errors
///
/// [`CycleError::CornerTooLarge`] with the first edge that is too short;
/// [`CycleError::UndecidedRounding`] when a comparison cannot be decided.
pub fn check_corners(g: &Groove) -> Result<(), CycleError> {
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

// ---------------------------------------------------------------------------
// §5 The roughing profile.
// ---------------------------------------------------------------------------

/// `flankA_r(y) = (y/f)·cot a + Δw` (`u ≥` this): flank A moved into the
/// groove by the Z allowance ("W(Δw): Z 轴的精加工余量", R-G75ROUGH).
#[must_use]
pub fn flank_a_rough(g: &Groove, y: &Real) -> Real {
    y / int(g.f) * &g.angles.cot_a + int(g.allowance_z)
}

/// `flankB_r(y) = (Y/f)·cot a + d + ((Y − y)/f)·cot b − Δw` (`u ≤` this):
/// flank B moved into the groove by Δw (R-G75ROUGH).
#[must_use]
pub fn flank_b_rough(g: &Groove, y: &Real) -> Real {
    p2(g).u + (int(g.depth) - y) / int(g.f) * &g.angles.cot_b - int(g.allowance_z)
}

/// `bottom_r = Y − Δu` (`y ≤` this): the bottom moved up by the X allowance
/// ("U(Δu): X 轴的精加工余量", R-G75ROUGH). `validate()` has made it > 0.
#[must_use]
pub fn bottom_rough(g: &Groove) -> i128 {
    g.depth - g.allowance_x
}

/// `chord3_r(y) = (Y/f)·cot a + t3 + Δw − ((Y − Δu − y)/f)·cot(a/2)`
/// (`u ≥` this, only when t3 > 0): the chord T3a–T3b of corner r3 moved by
/// both allowances (R-G75ROUGH: "a bottom corner feature (r3, r4) is kept by
/// its chord … moved by both allowances").
#[must_use]
pub fn chord3_rough(g: &Groove, y: &Real) -> Option<Real> {
    if !has_corner(g, corner::R3) {
        return None;
    }
    let rise = (int(bottom_rough(g)) - y) / int(g.f) * &g.angles.cot_half_a;
    Some(p1(g).u + &g.tangents[corner::R3] + int(g.allowance_z) - rise)
}

/// `chord4_r(y) = (Y/f)·cot a + d − t4 − Δw + ((Y − Δu − y)/f)·cot(b/2)`
/// (`u ≤` this, only when t4 > 0): the chord T4b–T4c of corner r4 moved by
/// both allowances (R-G75ROUGH).
#[must_use]
pub fn chord4_rough(g: &Groove, y: &Real) -> Option<Real> {
    if !has_corner(g, corner::R4) {
        return None;
    }
    let rise = (int(bottom_rough(g)) - y) / int(g.f) * &g.angles.cot_half_b;
    Some(p2(g).u - &g.tangents[corner::R4] - int(g.allowance_z) + rise)
}

/// `left(y) = max(flankA_r(y), chord3_r(y))`: the start-side boundary of
/// the roughing region at depth `y`.
///
/// R-G75MAXMIN: the maximum is itself a real number whose enclosure is
/// the interval extension of max; it is rounded as one value, so its
/// rounding never waits for the comparison of the two branches (which may
/// be exactly equal, e.g. at a layer bottom on the corner of the two
/// lines); `ceil(max(p, q)) = max(ceil p, ceil q)` in any case.
#[must_use]
pub fn left(g: &Groove, y: &Real) -> Real {
    let flank = flank_a_rough(g, y);
    // R-G75MAXMIN: max as one real (interval max), never a decided comparison.
    match chord3_rough(g, y) {
        Some(chord) => flank.max(&chord),
        None => flank,
    }
}

/// `right(y) = min(flankB_r(y), chord4_r(y))`: the far-side boundary of
/// the roughing region at depth `y` (R-G75MAXMIN as [`left`]).
#[must_use]
pub fn right(g: &Groove, y: &Real) -> Real {
    let flank = flank_b_rough(g, y);
    // R-G75MAXMIN: min as one real (interval min), never a decided comparison.
    match chord4_rough(g, y) {
        Some(chord) => flank.min(&chord),
        None => flank,
    }
}

// ---------------------------------------------------------------------------
// §6 Rounding.
// ---------------------------------------------------------------------------

fn to_i128(v: &BigInt) -> i128 {
    saturating_i128(v)
}

/// Nearest: `floor(v + 1/2)` (ties towards +u / +y).
fn nearest(v: &Real) -> Result<i128, CycleError> {
    v.nearest().map(|b| to_i128(&b))
}

/// In, on the start side: `ceil(v)`.
fn ceil(v: &Real) -> Result<i128, CycleError> {
    v.ceil().map(|b| to_i128(&b))
}

/// In, on the far side and for the depths: `floor(v)`.
fn floor(v: &Real) -> Result<i128, CycleError> {
    v.floor().map(|b| to_i128(&b))
}

/// A profile point rounded to nearest (`docs/G75.md` §6: "all finishing
/// points and centres, P3").
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn round_nearest(p: &RealPoint) -> Result<LocalPoint, CycleError> {
    Ok(LocalPoint::new(nearest(&p.u)?, nearest(&p.y)?))
}

// ---------------------------------------------------------------------------
// §7 Layers and plunges.
// ---------------------------------------------------------------------------

/// `y_top = floor(y3)`: the top of layer 1, the highest point of the
/// opening (≤ 0; 0 when L = 0), so that every plunge of layer 1 starts in
/// the air (R-G75LAYER).
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn y_top(g: &Groove) -> Result<i128, CycleError> {
    floor(&y3(g))
}

/// `M = ceil((Y − Δu)/Δv)`, or 1 without V (R-G75LAYER; "V(Δv): 径向切深时
/// 的安全距离 … 单次切削循环时的最大允许切深距离 (分层次进行切削, 单层最大深度) …
/// 未输入时默认为断续切削到凹槽最大深度 (不分层, 走刀方式与 G75 类似)").
#[must_use]
pub fn layer_count(g: &Groove) -> i128 {
    match g.layer {
        Some(v) => (bottom_rough(g) + v - 1) / v,
        None => 1,
    }
}

/// `y_m = min(m·Δv, Y − Δu)`, the bottom of layer `m` (1-based); `Y − Δu`
/// without V (R-G75LAYER).
#[must_use]
pub fn layer_bottom(g: &Groove, m: i128) -> i128 {
    match g.layer {
        Some(v) => (m.saturating_mul(v)).min(bottom_rough(g)),
        None => bottom_rough(g),
    }
}

/// The top of layer `m`: `y_top` for layer 1, `y_(m−1)` after (R-G75LAYER:
/// "Layer m ≥ 2 starts at `y_{m−1}`").
#[must_use]
pub fn layer_top(g: &Groove, m: i128, y_top: i128) -> i128 {
    if m <= 1 {
        y_top
    } else {
        layer_bottom(g, m - 1)
    }
}

/// The plunge positions of a layer: from `first` (`A_m1`) to `last`
/// (`A_mf`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PlungeRange {
    /// `A_m1 = ceil(left(y_m))`.
    pub first: i128,
    /// `A_mf = floor(right(y_m)) − w`.
    pub last: i128,
}

impl PlungeRange {
    /// The number of plunges: `A_m1`, `A_m1 + Δk`, … while `< A_mf`, then
    /// `A_mf`: `ceil((A_mf − A_m1)/Δk) + 1` (one when `A_m1 = A_mf`).
    /// Requires `first ≤ last`.
    #[must_use]
    pub fn count(&self, step: i128) -> i128 {
        (self.last - self.first + step - 1) / step + 1
    }

    /// The position of plunge `n` (1-based, `n ≤ count`): `A_m1 + (n − 1)Δk`,
    /// and `A_mf` for the last.
    #[must_use]
    pub fn position(&self, step: i128, n: i128) -> i128 {
        if n >= self.count(step) {
            self.last
        } else {
            self.first + (n - 1) * step
        }
    }
}

/// The plunge range of layer `m` (R-G75PLUNGE): "the tool fits with its
/// whole width at the layer's bottom `y_m`: `A_m1 = ceil(left(y_m))`,
/// `A_mf = floor(right(y_m)) − w`" (step ⑦: "Amf 点(此层最后一次轴向切削循环
/// 起点)").
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
pub fn plunge_range(g: &Groove, m: i128) -> Result<PlungeRange, CycleError> {
    let y = int(layer_bottom(g, m));
    Ok(PlungeRange { first: ceil(&left(g, &y))?, last: floor(&right(g, &y))? - g.tool })
}

/// The alarm `GrooveNarrowerThanTool` (R-G75PLUNGE): `A_mf < A_m1`, checked
/// on the last layer (the region narrows with depth, so no other layer is
/// narrower). Returns the last layer's range.
///
/// R-G75NARROWJ: checked whatever J is: A11, the approach point of every
/// path (step ①, also for J2), is a plunge position of layer 1, which is
/// no narrower than the last.
///
/// # Errors
///
/// [`CycleError::GrooveNarrowerThanTool`]; [`CycleError::UndecidedRounding`].
pub fn check_tool_fits(g: &Groove) -> Result<PlungeRange, CycleError> {
    // R-G75NARROWJ: for every J, J2 included.
    let range = plunge_range(g, layer_count(g))?;
    if range.last < range.first {
        let w = i64::try_from(g.tool).unwrap_or(i64::MAX);
        return Err(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(w, g.cycle.units) });
    }
    Ok(range)
}

/// The alarm `RidgesInLayers` (R-G75RIDGE): when the cycle roughs (J0, J1)
/// in more than one layer, "Z 轴快速移动进刀 Δk" (step ⑦) runs at the top of
/// each layer m ≥ 2, the bottom of layer m − 1, and step ② moves down into
/// layer m − 1 at `A_m1`. Those rapids cross only cut space when layer
/// m − 1's plunges cut it without gaps, that is when no two neighbouring
/// plunges are more than the tool width `w` apart. Their distances are Δk
/// and, last, at most Δk, and layer 1's range is the widest (the region
/// narrows with depth), so: refused when `M ≥ 2`, `Δk > w` and layer 1's
/// range `A_1f − A_11 > w` (then its first two plunges are more than `w`
/// apart and leave a ridge). A pointed tool (w = 0) in layers is thus
/// refused unless layer 1 is a single plunge position. The check is
/// conservative: a layer 2 whose rapids happen to miss every ridge is
/// refused too.
///
/// # Errors
///
/// [`CycleError::RidgesInLayers`]; [`CycleError::UndecidedRounding`].
pub fn check_ridges(g: &Groove) -> Result<(), CycleError> {
    let c = &g.cycle;
    if !c.path.roughs() || layer_count(g) < 2 || i128::from(c.step) <= g.tool {
        return Ok(());
    }
    let range = plunge_range(g, 1)?;
    if range.last - range.first > g.tool {
        let w = i64::try_from(g.tool).unwrap_or(i64::MAX);
        return Err(CycleError::RidgesInLayers {
            step: Length::new(c.step, c.units),
            tool_width: Length::new(w, c.units),
        });
    }
    Ok(())
}

/// The number of pecks of one plunge from `top` to `bottom`:
/// `ceil((bottom − top)/Δi)` (R-G75PECK: peck j feeds to
/// `min(top + j·Δi, bottom)`).
#[must_use]
pub fn peck_count(top: i128, bottom: i128, peck: i128) -> i128 {
    (bottom - top + peck - 1) / peck
}

/// One peck: a feed to `to`, then (if it did not reach the bottom and
/// e > 0) a rapid retract to `retract`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Peck {
    /// The peck's end depth, `min(top + j·Δi, bottom)`.
    pub to: i128,
    /// The retract depth `max(top, to − e_x)` after a peck that did not
    /// reach the bottom (`None` after the last peck, and when e = 0).
    pub retract: Option<i128>,
}

/// The pecks of one plunge from `top` to `bottom` (R-G75PECK), from the
/// manual's steps:
///
/// * ③ "从径向切削循环起点 Amn 径向(X 轴)切削进给 Δi/2";
/// * ④ "径向(X 轴)快速移动退刀 e，退刀方向与③进给方向相反";
/// * ⑤ "如果 X 轴再次切削进给(Δi/2+e)，进给终点仍在径向切削循环起点 Amn 与径向
///   进刀终点 Bmn 之间，X 轴再次切削进给(Δi/2+e)，然后执行④；… X 轴切削进给至
///   Bmn 点，然后执行⑥".
///
/// Peck j (1-based) feeds to `min(top + j·Δi, bottom)`; after every peck
/// that did not reach the bottom the tool retracts at rapid to
/// `max(top, end − e_x)` (no retract when e = 0), so every peck takes at
/// most Δi (Δi/2 of radius) of new depth. Step ⑥ (the retract to Amn) is
/// the caller's.
#[must_use]
pub fn pecks(g: &Groove, top: i128, bottom: i128) -> Vec<Peck> {
    let mut out = Vec::new();
    let mut j = 1_i128;
    loop {
        let to = (top + j * g.peck).min(bottom);
        if to >= bottom {
            out.push(Peck { to: bottom, retract: None });
            return out;
        }
        let retract = (g.retract > 0).then(|| top.max(to - g.retract));
        out.push(Peck { to, retract });
        j += 1;
    }
}

/// One layer of the roughing plan.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Layer {
    /// `m`, 1-based.
    pub number: i128,
    /// Where its plunges start (`y_top` or `y_(m−1)`).
    pub top: i128,
    /// `y_m`.
    pub bottom: i128,
    /// Its plunge positions.
    pub range: PlungeRange,
}

/// The roughing layers, after the closed-form count of their pecks
/// (`docs/G75.md` §9): `Σ_m (plunges of m) × ceil((y_m − top_m)/Δi)`,
/// refused when above [`MAX_PECKS`]. Every layer has at least one peck, so
/// more layers than the limit are refused at once.
///
/// R-G75PECKJ2: only a cycle that roughs (J0, J1) makes pecks; J2 has none
/// and is never refused for them (and this is not called for it).
///
/// # Errors
///
/// [`CycleError::TooManyPecks`]; [`CycleError::UndecidedRounding`].
pub fn rough_layers(g: &Groove, y_top: i128) -> Result<Vec<Layer>, CycleError> {
    let too_many = CycleError::TooManyPecks { limit: MAX_PECKS };
    let count = layer_count(g);
    let limit = i128::from(MAX_PECKS);
    // R-G75PECKJ2: called for J0 and J1 only. Every layer has a peck, so
    // more layers than the limit are refused before any range is rounded.
    if count > limit {
        return Err(too_many);
    }
    let mut total = 0_i128;
    let mut layers = Vec::new();
    for m in 1..=count {
        let (top, bottom) = (layer_top(g, m, y_top), layer_bottom(g, m));
        let range = plunge_range(g, m)?;
        let n = range.count(g.step).min(limit + 1);
        let p = peck_count(top, bottom, g.peck).min(limit + 1);
        total += n * p;
        if total > limit {
            return Err(too_many);
        }
        layers.push(Layer { number: m, top, bottom, range });
    }
    Ok(layers)
}

// ---------------------------------------------------------------------------
// §8 Step 9: the rough contour.
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// §8 Step 10: the finishing contour.
// ---------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------
// The profile, for tests.
// ---------------------------------------------------------------------------

/// A profile point, exact and rounded to nearest (local frame, without the
/// tool width).
#[derive(Clone, Debug)]
pub struct ProfilePoint {
    /// The exact point.
    pub exact: RealPoint,
    /// `floor(v + 1/2)` of each coordinate.
    pub rounded: LocalPoint,
}

impl ProfilePoint {
    fn of(p: RealPoint) -> Result<ProfilePoint, CycleError> {
        let rounded = round_nearest(&p)?;
        Ok(ProfilePoint { exact: p, rounded })
    }
}

/// A corner feature of the profile.
#[derive(Clone, Debug)]
pub struct CornerProfile {
    /// Chamfer or round.
    pub kind: CornerKind,
    /// Its tangent length `t` (radius increments).
    pub tangent: Real,
    /// Its first point along the finishing path.
    pub start: ProfilePoint,
    /// Its last point along the finishing path.
    pub end: ProfilePoint,
    /// A round's centre.
    pub centre: Option<ProfilePoint>,
    /// A round's direction: G02 when true (R-G75ARC).
    pub clockwise: Option<bool>,
}

/// The programmed (finishing) profile of a cycle (`docs/G75.md` §3), in
/// the local frame, without the tool width.
#[derive(Clone, Debug)]
pub struct Profile {
    /// S, the origin.
    pub s: ProfilePoint,
    /// P1, bottom corner on the start side.
    pub p1: ProfilePoint,
    /// P2, bottom corner on the far side.
    pub p2: ProfilePoint,
    /// P3, far corner of the opening.
    pub p3: ProfilePoint,
    /// The corner features indexed by [`corner`] (`None`: sharp).
    pub corners: [Option<CornerProfile>; 4],
    /// `floor(y3)`.
    pub y_top: i128,
    /// The vertices of the roughing region the rough contour visits
    /// ([`rough_vertices`]), without the tool width: R0 =
    /// `(ceil(left(y_top)), y_top)`, K1 (when t3 > 0 and `y_K1 > y_top`),
    /// K2 (or Q1), K3 (or Q2), K4 (when t4 > 0 and `y_K4 > y_top`), R3 =
    /// `(floor(right(y_top)), y_top)`.
    pub rough: Vec<RoughVertex>,
}

/// The profile of a cycle, exact and rounded, after `validate()` and the
/// corner alarms, with the rough contour's vertices (`docs/G75.md` §8 step
/// 9) whatever J is.
///
/// # Errors
///
/// As [`expand`], up to the corner alarms; the alarms of the roughing path
/// (groove narrower than the tool, too many pecks) are not checked.
pub fn profile(c: &G75Cycle) -> Result<Profile, CycleError> {
    c.validate()?;
    let g = groove(c);
    check_corners(&g)?;
    let mut corners: [Option<CornerProfile>; 4] = [None, None, None, None];
    for (index, slot) in corners.iter_mut().enumerate() {
        if let Some(feat) = feature(&g, index) {
            let clockwise = match &feat.centre {
                Some(centre) => Some(clockwise(&g, &feat.start, &feat.end, centre)?),
                None => None,
            };
            *slot = Some(CornerProfile {
                kind: feat.kind,
                tangent: g.tangents[index].clone(),
                start: ProfilePoint::of(feat.start)?,
                end: ProfilePoint::of(feat.end)?,
                centre: feat.centre.map(ProfilePoint::of).transpose()?,
                clockwise,
            });
        }
    }
    let (s, p1, p2, p3) = (
        ProfilePoint::of(RealPoint::new(int(0), int(0)))?,
        ProfilePoint::of(p1(&g))?,
        ProfilePoint::of(p2(&g))?,
        ProfilePoint::of(p3(&g))?,
    );
    let y_top = y_top(&g)?;
    let rough = rough_vertices(&g, y_top)?;
    Ok(Profile { s, p1, p2, p3, corners, y_top, rough })
}

// ---------------------------------------------------------------------------
// §8 The moves.
// ---------------------------------------------------------------------------

/// A move in the local frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct LocalMove {
    motion: LocalMotion,
    to: LocalPoint,
    role: Role,
}

/// The tool path being built: the current position and the moves.
struct Path {
    at: LocalPoint,
    moves: Vec<LocalMove>,
}

impl Path {
    /// Appends a move unless it ends where the tool is (R-G75ZERO: "No move
    /// is emitted whose end is the current position"; R-G75ARCZERO: also an
    /// arc whose rounded end is its rounded start).
    fn go(&mut self, motion: LocalMotion, to: LocalPoint, role: Role) {
        // R-G75ZERO, R-G75ARCZERO: arcs are dropped like any empty move.
        if to == self.at {
            return;
        }
        self.at = to;
        self.moves.push(LocalMove { motion, to, role });
    }

    fn rapid(&mut self, to: LocalPoint, role: Role) {
        self.go(LocalMotion::Rapid, to, role);
    }

    /// A rapid along Z (u) to `u`, the depth kept.
    fn rapid_u(&mut self, u: i128, role: Role) {
        self.rapid(LocalPoint::new(u, self.at.y), role);
    }

    /// A rapid along X (y) to `y`, the axial position kept.
    fn rapid_y(&mut self, y: i128, role: Role) {
        self.rapid(LocalPoint::new(self.at.u, y), role);
    }
}

/// `from`, the tool position before the cycle, in the local frame.
fn local_of(g: &Groove, p: Point) -> LocalPoint {
    let (s, x, z) = (g.cycle.start, i128::from(p.x), i128::from(p.z));
    LocalPoint::new(g.sz * (z - i128::from(s.z)), g.sx * (x - i128::from(s.x)))
}

/// A local point in absolute X/Z (`docs/G75.md` §2: `Z = Z_S + sz·u`,
/// `X = X_S + sx·y`), X checked first, then Z.
///
/// R-G75RANGE: a coordinate beyond ±[`MAX_LENGTH`] is refused with
/// `OutOfRange { field: PassCoordinate, value }`, `value` the coordinate
/// (saturated to the `i64` range if it lies beyond it).
fn absolute(g: &Groove, p: LocalPoint) -> Result<Point, CycleError> {
    let s = g.cycle.start;
    let x = i128::from(s.x).saturating_add(g.sx.saturating_mul(p.y));
    let z = i128::from(s.z).saturating_add(g.sz.saturating_mul(p.u));
    // R-G75RANGE: X before Z; the value saturates to i64.
    let checked = |v: i128| -> Result<i64, CycleError> {
        if v.abs() > i128::from(MAX_LENGTH) {
            let value = i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX });
            return Err(CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length::new(value, g.cycle.units),
            });
        }
        Ok(i64::try_from(v).unwrap_or_default())
    };
    let x = checked(x)?;
    let z = checked(z)?;
    Ok(Point::new(x, z))
}

/// The roughing moves (steps ②–⑧) of the planned layers.
///
/// For each layer m: from layer 2 on, `LayerChange(m)` rapids along Z to
/// `(A_m1, top of layer m−1)` and along X to `(A_m1, y_(m−1))` (step ⑧
/// "Z 轴快速定位到下一层起点 Z 轴处 Cmf，执行②" and ② "刀具定位到层起点 Am1");
/// then each plunge: its pecks (steps ③–⑤: `Peck` feeds, `PeckRetract`
/// rapids), `PlungeRetract` to `(A_mn, top)` (step ⑥ "径向(X 轴)快速移动退刀至
/// Amn 点"), and, before every plunge but the first, the `Step` rapid along Z
/// (step ⑦ "轴向(Z 轴)快速移动进刀 … Δk"). After the last layer, `Approach`
/// rapids along X to `y_top` and along Z to A11 (step ⑧ "径向(X 轴)快速移动到
/// 粗加工起点；然后回到粗加工起点 A11").
///
/// R-G75ROLES: `Step(p)` and the pecks carry the plunge they belong to or
/// move to; `LayerChange(m)` the layer it moves to.
fn rough_moves(g: &Groove, path: &mut Path, layers: &[Layer], a11: LocalPoint, y_top: i128) {
    for layer in layers {
        let m = layer.number;
        let m32 = u32::try_from(m).unwrap_or(u32::MAX);
        // R-G75ROLES: LayerChange(m) names the layer it moves to, Step the
        // plunge it moves to, the pecks and retracts their own plunge.
        if m >= 2 {
            path.rapid_u(layer.range.first, Role::LayerChange(m32));
            path.rapid_y(layer.top, Role::LayerChange(m32));
        }
        let plunges = layer.range.count(g.step);
        for n in 1..=plunges {
            let plunge = Plunge { layer: m32, number: u32::try_from(n).unwrap_or(u32::MAX) };
            let a = layer.range.position(g.step, n);
            if n >= 2 {
                path.rapid_u(a, Role::Step(plunge));
            }
            for peck in pecks(g, layer.top, layer.bottom) {
                path.go(LocalMotion::Feed, LocalPoint::new(a, peck.to), Role::Peck(plunge));
                if let Some(r) = peck.retract {
                    path.rapid(LocalPoint::new(a, r), Role::PeckRetract(plunge));
                }
            }
            path.rapid(LocalPoint::new(a, layer.top), Role::PlungeRetract(plunge));
        }
    }
    path.rapid_y(y_top, Role::Approach);
    path.rapid_u(a11.u, Role::Approach);
}

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
