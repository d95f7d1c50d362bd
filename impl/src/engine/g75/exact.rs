//! The exact geometry of a G75.1 groove and the decisions on it
//! (`docs/G75.md` §2–§6, reading R-G75ROUND).
//!
//! [`Geometry`] holds the words of a validated cycle as the local frame
//! sees them. [`Enclosures`] encloses every trigonometric value and derived
//! length at one precision (128 or 512 fraction bits) in [`Interval`]s, and
//! its [`Region`] the roughing region's boundaries (§5). A [`Quantity`]
//! names each real value of the groove (a point's coordinate, a corner
//! check, a boundary at a depth) so that it can be evaluated from its
//! formula at either precision; the [`Evaluator`] decides its floor,
//! ceiling, nearest integer or sign at 128 bits and, only when that is
//! undecided, at 512 bits with reading R-G75TIE.
//!
//! Twins: each formula is the one of the reference model's
//! `spec/src/g75/geometry.rs` (points, tangent lengths, corner checks) and
//! `spec/src/g75/region.rs` (`flank_a_rough`, `flank_b_rough`,
//! `chord3_rough`, `chord4_rough`, `left`, `right`), there over exact reals.

use core::cmp::Ordering;

use crate::engine::approx::{self, Approx};
use crate::engine::linuxcnc::FastPathStats;
use crate::engine::real::{self, Interval, Rounding, FAST, SLOW};
use crate::error::{CycleError, GrooveEdge};
use crate::g75::{corner, CornerKind, G75Cycle};

/// The words of a validated cycle as the local frame sees them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Geometry {
    /// X-word increments per radius increment (2 diameter, 1 radius).
    pub(super) f: i64,
    /// `Y = |H|`.
    pub(super) depth: i64,
    /// `d = |D|`.
    pub(super) width: i64,
    /// `Δu`.
    pub(super) du: i64,
    /// `Δw`.
    pub(super) dw: i64,
    /// Tool width `w` (0: pointed tool).
    pub(super) w: i64,
    /// A in 0.0001°.
    pub(super) a: u32,
    /// B in 0.0001°.
    pub(super) b: u32,
    /// L in 0.0001°.
    pub(super) l: u32,
    /// Corner sizes r1..r4 (radius increments).
    pub(super) size: [i64; 4],
    /// True for a round, false for a chamfer.
    pub(super) round: [bool; 4],
    /// Reading R-G75CHAMFER `axial-width`: a chamfer's size is its extent
    /// along Z.
    pub(super) axial_chamfer: bool,
    /// Reading R-G75SLOPE `falls-towards-d`: the opening falls towards +y
    /// in D's direction.
    pub(super) falls: bool,
}

impl Geometry {
    pub(super) fn new(c: &G75Cycle) -> Geometry {
        Geometry {
            f: c.x_mode.factor(),
            depth: c.depth.abs(),
            width: c.width.abs(),
            du: c.allowance_x,
            dw: c.allowance_z,
            w: c.width_of_tool(),
            a: c.flank_a,
            b: c.flank_b,
            l: c.slope,
            size: c.corners.map(|k| k.size),
            round: c.corners.map(|k| k.kind == CornerKind::Round),
            axial_chamfer: c.readings.chamfer_axial_width,
            falls: c.readings.slope_falls_towards_d,
        }
    }

    /// Size of corner `i`.
    pub(super) fn size(&self, i: usize) -> i64 {
        self.size.get(i).copied().unwrap_or(0)
    }

    /// True when corner `i` is a round of non-zero radius.
    pub(super) fn is_round(&self, i: usize) -> bool {
        self.size(i) > 0 && self.round.get(i).copied().unwrap_or(false)
    }

    /// `f` as an unsigned divisor (1 or 2).
    pub(super) fn fu(&self) -> u64 {
        self.f.unsigned_abs()
    }
}

