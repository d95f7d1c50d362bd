//! The Kani proofs: the harness bodies of [`crate::harness`] and
//! [`crate::groove`] over the windows of [`crate::windows`]. Run with
//! `cargo kani -p cycleref-proofs` (flags in `[workspace.metadata.kani]`,
//! Kani pinned in `.github/workflows/ci.yml`).
//!
//! Every harness has an explicit `#[kani::unwind(N)]`, equal to its entry
//! in [`crate::windows::UNWIND`]. `proofs/tests/unwind.rs` runs each body
//! over its window under `cargo test` with the engine's loops counting
//! their iterations (`cycleref` feature `loop-counters`) and fails when a
//! loop reaches N; each doc below gives the window, the bound, the largest
//! count measured there (`cargo test -p cycleref-proofs --test unwind --
//! --nocapture --test-threads 1`) and the contracts relied on (none yet:
//! the kernels are unrolled, not stubbed).

use crate::groove::{self, GrooveDomain, GrooveFixedPoint};
use crate::harness::{self, FixedPoint};
use crate::windows::{
    EQUIVALENCE_WINDOW, FINISHING_WINDOW, G32_WINDOW, G76_WINDOW, GROOVE_WINDOW, ISQRT_WINDOW,
    NO_PANIC_MOVES, NO_PANIC_WINDOW,
};

/// P1 over [`G76_WINDOW`] (k ≤ 6, one start, lead-in ≤ 3). Unwind 79;
/// measured: 78 moves in a cycle (the harness's loops), 4 levels counted,
/// 3 Newton steps, 9 gcd steps, 3 path steps tried per move. Contracts:
/// none.
#[kani::proof]
#[kani::unwind(79)]
fn depth_monotonicity() {
    harness::depth_monotonicity(&G76_WINDOW, &FixedPoint);
}

/// P2 over [`G76_WINDOW`]. Unwind 79; measured as P1 (78 moves). Contracts: none.
#[kani::proof]
#[kani::unwind(79)]
fn termination() {
    harness::termination(&G76_WINDOW, &FixedPoint);
}

/// P3 over [`FINISHING_WINDOW`] (k ≤ 4, two starts). Unwind 109;
/// measured: 108 moves (9 passes × 2 starts × 6), 3 levels counted, 9 gcd
/// steps. Contracts: none.
#[kani::proof]
#[kani::unwind(109)]
fn finishing() {
    harness::finishing(&FINISHING_WINDOW, &FixedPoint);
}

/// P4 over [`G76_WINDOW`]. Unwind 79; measured as P1 (78 moves). Contracts: none.
#[kani::proof]
#[kani::unwind(79)]
fn run_out_direction() {
    harness::run_out_direction(&G76_WINDOW, &FixedPoint);
}

/// P5 over [`G76_WINDOW`]. Unwind 79; measured as P1 (78 moves). Contracts: none.
#[kani::proof]
#[kani::unwind(79)]
fn no_overcut() {
    harness::no_overcut(&G76_WINDOW, &FixedPoint);
}

/// P6 over [`EQUIVALENCE_WINDOW`] (k, Δd ≤ 8). Unwind 81; measured on the
/// engine's side: 80 moves, 6 levels counted. The reference's loops
/// (`rust_decimal`, its square-root bisection) are not counted here, and
/// Kani would have to execute `rust_decimal` symbolically: this harness is
/// not expected to finish (issue 13). Contracts: none.
#[kani::proof]
#[kani::unwind(81)]
#[kani::solver(cadical)]
fn equivalence() {
    harness::equivalence(&EQUIVALENCE_WINDOW, &FixedPoint);
}

/// P7 over [`NO_PANIC_WINDOW`] (every documented input, pass limit 32), the
/// first 12 moves. Unwind 34; measured: 33 levels counted (the count stops
/// past the limit), 12 moves, 6 Newton steps on `u64` (the `u128` loop is
/// unreachable: Δd²n < 2^61 while counting), 12 gcd steps (L ≤ 999).
/// Contracts: none.
#[kani::proof]
#[kani::unwind(34)]
#[kani::solver(cadical)]
fn no_panic() {
    harness::no_panic(&NO_PANIC_WINDOW, &FixedPoint, NO_PANIC_MOVES);
}

/// P8 over every `x` in `0..=i64::MAX`. Unwind 7; measured: 6 Newton
/// steps (sampled, every x < 2^16, and x within 2 of each power of two).
/// Contracts: none.
#[kani::proof]
#[kani::unwind(7)]
#[kani::solver(cadical)]
fn isqrt_rounds() {
    harness::isqrt_rounds(ISQRT_WINDOW.0, ISQRT_WINDOW.1, cycleref::engine::round_sqrt);
}

/// G32 run-out over [`G32_WINDOW`]. Unwind 5; measured: 4 coordinates
/// checked by `validate`, 2 moves. Contracts: none.
#[kani::proof]
#[kani::unwind(5)]
fn g32_run_out() {
    harness::g32_run_out(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
}

/// G75.1 pecks and steps over [`GROOVE_WINDOW`] (≤ 4 increments). Unwind
/// 66; measured: 65 moves in a groove. The G75.1 engine's own loops are not
/// counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(66)]
fn groove_pecks_and_steps() {
    groove::groove_pecks_and_steps(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 layers over [`GROOVE_WINDOW`]. Unwind 66; measured: 65 moves (the
/// 64-slot layer table is indexed, not looped over past the layers). The
/// engine's loops are not counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(66)]
fn groove_layers() {
    groove::groove_layers(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 roughing region over [`GROOVE_WINDOW`]. Unwind 66; measured: 65
/// moves. The engine's loops are not counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(66)]
fn groove_inside() {
    groove::groove_inside(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 finishing contour over [`GROOVE_WINDOW`]. Unwind 66; measured: 65
/// moves. The engine's loops are not counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(66)]
fn groove_finish_is_profile() {
    groove::groove_finish_is_profile(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// The material left by roughing over [`GROOVE_WINDOW`] with grooving
/// tools only (the body model), J0 and J1. Unwind 66; measured: 65 moves.
/// Its loops over the material cells (up to 4 × 4) and the engine's loops
/// are not counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(66)]
fn groove_material() {
    let window = GrooveDomain { tool_width: (1, 2), path: (0, 1), ..GROOVE_WINDOW };
    groove::groove_material(&window, &GrooveFixedPoint);
}

/// Every documented input, the first 8 moves: no panic, no overflow.
/// Unwind 64, not checked here: the G75.1 engine's loops (its bit-by-bit
/// division among them) are not counted yet. Contracts: none.
#[kani::proof]
#[kani::unwind(64)]
#[kani::solver(cadical)]
fn groove_no_panic() {
    groove::groove_no_panic(&GrooveDomain::FULL, 8);
}
