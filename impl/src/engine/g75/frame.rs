//! The mapping from a G75.1 groove's local frame `(u, y)` to absolute
//! X and Z (`docs/G75.md` §2), the range check of every emitted coordinate
//! (reading R-G75RANGE) and the turning sense of a round (R-G75ARCDIR).
//!
//! Twins: `spec/src/g75/path.rs`, `absolute` (the range check) and
//! `spec/src/g75/contour.rs`, `clockwise`.

use super::contour::Local;
use crate::engine::arith::saturate_i64;
use crate::error::{CycleError, Field};
use crate::g75::G75Cycle;
use crate::units::{Length, Point, Units, MAX_LENGTH};

/// The mapping from the local frame to absolute X/Z (§2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Frame {
    /// S.
    pub(super) start: Point,
    /// `sx` (±1, [`G75Cycle::radial_sign`]).
    pub(super) sx: i64,
    /// `sz` (±1, [`G75Cycle::axial_sign`]).
    pub(super) sz: i64,
    /// For error values.
    pub(super) units: Units,
}

impl Frame {
    pub(super) fn new(c: &G75Cycle) -> Frame {
        Frame { start: c.start, sx: c.radial_sign(), sz: c.axial_sign(), units: c.units }
    }

    /// Absolute X of local `y` (`sx` is ±1: a negation, not a product).
    pub(super) fn x(&self, y: i128) -> i128 {
        i128::from(self.start.x) + if self.sx < 0 { -y } else { y }
    }

    /// Absolute Z of local `u` (`sz` is ±1).
    pub(super) fn z(&self, u: i128) -> i128 {
        i128::from(self.start.z) + if self.sz < 0 { -u } else { u }
    }

    /// An absolute coordinate within the range, as `i64`.
    pub(super) fn coordinate(&self, v: i128) -> Result<i64, CycleError> {
        match i64::try_from(v) {
            Ok(x) if (-MAX_LENGTH..=MAX_LENGTH).contains(&x) => Ok(x),
            _ => {
                let value = saturate_i64(v);
                Err(CycleError::OutOfRange {
                    field: Field::PassCoordinate,
                    value: Length::new(value, self.units),
                })
            }
        }
    }

    /// The absolute point of a local one, X checked before Z.
    ///
    /// Twin: `spec/src/g75/path.rs`, `absolute`.
    pub(super) fn point(&self, p: Local) -> Result<Point, CycleError> {
        let x = self.coordinate(self.x(p.1))?;
        let z = self.coordinate(self.z(p.0))?;
        Ok(Point::new(x, z))
    }

    /// [`Frame::point`] of a local point known to lie in the range (in
    /// the box of a plan's points whose corners [`Frame::point`] accepted):
    /// the same point, without the checks.
    pub(super) fn point_in_range(&self, p: Local) -> Point {
        Point::new(saturate_i64(self.x(p.1)), saturate_i64(self.z(p.0)))
    }

    /// Whether a round turns clockwise seen with +Z to the right and +X up
    /// (R-G75ARC). In local (u, y/f) coordinates the cross product of
    /// (start − centre) and (end − centre) is `ρ²·sin(a + L)` for r1,
    /// `ρ²·sin(b − L)` for r2 (both > 0: convex corners turn one way) and
    /// `−ρ²·sin a`, `−ρ²·sin b` for r3, r4 (concave, the other way); the map
    /// to (Z, X) multiplies it by `sz·sx`. Negative is clockwise.
    ///
    /// Twin: `spec/src/g75/contour.rs`, `clockwise`.
    pub(super) fn clockwise(&self, convex: bool) -> bool {
        let local = if convex { 1 } else { -1 };
        local * self.sx * self.sz < 0
    }
}
