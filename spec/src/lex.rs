//! Splitting program text into blocks of words, one block at a time.
//!
//! [`Lexer`] walks the program's bytes and yields one [`Block`] at a time,
//! borrowing its text and words from the source: no per-word or per-block
//! allocation on the usual path (a block's words live inline up to
//! [`INLINE_WORDS`]), so reading costs the same memory whatever the
//! program's length. [`lex`] collects the blocks for callers that want them
//! all.
//!
//! Accepted: `%` lines, a program number `O` in a block of its own, a
//! sequence number `N` at the start of a block, `( )` comments (also the
//! full-width `（ ）` of the Chinese manuals), `;` (and `；`) or a newline as
//! block end, blank lines, spaces anywhere between words and between an
//! address and its value, words in any order, upper or lower case, a
//! leading `/` (block delete, treated as switched off) and a UTF-8
//! byte-order mark at the start of the text.
//!
//! The text is read as bytes (reading R-ENCODING). Bytes inside a comment
//! are opaque: GSK controls write Chinese comments in GBK, which is not
//! UTF-8, and such a comment is kept and echoed byte for byte. Outside a
//! comment the text must be UTF-8; any other byte is an error naming its
//! line and byte column.
//!
//! Every block keeps its source line and text for messages and for echoing.

use std::borrow::Cow;

use arrayvec::ArrayVec;
use rust_decimal::Decimal;

use crate::error::{ErrorKind, ProgramError};

/// How many words a block holds without a heap allocation. Longer blocks
/// are read all the same, with one allocation.
pub const INLINE_WORDS: usize = 6;

/// A number as written after an address: a sign, digits, perhaps a
/// decimal point and more digits, borrowed from the program's text.
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Number<'a> {
    /// A leading minus sign.
    pub negative: bool,
    /// The digits and the decimal point, as written (`060.640`, `.5`, `6`):
    /// ASCII, kept as bytes (the lexer need not make a `str` of its line).
    digits: &'a [u8],
    /// Where the decimal point is in `digits`, if there is one.
    point: Option<u32>,
}

impl<'a> Number<'a> {
    /// A number from its parts: `digits` are ASCII digits with at most one
    /// `.` (the decimal point).
    #[must_use]
    pub fn new(negative: bool, digits: &'a str) -> Number<'a> {
        let point = digits.bytes().position(|b| b == b'.').and_then(|p| u32::try_from(p).ok());
        Number { negative, digits: digits.as_bytes(), point }
    }

    /// Digits before the decimal point, as written (leading zeros kept).
    #[must_use]
    pub fn int_digits(&self) -> &'a str {
        ascii(self.int_bytes())
    }

