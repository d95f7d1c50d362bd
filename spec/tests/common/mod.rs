//! Fixtures shared by the spec crate's test binaries.

use cycleref::linuxcnc::LinuxCncG76;
use cycleref::{IncrementSystem, InputUnit, Lead, LeadWord, Point, Units, XMode};

/// A straight LinuxCNC thread in G8 (radius), IS-C millimetres, worked by
/// hand in `linuxcnc.rs` (`straight_thread_by_hand`): X0 = 10, Z0 = 1,
/// `G76 P1 Z-10 I-0.5 J0.1 R1 K0.3 Q0 H0`, no taper. Other tests change
/// R (degression) and K (full depth) with `..STRAIGHT_RADIUS`.
pub const STRAIGHT_RADIUS: LinuxCncG76 = LinuxCncG76 {
    units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
    x_mode: XMode::Radius,
    start: Point::new(100_000, 10_000),
    end: Point::new(100_000, -100_000),
    pitch: Lead { word: LeadWord::K, mantissa: 1, scale: 0 },
    peak_offset: -5_000,
    initial_depth: 1_000,
    degression: 10_000,
    full_depth: 3_000,
    compound_angle: 0,
    spring_passes: 0,
    taper_distance: 0,
    entry_taper: false,
    exit_taper: false,
    pass_limit: 1_000_000,
};