/// The arithmetic the groove's formulas are written in: the rigorous
/// intervals of [`crate::engine::real`] at 128 or 512 fraction bits, and the
/// fast path's values with their bounds ([`Approx`], reading R-FASTPATH).
/// One home for each formula: [`Region`] and [`Enclosures`] are generic
/// over it, so each path evaluates the same expression.
pub(super) trait Real: Copy + core::fmt::Debug {
    /// The exact integer `v`.
    fn int(v: i128) -> Self;
    /// A value that decides nothing (a poisoned interval, an unknown value).
    fn poison() -> Self;
    /// `self + o`.
    fn add(&self, o: &Self) -> Self;
    /// `self − o`.
    fn sub(&self, o: &Self) -> Self;
    /// `self · o`.
    fn mul(&self, o: &Self) -> Self;
    /// `self / o`.
    fn div(&self, o: &Self) -> Self;
    /// `−self`.
    fn neg(&self) -> Self;
    /// `self · k`.
    fn mul_int(&self, k: i64) -> Self;
    /// `self / k`.
    fn div_int(&self, k: u64) -> Self;
    /// `max(self, o)`.
    fn max(&self, o: &Self) -> Self;
    /// `min(self, o)`.
    fn min(&self, o: &Self) -> Self;
    /// The sine and cosine of `k·0.00005°`.
    fn sin_cos(k: u32) -> (Self, Self);
    /// `tan(k·0.00005°)` from its sine and cosine.
    fn tan_of(k: u32, s: &Self, c: &Self) -> Self;
    /// `cot(k·0.00005°)` from its sine and cosine.
    fn cot_of(k: u32, s: &Self, c: &Self) -> Self;
    /// `tan` and `cot` of `k·0.00005°`.
    fn tan_cot(k: u32) -> (Self, Self);
}

impl<const N: usize> Real for Interval<N> {
    fn int(v: i128) -> Self {
        Interval::int(v)
    }
    fn poison() -> Self {
        Interval::poison()
    }
    fn add(&self, o: &Self) -> Self {
        Interval::add(self, o)
    }
    fn sub(&self, o: &Self) -> Self {
        Interval::sub(self, o)
    }
    fn mul(&self, o: &Self) -> Self {
        Interval::mul(self, o)
    }
    fn div(&self, o: &Self) -> Self {
        Interval::div(self, o)
    }
    fn neg(&self) -> Self {
        Interval::neg(self)
    }
    fn mul_int(&self, k: i64) -> Self {
        Interval::mul_int(self, k)
    }
    fn div_int(&self, k: u64) -> Self {
        Interval::div_int(self, k)
    }
    fn max(&self, o: &Self) -> Self {
        Interval::max(self, o)
    }
    fn min(&self, o: &Self) -> Self {
        Interval::min(self, o)
    }
    fn sin_cos(k: u32) -> (Self, Self) {
        real::sin_cos(k)
    }
    fn tan_of(k: u32, s: &Self, c: &Self) -> Self {
        real::tan_of(k, s, c)
    }
    fn cot_of(k: u32, s: &Self, c: &Self) -> Self {
        real::cot_of(k, s, c)
    }
    fn tan_cot(k: u32) -> (Self, Self) {
        real::tan_cot(k)
    }
}

impl Real for Approx {
    fn int(v: i128) -> Self {
        Approx::int_wide(v)
    }
    fn poison() -> Self {
        Approx::UNKNOWN
    }
    fn add(&self, o: &Self) -> Self {
        Approx::add(self, o)
    }
    fn sub(&self, o: &Self) -> Self {
        Approx::sub(self, o)
    }
    fn mul(&self, o: &Self) -> Self {
        Approx::mul(self, o)
    }
    fn div(&self, o: &Self) -> Self {
        Approx::div(self, o)
    }
    fn neg(&self) -> Self {
        Approx::neg(self)
    }
    fn mul_int(&self, k: i64) -> Self {
        Approx::mul_int(self, k)
    }
    fn div_int(&self, k: u64) -> Self {
        Approx::div_int(self, k)
    }
    fn max(&self, o: &Self) -> Self {
        Approx::max(self, o)
    }
    fn min(&self, o: &Self) -> Self {
        Approx::min(self, o)
    }
    fn sin_cos(k: u32) -> (Self, Self) {
        approx::sin_cos(k)
    }
    fn tan_of(k: u32, s: &Self, c: &Self) -> Self {
        approx::tan_of(k, s, c)
    }
    fn cot_of(k: u32, s: &Self, c: &Self) -> Self {
        approx::cot_of(k, s, c)
    }
    fn tan_cot(k: u32) -> (Self, Self) {
        approx::tan_cot(k)
    }
}

