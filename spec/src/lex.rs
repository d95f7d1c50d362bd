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
//! block end (on the linuxcnc profile `;` starts a comment to the end of
//! the line instead, reading R-LCNC-READER), blank lines, spaces anywhere between words and between an
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
//!
//! The module's parts: [`Number`] and [`Word`] (`lex/number.rs`), a
//! block's [`Words`] and the [`Block`] (`lex/block.rs`), lines, comments
//! and o-words (`lex/lines.rs`), the word scanner (`lex/scan.rs`); this
//! file holds the [`Lexer`] that walks the text.

use std::borrow::Cow;

use crate::error::{ErrorKind, ProgramError};

mod block;
mod lines;
mod number;
mod scan;

pub(crate) use block::letter_bit;
pub use block::{Block, Words, INLINE_WORDS};
use lines::{comment_end, decode, line_end_len, trim, Line, FULL_OPEN, FULL_SEMI};
pub use lines::{last_line_end, oword, split_line, OLabel};
use number::SLOW;
pub(crate) use number::{digits_value, POW10};
pub use number::{Number, Word};
use scan::{other_word, read_word, MARK_RULE};

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
    /// `;` starts a comment to the end of the line instead of ending the
    /// block (reading R-LCNC-READER `comment`, LinuxCNC's interpreter).
    semicolon_comments: bool,
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

/// The letters of [`Lexer::next_plain`]'s lines, by bit `letter - 'A'`:
/// every letter but M (a call or a return, which the reader's step reads
/// with the calls; N and O the fast scanner gives up on anyway).
const PLAIN_LETTERS: u32 = !block::letter_bit('M');

impl<'a> Lexer<'a> {
    /// A lexer over the bytes of a program. A UTF-8 byte-order mark at the
    /// start is skipped.
    #[must_use]
    pub fn new(src: &'a [u8]) -> Lexer<'a> {
        let pos = if src.starts_with(BOM) { BOM.len() } else { 0 };
        Lexer {
            src,
            pos,
            line: 0,
            line_start: pos,
            current: None,
            done: false,
            owords: false,
            semicolon_comments: false,
        }
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
            Lexer {
                src,
                pos: 0,
                line: 0,
                line_start: 0,
                current: None,
                done: false,
                owords: false,
                semicolon_comments: false,
            }
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
        Lexer {
            src,
            pos: at.pos,
            line: at.line,
            line_start,
            current,
            done: at.done,
            owords: false,
            semicolon_comments: false,
        }
    }

    /// The lexer reading LinuxCNC's o-word lines (`o100 call`) as blocks
    /// of their own, without words, their text the line: the reader reads
    /// them ([`oword`]).
    #[must_use]
    pub(crate) fn with_owords(mut self, on: bool) -> Lexer<'a> {
        self.owords = on;
        self
    }

    /// The lexer reading `;` as LinuxCNC does, a comment to the end of the
    /// line (kept in the block's text, as a `( )` comment), when `on`;
    /// else `;` ends the block (reading R-LCNC-READER).
    #[must_use]
    pub(crate) fn with_semicolon_comments(mut self, on: bool) -> Lexer<'a> {
        self.semicolon_comments = on;
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
    /// line's end) into `words` (empty on entry): its words and the offset
    /// after its block end, or `None` for the offset when the line is
    /// finished.
    ///
    /// The usual segment is read by [`segment_fast`](Lexer::segment_fast),
    /// which gives up on anything else; the segment is then read again from
    /// its start by the general scanner, which alone makes every error.
    #[inline(always)]
    fn segment(&self, whole: Line<'a>, start: usize, words: &mut Words<'a>) -> Result<Segment, ProgramError> {
        debug_assert!(words.is_empty());
        #[cfg(test)]
        if tests::GENERAL_ONLY.with(std::cell::Cell::get) {
            return self.segment_general(whole, start, words);
        }
        if let Some((seg, _)) = self.segment_fast::<false, false>(whole.bytes, start, words) {
            return Ok(seg);
        }
        *words = Words::new();
        self.segment_general(whole, start, words)
    }

