//! The exact real arithmetic of the G75.1 reference model
//! (`cycleref_spec::real`) and smoke tests of the model itself
//! (`cycleref_spec::g75`): trigonometric values against known decimals and
//! against the independently derived half-degree tangent table, the exact
//! rational cases, the rounding decisions at ties, the boundary rule
//! R-G75TIE (values that 512 fraction bits leave on exactly one rounding
//! boundary) and the refusal of an enclosure holding two, the seed's and
//! the slope example expanding without error, the rough contour's top
//! points on the region's boundary, and the order of the alarms.
//!
//! The golden, hand-worked expansions are in `g75_golden.rs` (written
//! independently); nothing here fixes a full move list.

use std::cmp::Ordering;
use std::collections::HashMap;

use cycleref::error::{CycleError, Field, GrooveEdge};
use cycleref::g75::{corner, Corner, CornerKind, G75Cycle, PathType, MAX_PECKS};
use cycleref::moves::{Motion, Role};
use cycleref::units::{IncrementSystem, InputUnit, Point, Units, XMode};
use cycleref_spec::g75;
use cycleref_spec::real::{Rational, Real, RIGHT_ANGLE};
use num_bigint::BigInt;
use proptest::prelude::*;

/// `deg` degrees in the unit of `real` (0.00005°).
const fn deg(d: u32) -> u32 {
    d * 20_000
}

#[test]
fn trig_values_against_known_decimals() {
    // sin 1° = 0.017452406437283512819418978516316…
    assert_eq!(Real::sin(deg(1)).to_decimal(30).unwrap(), "0.017452406437283512819418978516");
    // cos 45° = 0.70710678118654752440084436210485…
    assert_eq!(Real::cos(deg(45)).to_decimal(30).unwrap(), "0.707106781186547524400844362104");
    // tan 30° = 0.57735026918962576450914878050196…
    assert_eq!(Real::tan(deg(30)).to_decimal(30).unwrap(), "0.577350269189625764509148780501");
    // cot 60° = tan 30°.
    assert_eq!(Real::cot(deg(60)).to_decimal(30).unwrap(), "0.577350269189625764509148780501");
    // sin 60° = √3/2 = 0.86602540378443864676372317075294…
    assert_eq!(Real::sin(deg(60)).to_decimal(30).unwrap(), "0.866025403784438646763723170752");
    // cos 89.99995° = sin(0.00005°) = 8.726646259970540264423827…e-7
    assert_eq!(Real::cos(RIGHT_ANGLE - 1).to_decimal(22).unwrap(), "0.0000008726646259970540");
    // tan 0.00005° = 8.726646259973863125…e-7 and cot 0.00005° =
    // 1145915.5902613555293… (the smallest angle: half of A0.0001).
    assert_eq!(Real::tan(1).to_decimal(22).unwrap(), "0.0000008726646259973863");
    assert_eq!(Real::cot(1).to_decimal(6).unwrap(), "1145915.590261");
}

#[test]
fn enclosures_are_narrow_and_contain_the_value() {
    let s = Real::sin(deg(1));
    for bits in [64, 128, 256, 512] {
        let iv = s.enclose(bits).unwrap();
        assert_eq!(iv.bits(), bits);
        // At most a few units of the last place wide.
        assert!(iv.width() <= Rational::new(4, BigInt::from(1) << bits), "{bits}: {:?}", iv.width());
        let known = Rational::new(17_452_406_437_283_512_819_i128, BigInt::from(10).pow(21));
        assert!(iv.lower() <= Rational::new(17_452_406_437_283_513_i128, BigInt::from(10).pow(18)));
        assert!(iv.upper() >= known);
    }
}

#[test]
fn tangents_agree_with_the_half_degree_table() {
    // spec::tan's table was derived independently (decimal fixed point,
    // `spec/tests/tan_tables.rs`): round(tan(h/2 °) × 10^26).
    let scale = Real::int(BigInt::from(10).pow(26));
    for h in 0..180_u32 {
        let entry = cycleref_spec::tan::tan_half_degrees_scaled(h).unwrap();
        let v = (Real::tan(h * 10_000) * &scale).nearest().unwrap();
        assert_eq!(v, BigInt::from(entry), "tan({h}/2 °)");
    }
}

#[test]
fn pythagoras_holds_to_the_last_bit() {
    for k in [1, 7, 20_000, 123_457, 600_000, 900_000, 1_200_001, 1_799_999] {
        let (s, c) = (Real::sin(k), Real::cos(k));
        let one = &s * &s + &c * &c;
        let iv = one.enclose(256).unwrap();
        assert!(iv.lower() <= Rational::one() && iv.upper() >= Rational::one(), "k = {k}");
        assert!(iv.width() < Rational::new(1, BigInt::from(1) << 250), "k = {k}");
        let t = Real::tan(k) * Real::cot(k);
        let iv = t.enclose(256).unwrap();
        assert!(iv.lower() <= Rational::one() && iv.upper() >= Rational::one(), "k = {k}");
    }
}

#[test]
fn exact_rational_cases() {
    let half = Rational::new(1, 2);
    let cases: [(Real, Rational); 10] = [
        (Real::sin(0), Rational::zero()),
        (Real::sin(deg(30)), half.clone()),
        (Real::sin(deg(90)), Rational::one()),
        (Real::cos(0), Rational::one()),
        (Real::cos(deg(60)), half),
        (Real::cos(deg(90)), Rational::zero()),
        (Real::tan(0), Rational::zero()),
        (Real::tan(deg(45)), Rational::one()),
        (Real::cot(deg(45)), Rational::one()),
        (Real::cot(deg(90)), Rational::zero()),
    ];
    for (i, (v, r)) in cases.iter().enumerate() {
        assert_eq!(v.as_exact(), Some(r), "case {i}");
    }
    // Everything else is held as an expression, even at 60° and 30°.
    for v in [Real::sin(deg(60)), Real::cos(deg(30)), Real::tan(deg(60)), Real::cot(deg(30)), Real::sin(1)] {
        assert!(!v.is_exact());
    }
    // Arithmetic on exact values stays exact; 0 · x is exact 0.
    let v = Real::ratio(7, 3) * Real::cot(deg(45)) + Real::sin(deg(30));
    assert_eq!(v.as_exact(), Some(&Rational::new(17, 6)));
    assert_eq!((Real::int(0) * Real::sin(1)).as_exact(), Some(&Rational::zero()));
    assert!((Real::int(2) * Real::sin(1)).as_exact().is_none());
}