/// What the roughing region's boundaries (`docs/G75.md` §5) need, at the
/// precision `N`: enough to compute a layer's plunge range.
#[derive(Clone, Copy, Debug)]
pub(super) struct Region<R: Real> {
    /// `(Y/f)·cot a`, the u of P1.
    pub(super) p1u: R,
    /// `cot a`.
    pub(super) cot_a: R,
    /// `cot b`.
    pub(super) cot_b: R,
    /// `cot(a/2)` (only when r3 > 0).
    pub(super) cot_ha: R,
    /// `cot(b/2)` (only when r4 > 0).
    pub(super) cot_hb: R,
    /// Tangent length t3.
    pub(super) t3: R,
    /// Tangent length t4.
    pub(super) t4: R,
}

/// The exact integer `v` as an interval.
pub(super) fn int<R: Real>(v: i64) -> R {
    R::int(i128::from(v))
}

impl<R: Real> Region<R> {
    /// `flankA_r(y) = (y/f)·cot a + Δw`.
    ///
    /// Twin: `spec/src/g75/region.rs`, `flank_a_rough`.
    pub(super) fn flank_a(&self, g: &Geometry, y: &R) -> R {
        y.div_int(g.fu()).mul(&self.cot_a).add(&int(g.dw))
    }

    /// `flankB_r(y) = (Y/f)·cot a + d + ((Y − y)/f)·cot b − Δw`.
    ///
    /// Twin: `spec/src/g75/region.rs`, `flank_b_rough`.
    pub(super) fn flank_b(&self, g: &Geometry, y: &R) -> R {
        let rise = int::<R>(g.depth).sub(y).div_int(g.fu()).mul(&self.cot_b);
        self.p1u.add(&int(g.width)).add(&rise).sub(&int(g.dw))
    }

    /// `chord3_r(y) = (Y/f)·cot a + t3 + Δw − ((Y − Δu − y)/f)·cot(a/2)`.
    ///
    /// Twin: `spec/src/g75/region.rs`, `chord3_rough`.
    pub(super) fn chord3(&self, g: &Geometry, y: &R) -> R {
        let rise = int::<R>(g.depth - g.du).sub(y).div_int(g.fu()).mul(&self.cot_ha);
        self.p1u.add(&self.t3).add(&int(g.dw)).sub(&rise)
    }

    /// `chord4_r(y) = (Y/f)·cot a + d − t4 − Δw + ((Y − Δu − y)/f)·cot(b/2)`.
    ///
    /// Twin: `spec/src/g75/region.rs`, `chord4_rough`.
    pub(super) fn chord4(&self, g: &Geometry, y: &R) -> R {
        let rise = int::<R>(g.depth - g.du).sub(y).div_int(g.fu()).mul(&self.cot_hb);
        self.p1u.add(&int(g.width)).sub(&self.t4).sub(&int(g.dw)).add(&rise)
    }

    /// `left(y) = max(flankA_r(y), chord3_r(y))` (chord3 only when t3 > 0).
    ///
    /// Twin: `spec/src/g75/region.rs`, `left`.
    pub(super) fn left(&self, g: &Geometry, y: &R) -> R {
        let flank = self.flank_a(g, y);
        if g.size(corner::R3) > 0 {
            flank.max(&self.chord3(g, y))
        } else {
            flank
        }
    }

    /// `left(y)` or `right(y)` at the integer depth `y`.
    pub(super) fn side(&self, g: &Geometry, y: i128, left: bool) -> R {
        if left {
            self.left(g, &R::int(y))
        } else {
            self.right(g, &R::int(y))
        }
    }

    /// `right(y) = min(flankB_r(y), chord4_r(y))` (chord4 only when t4 > 0).
    ///
    /// Twin: `spec/src/g75/region.rs`, `right`.
    pub(super) fn right(&self, g: &Geometry, y: &R) -> R {
        let flank = self.flank_b(g, y);
        if g.size(corner::R4) > 0 {
            flank.min(&self.chord4(g, y))
        } else {
            flank
        }
    }
}

/// Every trigonometric value and derived length of the cycle at the
/// precision `N`. Values a cycle does not need (the half angles of absent
/// corners) are poisoned intervals: using one by mistake could only give
/// `UndecidedRounding`, never a wrong value.
#[derive(Clone, Copy, Debug)]
pub(super) struct Enclosures<R: Real> {
    /// The region's values.
    pub(super) r: Region<R>,
    /// `sin a`.
    pub(super) sin_a: R,
    /// `cos a`.
    pub(super) cos_a: R,
    /// `sin b`.
    pub(super) sin_b: R,
    /// `cos b`.
    pub(super) cos_b: R,
    /// `sin L`.
    pub(super) sin_l: R,
    /// `cos L`.
    pub(super) cos_l: R,
    /// Tangent length t1.
    pub(super) t1: R,
    /// Tangent length t2.
    pub(super) t2: R,
    /// `u3`.
    pub(super) u3: R,
    /// `y3`.
    pub(super) y3: R,
}

