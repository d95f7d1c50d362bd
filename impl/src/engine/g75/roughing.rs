//! The roughing of a G75.1 groove (`docs/G75.md` §7, §8 steps 2–8): the
//! layers, the peck count checked before any move (§9), the range check of
//! the roughing moves in closed form (R-G75RANGE), and the state machine
//! that streams the layer changes, pecks, retracts and steps.
//!
//! Twins: `spec/src/g75/roughing.rs` (`layer_count`, `layer_bottom`,
//! `plunge_range`, `peck_count`, `pecks`, `rough_layers`) and
//! `spec/src/g75/mod.rs`, `Cursor::step`, which makes the same moves a
//! peck at a time.

use super::exact::{plunges_at, Evaluator, Geometry};
use super::frame::Frame;
use super::G75Moves;
use crate::engine::arith::{ceil_div, floor_div, saturate_i64};
use crate::error::CycleError;
use crate::g75::{G75Cycle, MAX_PECKS};
use crate::moves::{Motion, Move, Plunge, Role};
use crate::units::{Point, MAX_LENGTH};

/// The layers of §7: `y_m = min(m·Δv, Y − Δu)`, `M = ceil((Y − Δu)/Δv)`,
/// one layer without V.
///
/// Twin: `spec/src/g75/roughing.rs`, `layer_count` and `layer_bottom`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Layers {
    /// `Y − Δu`, the bottom of the last layer.
    pub(super) rough_bottom: i64,
    /// Δv (0: one layer).
    pub(super) dv: i64,
    /// M.
    pub(super) count: i128,
    /// Reading R-G75LAYER `equal`: M layers of equal depth.
    pub(super) equal: bool,
}

/// The bottom `y_m` of layer `m` (1-based) of `count` layers: `min(m·Δv,
/// Y − Δu)`, or under R-G75LAYER `equal` (`equal`) `m·(D div M) + min(m,
/// D mod M)` with D = Y − Δu; `Y − Δu` without V (`dv` = 0).
///
/// Twin: `spec/src/g75/roughing.rs`, `layer_bottom`.
pub(super) fn layer_bottom(m: i128, dv: i64, rough_bottom: i64, count: i128, equal: bool) -> i64 {
    let d = i128::from(rough_bottom);
    if dv <= 0 {
        rough_bottom
    } else if equal {
        // count = ceil(D/Δv) ≥ 1.
        saturate_i64(m * (d / count) + m.min(d % count))
    } else {
        saturate_i64((m * i128::from(dv)).min(d))
    }
}

impl Layers {
    /// The layers of a validated cycle: `0 < Y − Δu < 2^27`, `1 ≤ Δv <
    /// 2^27`, so `M < 2^27`.
    pub(super) fn new(c: &G75Cycle, g: &Geometry) -> Layers {
        let rough_bottom = g.depth - g.du;
        let dv = c.layer.unwrap_or(0);
        let count = if dv > 0 { ceil_div(i128::from(rough_bottom), i128::from(dv)) } else { 1 };
        Layers { rough_bottom, dv, count, equal: c.readings.equal_layers }
    }

    /// The bottom `y_m` of layer `m` (1-based).
    pub(super) fn bottom(&self, m: i128) -> i64 {
        layer_bottom(m, self.dv, self.rough_bottom, self.count, self.equal)
    }

    /// The first layer (2..=M) whose bottom lies beyond `y`, for `y` below
    /// Y − Δu and at least layer 1's bottom, in closed form.
    fn first_below(&self, y: i128) -> i128 {
        let dv = i128::from(self.dv);
        if !self.equal {
            return floor_div(y, dv) + 1;
        }
        // Bottoms m·(q + 1) for m ≤ r, then m·q + r (q ≥ 1: M ≤ D).
        let d = i128::from(self.rough_bottom);
        let (q, r) = (d / self.count, d % self.count);
        let m = floor_div(y, q + 1) + 1;
        if m <= r {
            m
        } else {
            floor_div(y - r, q) + 1
        }
    }
}

