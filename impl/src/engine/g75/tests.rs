//! Unit tests of the G75.1 engine: worked examples by hand, the order of
//! the alarms, decisions on values that lie on a rounding boundary, sweeps
//! of square grooves, and every formula against `f64` where the float is
//! clear of a boundary.

extern crate std;

use core::cmp::Ordering;

use super::exact::{plunges_at, Enclosures, Evaluator, Fallback, Geometry, Quantity};
use super::*;
use crate::engine::approx::Approx;
use crate::engine::linuxcnc::FastPathStats;
use crate::engine::real::{Interval, Rounding, SLOW};
use crate::error::{Field, GrooveEdge};
use crate::g75::{corner, Corner, CornerKind, PathType, MAX_PECKS};
use crate::moves::Plunge;
use crate::units::{IncrementSystem, InputUnit, Point, Units, XMode, MAX_LENGTH};
use std::format;
use std::string::String;
use std::vec::Vec;

const IS_C: Units = Units { system: IncrementSystem::IsC, unit: InputUnit::Metric };

/// The seed's example: `G00 X60 Z30; G75.1 X50 Z30 P30000 Q50000 H-20
/// D-10 A45 B30; G75.1 R0.5;` at IS-C metric.
fn seed() -> G75Cycle {
    crate::examples::G75_SEED
}

/// The golden square groove of `proofs/tests/g75_golden.rs` at IS-B:
/// `G00 X40 Z5; G75.1 X30 Z0 P2000 Q3000 H-6 D-8; G75.1 R0.5 V4 U0.4
/// W0.2 I3 J1 A0.5 D0.4 E0.3 P0011`.
fn square() -> G75Cycle {
    G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(40_000, 5_000),
        start: Point::new(30_000, 0),
        peck: 2_000,
        step: 3_000,
        depth: -6_000,
        width: -8_000,
        flank_a: 900_000,
        flank_b: 900_000,
        slope: 0,
        retract: 500,
        layer: Some(4_000),
        allowance_x: 400,
        allowance_z: 200,
        tool_width: Some(3_000),
        path: PathType::RoughAndFinish,
        corners: [
            Corner { size: 500, kind: CornerKind::Chamfer },
            Corner::SHARP,
            Corner { size: 400, kind: CornerKind::Round },
            Corner { size: 300, kind: CornerKind::Round },
        ],
        readings: crate::G75Readings::DEFAULT,
    }
}

/// Moves as `G01 X28000 Z-200 peck 1.1` (increments), for the golden
/// lists below.
///
/// Twin: `proofs/tests/g75_golden.rs`, `render` (the same lines in
/// millimetres; `impl` cannot use a test helper of `proofs`).
fn render(moves: &[Move]) -> Vec<String> {
    moves
        .iter()
        .map(|m| {
            let g = match m.motion {
                Motion::Rapid => String::from("G00"),
                Motion::Feed => String::from("G01"),
                Motion::Thread { .. } => String::from("G32"),
                Motion::Arc { centre, clockwise } => {
                    format!("{} C{},{}", if clockwise { "G02" } else { "G03" }, centre.x, centre.z)
                }
            };
            let role = match m.role {
                Role::Peck(p) => format!("peck {}.{}", p.layer, p.number),
                Role::PeckRetract(p) => format!("peck-retract {}.{}", p.layer, p.number),
                Role::PlungeRetract(p) => format!("plunge-retract {}.{}", p.layer, p.number),
                Role::Step(p) => format!("step {}.{}", p.layer, p.number),
                Role::LayerChange(l) => format!("layer {l}"),
                other => format!("{other:?}"),
            };
            format!("{g} X{} Z{} {role}", m.to.x, m.to.z)
        })
        .collect()
}

/// The seed example worked by hand (docs/G75.md; A11: Z = 30 − 10 = 20).
#[test]
fn seed_example_by_hand() {
    let c = seed();
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    assert!(moves.iter().all(|m| m.pass.is_none()));
    // A11 = (ceil(100000·cot 45°), 0) = (100000, 0): X50 Z20.
    let mut expected = std::vec![String::from("G00 X500000 Z200000 Approach")];
    // One plunge: pecks to y = 30000·j (X47, X44, …, X32), each followed
    // by a retract of e_x = 2·5000 (X48, X45, …, X33), the 7th peck cut
    // short at y = 200000 (X30), then back to X50.
    let plunge = |z: i64, n: u32| {
        let mut v = Vec::new();
        for j in 1..=6_i64 {
            v.push(format!("G01 X{} Z{z} peck 1.{n}", 500_000 - 30_000 * j));
            v.push(format!("G00 X{} Z{z} peck-retract 1.{n}", 500_000 - 30_000 * j + 10_000));
        }
        v.push(format!("G01 X300000 Z{z} peck 1.{n}"));
        v.push(format!("G00 X500000 Z{z} plunge-retract 1.{n}"));
        v
    };
    expected.extend(plunge(200_000, 1));
    // A1f = floor(200000 + 0·cot 30°) = 200000: plunges at u = 100000,
    // 150000, 200000 (Z20, Z15, Z10).
    expected.push("G00 X500000 Z150000 step 1.2".into());
    expected.extend(plunge(150_000, 2));
    expected.push("G00 X500000 Z100000 step 1.3".into());
    expected.extend(plunge(100_000, 3));
    expected.extend([
        "G00 X500000 Z200000 Approach".into(),
        // R0 = S, Q1 = (100000, Y), Q2 = (200000, Y), R3 = (floor(200000
        // + 100000·√3) = 373205, 0): Z = 300000 − 373205.
        "G00 X500000 Z300000 RoughContour".into(),
        "G01 X300000 Z200000 RoughContour".into(),
        "G01 X300000 Z100000 RoughContour".into(),
        "G01 X500000 Z-73205 RoughContour".into(),
        "G00 X500000 Z200000 RoughContour".into(),
        "G00 X600000 Z300000 Return".into(),
    ]);
    assert_eq!(render(&moves), expected);
}

/// The seed example with J1 and I4 (w = 40000): the far side moves in by
/// w; the finishing contour goes S, P1, P2 − w, P3 − w (u3 = 373205.08…
/// → 373205).
#[test]
fn seed_with_tool_and_finish() {
    let c = G75Cycle { tool_width: Some(40_000), path: PathType::RoughAndFinish, ..seed() };
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    let r = render(&moves);
    let tail: Vec<&str> = r.iter().rev().take(12).rev().map(String::as_str).collect();
    assert_eq!(
        tail,
        [
            "G00 X500000 Z200000 Approach",
            "G00 X500000 Z300000 RoughContour",
            "G01 X300000 Z200000 RoughContour",
            "G01 X300000 Z140000 RoughContour",
            "G01 X500000 Z-33205 RoughContour",
            "G00 X500000 Z200000 RoughContour",
            // F0 = S: along Z to u = 0 (the X move is empty).
            "G00 X500000 Z300000 FinishContour",
            "G01 X300000 Z200000 FinishContour",
            "G01 X300000 Z140000 FinishContour",
            "G01 X500000 Z-33205 FinishContour",
            // Return: X and the final X move are empty; Z to S, then from.
            "G00 X500000 Z300000 Return",
            "G00 X600000 Z300000 Return",
        ]
    );
    assert!(r.contains(&String::from("G00 X500000 Z140000 step 1.3")));
}

