//! Errors of the program reader: every message names the line, the word and
//! the rule it breaks.

use std::fmt;

use cycleref::CycleError;

/// A program that cannot be expanded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProgramError {
    /// 1-based source line of the offending block.
    pub line: usize,
    /// The offending word as written (`Q0.15`), when one word is to blame.
    pub word: Option<String>,
    /// What is wrong.
    pub kind: ErrorKind,
}

/// What is wrong with a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// Text that is not a word, comment or block end.
    Syntax(String),
    /// A word where the program's format does not allow it (`N` inside a
    /// block, `O` beside other words).
    Misplaced {
        /// The rule.
        rule: &'static str,
    },
    /// A byte outside a comment that is not UTF-8 (reading R-ENCODING).
    Encoding {
        /// 1-based byte column in the line.
        column: usize,
        /// The byte.
        byte: u8,
    },
    /// A length that is not a whole number of least increments.
    NotInIncrements {
        /// The least increment, for example `0.001 mm`.
        increment: String,
    },
    /// A decimal point where the control forbids one.
    DecimalPointNotAllowed {
        /// The rule.
        rule: &'static str,
    },
    /// A word the cycle needs is missing.
    Missing {
        /// The word, in the manual's terms.
        what: &'static str,
        /// The rule (manual note).
        rule: &'static str,
    },
    /// A value outside its range table.
    OutOfRange {
        /// The allowed range.
        range: String,
    },
    /// An address the profile's cycle does not have.
    AddressNotInProfile {
        /// The cycle (and block) the word was found in.
        cycle: &'static str,
        /// The profile.
        profile: String,
    },
    /// The same address twice in one block.
    Duplicate,
    /// P(m)(r)(a) written with fewer digits than the profile allows.
    PartialP,
    /// A G code, M code or feature the reader does not model.
    Unsupported(String),
    /// An incremental move or a cycle before the position is known.
    PositionUnknown,
    /// Thread cutting with no spindle speed commanded (manual: "如果没有指令主轴速度，产生报警").
    NoSpindleSpeed,
    /// G20/G21 after the first motion: the position would change meaning.
    UnitChangeAfterMotion,
    /// A parameter value that the reader cannot use.
    Parameter(String),
    /// The cycle's own alarm.
    Cycle(CycleError),
    /// A subprogram call or return that cannot run (reading
    /// R-SUBPROGRAM).
    Subprogram(crate::reader::SubprogramError),
}

impl ErrorKind {
    /// The stable name of the kind (`not_in_increments`), as the
    /// conformance vectors write it; a cycle alarm is `cycle` here, and its
    /// own name is [`CycleError::name`]. A name never changes meaning; a
    /// new kind gets a new name.
    ///
    /// Twin (deliberate, from `vectors/README.md`): `cli/tests/vectors.rs`,
    /// `kind`, which checks the corpus against the documented names.
    #[must_use]
    pub const fn name(&self) -> &'static str {
        match self {
            ErrorKind::Syntax(_) => "syntax",
            ErrorKind::Misplaced { .. } => "misplaced",
            ErrorKind::Encoding { .. } => "encoding",
            ErrorKind::NotInIncrements { .. } => "not_in_increments",
            ErrorKind::DecimalPointNotAllowed { .. } => "decimal_point_not_allowed",
            ErrorKind::Missing { .. } => "missing",
            ErrorKind::OutOfRange { .. } => "out_of_range",
            ErrorKind::AddressNotInProfile { .. } => "address_not_in_profile",
            ErrorKind::Duplicate => "duplicate",
            ErrorKind::PartialP => "partial_p",
            ErrorKind::Unsupported(_) => "unsupported",
            ErrorKind::PositionUnknown => "position_unknown",
            ErrorKind::NoSpindleSpeed => "no_spindle_speed",
            ErrorKind::UnitChangeAfterMotion => "unit_change_after_motion",
            ErrorKind::Parameter(_) => "parameter",
            ErrorKind::Cycle(_) => "cycle",
            ErrorKind::Subprogram(_) => "subprogram",
        }
    }

    /// The stable kind of the error, as the conformance vectors write it
    /// (`expect.error.kind`) and the command prints it (`error[KIND]`):
    /// [`ErrorKind::name`], and for a cycle's alarm `cycle:` and
    /// [`CycleError::name`](cycleref::CycleError::name)
    /// (`cycle:too_many_passes`), and for a subprogram's error `subprogram:`
    /// and [`SubprogramError::name`](crate::reader::SubprogramError::name)
    /// (`subprogram:not_found`).
    ///
    /// ```
    /// use cycleref_spec::ErrorKind;
    /// assert_eq!(ErrorKind::Duplicate.stable_kind(), "duplicate");
    /// let alarm = ErrorKind::Cycle(cycleref::CycleError::StartInsideThread);
    /// assert_eq!(alarm.stable_kind(), "cycle:start_inside_thread");
    /// ```
    #[must_use]
    pub fn stable_kind(&self) -> String {
        match self {
            ErrorKind::Cycle(e) => format!("cycle:{}", e.name()),
            ErrorKind::Subprogram(e) => format!("subprogram:{}", e.name()),
            k => k.name().to_string(),
        }
    }
}

