//! The half-degree tangent tables of `cycleref-spec` (`10^26`-scaled) and
//! `cycleref` (`2^90`-scaled), derived again independently, and the proof
//! that the rounded products both crates compute are exact.
//!
//! # Derivation
//!
//! Everything is big-integer fixed point with `DIGITS` = 100 decimal
//! places (the scale `S = 10^100`), no floating point:
//!
//! * `π = 16 atan(1/5) − 4 atan(1/239)` (Machin), each arctangent by its
//!   alternating series;
//! * `x = h π ÷ 360` for `h` = 0..=179;
//! * `sin x` and `cos x` by their Taylor series, `tan x = sin x ÷ cos x`.
//!
//! Every division truncates, so each step adds at most one unit in the last
//! place (ulp, `10^-100`). Bounding generously: the two arctangents take at
//! most 73 and 22 terms, so `π` is off by under 3 000 ulps and `x` by under
//! 1 500; with `x < 1.6`, the series of `sin` and `cos` are then off by
//! under `10^5` ulps; and the quotient amplifies that by at most
//! `(1 + tan x) ÷ cos x < 116 ÷ 0.0087 < 1.4 × 10^4`, so `tan x` is within
//! `ERR_ULPS` = `10^10` ulps (`10^-90`) of the truth. `derivation_error_bound`
//! confirms this against a run at 140 digits, and `closed_forms` against the
//! angles whose tangents are known in radicals.
//!
//! # Margin
//!
//! See `rounded_products_never_near_a_tie`.

use std::sync::OnceLock;

use num_bigint::{BigInt, BigUint};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Working precision in decimal places.
const DIGITS: u32 = 100;
/// Bound on the error of a derived tangent, in ulps of `10^-DIGITS`.
const ERR_ULPS: u64 = 10_000_000_000;
/// Number of table entries (`h` = 0..=179).
const ENTRIES: u32 = 180;
/// Largest factor the products must handle: 999 999 999.
const MAX_FACTOR: i64 = cycleref::units::MAX_LENGTH;

fn pow10(n: u32) -> BigInt {
    BigInt::from(10u32).pow(n)
}

/// `atan(1/n) × s`, by the alternating series, truncating every division.
fn atan_inv(n: u32, s: &BigInt) -> BigInt {
    let n2 = BigInt::from(n) * n;
    let mut power = s / n; // s / n^(2k+1)
    let mut sum = BigInt::zero();
    let mut k = 0u32;
    while !power.is_zero() {
        let term = &power / (2 * k + 1);
        if k % 2 == 0 {
            sum += term;
        } else {
            sum -= term;
        }
        power /= &n2;
        k += 1;
    }
    sum
}

/// `π × s` by Machin's formula.
fn pi(s: &BigInt) -> BigInt {
    atan_inv(5, s) * 16 - atan_inv(239, s) * 4
}

/// `(sin x × s, cos x × s)` for `0 ≤ x × s` (`x < 2`), by Taylor series.
fn sin_cos(x: &BigInt, s: &BigInt) -> (BigInt, BigInt) {
    let mut sin = BigInt::zero();
    let mut cos = BigInt::zero();
    let mut term = s.clone(); // x^n / n! × s
    let mut n = 0u32;
    while !term.is_zero() {
        match n % 4 {
            0 => cos += &term,
            1 => sin += &term,
            2 => cos -= &term,
            _ => sin -= &term,
        }
        n += 1;
        term = (&term * x) / (s * n);
    }
    (sin, cos)
}

/// `tan(h ÷ 2 °) × 10^digits` for every `h` in 0..=179, within `ERR_ULPS`
/// (for `digits` = 100).
fn derive_tangents(digits: u32) -> Vec<BigInt> {
    let s = pow10(digits);
    let pi = pi(&s);
    (0..ENTRIES)
        .map(|h| {
            let x = &pi * h / 360u32;
            let (sin, cos) = sin_cos(&x, &s);
            sin * &s / cos
        })
        .collect()
}