/// The golden square groove (every value exact), as worked by hand in
/// `proofs/tests/g75_golden.rs`.
#[test]
fn square_groove_by_hand() {
    let moves: Vec<Move> = expand_g75(&square()).unwrap().collect();
    let plunge1 = |z: i64, n: u32| {
        std::vec![
            format!("G01 X28000 Z{z} peck 1.{n}"),
            format!("G00 X29000 Z{z} peck-retract 1.{n}"),
            format!("G01 X26000 Z{z} peck 1.{n}"),
            format!("G00 X30000 Z{z} plunge-retract 1.{n}"),
        ]
    };
    let plunge2 = |z: i64, n: u32| {
        std::vec![format!("G01 X24400 Z{z} peck 2.{n}"), format!("G00 X26000 Z{z} plunge-retract 2.{n}")]
    };
    let mut e = std::vec![String::from("G00 X30000 Z-200 Approach")];
    e.extend(plunge1(-200, 1));
    e.push("G00 X30000 Z-3200 step 1.2".into());
    e.extend(plunge1(-3200, 2));
    e.push("G00 X30000 Z-4800 step 1.3".into());
    e.extend(plunge1(-4800, 3));
    e.push("G00 X30000 Z-600 layer 2".into());
    e.push("G00 X26000 Z-600 layer 2".into());
    e.extend(plunge2(-600, 1));
    e.push("G00 X26000 Z-3600 step 2.2".into());
    e.extend(plunge2(-3600, 2));
    e.push("G00 X26000 Z-4500 step 2.3".into());
    e.extend(plunge2(-4500, 3));
    e.extend([
        "G00 X30000 Z-4500 Approach".into(),
        "G00 X30000 Z-200 Approach".into(),
        "G01 X25200 Z-200 RoughContour".into(),
        "G01 X24400 Z-600 RoughContour".into(),
        "G01 X24400 Z-4500 RoughContour".into(),
        "G01 X25000 Z-4800 RoughContour".into(),
        "G01 X30000 Z-4800 RoughContour".into(),
        "G00 X30000 Z-200 RoughContour".into(),
        "G00 X30000 Z500 FinishContour".into(),
        "G01 X29000 Z0 FinishContour".into(),
        "G01 X24800 Z0 FinishContour".into(),
        "G02 C24800,-400 X24000 Z-400 FinishContour".into(),
        "G01 X24000 Z-4700 FinishContour".into(),
        "G02 C24600,-4700 X24600 Z-5000 FinishContour".into(),
        "G01 X30000 Z-5000 FinishContour".into(),
        "G00 X30000 Z0 Return".into(),
        "G00 X40000 Z5000 Return".into(),
    ]);
    assert_eq!(render(&moves), e);
}

#[test]
fn square_profile() {
    let p = groove_profile(&square()).unwrap();
    let at: Vec<(i64, i64)> = p.finishing().iter().map(|q| (q.at.x, q.at.z)).collect();
    // T1s, T1a, T3a, T3b, T4b, T4c, P3: without the tool width.
    assert_eq!(
        at,
        [
            (30_000, 500),
            (29_000, 0),
            (24_800, 0),
            (24_000, -400),
            (24_000, -7_700),
            (24_600, -8_000),
            (30_000, -8_000)
        ]
    );
    assert_eq!(p.finishing()[0].segment, ProfileSegment::Start);
    assert_eq!(p.finishing()[1].segment, ProfileSegment::Line);
    assert_eq!(
        p.finishing()[3].segment,
        ProfileSegment::Arc { centre: Point::new(24_800, -400), clockwise: true }
    );
    assert_eq!(
        p.finishing()[5].segment,
        ProfileSegment::Arc { centre: Point::new(24_600, -7_700), clockwise: true }
    );
    let rough: Vec<(i64, i64)> = p.roughing().iter().map(|q| (q.x, q.z)).collect();
    // R0, K1, K2, K3, K4, R3 before the tool width.
    assert_eq!(
        rough,
        [
            (30_000, -200),
            (25_200, -200),
            (24_400, -600),
            (24_400, -7_500),
            (25_000, -7_800),
            (30_000, -7_800)
        ]
    );
}

/// Arc directions: r1 of an external groove cut towards +Z turns
/// clockwise (along the surface, then down the flank), r3 the other way;
/// mirroring one axis swaps both.
#[test]
fn arc_directions() {
    let round = |size| Corner { size, kind: CornerKind::Round };
    let base = G75Cycle {
        flank_a: 900_000,
        flank_b: 900_000,
        width: 100_000,
        path: PathType::Finish,
        corners: [round(1_000), round(1_000), round(1_000), round(1_000)],
        ..seed()
    };
    let arcs = |c: &G75Cycle| -> Vec<bool> {
        expand_g75(c)
            .unwrap()
            .filter_map(|m| match m.motion {
                Motion::Arc { clockwise, .. } => Some(clockwise),
                _ => None,
            })
            .collect()
    };
    // sx = −1 (H < 0), sz = +1: r1 cw, r3 ccw, r4 ccw, r2 cw.
    assert_eq!(arcs(&base), [true, false, false, true]);
    assert_eq!(arcs(&G75Cycle { width: -100_000, ..base }), [false, true, true, false]);
    assert_eq!(
        arcs(&G75Cycle { depth: 200_000, from: Point::new(400_000, 300_000), ..base }),
        [false, true, true, false]
    );
    // Every arc's end points are within one increment of its radius.
    for m in expand_g75(&base).unwrap() {
        if let Motion::Arc { centre, .. } = m.motion {
            let dz = (m.to.z - centre.z).abs();
            let dx = (m.to.x - centre.x).abs() / 2;
            assert!(dz.max(dx) == 1_000 && dz.min(dx) == 0, "{m:?}");
        }
    }
}

#[test]
fn errors_in_order() {
    // Corners larger than flank A (Y/f = 100000 with a = 90°).
    let c = G75Cycle {
        flank_a: 900_000,
        corners: [
            Corner { size: 60_000, kind: CornerKind::Chamfer },
            Corner::SHARP,
            Corner { size: 40_001, kind: CornerKind::Round },
            Corner::SHARP,
        ],
        ..seed()
    };
    assert_eq!(expand_g75(&c).err(), Some(CycleError::CornerTooLarge { edge: GrooveEdge::FlankA }));
    // Exactly the flank's length fits (exact comparison).
    let mut ok = c;
    ok.corners[corner::R3].size = 40_000;
    assert!(expand_g75(&ok).is_ok());
    // The bottom: t3 + t4 > d.
    let c = G75Cycle {
        corners: [
            Corner::SHARP,
            Corner::SHARP,
            Corner { size: 50_000, kind: CornerKind::Chamfer },
            Corner { size: 50_001, kind: CornerKind::Chamfer },
        ],
        ..seed()
    };
    assert_eq!(expand_g75(&c).err(), Some(CycleError::CornerTooLarge { edge: GrooveEdge::Bottom }));
    // A tool wider than the bottom.
    let c = G75Cycle { tool_width: Some(100_001), ..seed() };
    assert_eq!(
        expand_g75(&c).err(),
        Some(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(100_001, IS_C) })
    );
    let c = G75Cycle { tool_width: Some(100_000), ..seed() };
    assert!(expand_g75(&c).is_ok());
    // Too many pecks: pecks of 1 increment over 20 mm of diameter are
    // 200000 per plunge: 11 plunges (Δk = 1 mm) are too many, 2 are not.
    let c = G75Cycle { peck: 1, step: 10_000, ..seed() };
    assert_eq!(expand_g75(&c).err(), Some(CycleError::TooManyPecks { limit: MAX_PECKS }));
    let c = G75Cycle { peck: 1, step: 100_000, ..seed() };
    assert_eq!(expand_g75(&c).unwrap().filter(|m| matches!(m.role, Role::Peck(_))).count(), 400_000);
    // J2 makes no pecks: no limit.
    let c = G75Cycle { peck: 1, path: PathType::Finish, ..seed() };
    assert!(expand_g75(&c).is_ok());
    // Coordinates beyond the range: the groove's far flank at a start
    // near the Z limit (Z − 373205).
    let c = G75Cycle {
        start: Point::new(500_000, -MAX_LENGTH + 200_000),
        from: Point::new(600_000, -MAX_LENGTH + 200_000),
        ..seed()
    };
    // The first coordinate beyond: the third plunge at u = 200000? No:
    // Z = start − u, the steps reach Z = −MAX + 0 (in range); R3 at
    // u = 373205 is the first beyond.
    assert_eq!(
        expand_g75(&c).err(),
        Some(CycleError::OutOfRange {
            field: Field::PassCoordinate,
            value: Length::new(-MAX_LENGTH + 200_000 - 373_205, IS_C)
        })
    );
    // The pecks of layer 1 beyond X: S at X −MAX + 100000, sx = −1.
    let c = G75Cycle {
        start: Point::new(-MAX_LENGTH + 100_000, 300_000),
        from: Point::new(-MAX_LENGTH + 200_000, 300_000),
        ..seed()
    };
    // Peck 4 ends at y = 120000 > 100000: X = −MAX − 20000.
    assert_eq!(
        expand_g75(&c).err(),
        Some(CycleError::OutOfRange {
            field: Field::PassCoordinate,
            value: Length::new(-MAX_LENGTH - 20_000, IS_C)
        })
    );
}