    /// Digits after the decimal point, when there is a decimal point.
    #[must_use]
    pub fn frac_digits(&self) -> Option<&'a str> {
        self.frac_bytes().map(ascii)
    }

    /// [`Number::int_digits`] as bytes.
    pub(crate) fn int_bytes(&self) -> &'a [u8] {
        match self.point {
            Some(p) => self.digits.get(..p as usize).unwrap_or_default(),
            None => self.digits,
        }
    }

    /// [`Number::frac_digits`] as bytes.
    pub(crate) fn frac_bytes(&self) -> Option<&'a [u8]> {
        self.point.map(|p| self.digits.get(p as usize + 1..).unwrap_or_default())
    }

    /// True when the number was written with a decimal point.
    #[must_use]
    pub fn has_point(&self) -> bool {
        self.point.is_some()
    }

    /// The exact value, with the scale as written (`2.50` has scale 2), or
    /// `None` when no [`Decimal`] holds it exactly.
    #[must_use]
    pub fn decimal(&self) -> Option<Decimal> {
        let frac = self.frac_bytes().unwrap_or_default();
        let int = self.int_bytes();
        // The usual case without an allocation: at most 28 decimals and a
        // mantissa below 2^96.
        let mut mantissa: u128 = 0;
        let mut fits = frac.len() <= 28;
        for &b in int.iter().chain(frac) {
            match mantissa.checked_mul(10).and_then(|m| m.checked_add(u128::from(b - b'0'))) {
                Some(m) if m < (1 << 96) => mantissa = m,
                _ => {
                    fits = false;
                    break;
                }
            }
        }
        if fits {
            let scale = u32::try_from(frac.len()).ok()?;
            let signed = i128::try_from(mantissa).ok()?;
            let mut d = Decimal::try_from_i128_with_scale(signed, scale).ok()?;
            d.set_sign_negative(self.negative);
            return Some(d);
        }
        // Beyond that, `from_str_exact` decides (it may still hold the
        // value by dropping trailing zeros, or refuse to round).
        let mut s = String::with_capacity(int.len() + frac.len() + 3);
        if self.negative {
            s.push('-');
        }
        s.push_str(if int.is_empty() { "0" } else { ascii(int) });
        if !frac.is_empty() {
            s.push('.');
            s.push_str(ascii(frac));
        }
        Decimal::from_str_exact(&s).ok()
    }

    /// The value in units of 10^-`decimals` (least increments), exactly,
    /// by integer arithmetic: `Some(Some(v))`; `Some(None)` when the value
    /// is finer than that; `None` when it has too many digits for this
    /// shortcut (more than 18 with the decimals), which [`Number::decimal`]
    /// then decides.
    #[must_use]
    pub fn scaled(&self, decimals: u32) -> Option<Option<i64>> {
        let d = decimals as usize;
        if let Some(short) =
            scaled_short(self.int_bytes(), self.frac_bytes().unwrap_or_default(), self.negative, d)
        {
            return Some(short);
        }
        let (int, frac) = self.significant();
        if frac.len() > d {
            return Some(None);
        }
        if int.len() + d > 18 {
            return None;
        }
        // At most 18 digits in all: no overflow.
        let v = int.iter().chain(frac).fold(0_i64, |v, b| v * 10 + i64::from(b - b'0'));
        let v = v * POW10[d - frac.len()];
        Some(Some(if self.negative { -v } else { v }))
    }

    /// The value times 10^`scale`, when that is a whole number that an
    /// `i128` holds (digits finer than 10^-`scale` give `None`, as does a
    /// value of more than 38 digits). `75.10` with scale 1 is 751.
    #[must_use]
    pub fn exact(&self, scale: u32) -> Option<i128> {
        let (int, frac) = self.significant();
        let d = scale as usize;
        if frac.len() > d {
            return None;
        }
        if int.len() + d <= 18 {
            // At most 18 digits: an i64 holds them (the usual case: G
            // codes, leads).
            let v = int.iter().chain(frac).fold(0_i64, |v, b| v * 10 + i64::from(b - b'0'));
            let v = i128::from(v * POW10[d - frac.len()]);
            return Some(if self.negative { -v } else { v });
        }
        let mut v: i128 = 0;
        for b in int.iter().copied().chain((0..d).map(|i| frac.get(i).copied().unwrap_or(b'0'))) {
            v = v.checked_mul(10)?.checked_add(i128::from(b - b'0'))?;
        }
        Some(if self.negative { -v } else { v })
    }

    /// True when the value is greater than zero (as [`Number::decimal`]
    /// compared with zero: a value no `Decimal` holds is not).
    #[must_use]
    pub fn is_positive(&self) -> bool {
        // Up to 19 digits and a point, `decimal` always holds the value.
        if self.digits.len() <= 20 {
            !self.negative && self.digits.iter().any(|b| matches!(b, b'1'..=b'9'))
        } else {
            self.decimal().is_some_and(|d| d > Decimal::ZERO)
        }
    }

    /// The digits before the point without leading zeros and the digits
    /// after it without trailing zeros.
    fn significant(&self) -> (&'a [u8], &'a [u8]) {
        let b = self.digits;
        let (mut int, mut frac): (&[u8], &[u8]) = match self.point {
            Some(p) => (b.get(..p as usize).unwrap_or_default(), b.get(p as usize + 1..).unwrap_or_default()),
            None => (b, &[]),
        };
        while let [b'0', rest @ ..] = int {
            int = rest;
        }
        while let [rest @ .., b'0'] = frac {
            frac = rest;
        }
        (int, frac)
    }

    /// The value when it is a whole number (a decimal point followed only by
    /// zeros counts as whole).
    #[must_use]
    pub fn integer(&self) -> Option<i64> {
        let (int, frac) = self.significant();
        if !frac.is_empty() {
            return None;
        }
        let mut v: i64 = 0;
        for &b in int {
            v = v.checked_mul(10)?.checked_add(i64::from(b - b'0'))?;
        }
        Some(if self.negative { -v } else { v })
    }
}

/// An address letter and its number.
///
/// A word is its text and its letter (24 bytes, so that a block's words sit
/// inline and move cheaply); its [`Number`] is read from the text when it is
/// asked for. Two words are equal when their letters and texts are (where
/// the lexer found the number is not part of a word's value).
#[derive(Clone, Copy)]
pub struct Word<'a> {
    /// The address, upper case.
    pub letter: char,
    /// The word as written, from its letter to its last digit (spaces
    /// between the letter and the number kept): ASCII, kept as bytes (the
    /// lexer need not make a `str` of its line).
    raw: &'a [u8],
    /// Where the number's digits start in `raw` (after the spaces and the
    /// sign), or [`SLOW`] when `raw` is too long for a byte: the lexer
    /// knows it, so [`Word::number`] need not look again. These three
    /// fields fill what would be padding: a word stays 24 bytes.
    at: u8,
    /// Where the decimal point is in the digits, or [`SLOW`] for none.
    point: u8,
    /// A leading minus sign.
    negative: bool,
}

impl PartialEq for Word<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.letter == other.letter && self.raw == other.raw
    }
}

impl Eq for Word<'_> {}

impl std::fmt::Debug for Word<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Word").field("letter", &self.letter).field("raw", &ascii(self.raw)).finish()
    }
}

/// 10^k for k up to 18.
const POW10: [i64; 19] = {
    let mut p = [1_i64; 19];
    let mut k = 1;
    while k < 19 {
        p[k] = p[k - 1] * 10;
        k += 1;
    }
    p
};

/// `bytes`, ASCII by construction (a word's text, a number's digits), as
/// a `str`.
fn ascii(bytes: &[u8]) -> &str {
    std::str::from_utf8(bytes).unwrap_or_default()
}

impl std::fmt::Debug for Number<'_> {
    /// The digits as text (they are kept as bytes).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Number")
            .field("negative", &self.negative)
            .field("digits", &ascii(self.digits))
            .field("point", &self.point)
            .finish()
    }
}

