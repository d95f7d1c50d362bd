//! The typed parameters of one G92 thread-cutting cycle block (螺纹切削循环,
//! manuals/gsk980tdi-g92.txt, manuals/gsk988ta-g92.txt, FANUC's G92), as
//! the program reader resolves them: one home, used by the reference model
//! and the engine alike.
//!
//! A G92 block is one pass: A → B (X infeed, rapid) → thread to the cut end
//! C → run-out → retract in X to the X of A (rapid) → return in Z to A
//! (980TDi "循环过程" ①-④). It is the pass of a G76 cycle
//! ([`crate::engine::g76`]) at the programmed X: the engine expands it on
//! the same pass model.
//!
//! | point | definition |
//! |---|---|
//! | A | start point (起点): the tool position before the block, where it returns |
//! | B | cut start (切削起点): Z of A, X of C plus R (radius) |
//! | C | cut end (切削终点): X(U) Z(W) of the block |
//!
//! The reader has applied the profile's rules for the modal words (X, Z,
//! R, F/I, J, K, L) and for the run-out (reading R-G92RUNOUT), so
//! [`G92Cycle::run_out`] says what the block must do.

use crate::angle::StartAngle;
use crate::error::{CycleError, Field};
use crate::g76::{coordinates_in_range, RunOut};
use crate::lead::Lead;
use crate::readings::CycleReadings;
use crate::units::{Length, Point, Units, XMode};

/// One G92 thread-cutting cycle block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct G92Cycle {
    /// Increment system and unit of every length below.
    pub units: Units,
    /// Diameter or radius X words.
    pub x_mode: XMode,
    /// A: the tool position before the block (起点), where it returns.
    pub start: Point,
    /// C: the cut end X(U) Z(W) (切削终点).
    pub end: Point,
    /// R: X of the cut start B minus X of C (radius, signed; 0 for a
    /// straight thread).
    pub taper: i64,
    /// F or I: the lead.
    pub lead: Lead,
    /// The run-out to make (J, K, or the chamfer of parameter 5130/No.19).
    pub run_out: RunOut,
    /// L: number of starts (头数), 1..=999 (980TDi 1..99, the reader's
    /// range check).
    pub starts: u32,
    /// Q (988TA): the spindle angle of the first start (起始角); the other
    /// starts follow at 360° / L.
    pub start_angle: StartAngle,
    /// P1 (988TA): a face thread (端面螺纹). The long axis is X and the
    /// short axis Z: B = (X of A, Z of C + R), the cut runs along X, J is
    /// along Z and K along X (radius), the retract runs along Z to the Z
    /// of A and the return along X (reading R-G92FACE).
    pub face: bool,
    /// The readings in force for this block (R-RUNOUT, R-XRUNOUT),
    /// resolved for its profile; [`CycleReadings::DEFAULT`] unless chosen.
    pub readings: CycleReadings,
}

impl G92Cycle {
    /// Checks the range tables and the alarms that depend only on the
    /// programmed values: both engines call this first, so they refuse the
    /// same blocks with the same error.
    ///
    /// # Errors
    ///
    /// The first violated rule, as a [`CycleError`]: a coordinate or R
    /// outside the range table, the run-out words, L outside 1..999, the
    /// lead, then [`CycleError::FaceThread`] when C has the Z of A (980TDi:
    /// "也不能加工端面螺纹") on an axial thread, [`CycleError::NoThreadLength`]
    /// when C has the X of A on a face thread and
    /// [`CycleError::SteepFaceThread`] when its R exceeds its X travel
    /// (but under reading R-LONG988 `table`).
    pub fn validate(&self) -> Result<(), CycleError> {
        let c = self;
        coordinates_in_range(c.units, c.start, c.end, c.taper)?;
        c.run_out.validate_words(c.units)?;
        if !(1..=999).contains(&c.starts) {
            return Err(CycleError::CountOutOfRange { field: Field::Starts, value: c.starts });
        }
        c.run_out.validate_lead(c.lead, c.units)?;
        if !c.face && c.end.z == c.start.z {
            return Err(CycleError::FaceThread);
        }
        if c.face && c.end.x == c.start.x {
            return Err(CycleError::NoThreadLength);
        }
        // Reading R-G92FACE: a face thread's long axis is X, so its Z travel
        // R must not exceed its X travel as a radius (R-G32LONG would make
        // Z the long axis of the cut, and the lead would apply along Z).
        // Under reading R-LONG988 `table` the 988TA's table ("P = 1（端面螺纹）
        // 长轴 纵轴") makes X long whatever the displacements, as it makes Z
        // long on an axial steep taper: the cycle is made, and only the nc
        // output, whose G32 blocks would be read Z-long, refuses it.
        let travel = (c.end.x - c.start.x).unsigned_abs();
        // xf ≤ 2 and |R| ≤ MAX_LENGTH (checked above): the product fits.
        if c.face
            && !c.readings.long_axis_by_table
            && c.x_mode.factor().unsigned_abs() * c.taper.unsigned_abs() > travel
        {
            return Err(CycleError::SteepFaceThread {
                taper: Length::new(c.taper, c.units),
                travel: Length::new(c.end.x - c.start.x, c.units),
            });
        }
        Ok(())
    }
}
