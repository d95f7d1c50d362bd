//! Subprograms: `M98` calls and `M99` returns, followed as the control runs
//! them (reading R-SUBPROGRAM).
//!
//! The file holds the main program from its first block to its end (the
//! first block with M02 or M30, reading R-PROGRAMEND), then its
//! subprograms, each an `O` block, its blocks and an `M99`, as the FANUC
//! and GSK manuals lay a program and its subprograms out. A call replaces
//! itself with the subprogram's blocks, repeated; a return goes on after
//! the call. Only what runs is read: a subprogram no call reaches is
//! neither read nor checked.
//!
//! The text of the subprograms ([`Subprograms`]) is found when the first
//! call runs: a program without a call pays nothing. It is held whole (at
//! most [`MAX_SUBPROGRAM_TEXT`] bytes, whatever the main program's length);
//! the main program is still read a piece at a time, and a call keeps only
//! the place to return to (at most the machine's nesting depth of them).
//! The work is bounded: at most [`Machine::subprogram_block_limit`] blocks
//! run inside subprograms, counted as they run, so that the first phase
//! refuses a program whose calls repeat without end (or nearly) before
//! anything is written.

use crate::error::{ErrorKind, ProgramError};
use crate::lex::{oword, Block, Lexer, OLabel, Position, Word};
use crate::profile::{Dialect, Machine};

/// The most bytes the subprograms of a program (the text after the main
/// program's end) may have: they are held in memory while the program
/// runs. A longer text is an error naming where it starts.
pub const MAX_SUBPROGRAM_TEXT: usize = 1 << 20;

/// The default nesting depth: a subprogram called from the main program is
/// level 1, one it calls level 2, and so on to 4 (FANUC and GSK; some
/// FANUC models allow 10: `subprogram_nesting` in the parameter file).
pub const DEFAULT_SUBPROGRAM_NESTING: u8 = 4;

/// The nesting depth of the linuxcnc profile: LinuxCNC 2.9's `rs274` runs
/// 9 nested `call`s and refuses a 10th ("Too many subroutine levels").
pub const LINUXCNC_SUBPROGRAM_NESTING: u8 = 9;

/// The deepest nesting the parameter file may set.
pub const MAX_SUBPROGRAM_NESTING: u8 = 10;

/// The default of [`Machine::subprogram_block_limit`].
pub const DEFAULT_SUBPROGRAM_BLOCK_LIMIT: u64 = 1_000_000;

/// Where the main program starts (reading R-SUBPROGRAM): at the file's
/// start, or after the subprograms written before it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MainStart {
    /// The byte offset of its first line.
    pub offset: usize,
    /// The number of lines before it.
    pub lines_before: usize,
}

impl MainStart {
    /// Where the main program of `source` starts: [`may_hold_return`]
    /// first (no `M99`, no subprogram before the main program), then
    /// [`MainStartFinder`] over the text.
    ///
    /// ```
    /// use cycleref_spec::reader::MainStart;
    /// let p = b"O1000\nG00 U-2\nM99\nO0001\nG50 X100 Z10\nM98 P1000\nM30\n";
    /// assert_eq!(MainStart::of_text(p), MainStart { offset: 18, lines_before: 3 });
    /// assert!(p[18..].starts_with(b"O0001"));
    /// assert_eq!(MainStart::of_text(b"O0001\nG00 X1\nM30\n"), MainStart::default());
    /// ```
    #[must_use]
    pub fn of_text(source: &[u8]) -> MainStart {
        if !may_hold_return(source) {
            return MainStart::default();
        }
        let mut finder = MainStartFinder::default();
        finder.feed(source).unwrap_or_else(|| finder.finish())
    }
}

/// True when `bytes` may hold an `M99` (an `M`, perhaps spaces and zeros,
/// `99`, and no digit or point after): a test at the speed of a byte
/// search ahead of the reader's. False means that no block of `bytes` is
/// a return.
///
/// ```
/// use cycleref_spec::reader::may_hold_return;
/// assert!(may_hold_return(b"G00 X1\nM99\n"));
/// assert!(may_hold_return(b"m 099"));
/// assert!(!may_hold_return(b"G00 X99\nM999\nM98 P9901\n"));
/// ```
#[must_use]
pub fn may_hold_return(bytes: &[u8]) -> bool {
    memchr::memmem::find_iter(bytes, b"99").any(|i| {
        if matches!(bytes.get(i + 2), Some(b'0'..=b'9' | b'.')) {
            return false;
        }
        let mut j = i;
        while j > 0 && matches!(bytes[j - 1], b'0' | b' ' | b'\t') {
            j -= 1;
        }
        j > 0 && matches!(bytes[j - 1], b'M' | b'm')
    })
}