/// The derived tangents at `DIGITS` places, computed once.
fn tangents() -> &'static [BigInt] {
    static TANGENTS: OnceLock<Vec<BigInt>> = OnceLock::new();
    TANGENTS.get_or_init(|| derive_tangents(DIGITS))
}

fn scale() -> BigInt {
    pow10(DIGITS)
}

fn err() -> BigInt {
    BigInt::from(ERR_ULPS)
}

/// `round(t × m)` for a derived `t` (scale `10^DIGITS`), to nearest, after
/// checking the rounding is decidable: `t × m` is further than its error
/// `ERR_ULPS × m` ulps from a half-integer.
fn round_decidably(t: &BigInt, m: &BigInt, what: &str, h: u32) -> BigInt {
    let s = scale();
    let (q, r) = (t * m).div_mod_floor(&s);
    let twice_off_half: BigInt = (BigInt::from(2) * &r - &s).abs();
    assert!(
        twice_off_half > BigInt::from(2) * err() * m,
        "{what}: rounding of h = {h} is not decidable at {DIGITS} digits"
    );
    if BigInt::from(2) * r >= s {
        q + 1
    } else {
        q
    }
}

/// The correctly rounded `tan(h ÷ 2 °) × 10^26` of every `h`.
fn decimal_table() -> Vec<i128> {
    let m = pow10(cycleref_spec::tan::TAN_DECIMALS);
    (0..ENTRIES)
        .zip(tangents())
        .map(|(h, t)| round_decidably(t, &m, "10^26 table", h).to_i128().expect("fits i128"))
        .collect()
}

/// The correctly rounded `tan(h ÷ 2 °) × 2^90` of every `h`.
fn binary_table() -> Vec<u128> {
    let m = BigInt::one() << cycleref::tan::TAN_FRAC_BITS;
    (0..ENTRIES)
        .zip(tangents())
        .map(|(h, t)| round_decidably(t, &m, "2^90 table", h).to_u128().expect("fits u128"))
        .collect()
}

#[test]
fn tables_match_derivation() {
    let decimal = decimal_table();
    let binary = binary_table();
    for h in 0..ENTRIES {
        let i = h as usize;
        assert_eq!(cycleref_spec::tan::tan_half_degrees_scaled(h), Some(decimal[i]), "spec table, h = {h}");
        assert_eq!(cycleref::tan::tan_q90(h), Some(binary[i]), "engine table, h = {h}");
        let d = cycleref_spec::tan::tan_half_degrees(h).expect("in range");
        assert_eq!(d.scale(), cycleref_spec::tan::TAN_DECIMALS, "h = {h}");
        assert_eq!(d.mantissa(), decimal[i], "Decimal, h = {h}");
    }
    for h in [ENTRIES, ENTRIES + 1, u32::MAX] {
        assert_eq!(cycleref_spec::tan::tan_half_degrees_scaled(h), None);
        assert_eq!(cycleref_spec::tan::tan_half_degrees(h), None);
        assert_eq!(cycleref::tan::tan_q90(h), None);
        assert_eq!(cycleref_spec::tan::mul_tan_round(1, h), None);
        assert_eq!(cycleref::tan::mul_tan_round(1, h), None);
    }
}

#[test]
fn special_values() {
    assert_eq!(cycleref_spec::tan::tan_half_degrees_scaled(0), Some(0));
    assert_eq!(cycleref::tan::tan_q90(0), Some(0));
    assert_eq!(cycleref_spec::tan::tan_half_degrees_scaled(90), Some(10_i128.pow(26)));
    assert_eq!(cycleref::tan::tan_q90(90), Some(1u128 << 90));
    assert_eq!(cycleref_spec::tan::tan_half_degrees(90), Some(rust_decimal::Decimal::ONE));
    assert!(tangents()[0].is_zero(), "tan 0 is derived exactly");
    for v in [0, 1, -1, 7, -7, MAX_FACTOR, -MAX_FACTOR] {
        assert_eq!(cycleref_spec::tan::mul_tan_round(v, 0), Some(0));
        assert_eq!(cycleref::tan::mul_tan_round(v, 0), Some(0));
        assert_eq!(cycleref_spec::tan::mul_tan_round(v, 90), Some(v));
        assert_eq!(cycleref::tan::mul_tan_round(v, 90), Some(v));
    }
    for v in [MAX_FACTOR + 1, -MAX_FACTOR - 1, i64::MAX, i64::MIN] {
        for h in [0, 90, 179] {
            assert_eq!(cycleref_spec::tan::mul_tan_round(v, h), None, "v = {v}");
            assert_eq!(cycleref::tan::mul_tan_round(v, h), None, "v = {v}");
        }
    }
}