/// §9: the pecks of a roughing cycle, counted before any move, in closed
/// form per layer (R-G75PECK: a plunge from `t` to `b` has `ceil((b −
/// t)/Δi)` pecks). `layer1` and `last_layer` are the plunge ranges already
/// found for layers 1 and M; the others are evaluated here, in order.
///
/// Returns the number of plunges of the whole roughing (each ends in one
/// [`Role::PlungeRetract`](crate::Role::PlungeRetract) move).
///
/// Twin: `spec/src/g75/roughing.rs`, `rough_layers` (with `peck_count`).
pub(super) fn check_peck_count(
    ev: &mut Evaluator<'_>,
    c: &G75Cycle,
    layers: &Layers,
    y_top: i128,
    (a11, a1f): (i128, i128),
    (last_first, last_last): (i128, i128),
) -> Result<u64, CycleError> {
    let (di, dk) = (i128::from(c.peck), i128::from(c.step));
    let limit = i128::from(MAX_PECKS);
    let (count, dv, rough_bottom) = (layers.count, layers.dv, layers.rough_bottom);
    let pecks = |top: i128, bottom: i128| ceil_div(bottom - top, di);
    // Every layer has at least one plunge: the pecks of one plunge per
    // layer are a lower bound, in closed form (layers 2..M−1 are Δv deep).
    let mut lower = pecks(y_top, i128::from(layers.bottom(1)));
    if count >= 2 && layers.equal {
        // R-G75LAYER `equal`: layers 2..=M, the first r one increment
        // deeper than q (layer 1 among them when r ≥ 1).
        let d = i128::from(rough_bottom);
        let (q, r) = (d / count, d % count);
        let deeper = (r - 1).max(0);
        lower += deeper * pecks(0, q + 1) + (count - 1 - deeper) * pecks(0, q);
    } else if count >= 2 {
        let dvi = i128::from(dv);
        lower += (count - 2) * pecks(0, dvi) + pecks((count - 1) * dvi, i128::from(rough_bottom));
    }
    if lower > limit {
        return Err(CycleError::TooManyPecks { limit: MAX_PECKS });
    }
    // Now M ≤ lower ≤ MAX_PECKS: count exactly, layer by layer (and the
    // plunges, which the `nc` heading names).
    let (mut total, mut all_plunges): (i128, i128) = (0, 0);
    let mut top = y_top;
    let mut loops = crate::loop_counters::count!(G75_LAYERS);
    for m in 1..=count {
        loops.tick();
        let bottom = i128::from(layers.bottom(m));
        let (first, last) = if m == 1 {
            (a11, a1f)
        } else if m == count {
            (last_first, last_last)
        } else {
            ev.plunges(layers.bottom(m))?
        };
        // first ≤ last (the last layer's check and monotony), Δk ≥ 1.
        let plunges = ceil_div(last - first, dk) + 1;
        all_plunges = all_plunges.saturating_add(plunges);
        total = total.saturating_add(plunges.saturating_mul(pecks(top, bottom)));
        if total > limit {
            return Err(CycleError::TooManyPecks { limit: MAX_PECKS });
        }
        top = bottom;
    }
    // Every plunge has at least one peck: plunges ≤ pecks ≤ MAX_PECKS.
    Ok(u64::try_from(all_plunges).unwrap_or(u64::MAX))
}

