//! G92: golden tests worked by hand from the 980TDi and 988TA pages
//! (manuals/gsk980tdi-g92.txt, manuals/gsk988ta-g92.txt), every profile's
//! run-out rules, the modal words and every alarm. Each expected point is
//! derived in the comment above it; both engines must give it.

use cycleref::{
    CycleError, Flank, Lead, LeadWord, Motion, Move, Pass, PassKind, Point, Role, RunOut, StartAngle,
};
use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::profile::Machine;
use cycleref_spec::{read, ErrorKind, ProfileName, ProgramError};

fn example(name: &str) -> String {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every G92 block's moves, by both engines (which must agree).
fn blocks(src: &str, m: &Machine) -> Vec<Vec<Move>> {
    let p = read(src, m).unwrap_or_else(|e| panic!("{e}"));
    p.items
        .iter()
        .filter_map(Cycle::of)
        .filter(|c| matches!(c, Cycle::G92(_)))
        .map(|c| {
            let ours: Vec<Move> = expand(c, Engine::Impl).unwrap_or_else(|e| panic!("{e}")).collect();
            let reference: Vec<Move> = expand(c, Engine::Spec).unwrap_or_else(|e| panic!("{e}")).collect();
            assert_eq!(ours, reference, "line {}", c.line());
            ours
        })
        .collect()
}

fn error(src: &str, m: &Machine) -> ProgramError {
    let p = match read(src, m) {
        Err(e) => return e,
        Ok(p) => p,
    };
    for c in p.items.iter().filter_map(Cycle::of) {
        let ours = expand(c, Engine::Impl).err();
        let reference = expand(c, Engine::Spec).err();
        assert_eq!(ours, reference, "line {}", c.line());
        if let Some(e) = ours {
            return ProgramError { line: c.line(), word: None, kind: ErrorKind::Cycle(e) };
        }
    }
    panic!("expected an error:\n{src}")
}

fn machine(p: ProfileName) -> Machine {
    Machine::new(p)
}

const F3: Lead = Lead { word: LeadWord::F, mantissa: 3, scale: 0 };
const F2: Lead = Lead { word: LeadWord::F, mantissa: 2, scale: 0 };

fn pass(start: u16) -> Option<Pass> {
    Some(Pass { kind: PassKind::Single, number: 1, start, depth: 0, cut: 0, flank: Flank::Centre })
}

fn rapid(x: i64, z: i64, role: Role) -> Move {
    Move { motion: Motion::Rapid, to: Point::new(x, z), role, pass: pass(1) }
}

fn thread(x: i64, z: i64, sync: bool, lead: Lead, role: Role) -> Move {
    Move {
        motion: Motion::Thread { lead, start_angle: StartAngle::ZERO, sync },
        to: Point::new(x, z),
        role,
        pass: pass(1),
    }
}

/// One pass of O0012 at the cut-end X `x` (IS-B, diameter): A = (65, 5),
/// C = (x, -28), J3 K1. Z is the long axis (|W| = 33 > |R| = 0). ① rapid
/// to B = (x, 5); ② thread to K = 1 before C, Z-27, still at x (straight),
/// then the run-out to Z-28 and J = 3 (radius) outwards, x + 6; ③ rapid to
/// the X of A, X65; ④ rapid to A.
fn o0012_pass(x: i64) -> Vec<Move> {
    vec![
        rapid(x, 5_000, Role::Approach),
        thread(x, -27_000, true, F3, Role::Cut),
        thread(x + 6_000, -28_000, false, F3, Role::RunOut),
        rapid(65_000, -28_000, Role::Retract),
        rapid(65_000, 5_000, Role::Return),
    ]
}

/// The 980TDi's example O0012: four blocks, the last three giving only X
/// (Z, F, J and K modal); 1.3, 1, 0.7 and 0.1 mm of infeed.
#[test]
fn gsk980_example_o0012() {
    let got = blocks(&example("gsk980-g92-o0012.nc"), &machine(ProfileName::Gsk980));
    let want: Vec<Vec<Move>> = [58_700, 57_700, 57_000, 56_900].into_iter().map(o0012_pass).collect();
    assert_eq!(got, want);
}

/// The 988TA's version of O0012 repeats J3 K1 on every block: the same
/// passes (normal mode, THM = 0: J and K given, both run-outs).
#[test]
fn gsk988_example_o0012() {
    let src = "O0012;\nM3 S300 G0 X150 Z50 T0101;\nG0 X65 Z5;\nG92 X58.7 Z-28 F3 J3 K1;\nX57.7 J3 K1;\nX57 J3 K1;\n\
               X56.9 J3 K1;\nM30;\n";
    let got = blocks(src, &machine(ProfileName::Gsk988));
    let want: Vec<Vec<Move>> = [58_700, 57_700, 57_000, 56_900].into_iter().map(o0012_pass).collect();
    assert_eq!(got, want);
}

/// Figure 3-90 case 2 (U < 0, W < 0, R < 0), an external taper: A = (50,
/// 2), C = (40, -30), R-5: B = (40 + 2·(-5), 2) = (30, 2). Z long (32 > 5).
/// J1 K2: the run-out starts at Z = -30 + 2 = -28 on the cut line from B
/// to C: X = 30 + (40 - 30)·(-28 - 2)/(-30 - 2) = 30 + 9.375 = 39.375; it
/// ends at Z-30, J = 1 outwards: X42. Retract to X50, return to Z2.
#[test]
fn external_taper_with_run_out() {
    let src = "M3 S500\nG0 X50 Z2\nG92 X40 Z-30 R-5 F2 J1 K2\nM30\n";
    let got = blocks(src, &machine(ProfileName::Gsk980));
    assert_eq!(
        got,
        vec![vec![
            rapid(30_000, 2_000, Role::Approach),
            thread(39_375, -28_000, true, F2, Role::Cut),
            thread(42_000, -30_000, false, F2, Role::RunOut),
            rapid(50_000, -30_000, Role::Retract),
            rapid(50_000, 2_000, Role::Return),
        ]]
    );
}

/// R and U of different signs: U = 40 - 50 = -10, R = +4 (radius):
/// |R| = 4 <= |U/2| = 5, B = (48, 2) lies between A and C. J0: no run-out
/// (980TDi note 5). With R6, B would be at X52, beyond A (X50): the
/// manual's condition |R| <= |U/2| refuses it. At R5, B = (50, 2) is A
/// itself: the approach does not move and is left out (R-ZERO).
#[test]
fn opposite_signs_within_and_beyond_the_condition() {
    let m = machine(ProfileName::Gsk980);
    let got = blocks("M3 S500\nG0 X50 Z2\nG92 X40 Z-30 R4 F2 J0\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(48_000, 2_000, Role::Approach),
            thread(40_000, -30_000, true, F2, Role::Cut),
            rapid(50_000, -30_000, Role::Retract),
            rapid(50_000, 2_000, Role::Return),
        ]]
    );
    let got = blocks("M3 S500\nG0 X50 Z2\nG92 X40 Z-30 R5 F2 J0\nM30\n", &m);
    assert_eq!(got[0][0], thread(40_000, -30_000, true, F2, Role::Cut));
    let e = error("M3 S500\nG0 X50 Z2\nG92 X40 Z-30 R6 F2 J0\nM30\n", &m);
    assert_eq!(e.line, 3);
    let ErrorKind::Cycle(CycleError::TaperBeyondStart { taper, infeed }) = e.kind else { panic!("{e}") };
    assert_eq!((taper.increments, infeed.increments), (6_000, -10_000));
    assert!(e.to_string().contains("|R| <= |U/2|"), "{e}");
}

