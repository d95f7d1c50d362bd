//! The G75.1 proof harnesses (docs/G75.md §10): one function per property,
//! shared by Kani (`proofs/src/kani_proofs.rs`) and the tests
//! (`proofs/tests/g75_harnesses.rs`), like [`crate::harness`] for G76.
//!
//! The properties that need the groove's exact boundaries are stated for
//! right-angle grooves (A = B = 90°, L = 0), where every boundary is an
//! integer or a half-integer and the check is exact integer arithmetic; the
//! differential tests (`proofs/tests/g75_equivalence.rs`) carry them to every
//! angle through the reference model, whose geometry is exact.

use cycleref::g75::{corner, Corner, CornerKind, G75Cycle, PathType, RIGHT_ANGLE};
use cycleref::{CycleError, IncrementSystem, InputUnit, Motion, Move, Point, Role, Units, XMode};

use crate::cover;
use crate::verify::{any_in, assume, declare};

/// The inputs a G75.1 harness may choose: inclusive ranges in least
/// increments and 0.0001°, and codes for the discrete choices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GrooveDomain {
    /// |H|, X-word units.
    pub depth: (i64, i64),
    /// |D|.
    pub width: (i64, i64),
    /// P(Δi).
    pub peck: (i64, i64),
    /// Q(Δk).
    pub step: (i64, i64),
    /// R(e).
    pub retract: (i64, i64),
    /// V(Δv); 0 = no V.
    pub layer: (i64, i64),
    /// U(Δu).
    pub allowance_x: (i64, i64),
    /// W(Δw).
    pub allowance_z: (i64, i64),
    /// I(r); -1 = no I (pointed tool).
    pub tool_width: (i64, i64),
    /// Size of each corner r1..r4.
    pub corner: (i64, i64),
    /// Kinds of the corners as 4 bits (bit i set: corner i is a round).
    pub corner_kinds: (i64, i64),
    /// A and B, 0.0001°.
    pub flank: (i64, i64),
    /// L, 0.0001°.
    pub slope: (i64, i64),
    /// J: 0, 1, 2.
    pub path: (i64, i64),
    /// Bit 0: H > 0 (internal); bit 1: D < 0.
    pub signs: (i64, i64),
    /// Bit 0 IS-C, bit 1 inch, bit 2 radius X.
    pub units: (i64, i64),
}

impl GrooveDomain {
    /// Right-angle grooves small enough to enumerate a slice of: every
    /// exact-boundary property is checked here.
    pub const SQUARE: GrooveDomain = GrooveDomain {
        depth: (1, 12),
        width: (0, 10),
        peck: (1, 5),
        step: (1, 4),
        retract: (0, 1),
        layer: (0, 5),
        allowance_x: (0, 2),
        allowance_z: (0, 2),
        tool_width: (-1, 3),
        corner: (0, 2),
        corner_kinds: (0, 15),
        flank: (900_000, 900_000),
        slope: (0, 0),
        path: (0, 2),
        signs: (0, 3),
        units: (0, 7),
    };

    /// Wider right-angle grooves, for sampling (`proofs/tests/g75_exact.rs`,
    /// `proofs/tests/g75_harnesses.rs`): up to 400 increments deep and wide,
    /// up to 120-increment layers, tool widths to 80, corners to 40 of every
    /// kind, every unit code, sign and J.
    pub const SQUARE_WIDE: GrooveDomain = GrooveDomain {
        depth: (1, 400),
        width: (0, 400),
        peck: (1, 60),
        step: (1, 60),
        retract: (0, 20),
        layer: (0, 120),
        allowance_x: (0, 40),
        allowance_z: (0, 40),
        tool_width: (-1, 80),
        corner: (0, 40),
        ..GrooveDomain::SQUARE
    };

    /// The documented ranges (the manual's range tables), for sampling and
    /// for the no-panic proof.
    pub const FULL: GrooveDomain = GrooveDomain {
        depth: (1, 99_999_999),
        width: (0, 99_999_999),
        peck: (1, 99_999_999),
        step: (1, 99_999_999),
        retract: (0, 999_999),
        layer: (0, 99_999_999),
        allowance_x: (0, 99_999_999),
        allowance_z: (0, 99_999_999),
        tool_width: (-1, 99_999_999),
        corner: (0, 999_999),
        corner_kinds: (0, 15),
        flank: (1, 900_000),
        slope: (0, 899_999),
        path: (0, 2),
        signs: (0, 3),
        units: (0, 7),
    };

