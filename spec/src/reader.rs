//! The program reader: modal state and the typed cycle parameters.
//!
//! This is the one home of the program's meaning. It tracks what the cycles
//! depend on (position, motion mode, lead, units, spindle, the modal values
//! of G76 block 1) and turns every G76 into a [`G76Cycle`] that both the
//! reference model ([`crate::g76`]) and the engine (`cycleref::engine`)
//! expand.

use cycleref::angle::StartAngle;
use cycleref::g32::{G32Block, G32RunOut};
use cycleref::g75::{Corner, CornerKind, G75Cycle, PathType, RIGHT_ANGLE};
use cycleref::g76::{DepthMode, G76Cycle, Infeed, RunOut};
use cycleref::g92::G92Cycle;
use cycleref::lead::{Lead, LeadWord, MAX_LEAD_SCALE};
use cycleref::linuxcnc::LinuxCncG76;
use cycleref::units::{Point, MAX_LENGTH};
use cycleref::{InputUnit, Units, XMode};
use rust_decimal::Decimal;

use crate::error::ErrorKind::NotInIncrements;
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{letter_bit, Block, Lexer, Position, Word};
use crate::profile::{Dialect, G32Rules, Machine, PSplit, PqUnit, QUnit, RunOutRules};

mod calls;
mod g75;
mod g76;
mod items;
mod linuxcnc;
mod threads;
mod trace;
mod words;

pub use calls::{
    may_hold_return, MainEnd, MainStart, MainStartFinder, SubprogramError, Subprograms,
    DEFAULT_SUBPROGRAM_BLOCK_LIMIT, DEFAULT_SUBPROGRAM_NESTING, LINUXCNC_SUBPROGRAM_NESTING,
    MAX_SUBPROGRAM_NESTING, MAX_SUBPROGRAM_TEXT,
};
use calls::{Calls, Flow};
pub use g76::resolve_run_out;
pub use items::{
    G32Call, G75Call, G76Call, G92Call, Item, LinuxCncCall, MotionMode, Multipass, PlainMove, Program,
    Restore,
};
pub use threads::resolve_g32_run_out;
pub use words::{check_axis_words, length_word, q_word};
#[allow(clippy::wildcard_imports)]
use {g75::*, g76::*, threads::*, words::*};

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

/// X, Z, U and W of a block.
type AxisWords<'b, 'a> =
    (Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>);

#[derive(Debug)]
struct State<'m> {
    machine: &'m Machine,
    units: Units,
    x: Option<i64>,
    z: Option<i64>,
    moved: bool,
    motion: MotionMode,
    lead: Option<Lead>,
    speed: bool,
    spindle_on: bool,
    /// Block 1's modal values, of G76 and of G78 (each its own).
    modal: [G76Modal; 2],
    one_shot: G76OneShot,
    /// G32's modal J and K (seed 002: "J、K是模态代码 … 在执行非螺纹切削代码时取消").
    g32_j: Option<i64>,
    g32_k: Option<i64>,
    /// The start angle of the open continuous thread, if the previous block
    /// was a G32 block that leaves the synchronisation running.
    thread_run: Option<StartAngle>,
    /// G75.1 block 1 waiting for its block 2.
    g75_pending: Option<G75Block1>,
    /// G92's modal values (reading R-G92MODAL).
    g92: G92Modal,
    /// The X mode in force (the machine's, switched by G7/G8 on the
    /// linuxcnc profile).
    x_mode: XMode,
    /// LinuxCNC: G76 is the motion mode in force (a later block with X or
    /// Z runs it again and needs its words again, as the interpreter does).
    lcnc_g76: bool,
    /// LinuxCNC: G33 is the motion mode in force (likewise: every block
    /// needs its K).
    lcnc_g33: bool,
    /// LinuxCNC: the previous block with words was a G33 move, so the
    /// synchronisation runs on (R-LCNC-G33).
    lcnc_thread_run: bool,
    /// M02 or M30 has been read: the program has ended (reading
    /// R-PROGRAMEND).
    program_end: bool,
    /// Reading a trace ([`LineReader::for_trace`]): its rules as well.
    trace: bool,
}

