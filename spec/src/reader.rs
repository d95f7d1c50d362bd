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

mod linuxcnc;
mod trace;

/// What the reader found in a program, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item<'a> {
    /// A block that is not part of a cycle and commands no motion: echoed
    /// as written.
    Source(Block<'a>),
    /// A block of plain motion (G00-G03 with X, Z, U or W): echoed as
    /// written; the move it commands, from the reader's own modal state.
    Move(PlainMove<'a>),
    /// G76 block 1 (P Q R ...): sets modal values, produces no motion.
    G76Params(Block<'a>),
    /// G76 block 2: a cycle to expand.
    G76(G76Call<'a>),
    /// A G32 thread-cutting block.
    G32(G32Call<'a>),
    /// G75.1 block 1 (X Z P Q H D A B L): waits for its block 2.
    G75Params(Block<'a>),
    /// G75.1 block 2: a groove cycle to expand.
    G75(G75Call<'a>),
    /// A G92 thread-cutting cycle block (the first, or a repeat in G92
    /// mode): a cycle to expand.
    G92(G92Call<'a>),
    /// A LinuxCNC G76 block (the `linuxcnc` profile): a cycle to expand.
    LinuxCncG76(LinuxCncCall<'a>),
}

impl<'a> Item<'a> {
    /// The block the item was read from (for a cycle of two blocks, its
    /// second; block 1 is its own item).
    #[must_use]
    pub fn block(&self) -> &Block<'a> {
        match self {
            Item::Source(b) | Item::G76Params(b) | Item::G75Params(b) => b,
            Item::Move(m) => &m.block,
            Item::G76(c) => &c.block,
            Item::G32(c) => &c.block,
            Item::G75(c) => &c.block,
            Item::G92(c) => &c.block,
            Item::LinuxCncG76(c) => &c.block,
        }
    }
}

/// A block of plain motion as the reader resolves it: the one model of a
/// G00-G03 move, for `expand`'s echo, `check` (our program and a trace
/// alike) and `plot`.
///
/// An axis is `None` while no block has given it (reading R-CHECKPARTIAL:
/// a move before both axes are known moves along the one it gives).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlainMove<'a> {
    /// The block.
    pub block: Block<'a>,
    /// G00, G01, G02 or G03 (modal: the mode in force).
    pub motion: MotionMode,
    /// X and Z before the block (increments, in `x_mode`).
    pub from: (Option<i64>, Option<i64>),
    /// X and Z after it: the absolute words, or the incremental ones added
    /// to `from`.
    pub to: (Option<i64>, Option<i64>),
    /// The X mode in force (the machine's, switched by G7/G8 on the
    /// linuxcnc profile).
    pub x_mode: XMode,
}

/// One LinuxCNC G76 block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinuxCncCall<'a> {
    /// The block.
    pub block: Block<'a>,
    /// The resolved cycle.
    pub cycle: LinuxCncG76,
}

impl LinuxCncCall<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> LinuxCncCall<'static> {
        LinuxCncCall { block: self.block.detached(), cycle: self.cycle }
    }
}

/// One G92 block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G92Call<'a> {
    /// The block.
    pub block: Block<'a>,
    /// The resolved cycle.
    pub cycle: G92Cycle,
}

impl G92Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G92Call<'static> {
        G92Call { block: self.block.detached(), cycle: self.cycle }
    }
}

/// One G75.1 cycle of a program (its two blocks).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G75Call<'a> {
    /// Block 2 (R V U W I J A B D E P).
    pub block: Block<'a>,
    /// Line of block 1.
    pub params_line: usize,
    /// The resolved cycle.
    pub cycle: G75Cycle,
    /// Modal state to restore after the expansion.
    pub restore: Restore,
}

impl G75Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G75Call<'static> {
        G75Call {
            block: self.block.detached(),
            params_line: self.params_line,
            cycle: self.cycle,
            restore: self.restore,
        }
    }
}

/// One G32 block of a program (or LinuxCNC's G33, the same one
/// synchronised move: [`G32Call::code`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G32Call<'a> {
    /// `G32`, or `G33` on the linuxcnc profile, whose lead is the distance
    /// per revolution along the move (reading R-LCNC-SYNC).
    pub code: &'static str,
    /// The block.
    pub block: Block<'a>,
    /// The resolved block.
    pub g32: G32Block,
}

impl G32Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G32Call<'static> {
        G32Call { code: self.code, block: self.block.detached(), g32: self.g32 }
    }
}

/// Which multiple thread-cutting cycle a [`G76Call`] is: G76, or GSK's
/// enhanced G78, a front end on the same cycle (its infeed and depth modes
/// are in [`G76Cycle`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Multipass {
    /// G76, the multiple thread-cutting cycle.
    G76,
    /// G78, the GSK 980TDi's and 988TA's enhanced multiple thread-cutting
    /// cycle (增强型螺纹切削循环).
    G78,
}

impl Multipass {
    /// The G code as the manuals write it.
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            Multipass::G76 => "G76",
            Multipass::G78 => "G78",
        }
    }
}

/// One G76 or G78 cycle of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G76Call<'a> {
    /// G76 or G78.
    pub code: Multipass,
    /// Block 2 (the one with X(U) Z(W)).
    pub block: Block<'a>,
    /// Line of the block 1 whose values are in force, if any.
    pub params_line: Option<usize>,
    /// The resolved cycle.
    pub cycle: G76Cycle,
    /// What to program after the expansion to give the following blocks
    /// the modal state they had before the cycle.
    pub restore: Restore,
}

impl G76Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G76Call<'static> {
        G76Call {
            code: self.code,
            block: self.block.detached(),
            params_line: self.params_line,
            cycle: self.cycle,
            restore: self.restore,
        }
    }
}

/// Modal state to restore after an expanded cycle, whose last block leaves
/// G00 and the lead in F.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Restore {
    /// The motion G code in force before the cycle when it was not G00
    /// (G76 is a one-shot code; the expansion ends with G00). The F register
    /// needs no restoring: the expansion writes the lead exactly as the
    /// cycle programmed or inherited it (reading R-NCOUT).
    pub motion: Option<MotionMode>,
}

/// A program read with a machine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Program<'a> {
    /// The blocks and cycles, in order.
    pub items: Vec<Item<'a>>,
    /// The units in force for the cycles (fixed before the first motion).
    pub units: Units,
}

impl<'a> Program<'a> {
    /// The G32 blocks of the program.
    pub fn threads(&self) -> impl Iterator<Item = &G32Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G32(c) => Some(c),
            _ => None,
        })
    }

    /// The G75.1 cycles of the program.
    pub fn grooves(&self) -> impl Iterator<Item = &G75Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G75(c) => Some(c),
            _ => None,
        })
    }

    /// The cycles of the program.
    pub fn cycles(&self) -> impl Iterator<Item = &G76Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G76(c) => Some(c),
            _ => None,
        })
    }
}

