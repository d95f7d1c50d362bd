//! The rounded contours of a G75.1 groove in local coordinates `(u, y)`,
//! before the tool width and before the range check (`i128`): the
//! finishing profile of §8 step 10 (rounded to nearest, §6) and the rough
//! contour's vertices of §8 step 9 (rounded into the region).
//!
//! Both the moves ([`super::expand_g75`]) and the public profile
//! ([`super::groove_profile`]) are built from them. Twins:
//! `spec/src/g75/contour.rs`, `finish_contour` and `rough_vertices`.

use super::exact::{Evaluator, Quantity};
use crate::error::CycleError;
use crate::g75::corner;

/// A rounded local point `(u, y)`.
pub(super) type Local = (i128, i128);

/// The kind of segment that ends at a point of the finishing profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum LocalSegment {
    /// The first point.
    Start,
    /// A straight feed (an edge or a chamfer).
    Line,
    /// A round about `centre`; `convex` for the outer corners r1, r2.
    Arc {
        /// Rounded centre.
        centre: Local,
        /// True for r1 and r2 (material corners), false for r3 and r4.
        convex: bool,
    },
}

/// One point of the finishing profile: the point, its segment and whether
/// it lies on the far side (moved by −w for a grooving tool, §4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct ProfileLocal {
    pub(super) at: Local,
    pub(super) seg: LocalSegment,
    pub(super) far: bool,
}

/// The finishing profile of §8 step 10, rounded to nearest (§6), without
/// the tool width: F0 (T1s or S), then r1, flank A, r3, bottom, r4, flank
/// B, r2. At most 8 points.
///
/// Twin: `spec/src/g75/contour.rs`, `finish_contour`.
pub(super) fn finish_profile(ev: &mut Evaluator<'_>) -> Result<([ProfileLocal; 8], usize), CycleError> {
    let g = ev.g;
    let start = ProfileLocal { at: (0, 0), seg: LocalSegment::Start, far: false };
    let mut pts = [start; 8];
    let mut n = 0;
    let mut push = |p: ProfileLocal| {
        if let Some(slot) = pts.get_mut(n) {
            *slot = p;
            n += 1;
        }
    };
    let line = |at: Local, far: bool| ProfileLocal { at, seg: LocalSegment::Line, far };
    // F0 = T1s, or S without r1.
    if g.size(corner::R1) > 0 {
        push(ProfileLocal {
            at: (ev.nearest(Quantity::T1sU)?, ev.nearest(Quantity::T1sY)?),
            seg: LocalSegment::Start,
            far: false,
        });
        let t1a = (ev.nearest(Quantity::T1aU)?, ev.nearest(Quantity::T1aY)?);
        if g.is_round(corner::R1) {
            let centre = (ev.nearest(Quantity::C1U)?, ev.nearest(Quantity::C1Y)?);
            push(ProfileLocal { at: t1a, seg: LocalSegment::Arc { centre, convex: true }, far: false });
        } else {
            push(line(t1a, false));
        }
    } else {
        push(start);
    }
    // Flank A to T3a (or P1), r3 to T3b.
    let depth = i128::from(g.depth);
    if g.size(corner::R3) > 0 {
        push(line((ev.nearest(Quantity::T3aU)?, ev.nearest(Quantity::T3aY)?), false));
        let t3b = (ev.nearest(Quantity::T3bU)?, depth);
        if g.is_round(corner::R3) {
            let centre = (t3b.0, ev.nearest(Quantity::C3Y)?);
            push(ProfileLocal { at: t3b, seg: LocalSegment::Arc { centre, convex: false }, far: false });
        } else {
            push(line(t3b, false));
        }
    } else {
        push(line((ev.nearest(Quantity::P1U)?, depth), false));
    }
    // The bottom to T4b (or P2), r4 to T4c.
    if g.size(corner::R4) > 0 {
        let t4b = ev.nearest(Quantity::T4bU)?;
        push(line((t4b, depth), true));
        let t4c = (ev.nearest(Quantity::T4cU)?, ev.nearest(Quantity::T4cY)?);
        if g.is_round(corner::R4) {
            let centre = (t4b, ev.nearest(Quantity::C4Y)?);
            push(ProfileLocal { at: t4c, seg: LocalSegment::Arc { centre, convex: false }, far: true });
        } else {
            push(line(t4c, true));
        }
    } else {
        push(line((ev.nearest(Quantity::P2U)?, depth), true));
    }
    // Flank B to T2b (or P3), r2 to T2s.
    if g.size(corner::R2) > 0 {
        push(line((ev.nearest(Quantity::T2bU)?, ev.nearest(Quantity::T2bY)?), true));
        let t2s = (ev.nearest(Quantity::T2sU)?, ev.nearest(Quantity::T2sY)?);
        if g.is_round(corner::R2) {
            let centre = (ev.nearest(Quantity::C2U)?, ev.nearest(Quantity::C2Y)?);
            push(ProfileLocal { at: t2s, seg: LocalSegment::Arc { centre, convex: true }, far: true });
        } else {
            push(line(t2s, true));
        }
    } else {
        push(line((ev.nearest(Quantity::U3)?, ev.nearest(Quantity::Y3)?), true));
    }
    Ok((pts, n))
}

