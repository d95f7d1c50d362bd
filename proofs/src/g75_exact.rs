//! The G75.1 reference, `cycleref_spec::g75::expand`, restated in integers
//! (least increments) for right-angle grooves (A = B = 90°, L = 0), for the
//! `groove_equivalence` harness under Kani (issue 13: leave `num-bigint`
//! out of what Kani executes symbolically).
//!
//! At A = B = 90° and L = 0 every trigonometric value the reference uses is
//! one of its exact rational cases (`docs/G75.md` §6): sin a = sin b = 1,
//! cos a = cos b = 0, cot a = cot b = 0, cot(a/2) = cot(b/2) = 1, sin L = 0,
//! cos L = 1, tan L = 0, and the round's half angles (a + L)/2, (b − L)/2,
//! a/2, b/2 are all 45°, tan 45° = 1. So:
//!
//! * every tangent length is the corner's size, a chamfer's and a round's
//!   alike (`t = c`, `t = ρ·tan 45° = ρ`);
//! * every profile point, tangent point and round centre is a whole number
//!   of increments (P1 = (0, Y), P2 = (d, Y), P3 = (d, 0), T1s = (−t1, 0),
//!   C1 = (−t1, f·t1), …): rounding to nearest leaves them as they are;
//! * the roughing region's boundaries are `Δw`, `d − Δw`, `Y − Δu` and the
//!   corner chords `t3 + Δw − (Y − Δu − y)/f`, `d − t4 − Δw + (Y − Δu −
//!   y)/f`, whole or half increments (f = 2); their roundings in (`ceil`,
//!   `floor`) are exact integer divisions by f here;
//! * the opening is the line y = 0 (y3 = 0, `y_top = floor(y3) = 0`, under
//!   either value of R-G75SLOPE: at L = 0 it neither rises nor falls), and
//!   the corner alarms compare integers once multiplied by f.
//!
//! Nothing is left out for being inexact: every corner (chamfer or round,
//! any size) stays on the grid at 90°, so the restatement covers every
//! right-angle groove the words allow. R-G75TIE never applies (no value is
//! irrational) and `CycleError::UndecidedRounding` cannot occur, so the
//! restatement has no such branch.
//!
//! The steps, the alarms and their order (R-G75ORDER, R-G75DECIDE), and the
//! names follow `spec/src/g75/` function by function; each function says
//! which one it restates ("Twin: spec/src/g75/…"). Only integer arithmetic:
//! no engine code (`impl/src/engine/g75/`), no `num-bigint`. The words'
//! decoding is the shared type's (`G75Cycle::validate`, `width_of_tool`,
//! `radial_sign`, `axial_sign`, `XMode::factor`), which the reference calls
//! too. Every magnitude fits `i64` with room to spare: `validate` keeps
//! lengths below 10^8, corner sizes below 10^6 and coordinates below 10^9,
//! so no sum or product here exceeds about 4·10^12.
//!
//! Its loops are bounded by the groove: the layers (`ceil((Y − Δu)/Δv)`,
//! counted before any move as in the reference), the plunges of a layer,
//! the pecks of a plunge, the moves. Under `cargo test` the harness
//! (`crate::groove::groove_equivalence`) compares the engine with this
//! restatement and with the reference, and this restatement with the
//! reference; under Kani only the engine with this restatement.

use cycleref::error::{CycleError, Field, GrooveEdge};
use cycleref::g75::{corner, CornerKind, G75Cycle, MAX_PECKS, RIGHT_ANGLE};
use cycleref::moves::{Motion, Move, Plunge, Role};
use cycleref::units::{Length, Point, MAX_LENGTH};

/// True for the grooves this restatement covers: A = B = 90°, L = 0.
#[must_use]
pub const fn is_square(c: &G75Cycle) -> bool {
    c.flank_a == RIGHT_ANGLE && c.flank_b == RIGHT_ANGLE && c.slope == 0
}

