//! The fast path of the G75.1 engine (issue 33, reading R-FASTPATH): its
//! answers equal the interval arithmetic's, and it falls back rarely.
//!
//! * `pipeline_g75_program`: the 2 000 grooves of the `pipeline`
//!   benchmark's G75.1-heavy program (`benches/src/corpus.rs`,
//!   `g75_program`), read by the reader and each expanded with and without
//!   the fast path: the same moves, and the fallbacks counted per million
//!   values.
//! * `generated_grooves`: grooves over the words' ranges (every corner kind,
//!   slopes, layers, angles of any 0.0001°, the exact ones often): the same
//!   result (moves or alarm) on both paths, and the fallback rate.
//! * `near_rounding_boundaries`: a proptest aimed at the boundaries: a
//!   value `j·sin x`, `j·cos x` or `j·cot x` shifted by a dyadic constant so
//!   that it lies a few ulps (of `2^-64`) from an integer (floor, ceil) or a
//!   half-integer (nearest); the fast path's decision, when it decides, is
//!   the exact value's rounding (at 512 bits), and its bound holds.
//!
//! The differential tests (`g75_equivalence.rs`) compare both paths on
//! every generated groove as well.

use cycleref::engine::approx::{self, Approx};
use cycleref::engine::g75::expand_g75_exact;
use cycleref::engine::linuxcnc::FastPathStats;
use cycleref::engine::real::{self, Interval, Rounding, SLOW};
use cycleref::g75::{Corner, CornerKind, G75Cycle, PathType};
use cycleref::{expand_g75, CycleError, IncrementSystem, InputUnit, Move, Point, Units, XMode};
use proptest::prelude::*;

fn per_million(s: FastPathStats) -> f64 {
    s.fallbacks as f64 * 1e6 / s.values.max(1) as f64
}

/// Both paths on `c`: the same result; the fast path's counts.
fn both(c: &G75Cycle) -> (Result<Vec<Move>, CycleError>, FastPathStats) {
    let (got, stats) = match expand_g75(c) {
        Ok(mut m) => {
            let v: Vec<Move> = m.by_ref().collect();
            (Ok(v), m.fast_path_stats())
        }
        Err(e) => (Err(e), FastPathStats::default()),
    };
    let want: Result<Vec<Move>, CycleError> = expand_g75_exact(c).map(Iterator::collect);
    assert_eq!(got, want, "{c:?}");
    if let Ok(m) = expand_g75_exact(c) {
        assert_eq!(m.fast_path_stats().values, 0, "the exact path takes no fast decision");
    }
    (got, stats)
}

/// The G75.1-heavy program of the `pipeline` benchmark, as
/// `benches/src/corpus.rs` writes it (GSK 980TDi, IS-B).
fn g75_program(grooves: usize) -> String {
    let mut s = String::from("O0200;\nG50 X100 Z50;\nM03 S500;\n");
    for i in 0..grooves {
        let z = 3000 - (i % 40) * 25;
        let (zi, zf) = (z / 100, z % 100);
        s.push_str(&format!(
            "G00 X60 Z{zi}.{zf:02};\nG75.1 X50 Z{zi}.{zf:02} P3000 Q5000 H-20 D-10 A45 B30;\nG75.1 R0.5 I4 J1;\n"
        ));
    }
    s.push_str("G00 X100 Z50;\nM30;\n");
    s
}

#[test]
fn pipeline_g75_program() {
    let text = g75_program(2_000);
    let m = cycleref_spec::Machine::new(cycleref_spec::ProfileName::Gsk980);
    let program = cycleref_spec::read(&text, &m).unwrap();
    let (mut total, mut grooves, mut moves) = (FastPathStats::default(), 0, 0);
    for call in program.grooves() {
        let (got, s) = both(&call.cycle);
        moves += got.unwrap().len();
        total.values += s.values;
        total.fallbacks += s.fallbacks;
        grooves += 1;
    }
    println!(
        "pipeline G75.1 program: {grooves} grooves, {moves} moves, {} values, {} fallbacks ({:.1} per million)",
        total.values,
        total.fallbacks,
        per_million(total)
    );
    assert_eq!(grooves, 2_000);
    assert!(total.values >= 20_000);
    // 45° and 30° flanks, no value near a boundary: none falls back.
    assert_eq!(total.fallbacks, 0);
}

/// A fixed-seed generator (a 64-bit LCG).
struct Rng(u64);

impl Rng {
    fn next(&mut self, m: u64) -> u64 {
        self.0 = self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 33) % m
    }

    /// An angle in `lo..=hi` (0.0001°), one in four an exact one.
    fn angle(&mut self, lo: u32, hi: u32) -> u32 {
        const EXACT: [u32; 6] = [150_000, 300_000, 450_000, 600_000, 750_000, 900_000];
        if self.next(4) == 0 {
            let a = EXACT[usize::try_from(self.next(6)).unwrap()];
            if (lo..=hi).contains(&a) {
                return a;
            }
        }
        lo + u32::try_from(self.next(u64::from(hi - lo) + 1)).unwrap()
    }

    fn size(&mut self, lo: i64, hi: i64) -> i64 {
        lo + i64::try_from(self.next(u64::try_from(hi - lo).unwrap().max(1))).unwrap()
    }
}