/// An internal thread: A = (20, 2) inside C = (30, -20). J0.5 K1: the cut
/// runs at X30 to Z-19, the run-out to Z-20 and J = 0.5 towards A (inwards,
/// away from the work): X29. Retract to X20.
#[test]
fn internal_thread() {
    let got = blocks("M3 S500\nG0 X20 Z2\nG92 X30 Z-20 F1.5 J0.5 K1\nM30\n", &machine(ProfileName::Gsk980));
    let f15 = Lead { word: LeadWord::F, mantissa: 15, scale: 1 };
    assert_eq!(
        got,
        vec![vec![
            rapid(30_000, 2_000, Role::Approach),
            thread(30_000, -19_000, true, f15, Role::Cut),
            thread(29_000, -20_000, false, f15, Role::RunOut),
            rapid(20_000, -20_000, Role::Retract),
            rapid(20_000, 2_000, Role::Return),
        ]]
    );
}

/// A steep taper, X the long axis: A = (50, 2), C = (40, -3), R-10: B =
/// (20, 2); |W| = 5 <= |R| = 10. F1 J0.5 K2: the run-out starts K = 2
/// (radius) before C along X, X = 40 - 2·2 = 36, on the cut line: Z = 2 +
/// (-3 - 2)·(36 - 20)/(40 - 20) = -2; it ends at X40 with J = 0.5 along Z
/// back towards A: Z-2.5. Retract along X to X50 at Z-2.5, return.
#[test]
fn x_long_axis() {
    let got = blocks("M3 S500\nG0 X50 Z2\nG92 X40 Z-3 R-10 F1 J0.5 K2\nM30\n", &machine(ProfileName::Gsk980));
    let f1 = Lead { word: LeadWord::F, mantissa: 1, scale: 0 };
    assert_eq!(
        got,
        vec![vec![
            rapid(20_000, 2_000, Role::Approach),
            thread(36_000, -2_000, true, f1, Role::Cut),
            thread(40_000, -2_500, false, f1, Role::RunOut),
            rapid(50_000, -2_500, Role::Retract),
            rapid(50_000, 2_000, Role::Return),
        ]]
    );
}