/// A deliberate error in one step of the restatement, for the controls of
/// `proofs/tests/g75_exact.rs`, which check that the comparison with the
/// reference catches it. [`expand`] is [`expand_with`] with [`Slip::None`];
/// the harness under Kani never takes another.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slip {
    /// The restatement as the reference is.
    None,
    /// The plunge range's end one increment too far: `A_mf = floor(right(y_m)) − w + 1`.
    PlungeEndOffByOne,
    /// The start-side boundary rounded out instead of in: `floor(left(y))` for `ceil(left(y))`.
    LeftRoundedOut,
    /// The bottom rounds r3 and r4 turning the other way (the cross product's sign inverted).
    BottomRoundsReversed,
}

/// The cycle's words in the local frame (spec `Groove`): `Y = |H|`, `d =
/// |D|`, `w`, `Δi`, `Δk`, `e_x = f·e`, `Δv`, `Δu`, `Δw`, and the tangent
/// lengths `t1..t4` (indexed by [`corner`]).
#[derive(Clone, Copy, Debug)]
struct Square {
    cycle: G75Cycle,
    f: i64,
    sx: i64,
    sz: i64,
    depth: i64,
    width: i64,
    tool: i64,
    peck: i64,
    step: i64,
    retract: i64,
    layer: Option<i64>,
    allowance_x: i64,
    allowance_z: i64,
    tangents: [i64; 4],
    slip: Slip,
}

/// `floor(num / den)`, `den > 0`.
const fn floor_div(num: i64, den: i64) -> i64 {
    num.div_euclid(den)
}

/// `ceil(num / den)`, `den > 0`.
const fn ceil_div(num: i64, den: i64) -> i64 {
    -(-num).div_euclid(den)
}

/// Twin: `spec/src/g75/geometry.rs`, `groove` and `tangent_length`. The
/// tangent length is the size for a chamfer (R-G75CHAMFER: under
/// `axial-width` too, `c / (cos 90° + cos 0°) = c`) and `ρ·tan 45°
/// = ρ` for a round at every corner ((a + L)/2 = (b − L)/2 = a/2 = b/2 =
/// 45°); 0 for a sharp corner.
fn square(c: &G75Cycle, slip: Slip) -> Square {
    let f = c.x_mode.factor();
    Square {
        cycle: *c,
        f,
        sx: c.radial_sign(),
        sz: c.axial_sign(),
        depth: c.depth.abs(),
        width: c.width.abs(),
        tool: c.width_of_tool().abs(),
        peck: c.peck,
        step: c.step,
        retract: f * c.retract,
        layer: c.layer,
        allowance_x: c.allowance_x,
        allowance_z: c.allowance_z,
        tangents: [c.corners[0].size, c.corners[1].size, c.corners[2].size, c.corners[3].size],
        slip,
    }
}

/// Twin: `spec/src/g75/geometry.rs`, `check_corners` (with `flank_a_length`
/// `(Y/f)/sin a = Y/f` and `flank_b_length` `((Y − y3)/f)/sin b = Y/f`):
/// `t1 + t3 > Y/f` (flank A), `t3 + t4 > d` (the bottom), `t4 + t2 > Y/f`
/// (flank B), in this order; the flank comparisons times f.
fn check_corners(g: &Square) -> Result<(), CycleError> {
    let t = g.tangents;
    if g.f * (t[corner::R1] + t[corner::R3]) > g.depth {
        return Err(CycleError::CornerTooLarge { edge: GrooveEdge::FlankA });
    }
    if t[corner::R3] + t[corner::R4] > g.width {
        return Err(CycleError::CornerTooLarge { edge: GrooveEdge::Bottom });
    }
    if g.f * (t[corner::R4] + t[corner::R2]) > g.depth {
        return Err(CycleError::CornerTooLarge { edge: GrooveEdge::FlankB });
    }
    Ok(())
}

/// Twin: `spec/src/g75/region.rs`, `bottom_rough`: `Y − Δu`.
const fn bottom_rough(g: &Square) -> i64 {
    g.depth - g.allowance_x
}

