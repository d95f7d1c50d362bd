//! G75.1 golden tests: the seed's example and a right-angle groove with
//! layers, allowances, a tool width and corners, every move worked out by
//! hand from `docs/G75.md` (the working is in the comments; nothing here was
//! copied from a program's output). Both engines must give these moves.
//!
//! Notation (docs/G75.md §2): u = axial distance from S towards D's sign, y =
//! radial depth from S in X-word units (diameter), f = 2; absolute
//! `X = XS + sx·y`, `Z = ZS + sz·u`.

use cycleref::{Motion, Move, Role};
use cycleref_spec::differ::assert_same_moves;
use cycleref_spec::error::ErrorKind;
use cycleref_spec::profile::Machine;
use cycleref_spec::{read, ProfileName};

fn machine(increment: cycleref::IncrementSystem) -> Machine {
    let mut m = Machine::new(ProfileName::Gsk980);
    m.increment = increment;
    m
}

/// Moves as `G01 X28.000 Z-0.200 peck 1.1`.
///
/// Twins: `impl/src/engine/g75/tests.rs`, `render` (in increments), and
/// `spec/tests/golden.rs`, `render` (the G76/G32 lines, without roles).
fn render(moves: &[Move], decimals: u32) -> Vec<String> {
    let f = |v: i64| cycleref::units::Length { increments: v, decimals }.to_string();
    moves
        .iter()
        .map(|m| {
            let g = match m.motion {
                Motion::Rapid => "G00".to_string(),
                Motion::Feed => "G01".to_string(),
                Motion::Thread { .. } => "G32".to_string(),
                Motion::Arc { centre, clockwise } => {
                    format!("{} C(X{} Z{})", if clockwise { "G02" } else { "G03" }, f(centre.x), f(centre.z))
                }
            };
            let role = match m.role {
                Role::Peck(p) => format!("peck {}.{}", p.layer, p.number),
                Role::PeckRetract(p) => format!("peck-retract {}.{}", p.layer, p.number),
                Role::PlungeRetract(p) => format!("plunge-retract {}.{}", p.layer, p.number),
                Role::Step(p) => format!("step {}.{}", p.layer, p.number),
                Role::LayerChange(l) => format!("layer {l}"),
                Role::RoughContour => "rough".into(),
                Role::FinishContour => "finish".into(),
                Role::Approach => "approach".into(),
                Role::Return => "return".into(),
                other => format!("{other:?}"),
            };
            format!("{g} X{} Z{} {role}", f(m.to.x), f(m.to.z))
        })
        .collect()
}

/// Both engines' moves for the program's only G75.1, which must agree.
fn both(text: &str, machine: &Machine) -> (Vec<Move>, u32) {
    let program = read(text, machine).unwrap_or_else(|e| panic!("reads: {e}"));
    let call = program.grooves().next().expect("one G75.1");
    let spec = cycleref_spec::g75::expand(&call.cycle).expect("the reference expands");
    let engine: Vec<Move> = cycleref::expand_g75(&call.cycle).expect("the engine expands").collect();
    assert_same_moves(&Ok(engine), &Ok(spec.clone()), text);
    (spec, call.cycle.units.decimals())
}

fn error(text: &str, machine: &Machine) -> cycleref_spec::ProgramError {
    match read(text, machine) {
        Err(e) => e,
        Ok(program) => {
            let call = program.grooves().next().expect("one G75.1");
            let spec = cycleref_spec::g75::expand(&call.cycle).expect_err("the reference refuses");
            let engine = cycleref::expand_g75(&call.cycle).expect_err("the engine refuses");
            assert_eq!(spec, engine, "both engines give the same alarm");
            cycleref_spec::ProgramError { line: call.block.line, word: None, kind: ErrorKind::Cycle(spec) }
        }
    }
}