/// Reading R-G92MODAL. Block 2 gives only X: Z-28, R-1, F3, J3 K1 carry on.
/// B of block 2 = (57.7 - 2, 5) = (55.7, 5); the run-out starts at Z-27 on
/// the cut line from (55.7, 5) to (57.7, -28): X = 55.7 + 2·32/33 =
/// 57.63939… → 57.639; it ends at (63.7, -28). After G00 the mode's values
/// are forgotten: block 4 is straight, and with J and K omitted the 980TDi
/// runs out by No.19 (0 by default: none).
#[test]
fn modal_words_and_their_end() {
    let src = "M3 S500\nG0 X65 Z5\nG92 X58.7 Z-28 R-1 F3 J3 K1\nX57.7\nG0 X65\nG92 X57 Z-28\nM30\n";
    let got = blocks(src, &machine(ProfileName::Gsk980));
    assert_eq!(got.len(), 3);
    assert_eq!(
        got[1],
        vec![
            rapid(55_700, 5_000, Role::Approach),
            thread(57_639, -27_000, true, F3, Role::Cut),
            thread(63_700, -28_000, false, F3, Role::RunOut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
    assert_eq!(
        got[2],
        vec![
            rapid(57_000, 5_000, Role::Approach),
            thread(57_000, -28_000, true, F3, Role::Cut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
}

/// J and K omitted: the chamfer of the parameters. 980TDi No.19 = 10
/// (tenths of the lead): K = 10 × 0.1 × 3 = 3, J = K at 45° = 3, so the
/// run-out starts at Z-25 and ends at X58.7 + 6 = X64.7. 988TA 5130 = 10,
/// 5131 = 30°: K = 3, J = round(3 tan 30°) = round(1.7320508) = 1.732,
/// X58.7 + 3.464 = X62.164. FANUC 5130 = 10, 5131 = 0 (45°): as the 980TDi.
#[test]
fn chamfer_by_parameters() {
    let src = "M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3\nM30\n";
    let chamfered = |x_end: i64| {
        vec![vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -25_000, true, F3, Role::Cut),
            thread(x_end, -28_000, false, F3, Role::RunOut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]]
    };
    let mut m = machine(ProfileName::Gsk980);
    m.apply_toml("[parameters]\n19 = 10\n").unwrap();
    assert_eq!(blocks(src, &m), chamfered(64_700));
    let mut m = machine(ProfileName::Gsk988);
    m.apply_toml("[parameters]\n5130 = 10\n5131 = 30\n").unwrap();
    assert_eq!(blocks(src, &m), chamfered(62_164));
    // FANUC: a bare length is in increments (3401#0 = 0): Z-28. with its point.
    let mut m = machine(ProfileName::Fanuc);
    m.apply_toml("[parameters]\n5130 = 10\n").unwrap();
    assert_eq!(blocks("M3 S300\nG0 X65. Z5.\nG92 X58.7 Z-28. F3.0\nM30\n", &m), chamfered(64_700));
}

/// The 988TA's normal-mode rules (THM = 0): K omitted: no long-axis
/// run-out, J along X at the end (a pull-out from C, X58.7 → X64.7 at
/// Z-28); J omitted with K: none; J3 K0: none. The 980TDi's notes: K
/// omitted: K = J; J0 K1: none.
#[test]
fn run_out_rules_per_profile() {
    let one = |src: &str, p: ProfileName| blocks(src, &machine(p)).remove(0);
    let head = "M3 S300\nG0 X65 Z5\n";
    let g988 = one(&format!("{head}G92 X58.7 Z-28 F3 J3\n"), ProfileName::Gsk988);
    assert_eq!(g988[1], thread(58_700, -28_000, true, F3, Role::Cut));
    assert_eq!(g988[2], thread(64_700, -28_000, false, F3, Role::RunOut));
    for words in ["K1", "J3 K0"] {
        let none = one(&format!("{head}G92 X58.7 Z-28 F3 {words}\n"), ProfileName::Gsk988);
        assert_eq!(none[1], thread(58_700, -28_000, true, F3, Role::Cut), "{words}");
        assert_eq!(none[2].role, Role::Retract, "{words}");
    }
    // 980TDi note 4: K omitted, K = J = 3: the run-out starts at Z-25.
    let g980 = one(&format!("{head}G92 X58.7 Z-28 F3 J3\n"), ProfileName::Gsk980);
    assert_eq!(g980[1], thread(58_700, -25_000, true, F3, Role::Cut));
    assert_eq!(g980[2], thread(64_700, -28_000, false, F3, Role::RunOut));
    // Note 10: negative J and K are taken as positive; the 988TA refuses them.
    let negative = one(&format!("{head}G92 X58.7 Z-28 F3 J-3 K-1\n"), ProfileName::Gsk980);
    assert_eq!(negative, o0012_pass(58_700));
    let e = error(&format!("{head}G92 X58.7 Z-28 F3 J-3 K1\n"), &machine(ProfileName::Gsk988));
    assert_eq!((e.line, e.word.as_deref()), (3, Some("J-3")));
    // Note 7: J = 0, K ≠ 0: none.
    let none = one(&format!("{head}G92 X58.7 Z-28 F3 J0 K1\n"), ProfileName::Gsk980);
    assert_eq!(none[1], thread(58_700, -28_000, true, F3, Role::Cut));
}

/// A face thread, 988TA P1 (reading R-G92FACE: "P = 1（端面螺纹）长轴 纵轴，短轴
/// 横轴"): A = (X60, Z5), C = (X20, Z1), so W = -4 is the infeed along Z
/// and the cut runs along X (t = -1, towards the centre); s = +1 (A is on
/// the +Z side of C). R0: B = (X60, Z1). J1 K2: the run-out starts K = 2
/// (radius) before C along X, X = 20 + 2·2 = 24, on the cut line (Z1), and
/// ends at C's X with J = 1 along Z towards A: (X20, Z2). The retract runs
/// along Z to Z5 (X20), the return along X to A. With R-1, B = (X60, Z0)
/// and the run-out starts on the line from B to C at X24: Z = 0 + (1 - 0)·
/// (24 - 60)/(20 - 60) = 0.9.
#[test]
fn gsk988_face_thread() {
    let m = machine(ProfileName::Gsk988);
    let f2 = Lead { word: LeadWord::F, mantissa: 2, scale: 0 };
    let got = blocks("M3 S300\nG0 X60 Z5\nG92 X20 Z1 F2 J1 K2 P1\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(60_000, 1_000, Role::Approach),
            thread(24_000, 1_000, true, f2, Role::Cut),
            thread(20_000, 2_000, false, f2, Role::RunOut),
            rapid(20_000, 5_000, Role::Retract),
            rapid(60_000, 5_000, Role::Return),
        ]]
    );
    // P is modal: the next block (Z only) is a face thread too, R-1 modal
    // from its own word.
    let got = blocks("M3 S300\nG0 X60 Z5\nG92 X20 Z1 F2 J1 K2 P1\nZ0.5\nR-1 Z1\nM30\n", &m);
    assert_eq!(got.len(), 3);
    assert_eq!(got[1][0], rapid(60_000, 500, Role::Approach));
    assert_eq!(got[2][0], rapid(60_000, 0, Role::Approach));
    assert_eq!(got[2][1], thread(24_000, 900, true, f2, Role::Cut));
}

/// The 988TA's high-speed mode (5129 = 1), step (3) "X 轴以快速移动速度退刀
/// … 返回到 X 轴绝对坐标与起点相同处": J and K: as the normal mode; K omitted
/// ("长轴无退尾，短轴方向的退尾长度，固定为切削终点到起点的短轴轴向距离，与 J 是多少
/// 无关"): no run-out, the cut to C (X58.7 Z-28) and the rapid to X65; J
/// omitted ("长轴方向按 K 退尾"): the cut to Z-27 and the run-out to the X of
/// A, X65 Z-28, so the retract is empty and left out.
#[test]
fn gsk988_high_speed_mode() {
    let mut m = machine(ProfileName::Gsk988);
    m.apply_toml("[parameters]\n5129 = 1\n").unwrap();
    let head = "M3 S300\nG0 X65 Z5\n";
    let one = |words: &str| blocks(&format!("{head}G92 X58.7 Z-28 F3 {words}\n"), &m).remove(0);
    assert_eq!(one("J3 K1"), o0012_pass(58_700));
    assert_eq!(
        one("J3"),
        vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -28_000, true, F3, Role::Cut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
    assert_eq!(
        one("K1"),
        vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -27_000, true, F3, Role::Cut),
            thread(65_000, -28_000, false, F3, Role::RunOut),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
}

/// The 988TA's normal mode (THM = 5129 = 0, the default), step (3): "普通
/// G92：X 轴和 Z 轴同时进行切削，到 D 点" (reading R-G92RUNOUT, "The 988TA's
/// normal-mode step (3)"): the run-out is the move of X and Z together and
/// its end is the normal mode's D; X then returns to A's X at rapid (the
/// 980TDi's ③) before step (4)'s Z return, never a thread move all the way
/// to A's X.
///
/// A = (X40, Z3), C = (X30, Z-20), R-1 F2 J1 K1.5, IS-B, diameter X.
/// External (X_A = 40 > X_C = 30). B = (30 + 2·(-1), 3) = (28, 3). Z long
/// (|W| = 23 > |R| = 1). J and K both given and non-zero: both run-outs
/// (normal-mode rules). The cut ends K = 1.5 before C: Z = -20 + 1.5 =
/// -18.5, on the line from B to C: X = 28 + (30 - 28)·(3 - (-18.5))/(3 -
/// (-20)) = 28 + 43/23 = 29.8695652… → 29.870. The run-out (X and Z
/// together, the thread's lead) ends at D = (30 + 2·1, -20) = (32, -20).
/// Step ③: rapid to X40 at Z-20; step (4): rapid to Z3.
///
/// Note 5 ("当螺纹短轴方向退尾长度大于无退尾时的退刀距离时，系统默认短轴方向退尾长度
/// 为无退尾时的退刀距离"): with J6 the retract without run-out is (40 - 30)/2 =
/// 5 (radius) < 6, so J' = 5: the run-out ends at (30 + 2·5, -20) = (40,
/// -20), A's X, and the retract, which would not move, is left out (R-ZERO).
#[test]
fn gsk988_normal_mode_step_3() {
    let m = machine(ProfileName::Gsk988);
    let got = blocks("M3 S500\nG0 X40 Z3\nG92 X30 Z-20 R-1 F2 J1 K1.5\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(28_000, 3_000, Role::Approach),
            thread(29_870, -18_500, true, F2, Role::Cut),
            thread(32_000, -20_000, false, F2, Role::RunOut),
            rapid(40_000, -20_000, Role::Retract),
            rapid(40_000, 3_000, Role::Return),
        ]]
    );
    let got = blocks("M3 S500\nG0 X40 Z3\nG92 X30 Z-20 R-1 F2 J6 K1.5\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(28_000, 3_000, Role::Approach),
            thread(29_870, -18_500, true, F2, Role::Cut),
            thread(40_000, -20_000, false, F2, Role::RunOut),
            rapid(40_000, 3_000, Role::Return),
        ]]
    );
}

