//! Tests for the engine changes that cargo-mutants found the harness tests
//! let through (`proofs/README.md`, the mutation scores). Each expected
//! value is worked out by hand (the working is in the comments) or taken
//! from the exact reference `cycleref_spec`, never from the engine.
//!
//! The loop counters are process-wide, and every engine run records into
//! them: each test holds [`serial`] while it runs, so that the counter
//! checks read only their own runs.

use cycleref::loop_counters::{self, ISQRT_U128, ISQRT_U64};

/// One test at a time in this binary (see the module docs).
fn serial() -> std::sync::MutexGuard<'static, ()> {
    static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());
    SERIAL.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The reference's moves of a G75.1 cycle, once the engine's are found to
/// be the same (`differ::assert_same_moves`, the one "same moves" check).
fn g75_reference_moves(c: &cycleref::G75Cycle) -> Vec<cycleref::Move> {
    let reference = cycleref_spec::g75::expand(c);
    let engine = cycleref::expand_g75(c).map(Iterator::collect);
    cycleref_spec::differ::assert_same_moves(&engine, &reference, format_args!("{c:?}"));
    reference.expect("the reference expands it")
}

/// The engine and the reference both refuse the G76 cycle `c` with `e`,
/// before any move.
fn g76_refused_by_both(c: &cycleref::G76Cycle, e: cycleref::CycleError) {
    assert_eq!(cycleref::expand_g76(c).map(|_| ()), Err(e), "the engine");
    assert_eq!(cycleref_spec::g76::expand(c).map(|_| ()), Err(e), "the reference");
}

/// The engine and the reference both refuse the G75.1 cycle `c` with `e`,
/// before any move; `what` names the case in a failure.
fn g75_refused_by_both(c: &cycleref::G75Cycle, e: cycleref::CycleError, what: &str) {
    assert_eq!(cycleref_spec::g75::expand(c).map(|_| ()), Err(e), "{what}: the reference");
    assert_eq!(cycleref::expand_g75(c).map(|_| ()), Err(e), "{what}: the engine");
}

/// R-G75RANGE (and the G76/G92 range checks): the first pass coordinate
/// beyond ±999 999 999, `value` in IS-B metric increments.
fn beyond_the_range(value: i64) -> cycleref::CycleError {
    use cycleref::{CycleError, Field, Length, Units};
    CycleError::OutOfRange { field: Field::PassCoordinate, value: Length::new(value, Units::IS_B_METRIC) }
}

/// The first plunge of a one-layer `square_groove()` with S at X100.000
/// and a 1.000 tool (`c`), as the reference makes it and the engine too:
/// the approach to A_11 at Z `a11`, the pecks to X99.000 and X98.000, the
/// retract, and the step to the second plunge at Z `step`.
fn assert_first_plunge(c: &cycleref::G75Cycle, a11: i64, step: i64) {
    use cycleref::{Motion, Plunge, Point, Role};
    let moves = g75_reference_moves(c);
    let first: Vec<_> = moves.iter().take(5).map(|m| (m.motion, m.to, m.role)).collect();
    let plunge = |number: u32| Plunge { layer: 1, number };
    assert_eq!(
        first,
        [
            (Motion::Rapid, Point::new(100_000, a11), Role::Approach),
            (Motion::Feed, Point::new(99_000, a11), Role::Peck(plunge(1))),
            (Motion::Feed, Point::new(98_000, a11), Role::Peck(plunge(1))),
            (Motion::Rapid, Point::new(100_000, a11), Role::PlungeRetract(plunge(1))),
            (Motion::Rapid, Point::new(100_000, step), Role::Step(plunge(2))),
        ]
    );
}

/// A right-angle G75.1 rough groove (IS-B, diameter): S at X100.000 Z0
/// from X120.000 Z5.000, H−2.000, D3.000, Δi = Δk = 1.000, a pointed tool,
/// one layer, no allowances, no retract, sharp corners. The G75.1 tests
/// below change what they need with `..square_groove()`.
fn square_groove() -> cycleref::G75Cycle {
    use cycleref::g75::RIGHT_ANGLE;
    use cycleref::{Corner, PathType, Point, Units, XMode};
    cycleref::G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(120_000, 5_000),
        start: Point::new(100_000, 0),
        peck: 1_000,
        step: 1_000,
        depth: -2_000,
        width: 3_000,
        flank_a: RIGHT_ANGLE,
        flank_b: RIGHT_ANGLE,
        slope: 0,
        retract: 0,
        layer: None,
        allowance_x: 0,
        allowance_z: 0,
        tool_width: None,
        path: PathType::Rough,
        corners: [Corner::SHARP; 4],
        readings: cycleref::G75Readings::DEFAULT,
    }
}

/// The interval [lo, hi] of two integers, at the fast precision.
fn iv(lo: i128, hi: i128) -> cycleref::engine::real::Interval<{ cycleref::engine::real::FAST }> {
    use cycleref::engine::real::{Fixed, Interval};
    Interval::new(Fixed::from_int(lo), Fixed::from_int(hi))
}

/// The motion and end point of each of `moves` with role `role`.
fn with_role(moves: &[cycleref::Move], role: cycleref::Role) -> Vec<(cycleref::Motion, cycleref::Point)> {
    moves.iter().filter(|m| m.role == role).map(|m| (m.motion, m.to)).collect()
}

/// The Newton iterations `isqrt_floor` makes, recorded by `record_isqrt`.
fn newton_iterations(x: u128) -> (u32, u32) {
    loop_counters::reset();
    cycleref::engine::record_isqrt(x);
    (ISQRT_U64.max(), ISQRT_U128.max())
}

/// Newton's iterations counted exactly (the harnesses only check that they
/// stay below the unwind bound, which a count stuck at 0 passes): the start
/// is `g = 2^ceil(bits/2)`, each iteration is `y = (g + x/g) >> 1`, and
/// the one that finds `y ≥ g` ends the loop and is counted too.
#[test]
fn newton_iteration_counts() {
    let _serial = serial();
    // x = 2^16 (u64 loop): bits 17, g = 2^9 = 512; y = (512 + 128)/2 = 320;
    // (320 + 204)/2 = 262; (262 + 250)/2 = 256; (256 + 256)/2 = 256 ≥ 256:
    // 4 iterations, root 256.
    assert_eq!(newton_iterations(1 << 16), (4, 0));
    assert_eq!(cycleref::engine::isqrt_floor(1 << 16), 256);
    // x = 10^6 (u64 loop): bits 20, g = 2^10 = 1024; (1024 + 976)/2 = 1000;
    // (1000 + 1000)/2 = 1000 ≥ 1000: 2 iterations.
    assert_eq!(newton_iterations(1_000_000), (2, 0));
    // x = 2^64 (u128 loop): bits 65, g = 2^33 = 8 589 934 592;
    // (2^33 + 2^31)/2 = 5 368 709 120; (5 368 709 120 + 3 435 973 836)/2
    // = 4 402 341 478; (4 402 341 478 + 4 190 211 996)/2 = 4 296 276 737;
    // (4 296 276 737 + 4 293 658 254)/2 = 4 294 967 495;
    // (4 294 967 495 + 4 294 967 097)/2 = 4 294 967 296 = 2^32; then
    // (2^32 + 2^32)/2 = 2^32 ≥ 2^32: 6 iterations, root 2^32.
    assert_eq!(newton_iterations(1 << 64), (0, 6));
    // x = 2^128 - 1 (u128 loop): bits 128, g = 2^64; x / g = 2^64 - 1,
    // (2^64 + 2^64 - 1)/2 = 2^64 - 1; x / (2^64 - 1) = 2^64 + 1,
    // (2^64 - 1 + 2^64 + 1)/2 = 2^64 ≥ 2^64 - 1: 2 iterations, root
    // 2^64 - 1.
    assert_eq!(newton_iterations(u128::MAX), (0, 2));
    // (The roots of 2^64 and 2^128 − 1 are outside the kernel's contract, x
    // < 2^62, which every call checks here: only the loop counts, which
    // `record_isqrt` measures without calling the kernel, are asserted.)
    loop_counters::reset();
}

/// G92 with A on B's X (the taper brings the thread's start exactly to the
/// X of A): a valid cycle whose approach is empty; one increment further
/// out, B lies beyond A and the cycle is refused (reading R-G92SIDE; the
/// harnesses never reached the boundary, `< 0` could become `<= 0`).
#[test]
fn g92_with_a_on_the_x_of_b() {
    let _serial = serial();
    use cycleref::lead::{Lead, LeadWord};
    use cycleref::{CycleError, G92Cycle, Motion, Point, Role, RunOut, StartAngle, Units, XMode};

    let cycle = |a_x: i64| G92Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(a_x, 0),
        end: Point::new(40_000, -20_000),
        taper: 5_000,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: RunOut::None,
        starts: 1,
        start_angle: StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    // B: X = 40.000 + 2 · 5.000 = 50.000 (diameter), the X of A, at the Z
    // of A: B = A, so no approach. The cut along the taper to C, the
    // retract along X to 50.000, the return along Z to A.
    let c = cycle(50_000);
    let moves: Vec<_> = cycleref::expand_g92(&c).expect("A on B's X is valid").collect();
    assert_eq!(Ok(moves.clone()), cycleref_spec::g92::expand(&c));
    let path: Vec<_> =
        moves.iter().map(|m| (m.to, m.role, matches!(m.motion, Motion::Thread { .. }))).collect();
    assert_eq!(
        path,
        [
            (Point::new(40_000, -20_000), Role::Cut, true),
            (Point::new(50_000, -20_000), Role::Retract, false),
            (Point::new(50_000, 0), Role::Return, false),
        ]
    );
    // A one increment nearer the axis than B: B lies beyond A. The alarm
    // names R = 5.000 and the infeed U = 40.000 - 49.999 = -9.999.
    let c = cycle(49_999);
    let e = cycleref::expand_g92(&c).map(|_| ()).unwrap_err();
    let CycleError::TaperBeyondStart { taper, infeed } = e else { panic!("{e:?}") };
    assert_eq!((taper.increments, infeed.increments), (5_000, -9_999));
    assert_eq!(cycleref_spec::g92::expand(&c).map(|_| ()), Err(e));
}

/// G92 run-outs at their limits: K as long as |W| is allowed and one
/// increment more is the alarm (988TA note 4); a taper rising towards A
/// refuses a run-out only on an X long axis (reading R-XRUNOUT), not on a
/// Z long axis. Checked against the reference.
#[test]
fn g92_run_out_limits() {
    let _serial = serial();
    use cycleref::lead::{Lead, LeadWord};
    use cycleref::{CycleError, G92Cycle, Point, RunOut, StartAngle, Units, XMode};

    let cycle_from = |a_x: i64, end: Point, taper: i64, short: i64, long: i64| G92Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(a_x, 0),
        end,
        taper,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: RunOut::Amounts { short, long },
        starts: 1,
        start_angle: StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    let cycle = |end: Point, taper: i64, short: i64, long: i64| cycle_from(50_000, end, taper, short, long);
    let both = |c: &G92Cycle| {
        let ours = cycleref::expand_g92(c).map(Iterator::collect::<Vec<_>>);
        assert_eq!(ours, cycleref_spec::g92::expand(c), "{c:?}");
        ours
    };
    // Z long, |W| = 20.000: K = 20.000 expands, K = 20.001 is refused with
    // the long-axis length 20.000.
    let z_long = Point::new(40_000, -20_000);
    assert!(both(&cycle(z_long, 0, 1_000, 20_000)).is_ok());
    assert!(matches!(
        both(&cycle(z_long, 0, 1_000, 20_001)),
        Err(CycleError::RunOutTooLong { run_out, length }) if (run_out.increments, length.increments) == (20_001, 20_000)
    ));
    // Z long (|W| = 20.000 > |R| = 2.000), R > 0 on an external thread
    // (side +1): the run-out along X is allowed.
    assert!(both(&cycle(z_long, 2_000, 1_000, 5_000)).is_ok());
    // X long (|R| = 4.000 ≥ |W| = 3.000), R > 0 on an external thread: a
    // run-out along Z towards A would cut into the work.
    let x_long = Point::new(40_000, -3_000);
    assert!(matches!(
        both(&cycle(x_long, 4_000, 1_000, 2_000)),
        Err(CycleError::RunOutIntoWork { taper }) if taper.increments == 4_000
    ));
    // The same with R < 0 (the thread start below C): allowed.
    assert!(both(&cycle(Point::new(48_000, -3_000), -4_000, 1_000, 2_000)).is_ok());
    // Internal (A at X 30.000 below C, side -1), X long: R < 0 rises
    // towards A (s·R = 4.000 > 0) and is refused, R > 0 is allowed.
    assert!(matches!(
        both(&cycle_from(30_000, Point::new(40_000, -3_000), -4_000, 1_000, 2_000)),
        Err(CycleError::RunOutIntoWork { taper }) if taper.increments == -4_000
    ));
    assert!(both(&cycle_from(30_000, Point::new(32_000, -3_000), 4_000, 1_000, 2_000)).is_ok());
}

/// A G76 cycle for the `engine/g76.rs` survivors: IS-B metric, diameter X,
/// F2, one start, tool angle 0 (no flank shifts), one finishing pass, D2
/// off (D0, the right flank), no lead-in, run-out as given (the words it
/// does not name from `harness::PLAIN_CYCLE`).
fn g76_cycle(
    start: cycleref::Point,
    end: cycleref::Point,
    taper: i64,
    run_out: cycleref::RunOut,
) -> cycleref::G76Cycle {
    use cycleref::{G76Cycle, XMode};
    G76Cycle {
        x_mode: XMode::Diameter,
        start,
        end,
        taper,
        thread_height: 1_000,
        first_depth: 1_000,
        min_cut: 0,
        finishing_allowance: 0,
        tool_angle: 0,
        run_out,
        pass_limit: 100,
        ..cycleref_proofs::harness::PLAIN_CYCLE
    }
}