/// Finds where the main program starts, fed the program a piece (of whole
/// lines) at a time from its start. The main program is the first program
/// that does not end with `M99`: a block with words before any `O` block
/// starts it at the file's start; a program (an `O` block and what
/// follows) that reaches `M99` before M02, M30 or the next `O` block is a
/// subprogram; any other is the main program. A line the reader cannot
/// read is passed over here (it is reported if it runs).
#[derive(Debug, Default)]
pub struct MainStartFinder {
    /// The bytes and lines of the pieces fed so far.
    offset: usize,
    line: usize,
    /// Where the program being read starts, while it is not known to be
    /// a subprogram.
    current: Option<MainStart>,
    /// A subprogram has been read.
    subprograms: bool,
}

impl MainStartFinder {
    /// Reads `piece`: where the main program starts, once that is known.
    pub fn feed(&mut self, piece: &[u8]) -> Option<MainStart> {
        let mut lexer = Lexer::at_line(piece, self.line + 1);
        while let Some(block) = lexer.next_readable() {
            let here = MainStart { offset: self.offset + lexer.line_start(), lines_before: block.line - 1 };
            if program_block(&block).is_some() {
                if self.current.is_some() {
                    // The program before runs into this one: it is the main program.
                    return self.current;
                }
                self.current = Some(here);
            } else if !block.words.is_empty() {
                match self.current {
                    // Before any program: the main program starts at the
                    // file's start; after subprograms, here.
                    None if self.subprograms => return Some(here),
                    None => return Some(MainStart::default()),
                    Some(_) if is_return(&block) => {
                        self.current = None;
                        self.subprograms = true;
                    }
                    Some(start) if ends_program(&block) => return Some(start),
                    Some(_) => {}
                }
            }
        }
        self.offset += piece.len();
        self.line = lexer.line();
        None
    }

    /// At the end of the program: the program being read is the main
    /// program; or no block has words (the main program starts at the
    /// file's start); or every program returned, and the main program is
    /// empty and starts at the end.
    #[must_use]
    pub fn finish(&self) -> MainStart {
        match self.current {
            Some(start) => start,
            None if self.subprograms => MainStart { offset: self.offset, lines_before: self.line },
            None => MainStart::default(),
        }
    }
}

/// The text of a program's subprograms (reading R-SUBPROGRAM): the lines
/// before the main program's start, and the lines after the line that
/// holds its end.
#[derive(Clone, Copy, Debug, Default)]
pub struct Subprograms<'a> {
    /// The bytes before the main program's start (from line 1).
    pub before: &'a [u8],
    /// The bytes from the start of the line after the main program's end.
    pub after: &'a [u8],
    /// The number of the first line of `after` in the whole program.
    pub after_line: usize,
}

