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
//! --nocapture --test-threads 1`) and the contracts relied on.
//!
//! Contracts (`-Z function-contracts`, `[workspace.metadata.kani.unstable]`):
//! the small exact kernels (`cycleref::engine::arith`:
//! `isqrt_floor`, `round_sqrt`, `round_div`, `saturate_i64`, `floor_div`,
//! `ceil_div`; `cycleref::tan::mul_tan_round`) carry `requires`/`ensures`
//! (`cycleref::engine::contracts`). Each has a `proof_for_contract`
//! harness below; the cycle harnesses replace the kernels they reach by
//! their contracts (`stub_verified`), so that Kani does not unroll Newton's
//! loop or bit-blast the 128-bit products and divisions inside the cycles.
//! Every postcondition determines its kernel's result uniquely, so a stub
//! is exact: the cycle harnesses prove the same properties as with the
//! kernels. The loop maxima below are measured with the real kernels (what
//! the `stub_verified` harnesses would unroll without their stubs).

use crate::contracts;
use crate::g92;
use crate::groove::{self, GrooveDomain, GrooveFixedPoint};
use crate::harness::{self, FixedPoint};
use crate::linuxcnc;
use crate::schedule;
use crate::thread;
use crate::windows::{
    DIV_WINDOW, EQUIVALENCE_WINDOW, FINISHING_WINDOW, G32_WINDOW, G76_WINDOW, G92_WINDOW,
    GROOVE_EQUIVALENCE_WINDOW, GROOVE_NO_PANIC_LAYERS, GROOVE_NO_PANIC_MOVES, GROOVE_NO_PANIC_WINDOW,
    GROOVE_WINDOW, ISQRT_WINDOW, LCNC_DEPTH_WINDOW, LCNC_PASS_WINDOW, LCNC_SPRING_WINDOW, MUL_TAN_WINDOW,
    NO_PANIC_MOVES, NO_PANIC_WINDOW, NO_RAPID_WINDOW, ROUND_DIV_WINDOW, SATURATE_WINDOW,
    SCHEDULE_STEP_WINDOW,
};
use cycleref::engine::arith;

/// P1 over [`G76_WINDOW`] (k ≤ 6, one start, lead-in ≤ 3). Unwind 79;
/// measured: 78 moves in a cycle (the harness's loops), 4 levels counted,
/// 3 Newton steps, 9 gcd steps, 3 path steps tried per move. Contracts:
/// `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn depth_monotonicity() {
    harness::depth_monotonicity(&G76_WINDOW, &FixedPoint);
}

/// P2 over [`G76_WINDOW`]. Unwind 79; measured as P1 (78 moves). Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn termination() {
    harness::termination(&G76_WINDOW, &FixedPoint);
}

/// P3 over [`FINISHING_WINDOW`] (k ≤ 4, two starts). Unwind 109;
/// measured: 108 moves (9 passes × 2 starts × 6), 3 levels counted, 9 gcd
/// steps. Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(109)]
fn finishing() {
    harness::finishing(&FINISHING_WINDOW, &FixedPoint);
}

/// P4 over [`NO_RAPID_WINDOW`] ([`G76_WINDOW`] with threads from 1
/// increment long, so that its cover "run-out with X long" is reachable:
/// with |W| ≥ 20 and |i| ≤ 6 X is never long). Unwind 79; measured as P1
/// (78 moves). Contracts: `round_sqrt`, `mul_tan_round`, `round_div`,
/// `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn run_out_direction() {
    harness::run_out_direction(&NO_RAPID_WINDOW, &FixedPoint);
}

/// P5 over [`G76_WINDOW`]. Unwind 79; measured as P1 (78 moves). Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn no_overcut() {
    harness::no_overcut(&G76_WINDOW, &FixedPoint);
}