/// The equal-step depth mode (G78 等距离) counts its levels as `ceil((k -
/// d) / step)`, step = max(Δd, Δdmin, 1), before any move (reading
/// R-LIMIT); the harness windows never put such a cycle past its pass
/// limit, so `(k - d - step - 1) / step` passed them.
#[test]
fn equal_steps_count_their_levels() {
    let _serial = serial();
    use cycleref::{CycleError, DepthMode, Point, RunOut};
    // k = 10, d = 0, Δd = 3, Δdmin = 0: step max(3, 0, 1) = 3, levels at
    // 3, 6, 9, 10: ceil(10 / 3) = 4 rough passes.
    let c = |pass_limit: u32| cycleref::G76Cycle {
        thread_height: 10,
        first_depth: 3,
        depth_mode: DepthMode::Equal,
        pass_limit,
        // No finishing pass: the whole cycle's pass paths (R-BUDGET) are
        // its rough passes, so the rough limit's edge is what is tested.
        finishing_passes: 0,
        ..g76_cycle(Point::new(50_000, 0), Point::new(40_000, -20_000), 0, RunOut::None)
    };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(4)), Ok(4));
    // With a limit of 3 the four passes are refused, counted exactly.
    let e = CycleError::TooManyPasses { passes: 4, exact: true, limit: 3 };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(3)), Err(e));
    g76_refused_by_both(&c(3), e);
}

/// An X-long G76 thread (|i| ≥ |W|) whose run-out K equals |i| is allowed
/// (the alarm is for K > |i|, as the reference), and one increment more is
/// refused. Worked by hand: A (50.000, 0), D (40.000, -3.000), i = -4.000
/// (radius), k = 1.000, one rough pass at k - d = 1.000 and one finishing
/// pass, tool angle 0 (shift 0), J = 1.000, K = 4.000.
/// C = 40.000 + 2·(-4.000) = 32.000; A is outside C (side +1) and beyond
/// B (34.000) and the crest at D (42.000); |i| = 4.000 ≥ |W| = 3.000: X
/// long, and s·i < 0: the run-out does not go into the work (R-XRUNOUT).
/// Each pass at depth k starts at Bn = (32.000, 0) and ends at (40.000,
/// -3.000); the run-out starts K = 4.000 (8.000 on the diameter) before the
/// end along X, at X 32.000, which is Bn itself, so the cut is empty and
/// left out (R-ZERO); the run-out goes to X 40.000 and J = 1.000 along Z
/// towards A, Z -2.000; the retract to X 50.000, the return to A.
#[test]
fn g76_x_long_run_out_as_long_as_the_taper() {
    let _serial = serial();
    use cycleref::{CycleError, Motion, Point, Role, RunOut};
    let c = |k_run_out: i64| {
        g76_cycle(
            Point::new(50_000, 0),
            Point::new(40_000, -3_000),
            -4_000,
            RunOut::Amounts { short: 1_000, long: k_run_out },
        )
    };
    let moves: Vec<_> = cycleref::expand_g76(&c(4_000)).expect("K = |i| is allowed").collect();
    assert_eq!(Ok(moves.clone()), cycleref_spec::g76::expand(&c(4_000)));
    let pass = [
        (Point::new(32_000, 0), Role::Approach, false),
        (Point::new(40_000, -2_000), Role::RunOut, true),
        (Point::new(50_000, -2_000), Role::Retract, false),
        (Point::new(50_000, 0), Role::Return, false),
    ];
    let path: Vec<_> =
        moves.iter().map(|m| (m.to, m.role, matches!(m.motion, Motion::Thread { .. }))).collect();
    assert_eq!(path, [pass, pass].concat());
    let e = CycleError::RunOutTooLong {
        run_out: cycleref::Length::new(4_001, cycleref::Units::IS_B_METRIC),
        length: cycleref::Length::new(4_000, cycleref::Units::IS_B_METRIC),
    };
    g76_refused_by_both(&c(4_001), e);
}

/// The pass count when the depth law lasts to the pass limit (reading
/// R-LIMIT): the count stops with an inexact alarm only once a law level
/// lies beyond the limit; a law phase that ends at level limit + 1 is still
/// counted exactly. k = 60, d = 0, Δd = 40, Δdmin = 0 (m = 1), D0:
/// D1 = round(40·√1) = 40, D2 = round(40·√2) = round(56.57) = 57 (≥ 40 +
/// 1: the law holds), D3 = round(40·√3) = round(69.28) = 69 ≥ 60: the last
/// level, 60. Three levels, three passes: with a limit of 3 they are
/// allowed, with a limit of 2 refused with the exact count 3 (level 2 is a
/// law level at the limit, not beyond it).
#[test]
fn a_law_phase_that_ends_one_level_past_the_limit_is_counted_exactly() {
    let _serial = serial();
    use cycleref::{CycleError, Point, RunOut};
    let c = |pass_limit: u32| cycleref::G76Cycle {
        thread_height: 60,
        first_depth: 40,
        pass_limit,
        // No finishing pass: the whole cycle's pass paths (R-BUDGET) are
        // its rough passes, so the rough limit's edge is what is tested.
        finishing_passes: 0,
        ..g76_cycle(Point::new(50_000, 0), Point::new(40_000, -20_000), 0, RunOut::None)
    };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(3)), Ok(3));
    let e = CycleError::TooManyPasses { passes: 3, exact: true, limit: 2 };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(2)), Err(e));
    g76_refused_by_both(&c(2), e);
}

/// D2 (左右等量) cuts every level but the last twice: 2·levels − 1 rough
/// passes, which the pass limit is checked against before any move. Equal
/// steps, k = 10, d = 0, Δd = 3: levels 3, 6, 9, 10, so 2·4 − 1 = 7
/// passes (3 R, 3 L, 6 R, 6 L, 9 R, 9 L, 10 R): allowed with a limit of
/// 7, refused with 6.
#[test]
fn d2_counts_both_flanks() {
    let _serial = serial();
    use cycleref::{CycleError, DepthMode, Flank, Infeed, PassKind, Point, RunOut};
    let c = |pass_limit: u32| cycleref::G76Cycle {
        thread_height: 10,
        first_depth: 3,
        depth_mode: DepthMode::Equal,
        infeed: Infeed::LeftRight,
        pass_limit,
        // No finishing pass: the whole cycle's pass paths (R-BUDGET) are
        // its rough passes, so the rough limit's edge is what is tested.
        finishing_passes: 0,
        ..g76_cycle(Point::new(50_000, 0), Point::new(40_000, -20_000), 0, RunOut::None)
    };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(7)), Ok(7));
    let mut rough: Vec<_> = cycleref::expand_g76(&c(7))
        .expect("7 passes within a limit of 7")
        .filter_map(|m| m.pass)
        .filter(|p| p.kind == PassKind::Rough)
        .map(|p| (p.number, p.depth, p.flank))
        .collect();
    rough.dedup();
    let (r, l) = (Flank::Right, Flank::Left);
    assert_eq!(rough, [(1, 3, r), (2, 3, l), (3, 6, r), (4, 6, l), (5, 9, r), (6, 9, l), (7, 10, r)]);
    let e = CycleError::TooManyPasses { passes: 7, exact: true, limit: 6 };
    assert_eq!(cycleref::engine::g76::rough_pass_count(&c(6)), Err(e));
    g76_refused_by_both(&c(6), e);
}

/// A must be clear of B, not only of the crest at D (reading R-SIDE): on
/// a taper that rises towards A the crest at the start, B, lies further
/// out than the crest at D. External thread, D (40.000, -20.000), i =
/// 0.500 (radius), k = 1.000: C = 40.000 + 2·0.500 = 41.000, B = 41.000 +
/// 2·1.000 = 43.000, the crest at D 40.000 + 2·1.000 = 42.000. A at X
/// 42.500 is outside the crest at D but inside B: refused; A at 43.000, on
/// B's X, is allowed (the check is `s·(X_A − X_B) < 0`), one increment
/// inside it refused. The harness windows put A one increment beyond both
/// crests, never between them or inside.
#[test]
fn a_start_between_the_crest_at_d_and_b_is_inside_the_thread() {
    let _serial = serial();
    use cycleref::{CycleError, Point, RunOut};
    let c = |a_x: i64| g76_cycle(Point::new(a_x, 0), Point::new(40_000, -20_000), 500, RunOut::None);
    assert_eq!(cycleref::expand_g76(&c(42_500)).map(|_| ()), Err(CycleError::StartInsideThread));
    assert_eq!(cycleref_spec::g76::expand(&c(42_500)).map(|_| ()), Err(CycleError::StartInsideThread));
    let moves: Vec<_> = cycleref::expand_g76(&c(43_000)).expect("A on B's X is clear").collect();
    assert_eq!(Ok(moves), cycleref_spec::g76::expand(&c(43_000)));
    // One increment inside B is inside too.
    assert_eq!(cycleref::expand_g76(&c(42_999)).map(|_| ()), Err(CycleError::StartInsideThread));
    assert_eq!(cycleref_spec::g76::expand(&c(42_999)).map(|_| ()), Err(CycleError::StartInsideThread));
    // The taper falling towards A (i = -0.500): C = 39.000, B = 41.000,
    // the crest at D 42.000 now the further out. A at 41.500 is outside B
    // but inside the crest at D: refused; on the crest at D, 42.000: clear.
    let c = |a_x: i64| g76_cycle(Point::new(a_x, 0), Point::new(40_000, -20_000), -500, RunOut::None);
    assert_eq!(cycleref::expand_g76(&c(41_500)).map(|_| ()), Err(CycleError::StartInsideThread));
    assert_eq!(cycleref_spec::g76::expand(&c(41_500)).map(|_| ()), Err(CycleError::StartInsideThread));
    let moves: Vec<_> = cycleref::expand_g76(&c(42_000)).expect("A on the crest at D is clear").collect();
    assert_eq!(Ok(moves), cycleref_spec::g76::expand(&c(42_000)));
    assert_eq!(cycleref::expand_g76(&c(41_999)).map(|_| ()), Err(CycleError::StartInsideThread));
    assert_eq!(cycleref_spec::g76::expand(&c(41_999)).map(|_| ()), Err(CycleError::StartInsideThread));
}

/// G92's range check on B's X (reading R-RANGE): B may lie exactly at the
/// end of the range table, not beyond. An internal thread (A inside C,
/// side -1), IS-B, diameter X, C = (999 997.999, -20.000), R = 1.000: B's
/// X = 999 997 999 + 2·1 000 = 999 999 999 increments = MAX_LENGTH,
/// allowed (the approach goes to B = (999 999 999, 0)); with C one
/// increment further out, 999 998.000, B's X is 1 000 000 000: refused
/// with that value.
#[test]
fn g92_b_at_the_end_of_the_range() {
    let _serial = serial();
    use cycleref::lead::{Lead, LeadWord};
    use cycleref::{G92Cycle, Point, RunOut, StartAngle, Units, XMode};
    let cycle = |end_x: i64| G92Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(900_000_000, 0),
        end: Point::new(end_x, -20_000),
        taper: 1_000,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: RunOut::None,
        starts: 1,
        start_angle: StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    let moves: Vec<_> = cycleref::expand_g92(&cycle(999_997_999)).expect("B at the range's end").collect();
    assert_eq!(moves.first().map(|m| m.to), Some(Point::new(999_999_999, 0)), "the approach to B");
    assert_eq!(Ok(moves), cycleref_spec::g92::expand(&cycle(999_997_999)));
    let e = beyond_the_range(1_000_000_000);
    assert_eq!(cycleref::expand_g92(&cycle(999_998_000)).map(|_| ()), Err(e));
    assert_eq!(cycleref_spec::g92::expand(&cycle(999_998_000)).map(|_| ()), Err(e));
}

/// A cycle with nothing to cut (d = k: no rough level, reading R-NOROUGH;
/// m = 0: no finishing pass) has no pass, so nothing of a pass is checked:
/// not even a lead-in start beyond the range tables (reading R-RANGE looks
/// at the first planned pass, and there is none). With one finishing pass
/// the same lead-in start is refused. A (50.000, 999 000.000), D (40.000,
/// 998 000.000) in IS-B increments: W = -1 000 000, t = -1; under R-LEADIN
/// `whole-leads` F2 = 2 000 increments a revolution, E = 1 000 000:
/// ceil(10^6 / 2 000) = 500 leads, 1 000 000 long; the tool angle 0 gives
/// the finishing pass the shift 0, so its lead-in starts at Z = 999 000 000
/// + 1 000 000 = 1 000 000 000 > 999 999 999.
#[test]
fn a_cycle_without_passes_checks_no_lead_in() {
    let _serial = serial();
    use cycleref::{Point, RunOut};
    let c = |finishing_passes: u32| cycleref::G76Cycle {
        finishing_allowance: 1_000,
        finishing_passes,
        lead_in: 1_000_000,
        readings: cycleref::CycleReadings { lead_in_same_z: false, ..cycleref::CycleReadings::DEFAULT },
        ..g76_cycle(Point::new(50_000, 999_000_000), Point::new(40_000, 998_000_000), 0, RunOut::None)
    };
    let moves: Vec<_> = cycleref::expand_g76(&c(0)).expect("nothing to cut, nothing refused").collect();
    assert!(moves.is_empty());
    assert_eq!(cycleref_spec::g76::expand(&c(0)), Ok(moves));
    let e = beyond_the_range(1_000_000_000);
    g76_refused_by_both(&c(1), e);
}