/// `ceil(left(y))`. Twin: `spec/src/g75/region.rs`, `left` (R-G75MAXMIN:
/// the maximum rounded as one value), `flank_a_rough` (`(y/f)·cot a + Δw =
/// Δw`) and `chord3_rough` (`(Y/f)·cot a + t3 + Δw − ((Y − Δu − y)/f)·cot
/// 45° = t3 + Δw − (Y − Δu − y)/f`, only when t3 > 0), then
/// `spec/src/g75/rounding.rs`, `ceil`. Times f, both are integers.
fn left_in(g: &Square, y: i64) -> i64 {
    let flank = g.f * g.allowance_z;
    let t3 = g.tangents[corner::R3];
    let left = if t3 > 0 { flank.max(g.f * (t3 + g.allowance_z) - (bottom_rough(g) - y)) } else { flank };
    if g.slip == Slip::LeftRoundedOut {
        return floor_div(left, g.f);
    }
    ceil_div(left, g.f)
}

/// `floor(right(y))`. Twin: `spec/src/g75/region.rs`, `right` (R-G75MAXMIN),
/// `flank_b_rough` (`(Y/f)·cot a + d + ((Y − y)/f)·cot b − Δw = d − Δw`)
/// and `chord4_rough` (`d − t4 − Δw + (Y − Δu − y)/f`, only when t4 > 0),
/// then `spec/src/g75/rounding.rs`, `floor`.
fn right_in(g: &Square, y: i64) -> i64 {
    let flank = g.f * (g.width - g.allowance_z);
    let t4 = g.tangents[corner::R4];
    let right =
        if t4 > 0 { flank.min(g.f * (g.width - t4 - g.allowance_z) + (bottom_rough(g) - y)) } else { flank };
    floor_div(right, g.f)
}

/// Twin: `spec/src/g75/roughing.rs`, `layer_count`: `ceil((Y − Δu)/Δv)`, 1
/// without V.
const fn layer_count(g: &Square) -> i64 {
    match g.layer {
        Some(v) => (bottom_rough(g) + v - 1) / v,
        None => 1,
    }
}

/// Twin: `spec/src/g75/roughing.rs`, `layer_bottom`: `min(m·Δv, Y − Δu)`.
fn layer_bottom(g: &Square, m: i64) -> i64 {
    match g.layer {
        // Reading R-G75LAYER `equal`.
        Some(_) if g.cycle.readings.equal_layers => {
            let (d, count) = (bottom_rough(g), layer_count(g));
            m * (d / count) + m.min(d % count)
        }
        Some(v) => m.saturating_mul(v).min(bottom_rough(g)),
        None => bottom_rough(g),
    }
}

/// Twin: `spec/src/g75/roughing.rs`, `layer_top`.
fn layer_top(g: &Square, m: i64, y_top: i64) -> i64 {
    if m <= 1 {
        y_top
    } else {
        layer_bottom(g, m - 1)
    }
}

/// A layer's plunge positions (spec `PlungeRange`).
#[derive(Clone, Copy, Debug)]
struct Range {
    first: i64,
    last: i64,
}

impl Range {
    /// Twin: `spec/src/g75/roughing.rs`, `PlungeRange::count`.
    const fn count(self, step: i64) -> i64 {
        (self.last - self.first + step - 1) / step + 1
    }

    /// Twin: `spec/src/g75/roughing.rs`, `PlungeRange::position`.
    const fn position(self, step: i64, n: i64) -> i64 {
        if n >= self.count(step) {
            self.last
        } else {
            self.first + (n - 1) * step
        }
    }
}

/// Twin: `spec/src/g75/roughing.rs`, `plunge_range` (R-G75PLUNGE): `A_m1 =
/// ceil(left(y_m))`, `A_mf = floor(right(y_m)) − w`.
fn plunge_range(g: &Square, m: i64) -> Range {
    let y = layer_bottom(g, m);
    let mut last = right_in(g, y) - g.tool;
    if g.slip == Slip::PlungeEndOffByOne {
        last += 1;
    }
    Range { first: left_in(g, y), last }
}