/// One plunge of the seed example from X50 (y = 0) to X30 (y = 200000):
/// Δi = 30000, e = 0.5 mm radius = 10000 in X: pecks end at y = 30000·j
/// (X47, X44, X41, X38, X35, X32) and the seventh is cut short at the
/// bottom (X30); each of the first six is followed by a retract of 10000
/// (X48, X45, X42, X39, X36, X33); then the retract to the plunge start.
fn seed_plunge(z: &str, n: u32) -> Vec<String> {
    let mut v = Vec::new();
    for (peck, back) in [("47", "48"), ("44", "45"), ("41", "42"), ("38", "39"), ("35", "36"), ("32", "33")] {
        v.push(format!("G01 X{peck}.0000 Z{z} peck 1.{n}"));
        v.push(format!("G00 X{back}.0000 Z{z} peck-retract 1.{n}"));
    }
    v.push(format!("G01 X30.0000 Z{z} peck 1.{n}"));
    v.push(format!("G00 X50.0000 Z{z} plunge-retract 1.{n}"));
    v
}

const SEED: &str =
    "O0008;\nG00 X60 Z30 M3 S500;\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30;\nG75.1 R0.5;\nM30;\n";

/// Seed 001's example as written (IS-C, no I: a pointed tool, R-G75SEED).
///
/// S = (X50, Z30), sx = sz = -1, Y = 200000, hr = 100000, d = 100000.
/// Profile: P1 = (hr·cot 45, Y) = (100000, Y) = X30 Z20; P2 = (200000, Y)
/// = X30 Z10; P3: u3 = 200000 + 100000·√3 = 373205.08… (L = 0, y3 = 0).
/// Roughing (no allowances, no corners, one layer y1 = Y, y_top = 0):
/// A11 = ceil(Y/2·cot 45) = 100000 (Z20); A1f = floor(200000 + 0·cot 30)
/// = 200000 (Z10); plunges at u = 100000, 150000 and (150000 + 50000 is not
/// below A1f) 200000. Rough contour: R0 = (0, 0) = S, Q1 = (100000, Y),
/// Q2 = (200000, Y), R3 = (floor(373205.08), 0) = Z-7.3205.
#[test]
fn seed001_as_written() {
    let (moves, decimals) = both(SEED, &machine(cycleref::IncrementSystem::IsC));
    let mut expected = vec!["G00 X50.0000 Z20.0000 approach".to_string()];
    expected.extend(seed_plunge("20.0000", 1));
    expected.push("G00 X50.0000 Z15.0000 step 1.2".into());
    expected.extend(seed_plunge("15.0000", 2));
    expected.push("G00 X50.0000 Z10.0000 step 1.3".into());
    expected.extend(seed_plunge("10.0000", 3));
    expected.extend([
        // Back to A11 along Z (the X move to y_top is empty and omitted).
        "G00 X50.0000 Z20.0000 approach".to_string(),
        // Step 9: R0 = S, down flank A to Q1, the bottom to Q2, flank B to R3.
        "G00 X50.0000 Z30.0000 rough".into(),
        "G01 X30.0000 Z20.0000 rough".into(),
        "G01 X30.0000 Z10.0000 rough".into(),
        "G01 X50.0000 Z-7.3205 rough".into(),
        "G00 X50.0000 Z20.0000 rough".into(),
        // J0: no finishing; back to the point before the cycle.
        "G00 X60.0000 Z30.0000 return".into(),
    ]);
    assert_eq!(render(&moves, decimals), expected);
}