/// `Schedule::resume` refuses every state outside the engine's ranges,
/// one range at a time, and keeps the ones inside (the proofs only ever
/// make states inside them, so `&&` could become `||`, or `resume` always
/// `None`, and no harness noticed).
#[test]
fn a_schedule_is_resumed_only_inside_the_engine_ranges() {
    let _serial = serial();
    use cycleref::engine::schedule::Schedule;
    use cycleref::units::MAX_LENGTH;
    let max_level = MAX_LENGTH.unsigned_abs();
    // Inside: Δd = 3000, Δdmin = 0, k - d = 10 000, one level made at 3000.
    let s = Schedule::resume(3_000, 0, 10_000, 1, 3_000, false).expect("inside the ranges");
    assert_eq!((s.level(), s.depth(), s.min_phase()), (1, 3_000, false));
    // The ends of each range are inside.
    assert!(Schedule::resume(MAX_LENGTH, MAX_LENGTH, MAX_LENGTH, max_level, MAX_LENGTH, true).is_some());
    assert!(Schedule::resume(1, 0, 0, 0, 0, false).is_some());
    // One value outside, the others inside: refused.
    for (what, state) in [
        ("Δd 0", Schedule::resume(0, 0, 10_000, 1, 3_000, false)),
        ("Δd past the range", Schedule::resume(MAX_LENGTH + 1, 0, 10_000, 1, 3_000, false)),
        ("Δdmin below 0", Schedule::resume(3_000, -1, 10_000, 1, 3_000, false)),
        ("Δdmin past the range", Schedule::resume(3_000, MAX_LENGTH + 1, 10_000, 1, 3_000, false)),
        ("k - d below 0", Schedule::resume(3_000, 0, -1, 0, 0, false)),
        ("k - d past the range", Schedule::resume(3_000, 0, MAX_LENGTH + 1, 1, 3_000, false)),
        ("depth below 0", Schedule::resume(3_000, 0, 10_000, 1, -1, false)),
        ("depth past k - d", Schedule::resume(3_000, 0, 10_000, 1, 10_001, false)),
        ("level past the range", Schedule::resume(3_000, 0, 10_000, max_level + 1, 3_000, false)),
    ] {
        assert!(state.is_none(), "{what}");
    }
    // The same words at another state: every field of the state is the
    // one given (none kept from before), inside the ranges only.
    let t = s.with_state(5, 7_000, true).expect("inside the ranges");
    assert_eq!((t.level(), t.depth(), t.min_phase()), (5, 7_000, true));
    assert_eq!(t.with_state(1, 3_000, false), Some(s));
    assert!(s.with_state(1, 10_001, false).is_none(), "depth past k - d");
    assert!(s.with_state(1, -1, false).is_none(), "depth below 0");
    assert!(s.with_state(max_level + 1, 3_000, false).is_none(), "level past the range");
    assert!(s.with_state(max_level, 10_000, false).is_some(), "the ends");
    // The next level from there, by the law: round(3000·√2) = round(4242.64)
    // = 4243, above 3000 + max(Δdmin, 1) = 3001, so the law stays in force.
    let mut s = s;
    assert_eq!(s.next_level(), Some(4_243));
    assert_eq!((s.level(), s.depth(), s.min_phase()), (2, 4_243, false));
}

/// The law's square root is recorded for the unwind check with its own
/// argument Δd²·n (loop counters): Δd = 3000, n = 2, x = 18 000 000, bits
/// 25, g = 2^13 = 8192; y = (8192 + 2197)/2 = 5194; (5194 + 3465)/2 =
/// 4329; (4329 + 4158)/2 = 4243; (4243 + 4242)/2 = 4242; (4242 + 4243)/2 =
/// 4242 ≥ 4242: 5 iterations on u64. Δd² + n (9 000 002) and Δd²/n
/// (4 500 000) take 4, so a wrong argument is seen.
#[test]
fn the_law_records_its_own_square_root() {
    let _serial = serial();
    use cycleref::engine::schedule::Schedule;
    let mut s = Schedule::resume(3_000, 0, 10_000, 1, 3_000, false).expect("inside the ranges");
    loop_counters::reset();
    assert_eq!(s.next_level(), Some(4_243));
    assert_eq!((ISQRT_U64.max(), ISQRT_U128.max()), (5, 0));
    loop_counters::reset();
}

/// The contracts' predicates refuse a wrong answer at each bound (the
/// contract tests run them on the kernels' right answers only, so a bound
/// loosened by one, `<` → `<=`, went unseen: `contracts.rs` 32:27, 50:26,
/// 71:36, 71:69, 90:31). Worked by hand: √16 = 4, so 3 is not
/// `isqrt_floor(16)` ((3 + 1)² = 16 is not above 16); round(√12) = 3
/// (√12 = 3.46), so 4 is not `round_sqrt(12)` (4·3 = 12 is not below 12),
/// round(√20) = 4 (√20 = 4.47; 20 ≤ 4·5) and round(√21) = 5; 5/2 = 2.5
/// rounds away from zero to 3, so 2 is not `round_div(5, 2)` (the tie's
/// remainder 1 has num's sign), nor −2 `round_div(−5, 2)`; magnitudes of
/// 2^126 are outside `round_div`'s precondition, 2^126 − 1 inside.
#[test]
fn the_contracts_refuse_a_wrong_answer_at_each_bound() {
    let _serial = serial();
    use cycleref::engine::contracts::{
        isqrt_floor_ensures, round_div_ensures, round_div_requires, round_sqrt_ensures,
    };
    assert!(isqrt_floor_ensures(16, 4));
    assert!(!isqrt_floor_ensures(16, 3));
    assert!(!isqrt_floor_ensures(16, 5));
    assert!(isqrt_floor_ensures(15, 3));
    assert!(!isqrt_floor_ensures(15, 4));
    assert!(round_sqrt_ensures(12, 3));
    assert!(!round_sqrt_ensures(12, 4));
    assert!(round_sqrt_ensures(13, 4));
    assert!(round_sqrt_ensures(20, 4));
    assert!(!round_sqrt_ensures(21, 4));
    assert!(round_sqrt_ensures(21, 5));
    assert!(round_div_ensures(5, 2, 3));
    assert!(!round_div_ensures(5, 2, 2));
    assert!(round_div_ensures(-5, 2, -3));
    assert!(!round_div_ensures(-5, 2, -2));
    assert!(round_div_ensures(7, 3, 2));
    assert!(!round_div_ensures(7, 3, 3));
    // The ranges the callers use (issue 32): |num| < 2^67, 0 < |den| < 2^34.
    let (num_edge, den_edge) = (1_i128 << 67, 1_i128 << 34);
    assert!(round_div_requires(num_edge - 1, 1));
    assert!(round_div_requires(-(num_edge - 1), 1));
    assert!(!round_div_requires(num_edge, 1));
    assert!(!round_div_requires(-num_edge, 1));
    assert!(round_div_requires(1, den_edge - 1));
    assert!(round_div_requires(1, -(den_edge - 1)));
    assert!(!round_div_requires(1, den_edge));
    assert!(!round_div_requires(1, -den_edge));
    assert!(!round_div_requires(1, 0));
    // x < 2^62 for the square roots.
    assert!(cycleref::engine::contracts::sqrt_requires((1 << 62) - 1));
    assert!(!cycleref::engine::contracts::sqrt_requires(1 << 62));
}

/// The same for the other predicates the second half of the contracts.rs
/// run left alive (110:5-31 `div_requires`, 119:42 `floor_div_ensures`,
/// 132:42 `ceil_div_ensures`,
/// 155:15/29/39 the sign check of `mul_tan_round_ensures`). Worked by hand:
/// `floor_div` and `ceil_div` need a positive divisor below 2^34 and a
/// dividend below 2^72 in magnitude; 6/2 = 3, so 2 is not `floor_div(6, 2)` (the
/// remainder 2 is not below 2); tan 45° = 1 (h = 90 half-degrees), so
/// `mul_tan_round(±100, 90)` is ±100 and never the other sign.
#[test]
fn the_other_contracts_refuse_a_wrong_answer_at_each_bound() {
    let _serial = serial();
    use cycleref::engine::contracts::{
        ceil_div_ensures, div_requires, floor_div_ensures, mul_tan_round_ensures,
    };
    // The ranges the callers use (issue 32): |a| < 2^72, 0 < b < 2^34.
    let edge = 1_i128 << 72;
    assert!(div_requires(1, 1));
    assert!(!div_requires(1, 0));
    assert!(!div_requires(1, -1));
    assert!(div_requires(edge - 1, 1));
    assert!(div_requires(-(edge - 1), 1));
    assert!(!div_requires(edge, 1));
    assert!(!div_requires(-edge, 1));
    assert!(div_requires(1, (1 << 34) - 1));
    assert!(!div_requires(1, 1 << 34));
    assert!(floor_div_ensures(6, 2, 3));
    assert!(!floor_div_ensures(6, 2, 2));
    assert!(floor_div_ensures(-7, 2, -4));
    assert!(!floor_div_ensures(-7, 2, -3));
    // ceil(6/2) = 3, so 4 is not `ceil_div(6, 2)` (4·2 − 6 = 2 is not below 2).
    assert!(ceil_div_ensures(6, 2, 3));
    assert!(!ceil_div_ensures(6, 2, 4));
    assert!(mul_tan_round_ensures(100, 90, Some(100)));
    assert!(mul_tan_round_ensures(-100, 90, Some(-100)));
    assert!(!mul_tan_round_ensures(-100, 90, Some(100)));
    assert!(!mul_tan_round_ensures(100, 90, Some(-100)));
    assert!(mul_tan_round_ensures(0, 90, Some(0)));
}

/// `engine/g75/roughing.rs` 77:15 (`lower += …` → `-=`, `*=`) and 77:30
/// (`(M − 2) * pecks` → `+`, `/`) in `check_peck_count`: the closed-form
/// lower bound of the peck count
/// refuses a groove before its layers are counted one by one, which is
/// what bounds that loop by `MAX_PECKS` (the outcome alone cannot show it:
/// the count layer by layer refuses the groove too, one layer later).
/// Worked by hand: a right-angle groove (L = 0, so y_top = 0) of depth
/// Y = 1 000 001 increments, Δv = 1, Δi = 1, no allowance and no tool
/// width has M = 1 000 001 layers of one plunge of one peck each; the
/// bound is 1 (layer 1) + (M − 2)·1 + 1 (the last) = 1 000 001 >
/// MAX_PECKS = 10^6: `TooManyPecks`, and the layer loop never runs. One
/// layer less, 10^6 pecks, is admitted, and the loop counts all 10^6
/// layers.
///
/// Also 77:66 (`(M − 1) * Δv` → `/`, the top of the last layer in the
/// bound): Y = 10^6 in two layers of Δv = 500 000 has 500 000 + 500 000 =
/// 10^6 pecks, admitted, and both layers are counted; the mutant's last
/// layer starts at (2 − 1)/500 000 = 0, so its bound is 500 000 + 10^6,
/// and the groove is refused.
#[test]
fn the_peck_count_refuses_too_many_layers_before_counting_them() {
    use cycleref::g75::MAX_PECKS;
    use cycleref::loop_counters::G75_LAYERS;
    use cycleref::CycleError;
    use cycleref_proofs::groove::{any_groove, GrooveDomain};
    use cycleref_proofs::shim::{check, Mode};
    let _serial = serial();
    // Layers of two pecks (Δv = 2, Δi = 1), Y = 1 000 002: M = 500 001,
    // and the bound 2 (layer 1) + (M − 2)·2 + 2 (the last) = 1 000 002 >
    // 10^6: refused before counting too (a bound that adds the middle
    // layers' count and their pecks, or divides them, is below the limit).
    // Each case: (depth Y, Δv), refused or not, the layers counted one by
    // one.
    let cases = [
        ("10^6 + 1 layers of 1 peck", (1_000_001, 1), false, 0),
        ("500 001 layers of 2 pecks", (1_000_002, 2), false, 0),
        ("10^6 layers of 1 peck", (1_000_000, 1), true, 1_000_000),
        ("2 layers of 500 000 pecks", (1_000_000, 500_000), true, 2),
    ];
    for (name, (depth, layer), admitted, counted) in cases {
        let domain = GrooveDomain::layers_only((depth, depth), (1, 1), (layer, layer));
        // The domain is one point: its run makes the cycle (the domain's
        // choices are made inside the shim) and expands it.
        let r = check(name, Mode::Exhaustive { max_runs: 1 }, || {
            let c = any_groove(&domain);
            loop_counters::reset();
            let expanded = cycleref::expand_g75(&c).err();
            let refused = Some(CycleError::TooManyPecks { limit: MAX_PECKS });
            assert_eq!(expanded, if admitted { None } else { refused }, "{name}");
            assert_eq!(G75_LAYERS.max(), counted, "{name}: the layers counted one by one");
        });
        assert_eq!(r.runs, 1);
    }
    loop_counters::reset();
}

