//! The roughing region's boundaries (`docs/G75.md` §5): the flanks and the
//! corner chords moved in by the allowances, and `left`, `right`, the
//! region at a depth.
//!
//! Twin: `impl/src/engine/g75/exact.rs`, `Region` (`flank_a`, `flank_b`,
//! `chord3`, `chord4`, `left`, `right`).
//!
//! Restated in integers for right-angle grooves, function by function:
//! `proofs/src/g75_exact.rs` (each there names its twin here).

use cycleref::g75::corner;

use crate::real::Real;

use super::*;

/// `flankA_r(y) = (y/f)·cot a + Δw` (`u ≥` this): flank A moved into the
/// groove by the Z allowance ("W(Δw): Z 轴的精加工余量", R-G75ROUGH).
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::flank_a`.
#[must_use]
pub fn flank_a_rough(g: &Groove, y: &Real) -> Real {
    y / int(g.f) * &g.angles.cot_a + int(g.allowance_z)
}

/// `flankB_r(y) = (Y/f)·cot a + d + ((Y − y)/f)·cot b − Δw` (`u ≤` this):
/// flank B moved into the groove by Δw (R-G75ROUGH).
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::flank_b`.
#[must_use]
pub fn flank_b_rough(g: &Groove, y: &Real) -> Real {
    p2(g).u + (int(g.depth) - y) / int(g.f) * &g.angles.cot_b - int(g.allowance_z)
}

/// `bottom_r = Y − Δu` (`y ≤` this): the bottom moved up by the X allowance
/// ("U(Δu): X 轴的精加工余量", R-G75ROUGH). `validate()` has made it > 0.
#[must_use]
pub fn bottom_rough(g: &Groove) -> i128 {
    g.depth - g.allowance_x
}

/// `chord3_r(y) = (Y/f)·cot a + t3 + Δw − ((Y − Δu − y)/f)·cot(a/2)`
/// (`u ≥` this, only when t3 > 0): the chord T3a–T3b of corner r3 moved by
/// both allowances (R-G75ROUGH: "a bottom corner feature (r3, r4) is kept by
/// its chord … moved by both allowances").
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::chord3`.
#[must_use]
pub fn chord3_rough(g: &Groove, y: &Real) -> Option<Real> {
    if !has_corner(g, corner::R3) {
        return None;
    }
    let rise = (int(bottom_rough(g)) - y) / int(g.f) * &g.angles.cot_half_a;
    Some(p1(g).u + &g.tangents[corner::R3] + int(g.allowance_z) - rise)
}

/// `chord4_r(y) = (Y/f)·cot a + d − t4 − Δw + ((Y − Δu − y)/f)·cot(b/2)`
/// (`u ≤` this, only when t4 > 0): the chord T4b–T4c of corner r4 moved by
/// both allowances (R-G75ROUGH).
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::chord4`.
#[must_use]
pub fn chord4_rough(g: &Groove, y: &Real) -> Option<Real> {
    if !has_corner(g, corner::R4) {
        return None;
    }
    let rise = (int(bottom_rough(g)) - y) / int(g.f) * &g.angles.cot_half_b;
    Some(p2(g).u - &g.tangents[corner::R4] - int(g.allowance_z) + rise)
}

/// `left(y) = max(flankA_r(y), chord3_r(y))`: the start-side boundary of
/// the roughing region at depth `y`.
///
/// R-G75MAXMIN: the maximum is itself a real number whose enclosure is
/// the interval extension of max; it is rounded as one value, so its
/// rounding never waits for the comparison of the two branches (which may
/// be exactly equal, e.g. at a layer bottom on the corner of the two
/// lines); `ceil(max(p, q)) = max(ceil p, ceil q)` in any case.
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::left`.
#[must_use]
pub fn left(g: &Groove, y: &Real) -> Real {
    let flank = flank_a_rough(g, y);
    // R-G75MAXMIN: max as one real (interval max), never a decided comparison.
    match chord3_rough(g, y) {
        Some(chord) => flank.max(&chord),
        None => flank,
    }
}

/// `right(y) = min(flankB_r(y), chord4_r(y))`: the far-side boundary of
/// the roughing region at depth `y` (R-G75MAXMIN as [`left`]).
///
/// Twin: `impl/src/engine/g75/exact.rs`, `Region::right`.
#[must_use]
pub fn right(g: &Groove, y: &Real) -> Real {
    let flank = flank_b_rough(g, y);
    // R-G75MAXMIN: min as one real (interval min), never a decided comparison.
    match chord4_rough(g, y) {
        Some(chord) => flank.min(&chord),
        None => flank,
    }
}
