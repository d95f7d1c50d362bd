//! The cycles, each defined in one module that implements [`CycleCall`],
//! and the one table that lists them ([`registry!`](crate::pipeline)'s
//! invocation in [`crate::pipeline`]).
//!
//! A cycle's module says everything a consumer needs to know about it:
//!
//! * what it is: its G code, its blocks, where it starts, its units and X
//!   mode, the modal state to restore after it;
//! * its moves by either engine ([`CycleCall::engine`],
//!   [`CycleCall::reference`]), every alarm raised before the first move;
//! * the annotations its moves carry and how the `nc` writer comments them
//!   ([`NcStyle`]), its `nc` heading ([`CycleCall::heading`]);
//! * its row of the `passes` tables ([`PassTable`]);
//! * the regions it cuts, for `check`'s split rapids ([`Region`], reading
//!   R-CHECKSPLIT);
//! * how `plot` draws it ([`Panel`]);
//! * the features the conformance vectors tag it with.
//!
//! Consumers (`expand`'s writers, `passes`, `check`, `plot`, `vectors`, C
//! and Python) go through [`Cycle`](crate::Cycle), whose methods forward to the
//! module of the cycle at hand; none of them matches on the kind of cycle.
//!
//! # Adding a cycle
//!
//! 1. Its typed cycle, engine and reference (in `cycleref` and in this
//!    crate), and its front end in the [reader](crate::reader): the
//!    [`Item`](crate::Item) variant it yields.
//! 2. A module here implementing [`CycleCall`].
//! 3. One line in the registry of [`crate::pipeline`].
//! 4. Its templates in the conformance vectors (`cli/src/vectors/`, one
//!    file per cycle: program generators are the corpus's, not the
//!    reference's), its tests and its readings.
//!
//! Nothing else: `expand`, `passes`, `check`, `plot`, `vectors`, C and
//! Python read the cycle through [`Cycle`](crate::Cycle). The C interface
//! names the cycle's code in its `CyclerefCycle` enumeration.
//!
//! `spec/tests/registry.rs` holds this list to the code: every item that
//! calls a cycle has a module here and a line in the registry, and every
//! cycle of the registry is expanded, tabulated, drawn and tagged from its
//! module; the vectors' unit tests hold that the templates call every
//! cycle of the registry.

use std::fmt;

use cycleref::{CycleError, Move, Point, Units, XMode};

use crate::lex::Block;
use crate::pipeline::Engine;
use crate::reader::Restore;
use crate::text::TextBuf;

/// The accessors of a call whose typed cycle, `self.cycle`, holds the
/// start point, units and X mode ([`CycleCall::start`],
/// [`CycleCall::units`], [`CycleCall::x_mode`]).
macro_rules! frame_of_cycle {
    () => {
        fn start(&self) -> cycleref::Point {
            self.cycle.start
        }

        fn units(&self) -> cycleref::Units {
            self.cycle.units
        }

        fn x_mode(&self) -> cycleref::XMode {
            self.cycle.x_mode
        }
    };
}

mod g32;
mod g75;
mod g76;
mod g92;
mod linuxcnc;

pub use g75::{count_plunges, GrooveHeading};
pub use g76::MultipassHeading;

/// The reference's moves of one cycle, boxed: a stream that can be cloned
/// whatever its type.
pub trait ReferenceMoves: Iterator<Item = Move> + Send + Sync {
    /// A copy of the stream, where it stands.
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

/// One cycle of a program, as its call was read: what every consumer needs
/// of it. Implemented once per cycle, in the cycle's module.
pub trait CycleCall<'a> {
    /// The fixed-point engine's moves.
    type EngineMoves: Iterator<Item = Move> + Clone + fmt::Debug;

    /// The G code, as the manuals write it (`G76`, `G78`, `G32`, `G33`,
    /// `G75.1`, `G92`).
    fn code(&self) -> &'static str;

    /// The block that runs the cycle (G76 and G75.1: block 2).
    fn block(&self) -> &Block<'a>;

    /// The line of the block 1 whose values the cycle uses, if any.
    fn params_line(&self) -> Option<usize> {
        None
    }

    /// True for the cycles of two blocks, whose block 1
    /// [`params_line`](CycleCall::params_line) names when it was written.
    fn has_params_block(&self) -> bool {
        false
    }

    /// The cycle's start point.
    fn start(&self) -> Point;

    /// Where the tool is before the cycle when that is not its start point.
    fn tool_before_start(&self) -> Option<Point> {
        None
    }

    /// The units of the cycle's lengths.
    fn units(&self) -> Units;

    /// The X mode of the cycle's lengths (and of its moves).
    fn x_mode(&self) -> XMode;

    /// The modal state to program after the cycle's moves.
    fn restore(&self) -> Restore {
        Restore::default()
    }