impl fmt::Display for ProgramError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}", self.line)?;
        if let Some(w) = &self.word {
            // Cut and escaped: a 50 MB word or a control byte is never
            // echoed whole or raw.
            write!(f, ", word `{}`", shown(w))?;
        }
        write!(f, ": {}", self.kind)
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ErrorKind::Syntax(s) => write!(f, "cannot read {s}"),
            ErrorKind::Misplaced { rule } => write!(f, "misplaced word: {rule}"),
            ErrorKind::Encoding { column, byte } => write!(
                f,
                "byte 0x{byte:02X} at byte column {column} is not UTF-8 text (only a comment may hold text \
                 in another encoding, such as GBK)"
            ),
            ErrorKind::NotInIncrements { increment } => {
                write!(f, "the value is not a whole number of least increments ({increment})")
            }
            ErrorKind::DecimalPointNotAllowed { rule } => write!(f, "no decimal point allowed: {rule}"),
            ErrorKind::Missing { what, rule } => write!(f, "{what} is missing ({rule})"),
            ErrorKind::OutOfRange { range } => write!(f, "the value is outside the range table: {range}"),
            ErrorKind::AddressNotInProfile { cycle, profile } => {
                write!(f, "this address is not part of {cycle} on the {profile} profile")
            }
            ErrorKind::Duplicate => write!(f, "the address appears twice in the block"),
            ErrorKind::PartialP => write!(
                f,
                "P(m)(r)(a) must give all of m, r and a (last two digits a, next two r, the rest m); \
                 it can only be omitted as a whole (note 4)"
            ),
            ErrorKind::Unsupported(s) => write!(f, "not supported: {s}"),
            ErrorKind::PositionUnknown => {
                write!(f, "the tool position is not known yet (program an absolute X and Z, or G50, first)")
            }
            ErrorKind::NoSpindleSpeed => write!(
                f,
                "no spindle speed commanded before thread cutting (alarm: the system checks the \
                 spindle speed before threading, note 8)"
            ),
            ErrorKind::UnitChangeAfterMotion => {
                write!(f, "G20/G21 must come before the first motion of the program")
            }
            ErrorKind::Parameter(s) => write!(f, "parameter: {s}"),
            ErrorKind::Cycle(e) => write!(f, "{e}"),
            ErrorKind::Subprogram(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ProgramError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ErrorKind::Cycle(e) => Some(e),
            _ => None,
        }
    }
}

/// How a piece of the user's text is shown in a message: control bytes
/// escaped (a NUL or an escape sequence is never printed raw), and cut to
/// [`SHOWN_CHARS`] characters with `…` after, so that a 50 MB word does not
/// become a 50 MB message.
///
/// ```
/// use cycleref_spec::error::shown;
/// assert_eq!(shown("G76"), "G76");
/// assert_eq!(shown("a\0b"), "a\\u{0}b");
/// assert_eq!(shown(&"9".repeat(100)).chars().count(), 65);
/// ```
#[must_use]
pub fn shown(text: &str) -> String {
    let mut out = String::new();
    for (n, c) in text.chars().enumerate() {
        if n == SHOWN_CHARS {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// The longest piece of the user's text a message shows whole ([`shown`]).
pub const SHOWN_CHARS: usize = 64;