/// What [`State::scan`] found a block to be: the rest of its reading
/// takes the block itself.
#[derive(Debug)]
enum Next {
    /// A block echoed as written: read in full.
    Source,
    /// A block of plain motion, read in full: the position it starts from
    /// (the state holds where it ends).
    Move((Option<i64>, Option<i64>)),
    /// A block of the LinuxCNC dialect (read by `linuxcnc_block`).
    LinuxCnc,
    /// G75.1 block 1: read in full, pending.
    G75Params,
    /// G75.1 block 2, after its block 1.
    G75(G75Block1),
    /// G76 (G78) block 1: read in full.
    G76Params,
    /// G76 (G78) block 2.
    G76(Multipass),
    /// A G32 block.
    G32,
    /// A G92 block.
    G92,
}

/// Reading R-SUBPROGRAM: a subprogram call or return is refused, with its
/// line and word, until subprograms are expanded: an expansion that left
/// the call out, or read the subprogram where it stands in the file, would
/// not be the program the control runs.
fn subprogram(block: &Block<'_>, w: &Word<'_>) -> ProgramError {
    err(
        block,
        Some(w),
        ErrorKind::Unsupported(
            "a subprogram call or return (M98/M99) where no call is followed: a trace holds the moves as \
             the control ran them, and LinuxCNC calls subroutines with o-words, which are not followed yet \
             (reading R-SUBPROGRAM)"
                .into(),
        ),
    )
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

fn err(block: &Block<'_>, word: Option<&Word<'_>>, kind: ErrorKind) -> ProgramError {
    ProgramError { line: block.line, word: word.map(|w| w.text().into_owned()), kind }
}

/// The count parameters of `machine` (P(m), P(a), P(r), the chamfer angle,
/// G78's infeed and depth modes), checked when the parameter file is read
/// by the rules a cycle applies when it reads them (reading R-PARAMS), so
/// that a bad value is reported against the file and its key, not the
/// first program line that happens to use it. Length parameters are
/// checked where they are used, in the program's unit then in force.
///
/// # Errors
///
/// The first parameter outside its range, named with its key and range
/// (the error's line is 0: it belongs to no line).
///
/// ```
/// use cycleref_spec::reader::check_parameters;
/// use cycleref_spec::{Machine, ProfileName};
/// let mut m = Machine::new(ProfileName::Gsk988);
/// assert!(check_parameters(&m).is_ok());
/// m.apply_toml("[parameters]\n5142 = 100\n").unwrap();
/// let e = check_parameters(&m).unwrap_err();
/// assert_eq!(e.kind.to_string(), "parameter: 5142 = 100 is outside 1..99");
/// ```
pub fn check_parameters(machine: &Machine) -> Result<(), ProgramError> {
    LineReader::new(machine).state.check_params()
}

/// A cycle's alarm found when its block 2 is read, placed where the value
/// it is about was written (reading R-ERRLINE): at block 1's line
/// (`params_line`) for a word of block 1, else at block 2 with its word
/// when block 2 has it.
fn cycle_err(block: &Block<'_>, params_line: Option<usize>, e: cycleref::CycleError) -> ProgramError {
    match (e.field(), params_line) {
        (Some(field), Some(line)) if field.in_block_1() => {
            ProgramError { line, word: None, kind: ErrorKind::Cycle(e) }
        }
        (Some(field), _) => {
            let letter = field.word().chars().next().unwrap_or(' ');
            let word = block.all(letter).next();
            err(block, word, ErrorKind::Cycle(e))
        }
        (None, _) => err(block, None, ErrorKind::Cycle(e)),
    }
}

/// Reads `source` with `machine`, collecting every item.
///
/// This holds the whole program in memory; [`Reader`] reads it one item at
/// a time in constant memory.
///
/// # Errors
///
/// The first [`ProgramError`] in program order.
pub fn read<'a>(source: &'a str, machine: &Machine) -> Result<Program<'a>, ProgramError> {
    let mut reader = Reader::new(source.as_bytes(), machine);
    let items = reader.by_ref().collect::<Result<Vec<_>, _>>()?;
    Ok(Program { items, units: reader.units() })
}

