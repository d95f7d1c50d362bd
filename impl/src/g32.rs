//! The typed parameters of one G32 block (constant-lead thread cutting), as
//! the program reader resolves them (seed 002, manuals/gsk980tdi-g32.txt,
//! manuals/gsk988ta-g32.txt): one home, used by the reference model and the
//! engine alike.
//!
//! The reader has applied the profile's run-out rules (J, K, modal, the six
//! rules of seed 002) and the continuous-thread rules (which block
//! synchronises with the spindle, which Q counts), so the block says what
//! the control must do.

use crate::angle::StartAngle;
use crate::error::{CycleError, Field};
use crate::lead::Lead;
use crate::units::{Length, Point, Units, XMode, MAX_LENGTH};

/// The run-out of a G32 block, after the profile's rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum G32RunOut {
    /// No run-out: the thread ends at the programmed end point.
    None,
    /// Run-out: it starts `long` (K) before the end along the long axis and
    /// ends at the end's long-axis coordinate displaced `short` (J, signed)
    /// along the short axis.
    Amounts {
        /// J: signed short-axis displacement (radius increments when the
        /// short axis is X).
        short: i64,
        /// K: long-axis length (radius increments when the long axis is
        /// X), at least 0.
        long: i64,
    },
}

/// One G32 block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct G32Block {
    /// Increment system and unit of every length below.
    pub units: Units,
    /// Diameter or radius X words.
    pub x_mode: XMode,
    /// Where the tool is when the block starts.
    pub start: Point,
    /// The programmed end point X(U) Z(W).
    pub end: Point,
    /// F or I.
    pub lead: Lead,
    /// The run-out.
    pub run_out: G32RunOut,
    /// The spindle angle of the synchronised run this block belongs to: the
    /// first block's Q (later blocks' Q are ignored).
    pub start_angle: StartAngle,
    /// True when this block starts a synchronised run (the control waits
    /// for the one-revolution signal); false on a continuation block of a
    /// continuous thread.
    pub sync: bool,
    /// The readings in force (of these, G32 takes R-G32LONG's tie,
    /// [`CycleReadings::g32_tie_z`](crate::CycleReadings::g32_tie_z)).
    pub readings: crate::CycleReadings,
}

impl G32Block {
    /// Checks the range tables and the alarms that depend only on the
    /// programmed values: both engines call this first.
    ///
    /// # Errors
    ///
    /// The first violated rule.
    pub fn validate(&self) -> Result<(), CycleError> {
        let len = |v: i64| Length::new(v, self.units);
        let mut count = crate::loop_counters::count!(G32_VALIDATE);
        for (field, v) in [
            (Field::StartX, self.start.x),
            (Field::StartZ, self.start.z),
            (Field::EndX, self.end.x),
            (Field::EndZ, self.end.z),
        ] {
            count.tick();
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                return Err(CycleError::OutOfRange { field, value: len(v) });
            }
        }
        if self.lead.is_zero() {
            return Err(CycleError::ZeroLead);
        }
        if !self.lead.in_range() {
            return Err(CycleError::LeadOutOfRange);
        }
        if self.start == self.end {
            return Err(CycleError::NoMotion);
        }
        if let G32RunOut::Amounts { short, long } = self.run_out {
            if short.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                return Err(CycleError::OutOfRange { field: Field::RunOutShort, value: len(short) });
            }
            if !(0..=MAX_LENGTH).contains(&long) {
                return Err(CycleError::OutOfRange { field: Field::RunOutLong, value: len(long) });
            }
        }
        Ok(())
    }
}