#[test]
fn exact_ties_round_up() {
    let n = |v: Real| v.nearest().unwrap();
    assert_eq!(n(Real::ratio(5, 2)), BigInt::from(3));
    assert_eq!(n(Real::ratio(-5, 2)), BigInt::from(-2));
    assert_eq!(n(Real::ratio(1, 2)), BigInt::from(1));
    assert_eq!(n(Real::ratio(-1, 2)), BigInt::from(0));
    assert_eq!(n(Real::ratio(7, 3)), BigInt::from(2));
    assert_eq!(n(Real::ratio(-7, 3)), BigInt::from(-2));
    // Y odd on a diameter lathe at 45°: (Y/f)·cot 45° = 100000.5 → 100001.
    assert_eq!(n(Real::ratio(200_001, 2) * Real::cot(deg(45))), BigInt::from(100_001));
    assert_eq!(Real::ratio(200_001, 2).floor().unwrap(), BigInt::from(100_000));
    assert_eq!(Real::ratio(200_001, 2).ceil().unwrap(), BigInt::from(100_001));
    assert_eq!(Real::int(-4).floor().unwrap(), BigInt::from(-4));
    assert_eq!(Real::int(-4).ceil().unwrap(), BigInt::from(-4));
}

#[test]
fn irrational_roundings_are_decided() {
    // √3 = 3 tan 30° = 1.732…; 100000 √3 = 173205.0807…
    let r3 = Real::int(3) * Real::tan(deg(30));
    assert_eq!(r3.floor().unwrap(), BigInt::from(1));
    assert_eq!(r3.ceil().unwrap(), BigInt::from(2));
    assert_eq!(r3.nearest().unwrap(), BigInt::from(2));
    let big = Real::int(100_000) * Real::cot(deg(30));
    assert_eq!(big.nearest().unwrap(), BigInt::from(173_205));
    assert_eq!((-&big).nearest().unwrap(), BigInt::from(-173_205));
    assert_eq!((-&big).floor().unwrap(), BigInt::from(-173_206));
    // 1/2 + 10^-30 is above the tie, decided only beyond 64 bits.
    let near_tie = Real::ratio(1, 2) + Real::ratio(1, BigInt::from(10).pow(30)) * Real::sin(deg(90) - 1);
    assert_eq!(near_tie.nearest().unwrap(), BigInt::from(1));
    let below = Real::ratio(1, 2) - Real::ratio(1, BigInt::from(10).pow(30)) * Real::sin(1);
    assert_eq!(below.nearest().unwrap(), BigInt::from(0));
    assert_eq!(below.compare(&Real::ratio(1, 2)).unwrap(), Ordering::Less);
}

#[test]
fn max_and_min_round_without_deciding_equal_branches() {
    // Two expressions of the same irrational number: their comparison is
    // undecidable, the rounding of their max is not.
    // (Their comparison is equal by R-G75TIE: no precision separates them.)
    let a = Real::int(3) * Real::tan(deg(30));
    let b = Real::cot(deg(30));
    assert_eq!(a.compare(&b), Ok(Ordering::Equal));
    assert_eq!(a.max(&b).ceil().unwrap(), BigInt::from(2));
    assert_eq!(a.min(&b).floor().unwrap(), BigInt::from(1));
    assert_eq!(Real::ratio(1, 3).max(&Real::ratio(1, 2)).as_exact(), Some(&Rational::new(1, 2)));
}

#[test]
fn an_exact_integer_in_irrational_form_lies_on_its_boundary() {
    // 4 sin²60° − 3 = 0 exactly, but only as an expression of √3: no
    // precision decides its floor or sign. R-G75TIE (docs/G75.md §6): its
    // 512-bit enclosure holds exactly one boundary, so it lies on it.
    let s = Real::sin(deg(60));
    let zero = Real::int(4) * &s * &s - Real::int(3);
    let iv = zero.enclose(512).unwrap();
    assert!(iv.lower() < Rational::zero() && iv.upper() > Rational::zero(), "{iv:?}");
    assert_eq!(zero.floor(), Ok(BigInt::from(0)));
    assert_eq!(zero.ceil(), Ok(BigInt::from(0)));
    assert_eq!(zero.sign(), Ok(Ordering::Equal));
    assert_eq!(zero.compare(&Real::int(0)), Ok(Ordering::Equal));
    // Shifted onto other boundaries: floor(k) = ceil(k) = k, and the
    // nearest of k + 1/2 is k + 1 (a tie goes up), also below zero.
    let seven = &zero + Real::int(7);
    assert_eq!((seven.floor(), seven.ceil()), (Ok(BigInt::from(7)), Ok(BigInt::from(7))));
    let minus_seven = &zero - Real::int(7);
    assert_eq!((minus_seven.floor(), minus_seven.ceil()), (Ok(BigInt::from(-7)), Ok(BigInt::from(-7))));
    assert_eq!((&zero + Real::ratio(5, 2)).nearest(), Ok(BigInt::from(3)));
    assert_eq!((&zero - Real::ratio(5, 2)).nearest(), Ok(BigInt::from(-2)));
    // Away from a half-integer, the nearest needs no rule.
    assert_eq!(zero.nearest(), Ok(BigInt::from(0)));
    // An alarm comparison of equal values: not greater (a corner that just
    // fits is accepted).
    assert_eq!(Real::int(4).compare(&(Real::int(4) + &zero)), Ok(Ordering::Equal));
}