    /// The moves by the fixed-point engine.
    ///
    /// # Errors
    ///
    /// The cycle's alarm, before any move.
    fn engine(&self) -> Result<Self::EngineMoves, CycleError>;

    /// The moves by the exact-decimal reference.
    ///
    /// # Errors
    ///
    /// The cycle's alarm, before any move (the engine's).
    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError>;

    /// The number of rough passes the engine's moves counted before the
    /// first move, for the cycles that count them (G76, G78).
    fn rough_passes(_moves: &Self::EngineMoves) -> Option<u64> {
        None
    }

    /// The layers and plunges of a groove's roughing, for the cycles whose
    /// engine counts them before the first move (G75.1).
    fn layers_and_plunges(_moves: &Self::EngineMoves) -> Option<(u32, u64)> {
        None
    }

    /// The `nc` heading: the comment written before the cycle's moves,
    /// without its parentheses; `None` for a cycle without one (G32). Given
    /// the cycle's moves, which it may count on a copy.
    fn heading(&self, moves: &crate::pipeline::Moves) -> Option<Heading>;

    /// The annotations the cycle's moves carry beyond their role.
    fn annotations(&self) -> Annotations;

    /// How the `nc` writer writes the cycle's moves and comments them.
    fn nc_style(&self) -> NcStyle;

    /// The cycle's `passes` table.
    fn pass_table(&self) -> PassTable;

    /// True when the cycle's lead is not along the long axis that a G32
    /// block of its cut would take (reading R-G32LONG: by the
    /// displacements): a 988TA G92 or G78 under R-LONG988 `table` on a
    /// steep taper (|W| ≤ |i|, radius), whose lead is along Z while its cut,
    /// written as `G32 X… Z… F…`, would be read with the lead along X. Its
    /// moves are the cycle's; the nc output refuses it, since no G32 block
    /// says which axis the lead is on. False for the others.
    fn lead_off_g32_axis(&self) -> bool {
        false
    }

    /// The regions the cycle cuts (reading R-CHECKSPLIT), given its moves
    /// by the engine in use (which it may walk).
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    fn regions(&self, engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError>;

    /// The features the conformance vectors tag the cycle with, given its
    /// moves.
    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str));

    /// How `plot` draws the cycle, by the engine in use (which G75.1 asks
    /// for its programmed profile).
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    fn panel(&self, engine: Engine) -> Result<Panel, CycleError>;
}

/// An `nc` heading, as its cycle's module writes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Heading {
    /// `G76 line 4: 7 rough + 1 finish passes x 1 start`.
    Multipass(MultipassHeading),
    /// `G75.1 lines 3-4: J1 rough + finish, 2 layers, 9 plunges, tool width I3.000`.
    Groove(GrooveHeading),
    /// `G92 line 5: 1 pass x 2 starts`.
    SinglePass {
        /// The G code.
        code: &'static str,
        /// The line.
        line: usize,
        /// The number of starts.
        starts: u32,
    },
    /// `G76 line 6: LinuxCNC threading cycle`.
    Named {
        /// The G code.
        code: &'static str,
        /// The line.
        line: usize,
        /// What the cycle is.
        name: &'static str,
    },
}

/// Room for the text of any [`Heading`]: the longest, a G75.1's, has
/// four counts of at most 20 digits, a tool width of at most 62 bytes and
/// fewer than 90 other bytes.
pub const HEADING_BUF: usize = 256;

/// A count as [`TextBuf::integer`] takes it (a line number fits: `usize`
/// is at most 64 bits wide on the targets).
pub(crate) fn count(v: usize) -> u64 {
    u64::try_from(v).unwrap_or(u64::MAX)
}

impl Heading {
    /// The heading's text, built without `core::fmt` (issue 33: a heading
    /// a cycle, where `write!` cost more than the cycle's short moves).
    ///
    /// ```
    /// use cycleref::PathType;
    /// use cycleref_spec::cycles::{GrooveHeading, Heading};
    ///
    /// let groove = GrooveHeading {
    ///     params_line: 3,
    ///     line: 4,
    ///     path: PathType::RoughAndFinish,
    ///     layers: 2,
    ///     plunges: 9,
    ///     tool_width: None,
    /// };
    /// let text = Heading::Groove(groove).text();
    /// assert_eq!(text.as_str(), Some("G75.1 lines 3-4: J1 rough + finish, 2 layers, 9 plunges, tool pointed"));
    /// ```
    #[must_use]
    pub fn text(&self) -> TextBuf<HEADING_BUF> {
        let mut t = TextBuf::default();
        match self {
            Heading::Multipass(h) => h.put(&mut t),
            Heading::Groove(h) => h.put(&mut t),
            Heading::SinglePass { code, line, starts } => {
                // `G92 line 5: 1 pass x 2 starts`
                t.put(code.as_bytes());
                t.put(b" line ");
                t.integer(count(*line));
                t.put(b": 1 pass x ");
                t.integer(u64::from(*starts));
                t.put(if *starts == 1 { b" start" } else { b" starts" });
            }
            Heading::Named { code, line, name } => {
                // `G76 line 6: LinuxCNC threading cycle`
                t.put(code.as_bytes());
                t.put(b" line ");
                t.integer(count(*line));
                t.put(b": ");
                t.put(name.as_bytes());
            }
        }
        t
    }
}