/// The seed's example with the 4 mm tool it assumes programmed as I4
/// (w = 40000): the far positions move in by w. A1f = 200000 - 40000 =
/// 160000 (Z14): plunges at 100000, 150000 (Z15) and 160000 (Z14); the step
/// of 50000 is larger than the tool, so a ridge of 10000 (1 mm) stays
/// between the first two plunges (docs/G75.md §7). Q2 = Z14, R3 = 373205 -
/// 40000 = 333205 (Z-3.3205).
#[test]
fn seed001_with_i4() {
    let text = SEED.replace("G75.1 R0.5;", "G75.1 R0.5 I4;");
    let (moves, decimals) = both(&text, &machine(cycleref::IncrementSystem::IsC));
    let mut expected = vec!["G00 X50.0000 Z20.0000 approach".to_string()];
    expected.extend(seed_plunge("20.0000", 1));
    expected.push("G00 X50.0000 Z15.0000 step 1.2".into());
    expected.extend(seed_plunge("15.0000", 2));
    expected.push("G00 X50.0000 Z14.0000 step 1.3".into());
    expected.extend(seed_plunge("14.0000", 3));
    expected.extend([
        "G00 X50.0000 Z20.0000 approach".to_string(),
        "G00 X50.0000 Z30.0000 rough".into(),
        "G01 X30.0000 Z20.0000 rough".into(),
        "G01 X30.0000 Z14.0000 rough".into(),
        "G01 X50.0000 Z-3.3205 rough".into(),
        "G00 X50.0000 Z20.0000 rough".into(),
        "G00 X60.0000 Z30.0000 return".into(),
    ]);
    assert_eq!(render(&moves, decimals), expected);
}

const SQUARE: &str = "M03 S800\nG00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\nG75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011\n";

/// A square groove (A = B = 90°: every value exact) at IS-B with two
/// layers, allowances, a 3 mm tool, J1 and three corners: A(r1) a 0.5
/// chamfer, D(r3) a 0.4 round, E(r4) a 0.3 round.
///
/// Y = 6000, d = 8000, Δi = 2000, Δk = 3000, e_x = 1000, Δv = 4000,
/// Δu = 400, Δw = 200, w = 3000; t1 = 500, t3 = 400·tan 45 = 400, t4 = 300.
/// Roughing region: flankA_r = 200, flankB_r = 7800, bottom 5600,
/// chord3_r(y) = 600 - (5600 - y)/2, chord4_r(y) = 7500 + (5600 - y)/2.
/// Layers: y1 = 4000, y2 = 5600.
/// Layer 1: left(4000) = max(200, -200) = 200, right(4000) = min(7800,
/// 8300) = 7800, A1f = 4800: plunges 200, 3200, 4800; pecks to 2000
/// (retract to 1000) and 4000.
/// Layer 2 (top 4000): left(5600) = 600, right(5600) = 7500, A2f = 4500:
/// plunges 600, 3600, 4500; one peck each to 5600.
/// Rough contour: R0 = (200, 0) = A11 (omitted); K1: y = floor(5600 - 2·400)
/// = 4800, u = 200; K2 = (600, 5600); K3 = (7500 - 3000, 5600) = (4500,
/// 5600); K4: y = floor(5600 - 2·300) = 5000, u = 7800 - 3000 = 4800; R3 =
/// (4800, 0).
/// Finishing: T1s = (-500, 0), T1a = (0, 1000), T3a = (0, 6000 - 800) =
/// (0, 5200), T3b = (400, 6000), C3 = (400, 5200); T4b - w = (4700, 6000),
/// T4c - w = (5000, 5400), C4 - w = (4700, 5400); P3 - w = (5000, 0). Both
/// rounds turn clockwise seen with Z right, X up (down then -Z; -Z then up):
/// G02.
#[test]
fn square_groove_with_layers_tool_and_corners() {
    let (moves, decimals) = both(SQUARE, &machine(cycleref::IncrementSystem::IsB));
    let plunge1 = |z: &str, n: u32| {
        vec![
            format!("G01 X28.000 Z{z} peck 1.{n}"),
            format!("G00 X29.000 Z{z} peck-retract 1.{n}"),
            format!("G01 X26.000 Z{z} peck 1.{n}"),
            format!("G00 X30.000 Z{z} plunge-retract 1.{n}"),
        ]
    };
    let plunge2 = |z: &str, n: u32| {
        vec![format!("G01 X24.400 Z{z} peck 2.{n}"), format!("G00 X26.000 Z{z} plunge-retract 2.{n}")]
    };
    let mut expected = vec!["G00 X30.000 Z-0.200 approach".to_string()];
    expected.extend(plunge1("-0.200", 1));
    expected.push("G00 X30.000 Z-3.200 step 1.2".into());
    expected.extend(plunge1("-3.200", 2));
    expected.push("G00 X30.000 Z-4.800 step 1.3".into());
    expected.extend(plunge1("-4.800", 3));
    expected.push("G00 X30.000 Z-0.600 layer 2".into());
    expected.push("G00 X26.000 Z-0.600 layer 2".into());
    expected.extend(plunge2("-0.600", 1));
    expected.push("G00 X26.000 Z-3.600 step 2.2".into());
    expected.extend(plunge2("-3.600", 2));
    expected.push("G00 X26.000 Z-4.500 step 2.3".into());
    expected.extend(plunge2("-4.500", 3));
    expected.extend([
        "G00 X30.000 Z-4.500 approach".to_string(),
        "G00 X30.000 Z-0.200 approach".into(),
        "G01 X25.200 Z-0.200 rough".into(),
        "G01 X24.400 Z-0.600 rough".into(),
        "G01 X24.400 Z-4.500 rough".into(),
        "G01 X25.000 Z-4.800 rough".into(),
        "G01 X30.000 Z-4.800 rough".into(),
        "G00 X30.000 Z-0.200 rough".into(),
        "G00 X30.000 Z0.500 finish".into(),
        "G01 X29.000 Z0.000 finish".into(),
        "G01 X24.800 Z0.000 finish".into(),
        "G02 C(X24.800 Z-0.400) X24.000 Z-0.400 finish".into(),
        "G01 X24.000 Z-4.700 finish".into(),
        "G02 C(X24.600 Z-4.700) X24.600 Z-5.000 finish".into(),
        "G01 X30.000 Z-5.000 finish".into(),
        "G00 X30.000 Z0.000 return".into(),
        "G00 X40.000 Z5.000 return".into(),
    ]);
    assert_eq!(render(&moves, decimals), expected);
}