#[test]
fn the_boundary_rule_comes_after_the_512_bit_evaluation() {
    // R-G75TIE applies only to what 512 fraction bits leave undecided: a
    // value 2⁻⁴⁸⁰ below a boundary is decided as below it (the rule would
    // put it on the boundary).
    let tiny = |bits: u32| Real::ratio(1, BigInt::from(1) << bits) * Real::sin(deg(90) - 1);
    let below_half = Real::ratio(1, 2) - tiny(480);
    assert_eq!(below_half.nearest(), Ok(BigInt::from(0)));
    assert_eq!(below_half.compare(&Real::ratio(1, 2)), Ok(Ordering::Less));
    let below_three = Real::int(3) - tiny(480);
    assert_eq!(below_three.floor(), Ok(BigInt::from(2)));
    assert_eq!((Real::int(3) + tiny(480)).ceil(), Ok(BigInt::from(4)));
    // 2⁻⁵³⁰ is beyond 512 bits: the enclosure holds the boundary and the
    // value is taken to lie on it, the case docs/G75.md accepts as the
    // rule's only failure ("within about 2⁻⁵⁰⁰ increments of a boundary
    // without lying on it").
    assert_eq!((Real::ratio(1, 2) - tiny(530)).nearest(), Ok(BigInt::from(1)));
    assert_eq!((Real::int(3) - tiny(530)).floor(), Ok(BigInt::from(3)));
    assert_eq!((Real::int(3) + tiny(530)).ceil(), Ok(BigInt::from(3)));
    assert_eq!(tiny(530).sign(), Ok(Ordering::Equal));
}

#[test]
fn an_enclosure_with_two_boundaries_is_refused() {
    // 2⁶⁰⁰·(sin 1° − sin 1°) is 0, but its 512-bit enclosure is some 2⁸⁸
    // wide: it holds many integers and half-integers, so floor, ceil and
    // nearest stay UndecidedRounding. Its sign has one boundary only.
    let s = Real::sin(deg(1));
    let wide = Real::int(BigInt::from(1) << 600) * (&s - &s);
    let iv = wide.enclose(512).unwrap();
    assert!(iv.width() > Rational::integer(2));
    assert_eq!(wide.floor(), Err(CycleError::UndecidedRounding));
    assert_eq!(wide.ceil(), Err(CycleError::UndecidedRounding));
    assert_eq!(wide.nearest(), Err(CycleError::UndecidedRounding));
    assert_eq!(wide.sign(), Ok(Ordering::Equal));
    // A divisor whose enclosure still holds 0 gives no enclosure at all.
    let none = Real::int(1) / (&s - &s);
    assert_eq!(none.enclose(512), None);
    assert_eq!(none.floor(), Err(CycleError::UndecidedRounding));
    assert_eq!(none.sign(), Err(CycleError::UndecidedRounding));
}

// ---------------------------------------------------------------------------
// The model.
// ---------------------------------------------------------------------------

const IS_C: Units = Units { system: IncrementSystem::IsC, unit: InputUnit::Metric };

/// The seed's example at IS-C metric: G00 X60 Z30, then
/// `G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30; G75.1 R0.5;`.
fn seed() -> G75Cycle {
    cycleref::examples::G75_SEED
}

fn with_corners(mut c: G75Cycle) -> G75Cycle {
    c.corners[corner::R1] = Corner { size: 10_000, kind: CornerKind::Round };
    c.corners[corner::R2] = Corner { size: 5_000, kind: CornerKind::Chamfer };
    c.corners[corner::R3] = Corner { size: 10_000, kind: CornerKind::Round };
    c.corners[corner::R4] = Corner { size: 5_000, kind: CornerKind::Round };
    c
}

/// The shape every expansion has: it starts with the approach, ends at
/// `from`, never repeats a position, and carries no pass.
fn check_shape(c: &G75Cycle, moves: &[cycleref::Move]) {
    assert!(!moves.is_empty());
    assert_eq!(moves[0].role, Role::Approach);
    let last = moves.last().unwrap();
    assert_eq!(last.to, c.from);
    assert_eq!(last.role, Role::Return);
    let mut at = c.from;
    for m in moves {
        assert_ne!(m.to, at, "zero-length move {m:?}");
        assert!(m.pass.is_none());
        at = m.to;
    }
}

#[test]
fn seed_example_expands() {
    let c = seed();
    let moves = g75::expand(&c).unwrap();
    check_shape(&c, &moves);
    // Three plunges of seven pecks each (Δi = 3 mm diameter, depth 20 mm).
    let pecks = moves.iter().filter(|m| matches!(m.role, Role::Peck(_))).count();
    assert_eq!(pecks, 21);
    // The groove's exact profile: P1 at Z20, P2 at Z10, P3 at u = 37.3205…
    let p = g75::profile(&c).unwrap();
    assert_eq!(p.p1.rounded, g75::LocalPoint::new(100_000, 200_000));
    assert_eq!(p.p2.rounded, g75::LocalPoint::new(200_000, 200_000));
    assert_eq!(p.p3.rounded, g75::LocalPoint::new(373_205, 0));
    assert_eq!(p.p3.exact.u.to_decimal(6).unwrap(), "373205.080756");
    assert_eq!(p.y_top, 0);
}

