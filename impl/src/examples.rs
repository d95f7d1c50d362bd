//! The sources' worked examples as typed cycles: what the manuals' and the
//! seeds' example programs resolve to, for tests, benchmarks and
//! documentation. Each is checked against the program it comes from, read
//! by the reader (`spec/tests/examples.rs`), so a constant here cannot
//! drift from its source.
//!
//! ```
//! use cycleref::examples::M68X6;
//!
//! // 988TA O0013: G76 X60.64 Z-62 P3.68 Q1.8 F6 after G76 P020560 Q0.150 R0.1.
//! let moves: Vec<_> = cycleref::expand_g76(&M68X6)?.collect();
//! assert_eq!(moves.last().map(|m| m.to), Some(M68X6.start));
//! # Ok::<(), cycleref::CycleError>(())
//! ```

use crate::g75::{Corner, CornerKind, G75Cycle, PathType};
use crate::g76::{DepthMode, G76Cycle, Infeed, RunOut, DEFAULT_PASS_LIMIT};
use crate::lead::{Lead, LeadWord};
use crate::linuxcnc::LinuxCncG76;
use crate::units::{IncrementSystem, InputUnit, Point, Units, XMode};

/// M68x6 of the GSK 988TA manual (manuals/gsk988ta-g76.txt, O0013;
/// `examples/gsk988-m68x6.nc`): from A X80 Z10, `G76 P020560 Q0.150 R0.1`
/// then `G76 X60.64 Z-62 P3.680 Q1.800 F6`, IS-B metric: external, towards
/// -Z, k 3.68, Δd 1.8, Δdmin 0.15, d 0.1, two finishing passes, 60°, the
/// default chamfer of 0.5 lead at 45°.
pub const M68X6: G76Cycle = G76Cycle {
    units: Units::IS_B_METRIC,
    x_mode: XMode::Diameter,
    start: Point::new(80_000, 10_000),
    end: Point::new(60_640, -62_000),
    taper: 0,
    thread_height: 3680,
    first_depth: 1800,
    min_cut: 150,
    finishing_allowance: 100,
    finishing_passes: 2,
    tool_angle: 60,
    infeed: Infeed::RightFlank,
    depth_mode: DepthMode::Decreasing,
    lead_in: 0,
    starts: 1,
    lead: Lead { word: LeadWord::F, mantissa: 6, scale: 0 },
    run_out: RunOut::Chamfer { tenths_of_lead: 5, angle_degrees: 45, long: None },
    pass_limit: DEFAULT_PASS_LIMIT,
    // The gsk988 profile's readings: R-END `parallel` (a straight thread:
    // the same moves as `travel-i`), R-NOROUGH `one-at-zero` (d < k here:
    // the same moves as `none`).
    readings: crate::CycleReadings {
        pass_end: crate::readings::PassEnd::Parallel,
        one_rough_at_zero: true,
        ..crate::CycleReadings::DEFAULT
    },
};

/// The G75.1 example of the GSK 980TDi manual (seed 001) at IS-C metric:
/// from `G00 X60 Z30`, `G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30;
/// G75.1 R0.5;` (no tool width: the seed's 4 mm tool is not programmed,
/// reading R-G75SEED).
pub const G75_SEED: G75Cycle = G75Cycle {
    units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
    x_mode: XMode::Diameter,
    from: Point::new(600_000, 300_000),
    start: Point::new(500_000, 300_000),
    peck: 30_000,
    step: 50_000,
    depth: -200_000,
    width: -100_000,
    flank_a: 450_000,
    flank_b: 300_000,
    slope: 0,
    retract: 5_000,
    layer: None,
    allowance_x: 0,
    allowance_z: 0,
    tool_width: None,
    path: PathType::Rough,
    corners: [Corner::SHARP; 4],
    readings: crate::G75Readings::DEFAULT,
};

/// The trapezoidal groove on a slope of `examples/gsk980-g75-slope.nc` at
/// IS-B metric: from `G00 X90 Z12`, `G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60
/// B75 L10; G75.1 R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111;`
/// (flanks 60° and 75° on a 10° slope, a 2.5 mm tool, layers of 3, rough
/// and finish, rounds at all four corners). Checked against its program
/// by `spec/tests/g75_real.rs`, `the_slope_example_expands`.
pub const G75_SLOPE: G75Cycle = G75Cycle {
    units: Units::IS_B_METRIC,
    x_mode: XMode::Diameter,
    from: Point::new(90_000, 12_000),
    start: Point::new(80_000, 0),
    peck: 1_500,
    step: 2_000,
    depth: -9_000,
    width: -6_000,
    flank_a: 600_000,
    flank_b: 750_000,
    slope: 100_000,
    retract: 300,
    layer: Some(3_000),
    allowance_x: 300,
    allowance_z: 100,
    tool_width: Some(2_500),
    path: PathType::RoughAndFinish,
    corners: [
        Corner { size: 500, kind: CornerKind::Round },
        Corner { size: 500, kind: CornerKind::Round },
        Corner { size: 400, kind: CornerKind::Round },
        Corner { size: 400, kind: CornerKind::Round },
    ],
    readings: crate::G75Readings::DEFAULT,
};

/// A LinuxCNC G76 with every feature of its passes
/// (`spec/tests/data/lcnc-taper.ngc`, whose `rs274` output is checked in
/// beside it): G8 (radius), from X14 Z2, `G76 P1.5 Z-20 I-1 J0.2 R1.5
/// K0.92 Q29.5 H1 E1 L3`, IS-C metric: external, towards -Z, degression
/// 1.5 (9 rough passes), a compound angle, a spring pass, entry and exit
/// tapers.
pub const LINUXCNC_TAPER: LinuxCncG76 = LinuxCncG76 {
    units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
    x_mode: XMode::Radius,
    start: Point::new(140_000, 20_000),
    end: Point::new(140_000, -200_000),
    pitch: Lead { word: LeadWord::K, mantissa: 15, scale: 1 },
    peak_offset: -10_000,
    initial_depth: 2_000,
    degression: 15_000,
    full_depth: 9_200,
    compound_angle: 295_000,
    spring_passes: 1,
    taper_distance: 10_000,
    entry_taper: true,
    exit_taper: true,
    pass_limit: DEFAULT_PASS_LIMIT,
};
