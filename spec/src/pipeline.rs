//! One way to run a program: read it, and expand each of its cycles with a
//! chosen engine.
//!
//! Every consumer (the command's writers, `passes`, `plot`, `check`,
//! `vectors`, the C interface) goes through [`Cycle`] and [`expand`]: a new
//! cycle adds one variant here, one front end in the [reader](crate::reader),
//! one engine, one reference and one formatter entry, nothing else.
//!
//! Data flows one way: text → [`Reader`] → [`Item`] → [`Cycle`] →
//! [`expand`] → [`Moves`]. Nothing here holds more than one cycle: the
//! engine's moves are computed as they are taken; the reference model's
//! (exact decimals, written for clarity, not speed) are those of one cycle.

use std::fmt;

use cycleref::{
    CycleError, G32Moves, G75Moves, G76Moves, G92Moves, LinuxCncMoves, Move, Point, Units, XMode,
};

use crate::error::ProgramError;
use crate::profile::Machine;
use crate::reader::{G32Call, G75Call, G76Call, G92Call, Item, LinuxCncCall, Reader, Restore};

/// Which model expands the cycles. Both give the same moves, move by move.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Engine {
    /// The fixed-point engine of the `cycleref` crate: integers, no heap,
    /// moves computed one at a time.
    #[default]
    Impl,
    /// The exact-decimal reference model of this crate: the authority.
    Spec,
}

/// A cycle of a program, borrowed from the item the reader produced.
#[derive(Clone, Copy, Debug)]
pub enum Cycle<'r, 'a> {
    /// A G76 multiple thread-cutting cycle, or a G78 (its code in the call:
    /// the same cycle, another front end).
    G76(&'r G76Call<'a>),
    /// A G32 thread-cutting block.
    G32(&'r G32Call<'a>),
    /// A G75.1 groove cycle.
    G75(&'r G75Call<'a>),
    /// A G92 thread-cutting cycle block.
    G92(&'r G92Call<'a>),
    /// LinuxCNC's G76 (the `linuxcnc` profile).
    LinuxCnc(&'r LinuxCncCall<'a>),
}

impl<'r, 'a> Cycle<'r, 'a> {
    /// The cycle an item calls, if it calls one.
    #[must_use]
    pub fn of(item: &'r Item<'a>) -> Option<Cycle<'r, 'a>> {
        match item {
            Item::G76(c) => Some(Cycle::G76(c)),
            Item::G32(c) => Some(Cycle::G32(c)),
            Item::G75(c) => Some(Cycle::G75(c)),
            Item::G92(c) => Some(Cycle::G92(c)),
            Item::LinuxCncG76(c) => Some(Cycle::LinuxCnc(c)),
            Item::Source(_) | Item::Move(_) | Item::G76Params(_) | Item::G75Params(_) => None,
        }
    }

