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

/// The moves of a G75.1 cycle (`docs/G75.md` §8), in absolute X/Z, every
/// move with `pass: None`, one at a time:
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
/// Errors come in the order of `docs/G75.md`: `validate()`; the opening
/// below the bottom (R-G75SLOPE `falls-towards-d`); the corner alarms
/// (flank A, bottom, flank B); the groove narrower than the tool;
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
/// Validate, then stream: every value is decided and every move made and
/// checked once, keeping none, so that any alarm comes before the first
/// move; then the moves are made again as they are taken, a plunge's peck
/// at a time. Memory is the plan's (the contours' few points), whatever
/// the number of layers, plunges and pecks.
///
/// # Errors
///
/// The manual's alarms, as [`CycleError`].
///
/// Twin: `impl/src/engine/g75/mod.rs`, `expand_g75`.
pub fn moves(c: &G75Cycle) -> Result<impl Iterator<Item = Move> + Clone, CycleError> {
    let plan = plan(c)?;
    // Every move made and its coordinates checked, in move order; none kept.
    let mut check = Cursor::new(plan);
    let mut chunk = Vec::new();
    while check.next_chunk(&mut chunk) {
        for m in chunk.drain(..) {
            absolute_move(&check.plan.frame, &m)?;
        }
    }
    let mut cursor = Cursor::new(check.plan);
    let mut local = Vec::new();
    Ok(crate::pass::PassStream::new(move |out: &mut Vec<Move>| {
        local.clear();
        let more = cursor.next_chunk(&mut local);
        // Checked above: the same moves, so the same coordinates.
        out.extend(local.iter().filter_map(|m| absolute_move(&cursor.plan.frame, m).ok()));
        more
    }))
}

/// The moves of a G75.1 cycle, collected: [`moves`] for a caller that
/// keeps them all (tests, and the differential comparisons).
///
/// # Errors
///
/// As [`moves`].
pub fn expand(c: &G75Cycle) -> Result<Vec<Move>, CycleError> {
    Ok(moves(c)?.collect())
}

/// `m` in absolute X/Z (R-G75RANGE: its end X then Z, then an arc's
/// centre X then Z).
fn absolute_move(frame: &LocalFrame, m: &LocalMove) -> Result<Move, CycleError> {
    let to = frame.absolute(m.to)?;
    let motion = match m.motion {
        LocalMotion::Rapid => Motion::Rapid,
        LocalMotion::Feed => Motion::Feed,
        LocalMotion::Arc { centre, clockwise } => Motion::Arc { centre: frame.absolute(centre)?, clockwise },
    };
    Ok(Move { motion, to, role: m.role, pass: None })
}

/// Every value of a cycle decided, in the order of R-G75DECIDE: what the
/// moves are made from, in integers (the groove's exact values are made
/// again from the cycle for each batch of layers: they are not `Send`).
#[derive(Clone, Debug)]
struct Plan {
    cycle: G75Cycle,
    frame: LocalFrame,
    /// `Δk`, `Δi` and `e_x` (`Groove::step`, `::peck`, `::retract`).
    step: i128,
    peck: i128,
    retract: i128,
    y_top: i128,
    /// The layers (J0, J1; 0 for J2), each checked ([`check_layers`]).
    layers: i128,
    a11: LocalPoint,
    /// The rough contour's points (J0, J1).
    contour: Vec<LocalPoint>,
    /// The finishing contour's start and moves (J1, J2).
    finish: Option<(LocalPoint, Vec<ContourMove>)>,
    from: LocalPoint,
}

fn plan(c: &G75Cycle) -> Result<Plan, CycleError> {
    c.validate()?;
    let g = groove(c);
    // R-G75DECIDE: values are decided in this order (corners, last layer,
    // y_top, layers, rough contour, finishing contour in path order).
    check_corners(&g)?;
    check_tool_fits(&g)?;
    check_ridges(&g)?;
    let y_top = y_top(&g)?;
    let layers = if c.path.roughs() { check_layers(&g, y_top)? } else { 0 };
    let a11 = if layers >= 1 {
        LocalPoint::new(layer(&g, 1, y_top)?.range.first, y_top)
    } else {
        LocalPoint::new(plunge_range(&g, 1)?.first, y_top)
    };
    let contour = if c.path.roughs() { rough_contour(&g, y_top)? } else { Vec::new() };
    let finish = if c.path.finishes() { Some(finish_contour(&g)?) } else { None };
    let from = local_of(&g, c.from);
    let frame = LocalFrame::of(&g);
    Ok(Plan {
        cycle: *c,
        frame,
        step: g.step,
        peck: g.peck,
        retract: g.retract,
        y_top,
        layers,
        a11,
        contour,
        finish,
        from,
    })
}

/// Where the moves have got to.
#[derive(Clone, Copy, Debug)]
enum Stage {
    Approach,
    /// Layer `m` next (its change of layer, then its plunges).
    Layer(i128),
    /// Plunge `n` of `layer` next.
    Plunge(Layer, i128),
    /// Peck `j` of plunge `n` (at `a`) of `layer` next.
    Peck(Layer, i128, i128, i128),
    /// The end of the roughing: back to A11, the rough contour.
    RoughContour,
    Finish,
    Return,
    Done,
}

/// The moves of a [`Plan`], made a few at a time: steps 1 to 10 of
/// `docs/G75.md` §8.
///
/// The roughing moves (steps ②–⑧):
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
///
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `G75Moves::next_rough`.
#[derive(Clone, Debug)]
struct Cursor {
    plan: Plan,
    path: Path,
    stage: Stage,
    /// Layers `first..first + len` (at most [`LAYER_BATCH`]).
    layers: Vec<Layer>,
    first: i128,
}