/// A motion G code of group 01, as the reader keeps it modal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MotionMode {
    /// G00, rapid.
    G00,
    /// G01, linear feed.
    G01,
    /// G02, clockwise arc.
    G02,
    /// G03, counter-clockwise arc.
    G03,
    /// G32, thread cutting.
    G32,
    /// G92, the thread-cutting cycle (modal: a block with X(U) or Z(W)
    /// repeats it).
    G92,
}

impl MotionMode {
    /// The G code as written (`G01`).
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            MotionMode::G00 => "G00",
            MotionMode::G01 => "G01",
            MotionMode::G02 => "G02",
            MotionMode::G03 => "G03",
            MotionMode::G32 => "G32",
            MotionMode::G92 => "G92",
        }
    }

    /// The motion of G00-G03, which every dialect reads alike (`None` for
    /// another code): one home for both readers' tables.
    #[must_use]
    pub fn plain(code: i64) -> Option<MotionMode> {
        match code {
            0 => Some(MotionMode::G00),
            1 => Some(MotionMode::G01),
            2 => Some(MotionMode::G02),
            3 => Some(MotionMode::G03),
            _ => None,
        }
    }
}

/// X, Z, U and W of a block.
type AxisWords<'b, 'a> =
    (Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>);

/// Modal values of G76 block 1 and, on the 988TA, J and K (reading R-MODAL).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct G76Modal {
    finishing_passes: Option<u32>,
    chamfer: Option<u32>,
    /// G78's P(r) (G76's infeed D is one-shot).
    infeed: Option<Infeed>,
    /// G78's depth mode (980TDi P(m), 988TA D).
    depth_mode: Option<DepthMode>,
    tool_angle: Option<u32>,
    min_cut: Option<i64>,
    allowance: Option<i64>,
    j: Option<i64>,
    k: Option<i64>,
}

/// One-shot values of the last block 1 (D, L, E; J, K on the 980TDi).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct G76OneShot {
    /// The cycle whose block 1 set these (a G76 block 1 does not apply to
    /// a G78 block 2, nor the other way).
    code: Option<Multipass>,
    infeed: Option<Infeed>,
    starts: Option<u32>,
    lead_in: Option<i64>,
    j: Option<i64>,
    k: Option<i64>,
    line: Option<usize>,
}

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

/// The modal values of G92 (reading R-G92MODAL): the cut end, R, J, K, L
/// and P, kept from block to block while G92 is the motion mode (980TDi:
/// "F … J … K … L … 模态参数"; 988TA: "R … 模态值", "P … 模态指令"; FANUC:
/// X(U), Z(W) and R are modal in a canned cycle) and forgotten when
/// another motion G code is programmed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct G92Modal {
    end_x: Option<i64>,
    end_z: Option<i64>,
    taper: Option<i64>,
    j: Option<i64>,
    k: Option<i64>,
    starts: Option<u32>,
    /// P1 (988TA): a face thread.
    face: Option<bool>,
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

/// The values of a G75.1 block 1, kept until block 2 arrives.
#[derive(Clone, Debug, PartialEq, Eq)]
struct G75Block1 {
    /// Its line.
    line: usize,
    from: Point,
    start: Point,
    peck: i64,
    step: i64,
    depth: i64,
    width: i64,
    flank_a: u32,
    flank_b: u32,
    slope: u32,
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
            "a subprogram call or return (M98/M99, LinuxCNC's o-words): subprograms are not expanded yet, and \
             an expansion without them would not be the program the control runs (reading R-SUBPROGRAM)"
                .into(),
        ),
    )
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
    finished: bool,
}

impl<'a, 'm> Reader<'a, 'm> {
    /// A reader of `source` (the program's bytes) with `machine`.
    #[must_use]
    pub fn new(source: &'a [u8], machine: &'m Machine) -> Reader<'a, 'm> {
        Reader { source, reader: LineReader::new(machine), finished: false }
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
        if let Some(item) = self.reader.next_in(self.source) {
            return Some(item);
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
    pub fn next_in<'a>(&mut self, piece: &'a [u8]) -> Option<Result<Item<'a>, ProgramError>> {
        // Reading R-PROGRAMEND: after M02 or M30 the control runs nothing
        // more; the blocks after it are not read.
        if self.done || self.state.program_end {
            return None;
        }
        if !self.started {
            self.started = true;
            if let Err(e) = self.state.check_machine() {
                self.done = true;
                return Some(Err(e));
            }
        }
        let mut lexer = match self.at.take() {
            Some(at) => Lexer::resume(piece, at),
            None => Lexer::at_line(piece, self.line + 1),
        };
        // The block is read where it stays until it moves into its item.
        let mut block = Block::empty();
        match lexer.next_into(&mut block) {
            Some(Ok(())) => {}
            Some(Err(e)) => {
                self.done = true;
                return Some(Err(e));
            }
            None => {
                self.line = lexer.line();
                return None;
            }
        }
        self.at = Some(lexer.position());
        if let Some(first) = &self.state.g75_pending {
            // Note 3: "必须有两行 G75.1 代码" — block 2 must follow block 1.
            if !block.words.is_empty() && !is_g75_1(&block) {
                self.done = true;
                return Some(Err(lone_g75(first.line)));
            }
        }
        let item = match self.state.scan(&block) {
            // The usual block: it moves once, into the item returned.
            Ok(Next::Source) => return Some(Ok(Item::Source(block))),
            Ok(Next::Move(from)) => return Some(Ok(Item::Move(self.state.plain_move(block, from)))),
            Ok(next) => self.state.item(next, block),
            Err(e) => Err(e),
        };
        self.done = item.is_err();
        Some(item)
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
        match self.state.g75_pending.take() {
            Some(first) => Err(lone_g75(first.line)),
            None => Ok(()),
        }
    }
}

impl State<'_> {
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

/// True when `block` programs G75.1.
fn is_g75_1(block: &Block<'_>) -> bool {
    block.all('G').any(|w| w.number().exact(1) == Some(751))
}

fn lone_g75(line: usize) -> ProgramError {
    ProgramError {
        line,
        word: None,
        kind: ErrorKind::Missing {
            what: "the second G75.1 block (R V U W I J A B D E P)",
            rule: "G75.1 always takes two blocks, note 3: 必须有两行 G75.1 代码",
        },
    }
}

/// A length word in least increments of `units`, under `machine`'s
/// decimal-point rule (reading R-POINT): with a decimal point, or without
/// one on a GSK profile, the value is in mm (inch) and must be a whole
/// number of increments; without one on FANUC (unless calculator-type
/// input), it is the number of increments. The one home of the rule, used
/// by the program reader and by trace readers.
///
/// # Errors
///
/// A value finer than the increment or beyond the range tables.
#[inline]
pub fn length_word(
    machine: &Machine,
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
) -> Result<i64, ProgramError> {
    let bare = machine.profile.bare_length_is_increments && !machine.calculator_input;
    to_increments(units, block, w, bare)
}