    /// [`segment`](Lexer::segment) of a segment made only of ASCII white
    /// space, `( )` comments and words whose letter (not N or O) is followed
    /// at once by a number with at least one digit, ended by `;` or the
    /// line's end: one loop over its bytes that pushes each word as it
    /// reads it, the word as [`read_word`] makes it (the same text, digits'
    /// place, point and sign). `None`, with some of the words pushed, at
    /// anything else (`%`, `/`, N, O, a space after a letter, a letter
    /// without digits, a number longer than a byte's offsets, an unclosed
    /// comment, a byte outside ASCII, any other character): the general
    /// scanner reads that segment. Held equal to it by the proptest in
    /// this module's tests (issue 33: the lexer was a third of a reading).
    ///
    /// `FUSED`: `line` is the rest of the text from a line's start, whose
    /// end is not yet known ([`first_segment_fast`](Lexer::first_segment_fast)):
    /// a `\n` or `\r` ends the line (and the segment), as [`split_line`]
    /// ends it, and the line's length and the bytes to skip to the next
    /// are given with the segment when the segment ends at the line's end
    /// (`None` after a `;` that more of the line follows; never given
    /// unless `FUSED`). A `;` that starts a comment gives up (`None`).
    #[inline(always)]
    fn segment_fast<const FUSED: bool, const PLAIN: bool>(
        &self,
        line: &'a [u8],
        start: usize,
        words: &mut Words<'a>,
    ) -> Option<(Segment, Option<(usize, usize)>)> {
        let n = line.len();
        let mut pos = start;
        while pos < n {
            let b = line[pos];
            // The space between words first: one test, not the letter's
            // and the table of the other bytes (issue 33).
            if b == b' ' {
                pos += 1;
                continue;
            }
            let up = b & !0x20;
            if up.wrapping_sub(b'A') < 26 && up != b'N' && up != b'O' {
                // `b` is an ASCII letter: only 0x41..=0x5A and 0x61..=0x7A
                // map into A..=Z under `& !0x20`.
                if PLAIN && (PLAIN_LETTERS >> (up - b'A')) & 1 == 0 {
                    return None;
                }
                let word_start = pos;
                let mut p = pos + 1;
                let negative = match line.get(p) {
                    Some(b'-') => {
                        p += 1;
                        true
                    }
                    Some(b'+') => {
                        p += 1;
                        false
                    }
                    _ => false,
                };
                let digits_start = p;
                while p < n && line[p].wrapping_sub(b'0') < 10 {
                    p += 1;
                }
                let int_len = p - digits_start;
                let mut point = SLOW;
                let mut has_digits = int_len > 0;
                if p < n && line[p] == b'.' {
                    p += 1;
                    let frac_start = p;
                    while p < n && line[p].wrapping_sub(b'0') < 10 {
                        p += 1;
                    }
                    has_digits |= p > frac_start;
                    // `SLOW` itself is no offset (as in `read_word`).
                    point = u8::try_from(int_len).ok().filter(|&i| i != SLOW)?;
                } else if int_len >= usize::from(SLOW) {
                    return None;
                }
                if !has_digits {
                    return None;
                }
                // 1 or 2: the letter, perhaps a sign.
                let at = (digits_start - word_start) as u8;
                words.push(Word { letter: char::from(up), raw: &line[word_start..p], at, point, negative });
                pos = p;
                continue;
            }
            match b {
                b'\n' | b'\r' if FUSED => {
                    return Some((
                        Segment { end: pos, next: None },
                        Some((pos, pos + line_end_len(line, pos))),
                    ))
                }
                b' ' | b'\t' | b'\x0b' | b'\x0c' | b'\r' => pos += 1,
                b';' if self.semicolon_comments => {
                    return if FUSED { None } else { Some((Segment { end: n, next: None }, None)) }
                }
                b';' => {
                    let after = pos + 1;
                    let seg = Segment { end: pos, next: Some(after) };
                    if !FUSED {
                        return Some((seg, None));
                    }
                    let line_end = match line.get(after) {
                        None => Some((after, after)),
                        Some(b'\n' | b'\r') => Some((after, after + line_end_len(line, after))),
                        Some(_) => None,
                    };
                    return Some((seg, line_end));
                }
                b'(' => pos = comment_end(line, pos + 1)?,
                _ => return None,
            }
        }
        Some((Segment { end: n, next: None }, FUSED.then_some((n, n))))
    }