/// [`Number::scaled`] of the digits `int` `.` `frac` (leading and trailing
/// zeros included) when they are short enough to need no care: at most 18
/// digits, and at most 18 once scaled by 10^`d` (so no overflow); `None`
/// otherwise, for the caller's longer way (which drops the zeros first).
/// The one shortcut of [`Number::scaled`] and [`Word::scaled`].
#[inline]
fn scaled_short(int: &[u8], frac: &[u8], negative: bool, d: usize) -> Option<Option<i64>> {
    if int.len() + frac.len() > 18 || int.len() + d > 18 {
        return None;
    }
    let v = int.iter().chain(frac).fold(0_i64, |v, &b| v * 10 + i64::from(b - b'0'));
    let v = if frac.len() <= d {
        v * POW10[d - frac.len()]
    } else if v % POW10[frac.len() - d] == 0 {
        // Finer digits that are all zeros (`1.50000`, d = 3).
        v / POW10[frac.len() - d]
    } else {
        return Some(None);
    };
    Some(Some(if negative { -v } else { v }))
}

/// "Not known": see [`Word`].
const SLOW: u8 = u8::MAX;

impl<'a> Word<'a> {
    /// A word from `raw`, the text it was read from: an address letter,
    /// perhaps spaces or tabs, a sign, digits with at most one `.`.
    #[must_use]
    pub fn new(letter: char, raw: &'a str) -> Word<'a> {
        Word { letter, raw: raw.as_bytes(), at: SLOW, point: SLOW, negative: false }
    }

    /// The value.
    #[must_use]
    #[inline]
    pub fn number(&self) -> Number<'a> {
        if self.at != SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            let point = (self.point != SLOW).then_some(u32::from(self.point));
            return Number { negative: self.negative, digits, point };
        }
        self.number_slow()
    }

    /// [`Word::number`] read from the text (a word made by [`Word::new`],
    /// or one too long for the lexer's offsets).
    fn number_slow(&self) -> Number<'a> {
        let rest = ascii(self.raw.get(1..).unwrap_or_default()).trim_start_matches([' ', '\t']);
        match rest.as_bytes().first() {
            Some(b'-') => Number::new(true, rest.get(1..).unwrap_or_default()),
            Some(b'+') => Number::new(false, rest.get(1..).unwrap_or_default()),
            _ => Number::new(false, rest),
        }
    }

    /// [`Number::scaled`] of [`Word::number`], without making the number
    /// on the usual path (where the lexer found the digits and the point).
    #[inline]
    pub(crate) fn scaled(&self, decimals: u32) -> Option<Option<i64>> {
        if self.at != SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            let (int, frac): (&[u8], &[u8]) = if self.point == SLOW {
                (digits, &[])
            } else {
                let p = usize::from(self.point);
                (digits.get(..p).unwrap_or_default(), digits.get(p + 1..).unwrap_or_default())
            };
            if let Some(short) = scaled_short(int, frac, self.negative, decimals as usize) {
                return Some(short);
            }
        }
        self.number().scaled(decimals)
    }

    /// [`Number::integer`] of [`Word::number`], without making the number
    /// for a word of at most 18 digits without a point (a G or M code).
    #[inline]
    pub(crate) fn integer(&self) -> Option<i64> {
        if self.at != SLOW && self.point == SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            if digits.len() <= 18 {
                let mut v = 0_i64;
                for &b in digits {
                    v = v * 10 + i64::from(b - b'0');
                }
                return Some(if self.negative { -v } else { v });
            }
        }
        self.number().integer()
    }

    /// True when the word's number has a decimal point.
    #[inline]
    pub(crate) fn has_point(&self) -> bool {
        if self.at == SLOW {
            self.number().has_point()
        } else {
            self.point != SLOW
        }
    }

    /// The word as written, without the spaces inside it (for messages).
    #[must_use]
    pub fn text(&self) -> Cow<'a, str> {
        let raw = ascii(self.raw);
        if raw.bytes().any(|b| b == b' ' || b == b'\t') {
            Cow::Owned(raw.chars().filter(|c| !c.is_whitespace()).collect())
        } else {
            Cow::Borrowed(raw)
        }
    }
}

/// The words of a block: inline up to [`INLINE_WORDS`], on the heap
/// beyond. Derefs to a slice.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Words<'a> {
    store: WordStore<'a>,
    /// Bit `letter - 'A'` set when the letter is there ...
    present: u32,
    /// ... and when it is there more than once.
    repeated: u32,
}

/// The bit of an address letter in [`Words`]' masks (0 for a non-letter).
pub(crate) fn letter_bit(letter: char) -> u32 {
    if letter.is_ascii_uppercase() {
        1 << (letter as u32 - 'A' as u32)
    } else {
        0
    }
}

// The inline variant is the point: no allocation for an ordinary block.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq, Eq)]
enum WordStore<'a> {
    Inline(ArrayVec<Word<'a>, INLINE_WORDS>),
    Heap(Vec<Word<'a>>),
}

impl<'a> Words<'a> {
    /// No words.
    #[must_use]
    pub fn new() -> Words<'a> {
        Words { store: WordStore::Inline(ArrayVec::new()), present: 0, repeated: 0 }
    }

    /// True when a word has the address `letter`.
    #[must_use]
    pub fn has(&self, letter: char) -> bool {
        self.present & letter_bit(letter) != 0
    }

    /// True when more than one word has the address `letter`.
    #[must_use]
    pub fn repeats(&self, letter: char) -> bool {
        self.repeated & letter_bit(letter) != 0
    }

    /// Adds `w` after the others.
    #[inline]
    pub fn push(&mut self, w: Word<'a>) {
        let bit = letter_bit(w.letter);
        self.repeated |= self.present & bit;
        self.present |= bit;
        match &mut self.store {
            // The usual case, inlined: room in the inline words.
            WordStore::Inline(v) if !v.is_full() => v.push(w),
            _ => self.push_more(w),
        }
    }

    /// [`Words::push`] past the inline words.
    #[inline(never)]
    fn push_more(&mut self, w: Word<'a>) {
        match &mut self.store {
            WordStore::Inline(v) => {
                let mut heap = Vec::with_capacity(2 * INLINE_WORDS);
                heap.extend(v.drain(..));
                heap.push(w);
                self.store = WordStore::Heap(heap);
            }
            WordStore::Heap(v) => v.push(w),
        }
    }
}

