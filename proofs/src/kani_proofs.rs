//! The Kani harnesses. GENERATED from `proofs/src/catalogue.rs` by
//! `CYCLEREF_BLESS=1 cargo test -p cycleref-proofs --test catalogue`;
//! edit the catalogue, not this file.
//!
//! Each harness calls its body in `crate::bodies`, which the shim runs
//! here over the same window (`proofs/tests/kani_windows.rs`). Run one
//! with `cargo kani -p cycleref-proofs --harness kani_proofs::NAME
//! --exact`; the scheduled tier needs `--features kani-scheduled`.
//! Contracts (`-Z function-contracts`): each kernel's `proof_for_contract`
//! harness proves it over the ranges its callers use, and the cycle
//! harnesses replace it by that contract (`stub_verified`).

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(0)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn depth_monotonicity_d0() {
    crate::bodies::depth_monotonicity_d0();
}

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(1)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn depth_monotonicity_d1() {
    crate::bodies::depth_monotonicity_d1();
}

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(2)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn depth_monotonicity_d2() {
    crate::bodies::depth_monotonicity_d2();
}

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(3)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn depth_monotonicity_centre() {
    crate::bodies::depth_monotonicity_centre();
}

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(4)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn depth_monotonicity_left_flank() {
    crate::bodies::depth_monotonicity_left_flank();
}