impl<'a> Subprograms<'a> {
    /// The subprograms of the program `source` whose main program starts
    /// at `main`, borrowed from it.
    ///
    /// # Errors
    ///
    /// A block of the main program before its end that cannot be read, or
    /// subprograms longer than [`MAX_SUBPROGRAM_TEXT`].
    ///
    /// ```
    /// use cycleref_spec::reader::{MainStart, Subprograms};
    /// let program = b"M98 P1000\nM30\nO1000\nG00 X1\nM99\n";
    /// let subs = Subprograms::in_text(program, MainStart::of_text(program))?;
    /// assert_eq!((subs.before, subs.after), (&b""[..], &b"O1000\nG00 X1\nM99\n"[..]));
    /// assert_eq!(subs.after_line, 3);
    /// # Ok::<(), cycleref_spec::ProgramError>(())
    /// ```
    pub fn in_text(source: &'a [u8], main: MainStart) -> Result<Subprograms<'a>, ProgramError> {
        let before = &source[..main.offset];
        let rest = &source[main.offset..];
        let mut end = MainEnd::after(main.lines_before);
        let (after, after_line) = match end.feed(rest)? {
            Some(at) => (&rest[at..], end.line + 1),
            None => (&[][..], end.line + 1),
        };
        let sub = Subprograms { before, after, after_line };
        sub.check_length()?;
        Ok(sub)
    }

    /// The subprograms of a LinuxCNC program `source`: the whole of it
    /// (its definitions may stand anywhere), at most
    /// [`MAX_SUBPROGRAM_TEXT`] bytes.
    ///
    /// # Errors
    ///
    /// A program longer than [`MAX_SUBPROGRAM_TEXT`].
    pub fn whole(source: &'a [u8]) -> Result<Subprograms<'a>, ProgramError> {
        let sub = Subprograms { before: source, after: &[], after_line: 0 };
        sub.check_length()?;
        Ok(sub)
    }

    /// The error of subprograms longer than [`MAX_SUBPROGRAM_TEXT`].
    ///
    /// # Errors
    ///
    /// When `before` and `after` together are longer.
    pub fn check_length(&self) -> Result<(), ProgramError> {
        if self.before.len() + self.after.len() > MAX_SUBPROGRAM_TEXT {
            let line = if self.after.is_empty() { 1 } else { self.after_line };
            return Err(ProgramError {
                line,
                word: None,
                kind: ErrorKind::Subprogram(SubprogramError::TextTooLong { limit: MAX_SUBPROGRAM_TEXT }),
            });
        }
        Ok(())
    }

    /// The text of region `r` (0 before the main program, 1 after).
    fn region(&self, r: u8) -> &'a [u8] {
        if r == 0 {
            self.before
        } else {
            self.after
        }
    }
}

/// Finds where the main program ends, fed the main program a piece (of
/// whole lines) at a time from its start: the first block with M02 or
/// M30, as the reader ends the program there (reading R-PROGRAMEND).
#[derive(Debug, Default)]
pub struct MainEnd {
    /// The number of the last line read.
    pub line: usize,
}

impl MainEnd {
    /// Before the main program's first piece, which starts after line
    /// `lines_before` ([`MainStart::lines_before`]).
    #[must_use]
    pub fn after(lines_before: usize) -> MainEnd {
        MainEnd { line: lines_before }
    }

    /// Reads `piece`: the offset in it where the subprograms start (the
    /// line after the one holding the main program's end), or `None` when
    /// the end is not in this piece. After `Some`, [`MainEnd::line`] is
    /// the number of the line before that offset.
    ///
    /// # Errors
    ///
    /// A block that cannot be read.
    pub fn feed(&mut self, piece: &[u8]) -> Result<Option<usize>, ProgramError> {
        let mut lexer = Lexer::at_line(piece, self.line + 1);
        let mut block = Block::empty();
        while let Some(r) = lexer.next_into(&mut block) {
            r?;
            if ends_program(&block) {
                self.line = lexer.line();
                return Ok(Some(lexer.position().next_line_offset()));
            }
        }
        self.line = lexer.line();
        Ok(None)
    }
}

/// True when `block` ends the program (M02 or M30).
pub(crate) fn ends_program(block: &Block<'_>) -> bool {
    block.all('M').any(|w| matches!(w.integer(), Some(2 | 30)))
}

/// What is wrong with a subprogram call or return.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SubprogramError {
    /// A call names a program that is not among the subprograms.
    NotFound {
        /// The program as the dialect writes it (`O1000`, `o100`,
        /// `o<name>`).
        program: String,
    },
    /// The same program twice among the subprograms.
    DefinedTwice {
        /// The program.
        program: String,
        /// The line of its first definition.
        first: usize,
    },
    /// A call deeper than the nesting depth.
    TooDeep {
        /// The deepest nesting allowed.
        limit: u8,
    },
    /// `M99` in the main program, or LinuxCNC's `endsub`/`return`
    /// outside the subroutine it names.
    ReturnOutsideSubprogram,
    /// A subprogram that runs to the end of the file, or into the next
    /// program, without `M99` (LinuxCNC: a definition without `endsub`).
    NoReturn {
        /// The program.
        program: String,
        /// The line of its `O` block (`sub` line).
        line: usize,
    },
    /// M02 or M30 inside a FANUC or GSK subprogram.
    EndInSubprogram {
        /// The program.
        program: String,
    },
    /// A LinuxCNC subroutine defined inside another, or where `rs274`
    /// refuses it (after the program called it before its definition).
    MisplacedDefinition {
        /// The subroutine.
        program: String,
    },
    /// More blocks run inside subprograms than the limit.
    TooManyBlocks {
        /// The limit (`subprogram_block_limit`).
        limit: u64,
    },
    /// The subprograms' text is longer than [`MAX_SUBPROGRAM_TEXT`].
    TextTooLong {
        /// The limit in bytes.
        limit: usize,
    },
    /// `M98` without `P`, or a `P` that is not a call's.
    BadCall(&'static str),
    /// A word beside `M98` or `M99`, or after a LinuxCNC o-word, that the
    /// reader does not follow.
    WordBeside {
        /// `M98`, `M99` or the o-word's keyword.
        code: &'static str,
    },
    /// A LinuxCNC o-word other than `sub`, `endsub`, `return` and `call`
    /// (`if`, `while`, `repeat`, …): control flow is not followed.
    Unfollowed,
}

impl SubprogramError {
    /// The stable name of the error (`not_found`).
    #[must_use]
    pub const fn name(&self) -> &'static str {
        match self {
            SubprogramError::NotFound { .. } => "not_found",
            SubprogramError::DefinedTwice { .. } => "defined_twice",
            SubprogramError::TooDeep { .. } => "too_deep",
            SubprogramError::ReturnOutsideSubprogram => "return_outside_subprogram",
            SubprogramError::NoReturn { .. } => "no_return",
            SubprogramError::EndInSubprogram { .. } => "end_in_subprogram",
            SubprogramError::MisplacedDefinition { .. } => "misplaced_definition",
            SubprogramError::TooManyBlocks { .. } => "too_many_blocks",
            SubprogramError::TextTooLong { .. } => "text_too_long",
            SubprogramError::BadCall(_) => "bad_call",
            SubprogramError::WordBeside { .. } => "word_beside",
            SubprogramError::Unfollowed => "unfollowed",
        }
    }
}

