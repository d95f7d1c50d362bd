//! Errors of the cycle engines: the manual's alarm conditions.
//!
//! Both engines return these same values for the same cycle, so a caller can
//! compare them with `==`.

use core::fmt;

use crate::units::Length;

/// A cycle parameter, named by its manual letter in messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// X of the start point A.
    StartX,
    /// Z of the start point A.
    StartZ,
    /// X(U) of block 2: the thread end D.
    EndX,
    /// Z(W) of block 2: the thread end D.
    EndZ,
    /// R(i) of block 2.
    Taper,
    /// P(k) of block 2.
    ThreadHeight,
    /// Q(Δd) of block 2.
    FirstDepth,
    /// Q(Δdmin) of block 1.
    MinCut,
    /// R(d) of block 1.
    FinishingAllowance,
    /// P(m) of block 1.
    FinishingPasses,
    /// P(r) of block 1 or its parameter.
    Chamfer,
    /// Chamfer angle parameter (5131).
    ChamferAngle,
    /// P(a) of block 1.
    ToolAngle,
    /// E of block 1.
    LeadIn,
    /// L of block 1.
    Starts,
    /// J.
    RunOutShort,
    /// K.
    RunOutLong,
    /// A computed coordinate of a pass.
    PassCoordinate,
    /// X of the G75.1 groove start point S.
    GrooveStartX,
    /// Z of the G75.1 groove start point S.
    GrooveStartZ,
    /// X of the tool position before a G75.1 cycle.
    GrooveFromX,
    /// Z of the tool position before a G75.1 cycle.
    GrooveFromZ,
    /// P(Δi) of G75.1 block 1.
    Peck,
    /// Q(Δk) of G75.1 block 1.
    Step,
    /// H(h) of G75.1 block 1.
    GrooveDepth,
    /// D(d) of G75.1 block 1.
    BottomWidth,
    /// A(∠a) of G75.1 block 1.
    FlankA,
    /// B(∠b) of G75.1 block 1.
    FlankB,
    /// L(∠p) of G75.1 block 1.
    Slope,
    /// R(e) of G75.1 block 2.
    Retract,
    /// V(Δv) of G75.1 block 2.
    LayerDepth,
    /// U(Δu) of G75.1 block 2.
    AllowanceX,
    /// W(Δw) of G75.1 block 2.
    AllowanceZ,
    /// I(r) of G75.1 block 2.
    ToolWidth,
    /// A(r1) of G75.1 block 2.
    CornerR1,
    /// B(r2) of G75.1 block 2.
    CornerR2,
    /// D(r3) of G75.1 block 2.
    CornerR3,
    /// E(r4) of G75.1 block 2.
    CornerR4,
    /// LinuxCNC G76 P: the thread pitch.
    Pitch,
    /// LinuxCNC G76 I: the thread peak offset from the drive line.
    PeakOffset,
    /// LinuxCNC G76 J: the initial cut depth.
    InitialDepth,
    /// LinuxCNC G76 K: the full thread depth.
    FullDepth,
    /// LinuxCNC G76 R: the depth degression.
    Degression,
    /// LinuxCNC G76 Q: the compound slide angle.
    CompoundAngle,
    /// LinuxCNC G76 E: the taper distance.
    TaperDistance,
    /// LinuxCNC G76 H: the spring passes.
    SpringPasses,
}

impl Field {
    /// True for a value written in a cycle's block 1: G76's and G78's
    /// P(m)(r)(a), Q(Δdmin), R(d), E and L; G75.1's X, Z, P, Q, H, D, A, B
    /// and L. An alarm about it names block 1's line (reading R-ERRLINE).
    #[must_use]
    pub const fn in_block_1(self) -> bool {
        matches!(
            self,
            Field::MinCut
                | Field::FinishingAllowance
                | Field::FinishingPasses
                | Field::Chamfer
                | Field::ToolAngle
                | Field::LeadIn
                | Field::Starts
                | Field::GrooveStartX
                | Field::GrooveStartZ
                | Field::Peck
                | Field::Step
                | Field::GrooveDepth
                | Field::BottomWidth
                | Field::FlankA
                | Field::FlankB
                | Field::Slope
        )
    }