#[test]
fn seed_example_with_corners_and_finishing_expands() {
    for path in [PathType::Rough, PathType::RoughAndFinish, PathType::Finish] {
        let c = G75Cycle { path, ..with_corners(seed()) };
        let moves = g75::expand(&c).unwrap();
        check_shape(&c, &moves);
        let arcs: Vec<_> = moves
            .iter()
            .filter_map(|m| match m.motion {
                Motion::Arc { clockwise, .. } => Some(clockwise),
                _ => None,
            })
            .collect();
        if path.finishes() {
            // r1 (convex) is G03, r3 and r4 (concave) are G02 on this groove
            // cut towards −X and −Z; r2 is a chamfer.
            assert_eq!(arcs, [false, true, true]);
        } else {
            assert!(arcs.is_empty());
        }
        let with_i4 = G75Cycle { tool_width: Some(40_000), ..c };
        check_shape(&with_i4, &g75::expand(&with_i4).unwrap());
    }
}

#[test]
fn right_angle_groove_is_exact() {
    let c = G75Cycle { flank_a: 900_000, flank_b: 900_000, path: PathType::RoughAndFinish, ..seed() };
    let p = g75::profile(&c).unwrap();
    for q in [&p.p1, &p.p2, &p.p3] {
        assert!(q.exact.u.is_exact() && q.exact.y.is_exact());
    }
    let c = with_corners(c);
    let p = g75::profile(&c).unwrap();
    // tan 45° is exact, so the round corners of a square groove are exact.
    for feature in p.corners.iter().flatten() {
        assert!(feature.tangent.is_exact());
        assert!(feature.start.exact.u.is_exact() && feature.end.exact.y.is_exact());
    }
    check_shape(&c, &g75::expand(&c).unwrap());
}

#[test]
fn layers_slope_and_allowances_expand() {
    let c = G75Cycle {
        layer: Some(70_000),
        tool_width: Some(50_000),
        slope: 100_000,
        allowance_x: 4_000,
        allowance_z: 2_000,
        path: PathType::RoughAndFinish,
        ..with_corners(seed())
    };
    let moves = g75::expand(&c).unwrap();
    check_shape(&c, &moves);
    let layers: Vec<u32> = moves
        .iter()
        .filter_map(|m| match m.role {
            Role::LayerChange(l) => Some(l),
            _ => None,
        })
        .collect();
    assert!(layers.contains(&2) && layers.contains(&3));
    assert!(g75::profile(&c).unwrap().y_top < 0);
}

#[test]
fn alarm_order() {
    // Corners too large: flank A first, then the bottom, then flank B.
    let mut c = seed();
    c.corners[corner::R1] = Corner { size: 999_999, kind: CornerKind::Chamfer };
    c.corners[corner::R3] = Corner { size: 999_999, kind: CornerKind::Chamfer };
    assert_eq!(g75::expand(&c), Err(CycleError::CornerTooLarge { edge: GrooveEdge::FlankA }));
    c.corners[corner::R1] = Corner::SHARP;
    c.corners[corner::R3] = Corner { size: 60_000, kind: CornerKind::Chamfer };
    c.corners[corner::R4] = Corner { size: 60_000, kind: CornerKind::Chamfer };
    assert_eq!(g75::expand(&c), Err(CycleError::CornerTooLarge { edge: GrooveEdge::Bottom }));
    // Flank B is (Y/f)/sin 30° = 20 mm long.
    c.corners[corner::R3] = Corner::SHARP;
    c.corners[corner::R2] = Corner { size: 150_000, kind: CornerKind::Chamfer };
    assert_eq!(g75::expand(&c), Err(CycleError::CornerTooLarge { edge: GrooveEdge::FlankB }));
    // Corners that just meet are accepted: t4 + t2 = 20 mm, t3 + t4 = d.
    c.corners[corner::R2] = Corner { size: 140_000, kind: CornerKind::Chamfer };
    assert!(g75::profile(&c).is_ok());
    c.corners[corner::R2] = Corner::SHARP;
    c.corners[corner::R3] = Corner { size: 50_000, kind: CornerKind::Chamfer };
    c.corners[corner::R4] = Corner { size: 50_000, kind: CornerKind::Chamfer };
    assert!(g75::profile(&c).is_ok());
    // A tool wider than the bottom, for every J.
    for path in [PathType::Rough, PathType::Finish] {
        let c = G75Cycle { tool_width: Some(100_001), path, ..seed() };
        let w = cycleref::Length::new(100_001, IS_C);
        assert_eq!(g75::expand(&c), Err(CycleError::GrooveNarrowerThanTool { tool_width: w }));
    }
    let c = G75Cycle { tool_width: Some(100_000), ..seed() };
    assert!(g75::expand(&c).is_ok());
    // Too many pecks, but only when roughing.
    let c = G75Cycle { peck: 1, step: 1, ..seed() };
    assert_eq!(g75::expand(&c), Err(CycleError::TooManyPecks { limit: MAX_PECKS }));
    let c = G75Cycle { path: PathType::Finish, ..c };
    assert!(g75::expand(&c).is_ok());
    // Layers with a pointed tool: the ridges come first (R-G75RIDGE).
    let c = G75Cycle { layer: Some(1), ..seed() };
    let ridges = CycleError::RidgesInLayers {
        step: cycleref::Length::new(50_000, IS_C),
        tool_width: cycleref::Length::new(0, IS_C),
    };
    assert_eq!(g75::expand(&c), Err(ridges));
    assert!(g75::expand(&G75Cycle { path: PathType::Finish, ..c }).is_ok());
    let c = G75Cycle { layer: Some(1), tool_width: Some(50_000), ..seed() };
    assert_eq!(g75::expand(&c), Err(CycleError::TooManyPecks { limit: MAX_PECKS }));
    // A coordinate beyond the range tables: the first peck's X.
    let c = G75Cycle {
        start: Point::new(999_999_000, 0),
        from: Point::new(999_999_000, 10),
        depth: 200_000,
        ..seed()
    };
    match g75::expand(&c) {
        Err(CycleError::OutOfRange { field: Field::PassCoordinate, value }) => {
            assert_eq!(value.increments, 1_000_029_000);
        }
        other => panic!("{other:?}"),
    }
    // validate() comes first.
    let c = G75Cycle { depth: 0, ..c };
    assert_eq!(g75::expand(&c), Err(CycleError::NoGrooveDepth));
}