impl fmt::Display for Heading {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.text().as_str().ok_or(fmt::Error)?)
    }
}

/// What a cycle's moves say of themselves beyond their role ([`Move::role`]
/// and [`Move::pass`]), for the consumers that report them (`check`'s
/// report names a move by them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Annotations {
    /// Each move's pass: its kind, number, start, depth, cut and flank (G76,
    /// G78).
    Passes,
    /// Each move's pass in LinuxCNC's terms: its number, depth and cut
    /// (LinuxCNC's G76).
    LinuxCncPasses,
    /// Each move's start of a multi-start thread (G92).
    Starts,
    /// The plunge of each peck in the role (G75.1).
    Plunges,
    /// The role only (G32, G33).
    Roles,
}

/// How the `nc` writer writes a cycle's moves: the words of its moves and
/// the comments it writes before them, from the annotations (pass, start,
/// plunge, role) the moves carry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NcStyle {
    /// The words of a move.
    pub words: MoveWords,
    /// The comment before the first move of each pass.
    pub passes: PassComment,
    /// A comment before the first move of each plunge (`(layer 1 plunge
    /// 2)`, G75.1).
    pub plunges: bool,
    /// A comment before the moves of each contour (`(rough contour)`,
    /// `(finishing contour)`, G75.1).
    pub contours: bool,
}

impl NcStyle {
    /// G75.1's style: its words, no pass comments, a comment before each
    /// plunge and each contour. A constant, so that the `nc` writer's loop
    /// for it is made with every question of the style answered (issue 33).
    pub const GROOVE: NcStyle =
        NcStyle { words: MoveWords::Groove, passes: PassComment::None, plunges: true, contours: true };
}

/// The words of a cycle's moves in the `nc` output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MoveWords {
    /// `G00`, `G01`, `G32 X Z F [Q]`, arcs with their centre in a comment.
    Fanuc,
    /// LinuxCNC's: `G0`, `G33 X Z K` (reading R-LCNC-SYNC).
    LinuxCnc,
    /// G75.1's: arcs with I and K from their start, Q in millidegrees.
    Groove,
}

/// The comment before each pass of a cycle's moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PassComment {
    /// None.
    None,
    /// `(rough 1 start 1 depth 1.800 cut 1.800)`, at each new pass or start.
    Full,
    /// `(pass 3)` or `(full depth 1)`, at each new pass.
    Numbered,
    /// `(start 2)` at each new start, when the cycle has more than one.
    Starts,
}

/// The `passes` table of a cycle: each cycle's own table, or a row of one
/// table shared by the consecutive cycles of the same kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PassTable {
    /// A table of the cycle's passes: a row per pass with its number, kind,
    /// start, flank, depth, cut and start point Bn.
    Passes,
    /// LinuxCNC's: a row per pass with the X of its cut and its Z span.
    LinuxCncPasses,
    /// G75.1's: a row per plunge, then the contours' cutting moves.
    Plunges,
    /// A row of the table of single-block threads headed `title`: the
    /// block's line, its synchronisation or start, where the cut starts
    /// and ends, and where the run-out ends.
    Row {
        /// The table's title (`G32 blocks`, `G92 blocks`).
        title: &'static str,
        /// The table's columns.
        columns: [&'static str; 8],
        /// The block's synchronisation (G32: the second column says
        /// whether the move waits for the spindle), or `None` for a row
        /// per start (G92: the second column is the start's number).
        sync: Option<bool>,
    },
}

/// How `plot` draws a cycle: the panel it is drawn on and what the panel
/// shows beside the cycle's moves. The moves themselves, their roles and
/// passes, are drawn from the stream as for every consumer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Panel {
    /// A panel of its own with the manual's points A, B, C and D and the
    /// path of each pass, coloured by depth (G76, G78).
    Passes(PassesPanel),
    /// One path on the panel shared by the program's blocks drawn with the
    /// same title (G32, G33, G92, LinuxCNC's G76): a thread cut in several
    /// blocks is read on one picture.
    Blocks(BlocksPanel),
    /// A panel of its own with the groove's programmed profile and its
    /// roughing region under the toolpath (G75.1).
    Groove(GroovePanel),
}