    /// The material harness's slice in the tests (`proofs/tests/g75_harnesses.rs`,
    /// `proofs/tests/g75_mutants.rs`): grooving tools (w 1..=2), with and
    /// without layers, every corner size 0..=3 as chamfers, allowances, J0
    /// and J1, deep enough for ridges and slivers; H < 0, D > 0, IS-B metric
    /// diameter (unit code 0), each test widening the unit codes as it needs.
    pub const MATERIAL: GrooveDomain = GrooveDomain {
        depth: (6, 7),
        width: (4, 6),
        peck: (3, 3),
        step: (1, 3),
        retract: (1, 1),
        layer: (0, 2),
        allowance_x: (1, 2),
        allowance_z: (0, 1),
        tool_width: (1, 2),
        corner: (0, 3),
        corner_kinds: (0, 0),
        path: (0, 1),
        signs: (0, 0),
        units: (0, 0),
        ..GrooveDomain::SQUARE
    };

    /// Grooves of many layers and nothing else: right-angle, zero width, a
    /// pointed tool, no retract, allowance or corner, J0, H < 0, IS-B metric
    /// diameter; `depth`, `peck` and `layer` (Δv) as given. With `peck ≥
    /// layer` each layer is one plunge, so the layer loops run once per layer:
    /// the worst case of the peck count's loop (`proofs/tests/unwind.rs`,
    /// `proofs/tests/g75_harnesses.rs`).
    #[must_use]
    pub const fn layers_only(depth: (i64, i64), peck: (i64, i64), layer: (i64, i64)) -> GrooveDomain {
        GrooveDomain {
            depth,
            width: (0, 0),
            peck,
            step: (1, 1),
            retract: (0, 0),
            layer,
            allowance_x: (0, 0),
            allowance_z: (0, 0),
            tool_width: (-1, -1),
            corner: (0, 0),
            corner_kinds: (0, 0),
            flank: (900_000, 900_000),
            slope: (0, 0),
            path: (0, 0),
            signs: (0, 0),
            units: (0, 0),
        }
    }
}

/// A G75.1 cycle chosen from `d`: S = (X100, Z0) (in mm at the chosen
/// units), the tool 10 increments clear of the opening.
pub fn any_groove(d: &GrooveDomain) -> G75Cycle {
    let pick = |r: (i64, i64)| any_in(r.0, r.1);
    let depth = pick(d.depth);
    let width = pick(d.width);
    let signs = pick(d.signs);
    let units_code = pick(d.units);
    let units = Units {
        system: if units_code & 1 == 0 { IncrementSystem::IsB } else { IncrementSystem::IsC },
        unit: if units_code & 2 == 0 { InputUnit::Metric } else { InputUnit::Inch },
    };
    let x_mode = if units_code & 4 == 0 { XMode::Diameter } else { XMode::Radius };
    let sx = if signs & 1 == 1 { 1 } else { -1 };
    let sz = if signs & 2 == 2 { -1 } else { 1 };
    let start = Point::new(100 * units.per_unit(), 0);
    let layer = pick(d.layer);
    let tool = pick(d.tool_width);
    let kinds = pick(d.corner_kinds);
    let mut corners = [Corner::SHARP; 4];
    for (i, c) in corners.iter_mut().enumerate() {
        let size = pick(d.corner);
        let kind = if kinds >> i & 1 == 1 { CornerKind::Round } else { CornerKind::Chamfer };
        *c = Corner { size, kind };
    }
    let angle = |r: (i64, i64)| u32::try_from(any_in(r.0, r.1)).unwrap_or(0);
    G75Cycle {
        units,
        x_mode,
        from: Point::new(start.x - sx * 10, start.z - sz * 10),
        start,
        peck: pick(d.peck),
        step: pick(d.step),
        depth: sx * depth,
        width: if sz < 0 { -width } else { width },
        flank_a: angle(d.flank),
        flank_b: angle(d.flank),
        slope: angle(d.slope),
        retract: pick(d.retract),
        layer: (layer > 0).then_some(layer),
        allowance_x: pick(d.allowance_x),
        allowance_z: pick(d.allowance_z),
        tool_width: (tool >= 0).then_some(tool),
        path: match pick(d.path) {
            0 => PathType::Rough,
            1 => PathType::RoughAndFinish,
            _ => PathType::Finish,
        },
        corners,
        readings: cycleref::G75Readings::DEFAULT,
    }
}

