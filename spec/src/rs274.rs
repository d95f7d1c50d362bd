//! LinuxCNC's canonical machining calls, as its standalone interpreter
//! prints them (`rs274 -g FILE < /dev/null`): the external ground truth of
//! the `linuxcnc` profile (issue 15).
//!
//! Each output line is `<sequence> N..... <CALL>(<arguments>)`. The calls
//! read here are the motions and the spindle synchronisation:
//!
//! | call | meaning |
//! |---|---|
//! | `STRAIGHT_TRAVERSE(x, y, z, a, b, c)` | rapid to x z |
//! | `STRAIGHT_FEED(x, y, z, a, b, c)` | feed to x z; synchronised while a `START_SPEED_FEED_SYNC` is in force |
//! | `START_SPEED_FEED_SYNC(pitch, velocity_mode)` | synchronise the following feeds: `pitch` per revolution along the path |
//! | `STOP_SPEED_FEED_SYNCH()` | end synchronisation |
//!
//! X is a radius in the program's length unit (`rs274` prints the
//! interpreter's internal radius coordinate with four decimals, also in
//! G7), Z in the same unit; the pitch has six decimals. Every other call
//! is either read and checked by `check`, or one of [`SKIPPED_CALLS`]
//! (calls that cannot move the tool), or an error. Values are kept as the
//! exact decimals printed.

use std::fmt;

use cycleref::{Motion, Move, Units, XMode};
use rust_decimal::Decimal;

/// One motion of `rs274`'s canonical output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CanonMove {
    /// True for `STRAIGHT_TRAVERSE`, false for `STRAIGHT_FEED`.
    pub rapid: bool,
    /// X as printed: a radius, in the program's unit.
    pub x: Decimal,
    /// Z as printed.
    pub z: Decimal,
    /// The pitch of the synchronisation in force for a feed, as printed.
    pub pitch: Option<Decimal>,
    /// The 1-based line of the output where the call stands.
    pub line: usize,
}

/// Why a canonical output could not be read: where, and what.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CanonError {
    /// The 1-based line of the output.
    pub line: usize,
    /// What was wrong.
    pub kind: CanonErrorKind,
}

/// What was wrong with a line of a canonical output. Its `Display` names
/// the call, the offending argument or value, and what `check` reads.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum CanonErrorKind {
    /// Not `<sequence> N..... CALL(arguments)`.
    NotACall,
    /// An argument of `call` is not a number.
    NotANumber {
        /// The call.
        call: String,
        /// The argument, as shown (cut and escaped).
        argument: String,
        /// The number reader's reason, as it says it.
        reason: String,
    },
    /// `call` has `count` arguments where it takes one of `takes`.
    ArgumentCount {
        /// The call.
        call: String,
        /// The arguments given.
        count: usize,
        /// The counts it takes.
        takes: &'static [usize],
    },
    /// A motion of `call` moves U, V or W.
    UvwMoves {
        /// The call.
        call: String,
    },
    /// An arc's rotation is not a whole number.
    RotationNotWhole {
        /// The call.
        call: String,
        /// The rotation.
        rotation: Decimal,
    },
    /// A synchronisation call with other than 2 or 3 arguments.
    SyncArguments {
        /// The call.
        call: String,
    },
    /// A synchronisation in velocity mode (not 0).
    VelocityMode {
        /// The call.
        call: String,
        /// The mode.
        mode: Decimal,
    },
    /// A unit other than `CANON_UNITS_MM` or `CANON_UNITS_INCHES`.
    Unit {
        /// The call.
        call: String,
        /// The unit, as shown.
        unit: String,
    },
    /// A call `check` does not read and that is not known to leave the
    /// tool where it is (reading R-CHECKLCNC-CALLS).
    UnknownCall {
        /// The call, as shown.
        call: String,
    },
    /// An arc where [`read`] takes straight moves only.
    ArcInRead,
}

impl std::fmt::Display for CanonErrorKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CanonErrorKind::NotACall => f.write_str(
                "not a line of rs274's canonical output (`<sequence> N..... CALL(arguments)`, as `rs274 -g` \
                 prints it)",
            ),
            CanonErrorKind::NotANumber { call, argument, reason } => {
                write!(f, "{call}: argument `{argument}` is not a number ({reason})")
            }
            CanonErrorKind::ArgumentCount { call, count, takes } => {
                write!(f, "{call}: {count} arguments, the call takes {takes:?}")
            }
            CanonErrorKind::UvwMoves { call } => {
                write!(f, "{call}: U, V or W moves; a lathe trace moves X and Z only")
            }
            CanonErrorKind::RotationNotWhole { call, rotation } => {
                write!(f, "{call}: rotation {rotation} is not a whole number")
            }
            CanonErrorKind::SyncArguments { call } => write!(f, "{call}: expected 2 or 3 arguments"),
            CanonErrorKind::VelocityMode { call, mode } => {
                write!(f, "{call}: velocity mode {mode}: a thread is compared at a constant pitch (0)")
            }
            CanonErrorKind::Unit { call, unit } => {
                write!(f, "{call}: unit `{unit}` (CANON_UNITS_MM or CANON_UNITS_INCHES)")
            }
            CanonErrorKind::UnknownCall { call } => write!(
                f,
                "the call `{call}` is not read by the check and is not one known to leave the tool where it \
                 is (reading R-CHECKLCNC-CALLS)"
            ),
            CanonErrorKind::ArcInRead => f.write_str("ARC_FEED: read() takes straight moves only"),
        }
    }
}

impl std::fmt::Display for CanonError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.kind)
    }
}

impl std::error::Error for CanonError {}

/// Reads the motions of a canonical output, in order.
///
/// # Errors
///
/// A motion or synchronisation call whose arguments are not numbers.
///
/// ```
/// use cycleref_spec::rs274::read;
/// let text = "   11 N..... STRAIGHT_TRAVERSE(14.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)\n\
///             14 N..... START_SPEED_FEED_SYNC(1.500000,0)\n\
///             15 N..... STRAIGHT_FEED(13.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n\
///             16 N..... STOP_SPEED_FEED_SYNCH()\n";
/// let moves = read(text).unwrap();
/// assert_eq!(moves.len(), 2);
/// assert!(moves[0].rapid && moves[0].pitch.is_none());
/// assert_eq!(moves[1].pitch.unwrap().to_string(), "1.500000");
/// assert_eq!(moves[1].z.to_string(), "-20.0000");
/// ```
pub fn read(text: &str) -> Result<Vec<CanonMove>, CanonError> {
    let mut out = Vec::new();
    let mut pitch = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        match call(raw, line)? {
            Some(CanonCall::Motion { rapid, x, z, .. }) => {
                out.push(CanonMove { rapid, x, z, pitch: if rapid { None } else { pitch }, line });
            }
            Some(CanonCall::StartSync { pitch: p }) => pitch = Some(p),
            Some(CanonCall::StopSync) => pitch = None,
            Some(CanonCall::Arc { .. }) => return Err(CanonError { line, kind: CanonErrorKind::ArcInRead }),
            _ => {}
        }
    }
    Ok(out)
}