impl<R: Real> Enclosures<R> {
    /// The enclosures of a cycle's values (`docs/G75.md` §3, angles in
    /// units of 0.00005°: `a` is `2A`, `a/2` is `A`, `(a + L)/2` is `A + L`).
    ///
    /// Twin: `spec/src/g75/geometry.rs`, `groove` (the angles and tangent
    /// lengths), `tangent_length`, `u3`, `y3`.
    pub(super) fn new(g: &Geometry) -> Enclosures<R> {
        let (ka, kb, kl) = (2 * g.a, 2 * g.b, 2 * g.l);
        let (sin_a, cos_a) = R::sin_cos(ka);
        let (sin_b, cos_b) = R::sin_cos(kb);
        let (sin_l, cos_l) = R::sin_cos(kl);
        let cot_a = R::cot_of(ka, &sin_a, &cos_a);
        let cot_b = R::cot_of(kb, &sin_b, &cos_b);
        let tan_l = R::tan_of(kl, &sin_l, &cos_l);
        // A chamfer's tangent length (§3): its size, or under R-G75CHAMFER
        // `axial-width` c / (cos θ1 + cos θ2), θ1, θ2 its edges' angles to
        // the Z axis (`cos_edges`).
        // Written (c/2) / ((cos θ1 + cos θ2)/2): the fast path divides by
        // values of magnitude at most 1 only.
        let chamfer = |c: i64, cos_edges: &R| -> R {
            if g.axial_chamfer {
                int::<R>(c).div_int(2).div(&cos_edges.div_int(2))
            } else {
                int(c)
            }
        };
        // Tangent lengths (§3): a chamfer's as above, a round's ρ·tan(…).
        let t = |i: usize, half: u32, cos_edges: &R| -> R {
            let c = g.size(i);
            if c == 0 {
                int(0)
            } else if g.is_round(i) {
                R::tan_cot(half).0.mul_int(c)
            } else {
                chamfer(c, cos_edges)
            }
        };
        // The round's half angles (a ± L)/2, (b ∓ L)/2 (R-G75SLOPE: the
        // surface beyond the corner rises or falls); validate(): L < B
        // (rising), L < A (falling).
        let (half1, half2) =
            if g.falls { (g.a.saturating_sub(g.l), g.b + g.l) } else { (g.a + g.l, g.b.saturating_sub(g.l)) };
        let t1 = t(corner::R1, half1, &cos_a.add(&cos_l));
        let t2 = t(corner::R2, half2, &cos_b.add(&cos_l));
        // t3 and cot(a/2) (and t4, cot(b/2)) share one series.
        let half = |i: usize, k: u32, cos_edge: &R| -> (R, R) {
            let c = g.size(i);
            if c == 0 {
                return (int(0), R::poison());
            }
            let (tan_h, cot_h) = R::tan_cot(k);
            let t = if g.is_round(i) { tan_h.mul_int(c) } else { chamfer(c, &int::<R>(1).add(cos_edge)) };
            (t, cot_h)
        };
        let (t3, cot_ha) = half(corner::R3, g.a, &cos_a);
        let (t4, cot_hb) = half(corner::R4, g.b, &cos_b);
        // P1.u = (Y/f)·cot a.
        let hr = int::<R>(g.depth).div_int(g.fu());
        let p1u = hr.mul(&cot_a);
        // u3 = ((Y/f)·cot a + d + (Y/f)·cot b) / (1 ∓ tan L·cot b), y3 =
        // ∓f·u3·tan L (R-G75SLOPE: − rising, + falling towards D). Falling,
        // the divisor exceeds 1 when L > 0, which the fast path does not
        // divide by: those values fall back to the intervals.
        let num = p1u.add(&int(g.width)).add(&hr.mul(&cot_b));
        let (u3, y3) = if g.falls {
            let u3 = num.div(&int::<R>(1).add(&tan_l.mul(&cot_b)));
            (u3, u3.mul(&tan_l).mul_int(g.f))
        } else {
            let u3 = num.div(&int::<R>(1).sub(&tan_l.mul(&cot_b)));
            (u3, u3.mul(&tan_l).mul_int(g.f).neg())
        };
        Enclosures {
            r: Region { p1u, cot_a, cot_b, cot_ha, cot_hb, t3, t4 },
            sin_a,
            cos_a,
            sin_b,
            cos_b,
            sin_l,
            cos_l,
            t1,
            t2,
            u3,
            y3,
        }
    }