/// What a groove harness runs: an engine from a cycle to its moves.
pub trait GrooveEngine {
    /// The moves of `c`.
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    fn expand(&self, c: &G75Cycle) -> Result<Moves, CycleError>;
}

/// Moves collected from an engine (Kani handles a vector of a bounded
/// length; the windows keep it short).
pub type Moves = std::vec::Vec<Move>;

/// The fixed-point engine, `cycleref::expand_g75`.
#[derive(Clone, Copy, Debug, Default)]
pub struct GrooveFixedPoint;

impl GrooveEngine for GrooveFixedPoint {
    fn expand(&self, c: &G75Cycle) -> Result<Moves, CycleError> {
        cycleref::expand_g75(c).map(Iterator::collect)
    }
}

/// Local coordinates (docs/G75.md §2) of an absolute point: (u, y).
fn local(c: &G75Cycle, p: Point) -> (i64, i64) {
    (c.axial_sign() * (p.z - c.start.z), c.radial_sign() * (p.x - c.start.x))
}

/// Expands a chosen cycle, or prunes the run when it is refused.
fn expanded(c: &G75Cycle, engine: &(impl GrooveEngine + ?Sized)) -> Moves {
    match engine.expand(c) {
        Ok(moves) => moves,
        Err(_) => {
            assume(false);
            Moves::new()
        }
    }
}

/// Property: every peck takes at most Δi of new depth (Δi/2 of radius), a
/// peck moves along X only and away from the opening, every axial step is
/// at most Δk and along Z only, no move is empty, and the path ends where
/// it began.
pub fn groove_pecks_and_steps(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    declare(&["a full peck", "a short last step"]);
    let c = any_groove(d);
    let moves = expanded(&c, engine);
    let mut at = c.from;
    let mut deepest: Option<i64> = None;
    for m in &moves {
        assert_ne!(m.to, at, "no empty move");
        let (u0, y0) = local(&c, at);
        let (u1, y1) = local(&c, m.to);
        match m.role {
            Role::Peck(_) => {
                assert_eq!(u0, u1, "a peck moves along X only");
                assert!(y1 > y0, "a peck goes into the groove");
                let before = deepest.map_or(y0, |v| v.max(y0));
                assert!(y1 - before <= c.peck, "a peck takes at most Δi of new depth");
                cover!(y1 - before == c.peck, "a full peck");
                deepest = Some(before.max(y1));
            }
            Role::PeckRetract(_) => {
                assert_eq!(u0, u1);
                assert!(y1 < y0 && y0 - y1 <= c.retract * c.x_mode.factor(), "retract e at most");
            }
            Role::PlungeRetract(_) => {
                assert_eq!(u0, u1);
                deepest = None;
            }
            Role::Step(_) => {
                assert_eq!(y0, y1, "a step moves along Z only");
                assert!(u1 > u0 && u1 - u0 <= c.step, "a step goes on by at most Δk");
                cover!(u1 - u0 < c.step, "a short last step");
            }
            _ => {}
        }
        at = m.to;
    }
    assert_eq!(at, c.from, "the cycle ends where it began (step 10)");
}