impl std::fmt::Display for SubprogramError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SubprogramError::NotFound { program } => write!(
                f,
                "program {program} is not in the file (FANUC and GSK: subprograms stand before the main \
                 program or after its M02/M30, each from its O block to its M99; LinuxCNC: `{program} sub` \
                 … `{program} endsub`; reading R-SUBPROGRAM)"
            ),
            SubprogramError::DefinedTwice { program, first } => {
                write!(f, "program {program} is defined twice (first at line {first})")
            }
            SubprogramError::TooDeep { limit } => write!(
                f,
                "this call nests subprograms deeper than {limit} levels (the control's limit; \
                 `subprogram_nesting` in the parameter file)"
            ),
            SubprogramError::ReturnOutsideSubprogram => f.write_str(
                "a return outside the subprogram it ends: M99 in the main program (which runs from its \
                 first block to its M02/M30), or an `endsub`/`return` not in a subroutine called by that \
                 name (reading R-SUBPROGRAM)",
            ),
            SubprogramError::NoReturn { program, line } => write!(
                f,
                "subprogram {program} (line {line}) ends without its return (M99, `endsub`): it runs to \
                 here, the end of the file or the next program"
            ),
            SubprogramError::EndInSubprogram { program } => write!(
                f,
                "M02/M30 inside subprogram {program}: a subprogram returns with M99 (reading R-SUBPROGRAM)"
            ),
            SubprogramError::MisplacedDefinition { program } => write!(
                f,
                "the definition of {program} stands where LinuxCNC refuses it: inside another definition, \
                 or in the program's path after a call to it (rs274: \"found in illegal location\")"
            ),
            SubprogramError::TooManyBlocks { limit } => write!(
                f,
                "the subprogram calls run more than {limit} blocks (`subprogram_block_limit` in the \
                 parameter file raises the limit)"
            ),
            SubprogramError::TextTooLong { limit } => write!(
                f,
                "the subprograms' text is longer than {limit} bytes, the most that is held while the \
                 program runs (FANUC, GSK: the text around the main program; LinuxCNC: the whole program)"
            ),
            SubprogramError::BadCall(rule) => write!(f, "not a subprogram call: {rule}"),
            SubprogramError::WordBeside { code } => write!(
                f,
                "a word beside {code}: a call or a return stands in a block of its own (reading \
                 R-SUBPROGRAM: M98 L and Q, M99 P, a move with a call, LinuxCNC's arguments and return \
                 values are not followed)"
            ),
            SubprogramError::Unfollowed => f.write_str(
                "LinuxCNC's o-word control flow (if, while, do, repeat, break, continue) is not followed \
                 (reading R-SUBPROGRAM: sub, endsub, return and call are)",
            ),
        }
    }
}

