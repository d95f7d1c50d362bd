//! # cycleref-spec
//!
//! The exact reference model of lathe thread-cutting canned cycles, and the
//! NC program reader that feeds it and the fixed-point engine (`cycleref`).
//!
//! * [`reader`] reads a program, one item at a time, with a
//!   [`profile::Machine`] and resolves every cycle into its typed parameters
//!   ([`cycleref::G76Cycle`] and its twins): one home for the program's
//!   meaning, used by both engines.
//! * [`pipeline`] is the one way to run a program: each cycle of the reader
//!   expanded by the chosen [`Engine`], as an iterator of moves.
//! * [`g76`] expands a cycle exactly as the manuals define it, one function
//!   per formula, each quoting the manual.
//! * [`differ`] compares an engine's expansion with the reference's: the
//!   one same-moves assertion of the differential tests.
//! * [`exact`] and [`tan`] hold the only arithmetic beyond `+ - ×`: rounding
//!   to the least increment, square roots and tangents, all exact.
//!
//! Every reading chosen where the manuals are silent or ambiguous has an id
//! (`R-…`) and is collected in `docs/INTERPRETATIONS.md`.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod differ;
pub mod error;
pub mod exact;
pub mod g32;
pub mod g75;
pub mod g76;
pub mod lex;
pub mod pipeline;
pub mod profile;
pub mod reader;
pub mod real;
pub mod tan;

pub use error::{ErrorKind, ProgramError};
pub use pipeline::{expand, Cycle, Engine, Moves, RunError};
pub use profile::{Machine, ProfileName};
pub use reader::{read, G76Call, Item, LineReader, Program, Reader};