/// `engine/g75/roughing.rs` 97:37 (`last − first` → `last + first`) and
/// 97:50 (`+ 1` → `* 1`) in `check_peck_count`: the plunges of a layer,
/// `ceil((A_mf − A_m1)/Δk) + 1`, times its pecks, are what is compared
/// with `MAX_PECKS`, so a count off by a few plunges shows only at the
/// limit (§9: more than 10^6 pecks refused, 10^6 admitted). One layer
/// (no V), so the closed-form lower bound is one plunge's pecks, far
/// below the limit, and the exact count decides. Worked by hand, for
/// right-angle grooves (a = b = 90°, L = 0: y_top = 0, `left(y) = Δw`,
/// `right(y) = d − Δw`, so A_11 = Δw and A_1f = d − Δw − w), Δi = Δk = 1,
/// no U, a pointed tool (w = 0), no retract:
///
/// * Y = 1000, d = 1001, W1: A_11 = 1, A_1f = 1000, 1000 plunges of
///   1000 pecks, exactly 10^6: admitted. With `last + first` the count
///   is (1001 + 1)·1000 = 1 002 000: refused (A_11 = 1 > 0 is needed to
///   see it; at A_11 = 0 the two agree).
/// * Y = 9901, d = 100, no W: A_11 = 0, A_1f = 100, 101 plunges of 9901
///   pecks, 1 000 001: refused. With `* 1` the count is 100·9901 =
///   990 100: admitted.
///
/// The reference's `rough_layers` (which counts the same product) agrees;
/// the engine only checks up front, the moves are not drawn.
#[test]
fn the_peck_count_is_exact_at_the_limit() {
    use cycleref::g75::MAX_PECKS;
    use cycleref::{CycleError, G75Cycle};
    use cycleref_spec::g75::{groove, peck_count, rough_layers, y_top};
    let _serial = serial();
    let cycle = |depth: i64, width: i64, allowance_z: i64| G75Cycle {
        peck: 1,
        step: 1,
        depth,
        width,
        allowance_z,
        ..square_groove()
    };
    let refused = CycleError::TooManyPecks { limit: MAX_PECKS };
    // 1000 plunges from A_11 = 1 to A_1f = 1000, of 1000 pecks each.
    let c = cycle(1_000, 1_001, 1);
    let g = groove(&c);
    assert_eq!(y_top(&g), Ok(0));
    let layers = rough_layers(&g, 0).expect("the reference admits 10^6 pecks");
    assert_eq!(layers.len(), 1);
    let (first, last) = (layers[0].range.first, layers[0].range.last);
    assert_eq!((first, last), (1, 1_000));
    assert_eq!(layers[0].range.count(1) * peck_count(0, layers[0].bottom, 1), i128::from(MAX_PECKS));
    assert_eq!(cycleref::expand_g75(&c).map(|_| ()), Ok(()), "exactly 10^6 pecks");
    // 101 plunges from A_11 = 0 to A_1f = 100, of 9901 pecks each.
    let c = cycle(9_901, 100, 0);
    let g = groove(&c);
    assert_eq!(rough_layers(&g, 0).map(|_| ()), Err(refused));
    let range = cycleref_spec::g75::plunge_range(&g, 1).expect("a right-angle groove");
    assert_eq!((range.first, range.last, range.count(1)), (0, 100, 101));
    assert_eq!(cycleref::expand_g75(&c).map(|_| ()), Err(refused), "10^6 + 1 pecks");
}

/// `engine/real.rs` 66:26 (`SCRATCH = 2 * MAX_LIMBS` → `2 + MAX_LIMBS`,
/// found by a sampled run): the scratch buffers then hold a product of
/// two 8-limb numbers at most, so every product and quotient of the
/// 512-bit (`SLOW`, 10-limb) precision fails and comes back poisoned. The
/// G75.1 engine needs that precision only where the 128-bit one leaves a
/// floor or a ceiling open, which no harness window reaches: their
/// grooves are right-angled or drawn at random angles, whose values are
/// never integers made of irrational factors. The slope example
/// (`cycleref::examples::G75_SLOPE`, examples/gsk980-g75-slope.nc) is
/// made of them (R-G75TIE): with A = 60° and a round r3 the depth of K1
/// is `9000 − 300 − 2·400·tan 30°·sin 60° − 300·cos 60° = 8150` exactly,
/// and the second layer's right boundary `4500·cot 60° + 6000 + 1500·
/// cot 75° − 100 = 8900`. Its rough contour, worked out from the formulas
/// (mpmath, 80 digits; `impl/src/engine/g75/tests.rs`,
/// `slope_example_expands`): R0 (X83.629 Z0.947), K1 (X71.850 Z−2.453),
/// K2 (X71.300 Z−2.930), K3 (X71.300 Z−5.691), K4 (X71.971 Z−6.128), R3
/// (X83.629 Z−7.690), the tool's far side 2.500 short of the contour's;
/// then the rapid back to A_11 (X83.629 Z−0.967: ceil(left(3000)) =
/// ceil(966.025…)). The moves are the reference's.
#[test]
fn the_slope_example_decides_its_ties() {
    use cycleref::{Motion, Point, Role};
    let _serial = serial();
    let c = cycleref::examples::G75_SLOPE;
    let moves = g75_reference_moves(&c);
    assert_eq!(
        with_role(&moves, Role::RoughContour),
        [
            (Motion::Rapid, Point::new(83_629, 947)),
            (Motion::Feed, Point::new(71_850, -2_453)),
            (Motion::Feed, Point::new(71_300, -2_930)),
            (Motion::Feed, Point::new(71_300, -5_691)),
            (Motion::Feed, Point::new(71_971, -6_128)),
            (Motion::Feed, Point::new(83_629, -7_690)),
            (Motion::Rapid, Point::new(83_629, -967)),
        ]
    );
}

/// `engine/real.rs` 273:10 (`m < n` → `m <= n` in `limbs_divmod`, found
/// by a sampled run): a dividend of as many significant limbs as the
/// divisor was taken as smaller than it, quotient 0. `Fixed::div_round`
/// shifts the dividend up by the fraction limbs (two at the 128-bit
/// precision), so that happens for a dividend below 2^-64 and a divisor
/// of at least 1, where the quotient is a few ulps: 9 ulps / 3 is 3 ulps
/// exactly, and (2^64 − 1) ulps / 5 is 3 689 348 814 741 910 323 ulps
/// exactly (2^64 − 1 = 5 · 3 689 348 814 741 910 323); the mutant makes
/// both `[0, 1 ulp]`, which does not hold the quotient. No move of the
/// harness windows changed with it; the kernel must still divide every
/// input it is given, and the enclosures built on it rely on that.
#[test]
fn a_dividend_as_long_as_its_divisor_is_divided() {
    use cycleref::engine::real::{Fixed, Interval, FAST};
    let ulps = |u: u64| Interval::<FAST>::point(Fixed::from_ulps(u));
    assert_eq!(ulps(9).div(&Interval::int(3)), ulps(3));
    assert_eq!(ulps(u64::MAX).div(&Interval::int(5)), ulps(3_689_348_814_741_910_323));
    // A dividend shorter than the divisor (`engine/real.rs` 378:5,
    // `limbs_copy` → `()`, from the second sample: the remainder is then
    // left 0 and the quotient taken as exact): 1 ulp / 2^64 is below one
    // ulp but not 0, so its enclosure is [0, 1 ulp], not the point 0.
    let tiny = ulps(1).div(&Interval::int(1 << 64));
    assert_eq!(tiny, Interval::new(Fixed::zero(), Fixed::from_ulps(1)));
}

/// `engine/real.rs` 309:29 (`r̂ = top % v_top` → `top / v_top` in
/// `limbs_divmod`, found by the second sample): Knuth's step D3 corrects
/// the estimated quotient digit q̂ with the remainder r̂; without it q̂
/// can stay two too large, and step D6 adds back only once. At the 128-bit
/// precision, `Interval::div` divides A·2^128 by B; with A =
/// 0x7fffffffffffffff_4000000000000000 + 0x4000000000000001 ulps and B =
/// 0x4000000000000001_ffffffffffffffff (the limbs found by a throwaway
/// search over a restatement of the algorithm in Python) the exact
/// quotient, floor(A·2^128 / B) computed with Python's integers, is
/// 680 564 733 841 876 926 576 261 077 463 054 942 367 ulps, limbs
/// (least significant first) 0x9f, 0xffffffffffffffed, 1, 0, with a
/// remainder: the enclosure is that and one ulp more.
#[test]
fn a_quotient_digit_estimated_two_too_large_is_corrected() {
    use cycleref::engine::real::{Fixed, Interval, FAST};
    let a = Fixed::<FAST>::from_int(0x7fff_ffff_ffff_ffff_4000_0000_0000_0000)
        .checked_add(&Fixed::from_ulps(0x4000_0000_0000_0001))
        .expect("below 2^127");
    let b = Fixed::<FAST>::from_int(0x4000_0000_0000_0001_ffff_ffff_ffff_ffff);
    let q = Interval::point(a).div(&Interval::point(b));
    assert_eq!(q.lower().limbs(), &[0x9f, 0xffff_ffff_ffff_ffed, 1, 0]);
    assert_eq!(q.upper().limbs(), &[0xa0, 0xffff_ffff_ffff_ffed, 1, 0]);
}

/// `engine/real.rs` 834:25 (`nonneg(self) && nonneg(o)` → `||` in
/// `Interval::mul`, from the second sample): only a product of two
/// non-negative intervals is [lo·lo, hi·hi]; with one negative factor the
/// ends come from other pairs. By hand: [1, 2]·[−3, −1] = [−6, −1] (the
/// mutant gives [−3, −2], which holds neither 2·(−3) nor 1·(−1)), and
/// [−3, −1]·[1, 2] the same; [−1, 2]·[3, 4] = [−4, 8].
#[test]
fn interval_products_take_the_ends_of_every_sign() {
    assert_eq!(iv(1, 2).mul(&iv(-3, -1)), iv(-6, -1));
    assert_eq!(iv(-3, -1).mul(&iv(1, 2)), iv(-6, -1));
    assert_eq!(iv(-1, 2).mul(&iv(3, 4)), iv(-4, 8));
}

/// `engine/real.rs` 1409:28 (`lo < hi` → `lo > hi` in `integer_root`) and
/// 1467:15 (`n == 1 || a == b` → `&&` in `power`), found by a sampled
/// run: `power(n, a, b)` = n^(a/b) is an exact point when it is an
/// integer (LinuxCNC's depth law J·n^(1/R), R-LCNC-EXACT: an exact depth
/// is what `lcnc_termination` compares with K). With the first mutant no
/// root is ever found, with the second a ratio that reduces to 1 is an
/// exact root only below 2^32; both leave the series' enclosure, a narrow
/// interval but not a point. By hand: 8^(2/3) = 2² = 4, 9^(1/2) = 3,
/// 1024^(3/10) = 2³ = 8, 2^62^(1/2) = 2^31, and (2^40)^(3/3) = 2^40.
#[test]
fn powers_that_are_integers_are_exact() {
    use cycleref::engine::real::{power, Interval, FAST};
    let cases =
        [(8, 2, 3, 4), (9, 1, 2, 3), (1024, 3, 10, 8), (1 << 62, 1, 2, 1 << 31), (1 << 40, 3, 3, 1 << 40)];
    for (n, a, b, exact) in cases {
        assert_eq!(power::<FAST>(n, a, b), Interval::int(exact), "{n}^({a}/{b})");
    }
}

/// `engine/g75/roughing.rs` 89:34 (`m == 1` → `m != 1`) and 91:21
/// (`m == count` → `m != count`) in `check_peck_count`: each layer's
/// plunges are counted over its own range, A_m1 to A_mf; the first and
/// the last layer's ranges are known before the count, the others are
/// worked out. The mutants count layers 2..M with layer 1's range, or
/// the middle layers with the last layer's. On a right-angle groove every
/// layer has the same range, so they agree; here flank A leans. Worked by
/// hand (§9, R-G75REGION), radius mode (f = 1), flank A 45° (cot = 1),
/// flank B 90°, Y = 300 in layers of Δv = 100 (M = 3, bottoms 100, 200,
/// 300, y_top = 0), Δi = Δk = 1, a 0.001 tool (w = 1), no allowances:
/// flank A is at u = y, the bottom runs from P1 at u = 300 to P2 at
/// u = 300 + D, flank B stands at P2, so layer m's plunges run from A_m1 =
/// 100·m to A_mf = 300 + D − 1: D + 300 − 100·m plunges of 100 pecks. In
/// all, 100·(3D + 300) pecks:
///
/// * D = 3.233: 999 900, admitted. 89:34 counts layers 2 and 3 with layer
///   1's D + 200 plunges: 30 000 more, 1 029 900, refused.
/// * D = 3.234: 1 000 200, refused. 91:21 counts layer 2 with layer 3's
///   D plunges: 10 000 fewer, 990 200, admitted.
///
/// The ranges are checked against the reference's `plunge_range`, the
/// outcomes against its `rough_layers` and the engine's `expand_g75`.
#[test]
fn each_layer_is_counted_over_its_own_plunges() {
    use cycleref::g75::MAX_PECKS;
    use cycleref::{CycleError, G75Cycle, Point, XMode};
    use cycleref_spec::g75::{groove, plunge_range, rough_layers, y_top};
    let _serial = serial();
    let cycle = |width: i64| G75Cycle {
        x_mode: XMode::Radius,
        from: Point::new(120_000, -5_000),
        peck: 1,
        step: 1,
        depth: -300,
        width,
        flank_a: 450_000,
        layer: Some(100),
        tool_width: Some(1),
        ..square_groove()
    };
    let refused = CycleError::TooManyPecks { limit: MAX_PECKS };
    for (width, outcome) in [(3_233, Ok(())), (3_234, Err(refused))] {
        let c = cycle(width);
        let g = groove(&c);
        assert_eq!(y_top(&g), Ok(0), "D {width}");
        for m in 1..=3_i128 {
            let range = plunge_range(&g, m).expect("a layer of the groove");
            let (first, last) = (100 * m, 300 + i128::from(width) - 1);
            assert_eq!(
                (range.first, range.last, range.count(1)),
                (first, last, last - first + 1),
                "D {width}"
            );
        }
        assert_eq!(rough_layers(&g, 0).map(|_| ()), outcome, "D {width}: the reference");
        assert_eq!(cycleref::expand_g75(&c).map(|_| ()), outcome, "D {width}: the engine");
    }
}