    /// The next line and its first segment, read by
    /// [`segment_fast`](Lexer::segment_fast) straight from the text: one
    /// pass over the line's bytes finds its words and its end (the usual
    /// line, whose end the scan meets, needs no search for it; issue 33).
    /// `None` where `segment_fast` gives up (or at the end of the text),
    /// with the lexer where it was: the caller then reads the line as
    /// [`next_line`](Lexer::next_line) and [`segment`](Lexer::segment) do.
    ///
    /// `PLAIN`: an M word gives up too ([`next_plain`](Lexer::next_plain)).
    #[inline(always)]
    fn first_segment_fast<const PLAIN: bool>(
        &mut self,
        words: &mut Words<'a>,
    ) -> Option<(Line<'a>, Segment)> {
        #[cfg(test)]
        if tests::GENERAL_ONLY.with(std::cell::Cell::get) {
            return None;
        }
        let start = self.pos;
        let rest = self.src.get(start..).filter(|r| !r.is_empty())?;
        let (seg, line_end) = self.segment_fast::<true, PLAIN>(rest, 0, words)?;
        let (len, advance) = match (line_end, seg.next) {
            (Some(end), _) => end,
            // A `;` with more of the line after it.
            (None, Some(after)) => {
                let (tail, skip) = split_line(&rest[after..]);
                (after + tail.len(), after + skip)
            }
            (None, None) => return None,
        };
        #[cfg(test)]
        tests::FUSED_LINES.with(|n| n.set(n.get() + 1));
        self.pos += advance;
        self.line += 1;
        self.line_start = start;
        Some((Line { start, bytes: &rest[..len] }, seg))
    }

    /// The next block when it starts a line and has no M word (the
    /// reader's usual block, a move, a G76 or G32 block), read as
    /// [`next_into`](Lexer::next_into) reads it (by the same
    /// [`first_segment_fast`](Lexer::first_segment_fast) and
    /// [`trailing_segments`](Lexer::trailing_segments)), into `block`
    /// (empty on entry): true when read so. False, with the lexer and
    /// `block` to be dropped, for any other (an M word gives up where it
    /// is read; so does all that
    /// [`segment_fast`](Lexer::segment_fast) gives up on, a blank line,
    /// an error and the end of the text): the caller then reads the block
    /// from where it was by `next_into` (issue 33: the line-fed reader's
    /// usual step without its general work per block).
    #[inline(always)]
    pub(crate) fn next_plain(&mut self, block: &mut Block<'a>) -> bool {
        if self.done || self.current.is_some() || self.owords {
            return false;
        }
        let Some((line, seg)) = self.first_segment_fast::<true>(&mut block.words) else {
            return false;
        };
        let text = trim(&line.bytes[..seg.end]);
        if text.is_empty() && block.words.is_empty() {
            return false;
        }
        self.current = seg.next.filter(|&n| n < line.bytes.len()).map(|n| (line, n));
        block.line = self.line;
        block.text = Cow::Borrowed(text);
        self.trailing_segments(block).is_ok()
    }