impl Default for Words<'_> {
    fn default() -> Self {
        Words::new()
    }
}

impl<'a> std::ops::Deref for Words<'a> {
    type Target = [Word<'a>];

    fn deref(&self) -> &[Word<'a>] {
        match &self.store {
            WordStore::Inline(v) => v,
            WordStore::Heap(v) => v,
        }
    }
}

impl<'b, 'a> IntoIterator for &'b Words<'a> {
    type Item = &'b Word<'a>;
    type IntoIter = std::slice::Iter<'b, Word<'a>>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// One block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block<'a> {
    /// 1-based source line.
    pub line: usize,
    /// The block's source text without its block end, as bytes: a comment
    /// may hold text in another encoding than UTF-8 (reading R-ENCODING).
    pub text: Cow<'a, [u8]>,
    /// The words, in source order (comments, `N`, `O` and `%` removed).
    pub words: Words<'a>,
}

impl<'a> Block<'a> {
    /// No line, no text, no words: a block to read into.
    pub(crate) fn empty() -> Block<'a> {
        Block { line: 0, text: Cow::Borrowed(&[]), words: Words::new() }
    }

    /// The words with address `letter`.
    pub fn all(&self, letter: char) -> impl Iterator<Item = &Word<'a>> {
        let words: &[Word<'a>] = if self.words.has(letter) { &self.words } else { &[] };
        words.iter().filter(move |w| w.letter == letter)
    }

    /// The single word with address `letter`, if any.
    ///
    /// # Errors
    ///
    /// [`ErrorKind::Duplicate`] when the address appears twice.
    #[inline]
    pub fn get(&self, letter: char) -> Result<Option<&Word<'a>>, ProgramError> {
        if !self.words.repeats(letter) {
            // The usual case, decided by the masks (inlined: most blocks
            // have no S or F).
            if !self.words.has(letter) {
                return Ok(None);
            }
            return Ok(self.words.iter().find(|w| w.letter == letter));
        }
        self.get_repeated(letter)
    }

    /// [`Block::get`] of a letter that is there more than once: the error.
    fn get_repeated(&self, letter: char) -> Result<Option<&Word<'a>>, ProgramError> {
        let mut it = self.all(letter);
        let first = it.next();
        if let Some(second) = it.next() {
            return Err(ProgramError {
                line: self.line,
                word: Some(second.text().into_owned()),
                kind: ErrorKind::Duplicate,
            });
        }
        Ok(first)
    }

    /// True when the block has a word with address `letter`.
    #[must_use]
    pub fn has(&self, letter: char) -> bool {
        self.words.has(letter)
    }

    /// A copy of the block that outlives the text it was read from: its
    /// line and text, without its words (which borrow the text). For a
    /// consumer that keeps a few blocks of a program read a line at a time.
    #[must_use]
    pub fn detached(&self) -> Block<'static> {
        Block { line: self.line, text: Cow::Owned(self.text.to_vec()), words: Words::new() }
    }

    /// The text for a person: UTF-8 as it is, other bytes (a GBK comment)
    /// replaced by U+FFFD.
    #[must_use]
    pub fn text_lossy(&self) -> Cow<'_, str> {
        String::from_utf8_lossy(&self.text)
    }
}

/// Splits `source` into blocks.
///
/// # Errors
///
/// The first error of [`Lexer`].
pub fn lex(source: &str) -> Result<Vec<Block<'_>>, ProgramError> {
    Lexer::new(source.as_bytes()).collect()
}

/// The blocks of a program, one at a time (see the module documentation).
///
/// After an error the lexer yields nothing more.
#[derive(Clone, Debug)]
pub struct Lexer<'a> {
    src: &'a [u8],
    /// Byte offset of the next line.
    pos: usize,
    /// Number of the next line (1-based).
    line: usize,
    /// Byte offset of the line read last.
    line_start: usize,
    /// The current line and where in it the next block starts.
    current: Option<(Line<'a>, usize)>,
    done: bool,
    /// LinuxCNC's o-word lines are blocks of their own, not read as words
    /// ([`oword`]).
    owords: bool,
}

/// Where a [`Lexer`] stands in its source, kept while the lexer itself is
/// not (the source is borrowed again to go on): the line-fed reader
/// ([`crate::reader::LineReader`]) resumes a lexer over the same bytes with
/// it, one block at a time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Position {
    /// Byte offset of the next line.
    pos: usize,
    /// Number of the current line (1-based; 0 before the first).
    line: usize,
    /// The current line's start and end offsets (without its line end),
    /// and where in it the next block starts, when the line goes on.
    current: Option<(usize, usize, usize)>,
    done: bool,
}

impl Position {
    /// The offset of the line after the current one.
    pub(crate) fn next_line_offset(&self) -> usize {
        self.pos
    }
}

const BOM: &[u8] = b"\xEF\xBB\xBF";
/// Where `%` may stand (reading R-SEQNUM).
const MARK_RULE: &str = "`%` marks the start or the end of a program, on a line of its own";
const FULL_SEMI: &[u8] = "；".as_bytes();
const FULL_OPEN: &[u8] = "（".as_bytes();
const FULL_CLOSE: &[u8] = "）".as_bytes();