/// Property: layers. Every plunge of a layer reaches the same depth, the
/// layers get deeper by at most Δv each, and the last one reaches the
/// roughing bottom |H| - Δu.
pub fn groove_layers(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    declare(&["several layers"]);
    let c = any_groove(d);
    assume(c.path.roughs());
    // At most 64 layers (the window's bound; R-G75LAYER: ceil((|H| - U) / V)).
    let rough_depth = c.depth.abs() - c.allowance_x;
    assume(c.layer.is_none_or(|v| v > 0 && (rough_depth + v - 1) / v <= 64));
    let moves = expanded(&c, engine);
    let mut bottoms: [Option<i64>; 64] = [None; 64];
    let mut layers = 0_usize;
    for m in &moves {
        if let Role::Peck(p) = m.role {
            let layer = usize::try_from(p.layer).unwrap_or(usize::MAX);
            assert!((1..=64).contains(&layer), "the harness's windows have at most 64 layers");
            let (_, y) = local(&c, m.to);
            let slot = &mut bottoms[layer - 1];
            *slot = Some(slot.map_or(y, |b: i64| b.max(y)));
            layers = layers.max(layer);
        }
    }
    // Every plunge's last peck reaches its layer's bottom.
    let mut last: Option<(cycleref::Plunge, i64)> = None;
    for m in &moves {
        match m.role {
            Role::Peck(p) => last = Some((p, local(&c, m.to).1)),
            Role::PlungeRetract(p) => {
                let (q, y) = last.expect("a plunge has pecks");
                assert_eq!(p, q);
                assert_eq!(
                    Some(y),
                    bottoms[usize::try_from(p.layer).unwrap_or(1) - 1],
                    "plunge reaches its layer"
                );
            }
            _ => {}
        }
    }
    let roughing_bottom = c.depth.abs() - c.allowance_x;
    let mut previous = 0;
    for b in bottoms.iter().take(layers) {
        let b = b.expect("every layer has plunges");
        assert!(b > previous, "layers get deeper");
        if let Some(v) = c.layer {
            assert!(b - previous <= v, "a layer is at most Δv deep");
        }
        previous = b;
    }
    assert_eq!(previous, roughing_bottom, "the last layer reaches |H| - U");
    cover!(layers > 1, "several layers");
}

/// The roughing region of a right-angle groove, doubled so every boundary
/// is an integer (docs/G75.md §5 with cot 90° = 0, cot 45° = 1, tan 45° =
/// 1): `2u ≥ left2(y)`, `2(u + w) ≤ right2(y)`, `y ≤ |H| - Δu`.
struct SquareRegion {
    f: i64,
    bottom: i64,
    d: i64,
    dw: i64,
    t3: i64,
    t4: i64,
}

impl SquareRegion {
    fn new(c: &G75Cycle) -> SquareRegion {
        SquareRegion {
            f: c.x_mode.factor(),
            bottom: c.depth.abs() - c.allowance_x,
            d: c.width.abs(),
            dw: c.allowance_z,
            t3: c.corners[corner::R3].size,
            t4: c.corners[corner::R4].size,
        }
    }

    /// f·left(y), exact: max(Δw, t3 + Δw - (bottom - y)/f) (chord3 only with t3 > 0).
    fn left_f(&self, y: i64) -> i64 {
        let flank = self.f * self.dw;
        if self.t3 > 0 {
            flank.max(self.f * (self.t3 + self.dw) - (self.bottom - y))
        } else {
            flank
        }
    }

    /// f·right(y), exact.
    fn right_f(&self, y: i64) -> i64 {
        let flank = self.f * (self.d - self.dw);
        if self.t4 > 0 {
            flank.min(self.f * (self.d - self.t4 - self.dw) + (self.bottom - y))
        } else {
            flank
        }
    }

    /// `(2f·left, 2f·right)` at the depth `j + 1/2` (exact: each boundary
    /// is linear on `[j, j + 1]`, its kink being at an integer depth).
    fn bounds_at_centre(&self, j: i64) -> (i64, i64) {
        (self.left_f(j) + self.left_f(j + 1), self.right_f(j) + self.right_f(j + 1))
    }

    /// The tool, reference point (u, y) and width w, lies in the region
    /// (or above the opening, y ≤ 0, where there is only air).
    fn holds(&self, u: i64, y: i64, w: i64) -> bool {
        y <= 0 || y <= self.bottom && self.f * u >= self.left_f(y) && self.f * (u + w) <= self.right_f(y)
    }
}

/// Property: no roughing position of the tool, with its width, lies outside
/// the groove less the allowances (right-angle grooves: exact). Checked at
/// the end of every roughing move (pecks, retracts, steps, layer changes and
/// the rough contour); the region is convex, so the moves between them stay
/// inside too.
pub fn groove_inside(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    declare(&["touches the left boundary", "touches the right boundary", "with a bottom corner"]);
    let c = any_groove(d);
    assume(c.flank_a == RIGHT_ANGLE && c.flank_b == RIGHT_ANGLE && c.slope == 0);
    let moves = expanded(&c, engine);
    let region = SquareRegion::new(&c);
    let w = c.width_of_tool();
    for m in &moves {
        let roughing = matches!(
            m.role,
            Role::Peck(_)
                | Role::PeckRetract(_)
                | Role::PlungeRetract(_)
                | Role::Step(_)
                | Role::LayerChange(_)
                | Role::RoughContour
        );
        if roughing {
            let (u, y) = local(&c, m.to);
            assert!(region.holds(u, y, w), "{:?} at u {u} y {y} w {w} leaves the roughing region", m.role);
            cover!(y > 0 && region.f * u == region.left_f(y), "touches the left boundary");
            cover!(y > 0 && region.f * (u + w) == region.right_f(y), "touches the right boundary");
        }
    }
    cover!(c.corners[corner::R3].size > 0 && c.path.roughs(), "with a bottom corner");
}