/// The program's rule for a block's axis words, shared with the trace
/// readers: X with U, or Z with W, in one block is an error naming the
/// incremental word (absolute and incremental words for the same axis).
///
/// # Errors
///
/// Both words of one axis, or an axis word repeated.
pub fn check_axis_words(block: &Block<'_>) -> Result<(), ProgramError> {
    State::axis_words(block).map(|_| ())
}

fn increment_text(units: Units) -> String {
    let unit = match units.unit {
        InputUnit::Metric => "mm",
        InputUnit::Inch => "inch",
    };
    let mut s = String::from("0.");
    for _ in 1..units.decimals() {
        s.push('0');
    }
    s.push('1');
    format!("{s} {unit}")
}

fn range_err(units: Units, signed: bool) -> ErrorKind {
    let mut max = String::new();
    let _ = cycleref::units::write_fixed(&mut max, i128::from(MAX_LENGTH), units.decimals());
    ErrorKind::OutOfRange { range: if signed { format!("-{max}..{max}") } else { format!("0..{max}") } }
}

/// The bits ([`letter_bit`]) of the upper-case letters of `letters`.
fn letter_mask(letters: &str) -> u32 {
    letters.chars().fold(0, |m, c| m | letter_bit(c))
}

/// A length word in increments. `bare_increments` says what a value
/// without a decimal point means.
#[inline]
fn to_increments(
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
    bare_increments: bool,
) -> Result<i64, ProgramError> {
    // The usual word (inlined): a value in increments within range.
    if !bare_increments || w.has_point() {
        if let Some(Some(v)) = w.scaled(units.decimals()) {
            if v.unsigned_abs() <= MAX_LENGTH.unsigned_abs() {
                return Ok(v);
            }
        }
    }
    increments_slow(units, block, w, bare_increments)
}

/// [`to_increments`] of every word, errors included.
#[inline(never)]
fn increments_slow(
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
    bare_increments: bool,
) -> Result<i64, ProgramError> {
    let n = &w.number();
    let not_in_increments = || NotInIncrements { increment: increment_text(units) };
    // A value too large for any range table gets the range message, even
    // where it is too large for the arithmetic too; a value finer than the
    // increment gets the increment's.
    let v = if !n.has_point() && bare_increments {
        n.integer().ok_or_else(|| range_err(units, true))
    } else if let Some(v) = n.scaled(units.decimals()) {
        v.ok_or_else(not_in_increments)
    } else {
        match n.decimal() {
            // checked: a 28-digit value times 10^5 overflows a Decimal.
            Some(d) => match d.checked_mul(Decimal::from(units.per_unit())) {
                Some(scaled) if !scaled.fract().is_zero() => Err(not_in_increments()),
                Some(scaled) => i64::try_from(scaled.trunc()).map_err(|_| range_err(units, true)),
                None => Err(range_err(units, true)),
            },
            None => {
                let frac = n.frac_digits().unwrap_or_default().trim_end_matches('0');
                if frac.len() > units.decimals() as usize {
                    Err(not_in_increments())
                } else {
                    Err(range_err(units, true))
                }
            }
        }
    };
    let v = v.map_err(|kind| err(block, Some(w), kind))?;
    if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
        return Err(err(block, Some(w), range_err(units, true)));
    }
    Ok(v)
}

