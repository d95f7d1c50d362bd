//! Blocks: a block's [`Words`] (inline up to [`INLINE_WORDS`], with
//! masks of the letters they hold) and the [`Block`] the lexer yields.

use std::borrow::Cow;

use arrayvec::ArrayVec;

use super::number::Word;
use crate::error::{ErrorKind, ProgramError};

/// How many words a block holds without a heap allocation. Longer blocks
/// are read all the same, with one allocation.
pub const INLINE_WORDS: usize = 6;

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
pub(crate) const fn letter_bit(letter: char) -> u32 {
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

    /// The bits ([`letter_bit`]) of the letters the words have, and of
    /// those more than one word has.
    #[inline]
    pub(crate) fn letter_masks(&self) -> (u32, u32) {
        (self.present, self.repeated)
    }

    /// Adds `w` after the others.
    #[inline]
    pub fn push(&mut self, w: Word<'a>) {
        let bit = letter_bit(w.letter);
        self.repeated |= self.present & bit;
        self.present |= bit;
        // The usual case, inlined: room in the inline words (one test of
        // their length).
        let w = match &mut self.store {
            WordStore::Inline(v) => match v.try_push(w) {
                Ok(()) => return,
                Err(full) => full.element(),
            },
            WordStore::Heap(_) => w,
        };
        self.push_more(w);
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