impl<'a> Lexer<'a> {
    /// A lexer over the bytes of a program. A UTF-8 byte-order mark at the
    /// start is skipped.
    #[must_use]
    pub fn new(src: &'a [u8]) -> Lexer<'a> {
        let pos = if src.starts_with(BOM) { BOM.len() } else { 0 };
        Lexer { src, pos, line: 0, line_start: pos, current: None, done: false, owords: false }
    }

    /// A lexer over one piece of a program (a line read from a stream,
    /// say) whose first line is line `first_line` of the whole: blocks and
    /// errors carry the whole program's line numbers. A byte-order mark is
    /// skipped only when `first_line` is 1.
    #[must_use]
    pub fn at_line(src: &'a [u8], first_line: usize) -> Lexer<'a> {
        let mut lexer = if first_line <= 1 {
            Lexer::new(src)
        } else {
            Lexer { src, pos: 0, line: 0, line_start: 0, current: None, done: false, owords: false }
        };
        lexer.line = first_line.saturating_sub(1);
        lexer
    }

    /// Where the lexer stands, to [`resume`](Lexer::resume) it later.
    pub(crate) fn position(&self) -> Position {
        Position {
            pos: self.pos,
            line: self.line,
            current: self.current.map(|(l, next)| (l.start, l.start + l.bytes.len(), next)),
            done: self.done,
        }
    }

    /// The lexer over `src` at `at`, which [`position`](Lexer::position)
    /// gave for the same bytes.
    pub(crate) fn resume(src: &'a [u8], at: Position) -> Lexer<'a> {
        let current = at.current.and_then(|(start, end, next)| {
            let bytes = src.get(start..end)?;
            Some((Line { start, bytes }, next))
        });
        let line_start = current.map_or(at.pos, |(l, _)| l.start);
        Lexer { src, pos: at.pos, line: at.line, line_start, current, done: at.done, owords: false }
    }

    /// The lexer reading LinuxCNC's o-word lines (`o100 call`) as blocks
    /// of their own, without words, their text the line: the reader reads
    /// them ([`oword`]).
    #[must_use]
    pub(crate) fn with_owords(mut self, on: bool) -> Lexer<'a> {
        self.owords = on;
        self
    }

    /// After an error, goes on at the next line: the index of
    /// subprograms passes over a line it cannot read (only a block that
    /// runs reports its error).
    pub(crate) fn skip_line(&mut self) {
        self.current = None;
        self.done = false;
    }

    /// The byte offset of the line read last (of the last block's line).
    pub(crate) fn line_start(&self) -> usize {
        self.line_start
    }

    /// The next block of a line the lexer can read, passing over the
    /// others ([`skip_line`](Lexer::skip_line)): for the readers that look
    /// ahead for the subprograms, which report nothing of a line that does
    /// not run.
    pub(crate) fn next_readable(&mut self) -> Option<Block<'a>> {
        let mut block = Block::empty();
        loop {
            match self.next_into(&mut block) {
                None => return None,
                Some(Err(_)) => self.skip_line(),
                Some(Ok(())) => return Some(block),
            }
        }
    }

    /// The number of the line read last (0 before the first).
    pub(crate) fn line(&self) -> usize {
        self.line
    }

    /// The next line, without its line end (`\n`, `\r\n` or a lone `\r`,
    /// reading R-LINEEND).
    fn next_line(&mut self) -> Option<Line<'a>> {
        if self.pos >= self.src.len() {
            return None;
        }
        let start = self.pos;
        let rest = &self.src[self.pos..];
        let (bytes, advance) = split_line(rest);
        self.pos += advance;
        self.line += 1;
        self.line_start = start;
        // No UTF-8 check of the line as a whole: `segment` checks every
        // byte outside a comment, and a word is ASCII bytes.
        Some(Line { start, bytes })
    }

    /// Reads one segment of `line` from `start` (up to a block end or the
    /// line's end): its words and the offset after its block end, or
    /// `None` for the offset when the line is finished.
    fn segment(&self, whole: Line<'a>, start: usize, words: &mut Words<'a>) -> Result<Segment, ProgramError> {
        let line = whole.bytes;
        let line_no = self.line;
        let syntax = |msg: String| ProgramError { line: line_no, word: None, kind: ErrorKind::Syntax(msg) };
        let mut pos = start;
        // N and O only first; nothing after O; `/` only first; `%` alone.
        let mut seen = false;
        let mut program_number: Option<Word<'a>> = None;
        let mut mark = false;
        let out_of_place = |what: &str, rule: &'static str| ProgramError {
            line: line_no,
            word: Some(what.to_string()),
            kind: ErrorKind::Misplaced { rule },
        };
        while pos < line.len() {
            let b = line[pos];
            match b {
                b';' => return Ok(Segment { end: pos, next: Some(pos + 1) }),
                b'(' => {
                    pos =
                        comment_end(line, pos + 1).ok_or_else(|| syntax("an unclosed comment `(`".into()))?
                }
                b'%' if !seen && start == 0 => {
                    mark = true;
                    pos += 1;
                }
                b'%' => return Err(out_of_place("%", MARK_RULE)),
                b'/' if !seen && !mark => pos += 1,
                b'/' => return Err(out_of_place("/", "block delete `/` may only start a block")),
                b' ' | b'\t' | b'\x0b' | b'\x0c' | b'\r' => pos += 1,
                b if b.is_ascii_alphabetic() => {
                    let (word, end, has_digits) = read_word(whole, pos);
                    // The usual word goes straight to the block's words; the
                    // rules of the others are out of line.
                    if has_digits && !mark && program_number.is_none() && !matches!(word.letter, 'N' | 'O') {
                        words.push(word);
                    } else {
                        other_word(word, has_digits, mark, seen, &mut program_number, words, line_no)?;
                    }
                    seen = true;
                    pos = end;
                }
                b if b.is_ascii() => {
                    return Err(syntax(format!(
                        "the character `{}`",
                        crate::error::shown(&char::from(b).to_string())
                    )));
                }
                _ => {
                    let rest = &line[pos..];
                    if rest.starts_with(FULL_SEMI) {
                        return Ok(Segment { end: pos, next: Some(pos + FULL_SEMI.len()) });
                    }
                    if rest.starts_with(FULL_OPEN) {
                        pos = comment_end(line, pos + FULL_OPEN.len())
                            .ok_or_else(|| syntax("an unclosed comment `（`".into()))?;
                        continue;
                    }
                    match decode(rest) {
                        Some(c) if c.is_whitespace() => pos += c.len_utf8(),
                        Some(c) => {
                            return Err(syntax(format!(
                                "the character `{}`",
                                crate::error::shown(&c.to_string())
                            )))
                        }
                        None => {
                            return Err(ProgramError {
                                line: line_no,
                                word: None,
                                kind: ErrorKind::Encoding { column: pos + 1, byte: b },
                            })
                        }
                    }
                }
            }
        }
        Ok(Segment { end: line.len(), next: None })
    }
}