/// J2 runs only the finishing contour: approach to A11, then step 10.
#[test]
fn finish_only_runs_the_contour() {
    let text = SQUARE.replace("J1", "J2");
    let (moves, _) = both(&text, &machine(cycleref::IncrementSystem::IsB));
    assert_eq!(moves[0].role, Role::Approach);
    assert!(moves.iter().all(|m| !matches!(m.role, Role::Peck(_) | Role::RoughContour)));
    let finish: Vec<_> = moves.iter().filter(|m| m.role == Role::FinishContour).collect();
    assert_eq!(finish.len(), 7, "rapid to T1s, chamfer, flank A, round, bottom, round, flank B");
}

fn kind(e: &cycleref_spec::ProgramError) -> String {
    format!("{:?}", e.kind)
}

#[test]
fn missing_required_words() {
    let m = machine(cycleref::IncrementSystem::IsB);
    for (word, what) in [("H-6", "H(h)"), ("D-8", "D(d)"), ("P2000", "P(Δi)"), ("Q3000", "Q(Δk)")] {
        let text = SQUARE.replace(&format!(" {word}"), "");
        let e = error(&text, &m);
        assert!(matches!(e.kind, ErrorKind::Missing { .. }), "{word}: {e}");
        assert!(e.to_string().contains(what), "{e}");
        assert_eq!(e.line, 3);
    }
}