/// The length unit of a `USE_LENGTH_UNITS` call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonUnits {
    /// `CANON_UNITS_MM`.
    Mm,
    /// `CANON_UNITS_INCHES`.
    Inches,
}

/// The calls that cannot move the tool nor change how a printed
/// coordinate is read, skipped on purpose (reading R-CHECKLCNC-CALLS).
/// Each was seen in `rs274 -g` output of LinuxCNC 2.9 (Debian's
/// `linuxcnc-uspace`). The offsets (`SET_G5X_OFFSET`, `SET_G92_OFFSET`,
/// `USE_TOOL_LENGTH_OFFSET`) are among them because `rs274` prints every
/// motion in the program's own frame: after `G10 L2 P1 X0.5` or `G92 X5`
/// it still prints the programmed coordinates (checked by hand, and by
/// `cli/tests/check_canon.rs`).
pub const SKIPPED_CALLS: [&str; 36] = [
    "COMMENT",
    "MESSAGE",
    "ON_RESET",
    "SET_FEED_REFERENCE",
    "SET_FEED_RATE",
    "SET_FEED_MODE",
    "SET_SPINDLE_SPEED",
    "SET_SPINDLE_MODE",
    "START_SPINDLE_CLOCKWISE",
    "START_SPINDLE_COUNTERCLOCKWISE",
    "STOP_SPINDLE_TURNING",
    "ORIENT_SPINDLE",
    "ENABLE_FEED_OVERRIDE",
    "DISABLE_FEED_OVERRIDE",
    "ENABLE_SPEED_OVERRIDE",
    "DISABLE_SPEED_OVERRIDE",
    "ENABLE_ADAPTIVE_FEED",
    "DISABLE_ADAPTIVE_FEED",
    "ENABLE_FEED_HOLD",
    "DISABLE_FEED_HOLD",
    "FLOOD_ON",
    "FLOOD_OFF",
    "MIST_ON",
    "MIST_OFF",
    "DWELL",
    "SELECT_TOOL",
    "START_CHANGE",
    "CHANGE_TOOL",
    "USE_TOOL_LENGTH_OFFSET",
    "SET_G5X_OFFSET",
    "SET_G92_OFFSET",
    "SET_MOTION_CONTROL_MODE",
    "SET_NAIVECAM_TOLERANCE",
    "PROGRAM_STOP",
    "OPTIONAL_PROGRAM_STOP",
    "PROGRAM_END",
];

/// One canonical call of `rs274`'s output. Every call is one of these or
/// an error ([`call`]): a call that could move the tool is never skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonCall {
    /// `STRAIGHT_TRAVERSE` (rapid) or `STRAIGHT_FEED` to X (a radius) Z.
    Motion {
        /// True for `STRAIGHT_TRAVERSE`.
        rapid: bool,
        /// X as printed.
        x: Decimal,
        /// Z as printed.
        z: Decimal,
        /// Y, A, B and C as printed (a lathe's trace keeps them where they
        /// start).
        others: [Decimal; 4],
    },
    /// `ARC_FEED` in the XZ plane (LinuxCNC's G2/G3 with G18): the end
    /// and the centre, X as radii.
    Arc {
        /// X of the end (the second axis of the XZ plane), as printed.
        x: Decimal,
        /// Z of the end (the first axis).
        z: Decimal,
        /// X of the centre.
        cx: Decimal,
        /// Z of the centre.
        cz: Decimal,
        /// The rotation: -1 clockwise (G2), 1 counter-clockwise (G3);
        /// any other value is more than one turn.
        rotation: i64,
        /// Y (the axis end point), A, B and C as printed.
        others: [Decimal; 4],
    },
    /// `START_SPEED_FEED_SYNC`: the following feeds are synchronised at
    /// `pitch` per revolution along the path.
    StartSync {
        /// The pitch as printed.
        pitch: Decimal,
    },
    /// `STOP_SPEED_FEED_SYNCH`.
    StopSync,
    /// `USE_LENGTH_UNITS`: the unit of the coordinates that follow.
    Units(CanonUnits),
    /// `SET_XY_ROTATION`, in degrees.
    Rotation(Decimal),
    /// `SELECT_PLANE`: true for `CANON_PLANE_XZ`.
    Plane {
        /// The XZ plane, the only one an arc is read in.
        xz: bool,
    },
    /// One of [`SKIPPED_CALLS`].
    Skipped,
}

/// `s` as a decimal, as [`Decimal`]'s parser reads it: the plain forms
/// `rs274` prints (`-12.3456`, `0.0000`, up to 18 digits) digit by digit
/// ([`plain_number`]), without the general parser's work; any other form
/// by that parser.
fn number(s: &str) -> Result<Decimal, rust_decimal::Error> {
    plain_number(s.as_bytes()).map_or_else(|| s.parse(), Ok)
}

/// `b` as a decimal when it is a plain form: an optional sign, then at
/// most 18 digits and points, one point at most and one digit at least,
/// and not a negative zero (whose sign the parser keeps); `None` for any
/// other text.
#[inline]
fn plain_number(b: &[u8]) -> Option<Decimal> {
    let mut at = 0;
    plain_number_at(b, &mut at).filter(|_| at == b.len())
}

/// The plain form ([`plain_number`]) that starts at `b[*at]` and ends
/// before the first byte that cannot continue it, `*at` moved there; or
/// `None` when what stands there is no plain form.
#[inline(always)]
fn plain_number_at(b: &[u8], at: &mut usize) -> Option<Decimal> {
    let mut i = *at;
    let negative = b.get(i) == Some(&b'-');
    if matches!(b.get(i), Some(b'-' | b'+')) {
        i += 1;
    }
    let start = i;
    // `0.0000`, unsigned and not followed by a digit: what the reading
    // below gives for it (an exact zero of four decimals, ending there),
    // at once. It is most of `rs274`'s numbers (the axes a lathe does not
    // move).
    if !negative
        && b.get(i..i + 6) == Some(b"0.0000".as_slice())
        && !b.get(i + 6).is_some_and(u8::is_ascii_digit)
    {
        *at = i + 6;
        return Some(Decimal::new(0, 4));
    }
    // Exact within 18 digits, the most a plain form has (checked below;
    // beyond them the value is not used).
    let (mut mantissa, mut scale) = (0_i64, 0_u32);
    let digits = |i: &mut usize, mantissa: &mut i64, scale: &mut u32, fraction: bool| {
        while let Some(&c) = b.get(*i) {
            let digit = c.wrapping_sub(b'0');
            if digit >= 10 {
                break;
            }
            *mantissa = mantissa.wrapping_mul(10).wrapping_add(i64::from(digit));
            *scale += u32::from(fraction);
            *i += 1;
        }
    };
    digits(&mut i, &mut mantissa, &mut scale, false);
    let point = b.get(i) == Some(&b'.');
    if point {
        i += 1;
        // Four digits at a time while there are four (`rs274` prints four
        // decimals, six for a pitch): every byte of `v` in `0x30..=0x39`
        // (high nibble 3, and adding 6 to the low one carries nowhere),
        // then the pairs and the two pairs combined.
        while let Some(&[a, b1, c, d]) = b.get(i..i + 4) {
            let v = u32::from_le_bytes([a, b1, c, d]);
            if v & 0xF0F0_F0F0 != 0x3030_3030 || v.wrapping_add(0x0606_0606) & 0xF0F0_F0F0 != 0x3030_3030 {
                break;
            }
            let v = v - 0x3030_3030;
            let v = (v.wrapping_mul(10) + (v >> 8)) & 0x00FF_00FF;
            let v = (v.wrapping_mul(100) + (v >> 16)) & 0xFFFF;
            mantissa = mantissa.wrapping_mul(10_000).wrapping_add(i64::from(v));
            scale += 4;
            i += 4;
        }
        digits(&mut i, &mut mantissa, &mut scale, true);
    }
    let length = i - start;
    if length > 18 || length == usize::from(point) || (negative && mantissa == 0) {
        // Too long, no digit, or a negative zero.
        return None;
    }
    *at = i;
    Some(Decimal::new(if negative { -mantissa } else { mantissa }, scale))
}

