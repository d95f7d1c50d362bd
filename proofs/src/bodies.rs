//! The body of every Kani harness, one function each, with its window
//! bound in: `proofs/src/kani_proofs.rs` (generated from
//! [`crate::catalogue`]) calls these under `cargo kani`, and
//! `proofs/tests/kani_windows.rs` runs the very same functions here through
//! the shim over the same windows. Nothing else is in a body, so what runs
//! here is what Kani would prove.

use crate::contracts;
use crate::g92;
use crate::groove::{self, GrooveDomain, GrooveFixedPoint};
use crate::harness::{self, FixedPoint};
use crate::linuxcnc;
use crate::schedule;
use crate::thread;
use crate::windows::{
    depth_window, equivalence_window, flank_window, DIV_WINDOW, FINISHING_KANI_WINDOW, G32_WINDOW,
    G76_WINDOW, G92_WINDOW, GROOVE_EQUIVALENCE_WINDOW, GROOVE_NO_PANIC_LAYERS, GROOVE_NO_PANIC_MOVES,
    GROOVE_NO_PANIC_WINDOW, GROOVE_WINDOW, ISQRT_NEAR_WINDOW, ISQRT_WINDOW, LCNC_DEPTH_WINDOW,
    LCNC_PASS_WINDOW, LCNC_SPRING_WINDOW, MUL_TAN_WINDOW, NO_PANIC_MOVES, NO_PANIC_WINDOW, NO_RAPID_WINDOW,
    ROUND_DIV_WINDOW, RUN_OUT_KANI_WINDOW, SATURATE_WINDOW, SCHEDULE_STEP_WINDOW,
};
use cycleref::engine::arith;

/// One body per infeed mode of a G76 property: `$name_d0` … `$name_alternating`.
/// Every G76 body pins the readings at `CycleReadings::DEFAULT` (its cycles
/// come from `harness::any_cycle`, whose doc says which values that is and
/// why the properties are stated for them).
macro_rules! per_infeed {
    ($what:literal, $($name:ident = $mode:literal),* => |$w:ident| $body:expr, $window:expr) => {
        $(
            #[doc = concat!($what, ", infeed mode ", stringify!($mode), " (", stringify!($name), ").")]
            pub fn $name() {
                let $w = $window($mode);
                $body
            }
        )*
    };
}

per_infeed!(
    "P1, depth monotonicity, over `windows::depth_window`",
    depth_monotonicity_d0 = 0, depth_monotonicity_d1 = 1, depth_monotonicity_d2 = 2,
    depth_monotonicity_centre = 3, depth_monotonicity_left_flank = 4, depth_monotonicity_alternating = 5
    => |w| harness::depth_monotonicity(&w, &FixedPoint), depth_window
);

per_infeed!(
    "P2, termination at k − d, over `windows::depth_window`",
    termination_d0 = 0, termination_d1 = 1, termination_d2 = 2,
    termination_centre = 3, termination_left_flank = 4, termination_alternating = 5
    => |w| harness::termination(&w, &FixedPoint), depth_window
);

per_infeed!(
    "P5, no overcut, over `windows::flank_window(G76_WINDOW, mode)`",
    no_overcut_d0 = 0, no_overcut_d1 = 1, no_overcut_d2 = 2,
    no_overcut_centre = 3, no_overcut_left_flank = 4, no_overcut_alternating = 5
    => |w| harness::no_overcut(&w, &FixedPoint), |m| flank_window(G76_WINDOW, m)
);

per_infeed!(
    "No rapid enters the thread, over `windows::flank_window(NO_RAPID_WINDOW, mode)`",
    no_rapid_in_thread_d0 = 0, no_rapid_in_thread_d1 = 1, no_rapid_in_thread_d2 = 2,
    no_rapid_in_thread_centre = 3, no_rapid_in_thread_left_flank = 4, no_rapid_in_thread_alternating = 5
    => |w| thread::no_rapid_in_thread(&w, &FixedPoint), |m| flank_window(NO_RAPID_WINDOW, m)
);

per_infeed!(
    "P6, engine = reference, over `windows::equivalence_window`",
    equivalence_d0 = 0, equivalence_d1 = 1, equivalence_d2 = 2,
    equivalence_centre = 3, equivalence_left_flank = 4, equivalence_alternating = 5
    => |w| harness::equivalence(&w, &FixedPoint), equivalence_window
);

/// P3, finishing, over [`FINISHING_KANI_WINDOW`].
pub fn finishing() {
    harness::finishing(&FINISHING_KANI_WINDOW, &FixedPoint);
}

/// P4, the run-out's direction, over [`RUN_OUT_KANI_WINDOW`].
pub fn run_out_direction() {
    harness::run_out_direction(&RUN_OUT_KANI_WINDOW, &FixedPoint);
}

/// P7, no panic, over [`NO_PANIC_WINDOW`], the first [`NO_PANIC_MOVES`] moves.
pub fn no_panic() {
    harness::no_panic(&NO_PANIC_WINDOW, &FixedPoint, NO_PANIC_MOVES);
}

/// P8, the contract of `round_sqrt`, over [`ISQRT_WINDOW`].
pub fn isqrt_rounds() {
    harness::isqrt_rounds(ISQRT_WINDOW.0, ISQRT_WINDOW.1, arith::round_sqrt);
}

