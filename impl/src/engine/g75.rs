//! The fixed-point G75.1 engine: the radial trapezoidal groove cycle of
//! `docs/G75.md` (the definition the reference model `cycleref_spec::g75`
//! follows too) without heap, floating point, `unsafe` or panics, streamed
//! move by move.
//!
//! [`expand_g75`] computes the whole geometry and makes every check before
//! the first move; the [`G75Moves`] it returns then cannot fail. Errors come
//! in this order (reading R-G75ORDER):
//!
//! 1. [`G75Cycle::validate`];
//! 2. [`CycleError::CornerTooLarge`]: flank A, then the bottom, then flank B
//!    (§3);
//! 3. [`CycleError::GrooveNarrowerThanTool`] at the last layer (§7), for
//!    every J: the approach point A11 of step 1 needs layer 1's plunge
//!    range whatever J is (reading R-G75NARROW);
//! 4. [`CycleError::RidgesInLayers`] (§7, reading R-G75RIDGE): roughing
//!    (J0, J1) in more than one layer with Δk > w where layer 1's plunge
//!    range is wider than w;
//! 5. [`CycleError::TooManyPecks`] (§9), counted before any move, only when
//!    the cycle roughs (J0, J1): J2 makes no pecks (reading R-G75PECKS);
//! 6. [`CycleError::OutOfRange`] with [`Field::PassCoordinate`]: the first
//!    coordinate of the emitted moves, in move order (each move's end X,
//!    end Z, then an arc's centre X, centre Z), beyond
//!    [`MAX_LENGTH`]; the value is the absolute coordinate, saturated to
//!    `i64` (reading R-G75RANGE).
//!
//! [`CycleError::UndecidedRounding`] comes from the first value that cannot
//! be decided even with reading R-G75TIE (below): only an enclosure that
//! still holds two rounding boundaries at 512 bits (a poisoned one, which
//! the magnitudes below rule out). Values are computed in the order: the
//! corner comparisons, the last layer's plunge range, layer 1's, `y_top`,
//! the other layers' (while counting pecks), the rough contour (J0, J1),
//! the finishing contour (J1, J2). Values that the chosen J does not use are not computed
//! (reading R-G75NEED): J0 never computes the finishing points, J2 never
//! the rough contour.
//!
//! # Exact rounding
//!
//! Every coordinate is rounded from the exact real value of its formula in
//! `docs/G75.md` §3–§8, evaluated with the rigorous interval arithmetic of
//! [`crate::engine::real`]: at 128 fraction bits first, and, only if that
//! interval does not decide the rounding, again from the same formula at
//! 512 fraction bits (reading R-G75ROUND). Exact inputs (right angles, 45°,
//! the other exact cases of §6) give exact point intervals, decided
//! exactly.
//!
//! R-G75TIE: a value still undecided at 512 bits whose enclosure holds
//! exactly one rounding boundary (an integer for floor and ceil, a
//! half-integer for nearest, 0 for a sign; inside or on an end) is taken
//! to lie on it: `floor(k) = ceil(k) = k`, the nearest of `k + 1/2` is
//! `k + 1`, the sign is 0 ([`Iv::round_tie`], [`Iv::sign_tie`]). This is
//! how identities among irrational values are decided (a round on a 60°
//! flank, `tan 30°·sin 60° = 1/2`; a round whose `f·ρ` equals Δu,
//! `y_K1 = Y − 2Δu`). The rule is applied only to the 512-bit enclosure,
//! never to the 128-bit one, in `Eval::round`, `Eval::sign` and
//! `plunges_at` alike.
//!
//! The formulas are evaluated as written — in particular `((Y − Δu −
//! y)/f)·cot(a/2)` is 0 exactly at `y = Y − Δu` — so an expression is exact
//! in this engine exactly when it is exact in the reference model.
//!
//! # Magnitudes
//!
//! After `validate()`: `Y, d, Δu, Δw, w, Δi, Δk, Δv < 2^27`, corner sizes
//! `< 2^20`, `f ≤ 2`; every tangent or cotangent used is at most
//! `cot(0.00005°) < 2^21`; `1 − tan L·cot b = sin(b − L)/(sin b·cos L) ≥
//! sin(0.0001°) > 2^-20`. So `(Y/f)·cot a < 2^47`, `u3 < 2^69`, `y3 =
//! −f·u3·tan L` has `|y3| = f·(…)·sin L·sin b / sin(b − L) < 2^70`, and no
//! formula exceeds `2^96`: far inside the `2^127` of an [`Iv`], so no
//! interval operation overflows (an overflow would poison the interval and
//! give `UndecidedRounding`, never a wrong value). Rounded values are kept
//! in `i128` until the range check has bounded every coordinate of a move
//! by `MAX_LENGTH < 2^30`; only then are they narrowed to `i64`. The peck
//! count is formed in `i128` (at most `2^71` pecks per plunge times `2^48`
//! plunges per layer before the limit stops the count).
//!
//! # Work and memory
//!
//! Up front: a fixed number of interval evaluations (about forty) plus two
//! per layer while counting pecks (at most `MAX_PECKS` layers, since every
//! layer has at least one peck). Per move: O(1); a layer change evaluates
//! the layer's plunge range again (a handful of 256-bit interval products;
//! when 128 bits do not decide it, in practice only for a boundary exactly
//! on an integer (R-G75TIE), the 512-bit context is rebuilt once for that
//! layer, a bounded amount of work). A [`G75Moves`] is a fixed-size value
//! (2 088 bytes on 64-bit targets: the precomputed tail
//! of at most 22 moves and the 128-bit enclosures of the region's
//! boundaries; the test `size_of_the_iterator` bounds it).
//!
//! # Readings added by this engine
//!
//! Where `docs/G75.md` leaves a detail open, the simplest reading is taken;
//! the reference model must match them (each is also cited in the code):
//!
//! * R-G75ORDER, R-G75NARROW, R-G75PECKS, R-G75RANGE, R-G75NEED: above.
//!   R-G75RANGE checks only emitted moves: a move left out as empty
//!   (R-G75ZERO) has no coordinate to check, not even an arc centre.
//! * R-G75ROLES: the step-8 rapids back to `y_top` and A11 are
//!   [`Role::Approach`]; the rapids of step 9 (to R0, back to A11) are
//!   [`Role::RoughContour`]; the two rapids of step 10 to F0 are
//!   [`Role::FinishContour`]; the three rapids back to S and the one to
//!   `from` are [`Role::Return`]. J0 goes from A11 (after step 9) straight
//!   to `from`.
//! * R-G75ARCDIR: the turning sense of a round is fixed by the geometry
//!   (see `Frame::clockwise`): convex corners r1, r2 are G02 exactly when
//!   `sx·sz < 0`, concave corners r3, r4 exactly when `sx·sz > 0`.
//! * R-G75KCHECK: no alarm beyond §7's. The check `K2.u ≤ K3.u` (or Q1, Q2)
//!   is the last layer's `A_Mf ≥ A_M1` itself (at `y = Y − Δu`, `left` is
//!   K2's formula and `right` K3's); `K1.u ≤ K2.u`, `K4.u ≥ K3.u` and
//!   `y_K1, y_K4 ≤ Y − Δu` hold for every cycle (the chords meet the
//!   flanks above the bottom). `y_K1` (`y_K4`) may lie at or above
//!   `y_top` when the corner covers most of its flank and Δu > 0; then
//!   (§8) K1 (K4) is not a vertex and R0 (R3) lies on the chord.
//! * R-G75ARCZERO: an arc whose rounded end is its start is left out like
//!   any empty move (`TailBuilder::go`), centre and all.
//! * R-G75PROFILE: [`groove_profile`] checks `validate()` and the corners
//!   only, keeps every point (none is left out as empty; K1 and K4 are
//!   vertices only below `y_top`, as in the rough contour), and range-checks
//!   its own points in its order.

use core::cmp::Ordering;
use core::iter::FusedIterator;

use super::saturate_i64;
use crate::engine::real::{cot_of, sin_cos, tan_cot, tan_of, Iv, Rounding, FAST, SLOW};
use crate::error::{CycleError, Field, GrooveEdge};
use crate::g75::{corner, CornerKind, G75Cycle, MAX_PECKS};
use crate::moves::{Motion, Move, Plunge, Role};
use crate::units::{Length, Point, Units, MAX_LENGTH};

// ---------------------------------------------------------------------------
// The exact inputs, in the local frame (docs/G75.md §2).
// ---------------------------------------------------------------------------

/// The words of a validated cycle as the local frame sees them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Geo {
    /// X-word increments per radius increment (2 diameter, 1 radius).
    f: i64,
    /// `Y = |H|`.
    depth: i64,
    /// `d = |D|`.
    width: i64,
    /// `Δu`.
    du: i64,
    /// `Δw`.
    dw: i64,
    /// Tool width `w` (0: pointed tool).
    w: i64,
    /// A in 0.0001°.
    a: u32,
    /// B in 0.0001°.
    b: u32,
    /// L in 0.0001°.
    l: u32,
    /// Corner sizes r1..r4 (radius increments).
    size: [i64; 4],
    /// True for a round, false for a chamfer.
    round: [bool; 4],
}

impl Geo {
    fn new(c: &G75Cycle) -> Geo {
        Geo {
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
        }
    }

    /// Size of corner `i`.
    fn size(&self, i: usize) -> i64 {
        self.size.get(i).copied().unwrap_or(0)
    }

    /// True when corner `i` is a round of non-zero radius.
    fn is_round(&self, i: usize) -> bool {
        self.size(i) > 0 && self.round.get(i).copied().unwrap_or(false)
    }

    /// `f` as an unsigned divisor (1 or 2).
    fn fu(&self) -> u64 {
        self.f.unsigned_abs()
    }
}

// ---------------------------------------------------------------------------
// Enclosures of the geometry at one precision.
// ---------------------------------------------------------------------------

/// What the roughing region's boundaries (`docs/G75.md` §5) need, at the
/// precision `N`: enough to compute a layer's plunge range.
#[derive(Clone, Copy, Debug)]
struct Region<const N: usize> {
    /// `(Y/f)·cot a`, the u of P1.
    p1u: Iv<N>,
    /// `cot a`.
    cot_a: Iv<N>,
    /// `cot b`.
    cot_b: Iv<N>,
    /// `cot(a/2)` (only when r3 > 0).
    cot_ha: Iv<N>,
    /// `cot(b/2)` (only when r4 > 0).
    cot_hb: Iv<N>,
    /// Tangent length t3.
    t3: Iv<N>,
    /// Tangent length t4.
    t4: Iv<N>,
}

/// The exact integer `v` as an interval.
fn int<const N: usize>(v: i64) -> Iv<N> {
    Iv::int(i128::from(v))
}

impl<const N: usize> Region<N> {
    /// `flankA_r(y) = (y/f)·cot a + Δw`.
    fn flank_a(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
        y.div_int(g.fu()).mul(&self.cot_a).add(&int(g.dw))
    }

    /// `flankB_r(y) = (Y/f)·cot a + d + ((Y − y)/f)·cot b − Δw`.
    fn flank_b(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
        let rise = int::<N>(g.depth).sub(y).div_int(g.fu()).mul(&self.cot_b);
        self.p1u.add(&int(g.width)).add(&rise).sub(&int(g.dw))
    }

    /// `chord3_r(y) = (Y/f)·cot a + t3 + Δw − ((Y − Δu − y)/f)·cot(a/2)`.
    fn chord3(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
        let rise = int::<N>(g.depth - g.du).sub(y).div_int(g.fu()).mul(&self.cot_ha);
        self.p1u.add(&self.t3).add(&int(g.dw)).sub(&rise)
    }

    /// `chord4_r(y) = (Y/f)·cot a + d − t4 − Δw + ((Y − Δu − y)/f)·cot(b/2)`.
    fn chord4(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
        let rise = int::<N>(g.depth - g.du).sub(y).div_int(g.fu()).mul(&self.cot_hb);
        self.p1u.add(&int(g.width)).sub(&self.t4).sub(&int(g.dw)).add(&rise)
    }

    /// `left(y) = max(flankA_r(y), chord3_r(y))` (chord3 only when t3 > 0).
    fn left(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
        let flank = self.flank_a(g, y);
        if g.size(corner::R3) > 0 {
            flank.max(&self.chord3(g, y))
        } else {
            flank
        }
    }