/// P1: rough depths strictly increase level by level; every cut at least
/// min(Δdmin, what remains), a law cut never grows by more than rounding.
/// Window: `depth_window(5)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn depth_monotonicity_alternating() {
    crate::bodies::depth_monotonicity_alternating();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(0)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn termination_d0() {
    crate::bodies::termination_d0();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(1)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn termination_d1() {
    crate::bodies::termination_d1();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(2)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn termination_d2() {
    crate::bodies::termination_d2();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(3)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn termination_centre() {
    crate::bodies::termination_centre();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(4)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn termination_left_flank() {
    crate::bodies::termination_left_flank();
}

/// P2: the rough schedule ends exactly at k − d within the documented number
/// of levels. Window: `depth_window(5)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn termination_alternating() {
    crate::bodies::termination_alternating();
}

/// P3: m finishing passes per start at depth k, cutting d then 0, at the last
/// rough Z. Window: `FINISHING_KANI_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(97)]
fn finishing() {
    crate::bodies::finishing();
}

/// P4: every run-out ends away from the work, on the end line (Z long) or the
/// cut's X (X long), never beyond E. Window: `RUN_OUT_KANI_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn run_out_direction() {
    crate::bodies::run_out_direction();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(0)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_overcut_d0() {
    crate::bodies::no_overcut_d0();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(1)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_overcut_d1() {
    crate::bodies::no_overcut_d1();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(2)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn no_overcut_d2() {
    crate::bodies::no_overcut_d2();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(3)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_overcut_centre() {
    crate::bodies::no_overcut_centre();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(4)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_overcut_left_flank() {
    crate::bodies::no_overcut_left_flank();
}

/// P5: no pass start lies outside the final thread form by more than one
/// increment. Window: `flank_window(G76_WINDOW)(5)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_overcut_alternating() {
    crate::bodies::no_overcut_alternating();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(0)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_rapid_in_thread_d0() {
    crate::bodies::no_rapid_in_thread_d0();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(1)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_rapid_in_thread_d1() {
    crate::bodies::no_rapid_in_thread_d1();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(2)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(79)]
fn no_rapid_in_thread_d2() {
    crate::bodies::no_rapid_in_thread_d2();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(3)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_rapid_in_thread_centre() {
    crate::bodies::no_rapid_in_thread_centre();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(4)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_rapid_in_thread_left_flank() {
    crate::bodies::no_rapid_in_thread_left_flank();
}

/// No rapid enters the region between the crest and root lines (but the retract
/// after an X-long run-out). Window: `flank_window(NO_RAPID_WINDOW)(5)`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(49)]
fn no_rapid_in_thread_alternating() {
    crate::bodies::no_rapid_in_thread_alternating();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(0)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(46)]
#[kani::solver(cadical)]
fn equivalence_d0() {
    crate::bodies::equivalence_d0();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(1)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(46)]
#[kani::solver(cadical)]
fn equivalence_d1() {
    crate::bodies::equivalence_d1();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(2)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(81)]
#[kani::solver(cadical)]
fn equivalence_d2() {
    crate::bodies::equivalence_d2();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(3)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(46)]
#[kani::solver(cadical)]
fn equivalence_centre() {
    crate::bodies::equivalence_centre();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(4)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(46)]
#[kani::solver(cadical)]
fn equivalence_left_flank() {
    crate::bodies::equivalence_left_flank();
}

/// P6: the engine's moves (or alarm) equal the reference's, restated in
/// integers (crate::g76_exact). Window: `equivalence_window(5)`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(46)]
#[kani::solver(cadical)]
fn equivalence_alternating() {
    crate::bodies::equivalence_alternating();
}

/// P7: every cycle of the documented ranges, valid or not, gives an alarm or
/// moves in range; no panic, no overflow (first 12 moves). Window:
/// `NO_PANIC_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::tan::mul_tan_round)]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(34)]
#[kani::solver(cadical)]
fn no_panic() {
    crate::bodies::no_panic();
}

/// P8: round_sqrt rounds to nearest: (2s − 1)² ≤ 4x < (2s + 1)². Window:
/// `ISQRT_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::round_sqrt)]
#[kani::stub_verified(cycleref::engine::arith::isqrt_floor)]
#[kani::unwind(7)]
#[kani::solver(cadical)]
fn isqrt_rounds() {
    crate::bodies::isqrt_rounds();
}

/// The contract of round_sqrt_near: round(√x) whatever the guess, (2s −
/// 1)² ≤ 4x < (2s + 1)². Window: `ISQRT_NEAR_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::round_sqrt_near)]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::unwind(6)]
#[kani::solver(cadical)]
fn round_sqrt_near_contract() {
    crate::bodies::round_sqrt_near_contract();
}

/// The contract of isqrt_floor: s² ≤ x < (s + 1)². Window: `ISQRT_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::isqrt_floor)]
#[kani::unwind(7)]
#[kani::solver(cadical)]
fn isqrt_floor_contract() {
    crate::bodies::isqrt_floor_contract();
}

/// The contract of round_div: nearest, ties away from zero. Window:
/// `ROUND_DIV_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::round_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn round_div_contract() {
    crate::bodies::round_div_contract();
}

/// The contract of saturate_i64. Window: `SATURATE_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(2)]
fn saturate_i64_contract() {
    crate::bodies::saturate_i64_contract();
}

/// The contract of floor_div. Window: `DIV_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::floor_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn floor_div_contract() {
    crate::bodies::floor_div_contract();
}

/// The contract of ceil_div. Window: `DIV_WINDOW`.
#[kani::proof_for_contract(cycleref::engine::arith::ceil_div)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn ceil_div_contract() {
    crate::bodies::ceil_div_contract();
}

/// The contract of mul_tan_round: round(v·tan(h/2°)) from the table. Window:
/// `MUL_TAN_WINDOW`.
#[kani::proof_for_contract(cycleref::tan::mul_tan_round)]
#[kani::unwind(2)]
#[kani::solver(cadical)]
fn mul_tan_round_contract() {
    crate::bodies::mul_tan_round_contract();
}

/// G32: the run-out ends J along the short axis from the end and starts K
/// before it; only the first move synchronises. Window: `G32_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(5)]
fn g32_run_out() {
    crate::bodies::g32_run_out();
}

/// G32: no rapid in a thread block. Window: `G32_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(5)]
fn g32_no_rapid() {
    crate::bodies::g32_no_rapid();
}

/// G92: steps 1 to 5 in order, B from the words, the run-out K before C and J
/// away from the work, the starts' angles. Window: `G92_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(12)]
fn g92_pass() {
    crate::bodies::g92_pass();
}

/// G75.1: every peck at most Δi, every step at most Δk, retracts by e.
/// Window: `GROOVE_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_pecks_and_steps() {
    crate::bodies::groove_pecks_and_steps();
}

/// G75.1: layers of at most Δv, in order, the last at the bottom. Window:
/// `GROOVE_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_layers() {
    crate::bodies::groove_layers();
}

/// G75.1: roughing stays inside the profile less the allowances. Window:
/// `GROOVE_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_inside() {
    crate::bodies::groove_inside();
}

/// G75.1: the finishing contour is the programmed profile. Window:
/// `GROOVE_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(66)]
fn groove_finish_is_profile() {
    crate::bodies::groove_finish_is_profile();
}

/// G75.1: roughing with a grooving tool leaves no material but the allowances.
/// Window: `GROOVE_MATERIAL_WINDOW`.
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(128)]
fn groove_material() {
    crate::bodies::groove_material();
}

/// G75.1: the engine equals the reference restated in integers for right-angle
/// grooves. Window: `GROOVE_EQUIVALENCE_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(54)]
#[kani::solver(cadical)]
fn groove_equivalence() {
    crate::bodies::groove_equivalence();
}

/// G75.1: every documented groove of at most 1 152 layers, no panic, no
/// overflow (first 8 moves). Window: `GROOVE_NO_PANIC_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::floor_div)]
#[kani::stub_verified(cycleref::engine::arith::ceil_div)]
#[kani::stub_verified(cycleref::engine::arith::saturate_i64)]
#[kani::unwind(1153)]
#[kani::solver(cadical)]
fn groove_no_panic() {
    crate::bodies::groove_no_panic();
}

/// The depth schedule, one step from any level that satisfies the invariant (an
/// induction over every level). Window: `SCHEDULE_STEP_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::stub_verified(cycleref::engine::arith::round_sqrt)]
#[kani::unwind(7)]
#[kani::solver(cadical)]
fn schedule_step() {
    crate::bodies::schedule_step();
}

/// LinuxCNC G76: rough depths in order, each shallower than K, rounded depths
/// non-decreasing. Window: `LCNC_DEPTH_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::unwind(256)]
#[kani::solver(cadical)]
fn lcnc_depth_monotonicity() {
    crate::bodies::lcnc_depth_monotonicity();
}

/// LinuxCNC G76: refused exactly beyond the pass limit, otherwise N rough
/// passes, 1 + H at K, the return. Window: `LCNC_DEPTH_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::unwind(256)]
fn lcnc_termination() {
    crate::bodies::lcnc_termination();
}

/// LinuxCNC G76: the passes at full depth, the spring passes repeating the
/// deepest. Window: `LCNC_SPRING_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::unwind(256)]
fn lcnc_spring_passes() {
    crate::bodies::lcnc_spring_passes();
}

/// LinuxCNC G76: each pass's moves (R-LCNC-PASS), tapers, compound shift, no
/// rapid into the thread. Window: `LCNC_PASS_WINDOW`.
#[cfg(feature = "kani-scheduled")]
#[kani::proof]
#[kani::unwind(256)]
fn lcnc_pass_moves() {
    crate::bodies::lcnc_pass_moves();
}
