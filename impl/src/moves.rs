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
    /// Rapid along Z back to A.
    Return,
}

/// Rough or finishing pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PassKind {
    /// A rough pass (粗车), depth up to k - d.
    Rough,
    /// A finishing pass (精车), depth k.
    Finish,
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
