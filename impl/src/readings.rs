//! The readings of the manuals that a threading cycle's moves depend on and
//! that the sources leave open (docs/INTERPRETATIONS.md, issue 34), as the
//! cycle carries them: the program reader resolves each reading chosen for
//! the machine (`cycleref_spec::readings`) against the control profile and
//! puts the result here, so that the engine and the exact reference take
//! the same value.
//!
//! [`CycleReadings::DEFAULT`] is the project's default reading of every
//! point: the moves of a cycle carrying it are those of the cycles before
//! readings were selectable.

/// What a threading cycle (G76, G78, G92) does at the points its manuals
/// leave open, resolved for the cycle's control profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CycleReadings {
    /// Reading R-RUNOUT: the short-axis run-out J is clamped to the retract
    /// distance of a pass without run-out (the X of A on a Z-long thread,
    /// |W| on an X-long one), as 988TA G92 note 5 says ("当螺纹短轴方向退尾
    /// 长度大于无退尾时的退刀距离时，系统默认短轴方向退尾长度为无退尾时的退刀距离").
    /// `false`: J as written, beyond the retract point when it is longer
    /// (R-RUNOUT `gsk988-only` on a profile other than gsk988, whose pages
    /// are silent).
    pub clamp_run_out: bool,
    /// Reading R-XRUNOUT: an X-long run-out along Z towards A on a thread
    /// whose cut line rises towards A (s·i > 0) is refused
    /// ([`crate::CycleError::RunOutIntoWork`]) when `false`, made as
    /// written when `true` ("根据程序起点位置自动确定退尾方向", R-XRUNOUT
    /// `towards-start`).
    pub x_run_out_towards_start: bool,
}

impl CycleReadings {
    /// The default readings: J clamped on every profile, X-long run-outs
    /// into the work refused.
    pub const DEFAULT: CycleReadings = CycleReadings { clamp_run_out: true, x_run_out_towards_start: false };
}

impl Default for CycleReadings {
    fn default() -> CycleReadings {
        CycleReadings::DEFAULT
    }
}