/// The items of a program, one at a time, in program order.
///
/// The reader is the program's meaning in one place: it keeps the modal
/// state the cycles depend on and resolves each cycle's words into its
/// typed parameters, validated ([`G76Cycle::validate`] and its twins).
/// Its memory is the modal state and the current block, whatever the
/// program's length; items borrow their text from the source.
///
/// After the first error it yields nothing more. A program is read in two
/// phases by the command (reading R-STREAM): the first pass reads every
/// item and checks every cycle, and only a program without error is read a
/// second time to write its output, so an error leaves no output behind.
///
/// ```
/// use cycleref_spec::reader::{Item, Reader};
/// use cycleref_spec::{Machine, ProfileName};
///
/// let program = b"M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
/// let machine = Machine::new(ProfileName::Gsk988);
/// let mut cycles = 0;
/// for item in Reader::new(program, &machine) {
///     if let Item::G76(call) = item? {
///         assert_eq!(call.cycle.thread_height, 3680);
///         cycles += 1;
///     }
/// }
/// assert_eq!(cycles, 1);
/// # Ok::<(), cycleref_spec::ProgramError>(())
/// ```
pub struct Reader<'a, 'm> {
    source: &'a [u8],
    reader: LineReader<'m>,
    /// Where the main program starts, found before its first block.
    main: Option<MainStart>,
    /// The program's subprograms, found when the first call runs.
    subprograms: Option<Subprograms<'a>>,
    finished: bool,
}

impl<'a, 'm> Reader<'a, 'm> {
    /// A reader of `source` (the program's bytes) with `machine`.
    #[must_use]
    pub fn new(source: &'a [u8], machine: &'m Machine) -> Reader<'a, 'm> {
        Reader { source, reader: LineReader::new(machine), main: None, subprograms: None, finished: false }
    }

    /// The units in force (fixed before the first motion, reading R-UNITS).
    #[must_use]
    pub fn units(&self) -> Units {
        self.reader.units()
    }
}

impl<'a> Iterator for Reader<'a, '_> {
    type Item = Result<Item<'a>, ProgramError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.finished {
            return None;
        }
        let main = *self.main.get_or_insert_with(|| {
            let main = match self.reader.subprogram_text() {
                SubprogramText::AroundMain => MainStart::of_text(self.source),
                SubprogramText::None | SubprogramText::WholeProgram => MainStart::default(),
            };
            self.reader.start_at(main);
            main
        });
        let piece = &self.source[main.offset..];
        loop {
            match self.reader.step(piece, self.subprograms) {
                Ok(Step::Item(item)) => return Some(Ok(item)),
                Ok(Step::Piece) => break,
                Ok(Step::Subprograms) => match self.reader.subprograms_in(self.source, main) {
                    Ok(subs) => self.subprograms = Some(subs),
                    Err(e) => {
                        self.finished = true;
                        return Some(Err(e));
                    }
                },
                Err(e) => {
                    self.finished = true;
                    return Some(Err(e));
                }
            }
        }
        if self.finished {
            return None;
        }
        self.finished = true;
        self.reader.finish().err().map(Err)
    }
}