/// L2 on the 980TDi: the pass is cut twice from A, the second start at
/// 180°. 988TA L3 Q30: starts at 30°, 150° and 270°.
#[test]
fn multi_start_and_start_angle() {
    let got = blocks("M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1 L2\nM30\n", &machine(ProfileName::Gsk980));
    assert_eq!(got[0].len(), 10);
    let angles: Vec<(u16, u32, u32)> = got[0]
        .iter()
        .filter_map(|m| match m.motion {
            Motion::Thread { start_angle, sync: true, .. } => {
                Some((m.pass.unwrap().start, start_angle.num, start_angle.den))
            }
            _ => None,
        })
        .collect();
    assert_eq!(angles, [(1, 0, 1), (2, 180_000, 1)]);
    assert_eq!(
        got[0][5..],
        o0012_pass(58_700)[..]
            .iter()
            .map(|m| Move {
                pass: pass(2),
                motion: match m.motion {
                    Motion::Thread { lead, sync, .. } =>
                        Motion::Thread { lead, sync, start_angle: StartAngle::from_millidegrees(180_000) },
                    other => other,
                },
                ..*m
            })
            .collect::<Vec<_>>()[..]
    );
    let got =
        blocks("M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1 L3 Q30\nM30\n", &machine(ProfileName::Gsk988));
    let angles: Vec<u64> = got[0]
        .iter()
        .filter_map(|m| match m.motion {
            Motion::Thread { start_angle, sync: true, .. } => Some(start_angle.rounded_millidegrees()),
            _ => None,
        })
        .collect();
    assert_eq!(angles, [30_000, 150_000, 270_000]);
}