/// The range check in closed form against a brute-force scan of the
/// moves of a cycle expanded with a shifted start (same local path).
#[test]
fn range_check_matches_move_order() {
    // Layers need a step no wider than the tool (R-G75RIDGE).
    let cases = [
        G75Cycle { layer: Some(70_000), tool_width: Some(50_000), ..seed() },
        G75Cycle {
            layer: Some(70_000),
            step: 3_000,
            tool_width: Some(3_000),
            path: PathType::RoughAndFinish,
            ..seed()
        },
        G75Cycle {
            depth: 200_000,
            width: 100_000,
            layer: Some(45_000),
            tool_width: Some(60_000),
            from: Point::new(400_000, 300_000),
            path: PathType::RoughAndFinish,
            corners: [Corner { size: 3_000, kind: CornerKind::Round }; 4],
            ..seed()
        },
    ];
    for base in cases {
        let reference: Vec<Move> = expand_g75(&base).unwrap().collect();
        for dx in [0_i64, 1, 30_000, 100_000, 150_000, 170_000, 199_999, 200_000, 250_000] {
            for dz in [0_i64, 50_000, 100_000, 120_000, 373_205, 400_000] {
                // Move S so that the range ends at local y = dx and
                // u = dz, keeping the local path identical.
                let sx = base.radial_sign();
                let sz = base.axial_sign();
                let start = Point::new(sx * (MAX_LENGTH - dx), sz * (MAX_LENGTH - dz));
                let from = Point::new(start.x - sx * 10, start.z);
                if start.x.abs() > MAX_LENGTH || from.x.abs() > MAX_LENGTH {
                    continue;
                }
                let c = G75Cycle { start, from, ..base };
                // Brute force: the reference path moved by the shift.
                let mut expect = None;
                for m in &reference {
                    let mv =
                        |p: Point| Point::new(p.x + start.x - base.start.x, p.z + start.z - base.start.z);
                    let to = mv(m.to);
                    if m.role == Role::Return && m.to == base.from {
                        break;
                    }
                    let mut coords = std::vec![to.x, to.z];
                    if let Motion::Arc { centre, .. } = m.motion {
                        let cc = mv(centre);
                        coords.extend([cc.x, cc.z]);
                    }
                    if let Some(v) = coords.into_iter().find(|v| v.abs() > MAX_LENGTH) {
                        expect = Some(v);
                        break;
                    }
                }
                let got = expand_g75(&c).err();
                match expect {
                    None => assert!(got.is_none(), "dx {dx} dz {dz}: {got:?}"),
                    Some(v) => assert_eq!(
                        got,
                        Some(CycleError::OutOfRange {
                            field: Field::PassCoordinate,
                            value: Length::new(v, base.units)
                        }),
                        "dx {dx} dz {dz}"
                    ),
                }
            }
        }
    }
}

/// R-G75TIE on the slope example (examples/gsk980-g75-slope.nc) at IS-B:
/// with A = 60° and a round r3 the depth of K1 is `Y − Δu − f·ρ·tan 30°·
/// sin 60° − Δu·cos 60° = 9000 − 300 − 2·400·(1/2) − 300·(1/2) = 8150`,
/// an integer computed from irrational factors (tan 30°·sin 60° = 1/2)
/// that no enclosure decides; the second layer's right boundary
/// `flankB_r(6000) = 4500·cot 60° + 6000 + 1500·cot 75° − 100 = 1500√3 +
/// 5900 + 1500(2 − √3) = 8900` is another. Both are taken to lie on the
/// integer, and the cycle expands.
#[test]
fn tie_values_are_decided() {
    let c = slope_example();
    let g = Geometry::new(&c);
    // The 512-bit enclosures alone leave both floors open ...
    let slow = Enclosures::<Interval<SLOW>>::new(&g);
    assert_eq!(slow.eval(&g, Quantity::YK1).round(Rounding::Floor), None);
    assert_eq!(slow.eval(&g, Quantity::Right(6_000)).round(Rounding::Floor), None);
    // ... and R-G75TIE decides them on the boundary.
    let mut fallback = Fallback::default();
    let mut ev = Evaluator::new(g, false, &mut fallback);
    assert_eq!(ev.floor(Quantity::YK1), Ok(8_150));
    assert_eq!(ev.floor(Quantity::Right(6_000)), Ok(8_900));
    assert_eq!(ev.plunges(6_000), Ok((1_833, 6_400)));
    assert_eq!(plunges_at(&g, None, 6_000, &mut FastPathStats::default()), Some((1_833, 6_400)));
    let quick = Enclosures::<Approx>::new(&g).r;
    assert_eq!(plunges_at(&g, Some(&quick), 6_000, &mut FastPathStats::default()), Some((1_833, 6_400)));
    // U0.301 moves K1's depth off the integer (8148.5), the second
    // layer's boundary stays 8900.
    let moves: Vec<Move> = expand_g75(&G75Cycle { allowance_x: 301, ..c }).unwrap().collect();
    // Layer 2 (from y = 3000): plunges at 1833, 3833, 5833, then 6400.
    assert!(moves
        .iter()
        .any(|m| m.role == Role::Step(Plunge { layer: 2, number: 4 }) && m.to == Point::new(77_000, -6_400)));
    // The rounded sign of an exact zero enclosed by irrational terms:
    // tan 30°·sin 60° − 1/2.
    let zero = crate::engine::real::tan::<SLOW>(600_000)
        .mul(&crate::engine::real::sin::<SLOW>(1_200_000))
        .sub(&Interval::half());
    assert_eq!(zero.sign(), None);
    assert_eq!(zero.sign_tie(), Some(Ordering::Equal));
}

/// The slope example expands (R-G75TIE), with the rough contour of §8
/// step 9 worked out from the formulas (mpmath, 80 digits): `y_top =
/// floor(y3) = floor(−3628.815…) = −3629`; R0 = (ceil(left(−3629)) =
/// ceil(−947.602…), −3629) = (−947, −3629) (flank A: the chord of r3
/// meets it at y_K1 = 8150 > y_top); K1 = (ceil(flankA_r(8150)) =
/// ceil(4075·cot 60° + 100) = ceil(2452.702…), 8150); K2 =
/// (ceil(4500·cot 60° + 400·tan 30° + 100) = ceil(2929.016…), 8700); K3 =
/// (floor(8191.145…), 8700); y_K4 = floor(8029.409…) = 8029, K4 =
/// (floor(flankB_r(8029)) = floor(8628.165…), 8029); R3 =
/// (floor(right(−3629)) = floor(10190.041…), −3629). Absolute: X = 80000
/// − y, Z = −u, the far side less w = 2500.
#[test]
fn slope_example_expands() {
    let c = slope_example();
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    let contour: Vec<(Motion, Point)> =
        moves.iter().filter(|m| m.role == Role::RoughContour).map(|m| (m.motion, m.to)).collect();
    assert_eq!(
        contour,
        [
            (Motion::Rapid, Point::new(83_629, 947)),
            (Motion::Feed, Point::new(71_850, -2_453)),
            (Motion::Feed, Point::new(71_300, -2_930)),
            (Motion::Feed, Point::new(71_300, -8_191 + 2_500)),
            (Motion::Feed, Point::new(71_971, -8_628 + 2_500)),
            (Motion::Feed, Point::new(83_629, -10_190 + 2_500)),
            // Back to A11 = (ceil(left(3000)) = ceil(966.025…), y_top).
            (Motion::Rapid, Point::new(83_629, -967)),
        ]
    );
    let p = groove_profile(&c).unwrap();
    assert_eq!(
        p.roughing(),
        [
            Point::new(83_629, 947),
            Point::new(71_850, -2_453),
            Point::new(71_300, -2_930),
            Point::new(71_300, -8_191),
            Point::new(71_971, -8_628),
            Point::new(83_629, -10_190),
        ]
    );
    // Three layers (V3 over 8.7 mm of diameter): every plunge retracts to
    // its layer's top (y_top, 3000, 6000); the path ends at `from`.
    let tops: Vec<i64> =
        moves.iter().filter(|m| matches!(m.role, Role::PlungeRetract(_))).map(|m| m.to.x).collect();
    assert!(tops.iter().all(|x| [83_629, 77_000, 74_000].contains(x)), "{tops:?}");
    assert!(tops.contains(&74_000));
    assert_eq!(moves.last().map(|m| m.to), Some(c.from));
}

