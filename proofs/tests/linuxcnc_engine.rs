//! Differential tests: the fixed-point LinuxCNC G76 engine
//! (`cycleref::expand_linuxcnc`) against the exact reference
//! (`cycleref_spec::linuxcnc::expand`), and the engine's interval powers
//! (`cycleref::engine::real::power`) against the reference's
//! (`cycleref_spec::real::Real::power`).
//!
//! For every generated cycle, valid or not, both must give the same error
//! or the same moves, move by move (motion and lead, end point, role, pass
//! information); and the engine must equal itself with its fast path off
//! (`expand_linuxcnc_exact`, reading R-FASTPATH). The cycles span G7/G8,
//! mm and inch, both directions, internal and external threads, R in 1..3
//! with four decimals (and the R of exact roots, where a depth equals K
//! exactly, R-LCNC-TIE), Q in −45..45° with four decimals, H −1..3, E and
//! L, pass limits that refuse, coordinates beyond the range table and
//! words at its ends; K is chosen so that a cycle has at most about 30
//! rough passes. The default run tries
//! 400 cycles; `engine_equals_reference_long` (ignored) 20 000.

use cycleref::engine::real::{power, Interval, Rounding, FAST, SLOW};
use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
use cycleref::units::MAX_LENGTH;
use cycleref::{
    expand_linuxcnc, CycleError, IncrementSystem, InputUnit, Lead, LeadWord, Move, Point, Units, XMode,
};
use cycleref_spec::differ::assert_same_moves;
use cycleref_spec::real::Real;
use proptest::prelude::*;

fn spec(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    cycleref_spec::linuxcnc::expand(c)
}

fn engine(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    expand_linuxcnc(c).map(Iterator::collect)
}

/// The engine with its fast path off (R-FASTPATH): the interval
/// arithmetic alone.
fn engine_exact(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    cycleref::engine::linuxcnc::expand_linuxcnc_exact(c).map(Iterator::collect)
}

/// All three agree on `c` (the engine, the engine without its fast path
/// and the reference); returns the common result.
fn same(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    let s = spec(c);
    let e = engine(c);
    assert_same_moves(&e, &s, format_args!("{c:?}"));
    assert_eq!(e, engine_exact(c), "fast path against the intervals: {c:?}");
    s
}

/// How K is chosen against J.
#[derive(Clone, Copy, Debug)]
enum Depths {
    /// K in (J, J·ratio], ratio^R at most about 30 passes.
    Ratio(u32),
    /// K = J·m with m^R an integer: a rough depth equals K exactly.
    Tie(usize),
    /// J and K near the range table's end.
    Huge,
}

/// R and K/J of exact ties: (R in ten-thousandths, K/J), K/J = n^(1/R).
const TIES: [(u32, i64); 8] =
    [(10_000, 3), (10_000, 7), (15_000, 4), (15_000, 9), (20_000, 3), (20_000, 5), (30_000, 2), (25_000, 4)];

#[derive(Clone, Debug)]
struct Shape {
    inch: bool,
    diameter: bool,
    internal: bool,
    towards_plus: bool,
    x0_radius: i64,
    z0: i64,
    length: i64,
    pitch: Lead,
    i_abs: i64,
    j: i64,
    degression: u32,
    depths: Depths,
    compound_angle: i32,
    spring_passes: i32,
    taper: i64,
    l: u8,
    pass_limit: u32,
}

