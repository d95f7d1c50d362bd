//! The library under the `cycleref` command.
//!
//! Data flows one way: the program's bytes ([`Job`]) → the reader
//! ([`cycleref_spec::Reader`]) → each cycle expanded by the chosen engine
//! ([`cycleref_spec::pipeline`]) → a writer. What a writer needs of a
//! cycle (its heading, its `nc` style, its `passes` table, the annotations
//! its moves carry, the regions it cuts) comes from the cycle's module
//! ([`cycleref_spec::cycles`]); no module here matches on the kind of
//! cycle except `plot`, whose panels draw each kind's geometry. The
//! modules:
//!
//! * [`job`]: the program and its machine (profile, parameter file,
//!   options);
//! * [`failure`]: the failures a command can end in ([`Failure`], each
//!   with its stable kind, printed `error[KIND]: MESSAGE`);
//! * [`output`]: the streaming writers of `expand` (nc, json, jsonl) and
//!   `passes`;
//! * [`json`]: the typed documents (`cycleref-moves/1`, and the types
//!   `check`'s and the vectors' documents share), serialized straight into
//!   the writer by the one serializer ([`json::ser`]); their JSON Schemas
//!   are in `docs/schemas/`;
//! * [`format`](mod@format): the text forms of lengths, leads, angles and names;
//! * [`check`]: `check`, the comparison of a vendor's toolpath with ours;
//! * [`plot`]: `plot`, the SVG drawing (a panel module per kind of
//!   drawing over a shared canvas, and the trace's overlay);
//! * [`vectors`]: the generator of conformance vectors;
//! * [`conform`]: a vendor's outputs run against a corpus of them.
//!
//! Every command is a function of this library; the binary parses the
//! arguments and maps the outcome to an exit status: 0 success (and, for
//! `check`, agreement), 1 `check` found a difference, 2 an error. A closed
//! output pipe ends a command quietly with status 0, except `check`,
//! whose status is its verdict even then.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod check;
pub mod conform;
pub mod failure;
pub mod format;
pub mod job;
pub mod json;
pub mod output;
pub mod plot;
pub mod vectors;

pub use job::{Cause, Failure, Job, Options, Profile};
pub use output::Format;
