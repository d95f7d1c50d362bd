//! # cycleref-spec
//!
//! The exact reference model of lathe thread-cutting and grooving canned
//! cycles (G76, G32, G75.1), and the NC program reader that feeds it and
//! the fixed-point engine (`cycleref`).
//!
//! * [`reader`] reads a program, one item at a time, with a
//!   [`profile::Machine`] and resolves every cycle into its typed parameters
//!   ([`cycleref::G76Cycle`], [`cycleref::G32Block`],
//!   [`cycleref::G75Cycle`]): one home for the program's meaning, used by
//!   both engines.
//! * [`pipeline`] is the one way to run a program: each cycle of the reader
//!   expanded by the chosen [`Engine`], as an iterator of moves.
//! * [`g76`], [`g32`] and [`g75`] expand a cycle exactly as the manuals
//!   define it, one function per formula, each quoting the manual.
//! * [`differ`] compares an engine's expansion with the reference's: the
//!   one same-moves assertion of the differential tests.
//! * [`exact`], [`tan`] and [`real`] hold the only arithmetic beyond
//!   `+ - ×`: rounding to the least increment, square roots, tangents and
//!   G75.1's trigonometry, all exact.
//!
//! Every reading chosen where the manuals are silent or ambiguous has an id
//! (`R-…`) and is collected in `docs/INTERPRETATIONS.md`.
//!
//! # Example
//!
//! Read a program with a machine (profile, increment system, parameters)
//! and expand its cycles with either engine: the fixed-point engine
//! ([`Engine::Impl`]) and this crate's exact reference ([`Engine::Spec`])
//! give the same moves.
//!
//! ```
//! use cycleref_spec::{expand, read, Cycle, Engine, Machine, ProfileName};
//!
//! let text = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n";
//! let program = read(text, &Machine::new(ProfileName::Gsk988))?;
//! for cycle in program.items.iter().filter_map(Cycle::of) {
//!     let ours: Vec<_> = expand(cycle, Engine::Impl)?.collect();
//!     let reference: Vec<_> = expand(cycle, Engine::Spec)?.collect();
//!     assert_eq!(ours, reference);
//!     assert_eq!((cycle.code(), cycle.line(), ours.len()), ("G76", 4, 30));
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! [`read`] holds the program's items in memory; [`Reader`] (a program in
//! memory) and [`LineReader`] (a program read in pieces) give them one at a
//! time, and [`pipeline::validate`] checks a whole program in constant
//! memory. An error names the line, the word and the rule
//! ([`ProgramError`]), or the cycle's alarm ([`RunError`]).
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod cycles;
pub mod differ;
pub mod error;
pub mod exact;
pub mod g32;
pub mod g75;
pub mod g76;
pub mod g92;
pub mod lex;
pub mod linuxcnc;
pub mod pass;
pub mod pipeline;
pub mod profile;
pub mod reader;
pub mod readings;
pub mod real;
pub mod rs274;
pub mod tan;
pub mod text;

pub use error::{ErrorKind, ProgramError};
pub use pipeline::{expand, Cycle, Engine, Moves, RunError};
pub use profile::{Machine, ProfileName};
pub use reader::{read, G76Call, Item, LineReader, Program, Reader};