/// Whether the tool, moving in a straight line from `(u0, y0)` to `(u1, y1)`
/// (local, doubled: every coordinate times 2), sweeps the point `(pu, py)`
/// (doubled) with its body: a grooving tool of width `w2` (doubled) occupies
/// `[u, u + w]` at its reference point's depth `y` and everything above it
/// (`y' ≤ y`, towards the opening), as a blade does.
fn sweeps(from: (i64, i64), to: (i64, i64), w2: i64, p: (i64, i64)) -> bool {
    let ((u0, y0), (u1, y1), (pu, py)) = (from, to, p);
    if u0 == u1 {
        return u0 <= pu && pu <= u0 + w2 && py <= y0.max(y1);
    }
    // t = n / den in [0, 1] where u(t) = u0 + (u1 − u0)·t, den > 0.
    let (den, dir) = ((u1 - u0).abs(), (u1 - u0).signum());
    let n_at = |u: i64| dir * (u - u0);
    let (a, b) = (n_at(pu - w2), n_at(pu));
    let (lo, hi) = (a.min(b).max(0), a.max(b).min(den));
    if lo > hi {
        return false;
    }
    // y(t) is linear: its largest value on [lo, hi] is at an end.
    let below = |n: i64| {
        i128::from(py) * i128::from(den)
            <= i128::from(y0) * i128::from(den) + i128::from(y1 - y0) * i128::from(n)
    };
    below(lo) || below(hi)
}