/// The number of the program an `O` block starts, if `block` is one (the
/// lexer has checked that `O` stands alone at the block's start).
/// `Some(None)` for an `O` block whose number no call can name.
fn program_block(block: &Block<'_>) -> Option<Option<u32>> {
    if !block.words.is_empty() {
        return None;
    }
    let text = &block.text[..];
    let mut i = 0;
    // Before the O: spaces, a block delete, comments.
    loop {
        match text.get(i) {
            Some(b' ' | b'\t' | b'/') => i += 1,
            Some(b'(') => i += text[i..].iter().position(|&b| b == b')')? + 1,
            Some(b'O' | b'o') => break,
            _ => return None,
        }
    }
    i += 1;
    while matches!(text.get(i), Some(b' ' | b'\t')) {
        i += 1;
    }
    let digits = text[i..].iter().take_while(|b| b.is_ascii_digit()).count();
    let n = std::str::from_utf8(&text[i..i + digits]).ok()?;
    let after = text.get(i + digits);
    let number = n.parse::<u32>().ok().filter(|n| (1..=9999).contains(n) && after != Some(&b'.'));
    Some(number)
}

/// A LinuxCNC o-word of `block` (the lexer gives an o-word line as a
/// block without words): its label, its keyword in lower case, and
/// whether anything but a comment follows the keyword.
pub(crate) fn block_oword(block: &Block<'_>) -> Option<(OLabel, String, bool)> {
    if !block.words.is_empty() {
        return None;
    }
    let (label, keyword, rest) = oword(&block.text)?;
    let rest = rest.trim_ascii_start();
    let more = !(rest.is_empty() || rest.starts_with(b"(") || rest.starts_with(b";"));
    Some((label, String::from_utf8_lossy(keyword).to_ascii_lowercase(), more))
}

/// A subprogram's entry in the index: where its first block after the
/// `O` block (`sub` line) starts.
#[derive(Clone, Debug)]
struct Entry {
    label: OLabel,
    /// The region of [`Subprograms`] it is in (0 before the main program,
    /// 1 after).
    region: u8,
    /// The line of the `O` block (`sub` line).
    line: usize,
    /// Where the lexer stands after it.
    at: Position,
    /// LinuxCNC: the program's path has passed its definition.
    passed: bool,
    /// LinuxCNC: called before the path passed its definition (`rs274`
    /// then refuses the definition when the path reaches it).
    forward: bool,
}

/// How the dialect writes a program's label.
fn shown_label(label: &OLabel, lcnc: bool) -> String {
    match label {
        OLabel::Number(n) if !lcnc => format!("O{n:04}"),
        l => l.to_string(),
    }
}

/// Where a return goes.
#[derive(Clone, Copy, Debug)]
enum Return {
    /// Into the main program, which the caller's piece holds: after the
    /// call (the reader's own position in the piece).
    Main(Option<Position>),
    /// Into the calling subprogram, after the call.
    Sub((u8, Position)),
}

/// One subprogram running.
#[derive(Clone, Debug)]
struct Frame {
    /// Its index in [`Calls::index`].
    entry: usize,
    /// The runs still to start after this one.
    repeats: u32,
    back: Return,
}

/// The calls in progress and the index of the subprograms: the reader's
/// part of R-SUBPROGRAM.
#[derive(Debug, Default)]
pub(crate) struct Calls {
    /// Sorted by label; read when the first call runs.
    index: Option<Vec<Entry>>,
    frames: Vec<Frame>,
    /// Where the reader stands in the subprograms' text (region and
    /// place), while one runs.
    at: Option<(u8, Position)>,
    /// Blocks run inside subprograms so far.
    blocks: u64,
    /// LinuxCNC: the definition the main program's path is passing over,
    /// and the line of its `sub`.
    skipping: Option<(OLabel, usize)>,
}

/// What a call or return did.
pub(crate) enum Flow {
    /// A call: the reader goes on in the subprogram.
    Called,
    /// A return: the reader goes on after the call (or at the
    /// subprogram's start again), and in the main program when `main`
    /// holds the position to go on at there.
    Returned { main: Option<Option<Position>> },
    /// LinuxCNC: the block is part of a definition the path passes over.
    Skipped,
    /// A call, before the subprograms' index is read: read it
    /// ([`Calls::read_index`]) and run the block again.
    NeedsIndex,
}

fn sub_err(block: &Block<'_>, word: Option<&Word<'_>>, e: SubprogramError) -> ProgramError {
    ProgramError {
        line: block.line,
        word: word.map(|w| w.text().into_owned()),
        kind: ErrorKind::Subprogram(e),
    }
}

/// The error of `block`, naming the block's o-word (its text to the
/// keyword).
fn oword_err(block: &Block<'_>, e: SubprogramError) -> ProgramError {
    let text = String::from_utf8_lossy(&block.text);
    let word = text.split_whitespace().take(2).collect::<Vec<_>>().join(" ");
    ProgramError { line: block.line, word: Some(word), kind: ErrorKind::Subprogram(e) }
}