/// A call's arguments as read: the first [`Args::KEPT`] kept (no call
/// takes more), all of them counted, so that a call given too many is
/// named with their number.
#[derive(Clone)]
struct Args {
    kept: [Decimal; Args::KEPT],
    len: usize,
}

impl Args {
    /// The most arguments a call takes (`ARC_FEED` with U, V and W).
    const KEPT: usize = 12;
    const EMPTY: Args = Args { kept: [Decimal::ZERO; Args::KEPT], len: 0 };

    fn push(&mut self, d: Decimal) {
        if let Some(slot) = self.kept.get_mut(self.len) {
            *slot = d;
        }
        self.len += 1;
    }

    /// How many arguments the call was given.
    fn len(&self) -> usize {
        self.len
    }

    /// The arguments kept, in order: all of them when there are at most
    /// [`Args::KEPT`].
    fn kept(&self) -> &[Decimal] {
        &self.kept[..self.len.min(Args::KEPT)]
    }
}

/// A line that is not of the form `<sequence> N..... CALL(arguments)`.
#[derive(Debug, PartialEq, Eq)]
struct NotACall;

/// The name and the arguments of a line, `None` for an empty line: the
/// line trimmed, the sequence (digits) and the N word (`N`, then digits
/// and points) each up to a space, the call trimmed, its name up to the
/// first `(` and trimmed, its arguments up to the `)` that ends it.
fn parts(raw: &str) -> Result<Option<(&str, &str)>, NotACall> {
    let text = scan::trim(raw);
    if text.is_empty() {
        return Ok(None);
    }
    let (seq, rest) = scan::split_at_whitespace(text).ok_or(NotACall)?;
    let rest = scan::trim_start(rest);
    let (n, call) = scan::split_at_whitespace(rest).ok_or(NotACall)?;
    if seq.is_empty()
        || !seq.bytes().all(|b| b.is_ascii_digit())
        || !n.starts_with('N')
        || !n[1..].bytes().all(|b| b.is_ascii_digit() || b == b'.')
    {
        return Err(NotACall);
    }
    let call = scan::trim(call);
    let (name, rest) = scan::split_at_byte(call, b'(').ok_or(NotACall)?;
    Ok(Some((scan::trim(name), rest.strip_suffix(')').ok_or(NotACall)?)))
}

/// The name and the arguments of a line as `rs274` prints it
/// (`<sequence> N<number or .....> <name>(<arguments>)` with ASCII spaces)
/// in one pass over its bytes; `None` for any other line (empty, an
/// error, or spaced by other characters), which [`call`] then reads by
/// [`parts`]. Where it gives them they are those of [`parts`] (the test
/// `plain_readings_are_the_general_ones` compares them).
fn plain_parts(raw: &str) -> Option<(&str, &str)> {
    let (call, open, close) = plain_span(raw.as_bytes())?;
    Some((scan::trim(&raw[call..open]), &raw[open + 1..close]))
}

/// Where [`plain_parts`] finds the call in the bytes `b` of a line: the
/// offsets of the call's first byte, of its `(` and of the `)` that ends
/// the line (only ASCII spaces after it). Every byte before the call is
/// ASCII (spaces, digits, `N` and points), and each offset is that of an
/// ASCII byte, so a line's text can be cut there.
fn plain_span(b: &[u8]) -> Option<(usize, usize, usize)> {
    // Only ASCII bytes are looked for, and the bytes of other characters
    // are never ASCII: such a character is taken for none of them.
    let spaces = |i: usize| {
        // ASCII spaces (`rs274` pads with them) eight at a time, then
        // any space a byte at a time.
        let mut i = scan::skip_byte(b, i, b' ');
        while b.get(i).is_some_and(|&c| scan::is_space(c)) {
            i += 1;
        }
        i
    };
    let mut i = spaces(0);
    let sequence = i;
    while b.get(i).is_some_and(u8::is_ascii_digit) {
        i += 1;
    }
    if i == sequence || !b.get(i).is_some_and(|&c| scan::is_space(c)) {
        return None;
    }
    i = spaces(i);
    if b.get(i) != Some(&b'N') {
        return None;
    }
    i += 1;
    // `N.....` (no N word) at once, then what may follow.
    if b.get(i..i + 5) == Some(b".....".as_slice()) {
        i += 5;
    }
    while b.get(i).is_some_and(|&c| c.is_ascii_digit() || c == b'.') {
        i += 1;
    }
    if !b.get(i).is_some_and(|&c| scan::is_space(c)) {
        return None;
    }
    let call = spaces(i);
    let open = scan::find_byte(b, call, b'(')?;
    let close = b.iter().rposition(|&c| !scan::is_space(c))?;
    if close <= open || b[close] != b')' {
        return None;
    }
    Some((call, open, close))
}

/// Pushes the arguments `args` (the text between a call's parentheses)
/// onto `v` in one pass and gives true when every one is a
/// [`plain_number`] between ASCII spaces, as `rs274` prints them; false
/// for anything else (an empty text, only spaces, another form), which
/// [`call`] then reads an argument at a time. Where it gives arguments
/// they are those of that reading (`,` splits them, each is trimmed and
/// read by [`number`], whose first reading is [`plain_number`]): an
/// argument with a character that is not ASCII at either end is no plain
/// number once its ASCII spaces are trimmed, so trimming only those is
/// enough.
fn plain_numbers(args: &[u8], v: &mut Args) -> bool {
    let spaces = |mut i: usize| {
        while args.get(i).is_some_and(|&c| scan::is_space(c)) {
            i += 1;
        }
        i
    };
    let mut at = spaces(0);
    loop {
        let Some(d) = plain_number_at(args, &mut at) else { return false };
        v.push(d);
        at = spaces(at);
        match args.get(at) {
            None => return true,
            Some(b',') => at = spaces(at + 1),
            Some(_) => return false,
        }
    }
}