impl State<'_> {
    fn to_increments(
        &self,
        block: &Block<'_>,
        w: &Word<'_>,
        bare_increments: bool,
    ) -> Result<i64, ProgramError> {
        to_increments(self.units, block, w, bare_increments)
    }

    fn range_err(&self, signed: bool) -> ErrorKind {
        range_err(self.units, signed)
    }

    /// A length word (reading R-POINT: FANUC bare values are increments).
    #[inline(always)]
    fn length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        length_word(self.machine, self.units, block, w)
    }

    fn unsigned_length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        let v = self.length(block, w)?;
        if v < 0 {
            return Err(err(block, Some(w), self.range_err(false)));
        }
        Ok(v)
    }

    /// P(k), Q(Δd), Q(Δdmin): unit by the profile's state parameter.
    fn pq_length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        let bit = self.machine.profile.params.pq_unit.map_or(0, |p| self.machine.int_param(p));
        let v = match self.machine.profile.pq_unit(bit) {
            PqUnit::IncrementsNoPoint => {
                if w.number().has_point() {
                    return Err(err(
                        block,
                        Some(w),
                        ErrorKind::DecimalPointNotAllowed {
                            rule: "P(k), Q(Δd) and Q(Δdmin) of G76 are given in least increments",
                        },
                    ));
                }
                self.to_increments(block, w, true)?
            }
            PqUnit::Increments => {
                let v = w.number().integer().ok_or_else(|| {
                    err(
                        block,
                        Some(w),
                        ErrorKind::NotInIncrements {
                            increment: "the state parameter selects least increments for P and Q".into(),
                        },
                    )
                })?;
                if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                    return Err(err(block, Some(w), self.range_err(false)));
                }
                v
            }
            PqUnit::Length => self.to_increments(block, w, false)?,
        };
        if v < 0 {
            return Err(err(block, Some(w), self.range_err(false)));
        }
        Ok(v)
    }

    fn count(block: &Block<'_>, w: &Word<'_>, lo: i64, hi: i64) -> Result<u32, ProgramError> {
        match w.number().integer() {
            Some(v) if (lo..=hi).contains(&v) && !w.number().has_point() => {
                Ok(u32::try_from(v).unwrap_or(u32::MAX))
            }
            _ => {
                Err(err(block, Some(w), ErrorKind::OutOfRange { range: format!("whole number {lo}..{hi}") }))
            }
        }
    }

    fn lead(&self, block: &Block<'_>, w: &Word<'_>) -> Result<Lead, ProgramError> {
        let n = &w.number();
        let word = if w.letter == 'F' { LeadWord::F } else { LeadWord::I };
        let mut frac = n.frac_bytes().unwrap_or_default();
        while let [rest @ .., b'0'] = frac {
            frac = rest;
        }
        let scale = u32::try_from(frac.len()).unwrap_or(u32::MAX);
        let out = |range: &str| err(block, Some(w), ErrorKind::OutOfRange { range: range.into() });
        // Range tables of seed 000: F 0.0001..9999 mm / 0.00001..9.99 inch;
        // I 0.0001..254 (metric) / 0.0001..100 (inch).
        // The bounds in units of 10^-MAX_LEAD_SCALE (6 decimals).
        let (lo, hi, range) = match (word, self.units.unit) {
            // K is LinuxCNC's and never read here (`word` is F or I).
            (LeadWord::F | LeadWord::K, InputUnit::Metric) => (100, 9_999_000_000, "F 0.0001..9999 mm"),
            (LeadWord::F | LeadWord::K, InputUnit::Inch) => (10, 9_990_000, "F 0.00001..9.99 inch"),
            (LeadWord::I, InputUnit::Metric) => (100, 254_000_000, "I 0.0001..254 threads per inch"),
            (LeadWord::I, InputUnit::Inch) => (100, 100_000_000, "I 0.0001..100 threads per inch"),
        };
        // Finer than 10^-6: said so (it is no range of a table that is
        // wrong but the decimals; issue 30 found 6).
        if scale > MAX_LEAD_SCALE {
            return Err(out(&format!(
                "{range}, with at most {MAX_LEAD_SCALE} decimals (this lead has {scale})"
            )));
        }
        // Beyond an i128: outside the table.
        let value = n.exact(MAX_LEAD_SCALE).ok_or_else(|| out(range))?;
        if n.negative || value < lo || value > hi || scale > MAX_LEAD_SCALE {
            return Err(out(range));
        }
        // Within the range table and MAX_LEAD_SCALE, the digits fit a u64.
        let mantissa = n.int_bytes().iter().chain(frac).fold(0_u64, |m, b| m * 10 + u64::from(b - b'0'));
        Ok(Lead { word, mantissa, scale })
    }

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

    /// The lead of a thread block: its F or I, else the modal one; it
    /// becomes the modal lead.
    fn block_lead(&mut self, block: &Block<'_>) -> Result<Lead, ProgramError> {
        let lead = match (block.get('F')?, block.get('I')?) {
            (Some(f), Some(_)) => {
                return Err(err(block, Some(f), ErrorKind::Unsupported("both F and I in one block".into())))
            }
            (Some(w), None) | (None, Some(w)) => self.lead(block, w)?,
            (None, None) => self.lead.ok_or_else(|| {
                err(block, None, ErrorKind::Missing { what: "F(I) (lead)", rule: "a thread needs a lead" })
            })?,
        };
        self.lead = Some(lead);
        Ok(lead)
    }

    /// A G32 block: `X(U) Z(W) F(I) J K Q` (seed 002).
    fn g32_block<'a>(&mut self, block: Block<'a>) -> Result<G32Call<'a>, ProgramError> {
        let rules = self.machine.profile.g32_rules;
        let allowed = if rules == G32Rules::NoRunOut { "GXZUWFIQMST" } else { "GXZUWFIJKQMST" };
        self.check_addresses(&block, "G32", allowed, "")?;
        self.check_spindle(&block)?;
        let (Some(x0), Some(z0)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        let Point { x: xe, z: ze } = self.end_point(&block, Point::new(x0, z0))?;
        let lead = self.block_lead(&block)?;
        // J signed, K unsigned (seed 002), both modal.
        if let Some(w) = block.get('J')? {
            self.g32_j = Some(self.length(&block, w)?);
        }
        if let Some(w) = block.get('K')? {
            self.g32_k = Some(self.unsigned_length(&block, w)?);
        }
        let run_out = resolve_g32_run_out(rules, self.g32_j, self.g32_k);
        // Q: only the first block of a continuous thread counts (seed 002 rule 2).
        let q = match block.get('Q')? {
            Some(w) => Some(self.start_angle(&block, w)?),
            None => None,
        };
        let (sync, start_angle) = match self.thread_run {
            Some(angle) => (false, angle),
            None => (true, q.unwrap_or(StartAngle::ZERO)),
        };
        let g32 = G32Block {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(x0, z0),
            end: Point::new(xe, ze),
            lead,
            run_out,
            start_angle,
            sync,
        };
        // The position after the block is where the run-out ends (seed 002,
        // figure 3-82): the reference model says where.
        let moves = crate::g32::expand(&g32).map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        let last = moves.last().map_or(g32.end, |m| m.to);
        self.x = Some(last.x);
        self.z = Some(last.z);
        self.moved = true;
        // 988TA: a run-out in a middle segment makes the thread discontinuous.
        let breaks = rules == G32Rules::Gsk988 && run_out != G32RunOut::None;
        self.thread_run = if breaks { None } else { Some(start_angle) };
        Ok(G32Call { code: "G32", block, g32 })
    }

    /// The motion to restore after a G76 or G75.1 expansion: the mode in
    /// force, unless it is G00 (the expansion's last move) or G92 (every
    /// G92 block is expanded too, so the output never needs the mode back).
    fn restore(&self) -> Restore {
        let motion = match self.motion {
            MotionMode::G00 | MotionMode::G92 => None,
            m => Some(m),
        };
        Restore { motion }
    }

    /// A G92 block: `X(U) Z(W) R F(I)` and the profile's extras (980TDi: J
    /// K L; 988TA: J K L Q P), the first of a G92 mode or a repeat
    /// (readings R-G92MODAL, R-G92RUNOUT).
    fn g92_block<'a>(&mut self, block: Block<'a>) -> Result<G92Call<'a>, ProgramError> {
        let profile = &self.machine.profile;
        self.check_addresses(&block, "G92", "GXZUWRFIMST", profile.g92_extra)?;
        let with_line = |mut e: ProgramError| {
            if e.line == 0 {
                e.line = block.line;
            }
            e
        };
        let (Some(xa), Some(za)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        self.check_spindle(&block)?;
        // The cut end: each axis as programmed (U, W from A), else the
        // previous G92 block's (modal), else A's.
        let (xw, zw, uw, ww) = Self::axis_words(&block)?;
        let xc = self.axis(&block, xw, uw, Some(xa))?.filter(|_| xw.is_some() || uw.is_some());
        let zc = self.axis(&block, zw, ww, Some(za))?.filter(|_| zw.is_some() || ww.is_some());
        let end = Point::new(xc.or(self.g92.end_x).unwrap_or(xa), zc.or(self.g92.end_z).unwrap_or(za));
        let taper = match block.get('R')? {
            Some(w) => self.length(&block, w)?,
            None => self.g92.taper.unwrap_or(0),
        };
        let lead = self.block_lead(&block)?;
        // 980TDi note 10: "J、K输入负值时，按正值处理"; elsewhere J and K are
        // unsigned ("不带方向") and a negative one is refused.
        let negative_as_positive = profile.run_out == RunOutRules::Gsk980;
        let run_out_word = |w: &Word<'_>| {
            if negative_as_positive {
                self.length(&block, w).map(i64::abs)
            } else {
                self.unsigned_length(&block, w)
            }
        };
        let j = block.get('J')?.map(run_out_word).transpose()?;
        let k = block.get('K')?.map(run_out_word).transpose()?;
        if j.is_some() {
            self.g92.j = j;
        }
        if k.is_some() {
            self.g92.k = k;
        }
        if let Some(w) = block.get('L')? {
            self.g92.starts = Some(Self::count(&block, w, 1, profile.g92_max_starts)?);
        }
        if let Some(w) = block.get('P')? {
            // 988TA: "当 P=0 或省略 P 时，加工轴向螺纹；当 P=1 时，加工端面螺纹" (modal,
            // "螺纹类型，模态指令"; reading R-G92FACE).
            self.g92.face = Some(Self::count(&block, w, 0, 1)? == 1);
        }
        let start_angle = match block.get('Q')? {
            Some(w) => self.start_angle(&block, w)?,
            None => StartAngle::ZERO,
        };
        let p = &profile.params;
        let r = self.param_count(p.chamfer, 0, 99).map_err(with_line)?;
        let angle = match p.chamfer_angle {
            Some(n) => match self.param_count(n, 0, 89).map_err(with_line)? {
                0 => 45,
                v => v,
            },
            None => 45,
        };
        // 988TA: 5129 (THM) = 1 is the high-speed G92 mode, with its own
        // J/K rules (reading R-G92RUNOUT).
        let rules = if self.high_speed() { RunOutRules::Gsk988HighSpeed } else { profile.run_out };
        let run_out = resolve_run_out(rules, self.g92.j, self.g92.k, r, angle);
        let cycle = G92Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(xa, za),
            end,
            taper,
            lead,
            run_out,
            starts: self.g92.starts.unwrap_or(1),
            start_angle,
            face: self.g92.face.unwrap_or(false),
        };
        cycle.validate().map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        self.g92.end_x = Some(end.x);
        self.g92.end_z = Some(end.z);
        self.g92.taper = Some(taper);
        // The block ends back at A (step ④).
        self.moved = true;
        Ok(G92Call { block, cycle })
    }

    /// G32's Q in the profile's unit (reading R-G32Q).
    fn start_angle(&self, block: &Block<'_>, w: &Word<'_>) -> Result<StartAngle, ProgramError> {
        q_word(self.machine, self.units, block, w)
    }

    /// G76 or G78 block 1: `P(m)(r)(a) Q(Δdmin) R(d)` and the profile's
    /// extras (G76: J K on the 980TDi, D L E on the 988TA; G78: J K D L E,
    /// D L E).
    fn g76_block1(&mut self, block: &Block<'_>, code: Multipass) -> Result<(), ProgramError> {
        let profile = &self.machine.profile;
        let (name, extra) = match (code, profile.g78) {
            (Multipass::G78, Some(g78)) => ("G78 block 1", g78.block1_extra),
            _ => ("G76 block 1", profile.block1_extra),
        };
        self.check_addresses(block, name, "GPQRMST", extra)?;
        if let Some(p) = block.get('P')? {
            self.split_p(block, p, code)?;
        }
        let min_cut = block.get('Q')?.map(|q| self.pq_length(block, q)).transpose()?;
        let allowance = block.get('R')?.map(|r| self.unsigned_length(block, r)).transpose()?;
        let lead_in = block.get('E')?.map(|e| self.unsigned_length(block, e)).transpose()?;
        let j = block.get('J')?.map(|j| self.unsigned_length(block, j)).transpose()?;
        let k = block.get('K')?.map(|k| self.unsigned_length(block, k)).transpose()?;
        let modal = &mut self.modal[code as usize];
        if min_cut.is_some() {
            modal.min_cut = min_cut;
        }
        if allowance.is_some() {
            modal.allowance = allowance;
        }
        let mut one =
            G76OneShot { code: Some(code), line: Some(block.line), lead_in, j, k, ..G76OneShot::default() };
        if let Some(d) = block.get('D')? {
            match (code, profile.g78) {
                (Multipass::G78, Some(g78)) if g78.m_is_depth_mode => {
                    // 980TDi: D is the finishing passes, 0..99.
                    modal.finishing_passes = Some(Self::count(block, d, 0, 99)?);
                }
                (Multipass::G78, _) => {
                    // 988TA: D is the depth mode, 0 equal, 1 decreasing.
                    modal.depth_mode = Some(depth_mode(Self::count(block, d, 0, 1)?));
                }
                (Multipass::G76, _) => {
                    one.infeed = Some(match Self::count(block, d, 0, 2)? {
                        0 => Infeed::RightFlank,
                        1 => Infeed::RightCentre,
                        _ => Infeed::LeftRight,
                    });
                }
            }
        }
        if let Some(l) = block.get('L')? {
            let max = match (code, profile.g78) {
                (Multipass::G78, Some(g78)) => g78.max_starts,
                _ => 999,
            };
            one.starts = Some(Self::count(block, l, 1, max)?);
        }
        self.one_shot = one;
        Ok(())
    }

    /// Reading R-PSPLIT: last two digits a, next two r, the rest m. For
    /// G78 (reading R-G78P) r is the infeed mode and, on the 980TDi, m the
    /// depth mode.
    fn split_p(&mut self, block: &Block<'_>, p: &Word<'_>, code: Multipass) -> Result<(), ProgramError> {
        if p.number().has_point() || p.number().negative {
            return Err(err(
                block,
                Some(p),
                ErrorKind::DecimalPointNotAllowed { rule: "P(m)(r)(a) is a string of digits" },
            ));
        }
        let digits = p.number().int_digits();
        let n = digits.len();
        let part = |from: usize, to: usize| -> u32 { digits[from..to].parse().unwrap_or(0) };
        let whole = self.machine.profile.p_split == PSplit::WholeOnly;
        if whole && n < 5 {
            return Err(err(block, Some(p), ErrorKind::PartialP));
        }
        if n > 6 {
            return Err(err(
                block,
                Some(p),
                ErrorKind::OutOfRange { range: "m 0..99, r 00..99, a 00..99".into() },
            ));
        }
        let a = part(n.saturating_sub(2), n);
        let g78 = self.machine.profile.g78.filter(|_| code == Multipass::G78);
        let min = self.machine.profile.min_finishing_passes;
        let modal = &mut self.modal[code as usize];
        modal.tool_angle = Some(a);
        if n >= 3 {
            let r = part(n.saturating_sub(4), n - 2);
            match g78 {
                Some(g78) => {
                    let mode = g78.infeeds.get(r as usize).copied().ok_or_else(|| {
                        err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange {
                                range: format!("G78 infeed mode r 00..{:02}", g78.infeeds.len() - 1),
                            },
                        )
                    })?;
                    modal.infeed = Some(mode);
                }
                None => modal.chamfer = Some(r),
            }
        }
        if n >= 5 {
            let m = part(0, n - 4);
            match g78 {
                Some(g78) if g78.m_is_depth_mode => {
                    if m > 1 {
                        return Err(err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange {
                                range: "G78 depth mode m 0 (equal) or 1 (decreasing)".into(),
                            },
                        ));
                    }
                    modal.depth_mode = Some(depth_mode(m));
                }
                _ => {
                    if m < min {
                        return Err(err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange { range: format!("finishing passes m {min:02}..99") },
                        ));
                    }
                    modal.finishing_passes = Some(m);
                }
            }
        }
        Ok(())
    }

    fn param_count(&self, number: &str, lo: i64, hi: i64) -> Result<u32, ProgramError> {
        let v = self.machine.int_param(number);
        if (lo..=hi).contains(&v) {
            Ok(u32::try_from(v).unwrap_or(0))
        } else {
            Err(ProgramError {
                line: 0,
                word: None,
                kind: ErrorKind::Parameter(format!("{number} = {v} is outside {lo}..{hi}")),
            })
        }
    }

    fn param_length(&self, number: &str) -> Result<i64, ProgramError> {
        let d = self.machine.length_param(number).checked_mul(Decimal::from(self.units.per_unit()));
        match d.map(|d| (i64::try_from(d.trunc()), d.fract().is_zero())) {
            Some((Ok(v), true)) if (0..=MAX_LENGTH).contains(&v) => Ok(v),
            _ => Err(ProgramError {
                line: 0,
                word: None,
                kind: ErrorKind::Parameter(format!(
                    "{number} = {} is not a whole number of least increments in 0..{}",
                    self.machine.length_param(number),
                    MAX_LENGTH
                )),
            }),
        }
    }

    /// G76 or G78 block 2: `X(U) Z(W) R(i) P(k) Q(Δd) F(I)` and the
    /// profile's extras (J K on the 988TA).
    fn g76_block2<'a>(&mut self, block: Block<'a>, code: Multipass) -> Result<G76Call<'a>, ProgramError> {
        let profile = &self.machine.profile;
        let g78 = profile.g78.filter(|_| code == Multipass::G78);
        let (name, block1_extra, block2_extra) = match g78 {
            Some(g78) => ("G78 block 2", g78.block1_extra, g78.block2_extra),
            None => ("G76 block 2", profile.block1_extra, profile.block2_extra),
        };
        self.check_addresses(&block, name, "GXZUWRPQFIMST", block2_extra)?;
        let with_line = |mut e: ProgramError| {
            if e.line == 0 {
                e.line = block.line;
            }
            e
        };
        if self.high_speed() {
            // Reading R-RUNOUT: 5129 switches G76 (seed 000: "螺纹切削循环
            // G92,G76 的模式") and G78 (the 988TA G78 page: "G92，G76，G78
            // 的模式"), and no source gives their high-speed rules.
            let n = profile.params.thread_mode.unwrap_or("5129");
            return Err(err(
                &block,
                None,
                ErrorKind::Parameter(format!(
                    "{n} = {} selects the high-speed threading mode, whose {} rules the manuals do not \
                     give; set it to 0 (G92 follows it)",
                    self.machine.int_param(n),
                    code.code()
                )),
            ));
        }
        let (Some(xa), Some(za)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        self.check_spindle(&block)?;
        let Point { x: xd, z: zd } = self.end_point(&block, Point::new(xa, za))?;
        let taper = match block.get('R')? {
            Some(w) => self.length(&block, w)?,
            None => 0,
        };
        let k = self.depth_word(&block, 'P', "P(k) (thread height)", "alarm when P(k) is not given")?;
        let first_depth =
            self.depth_word(&block, 'Q', "Q(Δd) (first depth)", "alarm when Δd is not given")?;
        let lead = self.block_lead(&block)?;
        let mut j = None;
        let mut kk = None;
        if block2_extra.contains('J') {
            if let Some(w) = block.get('J')? {
                j = Some(self.unsigned_length(&block, w)?);
            }
            if let Some(w) = block.get('K')? {
                kk = Some(self.unsigned_length(&block, w)?);
            }
        }
        // Block 1's one-shot values apply to the block 2 of the same cycle.
        let one = std::mem::take(&mut self.one_shot);
        let one = if one.code == Some(code) { one } else { G76OneShot::default() };
        let modal = self.modal[code as usize];
        if block1_extra.contains('J') {
            j = one.j;
            kk = one.k;
        }
        if profile.jk_modal {
            let modal = &mut self.modal[code as usize];
            if j.is_some() {
                modal.j = j;
            }
            if kk.is_some() {
                modal.k = kk;
            }
            j = modal.j;
            kk = modal.k;
        }
        let p = &profile.params;
        let m = match modal.finishing_passes {
            Some(m) => m,
            None => self
                .param_count(p.finishing_passes, i64::from(profile.min_finishing_passes), 99)
                .map_err(with_line)?,
        };
        let a = match modal.tool_angle {
            Some(a) => a,
            None => self.param_count(p.tool_angle, 0, 99).map_err(with_line)?,
        };
        // G78 has no chamfer word (its P(r) is the infeed mode): the
        // parameter's (reading R-G78RUNOUT).
        let r = match modal.chamfer.filter(|_| g78.is_none()) {
            Some(r) => r,
            None => self.param_count(p.chamfer, 0, 99).map_err(with_line)?,
        };
        let angle = match p.chamfer_angle {
            Some(n) => match self.param_count(n, 0, 89).map_err(with_line)? {
                0 => 45,
                v => v,
            },
            None => 45,
        };
        let min_cut = match modal.min_cut {
            Some(v) => v,
            None => self.param_length(p.min_cut).map_err(with_line)?,
        };
        let allowance = match modal.allowance {
            Some(v) => v,
            None => self.param_length(p.finishing_allowance).map_err(with_line)?,
        };
        let run_out = resolve_run_out(profile.run_out, j, kk, r, angle);
        let (infeed, depth_mode) = match g78 {
            None => (one.infeed.unwrap_or(Infeed::RightFlank), DepthMode::Decreasing),
            Some(g78) => {
                let infeed = match modal.infeed {
                    Some(i) => i,
                    None => {
                        let last = i64::try_from(g78.infeeds.len()).unwrap_or(1) - 1;
                        let v = self.param_count(g78.infeed_param, 0, last).map_err(with_line)?;
                        g78.infeeds.get(v as usize).copied().unwrap_or(Infeed::RightFlank)
                    }
                };
                let depth = match modal.depth_mode {
                    Some(d) => d,
                    None => depth_mode(self.param_count(g78.depth_mode_param, 0, 1).map_err(with_line)?),
                };
                (infeed, depth)
            }
        };
        let restore = self.restore();
        let cycle = G76Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(xa, za),
            end: Point::new(xd, zd),
            taper,
            thread_height: k,
            first_depth,
            min_cut,
            finishing_allowance: allowance,
            finishing_passes: m,
            tool_angle: a,
            infeed,
            depth_mode,
            lead_in: one.lead_in.unwrap_or(0),
            starts: one.starts.unwrap_or(1),
            lead,
            run_out,
            pass_limit: self.machine.pass_limit,
        };
        cycle.validate().map_err(|e| cycle_err(&block, one.line, e))?;
        self.moved = true;
        Ok(G76Call { code, params_line: one.line, block, cycle, restore })
    }
}

