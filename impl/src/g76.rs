//! The typed parameters of one multiple thread-cutting cycle, G76 or GSK's
//! enhanced G78, as the program reader resolves them (one home, used by the
//! reference model and by the engine alike): G78 is a front end on the same
//! cycle, with infeed modes and a depth mode G76 lacks.
//!
//! Every length is in least increments; radius amounts (k, Δd, Δdmin, d, i,
//! E, J, K) are radius increments whatever [`XMode`] says, while the points
//! A and D carry X in X-word units. The reader has already applied the
//! profile's rules for omitted words (parameters 5140-5143 or No.57-60,
//! modal values) and for the run-out words, so [`RunOut`] says what the
//! cycle must do, not what was written.

use crate::error::{CycleError, Field};
use crate::lead::Lead;
use crate::readings::CycleReadings;
use crate::units::{Length, Point, Units, XMode, MAX_LENGTH};

/// Infeed mode (切入方式): the `D` word of the extended G76 (seed 000), the
/// `P(r)` digits of G78 (reading R-G78INFEED).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Infeed {
    /// G76 D0, G78 r = 2: along the right flank of the thread form (the
    /// original G76).
    RightFlank,
    /// G76 D1, G78 r = 3 (988TA 右中轮流): right flank and centre,
    /// alternately (odd levels right, even levels centre).
    RightCentre,
    /// G76 D2, G78 r = 4 (988TA 左右等量轮流): left and right flanks
    /// alternately, equal amounts: two passes (right, then left) at every
    /// depth level but the last.
    LeftRight,
    /// G78 r = 0 (沿螺纹牙型中线切入): every pass on the centre line of the
    /// final form (radial infeed).
    Centre,
    /// G78 r = 1 (沿螺纹牙型左边切入): every pass on the left flank, the
    /// right flank mirrored about the centre line.
    LeftFlank,
    /// G78 r = 3 on the 980TDi (交错切入): one pass a level, odd levels on the
    /// right flank, even levels on the left (reading R-G78ALT).
    Alternating,
}

impl Infeed {
    /// The rough passes of `levels` depth levels: one a level, but two at
    /// every level except the last in [`Infeed::LeftRight`] (right, then
    /// left). The one home of this count, for the engine and the reference.
    ///
    /// ```
    /// use cycleref::Infeed;
    /// assert_eq!(Infeed::RightFlank.passes(4), 4);
    /// assert_eq!(Infeed::LeftRight.passes(4), 7);
    /// assert_eq!(Infeed::LeftRight.passes(0), 0);
    /// ```
    #[must_use]
    pub const fn passes(self, levels: u64) -> u64 {
        match self {
            Infeed::LeftRight => levels.saturating_mul(2).saturating_sub(1),
            Infeed::RightFlank
            | Infeed::RightCentre
            | Infeed::Centre
            | Infeed::LeftFlank
            | Infeed::Alternating => levels,
        }
    }
}

/// How the rough depths grow (G78 P(m) on the 980TDi, D on the 988TA: 切深
/// 选择).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DepthMode {
    /// 递减式进刀: `round(Δd √n)` with the minimum cut (G76's schedule, the
    /// only one G76 has).
    Decreasing,
    /// 等距离进刀: every rough cut Δd (at least Δdmin, at least one
    /// increment): `D(n) = min(k - d, D(n-1) + max(Δd, Δdmin))`.
    Equal,
}

/// The run-out (退尾) the cycle must make, after the profile's rules for
/// J, K, r and the parameters have been applied by the reader.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RunOut {
    /// No run-out: the cut ends on the line D–E.
    None,
    /// Run-out by amounts: `short` (J) along the short axis, away from the
    /// work, and `long` (K) along the long axis, both radius increments.
    /// `long == 0` is a pull-out along the short axis only.
    Amounts {
        /// J: short-axis travel (radius increments, unsigned).
        short: i64,
        /// K: long-axis length (increments, radius where X is long).
        long: i64,
    },
    /// Run-out from the chamfer amount `r` (P(r) or parameter 5130/No.19):
    /// long-axis length `r * 0.1 * lead`, short-axis travel from the
    /// chamfer angle.
    Chamfer {
        /// r, in tenths of the lead (0..=99).
        tenths_of_lead: u32,
        /// Chamfer angle in degrees from the long axis (parameter 5131;
        /// the reader has already turned 0 into 45).
        angle_degrees: u32,
        /// K when it was programmed and the profile keeps it while J comes
        /// from r (GSK 980TDi G76 note 2).
        long: Option<i64>,
    },
}