/// A round r3 on a 60° flank whose K1 depth is exactly an integer, worked
/// by hand: `G75.1 X50 Z0 H-10 D-6 A60` (B90, L0), `U0.2 W0.1 D1 P0010`
/// (r3 a round of ρ = 1000), J0, IS-B diameter. t3 = 1000·tan 30° =
/// 1000/√3, `f·t3·sin 60° = 2·(1000/√3)·(√3/2) = 1000`, so `y_K1 = 10000
/// − 200 − 1000 − 200·cos 60° = 8700` exactly (R-G75TIE: taken on the
/// integer). y_top = 0 (L = 0) < 8700, so K1 is a vertex: K1 =
/// (ceil(flankA_r(8700)), 8700) = (ceil(4350/√3 + 100), 8700) =
/// (ceil(2611.473…), 8700) = (2612, 8700). R0 = (ceil(left(0)), 0):
/// flankA_r(0) = 100, chord3_r(0) = 5000/√3 + 1000/√3 + 100 − 4900·√3 <
/// 0, so (100, 0). K2 = (ceil(6000/√3 + 100), 9800) = (ceil(3564.101…),
/// 9800) = (3565, 9800). No r4: Q2 = (floor(5000/√3 + 6000 − 100), 9800)
/// = (floor(8786.751…), 9800) = (8786, 9800), and R3 = (8786, 0) (cot 90°
/// = 0). Absolute: X = 50000 − y, Z = −u.
#[test]
fn sixty_degree_round_with_an_integer_k1_depth() {
    let c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(52_000, 1_000),
        start: Point::new(50_000, 0),
        peck: 2_000,
        step: 1_500,
        depth: -10_000,
        width: -6_000,
        flank_a: 600_000,
        flank_b: 900_000,
        slope: 0,
        retract: 200,
        layer: None,
        allowance_x: 200,
        allowance_z: 100,
        tool_width: None,
        path: PathType::Rough,
        corners: [
            Corner::SHARP,
            Corner::SHARP,
            Corner { size: 1_000, kind: CornerKind::Round },
            Corner::SHARP,
        ],
        readings: crate::G75Readings::DEFAULT,
    };
    let g = Geometry::new(&c);
    // Undecided at 512 bits without the rule.
    assert_eq!(Enclosures::<Interval<SLOW>>::new(&g).eval(&g, Quantity::YK1).round(Rounding::Floor), None);
    let p = groove_profile(&c).unwrap();
    assert_eq!(
        p.roughing(),
        [
            Point::new(50_000, -100),
            Point::new(41_300, -2_612),
            Point::new(40_200, -3_565),
            Point::new(40_200, -8_786),
            Point::new(50_000, -8_786),
        ]
    );
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    let contour: Vec<Point> = moves.iter().filter(|m| m.role == Role::RoughContour).map(|m| m.to).collect();
    // A11 = (ceil(left(9800)), 0) = (3565, 0): rapid to R0, the feeds, back.
    assert_eq!(
        contour,
        [
            Point::new(50_000, -100),
            Point::new(41_300, -2_612),
            Point::new(40_200, -3_565),
            Point::new(40_200, -8_786),
            Point::new(50_000, -8_786),
            Point::new(50_000, -3_565),
        ]
    );
}

/// The commonest tie family: a round bottom corner whose radius (in
/// X-word units) equals the X allowance. Then `f·t3·sin a = f·ρ·tan(a/2)·
/// sin a = f·ρ·(1 − cos a)`, so the depth of K1 is `Y − Δu − f·ρ +
/// (f·ρ − Δu)·cos a = Y − 2Δu`, an integer, at every angle; R-G75TIE
/// takes it on the integer.
#[test]
fn round_corner_equal_to_the_allowance_is_decided() {
    // The golden square groove with A80: U0.8 and D0.4 (f·ρ = 800 = Δu).
    let c = G75Cycle { flank_a: 800_000, allowance_x: 800, ..square() };
    let g = Geometry::new(&c);
    assert_eq!(Enclosures::<Interval<SLOW>>::new(&g).eval(&g, Quantity::YK1).round(Rounding::Floor), None);
    // y_K1 = 6000 − 1600 = 4400; K1 = (ceil(2200·cot 80° + 200) =
    // ceil(587.919…), 4400); y_K4 = 6000 − 800 − 600 − 800·0 = 4600 (B90,
    // exact). R0 (200, 0), K2 (ceil(1064.620…), 5200), K3
    // (floor(8028.980…), 5200), K4 and R3 at floor(8328.980…) (mpmath).
    let p = groove_profile(&c).unwrap();
    assert_eq!(
        p.roughing(),
        [
            Point::new(30_000, -200),
            Point::new(25_600, -588),
            Point::new(24_800, -1_065),
            Point::new(24_800, -8_028),
            Point::new(25_400, -8_328),
            Point::new(30_000, -8_328),
        ]
    );
    assert!(expand_g75(&c).is_ok());
    assert!(expand_g75(&G75Cycle { flank_a: 900_000, ..c }).is_ok());
    assert!(expand_g75(&G75Cycle { allowance_x: 799, ..c }).is_ok());
    assert!(expand_g75(&G75Cycle { path: PathType::Finish, ..c }).is_ok());
}

/// R-G75K1Y: K4's u is `floor(flankB_r(y_K4))` at the integer `y_K4 =
/// floor(Y − Δu − f·t4·sin b − Δu·cos b)`, not at the exact real depth.
/// Here the exact depth is `80 + 16·cos 15° = 95.4548…`, so y_K4 = 95 and
/// `flankB_r(95) = 48·cot 23.7156° + 89 + (1/2)·cot 15° = 200.1322…`
/// (mpmath, 60 digits): K4 = (200, 95); at the exact depth the flank
/// would give floor(199.2835…) = 199 instead.
#[test]
fn k_vertices_use_the_integer_depth() {
    let c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(52_000, 1_500),
        start: Point::new(50_000, 1_000),
        peck: 10,
        step: 63,
        depth: -96,
        width: -89,
        flank_a: 237_156,
        flank_b: 150_000,
        slope: 0,
        retract: 1_599,
        layer: None,
        allowance_x: 0,
        allowance_z: 0,
        tool_width: Some(53),
        path: PathType::RoughAndFinish,
        corners: [
            Corner { size: 14, kind: CornerKind::Chamfer },
            Corner { size: 165, kind: CornerKind::Chamfer },
            Corner::SHARP,
            Corner { size: 8, kind: CornerKind::Round },
        ],
        readings: crate::G75Readings::DEFAULT,
    };
    let p = groove_profile(&c).unwrap();
    // R0, Q1, K3, K4, R3: K4 = (200, 95) → X = 50000 − 95, Z = 1000 − 200.
    assert_eq!(p.roughing()[3], Point::new(49_905, 800));
    // In the moves, less w = 53: Z = 1000 − 147.
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    assert!(moves.iter().any(|m| m.role == Role::RoughContour && m.to == Point::new(49_905, 853)));
}

/// R-G75ARCZERO: a round whose rounded end is its start is left out like
/// any empty move. At A = 0.0001° a round r3 of ρ = 1 has `t3 =
/// tan(0.00005°) ≈ 8.7·10⁻⁷`, so T3a and T3b both round to (P1.u, Y) with
/// P1.u = `1·cot 0.0001°` = 572957.795… → 572958.
#[test]
fn empty_arc_is_dropped() {
    let c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(110, 10),
        start: Point::new(100, 0),
        peck: 2,
        step: 2,
        depth: -2,
        width: 10,
        flank_a: 1,
        flank_b: 900_000,
        slope: 0,
        retract: 0,
        layer: None,
        allowance_x: 0,
        allowance_z: 0,
        tool_width: None,
        path: PathType::Finish,
        corners: [Corner::SHARP, Corner::SHARP, Corner { size: 1, kind: CornerKind::Round }, Corner::SHARP],
        readings: crate::G75Readings::DEFAULT,
    };
    // The profile keeps the round (R-G75PROFILE), of zero length.
    let p = groove_profile(&c).unwrap();
    let f = p.finishing();
    assert_eq!(f[1].at, Point::new(98, 572_958));
    assert_eq!(f[2].at, f[1].at);
    assert!(matches!(f[2].segment, ProfileSegment::Arc { .. }));
    // The moves do not: S, P1 (= T3a = T3b), P2, P3.
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    assert!(moves.iter().all(|m| !matches!(m.motion, Motion::Arc { .. })));
    let feeds: Vec<Point> = moves.iter().filter(|m| m.motion == Motion::Feed).map(|m| m.to).collect();
    assert_eq!(feeds, [Point::new(98, 572_958), Point::new(98, 572_968), Point::new(100, 572_968)]);
}