    /// The G code, as the manuals write it (`G76`, `G78`, `G32`, `G75.1`,
    /// `G92`).
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            Cycle::G76(c) => c.code.code(),
            Cycle::G32(c) => c.code,
            Cycle::G75(_) => "G75.1",
            Cycle::G92(_) => "G92",
            Cycle::LinuxCnc(_) => "G76",
        }
    }

    /// The line of the block that runs the cycle (G76 and G75.1: block 2).
    #[must_use]
    pub fn line(self) -> usize {
        match self {
            Cycle::G76(c) => c.block.line,
            Cycle::G32(c) => c.block.line,
            Cycle::G75(c) => c.block.line,
            Cycle::G92(c) => c.block.line,
            Cycle::LinuxCnc(c) => c.block.line,
        }
    }

    /// The line of the block 1 whose values the cycle uses (G76, G78 and
    /// G75.1), if any.
    #[must_use]
    pub fn params_line(self) -> Option<usize> {
        match self {
            Cycle::G76(c) => c.params_line,
            Cycle::G75(c) => Some(c.params_line),
            Cycle::G32(_) | Cycle::G92(_) | Cycle::LinuxCnc(_) => None,
        }
    }

    /// True for the cycles of two blocks (G76 and G78 of the FANUC-style
    /// profiles, G75.1), whose block 1 [`params_line`](Cycle::params_line)
    /// names (a G76 whose block 1 came from the parameters has none).
    #[must_use]
    pub fn has_params_block(self) -> bool {
        matches!(self, Cycle::G76(_) | Cycle::G75(_))
    }

    /// The cycle's start point (A of G76, G78 and G92; the G32 block's
    /// start; A of G75.1).
    #[must_use]
    pub fn start(self) -> Point {
        match self {
            Cycle::G76(c) => c.cycle.start,
            Cycle::G32(c) => c.g32.start,
            Cycle::G75(c) => c.cycle.start,
            Cycle::G92(c) => c.cycle.start,
            Cycle::LinuxCnc(c) => c.cycle.start,
        }
    }

    /// Where the tool is before the cycle when that is not its start
    /// point: G75.1's S, from which it rapids to A. `None` for the others,
    /// which start where the tool is.
    #[must_use]
    pub fn tool_before_start(self) -> Option<Point> {
        match self {
            Cycle::G75(c) => Some(c.cycle.from),
            Cycle::G76(_) | Cycle::G32(_) | Cycle::G92(_) | Cycle::LinuxCnc(_) => None,
        }
    }

    /// The line of the block that carries the word an alarm is about
    /// (reading R-ERRLINE): block 1's for a value written in block 1 (G76's
    /// P(m)(r)(a), Q(Δdmin), R(d), L, E; G75.1's X Z P Q H D A B L), else
    /// the line of the block that runs the cycle.
    #[must_use]
    pub fn line_of(self, error: &CycleError) -> usize {
        match (error.field(), self.params_line()) {
            (Some(field), Some(line)) if field.in_block_1() => line,
            _ => self.line(),
        }
    }

    /// The units of the cycle's lengths.
    #[must_use]
    pub fn units(self) -> Units {
        match self {
            Cycle::G76(c) => c.cycle.units,
            Cycle::G32(c) => c.g32.units,
            Cycle::G75(c) => c.cycle.units,
            Cycle::G92(c) => c.cycle.units,
            Cycle::LinuxCnc(c) => c.cycle.units,
        }
    }

    /// The X mode of the cycle's lengths (and of its moves).
    #[must_use]
    pub fn x_mode(self) -> XMode {
        match self {
            Cycle::G76(c) => c.cycle.x_mode,
            Cycle::G32(c) => c.g32.x_mode,
            Cycle::G75(c) => c.cycle.x_mode,
            Cycle::G92(c) => c.cycle.x_mode,
            Cycle::LinuxCnc(c) => c.cycle.x_mode,
        }
    }

    /// Where the tool is when the cycle starts.
    #[must_use]
    pub fn from(self) -> Point {
        match self {
            Cycle::G76(c) => c.cycle.start,
            Cycle::G32(c) => c.g32.start,
            Cycle::G75(c) => c.cycle.from,
            Cycle::G92(c) => c.cycle.start,
            Cycle::LinuxCnc(c) => c.cycle.start,
        }
    }

    /// The modal state to program after the cycle's moves (G76 and G75.1
    /// are one-shot codes whose expansion ends in G00).
    #[must_use]
    pub fn restore(self) -> Restore {
        match self {
            Cycle::G76(c) => c.restore,
            Cycle::G75(c) => c.restore,
            // G32 and G92 are modal: the mode in force is theirs, and every
            // G92 block is expanded (reading R-G92MODAL). LinuxCNC's G76 is
            // modal too, but a later block that would repeat it is refused
            // by the reader (its words are needed again), so the expansion's
            // G0 is what the following blocks see.
            Cycle::G32(_) | Cycle::G92(_) | Cycle::LinuxCnc(_) => Restore::default(),
        }
    }
}

/// The moves of one cycle, in order.
#[derive(Clone, Debug)]
pub struct Moves(Inner);

// Unboxed on purpose: one cycle's iterator lives on the stack, taken move by
// move in the hot loop (G75.1's, the largest, is boxed).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
enum Inner {
    G76(G76Moves),
    G32(G32Moves),
    G75(Box<G75Moves>),
    G92(G92Moves),
    LinuxCnc(LinuxCncMoves),
    /// The exact-decimal reference: a pass at a time (G76, G78, G92) or
    /// the cycle's moves held (G32, G75.1, LinuxCNC's G76).
    Reference(Box<dyn ReferenceMoves>),
}

