//! The Kani windows of `proofs/src/kani_proofs.rs`, outside `cfg(kani)` so
//! that the shim runs the same bodies over them (`proofs/tests/kani_windows.rs`)
//! and `proofs/tests/unwind.rs` measures the loop counts each harness
//! reaches in its window against its bound in `crate::catalogue` (Kani
//! needs `#[kani::unwind(N)]` with N above the largest iteration count of
//! every loop it unrolls).

use crate::groove::GrooveDomain;
use crate::harness::Domain;
use crate::linuxcnc::LcncDomain;
use crate::schedule::ScheduleDomain;

/// The G76 window of P1, P2, P4 and P5: thread heights up to 6 increments,
/// one start, every infeed mode of G76 and G78 and both depth modes (G78 is
/// the same cycle), side, direction, unit code, run-out kind,
/// tool and chamfer angle, lead (F and I) and lead-in E ≤ 3. The most
/// moves a cycle has here is 6 per pass (approach, lead-in, cut, run-out,
/// retract, return) times 13 passes (D2 with k = 6, Δd = 1: 6 levels, 11
/// rough passes, then m = 2): 78.
pub const G76_WINDOW: Domain = Domain {
    height: (1, 6),
    first_depth: (1, 6),
    min_cut: (0, 2),
    allowance: (0, 6),
    tool_angle: (0, 99),
    finishing: (0, 2),
    infeed: (0, 5),
    depth_mode: (0, 1),
    starts: (1, 1),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-6, 6),
    length: (20, 40),
    run_out_kind: (0, 3),
    run_out: (0, 4),
    chamfer: (0, 99),
    chamfer_angle: (1, 89),
    units: (0, 7),
    pass_limit: 16,
    lead_in: (0, 3),
    lead: (0, 3),
    wild_x: 2,
};

/// The window of `no_rapid_in_thread` and `run_out_direction`:
/// [`G76_WINDOW`] with threads from 1 increment long, so that X is the long
/// axis too (`|i| ≥ |W|`, taper ±6) and P4's cover "run-out with X long"
/// can be reached under Kani (`--fail-uncoverable`).
pub const NO_RAPID_WINDOW: Domain = Domain { length: (1, 40), ..G76_WINDOW };

/// P3's window: [`G76_WINDOW`] with two starts (the finishing passes per
/// start), k ≤ 4.
pub const FINISHING_WINDOW: Domain =
    Domain { height: (1, 4), first_depth: (1, 4), allowance: (0, 4), starts: (1, 2), ..G76_WINDOW };

/// The infeed modes of the split G76 harnesses, by their code in
/// [`Domain::infeed`], with the suffix of each harness's name: G76's D0, D1,
/// D2 and G78's centre, left flank and alternating flanks.
pub const INFEED_MODES: [(i64, &str); 6] =
    [(0, "d0"), (1, "d1"), (2, "d2"), (3, "centre"), (4, "left_flank"), (5, "alternating")];

/// [`G76_WINDOW`] with one infeed mode and the chamfer (r = 5 tenths of the
/// lead at 45°) fixed: the window of P1 and P2 for that mode. The depth
/// schedule does not read the chamfer; the tool angle, side, direction,
/// taper, lengths, run-out kind and amounts, unit code, lead and lead-in
/// stay symbolic, since they decide which moves are dropped as empty (the
/// counterexample of issue 32 needed a = 95°, a lead-in, a taper, an I lead
/// and inch radius together; with a = 60° no pass of the window loses its
/// approach: `tests/kani_windows.rs` found the cover unreachable). Since the
/// lead-in starts at Bn's Z (R-LEADIN `same-z`, issue 34), an approach is
/// dropped where a pass has no shift (a = 0) and X_Bn + E is X of A.
#[must_use]
pub const fn depth_window(infeed: i64) -> Domain {
    Domain { infeed: (infeed, infeed), chamfer: (5, 5), chamfer_angle: (45, 45), ..G76_WINDOW }
}

/// `base` with one infeed mode and the chamfer fixed (r = 5 tenths at 45°),
/// the tool angle left symbolic: the windows of P5 (`no_overcut`) and of
/// `no_rapid_in_thread`, whose passes move along the flanks.
#[must_use]
pub const fn flank_window(base: Domain, infeed: i64) -> Domain {
    Domain { infeed: (infeed, infeed), chamfer: (5, 5), chamfer_angle: (45, 45), ..base }
}

