//! The kernels' contracts under `cargo test`: each body of
//! `cycleref_proofs::contracts` (shared with its `proof_for_contract`
//! harness) checks requires ⇒ ensures exhaustively over a small window,
//! then sampled over the Kani window and over large values; a broken
//! kernel is caught by the assertion's own text.

use std::panic::catch_unwind;

use cycleref::engine::arith;
use cycleref_proofs::contracts;
use cycleref_proofs::harness;
use cycleref_proofs::shim::{self, check_and_print as check, Mode};
use cycleref_proofs::windows::{
    DIV_WINDOW, ISQRT_NEAR_WINDOW, ISQRT_WINDOW, MUL_TAN_WINDOW, ROUND_DIV_WINDOW, SATURATE_WINDOW,
};

const fn sample(seed: u64) -> Mode {
    Mode::Sample { runs: 100_000, seed }
}

/// Values near ±2^bits for every bit length: the carries and the
/// magnitudes uniform sampling misses.
fn near_powers(below: u32, mut body: impl FnMut(i128, i128)) {
    for bits in 0..below {
        let p = 1_i128 << bits;
        body(p - 3, p + 3);
        body(-p - 3, -p + 3);
    }
}

#[test]
fn isqrt_floor_contract() {
    let f = arith::isqrt_floor;
    check("isqrt_floor (exhaustive 0..=2^16)", Mode::Exhaustive { max_runs: 1 << 17 }, || {
        contracts::isqrt_floor(0, 1 << 16, f);
    });
    check("isqrt_floor (sampled window, x < 2^62)", sample(1), || {
        contracts::isqrt_floor(ISQRT_WINDOW.0, ISQRT_WINDOW.1, f)
    });
    for bits in 17..62 {
        let p = 1_u128 << bits;
        shim::check("isqrt_floor (near 2^bits)", Mode::Enumerate { max_runs: 16 }, || {
            contracts::isqrt_floor(p - 3, p + 3, f);
        });
    }
    shim::check("isqrt_floor (the top of its range)", Mode::Enumerate { max_runs: 16 }, || {
        contracts::isqrt_floor(ISQRT_WINDOW.1 - 5, ISQRT_WINDOW.1, f);
    });
}

/// The body of `round_sqrt_near`'s `proof_for_contract` over its exact
/// window (every `x < 2^62`, every guess), sampled; exhaustively over
/// small values and every guess near the root; and around large squares
/// with guesses within and beyond the corrections.
#[test]
fn round_sqrt_near_contract() {
    let f = arith::round_sqrt_near;
    let (x, guess) = ISQRT_NEAR_WINDOW;
    check("round_sqrt_near (sampled window)", sample(2), || contracts::round_sqrt_near(x.0, x.1, guess, f));
    check(
        "round_sqrt_near (exhaustive x ≤ 2^10, guess ≤ 40)",
        Mode::Exhaustive { max_runs: 50_000 },
        || {
            contracts::round_sqrt_near(0, 1 << 10, (0, 40), f);
        },
    );
    // s² ± s, the rounding's edges; s ≤ 2^31 - 1 keeps x < 2^62.
    for bits in 1..31 {
        let s = 1_u128 << bits;
        for x in [s * s - s, s * s + s] {
            shim::check("round_sqrt_near (around s² ± s)", Mode::Exhaustive { max_runs: 200 }, || {
                contracts::round_sqrt_near(x - 1, x + 1, (s.saturating_sub(8), s + 8), f);
            });
        }
    }
    // The largest root of the window: √(2^62 - 1) < 2^31, guesses at and
    // beyond the clamp at 2^31.
    shim::check("round_sqrt_near (the top of its range)", Mode::Exhaustive { max_runs: 200 }, || {
        contracts::round_sqrt_near(x.1 - 2, x.1, ((1 << 31) - 8, (1 << 31) + 8), f);
    });
}

/// A kernel that returns its guess unchecked is caught by the body of
/// `round_sqrt_near`'s contract.
#[test]
fn a_guess_taken_unchecked_is_caught() {
    let mode = Mode::Exhaustive { max_runs: 1 << 12 };
    let failure = catch_unwind(|| {
        check("mutant", mode, || contracts::round_sqrt_near(0, 1 << 5, (0, 40), |_, g| g));
    })
    .expect_err("a guess taken unchecked must be caught");
    let text = failure.downcast_ref::<String>().cloned().unwrap_or_default();
    assert!(text.ends_with("round_sqrt_near: the contract of round_sqrt"), "{text}");
}

#[test]
fn round_sqrt_contract_is_p8() {
    // P8 (`harness::isqrt_rounds`) is round_sqrt's proof_for_contract; its
    // exhaustive run is in harnesses.rs. Here: the squares' neighbours.
    // s² + s + 2 < 2^62 (the contract's range) for s ≤ 2^30.
    for bits in 1..=30 {
        let s = 1_u128 << bits;
        shim::check("round_sqrt (around s² ± s)", Mode::Enumerate { max_runs: 16 }, || {
            harness::isqrt_rounds(s * s - s - 2, s * s - s + 2, arith::round_sqrt);
        });
        shim::check("round_sqrt (around s² + s)", Mode::Enumerate { max_runs: 16 }, || {
            harness::isqrt_rounds(s * s + s - 2, s * s + s + 2, arith::round_sqrt);
        });
    }
}

