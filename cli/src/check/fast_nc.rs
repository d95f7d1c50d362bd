//! The fast path of an nc trace (reading R-FASTPATH, "the plain lines of
//! an nc trace"): the lines our own writer writes, `G00 X… Z…`,
//! `G01 X… Z… F…`, `G32 X… Z… F…`, `X…`, a comment, read here in one pass
//! over their bytes instead of by the program reader; every other line, and
//! every line whose reading would need what this path does not know, is
//! declined and read by the program reader as before. The reader stays the
//! reference: a line is taken here only where its steps and the state it
//! leaves are the reader's, and the two are held equal by a property test
//! (`tests::fast_path_is_the_reader`, adversarial lines included).
//!
//! What is known here is only what the lines taken here, and the reader's
//! items, show: where the tool is, the motion mode, the lead in force, and
//! whether a thread run is going on (the modal state a plain line reads and
//! sets in a trace, `State::scan` and `State::g32_block`). A lead is known
//! by value only as the reader resolved it: the text of a G32 block's F
//! word is kept with the lead the reader gave it, and a later F of the same
//! text is that lead (one home for the lead's rule, `State::lead`).
//!
//! The reader does not see the lines taken here, so before it reads a
//! declined line it is brought to the state those lines left, by reading
//! lines that set the same values (the last F, then the last move, and for
//! a thread its run), and renumbered ([`LineReader::start_at`]) so that the
//! declined line keeps its number: nothing of the reader is changed.

use cycleref::g32::G32RunOut;
use cycleref::units::MAX_LENGTH;
use cycleref::{Lead, Point, StartAngle, Units};
use cycleref_spec::reader::{Item, LineReader, MainStart, MotionMode};
use cycleref_spec::{Machine, ProgramError};

use super::{Context, Kind, Step};

/// The most F texts whose leads are kept (a trace has a few leads).
const LEADS: usize = 8;

/// 10 to the power of its index (a length's scale, at most its decimals).
const POW10: [i64; 10] =
    [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000, 100_000_000, 1_000_000_000];

/// The most bytes of an F word taken here (its letter included).
const F_BYTES: usize = 16;

/// The bytes of the window [`FastNc::scan_window`] reads a line in (a
/// power of two).
const WINDOW: usize = 64;

/// The most bytes before a word [`FastNc::scan_window`] reads: a word
/// begun there ends, with the byte after it, within the window.
const WINDOW_WORDS: usize = WINDOW - WORD_BYTES - 2;

/// The most bytes of a word [`FastNc::scan_window`] reads: its letter, a
/// sign, 9 digits, a point and at most 9 decimals (an F word, at most
/// [`F_BYTES`]).
const WORD_BYTES: usize = 21;

/// Bytes read by index, for [`FastNc::length_at`]: a piece of lines
/// (`None` past its end) or a [`Window`] (every index within it).
trait ByteAt {
    /// The byte at `i`, when there is one.
    fn byte_at(&self, i: usize) -> Option<u8>;
}

impl ByteAt for [u8] {
    #[inline(always)]
    fn byte_at(&self, i: usize) -> Option<u8> {
        self.get(i).copied()
    }
}

/// The [`WINDOW`] bytes [`FastNc::scan_window`] reads a line in: an index
/// is taken modulo the window (every index read there is below it), so no
/// read is checked.
struct Window<'a>(&'a [u8; WINDOW]);

impl ByteAt for Window<'_> {
    #[inline(always)]
    fn byte_at(&self, i: usize) -> Option<u8> {
        Some(self.0[i & (WINDOW - 1)])
    }
}

/// An F word's text (its letter included), at most [`F_BYTES`].
#[derive(Clone, Copy, PartialEq, Eq)]
struct FText {
    len: u8,
    bytes: [u8; F_BYTES],
}

impl FText {
    fn new(text: &[u8]) -> Option<FText> {
        let mut bytes = [0; F_BYTES];
        bytes.get_mut(..text.len())?.copy_from_slice(text);
        Some(FText { len: u8::try_from(text.len()).ok()?, bytes })
    }

    fn as_bytes(&self) -> &[u8] {
        self.bytes.get(..usize::from(self.len)).unwrap_or_default()
    }
}

/// The last move taken here, which the reader has not read.
#[derive(Clone, Copy)]
struct Unread {
    motion: MotionMode,
    from: Point,
    to: Point,
}

/// The move of a plain line taken here: what its [`Step`] holds besides
/// what every plain line's has (no centre, a start angle of 0 and the
/// line's number as its context), built into the step only where the
/// trace hands it on ([`Plain::step`]), so that the smaller value is the
/// one moved on the way.
#[derive(Clone, Copy, Debug)]
pub(super) struct Plain {
    kind: Kind,
    from: Point,
    to: Point,
    lead: Option<Lead>,
    sync: bool,
}