    /// `right(y) = min(flankB_r(y), chord4_r(y))` (chord4 only when t4 > 0).
    fn right(&self, g: &Geo, y: &Iv<N>) -> Iv<N> {
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
struct Ctx<const N: usize> {
    /// The region's values.
    r: Region<N>,
    /// `sin a`.
    sin_a: Iv<N>,
    /// `cos a`.
    cos_a: Iv<N>,
    /// `sin b`.
    sin_b: Iv<N>,
    /// `cos b`.
    cos_b: Iv<N>,
    /// `sin L`.
    sin_l: Iv<N>,
    /// `cos L`.
    cos_l: Iv<N>,
    /// Tangent length t1.
    t1: Iv<N>,
    /// Tangent length t2.
    t2: Iv<N>,
    /// `u3`.
    u3: Iv<N>,
    /// `y3`.
    y3: Iv<N>,
}

impl<const N: usize> Ctx<N> {
    /// The enclosures of a cycle's values (`docs/G75.md` §3, angles in
    /// units of 0.00005°: `a` is `2A`, `a/2` is `A`, `(a + L)/2` is `A + L`).
    fn new(g: &Geo) -> Ctx<N> {
        let (ka, kb, kl) = (2 * g.a, 2 * g.b, 2 * g.l);
        let (sin_a, cos_a) = sin_cos::<N>(ka);
        let (sin_b, cos_b) = sin_cos::<N>(kb);
        let (sin_l, cos_l) = sin_cos::<N>(kl);
        let cot_a = cot_of(ka, &sin_a, &cos_a);
        let cot_b = cot_of(kb, &sin_b, &cos_b);
        let tan_l = tan_of(kl, &sin_l, &cos_l);
        // Tangent lengths (§3): a chamfer's is its size, a round's ρ·tan(…).
        let t = |i: usize, half: u32| -> Iv<N> {
            let c = g.size(i);
            if c == 0 {
                int(0)
            } else if g.is_round(i) {
                tan_cot::<N>(half).0.mul_int(c)
            } else {
                int(c)
            }
        };
        let t1 = t(corner::R1, g.a + g.l);
        // validate(): L < B.
        let t2 = t(corner::R2, g.b.saturating_sub(g.l));
        // t3 and cot(a/2) (and t4, cot(b/2)) share one series.
        let half = |i: usize, k: u32| -> (Iv<N>, Iv<N>) {
            let c = g.size(i);
            if c == 0 {
                return (int(0), Iv::poison());
            }
            let (tan_h, cot_h) = tan_cot::<N>(k);
            let t = if g.is_round(i) { tan_h.mul_int(c) } else { int(c) };
            (t, cot_h)
        };
        let (t3, cot_ha) = half(corner::R3, g.a);
        let (t4, cot_hb) = half(corner::R4, g.b);
        // P1.u = (Y/f)·cot a.
        let hr = int::<N>(g.depth).div_int(g.fu());
        let p1u = hr.mul(&cot_a);
        // u3 = ((Y/f)·cot a + d + (Y/f)·cot b) / (1 − tan L·cot b).
        let num = p1u.add(&int(g.width)).add(&hr.mul(&cot_b));
        let den = int::<N>(1).sub(&tan_l.mul(&cot_b));
        let u3 = num.div(&den);
        // y3 = −f·u3·tan L.
        let y3 = u3.mul(&tan_l).mul_int(g.f).neg();
        Ctx {
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
    fn y_k(g: &Geo, t: &Iv<N>, sin: &Iv<N>, cos: &Iv<N>) -> Iv<N> {
        int::<N>(g.depth - g.du).sub(&t.mul(sin).mul_int(g.f)).sub(&cos.mul_int(g.du))
    }

    /// The enclosure of the quantity `q`.
    fn eval(&self, g: &Geo, q: Q) -> Iv<N> {
        let r = &self.r;
        let f = g.f;
        let rho = |i: usize| g.size(i);
        match q {
            // §3 alarms: (sum of tangent lengths) − (edge length).
            Q::CheckFlankA => {
                let edge = int::<N>(g.depth).div_int(g.fu()).div(&self.sin_a);
                self.t1.add(&r.t3).sub(&edge)
            }
            Q::CheckBottom => r.t3.add(&r.t4).sub(&int(g.width)),
            Q::CheckFlankB => {
                let edge = int::<N>(g.depth).sub(&self.y3).div_int(g.fu()).div(&self.sin_b);
                r.t4.add(&self.t2).sub(&edge)
            }
            Q::Left(y) => r.left(g, &Iv::int(y)),
            Q::Right(y) => r.right(g, &Iv::int(y)),
            Q::FlankA(y) => r.flank_a(g, &Iv::int(y)),
            Q::FlankB(y) => r.flank_b(g, &Iv::int(y)),
            Q::Y3 => self.y3,
            Q::U3 => self.u3,
            Q::YK1 => Ctx::y_k(g, &r.t3, &self.sin_a, &self.cos_a),
            Q::K2 => r.p1u.add(&r.t3).add(&int(g.dw)),
            Q::K3 => r.p1u.add(&int(g.width)).sub(&r.t4).sub(&int(g.dw)),
            Q::YK4 => Ctx::y_k(g, &r.t4, &self.sin_b, &self.cos_b),
            Q::P1U => r.p1u,
            Q::P2U => r.p1u.add(&int(g.width)),
            Q::T1sU => self.t1.mul(&self.cos_l).neg(),
            Q::T1sY => self.t1.mul(&self.sin_l).mul_int(f),
            Q::T1aU => self.t1.mul(&self.cos_a),
            Q::T1aY => self.t1.mul(&self.sin_a).mul_int(f),
            // C1 = T1a + ρ1·(−sin a, f·cos a).
            Q::C1U => self.t1.mul(&self.cos_a).sub(&self.sin_a.mul_int(rho(corner::R1))),
            Q::C1Y => {
                self.t1.mul(&self.sin_a).mul_int(f).add(&self.cos_a.mul_int(rho(corner::R1)).mul_int(f))
            }
            Q::T3aU => r.p1u.sub(&r.t3.mul(&self.cos_a)),
            Q::T3aY => int::<N>(g.depth).sub(&r.t3.mul(&self.sin_a).mul_int(f)),
            // T3b.u = C3.u.
            Q::T3bU => r.p1u.add(&r.t3),
            Q::C3Y => int(g.depth - f * rho(corner::R3)),
            // T4b.u = C4.u.
            Q::T4bU => r.p1u.add(&int(g.width)).sub(&r.t4),
            Q::T4cU => r.p1u.add(&int(g.width)).add(&r.t4.mul(&self.cos_b)),
            Q::T4cY => int::<N>(g.depth).sub(&r.t4.mul(&self.sin_b).mul_int(f)),
            Q::C4Y => int(g.depth - f * rho(corner::R4)),
            Q::T2bU => self.u3.sub(&self.t2.mul(&self.cos_b)),
            Q::T2bY => self.y3.add(&self.t2.mul(&self.sin_b).mul_int(f)),
            Q::T2sU => self.u3.add(&self.t2.mul(&self.cos_l)),
            Q::T2sY => self.y3.sub(&self.t2.mul(&self.sin_l).mul_int(f)),
            // C2 = T2b + ρ2·(sin b, f·cos b).
            Q::C2U => self.u3.sub(&self.t2.mul(&self.cos_b)).add(&self.sin_b.mul_int(rho(corner::R2))),
            Q::C2Y => self
                .y3
                .add(&self.t2.mul(&self.sin_b).mul_int(f))
                .add(&self.cos_b.mul_int(rho(corner::R2)).mul_int(f)),
        }
    }
}

/// A real quantity of the cycle (`docs/G75.md` §3–§8), named so that it can
/// be evaluated at either precision from its formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Q {
    /// `t1 + t3 − (Y/f)/sin a`.
    CheckFlankA,
    /// `t3 + t4 − d`.
    CheckBottom,
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

// ---------------------------------------------------------------------------
// Decisions: the fast path, then the same formula at 512 bits.
// ---------------------------------------------------------------------------

/// Decides roundings and signs of the cycle's quantities (R-G75ROUND): at
/// 128 fraction bits, then, if undecided, at 512 with R-G75TIE (the 512-bit
/// context is built at most once per expansion).
struct Eval {
    g: Geo,
    fast: Ctx<FAST>,
    slow: Option<Ctx<SLOW>>,
}

impl Eval {
    fn new(g: Geo) -> Eval {
        Eval { g, fast: Ctx::new(&g), slow: None }
    }

    fn slow(&mut self) -> &Ctx<SLOW> {
        let g = &self.g;
        self.slow.get_or_insert_with(|| Ctx::new(g))
    }

    /// `q` rounded by `r`: decided at 128 bits, else at 512 bits with
    /// reading R-G75TIE (a value whose 512-bit enclosure holds exactly one
    /// rounding boundary lies on it).
    fn round(&mut self, q: Q, r: Rounding) -> Result<i128, CycleError> {
        if let Some(v) = self.fast.eval(&self.g, q).round(r) {
            return Ok(v);
        }
        let g = self.g;
        self.slow().eval(&g, q).round_tie(r).ok_or(CycleError::UndecidedRounding)
    }

    /// `floor(q)`.
    fn floor(&mut self, q: Q) -> Result<i128, CycleError> {
        self.round(q, Rounding::Floor)
    }

    /// `ceil(q)`.
    fn ceil(&mut self, q: Q) -> Result<i128, CycleError> {
        self.round(q, Rounding::Ceil)
    }

    /// `floor(q + 1/2)`.
    fn nearest(&mut self, q: Q) -> Result<i128, CycleError> {
        self.round(q, Rounding::Nearest)
    }

    /// The sign of `q`: decided at 128 bits, else at 512 bits with reading
    /// R-G75TIE (a 512-bit enclosure that holds 0 is taken to be 0).
    fn sign(&mut self, q: Q) -> Result<Ordering, CycleError> {
        if let Some(v) = self.fast.eval(&self.g, q).sign() {
            return Ok(v);
        }
        let g = self.g;
        self.slow().eval(&g, q).sign_tie().ok_or(CycleError::UndecidedRounding)
    }

    /// §3: the corners must fit their edges (flank A, bottom, flank B).
    fn check_corners(&mut self) -> Result<(), CycleError> {
        for (q, edge) in [
            (Q::CheckFlankA, GrooveEdge::FlankA),
            (Q::CheckBottom, GrooveEdge::Bottom),
            (Q::CheckFlankB, GrooveEdge::FlankB),
        ] {
            if self.sign(q)? == Ordering::Greater {
                return Err(CycleError::CornerTooLarge { edge });
            }
        }
        Ok(())
    }

    /// The plunge range of the layer ending at `y` (R-G75PLUNGE):
    /// `(ceil(left(y)), floor(right(y)) − w)`.
    fn plunges(&mut self, y: i64) -> Result<(i128, i128), CycleError> {
        let first = self.ceil(Q::Left(i128::from(y)))?;
        let last = self.floor(Q::Right(i128::from(y)))? - i128::from(self.g.w);
        Ok((first, last))
    }
}

/// The plunge range of the layer ending at `y`, for the iterator: the same
/// decisions as [`Eval::plunges`], each end on its own (the fast context's
/// region, then, if undecided, a 512-bit context rebuilt from the words,
/// at most once, with reading R-G75TIE). `None` only if undecided at 512
/// bits, which [`expand_g75`] has excluded for every layer.
fn plunges_at(g: &Geo, fast: &Region<FAST>, y: i64) -> Option<(i128, i128)> {
    let yv = Iv::int(i128::from(y));
    let mut slow: Option<Region<SLOW>> = None;
    let first = match fast.left(g, &yv).round(Rounding::Ceil) {
        Some(v) => v,
        None => slow
            .get_or_insert_with(|| Ctx::<SLOW>::new(g).r)
            .left(g, &Iv::int(i128::from(y)))
            .round_tie(Rounding::Ceil)?,
    };
    let last = match fast.right(g, &yv).round(Rounding::Floor) {
        Some(v) => v,
        None => slow
            .get_or_insert_with(|| Ctx::<SLOW>::new(g).r)
            .right(g, &Iv::int(i128::from(y)))
            .round_tie(Rounding::Floor)?,
    };
    Some((first, last - i128::from(g.w)))
}

// ---------------------------------------------------------------------------
// Rounded geometry, in local coordinates (i128 until range-checked).
// ---------------------------------------------------------------------------

/// A rounded local point `(u, y)`.
type Local = (i128, i128);

/// The kind of segment that ends at a point of the finishing profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LocalSeg {
    /// The first point.
    Start,
    /// A straight feed (an edge or a chamfer).
    Line,
    /// A round about `centre`; `convex` for the outer corners r1, r2.
    Arc {
        /// Rounded centre.
        centre: Local,
        /// True for r1 and r2 (material corners), false for r3 and r4.
        convex: bool,
    },
}

/// One point of the finishing profile: the point, its segment and whether
/// it lies on the far side (moved by −w for a grooving tool, §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct ProfileLocal {
    at: Local,
    seg: LocalSeg,
    far: bool,
}

/// The finishing profile of §8 step 10, rounded to nearest (§6), without
/// the tool width: F0 (T1s or S), then r1, flank A, r3, bottom, r4, flank
/// B, r2. At most 8 points.
fn finish_profile(ev: &mut Eval) -> Result<([ProfileLocal; 8], usize), CycleError> {
    let g = ev.g;
    let start = ProfileLocal { at: (0, 0), seg: LocalSeg::Start, far: false };
    let mut pts = [start; 8];
    let mut n = 0;
    let mut push = |p: ProfileLocal| {
        if let Some(slot) = pts.get_mut(n) {
            *slot = p;
            n += 1;
        }
    };
    let line = |at: Local, far: bool| ProfileLocal { at, seg: LocalSeg::Line, far };
    // F0 = T1s, or S without r1.
    if g.size(corner::R1) > 0 {
        push(ProfileLocal {
            at: (ev.nearest(Q::T1sU)?, ev.nearest(Q::T1sY)?),
            seg: LocalSeg::Start,
            far: false,
        });
        let t1a = (ev.nearest(Q::T1aU)?, ev.nearest(Q::T1aY)?);
        if g.is_round(corner::R1) {
            let centre = (ev.nearest(Q::C1U)?, ev.nearest(Q::C1Y)?);
            push(ProfileLocal { at: t1a, seg: LocalSeg::Arc { centre, convex: true }, far: false });
        } else {
            push(line(t1a, false));
        }
    } else {
        push(start);
    }
    // Flank A to T3a (or P1), r3 to T3b.
    let depth = i128::from(g.depth);
    if g.size(corner::R3) > 0 {
        push(line((ev.nearest(Q::T3aU)?, ev.nearest(Q::T3aY)?), false));
        let t3b = (ev.nearest(Q::T3bU)?, depth);
        if g.is_round(corner::R3) {
            let centre = (t3b.0, ev.nearest(Q::C3Y)?);
            push(ProfileLocal { at: t3b, seg: LocalSeg::Arc { centre, convex: false }, far: false });
        } else {
            push(line(t3b, false));
        }
    } else {
        push(line((ev.nearest(Q::P1U)?, depth), false));
    }
    // The bottom to T4b (or P2), r4 to T4c.
    if g.size(corner::R4) > 0 {
        let t4b = ev.nearest(Q::T4bU)?;
        push(line((t4b, depth), true));
        let t4c = (ev.nearest(Q::T4cU)?, ev.nearest(Q::T4cY)?);
        if g.is_round(corner::R4) {
            let centre = (t4b, ev.nearest(Q::C4Y)?);
            push(ProfileLocal { at: t4c, seg: LocalSeg::Arc { centre, convex: false }, far: true });
        } else {
            push(line(t4c, true));
        }
    } else {
        push(line((ev.nearest(Q::P2U)?, depth), true));
    }
    // Flank B to T2b (or P3), r2 to T2s.
    if g.size(corner::R2) > 0 {
        push(line((ev.nearest(Q::T2bU)?, ev.nearest(Q::T2bY)?), true));
        let t2s = (ev.nearest(Q::T2sU)?, ev.nearest(Q::T2sY)?);
        if g.is_round(corner::R2) {
            let centre = (ev.nearest(Q::C2U)?, ev.nearest(Q::C2Y)?);
            push(ProfileLocal { at: t2s, seg: LocalSeg::Arc { centre, convex: true }, far: true });
        } else {
            push(line(t2s, true));
        }
    } else {
        push(line((ev.nearest(Q::U3)?, ev.nearest(Q::Y3)?), true));
    }
    Ok((pts, n))
}

/// A vertex of the rough contour (§8 step 9), before subtracting w; `far`
/// for the right-hand vertices (K3, K4, Q2, R3), which are moved by −w.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct RoughLocal {
    at: Local,
    far: bool,
}

/// R0, K1 and K2 (or Q1), K3 and K4 (or Q2), R3, rounded into the region
/// (§6, §8 step 9), before subtracting w. At most 6 vertices.
///
/// R0 and R3 are `left` and `right` at `y_top` (R-G75MAXMIN: the chord
/// where it is the boundary). R-G75K1Y: K1's u is flank A's at the integer
/// `y_K1` (K4's flank B's at `y_K4`), rounded in; K1 is a vertex only when
/// `y_K1 > y_top` (K4 when `y_K4 > y_top`): otherwise the chord is the
/// boundary over the whole depth and R0 (R3) already lies on it. K2 and K3
/// are vertices whenever r3, r4 are programmed.
fn rough_vertices(ev: &mut Eval, y_top: i128) -> Result<([RoughLocal; 6], usize), CycleError> {
    let g = ev.g;
    let bottom = i128::from(g.depth - g.du);
    let mut v = [RoughLocal { at: (0, 0), far: false }; 6];
    let mut n = 0;
    let mut push = |at: Local, far: bool| {
        if let Some(slot) = v.get_mut(n) {
            *slot = RoughLocal { at, far };
            n += 1;
        }
    };
    // R0 = (ceil(left(y_top)), y_top).
    push((ev.ceil(Q::Left(y_top))?, y_top), false);
    if g.size(corner::R3) > 0 {
        let y_k1 = ev.floor(Q::YK1)?;
        if y_k1 > y_top {
            push((ev.ceil(Q::FlankA(y_k1))?, y_k1), false);
        }
        push((ev.ceil(Q::K2)?, bottom), false);
    } else {
        push((ev.ceil(Q::FlankA(bottom))?, bottom), false);
    }
    if g.size(corner::R4) > 0 {
        push((ev.floor(Q::K3)?, bottom), true);
        let y_k4 = ev.floor(Q::YK4)?;
        if y_k4 > y_top {
            push((ev.floor(Q::FlankB(y_k4))?, y_k4), true);
        }
    } else {
        push((ev.floor(Q::FlankB(bottom))?, bottom), true);
    }
    // R3 = (floor(right(y_top)) − w, y_top), w subtracted by the caller.
    push((ev.floor(Q::Right(y_top))?, y_top), true);
    Ok((v, n))
}

// ---------------------------------------------------------------------------
// Absolute coordinates and the range check.
// ---------------------------------------------------------------------------

/// The mapping from the local frame to absolute X/Z (§2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Frame {
    /// S.
    start: Point,
    /// `sx`.
    sx: i64,
    /// `sz`.
    sz: i64,
    /// For error values.
    units: Units,
}

