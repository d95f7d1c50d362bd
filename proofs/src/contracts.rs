//! The contracts of the small exact kernels (`cycleref::engine::contracts`):
//! one body per contract, shared by the `#[kani::proof_for_contract]`
//! harnesses of `proofs/src/kani_proofs.rs` and the tests of
//! `proofs/tests/contracts.rs`.
//!
//! Each body chooses arguments in its window, assumes the kernel's
//! precondition, calls the kernel and asserts its postcondition (under
//! Kani the `proof_for_contract` instrumentation assumes and asserts them
//! too; here the body is the check). The tests run each body exhaustively
//! over a small window and sampled over large values; the Kani harnesses
//! over every argument.
//!
//! The kernel is a parameter, so that `proofs/tests/mutants.rs` can pass a
//! broken one.

use cycleref::engine::contracts as c;

use crate::cover;
use crate::verify::{any_i128_in, any_in, any_u128_in, assume, declare};

/// `isqrt_floor` over `x in lo..=hi`: `s² ≤ x < (s + 1)²`.
pub fn isqrt_floor(lo: u128, hi: u128, f: fn(u128) -> u128) {
    declare(&["isqrt_floor: a perfect square", "isqrt_floor: between squares"]);
    let x = any_u128_in(lo, hi);
    assume(c::sqrt_requires(x));
    let s = f(x);
    assert!(c::isqrt_floor_ensures(x, s), "isqrt_floor: s² ≤ x < (s + 1)²");
    cover!(s * s == x, "isqrt_floor: a perfect square");
    cover!(s * s < x, "isqrt_floor: between squares");
}

/// `round_sqrt_near` over `x in lo..=hi` and `guess in guess.0..=guess.1`:
/// the rounded root whatever the guess, `(2s - 1)² ≤ 4x < (2s + 1)²`
/// (`round_sqrt_ensures`), whether the guess is the root, is corrected by
/// at most `NEAR_STEPS` steps of one, or is left for Newton's method.
pub fn round_sqrt_near(lo: u128, hi: u128, guess: (u128, u128), f: fn(u128, u128) -> u128) {
    declare(&[
        "round_sqrt_near: the guess is the root",
        "round_sqrt_near: a guess corrected by steps of one",
        "round_sqrt_near: a guess too far, Newton's method",
    ]);
    let x = any_u128_in(lo, hi);
    let g = any_u128_in(guess.0, guess.1);
    assume(c::sqrt_requires(x));
    let s = f(x, g);
    assert!(c::round_sqrt_ensures(x, s), "round_sqrt_near: the contract of round_sqrt");
    let off = s.abs_diff(g);
    cover!(off == 0, "round_sqrt_near: the guess is the root");
    let near = u128::from(cycleref::engine::arith::NEAR_STEPS);
    cover!(off > 0 && off <= near, "round_sqrt_near: a guess corrected by steps of one");
    cover!(off > near, "round_sqrt_near: a guess too far, Newton's method");
}

/// `round_div` over `num in num_lo..=num_hi`, `den in den_lo..=den_hi`:
/// the nearest integer to `num / den`, ties away from zero.
pub fn round_div(num: (i128, i128), den: (i128, i128), f: fn(i128, i128) -> i128) {
    declare(&[
        "round_div: a tie away from zero, positive",
        "round_div: a tie away from zero, negative",
        "round_div: a negative divisor",
        "round_div: exact",
    ]);
    let n = any_i128_in(num.0, num.1);
    let d = any_i128_in(den.0, den.1);
    assume(c::round_div_requires(n, d));
    let r = f(n, d);
    assert!(c::round_div_ensures(n, d, r), "round_div: the nearest integer, ties away from zero");
    let tie = (n % d).unsigned_abs() * 2 == d.unsigned_abs();
    cover!(tie && r > 0, "round_div: a tie away from zero, positive");
    cover!(tie && r < 0, "round_div: a tie away from zero, negative");
    cover!(d < 0, "round_div: a negative divisor");
    cover!(n % d == 0, "round_div: exact");
}

/// `saturate_i64` over `v in lo..=hi`.
pub fn saturate_i64(lo: i128, hi: i128, f: fn(i128) -> i64) {
    declare(&["saturate_i64: below", "saturate_i64: inside", "saturate_i64: above"]);
    let v = any_i128_in(lo, hi);
    let r = f(v);
    assert!(c::saturate_i64_ensures(v, r), "saturate_i64: v, or the bound on its side");
    cover!(v < i128::from(i64::MIN), "saturate_i64: below");
    cover!(i64::try_from(v).is_ok(), "saturate_i64: inside");
    cover!(v > i128::from(i64::MAX), "saturate_i64: above");
}

/// `floor_div` (`ceil = false`) or `ceil_div` over `a in a.0..=a.1`, `b in
/// b.0..=b.1`.
pub fn div(a: (i128, i128), b: (i128, i128), ceil: bool, f: fn(i128, i128) -> i128) {
    declare(&["div: a negative dividend, inexact", "div: a positive dividend, inexact", "div: exact"]);
    let x = any_i128_in(a.0, a.1);
    let y = any_i128_in(b.0, b.1);
    assume(c::div_requires(x, y));
    let q = f(x, y);
    if ceil {
        assert!(c::ceil_div_ensures(x, y, q), "ceil_div: (q - 1) b < a ≤ q b");
    } else {
        assert!(c::floor_div_ensures(x, y, q), "floor_div: q b ≤ a < (q + 1) b");
    }
    cover!(x < 0 && x % y != 0, "div: a negative dividend, inexact");
    cover!(x > 0 && x % y != 0, "div: a positive dividend, inexact");
    cover!(x % y == 0, "div: exact");
}

/// `mul_tan_round` over `value in value.0..=value.1`, `h in h.0..=h.1`.
pub fn mul_tan_round(value: (i64, i64), h: (i64, i64), f: fn(i64, u32) -> Option<i64>) {
    declare(&[
        "mul_tan_round: refused, too long",
        "mul_tan_round: refused, beyond 89.5°",
        "mul_tan_round: negative",
        "mul_tan_round: rounded up",
        "mul_tan_round: rounded down",
    ]);
    let v = any_in(value.0, value.1);
    let half = u32::try_from(any_in(h.0, h.1)).unwrap_or(u32::MAX);
    let r = f(v, half);
    assert!(c::mul_tan_round_ensures(v, half, r), "mul_tan_round: round(value × T / 2^90), sign symmetric");
    let Some(r) = r else {
        cover!(
            v.unsigned_abs() > cycleref::units::MAX_LENGTH.unsigned_abs(),
            "mul_tan_round: refused, too long"
        );
        cover!(half > 179, "mul_tan_round: refused, beyond 89.5°");
        return;
    };
    let t = cycleref::tan::tan_q90(half).unwrap_or(0);
    let exact = u128::from(v.unsigned_abs()) * t;
    let back = u128::from(r.unsigned_abs()) << cycleref::tan::TAN_FRAC_BITS;
    cover!(v < 0 && r < 0, "mul_tan_round: negative");
    cover!(back > exact, "mul_tan_round: rounded up");
    cover!(back < exact, "mul_tan_round: rounded down");
}
