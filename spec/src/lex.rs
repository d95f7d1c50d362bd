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
use lines::{comment_end, decode, trim, Line, FULL_OPEN, FULL_SEMI};
pub use lines::{last_line_end, oword, split_line, OLabel};
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