/// The contract of `round_sqrt_near` over [`ISQRT_NEAR_WINDOW`]: every
/// `x < 2^62`, every guess.
pub fn round_sqrt_near_contract() {
    let (x, guess) = ISQRT_NEAR_WINDOW;
    contracts::round_sqrt_near(x.0, x.1, guess, arith::round_sqrt_near);
}

/// The contract of `isqrt_floor` over [`ISQRT_WINDOW`].
pub fn isqrt_floor_contract() {
    contracts::isqrt_floor(ISQRT_WINDOW.0, ISQRT_WINDOW.1, arith::isqrt_floor);
}

/// The contract of `round_div` over [`ROUND_DIV_WINDOW`].
pub fn round_div_contract() {
    contracts::round_div(ROUND_DIV_WINDOW.0, ROUND_DIV_WINDOW.1, arith::round_div);
}

/// The contract of `saturate_i64` over [`SATURATE_WINDOW`].
pub fn saturate_i64_contract() {
    contracts::saturate_i64(SATURATE_WINDOW.0, SATURATE_WINDOW.1, arith::saturate_i64);
}

/// The contract of `floor_div` over [`DIV_WINDOW`].
pub fn floor_div_contract() {
    contracts::div(DIV_WINDOW.0, DIV_WINDOW.1, false, arith::floor_div);
}

/// The contract of `ceil_div` over [`DIV_WINDOW`].
pub fn ceil_div_contract() {
    contracts::div(DIV_WINDOW.0, DIV_WINDOW.1, true, arith::ceil_div);
}

/// The contract of `mul_tan_round` over [`MUL_TAN_WINDOW`].
pub fn mul_tan_round_contract() {
    contracts::mul_tan_round(MUL_TAN_WINDOW.0, MUL_TAN_WINDOW.1, cycleref::tan::mul_tan_round);
}

/// The G32 run-out over [`G32_WINDOW`].
pub fn g32_run_out() {
    harness::g32_run_out(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
}

/// No rapid in a G32 block over [`G32_WINDOW`].
pub fn g32_no_rapid() {
    thread::g32_no_rapid(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
}

/// The G92 pass over [`G92_WINDOW`].
pub fn g92_pass() {
    g92::g92_pass(G92_WINDOW.0, G92_WINDOW.1, G92_WINDOW.2, &cycleref::expand_g92);
}

/// G75.1 pecks and steps over [`GROOVE_WINDOW`].
pub fn groove_pecks_and_steps() {
    groove::groove_pecks_and_steps(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 layers over [`GROOVE_WINDOW`].
pub fn groove_layers() {
    groove::groove_layers(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 roughing region over [`GROOVE_WINDOW`].
pub fn groove_inside() {
    groove::groove_inside(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 finishing contour over [`GROOVE_WINDOW`].
pub fn groove_finish_is_profile() {
    groove::groove_finish_is_profile(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// The window of [`groove_material`]: [`GrooveDomain::MATERIAL`], grooves 6
/// and 7 deep and 4 to 6 wide with grooving tools (widths 1 and 2), chamfered
/// corners up to 3, layers, allowances, J0 and J1, in IS-C inch diameter
/// and IS-B metric radius (f = 2 and f = 1): 442 368 grooves, enumerated by
/// `proofs/tests/kani_windows.rs`. Until issue 32 it was [`GROOVE_WINDOW`]
/// with grooving tools, where grooves of at most 4 increments never leave
/// a sliver along the boundary: the harness's cover of that case was
/// unreachable there (0 hits in 2·10^6 samples and three exhaustive
/// slices), and Kani's `--fail-uncoverable` would have failed.
pub const GROOVE_MATERIAL_WINDOW: GrooveDomain = GrooveDomain { units: (3, 4), ..GrooveDomain::MATERIAL };

/// G75.1 material left by roughing over [`GROOVE_MATERIAL_WINDOW`].
pub fn groove_material() {
    groove::groove_material(&GROOVE_MATERIAL_WINDOW, &GrooveFixedPoint);
}

/// G75.1 engine = reference over [`GROOVE_EQUIVALENCE_WINDOW`].
pub fn groove_equivalence() {
    groove::groove_equivalence(&GROOVE_EQUIVALENCE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 no panic over [`GROOVE_NO_PANIC_WINDOW`].
pub fn groove_no_panic() {
    groove::groove_no_panic(&GROOVE_NO_PANIC_WINDOW, GROOVE_NO_PANIC_MOVES, Some(GROOVE_NO_PANIC_LAYERS));
}

/// The depth schedule's one step over [`SCHEDULE_STEP_WINDOW`].
pub fn schedule_step() {
    schedule::schedule_step(&SCHEDULE_STEP_WINDOW, &cycleref::engine::schedule::Schedule::next_level);
}

/// LinuxCNC G76 depths over [`LCNC_DEPTH_WINDOW`].
pub fn lcnc_depth_monotonicity() {
    linuxcnc::lcnc_depth_monotonicity(&LCNC_DEPTH_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 termination over [`LCNC_DEPTH_WINDOW`].
pub fn lcnc_termination() {
    linuxcnc::lcnc_termination(&LCNC_DEPTH_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 passes at full depth over [`LCNC_SPRING_WINDOW`].
pub fn lcnc_spring_passes() {
    linuxcnc::lcnc_spring_passes(&LCNC_SPRING_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 moves of a pass over [`LCNC_PASS_WINDOW`].
pub fn lcnc_pass_moves() {
    linuxcnc::lcnc_pass_moves(&LCNC_PASS_WINDOW, &cycleref::expand_linuxcnc);
}
