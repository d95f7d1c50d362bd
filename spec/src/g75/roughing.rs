//! Layers and plunges (`docs/G75.md` §7): `y_top`, the layers, each layer's
//! plunge range, the tool-width and ridge alarms, the pecks and their
//! count.
//!
//! Twin: `impl/src/engine/g75/roughing.rs` (`Layers`, `check_peck_count`,
//! the `Roughing` state machine) and `impl/src/engine/g75/exact.rs`,
//! `Evaluator::plunges`.
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use cycleref::error::CycleError;
use cycleref::g75::MAX_PECKS;
use cycleref::units::Length;

use super::*;

/// `y_top = floor(y3)`: the top of layer 1, the highest point of the
/// opening (≤ 0; 0 when L = 0), so that every plunge of layer 1 starts in
/// the air (R-G75LAYER).
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`].
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, in `expand_with` (0).
pub fn y_top(g: &Groove) -> Result<i128, CycleError> {
    // R-G75SLOPE `falls-towards-d`: the opening's highest point is S.
    if g.cycle.readings.slope_falls_towards_d {
        return Ok(0);
    }
    floor(&y3(g))
}

/// `M = ceil((Y − Δu)/Δv)`, or 1 without V (R-G75LAYER; "V(Δv): 径向切深时
/// 的安全距离 … 单次切削循环时的最大允许切深距离 (分层次进行切削, 单层最大深度) …
/// 未输入时默认为断续切削到凹槽最大深度 (不分层, 走刀方式与 G75 类似)").
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `Layers::new`.
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `layer_count`.
#[must_use]
pub fn layer_count(g: &Groove) -> i128 {
    match g.layer {
        Some(v) => (bottom_rough(g) + v - 1) / v,
        None => 1,
    }
}

/// `y_m = min(m·Δv, Y − Δu)`, the bottom of layer `m` (1-based); `Y − Δu`
/// without V (R-G75LAYER). Under R-G75LAYER `equal`, with D = Y − Δu and
/// M = [`layer_count`]: `m·(D div M) + min(m, D mod M)` (the first D mod M
/// layers one increment deeper).
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `Layers::bottom`.
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `layer_bottom`.
#[must_use]
pub fn layer_bottom(g: &Groove, m: i128) -> i128 {
    match g.layer {
        Some(_) if g.cycle.readings.equal_layers => {
            let (d, count) = (bottom_rough(g), layer_count(g));
            m * (d / count) + m.min(d % count)
        }
        Some(v) => (m.saturating_mul(v)).min(bottom_rough(g)),
        None => bottom_rough(g),
    }
}

/// The top of layer `m`: `y_top` for layer 1, `y_(m−1)` after (R-G75LAYER:
/// "Layer m ≥ 2 starts at `y_{m−1}`").
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `layer_top`.
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
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Evaluator::plunges`.
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `plunge_range`.
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
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `check_tool_fits`.
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
/// [`CycleError::RidgesInLayers`] (reading R-G75RIDGE `refuse`, the
/// default; none under `as-written`); [`CycleError::UndecidedRounding`].
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `check_ridges`.
pub fn check_ridges(g: &Groove) -> Result<(), CycleError> {
    let c = &g.cycle;
    // Reading R-G75RIDGE `as-written`: the path as steps ②⑦⑧ write it.
    if c.readings.ridges_as_written || !c.path.roughs() || layer_count(g) < 2 || i128::from(c.step) <= g.tool
    {
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
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `peck_count`.
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
/// `max(top, end − e_x)` (no retract when e = 0; `end − e_x` under
/// R-G75PECK `as-written`, [`retract_to`]), so every peck takes at most Δi
/// (Δi/2 of radius) of new depth. Step ⑥ (the retract to Amn) is
/// the caller's.
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `G75Moves::next_rough`.
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
        let retract = (g.retract > 0).then(|| retract_to(&g.cycle, top, to, g.retract));
        out.push(Peck { to, retract });
        j += 1;
    }
}

/// Where the retract e (`e_x` in X-word units) after a peck ending at `to`
/// ends, in a plunge from `top` (R-G75PECK): `max(top, to − e_x)`
/// (`clamped`, the default), or `to − e_x` (`as-written`: step ④ "径向(X
/// 轴)快速移动退刀 e", even above Amn).
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `G75Moves::next_rough`
/// (`RoughStep::Retract`).
#[must_use]
pub fn retract_to(c: &G75Cycle, top: i128, to: i128, retract: i128) -> i128 {
    if c.readings.peck_retract_as_written {
        to - retract
    } else {
        top.max(to - retract)
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

/// The roughing layers, collected ([`check_layers`], then [`layer`] for
/// each): for tests; the moves take them one at a time.
///
/// # Errors
///
/// As [`check_layers`].
pub fn rough_layers(g: &Groove, y_top: i128) -> Result<Vec<Layer>, CycleError> {
    let count = check_layers(g, y_top)?;
    (1..=count).map(|m| layer(g, m, y_top)).collect()
}

/// Layer `m` (1-based): its top, its bottom and its plunges.
///
/// # Errors
///
/// [`CycleError::UndecidedRounding`] (from its plunge range).
pub fn layer(g: &Groove, m: i128, y_top: i128) -> Result<Layer, CycleError> {
    Ok(Layer {
        number: m,
        top: layer_top(g, m, y_top),
        bottom: layer_bottom(g, m),
        range: plunge_range(g, m)?,
    })
}

/// The number of roughing layers, after the closed-form count of their
/// pecks (`docs/G75.md` §9): `Σ_m (plunges of m) × ceil((y_m − top_m)/Δi)`,
/// refused when above [`MAX_PECKS`]. Every layer has at least one peck, so
/// more layers than the limit are refused at once. Every layer's plunge
/// range is decided here, in layer order; none is kept.
///
/// R-G75PECKJ2: only a cycle that roughs (J0, J1) makes pecks; J2 has none
/// and is never refused for them (and this is not called for it).
///
/// # Errors
///
/// [`CycleError::TooManyPecks`]; [`CycleError::UndecidedRounding`].
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `check_peck_count`.
///
/// Restated in integers (right-angle grooves): `proofs/src/g75_exact.rs`, `rough_layers`.
pub fn check_layers(g: &Groove, y_top: i128) -> Result<i128, CycleError> {
    let too_many = CycleError::TooManyPecks { limit: MAX_PECKS };
    let count = layer_count(g);
    let limit = i128::from(MAX_PECKS);
    // R-G75PECKJ2: called for J0 and J1 only. Every layer has a peck, so
    // more layers than the limit are refused before any range is rounded.
    if count > limit {
        return Err(too_many);
    }
    let mut total = 0_i128;
    for m in 1..=count {
        let (top, bottom) = (layer_top(g, m, y_top), layer_bottom(g, m));
        let range = plunge_range(g, m)?;
        let n = range.count(g.step).min(limit + 1);
        let p = peck_count(top, bottom, g.peck).min(limit + 1);
        total += n * p;
        if total > limit {
            return Err(too_many);
        }
    }
    Ok(count)
}
