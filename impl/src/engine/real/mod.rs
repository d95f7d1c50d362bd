//! Exact rounding support for the G75.1 engine (`docs/G75.md` §6,
//! reading R-G75ROUND): dyadic fixed-point interval arithmetic, the sine,
//! cosine, tangent and cotangent of angles `k · 0.00005°`, and the four
//! decisions the cycle makes on a real number (floor, ceil, nearest, sign).
//!
//! # Numbers
//!
//! An [`Fixed<N>`] is a signed integer of `N` 64-bit limbs (two's complement,
//! little-endian) read as `int · 2^-P` with `P = 64·(N − 2)` fraction bits:
//! the two top limbs hold the integer part, so every value lies in
//! `(−2^127, 2^127)`. The engine uses two precisions:
//!
//! * [`FAST`] = 4 limbs, `P = 128` (the fast path);
//! * [`SLOW`] = 10 limbs, `P = 512` (the highest precision of
//!   `docs/G75.md` §6, at which reading R-G75TIE applies:
//!   [`Interval::round_tie`], [`Interval::sign_tie`]).
//!
//! An [`Interval<N>`] is a closed interval `[lo, hi]` of such numbers that contains
//! the exact real value it stands for. Every operation rounds its lower end
//! down and its upper end up, so the containment is kept. Additions and
//! subtractions are exact; a product or quotient is exact whenever the exact
//! result is representable, so an operation on point intervals (exact
//! values) gives a point interval exactly when the exact result is a dyadic
//! number with at most `P` fraction bits. All exact values of the G75.1
//! geometry are dyadic with few fraction bits (the only exact trigonometric
//! values are 0, 1/2 and 1, and the only divisors are `f` ∈ {1, 2} and
//! sines, cosines and `1 − tan L·cot b` that are 1/2 or 1 when exact), so
//! exact inputs give exact point intervals and are decided exactly.
//!
//! An operation that would overflow (a magnitude of `2^127` or more), a
//! division by an interval that contains 0 and a series that does not
//! converge within its iteration bound "poison" the interval: every decision
//! on a poisoned interval is undecided, so the engine refuses
//! ([`crate::CycleError::UndecidedRounding`]) instead of guessing. None of
//! these can happen for a validated cycle: the largest magnitude the G75.1
//! formulas reach is below `2^96` (see `engine/g75/mod.rs`).
//!
//! # Trigonometry
//!
//! `sin` and `cos` of `x = k · π / 3 600 000` (`0 ≤ k ≤ 1 800 000`, 0° to
//! 90°) by their Taylor series. Each term is enclosed by interval
//! arithmetic; the series alternate with terms that decrease in magnitude
//! (`x < 2`), so the remainder after a term is at most the next term, whose
//! upper bound is added to both ends (a rigorous truncation bound). `π`
//! comes from [`PI_FRACTION`], hard-coded. The exact cases of
//! `docs/G75.md` §6 (sin 0, 30°, 90°; cos 0, 60°, 90°; tan 0, 45°; cot 45°,
//! 90°) are returned as exact point intervals.
//!
//! No heap, no floating point, no `unsafe`, no panics: every index is
//! bounded by the const generic `N` (checked at compile time to lie in
//! `3..=MAX_LIMBS`), every arithmetic operation is checked or wrapping on
//! purpose (limb arithmetic with explicit carries).

mod fixed;
mod interval;
mod limbs;
mod power;
#[cfg(test)]
mod tests;
mod trig;

/// Limbs of the fast precision: 128 fraction bits.
pub const FAST: usize = 4;

/// Limbs of the slow precision: 512 fraction bits (`docs/G75.md` §6).
pub const SLOW: usize = 10;

/// Most limbs an [`Fixed`] may have (the scratch buffers are sized for it).
pub const MAX_LIMBS: usize = 14;

/// Scratch size: a full product of two numbers of [`MAX_LIMBS`] limbs.
const SCRATCH: usize = 2 * MAX_LIMBS;

/// The fraction bits of π − 3, most significant 64-bit word first: `π =
/// 3 + Σ PI_FRACTION[i] · 2^(−64(i+1)) + δ`, `0 ≤ δ < 2^-640`.
///
/// These are the well-known hexadecimal digits of π
/// (`3.243F6A8885A308D313198A2E03707344A4093822299F31D0…`, the same digits
/// that initialise Blowfish's P-array and first S-box). The test
/// `pi_matches_machin` recomputes π from Machin's formula
/// `π = 16 atan(1/5) − 4 atan(1/239)` with this module's interval
/// arithmetic at 704 fraction bits and checks every one of these 640 bits.
pub const PI_FRACTION: [u64; 10] = [
    0x243F_6A88_85A3_08D3,
    0x1319_8A2E_0370_7344,
    0xA409_3822_299F_31D0,
    0x082E_FA98_EC4E_6C89,
    0x4528_21E6_38D0_1377,
    0xBE54_66CF_34E9_0C6C,
    0xC0AC_29B7_C97C_50DD,
    0x3F84_D5B5_B547_0917,
    0x9216_D5D9_8979_FB1B,
    0xD131_0BA6_98DF_B5AC,
];

/// 90° in the angle unit of this module, 0.00005°.
pub const RIGHT: u32 = 1_800_000;

/// 180° in the angle unit of this module: the angle `k` is `k·π/HALF_TURN`.
pub const HALF_TURN: u32 = 3_600_000;

pub use fixed::Fixed;
#[allow(deprecated)]
pub use fixed::Fx;
#[allow(deprecated)]
pub use interval::Iv;
pub use interval::{Interval, Rounding};
pub use power::{exp, ln, power};
pub use trig::{cos, cot, cot_of, pi, sin, sin_cos, tan, tan_cot, tan_of};