/// The derivation is within `ERR_ULPS` of a run at 140 digits, and
/// `tan x × tan(90° − x) = 1` holds within the combined error.
#[test]
fn derivation_error_bound() {
    let fine = derive_tangents(DIGITS + 40);
    let shift = pow10(40);
    let mut worst = BigInt::zero();
    for (t, f) in tangents().iter().zip(&fine) {
        // Both in ulps of 10^-140: the 100-digit error is |t·10^40 − f|.
        let off = (t * &shift - f).abs();
        worst = worst.max(off);
    }
    let worst_ulps = &worst / &shift;
    println!("largest difference from the 140-digit run: {worst_ulps} ulps of 1e-{DIGITS}");
    assert!(worst <= err() * &shift, "derivation off by {worst_ulps} ulps, more than {ERR_ULPS}");

    let s = scale();
    let t = tangents();
    for h in 1..ENTRIES {
        let (a, b) = (&t[h as usize], &t[(ENTRIES - h) as usize]);
        let off = (a * b - &s * &s).abs();
        let tolerance = err() * (a + b + err());
        assert!(off <= tolerance, "tan x · tan(90° − x) ≠ 1 at h = {h}");
    }
}

/// Angles whose tangents are known in radicals (15°, 18°, 22.5°, 30°, 36°,
/// 54°, 60°, 67.5°, 72°, 75°).
#[test]
fn closed_forms() {
    let s = scale();
    let root = |n: u32| (BigInt::from(n) * &s * &s).sqrt(); // √n × s, floor
    let (r2, r3, r5) = (root(2), root(3), root(5));
    // sqrt of a value given at scale s, result at scale s
    let sqrt_scaled = |v: &BigInt| (v * &s).sqrt();
    let five = BigInt::from(5);
    let cases: Vec<(u32, BigInt)> = vec![
        (30, &s * 2 - &r3),
        (36, sqrt_scaled(&(&s * 25 - &r5 * 10)) / &five),
        (45, &r2 - &s),
        (60, &r3 / 3u32),
        (72, sqrt_scaled(&(&s * 5 - &r5 * 2))),
        (108, sqrt_scaled(&(&s * 25 + &r5 * 10)) / &five),
        (120, r3.clone()),
        (135, &r2 + &s),
        (144, sqrt_scaled(&(&s * 5 + &r5 * 2))),
        (150, &s * 2 + &r3),
    ];
    for (h, closed) in cases {
        let off = (&tangents()[h as usize] - closed).abs();
        assert!(off <= err() + 100, "h = {h}: derived tangent off the closed form by {off} ulps");
    }
}