#[test]
fn angles_out_of_range() {
    let m = machine(cycleref::IncrementSystem::IsB);
    for (words, field) in [
        ("H-6 D-8 A0", cycleref::Field::FlankA),
        ("H-6 D-8 A90.001", cycleref::Field::FlankA),
        ("H-6 D-8 B91", cycleref::Field::FlankB),
        ("H-6 D-8 L90", cycleref::Field::Slope),
    ] {
        let e = error(&SQUARE.replace("H-6 D-8", words), &m);
        match e.kind {
            ErrorKind::Cycle(cycleref::CycleError::AngleOutOfRange { field: f, .. }) => assert_eq!(f, field),
            _ => panic!("{words}: {e}"),
        }
    }
    // L must stay below B.
    let e = error(&SQUARE.replace("H-6 D-8", "H-6 D-8 B30 L30"), &m);
    assert!(kind(&e).contains("SlopeNotBelowFlank"), "{e}");
    // Finer than the increment system's 0.001 degree.
    let e = error(&SQUARE.replace("H-6 D-8", "H-6 D-8 A45.0001"), &m);
    assert!(matches!(e.kind, ErrorKind::NotInIncrements { .. }), "{e}");
}

#[test]
fn groove_narrower_than_the_tool() {
    let m = machine(cycleref::IncrementSystem::IsB);
    // Bottom 8 less W 2×0.2 less the corners' chords (0.4 + 0.3) is 6.9 at
    // the roughing bottom: a 7 mm tool does not fit.
    let e = error(&SQUARE.replace("I3", "I7"), &m);
    assert!(kind(&e).contains("GrooveNarrowerThanTool"), "{e}");
    assert!(e.to_string().contains("narrower"), "{e}");
    // 6.9 fits exactly: one plunge in the last layer (A21 = 600 = 7500 - 6900).
    let (moves, _) = both(&SQUARE.replace("I3", "I6.9"), &m);
    assert!(moves.iter().any(|m| matches!(m.role, Role::Peck(p) if p.layer == 2)));
    assert!(moves.iter().all(|m| !matches!(m.role, Role::Peck(p) if p.layer == 2 && p.number > 1)));
    // W larger than half the bottom.
    let e = error(&SQUARE.replace("W0.2", "W4"), &m);
    assert!(kind(&e).contains("GrooveNarrowerThanTool"), "{e}");
}

/// R-G75RIDGE: roughing in layers with a step wider than the tool.
///
/// The square groove steps Q3 with a 3 mm tool: its plunges (200, 3200,
/// 4800 in layer 1) leave no gap, and layer 2's steps at the bottom of
/// layer 1 run in cut space. With Q3.001 the first two plunges of layer 1
/// (200 and 3201) are 3001 apart, one increment more than the tool, so a
/// ridge 0.001 wide stands between them the whole depth of layer 1, and
/// layer 2's step from 600 to 3601 at the depth of layer 1's bottom would
/// run through it: refused. Without V there is one layer (its steps run in
/// the air above the opening), and J2 does not rough: both expand.
#[test]
fn layers_with_a_step_wider_than_the_tool() {
    let m = machine(cycleref::IncrementSystem::IsB);
    let wide = SQUARE.replace("Q3000", "Q3001");
    let e = error(&wide, &m);
    assert!(kind(&e).contains("RidgesInLayers"), "{e}");
    assert!(e.to_string().contains("Q(Δk) = 3.001"), "{e}");
    assert!(e.to_string().contains("I = 3.000"), "{e}");
    assert_eq!(e.line, 4);
    // One layer: the ridge stays until the rough contour's bottom pass.
    let (moves, _) = both(&wide.replace(" V4", ""), &m);
    let plunges: Vec<i64> =
        moves.iter().filter(|m| matches!(m.role, Role::Step(_))).map(|m| m.to.z).collect();
    // Z = −u: plunges at u = 600 (K2: the chord of r3 at the bottom), 3601, 4500.
    assert_eq!(plunges, [-3_601, -4_500]);
    let (moves, _) = both(&wide.replace("J1", "J2"), &m);
    assert!(moves.iter().all(|m| !matches!(m.role, Role::Peck(_))));
    // The seed's groove in layers: a pointed tool (w = 0) leaves a ridge
    // between any two plunges; with I4, Q5 is still wider than the tool;
    // with I5 it is not (layer 1: A11 = 10, A1f = 20 − 5 = 15, one step).
    let mc = machine(cycleref::IncrementSystem::IsC);
    let e = error(&SEED.replace("G75.1 R0.5;", "G75.1 R0.5 V10;"), &mc);
    assert!(kind(&e).contains("RidgesInLayers"), "{e}");
    let e = error(&SEED.replace("G75.1 R0.5;", "G75.1 R0.5 V10 I4;"), &mc);
    assert!(kind(&e).contains("RidgesInLayers"), "{e}");
    let (moves, _) = both(&SEED.replace("G75.1 R0.5;", "G75.1 R0.5 V10 I5;"), &mc);
    assert!(moves.iter().any(|m| matches!(m.role, Role::Peck(p) if p.layer == 2)));
}