/// `engine/g75/roughing.rs` 190:33 (`y_lim − top` → `y_lim / top` in
/// `check_roughing`, closure `peck_beyond`; applied by hand, the mutation
/// run had not reached that line yet): the first peck end beyond the
/// range tables (R-G75RANGE: the first coordinate beyond ±999 999 999 in
/// move order) is `top + j·Δi` with `j = floor((y_lim − top)/Δi) + 1`,
/// clamped at the layer's bottom. Worked by hand: a right-angle groove
/// (y_top = 0), S = (X999 999 974, Z0) in IS-B increments, Y = +40 (so
/// X = 999 999 974 + y, and y_lim = 999 999 999 − 999 999 974 = 25),
/// Δi = 4, d = 10 with a tool as wide (one plunge position, u = 0), no
/// allowances, no retract, J0. The approach to A11 = (0, 0) is in range.
///
/// * No V, one layer from 0 to 40: pecks to 4, 8, …, 24 (X 999 999 998),
///   then 28: X = 1 000 000 002, the first beyond, j = floor(25/4) + 1 =
///   7. The mutant divides 25 by the top 0 and panics.
/// * V10: layers to 10, 20, 30, 40 (M = 4); layers 1 and 2 stay within
///   25; layer 3 pecks from 20 to 24 (X 999 999 998), then 28: X =
///   1 000 000 002 again, j = floor((25 − 20)/4) + 1 = 2. The mutant
///   takes j = floor((25/20)/4) + 1 = 1, the peck to 24, in range, and
///   lets the roughing through (applied by hand: a later move, at the
///   depth 40, is then reported, X 1 000 000 014).
///
/// * V10, Δi = 3 (`roughing.rs` 203:27 `(m − 1) * Δv` → `+`, `/`, 203:22
///   `m − 1` → `m + 1`, and 186:20 `Δv > 0` → `<`, which all report a peck
///   of the wrong layer top and agreed with Δi = 4 only because every top
///   they took is a multiple of 4): layer 3 pecks from 20 to 23, then 26:
///   X = 1 000 000 000, j = floor(5/3) + 1 = 2. The mutants' tops 12, 0
///   and 40 give 27, 27 and 28; with 186:20 the one-layer check peck from
///   0, 27.
/// * V10, Δi = 4, S at X999 999 989 (`roughing.rs` 193:11 `y1 > y_lim` →
///   `>=`): y_lim = 10 = the first layer's bottom, so layer 1 is in range
///   (its last peck ends on the limit, X 999 999 999) and layer 2's first
///   peck, 10 + 4 = 14, is the first beyond: X = 1 000 000 003. The
///   mutant takes layer 1 as beyond, finds its peck clamped at 10 in
///   range, and returns with nothing reported.
/// * V10, Δi = 4, S at Z999 999.999 (`roughing.rs` 196:12 `A_1f > u_lim`
///   → `>=`): the one plunge position, u = 0, is at the Z limit (u_lim =
///   999 999 999 − S.z = 0 = A_1f), so every Z is in range, and the peck
///   to 28 in layer 3 is again the first beyond, X = 1 000 000 002. The
///   mutant takes A_1f as beyond, finds its Z in range, and returns with
///   nothing reported.
///
/// The reference (`cycleref_spec::g75::expand`, which makes the moves
/// and checks them in order) reports the same.
#[test]
fn the_first_peck_beyond_the_range_is_reported() {
    use cycleref::{G75Cycle, Point};
    let _serial = serial();
    let cycle = |(x, z): (i64, i64), peck: i64, layer: Option<i64>| G75Cycle {
        from: Point::new(999_990_000, 5_000),
        start: Point::new(x, z),
        peck,
        step: 1,
        depth: 40,
        width: 10,
        layer,
        tool_width: Some(10),
        ..square_groove()
    };
    let cases = [
        ("one layer", (999_999_974, 0), 4, None, 1_000_000_002),
        ("layer 3 of 4", (999_999_974, 0), 4, Some(10), 1_000_000_002),
        ("layer 3 of 4, Δi = 3", (999_999_974, 0), 3, Some(10), 1_000_000_000),
        ("layer 2 of 4, layer 1 to the limit", (999_999_989, 0), 4, Some(10), 1_000_000_003),
        ("layer 3 of 4, S at the Z limit", (999_999_974, 999_999_999), 4, Some(10), 1_000_000_002),
    ];
    for (name, s, peck, layer, beyond) in cases {
        let beyond = beyond_the_range(beyond);
        g75_refused_by_both(&cycle(s, peck, layer), beyond, name);
    }
}

/// `engine/g75/roughing.rs` 182:21 (`u_lim = MAX − sz·S.z` →
/// `MAX / sz * S.z` in `check_roughing`): `u_lim` is the furthest u whose
/// Z = S.z + sz·u is within ±999 999 999, and a layer-1 plunge beyond it is
/// refused at the first step there (R-G75RANGE). The mutant's bound is
/// `sz·MAX·S.z`: 0 when S is at Z0 (the harness domains' S), hugely
/// negative when S lies behind Z0 along sz, hugely positive beyond it.
/// Worked by hand, a right-angle groove (y_top = 0) at S = (X100.000,
/// Z s) in IS-B increments, H−2.000 (X = 100 000 − y), D3.000 (sz = +1,
/// Z = s + u), Δi = 1000, Δk = 1000, a 1.000 tool, no allowances, no
/// retract, J0: A_11 = 0, A_1f = 3000 − 1000 = 2000, plunges at u = 0,
/// 1000, 2000, each of two pecks (to X99.000, X98.000).
///
/// * s = −1000 (Z−1.000): every Z is within range (−1000 … 1000), the
///   cycle is valid, its moves the reference's (the approach to A11 =
///   (X100.000, Z−1.000), pecks to X99.000 and X98.000, the retract to
///   X100.000, the step to Z0). The mutant's bound is −999 999 999 000,
///   below A_1f, and it refuses the cycle at the Z of its own first "step
///   beyond", u = (floor(−999 999 999 000/1000) + 1)·1000 =
///   −999 999 998 000.
/// * s = 999 999 499: u_lim = 500, so the step to the second plunge, u =
///   (floor(500/1000) + 1)·1000 = 1000, is the first coordinate beyond,
///   Z = 1 000 000 499. The mutant's bound, 999 999 999·999 999 499, is
///   beyond every plunge, so it does not report that step (applied by
///   hand: a later move, at u = 2000, is reported, Z 1 000 001 499).
#[test]
fn a_step_beyond_the_z_range_is_reported_wherever_s_is() {
    use cycleref::{G75Cycle, Point};
    let _serial = serial();
    let cycle = |z: i64| G75Cycle {
        from: Point::new(110_000, z),
        start: Point::new(100_000, z),
        tool_width: Some(1_000),
        ..square_groove()
    };
    assert_first_plunge(&cycle(-1_000), -1_000, 0);
    let c = cycle(999_999_499);
    let beyond = beyond_the_range(1_000_000_499);
    g75_refused_by_both(&c, beyond, "S beyond");
}

/// `engine/g75/roughing.rs` 197:40 (`floor_div(u_lim − a11, Δk)` →
/// `u_lim + a11` in `check_roughing`): the first step beyond the Z range
/// counts its steps from A_11, the first plunge of layer 1, which is at u =
/// 0 only when nothing keeps the tool off flank A. Here the finishing
/// allowance Δw = 0.500 does (R-G75REGION: left(y) = y·cot A + Δw, cot 90°
/// = 0). Worked by hand, a right-angle groove at S = (X100.000, Z s), IS-B,
/// H−2.000, D5.000 (sz = +1, Z = s + u), Δi = Δk = 1000, a 1.000 tool, Δw
/// = 500, Δu = 0: A_11 = 500, A_1f = 5000 − 1000 − 500 = 3500, plunges at
/// u = 500, 1500, 2500, 3500, each of two pecks (to X99.000, X98.000).
///
/// * s = −3000: every Z is within range (−2500 … 500); the first moves are
///   the approach to A_11 = (X100.000, Z−2.500), the pecks, the retract
///   and the step to u = 1500, Z−1.500.
/// * s = 999 999 399: u_lim = 999 999 999 − s = 600, A_11's Z (999 999
///   899) is in range, the step to u = 500 + (floor((600 − 500)/1000) +
///   1)·1000 = 1500 is the first coordinate beyond: Z = 1 000 000 899. The
///   mutant counts from u_lim + A_11 = 1100: u = 500 + 2·1000 = 2500, Z =
///   1 000 001 899.
#[test]
fn a_step_beyond_the_z_range_is_counted_from_the_first_plunge() {
    use cycleref::{G75Cycle, Point};
    let _serial = serial();
    let cycle = |z: i64| G75Cycle {
        from: Point::new(110_000, z),
        start: Point::new(100_000, z),
        width: 5_000,
        allowance_z: 500,
        tool_width: Some(1_000),
        ..square_groove()
    };
    assert_first_plunge(&cycle(-3_000), -2_500, -1_500);
    let c = cycle(999_999_399);
    let beyond = beyond_the_range(1_000_000_899);
    g75_refused_by_both(&c, beyond, "S beyond");
}

/// `engine/g75/contour.rs` 155:27 (`size(R3) > 0` → `>=` in
/// `rough_vertices`): an angled groove whose bottom corner r3 has size 0
/// (flank A 30°, flank B 18.67385°) roughs its contour along flank A to
/// the bottom in one feed; the mutant puts the corner's K1 and K2 in,
/// which round elsewhere than flank A's bottom point. The harness tests'
/// windows are right-angle grooves, where they coincide. The moves are
/// the exact reference's (`cycleref_spec::g75::expand`): 19 of them, the
/// ninth the rough contour's feed to X4.9897 Z0.1030 (IS-C inch).
#[test]
fn a_zero_bottom_corner_of_an_angled_groove_roughs_along_its_flank() {
    use cycleref::{Motion, Point, Role};
    let _serial = serial();
    let reference = g75_reference_moves(&angled_groove_with_a_zero_bottom_corner(false));
    assert_eq!(reference.len(), 19);
    assert_eq!(reference[8].to, Point::new(49_897, 1030));
    assert_eq!((reference[8].motion, reference[8].role), (Motion::Feed, Role::RoughContour));
}

/// The mirror of the test above, for flank B (`engine/g75/contour.rs`
/// 164:27, `size(R4) > 0` → `>=` in `rough_vertices`, left by the G75.1
/// run): a zero r4 on an angled flank B. With the mutant the rough contour
/// takes K3 and K4 of a zero corner (rounded elsewhere than flank B's
/// bottom point): applied by hand, the engine feeds to X4.9897 Z0.1118 and
/// X4.9900 Z0.1121 where the reference feeds to X4.9897 Z0.1120 and then
/// up flank B to X5.0000 Z0.1149, one move more in all (21 against 20).
/// The expected moves are the reference's.
#[test]
fn a_zero_bottom_corner_on_flank_b_roughs_along_it() {
    use cycleref::{Motion, Point, Role};
    let _serial = serial();
    let reference = g75_reference_moves(&angled_groove_with_a_zero_bottom_corner(true));
    assert_eq!(reference.len(), 20);
    // The rough contour along the bottom to flank B's bottom point (K3 − w)
    // and up flank B to R3 − w.
    assert_eq!(
        with_role(&reference, Role::RoughContour),
        [
            (Motion::Rapid, Point::new(50_000, 1_000)),
            (Motion::Feed, Point::new(49_902, 1_065)),
            (Motion::Feed, Point::new(49_897, 1_072)),
            (Motion::Feed, Point::new(49_897, 1_120)),
            (Motion::Feed, Point::new(50_000, 1_149)),
            (Motion::Rapid, Point::new(50_000, 1_072)),
        ]
    );
}

/// `engine/g75/profile.rs` 113:24 (`out.finish_len += 1` → `*= 1` in
/// `groove_profile`, left by the G75.1 run: nothing looked at the
/// finishing profile, only at the roughing vertices). The finishing
/// profile of the flank-B cycle above is the path of the reference's
/// finishing contour, with the points on flank B's side moved back by the
/// tool width (w = 54: the moves are the tool's, whose reference edge is
/// on flank A's side): S, the feed to X4.9892 Z0.1070, the arc (centre
/// X4.9894 Z0.1071, counter-clockwise) to X4.9892 Z0.1071, then
/// Z0.1119 + 54 and X5.0000 Z0.1150 + 54. The mutant's profile is empty.
#[test]
fn the_finishing_profile_is_the_finish_contour_with_the_tool_width() {
    use cycleref::{Motion, Point, ProfileSegment, Role};
    let _serial = serial();
    let c = angled_groove_with_a_zero_bottom_corner(true);
    let w = c.tool_width.expect("the cycle has a tool width");
    let contour = with_role(&g75_reference_moves(&c), Role::FinishContour);
    let arc = Motion::Arc { centre: Point::new(49_894, 1_071), clockwise: false };
    assert_eq!(
        contour,
        [
            (Motion::Rapid, Point::new(50_000, 1_000)),
            (Motion::Feed, Point::new(49_892, 1_070)),
            (arc, Point::new(49_892, 1_071)),
            (Motion::Feed, Point::new(49_892, 1_119)),
            (Motion::Feed, Point::new(50_000, 1_150)),
        ]
    );
    let profile = cycleref::groove_profile(&c).expect("the engine has the profile");
    let finishing: Vec<_> = profile.finishing().iter().map(|p| (p.segment, p.at)).collect();
    assert_eq!(
        finishing,
        [
            (ProfileSegment::Start, Point::new(50_000, 1_000)),
            (ProfileSegment::Line, Point::new(49_892, 1_070)),
            (
                ProfileSegment::Arc { centre: Point::new(49_894, 1_071), clockwise: false },
                Point::new(49_892, 1_071)
            ),
            (ProfileSegment::Line, Point::new(49_892, 1_119 + w)),
            (ProfileSegment::Line, Point::new(50_000, 1_150 + w)),
        ]
    );
}

/// The cycle of the two tests above: IS-C inch, flanks 30° and 18.67385°,
/// a zero bottom corner (a round of size 0) beside a round of 1; on flank
/// A (r3 = 0, A = 30°) or, `on_flank_b`, mirrored: the flanks and the
/// bottom corners exchanged (r4 = 0, B = 30°).
fn angled_groove_with_a_zero_bottom_corner(on_flank_b: bool) -> cycleref::G75Cycle {
    use cycleref::{Corner, CornerKind, G75Cycle, IncrementSystem, InputUnit, PathType, Point, Units, XMode};
    let chamfer = Corner { size: 0, kind: CornerKind::Chamfer };
    let (zero, one) =
        (Corner { size: 0, kind: CornerKind::Round }, Corner { size: 1, kind: CornerKind::Round });
    let (steep, shallow) = (600_000, 373_477);
    let (flank_a, flank_b, r3, r4) =
        if on_flank_b { (shallow, steep, one, zero) } else { (steep, shallow, zero, one) };
    G75Cycle {
        units: Units { system: IncrementSystem::IsC, unit: InputUnit::Inch },
        x_mode: XMode::Diameter,
        from: Point::new(52_000, 500),
        start: Point::new(50_000, 1000),
        peck: 108,
        step: 62,
        depth: -108,
        width: 102,
        flank_a,
        flank_b,
        slope: 0,
        retract: 1112,
        layer: Some(160),
        allowance_x: 5,
        allowance_z: 0,
        tool_width: Some(54),
        path: PathType::RoughAndFinish,
        corners: [chamfer, chamfer, r3, r4],
        readings: cycleref::G75Readings::DEFAULT,
    }
}