    /// `Y − Δu − f·t·sin θ − Δu·cos θ`: the exact depth of K1 (t3, a) or K4
    /// (t4, b).
    pub(super) fn y_k(g: &Geometry, t: &R, sin: &R, cos: &R) -> R {
        int::<R>(g.depth - g.du).sub(&t.mul(sin).mul_int(g.f)).sub(&cos.mul_int(g.du))
    }

    /// The enclosure of the quantity `q`.
    ///
    /// Twin: the function of the same name in `spec/src/g75/` for each
    /// quantity: `geometry.rs` (`t1s` … `c2`, `p1`, `p2`, `u3`, `y3`,
    /// `check_corners`), `region.rs` (`left`, `right`, `flank_a_rough`,
    /// `flank_b_rough`), `contour.rs` (`y_k1`, `k2`, `k3`, `y_k4`).
    pub(super) fn eval(&self, g: &Geometry, q: Quantity) -> R {
        let r = &self.r;
        let f = g.f;
        let rho = |i: usize| g.size(i);
        match q {
            // §3 alarms: (sum of tangent lengths) − (edge length).
            Quantity::CheckFlankA => {
                let edge = int::<R>(g.depth).div_int(g.fu()).div(&self.sin_a);
                self.t1.add(&r.t3).sub(&edge)
            }
            Quantity::CheckBottom => r.t3.add(&r.t4).sub(&int(g.width)),
            Quantity::CheckOpening => self.y3.sub(&int(g.depth)),
            Quantity::CheckFlankB => {
                let edge = int::<R>(g.depth).sub(&self.y3).div_int(g.fu()).div(&self.sin_b);
                r.t4.add(&self.t2).sub(&edge)
            }
            Quantity::Left(y) => r.left(g, &R::int(y)),
            Quantity::Right(y) => r.right(g, &R::int(y)),
            Quantity::FlankA(y) => r.flank_a(g, &R::int(y)),
            Quantity::FlankB(y) => r.flank_b(g, &R::int(y)),
            Quantity::Y3 => self.y3,
            Quantity::U3 => self.u3,
            Quantity::YK1 => Enclosures::y_k(g, &r.t3, &self.sin_a, &self.cos_a),
            Quantity::K2 => r.p1u.add(&r.t3).add(&int(g.dw)),
            Quantity::K3 => r.p1u.add(&int(g.width)).sub(&r.t4).sub(&int(g.dw)),
            Quantity::YK4 => Enclosures::y_k(g, &r.t4, &self.sin_b, &self.cos_b),
            Quantity::P1U => r.p1u,
            Quantity::P2U => r.p1u.add(&int(g.width)),
            Quantity::T1sU => self.t1.mul(&self.cos_l).neg(),
            // T1s.y = ±f·t1·sin L: below S's level rising, above falling.
            Quantity::T1sY if g.falls => self.t1.mul(&self.sin_l).mul_int(f).neg(),
            Quantity::T1sY => self.t1.mul(&self.sin_l).mul_int(f),
            Quantity::T1aU => self.t1.mul(&self.cos_a),
            Quantity::T1aY => self.t1.mul(&self.sin_a).mul_int(f),
            // C1 = T1a + ρ1·(−sin a, f·cos a).
            Quantity::C1U => self.t1.mul(&self.cos_a).sub(&self.sin_a.mul_int(rho(corner::R1))),
            Quantity::C1Y => {
                self.t1.mul(&self.sin_a).mul_int(f).add(&self.cos_a.mul_int(rho(corner::R1)).mul_int(f))
            }
            Quantity::T3aU => r.p1u.sub(&r.t3.mul(&self.cos_a)),
            Quantity::T3aY => int::<R>(g.depth).sub(&r.t3.mul(&self.sin_a).mul_int(f)),
            // T3b.u = C3.u.
            Quantity::T3bU => r.p1u.add(&r.t3),
            Quantity::C3Y => int(g.depth - f * rho(corner::R3)),
            // T4b.u = C4.u.
            Quantity::T4bU => r.p1u.add(&int(g.width)).sub(&r.t4),
            Quantity::T4cU => r.p1u.add(&int(g.width)).add(&r.t4.mul(&self.cos_b)),
            Quantity::T4cY => int::<R>(g.depth).sub(&r.t4.mul(&self.sin_b).mul_int(f)),
            Quantity::C4Y => int(g.depth - f * rho(corner::R4)),
            Quantity::T2bU => self.u3.sub(&self.t2.mul(&self.cos_b)),
            Quantity::T2bY => self.y3.add(&self.t2.mul(&self.sin_b).mul_int(f)),
            Quantity::T2sU => self.u3.add(&self.t2.mul(&self.cos_l)),
            // T2s.y = y3 ∓ f·t2·sin L.
            Quantity::T2sY if g.falls => self.y3.add(&self.t2.mul(&self.sin_l).mul_int(f)),
            Quantity::T2sY => self.y3.sub(&self.t2.mul(&self.sin_l).mul_int(f)),
            // C2 = T2b + ρ2·(sin b, f·cos b).
            Quantity::C2U => self.u3.sub(&self.t2.mul(&self.cos_b)).add(&self.sin_b.mul_int(rho(corner::R2))),
            Quantity::C2Y => self
                .y3
                .add(&self.t2.mul(&self.sin_b).mul_int(f))
                .add(&self.cos_b.mul_int(rho(corner::R2)).mul_int(f)),
        }
    }
}