/// A LinuxCNC o-word line (reading R-SUBPROGRAM): `o` and a number or a
/// `<name>`, then its keyword (`sub`, `endsub`, `call`, `return`, …) and
/// the rest of the line, spaces before them skipped. The number is as
/// written (`0100` and `100` are one label, as `rs274` reads them); the
/// name is lower case (`rs274` reads `o<MySub>` and `o<mysub>` alike).
#[must_use]
pub fn oword(line: &[u8]) -> Option<(OLabel, &[u8], &[u8])> {
    let skip = |b: &[u8]| -> usize { b.iter().take_while(|c| matches!(c, b' ' | b'\t')).count() };
    let mut i = skip(line);
    if !matches!(line.get(i), Some(b'o' | b'O')) {
        return None;
    }
    i += 1;
    i += skip(&line[i..]);
    let label = match line.get(i) {
        Some(b'<') => {
            let end = i + 1 + line[i + 1..].iter().position(|&b| b == b'>')?;
            let name = std::str::from_utf8(&line[i + 1..end]).ok()?.to_ascii_lowercase();
            i = end + 1;
            OLabel::Name(name)
        }
        Some(b'0'..=b'9') => {
            let n = line[i..].iter().take_while(|b| b.is_ascii_digit()).count();
            let number = std::str::from_utf8(&line[i..i + n]).ok()?.parse::<u64>().ok()?;
            i += n;
            OLabel::Number(number)
        }
        _ => return None,
    };
    i += skip(&line[i..]);
    let k = line[i..].iter().take_while(|b| b.is_ascii_alphabetic()).count();
    Some((label, &line[i..i + k], &line[i + k..]))
}

/// The label of a LinuxCNC o-word.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum OLabel {
    /// `o100`.
    Number(u64),
    /// `o<name>`, lower case.
    Name(String),
}

impl std::fmt::Display for OLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OLabel::Number(n) => write!(f, "o{n}"),
            OLabel::Name(s) => write!(f, "o<{s}>"),
        }
    }
}

/// The first line of `rest` without its line end, and the bytes to skip
/// to the next line: a line ends at `\n`, `\r\n` or a `\r` not followed
/// by `\n` (reading R-LINEEND: CR, LF and CR LF are all line ends, as the
/// controls' editors write them).
///
/// ```
/// use cycleref_spec::lex::split_line;
/// assert_eq!(split_line(b"G00 X1\r\nG01"), (&b"G00 X1"[..], 8));
/// assert_eq!(split_line(b"G00 X1\rG01"), (&b"G00 X1"[..], 7));
/// assert_eq!(split_line(b"G00 X1\nG01"), (&b"G00 X1"[..], 7));
/// assert_eq!(split_line(b"G00 X1"), (&b"G00 X1"[..], 6));
/// ```
#[inline]
#[must_use]
pub fn split_line(rest: &[u8]) -> (&[u8], usize) {
    // memchr2: a line end is found many bytes a step (a byte loop here was
    // a sixth of the reader's time).
    match memchr::memchr2(b'\n', b'\r', rest) {
        Some(i) if rest[i] == b'\r' && rest.get(i + 1) == Some(&b'\n') => (&rest[..i], i + 2),
        Some(i) => (&rest[..i], i + 1),
        None => (rest, rest.len()),
    }
}

/// Where a piece of whole lines may end in `buf` (the offset after its
/// last line end at or after `from`), or `None` when none is known yet: a
/// `\r` as the very last byte read may be the first half of a `\r\n`, so
/// it ends a line only at the end of the text (`eof`).
#[must_use]
pub fn last_line_end(buf: &[u8], from: usize, eof: bool) -> Option<usize> {
    let mut hay = buf.get(from..)?;
    loop {
        let i = memchr::memrchr2(b'\n', b'\r', hay)?;
        if hay[i] == b'\r' && from + i + 1 == buf.len() && !eof {
            hay = &hay[..i];
            continue;
        }
        return Some(from + i + 1);
    }
}

/// A line of the program.
#[derive(Clone, Copy, Debug)]
struct Line<'a> {
    /// Offset of the line's first byte in the source.
    start: usize,
    bytes: &'a [u8],
}