#[test]
fn an_irrational_formula_with_an_integer_value_is_decided() {
    // A90 B60 L30 D0: u3 = (Y/f)·cot 60° / (1 − tan 30°·cot 60°) = √3·Y/(2f)
    // and y3 = −f·u3·tan 30° = −Y/2 exactly, an integer given only as a
    // product of irrationals. R-G75TIE: y_top = floor(y3) = −Y/2 = −100000;
    // u3 = 50000·√3 = 86602.54… rounds to 86603.
    // (From X70 Z35: the seed's X60 Z30 is A11 itself, at y_top.)
    let c = G75Cycle {
        flank_a: 900_000,
        flank_b: 600_000,
        slope: 300_000,
        width: 0,
        from: Point::new(700_000, 350_000),
        ..seed()
    };
    let g = g75::groove(&c);
    assert!(!g75::y3(&g).is_exact());
    assert_eq!(g75::y_top(&g), Ok(-100_000));
    let p = g75::profile(&c).unwrap();
    assert_eq!(p.y_top, -100_000);
    assert_eq!(p.p3.rounded, g75::LocalPoint::new(86_603, -100_000));
    for path in [PathType::Rough, PathType::RoughAndFinish, PathType::Finish] {
        let c = G75Cycle { path, ..c };
        check_shape(&c, &g75::expand(&c).unwrap());
    }
}

#[test]
fn round_bottom_corners_on_exact_integer_depths_are_decided() {
    // y_K1 = floor(Y − Δu − f·t3·sin a − Δu·cos a) with t3 = ρ3·tan(a/2).
    // At a = 60°, tan 30°·sin 60° = 1/2 exactly, but only as a product of
    // two irrational values; whenever f·ρ3 = Δu, at any angle, y_K1 is
    // Y − 2Δu (tan(a/2)·sin a = 1 − cos a). Both were refused before
    // R-G75TIE; now they are the integers they are.
    let mut c = G75Cycle { flank_a: 600_000, flank_b: 600_000, path: PathType::RoughAndFinish, ..seed() };
    c.corners[corner::R3] = Corner { size: 5_000, kind: CornerKind::Round };
    // Y = 200000, U0, f = 2, ρ3 = 5000: y_K1 = 200000 − 2·5000·(1/2) = 195000.
    let g = g75::groove(&c);
    assert_eq!(g75::y_k1(&g), Ok(195_000));
    assert_eq!(g75::profile(&c).unwrap().rough[1].at.y, 195_000);
    check_shape(&c, &g75::expand(&c).unwrap());
    // U1.001: y_K1 = 200000 − 1001 − 5000 − 1001/2 = 193498.5, no tie.
    c.allowance_x = 1_001;
    assert_eq!(g75::y_k1(&g75::groove(&c)), Ok(193_498));
    check_shape(&c, &g75::expand(&c).unwrap());
    // A40, f·ρ3 = 2·1000 = Δu = 2000: y_K1 = Y − 2Δu = 196000.
    let mut c = G75Cycle { flank_a: 400_000, allowance_x: 2_000, ..seed() };
    c.corners[corner::R3] = Corner { size: 1_000, kind: CornerKind::Round };
    assert_eq!(g75::y_k1(&g75::groove(&c)), Ok(196_000));
    check_shape(&c, &g75::expand(&c).unwrap());
    // The same on the far side: B40, f·ρ4 = Δu: y_K4 = 196000.
    let mut c = G75Cycle { flank_b: 400_000, allowance_x: 2_000, ..seed() };
    c.corners[corner::R4] = Corner { size: 1_000, kind: CornerKind::Round };
    assert_eq!(g75::y_k4(&g75::groove(&c)), Ok(196_000));
    check_shape(&c, &g75::expand(&c).unwrap());
}

/// The moves of the rough contour (step 9) as (motion is a feed, end).
fn rough_contour_moves(moves: &[cycleref::Move]) -> Vec<(bool, Point)> {
    moves.iter().filter(|m| m.role == Role::RoughContour).map(|m| (m.motion == Motion::Feed, m.to)).collect()
}

