//! The tool path of `docs/G75.md` §8 in the local frame: the path being
//! built (empty moves left out), the map to absolute X/Z with the range
//! check, and the roughing moves of steps 2–8.
//!
//! Twin: `impl/src/engine/g75/frame.rs` (`Frame::point`, the range check),
//! `impl/src/engine/g75/tail.rs` (`TailBuilder`) and
//! `impl/src/engine/g75/roughing.rs` (`G75Moves::next_rough`).
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use cycleref::error::{CycleError, Field};
use cycleref::moves::{Plunge, Role};
use cycleref::units::{Length, Point, MAX_LENGTH};

use super::*;

/// A move in the local frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) struct LocalMove {
    pub(super) motion: LocalMotion,
    pub(super) to: LocalPoint,
    pub(super) role: Role,
}

/// The tool path being built: the current position and the moves.
pub(super) struct Path {
    pub(super) at: LocalPoint,
    pub(super) moves: Vec<LocalMove>,
}

impl Path {
    /// Appends a move unless it ends where the tool is (R-G75ZERO: "No move
    /// is emitted whose end is the current position"; R-G75ARCZERO: also an
    /// arc whose rounded end is its rounded start).
    ///
    /// Twin: `impl/src/engine/g75/tail.rs`, `TailBuilder::go`.
    pub(super) fn go(&mut self, motion: LocalMotion, to: LocalPoint, role: Role) {
        // R-G75ZERO, R-G75ARCZERO: arcs are dropped like any empty move.
        if to == self.at {
            return;
        }
        self.at = to;
        self.moves.push(LocalMove { motion, to, role });
    }

    pub(super) fn rapid(&mut self, to: LocalPoint, role: Role) {
        self.go(LocalMotion::Rapid, to, role);
    }

    /// A rapid along Z (u) to `u`, the depth kept.
    pub(super) fn rapid_u(&mut self, u: i128, role: Role) {
        self.rapid(LocalPoint::new(u, self.at.y), role);
    }

    /// A rapid along X (y) to `y`, the axial position kept.
    pub(super) fn rapid_y(&mut self, y: i128, role: Role) {
        self.rapid(LocalPoint::new(self.at.u, y), role);
    }
}

/// `from`, the tool position before the cycle, in the local frame.
pub(super) fn local_of(g: &Groove, p: Point) -> LocalPoint {
    let (s, x, z) = (g.cycle.start, i128::from(p.x), i128::from(p.z));
    LocalPoint::new(g.sz * (z - i128::from(s.z)), g.sx * (x - i128::from(s.x)))
}

/// A local point in absolute X/Z (`docs/G75.md` §2: `Z = Z_S + sz·u`,
/// `X = X_S + sx·y`), X checked first, then Z.
///
/// R-G75RANGE: a coordinate beyond ±[`MAX_LENGTH`] is refused with
/// `OutOfRange { field: PassCoordinate, value }`, `value` the coordinate
/// (saturated to the `i64` range if it lies beyond it).
///
/// Twin: `impl/src/engine/g75/frame.rs`, `Frame::point`.
pub(super) fn absolute(g: &Groove, p: LocalPoint) -> Result<Point, CycleError> {
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
///
/// Twin: `impl/src/engine/g75/roughing.rs`, `G75Moves::next_rough`.
pub(super) fn rough_moves(g: &Groove, path: &mut Path, layers: &[Layer], a11: LocalPoint, y_top: i128) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// R-G75RANGE: a coordinate beyond the range is reported with its
    /// value, saturated to `i64` on its own side. The groove of
    /// `G75_SLOPE` has H < 0 (`sx` = −1) and D < 0 (`sz` = −1) and S at
    /// X80.000 Z0, so a local depth of −2^64 is X 80 000 + 2^64 (beyond
    /// `i64::MAX`, reported as it), a depth of 2^64 is X 80 000 − 2^64
    /// (reported as `i64::MIN`), and the same along Z from u. Mutants of
    /// `absolute` that read the sign wrongly (cargo-mutants 83:57 `v < 0`
    /// → `v == 0`, `v > 0`) report the other end.
    #[test]
    fn a_coordinate_beyond_i64_is_reported_saturated_on_its_side() {
        let g = groove(&cycleref::examples::G75_SLOPE);
        assert_eq!((g.sx, g.sz), (-1, -1));
        let beyond = |value: i64| {
            Err(CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length::new(value, cycleref::Units::IS_B_METRIC),
            })
        };
        let big = 1_i128 << 64;
        assert_eq!(absolute(&g, LocalPoint::new(0, -big)), beyond(i64::MAX));
        assert_eq!(absolute(&g, LocalPoint::new(0, big)), beyond(i64::MIN));
        assert_eq!(absolute(&g, LocalPoint::new(-big, 0)), beyond(i64::MAX));
        assert_eq!(absolute(&g, LocalPoint::new(big, 0)), beyond(i64::MIN));
        // Within i64 but beyond the range: the value itself.
        assert_eq!(absolute(&g, LocalPoint::new(0, -1_000_000_000)), beyond(1_000_080_000));
    }
}