fn shape() -> impl Strategy<Value = Shape> {
    let geometry = (
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        prop_oneof![9 => 10_000_i64..400_000, 1 => (MAX_LENGTH - 20_000)..=MAX_LENGTH],
        -50_000_i64..50_000,
        1_i64..400_000,
        prop_oneof![
            (1_u64..=400, 1_u32..=3).prop_map(|(mantissa, scale)| Lead {
                word: LeadWord::F,
                mantissa,
                scale
            }),
            Just(Lead { word: LeadWord::F, mantissa: 9999, scale: 0 }),
            Just(Lead { word: LeadWord::F, mantissa: 1, scale: 6 }),
        ],
        prop_oneof![9 => 1_i64..20_000, 1 => Just(0_i64)],
    );
    let cut = (
        1_i64..5_000,
        10_000_u32..=30_000,
        prop_oneof![
            6 => (1_u32..=1_000).prop_map(Depths::Ratio),
            2 => (0..TIES.len()).prop_map(Depths::Tie),
            1 => Just(Depths::Huge),
        ],
        prop_oneof![
            2 => Just(0_i32),
            1 => Just(450_000_i32),
            1 => Just(-450_000_i32),
            1 => Just(295_000_i32),
            6 => -450_000_i32..=450_000,
        ],
        -1_i32..=3,
        prop_oneof![1 => Just(0_i64), 1 => 1_i64..30_000, 1 => Just(1_i64)],
        0_u8..=3,
        prop_oneof![9 => Just(1_000_000_u32), 1 => 0_u32..12],
    );
    (geometry, cut).prop_map(
        |(
            (inch, diameter, internal, towards_plus, x0_radius, z0, length, pitch, i_abs),
            (j, degression, depths, compound_angle, spring_passes, taper, l, pass_limit),
        )| Shape {
            inch,
            diameter,
            internal,
            towards_plus,
            x0_radius,
            z0,
            length,
            pitch,
            i_abs,
            j,
            degression,
            depths,
            compound_angle,
            spring_passes,
            taper,
            l,
            pass_limit,
        },
    )
}