    /// The word as the manual writes it.
    #[must_use]
    pub const fn word(self) -> &'static str {
        match self {
            Field::StartX => "X of the start point A",
            Field::StartZ => "Z of the start point A",
            Field::EndX => "X(U) (thread end D)",
            Field::EndZ => "Z(W) (thread end D)",
            Field::Taper => "R(i) (taper)",
            Field::ThreadHeight => "P(k) (thread height)",
            Field::FirstDepth => "Q(Δd) (first depth)",
            Field::MinCut => "Q(Δdmin) (minimum cut)",
            Field::FinishingAllowance => "R(d) (finishing allowance)",
            Field::FinishingPasses => "P(m) (finishing passes)",
            Field::Chamfer => "P(r) (chamfer)",
            Field::ChamferAngle => "chamfer angle (parameter 5131)",
            Field::ToolAngle => "P(a) (tool angle)",
            Field::LeadIn => "E (lead-in)",
            Field::Starts => "L (starts)",
            Field::RunOutShort => "J (run-out, short axis)",
            Field::RunOutLong => "K (run-out, long axis)",
            Field::PassCoordinate => "a pass coordinate",
            Field::GrooveStartX => "X of the groove start point",
            Field::GrooveStartZ => "Z of the groove start point",
            Field::GrooveFromX => "X of the tool before G75.1",
            Field::GrooveFromZ => "Z of the tool before G75.1",
            Field::Peck => "P(Δi) (radial peck)",
            Field::Step => "Q(Δk) (axial step)",
            Field::GrooveDepth => "H(h) (groove depth)",
            Field::BottomWidth => "D(d) (bottom width)",
            Field::FlankA => "A(∠a) (flank angle 1)",
            Field::FlankB => "B(∠b) (flank angle 2)",
            Field::Slope => "L(∠p) (slope angle)",
            Field::Retract => "R(e) (retract)",
            Field::LayerDepth => "V(Δv) (layer depth)",
            Field::AllowanceX => "U(Δu) (X finishing allowance)",
            Field::AllowanceZ => "W(Δw) (Z finishing allowance)",
            Field::ToolWidth => "I(r) (tool width)",
            Field::CornerR1 => "A(r1) (outer corner at the start)",
            Field::CornerR2 => "B(r2) (outer corner at the far end)",
            Field::CornerR3 => "D(r3) (bottom corner at the start side)",
            Field::CornerR4 => "E(r4) (bottom corner at the far side)",
            Field::Pitch => "P (thread pitch)",
            Field::PeakOffset => "I (thread peak offset)",
            Field::InitialDepth => "J (initial cut depth)",
            Field::FullDepth => "K (full thread depth)",
            Field::Degression => "R (depth degression)",
            Field::CompoundAngle => "Q (compound slide angle)",
            Field::TaperDistance => "E (taper distance)",
            Field::SpringPasses => "H (spring passes)",
        }
    }
}