impl RunOut {
    /// The range checks of the run-out's own words (J, K ≥ 0 within the
    /// range table, r 0..99, chamfer angle 1..89), in the order of
    /// [`G76Cycle::validate`]; shared by every cycle with a run-out (G76,
    /// G92).
    ///
    /// # Errors
    ///
    /// [`CycleError::OutOfRange`] or [`CycleError::CountOutOfRange`] for
    /// the first word outside its range.
    pub fn validate_words(self, units: Units) -> Result<(), CycleError> {
        let unsigned = |field: Field, v: i64| -> Result<(), CycleError> {
            if !(0..=MAX_LENGTH).contains(&v) {
                return Err(CycleError::OutOfRange { field, value: Length::new(v, units) });
            }
            Ok(())
        };
        match self {
            RunOut::None => {}
            RunOut::Amounts { short, long } => {
                unsigned(Field::RunOutShort, short)?;
                unsigned(Field::RunOutLong, long)?;
            }
            RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
                if let Some(k) = long {
                    unsigned(Field::RunOutLong, k)?;
                }
                if tenths_of_lead > MAX_CHAMFER_TENTHS {
                    return Err(CycleError::CountOutOfRange { field: Field::Chamfer, value: tenths_of_lead });
                }
                if !(1..=89).contains(&angle_degrees) {
                    return Err(CycleError::CountOutOfRange {
                        field: Field::ChamferAngle,
                        value: angle_degrees,
                    });
                }
            }
        }
        Ok(())
    }

    /// The checks of the lead and of the chamfer it makes: F0/I0, a lead
    /// beyond the range tables, and a chamfer `round(r × 0.1 × lead)`
    /// beyond the range table (it is a run-out length, K and J through the
    /// angle, also when K is programmed: an I lead of 0.0001 thread per
    /// inch is 254 m per revolution).
    ///
    /// # Errors
    ///
    /// [`CycleError::ZeroLead`], [`CycleError::LeadOutOfRange`], then
    /// [`CycleError::OutOfRange`] on [`Field::RunOutLong`].
    pub fn validate_lead(self, lead: Lead, units: Units) -> Result<(), CycleError> {
        if lead.is_zero() {
            return Err(CycleError::ZeroLead);
        }
        if !lead.in_range() {
            return Err(CycleError::LeadOutOfRange);
        }
        if let RunOut::Chamfer { tenths_of_lead, .. } = self {
            let chamfer = lead.chamfer_increments(tenths_of_lead, units);
            if chamfer > MAX_LENGTH.unsigned_abs().into() {
                let value = i64::try_from(chamfer).unwrap_or(i64::MAX);
                return Err(CycleError::OutOfRange {
                    field: Field::RunOutLong,
                    value: Length::new(value, units),
                });
            }
        }
        Ok(())
    }
}

/// One G76 multiple thread-cutting cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct G76Cycle {
    /// Increment system and unit of every length below.
    pub units: Units,
    /// Diameter or radius X words.
    pub x_mode: XMode,
    /// A: the tool position before the cycle (起点), where it returns.
    pub start: Point,
    /// D: the thread end point X(U) Z(W) of block 2 (螺纹终点).
    pub end: Point,
    /// R(i): taper, X of the thread start C minus X of D (radius, signed).
    pub taper: i64,
    /// P(k): thread height (牙高), total depth (radius, > 0).
    pub thread_height: i64,
    /// Q(Δd): first depth (第一次切深, radius, > 0).
    pub first_depth: i64,
    /// Q(Δdmin): minimum cut (最小切削量, radius).
    pub min_cut: i64,
    /// R(d): finishing allowance (精车余量, radius).
    pub finishing_allowance: i64,
    /// P(m): finishing passes (精车次数).
    pub finishing_passes: u32,
    /// P(a): tool angle (刀尖角度) in degrees, 0..=99.
    pub tool_angle: u32,
    /// D (G76) or P(r) (G78): infeed mode.
    pub infeed: Infeed,
    /// G78's depth mode; always [`DepthMode::Decreasing`] for G76.
    pub depth_mode: DepthMode,
    /// E: lead-in (旋进) distance along X (radius, unsigned); 0 is none.
    pub lead_in: i64,
    /// L: number of starts (头数), 1..=999.
    pub starts: u32,
    /// F or I: the lead.
    pub lead: Lead,
    /// The run-out to make.
    pub run_out: RunOut,
    /// Largest number of rough passes the cycle may have; beyond it the
    /// cycle is refused before any move is produced.
    pub pass_limit: u32,
    /// The readings in force for this cycle (R-RUNOUT, R-XRUNOUT),
    /// resolved for its profile; [`CycleReadings::DEFAULT`] unless chosen.
    pub readings: CycleReadings,
}