fn cycle(s: &Shape) -> LinuxCncG76 {
    let xf = if s.diameter { 2 } else { 1 };
    let (mut j, mut degression) = (s.j * xf, s.degression);
    let k = match s.depths {
        Depths::Ratio(thousandths) => {
            // ratio^R ≤ 30: ratio ≤ 30^(1/R), picked as a fraction of it.
            let r = f64::from(degression) / f64::from(DEGRESSION_ONE);
            let max_ratio = 30_f64.powf(1.0 / r);
            let ratio = 1.0 + (max_ratio - 1.0) * f64::from(thousandths) / 1000.0;
            let k = (j as f64 * ratio) as i64;
            k.max(j + 1)
        }
        Depths::Tie(i) => {
            let (r, m) = TIES[i];
            degression = r;
            j * m
        }
        Depths::Huge => {
            j = MAX_LENGTH / 2 + s.j;
            MAX_LENGTH
        }
    };
    let sigma = if s.internal { 1 } else { -1 };
    let z_end = if s.towards_plus { s.z0 + s.length } else { s.z0 - s.length };
    let x0 = s.x0_radius * xf;
    LinuxCncG76 {
        units: Units {
            system: IncrementSystem::IsC,
            unit: if s.inch { InputUnit::Inch } else { InputUnit::Metric },
        },
        x_mode: if s.diameter { XMode::Diameter } else { XMode::Radius },
        start: Point::new(x0, s.z0),
        end: Point::new(x0, z_end),
        pitch: s.pitch,
        peak_offset: sigma * s.i_abs * xf,
        initial_depth: j,
        degression,
        full_depth: k,
        compound_angle: s.compound_angle,
        spring_passes: s.spring_passes,
        taper_distance: s.taper,
        entry_taper: s.l & 1 != 0,
        exit_taper: s.l & 2 != 0,
        pass_limit: s.pass_limit,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn engine_equals_reference(s in shape()) {
        let _ = same(&cycle(&s));
    }
}

/// The worked cycles of `spec/tests/linuxcnc.rs` and the exact tie of
/// R-LCNC-TIE, with their counts.
#[test]
fn worked_cycles() {
    let mut c = cycleref::examples::LINUXCNC_TAPER;
    assert_eq!(same(&c).unwrap().len(), 11 * 6 + 1);
    // J0.1 R1.5 K0.4: δ_8 = 0.1·8^(2/3) = 0.4 = K exactly: 7 rough passes.
    c.initial_depth = 1_000;
    c.full_depth = 4_000;
    c.spring_passes = 0;
    let moves = same(&c).unwrap();
    let rough = moves.iter().filter(|m| m.pass.is_some_and(|p| p.kind == cycleref::PassKind::Rough)).count();
    assert_eq!(rough, 7 * 6);
    // Limits: 7 rough passes and the one at full depth (H0) are 8 pass
    // paths (reading R-BUDGET): they fit a limit of 8; 7 holds the rough
    // passes but not the whole cycle; 6 not even the rough passes.
    c.pass_limit = 8;
    assert!(same(&c).is_ok());
    c.pass_limit = 7;
    assert!(matches!(same(&c), Err(CycleError::TooMuchWork { pass_paths: 8, limit: 7 })));
    // H = 2^31 - 1 spring passes: 7 + 2^31 pass paths, refused before a
    // move by both (it would be unbounded work).
    c.pass_limit = 1_000_000;
    c.spring_passes = i32::MAX;
    let paths = 7 + 1 + u64::try_from(i32::MAX).unwrap();
    assert!(
        matches!(same(&c), Err(CycleError::TooMuchWork { pass_paths, limit: 1_000_000 }) if pass_paths == paths)
    );
    c.spring_passes = 0;
    c.pass_limit = 6;
    assert!(matches!(same(&c), Err(CycleError::TooManyPasses { passes: 6, exact: false, limit: 6 })));
    // A cut beyond the range table.
    c.pass_limit = 1_000_000;
    c.start.x = MAX_LENGTH - 5_000;
    c.end.x = c.start.x;
    c.peak_offset = -10_000; // external: every X at or below X₀ + K − J
    assert!(same(&c).is_ok());
    c.peak_offset = 10_000; // internal: the cut at X₀ + |I| + δ is beyond
    assert!(matches!(same(&c), Err(CycleError::OutOfRange { .. })));
}

/// Words at the range table's ends: the taper pitch of the largest P over
/// the shortest E and the deepest K, in both X modes.
#[test]
fn taper_pitch_at_the_ends() {
    for x_mode in [XMode::Radius, XMode::Diameter] {
        for (e, j, k) in [
            (1, MAX_LENGTH - 1, MAX_LENGTH),
            (MAX_LENGTH, 1, 2),
            (1, 1, 2),
            (MAX_LENGTH, MAX_LENGTH - 1, MAX_LENGTH),
        ] {
            let c = LinuxCncG76 {
                units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
                x_mode,
                start: Point::new(0, 0),
                end: Point::new(0, -10_000),
                pitch: Lead { word: LeadWord::F, mantissa: 9999, scale: 0 },
                peak_offset: 1,
                initial_depth: j,
                degression: 10_000,
                full_depth: k,
                compound_angle: 0,
                spring_passes: 0,
                taper_distance: e,
                entry_taper: true,
                exit_taper: true,
                pass_limit: 1_000_000,
            };
            assert_eq!(
                cycleref::engine::linuxcnc::taper_pitch(&c).unwrap(),
                cycleref_spec::linuxcnc::taper_pitch(&c)
            );
            let _ = same(&c);
        }
    }
}

/// `10^digits · v`, floored, at both ends of an enclosure (`10^digits · v
/// < 2^127`).
fn scaled_floor<const N: usize>(v: &Interval<N>, digits: u32) -> (i128, i128) {
    let mut s = *v;
    for _ in 0..digits {
        s = s.mul_int(10);
    }
    (s.lower().floor(), s.upper().floor())
}

/// The engine's power encloses the reference's digits, at both precisions.
#[test]
fn power_matches_the_reference_digits() {
    let cases = [
        (2, 2, 3),
        (10, 2, 3),
        (3, 1, 2),
        (7, 10_000, 15_000),
        (1_000_001, 10_000, 12_345),
        (4_294_967_297, 10_000, 29_999),
        (5, 10_000, 10_001),
        (123_456, 1, 64),
        (99, 7, 9),
    ];
    for (n, a, b) in cases {
        // 25 digits: 10^25 · n^(a/b) < 2^127.
        let reference = Real::power(n, a, b).to_decimal(25).unwrap();
        let digits: i128 = reference.replace('.', "").parse().unwrap();
        let fast = power::<FAST>(n, a, b);
        // 128 bits, less the error of the series, give well over 20
        // digits for values below 2^33: the enclosure is narrower than
        // 10^-20.
        let digits20 = digits / 10_i128.pow(5);
        let (lo, hi) = scaled_floor(&fast, 20);
        assert!(lo <= digits20 && digits20 <= hi, "{n}^({a}/{b}) = {reference}: fast {lo}..{hi}");
        assert!(hi - lo <= 1, "{n}^({a}/{b}): fast enclosure too wide");
        let slow = power::<SLOW>(n, a, b);
        assert_eq!(scaled_floor(&slow, 25), (digits, digits), "{n}^({a}/{b}) slow");
    }
}

/// Exact powers are exact point intervals; others are not.
#[test]
fn exact_powers() {
    assert_eq!(power::<FAST>(8, 2, 3), Interval::int(4));
    assert_eq!(power::<FAST>(9, 1, 2), Interval::int(3));
    assert_eq!(power::<FAST>(8, 10_000, 15_000), Interval::int(4));
    assert_eq!(power::<SLOW>(27, 10_000, 15_000), Interval::int(9));
    assert_eq!(power::<FAST>(1, 3, 7), Interval::int(1));
    assert_eq!(power::<FAST>(12_345, 5, 5), Interval::int(12_345));
    assert_eq!(power::<FAST>(1 << 62, 1, 62), Interval::int(2));
    assert_eq!(power::<FAST>(3_486_784_401, 10_000, 20_000), Interval::int(59_049));
    // 97^5 = 8 587 340 257: n^(4/5) = 97^4, where n^4 overflows u128.
    assert_eq!(power::<FAST>(8_587_340_257, 10_000, 12_500), Interval::int(88_529_281));
    for (n, a, b) in [(10, 1, 2), (2, 2, 3), (8, 1, 2), (1_000, 10_000, 10_001)] {
        assert!(!power::<FAST>(n, a, b).is_point(), "{n}^({a}/{b})");
        assert!(Real::power(n, a, b).as_exact().is_none());
    }
    for (n, a, b) in [(8, 2, 3), (9, 1, 2), (27, 10_000, 15_000), (8_587_340_257, 10_000, 12_500)] {
        assert!(Real::power(n, a, b).is_exact(), "{n}^({a}/{b}) in the reference");
    }
    // Outside the domain: poisoned, never a panic.
    assert!(!power::<FAST>(0, 1, 2).is_valid());
    assert!(!power::<FAST>(2, 0, 2).is_valid());
    assert!(!power::<FAST>(2, 3, 2).is_valid());
    assert!(!power::<FAST>(u64::MAX, 1, 2).is_valid());
    // A decision on an exact power is exact: J·8^(2/3) − 4J = 0.
    let zero = power::<FAST>(8, 2, 3).mul_int(1_000).sub(&Interval::int(4_000));
    assert_eq!(zero.round(Rounding::Floor), Some(0));
}

/// The generated cycles reach what they are meant to: most expand, with
/// passes of every kind and taper, and each error is met.
#[test]
fn generated_cycles_cover_the_cases() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = shape();
    let (mut ok, mut moves, mut limit, mut range, mut invalid, mut tapers, mut no_full) =
        (0, 0, 0, 0, 0, 0, 0);
    for _ in 0..400 {
        let c = cycle(&strategy.new_tree(&mut runner).unwrap().current());
        match same(&c) {
            Ok(m) => {
                ok += 1;
                moves += m.len();
                tapers += usize::from(
                    m.iter().any(|m| m.role == cycleref::Role::RunOut || m.role == cycleref::Role::LeadIn),
                );
                no_full += usize::from(
                    !m.iter().any(|m| m.pass.is_some_and(|p| p.kind == cycleref::PassKind::Finish)),
                );
            }
            Err(CycleError::TooManyPasses { .. }) => limit += 1,
            Err(CycleError::OutOfRange { field: cycleref::Field::PassCoordinate, .. }) => range += 1,
            Err(_) => invalid += 1,
        }
    }
    eprintln!("ok {ok} ({moves} moves), tapers {tapers}, no full-depth pass {no_full}, pass limit {limit}, out of range {range}, invalid {invalid}");
    assert!(ok >= 250 && tapers >= 50 && no_full >= 20 && limit >= 5 && range >= 5 && invalid >= 5);
}