#[test]
fn round_div_contract() {
    let f = arith::round_div;
    check("round_div (exhaustive |num| ≤ 60, |den| ≤ 12)", Mode::Exhaustive { max_runs: 4_000 }, || {
        contracts::round_div((-60, 60), (-12, 12), f);
    });
    let (num, den) = ROUND_DIV_WINDOW;
    check("round_div (sampled window)", sample(2), || contracts::round_div(num, den, f));
    check("round_div (sampled, small divisors)", sample(3), || {
        contracts::round_div(num, (-1_000, 1_000), f);
    });
    near_powers(67, |lo, hi| {
        shim::check("round_div (near powers)", Mode::Enumerate { max_runs: 200 }, || {
            contracts::round_div((lo, hi), (-7, 7), f);
        });
    });
}

#[test]
fn saturate_i64_contract() {
    let f = arith::saturate_i64;
    let (min, max) = (i128::from(i64::MIN), i128::from(i64::MAX));
    for (lo, hi) in [(-50, 50), (min - 20, min + 20), (max - 20, max + 20)] {
        check("saturate_i64 (exhaustive)", Mode::Exhaustive { max_runs: 200 }, || {
            contracts::saturate_i64(lo.min(-1 << 70), lo.min(-1 << 70), f);
            contracts::saturate_i64(lo, hi, f);
            contracts::saturate_i64(hi.max(1 << 70), hi.max(1 << 70), f);
        });
    }
    check("saturate_i64 (sampled)", sample(4), || {
        contracts::saturate_i64(SATURATE_WINDOW.0, SATURATE_WINDOW.1, f)
    });
}

#[test]
fn floor_and_ceil_div_contracts() {
    for (ceil, f) in [(false, arith::floor_div as fn(i128, i128) -> i128), (true, arith::ceil_div)] {
        check("div (exhaustive |a| ≤ 60, b ≤ 12)", Mode::Exhaustive { max_runs: 2_000 }, || {
            contracts::div((-60, 60), (1, 12), ceil, f);
        });
        check("div (sampled window)", sample(5), || contracts::div(DIV_WINDOW.0, DIV_WINDOW.1, ceil, f));
        check("div (sampled, small divisors)", sample(6), || {
            contracts::div(DIV_WINDOW.0, (1, 1_000), ceil, f);
        });
        near_powers(72, |lo, hi| {
            shim::check("div (near powers)", Mode::Enumerate { max_runs: 100 }, || {
                contracts::div((lo, hi), (1, 7), ceil, f);
            });
        });
    }
}

#[test]
fn mul_tan_round_contract() {
    let f = cycleref::tan::mul_tan_round;
    check(
        "mul_tan_round (exhaustive |v| ≤ 40, every h ≤ 181)",
        Mode::Exhaustive { max_runs: 20_000 },
        || {
            // The limit: the largest accepted length and the first refused.
            let v = match cycleref_proofs::verify::any_in(0, 2) {
                0 => cycleref_proofs::verify::any_in(-40, 40),
                1 => cycleref::units::MAX_LENGTH,
                _ => -cycleref::units::MAX_LENGTH - 1,
            };
            contracts::mul_tan_round((v, v), (0, 181), f);
        },
    );
    check("mul_tan_round (sampled window)", sample(7), || {
        contracts::mul_tan_round(MUL_TAN_WINDOW.0, MUL_TAN_WINDOW.1, f)
    });
    let max = cycleref::units::MAX_LENGTH;
    check("mul_tan_round (sampled, accepted)", sample(8), || {
        contracts::mul_tan_round((-max, max), (0, 179), f)
    });
}

/// Each body catches a broken kernel by its assertion's text, and passes
/// with the real kernel on the same window (the controls above).
#[test]
fn broken_kernels_are_caught() {
    fn caught(body: impl Fn() + std::panic::RefUnwindSafe, text: &str) {
        let failure = catch_unwind(|| shim::check("mutant", Mode::Exhaustive { max_runs: 4_000 }, &body))
            .expect_err("the mutant must be caught");
        let got = failure.downcast_ref::<String>().cloned().unwrap_or_default();
        assert!(got.ends_with(text), "{got}");
    }
    // Truncating division instead of rounding.
    caught(
        || contracts::round_div((-60, 60), (-12, 12), |n, d| n / d),
        "the nearest integer, ties away from zero",
    );
    // Ties to even would be another rounding: ties towards zero here.
    caught(
        || {
            contracts::round_div((-60, 60), (1, 12), |n, d| {
                (2 * n + d.signum() * n.signum() * (d - 1)) / (2 * d)
            })
        },
        "the nearest integer, ties away from zero",
    );
    // Truncation instead of floor.
    caught(|| contracts::div((-60, 60), (1, 12), false, |a, b| a / b), "floor_div: q b ≤ a < (q + 1) b");
    caught(|| contracts::div((-60, 60), (1, 12), true, arith::floor_div), "ceil_div: (q - 1) b < a ≤ q b");
    // A wrapping narrowing.
    #[allow(clippy::cast_possible_truncation)]
    caught(
        || contracts::saturate_i64(1 << 63, (1 << 63) + 3, |v| v as i64),
        "saturate_i64: v, or the bound on its side",
    );
    // Rounding the root down.
    caught(|| contracts::isqrt_floor(0, 200, arith::round_sqrt), "isqrt_floor: s² ≤ x < (s + 1)²");
    // A tangent product truncated instead of rounded.
    caught(
        || {
            contracts::mul_tan_round((0, 40), (0, 179), |v, h| {
                let t = cycleref::tan::tan_q90(h)?;
                i64::try_from((u128::from(v.unsigned_abs()) * t) >> 90).ok()
            });
        },
        "mul_tan_round: round(value × T / 2^90), sign symmetric",
    );
}