/// Where a block's worth of a line ends (its words go where the caller
/// says).
struct Segment {
    /// Where the block's text ends (its block end, or the line's end).
    end: usize,
    /// Where the next block starts, if the line goes on.
    next: Option<usize>,
}

impl<'a> Iterator for Lexer<'a> {
    type Item = Result<Block<'a>, ProgramError>;

    fn next(&mut self) -> Option<Self::Item> {
        let mut block = Block::empty();
        Some(self.next_into(&mut block)?.map(|()| block))
    }
}

impl<'a> Lexer<'a> {
    /// The next block, read into `block` (whose words it replaces), as
    /// [`Iterator::next`] gives it: the line-fed reader reads a block
    /// where it stays until it moves into its item.
    #[inline(always)]
    pub(crate) fn next_into(&mut self, block: &mut Block<'a>) -> Option<Result<(), ProgramError>> {
        if self.done {
            return None;
        }
        let r = self.next_block(block);
        if !matches!(r, Some(Ok(()))) {
            self.done = true;
        }
        r
    }

    #[inline(always)]
    fn next_block(&mut self, block: &mut Block<'a>) -> Option<Result<(), ProgramError>> {
        loop {
            let (line, start) = match self.current.take() {
                Some(c) => c,
                None => (self.next_line()?, 0),
            };
            block.words = Words::new();
            if self.owords && start == 0 && oword(line.bytes).is_some() {
                block.line = self.line;
                block.text = Cow::Borrowed(trim(line.bytes));
                return Some(Ok(()));
            }
            let seg = match self.segment(line, start, &mut block.words) {
                Ok(s) => s,
                Err(e) => return Some(Err(e)),
            };
            let text = trim(&line.bytes[start..seg.end]);
            // A block end that ends the line leaves nothing to read in it.
            self.current = seg.next.filter(|&n| n < line.bytes.len()).map(|n| (line, n));
            if text.is_empty() && block.words.is_empty() {
                continue;
            }
            block.line = self.line;
            block.text = Cow::Borrowed(text);
            // A comment after a block end on the same line belongs to that
            // block: take every following segment without words.
            while let Some((line, start)) = self.current {
                let mut words = Words::new();
                let seg = match self.segment(line, start, &mut words) {
                    Ok(s) => s,
                    Err(e) => return Some(Err(e)),
                };
                if !words.is_empty() {
                    break;
                }
                let more = trim(&line.bytes[start..seg.end]);
                if !more.is_empty() {
                    // One allocation of the joined size.
                    let mut t = Vec::with_capacity(block.text.len() + 1 + more.len());
                    t.extend_from_slice(&block.text);
                    t.push(b' ');
                    t.extend_from_slice(more);
                    block.text = Cow::Owned(t);
                }
                self.current = seg.next.filter(|&n| n < line.bytes.len()).map(|n| (line, n));
            }
            return Some(Ok(()));
        }
    }
}

fn misplaced(line: usize, word: &Word<'_>, rule: &'static str) -> ProgramError {
    ProgramError { line, word: Some(word.text().into_owned()), kind: ErrorKind::Misplaced { rule } }
}

/// The offset after the comment that starts before `from`, whose bytes are
/// opaque: it ends at the first `)` or `）`.
fn comment_end(line: &[u8], from: usize) -> Option<usize> {
    let rest = &line[from..];
    let close = rest.iter().enumerate().find_map(|(i, &b)| match b {
        b')' => Some(i + 1),
        0xEF if rest[i..].starts_with(FULL_CLOSE) => Some(i + FULL_CLOSE.len()),
        _ => None,
    })?;
    Some(from + close)
}

/// The UTF-8 character at the start of `bytes`, if they start with one.
fn decode(bytes: &[u8]) -> Option<char> {
    let len = match *bytes.first()? {
        b @ 0x00..=0x7F => return Some(char::from(b)),
        0xC2..=0xDF => 2,
        0xE0..=0xEF => 3,
        0xF0..=0xF4 => 4,
        _ => return None,
    };
    std::str::from_utf8(bytes.get(..len)?).ok()?.chars().next()
}

/// The UTF-8 character that ends `bytes`, if they end with one.
fn decode_last(bytes: &[u8]) -> Option<char> {
    if let Some(&b) = bytes.last().filter(|b| b.is_ascii()) {
        return Some(char::from(b));
    }
    (1..=4.min(bytes.len())).find_map(|n| {
        let tail = &bytes[bytes.len() - n..];
        std::str::from_utf8(tail).ok().and_then(|s| {
            let mut cs = s.chars();
            let c = cs.next_back()?;
            (c.len_utf8() == n).then_some(c)
        })
    })
}

/// `bytes` without leading and trailing white space (as `str::trim`).
#[inline]
fn trim(bytes: &[u8]) -> &[u8] {
    // The usual block: neither end is white space (a printable ASCII
    // character is not).
    match (bytes.first(), bytes.last()) {
        (Some(f), Some(l)) if f.is_ascii_graphic() && l.is_ascii_graphic() => bytes,
        _ => trim_ends(bytes),
    }
}

