//! The move model: what every engine produces, and what `cycleref` prints,
//! draws and compares.

use crate::angle::StartAngle;
use crate::lead::Lead;
use crate::units::Point;

/// How the tool moves to [`Move::to`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Motion {
    /// Positioning at rapid traverse (G00).
    Rapid,
    /// Linear feed (G01).
    Feed,
    /// Constant-lead thread cutting synchronised with the spindle (G32).
    Thread {
        /// The lead, exactly as programmed.
        lead: Lead,
        /// Spindle angle at which synchronisation starts (the one-revolution
        /// signal offset). Only meaningful on the first move of a
        /// synchronised run; later moves of the run repeat it.
        start_angle: StartAngle,
        /// True on the move where synchronisation with the spindle starts
        /// (the control waits for the one-revolution signal here).
        sync: bool,
    },
    /// Circular feed (G02 when `clockwise`, else G03) around `centre`.
    Arc {
        /// The arc's centre, absolute (X in X-word units).
        centre: Point,
        /// True for G02: clockwise seen with +Z to the right and +X up
        /// (R-G75ARC).
        clockwise: bool,
    },
}

/// Which plunge of a G75.1 cycle a move belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Plunge {
    /// 1-based layer (m).
    pub layer: u32,
    /// 1-based plunge within the layer (n).
    pub number: u32,
}

/// What a move does within its pass, in the manual's terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Role {
    /// Rapid from A to the pass start Bn (or to the lead-in start An).
    Approach,
    /// Screw-in from An to Bn (lead-in E, 旋进).
    LeadIn,
    /// The thread cut from Bn towards the end line D–E.
    Cut,
    /// The run-out (退尾) at the end of the cut.
    RunOut,
    /// Rapid along X to E (退刀终点), the X of A.
    Retract,
    /// Rapid along Z back to A; for G75.1 the moves back to the start
    /// point and to the point before the cycle (step 10).
    Return,
    /// G75.1 step 3/5: a peck, a radial feed of at most Δi (Δi/2 radius).
    Peck(Plunge),
    /// G75.1 step 4: the rapid retract e after a peck.
    PeckRetract(Plunge),
    /// G75.1 step 6: the rapid retract to the plunge start Amn.
    PlungeRetract(Plunge),
    /// G75.1 step 7: the axial rapid of at most Δk to the start of this plunge.
    Step(Plunge),
    /// G75.1 steps 8 and 2: the rapids to the start of this layer.
    LayerChange(u32),
    /// G75.1 step 9: the rough contour along the profile less the allowances.
    RoughContour,
    /// G75.1 step 10: the finishing contour along the programmed profile.
    FinishContour,
}

/// Rough or finishing pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PassKind {
    /// A rough pass (粗车), depth up to k - d.
    Rough,
    /// A finishing pass (精车), depth k.
    Finish,
    /// The one pass of a single-pass cycle block (G92), at the programmed
    /// X: its depth and cut are 0, since the block gives no thread height
    /// to measure them from.
    Single,
}

/// Where in the thread space a pass starts, for the infeed modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Flank {
    /// On the right flank line (D0, and the odd passes of D1 and D2).
    Right,
    /// On the centre line of the final form (even passes of D1).
    Centre,
    /// On the left flank line (the second pass of each D2 level).
    Left,
}

/// The pass a move belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Pass {
    /// Rough or finishing.
    pub kind: PassKind,
    /// 1-based number among the passes of its kind (rough 1..=n, finish 1..=m).
    pub number: u32,
    /// 1-based thread start (1..=L, L ≤ 999).
    pub start: u16,
    /// Thread depth of the pass from B (radius increments).
    pub depth: i64,
    /// Cut of the pass: depth minus the previous level's depth (radius
    /// increments); `d` for the first finishing pass and 0 for the others.
    pub cut: i64,
    /// Position of the pass in the infeed pattern.
    pub flank: Flank,
}

/// One move of a toolpath.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Move {
    /// Rapid, feed or thread.
    pub motion: Motion,
    /// End point of the move.
    pub to: Point,
    /// What the move does.
    pub role: Role,
    /// The pass the move belongs to, for cycles with passes.
    pub pass: Option<Pass>,
}