/// K1 (K4) is a vertex only below the layer top: when the moved chord
/// meets its flank at or above `y_top` the chord is the boundary over
/// the whole depth and R0 (R3) lies on it (§8, R-G75K1Y). A square
/// groove (exact) with chamfers r3 = r4 = 3 over a depth of 4 and Δu = 1
/// at f = 1: y_K1 = 4 − 1 − 3·1 − 1·0 = 0 = y_top.
#[test]
fn k1_above_the_top_is_not_a_vertex() {
    let c = G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Radius,
        from: Point::new(110, 10),
        start: Point::new(100, 0),
        peck: 2,
        step: 2,
        depth: -4,
        width: 10,
        flank_a: 900_000,
        flank_b: 900_000,
        slope: 0,
        retract: 0,
        layer: None,
        allowance_x: 1,
        allowance_z: 0,
        tool_width: None,
        path: PathType::Rough,
        corners: [
            Corner::SHARP,
            Corner::SHARP,
            Corner { size: 3, kind: CornerKind::Chamfer },
            Corner { size: 3, kind: CornerKind::Chamfer },
        ],
        readings: crate::G75Readings::DEFAULT,
    };
    // left(0) = max(0, 3 − (3 − 0)·cot 45°) = 0; right(0) = min(10, 7 +
    // 3) = 10. R0 (0, 0), K2 (3, 3), K3 (7, 3), R3 (10, 0): X = 100 − y,
    // Z = u.
    let p = groove_profile(&c).unwrap();
    assert_eq!(p.roughing(), [Point::new(100, 0), Point::new(97, 3), Point::new(97, 7), Point::new(100, 10)]);
    // Δu = 0: y_K1 = 1 > 0, K1 = (0, 1) and K4 = (10, 1) are vertices.
    let p = groove_profile(&G75Cycle { allowance_x: 0, ..c }).unwrap();
    assert_eq!(
        p.roughing(),
        [
            Point::new(100, 0),
            Point::new(99, 0),
            Point::new(96, 3),
            Point::new(96, 7),
            Point::new(99, 10),
            Point::new(100, 10)
        ]
    );
}

/// A groove on a slope, with four rounds and layers: the moves satisfy
/// the invariants of docs/G75.md §10 that need no exact boundary.
#[test]
fn slope_groove_invariants() {
    // U0.301 instead of U0.3 and B74 instead of B75: no value on a
    // rounding boundary (tie_values_are_decided has the example itself).
    let c = G75Cycle { allowance_x: 301, flank_b: 740_000, ..slope_example() };
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    let local = |p: Point| (c.axial_sign() * (p.z - c.start.z), c.radial_sign() * (p.x - c.start.x));
    let mut at = c.from;
    for m in &moves {
        assert_ne!(m.to, at);
        let ((u0, y0), (u1, y1)) = (local(at), local(m.to));
        match m.role {
            Role::Peck(_) => assert!(u0 == u1 && y1 > y0 && y1 - y0 <= c.peck + c.retract * 2),
            Role::Step(_) => assert!(y0 == y1 && u1 > u0 && u1 - u0 <= c.step),
            _ => {}
        }
        at = m.to;
    }
    assert_eq!(at, c.from);
    // y3 = −2·u3·tan 10° < 0: the opening rises towards the far side.
    let p = groove_profile(&c).unwrap();
    let last = p.finishing().last().unwrap();
    assert!(local(last.at).1 < 0);
    assert_eq!(p.finishing().len(), 8);
    assert_eq!(p.roughing().len(), 6);
    // The fast path (R-FASTPATH) and the slow context agree on every value
    // they decide.
    let mut fallback = Fallback::default();
    let mut ev = Evaluator::new(Geometry::new(&c), true, &mut fallback);
    let slow = Enclosures::<Interval<SLOW>>::new(&ev.g);
    for q in [
        Quantity::U3,
        Quantity::Y3,
        Quantity::Left(3_000),
        Quantity::YK4,
        Quantity::FlankA(8_148),
        Quantity::FlankB(8_029),
        Quantity::C1U,
        Quantity::C2Y,
        Quantity::T4cU,
        Quantity::T2sY,
    ] {
        let fast = ev.nearest(q).unwrap();
        assert_eq!(slow.eval(&ev.g, q).round(Rounding::Nearest), Some(fast), "{q:?}");
    }
    // y_K1 = 9000 − 301 − 400 − 150.5 = 8148.5 exactly: its floor is
    // decided, its nearest only by R-G75TIE (the tie goes up).
    assert_eq!(ev.floor(Quantity::YK1), Ok(8_148));
    assert_eq!(slow.eval(&ev.g, Quantity::YK1).round(Rounding::Nearest), None);
    assert_eq!(ev.nearest(Quantity::YK1), Ok(8_149));
}

/// `G00 X90 Z12; G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10; G75.1
/// R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111` at IS-B.
fn slope_example() -> G75Cycle {
    crate::examples::G75_SLOPE
}

/// The benchmark's wide groove (`benches/src/cases.rs`): `G00 X210 Z5;
/// G75.1 X200 Z0 P500 Q300 H-40 D-200 A80 B70; G75.1 R0.1 V10 I3 J1` at
/// IS-B: four layers of about 660 plunges.
fn wide_example() -> G75Cycle {
    G75Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        from: Point::new(210_000, 5_000),
        start: Point::new(200_000, 0),
        peck: 500,
        step: 300,
        depth: -40_000,
        width: -200_000,
        flank_a: 800_000,
        flank_b: 700_000,
        slope: 0,
        retract: 100,
        layer: Some(10_000),
        allowance_x: 0,
        allowance_z: 0,
        tool_width: Some(3_000),
        path: PathType::RoughAndFinish,
        corners: [Corner::SHARP; 4],
        readings: crate::G75Readings::DEFAULT,
    }
}

#[test]
fn wide_groove() {
    let c = wide_example();
    let t = std::time::Instant::now();
    let n = expand_g75(&c).unwrap().count();
    std::println!("wide: {n} moves in {:?}", t.elapsed());
    let t = std::time::Instant::now();
    let n2 = expand_g75(&seed()).unwrap().count();
    std::println!("seed: {n2} moves in {:?}", t.elapsed());
    let t = std::time::Instant::now();
    let n3 = expand_g75(&G75Cycle { allowance_x: 301, flank_b: 740_000, ..slope_example() }).unwrap().count();
    std::println!("slope: {n3} moves in {:?}", t.elapsed());
    let moves: Vec<Move> = expand_g75(&c).unwrap().collect();
    // Every plunge of a layer reaches the layer's bottom, and the layers
    // are 10 mm of diameter deep.
    let bottoms: Vec<i64> =
        moves.iter().filter(|m| matches!(m.role, Role::PlungeRetract(_))).map(|m| m.to.x).collect();
    assert!(bottoms.iter().all(|x| [200_000, 190_000, 180_000, 170_000].contains(x)));
    assert_eq!(moves.last().map(|m| m.to), Some(c.from));
}

/// A cutting move of the finishing contour: local end and arc centre.
type ContourMove = (i64, i64, Option<(i64, i64)>);

/// A small deterministic generator for the sweeps.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = u64::try_from(hi - lo + 1).unwrap();
        lo + i64::try_from(self.next() % span).unwrap()
    }
}

/// A random cycle: small sizes, any signs, units, J, corners.
fn random_cycle(r: &mut Rng, square: bool) -> G75Cycle {
    let units = Units {
        system: if r.range(0, 1) == 0 { IncrementSystem::IsB } else { IncrementSystem::IsC },
        unit: if r.range(0, 1) == 0 { InputUnit::Metric } else { InputUnit::Inch },
    };
    let x_mode = if r.range(0, 1) == 0 { XMode::Diameter } else { XMode::Radius };
    let sx = if r.range(0, 1) == 0 { -1 } else { 1 };
    let sz = if r.range(0, 1) == 0 { -1 } else { 1 };
    let depth = r.range(1, 40);
    let mut corners = [Corner::SHARP; 4];
    for k in &mut corners {
        if r.range(0, 2) == 0 {
            let kind = if r.range(0, 1) == 0 { CornerKind::Round } else { CornerKind::Chamfer };
            *k = Corner { size: r.range(1, 6), kind };
        }
    }
    let (flank_a, flank_b, slope) = if square {
        (900_000, 900_000, 0)
    } else {
        let b = u32::try_from(r.range(100_000, 900_000)).unwrap();
        let l = if r.range(0, 1) == 0 {
            0
        } else {
            u32::try_from(r.range(0, i64::from(b) - 1).min(600_000)).unwrap()
        };
        (u32::try_from(r.range(100_000, 900_000)).unwrap(), b, l)
    };
    let start = Point::new(100_000, 5_000);
    G75Cycle {
        units,
        x_mode,
        from: Point::new(start.x - sx * 10, start.z - sz * 10),
        start,
        peck: r.range(1, 12),
        step: r.range(1, 8),
        depth: sx * depth,
        width: sz * r.range(0, 30),
        flank_a,
        flank_b,
        slope,
        retract: r.range(0, 3),
        layer: if r.range(0, 1) == 0 { None } else { Some(r.range(1, 20)) },
        allowance_x: r.range(0, 3).min(depth - 1),
        allowance_z: r.range(0, 3),
        tool_width: if r.range(0, 1) == 0 { None } else { Some(r.range(0, 8)) },
        path: match r.range(0, 2) {
            0 => PathType::Rough,
            1 => PathType::RoughAndFinish,
            _ => PathType::Finish,
        },
        corners,
        readings: crate::G75Readings::DEFAULT,
    }
}