/// Why a cycle cannot be expanded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CycleError {
    /// A G32 block whose end point is where the tool already is: there is
    /// no thread to cut ("missing end point").
    NoMotion,
    /// A length outside the manual's range table (±999 999 999 increments).
    OutOfRange {
        /// Which word.
        field: Field,
        /// The value.
        value: Length,
    },
    /// A count outside its range (m 0..99, a 0..99, L 1..999, r 0..99,
    /// chamfer angle 1..89).
    CountOutOfRange {
        /// Which word.
        field: Field,
        /// The value.
        value: u32,
    },
    /// F0 or I0.
    ZeroLead,
    /// A lead outside the range tables (F up to 9999, I 0.0001..2540).
    LeadOutOfRange,
    /// Note 6: Δdmin > k.
    MinCutExceedsHeight {
        /// Δdmin.
        min_cut: Length,
        /// k.
        height: Length,
    },
    /// Note 6: d > k.
    AllowanceExceedsHeight {
        /// d.
        allowance: Length,
        /// k.
        height: Length,
    },
    /// G76 and G92 cannot cut face threads: the end point has the Z of A.
    FaceThread,
    /// G92 P1 (a face thread): the cut end C has the X of the start point:
    /// the thread has no length along its long axis.
    NoThreadLength,
    /// G92 P1: the taper R (along Z) exceeds the cut's X travel as a
    /// radius, so the cut would run longer along Z than along X, its long
    /// axis (reading R-G92FACE).
    SteepFaceThread {
        /// R (along Z).
        taper: Length,
        /// U: the cut's X travel (X-word units).
        travel: Length,
    },
    /// G92: the cut end C has the short-axis coordinate of the start point
    /// A (U = 0; W = 0 for a face thread): the block has no infeed, and the
    /// run-out and retract, whose direction comes from the start point,
    /// have none.
    NoInfeed,
    /// G92: R and U differ in sign and |R| > |U/2|: the cut start B lies
    /// beyond the start point A (980TDi, 988TA: "当 R 与 U 的符号不一致时，
    /// 要求 │R│≤│U/2│").
    TaperBeyondStart {
        /// R (radius).
        taper: Length,
        /// U: X of C minus X of A (X-word units: a diameter when X is).
        infeed: Length,
    },
    /// Note 7: the run-out on the long axis is longer than the thread on the
    /// long axis (checked against the shortest pass).
    RunOutTooLong {
        /// The run-out length along the long axis.
        run_out: Length,
        /// The long-axis length of the shortest pass.
        length: Length,
    },
    /// A run-out on a thread whose long axis is X (|i| >= |W|, G76; |R| >=
    /// |W|, G92) runs along Z towards the start point's Z (reading
    /// R-RUNOUT); when the thread's start lies beyond its end on A's side
    /// (`s·i > 0`: the cut line rises towards A) that is into the work, and
    /// the retract after it would cross the thread (reading R-XRUNOUT).
    RunOutIntoWork {
        /// i (G76) or R (G92), radius.
        taper: Length,
    },
    /// The start point A is not clear of the thread: it must lie on the
    /// side of B away from the work at the start, and clear of the crest at
    /// the end, or the retract to E would cut the thread.
    StartInsideThread,
    /// The flank shift of some pass reaches the thread end: the pass would
    /// have no length along Z.
    ThreadTooShort {
        /// The largest Z shift of a pass.
        shift: Length,
        /// |W|, the thread's length along Z.
        length: Length,
    },
    /// Lead-in E on a thread whose long axis is X: the manual defines E as
    /// an X distance, and no page shows a lead-in on a steep taper (reading
    /// R-LEADIN, under either value: along X, the screw-in would run
    /// against the cut where the taper falls towards A).
    LeadInOnXLongAxis,
    /// More rough passes than [`crate::g76::G76Cycle::pass_limit`].
    TooManyPasses {
        /// Rough passes the cycle would cut (a lower bound when `exact` is false).
        passes: u64,
        /// True when `passes` is the exact count.
        exact: bool,
        /// The limit.
        limit: u32,
    },
    /// More pass paths in the whole cycle than
    /// [`crate::g76::G76Cycle::pass_limit`] (reading R-BUDGET): G76's and
    /// G78's (rough + finishing) × starts, LinuxCNC's rough + full-depth and
    /// spring passes. Refused before the first move, so that no program of
    /// a few lines can make unbounded work.
    TooMuchWork {
        /// The pass paths the cycle would cut, exactly.
        pass_paths: u64,
        /// The limit.
        limit: u32,
    },
    /// A G75.1 word outside the manual's range for it.
    WordOutOfRange {
        /// Which word.
        field: Field,
        /// The value.
        value: Length,
        /// The manual's range, in its words.
        rule: &'static str,
    },
    /// A G75.1 angle outside its range (A, B: 0 < angle <= 90; L: 0 <= L < 90).
    AngleOutOfRange {
        /// A, B or L.
        field: Field,
        /// The value in 0.0001 degree.
        value: u32,
    },
    /// G75.1 with H0: there is no groove.
    NoGrooveDepth,
    /// G75.1 slope L not below flank angle B: flank B never meets the opening.
    SlopeNotBelowFlank {
        /// L in 0.0001 degree.
        slope: u32,
        /// B in 0.0001 degree.
        flank_b: u32,
    },
    /// G75.1 under reading R-G75SLOPE `falls-towards-d`: the slope L not
    /// below flank angle A, so flank A never goes down from S into the
    /// groove below the falling opening.
    SlopeNotBelowFlankA {
        /// L in 0.0001 degree.
        slope: u32,
        /// A in 0.0001 degree.
        flank_a: u32,
    },
    /// G75.1 under reading R-G75SLOPE `falls-towards-d`: the opening,
    /// falling at L in D's direction, reaches the bottom's level at or
    /// before flank B: the groove has no far flank.
    OpeningBelowBottom,
    /// G75.1 U(Δu) at least the depth |H|: no room is left to rough.
    AllowanceExceedsDepth {
        /// Δu.
        allowance: Length,
        /// |H|.
        depth: Length,
    },
    /// G75.1 corners larger than the edge they sit on.
    CornerTooLarge {
        /// The edge.
        edge: GrooveEdge,
    },
    /// G75.1: the groove, less the allowances and the bottom corners, is
    /// narrower than the tool at its bottom.
    GrooveNarrowerThanTool {
        /// The tool width I (0 for a pointed tool).
        tool_width: Length,
    },
    /// G75.1 roughed in layers (V) with a step Q(Δk) wider than the tool
    /// I, where layer 1's plunge range is wider than the tool: layer 1's
    /// plunges leave ridges, and the rapids of the next layer (the axial
    /// steps of step ⑦ at the bottom of the layer above, the move down to
    /// A21 of step ②) would run through them (reading R-G75RIDGE).
    RidgesInLayers {
        /// Q(Δk).
        step: Length,
        /// I (0 for a pointed tool).
        tool_width: Length,
    },
    /// G75.1 needs more pecks than [`crate::g75::MAX_PECKS`].
    TooManyPecks {
        /// The limit.
        limit: u64,
    },
    /// An engine could not decide the rounding of a computed value (or the
    /// sign of an alarm comparison) at its highest precision
    /// (`docs/G75.md` §6). It refuses rather than guess.
    UndecidedRounding,
}

