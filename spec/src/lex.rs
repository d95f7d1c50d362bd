//! Splitting program text into blocks of words.
//!
//! Accepts `%` lines, `O` numbers, `N` numbers, `( )` comments (also the
//! full-width `（ ）` of the Chinese manuals), `;` (and `；`) or a newline as
//! block end, blank lines, spaces anywhere between words and between an
//! address and its value, words in any order, upper or lower case, and a
//! leading `/` (block delete, treated as switched off). Every block keeps its
//! source line and text for messages and for echoing.

use rust_decimal::Decimal;

use crate::error::{ErrorKind, ProgramError};

/// A number as written after an address.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Number {
    /// A leading minus sign.
    pub negative: bool,
    /// Digits before the decimal point, as written (leading zeros kept).
    pub int_digits: String,
    /// Digits after the decimal point, when there is a decimal point.
    pub frac_digits: Option<String>,
}

impl Number {
    /// True when the number was written with a decimal point.
    #[must_use]
    pub fn has_point(&self) -> bool {
        self.frac_digits.is_some()
    }

    /// The exact value.
    #[must_use]
    pub fn decimal(&self) -> Option<Decimal> {
        let mut s = String::new();
        if self.negative {
            s.push('-');
        }
        if self.int_digits.is_empty() {
            s.push('0');
        } else {
            s.push_str(&self.int_digits);
        }
        if let Some(f) = &self.frac_digits {
            if !f.is_empty() {
                s.push('.');
                s.push_str(f);
            }
        }
        Decimal::from_str_exact(&s).ok()
    }

    /// The value when it is a whole number (a decimal point followed only by
    /// zeros counts as whole).
    #[must_use]
    pub fn integer(&self) -> Option<i64> {
        if let Some(f) = &self.frac_digits {
            if f.bytes().any(|b| b != b'0') {
                return None;
            }
        }
        let digits = self.int_digits.trim_start_matches('0');
        let v: i64 = if digits.is_empty() { 0 } else { digits.parse().ok()? };
        Some(if self.negative { -v } else { v })
    }
}

/// An address letter and its number.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Word {
    /// The address, upper case.
    pub letter: char,
    /// The value.
    pub number: Number,
    /// The word as written (for messages).
    pub text: String,
}

/// One block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    /// 1-based source line.
    pub line: usize,
    /// The block's source text without its block end.
    pub text: String,
    /// The words, in source order (comments, `N`, `O` and `%` removed).
    pub words: Vec<Word>,
}

impl Block {
    /// The words with address `letter`.
    pub fn all(&self, letter: char) -> impl Iterator<Item = &Word> {
        self.words.iter().filter(move |w| w.letter == letter)
    }

    /// The single word with address `letter`, if any.
    ///
    /// # Errors
    ///
    /// [`ErrorKind::Duplicate`] when the address appears twice.
    pub fn get(&self, letter: char) -> Result<Option<&Word>, ProgramError> {
        let mut it = self.all(letter);
        let first = it.next();
        if let Some(second) = it.next() {
            return Err(ProgramError {
                line: self.line,
                word: Some(second.text.clone()),
                kind: ErrorKind::Duplicate,
            });
        }
        Ok(first)
    }

    /// True when the block has a word with address `letter`.
    #[must_use]
    pub fn has(&self, letter: char) -> bool {
        self.words.iter().any(|w| w.letter == letter)
    }
}

/// Splits `source` into blocks.
///
/// # Errors
///
/// [`ErrorKind::Syntax`] for characters that are not part of a word, an
/// unclosed comment or an address without a number.
pub fn lex(source: &str) -> Result<Vec<Block>, ProgramError> {
    let mut blocks: Vec<Block> = Vec::new();
    for (i, line) in source.lines().enumerate() {
        let line_no = i + 1;
        let chars: Vec<(usize, char)> = line.char_indices().collect();
        let mut pos = 0;
        let mut start_byte = 0;
        let mut words = Vec::new();
        let syntax = |msg: String| ProgramError { line: line_no, word: None, kind: ErrorKind::Syntax(msg) };
        let first_block = blocks.len();
        let mut flush = |words: &mut Vec<Word>, from: usize, to: usize| {
            let text = line[from..to].trim().to_string();
            if text.is_empty() && words.is_empty() {
                return;
            }
            // A comment after a block end on the same line belongs to that block.
            if words.is_empty() && blocks.len() > first_block {
                if let Some(prev) = blocks.last_mut() {
                    prev.text.push(' ');
                    prev.text.push_str(&text);
                    return;
                }
            }
            blocks.push(Block { line: line_no, text, words: std::mem::take(words) });
        };
        while pos < chars.len() {
            let (byte, c) = chars[pos];
            match c {
                ';' | '；' => {
                    flush(&mut words, start_byte, byte);
                    pos += 1;
                    start_byte = chars.get(pos).map_or(line.len(), |p| p.0);
                }
                '(' | '（' => {
                    let close = chars[pos..].iter().position(|&(_, ch)| ch == ')' || ch == '）');
                    match close {
                        Some(off) => pos += off + 1,
                        None => return Err(syntax("an unclosed comment `(`".into())),
                    }
                }
                '%' | '/' | '\u{3000}' => pos += 1,
                c if c.is_whitespace() => pos += 1,
                c if c.is_ascii_alphabetic() => {
                    let letter = c.to_ascii_uppercase();
                    pos += 1;
                    while pos < chars.len() && (chars[pos].1 == ' ' || chars[pos].1 == '\t') {
                        pos += 1;
                    }
                    let num_start = pos;
                    let mut negative = false;
                    if pos < chars.len() && (chars[pos].1 == '-' || chars[pos].1 == '+') {
                        negative = chars[pos].1 == '-';
                        pos += 1;
                    }
                    let mut int_digits = String::new();
                    while pos < chars.len() && chars[pos].1.is_ascii_digit() {
                        int_digits.push(chars[pos].1);
                        pos += 1;
                    }
                    let mut frac_digits = None;
                    if pos < chars.len() && chars[pos].1 == '.' {
                        pos += 1;
                        let mut f = String::new();
                        while pos < chars.len() && chars[pos].1.is_ascii_digit() {
                            f.push(chars[pos].1);
                            pos += 1;
                        }
                        frac_digits = Some(f);
                    }
                    let no_digits =
                        int_digits.is_empty() && frac_digits.as_ref().is_none_or(|f| f.is_empty());
                    let end_byte = chars.get(pos).map_or(line.len(), |p| p.0);
                    let text: String = line[byte..end_byte].chars().filter(|c| !c.is_whitespace()).collect();
                    if no_digits {
                        return Err(ProgramError {
                            line: line_no,
                            word: Some(text),
                            kind: ErrorKind::Syntax(format!(
                                "the address `{letter}` without a number{}",
                                if num_start == pos { "" } else { " (only a sign)" }
                            )),
                        });
                    }
                    if letter == 'N' || letter == 'O' {
                        continue;
                    }
                    words.push(Word { letter, number: Number { negative, int_digits, frac_digits }, text });
                }
                other => return Err(syntax(format!("the character `{other}`"))),
            }
        }
        flush(&mut words, start_byte, line.len());
    }
    Ok(blocks)
}