/// docs/G75.md §10 on right-angle grooves, where every boundary is exact
/// in doubled integers: no empty move, pecks along X taking at most Δi
/// of new depth, steps along Z of at most Δk, every roughing position
/// with its width inside the roughing region, every plunge reaching its
/// layer's bottom, the finishing contour through the profile points,
/// the path ending at `from`.
#[test]
fn square_groove_sweep() {
    let mut r = Rng(0x1234_5678_9ABC_DEF1);
    let mut expanded = 0;
    for _ in 0..20_000 {
        let c = random_cycle(&mut r, true);
        let Ok(moves) = expand_g75(&c) else { continue };
        let moves: Vec<Move> = moves.collect();
        expanded += 1;
        let f = c.x_mode.factor();
        let (yy, d, du, dw, w) =
            (c.depth.abs(), c.width.abs(), c.allowance_x, c.allowance_z, c.width_of_tool());
        let (t3, t4) = (c.corners[corner::R3].size, c.corners[corner::R4].size);
        let bottom = yy - du;
        // f·left(y), f·right(y), exact (cot 90° = 0, cot 45° = 1).
        let left_f = |y: i64| {
            let flank = f * dw;
            if t3 > 0 {
                flank.max(f * (t3 + dw) - (bottom - y))
            } else {
                flank
            }
        };
        let right_f = |y: i64| {
            let flank = f * (d - dw);
            if t4 > 0 {
                flank.min(f * (d - t4 - dw) + (bottom - y))
            } else {
                flank
            }
        };
        let local = |p: Point| (c.axial_sign() * (p.z - c.start.z), c.radial_sign() * (p.x - c.start.x));
        let mut at = c.from;
        let mut deepest: Option<i64> = None;
        let mut last_peck: Option<(Plunge, i64)> = None;
        let mut layer_bottom: Vec<i64> = Vec::new();
        for m in &moves {
            assert_ne!(m.to, at, "{c:?}");
            let ((u0, y0), (u1, y1)) = (local(at), local(m.to));
            match m.role {
                Role::Peck(p) => {
                    assert!(u0 == u1 && y1 > y0, "{c:?}");
                    let before = deepest.map_or(y0, |v| v.max(y0));
                    assert!(y1 - before <= c.peck, "{c:?}");
                    deepest = Some(before.max(y1));
                    last_peck = Some((p, y1));
                }
                Role::PeckRetract(_) => {
                    assert!(u0 == u1 && y1 < y0 && y0 - y1 <= f * c.retract, "{c:?}");
                }
                Role::PlungeRetract(p) => {
                    let (q, y) = last_peck.unwrap();
                    assert_eq!(p, q);
                    let l = usize::try_from(p.layer).unwrap();
                    if layer_bottom.len() < l {
                        layer_bottom.push(y);
                    }
                    assert_eq!(layer_bottom[l - 1], y, "every plunge reaches its layer's bottom");
                    deepest = None;
                }
                Role::Step(_) => assert!(y0 == y1 && u1 > u0 && u1 - u0 <= c.step, "{c:?}"),
                _ => {}
            }
            let roughing = matches!(
                m.role,
                Role::Peck(_)
                    | Role::PeckRetract(_)
                    | Role::PlungeRetract(_)
                    | Role::Step(_)
                    | Role::LayerChange(_)
                    | Role::RoughContour
            );
            if roughing && y1 > 0 {
                assert!(y1 <= bottom, "{c:?}");
                assert!(f * u1 >= left_f(y1) && f * (u1 + w) <= right_f(y1), "{c:?} {m:?}");
            }
            at = m.to;
        }
        assert_eq!(at, c.from);
        if c.path.roughs() {
            assert_eq!(layer_bottom.last().copied(), Some(bottom));
            if let Some(v) = c.layer {
                assert!(layer_bottom.windows(2).all(|p| p[1] > p[0] && p[1] - p[0] <= v));
            }
        }
        if c.path.finishes() {
            // The contour's cutting moves (docs/G75.md §3 with a = b = 90°).
            // Twin: `proofs/src/groove.rs`, `groove_finish_is_profile` (the
            // same expected moves; the proofs crate depends on this one, so
            // its oracle cannot serve here).
            let [r1, r2, r3, r4] = c.corners;
            let arc = |k: Corner, centre: (i64, i64)| (k.kind == CornerKind::Round).then_some(centre);
            let mut expected: Vec<ContourMove> = Vec::new();
            if r1.size > 0 {
                expected.push((0, f * r1.size, arc(r1, (-r1.size, f * r1.size))));
            }
            if r3.size > 0 {
                expected.push((0, yy - f * r3.size, None));
                expected.push((r3.size, yy, arc(r3, (r3.size, yy - f * r3.size))));
            } else {
                expected.push((0, yy, None));
            }
            if r4.size > 0 {
                expected.push((d - r4.size - w, yy, None));
                expected.push((d - w, yy - f * r4.size, arc(r4, (d - r4.size - w, yy - f * r4.size))));
            } else {
                expected.push((d - w, yy, None));
            }
            if r2.size > 0 {
                expected.push((d - w, f * r2.size, None));
                expected.push((d + r2.size - w, 0, arc(r2, (d + r2.size - w, f * r2.size))));
            } else {
                expected.push((d - w, 0, None));
            }
            let mut pos = if r1.size > 0 { (-r1.size, 0) } else { (0, 0) };
            let expected: Vec<_> = expected
                .into_iter()
                .filter(|e| {
                    let keep = (e.0, e.1) != pos;
                    pos = (e.0, e.1);
                    keep
                })
                .collect();
            let got: Vec<ContourMove> = moves
                .iter()
                .filter(|m| m.role == Role::FinishContour && m.motion != Motion::Rapid)
                .map(|m| {
                    let (u, y) = local(m.to);
                    let centre = match m.motion {
                        Motion::Arc { centre, .. } => Some(local(centre)),
                        _ => None,
                    };
                    (u, y, centre)
                })
                .collect();
            assert_eq!(got, expected, "{c:?}");
        }
    }
    assert!(expanded > 5_000, "only {expanded} cycles expanded");
}

