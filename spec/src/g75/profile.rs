//! The whole groove with its exact and rounded values ([`profile`]), for
//! tests and plots.
//!
//! Twin: `impl/src/engine/g75/profile.rs`, `groove_profile` (rounded values
//! only, fixed-size).

use cycleref::error::CycleError;
use cycleref::g75::{CornerKind, G75Cycle};

use crate::real::Real;

use super::*;

/// A profile point, exact and rounded to nearest (local frame, without the
/// tool width).
#[derive(Clone, Debug)]
pub struct ProfilePoint {
    /// The exact point.
    pub exact: RealPoint,
    /// `floor(v + 1/2)` of each coordinate.
    pub rounded: LocalPoint,
}

impl ProfilePoint {
    pub(super) fn of(p: RealPoint) -> Result<ProfilePoint, CycleError> {
        let rounded = round_nearest(&p)?;
        Ok(ProfilePoint { exact: p, rounded })
    }
}

/// A corner feature of the profile.
#[derive(Clone, Debug)]
pub struct CornerProfile {
    /// Chamfer or round.
    pub kind: CornerKind,
    /// Its tangent length `t` (radius increments).
    pub tangent: Real,
    /// Its first point along the finishing path.
    pub start: ProfilePoint,
    /// Its last point along the finishing path.
    pub end: ProfilePoint,
    /// A round's centre.
    pub centre: Option<ProfilePoint>,
    /// A round's direction: G02 when true (R-G75ARC).
    pub clockwise: Option<bool>,
}

/// The programmed (finishing) profile of a cycle (`docs/G75.md` §3), in
/// the local frame, without the tool width.
#[derive(Clone, Debug)]
pub struct Profile {
    /// S, the origin.
    pub s: ProfilePoint,
    /// P1, bottom corner on the start side.
    pub p1: ProfilePoint,
    /// P2, bottom corner on the far side.
    pub p2: ProfilePoint,
    /// P3, far corner of the opening.
    pub p3: ProfilePoint,
    /// The corner features indexed by [`corner`](cycleref::g75::corner) (`None`: sharp).
    pub corners: [Option<CornerProfile>; 4],
    /// `floor(y3)`.
    pub y_top: i128,
    /// The vertices of the roughing region the rough contour visits
    /// ([`rough_vertices`]), without the tool width: R0 =
    /// `(ceil(left(y_top)), y_top)`, K1 (when t3 > 0 and `y_K1 > y_top`),
    /// K2 (or Q1), K3 (or Q2), K4 (when t4 > 0 and `y_K4 > y_top`), R3 =
    /// `(floor(right(y_top)), y_top)`.
    pub rough: Vec<RoughVertex>,
}

/// The profile of a cycle, exact and rounded, after `validate()` and the
/// corner alarms, with the rough contour's vertices (`docs/G75.md` §8 step
/// 9) whatever J is.
///
/// # Errors
///
/// As [`expand`], up to the corner alarms; the alarms of the roughing path
/// (groove narrower than the tool, too many pecks) are not checked.
///
/// Twin: `impl/src/engine/g75/profile.rs`, `groove_profile`.
pub fn profile(c: &G75Cycle) -> Result<Profile, CycleError> {
    c.validate()?;
    let g = groove(c);
    check_corners(&g)?;
    let mut corners: [Option<CornerProfile>; 4] = [None, None, None, None];
    for (index, slot) in corners.iter_mut().enumerate() {
        if let Some(feat) = feature(&g, index) {
            let clockwise = match &feat.centre {
                Some(centre) => Some(clockwise(&g, &feat.start, &feat.end, centre)?),
                None => None,
            };
            *slot = Some(CornerProfile {
                kind: feat.kind,
                tangent: g.tangents[index].clone(),
                start: ProfilePoint::of(feat.start)?,
                end: ProfilePoint::of(feat.end)?,
                centre: feat.centre.map(ProfilePoint::of).transpose()?,
                clockwise,
            });
        }
    }
    let (s, p1, p2, p3) = (
        ProfilePoint::of(RealPoint::new(int(0), int(0)))?,
        ProfilePoint::of(p1(&g))?,
        ProfilePoint::of(p2(&g))?,
        ProfilePoint::of(p3(&g))?,
    );
    let y_top = y_top(&g)?;
    let rough = rough_vertices(&g, y_top)?;
    Ok(Profile { s, p1, p2, p3, corners, y_top, rough })
}