/// Where the roughing state machine is within a plunge or a layer change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum RoughStep {
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
pub(super) struct Roughing {
    /// Number of layers M.
    pub(super) layers: u32,
    /// Current layer m (1-based).
    pub(super) m: u32,
    /// `Y − Δu`.
    pub(super) rough_bottom: i64,
    /// Δv (0: one layer).
    pub(super) dv: i64,
    /// Δi.
    pub(super) di: i64,
    /// Δk.
    pub(super) dk: i64,
    /// `e_x = f·e`.
    pub(super) ex: i64,
    /// Reading R-G75PECK `as-written`: the retract e not clamped at the
    /// plunge's start.
    pub(super) peck_as_written: bool,
    /// Reading R-G75LAYER `equal`: layers of equal depth.
    pub(super) equal_layers: bool,
    /// Top of the previous layer (for the LayerChange along Z).
    pub(super) prev_top: i64,
    /// Top of this layer.
    pub(super) top: i64,
    /// Bottom of this layer `y_m`.
    pub(super) bottom: i64,
    /// `A_m1`.
    pub(super) first: i64,
    /// `A_mf`.
    pub(super) last: i64,
    /// Current plunge position `A_mn`.
    pub(super) u: i64,
    /// Current plunge number n.
    pub(super) n: u32,
    /// End of the next peck before clamping: `top + j·Δi`.
    pub(super) target: i64,
    /// End of the last peck.
    pub(super) depth: i64,
    /// Next candidate move.
    pub(super) sub: RoughStep,
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
pub(super) fn check_roughing(
    c: &G75Cycle,
    frame: &Frame,
    y_top: i128,
    (a11, a1f): (i128, i128),
    layers: &Layers,
) -> Result<(), CycleError> {
    let max = i128::from(MAX_LENGTH);
    // The deepest y whose X is in range, and the furthest u whose Z is.
    let y_lim = max - i128::from(frame.sx) * i128::from(frame.start.x);
    let u_lim = max - i128::from(frame.sz) * i128::from(frame.start.z);
    let (di, dk) = (i128::from(c.peck), i128::from(c.step));
    let rough_bottom = i128::from(c.depth.abs() - c.allowance_x);
    let dv = i128::from(c.layer.unwrap_or(0));
    let y1 = i128::from(layers.bottom(1));
    // The first peck end beyond y_lim in a plunge from `top` to `bottom`
    // (top ≤ y_lim < bottom).
    let peck_beyond = |top: i128, bottom: i128| -> Result<(), CycleError> {
        let j = floor_div(y_lim - top, di) + 1;
        frame.coordinate(frame.x((top + j * di).min(bottom))).map(|_| ())
    };
    // Reading R-G75PECK `as-written`: a retract above the plunge's start,
    // highest after layer 1's first peck when it stops short of the
    // bottom (e_x > Δi): the move after that peck, before any other.
    let ex = i128::from(c.x_mode.factor()) * i128::from(c.retract);
    if c.readings.peck_retract_as_written && ex > di && y_top + di < y1 && y_top + di <= y_lim {
        frame.coordinate(frame.x(y_top + di - ex))?;
    }
    if y1 > y_lim {
        return peck_beyond(y_top, y1);
    }
    if a1f > u_lim {
        let u = a11 + (floor_div(u_lim - a11, dk) + 1) * dk;
        return frame.coordinate(frame.z(if u < a1f { u } else { a1f })).map(|_| ());
    }
    if rough_bottom > y_lim && layers.count >= 2 && dv > 0 {
        // The first layer whose bottom m·Δv (or Y − Δu; under R-G75LAYER
        // `equal` its own) is beyond y_lim: m ≥ 2.
        let m = layers.first_below(y_lim);
        return peck_beyond(i128::from(layers.bottom(m - 1)), i128::from(layers.bottom(m)));
    }
    Ok(())
}

impl G75Moves {
    /// The next roughing move, or `None` at the end of the roughing.
    ///
    /// Each step updates the state in place and names its candidate move
    /// (motion, local end, role); a candidate that would not move is left
    /// out (R-G75ZERO) and the next step taken.
    ///
    /// Twin: `spec/src/g75/mod.rs`, `Cursor::step` (with
    /// `spec/src/g75/roughing.rs`, `pecks`). Inlined into
    /// [`Iterator::next`] (issue 33: its call was a sixth of a move).
    #[inline(always)]
    pub(super) fn next_rough(&mut self) -> Option<Move> {
        let mut loops = crate::loop_counters::count!(G75_ROUGH_NEXT);
        loop {
            loops.tick();
            let r = &mut self.rough;
            let plunge = Plunge { layer: r.m, number: r.n };
            let (motion, u, y, role) = match r.sub {
                RoughStep::LayerZ => {
                    r.sub = RoughStep::LayerX;
                    (Motion::Rapid, r.first, r.prev_top, Role::LayerChange(r.m))
                }
                RoughStep::LayerX => {
                    r.sub = RoughStep::Peck;
                    (Motion::Rapid, r.first, r.top, Role::LayerChange(r.m))
                }
                RoughStep::Peck => {
                    // R-G75PECK: peck j to min(top + j·Δi, y_m).
                    let y = r.target.min(r.bottom);
                    r.target = r.target.saturating_add(r.di);
                    r.depth = y;
                    r.sub = if y < r.bottom { RoughStep::Retract } else { RoughStep::PlungeRetract };
                    (Motion::Feed, r.u, y, Role::Peck(plunge))
                }
                RoughStep::Retract => {
                    r.sub = RoughStep::Peck;
                    // R-G75PECK: clamped at the plunge's start, or e as
                    // written (`peck_as_written`, decided once per cycle).
                    let y = if r.peck_as_written { r.depth - r.ex } else { r.top.max(r.depth - r.ex) };
                    (Motion::Rapid, r.u, y, Role::PeckRetract(plunge))
                }
                RoughStep::PlungeRetract => {
                    r.sub = RoughStep::After;
                    (Motion::Rapid, r.u, r.top, Role::PlungeRetract(plunge))
                }
                RoughStep::After => {
                    if r.u < r.last {
                        // Step 7: on by Δk while below A_mf, then to A_mf.
                        let next = r.u.saturating_add(r.dk);
                        let u = if next < r.last { next } else { r.last };
                        r.u = u;
                        r.n = r.n.saturating_add(1);
                        r.target = r.top.saturating_add(r.di);
                        r.sub = RoughStep::Peck;
                        (Motion::Rapid, u, r.top, Role::Step(Plunge { layer: r.m, number: r.n }))
                    } else if r.m < r.layers {
                        self.next_layer();
                        continue;
                    } else {
                        return None;
                    }
                }
            };
            // R-G75ZERO: a move that would not move is left out. The
            // absolute point of a local one (range-checked up front).
            if (u, y) != self.at {
                self.at = (u, y);
                let p = &self.frame;
                let to = Point::new(p.start.x + p.sx * y, p.start.z + p.sz * u);
                return Some(Move { motion, to, role, pass: None });
            }
        }
    }

    /// Moves on to the next layer (steps 8 and 2). Kept out of line: once
    /// a layer, with the fallback's contexts in its frame, so that the
    /// per-move path stays small.
    #[inline(never)]
    pub(super) fn next_layer(&mut self) {
        let r = self.rough;
        let m = r.m.saturating_add(1);
        let bottom = layer_bottom(i128::from(m), r.dv, r.rough_bottom, i128::from(r.layers), r.equal_layers);
        // Decided in expand_g75 for every layer (the peck count), so the
        // fallback to the previous range is unreachable.
        let (first, last) = plunges_at(&self.geometry, self.region.as_ref(), bottom, &mut self.stats)
            .map_or((r.first, r.last), |(a, b)| (saturate_i64(a), saturate_i64(b)));
        self.rough = Roughing {
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
            sub: RoughStep::LayerZ,
            ..r
        };
    }
}
