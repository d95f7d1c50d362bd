//! Steps and groups for the unit tests of `align` and `compare`: one
//! fixture for both.

use cycleref::{InputUnit, Lead, LeadWord, Point, StartAngle, Units};

use super::{Context, Group, Kind, Step};

/// IS-B millimetres.
pub(super) const MM: Units = Units { system: cycleref::IncrementSystem::IsB, unit: InputUnit::Metric };

/// A move of `kind` to (x, z), from a program line; a thread move has the
/// lead F2 and starts synchronisation at 0°.
pub(super) fn step(kind: Kind, x: i64, z: i64, line: usize) -> Step {
    let lead = (kind == Kind::Thread).then_some(Lead { word: LeadWord::F, mantissa: 2, scale: 0 });
    Step {
        kind,
        from: None,
        to: Point::new(x, z),
        centre: None,
        lead,
        angle: StartAngle::ZERO,
        sync: kind == Kind::Thread,
        context: Context::Source { line },
    }
}

/// A pass at depth `x`: a rapid to its start and one thread move.
pub(super) fn pass(x: i64) -> Group {
    Group { rapids: vec![step(Kind::Rapid, x, 10, 1)], cuts: vec![step(Kind::Thread, x, -30, 2)] }
}