impl State<'_> {
    /// An angle word of G75.1 (A, B, L) in degrees, to 0.0001 degree; bare
    /// values are degrees ("A45 B30" in the seed's example). Range tables
    /// are checked by [`G75Cycle::validate`]; this refuses only what cannot
    /// be an angle at all.
    fn g75_angle(&self, block: &Block<'_>, w: &Word<'_>) -> Result<u32, ProgramError> {
        let out = || {
            err(
                block,
                Some(w),
                ErrorKind::OutOfRange { range: "0..90 degrees (A, B: 0 < a <= 90; L: 0 <= L < 90)".into() },
            )
        };
        let d = w.number().decimal().ok_or_else(out)?;
        if d.is_sign_negative() && !d.is_zero() {
            return Err(out());
        }
        // The range table gives angles to 0.001 degree at IS-B and 0.0001
        // degree at IS-C.
        let decimals: u32 = match self.units.system {
            cycleref::IncrementSystem::IsB => 3,
            cycleref::IncrementSystem::IsC => 4,
        };
        let t = d.checked_mul(Decimal::from(10_000)).ok_or_else(out)?;
        if d.normalize().scale() > decimals || !t.fract().is_zero() {
            return Err(err(
                block,
                Some(w),
                ErrorKind::NotInIncrements {
                    increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
                },
            ));
        }
        let t = u32::try_from(t.trunc()).map_err(|_| out())?;
        if t > 4 * RIGHT_ANGLE {
            return Err(out());
        }
        Ok(t)
    }

    /// A required length word of G75.1 block 1.
    fn g75_required<'b, 'a>(
        block: &'b Block<'a>,
        letter: char,
        what: &'static str,
    ) -> Result<&'b Word<'a>, ProgramError> {
        block.get(letter)?.ok_or_else(|| {
            err(
                block,
                None,
                ErrorKind::Missing {
                    what,
                    rule: "G75.1 block 1 needs H, D, P and Q; only they cannot be omitted (note 3)",
                },
            )
        })
    }

    /// G75.1 block 1: `X Z P(Δi) Q(Δk) H(h) D(d) A(∠a) B(∠b) L(∠p)` (seed 001).
    fn g75_block1<'a>(&self, block: &Block<'a>) -> Result<G75Block1, ProgramError> {
        // A block 2 where a block 1 is due (R-G75PAIR): it has block-2 words
        // and none of block 1's required ones.
        let second = ['R', 'V', 'U', 'W', 'I', 'J', 'E'].iter().any(|&c| block.has(c));
        let first = ['H', 'Q', 'X', 'Z', 'L'].iter().any(|&c| block.has(c));
        if second && !first {
            return Err(err(
                block,
                None,
                ErrorKind::Missing {
                    what: "the first G75.1 block (X Z P Q H D A B L) before this one",
                    rule: "G75.1 always takes two blocks, note 3: 必须有两行 G75.1 代码",
                },
            ));
        }
        self.check_addresses(block, "G75.1 block 1", "GXZPQHDABLMST", "")?;
        let (Some(x0), Some(z0)) = (self.x, self.z) else {
            return Err(err(block, None, ErrorKind::PositionUnknown));
        };
        // Note 3: "凹槽起点（X，Z）忽略时，默认当前刀具位置为凹槽起点".
        let x = match block.get('X')? {
            Some(w) => self.length(block, w)?,
            None => x0,
        };
        let z = match block.get('Z')? {
            Some(w) => self.length(block, w)?,
            None => z0,
        };
        let p = Self::g75_required(block, 'P', "P(Δi) (radial peck)")?;
        let q = Self::g75_required(block, 'Q', "Q(Δk) (axial step)")?;
        let h = Self::g75_required(block, 'H', "H(h) (groove depth)")?;
        let d = Self::g75_required(block, 'D', "D(d) (bottom width)")?;
        // P and Q follow state parameter 182.7 like G76's (seed 001:
        // "可由状态参数 NO182.7 选择").
        let peck = self.pq_length(block, p)?;
        let step = self.pq_length(block, q)?;
        let depth = self.length(block, h)?;
        let width = self.length(block, d)?;
        let angle = |letter: char, default: u32| -> Result<u32, ProgramError> {
            match block.get(letter)? {
                Some(w) => self.g75_angle(block, w),
                None => Ok(default),
            }
        };
        Ok(G75Block1 {
            line: block.line,
            from: Point::new(x0, z0),
            start: Point::new(x, z),
            peck,
            step,
            depth,
            width,
            flank_a: angle('A', RIGHT_ANGLE)?,
            flank_b: angle('B', RIGHT_ANGLE)?,
            slope: angle('L', 0)?,
        })
    }

    /// G75.1 block 2: `R(e) V(Δv) U(Δu) W(Δw) I(r) J A(r1) B(r2) D(r3) E(r4)
    /// P(a)(b)(d)(e)` (seed 001).
    fn g75_block2<'a>(&mut self, first: G75Block1, block: Block<'a>) -> Result<G75Call<'a>, ProgramError> {
        self.check_addresses(&block, "G75.1 block 2", "GRVUWIJABDEPMST", "")?;
        let opt = |letter: char| -> Result<Option<i64>, ProgramError> {
            match block.get(letter)? {
                Some(w) => self.length(&block, w).map(Some),
                None => Ok(None),
            }
        };
        let retract = opt('R')?.unwrap_or(0);
        let layer = opt('V')?;
        let allowance_x = opt('U')?.unwrap_or(0);
        let allowance_z = opt('W')?.unwrap_or(0);
        // "输入负值时当成正值处理": a negative I is its magnitude.
        let tool_width = opt('I')?.map(i64::abs);
        let path = match block.get('J')? {
            None => PathType::Rough,
            Some(w) => match Self::count(&block, w, 0, 2)? {
                0 => PathType::Rough,
                1 => PathType::RoughAndFinish,
                _ => PathType::Finish,
            },
        };
        let kinds = self.g75_corner_kinds(&block)?;
        let mut corners = [Corner::SHARP; 4];
        for (i, letter) in ['A', 'B', 'D', 'E'].into_iter().enumerate() {
            corners[i] = Corner { size: opt(letter)?.unwrap_or(0), kind: kinds[i] };
        }
        let cycle = G75Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            from: first.from,
            start: first.start,
            peck: first.peck,
            step: first.step,
            depth: first.depth,
            width: first.width,
            flank_a: first.flank_a,
            flank_b: first.flank_b,
            slope: first.slope,
            retract,
            layer,
            allowance_x,
            allowance_z,
            tool_width,
            path,
            corners,
        };
        cycle.validate().map_err(|e| cycle_err(&block, Some(first.line), e))?;
        let restore = self.restore();
        // Step 10: the tool ends where it was before the cycle.
        self.moved = true;
        Ok(G75Call { block, params_line: first.line, cycle, restore })
    }

    /// Reading R-G75P: the digits of P(a)(b)(d)(e) are read from the right
    /// (e is the last digit), so leading zeros may be dropped (P11 rounds
    /// D and E); each digit is 0 (chamfer) or 1 (round); omitted: chamfers.
    fn g75_corner_kinds(&self, block: &Block<'_>) -> Result<[CornerKind; 4], ProgramError> {
        let mut kinds = [CornerKind::Chamfer; 4];
        let Some(p) = block.get('P')? else {
            return Ok(kinds);
        };
        let bad = || {
            err(
                block,
                Some(p),
                ErrorKind::OutOfRange { range: "P(a)(b)(d)(e): up to four digits, each 0 or 1".into() },
            )
        };
        if p.number().has_point() || p.number().negative {
            return Err(bad());
        }
        let digits = p.number().int_digits().as_bytes();
        if digits.len() > 4 || digits.iter().any(|&c| c != b'0' && c != b'1') {
            return Err(bad());
        }
        for (i, &c) in digits.iter().rev().enumerate() {
            kinds[3 - i] = if c == b'1' { CornerKind::Round } else { CornerKind::Chamfer };
        }
        Ok(kinds)
    }
}

