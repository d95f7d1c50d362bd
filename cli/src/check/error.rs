//! The errors of `check`'s two toolpaths, typed: a block whose step cannot
//! be compared ([`StepError`], in our program or in a trace read as a
//! program) and a trace that cannot be read ([`TraceError`]). Each variant
//! is one rule, with the line (and the word, CSV column or call) it is
//! about; `Display` is the message, without the file's name (added once,
//! where the file is known), and `stable_kind` the kind `error[KIND]`
//! prints.

use std::borrow::Cow;
use std::fmt;
use std::io;

use cycleref_spec::rs274::{CanonError, CanonUnits};
use cycleref_spec::ProgramError;
use rust_decimal::Decimal;

/// A block whose step cannot be compared (reading R-CHECKARC), of our
/// program or of a trace read as a program. `word` is the word to blame
/// as written, when one is.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub(crate) enum StepError {
    /// A G32 or G92 block given as a plain move.
    ThreadNotPlain {
        /// The block's line.
        line: usize,
    },
    /// An arc's I beyond the range table.
    CentreOutOfRange {
        /// The block's line.
        line: usize,
        /// The I word.
        word: String,
    },
    /// An arc's I that is not a whole number of X increments.
    CentreNotInIncrements {
        /// The block's line.
        line: usize,
        /// The I word.
        word: String,
    },
    /// An arc given by its radius R.
    ArcByRadius {
        /// The block's line.
        line: usize,
        /// The R word.
        word: String,
    },
    /// An arc with neither I nor K.
    ArcWithoutCentre {
        /// The block's line.
        line: usize,
        /// The G02 or G03 word, when the block has it.
        word: Option<String>,
    },
    /// An arc before both X and Z are known.
    ArcStartUnknown {
        /// The block's line.
        line: usize,
        /// The G02 or G03 word, when the block has it.
        word: Option<String>,
    },
    /// A word of the arc the program reader refuses.
    Program(ProgramError),
}

impl StepError {
    /// The rule's name, without the area: `thread_not_plain`,
    /// `out_of_range`, `not_in_increments`, `arc_by_r`,
    /// `arc_without_centre`, `arc_start_unknown`, or a program error's
    /// stable kind.
    pub(crate) fn name(&self) -> Cow<'static, str> {
        Cow::Borrowed(match self {
            StepError::ThreadNotPlain { .. } => "thread_not_plain",
            StepError::CentreOutOfRange { .. } => "out_of_range",
            StepError::CentreNotInIncrements { .. } => "not_in_increments",
            StepError::ArcByRadius { .. } => "arc_by_r",
            StepError::ArcWithoutCentre { .. } => "arc_without_centre",
            StepError::ArcStartUnknown { .. } => "arc_start_unknown",
            StepError::Program(e) => return Cow::Owned(e.kind.stable_kind()),
        })
    }

    /// The stable kind of the error in our program: `check:` and its name
    /// (`check:arc_by_r`).
    pub(crate) fn stable_kind(&self) -> Cow<'static, str> {
        Cow::Owned(format!("check:{}", self.name()))
    }
}

