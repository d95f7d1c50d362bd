//! The reader fed a program a piece at a time, [`LineReader`]: where the
//! lexer stands in the piece, the subprogram calls it follows, and the
//! step from one block to its item.

use cycleref::Units;

use super::calls::{self, Calls, Flow};
use super::g75::{is_g75_1, lone_g75};
use super::g76::{G76Modal, G76OneShot};
use super::modal::Next;
use super::threads::G92Modal;
use super::{Item, MainStart, MotionMode, State, Subprograms};
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{Block, Lexer, Position};
use crate::profile::{Dialect, Machine};

/// Where a reader's subprograms are ([`LineReader::subprogram_text`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubprogramText {
    /// The reader follows no call (a trace).
    None,
    /// Before the main program's start and after its end (FANUC, GSK).
    AroundMain,
    /// Anywhere in the program (LinuxCNC's definitions).
    WholeProgram,
}

/// What [`LineReader::step`] gives.
#[derive(Debug)]
#[allow(
    clippy::large_enum_variant,
    reason = "an item is returned by value, as `next_in`'s Option<Result<Item>> is"
)]
pub enum Step<'a> {
    /// The next item.
    Item(Item<'a>),
    /// The piece has no more: the next step needs the next piece.
    Piece,
    /// A subprogram call runs: the next step needs the program's
    /// [`Subprograms`].
    Subprograms,
}

/// A LinuxCNC o-word where no call is followed (a trace).
fn subprogram_oword(block: &Block<'_>) -> ProgramError {
    let text = String::from_utf8_lossy(&block.text);
    ProgramError {
        line: block.line,
        word: text.split_whitespace().next().map(str::to_string),
        kind: ErrorKind::Unsupported(
            "an o-word in a trace: a trace holds the moves as the control ran them (reading R-SUBPROGRAM)"
                .into(),
        ),
    }
}

/// A reader fed a program a piece at a time: the same reader as
/// [`Reader`](super::Reader) (one state, one set of rules) for a program
/// that is not in memory as a whole, read from a file or a pipe line by
/// line. Its memory is the modal state, whatever the program's length; the
/// caller holds one piece.
///
/// A piece is one or more whole lines (with or without their line ends).
/// Call [`next_in`](LineReader::next_in) with the same piece until it
/// returns `None`, then with the next piece; after the last piece,
/// [`finish`](LineReader::finish) reports what the end of the program
/// leaves unfinished. Line numbers count from the first piece: items and
/// errors carry the whole program's line numbers.
///
/// ```
/// use cycleref_spec::reader::{Item, LineReader};
/// use cycleref_spec::{Machine, ProfileName};
///
/// let machine = Machine::new(ProfileName::Gsk988);
/// let mut reader = LineReader::new(&machine);
/// let mut line = Vec::new();
/// let mut cycle_lines = Vec::new();
/// for text in ["M03 S500", "G00 X80 Z10", "G76 P020560 Q0.1 R0.05", "G76 X60.64 Z-62 P3.68 Q1.8 F6"] {
///     line.clear();
///     line.extend_from_slice(text.as_bytes()); // a buffer reused for every line
///     while let Some(item) = reader.next_in(&line) {
///         if let Item::G76(call) = item? {
///             cycle_lines.push(call.block.line);
///         }
///     }
/// }
/// reader.finish()?;
/// assert_eq!(cycle_lines, [4]);
/// # Ok::<(), cycleref_spec::ProgramError>(())
/// ```
#[derive(Debug)]
pub struct LineReader<'m> {
    pub(super) state: State<'m>,
    /// The subprogram calls in progress (reading R-SUBPROGRAM).
    calls: Calls,
    /// Where the lexer stands in the current piece; `None` between pieces.
    at: Option<Position>,
    /// The number of the last line of the pieces finished so far.
    line: usize,
    started: bool,
    done: bool,
}