/// The few text operations [`call`] makes on a line, each exactly the
/// `str` method it names (`str::trim`, `str::trim_start`,
/// `str::split_once` with `char::is_whitespace` or an ASCII character)
/// but reading bytes while they are ASCII, and handing the rest to that
/// method at the first byte that is not: `rs274`'s lines are ASCII, and
/// the `char` searches were a third of `check`'s time on them.
mod scan {
    /// `char::is_whitespace` of an ASCII byte (U+000B included, unlike
    /// `u8::is_ascii_whitespace`).
    #[inline]
    pub(super) fn is_space(b: u8) -> bool {
        // `\t`, `\n`, U+000B, U+000C and `\r` are 9 to 13.
        b == b' ' || (b'\t'..=b'\r').contains(&b)
    }

    /// `s.trim_start()`.
    #[inline]
    pub(super) fn trim_start(s: &str) -> &str {
        match s.bytes().position(|b| !is_space(b)) {
            None => "",
            Some(i) if s.as_bytes()[i].is_ascii() => &s[i..],
            Some(_) => s.trim_start(),
        }
    }

    /// `s.trim()`.
    #[inline]
    pub(super) fn trim(s: &str) -> &str {
        let s = trim_start(s);
        match s.bytes().rposition(|b| !is_space(b)) {
            None => "",
            Some(i) if s.as_bytes()[i].is_ascii() => &s[..=i],
            Some(_) => s.trim_end(),
        }
    }

    /// `s.split_once(char::is_whitespace)`.
    #[inline]
    pub(super) fn split_at_whitespace(s: &str) -> Option<(&str, &str)> {
        match s.bytes().position(|b| is_space(b) || !b.is_ascii()) {
            Some(i) if s.as_bytes()[i].is_ascii() => Some((&s[..i], &s[i + 1..])),
            Some(_) => s.split_once(char::is_whitespace),
            None => None,
        }
    }

    /// The eight bytes of `b` from `i`, as a little-endian word, when
    /// there are eight.
    #[inline]
    fn word_at(b: &[u8], i: usize) -> Option<u64> {
        let w: [u8; 8] = b.get(i..i.checked_add(8)?)?.try_into().ok()?;
        Some(u64::from_le_bytes(w))
    }

    /// The index of the first byte of `b` from `i` that is not `c` (`b`'s
    /// length when there is none): eight bytes at a time while there
    /// are eight (the lowest byte of `w ^ c…c` that is not 0 is the first
    /// other byte), then a byte at a time.
    #[inline(always)]
    pub(super) fn skip_byte(b: &[u8], mut i: usize, c: u8) -> usize {
        let all = u64::from_le_bytes([c; 8]);
        while let Some(w) = word_at(b, i) {
            let x = w ^ all;
            if x != 0 {
                return i + (x.trailing_zeros() / 8) as usize;
            }
            i += 8;
        }
        while b.get(i) == Some(&c) {
            i += 1;
        }
        i.min(b.len())
    }

    /// The index of the first byte `c` of `b` from `i`, if any: eight
    /// bytes at a time while there are eight (a byte of `x = w ^ c…c` is
    /// 0 where `w` holds `c`; `(x − 1…1) & !x & 80…80` has the high bit
    /// of the lowest zero byte set, and none below it), then a byte at a
    /// time.
    #[inline(always)]
    pub(super) fn find_byte(b: &[u8], mut i: usize, c: u8) -> Option<usize> {
        const ONES: u64 = u64::from_le_bytes([1; 8]);
        const HIGHS: u64 = u64::from_le_bytes([0x80; 8]);
        let all = u64::from_le_bytes([c; 8]);
        while let Some(w) = word_at(b, i) {
            let x = w ^ all;
            let zero = x.wrapping_sub(ONES) & !x & HIGHS;
            if zero != 0 {
                return Some(i + (zero.trailing_zeros() / 8) as usize);
            }
            i += 8;
        }
        Some(i + b.get(i..)?.iter().position(|&d| d == c)?)
    }

    /// `s.split_once(c)` for an ASCII `c` (which, in UTF-8, is never part
    /// of another character's bytes).
    #[inline]
    pub(super) fn split_at_byte(s: &str, c: u8) -> Option<(&str, &str)> {
        debug_assert!(c.is_ascii());
        // A plain loop: the texts are a few bytes (an argument), where
        // `memchr`'s setup costs more than it saves.
        let i = s.bytes().position(|b| b == c)?;
        Some((&s[..i], &s[i + 1..]))
    }

    #[cfg(test)]
    mod tests {
        /// A refused line carries its line and a typed kind; the message reads
        /// as it always did.
        #[test]
        fn refusals_are_typed() {
            let e = crate::rs274::call("   12 N..... TELEPORT(1)", 12).expect_err("unknown call");
            assert_eq!(e.line, 12);
            assert_eq!(e.kind, crate::rs274::CanonErrorKind::UnknownCall { call: "TELEPORT".into() });
            assert_eq!(
            e.to_string(),
            "line 12: the call `TELEPORT` is not read by the check and is not one known to leave the tool \
             where it is (reading R-CHECKLCNC-CALLS)"
        );
            let e = crate::rs274::call("   3 N..... STRAIGHT_FEED(1, 0, 1)", 3).expect_err("three arguments");
            assert_eq!(
                e.kind,
                crate::rs274::CanonErrorKind::ArgumentCount {
                    call: "STRAIGHT_FEED".into(),
                    count: 3,
                    takes: &[6, 9]
                }
            );
            assert_eq!(e.to_string(), "line 3: STRAIGHT_FEED: 3 arguments, the call takes [6, 9]");
            let e = crate::rs274::call("   4 N..... STRAIGHT_FEED(1, 0, x, 0, 0, 0)", 4)
                .expect_err("not a number");
            assert!(
                matches!(&e.kind, crate::rs274::CanonErrorKind::NotANumber { argument, .. } if argument == "x"),
                "{e:?}"
            );
        }

        use proptest::prelude::*;

        use super::{split_at_byte, split_at_whitespace, trim, trim_start};

        /// Every character class the scan tells apart: ASCII spaces (the
        /// vertical tab among them), Unicode spaces of two and three
        /// bytes, other ASCII and other non-ASCII characters.
        fn line() -> impl Strategy<Value = String> {
            let chars = prop::sample::select(vec![
                ' ',
                '\t',
                '\n',
                '\x0b',
                '\x0c',
                '\r',
                '\u{85}',
                '\u{a0}',
                '\u{2003}',
                '\u{3000}',
                'a',
                'N',
                '.',
                ',',
                '(',
                ')',
                '1',
                '-',
                '\u{e9}',
                '\u{4e2d}',
                '\u{1f600}',
                '\u{feff}',
            ]);
            prop::collection::vec(chars, 0..12).prop_map(|v| v.into_iter().collect())
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(4096))]
            #[test]
            fn each_scan_is_the_str_method_it_names(s in line()) {
                prop_assert_eq!(trim(&s), s.trim());
                prop_assert_eq!(trim_start(&s), s.trim_start());
                prop_assert_eq!(split_at_whitespace(&s), s.split_once(char::is_whitespace));
                for c in [b'(', b','] {
                    prop_assert_eq!(split_at_byte(&s, c), s.split_once(char::from(c)));
                }
                let b = s.as_bytes();
                for i in 0..=b.len() + 1 {
                    for c in [b'(', b' ', 0x80, 0xe9] {
                        let want = b.get(i..).and_then(|r| r.iter().position(|&d| d == c)).map(|p| i + p);
                        prop_assert_eq!(super::find_byte(b, i, c), want);
                        let skip = b.get(i..).map_or(b.len(), |r| r.iter().position(|&d| d != c).map_or(b.len(), |p| i + p));
                        prop_assert_eq!(super::skip_byte(b, i, c), skip.max(i.min(b.len())));
                    }
                }
            }
        }
    }
}