/// `engine/g75/contour.rs` 167:17 (`y_k4 > y_top` → `>=` in
/// `rough_vertices`) and its mirror 157:17 (`y_k1 > y_top` → `>=`): a
/// groove whose bottom chamfers' chords meet the flanks between the layer
/// top and the next integer depth. The moves are the same either way (K4
/// is then R3, K1 is R0: the mutants' extra feed would not move and is left
/// out, R-G75ZERO), but `groove_profile` lists the roughing region's
/// vertices, and the mutants list R3 (R0) twice. Worked by hand (and the
/// reference `cycleref_spec::g75::profile` agrees): A60 B60, Y = 6001
/// (diameter, f = 2), U400 W200, d = 8000, chamfers r3 = r4 = 3118, no
/// slope, so y_top = 0 and y_K1 = y_K4 = floor(6001 − 400 − 2·3118·sin 60°
/// − 400·cos 60°) = floor(5401 − 3118·√3) = floor(0.4656…) = 0, not below
/// y_top: neither K1 nor K4 is a vertex. P1.u = 3000.5·cot 60° =
/// 1732.3395…; R0 = (ceil(max(flankA_r(0), chord3_r(0))), 0) =
/// (ceil(max(200, 199.7312…)), 0) = (200, 0); K2 =
/// (ceil(1732.3395… + 3118 + 200), 5601) = (5051, 5601); K3 =
/// (floor(1732.3395… + 8000 − 3318), 5601) = (6414, 5601); R3 =
/// (floor(min(flankB_r(0), chord4_r(0))), 0) =
/// (floor(min(11264.6790…, 11264.9478…)), 0) = (11264, 0), which is
/// K4 = (floor(flankB_r(0)), 0). Absolute, without the tool width:
/// X = 30000 − y, Z = −u.
#[test]
fn chords_meeting_the_flanks_at_the_layer_top_add_no_vertex() {
    use cycleref::{
        Corner, CornerKind, G75Cycle, IncrementSystem, InputUnit, Motion, PathType, Point, Role, Units, XMode,
    };
    let _serial = serial();
    let chamfer = Corner { size: 3118, kind: CornerKind::Chamfer };
    let c = G75Cycle {
        units: Units { system: IncrementSystem::IsB, unit: InputUnit::Metric },
        x_mode: XMode::Diameter,
        from: Point::new(40_000, 5_000),
        start: Point::new(30_000, 0),
        peck: 2_000,
        step: 1_000,
        depth: -6_001,
        width: -8_000,
        flank_a: 600_000,
        flank_b: 600_000,
        slope: 0,
        retract: 500,
        layer: None,
        allowance_x: 400,
        allowance_z: 200,
        tool_width: Some(1_000),
        path: PathType::RoughAndFinish,
        corners: [Corner::SHARP, Corner::SHARP, chamfer, chamfer],
        readings: cycleref::G75Readings::DEFAULT,
    };
    let by_hand = [
        Point::new(30_000, -200),
        Point::new(24_399, -5_051),
        Point::new(24_399, -6_414),
        Point::new(30_000, -11_264),
    ];
    // The reference's vertices, in the same frame.
    let reference = cycleref_spec::g75::profile(&c).expect("the reference has the profile");
    assert_eq!(reference.y_top, 0);
    let g = cycleref_spec::g75::groove(&c);
    assert_eq!((cycleref_spec::g75::y_k1(&g), cycleref_spec::g75::y_k4(&g)), (Ok(0), Ok(0)));
    let at = |u: i128, y: i128| Point::new(30_000 - i64::try_from(y).unwrap(), -i64::try_from(u).unwrap());
    let vertices: Vec<Point> = reference.rough.iter().map(|v| at(v.at.u, v.at.y)).collect();
    assert_eq!(vertices, by_hand);
    let profile = cycleref::groove_profile(&c).expect("the engine has the profile");
    assert_eq!(profile.roughing(), by_hand);
    // The moves are the reference's.
    let reference = g75_reference_moves(&c);
    assert_eq!(reference.len(), 28);
    // The rough contour: rapid to R0, feeds to K2, K3 − w, R3 − w (w =
    // 1000), rapid back to A11 = (5051, 0); no feed that would not move.
    assert_eq!(
        with_role(&reference, Role::RoughContour),
        [
            (Motion::Rapid, Point::new(30_000, -200)),
            (Motion::Feed, Point::new(24_399, -5_051)),
            (Motion::Feed, Point::new(24_399, -5_414)),
            (Motion::Feed, Point::new(30_000, -10_264)),
            (Motion::Rapid, Point::new(30_000, -5_051)),
        ]
    );
}

