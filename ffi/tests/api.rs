//! The C interface called from Rust through the `rlib`: its moves are the
//! engine's, its errors carry the right status, line and message.

use core::ffi::{c_char, CStr};
use core::ptr;

use cycleref_ffi::*;
use cycleref_spec::reader::Multipass;
use cycleref_spec::{read, Machine, ProfileName};

fn example(name: &str) -> String {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn options(profile: CyclerefProfile) -> CyclerefOptions {
    CyclerefOptions { profile: profile as u32, ..cycleref_options_default() }
}

/// `cycleref_expand` with a buffer of `capacity`: the status, the moves
/// written and the error.
#[allow(unsafe_code)]
fn expand_with(
    program: &[u8],
    opts: &CyclerefOptions,
    capacity: usize,
) -> (CyclerefStatus, usize, Vec<CyclerefMove>, CyclerefError) {
    let mut moves = vec![CyclerefMove::default(); capacity];
    let mut count = usize::MAX;
    let mut err = CyclerefError::default();
    // SAFETY: every pointer is valid for the call: the program slice, the
    // options, a buffer of `capacity` moves, `count` and `err`.
    let status = unsafe {
        cycleref_expand(
            program.as_ptr().cast(),
            program.len(),
            opts,
            if capacity == 0 { ptr::null_mut() } else { moves.as_mut_ptr() },
            capacity,
            &mut count,
            &mut err,
        )
    };
    moves.truncate(count.min(capacity));
    (status, count, moves, err)
}

fn expand(program: &str, opts: &CyclerefOptions) -> Result<Vec<CyclerefMove>, String> {
    let (status, n, _, err) = expand_with(program.as_bytes(), opts, 0);
    if status != CyclerefStatus::BufferTooSmall && status != CyclerefStatus::Ok {
        return Err(err.message());
    }
    let (status, count, moves, err) = expand_with(program.as_bytes(), opts, n);
    assert_eq!(status, CyclerefStatus::Ok, "{}", err.message());
    assert_eq!(err.status, CyclerefStatus::Ok);
    assert_eq!((err.line, err.message()), (0, String::new()));
    assert_eq!(count, n);
    Ok(moves)
}

/// Every move of every cycle of `program`, straight from the engine.
fn engine_moves(program: &str, machine: &Machine) -> Vec<CyclerefMove> {
    let p = read(program, machine).expect("reads");
    let mut out = Vec::new();
    for item in &p.items {
        match item {
            cycleref_spec::Item::G76(c) => {
                let kind = match c.code {
                    Multipass::G76 => CyclerefCycle::G76,
                    Multipass::G78 => CyclerefCycle::G78,
                };
                out.extend(
                    cycleref::expand_g76(&c.cycle)
                        .unwrap()
                        .map(|m| CyclerefMove::from_move(&m, c.cycle.units.decimals(), kind, c.block.line)),
                );
            }
            cycleref_spec::Item::G32(c) => out.extend(cycleref::expand_g32(&c.g32).unwrap().map(|m| {
                CyclerefMove::from_move(&m, c.g32.units.decimals(), CyclerefCycle::G32, c.block.line)
            })),
            cycleref_spec::Item::G75(c) => out.extend(cycleref::expand_g75(&c.cycle).unwrap().map(|m| {
                CyclerefMove::from_move(&m, c.cycle.units.decimals(), CyclerefCycle::G75, c.block.line)
            })),
            cycleref_spec::Item::G92(c) => out.extend(cycleref::expand_g92(&c.cycle).unwrap().map(|m| {
                CyclerefMove::from_move(&m, c.cycle.units.decimals(), CyclerefCycle::G92, c.block.line)
            })),
            cycleref_spec::Item::LinuxCncG76(c) => {
                out.extend(cycleref::expand_linuxcnc(&c.cycle).unwrap().map(|m| {
                    CyclerefMove::from_move(&m, c.cycle.units.decimals(), CyclerefCycle::G76, c.block.line)
                }))
            }
            // Named, not `_`: a new kind of item must be added here.
            cycleref_spec::Item::Source(_)
            | cycleref_spec::Item::Move(_)
            | cycleref_spec::Item::G76Params(_)
            | cycleref_spec::Item::G75Params(_) => {}
        }
    }
    out
}

#[test]
fn linuxcnc_program_through_the_c_interface() {
    // examples/linuxcnc-m20-taper.ngc: 17 passes of 6 moves and the closing
    // rapid (cli/tests/linuxcnc.rs works the count), IS-C (4 decimals), X
    // in G7 diameters as the program writes them.
    let text = example("linuxcnc-m20-taper.ngc");
    let moves = expand(&text, &options(CyclerefProfile::LinuxCnc)).unwrap();
    assert_eq!(moves.len(), 17 * 6 + 1);
    assert_eq!(moves, engine_moves(&text, &Machine::new(ProfileName::LinuxCnc)));
    assert!(moves.iter().all(|m| m.cycle == CyclerefCycle::G76 && m.line == 6 && m.decimals == 4));
    // Pass 1's "back" rapid: X 22 + (1.84 − 0.3) = 23.54, Z 2 − 0.15·tan 29.5°.
    assert_eq!((moves[0].motion, moves[0].x, moves[0].z), (CyclerefMotion::Rapid, 235_400, 19_151));
}

#[test]
fn m68x6_equals_the_engine() {
    let text = example("gsk988-m68x6.nc");
    let moves = expand(&text, &options(CyclerefProfile::Gsk988)).unwrap();
    assert_eq!(moves.len(), 30);
    assert_eq!(moves, engine_moves(&text, &Machine::new(ProfileName::Gsk988)));
    let m = moves[1];
    assert_eq!(
        (m.motion, m.role, m.x, m.z, m.sync),
        (CyclerefMotion::Thread, CyclerefRole::Cut, 64_400, -59_000, 1)
    );
    assert_eq!((m.lead_word, m.lead_mantissa, m.lead_scale), (CyclerefLeadWord::F, 6, 0));
    assert!(moves.iter().all(|m| m.line == 6 && m.has_pass == 1 && m.decimals == 3));
}

/// Every shipped example with its profile and increment system (the
/// gsk980 M68x6, G32 taper and G75.1 seed programs are written for IS-C, as
/// their comments say).
const EXAMPLES: &[(&str, CyclerefProfile, ProfileName, cycleref::IncrementSystem)] = {
    use cycleref::IncrementSystem::{IsB, IsC};
    &[
        ("fanuc-external.nc", CyclerefProfile::Fanuc, ProfileName::Fanuc, IsB),
        ("fanuc-internal.nc", CyclerefProfile::Fanuc, ProfileName::Fanuc, IsB),
        ("gsk980-m68x6.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsC),
        ("gsk980-g32-runout.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk980-g32-taper.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsC),
        ("seed000-extended.nc", CyclerefProfile::Gsk988, ProfileName::Gsk988, IsB),
        ("gsk980-g75-seed.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsC),
        ("gsk980-g75-square.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk980-g75-slope.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk980-g92-o0012.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk980-g78.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk988-g78.nc", CyclerefProfile::Gsk988, ProfileName::Gsk988, IsB),
    ]
};

/// Each of [`EXAMPLES`]: its name, its text, the options that expand it
/// through the C interface (its profile and increment system) and the
/// machine that expands it through the reader and the engine.
fn examples() -> impl Iterator<Item = (&'static str, String, CyclerefOptions, Machine)> {
    use cycleref::IncrementSystem::IsC;
    EXAMPLES.iter().map(|&(name, profile, p, system)| {
        let mut o = options(profile);
        o.increment = if system == IsC { CyclerefIncrement::IsC } else { CyclerefIncrement::IsB } as u32;
        let mut m = Machine::new(p);
        m.increment = system;
        (name, example(name), o, m)
    })
}

#[test]
fn every_example_equals_the_engine() {
    for (name, text, o, m) in examples() {
        let got = expand(&text, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!got.is_empty(), "{name}");
        assert_eq!(got, engine_moves(&text, &m), "{name}");
    }
}

#[test]
fn g32_moves_have_no_pass() {
    let text = example("gsk980-g32-runout.nc");
    let moves = expand(&text, &options(CyclerefProfile::Gsk980)).unwrap();
    // Worked out in spec/tests/g32.rs: cut and run-out, then three blocks
    // of a continuous thread, the last with a run-out.
    let got: Vec<_> = moves.iter().map(|m| (m.line, m.role, m.x, m.z, m.sync, m.start_angle_num)).collect();
    assert_eq!(
        got,
        vec![
            (5, CyclerefRole::Cut, 40_000, -27_000, 1, 90_000),
            (5, CyclerefRole::RunOut, 43_000, -30_000, 0, 90_000),
            (9, CyclerefRole::Cut, 34_000, -10_000, 1, 180_000),
            (10, CyclerefRole::Cut, 34_000, -30_000, 0, 180_000),
            (11, CyclerefRole::Cut, 37_600, -39_000, 0, 180_000),
            (11, CyclerefRole::RunOut, 40_000, -40_000, 0, 180_000),
        ]
    );
    for m in &moves {
        assert_eq!(
            (m.cycle, m.motion, m.has_pass, m.pass_number, m.pass_depth),
            (CyclerefCycle::G32, CyclerefMotion::Thread, 0, 0, 0)
        );
    }
}

/// The 980TDi's G92 example O0012 through the C interface: each block one
/// pass of kind `Single` (depth and cut 0), the values worked out in
/// spec/tests/g92.rs (A = X65 Z5, C at Z-28, J3 K1).
#[test]
fn g92_blocks_are_single_passes() {
    let text = example("gsk980-g92-o0012.nc");
    let moves = expand(&text, &options(CyclerefProfile::Gsk980)).unwrap();
    assert_eq!(moves.len(), 20);
    let first: Vec<_> = moves[..5].iter().map(|m| (m.line, m.motion, m.role, m.x, m.z, m.sync)).collect();
    assert_eq!(
        first,
        vec![
            (4, CyclerefMotion::Rapid, CyclerefRole::Approach, 58_700, 5_000, 0),
            (4, CyclerefMotion::Thread, CyclerefRole::Cut, 58_700, -27_000, 1),
            (4, CyclerefMotion::Thread, CyclerefRole::RunOut, 64_700, -28_000, 0),
            (4, CyclerefMotion::Rapid, CyclerefRole::Retract, 65_000, -28_000, 0),
            (4, CyclerefMotion::Rapid, CyclerefRole::Return, 65_000, 5_000, 0),
        ]
    );
    let lines: Vec<usize> = moves.iter().step_by(5).map(|m| m.line).collect();
    assert_eq!(lines, [4, 5, 6, 7]);
    for m in &moves {
        assert_eq!(
            (m.cycle, m.has_pass, m.pass_kind, m.pass_number, m.pass_start, m.pass_depth, m.pass_cut),
            (CyclerefCycle::G92, 1, CyclerefPassKind::Single, 1, 1, 0, 0)
        );
    }
}

/// A small right-angle G75.1 groove on the GSK 980TDi (IS-B, mm, X as a
/// diameter): a 2 mm grooving tool, pecks with a retract, J1, and a round
/// D(r3) of 0.5 at the bottom corner on the start side (P0010: the third
/// digit, d, is 1).
const GROOVE: &str =
    "M03 S600\nG00 X52 Z3\nG75.1 X50 Z0 P4000 Q2000 H-6 D-5\nG75.1 R0.5 I2 J1 D0.5 P0010\nM30\n";

/// The moves of `GROOVE`, worked out by hand from docs/G75.md (none copied
/// from a program's output), as (motion, role, X, Z, plunge layer, plunge
/// number) in increments of 0.001 mm.
///
/// S = (X50, Z0), from = (X52, Z3); H-6: sx = -1, Y = 6000 (diameter), f = 2;
/// D-5: sz = -1, d = 5000; Δi = 4000, Δk = 2000 (182.7 = 0: increments);
/// e = 500, so e_x = 1000; w = 2000; a = b = 90°, L = 0; ρ3 = 500, t3 =
/// ρ3·tan 45° = 500. Local (u, y) maps to X = 50000 - y, Z = -u.
///
/// * Roughing region (§5): flankA_r = 0, flankB_r = 5000, bottom 6000,
///   chord3_r(y) = 500 - (6000 - y)/2; one layer (no V), y1 = 6000, y_top =
///   floor(y3) = 0.
/// * Plunges (§7): A11 = ceil(max(0, 500)) = 500, A1f = 5000 - 2000 = 3000;
///   at 500, 2500 (< 3000), then 3000. Pecks: to 4000 (X46), retract to
///   max(0, 4000 - 1000) = 3000 (X47), to min(8000, 6000) = 6000 (X44), back
///   to y_top (X50). Each step carries the plunge it moves to.
/// * After the layer: back along Z to A11 (the X move is empty).
/// * Rough contour (step 9): R0 = (ceil(left(0)), 0) = (0, 0); y_K1 =
///   floor(6000 - 2·500) = 5000 > 0, K1 = (0, 5000) (X45 Z0); K2 = (500,
///   6000) (X44 Z-0.5); t4 = 0: Q2 = (5000 - 2000, 6000) (X44 Z-3); R3 =
///   (3000, 0) (X50 Z-3); back along Z to A11.
/// * Finishing (step 10): along Z to F0 = S (X50 Z0; the X move is empty);
///   flank A to T3a = (0, 6000 - 2·500) = (0, 5000) (X45 Z0); the round to
///   T3b = (500, 6000) (X44 Z-0.5) about C3 = (500, 5000) (X45 Z-0.5),
///   clockwise since sx·sz = +1 > 0 (R-G75ARCDIR: from east of the centre to
///   south of it, with Z right and X up); the bottom to P2 - w = (3000, 6000);
///   flank B to P3 - w = (3000, 0) (X50 Z-3).
/// * Return: along Z to u = 0 (X50 Z0; the X moves are empty), then to from.
fn groove_by_hand() -> Vec<(CyclerefMotion, CyclerefRole, i64, i64, u32, u32)> {
    use CyclerefMotion::{ArcCw, Feed, Rapid};
    use CyclerefRole::*;
    let mut v = vec![(Rapid, Approach, 50_000, -500, 0, 0)];
    for (n, z) in [(1, -500), (2, -2_500), (3, -3_000)] {
        if n > 1 {
            v.push((Rapid, Step, 50_000, z, 1, n));
        }
        v.extend([
            (Feed, Peck, 46_000, z, 1, n),
            (Rapid, PeckRetract, 47_000, z, 1, n),
            (Feed, Peck, 44_000, z, 1, n),
            (Rapid, PlungeRetract, 50_000, z, 1, n),
        ]);
    }
    v.extend([
        (Rapid, Approach, 50_000, -500, 0, 0),
        (Rapid, RoughContour, 50_000, 0, 0, 0),
        (Feed, RoughContour, 45_000, 0, 0, 0),
        (Feed, RoughContour, 44_000, -500, 0, 0),
        (Feed, RoughContour, 44_000, -3_000, 0, 0),
        (Feed, RoughContour, 50_000, -3_000, 0, 0),
        (Rapid, RoughContour, 50_000, -500, 0, 0),
        (Rapid, FinishContour, 50_000, 0, 0, 0),
        (Feed, FinishContour, 45_000, 0, 0, 0),
        (ArcCw, FinishContour, 44_000, -500, 0, 0),
        (Feed, FinishContour, 44_000, -3_000, 0, 0),
        (Feed, FinishContour, 50_000, -3_000, 0, 0),
        (Rapid, Return, 50_000, 0, 0, 0),
        (Rapid, Return, 52_000, 3_000, 0, 0),
    ]);
    v
}

#[test]
fn g75_groove_worked_by_hand() {
    let moves = expand(GROOVE, &options(CyclerefProfile::Gsk980)).unwrap();
    let got: Vec<_> =
        moves.iter().map(|m| (m.motion, m.role, m.x, m.z, m.plunge_layer, m.plunge_number)).collect();
    assert_eq!(got, groove_by_hand());
    assert_eq!(moves.len(), 29);
    for m in &moves {
        // Every move is the G75.1's, from its block 2, in 0.001 mm; no pass,
        // no thread fields.
        assert_eq!((m.cycle, m.line, m.decimals, m.has_pass, m.sync), (CyclerefCycle::G75, 4, 3, 0, 0));
        assert_eq!((m.lead_mantissa, m.pass_number, m.pass_depth), (0, 0, 0));
        if m.motion != CyclerefMotion::ArcCw {
            assert_eq!((m.centre_x, m.centre_z), (0, 0));
        }
    }
    // The round D(r3): centre C3 = (u, y) = (500, 5000), X45.000 Z-0.500.
    let arc = moves.iter().find(|m| m.motion == CyclerefMotion::ArcCw).unwrap();
    assert_eq!((arc.x, arc.z, arc.centre_x, arc.centre_z), (44_000, -500, 45_000, -500));
    // Its start (the end of flank A) and its end are both 0.5 mm (a radius)
    // from the centre: 1000 diameter increments in X, 500 in Z.
    let before = moves[moves.iter().position(|m| m.motion == CyclerefMotion::ArcCw).unwrap() - 1];
    assert_eq!((before.x - arc.centre_x, before.z - arc.centre_z), (0, 500));
    assert_eq!((arc.x - arc.centre_x, arc.z - arc.centre_z), (-1_000, 0));
    // The C values of the enums (include/cycleref.h) the moves carry.
    assert_eq!(
        [CyclerefCycle::G75 as u32, CyclerefMotion::ArcCw as u32, CyclerefMotion::ArcCcw as u32],
        [2, 3, 4]
    );
    let codes: Vec<u32> = moves.iter().take(6).map(|m| m.role as u32).collect();
    // approach, peck, peck-retract, peck, plunge-retract, step.
    assert_eq!(codes, [0, 6, 7, 6, 8, 9]);
    assert_eq!(
        [
            CyclerefRole::LayerChange,
            CyclerefRole::RoughContour,
            CyclerefRole::FinishContour,
            CyclerefRole::Return
        ]
        .map(|r| r as u32),
        [10, 11, 12, 5]
    );
    assert_eq!(moves, engine_moves(GROOVE, &Machine::new(ProfileName::Gsk980)));
    // D-5 turned to D5 (the groove towards +Z) mirrors Z about S's Z0, all
    // but the return to the point before the cycle, and turns the round the
    // other way: sx·sz = -1 < 0 gives G03 (R-G75ARCDIR).
    let mirrored = expand(&GROOVE.replace("D-5", "D5"), &options(CyclerefProfile::Gsk980)).unwrap();
    assert_eq!(mirrored.len(), moves.len());
    let n = moves.len() - 1;
    for (a, b) in mirrored[..n].iter().zip(&moves[..n]) {
        assert_eq!(
            (a.x, a.z, a.role, a.plunge_layer, a.plunge_number),
            (b.x, -b.z, b.role, b.plunge_layer, b.plunge_number)
        );
    }
    assert_eq!((mirrored[n].x, mirrored[n].z), (52_000, 3_000));
    let arc = mirrored.iter().find(|m| m.centre_x != 0).unwrap();
    assert_eq!((arc.motion, arc.centre_x, arc.centre_z), (CyclerefMotion::ArcCcw, 45_000, 500));
}

/// Layers: V3 splits the 6 mm (diameter) depth into two; the moves to the
/// second layer are `LAYER_CHANGE` with `plunge_layer` 2 and no plunge number.
#[test]
fn g75_layers_through_the_c_interface() {
    // Q2 is no wider than I2 (R-G75RIDGE); J0 roughs only.
    let text = GROOVE.replace("R0.5 I2 J1", "R0.5 V3 I2 J0");
    let moves = expand(&text, &options(CyclerefProfile::Gsk980)).unwrap();
    assert_eq!(moves, engine_moves(&text, &Machine::new(ProfileName::Gsk980)));
    // Layer 1 ends at y = 3000 (X47), layer 2 at 6000 (X44). At y = 3000 the
    // round's chord is not the boundary (500 - (6000 - 3000)/2 < 0), so A11 =
    // 0 and layer 1's plunges are at 0, 2000, 3000; layer 2 starts at A21 =
    // ceil(left(6000)) = 500: along Z at layer 1's top (X50), then down along
    // X to layer 1's bottom (X47), and plunges at 500, 2500, 3000.
    let change: Vec<_> = moves
        .iter()
        .filter(|m| m.role == CyclerefRole::LayerChange)
        .map(|m| (m.motion, m.x, m.z, m.plunge_layer, m.plunge_number))
        .collect();
    assert_eq!(
        change,
        [(CyclerefMotion::Rapid, 50_000, -500, 2, 0), (CyclerefMotion::Rapid, 47_000, -500, 2, 0)]
    );
    // One peck per plunge: 3000 (Δi = 4000) to X47 in layer 1, from X47 to
    // X44 in layer 2.
    let pecks: Vec<_> = moves
        .iter()
        .filter(|m| m.role == CyclerefRole::Peck)
        .map(|m| (m.plunge_layer, m.plunge_number, m.x, m.z))
        .collect();
    assert_eq!(
        pecks,
        [
            (1, 1, 47_000, 0),
            (1, 2, 47_000, -2_000),
            (1, 3, 47_000, -3_000),
            (2, 1, 44_000, -500),
            (2, 2, 44_000, -2_500),
            (2, 3, 44_000, -3_000),
        ]
    );
    assert!(moves.iter().all(|m| m.role != CyclerefRole::FinishContour));
}

#[test]
fn g75_errors_through_the_c_interface() {
    let o = options(CyclerefProfile::Gsk980);
    // The engine's alarm: a 6 mm tool in a bottom of 5 mm less the round's 0.5.
    let wide = GROOVE.replace("I2", "I6");
    let (status, count, _, err) = expand_with(wide.as_bytes(), &o, 40);
    assert_eq!(
        (status, count, err.status, err.line),
        (CyclerefStatus::CycleError, 0, CyclerefStatus::CycleError, 4)
    );
    assert!(err.message().starts_with("line 4, G75.1: the groove"), "{}", err.message());
    // The reader's: block 1 without its block 2.
    let lone = "M03 S600\nG00 X52 Z3\nG75.1 X50 Z0 P4000 Q2000 H-6 D-5\nM30\n";
    let (status, _, _, err) = expand_with(lone.as_bytes(), &o, 40);
    assert_eq!((status, err.line), (CyclerefStatus::ProgramError, 3));
    assert!(err.message().contains("two blocks"), "{}", err.message());
    // G75.1 is a GSK 980TDi cycle: the 988TA profile refuses it.
    let (status, _, _, err) = expand_with(GROOVE.as_bytes(), &options(CyclerefProfile::Gsk988), 40);
    assert_eq!((status, err.line), (CyclerefStatus::ProgramError, 3));
    assert!(err.message().contains("G75.1"), "{}", err.message());
}

#[test]
fn options_reach_the_machine() {
    let text = example("gsk988-m68x6.nc");
    let mut o = options(CyclerefProfile::Gsk988);
    o.increment = CyclerefIncrement::IsC as u32;
    let moves = expand(&text, &o).unwrap();
    assert_eq!((moves[0].decimals, moves[0].x), (4, 644_000));
    // Inch: the same words in 0.0001 inch.
    o.increment = CyclerefIncrement::IsB as u32;
    o.inch = 1;
    let moves = expand(&text, &o).unwrap();
    assert_eq!((moves[0].decimals, moves[0].x), (4, 644_000));
    // Radius X: X words are radii.
    let mut r = options(CyclerefProfile::Gsk988);
    r.radius = 1;
    let mut m = Machine::new(ProfileName::Gsk988);
    m.x_mode = cycleref::XMode::Radius;
    assert_eq!(expand(&text, &r).unwrap(), engine_moves(&text, &m));
    // The parameter file, and the fields overriding it.
    let toml = "increment = \"is-c\"\n[parameters]\n5142 = 3\n";
    let mut t = options(CyclerefProfile::Gsk988);
    t.params_toml = toml.as_ptr().cast::<c_char>();
    t.params_toml_len = toml.len();
    let mut m = Machine::new(ProfileName::Gsk988);
    m.apply_toml(toml).unwrap();
    assert_eq!(expand(&text, &t).unwrap(), engine_moves(&text, &m));
    t.increment = CyclerefIncrement::IsB as u32;
    assert_eq!(expand(&text, &t).unwrap()[0].decimals, 3);
}

/// The `readings` field (issue 34): `ID=VALUE` pairs, winning over the
/// parameter file's `[readings]`; an unknown value names the valid ones.
/// The 980TDi G92 with J8 longer than the retract (10 on the diameter):
/// clamped to X40 by default, X30 + 2·8 = X46 under R-RUNOUT=gsk988-only.
#[test]
fn readings_field() {
    let text = "M3 S300\nG00 X40 Z5\nG92 X30 Z-20 F2 J8 K2\nM30\n";
    let o = options(CyclerefProfile::Gsk980);
    assert!(o.readings.is_null());
    let default = expand(text, &o).unwrap();
    assert_eq!((default[2].x, default[2].z), (40_000, -20_000));
    let list = c"R-RUNOUT=gsk988-only, R-XRUNOUT=refuse";
    let chosen = CyclerefOptions { readings: list.as_ptr(), ..o };
    let moves = expand(text, &chosen).unwrap();
    assert_eq!((moves[2].x, moves[2].z), (46_000, -20_000));
    let mut m = Machine::new(ProfileName::Gsk980);
    m.readings.apply_list("R-RUNOUT=gsk988-only").unwrap();
    assert_eq!(moves, engine_moves(text, &m));
    // The field wins over the file.
    let toml = "[readings]\n\"R-RUNOUT\" = \"gsk988-only\"\n";
    let file =
        CyclerefOptions { params_toml: toml.as_ptr().cast::<c_char>(), params_toml_len: toml.len(), ..o };
    assert_eq!(expand(text, &file).unwrap(), moves);
    let back = c"R-RUNOUT=all-profiles";
    assert_eq!(expand(text, &CyclerefOptions { readings: back.as_ptr(), ..file }).unwrap(), default);
    let bad = c"R-RUNOUT=sometimes";
    let err = expand(text, &CyclerefOptions { readings: bad.as_ptr(), ..o }).unwrap_err();
    assert!(err.contains("its values are all-profiles, gsk988-only"), "{err}");
}

#[test]
fn buffer_too_small_reports_the_count_and_fills_the_buffer() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let all = expand(&text, &o).unwrap();
    for capacity in [0, 1, 29] {
        let (status, count, moves, err) = expand_with(text.as_bytes(), &o, capacity);
        assert_eq!(
            (status, count, err.status),
            (CyclerefStatus::BufferTooSmall, 30, CyclerefStatus::BufferTooSmall)
        );
        assert_eq!(moves, all[..capacity]);
        assert!(err.message().contains("30 moves"), "{}", err.message());
    }
    let (status, count, moves, _) = expand_with(text.as_bytes(), &o, 100);
    assert_eq!((status, count), (CyclerefStatus::Ok, 30));
    assert_eq!(moves, all);
}

#[test]
fn program_and_cycle_errors() {
    let o = options(CyclerefProfile::Gsk988);
    let missing_p =
        "G50 X100 Z50 M3 S300;\nG00 X80 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 Q1.800 F6;\n";
    let (status, count, _, err) = expand_with(missing_p.as_bytes(), &o, 10);
    assert_eq!(
        (status, count, err.status, err.line),
        (CyclerefStatus::ProgramError, 0, CyclerefStatus::ProgramError, 4)
    );
    assert!(err.message().contains("P(k)"), "{}", err.message());
    // Accepted by the reader, refused by the engine: A between the crest
    // and the root of the thread.
    let inside =
        "G50 X100 Z50 M3 S300;\nG00 X62 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\n";
    let (status, count, _, err) = expand_with(inside.as_bytes(), &o, 10);
    assert_eq!((status, count, err.line), (CyclerefStatus::CycleError, 0, 4));
    assert!(err.message().starts_with("line 4, G76: the start point A"), "{}", err.message());
}

#[test]
fn a_cycle_beyond_the_pass_limit_is_refused_by_the_count_only_call() {
    // Issue 30, found 3: with capacity 0 (count only) this ran past 60 s.
    // (999 999 rough + 99 finishing) × 999 starts = 999 097 902 pass paths
    // (reading R-BUDGET), above the default limit of 1 000 000.
    let o = options(CyclerefProfile::Gsk988);
    let program = "G50 X3000 Z50 M3 S300;\nG00 X2200 Z10;\nG76 P990000 Q0.001 R0 L999 E1;\nG76 X100 Z-62 \
                   P999.999 Q0.001 F6;\n";
    let started = std::time::Instant::now();
    let (status, count, _, err) = expand_with(program.as_bytes(), &o, 0);
    assert_eq!((status, count, err.line), (CyclerefStatus::CycleError, 0, 4));
    assert!(err.message().contains("999097902 pass paths"), "{}", err.message());
    assert!(started.elapsed() < std::time::Duration::from_secs(10));
}

#[test]
#[allow(unsafe_code)]
fn invalid_arguments() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let (status, _, _, err) = expand_with(b"G00 X\xff;", &o, 0);
    assert_eq!(status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("not UTF-8"), "{}", err.message());
    let mut bad = o;
    bad.increment = 9;
    assert_eq!(expand_with(text.as_bytes(), &bad, 0).0, CyclerefStatus::InvalidArgument);
    let mut bad = o;
    bad.params_toml_len = 3;
    let (status, _, _, err) = expand_with(text.as_bytes(), &bad, 0);
    assert_eq!(status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("params_toml"), "{}", err.message());
    let mut count = 7;
    let mut err = CyclerefError::default();
    // SAFETY: NULL where the function must refuse it; the other pointers
    // are valid.
    unsafe {
        let p = text.as_ptr().cast::<c_char>();
        assert_eq!(
            cycleref_expand(ptr::null(), 0, &o, ptr::null_mut(), 0, &mut count, &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!((count, err.line), (0, 0));
        assert!(err.message().contains("program is NULL"));
        assert_eq!(
            cycleref_expand(p, text.len(), ptr::null(), ptr::null_mut(), 0, &mut count, ptr::null_mut()),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!(
            cycleref_expand(p, text.len(), &o, ptr::null_mut(), 0, ptr::null_mut(), &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!(
            cycleref_expand(p, text.len(), &o, ptr::null_mut(), 1, &mut count, &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert!(err.message().contains("moves"), "{}", err.message());
    }
}

#[test]
#[allow(unsafe_code)]
fn the_step_api_yields_the_cycle() {
    let text = example("gsk988-m68x6.nc");
    let program = read(&text, &Machine::new(ProfileName::Gsk988)).unwrap();
    let cycle = program.cycles().next().unwrap().cycle;
    let params = CyclerefG76Params::from_cycle(&cycle);
    // The parameters tests/c/expand_example.c writes by hand.
    let by_hand = CyclerefG76Params {
        increment: CyclerefIncrement::IsB as u32,
        start_x: 80_000,
        start_z: 10_000,
        end_x: 60_640,
        end_z: -62_000,
        thread_height: 3_680,
        first_depth: 1_800,
        min_cut: 150,
        finishing_allowance: 100,
        finishing_passes: 2,
        tool_angle: 60,
        infeed: CyclerefInfeed::RightFlank as u32,
        starts: 1,
        lead_word: CyclerefLeadWord::F as u32,
        lead_mantissa: 6,
        run_out_kind: CyclerefRunOutKind::Chamfer as u32,
        run_out_tenths: 5,
        run_out_angle: 45,
        pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
        ..CyclerefG76Params::default()
    };
    assert_eq!(params, by_hand);
    assert_eq!(params.cycle(), Ok(cycle));
    assert_eq!(CyclerefG76Params { pass_limit: 0, ..by_hand }.cycle(), Ok(cycle));

    let mut err = CyclerefError::default();
    // SAFETY: valid params and error; the handle is used, then freed once.
    unsafe {
        let h = cycleref_g76_new(&params, &mut err);
        assert!(!h.is_null());
        assert_eq!(err.status, CyclerefStatus::Ok);
        let mut stepped = Vec::new();
        let mut m = CyclerefMove::default();
        while cycleref_g76_next(h, &mut m) == 1 {
            stepped.push(m);
        }
        assert_eq!(cycleref_g76_next(h, &mut m), 0);
        cycleref_g76_free(h);
        let expanded: Vec<_> = expand(&text, &options(CyclerefProfile::Gsk988))
            .unwrap()
            .into_iter()
            .map(|m| CyclerefMove { line: 0, ..m })
            .collect();
        assert_eq!(stepped, expanded);

        // Every kind of run-out and infeed round-trips.
        for run_out in [
            cycleref::RunOut::None,
            cycleref::RunOut::Amounts { short: 1_500, long: 2_000 },
            cycleref::RunOut::Chamfer { tenths_of_lead: 10, angle_degrees: 30, long: Some(2_500) },
        ] {
            for infeed in
                [cycleref::Infeed::RightFlank, cycleref::Infeed::RightCentre, cycleref::Infeed::LeftRight]
            {
                let c = cycleref::G76Cycle { run_out, infeed, ..cycle };
                assert_eq!(CyclerefG76Params::from_cycle(&c).cycle(), Ok(c));
            }
        }

        let inside = CyclerefG76Params { start_x: 62_000, ..params };
        assert!(cycleref_g76_new(&inside, &mut err).is_null());
        assert_eq!((err.status, err.line), (CyclerefStatus::CycleError, 0));
        for bad in [
            CyclerefG76Params { run_out_kind: 3, ..params },
            CyclerefG76Params { lead_word: 3, ..params },
            CyclerefG76Params { increment: 3, ..params },
            CyclerefG76Params { infeed: 6, ..params },
            CyclerefG76Params { depth_mode: 2, ..params },
        ] {
            assert!(cycleref_g76_new(&bad, &mut err).is_null());
            assert_eq!(err.status, CyclerefStatus::InvalidArgument);
        }
        assert!(cycleref_g76_new(ptr::null(), ptr::null_mut()).is_null());
        assert_eq!(cycleref_g76_next(ptr::null_mut(), &mut m), CyclerefStatus::InvalidArgument as i32);
        cycleref_g76_free(ptr::null_mut());
    }
}

#[test]
#[allow(unsafe_code)]
fn static_strings() {
    // SAFETY: both functions return static NUL-terminated strings.
    unsafe {
        assert_eq!(CStr::from_ptr(cycleref_version()).to_str(), Ok(env!("CARGO_PKG_VERSION")));
        assert_eq!(CStr::from_ptr(cycleref_status_name(-1)).to_str(), Ok("CYCLEREF_STATUS_BUFFER_TOO_SMALL"));
        assert_eq!(CStr::from_ptr(cycleref_status_name(0)).to_str(), Ok("CYCLEREF_STATUS_OK"));
        assert_eq!(CStr::from_ptr(cycleref_status_name(42)).to_str(), Ok("unknown status"));
    }
    for s in [
        CyclerefStatus::Ok,
        CyclerefStatus::BufferTooSmall,
        CyclerefStatus::ProgramError,
        CyclerefStatus::CycleError,
        CyclerefStatus::InvalidArgument,
        CyclerefStatus::Panic,
    ] {
        // SAFETY: as above.
        let name = unsafe { CStr::from_ptr(cycleref_status_name(s as i32)) };
        assert_eq!(name.to_str().unwrap(), format!("CYCLEREF_STATUS_{}", screaming(&format!("{s:?}"))));
    }
}

fn screaming(camel: &str) -> String {
    let mut out = String::new();
    for (i, c) in camel.chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(c.to_ascii_uppercase());
    }
    out
}

// ---------------------------------------------------------------------------
// The cursor: cycleref_cursor_open / _next / _close.

/// Opens a cursor on `program`: the cursor, or the error of the open.
#[allow(unsafe_code)]
fn open(program: &[u8], opts: &CyclerefOptions) -> Result<*mut CyclerefCursor, Box<CyclerefError>> {
    let mut err = CyclerefError::new(CyclerefStatus::Panic, 99, "not written");
    // SAFETY: the program slice, the options and `err` are valid for the call.
    let c = unsafe { cycleref_cursor_open(program.as_ptr().cast(), program.len(), opts, &mut err) };
    if c.is_null() {
        assert_ne!(err.status, CyclerefStatus::Ok);
        return Err(Box::new(err));
    }
    // Success clears the error.
    assert_eq!((err.status, err.line, err.message()), (CyclerefStatus::Ok, 0, String::new()));
    Ok(c)
}

/// Every move of `program` through a cursor, closed at the end.
#[allow(unsafe_code)]
fn cursor_moves(program: &[u8], opts: &CyclerefOptions) -> Result<Vec<CyclerefMove>, Box<CyclerefError>> {
    let c = open(program, opts)?;
    let mut moves = Vec::new();
    let mut err = CyclerefError::default();
    // SAFETY: `c` is a live cursor, used here only, closed once.
    unsafe {
        let mut m = CyclerefMove::default();
        loop {
            match cycleref_cursor_next(c, &mut m, &mut err) {
                1 => moves.push(m),
                0 => break,
                s => panic!("cycleref_cursor_next: {s}: {}", err.message()),
            }
            assert_eq!(err.status, CyclerefStatus::Ok);
        }
        // At the end it stays at the end and writes nothing.
        let sentinel = CyclerefMove { x: 12_345, ..CyclerefMove::default() };
        m = sentinel;
        assert_eq!(cycleref_cursor_next(c, &mut m, ptr::null_mut()), 0);
        assert_eq!(cycleref_cursor_next(c, &mut m, &mut err), 0);
        assert_eq!((m, err.status), (sentinel, CyclerefStatus::Ok));
        cycleref_cursor_close(c);
    }
    Ok(moves)
}

/// Every move of every cycle of `program` by the Rust pipeline (the
/// streaming reader, one dispatch), in the C form.
fn pipeline_moves(program: &[u8], machine: &Machine) -> Vec<CyclerefMove> {
    use cycleref_spec::pipeline::{expand, Cycle, Engine};
    let mut out = Vec::new();
    for item in cycleref_spec::Reader::new(program, machine) {
        let item = item.expect("reads");
        if let Some(cycle) = Cycle::of(&item) {
            let kind = match cycle {
                Cycle::G76(c) if c.code == Multipass::G78 => CyclerefCycle::G78,
                Cycle::G76(_) => CyclerefCycle::G76,
                Cycle::G32(_) => CyclerefCycle::G32,
                Cycle::G75(_) => CyclerefCycle::G75,
                Cycle::G92(_) => CyclerefCycle::G92,
                Cycle::LinuxCnc(_) => CyclerefCycle::G76,
            };
            let (decimals, line) = (cycle.units().decimals(), cycle.line());
            let ours: Vec<_> = expand(cycle, Engine::Impl).expect("expands").collect();
            // The reference model gives the same moves.
            assert_eq!(ours, expand(cycle, Engine::Spec).expect("expands").collect::<Vec<_>>());
            out.extend(ours.iter().map(|m| CyclerefMove::from_move(m, decimals, kind, line)));
        }
    }
    out
}

#[test]
fn cursor_m68x6_equals_expand_and_the_pipeline() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let moves = cursor_moves(text.as_bytes(), &o).unwrap();
    assert_eq!(moves.len(), 30);
    assert_eq!(moves, expand(&text, &o).unwrap());
    assert_eq!(moves, pipeline_moves(text.as_bytes(), &Machine::new(ProfileName::Gsk988)));
    assert_eq!(moves, engine_moves(&text, &Machine::new(ProfileName::Gsk988)));

    // The first pass, worked by hand (IS-B mm: 1 = 0.001 mm). A = X80 Z10,
    // D = X60.64 Z-62, k = 3.68, Δd = 1.8, a = 60°, right flank infeed,
    // chamfer r = 0.5 lead = 3 mm at 45° (the 988TA's 5131 = 0).
    // Depth 1.8: X = 60.64 + 2·(3.68 - 1.8) = 64.40; the flank shifts Z by
    // 1.8·tan 30° = 1.03923 → 1.039: Z = 10 - 1.039 = 8.961.
    let first: Vec<_> = moves[..5]
        .iter()
        .map(|m| (m.motion, m.role, m.x, m.z, m.sync, m.pass_number, m.pass_depth, m.pass_cut))
        .collect();
    use CyclerefMotion::{Rapid, Thread};
    use CyclerefRole::*;
    assert_eq!(
        first,
        [
            (Rapid, Approach, 64_400, 8_961, 0, 1, 1_800, 1_800),
            // The cut to where the 3 mm run-out starts: Z-62 + 3.
            (Thread, Cut, 64_400, -59_000, 1, 1, 1_800, 1_800),
            // 45°: 3 mm along Z, 3 mm radius (6 mm diameter) along X.
            (Thread, RunOut, 70_400, -62_000, 0, 1, 1_800, 1_800),
            (Rapid, Retract, 80_000, -62_000, 0, 1, 1_800, 1_800),
            (Rapid, Return, 80_000, 10_000, 0, 1, 1_800, 1_800),
        ]
    );
    for m in &moves[..5] {
        assert_eq!(
            (m.cycle, m.line, m.decimals, m.has_pass, m.pass_kind, m.pass_start, m.pass_flank),
            (CyclerefCycle::G76, 6, 3, 1, CyclerefPassKind::Rough, 1, CyclerefFlank::Right)
        );
    }
    for m in &moves[1..3] {
        assert_eq!((m.lead_word, m.lead_mantissa, m.lead_scale), (CyclerefLeadWord::F, 6, 0));
        assert_eq!((m.start_angle_num, m.start_angle_den), (0, 1));
    }
    // Pass 2: depth 1.8·√2 = 2.5456 → 2.546, cut 0.746; X = 60.64 +
    // 2·(3.68 - 2.546) = 62.908, Z = 10 - 2.546·tan 30° = 10 - 1.470.
    let m = moves[5];
    assert_eq!(
        (m.role, m.x, m.z, m.pass_number, m.pass_depth, m.pass_cut),
        (Approach, 62_908, 8_530, 2, 2_546, 746)
    );
}

#[test]
fn cursor_every_example_equals_expand() {
    for (name, text, o, m) in examples() {
        let got = cursor_moves(text.as_bytes(), &o).unwrap_or_else(|e| panic!("{name}: {}", e.message()));
        assert!(!got.is_empty(), "{name}");
        assert_eq!(got, expand(&text, &o).unwrap(), "{name}");
        assert_eq!(got, pipeline_moves(text.as_bytes(), &m), "{name}");
    }
    // A program of three kinds of cycle: each move names its own.
    // GROOVE without its M30: nothing after M30 is read (R-PROGRAMEND).
    let groove = GROOVE.replace("M30\n", "");
    let text = format!("{groove}G00 X80 Z10\nG76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\n");
    let got = cursor_moves(text.as_bytes(), &options(CyclerefProfile::Gsk980)).unwrap();
    assert_eq!(got, expand(&text, &options(CyclerefProfile::Gsk980)).unwrap());
    let mut kinds: Vec<_> = got.iter().map(|m| (m.cycle, m.line)).collect();
    kinds.dedup();
    assert_eq!(kinds, [(CyclerefCycle::G75, 4), (CyclerefCycle::G76, 7)]);
}

/// A program of `n` M68x6 cycles on the 988TA whose last cycle is `last`.
fn cycles_then(n: usize, last: &str) -> String {
    let mut p = String::from("G50 X100 Z50 M3 S300;\nG00 X80 Z10;\n");
    for _ in 0..n {
        p.push_str("G76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\nG00 X80 Z10;\n");
    }
    p.push_str(last);
    p
}

#[test]
fn cursor_refuses_a_program_whose_last_cycle_is_invalid() {
    let o = options(CyclerefProfile::Gsk988);
    let good = cycles_then(1_000, "M30;\n");
    assert_eq!(cursor_moves(good.as_bytes(), &o).unwrap().len(), 30_000);
    // Lines: 2 + 3 per cycle, so the last cycle's block 2 is line 3004.
    // The reader's error: block 2 without P(k).
    let missing_p = cycles_then(1_000, "G76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 Q1.800 F6;\n");
    let err = open(missing_p.as_bytes(), &o).unwrap_err();
    assert_eq!((err.status, err.line), (CyclerefStatus::ProgramError, 3_004));
    assert!(err.message().starts_with("line 3004"), "{}", err.message());
    assert!(err.message().contains("P(k)"), "{}", err.message());
    // The engine's alarm: A = X62 between the crest and the root.
    let inside =
        cycles_then(1_000, "G00 X62;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\n");
    let err = open(inside.as_bytes(), &o).unwrap_err();
    assert_eq!((err.status, err.line), (CyclerefStatus::CycleError, 3_005));
    assert!(err.message().starts_with("line 3005, G76: the start point A"), "{}", err.message());
    // cycleref_expand reports the same error, count 0.
    let (status, count, _, e) = expand_with(inside.as_bytes(), &o, 0);
    assert_eq!((status, count, e.line, e.message()), (CyclerefStatus::CycleError, 0, 3_005, err.message()));
    // A G75.1 alarm on the 980TDi.
    let wide = GROOVE.replace("I2", "I6");
    let err = open(wide.as_bytes(), &options(CyclerefProfile::Gsk980)).unwrap_err();
    assert_eq!((err.status, err.line), (CyclerefStatus::CycleError, 4));
    assert!(err.message().starts_with("line 4, G75.1: the groove"), "{}", err.message());
    // A NULL `err` is fine on failure too.
    // SAFETY: valid program and options, NULL `err`.
    #[allow(unsafe_code)]
    let c = unsafe {
        cycleref_cursor_open(
            wide.as_ptr().cast(),
            wide.len(),
            &options(CyclerefProfile::Gsk980),
            ptr::null_mut(),
        )
    };
    assert!(c.is_null());
}

/// Errors come in program order: an alarm before a later reader error is
/// the one reported, by the cursor and by `cycleref_expand` alike.
#[test]
fn the_first_error_in_program_order() {
    let o = options(CyclerefProfile::Gsk988);
    let text = "G50 X100 Z50 M3 S300;\nG00 X62 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\nG76 X60.64 Z-62 Q1.800 F6;\n";
    let err = open(text.as_bytes(), &o).unwrap_err();
    assert_eq!((err.status, err.line), (CyclerefStatus::CycleError, 4));
    let (status, _, _, e) = expand_with(text.as_bytes(), &o, 0);
    assert_eq!((status, e.line), (CyclerefStatus::CycleError, 4));
}

#[test]
#[allow(unsafe_code)]
fn cursor_arguments() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let err = open(b"G00 X\xff;", &o).unwrap_err();
    assert_eq!(err.status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("not UTF-8"), "{}", err.message());
    let err = open(text.as_bytes(), &CyclerefOptions { profile: 4, ..o }).unwrap_err();
    assert_eq!(err.status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("profile"), "{}", err.message());
    let err = open(text.as_bytes(), &CyclerefOptions { params_toml_len: 3, ..o }).unwrap_err();
    assert_eq!(err.status, CyclerefStatus::InvalidArgument);
    let mut err = CyclerefError::default();
    let mut m = CyclerefMove::default();
    // SAFETY: NULL where the functions must refuse it; every other pointer
    // is valid; the one cursor is closed once.
    unsafe {
        let p = text.as_ptr().cast::<c_char>();
        assert!(cycleref_cursor_open(ptr::null(), 0, &o, &mut err).is_null());
        assert_eq!((err.status, err.line), (CyclerefStatus::InvalidArgument, 0));
        assert!(err.message().contains("program is NULL"), "{}", err.message());
        assert!(cycleref_cursor_open(p, text.len(), ptr::null(), &mut err).is_null());
        assert!(err.message().contains("opts is NULL"), "{}", err.message());
        assert!(cycleref_cursor_open(p, text.len(), ptr::null(), ptr::null_mut()).is_null());

        assert_eq!(
            cycleref_cursor_next(ptr::null_mut(), &mut m, &mut err),
            CyclerefStatus::InvalidArgument as i32
        );
        assert!(err.message().contains("cursor is NULL"), "{}", err.message());
        assert_eq!(cycleref_cursor_next(ptr::null_mut(), &mut m, ptr::null_mut()), -4);
        let c = cycleref_cursor_open(p, text.len(), &o, &mut err);
        assert!(!c.is_null());
        assert_eq!(
            cycleref_cursor_next(c, ptr::null_mut(), &mut err),
            CyclerefStatus::InvalidArgument as i32
        );
        assert!(err.message().contains("out is NULL"), "{}", err.message());
        // The refused call took no move.
        assert_eq!(cycleref_cursor_next(c, &mut m, &mut err), 1);
        assert_eq!((m.x, m.z, err.status), (64_400, 8_961, CyclerefStatus::Ok));
        // Closing before the end frees everything.
        cycleref_cursor_close(c);
        cycleref_cursor_close(ptr::null_mut());
    }
}

/// The cursor keeps its own copy of the program: the caller's text may be
/// overwritten and freed right after the open.
#[test]
#[allow(unsafe_code)]
fn cursor_keeps_no_pointer() {
    let o = options(CyclerefProfile::Gsk988);
    let mut text = example("gsk988-m68x6.nc").into_bytes();
    let expected = cursor_moves(&text, &o).unwrap();
    let c = open(&text, &o).unwrap();
    text.fill(b' ');
    drop(text);
    let mut got = Vec::new();
    let mut m = CyclerefMove::default();
    // SAFETY: `c` is live, used here only, closed once.
    unsafe {
        while cycleref_cursor_next(c, &mut m, ptr::null_mut()) == 1 {
            got.push(m);
        }
        cycleref_cursor_close(c);
    }
    assert_eq!(got, expected);
}

/// A cursor may move to another thread; two cursors on one program are
/// independent.
#[test]
#[allow(unsafe_code)]
fn cursors_are_independent() {
    struct Send(*mut CyclerefCursor);
    // SAFETY: a cursor has no thread affinity (documented), and each one
    // is used by one thread at a time here.
    unsafe impl std::marker::Send for Send {}
    let o = options(CyclerefProfile::Gsk988);
    let text = example("gsk988-m68x6.nc");
    let expected = expand(&text, &o).unwrap();
    let (a, b) = (Send(open(text.as_bytes(), &o).unwrap()), Send(open(text.as_bytes(), &o).unwrap()));
    let take = |c: Send| {
        let mut v = Vec::new();
        let mut m = CyclerefMove::default();
        // SAFETY: the cursor is live, used by this thread only, closed once.
        unsafe {
            while cycleref_cursor_next(c.0, &mut m, ptr::null_mut()) == 1 {
                v.push(m);
            }
            cycleref_cursor_close(c.0);
        }
        v
    };
    let t = std::thread::spawn(move || take(a));
    assert_eq!(take(b), expected);
    assert_eq!(t.join().unwrap(), expected);
}

/// `cycleref_g92_new`/`_next`/`_free` on the 980TDi's O0012 first block
/// (`G0 X65 Z5; G92 X58.7 Z-28 F3 J3 K1`, worked out in spec/tests/g92.rs:
/// B = X58.7 Z5, the cut to Z-27, the run-out to X64.7 Z-28, the retract
/// to X65, the return to Z5), a two-start block at Q90 (starts at 90° and
/// 270°), the alarms and the arguments.
#[test]
#[allow(unsafe_code)]
fn the_g92_step_api() {
    let params = CyclerefG92Params {
        increment: CyclerefIncrement::IsB as u32,
        start_x: 65_000,
        start_z: 5_000,
        end_x: 58_700,
        end_z: -28_000,
        lead_word: CyclerefLeadWord::F as u32,
        lead_mantissa: 3,
        run_out_kind: CyclerefRunOutKind::Amounts as u32,
        run_out_short: 3_000,
        run_out_long: 1_000,
        starts: 1,
        ..CyclerefG92Params::default()
    };
    let stepped = |p: &CyclerefG92Params| -> Result<Vec<CyclerefMove>, Box<CyclerefError>> {
        let mut err = CyclerefError::default();
        // SAFETY: valid params and error; the handle is used, then freed once.
        unsafe {
            let h = cycleref_g92_new(p, &mut err);
            if h.is_null() {
                return Err(Box::new(err));
            }
            let mut out = Vec::new();
            let mut m = CyclerefMove::default();
            while cycleref_g92_next(h, &mut m) == 1 {
                out.push(m);
            }
            assert_eq!(cycleref_g92_next(h, &mut m), 0, "fused");
            cycleref_g92_free(h);
            Ok(out)
        }
    };
    let got: Vec<_> =
        stepped(&params).unwrap().iter().map(|m| (m.cycle, m.motion, m.role, m.x, m.z, m.sync)).collect();
    assert_eq!(
        got,
        [
            (CyclerefCycle::G92, CyclerefMotion::Rapid, CyclerefRole::Approach, 58_700, 5_000, 0),
            (CyclerefCycle::G92, CyclerefMotion::Thread, CyclerefRole::Cut, 58_700, -27_000, 1),
            (CyclerefCycle::G92, CyclerefMotion::Thread, CyclerefRole::RunOut, 64_700, -28_000, 0),
            (CyclerefCycle::G92, CyclerefMotion::Rapid, CyclerefRole::Retract, 65_000, -28_000, 0),
            (CyclerefCycle::G92, CyclerefMotion::Rapid, CyclerefRole::Return, 65_000, 5_000, 0),
        ]
    );
    // L2 from Q = 90°: 90° and 90° + 180°.
    let two =
        stepped(&CyclerefG92Params { starts: 2, start_angle_num: 90_000, start_angle_den: 1, ..params })
            .unwrap();
    let angles: Vec<_> = two
        .iter()
        .filter(|m| m.sync == 1)
        .map(|m| (m.pass_start, m.start_angle_num, m.start_angle_den))
        .collect();
    assert_eq!(angles, [(1, 90_000, 1), (2, 270_000, 1)]);
    // The manual's alarms are cycle errors; bad enum values invalid arguments.
    let e = stepped(&CyclerefG92Params { end_x: 65_000, ..params }).unwrap_err();
    assert_eq!(e.status, CyclerefStatus::CycleError);
    assert!(e.message().contains("U = 0"), "{}", e.message());
    let e = stepped(&CyclerefG92Params { run_out_kind: 3, ..params }).unwrap_err();
    assert_eq!(e.status, CyclerefStatus::InvalidArgument);
    // SAFETY: NULL arguments are refused, never read.
    unsafe {
        let mut err = CyclerefError::default();
        assert!(cycleref_g92_new(ptr::null(), &mut err).is_null());
        assert_eq!(err.status, CyclerefStatus::InvalidArgument);
        let mut m = CyclerefMove::default();
        assert_eq!(cycleref_g92_next(ptr::null_mut(), &mut m), CyclerefStatus::InvalidArgument as i32);
        cycleref_g92_free(ptr::null_mut());
    }
}