/// The call of one line of `rs274`'s output (`line` names it in an
/// error), or `None` for an empty line. A line is
/// `<sequence> N<number or .....> <CALL>(<arguments>)`.
///
/// # Errors
///
/// A line of another form, a call that is neither read nor one of
/// [`SKIPPED_CALLS`], or arguments that are not what the call takes.
///
/// ```
/// use cycleref_spec::rs274::{call, CanonCall};
/// let c = call("   10 N10    STRAIGHT_TRAVERSE(5.0000, 0.0000, 1.0000, 0.0000, 0.0000, 0.0000)", 10);
/// assert!(matches!(c, Ok(Some(CanonCall::Motion { rapid: true, .. }))));
/// assert!(call("   11 N..... SET_XY_ROTATION(30.0000)", 11).is_ok());
/// assert!(call("   12 N..... TELEPORT(1)", 12).is_err());
/// assert!(call("STRAIGHT_FEED(1, 0, 1, 0, 0, 0)", 13).is_err());
/// ```
pub fn call(raw: &str, line: usize) -> Result<Option<CanonCall>, CanonError> {
    let fail = |kind: CanonErrorKind| CanonError { line, kind };
    // `<sequence> N<number or .....> <call>`.
    let form = || fail(CanonErrorKind::NotACall);
    let (name, args) = match plain_parts(raw) {
        Some(parts) => parts,
        None => match parts(raw) {
            Ok(Some(parts)) => parts,
            Ok(None) => return Ok(None),
            Err(NotACall) => return Err(form()),
        },
    };
    // The arguments, read into one array in place (returning it by value
    // copied its 200 bytes for every line).
    let mut v = Args::EMPTY;
    let numbers = |v: &mut Args| -> Result<(), CanonError> {
        if plain_numbers(args.as_bytes(), v) {
            return Ok(());
        }
        // What the plain reading pushed is dropped: only the first `len`
        // arguments are ever read.
        v.len = 0;
        if scan::trim(args).is_empty() {
            return Ok(());
        }
        let mut rest = Some(args);
        while let Some(r) = rest {
            let (a, next) = match scan::split_at_byte(r, b',') {
                Some((a, next)) => (a, Some(next)),
                None => (r, None),
            };
            rest = next;
            let a = scan::trim(a);
            let d = number(a).map_err(|e| {
                fail(CanonErrorKind::NotANumber {
                    call: name.to_string(),
                    argument: crate::error::shown(a),
                    reason: e.to_string(),
                })
            })?;
            v.push(d);
        }
        Ok(())
    };
    let count = |v: &Args, want: &'static [usize]| {
        if want.contains(&v.len()) {
            Ok(())
        } else {
            Err(fail(CanonErrorKind::ArgumentCount { call: name.to_string(), count: v.len(), takes: want }))
        }
    };
    Ok(Some(match name {
        "STRAIGHT_TRAVERSE" | "STRAIGHT_FEED" => {
            numbers(&mut v)?;
            let v = &v;
            // X Y Z A B C, and U V W on machines that have them.
            count(v, &[6, 9])?;
            let v = v.kept();
            if v.len() == 9 && v[6..].iter().any(|d| !d.is_zero()) {
                return Err(fail(CanonErrorKind::UvwMoves { call: name.to_string() }));
            }
            CanonCall::Motion {
                rapid: name == "STRAIGHT_TRAVERSE",
                x: v[0],
                z: v[2],
                others: [v[1], v[3], v[4], v[5]],
            }
        }
        "ARC_FEED" => {
            // first_end, second_end, first_axis, second_axis, rotation,
            // axis_end_point, a, b, c (and u, v, w).
            numbers(&mut v)?;
            let v = &v;
            count(v, &[9, 12])?;
            let v = v.kept();
            if v.len() == 12 && v[9..].iter().any(|d| !d.is_zero()) {
                return Err(fail(CanonErrorKind::UvwMoves { call: name.to_string() }));
            }
            let rotation = i64::try_from(v[4]).ok().filter(|_| v[4].fract().is_zero()).ok_or_else(|| {
                fail(CanonErrorKind::RotationNotWhole { call: name.to_string(), rotation: v[4] })
            })?;
            CanonCall::Arc {
                z: v[0],
                x: v[1],
                cz: v[2],
                cx: v[3],
                rotation,
                others: [v[5], v[6], v[7], v[8]],
            }
        }
        "START_SPEED_FEED_SYNC" | "START_SPEED_FEED_SYNCH" => {
            // Two arguments (pitch, velocity mode), or three with the
            // spindle first (later LinuxCNC versions).
            numbers(&mut v)?;
            let v = &v;
            let v = v.kept();
            let pitch = match v.len() {
                2 => v[0],
                3 => v[1],
                _ => return Err(fail(CanonErrorKind::SyncArguments { call: name.to_string() })),
            };
            if v[v.len() - 1] != Decimal::ZERO {
                // Velocity mode: the pitch per revolution of the spindle
                // is a constant lead only without it (G33 prints 0).
                return Err(fail(CanonErrorKind::VelocityMode {
                    call: name.to_string(),
                    mode: v[v.len() - 1],
                }));
            }
            CanonCall::StartSync { pitch }
        }
        "STOP_SPEED_FEED_SYNCH" | "STOP_SPEED_FEED_SYNC" => CanonCall::StopSync,
        "USE_LENGTH_UNITS" => match scan::trim(args) {
            "CANON_UNITS_MM" => CanonCall::Units(CanonUnits::Mm),
            "CANON_UNITS_INCHES" => CanonCall::Units(CanonUnits::Inches),
            other => {
                return Err(fail(CanonErrorKind::Unit {
                    call: name.to_string(),
                    unit: crate::error::shown(other),
                }))
            }
        },
        "SET_XY_ROTATION" => {
            numbers(&mut v)?;
            let v = &v;
            count(v, &[1])?;
            CanonCall::Rotation(v.kept()[0])
        }
        "SELECT_PLANE" => CanonCall::Plane { xz: scan::trim(args) == "CANON_PLANE_XZ" },
        skipped if SKIPPED_CALLS.contains(&skipped) => CanonCall::Skipped,
        other => return Err(fail(CanonErrorKind::UnknownCall { call: crate::error::shown(other) })),
    }))
}

