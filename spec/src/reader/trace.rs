//! The reader's trace mode: a vendor's toolpath written as plain blocks
//! (an expanded program), read by the program's own reader and rules, with
//! what a trace may not hold refused by line and word (reading
//! R-CHECKWORDS in `docs/INTERPRETATIONS.md`).
//!
//! A trace is a log of moves, not a program: it holds no canned cycle and
//! no subprogram call, writes every length in the program's unit, and its
//! thread moves need no spindle command (the log may leave it out). Every
//! word it holds is one of a plain move, so that nothing that might shape
//! the part is passed over: there is no second table of G codes or lead
//! parser for traces.

use cycleref::units::{InputUnit, Units};

use super::{err, LineReader, MotionMode, State};
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{Block, Word};
use crate::profile::{Dialect, Machine};

impl<'m> LineReader<'m> {
    /// A reader of a trace (an expanded program) for `machine`, in the
    /// `units` of the program it is compared with.
    ///
    /// ```
    /// use cycleref_spec::reader::{Item, LineReader};
    /// use cycleref_spec::{Machine, ProfileName};
    ///
    /// let machine = Machine::new(ProfileName::Gsk980);
    /// let mut trace = LineReader::for_trace(&machine, machine.units());
    /// let mut moves = 0;
    /// for line in ["G00 X80 Z10", "G32 Z-20 F2", "G00 X90"] {
    ///     while let Some(item) = trace.next_in(line.as_bytes()) {
    ///         moves += usize::from(matches!(item?, Item::Move(_) | Item::G32(_)));
    ///     }
    /// }
    /// assert_eq!(moves, 3);
    /// // A canned cycle is no move of a trace.
    /// let mut trace = LineReader::for_trace(&machine, machine.units());
    /// let e = trace.next_in(b"G92 X58 Z-20 F2").unwrap().unwrap_err();
    /// assert_eq!(e.word.as_deref(), Some("G92"));
    /// # Ok::<(), cycleref_spec::ProgramError>(())
    /// ```
    #[must_use]
    pub fn for_trace(machine: &'m Machine, units: Units) -> LineReader<'m> {
        let mut reader = LineReader::new(machine);
        reader.state.trace = true;
        reader.state.units = units;
        reader
    }
}

/// The name of a plain motion in messages.
fn motion_name(m: MotionMode) -> &'static str {
    match m {
        MotionMode::G00 => "rapid",
        MotionMode::G01 => "feed",
        MotionMode::G02 | MotionMode::G03 => "arc",
        MotionMode::G32 | MotionMode::G92 => "thread",
    }
}

impl State<'_> {
    /// A trace's block: no canned cycle (`cycle`, the G word that calls
    /// one), and every word one of a plain move in `motion` (the mode in
    /// force after the block's G codes; `thread` on the linuxcnc profile
    /// for G33), `dwell` for a G04 block (reading R-CHECKWORDS).
    pub(super) fn trace_block(
        &self,
        block: &Block<'_>,
        cycle: Option<&Word<'_>>,
        motion: MotionMode,
        thread: bool,
        dwell: bool,
    ) -> Result<(), ProgramError> {
        let linuxcnc = self.machine.profile.dialect == Dialect::LinuxCnc;
        if let Some(w) = cycle {
            let moves = if linuxcnc { "G0/G1/G2/G3/G33" } else { "G00/G01/G02/G03/G32" };
            return Err(err(
                block,
                Some(w),
                ErrorKind::Unsupported(format!("a trace holds plain {moves} blocks, not canned cycles")),
            ));
        }
        let arc = matches!(motion, MotionMode::G02 | MotionMode::G03) && !thread;
        for w in &block.words {
            let ok =
                match w.letter {
                    'G' | 'M' | 'X' | 'Z' | 'F' | 'S' | 'T' => true,
                    'U' | 'W' => !linuxcnc,
                    'P' => dwell,
                    'Q' => thread && !linuxcnc,
                    'I' => arc || (thread && !linuxcnc),
                    'J' | 'K' if thread && !linuxcnc => return Err(err(
                        block,
                        Some(w),
                        ErrorKind::Unsupported(
                            "a run-out in a trace: a trace holds plain moves; write the run-out as its own \
                             block"
                                .into(),
                        ),
                    )),
                    'K' => arc || thread,
                    'R' if arc => {
                        return Err(err(
                            block,
                            Some(w),
                            ErrorKind::Unsupported(
                                "an arc in a trace gives its centre as I and K: the centre R implies is in \
                             general not a point of the increment grid, so it cannot be compared exactly \
                             (reading R-CHECKARC)"
                                    .into(),
                            ),
                        ))
                    }
                    _ => false,
                };
            if !ok {
                let name = if thread { "thread" } else { motion_name(motion) };
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::Unsupported(format!(
                        "{} (not a word of a plain {name} move in a trace, reading R-CHECKWORDS)",
                        w.letter
                    )),
                ));
            }
        }
        Ok(())
    }

    /// A trace is written in the program's unit (reading R-CHECKWORDS).
    pub(super) fn trace_unit(
        &self,
        block: &Block<'_>,
        w: &Word<'_>,
        unit: InputUnit,
    ) -> Result<(), ProgramError> {
        if unit == self.units.unit {
            Ok(())
        } else {
            Err(err(
                block,
                Some(w),
                ErrorKind::Unsupported(
                    "a change of the input unit in a trace: write the trace in the program's unit".into(),
                ),
            ))
        }
    }
}