/// The reference's moves, boxed: a stream that can be cloned (as every
/// [`Moves`] can) whatever its type.
trait ReferenceMoves: Iterator<Item = Move> + Send + Sync {
    fn boxed_clone(&self) -> Box<dyn ReferenceMoves>;
}

impl<T: Iterator<Item = Move> + Clone + Send + Sync + 'static> ReferenceMoves for T {
    fn boxed_clone(&self) -> Box<dyn ReferenceMoves> {
        Box::new(self.clone())
    }
}

impl Clone for Box<dyn ReferenceMoves> {
    fn clone(&self) -> Self {
        // The stream inside the box: `self.boxed_clone()` would find the
        // box itself (it is a `ReferenceMoves` too) and recurse.
        (**self).boxed_clone()
    }
}

impl fmt::Debug for dyn ReferenceMoves {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ReferenceMoves")
    }
}

impl Iterator for Moves {
    type Item = Move;

    #[inline]
    fn next(&mut self) -> Option<Move> {
        match &mut self.0 {
            Inner::G76(m) => m.next(),
            Inner::G32(m) => m.next(),
            Inner::G75(m) => m.next(),
            Inner::G92(m) => m.next(),
            Inner::LinuxCnc(m) => m.next(),
            Inner::Reference(m) => m.next(),
        }
    }
}

impl Moves {
    /// The number of rough passes of a G76 or G78 cycle (reading R-LIMIT),
    /// when the engine counted them before its first move (the fixed-point
    /// engine does); `None` for the other cycles and for the reference,
    /// whose count [`cycleref::engine::rough_pass_count`] gives.
    #[must_use]
    pub fn rough_passes(&self) -> Option<u64> {
        match &self.0 {
            Inner::G76(m) => Some(m.rough_passes()),
            _ => None,
        }
    }
}

/// The moves of `cycle` by `engine`.
///
/// Every alarm is raised here, before the first move: taking the moves
/// cannot fail.
///
/// # Errors
///
/// The cycle's alarm ([`CycleError`]); both engines raise the same one.
///
/// ```
/// use cycleref_spec::pipeline::{expand, Cycle, Engine};
/// use cycleref_spec::{read, Machine, ProfileName};
///
/// let text = "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
/// let program = read(text, &Machine::new(ProfileName::Gsk988))?;
/// let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
/// let ours: Vec<_> = expand(cycle, Engine::Impl)?.collect();
/// let reference: Vec<_> = expand(cycle, Engine::Spec)?.collect();
/// assert_eq!(ours, reference);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn expand(cycle: Cycle<'_, '_>, engine: Engine) -> Result<Moves, CycleError> {
    let inner = match (engine, cycle) {
        (Engine::Impl, Cycle::G76(c)) => Inner::G76(cycleref::expand_g76(&c.cycle)?),
        (Engine::Impl, Cycle::G32(c)) => Inner::G32(cycleref::expand_g32(&c.g32)?),
        (Engine::Impl, Cycle::G75(c)) => Inner::G75(Box::new(cycleref::expand_g75(&c.cycle)?)),
        (Engine::Impl, Cycle::G92(c)) => Inner::G92(cycleref::expand_g92(&c.cycle)?),
        (Engine::Spec, Cycle::G76(c)) => Inner::Reference(Box::new(crate::g76::moves(&c.cycle)?)),
        (Engine::Spec, Cycle::G32(c)) => Inner::Reference(Box::new(crate::g32::expand(&c.g32)?.into_iter())),
        (Engine::Spec, Cycle::G75(c)) => Inner::Reference(Box::new(crate::g75::moves(&c.cycle)?)),
        (Engine::Spec, Cycle::G92(c)) => Inner::Reference(Box::new(crate::g92::moves(&c.cycle)?)),
        (Engine::Impl, Cycle::LinuxCnc(c)) => Inner::LinuxCnc(cycleref::expand_linuxcnc(&c.cycle)?),
        (Engine::Spec, Cycle::LinuxCnc(c)) => Inner::Reference(Box::new(crate::linuxcnc::moves(&c.cycle)?)),
    };
    Ok(Moves(inner))
}

/// Why a program cannot be expanded: the reader refused a block, or a
/// cycle raised its alarm.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RunError {
    /// The reader's error (its line, word and rule).
    Program(ProgramError),
    /// A cycle's alarm while it was expanded.
    Cycle {
        /// The line of the block that runs the cycle.
        line: usize,
        /// The cycle's G code.
        code: &'static str,
        /// The alarm.
        error: CycleError,
    },
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Program(e) => write!(f, "{e}"),
            RunError::Cycle { line, code, error } => write!(f, "line {line}, {code}: {error}"),
        }
    }
}