/// [`trim`] of text that may start or end with white space.
fn trim_ends(mut bytes: &[u8]) -> &[u8] {
    // The usual case: ASCII white space (as `char::is_whitespace`) at the
    // ends; the loops below take any other.
    let ascii_space = |b: &u8| matches!(b, b' ' | b'\t' | b'\n' | b'\x0b' | b'\x0c' | b'\r');
    while let [b, rest @ ..] = bytes {
        if !ascii_space(b) {
            break;
        }
        bytes = rest;
    }
    while let [rest @ .., b] = bytes {
        if !ascii_space(b) {
            break;
        }
        bytes = rest;
    }
    // Both ends ASCII (and not white space, after the loops above): no
    // other white space can stand at either end.
    if bytes.first().is_none_or(u8::is_ascii) && bytes.last().is_none_or(u8::is_ascii) {
        return bytes;
    }
    while let Some(c) = decode(bytes).filter(|c| c.is_whitespace()) {
        bytes = &bytes[c.len_utf8()..];
    }
    while let Some(c) = decode_last(bytes).filter(|c| c.is_whitespace()) {
        bytes = &bytes[..bytes.len() - c.len_utf8()];
    }
    bytes
}

/// The word that starts at `start` (an ASCII letter) and the offset after it.
fn read_word(whole: Line<'_>, start: usize) -> (Word<'_>, usize, bool) {
    let line = whole.bytes;
    let letter = char::from(line[start].to_ascii_uppercase());
    let mut pos = start + 1;
    while let Some(b' ' | b'\t') = line.get(pos) {
        pos += 1;
    }
    let num_start = pos;
    if let Some(b'-' | b'+') = line.get(pos) {
        pos += 1;
    }
    let digits_start = pos;
    while let Some(b'0'..=b'9') = line.get(pos) {
        pos += 1;
    }
    let int_len = pos - digits_start;
    let mut frac_len = None;
    if let Some(b'.') = line.get(pos) {
        pos += 1;
        let frac_start = pos;
        while let Some(b'0'..=b'9') = line.get(pos) {
            pos += 1;
        }
        frac_len = Some(pos - frac_start);
    }
    // ASCII by construction: a letter, spaces, a sign, digits, a point.
    let raw = &line[start..pos];
    // The number's place in `raw`, when both offsets fit a byte below
    // `SLOW` (they do but for hundreds of spaces or digits; an `at` of
    // `SLOW` itself sends `Word::number` the slow way).
    let (at, point) = match (u8::try_from(digits_start - start), u8::try_from(int_len)) {
        (Ok(at), Ok(int)) if int != SLOW => (at, if frac_len.is_some() { int } else { SLOW }),
        _ => (SLOW, SLOW),
    };
    let negative = digits_start > num_start && line[num_start] == b'-';
    let word = Word { letter, raw, at, point, negative };
    // No error is made here: a `Result` carrying a `ProgramError` went
    // through memory on the hot path (a store-forwarding stall per word,
    // perf); `other_word` makes it.
    let has_digits = int_len > 0 || frac_len.is_some_and(|f| f > 0);
    (word, pos, has_digits)
}

/// A word of a segment that is not simply pushed: one without a number
/// (`has_digits` false), a word after `%` (`mark`), an N or O word, a word
/// after an O: the rules of [`Lexer`]'s `segment`, in their order.
#[inline(never)]
fn other_word<'a>(
    word: Word<'a>,
    has_digits: bool,
    mark: bool,
    seen: bool,
    program_number: &mut Option<Word<'a>>,
    words: &mut Words<'a>,
    line_no: usize,
) -> Result<(), ProgramError> {
    if !has_digits {
        return Err(no_number(line_no, &word));
    }
    if mark {
        return Err(misplaced(line_no, &word, MARK_RULE));
    }
    match word.letter {
        'N' if !seen => {}
        'N' => {
            return Err(misplaced(
                line_no,
                &word,
                "a sequence number N may only start a block (after an optional `/`)",
            ))
        }
        'O' if !seen => *program_number = Some(word),
        'O' => {
            return Err(misplaced(
                line_no,
                &word,
                "a program number O must stand at the start of a block of its own",
            ))
        }
        _ if program_number.is_some() => {
            // The O word is the one out of place.
            return Err(misplaced(
                line_no,
                program_number.as_ref().unwrap_or(&word),
                "a program number O must stand in a block of its own; nothing may follow it",
            ));
        }
        _ => words.push(word),
    }
    Ok(())
}

/// The error of a word without a number (perhaps with a sign or a point):
/// `word` from its letter to where the lexer stopped.
#[cold]
#[inline(never)]
fn no_number(line_no: usize, word: &Word<'_>) -> ProgramError {
    // Nothing but spaces after the letter: no sign (nor point) either.
    let bare = word.raw.iter().skip(1).all(|&b| b == b' ' || b == b'\t');
    ProgramError {
        line: line_no,
        word: Some(word.text().into_owned()),
        kind: ErrorKind::Syntax(format!(
            "the address `{}` without a number{}",
            word.letter,
            if bare { "" } else { " (only a sign)" }
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::trim;

    /// `trim` against `str::trim` (the definition it follows: white space
    /// as `char::is_whitespace`), on every pairing of a start and an end
    /// drawn from ASCII and other white space and text, ASCII or not.
    #[test]
    fn trim_is_str_trim() {
        let ends = ["", " ", "\t", "\r", "\u{3000}", "\u{a0}", " \u{3000} ", "\u{2003}\t"];
        let middles = ["", "G01 X1", "（注）", "\u{3000}", "X1\u{3000}Z2", "é", "a"];
        for start in ends {
            for middle in middles {
                for end in ends {
                    let text = format!("{start}{middle}{end}");
                    assert_eq!(trim(text.as_bytes()), text.trim().as_bytes(), "{text:?}");
                }
            }
        }
        // Bytes that are not UTF-8 stay (a GBK comment, reading R-ENCODING).
        assert_eq!(trim(b" (\xd6\xd0) "), b"(\xd6\xd0)");
        assert_eq!(trim(b"\xd6\xd0"), b"\xd6\xd0");
    }
}
