//! `groove_equivalence` (`proofs/src/groove.rs`) under `cargo test`: the
//! G75.1 engine against the reference (`cycleref_spec::g75::expand`,
//! `num-bigint`) and against the reference restated in integers
//! (`proofs/src/g75_exact.rs`, what the harness compares with under Kani),
//! and the restatement against the reference, for right-angle grooves:
//!
//! * exhaustively over the harness's Kani window
//!   ([`GROOVE_EQUIVALENCE_WINDOW`], 884 736 grooves);
//! * sampled over wider right-angle grooves (up to 400 increments, every
//!   unit code and corner kind);
//! * sampled over right-angle grooves with corners up to the words' limits,
//!   every unit code (IS-B and IS-C, metric and inch, X diameter and
//!   radius), and over the documented ranges;
//! * the controls: deliberate errors in single steps of the restatement,
//!   each caught by the comparison with the reference.

use cycleref_proofs::g75_exact::{self, Slip};
use cycleref_proofs::groove::{self, GrooveDomain, GrooveFixedPoint};
use cycleref_proofs::shim::{self, check_and_print as check, Mode};
use cycleref_proofs::windows::GROOVE_EQUIVALENCE_WINDOW;

/// The Kani window, every groove.
#[test]
fn equivalence_over_the_kani_window() {
    let r = check("groove equivalence (Kani window)", Mode::Exhaustive { max_runs: 900_000 }, || {
        groove::groove_equivalence(&GROOVE_EQUIVALENCE_WINDOW, &GrooveFixedPoint);
    });
    assert_eq!(r.runs, 884_736);
}

#[test]
fn equivalence_over_wider_square_grooves() {
    check("groove equivalence (square, sampled)", Mode::Sample { runs: 4_000, seed: 0x6737_3565 }, || {
        groove::groove_equivalence(&GrooveDomain::SQUARE_WIDE, &GrooveFixedPoint);
    });
}

/// Right-angle grooves whose corners are large against the groove (sizes
/// up to 1 000 in grooves up to 8 000 deep and wide), so that the corner
/// alarms, the chords of r3 and r4 (K1, K4 above or below the layer top)
/// and the rounds' centres are all reached; steps up to the tool widths, so
/// that layers are not all refused for their ridges; every unit code (IS-B
/// and IS-C, metric and inch, X diameter and radius).
const CORNERS: GrooveDomain = GrooveDomain {
    depth: (1, 8_000),
    width: (0, 8_000),
    peck: (100, 3_000),
    step: (100, 800),
    retract: (0, 300),
    layer: (0, 3_000),
    allowance_x: (0, 200),
    allowance_z: (0, 200),
    tool_width: (-1, 800),
    corner: (0, 1_000),
    ..GrooveDomain::SQUARE
};

/// The documented ranges at right angles: corners up to 999 999, grooves
/// up to 10^8, coordinates out of range, too many pecks.
const FULL_SQUARE: GrooveDomain =
    GrooveDomain { flank: (900_000, 900_000), slope: (0, 0), ..GrooveDomain::FULL };

#[test]
fn restatement_equals_the_reference_with_corners_in_every_unit_system() {
    check("groove equivalence (corners, sampled)", Mode::Sample { runs: 4_000, seed: 0x636f_726e }, || {
        groove::groove_equivalence(&CORNERS, &GrooveFixedPoint);
    });
    // Each unit code on its own, so that every one is sampled as often.
    for units in 0..=7 {
        let d = GrooveDomain { units: (units, units), ..CORNERS };
        check(
            &format!("groove equivalence (corners, unit code {units})"),
            Mode::Sample { runs: 500, seed: 31 + units.unsigned_abs() },
            || {
                groove::groove_equivalence(&d, &GrooveFixedPoint);
            },
        );
    }
    check("groove equivalence (documented ranges)", Mode::Sample { runs: 3_000, seed: 0x6675_6c6c }, || {
        groove::groove_equivalence(&FULL_SQUARE, &GrooveFixedPoint);
    });
}

/// The controls' slice of the Kani window: where each deliberate error
/// shows (the chord of r3 rounded at half increments needs f = 2, layers
/// or an odd roughing depth, and t3 = 1).
/// 82 944 grooves.
const CONTROL: GrooveDomain = GrooveDomain {
    width: (1, 3),
    retract: (1, 1),
    allowance_z: (0, 0),
    signs: (0, 1),
    ..GROOVE_EQUIVALENCE_WINDOW
};