/// The long run: 20 000 cycles (`cargo test -p cycleref-proofs --test
/// linuxcnc_engine -- --ignored`).
#[test]
#[ignore = "long run"]
fn engine_equals_reference_long() {
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config { cases: 20_000, ..Config::default() });
    runner
        .run(&shape(), |s| {
            let _ = same(&cycle(&s));
            Ok(())
        })
        .unwrap();
}

/// The new loops stay within the bounds their documentation gives
/// (feature `loop-counters`, on for this crate's tests): the iterator moves
/// on at most twice per move, the wide square root runs at most 128 steps
/// (from the highest pair of bits that is not zero), the
/// root search and gcd at most 47, the series far below `MAX_TERMS` (400)
/// even at 576 bits. The counts are process-wide maxima, so the other
/// tests of this file running meanwhile only add cycles of the same kind.
#[test]
fn loop_counts_stay_within_their_bounds() {
    use cycleref::loop_counters::{self, LCNC_ISQRT, LCNC_NEXT, LCNC_PASSES, REAL_EXP, REAL_LN, REAL_ROOT};
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    loop_counters::reset();
    let mut runner = TestRunner::deterministic();
    let strategy = shape();
    for _ in 0..100 {
        let _ = engine(&cycle(&strategy.new_tree(&mut runner).unwrap().current()));
    }
    // The slow powers too (576 bits, the longest series).
    let _ = power::<{ SLOW + 1 }>(4_294_967_297, 10_000, 29_999);
    let _ = power::<{ SLOW + 1 }>(3, 10_000, 10_001);
    let counts =
        [&LCNC_NEXT, &LCNC_ISQRT, &LCNC_PASSES, &REAL_ROOT, &REAL_LN, &REAL_EXP].map(|s| (s.name, s.max()));
    eprintln!("{counts:?}");
    assert!(LCNC_NEXT.max() <= 2);
    assert!((1..=128).contains(&LCNC_ISQRT.max()));
    assert!(LCNC_PASSES.max() <= 40);
    assert!(REAL_ROOT.max() <= 47);
    assert!(REAL_LN.max() <= 200 && REAL_EXP.max() <= 200);
}