/// Property: material (right-angle grooves, exact, grooving tools). The
/// roughing region (§5) starts full of material, sampled at the centres of
/// its increment cells; every feed move of the path removes what the tool's
/// body sweeps (see `sweeps`). Then:
///
/// * no rapid move sweeps material that is still there (a rapid through
///   material breaks the tool): the steps of step ⑦, the retracts, the
///   layer changes and the returns all run in cut space or in the air;
/// * once the plunges are done, what is left lies beside a layer's plunge
///   range (the band the rough contour cuts, step ⑨) or in a ridge between
///   two neighbouring plunges, at most `Δk − w` wide; ridges occur only
///   without layers (R-G75RIDGE refuses the others), so a ridge stands at
///   most the roughing depth `|H| − Δu` high;
/// * after the rough contour (J0, J1) only slivers along the boundary are
///   left, where a vertex rounded into the region (R-G75ROUND) moves the
///   contour off the exact boundary: by less than one increment, and by
///   less than `1 + 1/f` beside K1 and K4, which sit at the integer depth
///   above the exact corner of flank and chord. The check allows 2, the
///   bound at f = 1.
///
/// The groove carries `G75Readings::DEFAULT` (`any_groove`), so reading
/// R-G75RIDGE is pinned to its default `refuse`: R-G75RIDGE `as-written`
/// is exempt by design, since it makes layered roughing with ridges as
/// steps ②⑦⑧ write it and the next layer's rapids then cross the ridges
/// (docs/INTERPRETATIONS.md R-G75RIDGE), which the first point forbids.
pub fn groove_material(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    declare(&[
        "a ridge between plunges",
        "a sliver along the boundary",
        "several layers",
        "with a bottom corner",
    ]);
    let c = any_groove(d);
    assume(c.flank_a == RIGHT_ANGLE && c.flank_b == RIGHT_ANGLE && c.slope == 0 && c.path.roughs());
    let w = c.width_of_tool();
    assume(w > 0);
    let moves = expanded(&c, engine);
    let region = SquareRegion::new(&c);
    // Cells k = j·cols + i, centre (i + 1/2, j + 1/2), i in [0, d), j in
    // [0, bottom); `cell` gives the centre doubled.
    let (cols, rows) = (usize::try_from(region.d).unwrap_or(0), usize::try_from(region.bottom).unwrap_or(0));
    let cell = |k: usize| {
        let (i, j) = (i64::try_from(k % cols).unwrap_or(0), i64::try_from(k / cols).unwrap_or(0));
        (2 * i + 1, 2 * j + 1)
    };
    // 2f·u against 2f·left and 2f·right at the centre's depth: the distances
    // from the boundaries, times 2f.
    let margins = |(u2, y2): (i64, i64)| {
        let (left2, right2) = region.bounds_at_centre((y2 - 1) / 2);
        (region.f * u2 - left2, right2 - region.f * u2)
    };
    let mut material: std::vec::Vec<bool> = (0..cols * rows)
        .map(|k| {
            let (from_left, from_right) = margins(cell(k));
            from_left > 0 && from_right > 0
        })
        .collect();
    // (layer, u, bottom) of every peck.
    let mut pecks: std::vec::Vec<(u32, i64, i64)> = std::vec::Vec::new();
    let mut at = local(&c, c.from);
    let mut contour_started = false;
    for m in &moves {
        let to = local(&c, m.to);
        if m.role == Role::RoughContour && !contour_started {
            contour_started = true;
            let left = material.iter().enumerate().filter(|(_, here)| **here).map(|(k, _)| cell(k));
            check_plunge_leftovers(&c, &pecks, left);
        }
        if let Role::Peck(p) = m.role {
            pecks.push((p.layer, to.0, to.1));
        }
        let (from2, to2) = ((2 * at.0, 2 * at.1), (2 * to.0, 2 * to.1));
        if m.motion == Motion::Rapid {
            for (k, _) in material.iter().enumerate().filter(|(_, here)| **here) {
                let p = cell(k);
                assert!(
                    !sweeps(from2, to2, 2 * w, p),
                    "{:?} rapid from {at:?} to {to:?} runs through material at doubled {p:?}",
                    m.role
                );
            }
        } else if !contour_started || m.role == Role::RoughContour {
            // Roughing feeds remove material; the finishing contour is not
            // roughing and is left out.
            for (k, left) in material.iter_mut().enumerate() {
                *left = *left && !sweeps(from2, to2, 2 * w, cell(k));
            }
        }
        at = to;
    }
    for (k, _) in material.iter().enumerate().filter(|(_, here)| **here) {
        let (from_left, from_right) = margins(cell(k));
        // Less than 2 increments from a boundary (times 2f).
        let sliver = from_left < 4 * region.f || from_right < 4 * region.f;
        assert!(sliver, "the rough contour leaves material at doubled {:?} inside the region", cell(k));
        cover!(true, "a sliver along the boundary");
    }
    cover!(c.layer.is_some_and(|v| v < region.bottom), "several layers");
    cover!(c.corners[corner::R3].size > 0, "with a bottom corner");
}

/// What the plunges left (`groove_material`): each cell (doubled centre)
/// lies beside its layer's plunge range, or in a ridge between two
/// neighbouring plunges at most `Δk − w` wide, which only a single layer
/// may have (R-G75RIDGE).
fn check_plunge_leftovers(c: &G75Cycle, pecks: &[(u32, i64, i64)], left: impl Iterator<Item = (i64, i64)>) {
    let w = c.width_of_tool();
    // Each layer's bottom and sorted plunge positions, once.
    let layers = pecks.iter().map(|p| p.0).max().unwrap_or(0);
    let plunges: std::vec::Vec<(i64, std::vec::Vec<i64>)> = (1..=layers)
        .map(|layer| {
            let bottom = pecks.iter().filter(|p| p.0 == layer).map(|p| p.2).max().unwrap_or(0);
            let mut us: std::vec::Vec<i64> = pecks.iter().filter(|p| p.0 == layer).map(|p| p.1).collect();
            us.sort_unstable();
            us.dedup();
            (bottom, us)
        })
        .collect();
    for (pu2, py2) in left {
        // The layer holding this depth: the first whose bottom is below it.
        let Some((_, us)) = plunges.iter().find(|(bottom, _)| 2 * bottom > py2) else {
            panic!("material at doubled ({pu2}, {py2}) below every layer");
        };
        let (first, last) = (us[0], us[us.len() - 1]);
        let band = pu2 < 2 * first || pu2 > 2 * (last + w);
        let gap = us.windows(2).find(|p| 2 * (p[0] + w) < pu2 && pu2 < 2 * p[1]);
        assert!(
            band || gap.is_some(),
            "material at doubled ({pu2}, {py2}) is neither beside the plunges nor a ridge"
        );
        if let (Some(p), false) = (gap, band) {
            assert!(p[1] - p[0] <= c.step, "a ridge is at most Δk − w wide");
            assert!(
                c.layer.is_none_or(|v| v >= c.depth.abs() - c.allowance_x),
                "a ridge only without layers"
            );
            cover!(true, "a ridge between plunges");
        }
    }
}

