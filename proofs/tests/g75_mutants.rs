//! The G75.1 harnesses can fail: each one, run on an engine broken on
//! purpose in the way its property forbids, finds the break. The mutants
//! wrap the real engine and change its output, standing for the bugs a
//! vendor's groove cycle could have.

use cycleref::{CycleError, G75Cycle, Motion, Move, Role};
use cycleref_proofs::groove::{self, local_of, GrooveDomain, GrooveEngine, Moves};
use cycleref_proofs::shim::{check, Mode};

struct Mutant<F>(F);

impl<F: Fn(&G75Cycle, Vec<Move>) -> Vec<Move>> GrooveEngine for Mutant<F> {
    fn expand(&self, c: &G75Cycle) -> Result<Moves, CycleError> {
        cycleref::expand_g75(c).map(|m| (self.0)(c, m.collect()))
    }
}

const SMALL: GrooveDomain = GrooveDomain {
    depth: (1, 8),
    width: (0, 6),
    peck: (1, 3),
    step: (1, 3),
    retract: (1, 1),
    layer: (0, 3),
    allowance_x: (0, 1),
    allowance_z: (0, 0),
    tool_width: (-1, 2),
    corner: (0, 0),
    corner_kinds: (0, 0),
    path: (0, 0),
    ..GrooveDomain::SQUARE
};

const EXHAUSTIVE: Mode = Mode::Exhaustive { max_runs: 400_000 };

#[test]
#[should_panic(expected = "pecks")]
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
    check("pecks", EXHAUSTIVE, || groove::groove_pecks_and_steps(&SMALL, &e));
}

#[test]
#[should_panic(expected = "steps")]
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
    check("steps", EXHAUSTIVE, || groove::groove_pecks_and_steps(&SMALL, &e));
}

#[test]
#[should_panic(expected = "layers")]
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
    check("layers", EXHAUSTIVE, || groove::groove_layers(&SMALL, &e));
}

#[test]
#[should_panic(expected = "inside")]
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
    check("inside", EXHAUSTIVE, || groove::groove_inside(&SMALL, &e));
}

#[test]
#[should_panic(expected = "profile")]
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
    let d = GrooveDomain {
        corner: (0, 1),
        corner_kinds: (15, 15),
        path: (1, 2),
        depth: (6, 7),
        width: (3, 5),
        ..SMALL
    };
    check("profile", EXHAUSTIVE, || groove::groove_finish_is_profile(&d, &e));
}

#[test]
#[should_panic(expected = "profile")]
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
    let d = GrooveDomain { tool_width: (1, 2), path: (1, 2), depth: (6, 7), width: (3, 6), ..SMALL };
    check("profile", EXHAUSTIVE, || groove::groove_finish_is_profile(&d, &e));
}

/// Grooving tools, layers, J0: the material harness's slice.
const MATERIAL: GrooveDomain = GrooveDomain { tool_width: (1, 2), corner: (0, 1), signs: (0, 1), ..SMALL };

#[test]
#[should_panic(expected = "material")]
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
    check("material", EXHAUSTIVE, || groove::groove_material(&MATERIAL, &e));
}

#[test]
#[should_panic(expected = "material")]
fn a_rough_contour_left_out_is_caught() {
    // J0 without step 9: the band beside the plunges stays.
    let e = Mutant(|_: &G75Cycle, v: Vec<Move>| {
        v.into_iter().filter(|m| m.role != Role::RoughContour || m.motion == Motion::Rapid).collect()
    });
    check("material", EXHAUSTIVE, || groove::groove_material(&MATERIAL, &e));
}