impl Frame {
    fn new(c: &G75Cycle) -> Frame {
        Frame { start: c.start, sx: c.radial_sign(), sz: c.axial_sign(), units: c.units }
    }

    /// Absolute X of local `y`.
    fn x(&self, y: i128) -> i128 {
        i128::from(self.start.x) + i128::from(self.sx) * y
    }

    /// Absolute Z of local `u`.
    fn z(&self, u: i128) -> i128 {
        i128::from(self.start.z) + i128::from(self.sz) * u
    }

    /// An absolute coordinate within the range, as `i64`.
    fn coordinate(&self, v: i128) -> Result<i64, CycleError> {
        match i64::try_from(v) {
            Ok(x) if (-MAX_LENGTH..=MAX_LENGTH).contains(&x) => Ok(x),
            _ => {
                let value = i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX });
                Err(CycleError::OutOfRange {
                    field: Field::PassCoordinate,
                    value: Length::new(value, self.units),
                })
            }
        }
    }

    /// The absolute point of a local one, X checked before Z.
    fn point(&self, p: Local) -> Result<Point, CycleError> {
        let x = self.coordinate(self.x(p.1))?;
        let z = self.coordinate(self.z(p.0))?;
        Ok(Point::new(x, z))
    }

    /// Whether a round turns clockwise seen with +Z to the right and +X up
    /// (R-G75ARC). In local (u, y/f) coordinates the cross product of
    /// (start − centre) and (end − centre) is `ρ²·sin(a + L)` for r1,
    /// `ρ²·sin(b − L)` for r2 (both > 0: convex corners turn one way) and
    /// `−ρ²·sin a`, `−ρ²·sin b` for r3, r4 (concave, the other way); the map
    /// to (Z, X) multiplies it by `sz·sx`. Negative is clockwise.
    fn clockwise(&self, convex: bool) -> bool {
        let local = if convex { 1 } else { -1 };
        local * self.sx * self.sz < 0
    }
}

/// `⌊a / b⌋` for `b > 0`.
fn floor_div(a: i128, b: i128) -> i128 {
    let q = a / b;
    if a % b != 0 && a < 0 {
        q - 1
    } else {
        q
    }
}

/// `⌈a / b⌉` for `b > 0`.
fn ceil_div(a: i128, b: i128) -> i128 {
    -floor_div(-a, b)
}

// ---------------------------------------------------------------------------
// The fixed tail of the path.
// ---------------------------------------------------------------------------

/// How a leg of the tail moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LegKind {
    Rapid,
    Feed,
    Arc { centre: Point, clockwise: bool },
}

/// One precomputed move of the tail (after the pecks).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Leg {
    kind: LegKind,
    to: Point,
    role: Role,
}

/// Longest tail: 2 approach + 5 rough contour + 1 back to A11 + 2 finishing
/// approach + 7 contour + 3 return + 1 to `from` = 21.
const TAIL: usize = 22;

/// Builds the tail in move order from a known position, leaving out empty
/// moves (R-G75ZERO) and range-checking every emitted coordinate (R-G75RANGE).
struct TailBuilder {
    frame: Frame,
    at: Local,
    legs: [Leg; TAIL],
    len: usize,
}

impl TailBuilder {
    fn go(
        &mut self,
        to: Local,
        motion: Option<(Local, bool)>,
        feed: bool,
        role: Role,
    ) -> Result<(), CycleError> {
        if to == self.at {
            return Ok(());
        }
        let p = self.frame.point(to)?;
        let kind = match motion {
            Some((centre, clockwise)) => LegKind::Arc { centre: self.frame.point(centre)?, clockwise },
            None if feed => LegKind::Feed,
            None => LegKind::Rapid,
        };
        if let Some(slot) = self.legs.get_mut(self.len) {
            *slot = Leg { kind, to: p, role };
            self.len += 1;
        }
        self.at = to;
        Ok(())
    }

    fn rapid(&mut self, to: Local, role: Role) -> Result<(), CycleError> {
        self.go(to, None, false, role)
    }

    fn feed(&mut self, to: Local, role: Role) -> Result<(), CycleError> {
        self.go(to, None, true, role)
    }
}

// ---------------------------------------------------------------------------
// The moves.
// ---------------------------------------------------------------------------

/// Where the roughing state machine is within a plunge or a layer change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sub {
    /// LayerChange along Z at the previous layer's top.
    LayerZ,
    /// LayerChange along X down to this layer's top.
    LayerX,
    /// The next peck.
    Peck,
    /// The retract e after a peck that did not reach the bottom.
    Retract,
    /// The retract to the layer's top after the last peck.
    PlungeRetract,
    /// The step to the next plunge, or on to the next layer.
    After,
}

/// The roughing state (layers, plunges, pecks: §7, §8 step 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Rough {
    /// Number of layers M.
    layers: u32,
    /// Current layer m (1-based).
    m: u32,
    /// `Y − Δu`.
    rough_bottom: i64,
    /// Δv (0: one layer).
    dv: i64,
    /// Δi.
    di: i64,
    /// Δk.
    dk: i64,
    /// `e_x = f·e`.
    ex: i64,
    /// Top of the previous layer (for the LayerChange along Z).
    prev_top: i64,
    /// Top of this layer.
    top: i64,
    /// Bottom of this layer `y_m`.
    bottom: i64,
    /// `A_m1`.
    first: i64,
    /// `A_mf`.
    last: i64,
    /// Current plunge position `A_mn`.
    u: i64,
    /// Current plunge number n.
    n: u32,
    /// End of the next peck before clamping: `top + j·Δi`.
    target: i64,
    /// End of the last peck.
    depth: i64,
    /// Next candidate move.
    sub: Sub,
}

/// Which part of the path comes next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    /// Step 1: the rapid to A11.
    Approach,
    /// Steps 2–8.
    Rough,
    /// The precomputed tail.
    Tail,
    /// Nothing more.
    Done,
}

/// The moves of a G75.1 cycle, in order (`docs/G75.md` §8): an
/// [`Iterator`] of constant size made by [`expand_g75`]. It cannot fail:
/// every check was made before it was returned.
#[derive(Clone, Debug)]
pub struct G75Moves {
    frame: Frame,
    geo: Geo,
    region: Region<FAST>,
    stage: Stage,
    approach: Option<Leg>,
    roughs: bool,
    rough: Rough,
    at: (i64, i64),
    tail: [Leg; TAIL],
    tail_len: usize,
    tail_next: usize,
}

/// Expands a G75.1 cycle (`docs/G75.md`): the same error or the same moves
/// as the reference model.
///
/// # Errors
///
/// In this order (R-G75ORDER): [`G75Cycle::validate`]'s errors,
/// [`CycleError::CornerTooLarge`], [`CycleError::GrooveNarrowerThanTool`],
/// [`CycleError::RidgesInLayers`], [`CycleError::TooManyPecks`], [`CycleError::OutOfRange`] for a move
/// coordinate; [`CycleError::UndecidedRounding`] where a needed value cannot
/// be decided at 512 fraction bits even by R-G75TIE (an enclosure holding
/// two rounding boundaries).
pub fn expand_g75(c: &G75Cycle) -> Result<G75Moves, CycleError> {
    c.validate()?;
    let g = Geo::new(c);
    let frame = Frame::new(c);
    let mut ev = Eval::new(g);
    ev.check_corners()?;

    // §7 layers: y_m = min(m·Δv, Y − Δu); M = ceil((Y − Δu)/Δv), 1 without V.
    // validate(): 0 < Y − Δu < 2^27, 1 ≤ Δv < 2^27, so M < 2^27.
    let rough_bottom = g.depth - g.du;
    let dv = c.layer.unwrap_or(0);
    let layers = if dv > 0 { ceil_div(i128::from(rough_bottom), i128::from(dv)) } else { 1 };
    let y_of = |m: i128| -> i64 {
        if dv > 0 {
            saturate_i64((m * i128::from(dv)).min(i128::from(rough_bottom)))
        } else {
            rough_bottom
        }
    };
    // R-G75PLUNGE: the last layer is the narrowest (left grows, right
    // shrinks with depth); R-G75NARROW: checked for every J. This is also
    // the check K2.u ≤ K3.u (or Q1/Q2): at y = Y − Δu, left is K2's formula
    // and right K3's plus w.
    let (last_first, last_last) = ev.plunges(rough_bottom)?;
    if last_last < last_first {
        return Err(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(g.w, c.units) });
    }
    let y1 = y_of(1);
    let (a11, a1f) = if layers == 1 { (last_first, last_last) } else { ev.plunges(y1)? };
    // R-G75RIDGE: layered roughing with a step wider than the tool leaves
    // ridges in layer 1 that the next layer's rapids would cross.
    if c.path.roughs() && layers >= 2 && c.step > g.w && a1f - a11 > i128::from(g.w) {
        return Err(CycleError::RidgesInLayers {
            step: Length::new(c.step, c.units),
            tool_width: Length::new(g.w, c.units),
        });
    }
    // Layer tops: y_top = floor(y3) (R-G75LAYER).
    let y_top = ev.floor(Q::Y3)?;

    // §9: pecks counted in closed form per layer (R-G75PECK: a plunge from
    // t to b has ceil((b − t)/Δi) pecks), only when roughing (R-G75PECKS).
    let roughs = c.path.roughs();
    let (di, dk) = (i128::from(c.peck), i128::from(c.step));
    let limit = i128::from(MAX_PECKS);
    if roughs {
        let pecks = |top: i128, bottom: i128| ceil_div(bottom - top, di);
        // Every layer has at least one plunge: the pecks of one plunge per
        // layer are a lower bound, in closed form (layers 2..M−1 are Δv deep).
        let mut lower = pecks(y_top, i128::from(y1));
        if layers >= 2 {
            let dvi = i128::from(dv);
            lower += (layers - 2) * pecks(0, dvi) + pecks((layers - 1) * dvi, i128::from(rough_bottom));
        }
        if lower > limit {
            return Err(CycleError::TooManyPecks { limit: MAX_PECKS });
        }
        // Now M ≤ lower ≤ MAX_PECKS: count exactly, layer by layer.
        let mut total: i128 = 0;
        let mut top = y_top;
        for m in 1..=layers {
            let bottom = i128::from(y_of(m));
            let (first, last) = if m == 1 {
                (a11, a1f)
            } else if m == layers {
                (last_first, last_last)
            } else {
                ev.plunges(y_of(m))?
            };
            // first ≤ last (the last layer's check and monotony), Δk ≥ 1.
            let plunges = ceil_div(last - first, dk) + 1;
            total = total.saturating_add(plunges.saturating_mul(pecks(top, bottom)));
            if total > limit {
                return Err(CycleError::TooManyPecks { limit: MAX_PECKS });
            }
            top = bottom;
        }
    }
    // R-G75NEED: the rough contour only for J0/J1, the finishing profile
    // only for J1/J2.
    let rough_pts = if roughs { Some(rough_vertices(&mut ev, y_top)?) } else { None };
    let finish_pts = if c.path.finishes() { Some(finish_profile(&mut ev)?) } else { None };

    // R-G75RANGE, in move order. Step 1: the approach to A11.
    let a11_local = (a11, y_top);
    let a11_abs = frame.point(a11_local)?;
    if roughs {
        check_roughing(c, &frame, y_top, (a11, a1f), layers)?;
    }
    let w = i128::from(g.w);
    let top_last = if layers >= 2 { i128::from(y_of(layers - 1)) } else { y_top };
    let mut b = TailBuilder {
        frame,
        at: if roughs { (last_last, top_last) } else { a11_local },
        legs: [Leg { kind: LegKind::Rapid, to: c.from, role: Role::Return }; TAIL],
        len: 0,
    };
    if let Some((v, n)) = rough_pts {
        // Step 8: back along X to y_top and along Z to A11.
        b.rapid((b.at.0, y_top), Role::Approach)?;
        b.rapid(a11_local, Role::Approach)?;
        // Step 9: rapid to R0, feeds along the contour, rapid back to A11.
        for (i, p) in v.iter().take(n).enumerate() {
            let to = if p.far { (p.at.0 - w, p.at.1) } else { p.at };
            if i == 0 {
                b.rapid(to, Role::RoughContour)?;
            } else {
                b.feed(to, Role::RoughContour)?;
            }
        }
        b.rapid(a11_local, Role::RoughContour)?;
    }
    if let Some((pts, n)) = finish_pts {
        // Step 10: along Z to F0's u at y_top, along X to F0, the contour.
        let shift = |p: Local, far: bool| if far { (p.0 - w, p.1) } else { p };
        for (i, p) in pts.iter().take(n).enumerate() {
            let to = shift(p.at, p.far);
            match p.seg {
                LocalSeg::Start => {
                    if i == 0 {
                        b.rapid((to.0, y_top), Role::FinishContour)?;
                        b.rapid(to, Role::FinishContour)?;
                    }
                }
                LocalSeg::Line => b.feed(to, Role::FinishContour)?,
                LocalSeg::Arc { centre, convex } => {
                    let cw = frame.clockwise(convex);
                    b.go(to, Some((shift(centre, p.far), cw)), true, Role::FinishContour)?;
                }
            }
        }
        // Back: along X to min(y_top, y_end), along Z to u = 0, along X to S.
        let end = b.at;
        let y_back = y_top.min(end.1);
        b.rapid((end.0, y_back), Role::Return)?;
        b.rapid((0, y_back), Role::Return)?;
        b.rapid((0, 0), Role::Return)?;
    }
    // Step 10's end: back to the point before the cycle, in one move. The
    // builder's position is local; `from` may lie anywhere in range.
    let end_abs = frame.point(b.at)?;
    if end_abs != c.from {
        if let Some(slot) = b.legs.get_mut(b.len) {
            *slot = Leg { kind: LegKind::Rapid, to: c.from, role: Role::Return };
            b.len += 1;
        }
    }

    let approach =
        (a11_abs != c.from).then_some(Leg { kind: LegKind::Rapid, to: a11_abs, role: Role::Approach });
    let rough = Rough {
        // layers ≤ MAX_PECKS when roughing; 1 otherwise is never read.
        layers: u32::try_from(layers).unwrap_or(u32::MAX),
        m: 1,
        rough_bottom,
        dv,
        di: c.peck,
        dk: c.step,
        ex: g.f * c.retract,
        prev_top: saturate_i64(y_top),
        top: saturate_i64(y_top),
        bottom: y1,
        first: saturate_i64(a11),
        last: saturate_i64(a1f),
        u: saturate_i64(a11),
        n: 1,
        target: saturate_i64(y_top).saturating_add(c.peck),
        depth: saturate_i64(y_top),
        sub: Sub::Peck,
    };
    Ok(G75Moves {
        frame,
        geo: g,
        region: ev.fast.r,
        stage: Stage::Approach,
        approach,
        roughs,
        rough,
        at: (saturate_i64(a11), saturate_i64(y_top)),
        tail: b.legs,
        tail_len: b.len,
        tail_next: 0,
    })
}