/// A contour move in local coordinates: its end `(u, y)` and, for an arc,
/// its centre.
type LocalMove = (i64, i64, Option<(i64, i64)>);

/// Property: with J1 or J2 the finishing contour passes exactly through the
/// programmed profile (right-angle grooves, where every point is exact):
/// T1s, T1a, T3a, T3b, T4b, T4c, P3/T2b, T2s, with the far side shifted by
/// the tool width, rounds as arcs about their centres.
pub fn groove_finish_is_profile(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    declare(&["with an arc"]);
    let c = any_groove(d);
    assume(c.flank_a == RIGHT_ANGLE && c.flank_b == RIGHT_ANGLE && c.slope == 0 && c.path.finishes());
    let moves = expanded(&c, engine);
    let f = c.x_mode.factor();
    let y_bottom = c.depth.abs();
    let dd = c.width.abs();
    let w = c.width_of_tool();
    let [r1, r2, r3, r4] = c.corners;
    // Expected cutting moves of the contour (docs/G75.md §3 with a = b = 90°).
    // Twin: `impl/src/engine/g75/tests.rs`, `square_groove_sweep` (the
    // engine's own test of the same moves, which cannot use this crate).
    let mut expected: std::vec::Vec<LocalMove> = std::vec::Vec::new();
    let arc = |k: Corner, centre: (i64, i64)| (k.kind == CornerKind::Round).then_some(centre);
    if r1.size > 0 {
        expected.push((0, f * r1.size, arc(r1, (-r1.size, f * r1.size))));
    }
    if r3.size > 0 {
        expected.push((0, y_bottom - f * r3.size, None));
        expected.push((r3.size, y_bottom, arc(r3, (r3.size, y_bottom - f * r3.size))));
    } else {
        expected.push((0, y_bottom, None));
    }
    if r4.size > 0 {
        expected.push((dd - r4.size - w, y_bottom, None));
        expected.push((dd - w, y_bottom - f * r4.size, arc(r4, (dd - r4.size - w, y_bottom - f * r4.size))));
    } else {
        expected.push((dd - w, y_bottom, None));
    }
    if r2.size > 0 {
        expected.push((dd - w, f * r2.size, None));
        expected.push((dd + r2.size - w, 0, arc(r2, (dd + r2.size - w, f * r2.size))));
    } else {
        expected.push((dd - w, 0, None));
    }
    // The contour's first cutting move is the r1 chamfer/round (or flank A).
    let got: std::vec::Vec<LocalMove> = moves
        .iter()
        .filter(|m| m.role == Role::FinishContour && m.motion != Motion::Rapid)
        .map(|m| {
            let (u, y) = local(&c, m.to);
            let centre = match m.motion {
                Motion::Arc { centre, .. } => Some(local(&c, centre)),
                _ => None,
            };
            (u, y, centre)
        })
        .collect();
    // A chamfer of size 0 leaves no move; a flank of zero length neither.
    let expected: std::vec::Vec<_> = {
        let mut at = if r1.size > 0 { (-r1.size, 0) } else { (0, 0) };
        let mut out = std::vec::Vec::new();
        for e in expected {
            if (e.0, e.1) != at {
                out.push(e);
                at = (e.0, e.1);
            }
        }
        out
    };
    assert_eq!(got, expected, "the finishing contour is the programmed profile");
    cover!(got.iter().any(|g| g.2.is_some()), "with an arc");
}

/// The restatement a groove harness compares with: `crate::g75_exact`'s
/// `expand`, or one of its deliberate errors (the controls of
/// `proofs/tests/g75_exact.rs`).
pub type Restatement = fn(&G75Cycle) -> Result<std::vec::Vec<Move>, CycleError>;