/// Every rounded value of the profile and of layer 1's plunge range
/// against the formulas of docs/G75.md §3–§8 evaluated in `f64` (where
/// the float is clear of a rounding boundary), at arbitrary angles.
#[test]
fn formulas_against_floats() {
    let mut r = Rng(0xDEAD_BEEF_CAFE_F00D);
    let mut compared = 0;
    for _ in 0..3_000 {
        let mut c = random_cycle(&mut r, false);
        c.depth *= 1_000;
        c.width *= 1_000;
        c.peck *= 1_000;
        c.step *= 1_000;
        c.layer = c.layer.map(|v| v * 1_000);
        c.allowance_x *= 100;
        c.allowance_z *= 100;
        for k in &mut c.corners {
            k.size *= 300;
        }
        c.start = Point::new(10_000_000, 2_000_000);
        c.from = Point::new(c.start.x - c.radial_sign() * 10, c.start.z - c.axial_sign() * 10);
        let Ok(p) = groove_profile(&c) else { continue };
        let deg = |v: u32| f64::from(v) / 10_000.0 * core::f64::consts::PI / 180.0;
        let (a, b, l) = (deg(c.flank_a), deg(c.flank_b), deg(c.slope));
        let f = c.x_mode.factor() as f64;
        let (yy, d, du, dw, w) = (
            c.depth.abs() as f64,
            c.width.abs() as f64,
            c.allowance_x as f64,
            c.allowance_z as f64,
            c.width_of_tool() as f64,
        );
        let tl = |i: usize, half: f64| {
            let k = c.corners[i];
            let s = k.size as f64;
            if k.kind == CornerKind::Round {
                s * half.tan()
            } else {
                s
            }
        };
        let (t1, t2, t3, t4) = (tl(0, (a + l) / 2.0), tl(1, (b - l) / 2.0), tl(2, a / 2.0), tl(3, b / 2.0));
        let rho = |i: usize| c.corners[i].size as f64;
        let cot = |x: f64| x.cos() / x.sin();
        let p1 = yy / f * cot(a);
        let u3 = (p1 + d + yy / f * cot(b)) / (1.0 - l.tan() * cot(b));
        let y3 = -f * u3 * l.tan();
        let flank_a = |y: f64| y / f * cot(a) + dw;
        let flank_b = |y: f64| p1 + d + (yy - y) / f * cot(b) - dw;
        let chord3 = |y: f64| p1 + t3 + dw - (yy - du - y) / f * cot(a / 2.0);
        let chord4 = |y: f64| p1 + d - t4 - dw + (yy - du - y) / f * cot(b / 2.0);
        let mut exp: Vec<(f64, f64)> = Vec::new();
        if c.corners[0].size > 0 {
            exp.push((-t1 * l.cos(), f * t1 * l.sin()));
            exp.push((t1 * a.cos(), f * t1 * a.sin()));
        } else {
            exp.push((0.0, 0.0));
        }
        if c.corners[2].size > 0 {
            exp.push((p1 - t3 * a.cos(), yy - f * t3 * a.sin()));
            exp.push((p1 + t3, yy));
        } else {
            exp.push((p1, yy));
        }
        if c.corners[3].size > 0 {
            exp.push((p1 + d - t4, yy));
            exp.push((p1 + d + t4 * b.cos(), yy - f * t4 * b.sin()));
        } else {
            exp.push((p1 + d, yy));
        }
        if c.corners[1].size > 0 {
            exp.push((u3 - t2 * b.cos(), y3 + f * t2 * b.sin()));
            exp.push((u3 + t2 * l.cos(), y3 - f * t2 * l.sin()));
        } else {
            exp.push((u3, y3));
        }
        let mut centres: Vec<Option<(f64, f64)>> = std::vec![None; exp.len()];
        let mut i = 1;
        if c.corners[0].size > 0 {
            if c.corners[0].kind == CornerKind::Round {
                centres[i] = Some((t1 * a.cos() - rho(0) * a.sin(), f * t1 * a.sin() + f * rho(0) * a.cos()));
            }
            i += 1;
        }
        i += 1;
        if c.corners[2].size > 0 {
            if c.corners[2].kind == CornerKind::Round {
                centres[i] = Some((p1 + t3, yy - f * rho(2)));
            }
            i += 1;
        }
        i += 1;
        if c.corners[3].size > 0 {
            if c.corners[3].kind == CornerKind::Round {
                centres[i] = Some((p1 + d - t4, yy - f * rho(3)));
            }
            i += 1;
        }
        i += 1;
        if c.corners[1].size > 0 && c.corners[1].kind == CornerKind::Round {
            centres[i] =
                Some((u3 - t2 * b.cos() + rho(1) * b.sin(), y3 + f * t2 * b.sin() + f * rho(1) * b.cos()));
        }
        let local = |q: Point| (c.axial_sign() * (q.z - c.start.z), c.radial_sign() * (q.x - c.start.x));
        // `v` rounds to `got` unless the float is within 1e-6 of a boundary.
        let check = |v: f64, got: i64, what: &str| {
            let near = (v + 0.5 - (v + 0.5).round()).abs() < 1e-6;
            if !near {
                assert_eq!((v + 0.5).floor() as i64, got, "{what}: {v} in {c:?}");
            }
        };
        assert_eq!(p.finishing().len(), exp.len());
        for ((q, e), ctr) in p.finishing().iter().zip(&exp).zip(&centres) {
            let (u, y) = local(q.at);
            check(e.0, u, "u");
            check(e.1, y, "y");
            match (q.segment, ctr) {
                (ProfileSegment::Arc { centre, .. }, Some(cc)) => {
                    let (cu, cy) = local(centre);
                    check(cc.0, cu, "centre u");
                    check(cc.1, cy, "centre y");
                }
                (ProfileSegment::Arc { .. }, None) | (_, Some(_)) => panic!("arc mismatch {c:?}"),
                _ => {}
            }
        }
        // Roughing vertices: ceil on the left, floor on the right.
        let ceil = |v: f64, got: i64| {
            if (v - v.round()).abs() > 1e-6 {
                assert_eq!(v.ceil() as i64, got, "ceil {v} {c:?}");
            }
        };
        let floor = |v: f64, got: i64| {
            if (v - v.round()).abs() > 1e-6 {
                assert_eq!(v.floor() as i64, got, "floor {v} {c:?}");
            }
        };
        let rv: Vec<(i64, i64)> = p.roughing().iter().map(|q| local(*q)).collect();
        let y_top = rv[0].1;
        floor(y3, y_top);
        let left = |y: f64| if c.corners[2].size > 0 { flank_a(y).max(chord3(y)) } else { flank_a(y) };
        let right = |y: f64| if c.corners[3].size > 0 { flank_b(y).min(chord4(y)) } else { flank_b(y) };
        // R0, R3 on left/right (R-G75MAXMIN); K1, K4 on the flanks at the
        // integer depth, only below y_top (R-G75K1Y). A depth too near an
        // integer for the float leaves the vertex count open: skipped.
        let bottom = yy - du;
        let near_int = |v: f64| (v - v.round()).abs() < 1e-6;
        let yk1 = bottom - f * t3 * a.sin() - du * a.cos();
        let yk4 = bottom - f * t4 * b.sin() - du * b.cos();
        if (c.corners[2].size > 0 && near_int(yk1)) || (c.corners[3].size > 0 && near_int(yk4)) {
            continue;
        }
        ceil(left(y_top as f64), rv[0].0);
        let mut k = 1;
        if c.corners[2].size > 0 {
            let y = yk1.floor();
            if y as i64 > y_top {
                assert_eq!(rv[k].1, y as i64, "{c:?}");
                ceil(flank_a(y), rv[k].0);
                k += 1;
            }
            ceil(p1 + t3 + dw, rv[k].0);
            k += 1;
        } else {
            ceil(flank_a(bottom), rv[k].0);
            k += 1;
        }
        if c.corners[3].size > 0 {
            floor(p1 + d - t4 - dw, rv[k].0);
            k += 1;
            let y = yk4.floor();
            if y as i64 > y_top {
                assert_eq!(rv[k].1, y as i64, "{c:?}");
                floor(flank_b(y), rv[k].0);
                k += 1;
            }
        } else {
            floor(flank_b(bottom), rv[k].0);
            k += 1;
        }
        floor(right(y_top as f64), rv[k].0);
        assert_eq!(rv.len(), k + 1, "{c:?}");
        // Layer 1's plunge range, through the first move's Z (A11).
        if let Ok(mut moves) = expand_g75(&c) {
            let y1 = c.layer.map_or(bottom, |v| (v as f64).min(bottom));
            let first = moves.next().unwrap();
            ceil(left(y1), local(first.to).0);
            if c.path.roughs() {
                // The last plunge of layer 1: before the first layer change.
                let last = moves
                    .take_while(|m| !matches!(m.role, Role::LayerChange(_) | Role::Approach))
                    .filter(|m| matches!(m.role, Role::PlungeRetract(_)))
                    .last()
                    .unwrap();
                floor(right(y1) - w, local(last.to).0);
            }
            compared += 1;
        }
    }
    assert!(compared > 500, "only {compared} cycles compared");
}

#[test]
fn size_of_the_iterator() {
    let s = core::mem::size_of::<G75Moves>();
    std::println!("G75Moves: {s} bytes");
    assert!(s <= 1_300, "G75Moves is {s} bytes");
}

/// `v·2^-64` exactly, at 512 fraction bits.
fn at_512(v: i128) -> Interval<SLOW> {
    let x = Interval::<SLOW>::int(v).div_int(1 << 32).div_int(1 << 32);
    assert!(x.is_point());
    x
}