/// R-G75RANGE for the roughing moves, in move order, in closed form. Every
/// roughing position has `u ∈ [A11, A1f]` (layer 1 is the widest) and `y ∈
/// [y_top, Y − Δu]`, X and Z are monotone in y and u, and A11's X and Z
/// (the approach) are already checked; so the first coordinate out of range
/// is, in this order: X of the first peck of layer 1's first plunge beyond
/// the range (every plunge of layer 1 comes after it); Z of the first step
/// of layer 1 beyond it; X of the first peck beyond it in the first plunge
/// of the first deeper layer whose bottom is beyond it (its layer change
/// stays at the previous layer's depths, its Z within layer 1's).
fn check_roughing(
    c: &G75Cycle,
    frame: &Frame,
    y_top: i128,
    (a11, a1f): (i128, i128),
    layers: i128,
) -> Result<(), CycleError> {
    let max = i128::from(MAX_LENGTH);
    // The deepest y whose X is in range, and the furthest u whose Z is.
    let y_lim = max - i128::from(frame.sx) * i128::from(frame.start.x);
    let u_lim = max - i128::from(frame.sz) * i128::from(frame.start.z);
    let (di, dk) = (i128::from(c.peck), i128::from(c.step));
    let rough_bottom = i128::from(c.depth.abs() - c.allowance_x);
    let dv = i128::from(c.layer.unwrap_or(0));
    let y1 = if dv > 0 { dv.min(rough_bottom) } else { rough_bottom };
    // The first peck end beyond y_lim in a plunge from `top` to `bottom`
    // (top ≤ y_lim < bottom).
    let peck_beyond = |top: i128, bottom: i128| -> Result<(), CycleError> {
        let j = floor_div(y_lim - top, di) + 1;
        frame.coordinate(frame.x((top + j * di).min(bottom))).map(|_| ())
    };
    if y1 > y_lim {
        return peck_beyond(y_top, y1);
    }
    if a1f > u_lim {
        let u = a11 + (floor_div(u_lim - a11, dk) + 1) * dk;
        return frame.coordinate(frame.z(if u < a1f { u } else { a1f })).map(|_| ());
    }
    if rough_bottom > y_lim && layers >= 2 && dv > 0 {
        // The first layer whose bottom m·Δv (or Y − Δu) is beyond y_lim: m ≥ 2.
        let m = floor_div(y_lim, dv) + 1;
        let top = (m - 1) * dv;
        return peck_beyond(top, (m * dv).min(rough_bottom));
    }
    Ok(())
}

impl G75Moves {
    /// The absolute point of a local one (range-checked up front).
    fn abs(&self, u: i64, y: i64) -> Point {
        let p = self.frame;
        Point::new(p.start.x + p.sx * y, p.start.z + p.sz * u)
    }

    /// A roughing move to local `(u, y)`, or `None` when it would not move.
    fn rough_move(&mut self, motion: Motion, u: i64, y: i64, role: Role) -> Option<Move> {
        if (u, y) == self.at {
            return None;
        }
        self.at = (u, y);
        Some(Move { motion, to: self.abs(u, y), role, pass: None })
    }

    /// The plunge of the current layer and number.
    fn plunge(&self) -> Plunge {
        Plunge { layer: self.rough.m, number: self.rough.n }
    }

    /// The next roughing move, or `None` at the end of the roughing.
    fn next_rough(&mut self) -> Option<Move> {
        loop {
            let r = self.rough;
            match r.sub {
                Sub::LayerZ => {
                    self.rough.sub = Sub::LayerX;
                    let role = Role::LayerChange(r.m);
                    if let Some(mv) = self.rough_move(Motion::Rapid, r.first, r.prev_top, role) {
                        return Some(mv);
                    }
                }
                Sub::LayerX => {
                    self.rough.sub = Sub::Peck;
                    let role = Role::LayerChange(r.m);
                    if let Some(mv) = self.rough_move(Motion::Rapid, r.first, r.top, role) {
                        return Some(mv);
                    }
                }
                Sub::Peck => {
                    // R-G75PECK: peck j to min(top + j·Δi, y_m).
                    let y = r.target.min(r.bottom);
                    self.rough.target = r.target.saturating_add(r.di);
                    self.rough.depth = y;
                    self.rough.sub = if y < r.bottom { Sub::Retract } else { Sub::PlungeRetract };
                    let role = Role::Peck(self.plunge());
                    if let Some(mv) = self.rough_move(Motion::Feed, r.u, y, role) {
                        return Some(mv);
                    }
                }
                Sub::Retract => {
                    self.rough.sub = Sub::Peck;
                    let y = r.top.max(r.depth - r.ex);
                    let role = Role::PeckRetract(self.plunge());
                    if let Some(mv) = self.rough_move(Motion::Rapid, r.u, y, role) {
                        return Some(mv);
                    }
                }
                Sub::PlungeRetract => {
                    self.rough.sub = Sub::After;
                    let role = Role::PlungeRetract(self.plunge());
                    if let Some(mv) = self.rough_move(Motion::Rapid, r.u, r.top, role) {
                        return Some(mv);
                    }
                }
                Sub::After => {
                    if r.u < r.last {
                        // Step 7: on by Δk while below A_mf, then to A_mf.
                        let next = r.u.saturating_add(r.dk);
                        let u = if next < r.last { next } else { r.last };
                        self.rough.u = u;
                        self.rough.n = r.n.saturating_add(1);
                        self.rough.target = r.top.saturating_add(r.di);
                        self.rough.sub = Sub::Peck;
                        let role = Role::Step(self.plunge());
                        if let Some(mv) = self.rough_move(Motion::Rapid, u, r.top, role) {
                            return Some(mv);
                        }
                    } else if r.m < r.layers {
                        self.next_layer();
                    } else {
                        return None;
                    }
                }
            }
        }
    }

    /// Moves on to the next layer (steps 8 and 2).
    fn next_layer(&mut self) {
        let r = self.rough;
        let m = r.m.saturating_add(1);
        let bottom =
            if r.dv > 0 { (i64::from(m).saturating_mul(r.dv)).min(r.rough_bottom) } else { r.rough_bottom };
        // Decided in expand_g75 for every layer (the peck count), so the
        // fallback to the previous range is unreachable.
        let (first, last) = plunges_at(&self.geo, &self.region, bottom)
            .map_or((r.first, r.last), |(a, b)| (saturate_i64(a), saturate_i64(b)));
        self.rough = Rough {
            m,
            prev_top: r.top,
            top: r.bottom,
            bottom,
            first,
            last,
            u: first,
            n: 1,
            target: r.bottom.saturating_add(r.di),
            depth: r.bottom,
            sub: Sub::LayerZ,
            ..r
        };
    }
}

impl Iterator for G75Moves {
    type Item = Move;

    fn next(&mut self) -> Option<Move> {
        loop {
            match self.stage {
                Stage::Approach => {
                    self.stage = if self.roughs { Stage::Rough } else { Stage::Tail };
                    if let Some(l) = self.approach {
                        return Some(Move { motion: Motion::Rapid, to: l.to, role: l.role, pass: None });
                    }
                }
                Stage::Rough => match self.next_rough() {
                    Some(m) => return Some(m),
                    None => self.stage = Stage::Tail,
                },
                Stage::Tail => {
                    let Some(leg) = self.tail.get(self.tail_next).filter(|_| self.tail_next < self.tail_len)
                    else {
                        self.stage = Stage::Done;
                        return None;
                    };
                    self.tail_next += 1;
                    let motion = match leg.kind {
                        LegKind::Rapid => Motion::Rapid,
                        LegKind::Feed => Motion::Feed,
                        LegKind::Arc { centre, clockwise } => Motion::Arc { centre, clockwise },
                    };
                    return Some(Move { motion, to: leg.to, role: leg.role, pass: None });
                }
                Stage::Done => return None,
            }
        }
    }
}

impl FusedIterator for G75Moves {}

// ---------------------------------------------------------------------------
// The groove's profile, for plots and proofs.
// ---------------------------------------------------------------------------

/// How the finishing profile reaches a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ProfileSegment {
    /// The first point (T1s, or S without r1).
    Start,
    /// A straight segment (an edge, or a chamfer).
    Line,
    /// A round (G02 when `clockwise`, else G03) about `centre`.
    Arc {
        /// The round's centre, absolute.
        centre: Point,
        /// True for G02 (R-G75ARC).
        clockwise: bool,
    },
}

/// A point of the finishing profile and the segment that ends there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ProfilePoint {
    /// The point, absolute.
    pub at: Point,
    /// The segment from the previous point.
    pub segment: ProfileSegment,
}

/// The rounded groove of a G75.1 cycle in absolute coordinates, without the
/// tool width (`docs/G75.md` §3, §5, §8): fixed-size arrays with counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GrooveProfile {
    /// The finishing profile from T1s (or S) to T2s (or P3), rounded to
    /// nearest: F0, (T1a), T3a or P1, (T3b), T4b or P2, (T4c), T2b or P3,
    /// (T2s), the parenthesised ones with their corner. Only the first
    /// `finish_len` entries are meaningful.
    pub finish: [ProfilePoint; 8],
    /// Number of points in [`GrooveProfile::finish`] (4 to 8).
    pub finish_len: usize,
    /// The roughing region's vertices, rounded into the region, before
    /// subtracting the tool width: R0, K1 and K2 (or Q1), K3 and K4 (or
    /// Q2), R3, with K1 (K4) only when `y_K1 > y_top` (`y_K4 > y_top`), as
    /// in the rough contour (§8 step 9). Only the first `rough_len` entries
    /// are meaningful.
    pub rough: [Point; 6],
    /// Number of points in [`GrooveProfile::rough`] (4 to 6).
    pub rough_len: usize,
}

impl GrooveProfile {
    /// The finishing profile's points.
    #[must_use]
    pub fn finishing(&self) -> &[ProfilePoint] {
        self.finish.get(..self.finish_len).unwrap_or(&[])
    }

    /// The roughing region's vertices.
    #[must_use]
    pub fn roughing(&self) -> &[Point] {
        self.rough.get(..self.rough_len).unwrap_or(&[])
    }
}

