//! The typed parameters of one LinuxCNC G76 threading cycle
//! (`G76 P Z I J R K Q H E L`), as the program reader resolves them: one
//! home, used by the reference model and (later) the engine alike.
//!
//! The authority is LinuxCNC's interpreter, `convert_threading_cycle` and
//! `threading_pass` in `src/emc/rs274ngc/interp_convert.cc` (LinuxCNC
//! 2.9), where its documentation and its code differ the code wins (issue
//! 15; readings `R-LCNC…` in `docs/INTERPRETATIONS.md`).
//!
//! | word | field | meaning |
//! |---|---|---|
//! | P | [`pitch`](LinuxCncG76::pitch) | thread pitch, distance per revolution |
//! | Z | [`end`](LinuxCncG76::end) | final Z of the thread |
//! | I | [`peak_offset`](LinuxCncG76::peak_offset) | thread peak offset from the drive line (negative: external) |
//! | J | [`initial_depth`](LinuxCncG76::initial_depth) | initial cut depth, > 0 |
//! | R | [`degression`](LinuxCncG76::degression) | depth degression, 1 when below 1 or absent |
//! | K | [`full_depth`](LinuxCncG76::full_depth) | full thread depth, > J |
//! | Q | [`compound_angle`](LinuxCncG76::compound_angle) | compound slide angle |
//! | H | [`spring_passes`](LinuxCncG76::spring_passes) | spring passes after the full-depth pass |
//! | E | [`taper_distance`](LinuxCncG76::taper_distance) | taper distance along Z |
//! | L | [`entry_taper`](LinuxCncG76::entry_taper), [`exit_taper`](LinuxCncG76::exit_taper) | taper ends: 1 entry, 2 exit, 3 both |
//!
//! The drive line is the X of the tool before the block
//! ([`start`](LinuxCncG76::start)). I, J and K are X distances in the X
//! mode of the block: diameters in G7, radii in G8, as LinuxCNC halves them
//! in G7 before it uses them.

use crate::error::{CycleError, Field};
use crate::lead::Lead;
use crate::units::{Length, Point, Units, XMode, MAX_LENGTH};

/// One in [`LinuxCncG76::degression`]'s unit: R is held in ten-thousandths.
pub const DEGRESSION_ONE: u32 = 10_000;

/// Largest R the profile accepts, in ten-thousandths (R 100).
pub const MAX_DEGRESSION: u32 = 100 * DEGRESSION_ONE;

/// Q is held in ten-thousandths of a degree; |Q| must be below 90°.
pub const RIGHT_ANGLE: i32 = 900_000;

/// One LinuxCNC G76 threading cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LinuxCncG76 {
    /// Increment system and unit of every length below.
    pub units: Units,
    /// G7 (diameter) or G8 (radius) X words, at the block.
    pub x_mode: XMode,
    /// The tool position before the block: its X is the drive line, its Z
    /// where every pass starts (before the compound shift).
    pub start: Point,
    /// Where the cycle ends: X of the block's X word (the start's X when
    /// there is none) and Z of its Z word; the last move goes there.
    pub end: Point,
    /// P: the pitch, per revolution.
    pub pitch: Lead,
    /// I: the thread peak offset from the drive line, in X units (signed:
    /// negative for an external thread, positive for an internal one).
    pub peak_offset: i64,
    /// J: the initial cut depth from the peak, in X units, > 0.
    pub initial_depth: i64,
    /// R: the depth degression, in ten-thousandths ([`DEGRESSION_ONE`] =
    /// 1), at least 1: pass n cuts at depth `J · n^(1/R)` from the peak.
    pub degression: u32,
    /// K: the full thread depth from the peak, in X units, > J.
    pub full_depth: i64,
    /// Q: the compound slide angle in ten-thousandths of a degree (0 when
    /// absent or written -1, as LinuxCNC reads it), |Q| < 90°.
    pub compound_angle: i32,
    /// H: the spring passes after the first full-depth pass (-1: none at
    /// full depth at all, as LinuxCNC does for H-1).
    pub spring_passes: i32,
    /// E: the taper distance along Z (0: no taper).
    pub taper_distance: i64,
    /// L bit 1: an entry taper.
    pub entry_taper: bool,
    /// L bit 2: an exit taper.
    pub exit_taper: bool,
    /// Most rough passes a cycle may have (the machine's `pass_limit`).
    pub pass_limit: u32,
}

impl LinuxCncG76 {
    /// True for an internal thread (LinuxCNC's "boring": I > 0).
    #[must_use]
    pub const fn internal(&self) -> bool {
        self.peak_offset > 0
    }