/// Twin: `spec/src/g75/roughing.rs`, `check_tool_fits` (R-G75NARROWJ: for
/// every J): the last layer's range.
fn check_tool_fits(g: &Square) -> Result<(), CycleError> {
    let range = plunge_range(g, layer_count(g));
    if range.last < range.first {
        return Err(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(g.tool, g.cycle.units) });
    }
    Ok(())
}

/// Twin: `spec/src/g75/roughing.rs`, `check_ridges` (R-G75RIDGE).
fn check_ridges(g: &Square) -> Result<(), CycleError> {
    let c = &g.cycle;
    // Reading R-G75RIDGE `as-written`: no refusal.
    if c.readings.ridges_as_written || !c.path.roughs() || layer_count(g) < 2 || c.step <= g.tool {
        return Ok(());
    }
    let range = plunge_range(g, 1);
    if range.last - range.first > g.tool {
        return Err(CycleError::RidgesInLayers {
            step: Length::new(c.step, c.units),
            tool_width: Length::new(g.tool, c.units),
        });
    }
    Ok(())
}

/// Twin: `spec/src/g75/roughing.rs`, `peck_count`: `ceil((bottom − top)/Δi)`.
const fn peck_count(top: i64, bottom: i64, peck: i64) -> i64 {
    (bottom - top + peck - 1) / peck
}

/// One roughing layer (spec `Layer`).
#[derive(Clone, Copy, Debug)]
struct Layer {
    number: i64,
    top: i64,
    bottom: i64,
    range: Range,
}

/// Twin: `spec/src/g75/roughing.rs`, `rough_layers`: the layers, after the
/// closed-form peck count (§9, R-G75PECKJ2: J0 and J1 only).
fn rough_layers(g: &Square, y_top: i64) -> Result<Vec<Layer>, CycleError> {
    let too_many = CycleError::TooManyPecks { limit: MAX_PECKS };
    let count = layer_count(g);
    let limit = i64::try_from(MAX_PECKS).unwrap_or(i64::MAX);
    if count > limit {
        return Err(too_many);
    }
    let mut total = 0_i64;
    let mut layers = Vec::new();
    let mut m = 1;
    while m <= count {
        let (top, bottom) = (layer_top(g, m, y_top), layer_bottom(g, m));
        let range = plunge_range(g, m);
        let n = range.count(g.step).min(limit + 1);
        let p = peck_count(top, bottom, g.peck).min(limit + 1);
        total += n * p;
        if total > limit {
            return Err(too_many);
        }
        layers.push(Layer { number: m, top, bottom, range });
        m += 1;
    }
    Ok(layers)
}

/// A local point `(u, y)` (spec `LocalPoint`).
type At = (i64, i64);

/// How the tool moves, in the local frame (spec `LocalMotion`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Local {
    Rapid,
    Feed,
    Arc { centre: At, clockwise: bool },
}

/// The path being built (spec `path.rs`, `Path`).
struct Path {
    at: At,
    moves: Vec<(Local, At, Role)>,
}

impl Path {
    /// Twin: `spec/src/g75/path.rs`, `Path::go` (R-G75ZERO, R-G75ARCZERO).
    fn go(&mut self, motion: Local, to: At, role: Role) {
        if to == self.at {
            return;
        }
        self.at = to;
        self.moves.push((motion, to, role));
    }

    fn rapid(&mut self, to: At, role: Role) {
        self.go(Local::Rapid, to, role);
    }

    fn rapid_u(&mut self, u: i64, role: Role) {
        self.rapid((u, self.at.1), role);
    }

    fn rapid_y(&mut self, y: i64, role: Role) {
        self.rapid((self.at.0, y), role);
    }
}