#[test]
fn allowances_larger_than_the_groove() {
    let m = machine(cycleref::IncrementSystem::IsB);
    let e = error(&SQUARE.replace("U0.4", "U6"), &m);
    assert!(kind(&e).contains("AllowanceExceedsDepth"), "{e}");
    assert!(e.to_string().contains("U(Δu)"), "{e}");
    let e = error(&SQUARE.replace("U0.4", "U-0.4"), &m);
    assert!(kind(&e).contains("WordOutOfRange"), "{e}");
}

#[test]
fn corners_larger_than_their_edge() {
    let m = machine(cycleref::IncrementSystem::IsB);
    // Flank A is 3 mm long: r1 = 2.7 and r3 = 0.4 do not fit on it.
    let e = error(&SQUARE.replace("A0.5", "A2.7"), &m);
    assert!(kind(&e).contains("FlankA"), "{e}");
    // The bottom is 8 mm: 2.4 + 5.7 (and flank A still holds 0.5 + 2.4).
    let e = error(&SQUARE.replace("D0.4 E0.3", "D2.4 E5.7"), &m);
    assert!(kind(&e).contains("Bottom"), "{e}");
}

#[test]
fn lone_block_and_other_reader_errors() {
    let m = machine(cycleref::IncrementSystem::IsB);
    // Block 1 alone.
    let e = error("G00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\nM30\n", &m);
    assert!(e.to_string().contains("two blocks"), "{e}");
    assert_eq!(e.line, 2);
    let e = error("G00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\n", &m);
    assert!(e.to_string().contains("two blocks"), "{e}");
    // Block 2 alone.
    let e = error("G00 X40 Z5\nG75.1 R0.5\n", &m);
    assert!(e.to_string().contains("two blocks"), "{e}");
    // A block 1 without its required words (and nothing of block 2).
    let e = error("G00 X40 Z5\nG75.1 P2000 Q3000 D-8\nG75.1 R0.5\n", &m);
    assert!(e.to_string().contains("H(h)"), "{e}");
    // J and P digits.
    let e = error(&SQUARE.replace("J1", "J3"), &m);
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    let e = error(&SQUARE.replace("P0011", "P0021"), &m);
    assert!(e.to_string().contains("each 0 or 1"), "{e}");
    // H0.
    let e = error(&SQUARE.replace("H-6", "H0"), &m);
    assert!(kind(&e).contains("NoGrooveDepth"), "{e}");
    // A block-2 word in block 1.
    let e = error(&SQUARE.replace("D-8\n", "D-8 V4\n"), &m);
    assert!(e.to_string().contains("G75.1 block 1"), "{e}");
    // G75.1 is a 980TDi cycle.
    let e = error(SQUARE, &Machine::new(ProfileName::Gsk988));
    assert!(matches!(e.kind, ErrorKind::Unsupported(_)), "{e}");
}

/// P digits are read from the right (R-G75P): P11 rounds D and E.
#[test]
fn corner_digits_from_the_right() {
    let m = machine(cycleref::IncrementSystem::IsB);
    let a = read(SQUARE, &m).unwrap();
    let short = SQUARE.replace("P0011", "P11");
    let b = read(&short, &m).unwrap();
    assert_eq!(a.grooves().next().unwrap().cycle, b.grooves().next().unwrap().cycle);
}