/// The call of a line as `rs274 -g` prints its most frequent ones, read
/// from its bytes by the plain readings [`call`] tries first (the line's
/// form by `plain_parts`, the arguments by `plain_numbers`): a
/// `STRAIGHT_FEED` or `STRAIGHT_TRAVERSE` of six plain numbers, a
/// `START_SPEED_FEED_SYNC` of two or three in constant-pitch mode (the
/// last 0), a `STOP_SPEED_FEED_SYNCH` or a call of [`SKIPPED_CALLS`] whose
/// arguments are ASCII; `None` for any other line, which [`call`] then
/// reads (and is the one that names every error).
///
/// Where it gives a call, the line is ASCII (so valid UTF-8) and the
/// call is the one [`call`] gives for the same line read as text (by
/// construction, and by the test `plain_calls_are_the_general_ones` on
/// adversarial lines). It is given bytes because `check` reads a trace's
/// lines where they lie in its read buffer, and validating UTF-8 first
/// was a twentieth of its time on `rs274`'s output.
///
/// ```
/// use cycleref_spec::rs274::{call, plain_call, CanonCall};
/// let line = "   17 N..... STRAIGHT_FEED(10.7700, 0.0000, 1.9151, 0.0000, 0.0000, 0.0000)";
/// let c = plain_call(line.as_bytes()).unwrap();
/// assert_eq!(Ok(Some(c)), call(line, 17));
/// assert!(matches!(c, CanonCall::Motion { rapid: false, .. }));
/// // A form it does not read is left to `call`.
/// assert_eq!(plain_call(b"   18 N..... STRAIGHT_FEED(1, 0, 1, 0, 0, 0, 0, 0, 0)"), None);
/// ```
#[must_use]
pub fn plain_call(raw: &[u8]) -> Option<CanonCall> {
    // The arguments as `plain_numbers` reads them into `v`, when it does.
    fn numbers<'v>(args: &[u8], v: &'v mut Args) -> Option<&'v [Decimal]> {
        let read = plain_numbers(args, v);
        let v: &'v Args = v;
        read.then(|| v.kept())
    }
    // The bytes before the call and after its `)` are ASCII (`plain_span`),
    // the name is one of the ASCII names below, and the arguments are
    // plain numbers or required ASCII: the whole line is ASCII.
    let (call, open, close) = plain_span(raw)?;
    let (name, args) = (raw[call..open].trim_ascii(), &raw[open + 1..close]);
    let mut v = Args::EMPTY;
    match name {
        b"STRAIGHT_FEED" | b"STRAIGHT_TRAVERSE" => match numbers(args, &mut v)? {
            &[x, y, z, a, b, c] => {
                Some(CanonCall::Motion { rapid: name == b"STRAIGHT_TRAVERSE", x, z, others: [y, a, b, c] })
            }
            _ => None,
        },
        b"START_SPEED_FEED_SYNC" => match numbers(args, &mut v)? {
            // Velocity mode (not 0) is an error, named by `call`.
            &[pitch, mode] | &[_, pitch, mode] if mode.is_zero() => Some(CanonCall::StartSync { pitch }),
            _ => None,
        },
        // The arguments are not read (as by `call`), only required ASCII.
        b"STOP_SPEED_FEED_SYNCH" => args.is_ascii().then_some(CanonCall::StopSync),
        _ => (args.is_ascii() && SKIPPED_CALLS.iter().any(|s| s.as_bytes() == name))
            .then_some(CanonCall::Skipped),
    }
}

/// Our moves against `rs274`'s motions, call by call: the same kind
/// (rapid, or feed synchronised at a pitch), X as a radius (ours divided by
/// 2 in diameter mode) and Z within one increment of `units` plus half of
/// rs274's printed unit (10⁻⁴), the pitch within 10⁻⁶ (the lead of every
/// synchronised move, reading R-LCNC-SYNC).
///
/// # Errors
///
/// The first difference ([`CanonDifference`]), named by the move's index
/// and rs274's output line.
pub fn compare(
    ours: &[Move],
    canon: &[CanonMove],
    units: Units,
    x_mode: XMode,
) -> Result<(), CanonDifference> {
    if ours.len() != canon.len() {
        return Err(CanonDifference::Count { ours: ours.len(), theirs: canon.len() });
    }
    let dec = units.decimals();
    let inc = Decimal::new(1, dec);
    let tol = inc + Decimal::new(5, 5);
    let xf = Decimal::from(x_mode.factor());
    for (index, (m, k)) in ours.iter().zip(canon).enumerate() {
        let x = Decimal::new(m.to.x, dec) / xf;
        let z = Decimal::new(m.to.z, dec);
        if (x - k.x).abs() > tol || (z - k.z).abs() > tol {
            return Err(CanonDifference::Position { index, x, z, theirs: *k });
        }
        match (m.motion, k.rapid, k.pitch) {
            (Motion::Rapid, true, None) => {}
            (Motion::Thread { lead, .. }, false, Some(p)) => {
                let ours = Decimal::new(i64::try_from(lead.mantissa).unwrap_or(i64::MAX), lead.scale);
                if (ours - p).abs() > Decimal::new(1, 6) {
                    return Err(CanonDifference::Pitch { index, ours, theirs: *k });
                }
            }
            _ => return Err(CanonDifference::Kind { index, ours: m.motion, theirs: *k }),
        }
    }
    Ok(())
}

/// The first difference [`compare`] found between our moves and rs274's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonDifference {
    /// Not as many moves.
    Count {
        /// Ours.
        ours: usize,
        /// rs274's.
        theirs: usize,
    },
    /// A move ends elsewhere.
    Position {
        /// The move's index.
        index: usize,
        /// Our X, as a radius.
        x: Decimal,
        /// Our Z.
        z: Decimal,
        /// rs274's move.
        theirs: CanonMove,
    },
    /// A synchronised move at another pitch.
    Pitch {
        /// The move's index.
        index: usize,
        /// Our lead.
        ours: Decimal,
        /// rs274's move.
        theirs: CanonMove,
    },
    /// A move of another kind.
    Kind {
        /// The move's index.
        index: usize,
        /// Our motion.
        ours: Motion,
        /// rs274's move.
        theirs: CanonMove,
    },
}

impl fmt::Display for CanonDifference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CanonDifference::Count { ours, theirs } => write!(f, "{ours} moves against rs274's {theirs}"),
            CanonDifference::Position { index, x, z, theirs: k } => write!(
                f,
                "move {index}: ours X{x} Z{z} (X as a radius), rs274 X{} Z{} (output line {})",
                k.x, k.z, k.line
            ),
            CanonDifference::Pitch { index, ours, theirs: k } => {
                write!(
                    f,
                    "move {index}: pitch {ours} against rs274's {} (output line {})",
                    k.pitch.unwrap_or_default(),
                    k.line
                )
            }
            CanonDifference::Kind { index, ours, theirs } => {
                write!(f, "move {index}: {ours:?} against rs274's {theirs:?}")
            }
        }
    }
}

impl std::error::Error for CanonDifference {}

#[cfg(test)]
mod plain_tests {
    use proptest::prelude::*;

    use super::{number, parts, plain_numbers, plain_parts, Args};