/// Thousands of passes: large `n` in the power, every depth an interval
/// (R = 1.2345) or exact (R = 1), G7 and G8.
#[test]
fn thousands_of_passes() {
    let mut c = LinuxCncG76 {
        units: Units { system: IncrementSystem::IsC, unit: InputUnit::Inch },
        x_mode: XMode::Diameter,
        start: Point::new(200_000, 1_000),
        end: Point::new(200_000, -30_000),
        pitch: Lead { word: LeadWord::F, mantissa: 625, scale: 4 },
        peak_offset: -2_000,
        initial_depth: 10,
        degression: 12_345,
        full_depth: 10_000,
        compound_angle: -291_234,
        spring_passes: 2,
        taper_distance: 3_000,
        entry_taper: false,
        exit_taper: true,
        pass_limit: 1_000_000,
    };
    // δ_n < K ⇔ n < 1000^1.2345 = 5 052.43…: 5 052 rough passes, 3 at K,
    // 5 moves each (back, in, over, exit taper, out).
    assert_eq!(same(&c).unwrap().len(), (5_052 + 3) * 5 + 1);
    c.degression = DEGRESSION_ONE;
    c.x_mode = XMode::Radius;
    // δ_n = 10n < 10 000 for n ≤ 999.
    assert_eq!(same(&c).unwrap().len(), (999 + 3) * 5 + 1);
    c.pass_limit = 998;
    assert!(matches!(same(&c), Err(CycleError::TooManyPasses { .. })));
}
