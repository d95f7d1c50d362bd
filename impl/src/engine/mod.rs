//! The fixed-point engines: the cycles of the reference model
//! (`cycleref-spec`, the authority) in integers, without heap, floating
//! point, `unsafe` or panics, each checked completely before its first move
//! and then streamed move by move from a fixed-size iterator.
//!
//! # Layout
//!
//! | module | what it holds | its twin in `cycleref-spec` |
//! | --- | --- | --- |
//! | [`arith`] | the shared kernels (public for their contracts' proofs): the one `round_div`, the one saturating narrowing, floor and ceiling division, [`isqrt_floor`], [`round_sqrt`], [`round_sqrt_near`] | `spec/src/exact.rs` |
//! | [`contracts`] | the contracts of the kernels of `arith` and of [`mul_tan_round`](crate::tan::mul_tan_round), as predicates | — |
//! | [`g76`] | the G76 multi-pass threading cycle ([`expand_g76`], [`G76Moves`], [`rough_pass_count`]) | `spec/src/g76.rs` |
//! | `pass` (private) | one thread pass, shared by G76 and G92: its path from A through the cut and run-out back to A, and the walk that streams it | `spec/src/pass.rs` |
//! | [`g92`] | the G92 single-pass thread cycle ([`expand_g92`](g92::expand_g92)) on the shared pass | `spec/src/g92.rs` |
//! | [`g32`] | the G32 single thread block ([`expand_g32`](g32::expand_g32)) | `spec/src/g32.rs` |
//! | [`g75`] | the G75.1 trapezoidal groove ([`expand_g75`](g75::expand_g75), [`groove_profile`](g75::groove_profile)), split by concern: exact geometry, local contours, the absolute frame, roughing, the tail, the public profile | `spec/src/g75/` |
//! | [`schedule`] | the G76 depth schedule, one level at a time ([`Schedule`](schedule::Schedule), public for the proofs' one-step harness) | `spec/src/g76.rs` (`next_depth`) |
//! | [`linuxcnc`] | LinuxCNC's G76 ([`expand_linuxcnc`](linuxcnc::expand_linuxcnc), [`LinuxCncMoves`](linuxcnc::LinuxCncMoves), [`taper_pitch`](linuxcnc::taper_pitch)) | `spec/src/linuxcnc.rs` |
//! | [`approx`] | the fast path (reading R-FASTPATH): 64-bit fixed-point values with a rigorous error bound, decided only when no rounding boundary lies within it (LinuxCNC's G76, G75.1), else the intervals of [`real`] | — |
//! | [`real`] | dyadic fixed-point interval arithmetic, trigonometry, logarithm, exponential and powers (G75.1, LinuxCNC's G76) | `spec/src/real.rs` |
//!
//! Where an engine restates a formula of the reference, the comment on the
//! engine's function names its twin (file and function), and the twin names
//! it back.
//!
//! # Why nothing overflows
//!
//! `validate()` bounds every length word by [`MAX_LENGTH`](crate::units::MAX_LENGTH)
//! `< 2^30` in magnitude (G75.1 words by `2^27`), so:
//!
//! * lengths and coordinates are `i64`, and every sum of a few of them
//!   (a G76 pass point, a G32 end, a G75.1 roughing position) stays below
//!   `2^33`;
//! * products of two coordinates (a run-out start interpolated on the cut
//!   line, G76 and G32) are formed in `i128` (below `2^67`) and rounded by
//!   the one `round_div`;
//! * lead ratios (G76 chamfer and lead-in lengths) are `u128`, below
//!   `2^102`; the square roots of the depth schedule take `Δd² n < 2^93`;
//! * G75.1 values are first computed in 64-bit fixed point with a bound
//!   ([`approx`]; a value beyond `2^63` is unknown there and falls back),
//!   then enclosed in 128-bit (then 512-bit) intervals whose
//!   magnitudes stay below `2^96`, far inside the `2^127` of an interval;
//!   rounded values stay `i128` until the range check has bounded them;
//! * the one narrowing back to `i64` saturates, and only values that a
//!   range check then refuses (error values) can saturate.
//!
//! The detailed bounds are in each engine's module docs ([`g76`], [`g32`],
//! [`g75`]) and in comments next to the operations. Every other operation is
//! checked (`checked_*`, `saturating_*`) or bounded by such a comment; no
//! index, `unwrap`, `expect` or division can panic.

pub mod approx;
pub mod arith;
pub mod contracts;
pub mod g32;
pub mod g75;
pub mod g76;
pub mod g92;
pub mod linuxcnc;
pub(crate) mod pass;
pub mod real;
pub mod schedule;

pub use arith::{isqrt_floor, round_sqrt, round_sqrt_near};
#[cfg(feature = "loop-counters")]
pub use arith::{record_isqrt, record_isqrt_near};
pub use g76::{check_g76, expand_g76, rough_pass_count, G76Moves};