    /// Lines made of the pieces of rs274's lines and of what could stand
    /// in their place: ASCII and Unicode spaces, signs, points, commas,
    /// parentheses, other letters.
    fn line() -> impl Strategy<Value = String> {
        let pieces = prop::sample::select(vec![
            " ",
            "  ",
            "\t",
            "\x0b",
            "\r",
            "\u{a0}",
            "\u{3000}",
            "12",
            "7",
            "N",
            "N.....",
            "N10",
            ".",
            "-",
            "+",
            "0.0000",
            "-12.3456",
            "1.500000",
            ",",
            ", ",
            "(",
            ")",
            "STRAIGHT_FEED",
            "SET_XY_ROTATION",
            "\u{e9}",
            "CANON_PLANE_XZ",
            "1e3",
            "99999999999999999999",
            "",
        ]);
        // Mostly rs274's form, each part drawn with what may replace it.
        let space = || prop::sample::select(vec![" ", " ", " ", "   ", "\t", "\x0b", "\u{a0}", "", "x"]);
        let numbers = prop::collection::vec(
            (
                prop::sample::select(vec!["", "", " ", " ", "\u{a0}"]),
                prop::sample::select(vec![
                    "0.0000",
                    "-12.3456",
                    "1.500000",
                    "0.0000",
                    "-12.3456",
                    "1.500000",
                    "-0.0000",
                    "5.",
                    ".5",
                    "-",
                    "",
                    "1e3",
                    "+4",
                    "1.2.3",
                    "1234567890123456789",
                    "123456789012345678",
                    "\u{e9}",
                ]),
                prop::sample::select(vec!["", " ", "\t", "\u{3000}"]),
            ),
            0..8,
        )
        .prop_map(|v| v.iter().map(|(a, b, c)| format!("{a}{b}{c}")).collect::<Vec<_>>().join(","));
        let formed = (
            space(),
            prop::sample::select(vec!["13", "13", "7", "", "1a"]),
            space(),
            prop::sample::select(vec!["N.....", "N.....", "N10", "N", "M..", ""]),
            space(),
            prop::sample::select(vec!["STRAIGHT_FEED", "STOP_SPEED_FEED_SYNCH", "", "A B", "X\u{a0}"]),
            space(),
            prop::sample::select(vec!["(", "(", "(", "", "(("]),
            numbers,
            prop::sample::select(vec![")", ")", ")", "", "))", ") x"]),
            space(),
        )
            .prop_map(|(a, b, c, d, e, f, g, h, i, j, k)| format!("{a}{b}{c}{d}{e}{f}{g}{h}{i}{j}{k}"));
        prop_oneof![
            1 => prop::collection::vec(pieces, 0..16).prop_map(|v| v.concat()),
            3 => formed,
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(8192))]
        #[test]
        fn plain_readings_are_the_general_ones(raw in line()) {
            let Some((_, args)) = plain_parts(&raw).inspect(|&p| {
                assert_eq!(parts(&raw), Ok(Some(p)), "{raw:?}");
            }) else {
                return Ok(());
            };
            let mut v = Args::EMPTY;
            if plain_numbers(args.as_bytes(), &mut v) {
                let general: Vec<_> = args.split(',').map(|a| number(a.trim())).collect();
                prop_assert!(general.iter().all(Result::is_ok), "{:?}", args);
                let general: Vec<_> = general.into_iter().flatten().collect();
                prop_assert_eq!(v.len(), general.len());
                for (a, b) in v.kept().iter().zip(&general) {
                    prop_assert_eq!((a, a.to_string()), (b, b.to_string()), "{:?}", args);
                }
            }
        }
    }

    /// Lines of the forms [`plain_call`] reads, each part drawn with what
    /// may replace it.
    fn call_line() -> impl Strategy<Value = String> {
        let number = prop_oneof![
            6 => prop::sample::select(vec!["0.0000", "-12.3456", "2.038235", "0", "7", "123456789012345678"]),
            1 => prop::sample::select(vec![
                "-0.0000", "5.", ".5", "-", "", "1e3", "+4", "1.2.3", "1234567890123456789", "\u{e9}", "-0",
            ]),
        ];
        let separator = prop_oneof![
            8 => Just(", "),
            4 => Just(","),
            1 => prop::sample::select(vec![" ,", ",  ", "\t", ", \u{a0}", ""]),
        ];
        let args = (
            prop_oneof![2 => Just(6_usize), 2 => Just(2), 1 => 0_usize..9],
            prop::collection::vec((separator, number), 9),
        )
            .prop_map(|(n, v)| {
                v.iter()
                    .take(n)
                    .enumerate()
                    .map(|(k, (s, n))| if k == 0 { (*n).to_string() } else { format!("{s}{n}") })
                    .collect::<String>()
            });
        let name = prop::sample::select(vec![
            "STRAIGHT_FEED",
            "STRAIGHT_TRAVERSE",
            "START_SPEED_FEED_SYNC",
            "STOP_SPEED_FEED_SYNCH",
            "ENABLE_FEED_OVERRIDE",
            "COMMENT",
            "TELEPORT",
            "STRAIGHT_FEED ",
            " STRAIGHT_FEED",
            "ARC_FEED",
            "USE_LENGTH_UNITS",
        ]);
        let formed = (
            prop::sample::select(vec!["   ", "   ", " ", "", "\t", "\u{feff}"]),
            prop::sample::select(vec!["17", "17", "7", "", "1a"]),
            prop::sample::select(vec![" ", " ", " ", "  ", "", "\u{a0}"]),
            prop::sample::select(vec!["N.....", "N.....", "N10", "N", "M", ""]),
            prop::sample::select(vec![" ", " ", " ", "  ", "\t", ""]),
            name,
            prop::sample::select(vec!["(", "(", "((", ""]),
            prop_oneof![3 => args, 1 => prop::sample::select(vec!["\"\u{e9}\"", "\"a(b)\"", "CANON_UNITS_MM", ")"]).prop_map(String::from)],
            prop::sample::select(vec![")", ")", ")\r", ") ", "", "))", ")\r\r"]),
        )
            .prop_map(|(a, b, c, d, e, f, g, h, i)| format!("{a}{b}{c}{d}{e}{f}{g}{h}{i}"));
        // rs274's own lines, some with one character replaced, inserted
        // or removed.
        let good = prop::sample::select(vec!["0.0000", "-12.3456", "2.038235", "0", "7", "9.8500", "-0.5"]);
        let clean = (
            prop::sample::select(vec![
                "STRAIGHT_FEED",
                "STRAIGHT_TRAVERSE",
                "START_SPEED_FEED_SYNC",
                "STOP_SPEED_FEED_SYNCH",
                "ENABLE_FEED_OVERRIDE",
            ]),
            prop::collection::vec(good, 6),
        )
            .prop_map(|(name, v)| {
                let args = match name {
                    "STRAIGHT_FEED" | "STRAIGHT_TRAVERSE" => v.join(", "),
                    "START_SPEED_FEED_SYNC" => format!("{},{}", v[0], if v[1] == "7" { "1" } else { "0" }),
                    _ => String::new(),
                };
                format!("   17 N..... {name}({args})")
            });
        let edit = (
            0_usize..80,
            prop::sample::select(vec![
                "", "", " ", ",", ".", "-", "0", "9", "(", ")", "\r", "\u{a0}", "\u{e9}", "e",
            ]),
            0_usize..2,
        );
        let edited = (clean.clone(), edit).prop_map(|(line, (at, with, remove))| {
            let mut chars: Vec<char> = line.chars().collect();
            let at = at.min(chars.len());
            chars.drain(at..(at + remove).min(chars.len()));
            chars.splice(at..at, with.chars());
            chars.into_iter().collect::<String>()
        });
        prop_oneof![2 => formed, 1 => clean, 3 => edited]
    }

    /// The strategy reaches the plain reading often (and every value of
    /// it), so that the comparison above is not vacuous.
    #[test]
    fn call_lines_reach_the_plain_reading() {
        use proptest::strategy::ValueTree;
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let strategy = call_line();
        let mut kinds = [0_usize; 4];
        for _ in 0..4000 {
            let raw = strategy.new_tree(&mut runner).unwrap().current();
            match super::plain_call(raw.as_bytes()) {
                Some(super::CanonCall::Motion { .. }) => kinds[0] += 1,
                Some(super::CanonCall::StartSync { .. }) => kinds[1] += 1,
                Some(super::CanonCall::StopSync) => kinds[2] += 1,
                Some(super::CanonCall::Skipped) => kinds[3] += 1,
                _ => {}
            }
        }
        assert!(kinds.iter().all(|&k| k >= 20), "{kinds:?}");
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(8192))]
        #[test]
        fn plain_calls_are_the_general_ones(raw in call_line()) {
            if let Some(c) = super::plain_call(raw.as_bytes()) {
                prop_assert!(raw.is_ascii(), "{:?}", raw);
                let general = super::call(&raw, 3);
                // Debug shows each decimal's scale as well as its value.
                prop_assert_eq!(format!("{:?}", Ok::<_, super::CanonError>(Some(c))), format!("{general:?}"), "{:?}", raw);
            }
        }
    }

    /// Every line of two traces `rs274 -g` printed (LinuxCNC 2.9) is
    /// read plainly unless it is a call [`plain_call`] leaves to [`call`],
    /// and read as [`call`] reads it.
    #[test]
    fn rs274s_traces_are_read_plainly() {
        for trace in
            [include_str!("../tests/data/m20-taper.canon"), include_str!("../tests/data/lcnc-taper.canon")]
        {
            let (mut plain, mut left) = (0, 0);
            for (i, raw) in trace.lines().enumerate() {
                match super::plain_call(raw.as_bytes()) {
                    Some(c) => {
                        plain += 1;
                        assert_eq!(
                            format!("{:?}", super::call(raw, i + 1)),
                            format!("{:?}", Ok::<_, ()>(Some(c)))
                        );
                    }
                    None => {
                        left += 1;
                        let name = raw.split_whitespace().nth(2).unwrap_or("");
                        assert!(
                            ["USE_LENGTH_UNITS", "SET_XY_ROTATION", "SELECT_PLANE", "ARC_FEED"]
                                .iter()
                                .any(|n| name.starts_with(&format!("{n}("))),
                            "{raw:?}"
                        );
                    }
                }
            }
            assert!(plain > 100 && left < 10, "{plain} {left}");
        }
    }

    #[test]
    fn rs274s_lines_are_read_plainly() {
        let line = "   13 N..... STRAIGHT_TRAVERSE(11.0000, 0.0000, -2.0000, 0.0000, 0.0000, 0.0000) ";
        let (name, args) = plain_parts(line).unwrap();
        assert_eq!((name, args), ("STRAIGHT_TRAVERSE", "11.0000, 0.0000, -2.0000, 0.0000, 0.0000, 0.0000"));
        let mut v = Args::EMPTY;
        assert!(plain_numbers(args.as_bytes(), &mut v));
        assert_eq!(
            v.kept().iter().map(ToString::to_string).collect::<Vec<_>>()[..3],
            ["11.0000", "0.0000", "-2.0000"]
        );
        assert_eq!(
            plain_parts("   16 N..... START_SPEED_FEED_SYNC(2.038235,0)"),
            Some(("START_SPEED_FEED_SYNC", "2.038235,0"))
        );
        // Left to the general reading: no arguments, an empty line, a
        // negative zero, a Unicode space before the call.
        assert!(!plain_numbers(b"", &mut Args::EMPTY.clone()));
        assert!(!plain_numbers(b" -0.0000", &mut Args::EMPTY.clone()));
        assert_eq!(plain_parts("  "), None);
        assert_eq!(plain_parts("1 N..... STOP()\u{a0}"), None);
    }
}