/// A real quantity of the cycle (`docs/G75.md` §3–§8), named so that it can
/// be evaluated at either precision from its formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Quantity {
    /// `t1 + t3 − (Y/f)/sin a`.
    CheckFlankA,
    /// `t3 + t4 − d`.
    CheckBottom,
    /// `y3 − Y` (R-G75SLOPE `falls-towards-d`: the opening meets flank B
    /// above the bottom when negative).
    CheckOpening,
    /// `t4 + t2 − ((Y − y3)/f)/sin b`.
    CheckFlankB,
    /// `left(y)`.
    Left(i128),
    /// `right(y)` (before subtracting w).
    Right(i128),
    /// `flankA_r(y)`.
    FlankA(i128),
    /// `flankB_r(y)`.
    FlankB(i128),
    /// `y3`.
    Y3,
    /// `u3`.
    U3,
    /// `Y − Δu − f·t3·sin a − Δu·cos a`.
    YK1,
    /// `(Y/f)·cot a + t3 + Δw`.
    K2,
    /// `(Y/f)·cot a + d − t4 − Δw`.
    K3,
    /// `Y − Δu − f·t4·sin b − Δu·cos b`.
    YK4,
    /// P1.u.
    P1U,
    /// P2.u.
    P2U,
    /// T1s.u.
    T1sU,
    /// T1s.y.
    T1sY,
    /// T1a.u.
    T1aU,
    /// T1a.y.
    T1aY,
    /// C1.u.
    C1U,
    /// C1.y.
    C1Y,
    /// T3a.u.
    T3aU,
    /// T3a.y.
    T3aY,
    /// T3b.u (= C3.u).
    T3bU,
    /// C3.y.
    C3Y,
    /// T4b.u (= C4.u).
    T4bU,
    /// T4c.u.
    T4cU,
    /// T4c.y.
    T4cY,
    /// C4.y.
    C4Y,
    /// T2b.u.
    T2bU,
    /// T2b.y.
    T2bY,
    /// T2s.u.
    T2sU,
    /// T2s.y.
    T2sY,
    /// C2.u.
    C2U,
    /// C2.y.
    C2Y,
}

/// The interval contexts of the fallback (128 and 512 fraction bits), each
/// built from the words at most once per expansion, when a decision first
/// needs it. Kept apart from the [`Evaluator`] (several kilobytes that are
/// almost never filled): the caller owns it and lends it, so that nothing
/// copies it.
#[derive(Default)]
pub(super) struct Fallback {
    fast: Option<Enclosures<Interval<FAST>>>,
    slow: Option<Enclosures<Interval<SLOW>>>,
}

