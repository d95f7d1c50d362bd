//! The Kani proofs: the harness bodies of [`crate::harness`] with bounded
//! domains and unwind bounds that make CBMC finish. Run with
//! `cargo kani -p cycleref-proofs` (flags in `[workspace.metadata.kani]`).
//!
//! The windows are small because wide multiplications and divisions are
//! expensive for the solver; the tests cover the rest of the range.

use crate::harness::{self, Domain, FixedPoint};

/// A window the solver copes with: depths up to 64 increments, few passes.
const WINDOW: Domain = Domain {
    height: (1, 64),
    first_depth: (1, 64),
    min_cut: (0, 8),
    allowance: (0, 64),
    tool_angle: (0, 99),
    finishing: (0, 3),
    infeed: (0, 2),
    starts: (1, 2),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-64, 64),
    length: (200, 400),
    run_out_kind: (0, 3),
    run_out: (0, 16),
    chamfer: (0, 99),
    chamfer_angle: (1, 89),
    units: (0, 7),
    pass_limit: 64,
    wild_x: 2,
};

#[kani::proof]
#[kani::unwind(80)]
fn depth_monotonicity() {
    harness::depth_monotonicity(&WINDOW, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(80)]
fn termination() {
    harness::termination(&WINDOW, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(80)]
fn finishing() {
    harness::finishing(&WINDOW, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(80)]
fn run_out_direction() {
    harness::run_out_direction(&WINDOW, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(80)]
fn no_overcut() {
    harness::no_overcut(&WINDOW, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(40)]
#[kani::solver(cadical)]
fn equivalence() {
    const TINY: Domain = Domain {
        height: (1, 8),
        first_depth: (1, 8),
        min_cut: (0, 2),
        allowance: (0, 8),
        tool_angle: (0, 60),
        infeed: (0, 2),
        taper: (-4, 4),
        run_out_kind: (0, 1),
        run_out: (0, 2),
        pass_limit: 16,
        ..Domain::POINT
    };
    harness::equivalence(&TINY, &FixedPoint);
}

#[kani::proof]
#[kani::unwind(40)]
#[kani::solver(cadical)]
fn no_panic() {
    // The whole documented range; the pass count is bounded by the limit,
    // so the up-front count and the first moves are what the solver sees.
    const FULL: Domain = Domain { pass_limit: 32, ..Domain::FULL };
    harness::no_panic(&FULL, &FixedPoint, 12);
}

#[kani::proof]
#[kani::solver(cadical)]
fn isqrt_rounds() {
    harness::isqrt_rounds(0, i64::MAX, cycleref::engine::round_sqrt);
}

#[kani::proof]
#[kani::unwind(4)]
fn g32_run_out() {
    harness::g32_run_out(1_000, 100, &cycleref::expand_g32);
}

/// G75.1: right-angle grooves up to 6 increments deep and wide, few pecks.
const GROOVE_WINDOW: crate::groove::GrooveDomain = crate::groove::GrooveDomain {
    depth: (1, 6),
    width: (0, 6),
    peck: (1, 4),
    step: (1, 4),
    retract: (0, 1),
    layer: (0, 3),
    allowance_x: (0, 1),
    allowance_z: (0, 1),
    tool_width: (-1, 2),
    corner: (0, 1),
    corner_kinds: (0, 15),
    flank: (900_000, 900_000),
    slope: (0, 0),
    path: (0, 2),
    signs: (0, 3),
    units: (0, 7),
};

#[kani::proof]
#[kani::unwind(64)]
fn groove_pecks_and_steps() {
    crate::groove::groove_pecks_and_steps(&GROOVE_WINDOW, &crate::groove::GrooveFixedPoint);
}

#[kani::proof]
#[kani::unwind(64)]
fn groove_layers() {
    crate::groove::groove_layers(&GROOVE_WINDOW, &crate::groove::GrooveFixedPoint);
}

#[kani::proof]
#[kani::unwind(64)]
fn groove_inside() {
    crate::groove::groove_inside(&GROOVE_WINDOW, &crate::groove::GrooveFixedPoint);
}

#[kani::proof]
#[kani::unwind(64)]
fn groove_finish_is_profile() {
    crate::groove::groove_finish_is_profile(&GROOVE_WINDOW, &crate::groove::GrooveFixedPoint);
}

/// The material left by roughing: grooving tools only (the body model).
#[kani::proof]
#[kani::unwind(64)]
fn groove_material() {
    let window = crate::groove::GrooveDomain { tool_width: (1, 2), path: (0, 1), ..GROOVE_WINDOW };
    crate::groove::groove_material(&window, &crate::groove::GrooveFixedPoint);
}

/// Every documented input, the first 8 moves: no panic, no overflow.
#[kani::proof]
#[kani::unwind(64)]
#[kani::solver(cadical)]
fn groove_no_panic() {
    crate::groove::groove_no_panic(&crate::groove::GrooveDomain::FULL, 8);
}