#[test]
fn sixty_degree_round_corner_with_an_integer_k1_depth() {
    // IS-B metric, diameter (f = 2): G75.1 X50 Z0 P2 Q1.5 H-10 D-5 A60 B90;
    // G75.1 R0.5 U0.2 W0.1 J1 D1 P0010 (a round r3 of radius 1 mm).
    // Y = 10000, d = 5000, Δu = 200, Δw = 100, ρ3 = 1000, L = 0, no tool.
    //
    // By hand (√3 = 1.7320508075688772…):
    //   t3   = ρ3·tan 30° = 1000/√3 = 577.350…
    //   y_K1 = Y − Δu − f·t3·sin 60° − Δu·cos 60°
    //        = 10000 − 200 − 2·(1000/√3)·(√3/2) − 200·(1/2)
    //        = 9800 − 1000 − 100 = 8700 exactly, from irrational factors:
    //          R-G75TIE takes it on the integer, floor = 8700;
    //   K1   = (ceil(flankA_r(8700)), 8700), flankA_r(8700) = (8700/2)·cot 60°
    //          + 100 = 1450·√3 + 100 = 2611.4737… → K1 = (2612, 8700)
    //          (the moved chord meets flank A exactly there: chord3_r(8700)
    //          = 2000√3 + 100 − (1100/2)·√3 = 1450√3 + 100);
    //   K2   = (ceil((Y/f)·cot 60° + t3 + Δw), 9800) = ceil(5000/√3 +
    //          1000/√3 + 100) = ceil(2000√3 + 100) = ceil(3564.1016…) = 3565;
    //   Q2   = (floor(flankB_r(9800)), 9800), flankB_r = 5000/√3 + 5000 +
    //          0·cot 90° − 100 = 7786.7513… → 7786;
    //   R0   = (ceil(left(0)), 0): flankA_r(0) = 100, chord3_r(0) = 2000√3 +
    //          100 − 4900·cot 30° < 0 → (100, 0);
    //   R3   = (floor(right(0)), 0) = (floor(7786.7513…), 0) = (7786, 0)
    //          (flank B is square: the same u at every depth).
    //   A11  = (ceil(left(9800)), 0) = (3565, 0): the chord at the bottom.
    // Absolute (X = 50000 − y, Z = −u): R0 X50 Z−0.1, K1 X41.3 Z−2.612,
    // K2 X40.2 Z−3.565, Q2 X40.2 Z−7.786, R3 X50 Z−7.786, A11 X50 Z−3.565.
    let mut c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(52_000, 2_000),
        start: Point::new(50_000, 0),
        peck: 2_000,
        step: 1_500,
        depth: -10_000,
        width: -5_000,
        flank_a: 600_000,
        flank_b: 900_000,
        slope: 0,
        retract: 500,
        layer: None,
        allowance_x: 200,
        allowance_z: 100,
        tool_width: None,
        path: PathType::RoughAndFinish,
        corners: [Corner::SHARP; 4],
        readings: cycleref::G75Readings::DEFAULT,
    };
    c.corners[corner::R3] = Corner { size: 1_000, kind: CornerKind::Round };
    let g = g75::groove(&c);
    // The exact y_K1 is held as an expression of irrationals.
    let exact_k1 = Real::int(9_800)
        - Real::int(2) * &g.tangents[corner::R3] * Real::sin(deg(60))
        - Real::int(200) * Real::cos(deg(60));
    assert!(!exact_k1.is_exact());
    let iv = exact_k1.enclose(512).unwrap();
    assert!(iv.lower() <= Rational::integer(8_700) && iv.upper() >= Rational::integer(8_700));
    assert_eq!(exact_k1.floor(), Ok(BigInt::from(8_700)));
    assert_eq!(g75::y_k1(&g), Ok(8_700));
    assert_eq!(g75::k1(&g), Ok(g75::LocalPoint::new(2_612, 8_700)));
    assert_eq!(g75::k2(&g), Ok(g75::LocalPoint::new(3_565, 9_800)));
    let p = g75::profile(&c).unwrap();
    let rough: Vec<_> = p.rough.iter().map(|v| (v.at.u, v.at.y, v.far)).collect();
    assert_eq!(
        rough,
        [
            (100, 0, false),
            (2_612, 8_700, false),
            (3_565, 9_800, false),
            (7_786, 9_800, true),
            (7_786, 0, true)
        ]
    );
    let moves = g75::expand(&c).unwrap();
    check_shape(&c, &moves);
    assert_eq!(moves[0].to, Point::new(50_000, -3_565));
    assert_eq!(
        rough_contour_moves(&moves),
        [
            (false, Point::new(50_000, -100)),
            (true, Point::new(41_300, -2_612)),
            (true, Point::new(40_200, -3_565)),
            (true, Point::new(40_200, -7_786)),
            (true, Point::new(50_000, -7_786)),
            (false, Point::new(50_000, -3_565)),
        ]
    );
}