/// R-G32LONG: a G32 move whose X displacement as a radius equals its Z
/// displacement has X as its long axis (seed 002, "反之，X 轴为长轴"), so its
/// run-out starts K before the end along X and ends J along Z.
///
/// By hand, diameter X, IS-B metric: from X20.000 Z0 to X40.000 Z-10.000,
/// ΔX = 20.000 (10.000 as a radius) and ΔZ = -10.000. With K 3.000 the
/// run-out starts at X 40.000 − 2·3.000 = 34.000, on the line at Z 0 +
/// (−10.000)·(34.000 − 20.000)/20.000 = −7.000, and ends at Z −10.000 +
/// J 2.000 = −8.000, X 40.000. Taking Z as the long axis at the tie (the
/// `>` → `>=` mutant of `long_axis`) would end it at X 40.000 + 2·2.000,
/// Z −10.000.
#[test]
fn a_g32_move_at_45_degrees_has_x_as_its_long_axis() {
    let _serial = serial();
    use cycleref::lead::{Lead, LeadWord};
    use cycleref::{G32Block, G32RunOut, Motion, Point, Role, StartAngle, Units, XMode};
    use cycleref_spec::g76::LongAxis;

    let block = G32Block {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start: Point::new(20_000, 0),
        end: Point::new(40_000, -10_000),
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: G32RunOut::Amounts { short: 2_000, long: 3_000 },
        start_angle: StartAngle::ZERO,
        sync: true,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    assert_eq!(cycleref_spec::g32::long_axis(&block), LongAxis::X);
    let reference = cycleref_spec::g32::expand(&block).expect("the reference expands it");
    let engine: Vec<_> = cycleref::expand_g32(&block).expect("the engine expands it").collect();
    assert_eq!(engine, reference);
    let path: Vec<_> = reference.iter().map(|m| (m.to, m.role)).collect();
    assert_eq!(path, [(Point::new(34_000, -7_000), Role::Cut), (Point::new(40_000, -8_000), Role::RunOut)]);
    assert!(reference.iter().all(|m| matches!(m.motion, Motion::Thread { .. })));
}

/// `engine/real.rs` 196:23 (`k = i + b.len()` → `i * b.len()` in
/// `limbs_mul`): the carry out of row `i` of a schoolbook product belongs
/// in limb `i + len(b)`, just above the row. A row carries only when the
/// other factor's top limb is not 0, an integer part of 2^64 or more, so
/// no harness value reaches it. By hand, at the 128-bit precision (limbs
/// least significant first, two of fraction): 0.5 is [0, 2^63, 0, 0] and
/// 3·2^64 is [0, 0, 0, 3]; row 1 gives 2^63·3 = 2^64 + 2^63, so limb 4 is
/// 2^63 and the carry 1 goes to limb 5: the product is 3·2^63, exactly.
/// The mutant adds the carry to limb 4 and gives 2^63 + 1.
#[test]
fn a_product_carries_into_the_limb_above_its_row() {
    use cycleref::engine::real::{Interval, FAST};
    let half = Interval::<FAST>::int(1).div(&Interval::int(2));
    assert_eq!(half.mul(&Interval::int(3 << 64)), Interval::int(3 << 63));
    assert_eq!(Interval::<FAST>::int(3 << 64).mul(&half), Interval::int(3 << 63));
}

/// `engine/real.rs` 458:39 (`64 * (N − 2)` → `64 + (N − 2)` in
/// `Fixed::FRACTION_BITS`): the public count of fraction bits, which no
/// engine path reads. By the module's documentation, P = 64·(N − 2): 128
/// bits at the fast precision (4 limbs), 512 at the slow one (10 limbs);
/// and one ulp is 2^−P, so 2^P ulps make 1.
#[test]
fn the_fraction_bits_are_64_per_fraction_limb() {
    use cycleref::engine::real::{Fixed, Interval, FAST, SLOW};
    assert_eq!(Fixed::<FAST>::FRACTION_BITS, 128);
    assert_eq!(Fixed::<SLOW>::FRACTION_BITS, 512);
    // 2^63 ulps doubled FRACTION_BITS − 63 times is 2^P ulps (saturating,
    // so that a wrong count fails here rather than at compile time).
    let mut x = Interval::<FAST>::point(Fixed::from_ulps(1 << 63));
    for _ in 0..Fixed::<FAST>::FRACTION_BITS.saturating_sub(63) {
        x = x.mul_int(2);
    }
    assert_eq!(x, Interval::int(1));
}

/// `engine/real.rs` 648:35 and 650:35 (`2 * N - 2` → `2 * N + 2` in
/// `Fixed::div_round`, the dividend's and the quotient's lengths): the
/// scratch buffers hold `2 · MAX_LIMBS` limbs, so the longer slices exist
/// up to 13 limbs and the mutants change nothing there; at `MAX_LIMBS` =
/// 14 limbs, the most the type admits, they do not, and every quotient
/// would be poisoned. So each precision from the least (3 limbs) to the
/// most divides, by hand: 7 / 2 = 3.5 exactly; 1 / 3 lies between
/// floor(2^P / 3) and one ulp more, and 2^P / 3 = 0.0101…b, so every
/// fraction limb of the lower end is 0x5555555555555555 and the upper
/// end's lowest limb is 0x5555555555555556.
#[test]
fn every_precision_divides() {
    use cycleref::engine::real::{Interval, FAST, MAX_LIMBS, SLOW};
    fn check<const N: usize>() {
        let three_and_a_half = Interval::<N>::int(3).add(&Interval::half());
        assert_eq!(Interval::<N>::int(7).div(&Interval::int(2)), three_and_a_half, "{N} limbs");
        let third = Interval::<N>::int(1).div(&Interval::int(3));
        let fives = 0x5555_5555_5555_5555;
        let mut lower = [0_u64; N];
        lower[..N - 2].fill(fives);
        let mut upper = lower;
        upper[0] = fives + 1;
        assert_eq!((third.lower().limbs(), third.upper().limbs()), (&lower, &upper), "{N} limbs");
    }
    check::<3>();
    check::<FAST>();
    check::<SLOW>();
    check::<MAX_LIMBS>();
}

/// `engine/real.rs` 666:29 (`k < 0` → `k == 0`) and 667:38 (`neg &&
/// !zero` → `neg && zero`) in `Fixed::mul_int`: the sign of a product by
/// an integer is the product of the signs, and a zero product has none.
/// The harnesses multiply by positive integers only. By hand: 3·(−2) =
/// −6, (−3)·2 = −6, (−3)·(−2) = 6, (−3)·0 = 0, and −2.5·4 = −10.
#[test]
fn products_by_an_integer_take_both_signs() {
    use cycleref::engine::real::{Fixed, Interval, FAST};
    let int = Fixed::<FAST>::from_int;
    for (x, k, product) in [(3, -2, -6), (-3, 2, -6), (-3, -2, 6), (-3, 0, 0), (3, 2, 6)] {
        assert_eq!(int(x).mul_int(k), Some(int(product)), "{x}·{k}");
    }
    let minus_two_and_a_half = Interval::<FAST>::int(-3).add(&Interval::half());
    assert_eq!(minus_two_and_a_half.mul_int(4), Interval::int(-10));
}

/// `engine/real.rs` 804:86, 810:86, 822:22, 863:22, 909:80 and 915:80
/// (`self.ok && o.ok` → `||` in `Interval::add`, `sub`, `mul`, `div`,
/// `max`, `min`): a poisoned operand (an overflow, a division by an
/// interval holding 0, a series that did not converge) poisons the result,
/// on either side, so that every decision on it stays undecided
/// (`UndecidedRounding`) instead of reading a value that means nothing.
/// No validated cycle poisons an interval, so no harness sees it.
#[test]
fn a_poisoned_operand_poisons_every_result() {
    use cycleref::engine::real::{Interval, Rounding, FAST};
    let poison = Interval::<FAST>::poison();
    let two = Interval::<FAST>::int(2);
    type Operation = fn(&Interval<FAST>, &Interval<FAST>) -> Interval<FAST>;
    let operations: [(&str, Operation); 6] = [
        ("add", Interval::add),
        ("sub", Interval::sub),
        ("mul", Interval::mul),
        ("div", Interval::div),
        ("max", Interval::max),
        ("min", Interval::min),
    ];
    for (name, op) in operations {
        assert!(op(&two, &two).is_valid(), "{name} of 2 and 2");
        assert!(!op(&poison, &two).is_valid(), "{name} of poison and 2");
        assert!(!op(&two, &poison).is_valid(), "{name} of 2 and poison");
        assert_eq!(op(&two, &poison).round(Rounding::Floor), None, "{name}");
    }
    // A division by an interval holding 0 poisons too.
    assert!(!two.div(&Interval::int(0)).is_valid());
}

/// `engine/real.rs` 889:14 (`k < 0` → `k == 0` in `Interval::mul_int`): a
/// negative factor swaps the ends. By hand: [1, 2]·(−3) = [−6, −3]; the
/// mutant keeps them in place, [−3, −6], an interval upside down.
#[test]
fn an_interval_times_a_negative_integer_swaps_its_ends() {
    assert_eq!(iv(1, 2).mul_int(-3), iv(-6, -3));
    assert_eq!(iv(-1, 2).mul_int(-3), iv(-6, 3));
    assert_eq!(iv(1, 2).mul_int(0), iv(0, 0));
}

/// `engine/real.rs` 954:37 (`lo == 0 && hi == 0` → `||` in
/// `Interval::sign`): an interval that touches 0 at one end holds 0 and
/// numbers of one sign, so its sign is undecided; only [0, 0] is 0. By
/// hand: [1, 2] > 0, [−2, −1] < 0, [0, 0] = 0, and [0, 1], [−1, 0],
/// [−1, 1] undecided (`sign_tie`, R-G75TIE, takes each of those as 0).
#[test]
fn an_interval_touching_zero_has_no_sign() {
    use core::cmp::Ordering;
    let cases = [
        ((1, 2), Some(Ordering::Greater)),
        ((-2, -1), Some(Ordering::Less)),
        ((0, 0), Some(Ordering::Equal)),
        ((0, 1), None),
        ((-1, 0), None),
        ((-1, 1), None),
    ];
    for ((lo, hi), sign) in cases {
        assert_eq!(iv(lo, hi).sign(), sign, "[{lo}, {hi}]");
        assert_eq!(iv(lo, hi).sign_tie(), Some(sign.unwrap_or(Ordering::Equal)), "[{lo}, {hi}]");
    }
}

/// `spec/src/g75/roughing.rs` 169:33 (`range > tool` → `>=` in
/// `check_ridges`), R-G75RIDGE: roughing in layers with a step wider than
/// the tool is refused only when layer 1's plunge range is wider than the
/// tool, since two plunges one tool width apart leave no ridge. By hand,
/// `square_groove()` (D 3.000, right-angle flanks: every layer's plunges
/// run from u = 0 to D − w) in two layers (H −2.000 and V 1.000 in
/// diameter), Q 1.600:
///
/// * I 1.500: the range is 0 to 1.500, as wide as the tool: admitted, each
///   layer plunges at Z0 and (0 + 1.600 is beyond 1.500) Z1.500;
/// * I 1.499: the range is 0 to 1.501, wider than the tool: refused.
#[test]
fn a_plunge_range_as_wide_as_the_tool_leaves_no_ridge() {
    use cycleref::{CycleError, Length, Plunge, Point, Role, Units};
    let _serial = serial();
    let layered = |tool: i64| cycleref::G75Cycle {
        step: 1_600,
        layer: Some(1_000),
        tool_width: Some(tool),
        ..square_groove()
    };
    let moves = g75_reference_moves(&layered(1_500));
    let steps: Vec<_> =
        moves.iter().filter(|m| matches!(m.role, Role::Step(_))).map(|m| (m.role, m.to)).collect();
    let step = |layer: u32| Role::Step(Plunge { layer, number: 2 });
    assert_eq!(steps, [(step(1), Point::new(100_000, 1_500)), (step(2), Point::new(99_000, 1_500))]);
    let ridges = CycleError::RidgesInLayers {
        step: Length::new(1_600, Units::IS_B_METRIC),
        tool_width: Length::new(1_499, Units::IS_B_METRIC),
    };
    g75_refused_by_both(&layered(1_499), ridges, "I 1.499");
}

/// `engine/real.rs` 1023:13 (`frac > PI_FRACTION.len()` → `==`, `>=` in
/// `pi`): π is held to 640 fraction bits (10 limbs), so it is enclosed at
/// every precision up to 12 limbs and poisoned beyond. The digits are π's
/// hexadecimal expansion, 3.243F6A88 85A308D3 13198A2E 03707344 …, which
/// Blowfish's P-array and first S-box hold (an independent source): at 12
/// limbs the lower end is those 10 limbs and 3, the upper end one ulp
/// more; at 13 and 14 limbs π is poisoned.
#[test]
fn pi_is_enclosed_up_to_640_fraction_bits() {
    use cycleref::engine::real::pi;
    let lower: [u64; 12] = [
        0xD131_0BA6_98DF_B5AC,
        0x9216_D5D9_8979_FB1B,
        0x3F84_D5B5_B547_0917,
        0xC0AC_29B7_C97C_50DD,
        0xBE54_66CF_34E9_0C6C,
        0x4528_21E6_38D0_1377,
        0x082E_FA98_EC4E_6C89,
        0xA409_3822_299F_31D0,
        0x1319_8A2E_0370_7344,
        0x243F_6A88_85A3_08D3,
        3,
        0,
    ];
    let mut upper = lower;
    upper[0] += 1;
    let at_12 = pi::<12>();
    assert!(at_12.is_valid());
    assert_eq!((at_12.lower().limbs(), at_12.upper().limbs()), (&lower, &upper));
    assert!(!pi::<13>().is_valid());
    assert!(!pi::<14>().is_valid());
}

/// `engine/real.rs` 1108:14 and 1108:16 (the guard `k > RIGHT` of `sin`
/// made false or `k == RIGHT`) and their kin in `cos`, `sin_cos`, `tan_of`
/// and `cot_of`: the trigonometry is defined on 0° to 90° (`docs/G75.md`
/// §6; `validate()` keeps every angle there), and an angle beyond is
/// poisoned, never a series evaluated outside the range its truncation
/// bound was argued for. So are tan 90° and cot 0°. In the engine's units,
/// k·0.00005°: RIGHT = 1 800 000.
#[test]
fn angles_beyond_a_right_angle_are_poisoned() {
    use cycleref::engine::real::{cos, cot, sin, sin_cos, tan, tan_cot, Interval, FAST, RIGHT};
    let poisoned = |v: Interval<FAST>| !v.is_valid();
    for k in [RIGHT + 1, RIGHT + 600_000, 2 * RIGHT, u32::MAX] {
        let (s, c) = sin_cos::<FAST>(k);
        let (t, ct) = tan_cot::<FAST>(k);
        for (name, v) in [("sin", sin(k)), ("cos", cos(k)), ("tan", tan(k)), ("cot", cot(k))] {
            assert!(poisoned(v), "{name} of {k}");
        }
        for (name, v) in [("sin_cos", s), ("sin_cos", c), ("tan_cot", t), ("tan_cot", ct)] {
            assert!(poisoned(v), "{name} of {k}");
        }
    }
    assert!(poisoned(tan::<FAST>(RIGHT)) && poisoned(tan_cot::<FAST>(RIGHT).0));
    assert!(poisoned(cot::<FAST>(0)) && poisoned(tan_cot::<FAST>(0).1));
    // At the ends of the range: the exact values.
    assert_eq!(sin::<FAST>(RIGHT), Interval::int(1));
    assert_eq!(cos::<FAST>(RIGHT), Interval::int(0));
    assert_eq!(cot::<FAST>(RIGHT), Interval::int(0));
    assert_eq!(tan::<FAST>(0), Interval::int(0));
    // And 45° (k = 900 000), whose tangent and cotangent are exactly 1
    // (`tan_of` and `cot_of`'s own arms: the quotient of the one enclosure
    // `sin_cos` gives for both is not a point).
    assert_eq!(tan::<FAST>(900_000), Interval::int(1));
    assert_eq!(cot::<FAST>(900_000), Interval::int(1));
    assert_eq!(tan_cot::<FAST>(900_000), (Interval::int(1), Interval::int(1)));
}

/// `spec/src/g75/roughing.rs` 274:47 and 275:59 (`min(limit + 1)` →
/// `min(limit − 1)`, `min(limit * 1)` in `rough_layers`): a layer's plunge
/// and peck counts are each capped just above the limit, so that their
/// product cannot overflow and still exceeds the limit. §9: more than 10^6
/// pecks are refused. By hand, radius X, a pointed tool, Δi = Δk = 1,
/// right-angle flanks, no allowances: a layer of depth Y has Y pecks a
/// plunge, and its plunges run from u = 0 to u = D, D + 1 of them.
///
/// * Y = 1: D = 999 999 is 10^6 pecks, admitted; D = 10^6 is 10^6 + 1,
///   refused (274:47 caps the plunges at 999 999 and admits it).
/// * D = 0 (one plunge): Y = 10^6 is admitted, Y = 10^6 + 1 refused
///   (275:59 caps the pecks at 999 999 or 10^6 and admits it).
#[test]
fn a_layer_of_more_plunges_or_pecks_than_the_limit_is_refused() {
    use cycleref::g75::MAX_PECKS;
    use cycleref::{CycleError, XMode};
    let _serial = serial();
    let groove = |depth: i64, width: i64| cycleref::G75Cycle {
        x_mode: XMode::Radius,
        peck: 1,
        step: 1,
        depth: -depth,
        width,
        ..square_groove()
    };
    let refused = CycleError::TooManyPecks { limit: MAX_PECKS };
    // (Y, D, plunges, pecks a plunge, outcome)
    let cases = [
        (1, 999_999, 1_000_000, 1, Ok(())),
        (1, 1_000_000, 1_000_001, 1, Err(refused)),
        (1_000_000, 0, 1, 1_000_000, Ok(())),
        (1_000_001, 0, 1, 1_000_001, Err(refused)),
    ];
    for (depth, width, plunges, pecks, expected) in cases {
        let c = groove(depth, width);
        let g = cycleref_spec::g75::groove(&c);
        let range = cycleref_spec::g75::plunge_range(&g, 1).expect("a right-angle groove");
        assert_eq!((range.first, range.last, range.count(1)), (0, i128::from(width), plunges));
        assert_eq!(cycleref_spec::g75::peck_count(0, i128::from(depth), 1), pecks);
        let what = format!("Y {depth}, D {width}");
        assert_eq!(cycleref_spec::g75::rough_layers(&g, 0).map(|_| ()), expected, "{what}: the reference");
        assert_eq!(cycleref::expand_g75(&c).map(|_| ()), expected, "{what}: the engine");
    }
}

/// `engine/real.rs` 1350:14 (`!x.ok || x.lo < 0` → `&&` in `exp`): the
/// exponential's series is summed only over non-negative arguments (every
/// term increasing in x, so the interval product keeps its ends), and a
/// partly negative argument is poisoned, never summed with that argument's
/// failing premise. LinuxCNC's depth law takes it of a logarithm of
/// n ≥ 1 only. By hand: exp of −1, of [−1, 1] and of a poisoned interval
/// are poisoned; exp 0 = 1 exactly.
#[test]
fn the_exponential_refuses_a_negative_argument() {
    use cycleref::engine::real::{exp, Interval, FAST};
    assert!(!exp(&Interval::<FAST>::int(-1)).is_valid());
    assert!(!exp(&iv(-1, 1)).is_valid());
    assert!(!exp(&Interval::<FAST>::poison()).is_valid());
    assert_eq!(exp(&Interval::<FAST>::int(0)), Interval::int(1));
}

/// `engine/real.rs` 1462:15, 1462:31 and 1462:41 (an `||` of the domain
/// guard of `power` made `&&`): n^(a/b) is defined for 1 ≤ n < 2^63 and
/// 0 < a ≤ b (LinuxCNC's depth law, `n^(1/R)` with R ≥ 1) and poisoned
/// outside, as documented, even where a value could be given. By hand:
/// n = 0; n = (2^32 − 1)² ≥ 2^63, a perfect square, whose square root
/// 2^32 − 1 the integer-root search would find; a = 0 (4^0 = 1); a > b
/// (4^(3/2) = 8). Inside the domain, 4^(1/2) = 2 exactly.
#[test]
fn powers_outside_their_domain_are_poisoned() {
    use cycleref::engine::real::{power, Interval, FAST};
    let big_square = u64::from(u32::MAX) * u64::from(u32::MAX);
    assert!(big_square >= 1 << 63);
    for (n, a, b) in [(0, 1, 2), (big_square, 1, 2), (4, 0, 2), (4, 3, 2)] {
        assert!(!power::<FAST>(n, a, b).is_valid(), "{n}^({a}/{b})");
    }
    assert_eq!(power::<FAST>(4, 1, 2), Interval::int(2));
}

/// The non-negative number whose `N` limbs (two's complement, least
/// significant first) are `limbs`, built with the public operations only:
/// the integer part from its two top limbs, each fraction limb as ulps
/// scaled up by 2^64 per place (two exact products by 2^32).
fn fixed_from_limbs<const N: usize>(limbs: [u64; N]) -> cycleref::engine::real::Fixed<N> {
    use cycleref::engine::real::Fixed;
    let top = |i: usize| i128::from(limbs[i]);
    let mut x = Fixed::<N>::from_int((top(N - 1) << 64) | top(N - 2));
    for (place, &limb) in limbs.iter().take(N - 2).enumerate() {
        let mut term = Fixed::<N>::from_ulps(limb);
        for _ in 0..2 * place {
            term = term.mul_int(1 << 32).expect("inside the fraction");
        }
        x = x.checked_add(&term).expect("below 2^127");
    }
    assert_eq!(x.limbs(), &limbs);
    x
}

/// `Interval::div` of two points is the exact quotient rounded down and up:
/// with A and B the two numbers in ulps, the ends are floor(A·2^P / B) and
/// ceil(A·2^P / B) ulps, computed here with `num-bigint`, or the interval
/// is poisoned when the upper end is 2^(64N − 1) ulps or more. Checked
/// at `N` limbs on the cases given and on 4 000 more whose limbs are drawn
/// from the values that reach the rare steps of Knuth's division (0, 1, 2,
/// 2^63 − 1, 2^63, 2^64 − 2, 2^64 − 1, a random limb), with one to `N`
/// limbs in each operand, and, one case in four, the dividend's top limb
/// set to the divisor's (a quotient digit estimate above 2^64 − 1). Both
/// operands are kept non-negative (the top bit of the top limb clear):
/// the signs are `div_round`'s, around this magnitude division.
fn division_is_exact<const N: usize>(cases: &[([u64; N], [u64; N])]) {
    use cycleref::engine::real::{Fixed, Interval};
    use num_bigint::BigUint;
    let big = |limbs: &[u64; N]| {
        limbs.iter().rev().fold(BigUint::from(0_u8), |acc, &limb| (acc << 64_u32) + BigUint::from(limb))
    };
    let check = |a: [u64; N], b: [u64; N]| {
        let q = Interval::point(fixed_from_limbs(a)).div(&Interval::point(fixed_from_limbs(b)));
        let (quotient, remainder) = {
            let (x, y) = (big(&a) << Fixed::<N>::FRACTION_BITS, big(&b));
            (&x / &y, x % y)
        };
        let upper = &quotient + u8::from(remainder != BigUint::from(0_u8));
        if upper >= BigUint::from(1_u8) << (64 * N - 1) {
            assert!(!q.is_valid(), "{a:x?} / {b:x?} overflows");
        } else {
            assert!(q.is_valid(), "{a:x?} / {b:x?}");
            assert_eq!(
                (big(q.lower().limbs()), big(q.upper().limbs())),
                (quotient, upper),
                "{a:x?} / {b:x?}"
            );
        }
    };
    for &(a, b) in cases {
        check(a, b);
    }
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    let special = [0, 1, 2, (1 << 63) - 1, 1 << 63, u64::MAX - 1, u64::MAX];
    let operand = |next: &mut dyn FnMut() -> u64| {
        let length = 1 + usize::try_from(next() % N as u64).expect("small");
        let mut limbs = [0_u64; N];
        for limb in limbs.iter_mut().take(length) {
            let pick = usize::try_from(next() % 8).expect("small");
            *limb = special.get(pick).copied().unwrap_or_else(&mut *next);
        }
        limbs[N - 1] >>= 1;
        limbs
    };
    for case in 0..4_000 {
        let (mut a, b) = (operand(&mut next), operand(&mut next));
        if case % 4 == 0 {
            if let Some(top) = b.iter().rposition(|&limb| limb != 0) {
                let at = a.iter().rposition(|&limb| limb != 0).unwrap_or(top).max(top);
                a[at] = b[top];
                a[N - 1] &= !(1 << 63);
            }
        }
        if b.iter().any(|&limb| limb != 0) {
            check(a, b);
        }
    }
}

/// `engine/real.rs`, Knuth's division `limbs_divmod`, which the engines
/// reach only with divisors of one unit or more and quotients that need no
/// correction, so that the harness binaries let through changes to its
/// one-limb branch (285:29, 286:27), its digit correction (311, 314, 315)
/// and its add-back (340 to 355), and to the shift that gives back the
/// remainder (408:44, 408:63), whose being zero decides the upper end
/// (`div_round`). Each case is worked by hand:
///
/// - 7 ulps / 2 ulps, a one-limb divisor: 7·2^P / 2 = 3.5·2^P, exact;
///   at 128 bits, (2^64 − 1) ulps / 3 ulps = (2^64 − 1)/3 · 2^128 ulps,
///   exact, limbs 0, 0, 0x5555555555555555, 0.
/// - 1 ulp / (2^64 + 1) ulps at 128 bits: 2^128 = (2^64 + 1)(2^64 − 1) + 1,
///   so the quotient is 2^64 − 1 ulps with remainder 1; the divisor's top
///   limb is 1, normalised by a shift of 63, which puts the remainder's one
///   bit at the top of its low limb. The enclosure is [2^64 − 1, 2^64] ulps.
/// - 2 ulps / (2^64 + 1) ulps: 2^129 = (2^64 + 1)(2^65 − 2) + 2: [2^65 − 2,
///   2^65 − 1] ulps, the remainder's bit now at the bottom of the second
///   limb after the shift.
/// - The add-back case of Hacker's Delight's `divmnu` tests, 0x7fff 8000
///   0000 0000 / 0x8000 0000 0001 in 16-bit digits (most significant
///   first), scaled to 64-bit limbs: the dividend's limbs 2^63, 2^63 − 1
///   (below them, the two zero limbs of the shift by P), the divisor's 1,
///   0, 2^63 (least significant first); the quotient and remainder are left
///   to the big-integer oracle.
///
/// Then the patterned cases of [`division_is_exact`], at 3, 4 (`FAST`), 10
/// (`SLOW`) and 14 limbs.
#[test]
fn the_division_kernel_is_exact_on_every_path() {
    use cycleref::engine::real::{Fixed, Interval, FAST};
    const H: u64 = 1 << 63;
    let ulps = |u: u64| Interval::<FAST>::point(Fixed::from_ulps(u));
    let q = ulps(7).div(&ulps(2));
    assert!(q.is_point());
    assert_eq!(q.lower().limbs(), &[0, H, 3, 0]);
    let q = ulps(u64::MAX).div(&ulps(3));
    assert_eq!(q.lower().limbs(), &[0, 0, 0x5555_5555_5555_5555, 0]);
    assert!(q.is_point());
    let just_above = Interval::point(fixed_from_limbs::<FAST>([1, 1, 0, 0]));
    let q = ulps(1).div(&just_above);
    assert_eq!((q.lower().limbs(), q.upper().limbs()), (&[u64::MAX, 0, 0, 0], &[0, 1, 0, 0]));
    let q = ulps(2).div(&just_above);
    assert_eq!((q.lower().limbs(), q.upper().limbs()), (&[u64::MAX - 1, 1, 0, 0], &[u64::MAX, 1, 0, 0]));
    let _serial = serial();
    division_is_exact::<3>(&[]);
    division_is_exact::<FAST>(&[([H, H - 1, 0, 0], [1, 0, H, 0])]);
    division_is_exact::<{ cycleref::engine::real::SLOW }>(&[]);
    division_is_exact::<14>(&[]);
}

/// The edges of the interval operations that no engine reaches, each worked
/// by hand:
///
/// - `engine/real.rs` 863:53 (`o.lo < 0 || o.lo = 0` → `&&` in
///   `Interval::div`): a divisor holding a negative number poisons the
///   quotient, as documented ("poisoned when `o` contains 0 or a negative
///   number"): [1, 2] / [−2, −1] and [1, 2] / [−1, 1].
/// - 833:40 (`!v.lo < 0` → `v.lo < 0` in `Interval::mul`'s test for two
///   non-negative factors): [−3, −1]·[−2, −1] = [1, 6] (the products of the
///   ends are 6, 3, 2 and 1); the mutant takes [lo·lo, hi·hi] = [6, 1].
/// - 554:12 (`a != b` → `a == b` in `Fixed::checked_add`'s overflow test):
///   −1 + 2 = 1, operands of two signs, which never overflow; 2^126 + 2^126
///   = 2^127 does (the top bit is the sign), and −2^126 + −2^126 = −2^127
///   does not.
/// - 1007:21 (the guard `self.ok` → `true` in `Interval::sign_tie`): a
///   poisoned interval has no sign, tie or not.
#[test]
fn the_interval_operations_keep_their_documented_edges() {
    use cycleref::engine::real::{Fixed, Interval, FAST};
    assert!(!iv(1, 2).div(&iv(-2, -1)).is_valid());
    assert!(!iv(1, 2).div(&iv(-1, 1)).is_valid());
    assert_eq!(iv(2, 4).div(&iv(1, 2)), iv(1, 4));
    assert_eq!(iv(-3, -1).mul(&iv(-2, -1)), iv(1, 6));
    let int = Fixed::<FAST>::from_int;
    assert_eq!(int(-1).checked_add(&int(2)), Some(int(1)));
    assert_eq!(int(2).checked_add(&int(-1)), Some(int(1)));
    assert_eq!(int(1 << 126).checked_add(&int(1 << 126)), None);
    assert_eq!(int(-(1 << 126)).checked_add(&int(-(1 << 126))), Some(int(i128::MIN)));
    assert_eq!(Interval::<FAST>::poison().sign_tie(), None);
    assert_eq!(iv(-1, 1).sign_tie(), Some(std::cmp::Ordering::Equal));
}

/// `engine/real.rs` 1216 to 1227 (`Fixed::at_precision`: the whole
/// function → `None`, and the limb offsets `to − from`, `from − to` made
/// `+` or `/`): LinuxCNC's depth law computes its power at a
/// wider precision and narrows it (`engine/linuxcnc.rs`), and no harness
/// window makes the narrowing's outward rounding show. By hand:
///
/// - 1/3 at 10 limbs (`SLOW`, 512 fraction bits) is [0x5555…5555,
///   0x5555…5556] ulps; narrowed to 4 limbs (`FAST`, 128 bits) the lower
///   end drops six limbs of 0x5555… (rounded down: two limbs of
///   0x5555…5555) and the upper end rounds up (0x5555…5556 in the low
///   limb): the tightest enclosure of 1/3 at 128 bits.
/// - 7/4 at 128 bits (fraction limbs 0 and 0xC000…0, integer 1) widened to
///   512 bits is the same number exactly: six zero limbs appended below.
#[test]
fn a_change_of_precision_appends_or_rounds_the_fraction_limbs() {
    use cycleref::engine::real::{Interval, FAST, SLOW};
    const FIVES: u64 = 0x5555_5555_5555_5555;
    let third = Interval::<SLOW>::int(1).div_int(3);
    let mut lower = [FIVES; SLOW];
    lower[SLOW - 2..].copy_from_slice(&[0, 0]);
    let mut upper = lower;
    upper[0] += 1;
    assert_eq!((third.lower().limbs(), third.upper().limbs()), (&lower, &upper));
    let narrowed = third.at_precision::<FAST>();
    assert_eq!(narrowed.lower().limbs(), &[FIVES, FIVES, 0, 0]);
    assert_eq!(narrowed.upper().limbs(), &[FIVES + 1, FIVES, 0, 0]);
    let seven_quarters = Interval::<FAST>::int(7).div_int(4);
    assert_eq!(seven_quarters.lower().limbs(), &[0, 0xC000_0000_0000_0000, 1, 0]);
    let widened = seven_quarters.at_precision::<SLOW>();
    assert!(widened.is_point());
    let mut exact = [0_u64; SLOW];
    exact[SLOW - 3..].copy_from_slice(&[0xC000_0000_0000_0000, 1, 0]);
    assert_eq!(widened.lower().limbs(), &exact);
}

/// The logarithm, the exponential and the power (`engine/real.rs` 1269 to
/// 1321 in `atanh2` and `ln`, 1364 and 1390 in `exp`, 1426 `gcd_u32`),
/// LinuxCNC's depth law `n^(1/R)`, whose harnesses see only the depths it
/// rounds to. Each is checked against integers, not against the engine:
///
/// - exp(ln n) holds n and rounds to it, for n = 2, 3, 10, 1000, 2^40 + 1
///   and 2^63 − 1 (every branch of `ln`: e = 0 never, the power of two
///   below n, the series of (n − 2^e)/(n + 2^e) ≤ 1/3), at 4 and 10 limbs;
/// - ln 2 is within 2^−100 at 4 limbs (the series' tail bound is 2·z^(2k+1)
///   with its last term below 4 ulps), and holds 0.693147180559945309417232
///   (ln 2 to 24 places, a published constant), as ln 1024 holds ten times
///   that;
/// - ln 1 = 0 exactly, ln 0 and ln 2^63 are poisoned (outside 1 ≤ n < 2^63);
/// - e = exp 1 holds 2.718281828459045235360287 (published);
/// - the power reduces its exponent before looking for an exact root:
///   4^(10000/20000) = 2 exactly (LinuxCNC's R = 2 in ten-thousandths), as
///   8^(2/6) = 2.
#[test]
fn the_logarithm_and_the_exponential_hold_their_values() {
    use cycleref::engine::real::{exp, ln, power, Fixed, Interval, Rounding, FAST, SLOW};
    fn exp_of_ln<const N: usize>(n: u64) {
        let back = exp(&ln::<N>(n));
        let n = i128::from(n);
        let exact = Fixed::<N>::from_int(n);
        assert!(
            back.lower().cmp_signed(&exact).is_le() && back.upper().cmp_signed(&exact).is_ge(),
            "exp(ln {n}) holds {n}"
        );
        assert_eq!(back.round(Rounding::Nearest), Some(n), "exp(ln {n})");
    }
    for n in [2, 3, 10, 1000, (1 << 40) + 1, (1 << 63) - 1] {
        exp_of_ln::<FAST>(n);
        exp_of_ln::<SLOW>(n);
    }
    // `digits` read as an integer over 10^places lies in the interval scaled
    // by 10^places (exact products by 10), within one unit of the last place.
    fn holds<const N: usize>(x: &Interval<N>, digits: i128, places: u32) {
        let scale = |v: &Fixed<N>| (0..places).fold(*v, |v, _| v.mul_int(10).expect("small"));
        let (lo, hi) = (scale(x.lower()), scale(x.upper()));
        assert!(lo.floor() <= digits && hi.ceil() >= Some(digits), "{digits}e-{places}");
    }
    let ln2 = ln::<FAST>(2);
    let width = ln2.upper().checked_sub(ln2.lower()).expect("narrow");
    assert!(width.cmp_signed(&Fixed::from_ulps(1 << 28)).is_lt(), "ln 2 within 2^-100");
    holds(&ln2, 693_147_180_559_945_309_417_232, 24);
    holds(&ln::<FAST>(1024), 6_931_471_805_599_453_094_172_321, 24);
    holds(&ln::<SLOW>(2), 693_147_180_559_945_309_417_232, 24);
    assert_eq!(ln::<FAST>(1), Interval::int(0));
    assert!(!ln::<FAST>(0).is_valid());
    assert!(!ln::<FAST>(1 << 63).is_valid());
    holds(&exp(&Interval::<FAST>::int(1)), 2_718_281_828_459_045_235_360_287, 24);
    assert_eq!(power::<FAST>(4, 10_000, 20_000), Interval::int(2));
    assert_eq!(power::<FAST>(8, 2, 6), Interval::int(2));
}