/// Twin: `spec/src/g75/mod.rs`, `Cursor::step` (steps ②–⑧) and
/// `spec/src/g75/roughing.rs`, `pecks` (R-G75PECK: peck j to `min(top +
/// j·Δi, bottom)`, a retract to `max(top, end − e_x)` after each one that
/// did not reach the bottom, none when e = 0).
fn rough_moves(g: &Square, path: &mut Path, layers: &[Layer], a11: At, y_top: i64) {
    for layer in layers {
        let m = u32::try_from(layer.number).unwrap_or(u32::MAX);
        if layer.number >= 2 {
            path.rapid_u(layer.range.first, Role::LayerChange(m));
            path.rapid_y(layer.top, Role::LayerChange(m));
        }
        let plunges = layer.range.count(g.step);
        let mut n = 1;
        while n <= plunges {
            let plunge = Plunge { layer: m, number: u32::try_from(n).unwrap_or(u32::MAX) };
            let a = layer.range.position(g.step, n);
            if n >= 2 {
                path.rapid_u(a, Role::Step(plunge));
            }
            let mut j = 1;
            loop {
                let to = (layer.top + j * g.peck).min(layer.bottom);
                if to >= layer.bottom {
                    path.go(Local::Feed, (a, layer.bottom), Role::Peck(plunge));
                    break;
                }
                path.go(Local::Feed, (a, to), Role::Peck(plunge));
                if g.retract > 0 {
                    // Reading R-G75PECK: clamped at the plunge's start
                    // unless `as-written`.
                    let y = if g.cycle.readings.peck_retract_as_written {
                        to - g.retract
                    } else {
                        layer.top.max(to - g.retract)
                    };
                    path.rapid((a, y), Role::PeckRetract(plunge));
                }
                j += 1;
            }
            path.rapid((a, layer.top), Role::PlungeRetract(plunge));
            n += 1;
        }
    }
    path.rapid_y(y_top, Role::Approach);
    path.rapid_u(a11.0, Role::Approach);
}

/// The rough contour's points as tool positions. Twin:
/// `spec/src/g75/contour.rs`, `rough_contour` and `rough_vertices` with
/// `r0` (`(ceil(left(y_top)), y_top)`), `y_k1` (`floor(Y − Δu − f·t3·sin a −
/// Δu·cos a) = Y − Δu − f·t3`), `k1` (`ceil(flankA_r(y_K1)) = Δw`), `k2`
/// (`ceil((Y/f)·cot a + t3 + Δw) = t3 + Δw`), `q1` (`Δw`), `k3` (`d − t4 − Δw
/// − w`), `y_k4` (`Y − Δu − f·t4`), `k4` (`floor(flankB_r(y_K4)) − w = d −
/// Δw − w`), `q2` (`d − Δw − w`) and `r3` (`floor(right(y_top)) − w`).
fn rough_contour(g: &Square, y_top: i64) -> Vec<At> {
    let (b, w, dw, d) = (bottom_rough(g), g.tool, g.allowance_z, g.width);
    let (t3, t4) = (g.tangents[corner::R3], g.tangents[corner::R4]);
    let mut points = vec![(left_in(g, y_top), y_top)];
    if t3 > 0 {
        let y_k1 = b - g.f * t3;
        if y_k1 > y_top {
            points.push((dw, y_k1));
        }
        points.push((t3 + dw, b));
    } else {
        points.push((dw, b));
    }
    if t4 > 0 {
        points.push((d - t4 - dw - w, b));
        let y_k4 = b - g.f * t4;
        if y_k4 > y_top {
            points.push((d - dw - w, y_k4));
        }
    } else {
        points.push((d - dw - w, b));
    }
    points.push((right_in(g, y_top) - w, y_top));
    points
}

/// Twin: `spec/src/g75/contour.rs`, `clockwise` (R-G75ARC): the sign of the
/// local cross product `(start − centre) × (end − centre)`, G02 when it is
/// negative seen with +Z right and +X up, i.e. local negative when `sz·sx >
/// 0`, local positive when `sz·sx < 0`.
fn clockwise(g: &Square, start: At, end: At, centre: At) -> bool {
    let (su, sy) = (start.0 - centre.0, start.1 - centre.1);
    let (eu, ey) = (end.0 - centre.0, end.1 - centre.1);
    let cross = su * ey - sy * eu;
    match cross.signum() {
        -1 => g.sz * g.sx > 0,
        1 => g.sz * g.sx < 0,
        _ => false,
    }
}

