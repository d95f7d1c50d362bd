//! The fixed tail of a G75.1 path: every move after the roughing (the
//! return to A11, the rough contour, the finishing contour, the returns),
//! built once per plan in the local frame ([`LocalLeg`]s), then placed for
//! each groove: range-checked before the first move and kept in a
//! fixed-size array of [`Leg`]s.

use super::contour::Local;
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

/// One move of the tail in the local frame, as a [`super::G75Plan`] keeps
/// it: the same for a groove wherever it is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct LocalLeg {
    pub(super) kind: LegKind,
    pub(super) to: Local,
    pub(super) role: TailRole,
}

/// Builds the tail in move order from a known position, in the local frame,
/// leaving out empty moves (R-G75ZERO, R-G75ARCZERO): the frame is a
/// translation with signs, so a move is empty in the local frame exactly
/// when it is in absolute coordinates. The range check (R-G75RANGE) is
/// made when the legs are placed ([`super::place`]), leg by leg in this
/// order, each end before its arc's centre.
#[derive(Clone, Copy, Debug)]
pub(super) struct TailBuilder {
    /// The position after the last leg (the position before the first
    /// while there is none).
    pub(super) at: Local,
    pub(super) legs: [LocalLeg; TAIL],
    pub(super) len: usize,
    /// The centres of the arcs among `legs`, in order.
    pub(super) centres: [Local; ARCS],
    /// How many of `centres` are set.
    pub(super) arcs: usize,
}

impl TailBuilder {
    /// No leg yet, the tool at `at`.
    pub(super) fn new(at: Local) -> TailBuilder {
        TailBuilder {
            at,
            legs: [LocalLeg { kind: LegKind::Rapid, to: at, role: TailRole::Return }; TAIL],
            len: 0,
            centres: [at; ARCS],
            arcs: 0,
        }
    }

    /// Appends a move to `to` unless it would not move (R-G75ZERO,
    /// R-G75ARCZERO): a line, or (`motion`) a round about its centre
    /// turning clockwise or not.
    ///
    /// Twin: `spec/src/g75/path.rs`, `Path::go` (and `absolute`).
    pub(super) fn go(&mut self, to: Local, motion: Option<(Local, bool)>, feed: bool, role: TailRole) {
        match motion {
            None => self.line(to, if feed { LegKind::Feed } else { LegKind::Rapid }, role),
            Some((centre, clockwise)) => {
                if to == self.at {
                    return;
                }
                let i = self.arcs;
                if let Some(slot) = self.centres.get_mut(i) {
                    *slot = centre;
                    self.arcs += 1;
                }
                // i < ARCS = 4.
                let kind = LegKind::Arc { centre: u8::try_from(i).unwrap_or(u8::MAX), clockwise };
                self.push(to, kind, role);
            }
        }
    }

    /// [`TailBuilder::go`] for a straight move (`kind` a rapid or a feed):
    /// nothing appended when it would not move.
    #[inline]
    fn line(&mut self, to: Local, kind: LegKind, role: TailRole) {
        if to != self.at {
            self.push(to, kind, role);
        }
    }

    /// Appends a leg (at most [`TAIL`], the longest tail).
    #[inline]
    fn push(&mut self, to: Local, kind: LegKind, role: TailRole) {
        if let Some(slot) = self.legs.get_mut(self.len) {
            *slot = LocalLeg { kind, to, role };
            self.len += 1;
        }
        self.at = to;
    }

    pub(super) fn rapid(&mut self, to: Local, role: TailRole) {
        self.line(to, LegKind::Rapid, role);
    }

    pub(super) fn feed(&mut self, to: Local, role: TailRole) {
        self.line(to, LegKind::Feed, role);
    }
}