/// `line N, word `W`: ` or `line N: `, the word cut and escaped as the
/// program reader's errors show it ([`cycleref_spec::error::shown`]): a
/// huge word or a control byte is never echoed whole or raw.
fn at(f: &mut fmt::Formatter<'_>, line: usize, word: Option<&str>) -> fmt::Result {
    match word {
        Some(w) => write!(f, "line {line}, word `{}`: ", cycleref_spec::error::shown(w)),
        None => write!(f, "line {line}: "),
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::ThreadNotPlain { line } => {
                at(f, *line, None)?;
                f.write_str("a thread block is no plain move")
            }
            StepError::CentreOutOfRange { line, word } => {
                at(f, *line, Some(word))?;
                f.write_str("the arc centre distance is outside the range table")
            }
            StepError::CentreNotInIncrements { line, word } => {
                at(f, *line, Some(word))?;
                f.write_str(
                    "I is not a whole number of X increments (a radius; one more decimal than the increment \
                     only when X is a diameter)",
                )
            }
            StepError::ArcByRadius { line, word } => {
                at(f, *line, Some(word))?;
                f.write_str(
                    "an arc is compared by its centre: give I and K (the centre R implies is in general not \
                     a point of the increment grid, reading R-CHECKARC)",
                )
            }
            StepError::ArcWithoutCentre { line, word } => {
                at(f, *line, word.as_deref())?;
                f.write_str("an arc without a centre: give I and K (reading R-CHECKARC)")
            }
            StepError::ArcStartUnknown { line, word } => {
                at(f, *line, word.as_deref())?;
                f.write_str("an arc whose start point is not known (no earlier block gives both X and Z)")
            }
            StepError::Program(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for StepError {}

/// Why a trace cannot be read, or holds what `check` cannot compare. A
/// CSV row's error names the CSV line and the column; the other formats'
/// the line (and word, or call).
#[derive(Debug)]
#[non_exhaustive]
pub(crate) enum TraceError {
    /// The trace's file cannot be opened.
    CannotOpen {
        /// The path, as given.
        path: String,
        /// Why.
        error: io::Error,
    },
    /// A line cannot be read.
    CannotRead {
        /// The line.
        line: usize,
        /// Why.
        error: io::Error,
    },
    /// A line that is not UTF-8.
    NotUtf8 {
        /// The line.
        line: usize,
        /// The 1-based byte of the line that is not UTF-8.
        byte: usize,
    },
    /// A line of an expanded program the program reader refuses.
    Program {
        /// The reader's error.
        error: ProgramError,
        /// The line looks like a CSV header (the hint is given).
        csv_header: bool,
    },
    /// A block of an expanded program whose step cannot be compared.
    Step {
        /// Why.
        error: StepError,
        /// The line looks like a CSV header (the hint is given).
        csv_header: bool,
    },
    /// A canned cycle in an expanded program.
    CannedCycle {
        /// The block's line.
        line: usize,
    },
    /// A CSV header without the columns motion, x and z.
    CsvHeaderIncomplete {
        /// The header's line.
        line: usize,
    },
    /// A CSV header naming a column no trace has.
    CsvUnknownColumn {
        /// The header's line.
        line: usize,
        /// The column.
        column: String,
    },
    /// A CSV header naming a column twice.
    CsvColumnTwice {
        /// The header's line.
        line: usize,
        /// The column.
        column: String,
    },
    /// A CSV row with more fields than the header names.
    CsvTooManyFields {
        /// The row's line.
        line: usize,
        /// Its fields.
        fields: usize,
        /// The header's columns.
        columns: usize,
    },
    /// A CSV motion `arc` without its direction.
    CsvArcDirection {
        /// The row's line.
        line: usize,
    },
    /// A CSV motion no move has.
    CsvUnknownMotion {
        /// The row's line.
        line: usize,
        /// The motion.
        motion: String,
    },
    /// A CSV row without a length it needs (x, z; cx, cz of an arc).
    CsvMissing {
        /// The row's line.
        line: usize,
        /// The column.
        column: &'static str,
    },
    /// A CSV length that is not a decimal.
    CsvNotADecimal {
        /// The row's line.
        line: usize,
        /// The column.
        column: &'static str,
        /// The field.
        value: String,
    },
    /// A CSV length that is not a whole number of increments.
    CsvNotInIncrements {
        /// The row's line.
        line: usize,
        /// The column.
        column: &'static str,
        /// The field.
        value: String,
    },
    /// A CSV length beyond the range table.
    CsvOutOfRange {
        /// The row's line.
        line: usize,
        /// The column.
        column: &'static str,
        /// The field.
        value: String,
    },
    /// A CSV lead that is not a lead within the range tables.
    CsvBadLead {
        /// The row's line.
        line: usize,
        /// The field.
        value: String,
    },
    /// A lead or q on a CSV row that is not a thread move.
    CsvNotAThread {
        /// The row's line.
        line: usize,
        /// The column (`lead`, `q`).
        column: &'static str,
        /// The field.
        value: String,
    },
    /// A CSV thread row without its lead.
    CsvThreadWithoutLead {
        /// The row's line.
        line: usize,
    },
    /// A CSV start angle q that is not one.
    CsvBadStartAngle {
        /// The row's line.
        line: usize,
        /// The field.
        value: String,
    },
    /// An arc centre on a CSV row that is not an arc.
    CsvCentreOffArc {
        /// The row's line.
        line: usize,
    },
    /// A CSV arc without a centre (reading R-CHECKARC).
    CsvArcWithoutCentre {
        /// The row's line.
        line: usize,
    },
    /// A CSV arc's centre given both ways.
    CsvCentreTwice {
        /// The row's line.
        line: usize,
    },
    /// A CSV arc by i and k, and no earlier row gives its start.
    CsvArcStartUnknown {
        /// The row's line.
        line: usize,
    },
    /// A line of rs274's output that is not a call it reads.
    Canon(CanonError),
    /// An rs274 length that is not a whole number of increments.
    CanonNotInIncrements {
        /// The call's line.
        line: usize,
        /// The coordinate (`X`, `the centre's Z`).
        what: &'static str,
        /// Its value.
        value: Decimal,
    },
    /// An rs274 length beyond the range table.
    CanonOutOfRange {
        /// The call's line.
        line: usize,
        /// The coordinate.
        what: &'static str,
        /// Its value.
        value: Decimal,
    },
    /// An rs274 motion in a length unit that is not the program's.
    CanonUnits {
        /// The call's line.
        line: usize,
        /// The call.
        call: &'static str,
        /// The unit in force.
        trace: CanonUnits,
        /// The program's.
        program: CanonUnits,
    },
    /// An rs274 motion under an XY rotation.
    CanonRotation {
        /// The call's line.
        line: usize,
        /// The call.
        call: &'static str,
        /// The rotation, in degrees.
        degrees: Decimal,
    },
    /// An rs274 motion moving Y, A, B or C.
    CanonOtherAxis {
        /// The call's line.
        line: usize,
        /// The call.
        call: &'static str,
        /// The axis.
        axis: &'static str,
        /// Where the first motion had it.
        from: Decimal,
        /// Where this one has it.
        to: Decimal,
    },
    /// An rs274 pitch that is not a lead of at most 6 decimals.
    CanonPitch {
        /// The call's line.
        line: usize,
        /// The pitch.
        pitch: Decimal,
    },
    /// An rs274 arc outside the XZ plane.
    CanonArcPlane {
        /// The call's line.
        line: usize,
    },
    /// An rs274 arc while synchronised (a threaded arc).
    CanonThreadedArc {
        /// The call's line.
        line: usize,
    },
    /// An rs274 arc of more than one turn.
    CanonArcTurns {
        /// The call's line.
        line: usize,
        /// Its rotation.
        rotation: i64,
    },
    /// An rs274 trace compared on a profile that is not linuxcnc.
    CanonProfile,
    /// A trace with no moves (reading R-CHECKEMPTY).
    Empty,
}

impl TraceError {
    /// The rule's name, without the area (`not_a_decimal`); a program
    /// error's (or a step error's) own for an expanded program's line.
    pub(crate) fn name(&self) -> Cow<'static, str> {
        Cow::Borrowed(match self {
            TraceError::CannotOpen { .. } => "cannot_open",
            TraceError::CannotRead { .. } => "cannot_read",
            TraceError::NotUtf8 { .. } => "not_utf8",
            TraceError::Program { error, .. } => return Cow::Owned(error.kind.stable_kind()),
            TraceError::Step { error, .. } => return error.name(),
            TraceError::CannedCycle { .. } => "canned_cycle",
            TraceError::CsvHeaderIncomplete { .. } => "csv_header_incomplete",
            TraceError::CsvUnknownColumn { .. } => "csv_unknown_column",
            TraceError::CsvColumnTwice { .. } => "csv_column_twice",
            TraceError::CsvTooManyFields { .. } => "csv_too_many_fields",
            TraceError::CsvArcDirection { .. } => "csv_arc_direction",
            TraceError::CsvUnknownMotion { .. } => "csv_unknown_motion",
            TraceError::CsvMissing { .. } => "csv_missing_field",
            TraceError::CsvNotADecimal { .. } => "not_a_decimal",
            TraceError::CsvNotInIncrements { .. } | TraceError::CanonNotInIncrements { .. } => {
                "not_in_increments"
            }
            TraceError::CsvOutOfRange { .. } | TraceError::CanonOutOfRange { .. } => "out_of_range",
            TraceError::CsvBadLead { .. } | TraceError::CanonPitch { .. } => "bad_lead",
            TraceError::CsvNotAThread { .. } => "csv_not_a_thread_row",
            TraceError::CsvThreadWithoutLead { .. } => "csv_thread_without_lead",
            TraceError::CsvBadStartAngle { .. } => "bad_start_angle",
            TraceError::CsvCentreOffArc { .. } => "csv_centre_off_arc",
            TraceError::CsvArcWithoutCentre { .. } => "arc_without_centre",
            TraceError::CsvCentreTwice { .. } => "csv_centre_twice",
            TraceError::CsvArcStartUnknown { .. } => "arc_start_unknown",
            TraceError::Canon(_) => "canon_call",
            TraceError::CanonUnits { .. } => "canon_units",
            TraceError::CanonRotation { .. } => "canon_rotation",
            TraceError::CanonOtherAxis { .. } => "canon_other_axis",
            TraceError::CanonArcPlane { .. } => "canon_arc_plane",
            TraceError::CanonThreadedArc { .. } => "canon_threaded_arc",
            TraceError::CanonArcTurns { .. } => "canon_arc_turns",
            TraceError::CanonProfile => "canon_profile",
            TraceError::Empty => "empty",
        })
    }

    /// The stable kind: `trace:` and the rule's name
    /// (`trace:not_a_decimal`, `trace:empty`; `trace:syntax` for a line
    /// of an expanded program the reader cannot read).
    pub(crate) fn stable_kind(&self) -> Cow<'static, str> {
        Cow::Owned(format!("trace:{}", self.name()))
    }
}

/// The hint after an error of a line that looks like a CSV header.
const CSV_HINT: &str = " (this looks like a CSV header: pass --trace-format csv)";

/// `CANON_UNITS_MM` or `CANON_UNITS_INCHES`.
fn unit_name(u: CanonUnits) -> &'static str {
    match u {
        CanonUnits::Mm => "CANON_UNITS_MM",
        CanonUnits::Inches => "CANON_UNITS_INCHES",
    }
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TraceError::CannotOpen { path, error } => write!(f, "{path}: {error}"),
            TraceError::CannotRead { line, error } => write!(f, "line {line}: {error}"),
            TraceError::NotUtf8 { line, byte } => write!(f, "line {line}, byte {byte}: not UTF-8 text"),
            TraceError::Program { error, csv_header } => {
                write!(f, "{error}{}", if *csv_header { CSV_HINT } else { "" })
            }
            TraceError::Step { error, csv_header } => {
                write!(f, "{error}{}", if *csv_header { CSV_HINT } else { "" })
            }
            TraceError::CannedCycle { line } => {
                write!(f, "line {line}: a trace holds plain moves, not canned cycles")
            }
            TraceError::CsvHeaderIncomplete { line } => write!(
                f,
                "CSV line {line}: the header must name the columns motion, x and z (lead, q, i, k, cx and cz \
                 are optional)"
            ),
            TraceError::CsvUnknownColumn { line, column } => write!(
                f,
                "CSV line {line}: unknown column `{column}` (the columns are {})",
                super::trace::CSV_COLUMNS.join(", ")
            ),
            TraceError::CsvColumnTwice { line, column } => {
                write!(f, "CSV line {line}: the column `{column}` appears twice")
            }
            TraceError::CsvTooManyFields { line, fields, columns } => {
                write!(f, "CSV line {line}: {fields} fields, the header names {columns}")
            }
            TraceError::CsvArcDirection { line } => write!(
                f,
                "CSV line {line}: motion `arc` needs a direction: arc-cw (G02) or arc-ccw (G03)"
            ),
            TraceError::CsvUnknownMotion { line, motion } => write!(
                f,
                "CSV line {line}: unknown motion `{motion}` (rapid, feed, thread, arc-cw, arc-ccw; or G00, \
                 G01, G32, G02, G03)"
            ),
            TraceError::CsvMissing { line, column } => write!(f, "CSV line {line}: {column} is missing"),
            TraceError::CsvNotADecimal { line, column, value } => {
                write!(f, "CSV line {line}: {column} `{value}` is not a decimal")
            }
            TraceError::CsvNotInIncrements { line, column, value } => {
                write!(f, "CSV line {line}: {column} `{value}` is not a whole number of increments")
            }
            TraceError::CsvOutOfRange { line, column, value } => {
                write!(f, "CSV line {line}: {column} `{value}` is outside the range table")
            }
            TraceError::CsvBadLead { line, value } => write!(
                f,
                "CSV line {line}: lead `{value}` (write F6.0, I20 or 6.0, within the range tables)"
            ),
            TraceError::CsvNotAThread { line, column, value } => {
                write!(f, "CSV line {line}: {column} `{value}` on a row that is not a thread move")
            }
            TraceError::CsvThreadWithoutLead { line } => {
                write!(f, "CSV line {line}: a thread row needs its lead")
            }
            TraceError::CsvBadStartAngle { line, value } => write!(
                f,
                "CSV line {line}: q `{value}` must be 0 to 360000 thousandths of a degree, in steps of 0.1"
            ),
            TraceError::CsvCentreOffArc { line } => write!(
                f,
                "CSV line {line}: an arc centre on a row that is not an arc (arc-cw or arc-ccw)"
            ),
            TraceError::CsvArcWithoutCentre { line } => write!(
                f,
                "CSV line {line}: an arc without a centre: give i and k, or cx and cz (reading R-CHECKARC)"
            ),
            TraceError::CsvCentreTwice { line } => {
                write!(f, "CSV line {line}: give the centre once: i and k, or cx and cz, not both")
            }
            TraceError::CsvArcStartUnknown { line } => write!(
                f,
                "CSV line {line}: i and k are from the arc's start, and no earlier row gives it (use cx, cz)"
            ),
            TraceError::Canon(e) => e.fmt(f),
            TraceError::CanonNotInIncrements { line, what, value } => {
                write!(f, "line {line}: {what} {value} is not a whole number of increments")
            }
            TraceError::CanonOutOfRange { line, what, value } => {
                write!(f, "line {line}: {what} {value} is beyond the range table")
            }
            TraceError::CanonUnits { line, call, trace, program } => write!(
                f,
                "line {line}: {call} in {} while the program is in {}: write the trace in the program's unit \
                 (USE_LENGTH_UNITS)",
                unit_name(*trace),
                unit_name(*program)
            ),
            TraceError::CanonRotation { line, call, degrees } => write!(
                f,
                "line {line}: {call} under an XY rotation of {degrees} degrees: a trace is compared unrotated \
                 (SET_XY_ROTATION(0))"
            ),
            TraceError::CanonOtherAxis { line, call, axis, from, to } => write!(
                f,
                "line {line}: {call} moves {axis} from {from} to {to}: a lathe trace moves X and Z only"
            ),
            TraceError::CanonPitch { line, pitch } => {
                write!(f, "line {line}: pitch {pitch} is not a lead of at most 6 decimals")
            }
            TraceError::CanonArcPlane { line } => write!(
                f,
                "line {line}: ARC_FEED outside the XZ plane (SELECT_PLANE(CANON_PLANE_XZ), G18)"
            ),
            TraceError::CanonThreadedArc { line } => write!(
                f,
                "line {line}: ARC_FEED while synchronised: a threaded arc is not a move the check reads"
            ),
            TraceError::CanonArcTurns { line, rotation } => write!(
                f,
                "line {line}: ARC_FEED of rotation {rotation}: an arc of more than one turn (P) is not a move \
                 the check reads"
            ),
            TraceError::CanonProfile => {
                f.write_str("an rs274 trace (.canon) is LinuxCNC's: compare it with --profile linuxcnc")
            }
            TraceError::Empty => f.write_str("the trace has no moves (reading R-CHECKEMPTY)"),
        }
    }
}

impl std::error::Error for TraceError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            TraceError::CannotOpen { error, .. } | TraceError::CannotRead { error, .. } => Some(error),
            TraceError::Program { error, .. } => Some(error),
            TraceError::Step { error, .. } => Some(error),
            TraceError::Canon(e) => Some(e),
            _ => None,
        }
    }
}

impl TraceError {
    /// The failure of the trace named `name` (its file, or `<stdin>`;
    /// `None` when the message names it already): the message the
    /// command prints, with the rule's kind.
    pub(crate) fn failure(&self, name: Option<&str>) -> crate::Failure {
        let message = match name {
            Some(name) => format!("{name}: {self}"),
            None => self.to_string(),
        };
        crate::Failure::with_kind(crate::job::Cause::Trace, self.stable_kind(), message)
    }
}