impl RunError {
    /// The stable kind of the error ([`crate::ErrorKind::stable_kind`]): the
    /// reader's, or `cycle:` and the alarm's name.
    #[must_use]
    pub fn stable_kind(&self) -> String {
        match self {
            RunError::Program(e) => e.kind.stable_kind(),
            RunError::Cycle { error, .. } => format!("cycle:{}", error.name()),
        }
    }
}

impl std::error::Error for RunError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RunError::Program(e) => Some(e),
            RunError::Cycle { error, .. } => Some(error),
        }
    }
}

impl From<ProgramError> for RunError {
    fn from(e: ProgramError) -> RunError {
        RunError::Program(e)
    }
}

/// The moves of `cycle` by `engine`, its alarm named with its line.
///
/// # Errors
///
/// [`RunError::Cycle`].
pub fn expand_at(cycle: Cycle<'_, '_>, engine: Engine) -> Result<Moves, RunError> {
    expand(cycle, engine).map_err(|error| RunError::Cycle {
        line: cycle.line_of(&error),
        code: cycle.code(),
        error,
    })
}

/// What the first phase learnt of a program that reads and expands
/// without error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Summary {
    /// The units in force for the cycles.
    pub units: Units,
    /// The number of items (blocks and cycles).
    pub items: usize,
    /// The number of cycles.
    pub cycles: usize,
    /// The number of G76 cycles.
    pub g76: usize,
    /// The number of G32 blocks.
    pub g32: usize,
    /// The number of G75.1 cycles.
    pub g75: usize,
    /// The number of G92 blocks.
    pub g92: usize,
    /// The number of LinuxCNC G76 cycles.
    pub linuxcnc: usize,
}

/// The first phase of a run (reading R-STREAM): reads every item of
/// `source` and expands every cycle with `engine`, keeping nothing but
/// counts, so that the second phase can stream its output knowing that no
/// error will interrupt it.
///
/// # Errors
///
/// The first error in program order.
pub fn validate(source: &[u8], machine: &Machine, engine: Engine) -> Result<Summary, RunError> {
    let mut reader = Reader::new(source, machine);
    let mut validation = Validation::new(engine);
    for item in reader.by_ref() {
        validation.item(&item?)?;
    }
    Ok(validation.summary(reader.units()))
}

/// The first phase of a run fed one item at a time, for a program read in
/// pieces ([`LineReader`](crate::reader::LineReader)); [`validate`] for a
/// program in memory.
#[derive(Clone, Copy, Debug)]
pub struct Validation {
    engine: Engine,
    items: usize,
    /// Cycles by kind: G76, G32, G75.1, G92, LinuxCNC G76.
    cycles: [usize; 5],
}

impl Validation {
    /// Nothing checked yet; cycles will be expanded with `engine`.
    #[must_use]
    pub fn new(engine: Engine) -> Validation {
        Validation { engine, items: 0, cycles: [0; 5] }
    }

    /// Checks the next item of the program.
    ///
    /// # Errors
    ///
    /// The alarm of the cycle the item calls, with its line.
    pub fn item(&mut self, item: &Item<'_>) -> Result<(), RunError> {
        self.items += 1;
        if let Some(cycle) = Cycle::of(item) {
            self.cycles[match cycle {
                Cycle::G76(_) => 0,
                Cycle::G32(_) => 1,
                Cycle::G75(_) => 2,
                Cycle::G92(_) => 3,
                Cycle::LinuxCnc(_) => 4,
            }] += 1;
            // Every alarm is raised before the first move: the moves are
            // not taken.
            expand_at(cycle, self.engine)?;
        }
        Ok(())
    }

    /// What was learnt, with the `units` the reader ended with.
    #[must_use]
    pub fn summary(&self, units: Units) -> Summary {
        let [g76, g32, g75, g92, linuxcnc] = self.cycles;
        Summary {
            units,
            items: self.items,
            cycles: g76 + g32 + g75 + g92 + linuxcnc,
            g76,
            g32,
            g75,
            g92,
            linuxcnc,
        }
    }
}