/// Decides roundings and signs of the cycle's quantities: first on the fast
/// path (R-FASTPATH: 64-bit fixed point with a bound, [`Approx`]), then, if
/// that does not decide, at 128 fraction bits, then at 512 with R-G75TIE
/// (R-G75ROUND). Each context is built at most once per expansion, when a
/// decision first needs it (in the [`Fallback`] it borrows).
pub(super) struct Evaluator<'f> {
    pub(super) g: Geometry,
    /// The fast path's values (`None`: the fast path is off).
    pub(super) quick: Option<Enclosures<Approx>>,
    /// The 128- and 512-bit contexts.
    fallback: &'f mut Fallback,
    /// The values decided and the fast path's fallbacks.
    pub(super) stats: FastPathStats,
}

impl<'f> Evaluator<'f> {
    /// The evaluator of a geometry, with the fast path on or off, building
    /// its interval contexts in `fallback` when needed.
    pub(super) fn new(g: Geometry, fast_path: bool, fallback: &'f mut Fallback) -> Evaluator<'f> {
        let quick = fast_path.then(|| Enclosures::new(&g));
        Evaluator { g, quick, fallback, stats: FastPathStats::default() }
    }

    pub(super) fn fast(&mut self) -> &Enclosures<Interval<FAST>> {
        let g = &self.g;
        self.fallback.fast.get_or_insert_with(|| Enclosures::new(g))
    }

    pub(super) fn slow(&mut self) -> &Enclosures<Interval<SLOW>> {
        let g = &self.g;
        self.fallback.slow.get_or_insert_with(|| Enclosures::new(g))
    }

    /// The fast path's decision on `q`, counted (`None`: fall back).
    #[inline]
    fn quick<T>(&mut self, q: Quantity, decide: impl Fn(&Approx) -> Option<T>) -> Option<T> {
        let quick = self.quick.as_ref()?;
        let v = decide(&quick.eval(&self.g, q));
        self.stats.values = self.stats.values.saturating_add(1);
        self.stats.fallbacks = self.stats.fallbacks.saturating_add(u64::from(v.is_none()));
        v
    }

    /// `q` rounded by `r`: decided on the fast path, else at 128 bits, else
    /// at 512 bits with reading R-G75TIE (a value whose 512-bit enclosure
    /// holds exactly one rounding boundary lies on it).
    pub(super) fn round(&mut self, q: Quantity, r: Rounding) -> Result<i128, CycleError> {
        match self.quick(q, |a| a.round(r)) {
            Some(v) => Ok(v),
            None => self.round_exact(q, r),
        }
    }

    /// [`Evaluator::round`] by the intervals alone (128 bits, then 512
    /// with R-G75TIE): out of line, so that the fast path's caller keeps a
    /// small frame.
    #[cold]
    #[inline(never)]
    fn round_exact(&mut self, q: Quantity, r: Rounding) -> Result<i128, CycleError> {
        let g = self.g;
        if let Some(v) = self.fast().eval(&g, q).round(r) {
            return Ok(v);
        }
        self.slow().eval(&g, q).round_tie(r).ok_or(CycleError::UndecidedRounding)
    }

    /// `floor(q)`.
    pub(super) fn floor(&mut self, q: Quantity) -> Result<i128, CycleError> {
        self.round(q, Rounding::Floor)
    }

    /// `ceil(q)`.
    pub(super) fn ceil(&mut self, q: Quantity) -> Result<i128, CycleError> {
        self.round(q, Rounding::Ceil)
    }

    /// `floor(q + 1/2)`.
    pub(super) fn nearest(&mut self, q: Quantity) -> Result<i128, CycleError> {
        self.round(q, Rounding::Nearest)
    }

    /// The sign of `q`: decided on the fast path, else at 128 bits, else at
    /// 512 bits with reading R-G75TIE (a 512-bit enclosure that holds 0 is
    /// taken to be 0).
    pub(super) fn sign(&mut self, q: Quantity) -> Result<Ordering, CycleError> {
        match self.quick(q, Approx::sign) {
            Some(v) => Ok(v),
            None => self.sign_exact(q),
        }
    }

    /// [`Evaluator::sign`] by the intervals alone, out of line.
    #[cold]
    #[inline(never)]
    fn sign_exact(&mut self, q: Quantity) -> Result<Ordering, CycleError> {
        let g = self.g;
        if let Some(v) = self.fast().eval(&g, q).sign() {
            return Ok(v);
        }
        self.slow().eval(&g, q).sign_tie().ok_or(CycleError::UndecidedRounding)
    }

    /// The evaluator of a cycle after the checks that every use of its
    /// geometry starts with: `validate()`, then the corners (§3).
    pub(super) fn checked(
        c: &G75Cycle,
        fast_path: bool,
        fallback: &'f mut Fallback,
    ) -> Result<Evaluator<'f>, CycleError> {
        c.validate()?;
        Evaluator::corners_checked(c, fast_path, fallback)
    }