impl<'m> LineReader<'m> {
    /// A reader, before the first piece of a program read with `machine`.
    #[must_use]
    pub fn new(machine: &'m Machine) -> LineReader<'m> {
        LineReader {
            calls: Calls::default(),
            state: State {
                machine,
                units: machine.units(),
                x: None,
                z: None,
                moved: false,
                motion: MotionMode::G00,
                lead: None,
                speed: false,
                spindle_on: false,
                modal: [G76Modal::default(); 2],
                one_shot: G76OneShot::default(),
                g32_j: None,
                g32_k: None,
                thread_run: None,
                g75_pending: None,
                g92: G92Modal::default(),
                x_mode: machine.x_mode,
                lcnc_g76: false,
                lcnc_g33: false,
                lcnc_thread_run: false,
                program_end: false,
                trace: false,
                pq_unit: machine
                    .profile
                    .pq_unit(machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p))),
                high_speed: machine.profile.params.thread_mode.is_some_and(|n| machine.int_param(n) != 0),
            },
            at: None,
            line: 0,
            started: false,
            done: false,
        }
    }

    /// The units in force (fixed before the first motion, reading R-UNITS).
    #[must_use]
    pub fn units(&self) -> Units {
        self.state.units
    }

    /// Where this reader's subprograms are (reading R-SUBPROGRAM): none
    /// (a trace), around the main program (FANUC and GSK: its caller then
    /// finds where the main program starts, [`MainStart`], and starts the
    /// reader there, [`LineReader::start_at`]), or anywhere in the program
    /// (LinuxCNC's `sub` … `endsub`).
    #[must_use]
    pub fn subprogram_text(&self) -> SubprogramText {
        if !self.state.follows_calls() {
            SubprogramText::None
        } else if self.state.machine.profile.dialect == Dialect::LinuxCnc {
            SubprogramText::WholeProgram
        } else {
            SubprogramText::AroundMain
        }
    }

    /// The subprograms of the program `source`, whose main program
    /// starts at `main`, as [`LineReader::step`] asks for them: its text
    /// around the main program ([`Subprograms::in_text`]) or, for
    /// LinuxCNC, all of it ([`Subprograms::whole`]).
    ///
    /// # Errors
    ///
    /// As [`Subprograms::in_text`] and [`Subprograms::whole`].
    pub fn subprograms_in<'a>(
        &self,
        source: &'a [u8],
        main: MainStart,
    ) -> Result<Subprograms<'a>, ProgramError> {
        match self.subprogram_text() {
            SubprogramText::WholeProgram => Subprograms::whole(source),
            SubprogramText::AroundMain | SubprogramText::None => Subprograms::in_text(source, main),
        }
    }

    /// Starts the reading at the main program's start `main`: the first
    /// piece is the text from [`MainStart::offset`], its first line
    /// numbered after [`MainStart::lines_before`]. Before the first piece.
    pub fn start_at(&mut self, main: MainStart) {
        self.line = main.lines_before;
    }

    /// The number of the last line of the pieces finished so far (the
    /// next piece starts at the line after it).
    #[must_use]
    pub fn lines_read(&self) -> usize {
        self.line
    }

    /// True once the units can no longer change (reading R-UNITS: G20/G21
    /// only before the first motion or known position): in a valid
    /// program, [`units`](LineReader::units) are then those the program
    /// ends with.
    #[must_use]
    pub fn units_settled(&self) -> bool {
        self.state.units_settled()
    }

    /// The next item of `piece`, or `None` when the piece has no more (the
    /// next call starts the next piece). After an error the reader yields
    /// nothing more.
    ///
    /// This reader is given no subprograms: a call (`M98`) is an error
    /// naming it. [`LineReader::step`] follows calls.
    pub fn next_in<'a>(&mut self, piece: &'a [u8]) -> Option<Result<Item<'a>, ProgramError>> {
        match self.step(piece, None) {
            Ok(Step::Item(item)) => Some(Ok(item)),
            Ok(Step::Piece) => None,
            Ok(Step::Subprograms) => Some(Err(self.no_subprograms(piece))),
            Err(e) => Some(Err(e)),
        }
    }

    /// [`LineReader::next_in`] with the item lent to `f` where it was
    /// returned, not moved (an item is a few hundred bytes): what `f`
    /// makes of it, or `None` when the piece has no more.
    ///
    /// ```
    /// use cycleref_spec::reader::{Item, LineReader};
    /// use cycleref_spec::{Machine, ProfileName};
    ///
    /// let machine = Machine::new(ProfileName::Gsk988);
    /// let mut reader = LineReader::new(&machine);
    /// let piece = b"M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
    /// let mut cycle_lines = Vec::new();
    /// while let Some(line) = reader.next_in_with(piece, |item| matches!(item, Item::G76(_)).then(|| item.block().line)) {
    ///     cycle_lines.extend(line?);
    /// }
    /// reader.finish()?;
    /// assert_eq!(cycle_lines, [4]);
    /// # Ok::<(), cycleref_spec::ProgramError>(())
    /// ```
    pub fn next_in_with<'a, T>(
        &mut self,
        piece: &'a [u8],
        f: impl FnOnce(&Item<'a>) -> T,
    ) -> Option<Result<T, ProgramError>> {
        match self.step(piece, None) {
            Ok(Step::Item(ref item)) => Some(Ok(f(item))),
            Ok(Step::Piece) => None,
            Ok(Step::Subprograms) => Some(Err(self.no_subprograms(piece))),
            Err(e) => Some(Err(e)),
        }
    }

    /// The error of a subprogram call met by [`LineReader::next_in`],
    /// which is given no subprograms; the reader yields nothing more.
    #[cold]
    fn no_subprograms(&mut self, piece: &[u8]) -> ProgramError {
        self.done = true;
        let at = self.at.take();
        let mut lexer = match at {
            Some(at) => Lexer::resume(piece, at),
            None => Lexer::at_line(piece, self.line + 1),
        };
        let mut block = Block::empty();
        let line = match lexer.next_into(&mut block) {
            Some(Ok(())) => block.line,
            _ => self.line + 1,
        };
        ProgramError {
            line,
            word: Some("M98".into()),
            kind: ErrorKind::Unsupported(
                "a subprogram call read without the program's subprograms (LineReader::next_in; \
                 LineReader::step follows calls)"
                    .into(),
            ),
        }
    }

    /// The next step of reading `piece`, following subprogram calls
    /// (reading R-SUBPROGRAM): an item, the end of the piece
    /// ([`Step::Piece`]: call again with the next piece), or
    /// [`Step::Subprograms`] when a call runs and `subprograms` is `None`:
    /// call again with the same piece and the program's
    /// [`Subprograms`] (found once, with [`Subprograms::in_text`], or with
    /// [`MainEnd`](super::MainEnd) over a file), and with them on every later call. A
    /// program whose subprograms come before it starts after them
    /// ([`LineReader::start_at`]). While a subprogram
    /// runs, the reader reads the subprograms' text and keeps its place in
    /// `piece`, which must be the same bytes until the step that returns
    /// [`Step::Piece`]. After an error the reader yields nothing more
    /// ([`Step::Piece`]).
    ///
    /// ```
    /// use cycleref_spec::reader::{Item, LineReader, MainStart, Step, Subprograms};
    /// use cycleref_spec::{Machine, ProfileName};
    ///
    /// let program = b"G00 X80 Z5\nM98 P21000\nM30\nO1000\nG00 U-2\nM99\n";
    /// let machine = Machine::new(ProfileName::Gsk980);
    /// let mut reader = LineReader::new(&machine);
    /// let mut subs = None;
    /// let mut lines = Vec::new();
    /// loop {
    ///     match reader.step(program, subs)? {
    ///         Step::Item(Item::Move(m)) => lines.push((m.block.line, m.to.0)),
    ///         Step::Item(_) => {}
    ///         Step::Subprograms => subs = Some(Subprograms::in_text(program, MainStart::of_text(program))?),
    ///         Step::Piece => break,
    ///     }
    /// }
    /// reader.finish()?;
    /// // Line 5 runs twice: X80 (diameter, IS-B) less 2 mm, twice.
    /// assert_eq!(lines, [(1, Some(80_000)), (5, Some(78_000)), (5, Some(76_000))]);
    /// # Ok::<(), cycleref_spec::ProgramError>(())
    /// ```
    ///
    /// # Errors
    ///
    /// The first [`ProgramError`], in the order the control runs the
    /// blocks.
    pub fn step<'a>(
        &mut self,
        piece: &'a [u8],
        subprograms: Option<Subprograms<'a>>,
    ) -> Result<Step<'a>, ProgramError> {
        // The usual block in a function of its own size; any other, and
        // the first, by the general step.
        if self.started && !self.done && !self.state.program_end {
            let mut block = Block::empty();
            // The block moves once, into the item returned (`scan_plain`
            // gives a move or a block echoed).
            match self.step_plain(piece, &mut block) {
                Some(Some(Next::Move(from))) => {
                    return Ok(Step::Item(Item::Move(self.state.plain_move(block, from))))
                }
                Some(Some(_)) => return Ok(Step::Item(Item::Source(block))),
                // Read, not a plain move (a G76 or G32 block, S, T):
                // its item as the general step makes it.
                Some(None) => return self.item_of(block),
                None => {}
            }
        }
        self.step_general(piece, subprograms)
    }

    /// [`LineReader::step`] of any block.
    #[inline(never)]
    fn step_general<'a>(
        &mut self,
        piece: &'a [u8],
        subprograms: Option<Subprograms<'a>>,
    ) -> Result<Step<'a>, ProgramError> {
        // Reading R-PROGRAMEND: after M02 or M30 the control runs nothing
        // more; the blocks after it are not read.
        if self.done || self.state.program_end {
            return Ok(Step::Piece);
        }
        if !self.started {
            self.started = true;
            if let Err(e) = self.state.check_machine() {
                return Err(self.fail(e));
            }
        }
        loop {
            // The block is read where it stays until it moves into its item.
            let mut block = Block::empty();
            let before = self.at;
            let lcnc = self.state.machine.profile.dialect == Dialect::LinuxCnc;
            let semi = self.state.machine.readings.semicolon_comments(lcnc);
            if self.calls.running() {
                let (text, at) = self.calls.position(subprograms);
                let mut lexer = match at {
                    Some(at) => Lexer::resume(text, at),
                    None => Lexer::at_line(text, 1),
                }
                .with_owords(lcnc)
                .with_semicolon_comments(semi);
                match lexer.next_into(&mut block) {
                    Some(Ok(())) => {}
                    Some(Err(e)) => return Err(self.fail(e)),
                    None => {
                        let e = self.calls.no_return(lexer.line(), lcnc);
                        return Err(self.fail(e));
                    }
                }
                self.calls.set_position(lexer.position());
                if let Err(e) = self.calls.check_block(&block, self.state.machine) {
                    return Err(self.fail(e));
                }
            } else {
                let mut lexer = match self.at.take() {
                    Some(at) => Lexer::resume(piece, at),
                    None => Lexer::at_line(piece, self.line + 1),
                }
                .with_owords(lcnc)
                .with_semicolon_comments(semi);
                match lexer.next_into(&mut block) {
                    Some(Ok(())) => {}
                    // A line of a definition the path passes over is not
                    // read (LinuxCNC).
                    Some(Err(_)) if self.calls.skipping() => {
                        lexer.skip_line();
                        self.at = Some(lexer.position());
                        continue;
                    }
                    Some(Err(e)) => return Err(self.fail(e)),
                    None => {
                        self.line = lexer.line();
                        return Ok(Step::Piece);
                    }
                }
                self.at = Some(lexer.position());
            }
            if let Some(first) = &self.state.g75_pending {
                // Note 3: "必须有两行 G75.1 代码" — block 2 must follow block 1.
                if !block.words.is_empty() && !is_g75_1(&block) {
                    let e = lone_g75(first.line);
                    return Err(self.fail(e));
                }
            }
            // A block of FANUC or GSK without an M word neither calls nor
            // returns (`Calls::flow` would say `None`): most blocks, read
            // without the call.
            if self.state.follows_calls() && (lcnc || block.words.has('M')) {
                let mut flow = self.calls.flow(&block, self.state.machine, self.at);
                if matches!(flow, Some(Ok(Flow::NeedsIndex))) {
                    let Some(subs) = subprograms else {
                        // Read again once the caller has the subprograms.
                        self.at = before;
                        return Ok(Step::Subprograms);
                    };
                    if let Err(e) = self.calls.read_index(subs, lcnc, semi, block.line) {
                        return Err(self.fail(e));
                    }
                    flow = self.calls.flow(&block, self.state.machine, self.at);
                }
                match flow {
                    None => {}
                    Some(Ok(Flow::Called | Flow::Skipped | Flow::Returned { main: None })) => continue,
                    Some(Ok(Flow::Returned { main: Some(at) })) => {
                        self.at = at;
                        continue;
                    }
                    // Read above: the index is there.
                    Some(Ok(Flow::NeedsIndex)) => continue,
                    Some(Err(e)) => return Err(self.fail(e)),
                }
            } else if lcnc && calls::block_oword(&block).is_some() {
                return Err(self.fail(subprogram_oword(&block)));
            }
            return self.item_of(block);
        }
    }

    /// The item of `block`, read (where it stood) and followed (its calls,
    /// G75.1's block 2) by the step: the modal state's scan and item.
    #[inline(never)]
    fn item_of<'a>(&mut self, block: Block<'a>) -> Result<Step<'a>, ProgramError> {
        let item = match self.state.scan(&block) {
            // The usual block: it moves once, into the item returned.
            Ok(Next::Source) => return Ok(Step::Item(Item::Source(block))),
            Ok(Next::Move(from)) => return Ok(Step::Item(Item::Move(self.state.plain_move(block, from)))),
            Ok(next) => self.state.item(next, block),
            Err(e) => Err(e),
        };
        item.map(Step::Item).map_err(|e| self.fail(e))
    }

    /// [`LineReader::step`] of the usual block: one that starts a line,
    /// without an M word ([`Lexer::next_plain`]), where no subprogram runs
    /// and no G75.1 block 2 is awaited (FANUC and GSK). The block is read
    /// into `block` (empty on entry), as `step` reads it (a block without
    /// an M word neither calls nor returns), and the lexer's place kept:
    /// `Some(Some(next))` where [`State::scan_plain`] reads it, as `step`
    /// reads it; `Some(None)`, the state untouched, for the block's item
    /// to be made by [`LineReader::item_of`] (a G76 or G32 block: issue
    /// 33, 2 875 instructions a G76 line by the general step). `None`, the
    /// reader untouched and `block` to be dropped, for any other block,
    /// which `step` reads from where it was (issue 33: `step`'s work for
    /// every block, the calls, the block's other checks and the general
    /// lexer's state, was about a fifth of a reading). Held equal to
    /// `step`'s general reading by the proptests of `modal.rs`.
    #[inline(always)]
    fn step_plain<'a>(&mut self, piece: &'a [u8], block: &mut Block<'a>) -> Option<Option<Next>> {
        #[cfg(test)]
        if super::modal::tests::GENERAL_ONLY.with(std::cell::Cell::get) {
            return None;
        }
        let machine = self.state.machine;
        if machine.profile.dialect == Dialect::LinuxCnc
            || self.state.trace
            || self.state.g75_pending.is_some()
            || self.calls.running()
        {
            return None;
        }
        let mut lexer = match self.at {
            Some(at) => Lexer::resume(piece, at),
            None => Lexer::at_line(piece, self.line + 1),
        }
        .with_semicolon_comments(machine.readings.semicolon_comments(false));
        if !lexer.next_plain(block) {
            return None;
        }
        self.at = Some(lexer.position());
        let next = self.state.scan_plain(block);
        #[cfg(test)]
        match next {
            Some(_) => super::modal::tests::PLAIN_STEPS.with(|n| n.set(n.get() + 1)),
            None => super::modal::tests::LEXED_STEPS.with(|n| n.set(n.get() + 1)),
        }
        Some(next)
    }

    /// Ends the reading at error `e`.
    fn fail(&mut self, e: ProgramError) -> ProgramError {
        self.done = true;
        e
    }

    /// The end of the program, after its last piece.
    ///
    /// # Errors
    ///
    /// A G75.1 block 1 without its block 2.
    pub fn finish(&mut self) -> Result<(), ProgramError> {
        if self.done {
            return Ok(());
        }
        self.done = true;
        if let Some(e) = self.calls.unfinished() {
            return Err(e);
        }
        match self.state.g75_pending.take() {
            Some(first) => Err(lone_g75(first.line)),
            None => Ok(()),
        }
    }
}
