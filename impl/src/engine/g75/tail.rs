//! The fixed tail of a G75.1 path: every move after the roughing (the
//! return to A11, the rough contour, the finishing contour, the returns),
//! computed and range-checked before the first move and kept in a
//! fixed-size array of [`Leg`]s.

use super::contour::Local;
use super::frame::Frame;
use crate::error::CycleError;
use crate::moves::Role;
use crate::units::Point;

/// How a leg of the tail moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum LegKind {
    Rapid,
    Feed,
    /// A round about `centres[centre]` (the centres are kept apart, so that
    /// a leg stays small).
    Arc {
        centre: u8,
        clockwise: bool,
    },
}

/// The role of a leg of the tail: the field-less [`Role`]s it can have
/// (R-G75ROLES), in one byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum TailRole {
    Approach,
    RoughContour,
    FinishContour,
    Return,
}

impl TailRole {
    /// The move's [`Role`].
    pub(super) fn role(self) -> Role {
        match self {
            TailRole::Approach => Role::Approach,
            TailRole::RoughContour => Role::RoughContour,
            TailRole::FinishContour => Role::FinishContour,
            TailRole::Return => Role::Return,
        }
    }
}

/// One precomputed move of the tail (after the pecks).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Leg {
    pub(super) kind: LegKind,
    pub(super) to: Point,
    pub(super) role: TailRole,
}

/// Most rounds of a tail: the finishing contour's r1..r4.
pub(super) const ARCS: usize = 4;

/// Longest tail: 2 approach + 5 rough contour + 1 back to A11 + 2 finishing
/// approach + 7 contour + 3 return + 1 to `from` = 21.
pub(super) const TAIL: usize = 22;

/// Builds the tail in move order from a known position, leaving out empty
/// moves (R-G75ZERO) and range-checking every emitted coordinate (R-G75RANGE).
pub(super) struct TailBuilder {
    pub(super) frame: Frame,
    pub(super) at: Local,
    pub(super) legs: [Leg; TAIL],
    pub(super) len: usize,
    /// The centres of the arcs among `legs`, in order.
    pub(super) centres: [Point; ARCS],
    /// How many of `centres` are set.
    pub(super) arcs: usize,
}

impl TailBuilder {
    /// Appends a move to `to` unless it would not move (R-G75ZERO,
    /// R-G75ARCZERO), range-checking its end and centre (R-G75RANGE).
    ///
    /// Twin: `spec/src/g75/path.rs`, `Path::go` (and `absolute`).
    pub(super) fn go(
        &mut self,
        to: Local,
        motion: Option<(Local, bool)>,
        feed: bool,
        role: TailRole,
    ) -> Result<(), CycleError> {
        match motion {
            None => self.line(to, if feed { LegKind::Feed } else { LegKind::Rapid }, role),
            Some((centre, clockwise)) => {
                if to == self.at {
                    return Ok(());
                }
                let p = self.frame.point(to)?;
                let at = self.frame.point(centre)?;
                let i = self.arcs;
                if let Some(slot) = self.centres.get_mut(i) {
                    *slot = at;
                    self.arcs += 1;
                }
                // i < ARCS = 4.
                let kind = LegKind::Arc { centre: u8::try_from(i).unwrap_or(u8::MAX), clockwise };
                self.push(p, kind, role);
                self.at = to;
                Ok(())
            }
        }
    }

    /// [`TailBuilder::go`] for a straight move (`kind` a rapid or a feed):
    /// its end range-checked, nothing appended when it would not move.
    #[inline]
    fn line(&mut self, to: Local, kind: LegKind, role: TailRole) -> Result<(), CycleError> {
        if to == self.at {
            return Ok(());
        }
        let p = self.frame.point(to)?;
        self.push(p, kind, role);
        self.at = to;
        Ok(())
    }

    /// Appends a leg (at most [`TAIL`], the longest tail).
    #[inline]
    fn push(&mut self, to: Point, kind: LegKind, role: TailRole) {
        if let Some(slot) = self.legs.get_mut(self.len) {
            *slot = Leg { kind, to, role };
            self.len += 1;
        }
    }

    pub(super) fn rapid(&mut self, to: Local, role: TailRole) -> Result<(), CycleError> {
        self.line(to, LegKind::Rapid, role)
    }

    pub(super) fn feed(&mut self, to: Local, role: TailRole) -> Result<(), CycleError> {
        self.line(to, LegKind::Feed, role)
    }
}
