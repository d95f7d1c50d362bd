//! The fast path of the LinuxCNC G76 engine (issue 33, reading R-FASTPATH):
//! its answers equal the interval arithmetic's, and it falls back rarely.
//!
//! * `peer_benchmark_program`: the 2 000 cycles of the `pipeline` peer
//!   benchmark (`benches/src/corpus.rs`, `linuxcnc_program`), each expanded
//!   with and without the fast path: the same moves, and the fallbacks
//!   counted per million values.
//! * `near_half_increments`: a proptest aimed at the rounding boundaries:
//!   a depth `J·n^(1/R)` shifted by a dyadic constant so that it lies a few
//!   ulps (of `2^-64`) from a half increment; the fast path's decision, when
//!   it decides, is the exact value's rounding (at 512 bits), and its bound
//!   holds.
//! * `spread_of_generated_depths`: the fallback rate over many depths of
//!   many depth laws (R with four decimals), the values the engine rounds.

use cycleref::engine::approx::{self, Approx};
use cycleref::engine::linuxcnc::{expand_linuxcnc_exact, FastPathStats};
use cycleref::engine::real::{power, Interval, Rounding, SLOW};
use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
use cycleref::{expand_linuxcnc, IncrementSystem, InputUnit, Lead, LeadWord, Move, Point, Units, XMode};
use proptest::prelude::*;

/// Cycle `i` of the peer benchmark's program: `G7 G0 X22 Z2`, then `G76
/// P1.5 Z-… I-2 J0.3 R1.5 K… Q29.5 H1 E1 L3` with Z over −20 … −30 mm
/// (41 values) and K over 1.84 … 1.92 mm (9 values).
fn peer_cycle(i: i64) -> LinuxCncG76 {
    let z = 2000 + (i % 41) * 25; // hundredths of a mm
    let k = 184 + i % 9;
    LinuxCncG76 {
        units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
        x_mode: XMode::Diameter,
        start: Point::new(220_000, 20_000),
        end: Point::new(220_000, -z * 100),
        pitch: Lead { word: LeadWord::K, mantissa: 15, scale: 1 },
        peak_offset: -20_000,
        initial_depth: 3_000,
        degression: 15_000,
        full_depth: k * 100,
        compound_angle: 295_000,
        spring_passes: 1,
        taper_distance: 10_000,
        entry_taper: true,
        exit_taper: true,
        pass_limit: 1_000_000,
    }
}

fn per_million(s: FastPathStats) -> f64 {
    s.fallbacks as f64 * 1e6 / s.values.max(1) as f64
}

#[test]
fn peer_benchmark_program() {
    let mut total = FastPathStats::default();
    let mut moves = 0;
    for i in 0..2_000 {
        let c = peer_cycle(i);
        let mut fast = expand_linuxcnc(&c).unwrap();
        let got: Vec<Move> = fast.by_ref().collect();
        let want: Vec<Move> = expand_linuxcnc_exact(&c).unwrap().collect();
        assert_eq!(got, want, "cycle {i}");
        let s = fast.fast_path_stats();
        total.values += s.values;
        total.fallbacks += s.fallbacks;
        moves += got.len();
        let exact = expand_linuxcnc_exact(&c).unwrap().fast_path_stats();
        assert_eq!(exact.values, exact.fallbacks, "the exact path decides nothing on the fast path");
    }
    println!(
        "peer program: {moves} moves, {} values, {} fallbacks ({:.1} per million)",
        total.values,
        total.fallbacks,
        per_million(total)
    );
    assert!(total.values > 100_000);
    // The program has no value within 2^-40 of a half increment: none.
    assert_eq!(total.fallbacks, 0);
}

/// `v·2^-64` exactly, at 512 fraction bits.
fn exact_of(v: i128) -> Interval<SLOW> {
    let x = Interval::<SLOW>::int(v).div_int(1 << 32).div_int(1 << 32);
    assert!(x.is_point());
    x
}

/// The exact `J·n^(a/b)` at 512 bits (computed at 576 and narrowed).
fn exact_depth(n: u64, a: u32, b: u32, j: i64) -> Interval<SLOW> {
    power::<{ SLOW + 1 }>(n, a, b).at_precision::<SLOW>().mul_int(j)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, ..ProptestConfig::default() })]

    /// A depth `J·n^(a/b)` minus a constant `c` chosen so that the value is
    /// `1/2 + δ` ulps of `2^-64`: the fast path decides only when `|δ|`
    /// exceeds its bound, and then as the exact value rounds.
    #[test]
    fn near_half_increments(
        n in 2_u64..2_000_000,
        degression in 10_001_u32..300_000,
        j in 1_i64..1_000_000,
        delta in -3_000_i128..3_000,
        far in any::<bool>(),
    ) {
        let d = approx::power(n, DEGRESSION_ONE, degression).mul_int(j);
        prop_assert_ne!(d, Approx::UNKNOWN);
        let exact = exact_depth(n, DEGRESSION_ONE, degression, j);
        // The bound holds: |v − x| ≤ e.
        let v = exact_of(d.value());
        let e = exact_of(i128::try_from(d.bound()).unwrap());
        prop_assert!(v.sub(&exact).sub(&e).sign() != Some(core::cmp::Ordering::Greater));
        prop_assert!(exact.sub(&v).sub(&e).sign() != Some(core::cmp::Ordering::Greater));
        // δ a few ulps, or a few bounds, from the boundary 1/2.
        let delta = if far { delta * i128::try_from(d.bound()).unwrap().max(1) / 1_000 } else { delta };
        let c = d.value() - (1_i128 << 63) - delta;
        let shifted = d.sub(&Approx::new(c, 0));
        let exact_shifted = exact.sub(&exact_of(c));
        let want = exact_shifted.round(Rounding::Nearest);
        match shifted.round_half_away() {
            Some(k) => {
                prop_assert_eq!(Some(k), want);
                prop_assert!(delta.unsigned_abs() > d.bound());
            }
            None => prop_assert!(delta.unsigned_abs() <= d.bound() + 1),
        }
    }
}

/// Many depth laws and depths, each value rounded as a coordinate (`δ` in
/// increments, and `δ/2` for G7): the fallback rate per million, and the
/// decided values against the exact ones.
#[test]
fn spread_of_generated_depths() {
    let (mut values, mut fallbacks) = (0_u64, 0_u64);
    let mut state = 0x6c63_6e63_u64;
    let mut next = |m: u64| {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (state >> 33) % m
    };
    for _ in 0..20_000 {
        let degression = 10_000 + u32::try_from(next(290_000)).unwrap();
        let j = 1 + i64::try_from(next(200_000)).unwrap();
        let n = 2 + next(60);
        let d = approx::power(n, DEGRESSION_ONE, degression).mul_int(j);
        for (value, xf) in [(d, 1_u64), (d.div_int(2), 2)] {
            values += 1;
            match value.round_half_away() {
                Some(k) => {
                    if values % 50 == 0 {
                        let exact = exact_depth(n, DEGRESSION_ONE, degression, j).div_int(xf);
                        assert_eq!(exact.round(Rounding::Nearest), Some(k), "{n} {degression} {j}");
                    }
                }
                None => fallbacks += 1,
            }
        }
    }
    let rate = fallbacks as f64 * 1e6 / values as f64;
    println!("generated depths: {values} values, {fallbacks} fallbacks ({rate:.1} per million)");
    assert!(rate < 10.0, "{rate} per million");
}