#[cfg(test)]
mod number_tests {
    use rust_decimal::Decimal;

    use super::number;

    #[test]
    fn the_fast_reading_of_a_number_is_the_parsers() {
        let forms = [
            "0",
            "0.0000",
            "-0.0000",
            "-0",
            "1",
            "-1",
            "12.3456",
            "-12.3456",
            "+4.5",
            ".5",
            "-.5",
            "5.",
            "-5.",
            "123456789012345678",
            "1234567890123456789",
            "99999999.9999999999",
            "0.000000000000000001",
            "1e3",
            "1.2.3",
            "-",
            "+",
            ".",
            "",
            "--1",
            "1,5",
            " 1",
            "007.0100",
            // Four digits at a time, and what is left after them.
            "1.23456",
            "2.038235",
            "12.345678",
            "0.12345678",
            "0.1234567890123456",
            "0.12345678901234567",
            "3.14159265358979323",
            "1.2345.6",
            "1.234:",
            "1.23/4",
            "-0.0000001",
            "9999.99999999",
            // The zero of four decimals, and what may follow it.
            "+0.0000",
            "0.00000",
            "0.00001",
            "0.0000.",
            "0.0000.5",
            "00.0000",
            "0.000",
            "-0.00001",
        ];
        for s in forms {
            let ours = number(s);
            let parser = s.parse::<Decimal>();
            assert_eq!(ours.is_ok(), parser.is_ok(), "{s}");
            if let (Ok(a), Ok(b)) = (ours, parser) {
                assert_eq!((a, a.to_string()), (b, b.to_string()), "{s}");
            }
        }
        // Every pitch of six decimals over a range.
        for m in (0_i64..=3_000_000).step_by(997) {
            let s = format!("{}.{:06}", m / 1_000_000, m % 1_000_000);
            assert_eq!(number(&s).map(|d| d.to_string()), s.parse::<Decimal>().map(|d| d.to_string()), "{s}");
        }
        // Every value of four decimals over a range, both signs.
        for m in -20_000_i64..=20_000 {
            let s = format!("{}{}.{:04}", if m < 0 { "-" } else { "" }, m.abs() / 10_000, m.abs() % 10_000);
            assert_eq!(number(&s).map(|d| d.to_string()), s.parse::<Decimal>().map(|d| d.to_string()), "{s}");
        }
    }
}
