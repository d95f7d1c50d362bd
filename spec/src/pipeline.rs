//! One way to run a program: read it, and expand each of its cycles with a
//! chosen engine.
//!
//! Every consumer (the command's writers, `passes`, `plot`, `check`,
//! `vectors`, the C interface, Python) goes through [`Cycle`] and
//! [`expand`]. A cycle is defined in one module of [`crate::cycles`] and
//! registered by one line of the `registry!` table below, which makes
//! [`Cycle`], its forwarding methods and [`Moves`]; what else adding a cycle
//! takes is listed in [`crate::cycles`].
//!
//! Data flows one way: text → [`Reader`] → [`Item`] → [`Cycle`] →
//! [`expand`] → [`Moves`]. Nothing here holds more than one cycle: the
//! engine's moves are computed as they are taken; the reference model's
//! (exact decimals, written for clarity, not speed) are those of one cycle.

use std::fmt;

use cycleref::{
    CycleError, G32Moves, G75Moves, G76Moves, G92Moves, LinuxCncMoves, Move, Point, Units, XMode,
};

use crate::cycles::{Annotations, CycleCall, Heading, NcStyle, Panel, PassTable, ReferenceMoves, Region};
use crate::lex::Block;

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

/// The registry: one line per cycle, `Variant: Item::Variant(Call) =>
/// EngineMoves`. It makes [`Cycle`] (the cycle an [`Item`] calls), its
/// methods, each forwarding to the cycle's module in [`crate::cycles`],
/// and [`Moves`] (the stream of either engine).
macro_rules! registry {
    ($($(#[$doc:meta])* $variant:ident: $item:ident($call:ident) => $engine:ty;)*) => {
        /// A cycle of a program, borrowed from the item the reader
        /// produced. Its methods are those of [`CycleCall`], implemented
        /// in the cycle's module of [`crate::cycles`].
        #[derive(Clone, Copy, Debug)]
        pub enum Cycle<'r, 'a> {
            $($(#[$doc])* $variant(&'r $call<'a>),)*
        }

        /// A cycle of a program detached from the text it was read from
        /// ([`Cycle::detached`]): kept after the reader has moved on.
        #[derive(Clone, Debug)]
        pub enum OwnedCycle {
            $($(#[$doc])* $variant($call<'static>),)*
        }

        impl OwnedCycle {
            /// The cycle, to expand or ask.
            #[must_use]
            pub fn cycle(&self) -> Cycle<'_, 'static> {
                match self {
                    $(OwnedCycle::$variant(c) => Cycle::$variant(c),)*
                }
            }
        }

        /// The number of cycles in the registry.
        pub const CYCLE_KINDS: usize = [$(stringify!($variant)),*].len();

        impl<'r, 'a> Cycle<'r, 'a> {
            /// The cycle an item calls, if it calls one.
            #[must_use]
            pub fn of(item: &'r Item<'a>) -> Option<Cycle<'r, 'a>> {
                match item {
                    $(Item::$item(c) => Some(Cycle::$variant(c)),)*
                    _ => None,
                }
            }

            /// The cycle detached from the text it was read from (its
            /// block's text copied).
            #[must_use]
            pub fn detached(self) -> OwnedCycle {
                match self {
                    $(Cycle::$variant(c) => OwnedCycle::$variant(c.detached()),)*
                }
            }

            /// The cycle's place in the registry, `0..CYCLE_KINDS`.
            #[must_use]
            pub fn index(self) -> usize {
                let mut i = 0;
                $(
                    if let Cycle::$variant(_) = self {
                        return i;
                    }
                    i += 1;
                )*
                i
            }

            /// The moves of the cycle by `engine`.
            fn moves(self, engine: Engine) -> Result<Moves, CycleError> {
                Ok(Moves(match (self, engine) {
                    $(
                        (Cycle::$variant(c), Engine::Impl) => Inner::$variant(c.engine()?),
                        (Cycle::$variant(c), Engine::Spec) => Inner::Reference(c.reference()?),
                    )*
                }))
            }

            /// The `nc` heading ([`CycleCall::heading`]).
            #[must_use]
            pub fn heading(self, moves: &Moves) -> Option<Heading> {
                match self {
                    $(Cycle::$variant(c) => c.heading(moves),)*
                }
            }

            /// The regions the cycle cuts, for `check` ([`CycleCall::regions`]).
            ///
            /// # Errors
            ///
            /// The cycle's alarm.
            pub fn regions(self, engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
                match self {
                    $(Cycle::$variant(c) => c.regions(engine, out),)*
                }
            }

            /// The features the conformance vectors tag the cycle with
            /// ([`CycleCall::tags`]).
            pub fn tags(self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
                match self {
                    $(Cycle::$variant(c) => c.tags(moves, tag),)*
                }
            }

            /// How `plot` draws the cycle ([`CycleCall::panel`]).
            ///
            /// # Errors
            ///
            /// The cycle's alarm.
            pub fn panel(self, engine: Engine) -> Result<Panel, CycleError> {
                match self {
                    $(Cycle::$variant(c) => c.panel(engine),)*
                }
            }

            registry!(@forward [$($variant)*]
                /// The G code, as the manuals write it (`G76`, `G78`, `G32`,
                /// `G33`, `G75.1`, `G92`).
                code -> &'static str;
                /// The block that runs the cycle (G76 and G75.1: block 2).
                block -> &'r Block<'a>;
                /// The line of the block 1 whose values the cycle uses (G76,
                /// G78 and G75.1), if any.
                params_line -> Option<usize>;
                /// True for the cycles of two blocks (G76 and G78 of the
                /// FANUC-style profiles, G75.1), whose block 1
                /// [`params_line`](Cycle::params_line) names (a G76 whose
                /// block 1 came from the parameters has none).
                has_params_block -> bool;
                /// The cycle's start point (A of G76, G78 and G92; the G32
                /// block's start; A of G75.1).
                start -> Point;
                /// Where the tool is before the cycle when that is not its
                /// start point: G75.1's S, from which it rapids to A. `None`
                /// for the others, which start where the tool is.
                tool_before_start -> Option<Point>;
                /// The units of the cycle's lengths.
                units -> Units;
                /// The X mode of the cycle's lengths (and of its moves).
                x_mode -> XMode;
                /// The modal state to program after the cycle's moves (G76
                /// and G75.1 are one-shot codes whose expansion ends in G00).
                restore -> Restore;
                /// The annotations the cycle's moves carry.
                annotations -> Annotations;
                /// How the `nc` writer writes the cycle's moves.
                nc_style -> NcStyle;
                /// The cycle's `passes` table.
                pass_table -> PassTable;
                /// True when the cycle's lead is not along the long axis a
                /// G32 block of its cut would take
                /// ([`CycleCall::lead_off_g32_axis`]): the nc output refuses it.
                lead_off_g32_axis -> bool;
            );
        }

        // Unboxed on purpose: one cycle's iterator lives on the stack,
        // taken move by move in the hot loop (G75.1's, the largest, is
        // boxed).
        #[allow(clippy::large_enum_variant)]
        #[derive(Clone, Debug)]
        enum Inner {
            $($variant($engine),)*
            /// The exact-decimal reference: a pass at a time (G76, G78,
            /// G92) or the cycle's moves held (G32, G75.1, LinuxCNC's G76).
            Reference(Box<dyn ReferenceMoves>),
        }

        impl Iterator for Moves {
            type Item = Move;

            #[inline]
            fn next(&mut self) -> Option<Move> {
                match &mut self.0 {
                    $(Inner::$variant(m) => m.next(),)*
                    Inner::Reference(m) => m.next(),
                }
            }
        }

        impl Moves {
            /// Calls `f` with each move, in order, until it fails: the
            /// moves the iterator gives, the engine chosen once for the
            /// cycle instead of once a move (the nc writer's loop: the
            /// engine's own `next` inlined into it, no match and no copy
            /// of the move through an `Option` per move; issue 33).
            ///
            /// ```
            /// use cycleref_spec::pipeline::{expand, Cycle, Engine};
            /// use cycleref_spec::{read, Machine, ProfileName};
            ///
            /// let text = "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
            /// let program = read(text, &Machine::new(ProfileName::Gsk988))?;
            /// let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
            /// let mut taken = Vec::new();
            /// expand(cycle, Engine::Impl)?.try_for_each_move(|m| {
            ///     taken.push(m);
            ///     Ok::<(), ()>(())
            /// }).expect("no error");
            /// assert_eq!(taken, expand(cycle, Engine::Impl)?.collect::<Vec<_>>());
            /// // The first error stops the walk.
            /// let mut seen = 0;
            /// let stopped = expand(cycle, Engine::Impl)?.try_for_each_move(|_| {
            ///     seen += 1;
            ///     if seen == 3 { Err("stop") } else { Ok(()) }
            /// });
            /// assert_eq!((stopped, seen), (Err("stop"), 3));
            /// # Ok::<(), Box<dyn std::error::Error>>(())
            /// ```
            ///
            /// # Errors
            ///
            /// The first error `f` returns.
            #[inline]
            pub fn try_for_each_move<E>(self, mut f: impl FnMut(Move) -> Result<(), E>) -> Result<(), E> {
                match self.0 {
                    $(Inner::$variant(m) => m.walk(&mut f)?,)*
                    Inner::Reference(m) => {
                        for x in m {
                            f(x)?;
                        }
                    }
                }
                Ok(())
            }

            /// The number of rough passes of a G76 or G78 cycle (reading
            /// R-LIMIT), when the engine counted them before its first move
            /// (the fixed-point engine does); `None` for the other cycles
            /// and for the reference, whose count
            /// [`cycleref::engine::rough_pass_count`] gives.
            #[must_use]
            pub fn rough_passes(&self) -> Option<u64> {
                match &self.0 {
                    $(Inner::$variant(m) => <$call<'_> as CycleCall<'_>>::rough_passes(m),)*
                    Inner::Reference(_) => None,
                }
            }

            /// The layers and plunges of a G75.1 cycle's roughing, when the
            /// engine counted them before its first move (the fixed-point
            /// engine does); `None` for the other cycles and for the
            /// reference.
            #[must_use]
            pub fn layers_and_plunges(&self) -> Option<(u32, u64)> {
                match &self.0 {
                    $(Inner::$variant(m) => <$call<'_> as CycleCall<'_>>::layers_and_plunges(m),)*
                    Inner::Reference(_) => None,
                }
            }
        }
    };
    (@forward [$($variant:ident)*]) => {};
    (@forward [$($variant:ident)*] $(#[$doc:meta])* $name:ident -> $ty:ty; $($rest:tt)*) => {
        $(#[$doc])*
        #[must_use]
        pub fn $name(self) -> $ty {
            match self {
                $(Cycle::$variant(c) => c.$name(),)*
            }
        }
        registry!(@forward [$($variant)*] $($rest)*);
    };
}

registry! {
    /// A G76 multiple thread-cutting cycle, or a G78 (its code in the
    /// call: the same cycle, another front end).
    G76: G76(G76Call) => G76Moves;
    /// A G32 thread-cutting block (or LinuxCNC's G33).
    G32: G32(G32Call) => G32Moves;
    /// A G75.1 groove cycle.
    G75: G75(G75Call) => Box<G75Moves>;
    /// A G92 thread-cutting cycle block.
    G92: G92(G92Call) => G92Moves;
    /// LinuxCNC's G76 (the `linuxcnc` profile).
    LinuxCnc: LinuxCncG76(LinuxCncCall) => LinuxCncMoves;
}

impl Cycle<'_, '_> {
    /// The line of the block that runs the cycle (G76 and G75.1: block 2).
    #[must_use]
    pub fn line(self) -> usize {
        self.block().line
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

    /// Where the tool is when the cycle starts.
    #[must_use]
    pub fn from(self) -> Point {
        self.tool_before_start().unwrap_or(self.start())
    }
}

/// The moves of one cycle, in order.
#[derive(Clone, Debug)]
pub struct Moves(Inner);

/// How [`Moves::try_for_each_move`] takes an engine's moves: by its
/// iterator, or by the engine's own loop where it has one (G75.1's
/// [`G75Moves::try_for_each_move`], the same moves).
trait Walk: Iterator<Item = Move> + Sized {
    /// Calls `f` with each move until it fails.
    #[inline]
    fn walk<E>(self, f: &mut impl FnMut(Move) -> Result<(), E>) -> Result<(), E> {
        for x in self {
            f(x)?;
        }
        Ok(())
    }
}

impl Walk for G76Moves {}
impl Walk for G32Moves {}
impl Walk for G92Moves {}
impl Walk for LinuxCncMoves {}

impl Walk for Box<G75Moves> {
    #[inline]
    fn walk<E>(mut self, f: &mut impl FnMut(Move) -> Result<(), E>) -> Result<(), E> {
        self.try_for_each_move(f)
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
    cycle.moves(engine)
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
    expand(cycle, engine).map_err(|error| at(cycle, error))
}

/// `error`, the alarm of `cycle`, named with its line.
fn at(cycle: Cycle<'_, '_>, error: CycleError) -> RunError {
    RunError::Cycle { line: cycle.line_of(&error), code: cycle.code(), error }
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
    /// The line and G code of the first cycle whose lead is not along the
    /// long axis a G32 block of its moves would take
    /// ([`Cycle::lead_off_g32_axis`]): such a program cannot be written as
    /// plain blocks (reading R-LONG988).
    pub lead_off_g32_axis: Option<(usize, &'static str)>,
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
    cycles: [usize; CYCLE_KINDS],
    /// [`Summary::lead_off_g32_axis`].
    lead_off_g32_axis: Option<(usize, &'static str)>,
}

impl Validation {
    /// Nothing checked yet; cycles will be expanded with `engine`.
    #[must_use]
    pub fn new(engine: Engine) -> Validation {
        Validation { engine, items: 0, cycles: [0; CYCLE_KINDS], lead_off_g32_axis: None }
    }

    /// Checks the next item of the program.
    ///
    /// # Errors
    ///
    /// The alarm of the cycle the item calls, with its line.
    pub fn item(&mut self, item: &Item<'_>) -> Result<(), RunError> {
        self.items += 1;
        if let Some(cycle) = Cycle::of(item) {
            self.cycles[cycle.index()] += 1;
            // Every alarm is raised before the first move: the moves are
            // not taken (a G75.1, G76 or G78 by the engine is only
            // checked, issue 33).
            match (cycle, self.engine) {
                (Cycle::G75(c), Engine::Impl) => c.check_engine().map_err(|error| at(cycle, error))?,
                (Cycle::G76(c), Engine::Impl) => c.check_engine().map_err(|error| at(cycle, error))?,
                _ => drop(expand_at(cycle, self.engine)?),
            }
            if self.lead_off_g32_axis.is_none() && cycle.lead_off_g32_axis() {
                self.lead_off_g32_axis = Some((cycle.line(), cycle.code()));
            }
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
            lead_off_g32_axis: self.lead_off_g32_axis,
        }
    }
}