    /// The segments without words that follow a block on its line (a
    /// comment after its `;`), joined to its text, as
    /// [`next_into`](Lexer::next_into) reads them.
    #[inline(always)]
    fn trailing_segments(&mut self, block: &mut Block<'a>) -> Result<(), ProgramError> {
        // A comment after a block end on the same line belongs to that
        // block: take every following segment without words.
        while let Some((line, start)) = self.current {
            let mut words = Words::new();
            let seg = self.segment(line, start, &mut words)?;
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
        Ok(())
    }

    /// [`segment`](Lexer::segment) of any segment, with every rule and
    /// every error.
    #[inline(never)]
    fn segment_general(
        &self,
        whole: Line<'a>,
        start: usize,
        words: &mut Words<'a>,
    ) -> Result<Segment, ProgramError> {
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
                b';' if self.semicolon_comments => return Ok(Segment { end: line.len(), next: None }),
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
            block.words = Words::new();
            let (line, start, seg) = match self.current.take() {
                Some((line, start)) => match self.segment(line, start, &mut block.words) {
                    Ok(s) => (line, start, s),
                    Err(e) => return Some(Err(e)),
                },
                // A line whose first segment `segment_fast` reads is no
                // o-word line: it gives up at an O.
                None => match self.first_segment_fast::<false>(&mut block.words) {
                    Some((line, seg)) => (line, 0, seg),
                    None => {
                        block.words = Words::new();
                        let line = self.next_line()?;
                        if self.owords && oword(line.bytes).is_some() {
                            block.line = self.line;
                            block.text = Cow::Borrowed(trim(line.bytes));
                            return Some(Ok(()));
                        }
                        match self.segment(line, 0, &mut block.words) {
                            Ok(s) => (line, 0, s),
                            Err(e) => return Some(Err(e)),
                        }
                    }
                },
            };
            let text = trim(&line.bytes[start..seg.end]);
            // A block end that ends the line leaves nothing to read in it.
            self.current = seg.next.filter(|&n| n < line.bytes.len()).map(|n| (line, n));
            if text.is_empty() && block.words.is_empty() {
                continue;
            }
            block.line = self.line;
            block.text = Cow::Borrowed(text);
            return Some(self.trailing_segments(block));
        }
    }
}

#[cfg(test)]
mod tests {
    //! The lexer's fast segment reader held equal to the general one.

    use std::cell::Cell;

    use proptest::prelude::*;

    use super::{Block, Lexer, ProgramError};

    thread_local! {
        /// Set: every segment is read by the general scanner alone.
        pub(super) static GENERAL_ONLY: Cell<bool> = const { Cell::new(false) };
        /// How many lines `first_segment_fast` has read.
        pub(super) static FUSED_LINES: Cell<usize> = const { Cell::new(0) };
    }

    /// A block with every field of its words (a word's `==` compares its
    /// letter and text only).
    type Seen = (usize, Vec<u8>, Vec<(char, Vec<u8>, u8, u8, bool)>, Vec<String>);

    fn seen(b: &Block<'_>) -> Seen {
        let words = b.words.iter().map(|w| (w.letter, w.raw.to_vec(), w.at, w.point, w.negative)).collect();
        let numbers = b.words.iter().map(|w| format!("{:?}", w.number())).collect();
        (b.line, b.text.to_vec(), words, numbers)
    }

    fn read(
        src: &[u8],
        semicolon_comments: bool,
        owords: bool,
        general: bool,
    ) -> Vec<Result<Seen, ProgramError>> {
        GENERAL_ONLY.with(|g| g.set(general));
        let out = Lexer::new(src)
            .with_semicolon_comments(semicolon_comments)
            .with_owords(owords)
            .map(|r| r.map(|b| seen(&b)))
            .collect();
        GENERAL_ONLY.with(|g| g.set(false));
        out
    }

    fn assert_same(src: &[u8]) {
        for semi in [false, true] {
            for owords in [false, true] {
                assert_eq!(
                    read(src, semi, owords, false),
                    read(src, semi, owords, true),
                    "{:?} (semicolon comments {semi}, o-words {owords})",
                    String::from_utf8_lossy(src)
                );
            }
        }
    }