#[test]
fn the_slope_example_expands() {
    // examples/gsk980-g75-slope.nc, IS-B metric, diameter: G00 X90 Z12;
    // G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10;
    // G75.1 R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111.
    let path = format!("{}/../examples/gsk980-g75-slope.nc", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(path).unwrap();
    let machine = cycleref_spec::Machine::new(cycleref_spec::ProfileName::Gsk980);
    let program = cycleref_spec::read(&text, &machine).unwrap();
    let calls: Vec<_> = program.grooves().collect();
    assert_eq!(calls.len(), 1);
    let c = calls[0].cycle;
    assert_eq!(c, cycleref::examples::G75_SLOPE);
    let g = g75::groove(&c);
    // Two values lie exactly on a rounding boundary (R-G75TIE):
    // y_K1 = 9000 − 300 − 2·400·tan 30°·sin 60° − 300·cos 60°
    //      = 8700 − 400 − 150 = 8150;
    assert_eq!(g75::y_k1(&g), Ok(8_150));
    // layer 2's far side, flankB_r(6000) = 4500·cot 60° + 6000 + 1500·cot 75°
    // − 100 = 1500√3 + 5900 + 1500·(2 − √3) = 8900, so A_2f = 8900 − 2500.
    assert_eq!(g75::flank_b_rough(&g, &Real::int(6_000)).floor(), Ok(BigInt::from(8_900)));
    assert_eq!(g75::plunge_range(&g, 2), Ok(g75::PlungeRange { first: 1_833, last: 6_400 }));
    // The rough contour (mpmath, 80 digits): y3 = −3628.815…, y_top = −3629;
    // left(y_top) = flankA_r = −947.602… → R0 u = −947; K1 = ceil(2452.702…)
    // at 8150; K2 = ceil(2929.016…) at 8700; K3 = floor(8191.145…) − 2500;
    // y_K4 = floor(8029.409…) = 8029 > y_top, K4 = floor(8628.165…) − 2500;
    // right(y_top) = flankB_r = 10190.041… → R3 u = 10190 − 2500.
    let p = g75::profile(&c).unwrap();
    assert_eq!(p.y_top, -3_629);
    let rough: Vec<_> = p.rough.iter().map(|v| (v.at.u, v.at.y, v.far)).collect();
    assert_eq!(
        rough,
        [
            (-947, -3_629, false),
            (2_453, 8_150, false),
            (2_930, 8_700, false),
            (8_191, 8_700, true),
            (8_628, 8_029, true),
            (10_190, -3_629, true),
        ]
    );
    for path in [PathType::Rough, PathType::RoughAndFinish, PathType::Finish] {
        let c = G75Cycle { path, ..c };
        let moves = g75::expand(&c).unwrap();
        check_shape(&c, &moves);
        check_in_region(&c, &moves).unwrap();
        let layers = moves.iter().filter(|m| matches!(m.role, Role::LayerChange(_))).count();
        assert_eq!(layers, if path.roughs() { 4 } else { 0 }, "{path:?}");
        if path.roughs() {
            // X = 80000 − y, Z = −u; A11 = (967, −3629).
            assert_eq!(
                rough_contour_moves(&moves),
                [
                    (false, Point::new(83_629, 947)),
                    (true, Point::new(71_850, -2_453)),
                    (true, Point::new(71_300, -2_930)),
                    (true, Point::new(71_300, -5_691)),
                    (true, Point::new(71_971, -6_128)),
                    (true, Point::new(83_629, -7_690)),
                    (false, Point::new(83_629, -967)),
                ]
            );
        }
    }
    // U0.301 moves y_K1 off the integer (8148.5 → 8148); layer 2's far side
    // is still 8900 exactly.
    let c = G75Cycle { allowance_x: 301, ..c };
    assert_eq!(g75::y_k1(&g75::groove(&c)), Ok(8_148));
    check_shape(&c, &g75::expand(&c).unwrap());
}

#[test]
fn rough_contour_top_points_lie_in_the_region() {
    // Found by `expansions_are_well_formed`: a shallow groove with large
    // allowances and an r4 chamfer. The r4 chord less the allowances meets
    // flank B less Δw at y_K4 = floor(−1582.591…) = −1583, above y_top =
    // −1582, so at y_top the chord bounds the region: right(y_top) =
    // chord4_r(y_top) = 31612.685… (flankB_r(y_top) is 31613.something).
    // docs/G75.md §8: R3 = (floor(right(y_top)) − w, y_top) = (31612, −1582)
    // on the chord, and K4 is no vertex (y_K4 ≤ y_top). On the start side
    // the chord of r3 meets flank A at y_K1 = −810 > y_top: K1 stays and R0
    // = ceil(left(y_top)) = ceil(flankA_r(y_top)) = ceil(−5870.204…).
    let mut c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Radius,
        from: Point::new(100_000, 0),
        start: Point::new(100_000, 0),
        peck: 1_000,
        step: 2_600,
        depth: 2_798,
        width: 17_505,
        flank_a: 106_420,
        flank_b: 680_328,
        slope: 26_501,
        retract: 0,
        layer: None,
        allowance_x: 1_633,
        allowance_z: 2_549,
        tool_width: None,
        path: PathType::Rough,
        corners: [Corner::SHARP; 4],
        readings: cycleref::G75Readings::DEFAULT,
    };
    c.corners[corner::R3] = Corner { size: 2_002, kind: CornerKind::Chamfer };
    c.corners[corner::R4] = Corner { size: 2_304, kind: CornerKind::Chamfer };
    let g = g75::groove(&c);
    let y_top = g75::y_top(&g).unwrap();
    assert_eq!((y_top, g75::y_k1(&g).unwrap(), g75::y_k4(&g).unwrap()), (-1_582, -810, -1_583));
    let top = Real::int(y_top);
    let right = g75::right(&g, &top);
    assert_eq!(right.to_decimal(3).unwrap(), "31612.685");
    assert_eq!(g75::flank_b_rough(&g, &top).floor(), Ok(BigInt::from(31_613)));
    let contour = g75::rough_contour(&g, y_top).unwrap();
    assert_eq!(
        contour,
        [
            g75::LocalPoint::new(-5_870, -1_582),
            g75::LocalPoint::new(-1_761, -810),
            g75::LocalPoint::new(19_442, 1_165),
            g75::LocalPoint::new(27_542, 1_165),
            g75::LocalPoint::new(31_612, -1_582),
        ]
    );
    let (r0, r3) = (contour[0], contour[4]);
    assert_ne!(Real::int(r0.u).compare(&g75::left(&g, &top)), Ok(Ordering::Less));
    assert_ne!(Real::int(r3.u + g.tool).compare(&right), Ok(Ordering::Greater));
    let moves = g75::expand(&c).unwrap();
    check_shape(&c, &moves);
    check_in_region(&c, &moves).unwrap();
}

/// Random cycles of IS-B size, kept small (at most some 10⁵ pecks and 200
/// layers) so that every case runs quickly; `alarm_order` covers the large
/// counts.
fn arb_cycle() -> impl Strategy<Value = G75Cycle> {
    let corner = (0_i64..3_000, any::<bool>()).prop_map(|(size, round)| Corner {
        size,
        kind: if round { CornerKind::Round } else { CornerKind::Chamfer },
    });
    (
        (500_i64..=40_000, 500_i64..=40_000, 1_i64..=200_000, 0_i64..=100_000, any::<bool>(), any::<bool>()),
        (1_u32..=900_000, 1_u32..=900_000, 0_u32..900_000),
        (0_i64..=5_000, proptest::option::of(1_000_i64..=100_000), 0_i64..=3_000, 0_i64..=3_000),
        (
            proptest::option::of(0_i64..=10_000),
            0_u8..3,
            [corner.clone(), corner.clone(), corner.clone(), corner],
        ),
        (any::<bool>(), -50_000_i64..50_000, -50_000_i64..50_000),
    )
        .prop_map(|(words, angles, block2, tool, place)| {
            let (peck, step, depth, width, neg_h, neg_d) = words;
            let (flank_a, flank_b, slope) = angles;
            let (retract, layer, allowance_x, allowance_z) = block2;
            let (tool_width, j, corners) = tool;
            let (radius, fx, fz) = place;
            G75Cycle {
                units: Units::IS_B_METRIC,
                x_mode: if radius { XMode::Radius } else { XMode::Diameter },
                from: Point::new(100_000 + fx, fz),
                start: Point::new(100_000, 0),
                peck,
                step,
                depth: if neg_h { -depth } else { depth },
                width: if neg_d { -width } else { width },
                flank_a,
                flank_b,
                slope: slope % flank_b,
                retract,
                layer,
                allowance_x,
                allowance_z,
                tool_width,
                path: [PathType::Rough, PathType::RoughAndFinish, PathType::Finish][usize::from(j)],
                corners,
                readings: cycleref::G75Readings::DEFAULT,
            }
        })
}