/// The alarms, each on its line and word: no infeed (U = 0), a face
/// thread (W = 0), a run-out longer than the thread (988TA note 4), L
/// beyond 99 on the 980TDi, P outside 0..1, a P1 face thread without X
/// travel or steeper along Z than along X, G92 without an end point, words
/// the profile does not have.
#[test]
fn alarms() {
    let m980 = machine(ProfileName::Gsk980);
    let m988 = machine(ProfileName::Gsk988);
    let head = "M3 S300\nG0 X65 Z5\n";
    let e = error(&format!("{head}G92 X65 Z-28 F3\n"), &m980);
    assert_eq!((e.line, e.kind), (3, ErrorKind::Cycle(CycleError::NoInfeed)));
    let e = error(&format!("{head}G92 X58 W0 F3\n"), &m980);
    assert_eq!((e.line, e.kind), (3, ErrorKind::Cycle(CycleError::FaceThread)));
    let e = error(&format!("{head}G92 X58 Z4 F3 J1 K2\n"), &m980);
    let ErrorKind::Cycle(CycleError::RunOutTooLong { run_out, length }) = e.kind else { panic!("{e}") };
    assert_eq!((run_out.increments, length.increments), (2_000, 1_000));
    let e = error(&format!("{head}G92 X58 Z-28 F3 L100\n"), &m980);
    assert_eq!((e.line, e.word.as_deref()), (3, Some("L100")));
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    let e = error(&format!("{head}G92 X58 Z-28 F3 P2\n"), &m988);
    assert_eq!((e.line, e.word.as_deref()), (3, Some("P2")));
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    // A face thread (P1) whose cut end has the X of A has no length.
    let e = error(&format!("{head}G92 X65 Z1 F3 P1\n"), &m988);
    assert_eq!((e.line, e.kind), (3, ErrorKind::Cycle(CycleError::NoThreadLength)));
    // X65 → X61: 2 mm of X travel as a radius; R-2 is as much (45°, X still
    // the long axis by R-G32LONG's tie), R-2.001 more: refused under
    // R-LONG988 `displacement` (under the default `table` it is made with
    // X long, spec/tests/readings.rs).
    let mut m988d = machine(ProfileName::Gsk988);
    m988d.readings.apply_pair("R-LONG988=displacement").unwrap();
    assert!(blocks(&format!("{head}G92 X61 Z1 R-2 F3 P1\n"), &m988d).len() == 1);
    let e = error(&format!("{head}G92 X61 Z1 R-2.001 F3 P1\n"), &m988d);
    let ErrorKind::Cycle(CycleError::SteepFaceThread { taper, travel }) = e.kind else { panic!("{e}") };
    assert_eq!((taper.increments, travel.increments), (-2_001, -4_000));
    let e = error(&format!("{head}G92 F3\n"), &m980);
    assert!(matches!(e.kind, ErrorKind::Missing { .. }), "{e}");
    let e = error(&format!("{head}G92 X58 Z-28 F3 Q30\n"), &m980);
    assert!(matches!(e.kind, ErrorKind::AddressNotInProfile { .. }), "{e}");
    let e = error(&format!("{head}G92 X58 Z-28 F3 J1\n"), &machine(ProfileName::Fanuc));
    assert_eq!(e.word.as_deref(), Some("J1"));
    assert!(matches!(e.kind, ErrorKind::AddressNotInProfile { .. }), "{e}");
}