/// P6 over [`EQUIVALENCE_WINDOW`] (k, Δd ≤ 8): the engine against the
/// reference restated in integers (`crate::g76_exact`; under `cargo test`
/// the harness also compares both with the decimal reference), so that
/// Kani executes no `rust_decimal`. Unwind 81; measured: 80 moves on the
/// engine's side and on the restatement's (`proofs/tests/unwind.rs`), 6
/// levels counted; the restatement's own loops: its levels and passes (at
/// most 8 and 16 here), and the reference's square-root bisection, at most
/// 65 iterations by construction (an interval of 2^64 halved to nothing).
/// Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64`
/// (stubbed; the restatement uses the reference's integer kernels, not
/// these).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(81)]
#[kani::solver(cadical)]
fn equivalence() {
    harness::equivalence(&EQUIVALENCE_WINDOW, &FixedPoint);
}

/// P7 over [`NO_PANIC_WINDOW`] (every documented input, pass limit 32), the
/// first 12 moves. Unwind 34; measured: 33 levels counted (the count stops
/// past the limit), 12 moves, 6 Newton steps on `u64` (the `u128` loop is
/// unreachable: Δd²n < 2^61 while counting), 12 gcd steps (L ≤ 999).
/// Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(34)]
#[kani::solver(cadical)]
fn no_panic() {
    harness::no_panic(&NO_PANIC_WINDOW, &FixedPoint, NO_PANIC_MOVES);
}

/// P8, the `proof_for_contract` of `round_sqrt`, over every `x` in `u128`.
/// Unwind 8; measured without the stub: 7 Newton steps on `u128`, 6 on
/// `u64` (every x < 2^16, x within 2 of each power of two, sampled).
/// Contracts: `isqrt_floor` (stubbed).
#[kani::proof_for_contract(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::isqrt_floor)]
#[kani::unwind(8)]
#[kani::solver(cadical)]
fn isqrt_rounds() {
    harness::isqrt_rounds(ISQRT_WINDOW.0, ISQRT_WINDOW.1, arith::round_sqrt);
}

/// The contract of `isqrt_floor` (`s² ≤ x < (s + 1)²`) over every `x` in
/// `u128`. Unwind 8; measured: 7 Newton steps on `u128`, 6 on `u64`.
/// Contracts: none (the kernel itself).
#[kani::proof_for_contract(cycleref::engine::arith::isqrt_floor)]
#[kani::unwind(8)]
#[kani::solver(cadical)]
fn isqrt_floor_contract() {
    contracts::isqrt_floor(ISQRT_WINDOW.0, ISQRT_WINDOW.1, arith::isqrt_floor);
}

/// The contract of `round_div` (nearest, ties away from zero) over
/// magnitudes below `2^126`, divisor non-zero. No loop: unwind 2.
/// Contracts: none.
#[kani::proof_for_contract(cycleref::engine::arith::round_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn round_div_contract() {
    contracts::round_div(ROUND_DIV_WINDOW.0, ROUND_DIV_WINDOW.1, arith::round_div);
}

/// The contract of `saturate_i64` over every `i128`. No loop: unwind 2.
/// Contracts: none.
#[kani::proof_for_contract(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(2)]
fn saturate_i64_contract() {
    contracts::saturate_i64(SATURATE_WINDOW.0, SATURATE_WINDOW.1, arith::saturate_i64);
}

/// The contract of `floor_div` over dividends below `2^120` in magnitude
/// and every positive divisor. No loop: unwind 2. Contracts: none.
#[kani::proof_for_contract(cycleref::engine::arith::floor_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn floor_div_contract() {
    contracts::div(DIV_WINDOW.0, DIV_WINDOW.1, false, arith::floor_div);
}

/// The contract of `ceil_div`, as `floor_div`'s. No loop: unwind 2.
/// Contracts: none (it calls floor division's unchecked body, not the
/// kernel with the contract).
#[kani::proof_for_contract(cycleref::engine::arith::ceil_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn ceil_div_contract() {
    contracts::div(DIV_WINDOW.0, DIV_WINDOW.1, true, arith::ceil_div);
}

/// The contract of `mul_tan_round` over every `i64` value and half-degree
/// code. No loop (a table lookup): unwind 2. Contracts: none.
#[kani::proof_for_contract(cycleref::tan::mul_tan_round)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn mul_tan_round_contract() {
    contracts::mul_tan_round(MUL_TAN_WINDOW.0, MUL_TAN_WINDOW.1, cycleref::tan::mul_tan_round);
}