/// G32's Q as a start angle, in the profile's unit (reading R-G32Q): the one
/// home of the rule, used by the program reader and by trace readers.
///
/// # Errors
///
/// A value outside 0..360°, finer than the unit, or a decimal point where
/// the profile forbids one.
pub fn q_word(
    machine: &Machine,
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
) -> Result<StartAngle, ProgramError> {
    let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
    let out = |range: &str| err(block, Some(w), ErrorKind::OutOfRange { range: range.into() });
    if w.number().negative {
        return Err(out("0..360 degrees"));
    }
    match machine.profile.q_unit(bit) {
        QUnit::Millidegrees { no_point } => {
            if no_point && w.number().has_point() {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::DecimalPointNotAllowed { rule: "Q of G32 is given in 0.001 degree" },
                ));
            }
            match w.number().integer() {
                Some(v) if (0..=360_000).contains(&v) => {
                    Ok(StartAngle::from_millidegrees(u64::try_from(v).unwrap_or(0)))
                }
                _ => Err(out("0..360000 thousandths of a degree, whole")),
            }
        }
        QUnit::Degrees { wrap } => {
            let d = w.number().decimal().ok_or_else(|| out("0..360 degrees"))?;
            let decimals = match units.system {
                cycleref::IncrementSystem::IsB => 3,
                cycleref::IncrementSystem::IsC => 4,
            };
            let ten_thousandths =
                d.checked_mul(Decimal::from(10_000)).ok_or_else(|| out("0..360 degrees"))?;
            if d.scale() > decimals || !ten_thousandths.fract().is_zero() {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::NotInIncrements {
                        increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
                    },
                ));
            }
            let mut t: u64 = u64::try_from(ten_thousandths.trunc()).map_err(|_| out("0..360 degrees"))?;
            if t > 3_600_000 {
                if wrap {
                    t %= 3_600_000;
                } else {
                    return Err(out("0..360 degrees"));
                }
            }
            // t / 10 thousandths of a degree, in lowest terms.
            Ok(if t % 10 == 0 {
                StartAngle::from_millidegrees(t / 10)
            } else {
                StartAngle { num: u32::try_from(t).unwrap_or(u32::MAX), den: 10 }
            })
        }
    }
}