impl Plain {
    /// The step of this move, taken from line `line`.
    #[inline(always)]
    pub(super) fn step(self, line: usize) -> Step {
        Step {
            kind: self.kind,
            from: Some(self.from),
            to: self.to,
            centre: None,
            lead: self.lead,
            angle: StartAngle::ZERO,
            sync: self.sync,
            context: Context::Source { line },
        }
    }
}

/// A line taken here.
#[derive(Debug, PartialEq, Eq)]
enum Line<'a> {
    /// Empty, or a comment alone: no block, no change.
    Nothing,
    /// A plain line: its G code (G00, G01, G32), X, Z (in increments) and
    /// F word (its text).
    Move { g: Option<MotionMode>, x: Option<i64>, z: Option<i64>, f: Option<&'a [u8]> },
}

/// True when `line` (without its line end) has a comment from `i` to its
/// end: `(`, printable ASCII without parentheses and semicolons, `)`. The
/// bytes are tested all at once (no branch a byte).
fn comment_ends(line: &[u8], i: usize) -> bool {
    let Some(body) = line.get(i + 1..line.len().saturating_sub(1)) else {
        return false;
    };
    line.get(i) == Some(&b'(')
        && line.len() >= i + 2
        && line.last() == Some(&b')')
        && body.iter().fold(true, |ok, &b| {
            ok & (b.wrapping_sub(b' ') <= b'~' - b' ') & (b != b'(') & (b != b')') & (b != b';')
        })
}

/// The fast path's state (see the module's documentation).
pub(super) struct FastNc {
    /// False: every line is declined (the reader alone).
    enabled: bool,
    /// A length without a decimal point is in increments (reading R-POINT:
    /// the rule of `length_word`).
    bare_increments: bool,
    decimals: u32,
    per_unit: i64,
    /// Where the tool is, when known.
    x: Option<i64>,
    z: Option<i64>,
    /// The motion mode in force, when known.
    motion: Option<MotionMode>,
    /// The lead in force, when known.
    lead: Option<Lead>,
    /// The thread run in force (`Some(None)`: none), when known.
    thread_run: Option<Option<StartAngle>>,
    /// F texts and the leads the reader gave them.
    leads: Vec<(FText, Lead)>,
    /// What the reader has not read: the last F, the last move.
    unread_f: Option<FText>,
    unread_move: Option<Unread>,
}

impl FastNc {
    /// The fast path of a trace read for `machine` in `units` (`enabled`
    /// false: none; the linuxcnc profile has none either).
    pub(super) fn new(machine: &Machine, units: Units, enabled: bool) -> FastNc {
        let linuxcnc = machine.profile.dialect == cycleref_spec::profile::Dialect::LinuxCnc;
        FastNc {
            enabled: enabled && !linuxcnc,
            bare_increments: machine.profile.bare_length_is_increments && !machine.calculator_input,
            decimals: units.decimals(),
            per_unit: units.per_unit(),
            x: None,
            z: None,
            motion: None,
            lead: None,
            thread_run: None,
            leads: Vec::new(),
            unread_f: None,
            unread_move: None,
        }
    }

    /// The lead the reader gave the F text `f`, when known (texts compared
    /// whole: the bytes after a text's length are zeros in each).
    fn cached(&self, f: &FText) -> Option<Lead> {
        self.leads.iter().find(|(t, _)| t == f).map(|(_, l)| *l)
    }

    /// A length word's number, from byte `i` of `bytes` (after its
    /// letter) to the first byte that is not a digit or its point, in
    /// increments, when it is `-`? digits (`.` digits)? within the range
    /// tables and the increment, and where it ends; else `None`. One
    /// reading of the number for both ways of reading a line: a piece of
    /// lines, checked against its end ([`FastNc::scan`]), and a window,
    /// unchecked ([`FastNc::scan_window`]).
    #[inline(always)]
    fn length_at<B: ByteAt + ?Sized>(&self, bytes: &B, mut i: usize) -> Option<(i64, usize)> {
        let digit = |i: usize| bytes.byte_at(i).map(|b| b.wrapping_sub(b'0')).filter(|&d| d <= 9);
        let negative = bytes.byte_at(i) == Some(b'-');
        i += usize::from(negative);
        // The integer part: 1 to 9 digits.
        let start = i;
        let mut whole = 0_i64;
        while let Some(d) = digit(i) {
            if i - start == 9 {
                return None;
            }
            whole = whole * 10 + i64::from(d);
            i += 1;
        }
        if i == start {
            return None;
        }
        let v = if bytes.byte_at(i) == Some(b'.') {
            // A point and 1 to `decimals` digits.
            i += 1;
            let start = i;
            let decimals = self.decimals as usize;
            let mut digits = 0_i64;
            while let Some(d) = digit(i) {
                if i - start == decimals {
                    return None;
                }
                digits = digits * 10 + i64::from(d);
                i += 1;
            }
            let len = i - start;
            if len == 0 || bytes.byte_at(i) == Some(b'.') {
                return None;
            }
            whole.checked_mul(self.per_unit)?.checked_add(digits * POW10.get(decimals - len)?)?
        } else if self.bare_increments {
            whole
        } else {
            whole.checked_mul(self.per_unit)?
        };
        if v > MAX_LENGTH {
            return None;
        }
        Some((if negative { -v } else { v }, i))
    }