/// The model's checks, direct: the run-out words share G76's rules.
#[test]
fn validate_shares_the_run_out_checks() {
    let c = cycleref::G92Cycle {
        units: cycleref::Units::IS_B_METRIC,
        x_mode: cycleref::XMode::Diameter,
        start: Point::new(65_000, 5_000),
        end: Point::new(58_700, -28_000),
        taper: 0,
        lead: F3,
        run_out: RunOut::Chamfer { tenths_of_lead: 100, angle_degrees: 45, long: None },
        starts: 1,
        start_angle: StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    assert!(matches!(c.validate(), Err(CycleError::CountOutOfRange { value: 100, .. })));
    let c = cycleref::G92Cycle { starts: 0, run_out: RunOut::None, ..c };
    assert!(matches!(c.validate(), Err(CycleError::CountOutOfRange { value: 0, .. })));
}

/// Reading R-XRUNOUT. A = (60, 2), C = (40, -3), R+8: B = (56, 2); |W| = 5
/// <= |R| = 8, X long. The cut line rises towards A (s = +1, R > 0): at
/// Z = -3 + 0.5 it lies at X = 40 + 2·8·0.5/5 = 41.6, above C's X40, so a
/// run-out J0.5 along Z towards A would end 0.8 (radius) inside the work:
/// refused. With J0 (no run-out) the block expands: B, C, X60, A.
#[test]
fn x_long_run_out_into_the_work_is_refused() {
    let m = machine(ProfileName::Gsk980);
    let e = error("M3 S500\nG0 X60 Z2\nG92 X40 Z-3 R8 F1 J0.5 K2\nM30\n", &m);
    assert_eq!(e.line, 3);
    let ErrorKind::Cycle(CycleError::RunOutIntoWork { taper }) = e.kind else { panic!("{e}") };
    assert_eq!(taper.increments, 8_000);
    let f1 = Lead { word: LeadWord::F, mantissa: 1, scale: 0 };
    let got = blocks("M3 S500\nG0 X60 Z2\nG92 X40 Z-3 R8 F1 J0\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(56_000, 2_000, Role::Approach),
            thread(40_000, -3_000, true, f1, Role::Cut),
            rapid(60_000, -3_000, Role::Retract),
            rapid(60_000, 2_000, Role::Return),
        ]]
    );
}

/// Figure 3-90 (980TDi), the cases other than 2 (`external_taper_with_run_out`),
/// on the gsk980 profile, IS-B, diameter X. B = (X_C + 2R, Z_A); Z long in
/// each (|W| > |R|); the run-out starts K before C along Z on the line B–C
/// and ends at the Z of C, J (radius) towards A's side; then X to A's X and
/// Z to A.
///
/// 1) U > 0, W < 0, R > 0 (internal, towards -Z): A = (20, 2), C = (30,
///    -20), R1: B = (32, 2). J0.5 K1: Z = -20 + 1 = -19, X = 32 + (30 - 32)·
///    (2 + 19)/(2 + 20) = 32 - 42/22 = 30.0909… → 30.091; the run-out ends
///    at (30 - 2·0.5, -20) = (29, -20) (inwards, towards A).
/// 3) U > 0, W > 0, R < 0, |R| <= |U/2| (internal, towards +Z): A = (20,
///    -30), C = (30, -5), R-2 (2 <= 5): B = (26, -30). J0.5 K1.5: Z = -5 -
///    1.5 = -6.5, X = 26 + 4·(-6.5 + 30)/25 = 26 + 3.76 = 29.76; the
///    run-out ends at (29, -5).
/// 4) U < 0, W > 0, R > 0, |R| <= |U/2| (external, towards +Z): A = (50,
///    -30), C = (40, -5), R3 (3 <= 5): B = (46, -30). J1 K2: Z = -5 - 2 =
///    -7, X = 46 - 6·(-7 + 30)/25 = 46 - 5.52 = 40.48; the run-out ends at
///    (40 + 2·1, -5) = (42, -5).
#[test]
fn figure_3_90_cases_1_3_4() {
    let m = machine(ProfileName::Gsk980);
    let f1 = Lead { word: LeadWord::F, mantissa: 1, scale: 0 };
    let case = |a: (i64, i64), words: &str| {
        let src = format!("M3 S500\nG0 X{} Z{}\nG92 {words}\nM30\n", a.0, a.1);
        blocks(&src, &m).remove(0)
    };
    assert_eq!(
        case((20, 2), "X30 Z-20 R1 F1 J0.5 K1"),
        vec![
            rapid(32_000, 2_000, Role::Approach),
            thread(30_091, -19_000, true, f1, Role::Cut),
            thread(29_000, -20_000, false, f1, Role::RunOut),
            rapid(20_000, -20_000, Role::Retract),
            rapid(20_000, 2_000, Role::Return),
        ]
    );
    assert_eq!(
        case((20, -30), "X30 Z-5 R-2 F1 J0.5 K1.5"),
        vec![
            rapid(26_000, -30_000, Role::Approach),
            thread(29_760, -6_500, true, f1, Role::Cut),
            thread(29_000, -5_000, false, f1, Role::RunOut),
            rapid(20_000, -5_000, Role::Retract),
            rapid(20_000, -30_000, Role::Return),
        ]
    );
    assert_eq!(
        case((50, -30), "X40 Z-5 R3 F1 J1 K2"),
        vec![
            rapid(46_000, -30_000, Role::Approach),
            thread(40_480, -7_000, true, f1, Role::Cut),
            thread(42_000, -5_000, false, f1, Role::RunOut),
            rapid(50_000, -5_000, Role::Retract),
            rapid(50_000, -30_000, Role::Return),
        ]
    );
}