/// G78's depth mode from its digit (980TDi P(m), 988TA D, parameters No.061
/// and 5145): 0 equal steps (等距离进刀), 1 decreasing (递减式进刀).
fn depth_mode(v: u32) -> DepthMode {
    if v == 0 {
        DepthMode::Equal
    } else {
        DepthMode::Decreasing
    }
}

/// Reading R-G32RUNOUT: the profile's rules for G32's modal J and K.
#[must_use]
pub fn resolve_g32_run_out(rules: G32Rules, j: Option<i64>, k: Option<i64>) -> G32RunOut {
    match (rules, j, k) {
        (G32Rules::NoRunOut, _, _) | (_, None | Some(0), _) => G32RunOut::None,
        // Seed 002: K omitted, or K = 0 with J != 0: K = J.
        (G32Rules::Gsk980, Some(j), None | Some(0)) => G32RunOut::Amounts { short: j, long: j.abs() },
        (G32Rules::Gsk980, Some(j), Some(k)) => G32RunOut::Amounts { short: j, long: k },
        // 988TA: K omitted: no long-axis run-out, J along the short axis.
        (G32Rules::Gsk988, Some(j), None | Some(0)) => G32RunOut::Amounts { short: j, long: 0 },
        (G32Rules::Gsk988, Some(j), Some(k)) => G32RunOut::Amounts { short: j, long: k },
    }
}