/// The rounded profile of a G75.1 cycle: the finishing profile (§3, §8 step
/// 10) and the roughing region's vertices (§5, §8 step 9), absolute,
/// without the tool width, whatever J is.
///
/// # Errors
///
/// [`G75Cycle::validate`]'s errors, [`CycleError::CornerTooLarge`],
/// [`CycleError::UndecidedRounding`], and [`CycleError::OutOfRange`] for the
/// first point beyond the range (finishing points in order, each point
/// before its centre, then the roughing vertices). The alarms of the
/// roughing path (groove narrower than the tool, too many pecks) are not
/// checked: the profile exists without them.
pub fn groove_profile(c: &G75Cycle) -> Result<GrooveProfile, CycleError> {
    c.validate()?;
    let g = Geo::new(c);
    let frame = Frame::new(c);
    let mut ev = Eval::new(g);
    ev.check_corners()?;
    let (pts, n) = finish_profile(&mut ev)?;
    let y_top = ev.floor(Q::Y3)?;
    let (vs, m) = rough_vertices(&mut ev, y_top)?;
    let mut out = GrooveProfile {
        finish: [ProfilePoint { at: c.start, segment: ProfileSegment::Start }; 8],
        finish_len: 0,
        rough: [c.start; 6],
        rough_len: 0,
    };
    for (slot, p) in out.finish.iter_mut().zip(pts.iter().take(n)) {
        let at = frame.point(p.at)?;
        let segment = match p.seg {
            LocalSeg::Start => ProfileSegment::Start,
            LocalSeg::Line => ProfileSegment::Line,
            LocalSeg::Arc { centre, convex } => {
                ProfileSegment::Arc { centre: frame.point(centre)?, clockwise: frame.clockwise(convex) }
            }
        };
        *slot = ProfilePoint { at, segment };
        out.finish_len += 1;
    }
    for (slot, v) in out.rough.iter_mut().zip(vs.iter().take(m)) {
        *slot = frame.point(v.at)?;
        out.rough_len += 1;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::g75::{Corner, PathType};
    use crate::units::{IncrementSystem, InputUnit, XMode};
    use std::format;
    use std::string::String;
    use std::vec::Vec;

    const IS_C: Units = Units { system: IncrementSystem::IsC, unit: InputUnit::Metric };

    /// The seed's example: `G00 X60 Z30; G75.1 X50 Z30 P30000 Q50000 H-20
    /// D-10 A45 B30; G75.1 R0.5;` at IS-C metric.
    fn seed() -> G75Cycle {
        G75Cycle {
            units: IS_C,
            x_mode: XMode::Diameter,
            from: Point::new(600_000, 300_000),
            start: Point::new(500_000, 300_000),
            peck: 30_000,
            step: 50_000,
            depth: -200_000,
            width: -100_000,
            flank_a: 450_000,
            flank_b: 300_000,
            slope: 0,
            retract: 5_000,
            layer: None,
            allowance_x: 0,
            allowance_z: 0,
            tool_width: None,
            path: PathType::Rough,
            corners: [Corner::SHARP; 4],
        }
    }

    /// The golden square groove of `proofs/tests/g75_golden.rs` at IS-B:
    /// `G00 X40 Z5; G75.1 X30 Z0 P2000 Q3000 H-6 D-8; G75.1 R0.5 V4 U0.4
    /// W0.2 I3 J1 A0.5 D0.4 E0.3 P0011`.
    fn square() -> G75Cycle {
        G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            from: Point::new(40_000, 5_000),
            start: Point::new(30_000, 0),
            peck: 2_000,
            step: 3_000,
            depth: -6_000,
            width: -8_000,
            flank_a: 900_000,
            flank_b: 900_000,
            slope: 0,
            retract: 500,
            layer: Some(4_000),
            allowance_x: 400,
            allowance_z: 200,
            tool_width: Some(3_000),
            path: PathType::RoughAndFinish,
            corners: [
                Corner { size: 500, kind: CornerKind::Chamfer },
                Corner::SHARP,
                Corner { size: 400, kind: CornerKind::Round },
                Corner { size: 300, kind: CornerKind::Round },
            ],
        }
    }

    fn render(moves: &[Move]) -> Vec<String> {
        moves
            .iter()
            .map(|m| {
                let g = match m.motion {
                    Motion::Rapid => String::from("G00"),
                    Motion::Feed => String::from("G01"),
                    Motion::Thread { .. } => String::from("G32"),
                    Motion::Arc { centre, clockwise } => {
                        format!("{} C{},{}", if clockwise { "G02" } else { "G03" }, centre.x, centre.z)
                    }
                };
                let role = match m.role {
                    Role::Peck(p) => format!("peck {}.{}", p.layer, p.number),
                    Role::PeckRetract(p) => format!("peck-retract {}.{}", p.layer, p.number),
                    Role::PlungeRetract(p) => format!("plunge-retract {}.{}", p.layer, p.number),
                    Role::Step(p) => format!("step {}.{}", p.layer, p.number),
                    Role::LayerChange(l) => format!("layer {l}"),
                    other => format!("{other:?}"),
                };
                format!("{g} X{} Z{} {role}", m.to.x, m.to.z)
            })
            .collect()
    }

    /// The seed example worked by hand (docs/G75.md; A11: Z = 30 − 10 = 20).
    #[test]
    fn seed_example_by_hand() {
        let c = seed();
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        assert!(moves.iter().all(|m| m.pass.is_none()));
        // A11 = (ceil(100000·cot 45°), 0) = (100000, 0): X50 Z20.
        let mut expected = std::vec![String::from("G00 X500000 Z200000 Approach")];
        // One plunge: pecks to y = 30000·j (X47, X44, …, X32), each followed
        // by a retract of e_x = 2·5000 (X48, X45, …, X33), the 7th peck cut
        // short at y = 200000 (X30), then back to X50.
        let plunge = |z: i64, n: u32| {
            let mut v = Vec::new();
            for j in 1..=6_i64 {
                v.push(format!("G01 X{} Z{z} peck 1.{n}", 500_000 - 30_000 * j));
                v.push(format!("G00 X{} Z{z} peck-retract 1.{n}", 500_000 - 30_000 * j + 10_000));
            }
            v.push(format!("G01 X300000 Z{z} peck 1.{n}"));
            v.push(format!("G00 X500000 Z{z} plunge-retract 1.{n}"));
            v
        };
        expected.extend(plunge(200_000, 1));
        // A1f = floor(200000 + 0·cot 30°) = 200000: plunges at u = 100000,
        // 150000, 200000 (Z20, Z15, Z10).
        expected.push("G00 X500000 Z150000 step 1.2".into());
        expected.extend(plunge(150_000, 2));
        expected.push("G00 X500000 Z100000 step 1.3".into());
        expected.extend(plunge(100_000, 3));
        expected.extend([
            "G00 X500000 Z200000 Approach".into(),
            // R0 = S, Q1 = (100000, Y), Q2 = (200000, Y), R3 = (floor(200000
            // + 100000·√3) = 373205, 0): Z = 300000 − 373205.
            "G00 X500000 Z300000 RoughContour".into(),
            "G01 X300000 Z200000 RoughContour".into(),
            "G01 X300000 Z100000 RoughContour".into(),
            "G01 X500000 Z-73205 RoughContour".into(),
            "G00 X500000 Z200000 RoughContour".into(),
            "G00 X600000 Z300000 Return".into(),
        ]);
        assert_eq!(render(&moves), expected);
    }

    /// The seed example with J1 and I4 (w = 40000): the far side moves in by
    /// w; the finishing contour goes S, P1, P2 − w, P3 − w (u3 = 373205.08…
    /// → 373205).
    #[test]
    fn seed_with_tool_and_finish() {
        let c = G75Cycle { tool_width: Some(40_000), path: PathType::RoughAndFinish, ..seed() };
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        let r = render(&moves);
        let tail: Vec<&str> = r.iter().rev().take(12).rev().map(String::as_str).collect();
        assert_eq!(
            tail,
            [
                "G00 X500000 Z200000 Approach",
                "G00 X500000 Z300000 RoughContour",
                "G01 X300000 Z200000 RoughContour",
                "G01 X300000 Z140000 RoughContour",
                "G01 X500000 Z-33205 RoughContour",
                "G00 X500000 Z200000 RoughContour",
                // F0 = S: along Z to u = 0 (the X move is empty).
                "G00 X500000 Z300000 FinishContour",
                "G01 X300000 Z200000 FinishContour",
                "G01 X300000 Z140000 FinishContour",
                "G01 X500000 Z-33205 FinishContour",
                // Return: X and the final X move are empty; Z to S, then from.
                "G00 X500000 Z300000 Return",
                "G00 X600000 Z300000 Return",
            ]
        );
        assert!(r.contains(&String::from("G00 X500000 Z140000 step 1.3")));
    }

    /// The golden square groove (every value exact), as worked by hand in
    /// `proofs/tests/g75_golden.rs`.
    #[test]
    fn square_groove_by_hand() {
        let moves: Vec<Move> = expand_g75(&square()).unwrap().collect();
        let plunge1 = |z: i64, n: u32| {
            std::vec![
                format!("G01 X28000 Z{z} peck 1.{n}"),
                format!("G00 X29000 Z{z} peck-retract 1.{n}"),
                format!("G01 X26000 Z{z} peck 1.{n}"),
                format!("G00 X30000 Z{z} plunge-retract 1.{n}"),
            ]
        };
        let plunge2 = |z: i64, n: u32| {
            std::vec![format!("G01 X24400 Z{z} peck 2.{n}"), format!("G00 X26000 Z{z} plunge-retract 2.{n}")]
        };
        let mut e = std::vec![String::from("G00 X30000 Z-200 Approach")];
        e.extend(plunge1(-200, 1));
        e.push("G00 X30000 Z-3200 step 1.2".into());
        e.extend(plunge1(-3200, 2));
        e.push("G00 X30000 Z-4800 step 1.3".into());
        e.extend(plunge1(-4800, 3));
        e.push("G00 X30000 Z-600 layer 2".into());
        e.push("G00 X26000 Z-600 layer 2".into());
        e.extend(plunge2(-600, 1));
        e.push("G00 X26000 Z-3600 step 2.2".into());
        e.extend(plunge2(-3600, 2));
        e.push("G00 X26000 Z-4500 step 2.3".into());
        e.extend(plunge2(-4500, 3));
        e.extend([
            "G00 X30000 Z-4500 Approach".into(),
            "G00 X30000 Z-200 Approach".into(),
            "G01 X25200 Z-200 RoughContour".into(),
            "G01 X24400 Z-600 RoughContour".into(),
            "G01 X24400 Z-4500 RoughContour".into(),
            "G01 X25000 Z-4800 RoughContour".into(),
            "G01 X30000 Z-4800 RoughContour".into(),
            "G00 X30000 Z-200 RoughContour".into(),
            "G00 X30000 Z500 FinishContour".into(),
            "G01 X29000 Z0 FinishContour".into(),
            "G01 X24800 Z0 FinishContour".into(),
            "G02 C24800,-400 X24000 Z-400 FinishContour".into(),
            "G01 X24000 Z-4700 FinishContour".into(),
            "G02 C24600,-4700 X24600 Z-5000 FinishContour".into(),
            "G01 X30000 Z-5000 FinishContour".into(),
            "G00 X30000 Z0 Return".into(),
            "G00 X40000 Z5000 Return".into(),
        ]);
        assert_eq!(render(&moves), e);
    }

    #[test]
    fn square_profile() {
        let p = groove_profile(&square()).unwrap();
        let at: Vec<(i64, i64)> = p.finishing().iter().map(|q| (q.at.x, q.at.z)).collect();
        // T1s, T1a, T3a, T3b, T4b, T4c, P3: without the tool width.
        assert_eq!(
            at,
            [
                (30_000, 500),
                (29_000, 0),
                (24_800, 0),
                (24_000, -400),
                (24_000, -7_700),
                (24_600, -8_000),
                (30_000, -8_000)
            ]
        );
        assert_eq!(p.finishing()[0].segment, ProfileSegment::Start);
        assert_eq!(p.finishing()[1].segment, ProfileSegment::Line);
        assert_eq!(
            p.finishing()[3].segment,
            ProfileSegment::Arc { centre: Point::new(24_800, -400), clockwise: true }
        );
        assert_eq!(
            p.finishing()[5].segment,
            ProfileSegment::Arc { centre: Point::new(24_600, -7_700), clockwise: true }
        );
        let rough: Vec<(i64, i64)> = p.roughing().iter().map(|q| (q.x, q.z)).collect();
        // R0, K1, K2, K3, K4, R3 before the tool width.
        assert_eq!(
            rough,
            [
                (30_000, -200),
                (25_200, -200),
                (24_400, -600),
                (24_400, -7_500),
                (25_000, -7_800),
                (30_000, -7_800)
            ]
        );
    }

    /// Arc directions: r1 of an external groove cut towards +Z turns
    /// clockwise (along the surface, then down the flank), r3 the other way;
    /// mirroring one axis swaps both.
    #[test]
    fn arc_directions() {
        let round = |size| Corner { size, kind: CornerKind::Round };
        let base = G75Cycle {
            flank_a: 900_000,
            flank_b: 900_000,
            width: 100_000,
            path: PathType::Finish,
            corners: [round(1_000), round(1_000), round(1_000), round(1_000)],
            ..seed()
        };
        let arcs = |c: &G75Cycle| -> Vec<bool> {
            expand_g75(c)
                .unwrap()
                .filter_map(|m| match m.motion {
                    Motion::Arc { clockwise, .. } => Some(clockwise),
                    _ => None,
                })
                .collect()
        };
        // sx = −1 (H < 0), sz = +1: r1 cw, r3 ccw, r4 ccw, r2 cw.
        assert_eq!(arcs(&base), [true, false, false, true]);
        assert_eq!(arcs(&G75Cycle { width: -100_000, ..base }), [false, true, true, false]);
        assert_eq!(
            arcs(&G75Cycle { depth: 200_000, from: Point::new(400_000, 300_000), ..base }),
            [false, true, true, false]
        );
        // Every arc's end points are within one increment of its radius.
        for m in expand_g75(&base).unwrap() {
            if let Motion::Arc { centre, .. } = m.motion {
                let dz = (m.to.z - centre.z).abs();
                let dx = (m.to.x - centre.x).abs() / 2;
                assert!(dz.max(dx) == 1_000 && dz.min(dx) == 0, "{m:?}");
            }
        }
    }

    #[test]
    fn errors_in_order() {
        // Corners larger than flank A (Y/f = 100000 with a = 90°).
        let c = G75Cycle {
            flank_a: 900_000,
            corners: [
                Corner { size: 60_000, kind: CornerKind::Chamfer },
                Corner::SHARP,
                Corner { size: 40_001, kind: CornerKind::Round },
                Corner::SHARP,
            ],
            ..seed()
        };
        assert_eq!(expand_g75(&c).err(), Some(CycleError::CornerTooLarge { edge: GrooveEdge::FlankA }));
        // Exactly the flank's length fits (exact comparison).
        let mut ok = c;
        ok.corners[corner::R3].size = 40_000;
        assert!(expand_g75(&ok).is_ok());
        // The bottom: t3 + t4 > d.
        let c = G75Cycle {
            corners: [
                Corner::SHARP,
                Corner::SHARP,
                Corner { size: 50_000, kind: CornerKind::Chamfer },
                Corner { size: 50_001, kind: CornerKind::Chamfer },
            ],
            ..seed()
        };
        assert_eq!(expand_g75(&c).err(), Some(CycleError::CornerTooLarge { edge: GrooveEdge::Bottom }));
        // A tool wider than the bottom.
        let c = G75Cycle { tool_width: Some(100_001), ..seed() };
        assert_eq!(
            expand_g75(&c).err(),
            Some(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(100_001, IS_C) })
        );
        let c = G75Cycle { tool_width: Some(100_000), ..seed() };
        assert!(expand_g75(&c).is_ok());
        // Too many pecks: pecks of 1 increment over 20 mm of diameter are
        // 200000 per plunge: 11 plunges (Δk = 1 mm) are too many, 2 are not.
        let c = G75Cycle { peck: 1, step: 10_000, ..seed() };
        assert_eq!(expand_g75(&c).err(), Some(CycleError::TooManyPecks { limit: MAX_PECKS }));
        let c = G75Cycle { peck: 1, step: 100_000, ..seed() };
        assert_eq!(expand_g75(&c).unwrap().filter(|m| matches!(m.role, Role::Peck(_))).count(), 400_000);
        // J2 makes no pecks: no limit.
        let c = G75Cycle { peck: 1, path: PathType::Finish, ..seed() };
        assert!(expand_g75(&c).is_ok());
        // Coordinates beyond the range: the groove's far flank at a start
        // near the Z limit (Z − 373205).
        let c = G75Cycle {
            start: Point::new(500_000, -MAX_LENGTH + 200_000),
            from: Point::new(600_000, -MAX_LENGTH + 200_000),
            ..seed()
        };
        // The first coordinate beyond: the third plunge at u = 200000? No:
        // Z = start − u, the steps reach Z = −MAX + 0 (in range); R3 at
        // u = 373205 is the first beyond.
        assert_eq!(
            expand_g75(&c).err(),
            Some(CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length::new(-MAX_LENGTH + 200_000 - 373_205, IS_C)
            })
        );
        // The pecks of layer 1 beyond X: S at X −MAX + 100000, sx = −1.
        let c = G75Cycle {
            start: Point::new(-MAX_LENGTH + 100_000, 300_000),
            from: Point::new(-MAX_LENGTH + 200_000, 300_000),
            ..seed()
        };
        // Peck 4 ends at y = 120000 > 100000: X = −MAX − 20000.
        assert_eq!(
            expand_g75(&c).err(),
            Some(CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length::new(-MAX_LENGTH - 20_000, IS_C)
            })
        );
    }

    /// The range check in closed form against a brute-force scan of the
    /// moves of a cycle expanded with a shifted start (same local path).
    #[test]
    fn range_check_matches_move_order() {
        // Layers need a step no wider than the tool (R-G75RIDGE).
        let cases = [
            G75Cycle { layer: Some(70_000), tool_width: Some(50_000), ..seed() },
            G75Cycle {
                layer: Some(70_000),
                step: 3_000,
                tool_width: Some(3_000),
                path: PathType::RoughAndFinish,
                ..seed()
            },
            G75Cycle {
                depth: 200_000,
                width: 100_000,
                layer: Some(45_000),
                tool_width: Some(60_000),
                from: Point::new(400_000, 300_000),
                path: PathType::RoughAndFinish,
                corners: [Corner { size: 3_000, kind: CornerKind::Round }; 4],
                ..seed()
            },
        ];
        for base in cases {
            let reference: Vec<Move> = expand_g75(&base).unwrap().collect();
            for dx in [0_i64, 1, 30_000, 100_000, 150_000, 170_000, 199_999, 200_000, 250_000] {
                for dz in [0_i64, 50_000, 100_000, 120_000, 373_205, 400_000] {
                    // Move S so that the range ends at local y = dx and
                    // u = dz, keeping the local path identical.
                    let sx = base.radial_sign();
                    let sz = base.axial_sign();
                    let start = Point::new(sx * (MAX_LENGTH - dx), sz * (MAX_LENGTH - dz));
                    let from = Point::new(start.x - sx * 10, start.z);
                    if start.x.abs() > MAX_LENGTH || from.x.abs() > MAX_LENGTH {
                        continue;
                    }
                    let c = G75Cycle { start, from, ..base };
                    // Brute force: the reference path moved by the shift.
                    let mut expect = None;
                    for m in &reference {
                        let mv =
                            |p: Point| Point::new(p.x + start.x - base.start.x, p.z + start.z - base.start.z);
                        let to = mv(m.to);
                        if m.role == Role::Return && m.to == base.from {
                            break;
                        }
                        let mut coords = std::vec![to.x, to.z];
                        if let Motion::Arc { centre, .. } = m.motion {
                            let cc = mv(centre);
                            coords.extend([cc.x, cc.z]);
                        }
                        if let Some(v) = coords.into_iter().find(|v| v.abs() > MAX_LENGTH) {
                            expect = Some(v);
                            break;
                        }
                    }
                    let got = expand_g75(&c).err();
                    match expect {
                        None => assert!(got.is_none(), "dx {dx} dz {dz}: {got:?}"),
                        Some(v) => assert_eq!(
                            got,
                            Some(CycleError::OutOfRange {
                                field: Field::PassCoordinate,
                                value: Length::new(v, base.units)
                            }),
                            "dx {dx} dz {dz}"
                        ),
                    }
                }
            }
        }
    }

    /// R-G75TIE on the slope example (examples/gsk980-g75-slope.nc) at IS-B:
    /// with A = 60° and a round r3 the depth of K1 is `Y − Δu − f·ρ·tan 30°·
    /// sin 60° − Δu·cos 60° = 9000 − 300 − 2·400·(1/2) − 300·(1/2) = 8150`,
    /// an integer computed from irrational factors (tan 30°·sin 60° = 1/2)
    /// that no enclosure decides; the second layer's right boundary
    /// `flankB_r(6000) = 4500·cot 60° + 6000 + 1500·cot 75° − 100 = 1500√3 +
    /// 5900 + 1500(2 − √3) = 8900` is another. Both are taken to lie on the
    /// integer, and the cycle expands.
    #[test]
    fn tie_values_are_decided() {
        let c = slope_example();
        let g = Geo::new(&c);
        // The 512-bit enclosures alone leave both floors open ...
        let slow = Ctx::<SLOW>::new(&g);
        assert_eq!(slow.eval(&g, Q::YK1).round(Rounding::Floor), None);
        assert_eq!(slow.eval(&g, Q::Right(6_000)).round(Rounding::Floor), None);
        // ... and R-G75TIE decides them on the boundary.
        let mut ev = Eval::new(g);
        assert_eq!(ev.floor(Q::YK1), Ok(8_150));
        assert_eq!(ev.floor(Q::Right(6_000)), Ok(8_900));
        assert_eq!(ev.plunges(6_000), Ok((1_833, 6_400)));
        assert_eq!(plunges_at(&g, &ev.fast.r, 6_000), Some((1_833, 6_400)));
        // U0.301 moves K1's depth off the integer (8148.5), the second
        // layer's boundary stays 8900.
        let moves: Vec<Move> = expand_g75(&G75Cycle { allowance_x: 301, ..c }).unwrap().collect();
        // Layer 2 (from y = 3000): plunges at 1833, 3833, 5833, then 6400.
        assert!(moves
            .iter()
            .any(|m| m.role == Role::Step(Plunge { layer: 2, number: 4 })
                && m.to == Point::new(77_000, -6_400)));
        // The rounded sign of an exact zero enclosed by irrational terms:
        // tan 30°·sin 60° − 1/2.
        let zero = crate::engine::real::tan::<SLOW>(600_000)
            .mul(&crate::engine::real::sin::<SLOW>(1_200_000))
            .sub(&Iv::half());
        assert_eq!(zero.sign(), None);
        assert_eq!(zero.sign_tie(), Some(Ordering::Equal));
    }

    /// The slope example expands (R-G75TIE), with the rough contour of §8
    /// step 9 worked out from the formulas (mpmath, 80 digits): `y_top =
    /// floor(y3) = floor(−3628.815…) = −3629`; R0 = (ceil(left(−3629)) =
    /// ceil(−947.602…), −3629) = (−947, −3629) (flank A: the chord of r3
    /// meets it at y_K1 = 8150 > y_top); K1 = (ceil(flankA_r(8150)) =
    /// ceil(4075·cot 60° + 100) = ceil(2452.702…), 8150); K2 =
    /// (ceil(4500·cot 60° + 400·tan 30° + 100) = ceil(2929.016…), 8700); K3 =
    /// (floor(8191.145…), 8700); y_K4 = floor(8029.409…) = 8029, K4 =
    /// (floor(flankB_r(8029)) = floor(8628.165…), 8029); R3 =
    /// (floor(right(−3629)) = floor(10190.041…), −3629). Absolute: X = 80000
    /// − y, Z = −u, the far side less w = 2500.
    #[test]
    fn slope_example_expands() {
        let c = slope_example();
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        let contour: Vec<(Motion, Point)> =
            moves.iter().filter(|m| m.role == Role::RoughContour).map(|m| (m.motion, m.to)).collect();
        assert_eq!(
            contour,
            [
                (Motion::Rapid, Point::new(83_629, 947)),
                (Motion::Feed, Point::new(71_850, -2_453)),
                (Motion::Feed, Point::new(71_300, -2_930)),
                (Motion::Feed, Point::new(71_300, -8_191 + 2_500)),
                (Motion::Feed, Point::new(71_971, -8_628 + 2_500)),
                (Motion::Feed, Point::new(83_629, -10_190 + 2_500)),
                // Back to A11 = (ceil(left(3000)) = ceil(966.025…), y_top).
                (Motion::Rapid, Point::new(83_629, -967)),
            ]
        );
        let p = groove_profile(&c).unwrap();
        assert_eq!(
            p.roughing(),
            [
                Point::new(83_629, 947),
                Point::new(71_850, -2_453),
                Point::new(71_300, -2_930),
                Point::new(71_300, -8_191),
                Point::new(71_971, -8_628),
                Point::new(83_629, -10_190),
            ]
        );
        // Three layers (V3 over 8.7 mm of diameter): every plunge retracts to
        // its layer's top (y_top, 3000, 6000); the path ends at `from`.
        let tops: Vec<i64> =
            moves.iter().filter(|m| matches!(m.role, Role::PlungeRetract(_))).map(|m| m.to.x).collect();
        assert!(tops.iter().all(|x| [83_629, 77_000, 74_000].contains(x)), "{tops:?}");
        assert!(tops.contains(&74_000));
        assert_eq!(moves.last().map(|m| m.to), Some(c.from));
    }

    /// A round r3 on a 60° flank whose K1 depth is exactly an integer, worked
    /// by hand: `G75.1 X50 Z0 H-10 D-6 A60` (B90, L0), `U0.2 W0.1 D1 P0010`
    /// (r3 a round of ρ = 1000), J0, IS-B diameter. t3 = 1000·tan 30° =
    /// 1000/√3, `f·t3·sin 60° = 2·(1000/√3)·(√3/2) = 1000`, so `y_K1 = 10000
    /// − 200 − 1000 − 200·cos 60° = 8700` exactly (R-G75TIE: taken on the
    /// integer). y_top = 0 (L = 0) < 8700, so K1 is a vertex: K1 =
    /// (ceil(flankA_r(8700)), 8700) = (ceil(4350/√3 + 100), 8700) =
    /// (ceil(2611.473…), 8700) = (2612, 8700). R0 = (ceil(left(0)), 0):
    /// flankA_r(0) = 100, chord3_r(0) = 5000/√3 + 1000/√3 + 100 − 4900·√3 <
    /// 0, so (100, 0). K2 = (ceil(6000/√3 + 100), 9800) = (ceil(3564.101…),
    /// 9800) = (3565, 9800). No r4: Q2 = (floor(5000/√3 + 6000 − 100), 9800)
    /// = (floor(8786.751…), 9800) = (8786, 9800), and R3 = (8786, 0) (cot 90°
    /// = 0). Absolute: X = 50000 − y, Z = −u.
    #[test]
    fn sixty_degree_round_with_an_integer_k1_depth() {
        let c = G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            from: Point::new(52_000, 1_000),
            start: Point::new(50_000, 0),
            peck: 2_000,
            step: 1_500,
            depth: -10_000,
            width: -6_000,
            flank_a: 600_000,
            flank_b: 900_000,
            slope: 0,
            retract: 200,
            layer: None,
            allowance_x: 200,
            allowance_z: 100,
            tool_width: None,
            path: PathType::Rough,
            corners: [
                Corner::SHARP,
                Corner::SHARP,
                Corner { size: 1_000, kind: CornerKind::Round },
                Corner::SHARP,
            ],
        };
        let g = Geo::new(&c);
        // Undecided at 512 bits without the rule.
        assert_eq!(Ctx::<SLOW>::new(&g).eval(&g, Q::YK1).round(Rounding::Floor), None);
        let p = groove_profile(&c).unwrap();
        assert_eq!(
            p.roughing(),
            [
                Point::new(50_000, -100),
                Point::new(41_300, -2_612),
                Point::new(40_200, -3_565),
                Point::new(40_200, -8_786),
                Point::new(50_000, -8_786),
            ]
        );
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        let contour: Vec<Point> =
            moves.iter().filter(|m| m.role == Role::RoughContour).map(|m| m.to).collect();
        // A11 = (ceil(left(9800)), 0) = (3565, 0): rapid to R0, the feeds, back.
        assert_eq!(
            contour,
            [
                Point::new(50_000, -100),
                Point::new(41_300, -2_612),
                Point::new(40_200, -3_565),
                Point::new(40_200, -8_786),
                Point::new(50_000, -8_786),
                Point::new(50_000, -3_565),
            ]
        );
    }

    /// The commonest tie family: a round bottom corner whose radius (in
    /// X-word units) equals the X allowance. Then `f·t3·sin a = f·ρ·tan(a/2)·
    /// sin a = f·ρ·(1 − cos a)`, so the depth of K1 is `Y − Δu − f·ρ +
    /// (f·ρ − Δu)·cos a = Y − 2Δu`, an integer, at every angle; R-G75TIE
    /// takes it on the integer.
    #[test]
    fn round_corner_equal_to_the_allowance_is_decided() {
        // The golden square groove with A80: U0.8 and D0.4 (f·ρ = 800 = Δu).
        let c = G75Cycle { flank_a: 800_000, allowance_x: 800, ..square() };
        let g = Geo::new(&c);
        assert_eq!(Ctx::<SLOW>::new(&g).eval(&g, Q::YK1).round(Rounding::Floor), None);
        // y_K1 = 6000 − 1600 = 4400; K1 = (ceil(2200·cot 80° + 200) =
        // ceil(587.919…), 4400); y_K4 = 6000 − 800 − 600 − 800·0 = 4600 (B90,
        // exact). R0 (200, 0), K2 (ceil(1064.620…), 5200), K3
        // (floor(8028.980…), 5200), K4 and R3 at floor(8328.980…) (mpmath).
        let p = groove_profile(&c).unwrap();
        assert_eq!(
            p.roughing(),
            [
                Point::new(30_000, -200),
                Point::new(25_600, -588),
                Point::new(24_800, -1_065),
                Point::new(24_800, -8_028),
                Point::new(25_400, -8_328),
                Point::new(30_000, -8_328),
            ]
        );
        assert!(expand_g75(&c).is_ok());
        assert!(expand_g75(&G75Cycle { flank_a: 900_000, ..c }).is_ok());
        assert!(expand_g75(&G75Cycle { allowance_x: 799, ..c }).is_ok());
        assert!(expand_g75(&G75Cycle { path: PathType::Finish, ..c }).is_ok());
    }

    /// R-G75K1Y: K4's u is `floor(flankB_r(y_K4))` at the integer `y_K4 =
    /// floor(Y − Δu − f·t4·sin b − Δu·cos b)`, not at the exact real depth.
    /// Here the exact depth is `80 + 16·cos 15° = 95.4548…`, so y_K4 = 95 and
    /// `flankB_r(95) = 48·cot 23.7156° + 89 + (1/2)·cot 15° = 200.1322…`
    /// (mpmath, 60 digits): K4 = (200, 95); at the exact depth the flank
    /// would give floor(199.2835…) = 199 instead.
    #[test]
    fn k_vertices_use_the_integer_depth() {
        let c = G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            from: Point::new(52_000, 1_500),
            start: Point::new(50_000, 1_000),
            peck: 10,
            step: 63,
            depth: -96,
            width: -89,
            flank_a: 237_156,
            flank_b: 150_000,
            slope: 0,
            retract: 1_599,
            layer: None,
            allowance_x: 0,
            allowance_z: 0,
            tool_width: Some(53),
            path: PathType::RoughAndFinish,
            corners: [
                Corner { size: 14, kind: CornerKind::Chamfer },
                Corner { size: 165, kind: CornerKind::Chamfer },
                Corner::SHARP,
                Corner { size: 8, kind: CornerKind::Round },
            ],
        };
        let p = groove_profile(&c).unwrap();
        // R0, Q1, K3, K4, R3: K4 = (200, 95) → X = 50000 − 95, Z = 1000 − 200.
        assert_eq!(p.roughing()[3], Point::new(49_905, 800));
        // In the moves, less w = 53: Z = 1000 − 147.
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        assert!(moves.iter().any(|m| m.role == Role::RoughContour && m.to == Point::new(49_905, 853)));
    }

    /// R-G75ARCZERO: a round whose rounded end is its start is left out like
    /// any empty move. At A = 0.0001° a round r3 of ρ = 1 has `t3 =
    /// tan(0.00005°) ≈ 8.7·10⁻⁷`, so T3a and T3b both round to (P1.u, Y) with
    /// P1.u = `1·cot 0.0001°` = 572957.795… → 572958.
    #[test]
    fn empty_arc_is_dropped() {
        let c = G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            from: Point::new(110, 10),
            start: Point::new(100, 0),
            peck: 2,
            step: 2,
            depth: -2,
            width: 10,
            flank_a: 1,
            flank_b: 900_000,
            slope: 0,
            retract: 0,
            layer: None,
            allowance_x: 0,
            allowance_z: 0,
            tool_width: None,
            path: PathType::Finish,
            corners: [
                Corner::SHARP,
                Corner::SHARP,
                Corner { size: 1, kind: CornerKind::Round },
                Corner::SHARP,
            ],
        };
        // The profile keeps the round (R-G75PROFILE), of zero length.
        let p = groove_profile(&c).unwrap();
        let f = p.finishing();
        assert_eq!(f[1].at, Point::new(98, 572_958));
        assert_eq!(f[2].at, f[1].at);
        assert!(matches!(f[2].segment, ProfileSegment::Arc { .. }));
        // The moves do not: S, P1 (= T3a = T3b), P2, P3.
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        assert!(moves.iter().all(|m| !matches!(m.motion, Motion::Arc { .. })));
        let feeds: Vec<Point> = moves.iter().filter(|m| m.motion == Motion::Feed).map(|m| m.to).collect();
        assert_eq!(feeds, [Point::new(98, 572_958), Point::new(98, 572_968), Point::new(100, 572_968)]);
    }

    /// K1 (K4) is a vertex only below the layer top: when the moved chord
    /// meets its flank at or above `y_top` the chord is the boundary over
    /// the whole depth and R0 (R3) lies on it (§8, R-G75K1Y). A square
    /// groove (exact) with chamfers r3 = r4 = 3 over a depth of 4 and Δu = 1
    /// at f = 1: y_K1 = 4 − 1 − 3·1 − 1·0 = 0 = y_top.
    #[test]
    fn k1_above_the_top_is_not_a_vertex() {
        let c = G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Radius,
            from: Point::new(110, 10),
            start: Point::new(100, 0),
            peck: 2,
            step: 2,
            depth: -4,
            width: 10,
            flank_a: 900_000,
            flank_b: 900_000,
            slope: 0,
            retract: 0,
            layer: None,
            allowance_x: 1,
            allowance_z: 0,
            tool_width: None,
            path: PathType::Rough,
            corners: [
                Corner::SHARP,
                Corner::SHARP,
                Corner { size: 3, kind: CornerKind::Chamfer },
                Corner { size: 3, kind: CornerKind::Chamfer },
            ],
        };
        // left(0) = max(0, 3 − (3 − 0)·cot 45°) = 0; right(0) = min(10, 7 +
        // 3) = 10. R0 (0, 0), K2 (3, 3), K3 (7, 3), R3 (10, 0): X = 100 − y,
        // Z = u.
        let p = groove_profile(&c).unwrap();
        assert_eq!(
            p.roughing(),
            [Point::new(100, 0), Point::new(97, 3), Point::new(97, 7), Point::new(100, 10)]
        );
        // Δu = 0: y_K1 = 1 > 0, K1 = (0, 1) and K4 = (10, 1) are vertices.
        let p = groove_profile(&G75Cycle { allowance_x: 0, ..c }).unwrap();
        assert_eq!(
            p.roughing(),
            [
                Point::new(100, 0),
                Point::new(99, 0),
                Point::new(96, 3),
                Point::new(96, 7),
                Point::new(99, 10),
                Point::new(100, 10)
            ]
        );
    }

    /// A groove on a slope, with four rounds and layers: the moves satisfy
    /// the invariants of docs/G75.md §10 that need no exact boundary.
    #[test]
    fn slope_groove_invariants() {
        // U0.301 instead of U0.3 and B74 instead of B75: no value on a
        // rounding boundary (tie_values_are_decided has the example itself).
        let c = G75Cycle { allowance_x: 301, flank_b: 740_000, ..slope_example() };
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        let local = |p: Point| (c.axial_sign() * (p.z - c.start.z), c.radial_sign() * (p.x - c.start.x));
        let mut at = c.from;
        for m in &moves {
            assert_ne!(m.to, at);
            let ((u0, y0), (u1, y1)) = (local(at), local(m.to));
            match m.role {
                Role::Peck(_) => assert!(u0 == u1 && y1 > y0 && y1 - y0 <= c.peck + c.retract * 2),
                Role::Step(_) => assert!(y0 == y1 && u1 > u0 && u1 - u0 <= c.step),
                _ => {}
            }
            at = m.to;
        }
        assert_eq!(at, c.from);
        // y3 = −2·u3·tan 10° < 0: the opening rises towards the far side.
        let p = groove_profile(&c).unwrap();
        let last = p.finishing().last().unwrap();
        assert!(local(last.at).1 < 0);
        assert_eq!(p.finishing().len(), 8);
        assert_eq!(p.roughing().len(), 6);
        // The fast and slow contexts agree on every value they decide.
        let mut ev = Eval::new(Geo::new(&c));
        let slow = Ctx::<SLOW>::new(&ev.g);
        for q in [
            Q::U3,
            Q::Y3,
            Q::Left(3_000),
            Q::YK4,
            Q::FlankA(8_148),
            Q::FlankB(8_029),
            Q::C1U,
            Q::C2Y,
            Q::T4cU,
            Q::T2sY,
        ] {
            let fast = ev.nearest(q).unwrap();
            assert_eq!(slow.eval(&ev.g, q).round(Rounding::Nearest), Some(fast), "{q:?}");
        }
        // y_K1 = 9000 − 301 − 400 − 150.5 = 8148.5 exactly: its floor is
        // decided, its nearest only by R-G75TIE (the tie goes up).
        assert_eq!(ev.floor(Q::YK1), Ok(8_148));
        assert_eq!(slow.eval(&ev.g, Q::YK1).round(Rounding::Nearest), None);
        assert_eq!(ev.nearest(Q::YK1), Ok(8_149));
    }

    /// `G00 X90 Z12; G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10; G75.1
    /// R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111` at IS-B.
    fn slope_example() -> G75Cycle {
        G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            start: Point::new(80_000, 0),
            from: Point::new(90_000, 12_000),
            peck: 1_500,
            step: 2_000,
            depth: -9_000,
            width: -6_000,
            flank_a: 600_000,
            flank_b: 750_000,
            slope: 100_000,
            retract: 300,
            layer: Some(3_000),
            allowance_x: 300,
            allowance_z: 100,
            tool_width: Some(2_500),
            path: PathType::RoughAndFinish,
            corners: [
                Corner { size: 500, kind: CornerKind::Round },
                Corner { size: 500, kind: CornerKind::Round },
                Corner { size: 400, kind: CornerKind::Round },
                Corner { size: 400, kind: CornerKind::Round },
            ],
        }
    }

    /// The benchmark's wide groove (`benches/src/cases.rs`): `G00 X210 Z5;
    /// G75.1 X200 Z0 P500 Q300 H-40 D-200 A80 B70; G75.1 R0.1 V10 I3 J1` at
    /// IS-B: four layers of about 660 plunges.
    fn wide_example() -> G75Cycle {
        G75Cycle {
            units: Units::IS_B_METRIC,
            x_mode: XMode::Diameter,
            from: Point::new(210_000, 5_000),
            start: Point::new(200_000, 0),
            peck: 500,
            step: 300,
            depth: -40_000,
            width: -200_000,
            flank_a: 800_000,
            flank_b: 700_000,
            slope: 0,
            retract: 100,
            layer: Some(10_000),
            allowance_x: 0,
            allowance_z: 0,
            tool_width: Some(3_000),
            path: PathType::RoughAndFinish,
            corners: [Corner::SHARP; 4],
        }
    }

    #[test]
    fn wide_groove() {
        let c = wide_example();
        let t = std::time::Instant::now();
        let n = expand_g75(&c).unwrap().count();
        std::println!("wide: {n} moves in {:?}", t.elapsed());
        let t = std::time::Instant::now();
        let n2 = expand_g75(&seed()).unwrap().count();
        std::println!("seed: {n2} moves in {:?}", t.elapsed());
        let t = std::time::Instant::now();
        let n3 =
            expand_g75(&G75Cycle { allowance_x: 301, flank_b: 740_000, ..slope_example() }).unwrap().count();
        std::println!("slope: {n3} moves in {:?}", t.elapsed());
        let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
        // Every plunge of a layer reaches the layer's bottom, and the layers
        // are 10 mm of diameter deep.
        let bottoms: Vec<i64> =
            moves.iter().filter(|m| matches!(m.role, Role::PlungeRetract(_))).map(|m| m.to.x).collect();
        assert!(bottoms.iter().all(|x| [200_000, 190_000, 180_000, 170_000].contains(x)));
        assert_eq!(moves.last().map(|m| m.to), Some(c.from));
    }

    /// A cutting move of the finishing contour: local end and arc centre.
    type ContourMove = (i64, i64, Option<(i64, i64)>);

    /// A small deterministic generator for the sweeps.
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }

        fn range(&mut self, lo: i64, hi: i64) -> i64 {
            let span = u64::try_from(hi - lo + 1).unwrap();
            lo + i64::try_from(self.next() % span).unwrap()
        }
    }

    /// A random cycle: small sizes, any signs, units, J, corners.
    fn random_cycle(r: &mut Rng, square: bool) -> G75Cycle {
        let units = Units {
            system: if r.range(0, 1) == 0 { IncrementSystem::IsB } else { IncrementSystem::IsC },
            unit: if r.range(0, 1) == 0 { InputUnit::Metric } else { InputUnit::Inch },
        };
        let x_mode = if r.range(0, 1) == 0 { XMode::Diameter } else { XMode::Radius };
        let sx = if r.range(0, 1) == 0 { -1 } else { 1 };
        let sz = if r.range(0, 1) == 0 { -1 } else { 1 };
        let depth = r.range(1, 40);
        let mut corners = [Corner::SHARP; 4];
        for k in &mut corners {
            if r.range(0, 2) == 0 {
                let kind = if r.range(0, 1) == 0 { CornerKind::Round } else { CornerKind::Chamfer };
                *k = Corner { size: r.range(1, 6), kind };
            }
        }
        let (flank_a, flank_b, slope) = if square {
            (900_000, 900_000, 0)
        } else {
            let b = u32::try_from(r.range(100_000, 900_000)).unwrap();
            let l = if r.range(0, 1) == 0 {
                0
            } else {
                u32::try_from(r.range(0, i64::from(b) - 1).min(600_000)).unwrap()
            };
            (u32::try_from(r.range(100_000, 900_000)).unwrap(), b, l)
        };
        let start = Point::new(100_000, 5_000);
        G75Cycle {
            units,
            x_mode,
            from: Point::new(start.x - sx * 10, start.z - sz * 10),
            start,
            peck: r.range(1, 12),
            step: r.range(1, 8),
            depth: sx * depth,
            width: sz * r.range(0, 30),
            flank_a,
            flank_b,
            slope,
            retract: r.range(0, 3),
            layer: if r.range(0, 1) == 0 { None } else { Some(r.range(1, 20)) },
            allowance_x: r.range(0, 3).min(depth - 1),
            allowance_z: r.range(0, 3),
            tool_width: if r.range(0, 1) == 0 { None } else { Some(r.range(0, 8)) },
            path: match r.range(0, 2) {
                0 => PathType::Rough,
                1 => PathType::RoughAndFinish,
                _ => PathType::Finish,
            },
            corners,
        }
    }

    /// docs/G75.md §10 on right-angle grooves, where every boundary is exact
    /// in doubled integers: no empty move, pecks along X taking at most Δi
    /// of new depth, steps along Z of at most Δk, every roughing position
    /// with its width inside the roughing region, every plunge reaching its
    /// layer's bottom, the finishing contour through the profile points,
    /// the path ending at `from`.
    #[test]
    fn square_groove_sweep() {
        let mut r = Rng(0x1234_5678_9ABC_DEF1);
        let mut expanded = 0;
        for _ in 0..20_000 {
            let c = random_cycle(&mut r, true);
            let Ok(moves) = expand_g75(&c) else { continue };
            let moves: Vec<Move> = moves.collect();
            expanded += 1;
            let f = c.x_mode.factor();
            let (yy, d, du, dw, w) =
                (c.depth.abs(), c.width.abs(), c.allowance_x, c.allowance_z, c.width_of_tool());
            let (t3, t4) = (c.corners[corner::R3].size, c.corners[corner::R4].size);
            let bottom = yy - du;
            // f·left(y), f·right(y), exact (cot 90° = 0, cot 45° = 1).
            let left_f = |y: i64| {
                let flank = f * dw;
                if t3 > 0 {
                    flank.max(f * (t3 + dw) - (bottom - y))
                } else {
                    flank
                }
            };
            let right_f = |y: i64| {
                let flank = f * (d - dw);
                if t4 > 0 {
                    flank.min(f * (d - t4 - dw) + (bottom - y))
                } else {
                    flank
                }
            };
            let local = |p: Point| (c.axial_sign() * (p.z - c.start.z), c.radial_sign() * (p.x - c.start.x));
            let mut at = c.from;
            let mut deepest: Option<i64> = None;
            let mut last_peck: Option<(Plunge, i64)> = None;
            let mut layer_bottom: Vec<i64> = Vec::new();
            for m in &moves {
                assert_ne!(m.to, at, "{c:?}");
                let ((u0, y0), (u1, y1)) = (local(at), local(m.to));
                match m.role {
                    Role::Peck(p) => {
                        assert!(u0 == u1 && y1 > y0, "{c:?}");
                        let before = deepest.map_or(y0, |v| v.max(y0));
                        assert!(y1 - before <= c.peck, "{c:?}");
                        deepest = Some(before.max(y1));
                        last_peck = Some((p, y1));
                    }
                    Role::PeckRetract(_) => {
                        assert!(u0 == u1 && y1 < y0 && y0 - y1 <= f * c.retract, "{c:?}");
                    }
                    Role::PlungeRetract(p) => {
                        let (q, y) = last_peck.unwrap();
                        assert_eq!(p, q);
                        let l = usize::try_from(p.layer).unwrap();
                        if layer_bottom.len() < l {
                            layer_bottom.push(y);
                        }
                        assert_eq!(layer_bottom[l - 1], y, "every plunge reaches its layer's bottom");
                        deepest = None;
                    }
                    Role::Step(_) => assert!(y0 == y1 && u1 > u0 && u1 - u0 <= c.step, "{c:?}"),
                    _ => {}
                }
                let roughing = matches!(
                    m.role,
                    Role::Peck(_)
                        | Role::PeckRetract(_)
                        | Role::PlungeRetract(_)
                        | Role::Step(_)
                        | Role::LayerChange(_)
                        | Role::RoughContour
                );
                if roughing && y1 > 0 {
                    assert!(y1 <= bottom, "{c:?}");
                    assert!(f * u1 >= left_f(y1) && f * (u1 + w) <= right_f(y1), "{c:?} {m:?}");
                }
                at = m.to;
            }
            assert_eq!(at, c.from);
            if c.path.roughs() {
                assert_eq!(layer_bottom.last().copied(), Some(bottom));
                if let Some(v) = c.layer {
                    assert!(layer_bottom.windows(2).all(|p| p[1] > p[0] && p[1] - p[0] <= v));
                }
            }
            if c.path.finishes() {
                // The contour's cutting moves (docs/G75.md §3 with a = b = 90°).
                let [r1, r2, r3, r4] = c.corners;
                let arc = |k: Corner, centre: (i64, i64)| (k.kind == CornerKind::Round).then_some(centre);
                let mut expected: Vec<ContourMove> = Vec::new();
                if r1.size > 0 {
                    expected.push((0, f * r1.size, arc(r1, (-r1.size, f * r1.size))));
                }
                if r3.size > 0 {
                    expected.push((0, yy - f * r3.size, None));
                    expected.push((r3.size, yy, arc(r3, (r3.size, yy - f * r3.size))));
                } else {
                    expected.push((0, yy, None));
                }
                if r4.size > 0 {
                    expected.push((d - r4.size - w, yy, None));
                    expected.push((d - w, yy - f * r4.size, arc(r4, (d - r4.size - w, yy - f * r4.size))));
                } else {
                    expected.push((d - w, yy, None));
                }
                if r2.size > 0 {
                    expected.push((d - w, f * r2.size, None));
                    expected.push((d + r2.size - w, 0, arc(r2, (d + r2.size - w, f * r2.size))));
                } else {
                    expected.push((d - w, 0, None));
                }
                let mut pos = if r1.size > 0 { (-r1.size, 0) } else { (0, 0) };
                let expected: Vec<_> = expected
                    .into_iter()
                    .filter(|e| {
                        let keep = (e.0, e.1) != pos;
                        pos = (e.0, e.1);
                        keep
                    })
                    .collect();
                let got: Vec<ContourMove> = moves
                    .iter()
                    .filter(|m| m.role == Role::FinishContour && m.motion != Motion::Rapid)
                    .map(|m| {
                        let (u, y) = local(m.to);
                        let centre = match m.motion {
                            Motion::Arc { centre, .. } => Some(local(centre)),
                            _ => None,
                        };
                        (u, y, centre)
                    })
                    .collect();
                assert_eq!(got, expected, "{c:?}");
            }
        }
        assert!(expanded > 5_000, "only {expanded} cycles expanded");
    }

    /// Every rounded value of the profile and of layer 1's plunge range
    /// against the formulas of docs/G75.md §3–§8 evaluated in `f64` (where
    /// the float is clear of a rounding boundary), at arbitrary angles.
    #[test]
    fn formulas_against_floats() {
        let mut r = Rng(0xDEAD_BEEF_CAFE_F00D);
        let mut compared = 0;
        for _ in 0..3_000 {
            let mut c = random_cycle(&mut r, false);
            c.depth *= 1_000;
            c.width *= 1_000;
            c.peck *= 1_000;
            c.step *= 1_000;
            c.layer = c.layer.map(|v| v * 1_000);
            c.allowance_x *= 100;
            c.allowance_z *= 100;
            for k in &mut c.corners {
                k.size *= 300;
            }
            c.start = Point::new(10_000_000, 2_000_000);
            c.from = Point::new(c.start.x - c.radial_sign() * 10, c.start.z - c.axial_sign() * 10);
            let Ok(p) = groove_profile(&c) else { continue };
            let deg = |v: u32| f64::from(v) / 10_000.0 * core::f64::consts::PI / 180.0;
            let (a, b, l) = (deg(c.flank_a), deg(c.flank_b), deg(c.slope));
            let f = c.x_mode.factor() as f64;
            let (yy, d, du, dw, w) = (
                c.depth.abs() as f64,
                c.width.abs() as f64,
                c.allowance_x as f64,
                c.allowance_z as f64,
                c.width_of_tool() as f64,
            );
            let tl = |i: usize, half: f64| {
                let k = c.corners[i];
                let s = k.size as f64;
                if k.kind == CornerKind::Round {
                    s * half.tan()
                } else {
                    s
                }
            };
            let (t1, t2, t3, t4) =
                (tl(0, (a + l) / 2.0), tl(1, (b - l) / 2.0), tl(2, a / 2.0), tl(3, b / 2.0));
            let rho = |i: usize| c.corners[i].size as f64;
            let cot = |x: f64| x.cos() / x.sin();
            let p1 = yy / f * cot(a);
            let u3 = (p1 + d + yy / f * cot(b)) / (1.0 - l.tan() * cot(b));
            let y3 = -f * u3 * l.tan();
            let flank_a = |y: f64| y / f * cot(a) + dw;
            let flank_b = |y: f64| p1 + d + (yy - y) / f * cot(b) - dw;
            let chord3 = |y: f64| p1 + t3 + dw - (yy - du - y) / f * cot(a / 2.0);
            let chord4 = |y: f64| p1 + d - t4 - dw + (yy - du - y) / f * cot(b / 2.0);
            let mut exp: Vec<(f64, f64)> = Vec::new();
            if c.corners[0].size > 0 {
                exp.push((-t1 * l.cos(), f * t1 * l.sin()));
                exp.push((t1 * a.cos(), f * t1 * a.sin()));
            } else {
                exp.push((0.0, 0.0));
            }
            if c.corners[2].size > 0 {
                exp.push((p1 - t3 * a.cos(), yy - f * t3 * a.sin()));
                exp.push((p1 + t3, yy));
            } else {
                exp.push((p1, yy));
            }
            if c.corners[3].size > 0 {
                exp.push((p1 + d - t4, yy));
                exp.push((p1 + d + t4 * b.cos(), yy - f * t4 * b.sin()));
            } else {
                exp.push((p1 + d, yy));
            }
            if c.corners[1].size > 0 {
                exp.push((u3 - t2 * b.cos(), y3 + f * t2 * b.sin()));
                exp.push((u3 + t2 * l.cos(), y3 - f * t2 * l.sin()));
            } else {
                exp.push((u3, y3));
            }
            let mut centres: Vec<Option<(f64, f64)>> = std::vec![None; exp.len()];
            let mut i = 1;
            if c.corners[0].size > 0 {
                if c.corners[0].kind == CornerKind::Round {
                    centres[i] =
                        Some((t1 * a.cos() - rho(0) * a.sin(), f * t1 * a.sin() + f * rho(0) * a.cos()));
                }
                i += 1;
            }
            i += 1;
            if c.corners[2].size > 0 {
                if c.corners[2].kind == CornerKind::Round {
                    centres[i] = Some((p1 + t3, yy - f * rho(2)));
                }
                i += 1;
            }
            i += 1;
            if c.corners[3].size > 0 {
                if c.corners[3].kind == CornerKind::Round {
                    centres[i] = Some((p1 + d - t4, yy - f * rho(3)));
                }
                i += 1;
            }
            i += 1;
            if c.corners[1].size > 0 && c.corners[1].kind == CornerKind::Round {
                centres[i] = Some((
                    u3 - t2 * b.cos() + rho(1) * b.sin(),
                    y3 + f * t2 * b.sin() + f * rho(1) * b.cos(),
                ));
            }
            let local = |q: Point| (c.axial_sign() * (q.z - c.start.z), c.radial_sign() * (q.x - c.start.x));
            // `v` rounds to `got` unless the float is within 1e-6 of a boundary.
            let check = |v: f64, got: i64, what: &str| {
                let near = (v + 0.5 - (v + 0.5).round()).abs() < 1e-6;
                if !near {
                    assert_eq!((v + 0.5).floor() as i64, got, "{what}: {v} in {c:?}");
                }
            };
            assert_eq!(p.finishing().len(), exp.len());
            for ((q, e), ctr) in p.finishing().iter().zip(&exp).zip(&centres) {
                let (u, y) = local(q.at);
                check(e.0, u, "u");
                check(e.1, y, "y");
                match (q.segment, ctr) {
                    (ProfileSegment::Arc { centre, .. }, Some(cc)) => {
                        let (cu, cy) = local(centre);
                        check(cc.0, cu, "centre u");
                        check(cc.1, cy, "centre y");
                    }
                    (ProfileSegment::Arc { .. }, None) | (_, Some(_)) => panic!("arc mismatch {c:?}"),
                    _ => {}
                }
            }
            // Roughing vertices: ceil on the left, floor on the right.
            let ceil = |v: f64, got: i64| {
                if (v - v.round()).abs() > 1e-6 {
                    assert_eq!(v.ceil() as i64, got, "ceil {v} {c:?}");
                }
            };
            let floor = |v: f64, got: i64| {
                if (v - v.round()).abs() > 1e-6 {
                    assert_eq!(v.floor() as i64, got, "floor {v} {c:?}");
                }
            };
            let rv: Vec<(i64, i64)> = p.roughing().iter().map(|q| local(*q)).collect();
            let y_top = rv[0].1;
            floor(y3, y_top);
            let left = |y: f64| if c.corners[2].size > 0 { flank_a(y).max(chord3(y)) } else { flank_a(y) };
            let right = |y: f64| if c.corners[3].size > 0 { flank_b(y).min(chord4(y)) } else { flank_b(y) };
            // R0, R3 on left/right (R-G75MAXMIN); K1, K4 on the flanks at the
            // integer depth, only below y_top (R-G75K1Y). A depth too near an
            // integer for the float leaves the vertex count open: skipped.
            let bottom = yy - du;
            let near_int = |v: f64| (v - v.round()).abs() < 1e-6;
            let yk1 = bottom - f * t3 * a.sin() - du * a.cos();
            let yk4 = bottom - f * t4 * b.sin() - du * b.cos();
            if (c.corners[2].size > 0 && near_int(yk1)) || (c.corners[3].size > 0 && near_int(yk4)) {
                continue;
            }
            ceil(left(y_top as f64), rv[0].0);
            let mut k = 1;
            if c.corners[2].size > 0 {
                let y = yk1.floor();
                if y as i64 > y_top {
                    assert_eq!(rv[k].1, y as i64, "{c:?}");
                    ceil(flank_a(y), rv[k].0);
                    k += 1;
                }
                ceil(p1 + t3 + dw, rv[k].0);
                k += 1;
            } else {
                ceil(flank_a(bottom), rv[k].0);
                k += 1;
            }
            if c.corners[3].size > 0 {
                floor(p1 + d - t4 - dw, rv[k].0);
                k += 1;
                let y = yk4.floor();
                if y as i64 > y_top {
                    assert_eq!(rv[k].1, y as i64, "{c:?}");
                    floor(flank_b(y), rv[k].0);
                    k += 1;
                }
            } else {
                floor(flank_b(bottom), rv[k].0);
                k += 1;
            }
            floor(right(y_top as f64), rv[k].0);
            assert_eq!(rv.len(), k + 1, "{c:?}");
            // Layer 1's plunge range, through the first move's Z (A11).
            if let Ok(mut moves) = expand_g75(&c) {
                let y1 = c.layer.map_or(bottom, |v| (v as f64).min(bottom));
                let first = moves.next().unwrap();
                ceil(left(y1), local(first.to).0);
                if c.path.roughs() {
                    // The last plunge of layer 1: before the first layer change.
                    let last = moves
                        .take_while(|m| !matches!(m.role, Role::LayerChange(_) | Role::Approach))
                        .filter(|m| matches!(m.role, Role::PlungeRetract(_)))
                        .last()
                        .unwrap();
                    floor(right(y1) - w, local(last.to).0);
                }
                compared += 1;
            }
        }
        assert!(compared > 500, "only {compared} cycles compared");
    }

    #[test]
    fn size_of_the_iterator() {
        let s = core::mem::size_of::<G75Moves>();
        assert!(s <= 2_200, "G75Moves is {s} bytes");
    }
}