/// How many layers a stream decides at a time (from the groove made again
/// for them).
const LAYER_BATCH: i128 = 1024;

impl Cursor {
    fn new(plan: Plan) -> Cursor {
        let at = plan.from;
        Cursor {
            plan,
            path: Path { at, moves: Vec::new() },
            stage: Stage::Approach,
            layers: Vec::new(),
            first: 1,
        }
    }

    /// Layer `m`, from the batch that holds it (decided by `plan` already,
    /// so never an error here: `None` would end the moves).
    fn layer(&mut self, m: i128) -> Option<Layer> {
        let held = usize::try_from(m - self.first).ok().and_then(|i| self.layers.get(i));
        if let Some(layer) = held {
            return Some(*layer);
        }
        let g = groove(&self.plan.cycle);
        self.layers.clear();
        self.first = m;
        for k in m..=(m + LAYER_BATCH - 1).min(self.plan.layers) {
            self.layers.push(layer(&g, k, self.plan.y_top).ok()?);
        }
        self.layers.first().copied()
    }

    /// Appends the next few moves (those of one peck, at most) to `out`;
    /// false once there are none.
    fn next_chunk(&mut self, out: &mut Vec<LocalMove>) -> bool {
        loop {
            self.step();
            if !self.path.moves.is_empty() {
                out.append(&mut self.path.moves);
                return true;
            }
            if matches!(self.stage, Stage::Done) {
                return false;
            }
        }
    }

    /// Makes the moves of the current stage and moves to the next.
    #[allow(clippy::too_many_lines, reason = "one arm a stage of docs/G75.md §8, in path order")]
    fn step(&mut self) {
        let fetched = match self.stage {
            Stage::Layer(m) if m <= self.plan.layers => self.layer(m),
            _ => None,
        };
        let (p, path) = (&self.plan, &mut self.path);
        self.stage = match self.stage {
            Stage::Approach => {
                path.rapid(p.a11, Role::Approach);
                if p.layers >= 1 {
                    Stage::Layer(1)
                } else if !p.contour.is_empty() {
                    Stage::RoughContour
                } else {
                    Stage::Finish
                }
            }
            Stage::Layer(m) if m > p.layers => {
                path.rapid_y(p.y_top, Role::Approach);
                path.rapid_u(p.a11.u, Role::Approach);
                Stage::RoughContour
            }
            Stage::Layer(m) => {
                // Decided by `plan` (check_layers): never missing here.
                let Some(layer) = fetched else {
                    self.stage = Stage::Done;
                    return;
                };
                let m32 = u32::try_from(m).unwrap_or(u32::MAX);
                // R-G75ROLES: LayerChange(m) names the layer it moves to.
                if m >= 2 {
                    path.rapid_u(layer.range.first, Role::LayerChange(m32));
                    path.rapid_y(layer.top, Role::LayerChange(m32));
                }
                Stage::Plunge(layer, 1)
            }
            Stage::Plunge(layer, n) if n > layer.range.count(p.step) => Stage::Layer(layer.number + 1),
            Stage::Plunge(layer, n) => {
                let a = layer.range.position(p.step, n);
                if n >= 2 {
                    path.rapid_u(a, Role::Step(plunge(&layer, n)));
                }
                Stage::Peck(layer, n, a, 1)
            }
            Stage::Peck(layer, n, a, j) => {
                // R-G75PECK: peck j feeds to min(top + j·Δi, bottom); after a
                // peck short of the bottom the tool retracts to
                // max(top, end − e) (none when e = 0), to end − e under
                // `as-written`.
                let role = plunge(&layer, n);
                let to = (layer.top + j * p.peck).min(layer.bottom);
                path.go(LocalMotion::Feed, LocalPoint::new(a, to), Role::Peck(role));
                if to >= layer.bottom {
                    path.rapid(LocalPoint::new(a, layer.top), Role::PlungeRetract(role));
                    Stage::Plunge(layer, n + 1)
                } else {
                    if p.retract > 0 {
                        path.rapid(
                            LocalPoint::new(a, retract_to(&p.cycle, layer.top, to, p.retract)),
                            Role::PeckRetract(role),
                        );
                    }
                    Stage::Peck(layer, n, a, j + 1)
                }
            }
            Stage::RoughContour => {
                let mut points = p.contour.iter();
                if let Some(r0) = points.next() {
                    path.rapid_u(r0.u, Role::RoughContour);
                    for q in points {
                        path.go(LocalMotion::Feed, *q, Role::RoughContour);
                    }
                    path.rapid_u(p.a11.u, Role::RoughContour);
                }
                Stage::Finish
            }
            Stage::Finish => {
                if let Some((start, moves)) = &p.finish {
                    // Along X to min(y_top, F0's y) first: F0 lies above
                    // y_top only when the opening falls (R-G75SLOPE).
                    path.rapid_y(p.y_top.min(start.y), Role::FinishContour);
                    path.rapid_u(start.u, Role::FinishContour);
                    path.rapid_y(start.y, Role::FinishContour);
                    for m in moves {
                        path.go(m.motion, m.to, Role::FinishContour);
                    }
                    path.rapid_y(p.y_top.min(path.at.y), Role::Return);
                    path.rapid_u(0, Role::Return);
                    path.rapid_y(0, Role::Return);
                }
                Stage::Return
            }
            Stage::Return => {
                path.rapid(p.from, Role::Return);
                Stage::Done
            }
            Stage::Done => Stage::Done,
        };
    }
}

/// R-G75ROLES: plunge `n` of `layer`, as the roles name it.
fn plunge(layer: &Layer, n: i128) -> cycleref::moves::Plunge {
    cycleref::moves::Plunge {
        layer: u32::try_from(layer.number).unwrap_or(u32::MAX),
        number: u32::try_from(n).unwrap_or(u32::MAX),
    }
}