/// Every quantity of the groove (R-FASTPATH), at the depths `ys` for the
/// region's boundaries.
fn every_quantity(ys: &[i128]) -> Vec<Quantity> {
    let mut qs = std::vec![
        Quantity::CheckFlankA,
        Quantity::CheckBottom,
        Quantity::CheckFlankB,
        Quantity::Y3,
        Quantity::U3,
        Quantity::YK1,
        Quantity::K2,
        Quantity::K3,
        Quantity::YK4,
        Quantity::P1U,
        Quantity::P2U,
        Quantity::T1sU,
        Quantity::T1sY,
        Quantity::T1aU,
        Quantity::T1aY,
        Quantity::C1U,
        Quantity::C1Y,
        Quantity::T3aU,
        Quantity::T3aY,
        Quantity::T3bU,
        Quantity::C3Y,
        Quantity::T4bU,
        Quantity::T4cU,
        Quantity::T4cY,
        Quantity::C4Y,
        Quantity::T2bU,
        Quantity::T2bY,
        Quantity::T2sU,
        Quantity::T2sY,
        Quantity::C2U,
        Quantity::C2Y,
    ];
    for &y in ys {
        qs.extend([Quantity::Left(y), Quantity::Right(y), Quantity::FlankA(y), Quantity::FlankB(y)]);
    }
    qs
}

/// The fast path's bound of every formula (R-FASTPATH) against the exact
/// value at 512 bits, on grooves that reach the formulas' extremes: the
/// examples, every corner kind, a slope, flanks of 0.0001° and 89.9999°
/// (cotangents near 2^20, the largest the magnitudes allow) and sizes near
/// the words' limits. Where the fast path decides a rounding or a sign it
/// is the exact value's (R-G75TIE's at 512 bits); where its value would
/// overflow it is unknown and decides nothing.
#[test]
fn fast_path_bounds_hold_for_every_formula() {
    let mut cycles = std::vec![seed(), square(), slope_example(), wide_example()];
    let mut steep = slope_example();
    steep.flank_a = 1;
    steep.flank_b = 899_999;
    steep.slope = 0;
    cycles.push(steep);
    let mut flat = slope_example();
    flat.flank_a = 899_999;
    flat.flank_b = 1_000;
    flat.slope = 999;
    cycles.push(flat);
    let mut huge = wide_example();
    huge.depth = -(1 << 26);
    huge.width = -(1 << 26);
    huge.flank_a = 7;
    huge.flank_b = 13;
    huge.corners = [Corner { size: 1 << 19, kind: CornerKind::Round }; 4];
    cycles.push(huge);
    let (mut checked, mut unknown, mut decided) = (0, 0, 0);
    let mut worst = 0.0_f64;
    for c in &cycles {
        let g = Geometry::new(c);
        let quick = Enclosures::<Approx>::new(&g);
        let slow = Enclosures::<Interval<SLOW>>::new(&g);
        let ys = [0, 1, i128::from(g.depth - g.du) / 2, i128::from(g.depth - g.du)];
        for q in every_quantity(&ys) {
            let a = quick.eval(&g, q);
            let x = slow.eval(&g, q);
            if a.is_unknown() {
                unknown += 1;
                continue;
            }
            if !x.is_valid() {
                // A value the cycle does not have (an absent corner's).
                continue;
            }
            let e = i128::try_from(a.bound()).unwrap();
            let (lo, hi) = (at_512(a.value() - e), at_512(a.value() + e));
            assert!(lo.lower().cmp_signed(x.lower()) != Ordering::Greater, "{c:?} {q:?}: {a:?}");
            assert!(x.upper().cmp_signed(hi.upper()) != Ordering::Greater, "{c:?} {q:?}: {a:?}");
            checked += 1;
            let scale = (a.value().unsigned_abs() as f64).max(1.0);
            worst = worst.max(a.bound() as f64 / scale);
            for r in [Rounding::Floor, Rounding::Ceil, Rounding::Nearest] {
                if let Some(k) = a.round(r) {
                    decided += 1;
                    assert_eq!(x.round_tie(r), Some(k), "{c:?} {q:?} {r:?}");
                }
            }
            if let Some(s) = a.sign() {
                assert_eq!(x.sign_tie(), Some(s), "{c:?} {q:?}");
            }
        }
    }
    std::println!("{checked} values within their bounds ({decided} roundings decided), {unknown} unknown; largest relative bound {worst:.2e}");
    assert!(checked > 150 && decided > 300);
}

/// `expand_g75_planned` with one plan kept across cycles gives exactly what
/// `expand_g75` gives each cycle alone (moves, alarm, the fast path's
/// counts): random grooves, each also moved to other places (the plan
/// reused) and to places where the moves leave the range (R-G75RANGE after
/// a reused plan), and cycles that the geometry refuses (no plan kept).
#[test]
fn planned_expansion_is_the_plain_one() {
    let outcome = |r: Result<G75Moves, CycleError>| {
        r.map(|mut m| {
            let moves: Vec<Move> = m.by_ref().collect();
            (moves, m.fast_path_stats(), m.layers_and_plunges())
        })
    };
    let mut r = Rng(0x0F0E_0D0C_0B0A_0908);
    let mut plan = None;
    let (mut reused, mut refused, mut out_of_range) = (0, 0, 0);
    for i in 0..6_000 {
        let c = random_cycle(&mut r, i % 3 == 0);
        let far = MAX_LENGTH - 20;
        let shifts = [(0, 0), (-2_000, 7_000), (far - c.start.x, 0), (0, far - c.start.z), (3, -3)];
        for (dx, dz) in shifts {
            let mut m = c;
            m.start = Point::new(c.start.x + dx, c.start.z + dz);
            m.from = Point::new(c.from.x + dx, c.from.z + dz);
            let fits = matches!(&plan, Some(p) if G75Plan::fits(p, &m));
            let want = outcome(expand_g75(&m));
            let got = outcome(expand_g75_planned(&m, &mut plan));
            assert_eq!(got, want, "{m:?}");
            // The check alone, from the plan kept and from none.
            let alarm = want.as_ref().err().cloned();
            assert_eq!(check_g75_planned(&m, &mut plan).err(), alarm, "{m:?}");
            assert_eq!(check_g75_planned(&m, &mut None).err(), alarm, "{m:?}");
            reused += usize::from(fits);
            refused += usize::from(want.is_err() && plan.is_none());
            out_of_range += usize::from(
                fits && matches!(want, Err(CycleError::OutOfRange { field: Field::PassCoordinate, .. })),
            );
        }
    }
    // Each kind of case was met (the counts only guard the sweep's reach).
    assert!(reused > 10_000 && refused > 100 && out_of_range > 1_000, "{reused} {refused} {out_of_range}");
}

/// `G75Moves::try_for_each_move` gives the moves `Iterator::next` gives, in
/// order, and stops at the first error of its closure: random grooves
/// (every J, layers, pecks, corners, both directions), each walked whole
/// and stopped at a random move.
#[test]
fn walked_moves_are_the_iterated_ones() {
    let mut r = Rng(0x7A1C_0FF3_3D15_0075);
    let (mut walked, mut stopped) = (0, 0);
    for i in 0..3_000 {
        let c = random_cycle(&mut r, i % 3 == 0);
        let Ok(moves) = expand_g75(&c) else { continue };
        let want: Vec<Move> = moves.clone().collect();
        let mut got = Vec::new();
        let mut all = moves.clone();
        assert_eq!(
            all.try_for_each_move(|m| {
                got.push(m);
                Ok::<(), ()>(())
            }),
            Ok(())
        );
        assert_eq!(got, want, "{c:?}");
        // Nothing is left after the walk.
        assert_eq!(all.next(), None);
        walked += 1;
        // Stopped at move `k`: the moves before it and that one taken,
        // the iterator then goes on after it.
        if want.is_empty() {
            continue;
        }
        let k = usize::try_from(r.range(0, i64::try_from(want.len()).unwrap() - 1)).unwrap();
        let mut part = moves.clone();
        let mut seen = Vec::new();
        let result = part.try_for_each_move(|m| {
            seen.push(m);
            if seen.len() == k + 1 {
                Err(k)
            } else {
                Ok(())
            }
        });
        assert_eq!(result, Err(k));
        assert_eq!(seen, want[..=k].to_vec());
        assert_eq!(part.collect::<Vec<_>>(), want[k + 1..].to_vec(), "{c:?}");
        stopped += 1;
    }
    assert!(walked > 1_000 && stopped > 1_000, "{walked} {stopped}");
}