    /// [`Evaluator::checked`] for a cycle that passed `validate()`: the
    /// corners (§3) only.
    pub(super) fn corners_checked(
        c: &G75Cycle,
        fast_path: bool,
        fallback: &'f mut Fallback,
    ) -> Result<Evaluator<'f>, CycleError> {
        let mut ev = Evaluator::new(Geometry::new(c), fast_path, fallback);
        ev.check_corners()?;
        Ok(ev)
    }

    /// §3: the corners must fit their edges (flank A, bottom, flank B).
    ///
    /// Twin: `spec/src/g75/geometry.rs`, `check_corners`.
    pub(super) fn check_corners(&mut self) -> Result<(), CycleError> {
        // R-G75SLOPE `falls-towards-d`: the opening must meet flank B above
        // the bottom (y3 < Y), before the corners (flank B's length).
        if self.g.falls && self.sign(Quantity::CheckOpening)? != Ordering::Less {
            return Err(CycleError::OpeningBelowBottom);
        }
        for (q, edge) in [
            (Quantity::CheckFlankA, GrooveEdge::FlankA),
            (Quantity::CheckBottom, GrooveEdge::Bottom),
            (Quantity::CheckFlankB, GrooveEdge::FlankB),
        ] {
            if self.sign(q)? == Ordering::Greater {
                return Err(CycleError::CornerTooLarge { edge });
            }
        }
        Ok(())
    }

    /// `y_top`, the top of layer 1 (R-G75LAYER): the highest point of the
    /// opening, `floor(y3)` when it rises towards D, S's level (0) when it
    /// falls (R-G75SLOPE).
    ///
    /// Twin: `spec/src/g75/roughing.rs`, `y_top`.
    pub(super) fn y_top(&mut self) -> Result<i128, CycleError> {
        if self.g.falls {
            Ok(0)
        } else {
            self.floor(Quantity::Y3)
        }
    }

    /// The plunge range of the layer ending at `y` (R-G75PLUNGE):
    /// `(ceil(left(y)), floor(right(y)) − w)`.
    ///
    /// Twin: `spec/src/g75/roughing.rs`, `plunge_range`.
    pub(super) fn plunges(&mut self, y: i64) -> Result<(i128, i128), CycleError> {
        let first = self.ceil(Quantity::Left(i128::from(y)))?;
        let last = self.floor(Quantity::Right(i128::from(y)))? - i128::from(self.g.w);
        Ok((first, last))
    }
}

/// The plunge range of the layer ending at `y`, for the iterator: the same
/// decisions as [`Evaluator::plunges`], each end on its own (the fast path's
/// region when there is one, then a 128-bit context, then a 512-bit one,
/// each rebuilt from the words at most once, with reading R-G75TIE at 512
/// bits), counted in `stats`. `None` only if undecided at 512 bits, which
/// [`expand_g75`](super::expand_g75) has excluded for every layer.
pub(super) fn plunges_at(
    g: &Geometry,
    quick: Option<&Region<Approx>>,
    y: i64,
    stats: &mut FastPathStats,
) -> Option<(i128, i128)> {
    let y = i128::from(y);
    let mut fast: Option<Region<Interval<FAST>>> = None;
    let mut slow: Option<Region<Interval<SLOW>>> = None;
    let mut decide = |left: bool, r: Rounding| -> Option<i128> {
        if let Some(quick) = quick {
            let v = quick.side(g, y, left).round(r);
            stats.values = stats.values.saturating_add(1);
            stats.fallbacks = stats.fallbacks.saturating_add(u64::from(v.is_none()));
            if v.is_some() {
                return v;
            }
        }
        let f = fast.get_or_insert_with(|| Enclosures::<Interval<FAST>>::new(g).r);
        if let Some(v) = f.side(g, y, left).round(r) {
            return Some(v);
        }
        slow.get_or_insert_with(|| Enclosures::<Interval<SLOW>>::new(g).r).side(g, y, left).round_tie(r)
    };
    let first = decide(true, Rounding::Ceil)?;
    let last = decide(false, Rounding::Floor)?;
    Some((first, last - i128::from(g.w)))
}