/// A vertex of the rough contour (§8 step 9), before subtracting w; `far`
/// for the right-hand vertices (K3, K4, Q2, R3), which are moved by −w.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct RoughLocal {
    pub(super) at: Local,
    pub(super) far: bool,
}

/// R0, K1 and K2 (or Q1), K3 and K4 (or Q2), R3, rounded into the region
/// (§6, §8 step 9), before subtracting w. At most 6 vertices.
///
/// R0 and R3 are `left` and `right` at `y_top` (R-G75MAXMIN: the chord
/// where it is the boundary). R-G75K1Y: K1's u is flank A's at the integer
/// `y_K1` (K4's flank B's at `y_K4`), rounded in; K1 is a vertex only when
/// `y_K1 > y_top` (K4 when `y_K4 > y_top`): otherwise the chord is the
/// boundary over the whole depth and R0 (R3) already lies on it. K2 and K3
/// are vertices whenever r3, r4 are programmed.
///
/// Twin: `spec/src/g75/contour.rs`, `rough_vertices`.
pub(super) fn rough_vertices(
    ev: &mut Evaluator<'_>,
    y_top: i128,
) -> Result<([RoughLocal; 6], usize), CycleError> {
    let g = ev.g;
    let bottom = i128::from(g.depth - g.du);
    let mut v = [RoughLocal { at: (0, 0), far: false }; 6];
    let mut n = 0;
    let mut push = |at: Local, far: bool| {
        if let Some(slot) = v.get_mut(n) {
            *slot = RoughLocal { at, far };
            n += 1;
        }
    };
    // R0 = (ceil(left(y_top)), y_top).
    push((ev.ceil(Quantity::Left(y_top))?, y_top), false);
    if g.size(corner::R3) > 0 {
        let y_k1 = ev.floor(Quantity::YK1)?;
        if y_k1 > y_top {
            push((ev.ceil(Quantity::FlankA(y_k1))?, y_k1), false);
        }
        push((ev.ceil(Quantity::K2)?, bottom), false);
    } else {
        push((ev.ceil(Quantity::FlankA(bottom))?, bottom), false);
    }
    if g.size(corner::R4) > 0 {
        push((ev.floor(Quantity::K3)?, bottom), true);
        let y_k4 = ev.floor(Quantity::YK4)?;
        if y_k4 > y_top {
            push((ev.floor(Quantity::FlankB(y_k4))?, y_k4), true);
        }
    } else {
        push((ev.floor(Quantity::FlankB(bottom))?, bottom), true);
    }
    // R3 = (floor(right(y_top)) − w, y_top), w subtracted by the caller.
    push((ev.floor(Quantity::Right(y_top))?, y_top), true);
    Ok((v, n))
}