/// P6's window with one infeed mode ([`EQUIVALENCE_WINDOW`] fixes the
/// chamfer, the units and the lead already).
#[must_use]
pub const fn equivalence_window(infeed: i64) -> Domain {
    Domain { infeed: (infeed, infeed), ..EQUIVALENCE_WINDOW }
}

/// P3's Kani window: [`FINISHING_WINDOW`] with the tool angle (60°) and
/// the chamfer (5 tenths at 45°) fixed, which the finishing passes do not
/// read.
pub const FINISHING_KANI_WINDOW: Domain =
    Domain { tool_angle: (60, 60), chamfer: (5, 5), chamfer_angle: (45, 45), ..FINISHING_WINDOW };

/// P4's Kani window: [`NO_RAPID_WINDOW`] with the tool angle fixed (60°);
/// the chamfer stays symbolic (a chamfered run-out is what P4 checks).
pub const RUN_OUT_KANI_WINDOW: Domain = Domain { tool_angle: (60, 60), ..NO_RAPID_WINDOW };

/// P6's window: k, Δd ≤ 8, straight and small tapers, one start, m = 1.
pub const EQUIVALENCE_WINDOW: Domain = Domain {
    height: (1, 8),
    first_depth: (1, 8),
    min_cut: (0, 2),
    allowance: (0, 8),
    tool_angle: (0, 60),
    infeed: (0, 5),
    depth_mode: (0, 1),
    taper: (-4, 4),
    run_out_kind: (0, 1),
    run_out: (0, 2),
    pass_limit: 16,
    ..Domain::POINT
};

/// P7's window: every documented input, pass limit 32, the first
/// [`NO_PANIC_MOVES`] moves.
pub const NO_PANIC_WINDOW: Domain = Domain { pass_limit: 32, ..Domain::FULL };

/// Moves of each cycle that P7 looks at under Kani.
pub const NO_PANIC_MOVES: usize = 12;

/// P8's window (the contract of `round_sqrt`) and the window of the
/// contract of `isqrt_floor`: their precondition, `x < 2^62`
/// (`cycleref::engine::contracts::SQRT_LIMIT`). Until issue 32 every
/// `u128`, which CBMC does not finish.
pub const ISQRT_WINDOW: (u128, u128) = (0, (1 << 62) - 1);

/// The contract of `round_sqrt_near`: its precondition, `x < 2^62` (as
/// [`ISQRT_WINDOW`]), and every guess (the guess changes only the speed).
pub const ISQRT_NEAR_WINDOW: ((u128, u128), (u128, u128)) = (ISQRT_WINDOW, (0, u128::MAX));

/// The contract of `round_div`: its precondition, numerators below `2^67`
/// and divisors below `2^34` in magnitude (the divisor non-zero). Until
/// issue 32 both below `2^126`.
pub const ROUND_DIV_WINDOW: ((i128, i128), (i128, i128)) =
    ((-(1 << 67) + 1, (1 << 67) - 1), (-(1 << 34) + 1, (1 << 34) - 1));

/// The contract of `saturate_i64`: every `i128`.
pub const SATURATE_WINDOW: (i128, i128) = (i128::MIN, i128::MAX);

/// The contracts of `floor_div` and `ceil_div`: their precondition,
/// dividends below `2^72` in magnitude and divisors from 1 to `2^34 − 1`.
/// Until issue 32 dividends below `2^120` and every positive divisor.
pub const DIV_WINDOW: ((i128, i128), (i128, i128)) = ((-(1 << 72) + 1, (1 << 72) - 1), (1, (1 << 34) - 1));

/// The contract of `mul_tan_round`: every `i64` value, every half-degree
/// code `0..=u32::MAX` (beyond 179 refused).
pub const MUL_TAN_WINDOW: ((i64, i64), (i64, i64)) = ((i64::MIN, i64::MAX), (0, u32::MAX as i64));

/// The G32 run-out window: start and end within 1 000 increments, |J|, K ≤ 100.
pub const G32_WINDOW: (i64, i64) = (1_000, 100);

