//! The reader's front end for the `linuxcnc` profile: LinuxCNC's word set
//! (`G76 P Z I J R K Q H E L`, G7/G8), with the interpreter's conditions
//! as errors in its own words beside ours (readings R-LCNC-* in
//! `docs/INTERPRETATIONS.md`). The modal state, the lengths and the
//! spindle are the reader's one home; only the words differ.

use cycleref::angle::StartAngle;
use cycleref::g32::{G32Block, G32RunOut};
use cycleref::lead::{Lead, LeadWord, MAX_LEAD_SCALE};
use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE, MAX_DEGRESSION, RIGHT_ANGLE};
use cycleref::units::{InputUnit, Point, XMode};
use rust_decimal::Decimal;

use super::{err, G32Call, Item, LinuxCncCall, MotionMode, State};
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{Block, Word};
use crate::readings::LcncG7;

/// The G codes this front end reads (anything else is refused by name).
const KNOWN: &str =
    "G0-G4, G7, G8, G18, G20, G21, G33, G40, G54-G59, G61, G64, G76, G80, G90, G94, G95, G96, G97";

/// LinuxCNC's own text of an error, beside ours.
const P_MISSING: &str = "LinuxCNC: \"P word missing with G76\"";
const IJK_MISSING: &str = "LinuxCNC: \"I J or K words missing with G76\"";

