//! The word scanner: one word read from a line where its letter stands
//! (its number's place noted for [`Word::number`]), and the rules of the
//! words that are not simply a block's (`N`, `O`, a word after `%`, an
//! address without a number).

use super::block::Words;
use super::lines::Line;
use super::number::{Word, SLOW};
use crate::error::{ErrorKind, ProgramError};

/// Where `%` may stand (reading R-SEQNUM).
pub(super) const MARK_RULE: &str = "`%` marks the start or the end of a program, on a line of its own";

fn misplaced(line: usize, word: &Word<'_>, rule: &'static str) -> ProgramError {
    ProgramError { line, word: Some(word.text().into_owned()), kind: ErrorKind::Misplaced { rule } }
}

/// The word that starts at `start` (an ASCII letter) and the offset after it.
pub(super) fn read_word(whole: Line<'_>, start: usize) -> (Word<'_>, usize, bool) {
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
/// after an O: the rules of [`Lexer`](super::Lexer)'s `segment`, in their order.
#[inline(never)]
pub(super) fn other_word<'a>(
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
