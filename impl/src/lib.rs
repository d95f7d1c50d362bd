//! # cycleref
//!
//! The shared model of lathe threading and grooving canned cycles (units,
//! leads, cycle parameters, moves, errors) and the fixed-point engine that
//! expands them.
//!
//! `no_std`, no heap, no floating point, no `unsafe`: fit to run inside a
//! control. The reference model it must equal is `cycleref-spec`.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod angle;
pub mod engine;
pub mod error;
pub mod examples;
pub mod g32;
pub mod g75;
pub mod g76;
pub mod lead;
pub mod loop_counters;
pub mod moves;
pub mod tan;
pub mod units;

pub use angle::{StartAngle, StartSpacing};
pub use engine::g32::{expand_g32, G32Moves};
pub use engine::g75::{expand_g75, groove_profile, G75Moves, GrooveProfile, ProfilePoint, ProfileSegment};
pub use engine::{expand_g76, G76Moves};
pub use error::{CycleError, Field, GrooveEdge};
pub use g32::{G32Block, G32RunOut};
pub use g75::{Corner, CornerKind, G75Cycle, PathType};
pub use g76::{G76Cycle, Infeed, RunOut};
pub use lead::{Lead, LeadWord, Ratio};
pub use moves::{Flank, Motion, Move, Pass, PassKind, Plunge, Role};
pub use units::{IncrementSystem, InputUnit, Length, Point, Units, XMode};