/// Grooves over the words' ranges, from a fixed-seed generator: both paths
/// agree, and the fast path falls back rarely.
#[test]
fn generated_grooves() {
    let mut rng = Rng(0x6737_3531);
    let (mut total, mut valid, mut refused) = (FastPathStats::default(), 0, 0);
    for _ in 0..3_000 {
        let (a, b) = (rng.angle(1, 900_000), rng.angle(1, 900_000));
        let l = if rng.next(2) == 0 { 0 } else { rng.angle(0, 899_999) };
        let max = if rng.next(2) == 0 { 200 } else { 20_000 };
        let depth = rng.size(1, max);
        let width = rng.size(0, max);
        let corners = [0; 4].map(|_| {
            let size = match rng.next(3) {
                0 => 0,
                1 => rng.size(1, max / 50 + 2),
                _ => rng.size(1, max / 10 + 2),
            };
            let kind = if rng.next(2) == 0 { CornerKind::Round } else { CornerKind::Chamfer };
            Corner { size, kind }
        });
        let c = G75Cycle {
            units: Units {
                system: if rng.next(2) == 0 { IncrementSystem::IsB } else { IncrementSystem::IsC },
                unit: InputUnit::Metric,
            },
            x_mode: if rng.next(2) == 0 { XMode::Diameter } else { XMode::Radius },
            from: Point::new(48_000, 500),
            start: Point::new(50_000, 1_000),
            peck: rng.size(1, max / 10 + 2),
            step: rng.size(1, max / 10 + 2),
            depth: -depth,
            width: -width,
            flank_a: a,
            flank_b: b,
            slope: l,
            retract: rng.size(0, 200),
            layer: if rng.next(2) == 0 { None } else { Some(rng.size(1, max)) },
            allowance_x: if rng.next(2) == 0 { 0 } else { rng.size(0, max / 8 + 1) },
            allowance_z: if rng.next(2) == 0 { 0 } else { rng.size(0, max / 8 + 1) },
            tool_width: if rng.next(2) == 0 { None } else { Some(rng.size(0, max / 2 + 1)) },
            path: match rng.next(3) {
                0 => PathType::Rough,
                1 => PathType::RoughAndFinish,
                _ => PathType::Finish,
            },
            corners,
            // R-G75CHAMFER `axial-width` on half the grooves: its tangent
            // lengths are quotients on the fast path.
            readings: cycleref::G75Readings {
                chamfer_axial_width: rng.next(2) == 0,
                ..cycleref::G75Readings::DEFAULT
            },
        };
        let (got, s) = both(&c);
        if got.is_ok() {
            valid += 1;
        } else {
            refused += 1;
        }
        total.values += s.values;
        total.fallbacks += s.fallbacks;
    }
    let rate = per_million(total);
    println!(
        "generated grooves: {valid} valid, {refused} refused; {} values, {} fallbacks ({rate:.0} per million)",
        total.values, total.fallbacks
    );
    assert!(valid > 500, "{valid} valid grooves");
    // Fallbacks come from values exactly on a boundary (the exact angles'
    // identities, R-G75TIE) and the rare value within 2^-40 of one.
    assert!(rate < 20_000.0, "{rate} per million");
}

/// `v·2^-64` exactly, at 512 fraction bits.
fn exact_of(v: i128) -> Interval<SLOW> {
    let x = Interval::<SLOW>::int(v).div_int(1 << 32).div_int(1 << 32);
    assert!(x.is_point());
    x
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2_000, ..ProptestConfig::default() })]

    /// `j·f(k·0.00005°)` for f = sin, cos, cot, shifted by a constant `c` so
    /// that it lies `δ` ulps from a rounding boundary: the fast path decides
    /// only when `|δ|` exceeds its bound, and then as the exact value rounds.
    #[test]
    fn near_rounding_boundaries(
        k in 1_u32..1_800_000,
        which in 0_u8..3,
        j in 1_i64..1_000_000,
        delta in -3_000_i128..3_000,
        nearest in any::<bool>(),
    ) {
        let (s, c) = approx::sin_cos(k);
        let (es, ec) = real::sin_cos::<{ SLOW + 1 }>(k);
        let (a, x) = match which {
            0 => (s, es),
            1 => (c, ec),
            _ => (approx::cot_of(k, &s, &c), real::cot_of(k, &es, &ec)),
        };
        let (a, x) = (a.mul_int(j), x.at_precision::<SLOW>().mul_int(j));
        prop_assume!(!a.is_unknown());
        // The bound holds: |v − x| ≤ e.
        let (v, e) = (exact_of(a.value()), exact_of(i128::try_from(a.bound()).unwrap()));
        prop_assert!(v.sub(&x).sub(&e).sign() != Some(core::cmp::Ordering::Greater));
        prop_assert!(x.sub(&v).sub(&e).sign() != Some(core::cmp::Ordering::Greater));
        // The boundary: 1/2 (nearest) or 0 (floor, ceil), δ ulps below the value.
        let boundary = if nearest { 1_i128 << 63 } else { 0 };
        let shift = a.value() - boundary - delta;
        let (shifted, exact) = (a.sub(&Approx::new(shift, 0)), x.sub(&exact_of(shift)));
        for r in [Rounding::Floor, Rounding::Ceil, Rounding::Nearest] {
            let want = exact.round(r);
            match shifted.round(r) {
                Some(got) => prop_assert_eq!(Some(got), want),
                None => prop_assert!(
                    delta.unsigned_abs() <= shifted.bound() + 1 || (r == Rounding::Nearest) != nearest
                ),
            }
        }
    }
}