impl Calls {
    /// True while a subprogram runs.
    pub(crate) fn running(&self) -> bool {
        !self.frames.is_empty()
    }

    /// True while the main program's path passes over a LinuxCNC
    /// definition.
    pub(crate) fn skipping(&self) -> bool {
        self.skipping.is_some()
    }

    /// The error of a definition the program ends inside (LinuxCNC).
    pub(crate) fn unfinished(&self) -> Option<ProgramError> {
        self.skipping.as_ref().map(|(label, line)| ProgramError {
            line: *line,
            word: Some(format!("{label} sub")),
            kind: ErrorKind::Subprogram(SubprogramError::NoReturn {
                program: label.to_string(),
                line: *line,
            }),
        })
    }

    /// True once the subprograms' index is read.
    fn has_index(&self) -> bool {
        self.index.is_some()
    }

    /// Where the reader stands in the subprograms' text: the region's
    /// text in `subs`, and the place in it.
    pub(crate) fn position<'a>(&self, subs: Option<Subprograms<'a>>) -> (&'a [u8], Option<Position>) {
        match (self.at, subs) {
            (Some((r, at)), Some(subs)) => (subs.region(r), Some(at)),
            _ => (&[], None),
        }
    }

    /// Sets where the reader stands in the region it reads.
    pub(crate) fn set_position(&mut self, at: Position) {
        if let Some((_, p)) = &mut self.at {
            *p = at;
        }
    }

    /// Reads the index of `subs`: every `O` block (LinuxCNC: `sub` line)
    /// and where its program starts. A line that cannot be read is passed
    /// over: only a block that runs reports its error. `line` is the line
    /// of the first call, which the path has reached.
    pub(crate) fn read_index(
        &mut self,
        subs: Subprograms<'_>,
        lcnc: bool,
        semi: bool,
        line: usize,
    ) -> Result<(), ProgramError> {
        let mut index: Vec<Entry> = Vec::new();
        for (region, text, first_line) in [(0, subs.before, 1), (1, subs.after, subs.after_line)] {
            let mut lexer = Lexer::at_line(text, first_line).with_owords(lcnc).with_semicolon_comments(semi);
            while let Some(block) = lexer.next_readable() {
                let label = if lcnc {
                    match block_oword(&block) {
                        Some((label, keyword, _)) if keyword == "sub" => label,
                        _ => continue,
                    }
                } else {
                    let Some(Some(program)) = program_block(&block) else { continue };
                    OLabel::Number(u64::from(program))
                };
                match index.binary_search_by(|e| e.label.cmp(&label)) {
                    Ok(i) => {
                        return Err(ProgramError {
                            line: block.line,
                            word: None,
                            kind: ErrorKind::Subprogram(SubprogramError::DefinedTwice {
                                program: shown_label(&label, lcnc),
                                first: index[i].line,
                            }),
                        })
                    }
                    Err(i) => {
                        let passed = block.line < line;
                        let at = lexer.position();
                        index
                            .insert(i, Entry { label, region, line: block.line, at, passed, forward: false });
                    }
                }
            }
        }
        self.index = Some(index);
        Ok(())
    }

    /// The checks of a block read inside a subprogram, before it is read
    /// as any other: the count of blocks run, and the end of the
    /// subprogram's text.
    pub(crate) fn check_block(&mut self, block: &Block<'_>, machine: &Machine) -> Result<(), ProgramError> {
        if !self.running() {
            return Ok(());
        }
        self.blocks += 1;
        if self.blocks > machine.subprogram_block_limit {
            let limit = machine.subprogram_block_limit;
            return Err(sub_err(block, None, SubprogramError::TooManyBlocks { limit }));
        }
        if machine.profile.dialect == Dialect::LinuxCnc {
            // rs274: M2 in a subroutine ends the program.
            return Ok(());
        }
        if program_block(block).is_some() {
            let (program, line) = self.running_program(false);
            return Err(sub_err(block, None, SubprogramError::NoReturn { program, line }));
        }
        if ends_program(block) && !is_return(block) {
            let word = block.all('M').find(|w| matches!(w.integer(), Some(2 | 30)));
            let (program, _) = self.running_program(false);
            return Err(sub_err(block, word, SubprogramError::EndInSubprogram { program }));
        }
        Ok(())
    }

    /// The subprogram running, as the dialect writes it, and the line of
    /// its `O` block (`sub` line): for messages.
    fn running_program(&self, lcnc: bool) -> (String, usize) {
        let entry = self.frames.last().and_then(|f| self.index.as_ref()?.get(f.entry));
        entry.map_or((String::new(), 0), |e| (shown_label(&e.label, lcnc), e.line))
    }

    /// The error of a subprogram whose text ends before its return, at
    /// the last line (`line`).
    pub(crate) fn no_return(&self, line: usize, lcnc: bool) -> ProgramError {
        let (program, at) = self.running_program(lcnc);
        ProgramError {
            line,
            word: None,
            kind: ErrorKind::Subprogram(SubprogramError::NoReturn { program, line: at }),
        }
    }

    /// Runs `block` if it is a call or a return, or (LinuxCNC) part of a
    /// definition the path passes over (`None` if it is none of these).
    /// `main` is the reader's position in the main program, kept by a
    /// call from it.
    pub(crate) fn flow(
        &mut self,
        block: &Block<'_>,
        machine: &Machine,
        main: Option<Position>,
    ) -> Option<Result<Flow, ProgramError>> {
        if machine.profile.dialect == Dialect::LinuxCnc {
            return self.oword_flow(block, machine, main);
        }
        // One pass over the block's M words (every block of a program
        // comes here).
        let (mut call, mut ret) = (None, None);
        for w in block.all('M') {
            match w.integer() {
                Some(98) => call = call.or(Some(w)),
                Some(99) => ret = ret.or(Some(w)),
                _ => {}
            }
        }
        match (call, ret) {
            (None, None) => None,
            (Some(_), Some(w)) => {
                Some(Err(sub_err(block, Some(w), SubprogramError::WordBeside { code: "M98" })))
            }
            (Some(_), None) if !self.has_index() => Some(Ok(Flow::NeedsIndex)),
            (Some(m), None) => Some(self.m98(block, m, machine, main).map(|()| Flow::Called)),
            (None, Some(m)) => Some(self.m99(block, m).map(|main| Flow::Returned { main })),
        }
    }

    /// The LinuxCNC o-words: `sub` … `endsub` passed over on the path,
    /// `call`, `endsub` and `return` run; the others refused.
    fn oword_flow(
        &mut self,
        block: &Block<'_>,
        machine: &Machine,
        main: Option<Position>,
    ) -> Option<Result<Flow, ProgramError>> {
        let oword = block_oword(block);
        if let Some((skipped, _)) = &self.skipping {
            return Some(match oword {
                Some((label, k, _)) if k == "endsub" && label == *skipped => {
                    self.skipping = None;
                    Ok(Flow::Skipped)
                }
                Some((label, k, _)) if k == "sub" => {
                    Err(oword_err(block, SubprogramError::MisplacedDefinition { program: label.to_string() }))
                }
                _ => Ok(Flow::Skipped),
            });
        }
        let (label, keyword, more) = oword?;
        Some(match keyword.as_str() {
            "sub" if self.running() => {
                Err(oword_err(block, SubprogramError::MisplacedDefinition { program: label.to_string() }))
            }
            "sub" => {
                let entry = self.entry_mut(&label);
                if entry.as_ref().is_some_and(|e| e.forward) {
                    return Some(Err(oword_err(
                        block,
                        SubprogramError::MisplacedDefinition { program: label.to_string() },
                    )));
                }
                if let Some(e) = entry {
                    e.passed = true;
                }
                self.skipping = Some((label, block.line));
                Ok(Flow::Skipped)
            }
            "call" | "endsub" | "return" if more => {
                Err(oword_err(block, SubprogramError::WordBeside { code: "an o-word" }))
            }
            "call" if !self.has_index() => Ok(Flow::NeedsIndex),
            "call" => self.call(block, &label, 1, machine, main, true).map(|()| Flow::Called),
            "endsub" | "return" => {
                let runs =
                    self.frames.last().and_then(|f| self.index.as_ref()?.get(f.entry)).map(|e| &e.label);
                if runs != Some(&label) {
                    return Some(Err(oword_err(block, SubprogramError::ReturnOutsideSubprogram)));
                }
                Ok(Flow::Returned { main: self.ret() })
            }
            _ => Err(oword_err(block, SubprogramError::Unfollowed)),
        })
    }

    fn entry_mut(&mut self, label: &OLabel) -> Option<&mut Entry> {
        let index = self.index.as_mut()?;
        let i = index.binary_search_by(|e| e.label.cmp(label)).ok()?;
        index.get_mut(i)
    }

    fn m98(
        &mut self,
        block: &Block<'_>,
        m98: &Word<'_>,
        machine: &Machine,
        main: Option<Position>,
    ) -> Result<(), ProgramError> {
        if let Some(w) = block.words.iter().find(|w| w.letter != 'P' && !std::ptr::eq(*w, m98)) {
            return Err(sub_err(block, Some(w), SubprogramError::WordBeside { code: "M98" }));
        }
        let Some(p) = block.get('P')? else {
            return Err(sub_err(
                block,
                Some(m98),
                SubprogramError::BadCall("M98 needs P, the program to call"),
            ));
        };
        let (program, repeats) =
            call_number(p).map_err(|rule| sub_err(block, Some(p), SubprogramError::BadCall(rule)))?;
        self.call(block, &OLabel::Number(u64::from(program)), repeats, machine, main, false).map_err(
            |mut e| {
                e.word = Some(p.text().into_owned());
                e
            },
        )
    }

    /// Calls `label`, `repeats` times.
    fn call(
        &mut self,
        block: &Block<'_>,
        label: &OLabel,
        repeats: u32,
        machine: &Machine,
        main: Option<Position>,
        lcnc: bool,
    ) -> Result<(), ProgramError> {
        let index = self.index.as_deref().unwrap_or_default();
        let Ok(i) = index.binary_search_by(|e| e.label.cmp(label)) else {
            return Err(oword_err(block, SubprogramError::NotFound { program: shown_label(label, lcnc) }));
        };
        if self.frames.len() >= usize::from(machine.subprogram_nesting) {
            return Err(oword_err(block, SubprogramError::TooDeep { limit: machine.subprogram_nesting }));
        }
        let back = match self.at {
            Some(at) if self.running() => Return::Sub(at),
            _ => Return::Main(main),
        };
        let Some(entry) = self.index.as_mut().and_then(|x| x.get_mut(i)) else {
            return Err(oword_err(block, SubprogramError::NotFound { program: shown_label(label, lcnc) }));
        };
        if lcnc && !entry.passed {
            entry.forward = true;
        }
        self.at = Some((entry.region, entry.at));
        self.frames.push(Frame { entry: i, repeats: repeats - 1, back });
        Ok(())
    }

    fn m99(&mut self, block: &Block<'_>, m99: &Word<'_>) -> Result<Option<Option<Position>>, ProgramError> {
        if let Some(w) = block.words.iter().find(|w| !std::ptr::eq(*w, m99)) {
            return Err(sub_err(block, Some(w), SubprogramError::WordBeside { code: "M99" }));
        }
        if !self.running() {
            return Err(sub_err(block, Some(m99), SubprogramError::ReturnOutsideSubprogram));
        }
        Ok(self.ret())
    }

    /// The return of the subprogram running: its next run, or back to
    /// its caller (`Some` with the main program's position, when the
    /// caller is the main program).
    fn ret(&mut self) -> Option<Option<Position>> {
        let frame = self.frames.last_mut()?;
        if frame.repeats > 0 {
            frame.repeats -= 1;
            let entry = self.index.as_ref()?.get(frame.entry)?;
            self.at = Some((entry.region, entry.at));
            return None;
        }
        let back = frame.back;
        self.frames.pop();
        match back {
            Return::Sub(at) => {
                self.at = Some(at);
                None
            }
            Return::Main(at) => {
                self.at = None;
                Some(at)
            }
        }
    }
}