/// The partial quotients of every real in `[lo/s, hi/s]` agree up to the
/// convergent whose denominator first exceeds `qmax`. Returns `(p_k, q_k,
/// q_{k+1})` for the last convergent with `q_k ≤ qmax`, or `None` if the
/// interval is too wide to tell.
fn convergents_below(
    lo: &BigInt,
    hi: &BigInt,
    s: &BigInt,
    qmax: &BigInt,
) -> Option<(BigInt, BigInt, BigInt)> {
    let (mut an, mut ad) = (lo.clone(), s.clone());
    let (mut bn, mut bd) = (hi.clone(), s.clone());
    // p_{-2}, p_{-1}, q_{-2}, q_{-1}
    let (mut p0, mut p1) = (BigInt::zero(), BigInt::one());
    let (mut q0, mut q1) = (BigInt::one(), BigInt::zero());
    let mut k = 0u32;
    loop {
        if ad.is_zero() || bd.is_zero() {
            return None;
        }
        let a = an.div_floor(&ad);
        if a != bn.div_floor(&bd) {
            return None;
        }
        let p = &a * &p1 + &p0;
        let q = &a * &q1 + &q0;
        if &q > qmax {
            // q1 is q_k (k ≥ 1 so the best-approximation theorem applies).
            return (k >= 2).then_some((p1, q1, q));
        }
        (an, ad) = (ad.clone(), &an - &a * &ad);
        (bn, bd) = (bd.clone(), &bn - &a * &bd);
        (p0, p1) = (p1, p);
        (q0, q1) = (q1, q);
        k += 1;
    }
}

/// Formats `num ÷ 10^DIGITS` (positive) as `d.ddde-N`.
fn scientific(num: &BigInt) -> String {
    let digits = num.to_string();
    let exponent = i64::try_from(digits.len()).expect("short") - 1 - i64::from(DIGITS);
    format!("{}.{}e{exponent}", &digits[..1], &digits[1..4])
}

/// The margin proof: for every `h` in 1..=179 but 90 and every
/// `1 ≤ v ≤ 999_999_999`, `v × tan(h ÷ 2 °)` is more than `1e-15` from
/// every half-integer.
///
/// Let `t = tan(h ÷ 2 °)` (irrational for these `h`) and `p_k/q_k` the
/// last convergent of its continued fraction with `q_k ≤ Q = 2 ×
/// 999_999_999`. By the best-approximation theorem, every `1 ≤ q <
/// q_{k+1}` has `‖q t‖ ≥ |q_k t − p_k|` (`‖·‖` the distance to the nearest
/// integer). With `q = 2v ≤ Q < q_{k+1}`:
///
/// `|v t − (j + ½)| = |2v t − (2j + 1)| ÷ 2 ≥ ‖2v t‖ ÷ 2 ≥ |q_k t − p_k| ÷ 2`.
///
/// The convergents are computed for both ends of the interval `t ± 1e-90`
/// the derivation guarantees, and used only where they agree, so they are
/// those of the true `t`; the bound is the smaller of the two ends.
///
/// The spec's products are off by less than `1e9 × 0.5e-26 = 5e-18` and
/// the engine's by less than `2^30 × 2^-91 = 2^-61 ≈ 4.3e-19`, both far
/// below `1e-15`, so both round every product exactly. (For `h` = 0 and 90
/// the tangents are 0 and 1 and the tables hold them exactly.)
#[test]
fn rounded_products_never_near_a_tie() {
    let s = scale();
    let qmax = BigInt::from(2 * MAX_FACTOR);
    let threshold = pow10(DIGITS - 15); // 1e-15 at scale 10^DIGITS
    let mut smallest: Option<(BigInt, u32, BigInt)> = None;
    for h in (1..ENTRIES).filter(|&h| h != 90) {
        let t = &tangents()[h as usize];
        let (lo, hi) = (t - err(), t + err());
        let (p, q, q_next) = convergents_below(&lo, &hi, &s, &qmax)
            .unwrap_or_else(|| panic!("h = {h}: continued fraction not determined at {DIGITS} digits"));
        let at_lo = &q * &lo - &p * &s;
        let at_hi = &q * &hi - &p * &s;
        assert_eq!(at_lo.sign(), at_hi.sign(), "h = {h}: p_k/q_k inside the interval");
        // Distance to a half-integer, at scale 10^DIGITS: |q_k t − p_k| ÷ 2.
        let margin = at_lo.abs().min(at_hi.abs()) / 2;
        assert!(
            margin > threshold,
            "h = {h}: products may come within {} of a half-integer (q_k = {q}, q_k+1 = {q_next})",
            scientific(&margin)
        );
        if smallest.as_ref().is_none_or(|(m, _, _)| &margin < m) {
            smallest = Some((margin, h, q));
        }
    }
    let (margin, h, q) = smallest.expect("some angle");
    println!(
        "smallest margin: {} at h = {h} ({}°), q_k = {q}: no v·tan within it of a half-integer",
        scientific(&margin),
        f_angle(h)
    );
}

