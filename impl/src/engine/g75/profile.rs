//! The public profile of a G75.1 groove ([`groove_profile`]), for plots
//! and proofs: the rounded finishing profile and the roughing region's
//! vertices in absolute coordinates, whatever J is (reading R-G75PROFILE).
//!
//! Twin: `spec/src/g75/profile.rs`, `profile`, which keeps the exact values
//! beside the rounded ones.

use super::contour::{finish_profile, rough_vertices, LocalSegment};
use super::exact::{Evaluator, Fallback};
use super::frame::Frame;
use crate::error::CycleError;
use crate::g75::G75Cycle;
use crate::units::Point;

/// How the finishing profile reaches a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ProfileSegment {
    /// The first point (T1s, or S without r1).
    Start,
    /// A straight segment (an edge, or a chamfer).
    Line,
    /// A round (G02 when `clockwise`, else G03) about `centre`.
    Arc {
        /// The round's centre, absolute.
        centre: Point,
        /// True for G02 (R-G75ARC).
        clockwise: bool,
    },
}

/// A point of the finishing profile and the segment that ends there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ProfilePoint {
    /// The point, absolute.
    pub at: Point,
    /// The segment from the previous point.
    pub segment: ProfileSegment,
}

/// The rounded groove of a G75.1 cycle in absolute coordinates, without the
/// tool width (`docs/G75.md` §3, §5, §8): fixed-size arrays with counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GrooveProfile {
    /// The finishing profile from T1s (or S) to T2s (or P3), rounded to
    /// nearest: F0, (T1a), T3a or P1, (T3b), T4b or P2, (T4c), T2b or P3,
    /// (T2s), the parenthesised ones with their corner. Only the first
    /// `finish_len` entries are meaningful.
    pub finish: [ProfilePoint; 8],
    /// Number of points in [`GrooveProfile::finish`] (4 to 8).
    pub finish_len: usize,
    /// The roughing region's vertices, rounded into the region, before
    /// subtracting the tool width: R0, K1 and K2 (or Q1), K3 and K4 (or
    /// Q2), R3, with K1 (K4) only when `y_K1 > y_top` (`y_K4 > y_top`), as
    /// in the rough contour (§8 step 9). Only the first `rough_len` entries
    /// are meaningful.
    pub rough: [Point; 6],
    /// Number of points in [`GrooveProfile::rough`] (4 to 6).
    pub rough_len: usize,
}

impl GrooveProfile {
    /// The finishing profile's points.
    #[must_use]
    pub fn finishing(&self) -> &[ProfilePoint] {
        self.finish.get(..self.finish_len).unwrap_or(&[])
    }

    /// The roughing region's vertices.
    #[must_use]
    pub fn roughing(&self) -> &[Point] {
        self.rough.get(..self.rough_len).unwrap_or(&[])
    }
}

/// The rounded profile of a G75.1 cycle: the finishing profile (§3, §8 step
/// 10) and the roughing region's vertices (§5, §8 step 9), absolute,
/// without the tool width, whatever J is.
///
/// # Errors
///
/// [`G75Cycle::validate`]'s errors, [`CycleError::CornerTooLarge`],
/// [`CycleError::UndecidedRounding`], and [`CycleError::OutOfRange`] for the
/// first point beyond the range (finishing points in order, each point
/// before its centre, then the roughing vertices). The alarms of the
/// roughing path (groove narrower than the tool, too many pecks) are not
/// checked: the profile exists without them.
///
/// Twin: `spec/src/g75/profile.rs`, `profile`.
pub fn groove_profile(c: &G75Cycle) -> Result<GrooveProfile, CycleError> {
    let mut fallback = Fallback::default();
    let mut ev = Evaluator::checked(c, true, &mut fallback)?;
    let frame = Frame::new(c);
    let (pts, n) = finish_profile(&mut ev)?;
    let y_top = ev.y_top()?;
    let (vs, m) = rough_vertices(&mut ev, y_top)?;
    let mut out = GrooveProfile {
        finish: [ProfilePoint { at: c.start, segment: ProfileSegment::Start }; 8],
        finish_len: 0,
        rough: [c.start; 6],
        rough_len: 0,
    };
    let mut loops = crate::loop_counters::count!(G75_CONTOUR);
    for (slot, p) in out.finish.iter_mut().zip(pts.iter().take(n)) {
        loops.tick();
        let at = frame.point(p.at)?;
        let segment = match p.seg {
            LocalSegment::Start => ProfileSegment::Start,
            LocalSegment::Line => ProfileSegment::Line,
            LocalSegment::Arc { centre, convex } => {
                ProfileSegment::Arc { centre: frame.point(centre)?, clockwise: frame.clockwise(convex) }
            }
        };
        *slot = ProfilePoint { at, segment };
        out.finish_len += 1;
    }
    let mut loops = crate::loop_counters::count!(G75_CONTOUR);
    for (slot, v) in out.rough.iter_mut().zip(vs.iter().take(m)) {
        loops.tick();
        *slot = frame.point(v.at)?;
        out.rough_len += 1;
    }
    Ok(out)
}