    /// σ of reading R-LCNC-PASS: +1 for an external thread (I < 0), -1 for
    /// an internal one; a pass at depth δ cuts at X₀ − σ(|I| + δ).
    #[must_use]
    pub const fn sigma(&self) -> i64 {
        if self.internal() {
            -1
        } else {
            1
        }
    }

    /// Checks the interpreter's conditions on the words and the range
    /// tables: both models call this first, so they refuse the same
    /// cycles with the same error.
    ///
    /// # Errors
    ///
    /// The first violated rule: a coordinate, I, J, K or E outside
    /// ±[`MAX_LENGTH`]; [`CycleError::WordOutOfRange`] for I = 0, J <= 0,
    /// K <= J (LinuxCNC's "In G76, I must not be 0", "In G76, J must be
    /// greater than 0", "In G76, K must be greater than J"), for R above
    /// 100, Q with |Q| >= 90°, H below -1 and a negative E; the lead's own
    /// range.
    ///
    /// ```
    /// use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
    /// use cycleref::{Lead, LeadWord, Point, Units, IncrementSystem, InputUnit, XMode};
    /// let units = Units { system: IncrementSystem::IsC, unit: InputUnit::Metric };
    /// let mut c = LinuxCncG76 {
    ///     units, x_mode: XMode::Radius,
    ///     start: Point::new(140_000, 20_000), end: Point::new(140_000, -200_000),
    ///     pitch: Lead { word: LeadWord::F, mantissa: 15, scale: 1 },
    ///     peak_offset: -10_000, initial_depth: 2_000, degression: 15_000,
    ///     full_depth: 9_200, compound_angle: 295_000, spring_passes: 1,
    ///     taper_distance: 10_000, entry_taper: true, exit_taper: true,
    ///     pass_limit: 1_000_000,
    /// };
    /// assert!(c.validate().is_ok());
    /// c.full_depth = 2_000; // K = J
    /// assert_eq!(c.validate().unwrap_err().to_string(),
    ///     "K (full thread depth) = 0.2000 is outside its range (LinuxCNC: \"In G76, K must be greater than J\")");
    /// ```
    pub fn validate(&self) -> Result<(), CycleError> {
        let c = self;
        let len = |v: i64| Length::new(v, c.units);
        let words = [
            (Field::StartX, c.start.x),
            (Field::StartZ, c.start.z),
            (Field::EndX, c.end.x),
            (Field::EndZ, c.end.z),
            (Field::PeakOffset, c.peak_offset),
            (Field::InitialDepth, c.initial_depth),
            (Field::FullDepth, c.full_depth),
            (Field::TaperDistance, c.taper_distance),
        ];
        for (field, v) in words {
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                return Err(CycleError::OutOfRange { field, value: len(v) });
            }
        }
        let out = |field, v: i64, rule| Err(CycleError::WordOutOfRange { field, value: len(v), rule });
        if c.peak_offset == 0 {
            return out(Field::PeakOffset, 0, "LinuxCNC: \"In G76, I must not be 0\"");
        }
        if c.initial_depth <= 0 {
            return out(
                Field::InitialDepth,
                c.initial_depth,
                "LinuxCNC: \"In G76, J must be greater than 0\"",
            );
        }
        if c.full_depth <= c.initial_depth {
            return out(Field::FullDepth, c.full_depth, "LinuxCNC: \"In G76, K must be greater than J\"");
        }
        if !(DEGRESSION_ONE..=MAX_DEGRESSION).contains(&c.degression) {
            return Err(CycleError::WordOutOfRange {
                field: Field::Degression,
                value: Length { increments: i64::from(c.degression), decimals: 4 },
                rule: "1 <= R <= 100 (R below 1 is read as 1)",
            });
        }
        if c.compound_angle.unsigned_abs() >= RIGHT_ANGLE.unsigned_abs() {
            return Err(CycleError::WordOutOfRange {
                field: Field::CompoundAngle,
                value: Length { increments: i64::from(c.compound_angle), decimals: 4 },
                rule: "-90 < Q < 90 degrees",
            });
        }
        if c.spring_passes < -1 {
            return Err(CycleError::WordOutOfRange {
                field: Field::SpringPasses,
                value: Length { increments: i64::from(c.spring_passes), decimals: 0 },
                rule: "LinuxCNC: \"Negative H word used\" below -1",
            });
        }
        if c.taper_distance < 0 {
            return out(Field::TaperDistance, c.taper_distance, "E >= 0 (LinuxCNC reads a negative E as 0)");
        }
        if !c.pitch.in_range() {
            return Err(CycleError::LeadOutOfRange);
        }
        Ok(())
    }
}