/// `h ÷ 2` as text, e.g. `"44.5"`.
fn f_angle(h: u32) -> String {
    if h % 2 == 0 {
        format!("{}", h / 2)
    } else {
        format!("{}.5", h / 2)
    }
}

/// `round(|v| × t)`, ties away from zero, for a derived `t` given as
/// `t128 = floor(t × 2^128)` (within `2^-127` of `t`): decided only when the
/// product is further than its error from a half-integer.
fn derived_round(magnitude: u64, t128: &BigUint) -> u64 {
    let product = t128 * magnitude;
    // The low 128 bits: the fraction, in units of 2^-128.
    let mut limbs = product.iter_u64_digits();
    let low = u128::from(limbs.next().unwrap_or(0));
    let fraction = low | u128::from(limbs.next().unwrap_or(0)) << 64;
    let whole = (product >> 128u32).to_u64().expect("fits u64");
    let half = 1u128 << 127;
    // Error of the product: below 2 × |v| units of 2^-128.
    let tolerance = u128::from(magnitude) * 2 + 1;
    assert!(fraction.abs_diff(half) > tolerance, "|v| = {magnitude}: product too close to a tie to decide");
    if fraction >= half {
        whole + 1
    } else {
        whole
    }
}

/// Both crates' products against the derived ones: v in 0..2000, the 1000
/// largest factors, and 10 000 pseudo-random factors per angle, each also
/// negated.
#[test]
fn products_match_derivation() {
    let s = scale();
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        i64::try_from((state >> 33) % 1_000_000_000).expect("small")
    };
    let mut checked = 0u64;
    for h in 0..ENTRIES {
        let t128 = ((&tangents()[h as usize] << 128u32) / &s).to_biguint().expect("non-negative");
        let mut values: Vec<i64> = (0..2000).chain(MAX_FACTOR - 999..=MAX_FACTOR).collect();
        values.extend((0..10_000).map(|_| next()));
        for v in values {
            let rounded = i64::try_from(derived_round(v.unsigned_abs(), &t128)).expect("fits i64");
            for (v, expected) in [(v, rounded), (-v, -rounded)] {
                let spec = cycleref_spec::tan::mul_tan_round(v, h);
                let engine = cycleref::tan::mul_tan_round(v, h);
                assert_eq!(spec, Some(expected), "spec, v = {v}, h = {h}");
                assert_eq!(engine, Some(expected), "engine, v = {v}, h = {h}");
                checked += 1;
            }
        }
    }
    println!("{checked} products checked");
}

/// `n` with `_` every three digits from the right.
fn grouped(n: &str) -> String {
    let mut out = String::new();
    for (i, c) in n.chars().enumerate() {
        if i > 0 && (n.len() - i) % 3 == 0 {
            out.push('_');
        }
        out.push(c);
    }
    out
}

/// Prints both tables as Rust, to paste into `spec/src/tan.rs` and
/// `impl/src/tan.rs`.
#[test]
#[ignore = "prints the tables to regenerate them"]
fn print_tables() {
    println!("const TAN_HALF_DEGREES: [i128; 180] = [");
    for (h, t) in (0..ENTRIES).zip(decimal_table()) {
        println!("    {}, // {}°", grouped(&t.to_string()), f_angle(h));
    }
    println!("];");
    println!();
    println!("const TAN_Q90: [u128; TAN_ENTRIES as usize] = [");
    for (h, t) in (0..ENTRIES).zip(binary_table()) {
        println!("    {}, // {}°", grouped(&t.to_string()), f_angle(h));
    }
    println!("];");
}