/// The G92 window: A, C and R within 1 000 increments, J and K up to
/// 100, one or two starts.
pub const G92_WINDOW: (i64, i64, i64) = (1_000, 100, 2);

/// G75.1: right-angle grooves up to 4 increments deep and wide, layers up
/// to 3, allowances and corner sizes up to 1, a pointed tool or widths
/// 1..=2; as [`GrooveDomain::SQUARE`] retract 0..=1, every corner kind, J,
/// sign and unit code.
pub const GROOVE_WINDOW: GrooveDomain = GrooveDomain {
    depth: (1, 4),
    width: (0, 4),
    peck: (1, 4),
    step: (1, 4),
    layer: (0, 3),
    allowance_x: (0, 1),
    allowance_z: (0, 1),
    tool_width: (-1, 2),
    corner: (0, 1),
    ..GrooveDomain::SQUARE
};

/// `groove_equivalence`'s window: right-angle grooves 2 to 4 increments
/// deep and 0 to 3 wide, pecks of 2 (full and short last pecks), steps 1
/// and 2 (ridges and a short last step), retract 0 and 1, no V or Δv 1 and
/// 2 (up to 4 layers), allowances 0 and 1, tool widths 0 and 1 (I0 is the
/// pointed tool: `width_of_tool` is 0 either way), corner sizes 0 and 1 at
/// each corner with r2, r3, r4 rounds and r1 a chamfer or a round (at 90° a
/// chamfer and a round have the same tangent points and the same roughing
/// chord; they differ only in the move's motion, which r1 covers), every J
/// and sign, IS-C inch diameter and IS-B metric radius (f = 2 and f = 1).
/// 884 736 grooves, all enumerated under `cargo test`
/// (`proofs/tests/g75_exact.rs`): the shim runs the engine, the integer
/// restatement and the `num-bigint` reference on each.
pub const GROOVE_EQUIVALENCE_WINDOW: GrooveDomain = GrooveDomain {
    depth: (2, 4),
    width: (0, 3),
    peck: (2, 2),
    step: (1, 2),
    retract: (0, 1),
    layer: (0, 2),
    allowance_x: (0, 1),
    allowance_z: (0, 1),
    tool_width: (0, 1),
    corner: (0, 1),
    corner_kinds: (14, 15),
    path: (0, 2),
    signs: (0, 3),
    units: (3, 4),
    ..GrooveDomain::SQUARE
};

/// `groove_no_panic`'s window: every documented input
/// ([`GrooveDomain::FULL`]) of at most [`GROOVE_NO_PANIC_LAYERS`] layers, the
/// first [`GROOVE_NO_PANIC_MOVES`] moves of each groove.
pub const GROOVE_NO_PANIC_WINDOW: GrooveDomain = GrooveDomain::FULL;

/// The most layers of a groove in `groove_no_panic`'s window (`|H| ≤
/// 1 152·Δv`; see `crate::groove::groove_no_panic`). The peck count's loop
/// over the layers runs once per layer, so its count is at most this. The
/// unwind bound [`GROOVE_NO_PANIC_UNWIND`] was set by the engine's largest
/// loop capacity when `engine::real` divided bit by bit (a dividend of
/// `2N − 2` limbs at the slow precision N = 10: 1 152 bits), and this layer
/// bound is the most the same unwind bound covers; the division is now
/// Knuth's algorithm D (at most 18 quotient limbs), so the layers are the
/// largest capacity, and both stay. Grooves of more layers
/// (up to `MAX_PECKS` = 10^6) are left to the tests here
/// (`proofs/tests/g75_harnesses.rs`).
pub const GROOVE_NO_PANIC_LAYERS: i64 = 1_152;

/// Moves of each groove that `groove_no_panic` looks at under Kani.
pub const GROOVE_NO_PANIC_MOVES: usize = 8;

/// `groove_no_panic`'s unwind bound: one above the most iterations the
/// loops it reaches can make by construction: the layers
/// [`GROOVE_NO_PANIC_LAYERS`] (below), the long division 18 quotient limbs
/// (Knuth's algorithm D; measured: 4), the Taylor series 400 terms (`MAX_TERMS`; measured: 20),
/// a limb loop 28 limbs (the scratch buffers), the contour points 8 (the
/// profile's arrays), the layers [`GROOVE_NO_PANIC_LAYERS`] (measured: 1 152,
/// enumerated); and above the measured counts of the iterator's state
/// machines (3 roughing steps, 2 stages) and of the harness's loop (8 moves).
pub const GROOVE_NO_PANIC_UNWIND: u32 = 1_153;