/// G32 run-out over [`G32_WINDOW`]. Unwind 5; measured: 4 coordinates
/// checked by `validate`, 2 moves. Contracts: `round_div`, `saturate_i64`
/// (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(5)]
fn g32_run_out() {
    harness::g32_run_out(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
}

/// No rapid enters the thread (G76, Z and X long) over
/// [`NO_RAPID_WINDOW`] ([`G76_WINDOW`] with lengths from 1, so X long too):
/// every rapid stays out of the open region between the crest and root
/// lines from the last pass start to D (`crate::thread`), but the retract
/// after an X-long run-out (the finding in `crate::thread`), checked as the
/// moves stream. Unwind 79; measured: 78 moves (the harness's loop), the
/// engine's loops as P1.
/// Contracts: `round_sqrt`, `mul_tan_round`, `round_div`, `saturate_i64`
/// (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn no_rapid_in_thread() {
    thread::no_rapid_in_thread(&NO_RAPID_WINDOW, &FixedPoint);
}

/// No rapid in a G32 block over [`G32_WINDOW`]. Unwind 5; measured as
/// `g32_run_out` (4 coordinates checked by `validate`, 2 moves).
/// Contracts: `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(5)]
fn g32_no_rapid() {
    thread::g32_no_rapid(G32_WINDOW.0, G32_WINDOW.1, &cycleref::expand_g32);
}

/// The G92 pass over [`G92_WINDOW`]: steps ①-④ in order, B from the
/// words, the run-out K before C and J away from the work, every point
/// between the X of A and the cut line, the starts' angles. Unwind 12;
/// measured: 10 moves (two starts of 5), 4 path steps to a move, 2
/// iterations of `G92Moves::next`, 9 gcd steps.
/// Contracts: `round_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(12)]
fn g92_pass() {
    g92::g92_pass(G92_WINDOW.0, G92_WINDOW.1, G92_WINDOW.2, &cycleref::expand_g92);
}