/// Property: engine = reference for right-angle grooves (A = B = 90°, L =
/// 0): for every groove drawn from `d`, the engine's moves (or its alarm)
/// equal the reference's.
///
/// The reference is `cycleref_spec::g75::expand`, exact over `num-bigint`.
/// Under Kani the engine is compared with the reference restated in
/// integers, [`crate::g75_exact::expand`] (the same steps on whole
/// increments: at right angles every value of the reference is an integer
/// or a half-integer), so that Kani does not execute `num-bigint`
/// symbolically; under `cargo test` the engine is compared with both, and
/// the restatement with the reference, so the restatement is itself held to
/// the reference on every groove run here.
pub fn groove_equivalence(d: &GrooveDomain, engine: &(impl GrooveEngine + ?Sized)) {
    groove_equivalence_with(d, engine, crate::g75_exact::expand);
}

/// [`groove_equivalence`] against a given restatement (the controls pass a
/// restatement with a deliberate error, which the comparison with the
/// reference must catch).
pub fn groove_equivalence_with(
    d: &GrooveDomain,
    engine: &(impl GrooveEngine + ?Sized),
    restated: Restatement,
) {
    declare(&[
        "a groove that expands",
        "a corner too large",
        "a groove narrower than the tool",
        "ridges in layers",
        "several layers",
        "with an arc",
    ]);
    let c = any_groove(d);
    assume(crate::g75_exact::is_square(&c));
    let ours = engine.expand(&c);
    let exact = restated(&c);
    #[cfg(not(kani))]
    {
        let reference = cycleref_spec::g75::expand(&c);
        assert_eq!(ours, reference, "engine and reference differ for {c:?}");
        assert_eq!(exact, reference, "the integer restatement and the reference differ for {c:?}");
    }
    assert_eq!(ours, exact, "engine and reference differ (the reference in integers) for {c:?}");
    cover!(ours.is_ok(), "a groove that expands");
    cover!(matches!(ours, Err(CycleError::CornerTooLarge { .. })), "a corner too large");
    cover!(matches!(ours, Err(CycleError::GrooveNarrowerThanTool { .. })), "a groove narrower than the tool");
    cover!(matches!(ours, Err(CycleError::RidgesInLayers { .. })), "ridges in layers");
    if let Ok(moves) = &ours {
        cover!(moves.iter().any(|m| matches!(m.role, Role::LayerChange(_))), "several layers");
        cover!(moves.iter().any(|m| matches!(m.motion, Motion::Arc { .. })), "with an arc");
    }
}

/// Property: over the documented ranges, expanding never panics or
/// overflows; every move lies within the coordinate range; a cycle either
/// expands or is refused with an alarm. Bounded to the first `limit` moves.
///
/// `most_layers`, when given, keeps the grooves of at most that many layers
/// (the Kani window, `crate::windows::GROOVE_NO_PANIC_LAYERS`): the peck
/// count (§9) runs a loop over the layers before the first move, one
/// iteration per layer, and Kani's unwind bound must exceed it. The bound
/// is stated on the words, not taken from the engine: the layer count is
/// `M = ceil((Y − Δu)/Δv)` with `Y = |H|` and `Δu ≥ 0` (§7), so `M ≤
/// ceil(|H|/Δv) ≤ most_layers` when `|H| ≤ most_layers·Δv`; without V
/// there is one layer. Returns the number of moves looked at (the
/// harness's own loop, which `proofs/tests/unwind.rs` measures).
pub fn groove_no_panic(d: &GrooveDomain, limit: usize, most_layers: Option<i64>) -> usize {
    declare(&["a valid groove", "several layers"]);
    let c = any_groove(d);
    if let (Some(most), Some(v)) = (most_layers, c.layer) {
        // Saturating: the check holds for any words the domain gives.
        assume(c.depth.abs() <= most.saturating_mul(v));
    }
    let mut looked_at = 0;
    if let Ok(moves) = cycleref::expand_g75(&c) {
        for m in moves.take(limit) {
            looked_at += 1;
            assert!(
                m.to.x.abs() <= cycleref::units::MAX_LENGTH && m.to.z.abs() <= cycleref::units::MAX_LENGTH,
                "every move lies within the coordinate range"
            );
        }
        cover!(true, "a valid groove");
        // M ≥ 2: the rough bottom Y − Δu lies below the first layer Δv.
        cover!(c.layer.is_some_and(|v| c.depth.abs() - c.allowance_x > v), "several layers");
    }
    looked_at
}

/// `from`, for tests: the tool position before the cycle (kept public for
/// the mutants).
pub fn local_of(c: &G75Cycle, p: Point) -> (i64, i64) {
    local(c, p)
}