fn caught(slip: Slip) {
    let mutant: groove::Restatement = match slip {
        Slip::None => g75_exact::expand,
        Slip::PlungeEndOffByOne => |c| g75_exact::expand_with(c, Slip::PlungeEndOffByOne),
        Slip::LeftRoundedOut => |c| g75_exact::expand_with(c, Slip::LeftRoundedOut),
        Slip::BottomRoundsReversed => |c| g75_exact::expand_with(c, Slip::BottomRoundsReversed),
    };
    let r = shim::caught(
        Mode::Exhaustive { max_runs: 100_000 },
        || groove::groove_equivalence_with(&CONTROL, &GrooveFixedPoint, g75_exact::expand),
        || groove::groove_equivalence_with(&CONTROL, &GrooveFixedPoint, mutant),
        "the integer restatement and the reference differ",
    );
    eprintln!("{slip:?}: caught; the control ran {} grooves", r.runs);
}

/// An off-by-one plunge range end (`A_mf` one increment past
/// `floor(right(y_m)) − w`) is caught.
#[test]
fn an_off_by_one_plunge_range_end_is_caught() {
    caught(Slip::PlungeEndOffByOne);
}

/// The start-side boundary rounded out (`floor` for `ceil`: the chord of
/// r3 at a half increment) is caught.
#[test]
fn a_boundary_rounded_out_is_caught() {
    caught(Slip::LeftRoundedOut);
}

/// The bottom rounds r3, r4 turning the wrong way (G02 for G03) are caught.
#[test]
fn bottom_rounds_turning_the_wrong_way_are_caught() {
    caught(Slip::BottomRoundsReversed);
}

/// The alarms that no groove drawn by `any_groove` reaches (its start is
/// X100 mm, Z0): a coordinate beyond ±999 999 999 (R-G75RANGE: the first
/// in move order, X before Z), every move kind's end crossing the limit in
/// turn as S moves towards it; and too many pecks (§9). The engine, the
/// restatement and the reference agree on each.
#[test]
fn range_and_peck_alarms_agree() {
    use cycleref::g75::{Corner, CornerKind, G75Cycle, PathType, RIGHT_ANGLE};
    use cycleref::units::MAX_LENGTH;
    use cycleref::{IncrementSystem, InputUnit, Point, Units, XMode};
    let round = Corner { size: 2, kind: CornerKind::Round };
    let base = G75Cycle {
        units: Units { system: IncrementSystem::IsB, unit: InputUnit::Metric },
        x_mode: XMode::Diameter,
        from: Point::new(0, 0),
        start: Point::new(0, 0),
        peck: 3,
        step: 2,
        depth: 12,
        width: 9,
        flank_a: RIGHT_ANGLE,
        flank_b: RIGHT_ANGLE,
        slope: 0,
        retract: 1,
        layer: None,
        allowance_x: 1,
        allowance_z: 1,
        tool_width: Some(2),
        path: PathType::RoughAndFinish,
        corners: [round, round, Corner { size: 1, kind: CornerKind::Chamfer }, round],
        readings: cycleref::G75Readings::DEFAULT,
    };
    let same = |c: &G75Cycle| {
        let ours = cycleref::expand_g75(c).map(Iterator::collect::<Vec<_>>);
        let reference = cycleref_spec::g75::expand(c);
        assert_eq!(ours, reference, "engine and reference differ for {c:?}");
        assert_eq!(
            g75_exact::expand(c),
            reference,
            "the integer restatement and the reference differ for {c:?}"
        );
        reference
    };
    let (mut out_of_range, mut expanded) = (0, 0);
    for (sx, sz) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
        for k in -2..=20 {
            for axis in 0..2 {
                let near = MAX_LENGTH - k;
                let start = if axis == 0 { Point::new(sx * near, 0) } else { Point::new(0, sz * near) };
                let c =
                    G75Cycle { start, from: start, depth: sx * base.depth, width: sz * base.width, ..base };
                match same(&c) {
                    Err(cycleref::CycleError::OutOfRange { .. }) => out_of_range += 1,
                    Ok(_) => expanded += 1,
                    Err(_) => {}
                }
            }
        }
    }
    eprintln!("near the range limit: {out_of_range} out of range, {expanded} expanded");
    assert!(out_of_range > 0 && expanded > 0);
    // 10^6 pecks and one more: a zero-width groove, one plunge, pecks of 1.
    for depth in [999_999, 1_000_000, 1_000_001] {
        let c = G75Cycle {
            depth,
            width: 0,
            peck: 1,
            tool_width: None,
            allowance_x: 0,
            allowance_z: 0,
            path: PathType::Rough,
            corners: [Corner::SHARP; 4],
            ..base
        };
        let r = same(&c);
        assert_eq!(r.is_err(), depth > 1_000_000, "{r:?}");
    }
}