/// 980TDi note 3 ("省略J时，长轴方向按K退尾，短轴方向按№.19号参数设定值退尾") and
/// note 6 ("J≠0，K=0 时，按K=J退尾"), on O0012's first block (A = X65 Z5,
/// C = X58.7 Z-28, F3).
///
/// * Note 3, K1, No.19 = 10: the short axis by No.19, J = 10 × 0.1 × 3 ×
///   tan 45° = 3; the long axis K = 1: the cut to Z-27, the run-out to
///   X58.7 + 6 = X64.7 at Z-28 (O0012's pass). No.19 = 5: J = 1.5, X61.7.
///   No.19 = 0 (the default): no short-axis run-out, so none at all: the
///   cut runs to C.
/// * Note 6, J2 K0: K = J = 2: the cut to Z-26, the run-out to X58.7 + 4 =
///   X62.7 at Z-28.
#[test]
fn gsk980_notes_3_and_6() {
    let src = |words: &str| format!("M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3 {words}\nM30\n");
    let with19 = |v: u32| {
        let mut m = machine(ProfileName::Gsk980);
        m.apply_toml(&format!("[parameters]\n19 = {v}\n")).unwrap();
        m
    };
    assert_eq!(blocks(&src("K1"), &with19(10)).remove(0), o0012_pass(58_700));
    let got = blocks(&src("K1"), &with19(5)).remove(0);
    assert_eq!(got[1], thread(58_700, -27_000, true, F3, Role::Cut));
    assert_eq!(got[2], thread(61_700, -28_000, false, F3, Role::RunOut));
    assert_eq!(
        blocks(&src("K1"), &machine(ProfileName::Gsk980)).remove(0),
        vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -28_000, true, F3, Role::Cut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
    let got = blocks(&src("J2 K0"), &machine(ProfileName::Gsk980)).remove(0);
    assert_eq!(
        got,
        vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -26_000, true, F3, Role::Cut),
            thread(62_700, -28_000, false, F3, Role::RunOut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
}

/// Threads per inch (I, "螺纹每英寸牙数", modal like F) on G92 and G78, where
/// the lead matters: the chamfer of the parameters, K = r × 0.1 × lead.
///
/// * G92, 980TDi, I8 (lead 25.4/8 = 3.175 mm), No.19 = 10: K = 3.175, J =
///   3.175 (45°). A = X70 Z5, C = X58.7 Z-28: the cut to Z-28 + 3.175 =
///   Z-24.825, the run-out to X58.7 + 6.35 = X65.05 at Z-28 (short of X70,
///   no clamp), the retract to X70, the return. Every thread move carries
///   I8.
/// * G78, 988TA, the example's thread with I8 and J, K omitted (5130 = 10,
///   5131 = 0: 45°): K = J = 3.175; the passes of `gsk988_example_and_g76`
///   (X62.4 Z9.254, X61.0 Z8.964, two finishing X60 Z8.964): each cut ends
///   at Z-60 + 3.175 = Z-56.825 and its run-out at X + 6.35 (68.75, 67.35,
///   66.35, 66.35) at Z-60.
#[test]
fn threads_per_inch() {
    let i8 = Lead { word: LeadWord::I, mantissa: 8, scale: 0 };
    let mut m = machine(ProfileName::Gsk980);
    m.apply_toml("[parameters]\n19 = 10\n").unwrap();
    let got = blocks("M3 S300\nG0 X70 Z5\nG92 X58.7 Z-28 I8\nM30\n", &m);
    assert_eq!(
        got,
        vec![vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -24_825, true, i8, Role::Cut),
            thread(65_050, -28_000, false, i8, Role::RunOut),
            rapid(70_000, -28_000, Role::Retract),
            rapid(70_000, 5_000, Role::Return),
        ]]
    );

    let mut m = machine(ProfileName::Gsk988);
    m.apply_toml("[parameters]\n5130 = 10\n").unwrap();
    let src = "M3 S300\nG00 X80 Z10\nG78 P020245 Q0.15 R0.5\nG78 X60 Z-60 P3 Q1.8 I8\nM30\n";
    let p = read(src, &m).unwrap_or_else(|e| panic!("{e}"));
    let c = p.items.iter().find_map(Cycle::of).expect("the G78");
    let ours: Vec<Move> = expand(c, Engine::Impl).unwrap().collect();
    let reference: Vec<Move> = expand(c, Engine::Spec).unwrap().collect();
    assert_eq!(ours, reference);
    let ends: Vec<(Motion, i64, i64)> = ours.iter().map(|m| (m.motion, m.to.x, m.to.z)).collect();
    let thread_to = |sync| Motion::Thread { lead: i8, start_angle: StartAngle::ZERO, sync };
    let mut want = Vec::new();
    for (x, z) in [(62_400, 9_254), (61_000, 8_964), (60_000, 8_964), (60_000, 8_964)] {
        want.extend([
            (Motion::Rapid, x, z),
            (thread_to(true), x, -56_825),
            (thread_to(false), x + 6_350, -60_000),
            (Motion::Rapid, 80_000, -60_000),
            (Motion::Rapid, 80_000, 10_000),
        ]);
    }
    assert_eq!(ends, want);
}