/// One corner feature: its start and end along the finishing path and, for
/// a round, its centre (spec `Feature`).
type Feature = (At, At, Option<At>);

/// Twin: `spec/src/g75/geometry.rs`, `feature` with `t1s`, `t1a`, `c1`,
/// `t3a`, `t3b`, `c3`, `t4b`, `t4c`, `c4`, `t2b`, `t2s`, `c2` at a = b =
/// 90°, L = 0 (ρ = t):
///
/// r1: T1s = (−t1, 0) → T1a = (0, f·t1), C1 = (−t1, f·t1);
/// r3: T3a = (0, Y − f·t3) → T3b = (t3, Y), C3 = (t3, Y − f·t3);
/// r4: T4b = (d − t4, Y) → T4c = (d, Y − f·t4), C4 = (d − t4, Y − f·t4);
/// r2: T2b = (d, f·t2) → T2s = (d + t2, 0), C2 = (d + t2, f·t2).
fn feature(g: &Square, index: usize) -> Option<Feature> {
    let corner = g.cycle.corners[index];
    if corner.size == 0 {
        return None;
    }
    let (t, f, y, d) = (g.tangents[index], g.f, g.depth, g.width);
    let (start, end, centre) = match index {
        corner::R1 => ((-t, 0), (0, f * t), (-t, f * t)),
        corner::R2 => ((d, f * t), (d + t, 0), (d + t, f * t)),
        corner::R3 => ((0, y - f * t), (t, y), (t, y - f * t)),
        _ => ((d - t, y), (d, y - f * t), (d - t, y - f * t)),
    };
    Some((start, end, (corner.kind == CornerKind::Round).then_some(centre)))
}

/// Twin: `spec/src/g75/contour.rs`, `finish_contour`: F0 (T1s, or S) and
/// the moves r1, flank A to T3a (or P1 = (0, Y)), r3, the bottom to T4b − w
/// (or P2 − w = (d − w, Y)), r4, flank B to T2b − w (or P3 − w = (d − w,
/// 0)), r2; every point already whole (rounding to nearest keeps it), the
/// far side less w (R-G75TOOL).
fn finish_contour(g: &Square) -> (At, Vec<(Local, At)>) {
    let (w, f, y, d) = (g.tool, g.f, g.depth, g.width);
    let less = |p: At, shift: i64| (p.0 - shift, p.1);
    let mut moves = Vec::new();
    let corner_move = |index: usize, shift: i64, moves: &mut Vec<(Local, At)>| {
        if let Some((start, end, centre)) = feature(g, index) {
            let motion = match centre {
                None => Local::Feed,
                Some(c) => {
                    let mut turn = clockwise(g, start, end, c);
                    if g.slip == Slip::BottomRoundsReversed && (index == corner::R3 || index == corner::R4) {
                        turn = !turn;
                    }
                    Local::Arc { centre: less(c, shift), clockwise: turn }
                }
            };
            moves.push((motion, less(end, shift)));
        }
    };
    let t = g.tangents;
    let start = if t[corner::R1] > 0 { (-t[corner::R1], 0) } else { (0, 0) };
    corner_move(corner::R1, 0, &mut moves);
    moves.push((Local::Feed, if t[corner::R3] > 0 { (0, y - f * t[corner::R3]) } else { (0, y) }));
    corner_move(corner::R3, 0, &mut moves);
    moves.push((Local::Feed, less(if t[corner::R4] > 0 { (d - t[corner::R4], y) } else { (d, y) }, w)));
    corner_move(corner::R4, w, &mut moves);
    moves.push((Local::Feed, less(if t[corner::R2] > 0 { (d, f * t[corner::R2]) } else { (d, 0) }, w)));
    corner_move(corner::R2, w, &mut moves);
    (start, moves)
}

/// Twin: `spec/src/g75/path.rs`, `local_of`.
fn local_of(g: &Square, p: Point) -> At {
    let s = g.cycle.start;
    (g.sz * (p.z - s.z), g.sx * (p.x - s.x))
}