/// An edge of the G75.1 groove, for [`CycleError::CornerTooLarge`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GrooveEdge {
    /// Flank A: corners A(r1) and D(r3).
    FlankA,
    /// The inner bottom: corners D(r3) and E(r4) (and the tool width).
    Bottom,
    /// Flank B: corners E(r4) and B(r2).
    FlankB,
}

impl fmt::Display for CycleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CycleError::OutOfRange { field, value } => write!(
                f,
                "{} = {value} is outside the range table (at most 999999999 least increments)",
                field.word()
            ),
            CycleError::CountOutOfRange { field, value } => {
                let range = match field {
                    Field::FinishingPasses | Field::ToolAngle | Field::Chamfer => "0..99",
                    Field::Starts => "1..999",
                    Field::ChamferAngle => "1..89 degrees",
                    _ => "its range",
                };
                write!(f, "{} = {value} is outside {range}", field.word())
            }
            CycleError::ZeroLead => write!(f, "the lead F(I) is zero: no thread can be cut"),
            CycleError::NoMotion => {
                write!(f, "the end point X(U) Z(W) is the current position: there is no thread to cut")
            }
            CycleError::LeadOutOfRange => {
                write!(f, "the lead F(I) is outside the range table (F up to 9999, I 0.0001..2540)")
            }
            CycleError::MinCutExceedsHeight { min_cut, height } => write!(
                f,
                "Q(Δdmin) = {min_cut} is larger than the thread height P(k) = {height} (alarm: note 6, \
                 minimum cut larger than the thread height)"
            ),
            CycleError::AllowanceExceedsHeight { allowance, height } => write!(
                f,
                "R(d) = {allowance} is larger than the thread height P(k) = {height} (alarm: note 6, \
                 finishing allowance larger than the thread height)"
            ),
            CycleError::FaceThread => {
                write!(f, "the thread end Z(W) equals the Z of the start point: G76 and G92 cannot cut face threads")
            }
            CycleError::NoThreadLength => write!(
                f,
                "the cut end X(U) equals the X of the start point: a G92 P1 face thread, cut along X, has \
                 no length"
            ),
            CycleError::SteepFaceThread { taper, travel } => write!(
                f,
                "R = {taper} along Z exceeds the X travel U = {travel} as a radius: a G92 P1 face thread \
                 cuts along X, its long axis, and the cut would run longer along Z"
            ),
            CycleError::NoInfeed => write!(
                f,
                "the cut end lies on the start point A's short-axis coordinate (U = 0; W = 0 for a P1 face \
                 thread): G92 takes the direction of its infeed, run-out and retract from the start point, \
                 and there is none"
            ),
            CycleError::TaperBeyondStart { taper, infeed } => write!(
                f,
                "R = {taper} and U = {infeed} differ in sign and |R| is larger than U as a radius: the cut \
                 start B lies beyond the start point A (G92: when R and U differ in sign, |R| <= |U/2| in \
                 diameter, |R| <= |U| in radius)"
            ),
            CycleError::RunOutTooLong { run_out, length } => write!(
                f,
                "the run-out along the long axis ({run_out}) is longer than the thread on the long axis \
                 ({length}) (alarm: G76 note 7, G32 note 4, 988TA G92 note 4)"
            ),
            CycleError::RunOutIntoWork { taper } => write!(
                f,
                "the long axis is X and the run-out J runs along Z towards the start point, which with the \
                 taper {taper} (the thread's start lying beyond its end on the start point's side) is into \
                 the work: the run-out and the retract after it would cut the thread (reading R-XRUNOUT; \
                 program J0 or the taper the other way)"
            ),
            CycleError::StartInsideThread => write!(
                f,
                "the start point A lies inside the thread (between the crest line through B and the \
                 root): the retract to E would cut the thread"
            ),
            CycleError::ThreadTooShort { shift, length } => write!(
                f,
                "a pass is shifted {shift} along Z by depth x tan(a/2), which reaches the thread end \
                 ({length} from A): the pass would have no length"
            ),
            CycleError::LeadInOnXLongAxis => write!(
                f,
                "lead-in E is an X distance and cannot be used on a thread whose long axis is X \
                 (|i| >= |W|)"
            ),
            CycleError::TooManyPasses { passes, exact, limit } => {
                let more = if exact { "" } else { "more than " };
                write!(f, "the cycle needs {more}{passes} rough passes, above the pass limit {limit}")
            }
            CycleError::TooMuchWork { pass_paths, limit } => write!(
                f,
                "the cycle cuts {pass_paths} pass paths (rough and finishing passes, times the starts), above \
                 the pass limit {limit} (`pass_limit` in the parameter file raises it)"
            ),
            CycleError::WordOutOfRange { field, value, rule } => {
                write!(f, "{} = {value} is outside its range ({rule})", field.word())
            }
            CycleError::AngleOutOfRange { field, value } => {
                let range = if field == Field::Slope { "0 <= L < 90" } else { "0 < angle <= 90" };
                write!(f, "{} = ", field.word())?;
                crate::units::write_fixed(f, i128::from(value), 4)?;
                write!(f, " degrees is outside {range}")
            }
            CycleError::NoGrooveDepth => write!(f, "G75.1 H(h) = 0: the groove has no depth"),
            CycleError::SlopeNotBelowFlank { slope, flank_b } => {
                write!(f, "L(∠p) = ")?;
                crate::units::write_fixed(f, i128::from(slope), 4)?;
                write!(f, " degrees is not below B(∠b) = ")?;
                crate::units::write_fixed(f, i128::from(flank_b), 4)?;
                write!(f, " degrees: flank B never meets the slope of the opening")
            }
            CycleError::SlopeNotBelowFlankA { slope, flank_a } => {
                write!(f, "L(∠p) = ")?;
                crate::units::write_fixed(f, i128::from(slope), 4)?;
                write!(f, " degrees is not below A(∠a) = ")?;
                crate::units::write_fixed(f, i128::from(flank_a), 4)?;
                write!(f, " degrees: with the opening falling towards D (R-G75SLOPE falls-towards-d) flank A never goes down into the groove")
            }
            CycleError::OpeningBelowBottom => write!(
                f,
                "the opening, falling at L(∠p) towards D (R-G75SLOPE falls-towards-d), reaches the bottom's \
                 level H(h) at or before flank B: the groove has no far flank"
            ),
            CycleError::AllowanceExceedsDepth { allowance, depth } => write!(
                f,
                "U(Δu) = {allowance} is not smaller than the groove depth |H| = {depth}: the allowance \
                 is larger than the groove"
            ),
            CycleError::CornerTooLarge { edge } => {
                let (edge, words) = match edge {
                    GrooveEdge::FlankA => ("flank A", "A(r1) and D(r3)"),
                    GrooveEdge::Bottom => ("the inner bottom D(d)", "D(r3) and E(r4)"),
                    GrooveEdge::FlankB => ("flank B", "E(r4) and B(r2)"),
                };
                write!(f, "the corners {words} together are longer than {edge}")
            }
            CycleError::GrooveNarrowerThanTool { tool_width } => write!(
                f,
                "the groove, less the allowances U/W and the bottom corners D(r3)/E(r4), is narrower \
                 at its bottom than the tool I = {tool_width}"
            ),
            CycleError::RidgesInLayers { step, tool_width } => write!(
                f,
                "Q(Δk) = {step} is wider than the tool (I = {tool_width}) in a groove roughed in \
                 layers V(Δv): the plunges of a layer leave ridges between them and the next \
                 layer's rapids would run through them; program Q no wider than the tool"
            ),
            CycleError::TooManyPecks { limit } => {
                write!(f, "the G75.1 cycle needs more than {limit} pecks")
            }
            CycleError::UndecidedRounding => write!(
                f,
                "a G75.1 coordinate could not be rounded to the least increment with certainty at \
                 512 fraction bits; refused rather than guessed"
            ),
        }
    }
}

