//! The G75.1 harnesses can fail: each one, run on an engine broken on
//! purpose in the way its property forbids, finds the break. The mutants
//! wrap the real engine and change its output, standing for the bugs a
//! vendor's groove cycle could have.

use cycleref::{CycleError, G75Cycle, Motion, Move, Role};
use cycleref_proofs::groove::{self, local_of, GrooveDomain, GrooveEngine, GrooveFixedPoint, Moves};
use cycleref_proofs::shim::{self, Mode};

/// Runs `body` exhaustively within `max_runs` on the real engine (the
/// control: it must pass, every declared cover satisfied) and on the
/// mutant, whose run must fail with `expected` in the failing assertion's
/// own message (not the check's name, which every shim panic carries).
fn caught<M: GrooveEngine>(max_runs: u64, body: impl Fn(&dyn GrooveEngine), mutant: M, expected: &str) {
    let mode = Mode::Exhaustive { max_runs };
    let r = shim::caught(mode, || body(&GrooveFixedPoint), || body(&mutant), expected);
    eprintln!("control: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
}

struct Mutant<F>(F);

impl<F: Fn(&G75Cycle, Vec<Move>) -> Vec<Move>> GrooveEngine for Mutant<F> {
    fn expand(&self, c: &G75Cycle) -> Result<Moves, CycleError> {
        cycleref::expand_g75(c).map(|m| (self.0)(c, m.collect()))
    }
}

/// Small right-angle grooves in every unit code (IS-B/IS-C, mm/inch,
/// diameter/radius), both signs of H and D, pointed tool or widths 1..=2,
/// with and without layers: 5 × 5 × 2 × 3 × 3 × 2 × 4 × 4 × 8 = 57 600.
const SMALL: GrooveDomain = GrooveDomain {
    depth: (1, 5),
    width: (0, 4),
    peck: (1, 2),
    step: (1, 3),
    retract: (1, 1),
    layer: (0, 2),
    allowance_x: (0, 1),
    allowance_z: (0, 0),
    tool_width: (-1, 2),
    corner: (0, 0),
    corner_kinds: (0, 0),
    path: (0, 0),
    signs: (0, 3),
    units: (0, 7),
    ..GrooveDomain::SQUARE
};

/// The run budget of every case.
const BUDGET: u64 = 300_000;

#[test]
fn a_peck_too_deep_is_caught() {
    // The first peck of every plunge goes one increment further (Δi + 1).
    let e = Mutant(|c: &G75Cycle, mut v: Vec<Move>| {
        let mut seen = None;
        for m in &mut v {
            if let Role::Peck(p) = m.role {
                if seen != Some(p) {
                    seen = Some(p);
                    m.to.x += c.radial_sign();
                }
            }
        }
        v
    });
    caught(BUDGET, |e| groove::groove_pecks_and_steps(&SMALL, e), e, "a peck takes at most Δi of new depth");
}

#[test]
fn a_step_too_long_is_caught() {
    // The last plunge of a layer is placed one increment beyond Δk.
    let e = Mutant(|c: &G75Cycle, mut v: Vec<Move>| {
        let mut shift = false;
        for m in &mut v {
            match m.role {
                Role::Step(_) => {
                    let (u0, _) = local_of(c, m.to);
                    let _ = u0;
                    m.to.z += c.axial_sign() * c.step;
                    shift = true;
                }
                Role::Peck(_) | Role::PeckRetract(_) | Role::PlungeRetract(_) if shift => {
                    m.to.z += c.axial_sign() * c.step;
                }
                _ => shift = false,
            }
        }
        v
    });
    caught(BUDGET, |e| groove::groove_pecks_and_steps(&SMALL, e), e, "a step goes on by at most Δk");
}

#[test]
fn a_plunge_short_of_its_layer_is_caught() {
    // The last plunge of the last layer stops one increment short.
    let e = Mutant(|c: &G75Cycle, mut v: Vec<Move>| {
        let last = v.iter().rposition(|m| matches!(m.role, Role::Peck(_)));
        if let Some(i) = last {
            if local_of(c, v[i].to).1 > 1 {
                v[i].to.x -= c.radial_sign();
            }
        }
        v
    });
    caught(BUDGET, |e| groove::groove_layers(&SMALL, e), e, "the last layer reaches |H| - U");
}

#[test]
fn a_plunge_into_the_allowance_is_caught() {
    // Plunges placed one increment towards flank A (rounding outwards).
    let e = Mutant(|c: &G75Cycle, mut v: Vec<Move>| {
        for m in &mut v {
            if matches!(m.role, Role::Peck(_) | Role::PeckRetract(_) | Role::PlungeRetract(_)) {
                m.to.z -= c.axial_sign();
            }
        }
        v
    });
    // Corners of size 0..=1 (the cover "with a bottom corner"), IS-C inch
    // diameter and IS-B metric radius: 4 × 5 × 2 × 3 × 2 × 4 × 16 × 4 × 2 = 122 880.
    let d =
        GrooveDomain { depth: (1, 4), peck: (3, 3), step: (1, 2), corner: (0, 1), units: (3, 4), ..SMALL };
    caught(BUDGET, |e| groove::groove_inside(&d, e), e, "leaves the roughing region");
}

/// The finishing contour's slice: corners of size 0..=1, rounds, J1 and J2;
/// pecking fixed (the contour does not depend on it): 16 × 2 × 2 × 3 × 4 ×
/// 4 × 8 = 24 576 grooves.
const PROFILE: GrooveDomain = GrooveDomain {
    corner: (0, 1),
    corner_kinds: (15, 15),
    path: (1, 2),
    depth: (6, 7),
    width: (3, 5),
    peck: (1, 1),
    step: (3, 3),
    layer: (0, 0),
    allowance_x: (0, 0),
    ..SMALL
};

#[test]
fn a_round_without_its_centre_is_caught() {
    // Rounds cut as straight chamfers.
    let e = Mutant(|_: &G75Cycle, mut v: Vec<Move>| {
        for m in &mut v {
            if let Motion::Arc { .. } = m.motion {
                m.motion = Motion::Feed;
            }
        }
        v
    });
    let d = GrooveDomain { corner: (0, 1), corner_kinds: (15, 15), ..PROFILE };
    caught(
        BUDGET,
        |e| groove::groove_finish_is_profile(&d, e),
        e,
        "the finishing contour is the programmed profile",
    );
}

#[test]
fn a_finish_without_the_width_compensation_is_caught() {
    // The far side cut with the reference corner (no -w shift).
    let e = Mutant(|c: &G75Cycle, mut v: Vec<Move>| {
        let w = c.width_of_tool();
        let mut far = false;
        for m in &mut v {
            if m.role == Role::FinishContour {
                let (u, _) = local_of(c, m.to);
                if far || u > 0 && m.motion != Motion::Rapid && local_of(c, m.to).1 == c.depth.abs() {
                    far = true;
                }
                if far {
                    m.to.z += c.axial_sign() * w;
                }
            }
        }
        v
    });
    let d = GrooveDomain { tool_width: (1, 2), width: (3, 6), ..PROFILE };
    caught(
        BUDGET,
        |e| groove::groove_finish_is_profile(&d, e),
        e,
        "the finishing contour is the programmed profile",
    );
}

/// The material harness's slice: grooving tools, with and without layers,
/// every corner size 0..=3 (chamfers), J0 and J1, deep enough for ridges
/// and slivers (each a declared cover): 221 184 grooves.
const MATERIAL: GrooveDomain = GrooveDomain::MATERIAL;

#[test]
fn a_step_at_the_plunge_bottom_is_caught() {
    // The tool steps along Z before it retracts: the rapid runs at the
    // bottom of the plunge, through the material beside it.
    let e = Mutant(|_: &G75Cycle, mut v: Vec<Move>| {
        for i in 1..v.len().saturating_sub(1) {
            if matches!(v[i].role, Role::PlungeRetract(_)) && matches!(v[i + 1].role, Role::Step(_)) {
                v[i].to.z = v[i + 1].to.z;
                v[i].to.x = v[i - 1].to.x;
            }
        }
        v
    });
    caught(BUDGET, |e| groove::groove_material(&MATERIAL, e), e, "runs through material");
}

#[test]
fn a_rough_contour_left_out_is_caught() {
    // J0 without step 9: the band beside the plunges stays.
    let e = Mutant(|_: &G75Cycle, v: Vec<Move>| {
        v.into_iter().filter(|m| m.role != Role::RoughContour || m.motion == Motion::Rapid).collect()
    });
    caught(BUDGET, |e| groove::groove_material(&MATERIAL, e), e, "inside the region");
}