/// What a [`Panel::Passes`] shows beside the moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PassesPanel {
    /// The manual's points A (start), B (depth reference), C (thread
    /// start) and D (thread end), in increments, X as programmed.
    pub points: [Point; 4],
    /// +1 when the cut goes towards +Z, -1 otherwise (t).
    pub direction: i64,
    /// +1 for an external thread (A outside C), -1 for an internal one (s).
    pub side: i64,
    /// The number of starts L.
    pub starts: u32,
    /// The lead F, I or E (and K of an X-long thread).
    pub lead: cycleref::Lead,
}

/// Where a [`Panel::Blocks`] path is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BlocksPanel {
    /// The shared panel's title (`G32`, `G33`, `G92`, `G76 (LinuxCNC)`):
    /// the blocks of one title share one panel.
    pub title: &'static str,
    /// X drawn as a diameter whatever the block's X mode (doubled in G8),
    /// as `check` holds it on the `linuxcnc` profile (reading R-CHECKLCNC),
    /// so that a trace's marks fall on the path.
    pub x_as_diameter: bool,
    /// The legend's name of the moves whose role is
    /// [`Role::RunOut`](cycleref::Role::RunOut) (`run-out (J, K)`).
    pub run_out: &'static str,
    /// The legend's note on where the spindle synchronises (`each pass`).
    pub synchronises: &'static str,
    /// The legend's note on the block's own rapids (`A → B, retract,
    /// return to A`), or `None` for a block without rapids (G32).
    pub rapids: Option<&'static str>,
}

/// What a [`Panel::Groove`] shows beside the moves.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GroovePanel {
    /// The tool's width I, or `None` for a pointed tool.
    pub tool_width: Option<i64>,
    /// The direction along Z in which the tool's width lies from the point
    /// its moves follow: +1 when the groove's width D ≥ 0, -1 otherwise.
    pub width_direction: i64,
    /// The programmed profile: the finishing contour (J2) of the same
    /// groove for a pointed tool, by the same engine, from its start on the
    /// surface to its end; so that the drawing cannot disagree with the
    /// expansion.
    pub profile: Vec<Move>,
    /// The roughing region's outline ([`cycleref::groove_profile`]'s
    /// roughing vertices: R0, K1 and K2 (or Q1), K3 and K4 (or Q2), R3),
    /// absolute, without the tool width.
    pub roughing: Vec<Point>,
}

/// A region a cycle cuts, an open box in increments (X in the units the
/// trace is compared in, a diameter on diameter machines): its edges are
/// outside it (reading R-CHECKSPLIT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    /// The lowest X, outside.
    pub x_lo: i128,
    /// The highest X, outside.
    pub x_hi: i128,
    /// The lowest Z, outside.
    pub z_lo: i128,
    /// The highest Z, outside.
    pub z_hi: i128,
}

impl Region {
    /// The box that spans `points`; `None` for none.
    #[must_use]
    pub fn spanning(points: &[(i128, i128)]) -> Option<Region> {
        let (&(x0, z0), rest) = points.split_first()?;
        let mut r = Region { x_lo: x0, x_hi: x0, z_lo: z0, z_hi: z0 };
        for &(x, z) in rest {
            r.x_lo = r.x_lo.min(x);
            r.x_hi = r.x_hi.max(x);
            r.z_lo = r.z_lo.min(z);
            r.z_hi = r.z_hi.max(z);
        }
        Some(r)
    }

    /// The box with a dimension of no extent widened by one increment to
    /// each side (the cut line of a straight or face thread).
    #[must_use]
    pub fn widened_where_flat(mut self) -> Region {
        if self.x_lo == self.x_hi {
            self.x_lo -= 1;
            self.x_hi += 1;
        }
        if self.z_lo == self.z_hi {
            self.z_lo -= 1;
            self.z_hi += 1;
        }
        self
    }

    /// True when the straight path from `p` to `q` meets the open box. Only
    /// paths along one axis are decided (a split's legs are); a diagonal
    /// gives false.
    #[must_use]
    pub fn crossed_by(&self, p: Point, q: Point) -> bool {
        let (px, pz, qx, qz) = (i128::from(p.x), i128::from(p.z), i128::from(q.x), i128::from(q.z));
        if px == qx {
            self.x_lo < px && px < self.x_hi && pz.min(qz) < self.z_hi && pz.max(qz) > self.z_lo
        } else if pz == qz {
            self.z_lo < pz && pz < self.z_hi && px.min(qx) < self.x_hi && px.max(qx) > self.x_lo
        } else {
            false
        }
    }
}

/// Calls `f` with each move of `c` by `engine`, in order, in constant
/// memory.
fn for_each_move<'a, C: CycleCall<'a>>(
    c: &C,
    engine: Engine,
    mut f: impl FnMut(&Move),
) -> Result<(), CycleError> {
    match engine {
        Engine::Impl => c.engine()?.for_each(|m| f(&m)),
        Engine::Spec => c.reference()?.for_each(|m| f(&m)),
    }
    Ok(())
}