/// True when `block` returns (M99).
fn is_return(block: &Block<'_>) -> bool {
    block.all('M').any(|w| w.integer() == Some(99))
}

/// The program and the number of runs of `M98 P`: as the FANUC and GSK
/// manuals write it, the last four digits are the program's number and
/// the digits before them (at most four) the number of runs, 1 when there
/// are none.
fn call_number(p: &Word<'_>) -> Result<(u32, u32), &'static str> {
    const RULE: &str = "P is the program number (four digits at most), after the number of runs \
                        (four digits at most): P31000 runs O1000 three times";
    let n = p.number();
    if n.negative || n.has_point() {
        return Err(RULE);
    }
    let digits = n.int_digits().as_bytes();
    if digits.is_empty() || digits.len() > 8 {
        return Err(RULE);
    }
    let split = digits.len().saturating_sub(4);
    let parse = |d: &[u8]| d.iter().fold(0u32, |v, &b| v * 10 + u32::from(b - b'0'));
    let program = parse(&digits[split..]);
    let repeats = if split == 0 { 1 } else { parse(&digits[..split]) };
    if program == 0 {
        return Err("O0000 is not a program number (P names a program from 1 to 9999)");
    }
    if repeats == 0 {
        return Err("the number of runs before the program number is 0 (P01000 runs O1000 no times)");
    }
    Ok((program, repeats))
}