/// Every tool position of roughing (the moves before the finishing
/// contour), with its width, lies in the roughing region, decided exactly
/// against the unrounded boundaries (`docs/G75.md` §10). For an integer
/// `u`, `u ≥ left(y)` is `u ≥ ceil(left(y))` and `u + w ≤ right(y)` is
/// `u + w ≤ floor(right(y))`; the bounds are decided once per depth. This
/// includes R0 and R3, the rough contour's points at `y_top`, against
/// `left`/`right` (not only the flanks: the chord of a bottom corner bounds
/// the region when it meets its flank above `y_top`).
fn check_in_region(c: &G75Cycle, moves: &[cycleref::Move]) -> Result<(), TestCaseError> {
    let g = g75::groove(c);
    let mut bounds: HashMap<i128, (BigInt, BigInt)> = HashMap::new();
    for m in moves {
        if matches!(m.role, Role::FinishContour | Role::Return) {
            break;
        }
        let u = g.sz * (i128::from(m.to.z) - i128::from(c.start.z));
        let y = g.sx * (i128::from(m.to.x) - i128::from(c.start.x));
        prop_assert!(y <= g75::bottom_rough(&g), "{:?} below the roughing bottom", m);
        let (left, right) = match bounds.get(&y) {
            Some(b) => b.clone(),
            None => {
                let real_y = Real::int(y);
                let left = g75::left(&g, &real_y).ceil();
                let right = g75::right(&g, &real_y).floor();
                prop_assert!(left.is_ok() && right.is_ok(), "{:?}: boundary undecided", m);
                let b = (left.unwrap_or_default(), right.unwrap_or_default());
                bounds.insert(y, b.clone());
                b
            }
        };
        prop_assert!(BigInt::from(u) >= left, "{:?} before the start-side boundary", m);
        prop_assert!(BigInt::from(u + g.tool) <= right, "{:?} beyond the far-side boundary", m);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Any cycle either expands into a well-formed path or is refused with
    /// an alarm; pecks take at most Δi and steps at most Δk. Never
    /// `UndecidedRounding`: with R-G75TIE only an enclosure holding two
    /// boundaries at 512 bits is refused, which the widths rule out.
    #[test]
    fn expansions_are_well_formed(c in arb_cycle()) {
        match g75::expand(&c) {
            Ok(moves) => {
                check_shape(&c, &moves);
                check_in_region(&c, &moves)?;
                let f = c.x_mode.factor();
                let mut at = c.from;
                for m in &moves {
                    match m.role {
                        Role::Peck(_) => {
                            prop_assert_eq!(m.to.z, at.z);
                            prop_assert!((m.to.x - at.x).abs() <= c.peck + f * c.retract);
                        }
                        Role::Step(_) => {
                            prop_assert_eq!(m.to.x, at.x);
                            prop_assert!((m.to.z - at.z).abs() <= c.step);
                        }
                        _ => {}
                    }
                    at = m.to;
                }
            }
            Err(e) => {
                prop_assert!(c.validate().is_err() || matches!(
                    e,
                    CycleError::CornerTooLarge { .. }
                        | CycleError::GrooveNarrowerThanTool { .. }
                        | CycleError::RidgesInLayers { .. }
                        | CycleError::TooManyPecks { .. }
                        | CycleError::OutOfRange { .. }
                ), "{:?}", e);
            }
        }
    }
    /// R-G75TIE on a whole family: a round bottom corner whose `f·ρ`
    /// equals U puts the chord's meeting point with its flank at exactly
    /// `Y − 2Δu` at every angle (`tan(a/2)·sin a = 1 − cos a`), an integer
    /// computed from irrational terms. It is decided as that integer, on
    /// both sides, and the cycle expands into the region.
    #[test]
    fn round_corners_equal_to_the_allowance_are_decided(
        c in arb_cycle(),
        rho in 1_i64..=1_000,
        far in any::<bool>(),
    ) {
        let f = c.x_mode.factor();
        let mut c = G75Cycle { allowance_x: f * rho, depth: c.depth.signum() * c.depth.abs().max(4 * f * rho + 1), ..c };
        c.corners[if far { corner::R4 } else { corner::R3 }] = Corner { size: rho, kind: CornerKind::Round };
        prop_assume!(c.validate().is_ok());
        let g = g75::groove(&c);
        let expected = i128::from(c.depth.abs() - 2 * f * rho);
        let y = if far { g75::y_k4(&g) } else { g75::y_k1(&g) };
        prop_assert_eq!(y, Ok(expected));
        match g75::expand(&c) {
            Ok(moves) => {
                check_shape(&c, &moves);
                check_in_region(&c, &moves)?;
            }
            Err(e) => prop_assert!(matches!(
                e,
                CycleError::CornerTooLarge { .. }
                    | CycleError::GrooveNarrowerThanTool { .. }
                    | CycleError::RidgesInLayers { .. }
                    | CycleError::TooManyPecks { .. }
                    | CycleError::OutOfRange { .. }
            ), "{:?}", e),
        }
    }
}
