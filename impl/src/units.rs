//! Increment systems, input units and lengths in least increments.
//!
//! DOMAIN decision 1: every length is an exact integer number of least
//! increments of the configured increment system. `i64` holds every value of
//! the range tables (at most 999 999 999 increments, see [`MAX_LENGTH`]) with
//! more than nine orders of magnitude to spare.

use core::fmt;

/// The increment system of the control (最小输入增量).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IncrementSystem {
    /// IS-B: 0.001 mm / 0.0001 inch.
    IsB,
    /// IS-C: 0.0001 mm / 0.00001 inch.
    IsC,
}

/// Metric (G21) or inch (G20) input.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum InputUnit {
    /// Millimetres (G21, 公制输入).
    Metric,
    /// Inches (G20, 英制输入).
    Inch,
}

/// Increment system and input unit together: they fix the least increment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Units {
    /// IS-B or IS-C.
    pub system: IncrementSystem,
    /// mm or inch.
    pub unit: InputUnit,
}

impl Units {
    /// IS-B, metric: 0.001 mm, the most common configuration.
    pub const IS_B_METRIC: Units = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };

    /// Number of decimals of one least increment in the input unit
    /// (IS-B mm 3, IS-B inch 4, IS-C mm 4, IS-C inch 5).
    #[must_use]
    pub const fn decimals(self) -> u32 {
        match (self.system, self.unit) {
            (IncrementSystem::IsB, InputUnit::Metric) => 3,
            (IncrementSystem::IsB, InputUnit::Inch) | (IncrementSystem::IsC, InputUnit::Metric) => 4,
            (IncrementSystem::IsC, InputUnit::Inch) => 5,
        }
    }

    /// Increments in one mm (metric) or one inch.
    #[must_use]
    pub const fn per_unit(self) -> i64 {
        10_i64.pow(self.decimals())
    }
}

/// Whether X words are diameters (the default on lathes) or radii.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum XMode {
    /// X is programmed as a diameter: a radius amount `r` moves X by `2 r`.
    Diameter,
    /// X is programmed as a radius.
    Radius,
}

impl XMode {
    /// Increments of X per increment of radius (2 for diameter, 1 for radius).
    #[must_use]
    pub const fn factor(self) -> i64 {
        match self {
            XMode::Diameter => 2,
            XMode::Radius => 1,
        }
    }
}

/// Largest magnitude, in increments, of any length word in the manuals'
/// range tables: 999999.999 mm at IS-B, 99999.9999 mm at IS-C,
/// 99999.9999 inch at IS-B and 9999.99999 inch at IS-C are all
/// 999 999 999 increments.
pub const MAX_LENGTH: i64 = 999_999_999;

/// A point in the XZ plane, in increments; `x` is in X-word units
/// (diameter increments when [`XMode::Diameter`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Point {
    /// X coordinate (diameter or radius increments, as programmed).
    pub x: i64,
    /// Z coordinate in increments.
    pub z: i64,
}

impl Point {
    /// A point from its coordinates.
    #[must_use]
    pub const fn new(x: i64, z: i64) -> Point {
        Point { x, z }
    }
}

/// A length in increments together with the number of decimals needed to
/// print it: used in error messages so they show the value as programmed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Length {
    /// Value in least increments.
    pub increments: i64,
    /// Decimals of one increment ([`Units::decimals`]).
    pub decimals: u32,
}

impl Length {
    /// A length of `increments` in `units`.
    #[must_use]
    pub const fn new(increments: i64, units: Units) -> Length {
        Length { increments, decimals: units.decimals() }
    }
}

impl fmt::Display for Length {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_fixed(f, i128::from(self.increments), self.decimals)
    }
}

/// Writes `value / 10^decimals` with exactly `decimals` decimals.
///
/// # Errors
///
/// Only those of the underlying writer.
pub fn write_fixed<W: fmt::Write>(w: &mut W, value: i128, decimals: u32) -> fmt::Result {
    let scale = 10_u128.pow(decimals);
    let sign = if value < 0 { "-" } else { "" };
    let mag = value.unsigned_abs();
    if decimals == 0 {
        return write!(w, "{sign}{mag}");
    }
    write!(w, "{sign}{}.{:0width$}", mag / scale, mag % scale, width = decimals as usize)
}
