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
use cycleref::moves::Role;
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
#[derive(Clone, Debug)]
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
#[cfg(test)]
pub(super) fn absolute(g: &Groove, p: LocalPoint) -> Result<Point, CycleError> {
    LocalFrame::of(g).absolute(p)
}

/// What the map to absolute X/Z needs of a groove: S, the signs and the units, in
/// integers (a stream keeps it; the groove's exact values stay behind).
#[derive(Clone, Copy, Debug)]
pub(super) struct LocalFrame {
    start: Point,
    sx: i128,
    sz: i128,
    units: cycleref::Units,
}

impl LocalFrame {
    pub(super) fn of(g: &Groove) -> LocalFrame {
        LocalFrame { start: g.cycle.start, sx: g.sx, sz: g.sz, units: g.cycle.units }
    }

    /// `p` in absolute X/Z (`docs/G75.md` §2: `Z = Z_S + sz·u`, `X = X_S
    /// + sx·y`), X checked first, then Z (R-G75RANGE).
    pub(super) fn absolute(&self, p: LocalPoint) -> Result<Point, CycleError> {
        let s = self.start;
        let x = i128::from(s.x).saturating_add(self.sx.saturating_mul(p.y));
        let z = i128::from(s.z).saturating_add(self.sz.saturating_mul(p.u));
        // R-G75RANGE: X before Z; the value saturates to i64.
        let checked = |v: i128| -> Result<i64, CycleError> {
            if v.abs() > i128::from(MAX_LENGTH) {
                let value = i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX });
                return Err(CycleError::OutOfRange {
                    field: Field::PassCoordinate,
                    value: Length::new(value, self.units),
                });
            }
            Ok(i64::try_from(v).unwrap_or_default())
        };
        let x = checked(x)?;
        let z = checked(z)?;
        Ok(Point::new(x, z))
    }
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