/// Reading R-RUNOUT: the profile's rules for J, K and r, turned into what
/// the cycle must do.
#[must_use]
pub fn resolve_run_out(rules: RunOutRules, j: Option<i64>, k: Option<i64>, r: u32, angle: u32) -> RunOut {
    let chamfer = |long: Option<i64>| {
        if r == 0 && long.is_none() {
            RunOut::None
        } else {
            RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long }
        }
    };
    match rules {
        RunOutRules::ChamferOnly => chamfer(None),
        RunOutRules::Gsk980 => match (j, k) {
            // Note 1: J and K omitted: by P(r) (or No.19).
            (None, None) => chamfer(None),
            // Note 2: J omitted, K != 0: J by P(r), K as given.
            (None, Some(k)) if k != 0 => {
                if r == 0 {
                    RunOut::None
                } else {
                    RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long: Some(k) }
                }
            }
            (None, Some(_)) => chamfer(None),
            // Note 4: J = 0: none.
            (Some(0), _) => RunOut::None,
            // Note 3: K omitted or K = 0 with J != 0: K = J.
            (Some(j), None | Some(0)) => RunOut::Amounts { short: j, long: j },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
        RunOutRules::Gsk988HighSpeed => match (j, k) {
            // As the normal mode: the chamfer of 5130 and 5131.
            (None, None) => chamfer(None),
            // "省略 K 时，长轴无退尾，短轴方向的退尾长度，固定为切削终点到起点的短轴轴向
            // 距离，与 J 是多少无关": the rapid retract to the X of A is all
            // there is (step (3)); J = 0 or K = 0 likewise.
            (_, None | Some(0)) | (Some(0), _) => RunOut::None,
            // "省略 J 时，长轴方向按 K 退尾": K along the long axis, the short
            // axis all the way to the X of A (J' is clamped there).
            (None, Some(k)) => RunOut::Amounts { short: MAX_LENGTH, long: k },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
        RunOutRules::Gsk988 => match (j, k) {
            // Seed 000: J and K omitted: by r and 5131, or 5130.
            (None, None) => chamfer(None),
            // G92 normal mode (note 9): J omitted: none.
            (None, Some(_)) | (Some(0), _) | (Some(_), Some(0)) => RunOut::None,
            // K omitted: no long-axis run-out, short axis by J.
            (Some(j), None) => RunOut::Amounts { short: j, long: 0 },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
    }
}