impl core::error::Error for CycleError {}

impl CycleError {
    /// The word whose value the alarm is about, when it is about one
    /// (a value outside its range table or its manual's range).
    #[must_use]
    pub const fn field(&self) -> Option<Field> {
        match self {
            Self::OutOfRange { field, .. }
            | Self::CountOutOfRange { field, .. }
            | Self::WordOutOfRange { field, .. }
            | Self::AngleOutOfRange { field, .. } => Some(*field),
            _ => None,
        }
    }

    /// The alarm's stable name (`min_cut_exceeds_height`), as the
    /// conformance vectors write it after `cycle:`. A name never changes
    /// meaning; a new alarm gets a new name.
    ///
    /// Twin (deliberate, from `vectors/README.md`): `cli/tests/vectors.rs`,
    /// `kind`, which checks the corpus against the documented names.
    #[must_use]
    pub const fn name(&self) -> &'static str {
        match self {
            Self::NoMotion => "no_motion",
            Self::OutOfRange { .. } => "out_of_range",
            Self::CountOutOfRange { .. } => "count_out_of_range",
            Self::ZeroLead => "zero_lead",
            Self::LeadOutOfRange => "lead_out_of_range",
            Self::MinCutExceedsHeight { .. } => "min_cut_exceeds_height",
            Self::AllowanceExceedsHeight { .. } => "allowance_exceeds_height",
            Self::FaceThread => "face_thread",
            Self::NoInfeed => "no_infeed",
            Self::NoThreadLength => "no_thread_length",
            Self::SteepFaceThread { .. } => "steep_face_thread",
            Self::TaperBeyondStart { .. } => "taper_beyond_start",
            Self::RunOutTooLong { .. } => "run_out_too_long",
            Self::RunOutIntoWork { .. } => "run_out_into_work",
            Self::StartInsideThread => "start_inside_thread",
            Self::ThreadTooShort { .. } => "thread_too_short",
            Self::LeadInOnXLongAxis => "lead_in_on_x_long_axis",
            Self::TooManyPasses { .. } => "too_many_passes",
            Self::TooMuchWork { .. } => "too_much_work",
            Self::WordOutOfRange { .. } => "word_out_of_range",
            Self::AngleOutOfRange { .. } => "angle_out_of_range",
            Self::NoGrooveDepth => "no_groove_depth",
            Self::SlopeNotBelowFlank { .. } => "slope_not_below_flank",
            Self::SlopeNotBelowFlankA { .. } => "slope_not_below_flank_a",
            Self::OpeningBelowBottom => "opening_below_bottom",
            Self::AllowanceExceedsDepth { .. } => "allowance_exceeds_depth",
            Self::CornerTooLarge { .. } => "corner_too_large",
            Self::GrooveNarrowerThanTool { .. } => "groove_narrower_than_tool",
            Self::RidgesInLayers { .. } => "ridges_in_layers",
            Self::TooManyPecks { .. } => "too_many_pecks",
            Self::UndecidedRounding => "undecided_rounding",
        }
    }
}