/// G75.1 pecks and steps over [`GROOVE_WINDOW`] (≤ 4 increments). Unwind
/// 66; measured: 65 moves in a groove (the harness's loops); the engine's loops (measured by `groove_loops_stay_below_the_unwind_bounds`): 2 iterator stages, 3 roughing steps, 4 layers counted, 8 contour points, 16 Taylor terms (sin and cos of the right angle), 4 limb iterations, no long division (right angles are exact); the limb loops written as iterator adaptors (`all`, `any`) run over at most 28 limbs.
/// Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_pecks_and_steps() {
    groove::groove_pecks_and_steps(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 layers over [`GROOVE_WINDOW`]. Unwind 66; measured: 65 moves (the
/// 64-slot layer table is indexed, not looped over past the layers);
/// the engine's loops as [`groove_pecks_and_steps`]. Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_layers() {
    groove::groove_layers(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 roughing region over [`GROOVE_WINDOW`]. Unwind 66; measured: 65
/// moves; the engine's loops as [`groove_pecks_and_steps`]. Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_inside() {
    groove::groove_inside(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// G75.1 finishing contour over [`GROOVE_WINDOW`]. Unwind 66; measured: 65
/// moves; the engine's loops as [`groove_pecks_and_steps`]. Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_finish_is_profile() {
    groove::groove_finish_is_profile(&GROOVE_WINDOW, &GrooveFixedPoint);
}

/// The material left by roughing over [`GROOVE_WINDOW`] with grooving
/// tools only (the body model), J0 and J1. Unwind 66; measured: 65 moves.
/// Its loops over the material cells run over at most 4 × 4 cells (the
/// window's depth and width); the engine's loops as
/// [`groove_pecks_and_steps`]. Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_material() {
    let window = GrooveDomain { tool_width: (1, 2), path: (0, 1), ..GROOVE_WINDOW };
    groove::groove_material(&window, &GrooveFixedPoint);
}

/// G75.1 engine = reference for right-angle grooves over
/// [`GROOVE_EQUIVALENCE_WINDOW`] (2 to 4 increments deep, 0 to 3 wide,
/// pecks of 2, steps 1 and 2, up to 4 layers, allowances, tool widths 0 and
/// 1, corners of size 0 and 1, every J, sign, f = 1 and 2): the engine
/// against the reference restated in integers (`crate::g75_exact`; under
/// `cargo test` the harness also compares both with the `num-bigint`
/// reference, over this whole window: 884 736 grooves), so that Kani
/// executes no `num-bigint`. Unwind 54; measured over the whole window
/// (`proofs/tests/unwind.rs`): 53 moves on each side (engine and integer
/// restatement), 16 Taylor terms, 8 contour points, 4 layers counted, 4
/// limb iterations, 3 roughing steps, 2 stages, no long division; the
/// restatement's loops (its layers, plunges and pecks) are bounded by its
/// moves. Contracts: `floor_div`, `ceil_div`, `saturate_i64` (stubbed; the
/// restatement uses none of the engine's kernels).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(54)]
#[kani::solver(cadical)]
fn groove_equivalence() {
    groove::groove_equivalence(&GROOVE_EQUIVALENCE_WINDOW, &GrooveFixedPoint);
}

/// Every documented input of at most 1 152 layers
/// ([`GROOVE_NO_PANIC_WINDOW`], [`GROOVE_NO_PANIC_LAYERS`]: `|H| ≤ 1 152·Δv`,
/// stated on the words), the first 8 moves: no panic, no overflow, every
/// move in range. Unwind 1 153, one above the most iterations any loop
/// reached here can make by construction: the layers (1 152, the bound
/// of the window, chosen when a bit-by-bit division of 1 152 steps set
/// the bound; the division is now Knuth's algorithm D: at most 18 quotient
/// limbs, measured 4), the Taylor series (400 terms; measured 20), the
/// limb loops (28), the contour points (8), and the peck count's loop over
/// the layers (the window's 1 152; measured 1 152, enumerated); the
/// iterator's state machines measured 3 and 2, the harness's loop 8 moves.
/// Grooves of more layers (up to 10^6 of one peck, `MAX_PECKS`) are
/// outside this window and checked under `cargo test` only. Kani is still
/// not expected to finish in practice: the division and the series run on
/// symbolic 1 152-bit and 640-bit numbers, and would need contracts of
/// their own (issue 13). Contracts: `floor_div`, `ceil_div`,
/// `saturate_i64` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(1153)]
#[kani::solver(cadical)]
fn groove_no_panic() {
    groove::groove_no_panic(&GROOVE_NO_PANIC_WINDOW, GROOVE_NO_PANIC_MOVES, Some(GROOVE_NO_PANIC_LAYERS));
}

/// The depth schedule, one step from any level `n` (an induction: see
/// `crate::schedule`), over [`SCHEDULE_STEP_WINDOW`]: every documented Δd,
/// Δdmin, k - d and every state that satisfies the invariant, so every
/// level of every cycle. No loop over the levels; the only loop reached is
/// Newton's in `round_sqrt` (stubbed). Unwind 7; measured without the
/// stub: 5 Newton steps on `u64` (a law state has `Δd² (n + 1) < 2^61`,
/// never `u128`; the minimum-cut phase takes no root), and 6 is Newton's
/// most on any `u64`. Contracts: `round_sqrt` (stubbed).
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::unwind(7)]
#[kani::solver(cadical)]
fn schedule_step() {
    schedule::schedule_step(&SCHEDULE_STEP_WINDOW, &cycleref::engine::schedule::Schedule::next_level);
}

/// LinuxCNC G76 depths (`crate::linuxcnc::lcnc_depth_monotonicity`) over
/// [`LCNC_DEPTH_WINDOW`]: R = p/q symbolic (q ≤ 4, 1 ≤ R ≤ 3, in ten-thousandths: the quarters), J ≤ 3,
/// K ≤ 6, H -1..2, G7/G8, both sides, Q 0 and 29.5°, pass limit 12: rough
/// passes numbered in order, each shallower than K exactly, depth
/// round(δ_n/ξ) non-decreasing with cut ≥ 0 and at most round(K/ξ), its
/// cut X the exact depth rounded. Unwind 256; measured over the window
/// (`proofs/tests/linuxcnc_harnesses.rs`, `every_loop_stays_below_its_unwind_bound`):
/// 60 atanh terms (the largest), 3 quotient limbs of `real::limbs_divmod`, 39
/// exp steps, 32 root-search and gcd steps, 15 sine/cosine terms, 13
/// passes checked, 5 limb iterations, 2 iterator rounds, 61 moves of one
/// cycle (the harness's loop); the harness's `pow` at most 12, its
/// exact-root search at most 12. No contract: the engine's interval
/// kernels (`engine::real`) have none, so Kani bit-blasts 192-bit series;
/// the harness is sound as written but expensive (like `groove_no_panic`).
/// Covers: three or more rough passes; two at the same rounded depth; one
/// at round(K/ξ); an exact root beyond the first pass; a fractional R; G7;
/// internal.
#[kani::proof]
#[kani::unwind(256)]
#[kani::solver(cadical)]
fn lcnc_depth_monotonicity() {
    linuxcnc::lcnc_depth_monotonicity(&LCNC_DEPTH_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 termination (`crate::linuxcnc::lcnc_termination`) over
/// [`LCNC_DEPTH_WINDOW`]: refused with `TooManyPasses` exactly when
/// `J^p·13^q < K^p`; otherwise the last rough pass N has `J^p·N^q < K^p ≤
/// J^p·(N + 1)^q`, then 1 + H passes at K and the return, `(N + 1 + H)·4 +
/// 1` moves. Unwind 256; measured as [`lcnc_depth_monotonicity`]. No
/// contract (as there). Covers: a single rough pass; δ_(N+1) = K exactly;
/// H = -1; H ≥ 1; refused beyond the limit; as many rough passes as the
/// limit.
#[kani::proof]
#[kani::unwind(256)]
#[kani::solver(cadical)]
fn lcnc_termination() {
    linuxcnc::lcnc_termination(&LCNC_DEPTH_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 passes at full depth (`crate::linuxcnc::lcnc_spring_passes`)
/// over [`LCNC_SPRING_WINDOW`] (K ≤ 5, R 1..2, every angle, H -1..2, E 0..2
/// with every L, both directions and sides): depth round(K/ξ), cut X X₀ −
/// σ(|I| + K), out at X₀, the deepest pass ending at Z, spring passes
/// repeating it. Unwind 256; measured: 3 quotient limbs of division, 128 bit pairs of
/// `isqrt_wide` (the taper pitch), 60 atanh terms, 39 exp steps, 32 root
/// and gcd steps, 15 sine/cosine terms, 9 passes checked, 67 moves of one
/// cycle. No contract (as [`lcnc_depth_monotonicity`]). Covers: H ≥ 1; a
/// compound angle; an exit taper; an entry taper; internal; towards +Z; G7
/// with an odd K; a first full-depth pass that cuts nothing.
#[kani::proof]
#[kani::unwind(256)]
#[kani::solver(cadical)]
fn lcnc_spring_passes() {
    linuxcnc::lcnc_spring_passes(&LCNC_SPRING_WINDOW, &cycleref::expand_linuxcnc);
}

/// LinuxCNC G76 moves of a pass (`crate::linuxcnc::lcnc_pass_moves`) over
/// [`LCNC_PASS_WINDOW`] (K ≤ 4, R 1 and 2, every angle, H 0..1, E 0..3 with
/// every L, threads 2 to 6 long): R-LCNC-PASS move by move, synchronised
/// moves never rapids, the taper pitch restated in integers, tapers between
/// the back X and the cut X and within the pass's Z span, no rapid into
/// the thread region but a non-tapered pass's "in". Unwind 256; measured
/// as [`lcnc_spring_passes`] but 61 moves of one cycle. No contract.
/// Also: each pass's start shifted by the compound angle the right way
/// (δ/ξ rounded at 45°). Covers: each taper alone and both; L without E; a
/// taper longer than the pass; a pass that runs backwards; tapers internal
/// and towards +Z; an in rapid to the cut; an out rapid from the cut; an
/// exit taper ending on the crest; a shift against the thread; a 45°
/// shift.
#[kani::proof]
#[kani::unwind(256)]
#[kani::solver(cadical)]
fn lcnc_pass_moves() {
    linuxcnc::lcnc_pass_moves(&LCNC_PASS_WINDOW, &cycleref::expand_linuxcnc);
}