    /// The line at the start of `rest` (a piece of whole lines), when it
    /// has one of the shapes taken here, and its length: the line ends
    /// there, at the end of `rest` or at a line end (`\n` or `\r`, reading
    /// R-LINEEND: [`FastNc::line_end`]). Its words are read in order, each
    /// at most once, and the line's end is found where they end (a
    /// comment's end many bytes a step); its bytes are then all printable
    /// ASCII.
    fn scan<'a>(&self, rest: &'a [u8]) -> Option<(Line<'a>, usize)> {
        // Where a line that goes on at `i` with a comment ends (the end
        // of `rest`, or its next line end).
        let line_len = |i: usize| {
            let tail = rest.get(i..).unwrap_or_default();
            i + memchr::memchr2(b'\n', b'\r', tail).unwrap_or(tail.len())
        };
        match rest.first() {
            None | Some(b'\n' | b'\r') => return Some((Line::Nothing, 0)),
            Some(b'(') => {
                let len = line_len(0);
                return comment_ends(rest.get(..len)?, 0).then_some((Line::Nothing, len));
            }
            Some(_) => {}
        }
        // After a word that ends at `i`: the end of the line (`Err` of its
        // length), or a space and the next word's start (`Ok`); anything
        // else declines.
        let after = |i: usize| match rest.get(i) {
            None | Some(b'\n' | b'\r') => Some(Err(i)),
            Some(b' ') => Some(Ok(i + 1)),
            Some(_) => None,
        };
        // The next word's start, when the line goes on.
        let word = |at: Result<usize, usize>, letter: u8| at.ok().filter(|&i| rest.get(i) == Some(&letter));
        let (mut g, mut x, mut z, mut f) = (None, None, None, None);
        // Words in the order G X Z F, one space between them, a comment
        // last.
        let mut at = Ok(0);
        if let Some(i) = word(at, b'G') {
            g = Some(match rest.get(i + 1..i + 3)? {
                b"00" => MotionMode::G00,
                b"01" => MotionMode::G01,
                b"32" => MotionMode::G32,
                _ => return None,
            });
            at = after(i + 3)?;
        }
        if let Some(i) = word(at, b'X') {
            let (v, end) = self.length_at(rest, i + 1)?;
            x = Some(v);
            at = after(end)?;
        }
        if let Some(i) = word(at, b'Z') {
            let (v, end) = self.length_at(rest, i + 1)?;
            z = Some(v);
            at = after(end)?;
        }
        if let Some(i) = word(at, b'F') {
            // F: digits (. digits)?, not zero, to a space or the line's end.
            let mut end = i + 1;
            while !matches!(rest.get(end), None | Some(b' ' | b'\n' | b'\r')) {
                end += 1;
            }
            let word = rest.get(i..end)?;
            let number = word.get(1..)?;
            let (int, frac) = match number.iter().position(|&b| b == b'.') {
                Some(p) => (number.get(..p)?, number.get(p + 1..)?),
                None => (number, &b"0"[..]),
            };
            let digits = |d: &[u8]| !d.is_empty() && d.iter().all(u8::is_ascii_digit);
            if !digits(int) || !digits(frac) || !number.iter().any(|b| (b'1'..=b'9').contains(b)) {
                return None;
            }
            FText::new(word)?;
            f = Some(word);
            at = after(end)?;
        }
        // After a space, a word that is none of the above (or none at
        // all): only a comment to the end of the line.
        let len = match at {
            Err(len) => len,
            Ok(i) => {
                let len = line_len(i);
                if !comment_ends(rest.get(..len)?, i) {
                    return None;
                }
                len
            }
        };
        if x.is_none() && z.is_none() {
            return None;
        }
        Some((Line::Move { g, x, z, f }, len))
    }

    /// [`FastNc::scan`] of a line that begins a window of [`WINDOW`]
    /// bytes, when the line is a move whose words are all of the writer's
    /// shapes (`G00`, `G01` or `G32`, lengths `-`? 1 to 9 digits and at
    /// most `decimals` after a point, an F word of digits and a point)
    /// and it ends within the window at a line end; `None` where it is not,
    /// and then [`FastNc::scan`] reads the line (comments, the ends of
    /// pieces, everything else). Every byte is read at an index below
    /// [`WINDOW`] (the words begin at most at [`WINDOW_WORDS`] and are at
    /// most [`WORD_BYTES`] long), so no read is checked against the line's
    /// length and no line is read beyond its end: where this gives a line,
    /// it is [`FastNc::scan`]'s (the property test
    /// `tests::window_is_the_scan` holds the two equal).
    #[inline(always)]
    fn scan_window<'a>(&self, w: &'a [u8; WINDOW]) -> Option<(Line<'a>, usize)> {
        // The byte at `i`, in the window (every `i` here is below it).
        let at = |i: usize| w[i & (WINDOW - 1)];
        let digit = |i: usize| at(i).wrapping_sub(b'0');
        if self.decimals as usize >= POW10.len() {
            return None;
        }
        // A line end (the window holds no end of the piece).
        let end = |i: usize| matches!(at(i), b'\n' | b'\r');
        let (mut g, mut f) = (None, None);
        let mut i = 0;
        // After a word that ends at `i`: the line's end (`true`), or a
        // space and the next word (`false`, `i` past the space).
        let mut ended = false;
        if at(0) == b'G' {
            g = Some(match (at(1), at(2)) {
                (b'0', b'0') => MotionMode::G00,
                (b'0', b'1') => MotionMode::G01,
                (b'3', b'2') => MotionMode::G32,
                _ => return None,
            });
            i = 3;
            ended = end(i);
            if !ended {
                if at(i) != b' ' {
                    return None;
                }
                i += 1;
            }
        }
        let x = self.window_word(w, &mut i, &mut ended, b'X')?;
        let z = self.window_word(w, &mut i, &mut ended, b'Z')?;
        if !ended && at(i) == b'F' {
            // digits (. digits)?, not zero, at most `F_BYTES` with its letter.
            let start = i;
            let mut e = i + 1;
            let mut nonzero = false;
            while digit(e) <= 9 && e - start < F_BYTES {
                nonzero |= at(e) != b'0';
                e += 1;
            }
            if e == start + 1 {
                return None;
            }
            if at(e) == b'.' {
                e += 1;
                let frac = e;
                while digit(e) <= 9 && e - start < F_BYTES {
                    nonzero |= at(e) != b'0';
                    e += 1;
                }
                if e == frac {
                    return None;
                }
            }
            if !nonzero || e - start > F_BYTES || !end(e) {
                return None;
            }
            f = Some(&w[start..e]);
            i = e;
            ended = true;
        }
        if !ended || (x.is_none() && z.is_none()) {
            return None;
        }
        Some((Line::Move { g, x, z, f }, i))
    }

    /// The length word `letter` (X or Z) at `i` of a window, where the
    /// line has not `ended`: `Some(None)` when it is not there, its value
    /// when it is, with `i` moved past it and the space after it or
    /// `ended` set at the line's end; `None` where
    /// [`FastNc::scan_window`] declines the line.
    #[inline(always)]
    fn window_word(
        &self,
        w: &[u8; WINDOW],
        i: &mut usize,
        ended: &mut bool,
        letter: u8,
    ) -> Option<Option<i64>> {
        let at = |i: usize| w[i & (WINDOW - 1)];
        if *ended || at(*i) != letter {
            return Some(None);
        }
        let (v, e) = self.length_at(&Window(w), *i + 1)?;
        *i = e;
        *ended = matches!(at(e), b'\n' | b'\r');
        if !*ended {
            if at(e) != b' ' || e >= WINDOW_WORDS {
                return None;
            }
            *i = e + 1;
        }
        Some(Some(v))
    }

    /// `line` (without its line end), when it is one of the shapes taken
    /// here ([`FastNc::scan`] of the whole line).
    #[cfg(test)]
    fn parse<'a>(&self, line: &'a [u8]) -> Option<Line<'a>> {
        self.scan(line).filter(|&(_, len)| len == line.len()).map(|(l, _)| l)
    }

    /// Where the line that ends at `len` in `rest` is followed by the next
    /// (after its `\n`, `\r\n` or lone `\r`, as [`split_line`] finds it).
    ///
    /// [`split_line`]: cycleref_spec::lex::split_line
    fn line_end(rest: &[u8], len: usize) -> usize {
        match (rest.get(len), rest.get(len + 1)) {
            (Some(b'\r'), Some(b'\n')) => len + 2,
            (Some(_), _) => len + 1,
            (None, _) => len,
        }
    }

    /// The move of the line at the start of `rest` (a piece of whole
    /// lines; line number `number`) when it is taken here, and where the
    /// next line starts in `rest`: `Some((None, _))` for a line taken
    /// without a move, `None` when declined.
    pub(super) fn take_at(&mut self, rest: &[u8], number: usize) -> Option<(Option<Plain>, usize)> {
        if !self.enabled || number == 1 {
            return None;
        }
        let window = rest.first_chunk::<WINDOW>().filter(|_| rest.first() != Some(&b'('));
        let (line, len) = match window.and_then(|w| self.scan_window(w)) {
            Some(taken) => taken,
            None => self.scan(rest)?,
        };
        let step = self.take_line(line)?;
        Some((step, Self::line_end(rest, len)))
    }

    /// The move of `line` when it is taken here: `Some(None)` for a line
    /// taken without a move, `None` when declined.
    fn take_line(&mut self, line: Line<'_>) -> Option<Option<Plain>> {
        let Line::Move { g, x, z, f } = line else {
            return Some(None);
        };
        let motion = g.or(self.motion)?;
        let from = Point::new(self.x?, self.z?);
        let to = Point::new(x.unwrap_or(from.x), z.unwrap_or(from.z));
        let f_text = f.and_then(FText::new);
        let step = match motion {
            MotionMode::G00 | MotionMode::G01 => {
                // F sets the lead in force (`State::scan`): its value is
                // known when the reader gave this text's.
                if f.is_some() {
                    self.lead = f_text.as_ref().and_then(|t| self.cached(t));
                }
                self.thread_run = Some(None);
                let kind = if motion == MotionMode::G00 { Kind::Rapid } else { Kind::Feed };
                (from != to).then_some(Plain { kind, from, to, lead: None, sync: false })
            }
            MotionMode::G32 => {
                let sync = match self.thread_run? {
                    None => true,
                    Some(a) if a == StartAngle::ZERO => false,
                    Some(_) => return None,
                };
                let lead = match f {
                    Some(_) => f_text.as_ref().and_then(|t| self.cached(t))?,
                    None => self.lead?,
                };
                if from == to {
                    return None;
                }
                self.lead = Some(lead);
                self.thread_run = Some(Some(StartAngle::ZERO));
                Some(Plain { kind: Kind::Thread, from, to, lead: Some(lead), sync })
            }
            _ => return None,
        };
        if f_text.is_some() {
            self.unread_f = f_text;
        }
        self.motion = Some(motion);
        (self.x, self.z) = (Some(to.x), Some(to.z));
        self.unread_move = Some(Unread { motion, from, to });
        Some(step)
    }

    /// A length in increments as a word's number (with its decimal point).
    fn number(&self, v: i64, out: &mut Vec<u8>) {
        if v < 0 {
            out.push(b'-');
        }
        let (int, frac) = (
            v.unsigned_abs() / self.per_unit.unsigned_abs(),
            v.unsigned_abs() % self.per_unit.unsigned_abs(),
        );
        out.extend_from_slice(int.to_string().as_bytes());
        out.push(b'.');
        let frac = frac.to_string();
        for _ in frac.len()..self.decimals as usize {
            out.push(b'0');
        }
        out.extend_from_slice(frac.as_bytes());
    }

    /// Brings `reader` to the state the lines taken here left, and numbers
    /// its next line `number`: before it reads a declined line.
    ///
    /// # Errors
    ///
    /// None where this path takes only what the reader reads alike (the
    /// property test); an error of the lines read is passed on.
    pub(super) fn sync(&mut self, reader: &mut LineReader<'_>, number: usize) -> Result<(), ProgramError> {
        let mut lines: Vec<Vec<u8>> = Vec::new();
        if let Some(f) = self.unread_f.take() {
            lines.push(f.as_bytes().to_vec());
        }
        if let Some(m) = self.unread_move.take() {
            let mut line = Vec::with_capacity(32);
            let point = |code: &[u8], p: Point, line: &mut Vec<u8>| {
                line.extend_from_slice(code);
                line.extend_from_slice(b" X");
                self.number(p.x, line);
                line.extend_from_slice(b" Z");
                self.number(p.z, line);
            };
            match m.motion {
                // A thread run, as the last thread block began it or went
                // on with it: a fresh run from where that block started.
                MotionMode::G32 => {
                    point(b"G00", m.from, &mut line);
                    lines.push(std::mem::take(&mut line));
                    point(b"G32", m.to, &mut line);
                }
                MotionMode::G00 => point(b"G00", m.to, &mut line),
                _ => point(b"G01", m.to, &mut line),
            }
            lines.push(line);
        }
        for line in &lines {
            while let Some(r) = reader.next_in_with(line, |_| ()) {
                r?;
            }
        }
        reader.start_at(MainStart { offset: 0, lines_before: number - 1 });
        Ok(())
    }

    /// What the reader's `item` shows of the state (the items of a
    /// declined line, in order).
    pub(super) fn learn(&mut self, item: &Item<'_>) {
        match item {
            Item::Move(m) => {
                (self.x, self.z) = m.to;
                self.motion = Some(m.motion);
                self.thread_run = Some(None);
                if m.block.words.has('F') {
                    self.lead = None;
                }
            }
            Item::G32(c) if c.g32.run_out == G32RunOut::None => {
                (self.x, self.z) = (Some(c.g32.end.x), Some(c.g32.end.z));
                self.motion = Some(MotionMode::G32);
                self.thread_run = Some(Some(c.g32.start_angle));
                self.lead = Some(c.g32.lead);
                if let (Ok(Some(f)), false) = (c.block.get('F'), c.block.words.has('I')) {
                    let text = f.text();
                    if let Some(t) = FText::new(text.as_bytes()) {
                        if self.cached(&t).is_none() && self.leads.len() < LEADS {
                            self.leads.push((t, c.g32.lead));
                        }
                    }
                }
            }
            Item::Source(b) if b.words.is_empty() => {}
            _ => {
                (self.x, self.z, self.motion, self.lead, self.thread_run) = (None, None, None, None, None);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use cycleref::units::{IncrementSystem, InputUnit};
    use cycleref::XMode;
    use cycleref_spec::ProfileName;
    use proptest::prelude::*;

    use super::super::trace::NcTrace;
    use super::*;

    /// Every step and the first error of `text` read as a trace, with or
    /// without the fast path.
    fn read(text: &str, machine: &Machine, units: Units, fast: bool) -> Vec<String> {
        let trace = NcTrace::new(Box::new(text.as_bytes()), machine, units, fast);
        let mut out = Vec::new();
        for r in trace {
            match r {
                Ok(s) => out.push(format!("{s:?}")),
                Err(e) => {
                    out.push(format!("{e:?} / {e}"));
                    break;
                }
            }
        }
        out
    }

    fn machine(profile: u8, calculator: bool, radius: bool) -> Machine {
        let name = match profile % 3 {
            0 => ProfileName::Gsk980,
            1 => ProfileName::Gsk988,
            _ => ProfileName::Fanuc,
        };
        let mut m = Machine::new(name);
        m.calculator_input = calculator;
        if radius {
            m.x_mode = XMode::Radius;
        }
        m
    }

    fn units(inch: bool, is_c: bool) -> Units {
        Units {
            system: if is_c { IncrementSystem::IsC } else { IncrementSystem::IsB },
            unit: if inch { InputUnit::Inch } else { InputUnit::Metric },
        }
    }

    /// Numbers: the writer's, and adversarial ones.
    fn number() -> impl Strategy<Value = String> {
        prop_oneof![
            4 => prop::sample::select(vec![
                "10.000", "10.0", "10", "-5.5", "-5.500", "0", "0.0", "-0.000", "20.001", "64.400",
                "-37.000", "8.961", "10.0001", "10.00001", "10.000000", "999999.999", "1000000.000",
                "999999999", "1000000000", "99999999999999999999", "9999.9999", "99999.99999",
                "007.5", ".5", "5.", "+5.0", "-", "1e5", "1.2.3", "--1", "0.1", "1.10",
                "1.00000000000000000000000001", "-0.99999999999999999999999",
            ]).prop_map(str::to_string),
            1 => ("-?[0-9]{1,3}", "[0-9]{6,30}").prop_map(|(i, f)| format!("{i}.{f}")),
            2 => ("-?[0-9]{1,3}", "[0-9]{1,4}").prop_map(|(i, f)| format!("{i}.{f}")),
            1 => "[-+.0-9]{0,12}",
        ]
    }

    fn lead() -> impl Strategy<Value = String> {
        prop::sample::select(vec![
            "6.0",
            "6",
            "2",
            "2.0",
            "0.15",
            "0.2",
            "0",
            "0.0",
            "1.5",
            "6.00",
            "06.0",
            "0.0000001",
            "99999",
            "10000",
            "1.2345678",
            ".5",
            "5.",
            "-2",
            "12345678901234567",
        ])
        .prop_map(str::to_string)
    }

    fn comment() -> impl Strategy<Value = String> {
        prop_oneof![
            3 => prop::sample::select(vec![
                "(rough 1 start 1 depth 1.800 cut 1.800)", "(part 0)", "()", "(a;b)", "(a(b)c)", "(unclosed",
                "(ü)", "(日本語)", "(tab\there)", "(%)", "(/)", "(G00 X1 Z1)", "(MSG, hi)", "(a) (b)",
                "(a)x", ")",
            ]).prop_map(str::to_string),
            1 => "\\([ -~]{0,12}\\)",
            1 => "\\(\\PC{0,6}\\)",
        ]
    }

    /// A word of any letter.
    fn any_word() -> impl Strategy<Value = String> {
        ("[A-Za-z]", number()).prop_map(|(l, n)| format!("{l}{n}"))
    }

    /// A line of the writer's shape, or near it.
    fn plain_line() -> impl Strategy<Value = String> {
        (
            prop::sample::select(vec![
                "", "G00", "G01", "G32", "G0", "G1", "G02", "G33", "g00", "G04", "G50",
            ]),
            prop::option::of(number()),
            prop::option::of(number()),
            prop::option::of(lead()),
            prop::option::of(comment()),
            prop::sample::select(vec![" ", " ", " ", " ", "  ", "\t", ""]),
        )
            .prop_map(|(g, x, z, f, c, sep)| {
                let mut words: Vec<String> = Vec::new();
                if !g.is_empty() {
                    words.push(g.to_string());
                }
                words.extend(x.map(|x| format!("X{x}")));
                words.extend(z.map(|z| format!("Z{z}")));
                words.extend(f.map(|f| format!("F{f}")));
                words.extend(c);
                words.join(sep)
            })
    }

    fn line() -> impl Strategy<Value = String> {
        prop_oneof![
            12 => plain_line(),
            3 => comment(),
            1 => Just(String::new()),
            2 => prop::collection::vec(any_word(), 1..4).prop_map(|w| w.join(" ")),
            1 => (plain_line(), any_word()).prop_map(|(l, w)| format!("{l} {w}")),
            1 => (any_word(), plain_line()).prop_map(|(w, l)| format!("{w} {l}")),
            2 => prop::sample::select(vec![
                "G50 X100 Z50", "G50 X10.0 Z-5.0", "M03 S500", "O0100", "F2", "F6.0", "G01", "G32",
                "G32 X1.0 Z2.0 F2 Q5", "G00 U1.0 W2.0", "G04 P1", "G32 X10.0 Z-20.0 I5", "%",
                "/G00 X1.0 Z1.0", "N10 G00 X1.0 Z1.0", "G00 X1.0 Z1.0;G01 Z2.0", "G02 X1.0 Z1.0 I1.0 K1.0",
                " G00 X1.0 Z1.0", "G00 X1.0 Z1.0 ", "G00 X1.0 Z1.0 F6.0 (c)", "G76 P020560 Q150 R0.1",
                "G20", "G21", "G00 X1.0 X2.0", "G00 G01 X1.0", "X1.0 G00", "Z1.0 X1.0", "G32 F6.0 X1.0",
                "G00 X10.000 Z10.000", "G32 X10.000 Z-20.000 F6.0", "G32 X12.000 Z-23.000 F6.0",
                "G32 X10.000 Z-20.000", "G32 Z-25.000 F2.0", "X12.000", "Z-2.000", "M30", "M02",
                "G00 X\u{e9}1.0", "G00 X1.0 Z1.0\r",
                // Comments after each kind of word, and lines that end
                // after a space or inside a word.
                "G01 X1.0 (c)", "G00 (c)", "F0.2 (c)", "Z-2.000 F0.2", "G32 Z-20.000 F2 (x)",
                "X1.000 (a;b)", "G00 X1.000 Z", "G00 X", "G0", "G00 X1.000 Z2.000 F", "(c) X1.0",
                "G00 X1.000 (", "G00 X1.000 ( )", "G00 X1.000 ()", "G00 X1.000 Z2.000 (é)",
            ]).prop_map(str::to_string),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The fast path gives the reader's steps and errors, line for
        /// line, on lines of the writer's shapes and on adversarial ones
        /// (every word letter, odd spacing, comments, Unicode, huge and
        /// malformed numbers), under every profile of the FANUC-style
        /// dialects, both units and increment systems, calculator input
        /// and radius X.
        #[test]
        fn fast_path_is_the_reader(
            lines in prop::collection::vec(line(), 1..40),
            profile in 0_u8..3,
            calculator in any::<bool>(),
            radius in any::<bool>(),
            inch in any::<bool>(),
            is_c in any::<bool>(),
            start in prop::sample::select(vec!["G50 X100.0 Z50.0", "G00 X80.000 Z10.000", "O0100", ""]),
            ends in prop::collection::vec(prop::sample::select(vec!["\n", "\n", "\n", "\r\n", "\r"]), 41),
            last_end in any::<bool>(),
        ) {
            let m = machine(profile, calculator, radius);
            let u = units(inch, is_c);
            // Each line ended by LF, CR LF or a lone CR (R-LINEEND), the
            // last with or without one: the fast path finds line ends
            // itself.
            let mut text = String::new();
            let count = lines.len() + 1;
            for (n, (line, end)) in std::iter::once(start.to_string()).chain(lines).zip(&ends).enumerate() {
                text.push_str(&line);
                if n + 1 < count || last_end {
                    text.push_str(end);
                }
            }
            prop_assert_eq!(read(&text, &m, u, true), read(&text, &m, u, false), "{}", text);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// Where the window's reading takes a line, it is the scan's: the
        /// same words and length, on lines of the writer's shapes and
        /// adversarial ones followed by what else a piece may hold, under
        /// both units and increment systems and every profile.
        #[test]
        fn window_is_the_scan(
            first in line(),
            ends in prop::sample::select(vec!["\n", "\r\n", "\r", ""]),
            after in "[ -~\n\r]{0,80}",
            profile in 0_u8..3,
            calculator in any::<bool>(),
            inch in any::<bool>(),
            is_c in any::<bool>(),
        ) {
            let f = FastNc::new(&machine(profile, calculator, false), units(inch, is_c), true);
            let text = format!("{first}{ends}{after}");
            let rest = text.as_bytes();
            if let Some(w) = rest.first_chunk::<WINDOW>() {
                if let Some(taken) = f.scan_window(w) {
                    prop_assert_eq!(Some(taken), f.scan(rest), "{:?}", text);
                }
            }
        }
    }

    #[test]
    fn the_writers_lines_are_taken_and_the_reader_agrees() {
        let m = Machine::new(ProfileName::Gsk980);
        let u = m.units();
        let text = "O0100\nG50 X100 Z50\nM03 S500\n(part 0)\nG00 X80 Z10\n(G76 line 7)\n\
                    G00 X64.400 Z8.961\nG32 X64.400 Z-37.000 F6.0\nG32 X70.400 Z-40.000 F6.0\n\
                    G00 X80.000 Z-40.000\nG00 X80.000 Z10.000\nG00 X62.908 Z8.530\n\
                    G32 X62.908 Z-37.000 F6.0\nG32 X68.908 Z-40.000 F6.0\nG00 X80.000 Z-40.000\n\
                    G01 X21.001 Z-3.25 F0.15 (finish 1)\nX24.004\nG01 Z-9.003\nG00 X100 Z50\n\
                    G32 X62.908 Z-37.000\nG00 X10.0 Z1.0 ; x\n";
        let fast = read(text, &m, u, true);
        assert_eq!(fast, read(text, &m, u, false));
        // The last line's `;` ends a block whose `x` the reader refuses:
        // declined, and the reader's error stands.
        assert!(fast.last().is_some_and(|e| e.starts_with("Program { error: ProgramError { line: 21")));
        // The shapes taken here.
        let mut f = FastNc::new(&m, u, true);
        f.x = Some(1);
        f.z = Some(1);
        f.motion = Some(MotionMode::G00);
        assert_eq!(
            f.parse(b"G00 X64.400 Z8.961"),
            Some(Line::Move { g: Some(MotionMode::G00), x: Some(64_400), z: Some(8_961), f: None })
        );
        assert_eq!(
            f.parse(b"G01 X21.001 Z-3.25 F0.15 (finish 1)"),
            Some(Line::Move {
                g: Some(MotionMode::G01),
                x: Some(21_001),
                z: Some(-3_250),
                f: Some(&b"F0.15"[..])
            })
        );
        assert_eq!(f.parse(b"(part 0)"), Some(Line::Nothing));
        assert_eq!(f.parse(b"G00 X10.0 Z1.0 ; x"), None);
        assert_eq!(f.parse(b"G00  X10.0"), None);
        assert_eq!(f.parse(b"G00 X10.0001"), None);
        // The window's reading takes the writer's lines, as the scan does.
        for line in ["G32 X64.400 Z-37.000 F6.0", "G00 X80.000 Z10.000", "X24.004", "G01 Z-9.003 F0.15"] {
            let text = format!("{line}\n{}", "G00 X80.000 Z10.000\n".repeat(4));
            let w = text.as_bytes().first_chunk::<WINDOW>().copied();
            let taken = w.as_ref().and_then(|w| f.scan_window(w));
            assert!(taken.is_some(), "{line}");
            assert_eq!(taken, f.scan(text.as_bytes()), "{line}");
        }
    }
}