    /// Pieces a program is made of, the adversarial ones included: every
    /// letter in both cases, signs, points, spaces and tabs between a
    /// letter and its number, comments (also unclosed and full-width),
    /// `%`, `/`, `;` and `；`, line ends, Unicode white space and letters,
    /// a byte that is not UTF-8, numbers too long for a byte's offsets.
    fn piece() -> impl Strategy<Value = Vec<u8>> {
        let fixed: Vec<&'static [u8]> = vec![
            b" ",
            b"  ",
            b"\t",
            b"\x0b",
            b"\x0c",
            b"\r",
            b"\n",
            b"\r\n",
            b";",
            b"(",
            b")",
            b"(note)",
            b"(G01 X1;)",
            b"%",
            b"/",
            b"-",
            b"+",
            b".",
            b"0",
            b"1",
            b"9",
            b"00",
            b"12.5",
            b"-0.001",
            b"+7",
            b"..",
            b"--",
            "；".as_bytes(),
            "（注）".as_bytes(),
            "（".as_bytes(),
            "）".as_bytes(),
            "\u{3000}".as_bytes(),
            "é".as_bytes(),
            "中".as_bytes(),
            b"\xff",
            b"\xef\xbb\xbf",
            b"#",
            b"=",
            b"N10",
            b"O0100",
            b"o100 call",
            b"M98 P1000",
            b"G76",
            b"G75.1",
            b"X",
            b"x-",
            b"F.",
            b"F0.",
            b"Z-.5",
            b"u+.25",
        ];
        prop_oneof![
            4 => proptest::sample::select(fixed).prop_map(<[u8]>::to_vec),
            3 => (proptest::char::range('A', 'Z'), any::<bool>()).prop_map(|(c, lower)| {
                let c = if lower { c.to_ascii_lowercase() } else { c };
                vec![c as u8]
            }),
            2 => "[A-Za-z][-+]?[0-9]{0,6}(\\.[0-9]{0,6})?".prop_map(String::into_bytes),
            1 => (0_usize..300, proptest::sample::select(vec![b'0', b'7', b' '])).prop_map(|(n, b)| vec![b; n]),
            1 => (proptest::char::range('A', 'Z'), 250_usize..260, any::<bool>()).prop_map(|(c, n, point)| {
                let mut v = vec![c as u8];
                v.extend(std::iter::repeat_n(b'4', n));
                if point {
                    v.extend_from_slice(b".5");
                }
                v
            }),
            1 => any::<char>().prop_map(|c| c.to_string().into_bytes()),
        ]
    }

    /// The usual lines are read in one pass (`first_segment_fast`): every
    /// line end, a comment, a `;` at the line's end; not a `;` with a
    /// comment after it (its line's end is searched for), nor `%`.
    #[test]
    fn usual_lines_are_read_in_one_pass() {
        let src = b"G00 X80 Z10;\r\nG01 X21.001 Z-3.25 F0.15; (finish 1)\nX24.004\r(part 3)\n%\nZ1";
        FUSED_LINES.with(|n| n.set(0));
        let blocks: Vec<_> = Lexer::new(src).map(|r| r.map(|b| seen(&b))).collect();
        let fused = FUSED_LINES.with(Cell::get);
        // Lines 1, 2 (its end searched for after the `;`), 3, 4 and 6; not
        // line 5, `%` (a block of its own, without words).
        assert_eq!(fused, 5);
        let lines: Vec<usize> = blocks.iter().map(|b| b.as_ref().map_or(0, |b| b.0)).collect();
        assert_eq!(lines, [1, 2, 3, 4, 5, 6]);
        assert_eq!(
            blocks[1].as_ref().map(|b| b.1.clone()).ok(),
            Some(b"G01 X21.001 Z-3.25 F0.15 (finish 1)".to_vec())
        );
        assert_same(src);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn fast_segments_are_the_general_ones(pieces in proptest::collection::vec(piece(), 0..24)) {
            assert_same(&pieces.concat());
        }

        #[test]
        fn fast_segments_of_program_lines(lines in proptest::collection::vec(
            "(N[0-9]{1,4} )?(G0[0-3] )?([XZUWF]-?[0-9]{1,3}(\\.[0-9]{0,4})? ?){0,5}(;|\\(c\\))?",
            0..12,
        )) {
            assert_same(lines.join("\n").as_bytes());
        }
    }
}