/// The 988TA's taper condition in radius mode ("短轴为半径编程时：│R│≤│短轴
/// 起点和终点差值│"), X words radii: A = X25 Z2, C = X20 Z-30, U = -5
/// (radius), J0 (no run-out). R4: B = X20 + 4 = X24, between A and C. R5:
/// B = X25 = A, the approach left out (R-ZERO). R5.001 > |U| = 5: B beyond
/// A, refused (`TaperBeyondStart`, R and U in radius increments).
#[test]
fn gsk988_taper_condition_in_radius_mode() {
    let mut m = machine(ProfileName::Gsk988);
    m.apply_toml("x = \"radius\"\n").unwrap();
    let src = |r: &str| format!("M3 S500\nG0 X25 Z2\nG92 X20 Z-30 R{r} F2 J0\nM30\n");
    assert_eq!(
        blocks(&src("4"), &m),
        vec![vec![
            rapid(24_000, 2_000, Role::Approach),
            thread(20_000, -30_000, true, F2, Role::Cut),
            rapid(25_000, -30_000, Role::Retract),
            rapid(25_000, 2_000, Role::Return),
        ]]
    );
    assert_eq!(blocks(&src("5"), &m)[0][0], thread(20_000, -30_000, true, F2, Role::Cut));
    let e = error(&src("5.001"), &m);
    assert_eq!(e.line, 3);
    let ErrorKind::Cycle(CycleError::TaperBeyondStart { taper, infeed }) = e.kind else { panic!("{e}") };
    assert_eq!((taper.increments, infeed.increments), (5_001, -5_000));
}

/// The 988TA's L ("多头螺纹的头数（1～999）"): L999 is accepted, 999 passes of
/// five moves (O0012's first block, J3 K1), the last start at 998 × 360°/999
/// = 998 × 360 000/999 thousandths = 998 × 40 000/111 (÷ 9) = 39 920 000/111
/// = 359 639.639… thousandths (359.6396…°), kept exact as that fraction;
/// L1000 is refused on its word.
#[test]
fn gsk988_starts_999_and_1000() {
    let m = machine(ProfileName::Gsk988);
    let head = "M3 S300\nG0 X65 Z5\n";
    let got = blocks(&format!("{head}G92 X58.7 Z-28 F3 J3 K1 L999\nM30\n"), &m).remove(0);
    assert_eq!(got.len(), 999 * 5);
    let last = got[998 * 5 + 1];
    assert_eq!((last.pass.unwrap().start, last.to.x, last.to.z), (999, 58_700, -27_000));
    let Motion::Thread { start_angle, sync: true, .. } = last.motion else { panic!("{last:?}") };
    assert_eq!((start_angle.num, start_angle.den), (39_920_000, 111));
    let e = error(&format!("{head}G92 X58.7 Z-28 F3 J3 K1 L1000\nM30\n"), &m);
    assert_eq!((e.line, e.word.as_deref()), (3, Some("L1000")));
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
}

/// 988TA note 4 ("当螺纹长轴方向退尾长度大于长轴的螺纹加工长度时，系统产生报警") on
/// the gsk988 machine: A = X65 Z5, C = X58 Z4 (|W| = 1), J1 K2: K = 2 > 1,
/// `RunOutTooLong` (2, 1); K1 (= |W|) is accepted, the cut is empty and
/// left out (R-ZERO): the run-out runs from B straight to (X58 + 2, Z4).
#[test]
fn gsk988_note_4() {
    let m = machine(ProfileName::Gsk988);
    let e = error("M3 S300\nG0 X65 Z5\nG92 X58 Z4 F3 J1 K2\nM30\n", &m);
    assert_eq!(e.line, 3);
    let ErrorKind::Cycle(CycleError::RunOutTooLong { run_out, length }) = e.kind else { panic!("{e}") };
    assert_eq!((run_out.increments, length.increments), (2_000, 1_000));
    let got = blocks("M3 S300\nG0 X65 Z5\nG92 X58 Z4 F3 J1 K1\nM30\n", &m).remove(0);
    assert_eq!(
        got,
        vec![
            rapid(58_000, 5_000, Role::Approach),
            thread(60_000, 4_000, true, F3, Role::RunOut),
            rapid(65_000, 4_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]
    );
}

/// FANUC's G92 chamfers by 5130 at the angle of 5131 (the profile reads
/// it): 5130 = 10, 5131 = 30: K = 10 × 0.1 × 3 = 3, J = round(3 tan 30°) =
/// round(1.7320508) = 1.732: the cut to Z-25, the run-out to X58.7 + 3.464
/// = X62.164 at Z-28. 5131 = 60: J = round(3 tan 60°) = round(5.1961524)
/// = 5.196, X58.7 + 10.392 = X69.092, beyond A's X65: clamped there
/// (R-RUNOUT, note 5 adopted for all profiles), so the retract is empty.
#[test]
fn fanuc_chamfer_angle() {
    let src = "M3 S300\nG0 X65. Z5.\nG92 X58.7 Z-28. F3.0\nM30\n";
    let mut m = machine(ProfileName::Fanuc);
    m.apply_toml("[parameters]\n5130 = 10\n5131 = 30\n").unwrap();
    assert_eq!(
        blocks(src, &m),
        vec![vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -25_000, true, F3, Role::Cut),
            thread(62_164, -28_000, false, F3, Role::RunOut),
            rapid(65_000, -28_000, Role::Retract),
            rapid(65_000, 5_000, Role::Return),
        ]]
    );
    m.apply_toml("[parameters]\n5131 = 60\n").unwrap();
    assert_eq!(
        blocks(src, &m),
        vec![vec![
            rapid(58_700, 5_000, Role::Approach),
            thread(58_700, -25_000, true, F3, Role::Cut),
            thread(65_000, -28_000, false, F3, Role::RunOut),
            rapid(65_000, 5_000, Role::Return),
        ]]
    );
}