impl State<'_> {
    /// One block of a LinuxCNC program.
    pub(super) fn linuxcnc_block<'a>(&mut self, block: Block<'a>) -> Result<Item<'a>, ProgramError> {
        // A block with words ends a run of G33 moves unless it is one.
        let continuing = !block.words.is_empty() && std::mem::take(&mut self.lcnc_thread_run);
        let mut motion = None;
        let mut g76 = false;
        let mut g33 = false;
        let mut mode = None;
        let mut cycle_word = None;
        let mut dwell = false;
        for w in block.all('G') {
            // A whole code: `integer` gives None for any other.
            let whole = w.number().integer();
            match whole {
                Some(c @ 0..=3) => motion = MotionMode::plain(c),
                Some(76) => {
                    g76 = true;
                    cycle_word = cycle_word.or(Some(w));
                }
                Some(33) => g33 = true,
                Some(7) => mode = Some(XMode::Diameter),
                Some(8) => mode = Some(XMode::Radius),
                Some(20) => self.set_unit(&block, w, InputUnit::Inch)?,
                Some(21) => self.set_unit(&block, w, InputUnit::Metric)?,
                Some(4) => dwell = true,
                Some(18 | 40 | 54..=59 | 61 | 64 | 80 | 90 | 94 | 95 | 96 | 97) => {}
                Some(41 | 42) => {
                    return Err(err(
                        &block,
                        Some(w),
                        ErrorKind::Unsupported(
                            "cutter radius compensation (not modelled; LinuxCNC refuses a G76 with it on: \
                             \"Cannot use G76 threading cycle with cutter radius compensation on\")"
                                .into(),
                        ),
                    ))
                }
                _ => {
                    let code = w.number().decimal().unwrap_or(Decimal::NEGATIVE_ONE);
                    return Err(err(
                        &block,
                        Some(w),
                        ErrorKind::Unsupported(format!("G{code} (the linuxcnc profile reads {KNOWN})")),
                    ));
                }
            }
        }
        for w in &block.words {
            if matches!(w.letter, 'U' | 'W' | 'Y' | 'A' | 'B' | 'C' | 'V') {
                return Err(err(
                    &block,
                    Some(w),
                    ErrorKind::Unsupported(format!(
                        "{} (an axis of its own in LinuxCNC, not incremental X or Z; the reader models the X \
                         and Z of a lathe)",
                        w.letter
                    )),
                ));
            }
        }
        for w in block.all('M') {
            match w.number().integer() {
                Some(3 | 4) => self.spindle_on = true,
                Some(5) => self.spindle_on = false,
                Some(98 | 99) => return Err(super::subprogram(&block, w)),
                // M2 and M30 end the program (reading R-PROGRAMEND); a
                // trace goes on after them.
                Some(2 | 30) => self.program_end = !self.trace,
                _ => {}
            }
        }
        if self.trace {
            let m = motion.unwrap_or(self.motion);
            let thread = g33 || (self.lcnc_g33 && motion.is_none() && !g76);
            self.trace_block(&block, cycle_word, m, thread, dwell)?;
        }
        // Reading R-LCNC-G7: a G7/G8 that changes the X mode in a G76
        // block is refused, or read as LinuxCNC reads it (`switched`: the
        // mode switched to, whose G76 words LinuxCNC scales once more).
        let switched = match mode {
            Some(m) if g76 && m != self.x_mode => match self.machine.readings.lcnc_g7 {
                LcncG7::AsInterpreter => Some(m),
                LcncG7::Refuse => return Err(err(
                    &block,
                    None,
                    ErrorKind::Unsupported(
                        "a G7/G8 that changes the X mode in the G76 block (LinuxCNC then scales I, J and K \
                             twice, interp_convert.cc l.2773-2777 and l.5724-5728: program G7/G8 in a block \
                             of its own; or --reading R-LCNC-G7=as-interpreter)"
                            .into(),
                    ),
                )),
            },
            _ => None,
        };
        if let Some(m) = mode {
            self.switch_x_mode(&block, m)?;
        }
        if usize::from(g76) + usize::from(g33) + usize::from(motion.is_some()) > 1 {
            return Err(err(
                &block,
                None,
                ErrorKind::Unsupported("two motion G codes in one block (of G0-G3, G33, G76)".into()),
            ));
        }
        if let Some(m) = motion {
            self.motion = m;
        }
        if motion.is_some() || g33 || g76 {
            self.lcnc_g76 = g76;
            self.lcnc_g33 = g33;
        }
        let axes = block.has('X') || block.has('Z');
        if g76 || (self.lcnc_g76 && axes) {
            return self.linuxcnc_g76(block, switched).map(Item::LinuxCncG76);
        }
        if g33 || (self.lcnc_g33 && axes) {
            return self.linuxcnc_g33(block, continuing).map(Item::G32);
        }
        if axes && !dwell {
            let from = (self.x, self.z);
            self.x = self.axis(&block, block.get('X')?, None, self.x)?;
            self.z = self.axis(&block, block.get('Z')?, None, self.z)?;
            self.moved = true;
            return Ok(Item::Move(self.plain_move(block, from)));
        }
        Ok(Item::Source(block))
    }

    /// G7/G8: the position kept in the old mode is converted (a radius
    /// doubles; a diameter halves, and must be a whole number of
    /// increments as a radius).
    fn switch_x_mode(&mut self, block: &Block<'_>, to: XMode) -> Result<(), ProgramError> {
        if to == self.x_mode {
            return Ok(());
        }
        if let Some(x) = self.x {
            self.x = Some(match to {
                XMode::Diameter => x * 2,
                XMode::Radius if x % 2 == 0 => x / 2,
                XMode::Radius => {
                    return Err(err(
                        block,
                        None,
                        ErrorKind::NotInIncrements {
                            increment: "the X position as a radius after G8 (half of an odd diameter)".into(),
                        },
                    ))
                }
            });
        }
        self.x_mode = to;
        Ok(())
    }

    /// A decimal word with at most `scale` decimals, as `mantissa`, `scale`.
    fn fixed(block: &Block<'_>, w: &Word<'_>, scale: u32, range: &str) -> Result<i64, ProgramError> {
        let out = || err(block, Some(w), ErrorKind::OutOfRange { range: range.into() });
        let d = w.number().decimal().ok_or_else(out)?;
        let scaled = d.checked_mul(Decimal::from(10_i64.pow(scale))).ok_or_else(out)?;
        if !scaled.fract().is_zero() {
            return Err(err(
                block,
                Some(w),
                ErrorKind::NotInIncrements { increment: format!("{} of its unit", Decimal::new(1, scale)) },
            ));
        }
        i64::try_from(scaled).map_err(|_| out())
    }

    /// A whole-number word (LinuxCNC's integer words H and L).
    fn whole(block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        let d = w.number().decimal().filter(|d| d.fract().is_zero());
        d.and_then(|d| i64::try_from(d).ok())
            .ok_or_else(|| err(block, Some(w), ErrorKind::OutOfRange { range: "a whole number".into() }))
    }

    /// `G33 X Z K`: one move synchronised with the spindle, K the distance
    /// per revolution along the move (LinuxCNC's `START_SPEED_FEED_SYNCH(K)`
    /// before `STRAIGHT_FEED`, interp_convert.cc l.5520-5531; not halved in
    /// G7). The spindle index is awaited only where synchronisation starts:
    /// a G33 right after another G33 continues it (`continuing`; the
    /// trajectory planner waits only "if we aren't already synced",
    /// tp.c l.3531-3538, R-LCNC-G33).
    fn linuxcnc_g33<'a>(&mut self, block: Block<'a>, continuing: bool) -> Result<G32Call<'a>, ProgramError> {
        if let Some(f) = block.get('F')? {
            return Err(err(
                &block,
                Some(f),
                ErrorKind::Unsupported(
                    "F in a G33 block (LinuxCNC: \"F word used with a g33/g33.1\")".into(),
                ),
            ));
        }
        self.check_addresses(&block, "G33", "GXZKMST", "")?;
        let k = block.get('K')?.ok_or_else(|| {
            err(
                &block,
                None,
                ErrorKind::Missing {
                    what: "K (distance per revolution)",
                    rule: "LinuxCNC: \"K word missing with g33/g33.1\"",
                },
            )
        })?;
        let (x0, z0) = self.turning_at(&block, "LinuxCNC: \"Spindle not turning in G33\"")?;
        let lead = Self::pitch(&block, k)?;
        let end = Point::new(
            block.get('X')?.map(|w| self.length(&block, w)).transpose()?.unwrap_or(x0),
            block.get('Z')?.map(|w| self.length(&block, w)).transpose()?.unwrap_or(z0),
        );
        let g32 = G32Block {
            units: self.units,
            x_mode: self.x_mode,
            start: Point::new(x0, z0),
            end,
            lead,
            run_out: G32RunOut::None,
            start_angle: StartAngle::ZERO,
            sync: !continuing,
            // G33 has no run-out, so R-G32LONG's tie moves nothing.
            readings: cycleref::CycleReadings::DEFAULT,
        };
        g32.validate().map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        self.x = Some(end.x);
        self.z = Some(end.z);
        self.moved = true;
        self.lcnc_thread_run = true;
        Ok(G32Call { code: "G33", block, g32 })
    }

    /// Where a threading block starts: the spindle must turn (M3 or M4; its
    /// speed may be 0, as `convert_motion` does not check it; `rule` is the
    /// interpreter's message for the block) and the position be known.
    fn turning_at(&self, block: &Block<'_>, rule: &'static str) -> Result<(i64, i64), ProgramError> {
        // A trace is a log of moves: it need not hold the spindle's words.
        if !self.spindle_on && !self.trace {
            return Err(err(block, None, ErrorKind::Missing { what: "M3 or M4 (a turning spindle)", rule }));
        }
        match (self.x, self.z) {
            (Some(x0), Some(z0)) => Ok((x0, z0)),
            _ => Err(err(block, None, ErrorKind::PositionUnknown)),
        }
    }

    /// A pitch (G76 P, G33 K): > 0, at most 6 decimals, kept with the
    /// fewest decimals that hold it (P1.5 is 15 tenths).
    fn pitch(block: &Block<'_>, w: &Word<'_>) -> Result<Lead, ProgramError> {
        let mut scale = MAX_LEAD_SCALE;
        let range = format!("{} > 0 with at most 6 decimals", w.letter);
        let mantissa = Self::fixed(block, w, scale, &range)?;
        let mut mantissa = u64::try_from(mantissa).ok().filter(|m| *m > 0).ok_or_else(|| {
            err(block, Some(w), ErrorKind::OutOfRange { range: format!("{} > 0", w.letter) })
        })?;
        while scale > 0 && mantissa % 10 == 0 {
            mantissa /= 10;
            scale -= 1;
        }
        // LinuxCNC's pitch, written K as a G33 writes it.
        Ok(Lead { word: LeadWord::K, mantissa, scale })
    }

    /// `G76 P Z I J R K Q H E L` (X optional), LinuxCNC's threading cycle;
    /// `switched`: the X mode a G7/G8 of this block switched to under
    /// R-LCNC-G7 `as-interpreter`, where I, J and K are scaled as
    /// LinuxCNC's `convert_lathe_diameter_mode` scales them (halved to G7,
    /// a half increment refused as any length finer than the increment;
    /// doubled to G8).
    fn linuxcnc_g76<'a>(
        &mut self,
        block: Block<'a>,
        switched: Option<XMode>,
    ) -> Result<LinuxCncCall<'a>, ProgramError> {
        self.check_addresses(&block, "G76", "GXZPIJRKQHELMSTF", "")?;
        let (x0, z0) = self.turning_at(&block, "LinuxCNC: \"Chosen spindle (0) not turning in G76\"")?;
        let p = block.get('P')?.ok_or_else(|| {
            err(&block, None, ErrorKind::Missing { what: "P (thread pitch)", rule: P_MISSING })
        })?;
        let (Some(i), Some(j), Some(k)) = (block.get('I')?, block.get('J')?, block.get('K')?) else {
            return Err(err(
                &block,
                None,
                ErrorKind::Missing {
                    what: "I, J and K (peak offset, first depth, full depth)",
                    rule: IJK_MISSING,
                },
            ));
        };
        // P: the pitch, > 0 (the interpreter accepts any P but -1, its
        // "missing" value; a pitch of 0 or below cuts no thread: refused).
        let pitch = Self::pitch(&block, p)?;
        let end_x = match block.get('X')? {
            Some(w) => self.length(&block, w)?,
            None => x0,
        };
        let end_z = match block.get('Z')? {
            Some(w) => self.length(&block, w)?,
            None => z0,
        };
        if end_z == z0 {
            // Beyond the interpreter (R-LCNC-G33): a thread of no length,
            // whose passes would be G33 moves our reader refuses.
            return Err(err(
                &block,
                block.get('Z')?,
                ErrorKind::OutOfRange {
                    range: "a Z other than the current Z (a thread of no length, reading R-LCNC-G33)".into(),
                },
            ));
        }
        let scaled = |w: &Word<'_>, v: i64| -> Result<i64, ProgramError> {
            match switched {
                None => Ok(v),
                // Doubled within i64 (a length is below 2^40); the range
                // table is the cycle's check (`LinuxCncG76::validate`).
                Some(XMode::Radius) => v.checked_mul(2).ok_or_else(|| {
                    err(
                        &block,
                        Some(w),
                        ErrorKind::OutOfRange { range: "a length doubled by G8 (R-LCNC-G7)".into() },
                    )
                }),
                Some(XMode::Diameter) if v % 2 == 0 => Ok(v / 2),
                Some(XMode::Diameter) => Err(err(
                    &block,
                    Some(w),
                    ErrorKind::NotInIncrements { increment: "the word halved by G7 (R-LCNC-G7)".into() },
                )),
            }
        };
        let peak_offset = scaled(i, self.length(&block, i)?)?;
        let initial_depth = scaled(j, self.length(&block, j)?)?;
        let full_depth = scaled(k, self.length(&block, k)?)?;
        // R: below 1 or absent, 1 (R-LCNC-WORDS, l.5748).
        let degression = match block.get('R')? {
            Some(w) => {
                let v = Self::fixed(&block, w, 4, "R with at most 4 decimals")?;
                let one = i64::from(DEGRESSION_ONE);
                if v > i64::from(MAX_DEGRESSION) {
                    return Err(err(&block, Some(w), ErrorKind::OutOfRange { range: "R <= 100".into() }));
                }
                u32::try_from(v.max(one)).unwrap_or(DEGRESSION_ONE)
            }
            None => DEGRESSION_ONE,
        };
        // Q: absent or -1 is 0 (l.5739); |Q| < 90°.
        let compound_angle = match block.get('Q')? {
            Some(w) => {
                let v = Self::fixed(&block, w, 4, "Q in degrees with at most 4 decimals")?;
                if v == -10_000 {
                    0
                } else {
                    i32::try_from(v)
                        .ok()
                        .filter(|v| v.unsigned_abs() < RIGHT_ANGLE.unsigned_abs())
                        .ok_or_else(|| {
                            err(
                                &block,
                                Some(w),
                                ErrorKind::OutOfRange { range: "-90 < Q < 90 degrees".into() },
                            )
                        })?
                }
            }
            None => 0,
        };
        // H: whole, >= -1 (read_h: "Negative H word used" below -1).
        let spring_passes = match block.get('H')? {
            Some(w) => {
                let v = Self::whole(&block, w)?;
                i32::try_from(v).ok().filter(|v| *v >= -1 && *v <= 999_999).ok_or_else(|| {
                    err(
                        &block,
                        Some(w),
                        ErrorKind::OutOfRange {
                            range: "-1..999999 (LinuxCNC: \"Negative H word used\")".into(),
                        },
                    )
                })?
            }
            None => 0,
        };
        // E: a length, below 0 read as 0 (l.5755).
        let taper_distance = match block.get('E')? {
            Some(w) => self.length(&block, w)?.max(0),
            None => 0,
        };
        // L: whole, >= 0 (read_l: "Negative L word used"); bits 1 and 2.
        let taper_ends = match block.get('L')? {
            Some(w) => {
                let v = Self::whole(&block, w)?;
                if v < 0 {
                    return Err(err(
                        &block,
                        Some(w),
                        ErrorKind::OutOfRange { range: "L >= 0 (LinuxCNC: \"Negative L word used\")".into() },
                    ));
                }
                v
            }
            None => 0,
        };
        let cycle = LinuxCncG76 {
            units: self.units,
            x_mode: self.x_mode,
            start: Point::new(x0, z0),
            end: Point::new(end_x, end_z),
            pitch,
            peak_offset,
            initial_depth,
            degression,
            full_depth,
            compound_angle,
            spring_passes,
            taper_distance,
            entry_taper: taper_ends & 1 != 0,
            exit_taper: taper_ends & 2 != 0,
            pass_limit: self.machine.pass_limit,
        };
        cycle.validate().map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        // l.5791-5794: the tool ends at the block's X Z.
        self.x = Some(end_x);
        self.z = Some(end_z);
        self.moved = true;
        Ok(LinuxCncCall { block, cycle })
    }
}