/// Twin: `spec/src/g75/path.rs`, `LocalFrame::absolute` (R-G75RANGE: X checked before
/// Z; no value here lies beyond `i64`, so none is saturated).
fn absolute(g: &Square, p: At) -> Result<Point, CycleError> {
    let s = g.cycle.start;
    let x = s.x + g.sx * p.1;
    let z = s.z + g.sz * p.0;
    for v in [x, z] {
        if v.abs() > MAX_LENGTH {
            return Err(CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length::new(v, g.cycle.units),
            });
        }
    }
    Ok(Point::new(x, z))
}

/// `cycleref_spec::g75::expand` in integers for a right-angle groove
/// ([`is_square`]): the same moves, or the same alarm with the same values.
///
/// # Errors
///
/// The reference's alarms.
///
/// # Panics
///
/// On a valid cycle that is not a right-angle groove.
pub fn expand(c: &G75Cycle) -> Result<Vec<Move>, CycleError> {
    expand_with(c, Slip::None)
}

/// [`expand`] with the deliberate error `slip` (the controls' mutants).
///
/// Twin: `spec/src/g75/mod.rs`, `expand`: validate; the corner alarms; the
/// tool fit; the ridges; `y_top`; the layers (J0, J1); A11; the approach;
/// the roughing moves and the rough contour (J0, J1); the finishing contour
/// and the return to S (J1, J2); the return to `from`; the range check in
/// move order (end X, end Z, an arc's centre X, Z).
///
/// # Errors
///
/// The reference's alarms.
///
/// # Panics
///
/// On a valid cycle that is not a right-angle groove.
pub fn expand_with(c: &G75Cycle, slip: Slip) -> Result<Vec<Move>, CycleError> {
    c.validate()?;
    assert!(is_square(c), "g75_exact restates right-angle grooves only (A = B = 90°, L = 0)");
    let g = square(c, slip);
    check_corners(&g)?;
    check_tool_fits(&g)?;
    check_ridges(&g)?;
    // Twin: spec/src/g75/roughing.rs, `y_top`: floor(y3), y3 = −f·u3·tan 0 = 0.
    let y_top = 0;
    let layers = if c.path.roughs() { rough_layers(&g, y_top)? } else { Vec::new() };
    let a11 = match layers.first() {
        Some(layer) => (layer.range.first, y_top),
        None => (plunge_range(&g, 1).first, y_top),
    };
    let mut path = Path { at: local_of(&g, c.from), moves: Vec::new() };
    path.rapid(a11, Role::Approach);
    if c.path.roughs() {
        rough_moves(&g, &mut path, &layers, a11, y_top);
        let contour = rough_contour(&g, y_top);
        let mut points = contour.iter();
        if let Some(r0) = points.next() {
            path.rapid_u(r0.0, Role::RoughContour);
        }
        for p in points {
            path.go(Local::Feed, *p, Role::RoughContour);
        }
        path.rapid_u(a11.0, Role::RoughContour);
    }
    if c.path.finishes() {
        let (start, moves) = finish_contour(&g);
        path.rapid_u(start.0, Role::FinishContour);
        path.rapid_y(start.1, Role::FinishContour);
        for (motion, to) in moves {
            path.go(motion, to, Role::FinishContour);
        }
        path.rapid_y(y_top.min(path.at.1), Role::Return);
        path.rapid_u(0, Role::Return);
        path.rapid_y(0, Role::Return);
    }
    path.rapid(local_of(&g, c.from), Role::Return);
    let mut out = Vec::with_capacity(path.moves.len());
    for (motion, to, role) in path.moves {
        let to = absolute(&g, to)?;
        let motion = match motion {
            Local::Rapid => Motion::Rapid,
            Local::Feed => Motion::Feed,
            Local::Arc { centre, clockwise } => Motion::Arc { centre: absolute(&g, centre)?, clockwise },
        };
        out.push(Move { motion, to, role, pass: None });
    }
    Ok(out)
}