/// The one-step schedule harness: every documented Δd, Δdmin, k - d
/// (`< 2^30`) and every state (depth ≤ k - d, level ≤ depth) that
/// satisfies the invariant, i.e. every level of every cycle.
pub const SCHEDULE_STEP_WINDOW: ScheduleDomain = ScheduleDomain {
    first_depth: (1, 999_999_999),
    min_cut: (0, 999_999_999),
    last: (0, 999_999_999),
    depth: (0, 999_999_999),
    level: (0, 999_999_999),
};

/// The LinuxCNC depth window of `lcnc_depth_monotonicity` and
/// `lcnc_termination`: J ≤ 3, K − J ≤ 3 (K ≤ 6), R = p/q for every q ≤ 4
/// and q ≤ p ≤ 3q with `10 000·p/q` an integer (R in ten-thousandths: so
/// the quarters from 1 to 3, 1, 5/4, 3/2, 7/4, 2, 9/4, 5/2, 11/4, 3; a
/// third is no ten-thousandth), H from -1 to 2, G7
/// and G8, both sides, X₀ from 0 to 2 (coordinates of either sign after
/// the rounding), Q 0 and 29.5°, no taper, pass limit 12 (J = 1, K = 6, R
/// = 3 would take 215 rough passes: refused). The most moves: 12 rough
/// passes and 3 at full depth, 4 moves each, and the return: 61.
pub const LCNC_DEPTH_WINDOW: LcncDomain = LcncDomain {
    initial_depth: (1, 3),
    extra_depth: (1, 3),
    denominator: (1, 4),
    max_degression: 3,
    peak_offset: (1, 1),
    x0: (0, 2),
    length: (10, 10),
    angle: (0, 1),
    spring_passes: (-1, 2),
    taper_distance: (0, 0),
    taper_bits: (0, 0),
    diameter: (0, 1),
    internal: (0, 1),
    towards_plus: (0, 0),
    pass_limit: 12,
};

/// The window of `lcnc_spring_passes`: K ≤ 5, R from 1 to 2, every angle of
/// [`crate::linuxcnc::ANGLES`], H from -1 to 2, both directions and sides,
/// G7/G8, E 0 and 2 with every L, pass limit 8.
pub const LCNC_SPRING_WINDOW: LcncDomain = LcncDomain {
    initial_depth: (1, 2),
    extra_depth: (1, 3),
    denominator: (1, 2),
    max_degression: 2,
    peak_offset: (1, 2),
    x0: (0, 0),
    length: (10, 10),
    angle: (0, 3),
    spring_passes: (-1, 2),
    taper_distance: (0, 2),
    taper_bits: (0, 3),
    diameter: (0, 1),
    internal: (0, 1),
    towards_plus: (0, 1),
    pass_limit: 8,
};

/// The window of `lcnc_pass_moves`: J ≤ 2, K ≤ 4, R 1 and 2, |I| ≤ 2, every
/// angle, H 0 and 1, E from 0 to 3 with every L on threads 2 to 6 long (E
/// longer than the pass too), both directions and sides, G7/G8, pass
/// limit 8.
pub const LCNC_PASS_WINDOW: LcncDomain = LcncDomain {
    initial_depth: (1, 2),
    extra_depth: (1, 2),
    denominator: (1, 1),
    max_degression: 2,
    peak_offset: (1, 2),
    x0: (0, 0),
    length: (2, 6),
    angle: (0, 3),
    spring_passes: (0, 1),
    taper_distance: (0, 3),
    taper_bits: (0, 3),
    diameter: (0, 1),
    internal: (0, 1),
    towards_plus: (0, 1),
    pass_limit: 8,
};

/// The unwind bound of harness `name` (`crate::catalogue::unwind`, where
/// the bounds live).
///
/// # Panics
///
/// When `name` is not a Kani harness.
#[cfg(not(kani))]
#[must_use]
pub fn unwind(name: &str) -> u32 {
    crate::catalogue::unwind(name)
}
