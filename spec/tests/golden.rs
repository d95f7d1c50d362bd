//! Golden tests: the worked examples of the seeds and manual pages, with the
//! expected depths and coordinates worked out by hand from the manual's
//! formulas in the comments (not copied from the program's output).
//!
//! Notation: k thread height, Δd first depth, Δdmin minimum cut, d
//! finishing allowance, k' = k - d, Nn = round(Δd √n), Dn the depth of rough
//! level n (DOMAIN decision 3), shift = round(Dn tan(a/2)), Bn = (XD + 2(k -
//! Dn), ZA - shift) for an external thread cut towards -Z (diameter X).

use cycleref::{Motion, Move, PassKind, Role};
use cycleref_spec::profile::Machine;
use cycleref_spec::{read, ProfileName};

fn example(name: &str) -> String {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Moves as compact NC-like strings: `G00 X64.400 Z8.961`, `G32 …`.
///
/// Twin: `proofs/tests/g75_golden.rs`, `render` (G75.1 lines, with each
/// move's role).
fn render(moves: &[Move], decimals: u32) -> Vec<String> {
    let f = |v: i64| cycleref::units::Length { increments: v, decimals }.to_string();
    moves
        .iter()
        .map(|m| {
            let g = match m.motion {
                Motion::Rapid => "G00",
                Motion::Feed => "G01",
                Motion::Thread { .. } => "G32",
                Motion::Arc { clockwise: true, .. } => "G02",
                Motion::Arc { clockwise: false, .. } => "G03",
            };
            format!("{g} X{} Z{}", f(m.to.x), f(m.to.z))
        })
        .collect()
}

fn expand_example(name: &str, machine: &Machine) -> Vec<Move> {
    let text = example(name);
    let program = read(&text, machine).expect("reads");
    let call = program.cycles().next().expect("one G76");
    cycleref_spec::g76::expand(&call.cycle).expect("expands")
}

/// One pass: approach to Bn, cut to the run-out start, run-out, retract to
/// E, return to A.
fn pass(bx: &str, bz: &str, run_start: (&str, &str), run_end: (&str, &str), a: (&str, &str)) -> Vec<String> {
    vec![
        format!("G00 X{bx} Z{bz}"),
        format!("G32 X{} Z{}", run_start.0, run_start.1),
        format!("G32 X{} Z{}", run_end.0, run_end.1),
        format!("G00 X{} Z{}", a.0, run_end.1),
        format!("G00 X{} Z{}", a.0, a.1),
    ]
}

/// manuals/gsk988ta-g76.txt, O0013, M68x6:
/// `G00 X80 Z10; G76 P020560 Q0.150 R0.1; G76 X60.64 Z-62 P3.680 Q1.800 F6`.
///
/// m = 2, r = 05, a = 60, Δdmin = 0.15, d = 0.1, k = 3.68, Δd = 1.8,
/// lead 6. k' = 3.58. A = (80, 10), D = (60.64, -62), i = 0: C at X60.64,
/// B at X60.64 + 2 × 3.68 = X68 (the major diameter). External (80 > 60.64),
/// cutting towards -Z.
///
/// Depths: N1 = 1.8 → D1 = 1.800. N2 = 1.8 √2 = 2.54558 → 2.546 ≥ 1.8 +
/// 0.15 → D2 = 2.546. N3 = 1.8 √3 = 3.11769 → 3.118 ≥ 2.696 → D3 = 3.118.
/// N4 = 3.6 ≥ k' → D4 = 3.580 (four rough passes).
///
/// X of Bn = 60.64 + 2 (3.68 - Dn): 64.400, 62.908, 61.764, 60.840;
/// finishing 60.640.
/// Shift = Dn tan 30° (tan 30° = 0.5773503): 1.0392 → 1.039, 1.4699 → 1.470,
/// 1.8002 → 1.800, 2.0669 → 2.067; Z of Bn = 10 - shift: 8.961, 8.530,
/// 8.200, 7.933; finishing at the last rough Z, 7.933.
///
/// Run-out: no J/K programmed on the 988TA, so the chamfer r = 5 tenths of
/// the lead: K = 0.5 × 6 = 3.000 (the manual's comment: "倒角宽度 3mm"),
/// with parameter 5131 = 0 → 45°: J = 3.000 (X + 6.000 on the diameter).
/// The cut ends at Z-62 + 3 = Z-59, the run-out at Z-62, X + 6.
#[test]
fn gsk988_m68x6() {
    let moves = expand_example("gsk988-m68x6.nc", &Machine::new(ProfileName::Gsk988));
    let a = ("80.000", "10.000");
    let mut expected = Vec::new();
    for (x, z, xr) in [
        ("64.400", "8.961", "70.400"),
        ("62.908", "8.530", "68.908"),
        ("61.764", "8.200", "67.764"),
        ("60.840", "7.933", "66.840"),
        ("60.640", "7.933", "66.640"),
        ("60.640", "7.933", "66.640"),
    ] {
        expected.extend(pass(x, z, (x, "-59.000"), (xr, "-62.000"), a));
    }
    assert_eq!(render(&moves, 3), expected);
    // Annotations: 4 rough passes with their depths and cuts, then 2 finishing.
    let passes: Vec<_> = moves.iter().filter(|m| m.role == Role::Approach).map(|m| m.pass.unwrap()).collect();
    let depths: Vec<_> = passes.iter().map(|p| (p.kind, p.number, p.depth, p.cut)).collect();
    assert_eq!(
        depths,
        vec![
            (PassKind::Rough, 1, 1800, 1800),
            (PassKind::Rough, 2, 2546, 746),
            (PassKind::Rough, 3, 3118, 572),
            (PassKind::Rough, 4, 3580, 462),
            (PassKind::Finish, 1, 3680, 100),
            (PassKind::Finish, 2, 3680, 0),
        ]
    );
    // The lead is 6 on every thread move; the first thread move of each pass synchronises.
    for m in &moves {
        if let Motion::Thread { lead, sync, .. } = m.motion {
            assert_eq!((lead.mantissa, lead.scale), (6, 0));
            assert_eq!(sync, m.role == Role::Cut);
        }
    }
}

/// manuals/gsk980tdi-g76.txt, O0013 at IS-C (the manual: "系统最小输入增量为
/// 0.0001mm"), P and Q in increments (No.182.7 = 0): `Q1500` = 0.15,
/// `P36800` = 3.68, `Q18000` = 1.8.
///
/// Depths to 0.0001: N2 = 2.545584 → 2.5456, N3 = 3.117691 → 3.1177, D4 =
/// 3.58. X of Bn = 60.64 + 2 (3.68 - Dn): 64.4000, 62.9088, 61.7646, 60.8400.
/// Shift = Dn × 0.57735027: 1.039230 → 1.0392, 1.469700 → 1.4697, 1.800011 →
/// 1.8000, 2.066914 → 2.0669; Z = 8.9608, 8.5303, 8.2000, 7.9331.
/// Run-out: no J/K → P(r) = 05: K = 3, 45° on the 980TDi: J = 3.
#[test]
fn gsk980_m68x6_is_c() {
    let mut m = Machine::new(ProfileName::Gsk980);
    m.increment = cycleref::IncrementSystem::IsC;
    let moves = expand_example("gsk980-m68x6.nc", &m);
    let a = ("80.0000", "10.0000");
    let mut expected = Vec::new();
    for (x, z, xr) in [
        ("64.4000", "8.9608", "70.4000"),
        ("62.9088", "8.5303", "68.9088"),
        ("61.7646", "8.2000", "67.7646"),
        ("60.8400", "7.9331", "66.8400"),
        ("60.6400", "7.9331", "66.6400"),
        ("60.6400", "7.9331", "66.6400"),
    ] {
        expected.extend(pass(x, z, (x, "-59.0000"), (xr, "-62.0000"), a));
    }
    assert_eq!(render(&moves, 4), expected);
}

/// Seed 000's example: `G00 X80 Z10; G76 P020545 Q0.15 R0.5;
/// G76 X60 Z-60 P3 Q1.8 F300 J1.5 K2`.
///
/// k = 3, Δd = 1.8, d = 0.5, k' = 2.5, a = 45. N1 = 1.8 → D1 = 1.8; N2 =
/// 2.546 ≥ k' → D2 = 2.5 (the figure of the 988TA G78 page shows exactly
/// 1.8mm, 2.5mm, 0.5mm, k = 3mm). X of Bn = 60 + 2 (3 - Dn): 62.4, 61.0,
/// finishing 60. tan 22.5° = 0.41421356: shifts 0.745584 → 0.746 and
/// 1.035534 → 1.036: Z 9.254, 8.964. J = 1.5, K = 2 (both non-zero: the
/// normal-mode G92 rule gives both): the cut ends at Z-58 and the run-out at
/// Z-60, X + 3.
#[test]
fn seed000_extended() {
    let moves = expand_example("seed000-extended.nc", &Machine::new(ProfileName::Gsk988));
    let a = ("80.000", "10.000");
    let mut expected = Vec::new();
    for (x, z, xr) in [
        ("62.400", "9.254", "65.400"),
        ("61.000", "8.964", "64.000"),
        ("60.000", "8.964", "63.000"),
        ("60.000", "8.964", "63.000"),
    ] {
        expected.extend(pass(x, z, (x, "-58.000"), (xr, "-60.000"), a));
    }
    assert_eq!(render(&moves, 3), expected);
}

/// Seed 004, example 1 (FANUC, external): `G00 X26.0 Z3.0;
/// G76 P020560 Q100 R0.1; G76 X21.4 Z-26.0 R0 P1300 Q400 F2.0`.
///
/// FANUC P and Q without decimal point are least increments (IS-B): k =
/// 1.3, Δd = 0.4, Δdmin = 0.1; d = 0.1 → k' = 1.2.
/// N1 = 0.4; N2 = 0.5657 → 0.566 (≥ 0.5); N3 = 0.6928 → 0.693 (≥ 0.666);
/// N4 = 0.8 (≥ 0.793); N5 = 0.8944 → 0.894 < 0.8 + 0.1: the minimum cut
/// takes over: 0.9, 1.0, 1.1, 1.2 (eight rough passes).
/// X of Bn = 21.4 + 2 (1.3 - Dn): 23.2, 22.868, 22.614, 22.4, 22.2, 22.0,
/// 21.8, 21.6; finishing 21.4.
/// Shifts (tan 30°): 0.2309 → 0.231, 0.3268 → 0.327, 0.4001 → 0.400,
/// 0.4619 → 0.462, 0.5196 → 0.520, 0.5774 → 0.577, 0.6351 → 0.635,
/// 0.6928 → 0.693: Z = 2.769, 2.673, 2.600, 2.538, 2.480, 2.423, 2.365,
/// 2.307.
/// Run-out: r = 05 → K = 0.5 × 2 = 1, 45° (5131 = 0) → J = 1: the cut ends at
/// Z-25, the run-out at Z-26, X + 2.
#[test]
fn fanuc_external() {
    let moves = expand_example("fanuc-external.nc", &Machine::new(ProfileName::Fanuc));
    let a = ("26.000", "3.000");
    let mut expected = Vec::new();
    for (x, z, xr) in [
        ("23.200", "2.769", "25.200"),
        ("22.868", "2.673", "24.868"),
        ("22.614", "2.600", "24.614"),
        ("22.400", "2.538", "24.400"),
        ("22.200", "2.480", "24.200"),
        ("22.000", "2.423", "24.000"),
        ("21.800", "2.365", "23.800"),
        ("21.600", "2.307", "23.600"),
        ("21.400", "2.307", "23.400"),
        ("21.400", "2.307", "23.400"),
    ] {
        expected.extend(pass(x, z, (x, "-25.000"), (xr, "-26.000"), a));
    }
    assert_eq!(render(&moves, 3), expected);
}

/// Seed 004, example 2 (FANUC, internal): `G00 X26.0 Z3.0;
/// G76 P020160 Q100 R0.1; G76 X36.0 Z-40.0 R0 P1950 Q400 F3.0`.
///
/// A (X26) lies inside C (X36): internal thread, B at 36 - 2 × 1.95 = 32.1.
/// k = 1.95, Δd = 0.4, Δdmin = 0.1, d = 0.1, k' = 1.85. As above up to
/// 0.8, then the minimum cut: 0.9, 1.0, … 1.8, and k' = 1.85 (15 levels).
/// X of Bn = 36 - 2 (1.95 - Dn): 32.9, 33.232, 33.486, 33.7, 33.9, … 35.7,
/// 35.8; finishing 36.0.
/// Shifts: as above, then 1.3 → 0.7506 → 0.751 … 1.8 → 1.0392 → 1.039,
/// 1.85 → 1.0681 → 1.068.
/// Run-out: r = 01 → K = 0.1 × 3 = 0.3, J = 0.3, towards A (smaller X): X - 0.6.
#[test]
fn fanuc_internal() {
    let moves = expand_example("fanuc-internal.nc", &Machine::new(ProfileName::Fanuc));
    let out = render(&moves, 3);
    // 15 rough + 2 finishing passes of 5 moves.
    assert_eq!(out.len(), 17 * 5);
    assert_eq!(
        out[0..5],
        pass("32.900", "2.769", ("32.900", "-39.700"), ("32.300", "-40.000"), ("26.000", "3.000"))
    );
    // Level 9: D = 1.3, X = 36 - 2 × 0.65 = 34.7, shift 0.751.
    assert_eq!(out[8 * 5], "G00 X34.700 Z2.249");
    // Level 15: D = 1.85, X = 35.8, shift 1.068 → Z 1.932.
    assert_eq!(out[14 * 5], "G00 X35.800 Z1.932");
    assert_eq!(out[14 * 5 + 2], "G32 X35.200 Z-40.000");
    // Finishing at X36 (D), the last rough Z.
    assert_eq!(
        out[15 * 5..16 * 5],
        pass("36.000", "1.932", ("36.000", "-39.700"), ("35.400", "-40.000"), ("26.000", "3.000"))
    );
}

fn expand_text(src: &str) -> Vec<Move> {
    let program = read(src, &Machine::new(ProfileName::Gsk988)).unwrap_or_else(|e| panic!("{e}"));
    let call = program.cycles().next().expect("one G76");
    cycleref_spec::g76::expand(&call.cycle).expect("expands")
}

/// The pass starts (approach ends) with their flank, as `(X, Z, flank)`.
fn starts(moves: &[Move]) -> Vec<(String, String, cycleref::Flank, PassKind, u32)> {
    let f = |v: i64| cycleref::units::Length { increments: v, decimals: 3 }.to_string();
    moves
        .iter()
        .filter(|m| m.role == Role::Approach)
        .map(|m| {
            let p = m.pass.unwrap();
            (f(m.to.x), f(m.to.z), p.flank, p.kind, p.number)
        })
        .collect()
}

/// Infeed D2 (左右等量轮流切入) on seed 000's thread without run-out:
/// k = 3, Δd = 1.8, d = 0.5 (k' = 2.5), a = 45 (tan 22.5° = 0.41421356).
/// Levels 1.8 and 2.5. The centre line zc = round(2.5 × 0.41421356) =
/// round(1.035534) = 1.036 (reading R-INFEED).
/// Level 1 (not the last): right flank shift round(1.8 × 0.41421356) =
/// round(0.745584) = 0.746 → Z 9.254; left flank 2 × 1.036 - 0.746 = 1.326
/// → Z 8.674; X = 60 + 2 × (3 - 1.8) = 62.4 for both.
/// Level 2 (the last, k - d): once, shift 1.036 → Z 8.964, X 61.0.
/// Finishing at X60 (D), the last rough Z 8.964.
#[test]
fn infeed_d2_left_right() {
    use cycleref::Flank::{Centre, Left, Right};
    let moves = expand_text("M03 S500\nG00 X80 Z10\nG76 P010045 Q0.15 R0.5 D2\nG76 X60 Z-60 P3 Q1.8 F3\n");
    assert_eq!(
        starts(&moves),
        vec![
            ("62.400".into(), "9.254".into(), Right, PassKind::Rough, 1),
            ("62.400".into(), "8.674".into(), Left, PassKind::Rough, 2),
            ("61.000".into(), "8.964".into(), Right, PassKind::Rough, 3),
            ("60.000".into(), "8.964".into(), Centre, PassKind::Finish, 1),
        ]
    );
    // Both passes of level 1 cut 1.8 (the level's cut), level 2 cuts 0.7.
    let cuts: Vec<i64> =
        moves.iter().filter(|m| m.role == Role::Approach).map(|m| m.pass.unwrap().cut).collect();
    assert_eq!(cuts, vec![1800, 1800, 700, 500]);
}

/// Infeed D1 (右中轮流切入): k = 3, Δd = 1, Δdmin = 0.1, d = 0.2 (k' = 2.8),
/// a = 60 (tan 30° = 0.5773503). Levels round(√n) to 0.001: 1.000, 1.414,
/// 1.732, 2.000, 2.236, 2.449, 2.646, then √8 = 2.828 ≥ 2.8 → 2.800 (every
/// law step is above Δdmin). zc = round(2.8 × 0.5773503) = round(1.616581)
/// = 1.617 → Z 8.383. Odd levels on the right flank: 1.000 × tan = 0.57735
/// → 0.577 (Z 9.423); 1.732 → 0.99997 → 1.000 (Z 9.000); 2.236 → 1.290955 →
/// 1.291 (Z 8.709); 2.646 → 1.527669 → 1.528 (Z 8.472). Even levels on the
/// centre line, Z 8.383. X = 60 + 2 (3 - D).
#[test]
fn infeed_d1_right_centre() {
    use cycleref::Flank::{Centre, Right};
    let moves = expand_text("M03 S500\nG00 X80 Z10\nG76 P010060 Q0.1 R0.2 D1\nG76 X60 Z-60 P3 Q1 F3\n");
    let r = PassKind::Rough;
    assert_eq!(
        starts(&moves),
        vec![
            ("64.000".into(), "9.423".into(), Right, r, 1),
            ("63.172".into(), "8.383".into(), Centre, r, 2),
            ("62.536".into(), "9.000".into(), Right, r, 3),
            ("62.000".into(), "8.383".into(), Centre, r, 4),
            ("61.528".into(), "8.709".into(), Right, r, 5),
            ("61.102".into(), "8.383".into(), Centre, r, 6),
            ("60.708".into(), "8.472".into(), Right, r, 7),
            ("60.400".into(), "8.383".into(), Centre, r, 8),
            ("60.000".into(), "8.383".into(), Centre, PassKind::Finish, 1),
        ]
    );
}

/// Lead-in E (旋进) on the M68x6 thread: E = 0.5 (radius), the lead-in
/// start "与切削起点 Bn 距离为 E 的位置", E out along X at Bn's Z (reading
/// R-LEADIN, `same-z`). Pass 1: D1 = 1.8, Bn = (60.64 + 2 × (3.68 - 1.8),
/// 10 - round(1.8 × tan 30°)) = (64.400, 10 - 1.039) = (64.400, 8.961), so
/// An = (64.400 + 2 × 0.5, 8.961) = (65.400, 8.961): a rapid to An, then a
/// thread move (synchronised) along X to Bn, then the cut (not
/// synchronised again). (Under `whole-leads`, 1 lead of 6 back: An =
/// (65.400, 14.961).)
#[test]
fn lead_in_screws_in_over_one_lead() {
    let moves = expand_text(
        "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 E0.5\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n",
    );
    let first: Vec<String> = render(&moves[..4], 3);
    assert_eq!(
        first,
        vec!["G00 X65.400 Z8.961", "G32 X64.400 Z8.961", "G32 X64.400 Z-59.000", "G32 X70.400 Z-62.000"]
    );
    let syncs: Vec<bool> =
        moves[..4].iter().map(|m| matches!(m.motion, Motion::Thread { sync: true, .. })).collect();
    assert_eq!(syncs, vec![false, true, false, false]);
    assert_eq!(moves[1].role, Role::LeadIn);
}

/// Three starts (L3): every pass is cut for starts at 0°, 120° and 240°
/// before the next depth (reading R-STARTS); the start angle travels with
/// the synchronised move.
#[test]
fn three_starts_cut_each_depth_in_turn() {
    let moves = expand_text("M03 S500\nG00 X80 Z10\nG76 P010060 Q0.1 R0 L3\nG76 X60 Z-30 P1 Q1 F6\n");
    let order: Vec<(u32, u16, u32, u32)> = moves
        .iter()
        .filter_map(|m| match m.motion {
            Motion::Thread { start_angle, sync: true, .. } => {
                let p = m.pass.unwrap();
                Some((p.number, p.start, start_angle.num, start_angle.den))
            }
            _ => None,
        })
        .collect();
    // k = 1, Δd = 1: one rough level at k - d = 1, then one finishing pass.
    assert_eq!(
        order,
        vec![
            (1, 1, 0, 1),
            (1, 2, 120_000, 1),
            (1, 3, 240_000, 1),
            (1, 1, 0, 1),
            (1, 2, 120_000, 1),
            (1, 3, 240_000, 1)
        ]
    );
}