/// A reader fed a program a piece at a time: the same reader as [`Reader`]
/// (one state, one set of rules) for a program that is not in memory as a
/// whole, read from a file or a pipe line by line. Its memory is the modal
/// state, whatever the program's length; the caller holds one piece.
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
    state: State<'m>,
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
            Ok(Step::Subprograms) => {
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
                Some(Err(ProgramError {
                    line,
                    word: Some("M98".into()),
                    kind: ErrorKind::Unsupported(
                        "a subprogram call read without the program's subprograms (LineReader::next_in; \
                         LineReader::step follows calls)"
                            .into(),
                    ),
                }))
            }
            Err(e) => Some(Err(e)),
        }
    }

    /// The next step of reading `piece`, following subprogram calls
    /// (reading R-SUBPROGRAM): an item, the end of the piece
    /// ([`Step::Piece`]: call again with the next piece), or
    /// [`Step::Subprograms`] when a call runs and `subprograms` is `None`:
    /// call again with the same piece and the program's
    /// [`Subprograms`] (found once, with [`Subprograms::in_text`], or with
    /// [`MainEnd`] over a file), and with them on every later call. A
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
            if self.calls.running() {
                let (text, at) = self.calls.position(subprograms);
                let mut lexer = match at {
                    Some(at) => Lexer::resume(text, at),
                    None => Lexer::at_line(text, 1),
                }
                .with_owords(lcnc);
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
                .with_owords(lcnc);
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
            if self.state.follows_calls() {
                let mut flow = self.calls.flow(&block, self.state.machine, self.at);
                if matches!(flow, Some(Ok(Flow::NeedsIndex))) {
                    let Some(subs) = subprograms else {
                        // Read again once the caller has the subprograms.
                        self.at = before;
                        return Ok(Step::Subprograms);
                    };
                    if let Err(e) = self.calls.read_index(subs, lcnc, block.line) {
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
            let item = match self.state.scan(&block) {
                // The usual block: it moves once, into the item returned.
                Ok(Next::Source) => return Ok(Step::Item(Item::Source(block))),
                Ok(Next::Move(from)) => {
                    return Ok(Step::Item(Item::Move(self.state.plain_move(block, from))))
                }
                Ok(next) => self.state.item(next, block),
                Err(e) => Err(e),
            };
            return item.map(Step::Item).map_err(|e| self.fail(e));
        }
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

impl State<'_> {
    /// True when the reader follows subprogram calls: a program, not a
    /// trace (which holds no calls).
    fn follows_calls(&self) -> bool {
        !self.trace
    }

    /// The machine's settings that no program can use (none at present:
    /// 5129 = 1, the 988TA's high-speed threading mode, is refused by the
    /// G76 block it would change, and followed by G92).
    #[allow(clippy::unnecessary_wraps, clippy::unused_self)]
    fn check_machine(&self) -> Result<(), ProgramError> {
        Ok(())
    }

    /// The count parameters a cycle reads when its block leaves a value
    /// out, checked by the same rules as there (reading R-PARAMS).
    fn check_params(&self) -> Result<(), ProgramError> {
        let profile = &self.machine.profile;
        let p = &profile.params;
        self.param_count(p.finishing_passes, i64::from(profile.min_finishing_passes), 99)?;
        self.param_count(p.tool_angle, 0, 99)?;
        self.param_count(p.chamfer, 0, 99)?;
        if let Some(n) = p.chamfer_angle {
            self.param_count(n, 0, 89)?;
        }
        if let Some(g78) = profile.g78 {
            let last = i64::try_from(g78.infeeds.len()).unwrap_or(1) - 1;
            self.param_count(g78.infeed_param, 0, last)?;
            self.param_count(g78.depth_mode_param, 0, 1)?;
        }
        Ok(())
    }

    /// True when the 988TA's parameter 5129 (THM) selects the high-speed
    /// threading mode.
    fn high_speed(&self) -> bool {
        self.machine.profile.params.thread_mode.is_some_and(|n| self.machine.int_param(n) != 0)
    }
}

impl State<'_> {
    /// The item of `block` once [`State::scan`] has said what it is.
    fn item<'a>(&mut self, next: Next, block: Block<'a>) -> Result<Item<'a>, ProgramError> {
        match next {
            Next::Source => Ok(Item::Source(block)),
            Next::Move(from) => Ok(Item::Move(self.plain_move(block, from))),
            Next::LinuxCnc => self.linuxcnc_block(block),
            Next::G75Params => Ok(Item::G75Params(block)),
            Next::G75(first) => self.g75_block2(first, block).map(Item::G75),
            Next::G76Params => Ok(Item::G76Params(block)),
            Next::G76(code) => self.g76_block2(block, code).map(Item::G76),
            Next::G32 => self.g32_block(block).map(Item::G32),
            Next::G92 => self.g92_block(block).map(Item::G92),
        }
    }

    /// Reads `block` in the modal state as far as deciding its item: all
    /// of it for a block that is not a cycle's (most are), which then
    /// moves once, into its item.
    fn scan(&mut self, block: &Block<'_>) -> Result<Next, ProgramError> {
        if self.machine.profile.dialect == Dialect::LinuxCnc {
            return Ok(Next::LinuxCnc);
        }
        // G codes of the block.
        let mut g76: Option<Multipass> = None;
        let mut g75 = false;
        let mut g50 = false;
        let mut g04 = false;
        let mut motion = None;
        // The G word of a canned cycle (refused in a trace).
        let mut cycle_word = None;
        for w in block.all('G') {
            let whole = w.integer();
            if matches!(whole, Some(76 | 78 | 92)) || (whole.is_none() && w.number().exact(1) == Some(751)) {
                cycle_word = cycle_word.or(Some(w));
            }
            match whole {
                Some(c @ 0..=3) => motion = MotionMode::plain(c),
                Some(32) => motion = Some(MotionMode::G32),
                Some(92) => motion = Some(MotionMode::G92),
                Some(4) => g04 = true,
                Some(50) => g50 = true,
                Some(76) => g76 = Some(Multipass::G76),
                Some(78) => {
                    if self.machine.profile.g78.is_none() {
                        return Err(err(
                            block,
                            Some(w),
                            ErrorKind::Unsupported(format!(
                                "G78 on the {} profile (G78 is GSK's enhanced thread-cutting cycle: use the \
                                 gsk980 or gsk988 profile)",
                                self.machine.profile.name
                            )),
                        ));
                    }
                    g76 = Some(Multipass::G78);
                }
                Some(20) => self.set_unit(block, w, InputUnit::Inch)?,
                Some(21) => self.set_unit(block, w, InputUnit::Metric)?,
                Some(18 | 40 | 54..=59 | 96 | 97 | 98 | 99) => {}
                None if w.number().exact(1) == Some(751) => {
                    if !self.machine.profile.g75_1 {
                        return Err(err(
                            block,
                            Some(w),
                            ErrorKind::Unsupported(format!(
                                "G75.1 on the {} profile (G75.1 is a GSK 980TDi cycle: use the gsk980 \
                                 profile)",
                                self.machine.profile.name
                            )),
                        ));
                    }
                    g75 = true;
                }
                _ => {
                    let code = w.number().decimal().unwrap_or(Decimal::NEGATIVE_ONE);
                    return Err(err(
                        block,
                        Some(w),
                        ErrorKind::Unsupported(format!(
                            "G{code} (the reader models G00-G04, G18, G20/G21, G32, G40, G50, G54-G59, \
                             G75.1, G76, G92 (the thread-cutting cycle), G96-G99)"
                        )),
                    ));
                }
            }
        }
        // M codes and S.
        for w in block.all('M') {
            match w.integer() {
                Some(3 | 4) => self.spindle_on = true,
                Some(5) => self.spindle_on = false,
                Some(98 | 99) => return Err(subprogram(block, w)),
                // A trace goes on after it: its moves are compared.
                Some(2 | 30) => self.program_end = !self.trace,
                _ => {}
            }
        }
        if self.trace {
            let m = motion.unwrap_or(self.motion);
            self.trace_block(block, cycle_word, m, m == MotionMode::G32, g04)?;
        }
        if let Some(s) = block.get('S')? {
            // Reading R-SPINDLE: `G50 S` alone clamps the spindle speed; with X/Z
            // (the manuals' "G50 X100 Z50 M3 S300") S is the speed.
            let clamp = g50 && !block.has('X') && !block.has('Z');
            if !clamp && s.number().is_positive() {
                self.speed = true;
            }
        }
        if !block.words.is_empty() {
            // Continuity needs consecutive G32 blocks (a comment line does not count).
            let thread_block = motion.unwrap_or(self.motion) == MotionMode::G32
                && g76.is_none()
                && !g50
                && !g04
                && ['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c));
            if !thread_block {
                self.thread_run = None;
                // Seed 002: J and K are cancelled by a non-thread motion.
                if motion.is_some_and(|m| m != MotionMode::G32) || g76.is_some() || g75 {
                    self.g32_j = None;
                    self.g32_k = None;
                }
            }
        }
        if g75 {
            if motion.is_some() || g76.is_some() || g50 || g04 {
                return Err(err(
                    block,
                    None,
                    ErrorKind::Unsupported("another G code of group 00/01 in the same block as G75.1".into()),
                ));
            }
            return match self.g75_pending.take() {
                None => {
                    self.g75_pending = Some(self.g75_block1(block)?);
                    Ok(Next::G75Params)
                }
                Some(first) => Ok(Next::G75(first)),
            };
        }
        if let Some(code) = g76 {
            if motion.is_some() {
                return Err(err(
                    block,
                    None,
                    ErrorKind::Unsupported(format!("a motion G code in the same block as {}", code.code())),
                ));
            }
            return if ['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c)) {
                Ok(Next::G76(code))
            } else {
                self.g76_block1(block, code)?;
                Ok(Next::G76Params)
            };
        }
        if let Some(f) = block.get('F')? {
            if f.number().is_positive() {
                self.lead =
                    Some(self.lead(block, f).unwrap_or(Lead { word: LeadWord::F, mantissa: 0, scale: 0 }));
            }
        }
        if let Some(m) = motion {
            if m != MotionMode::G92 {
                // Reading R-G92MODAL: another motion code ends the G92 mode.
                self.g92 = G92Modal::default();
            }
            self.motion = m;
        }
        if matches!(motion, Some(MotionMode::G32 | MotionMode::G92))
            && !g04
            && !g50
            && !['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c))
        {
            let rule = if motion == Some(MotionMode::G32) {
                "G32 cuts to an end point"
            } else {
                "G92 cuts to its cut end point C"
            };
            return Err(err(block, None, ErrorKind::Missing { what: "X(U) Z(W) (the end point)", rule }));
        }
        if g04 {
            return Ok(Next::Source);
        }
        let (xw, zw, uw, ww) = Self::axis_words(block)?;
        if g50 {
            if uw.is_some() || ww.is_some() {
                return Err(err(block, uw.or(ww), ErrorKind::Unsupported("U/W in G50".into())));
            }
            if let Some(w) = xw {
                self.x = Some(self.length(block, w)?);
            }
            if let Some(w) = zw {
                self.z = Some(self.length(block, w)?);
            }
            return Ok(Next::Source);
        }
        if xw.is_some() || zw.is_some() || uw.is_some() || ww.is_some() {
            if self.motion == MotionMode::G32 {
                return Ok(Next::G32);
            }
            if self.motion == MotionMode::G92 {
                return Ok(Next::G92);
            }
            self.g32_j = None;
            self.g32_k = None;
            let from = (self.x, self.z);
            self.x = self.axis(block, xw, uw, self.x)?;
            self.z = self.axis(block, zw, ww, self.z)?;
            self.moved = true;
            return Ok(Next::Move(from));
        }
        Ok(Next::Source)
    }

    /// The move of a plain block from `from` to where the state now holds
    /// the tool.
    fn plain_move<'a>(&self, block: Block<'a>, from: (Option<i64>, Option<i64>)) -> PlainMove<'a> {
        PlainMove { block, motion: self.motion, from, to: (self.x, self.z), x_mode: self.x_mode }
    }

    /// True once the unit can no longer change (reading R-UNITS): after
    /// the first motion, or once a position is known (G50).
    fn units_settled(&self) -> bool {
        self.moved || self.x.is_some() || self.z.is_some()
    }

    /// G20/G21 (reading R-UNITS): the unit may change only before the
    /// first motion.
    fn set_unit(&mut self, block: &Block<'_>, w: &Word<'_>, unit: InputUnit) -> Result<(), ProgramError> {
        if self.trace {
            return self.trace_unit(block, w, unit);
        }
        if unit != self.units.unit {
            if self.units_settled() {
                return Err(err(block, Some(w), ErrorKind::UnitChangeAfterMotion));
            }
            self.units.unit = unit;
        }
        Ok(())
    }

    #[inline(always)]
    fn axis(
        &self,
        block: &Block<'_>,
        abs: Option<&Word<'_>>,
        inc: Option<&Word<'_>>,
        cur: Option<i64>,
    ) -> Result<Option<i64>, ProgramError> {
        if let Some(w) = abs {
            return Ok(Some(self.length(block, w)?));
        }
        if let Some(w) = inc {
            let d = self.length(block, w)?;
            let c = cur.ok_or_else(|| err(block, Some(w), ErrorKind::PositionUnknown))?;
            let v = c + d;
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                return Err(err(block, Some(w), self.range_err(true)));
            }
            return Ok(Some(v));
        }
        Ok(cur)
    }

    /// X, Z, U and W of a block; X with U or Z with W is an error.
    #[inline(always)]
    fn axis_words<'b, 'a>(block: &'b Block<'a>) -> Result<AxisWords<'b, 'a>, ProgramError> {
        if !['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c)) {
            return Ok((None, None, None, None));
        }
        let (xw, zw, uw, ww) = if ['X', 'Z', 'U', 'W'].iter().any(|&c| block.words.repeats(c)) {
            // `get` names the repeated word.
            (block.get('X')?, block.get('Z')?, block.get('U')?, block.get('W')?)
        } else {
            // The usual case: one pass over the words.
            let (mut xw, mut zw, mut uw, mut ww) = (None, None, None, None);
            for w in &block.words {
                match w.letter {
                    'X' => xw = Some(w),
                    'Z' => zw = Some(w),
                    'U' => uw = Some(w),
                    'W' => ww = Some(w),
                    _ => {}
                }
            }
            (xw, zw, uw, ww)
        };
        if xw.is_some() && uw.is_some() || zw.is_some() && ww.is_some() {
            return Err(err(
                block,
                uw.or(ww),
                ErrorKind::Unsupported("absolute and incremental words for the same axis".into()),
            ));
        }
        Ok((xw, zw, uw, ww))
    }

    /// The end point X(U) Z(W) of a block that starts at `from`.
    fn end_point(&self, block: &Block<'_>, from: Point) -> Result<Point, ProgramError> {
        let (xw, zw, uw, ww) = Self::axis_words(block)?;
        let x = self.axis(block, xw, uw, Some(from.x))?.unwrap_or(from.x);
        let z = self.axis(block, zw, ww, Some(from.z))?.unwrap_or(from.z);
        Ok(Point::new(x, z))
    }

    fn check_spindle(&self, block: &Block<'_>) -> Result<(), ProgramError> {
        // A trace is a log of moves: it need not hold the spindle's words.
        if self.trace || (self.speed && self.spindle_on) {
            Ok(())
        } else {
            Err(err(block, None, ErrorKind::NoSpindleSpeed))
        }
    }

    /// Every word of `block` has an address of `allowed` or `extra`.
    fn check_addresses(
        &self,
        block: &Block<'_>,
        cycle: &'static str,
        allowed: &str,
        extra: &str,
    ) -> Result<(), ProgramError> {
        // Most words are upper-case letters of the lists: a bit test each;
        // the lists themselves are read for any other.
        let listed = letter_mask(allowed) | letter_mask(extra);
        for w in &block.words {
            if letter_bit(w.letter) & listed != 0 {
                continue;
            }
            if !allowed.contains(w.letter) && !extra.contains(w.letter) {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::AddressNotInProfile { cycle, profile: self.machine.profile.name.to_string() },
                ));
            }
        }
        Ok(())
    }

    /// P(k) or Q(Δd) of G76 block 2: required, in the profile's P/Q unit,
    /// 1..=the profile's range table.
    fn depth_word(
        &self,
        block: &Block<'_>,
        letter: char,
        what: &'static str,
        rule: &'static str,
    ) -> Result<i64, ProgramError> {
        let max = self.machine.profile.max_depth_increments;
        let w = block.get(letter)?.ok_or_else(|| err(block, None, ErrorKind::Missing { what, rule }))?;
        let v = self.pq_length(block, w)?;
        if v == 0 || v > max {
            return Err(err(
                block,
                Some(w),
                ErrorKind::OutOfRange { range: format!("1..{max} least increments") },
            ));
        }
        Ok(v)
    }
}