/// The range-table check of a threading cycle's coordinate words, in
/// order (reading R-RANGE): the start point, the end point, then the taper;
/// the first outside ±[`MAX_LENGTH`] is [`CycleError::OutOfRange`]. Shared
/// by G76 and G92.
pub(crate) fn coordinates_in_range(
    units: Units,
    start: Point,
    end: Point,
    taper: i64,
) -> Result<(), CycleError> {
    let words = [
        (Field::StartX, start.x),
        (Field::StartZ, start.z),
        (Field::EndX, end.x),
        (Field::EndZ, end.z),
        (Field::Taper, taper),
    ];
    for (field, v) in words {
        if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
            return Err(CycleError::OutOfRange { field, value: Length::new(v, units) });
        }
    }
    Ok(())
}

/// Default [`G76Cycle::pass_limit`].
pub const DEFAULT_PASS_LIMIT: u32 = 1_000_000;

/// Longest run-out chamfer in tenths of a lead (`r` is two digits).
pub const MAX_CHAMFER_TENTHS: u32 = 99;

impl G76Cycle {
    fn len(&self, v: i64) -> Length {
        Length::new(v, self.units)
    }

    /// Checks the range tables and the alarm conditions that depend only on
    /// the programmed values (seed 000 and manuals/gsk988ta-g76.txt notes
    /// 5-7): both engines call this first, so they refuse the same cycles
    /// with the same error.
    ///
    /// # Errors
    ///
    /// The first violated rule, as a [`CycleError`].
    pub fn validate(&self) -> Result<(), CycleError> {
        let c = self;
        coordinates_in_range(c.units, c.start, c.end, c.taper)?;
        let positive = |field: Field, v: i64| -> Result<(), CycleError> {
            if !(1..=MAX_LENGTH).contains(&v) {
                return Err(CycleError::OutOfRange { field, value: c.len(v) });
            }
            Ok(())
        };
        positive(Field::ThreadHeight, c.thread_height)?;
        positive(Field::FirstDepth, c.first_depth)?;
        let unsigned = |field: Field, v: i64| -> Result<(), CycleError> {
            if !(0..=MAX_LENGTH).contains(&v) {
                return Err(CycleError::OutOfRange { field, value: c.len(v) });
            }
            Ok(())
        };
        unsigned(Field::MinCut, c.min_cut)?;
        unsigned(Field::FinishingAllowance, c.finishing_allowance)?;
        unsigned(Field::LeadIn, c.lead_in)?;
        c.run_out.validate_words(c.units)?;
        if c.finishing_passes > 99 {
            return Err(CycleError::CountOutOfRange {
                field: Field::FinishingPasses,
                value: c.finishing_passes,
            });
        }
        if c.tool_angle > 99 {
            return Err(CycleError::CountOutOfRange { field: Field::ToolAngle, value: c.tool_angle });
        }
        if !(1..=999).contains(&c.starts) {
            return Err(CycleError::CountOutOfRange { field: Field::Starts, value: c.starts });
        }
        c.run_out.validate_lead(c.lead, c.units)?;
        // Note 6: minimum cut or finishing allowance larger than the thread height.
        if c.min_cut > c.thread_height {
            return Err(CycleError::MinCutExceedsHeight {
                min_cut: c.len(c.min_cut),
                height: c.len(c.thread_height),
            });
        }
        if c.finishing_allowance > c.thread_height {
            return Err(CycleError::AllowanceExceedsHeight {
                allowance: c.len(c.finishing_allowance),
                height: c.len(c.thread_height),
            });
        }
        // "G76 代码不能加工端面螺纹": D on the Z of A is a face thread.
        if c.end.z == c.start.z {
            return Err(CycleError::FaceThread);
        }
        Ok(())
    }
}
