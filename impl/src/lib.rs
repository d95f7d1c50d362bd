//! # cycleref
//!
//! The shared model of lathe threading and grooving canned cycles (units,
//! leads, cycle parameters, moves, errors) and the fixed-point engine that
//! expands them.
//!
//! `no_std`, no heap, no floating point, no `unsafe`: fit to run inside a
//! control. The reference model it must equal is `cycleref-spec`, which
//! also reads NC programs into these cycles (its crate docs show a program
//! read and expanded by either engine).
//!
//! # Example
//!
//! The M68x6 thread of the GSK 988TA manual (`G00 X80 Z10; G76 P020560
//! Q0.150 R0.1; G76 X60.64 Z-62 P3.680 Q1.800 F6`), its parameters given
//! directly in least increments (IS-B: 0.001 mm), expanded move by move:
//!
//! ```
//! use cycleref::{expand_g76, DepthMode, G76Cycle, Infeed, Lead, LeadWord, Motion, Point, RunOut, Units, XMode};
//!
//! let cycle = G76Cycle {
//!     units: Units::IS_B_METRIC,
//!     x_mode: XMode::Diameter,
//!     start: Point::new(80_000, 10_000),   // A: X80 Z10
//!     end: Point::new(60_640, -62_000),    // D: X60.64 Z-62
//!     taper: 0,
//!     thread_height: 3_680,                // P(k) 3.68
//!     first_depth: 1_800,                  // Q(Δd) 1.8
//!     min_cut: 150,                        // Q(Δdmin) 0.15
//!     finishing_allowance: 100,            // R(d) 0.1
//!     finishing_passes: 2,                 // P(m) 02
//!     tool_angle: 60,                      // P(a) 60
//!     infeed: Infeed::RightFlank,
//!     depth_mode: DepthMode::Decreasing,
//!     lead_in: 0,
//!     starts: 1,
//!     lead: Lead { word: LeadWord::F, mantissa: 6, scale: 0 }, // F6
//!     run_out: RunOut::Amounts { short: 3_000, long: 3_000 }, // the 45° chamfer of r = 05
//!     pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
//!     readings: cycleref::CycleReadings::DEFAULT,
//! };
//! let moves: Vec<_> = expand_g76(&cycle)?.collect();
//! // 4 rough and 2 finishing passes of 5 moves.
//! assert_eq!(moves.len(), 30);
//! // The first pass: rapid to B1 (X64.4 Z8.961), cut to Z-59, run-out to X70.4 Z-62.
//! assert_eq!(moves[0].to, Point::new(64_400, 8_961));
//! assert!(matches!(moves[1].motion, Motion::Thread { sync: true, .. }));
//! assert_eq!((moves[1].to, moves[2].to), (Point::new(64_400, -59_000), Point::new(70_400, -62_000)));
//! assert_eq!(moves[0].pass.map(|p| p.depth), Some(1_800));
//! # Ok::<(), cycleref::CycleError>(())
//! ```
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
pub mod g92;
pub mod lead;
pub mod linuxcnc;
pub mod loop_counters;
pub mod moves;
pub mod readings;
pub mod tan;
pub mod units;

pub use angle::{StartAngle, StartSpacing};
pub use engine::g32::{expand_g32, G32Moves};
pub use engine::g75::{expand_g75, groove_profile, G75Moves, GrooveProfile, ProfilePoint, ProfileSegment};
pub use engine::g92::{expand_g92, G92Moves};
pub use engine::linuxcnc::{expand_linuxcnc, LinuxCncMoves};
pub use engine::{expand_g76, G76Moves};
pub use error::{CycleError, Field, GrooveEdge};
pub use g32::{G32Block, G32RunOut};
pub use g75::{Corner, CornerKind, G75Cycle, PathType};
pub use g76::{DepthMode, G76Cycle, Infeed, RunOut};
pub use g92::G92Cycle;
pub use lead::{Lead, LeadWord, Ratio};
pub use linuxcnc::LinuxCncG76;
pub use moves::{Flank, Motion, Move, Pass, PassKind, Plunge, Role};
pub use readings::{CycleReadings, G75Readings};
pub use units::{IncrementSystem, InputUnit, Length, Point, Units, XMode};
