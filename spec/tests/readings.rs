//! Readings per control (issue 34): each selectable reading's non-default
//! value on a program whose moves are worked by hand from the manual's
//! words (the arithmetic in the comments), the default unchanged, both
//! engines equal under every value, and the errors naming the valid ids
//! and values. IS-B metric, X as a diameter; J, K and E are radius values.

use cycleref::{CycleError, Move, Point, Role};
use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::profile::{Machine, ParamsError};
use cycleref_spec::readings::{Listing, Readings, TABLE};
use cycleref_spec::{read, ErrorKind, ProfileName};

/// Every cycle's moves, by both engines (which must agree), or the first
/// error (reader or cycle), which both engines must also agree on.
fn run(src: &str, m: &Machine) -> Result<Vec<Move>, ErrorKind> {
    let p = read(src, m).map_err(|e| e.kind)?;
    let mut all = Vec::new();
    for c in p.items.iter().filter_map(Cycle::of) {
        let ours: Result<Vec<Move>, CycleError> = expand(c, Engine::Impl).map(Iterator::collect);
        let reference: Result<Vec<Move>, CycleError> = expand(c, Engine::Spec).map(Iterator::collect);
        assert_eq!(ours, reference, "line {}", c.line());
        all.extend(ours.map_err(ErrorKind::Cycle)?);
    }
    Ok(all)
}

fn machine(profile: ProfileName, readings: &[&str]) -> Machine {
    let mut m = Machine::new(profile);
    for r in readings {
        m.readings.apply_pair(r).unwrap_or_else(|e| panic!("{e}"));
    }
    m
}

fn ends(moves: &[Move]) -> Vec<(Role, Point)> {
    moves.iter().map(|m| (m.role, m.to)).collect()
}

/// The 980TDi's G92 with a run-out J longer than the retract.
/// A = (X40, Z5), C = (X30, Z-20), R = 0: Z long (|W| = 25 > 0). K = 2:
/// the cut ends at Z-20 + 2 = Z-18 on X30. J = 8 (radius) is 16 on the
/// diameter; the retract without run-out is X40 - X30 = 10.
const G92_LONG_J: &str = "M3 S300\nG00 X40 Z5\nG92 X30 Z-20 F2 J8 K2\nM30\n";

/// R-RUNOUT `all-profiles` (default): 988TA G92 note 5 clamps J to the
/// retract, 16 → 10: the run-out ends at X40, Z-20, so the retract to X40
/// does not move (R-ZERO) and Z returns to Z5.
#[test]
fn run_out_clamped_by_default() {
    let got = run(G92_LONG_J, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(30_000, 5_000)),
            (Role::Cut, Point::new(30_000, -18_000)),
            (Role::RunOut, Point::new(40_000, -20_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    );
}

/// R-RUNOUT `gsk988-only` on the 980TDi: J as written, X30 + 2·8 = X46 at
/// Z-20; then step ③, "X 轴以快速移动速度退刀 … 返回到 X 轴绝对坐标与起点相同处":
/// back to X40 at Z-20; step ④ Z to Z5.
#[test]
fn run_out_as_written_on_gsk980_under_gsk988_only() {
    let got = run(G92_LONG_J, &machine(ProfileName::Gsk980, &["R-RUNOUT=gsk988-only"])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(30_000, 5_000)),
            (Role::Cut, Point::new(30_000, -18_000)),
            (Role::RunOut, Point::new(46_000, -20_000)),
            (Role::Retract, Point::new(40_000, -20_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    );
}

/// On the 988TA, whose page has note 5, `gsk988-only` changes nothing.
#[test]
fn run_out_still_clamped_on_gsk988_under_gsk988_only() {
    let default = run(G92_LONG_J, &machine(ProfileName::Gsk988, &[])).unwrap();
    let chosen = run(G92_LONG_J, &machine(ProfileName::Gsk988, &["R-RUNOUT=gsk988-only"])).unwrap();
    assert_eq!(default, chosen);
    assert_eq!(default[2].to, Point::new(40_000, -20_000));
}

/// The same on a G76 of the 980TDi (J, K in block 1, P/Q in increments):
/// k = 1 mm, Δd = 1 mm, d = 0, m = 1, a = 0: one rough pass at depth
/// k - d = 1 and one finishing pass at k, both ending at X_D + 2·(k - Dn)
/// = X30, no flank shift (a = 0); A = (X40, Z5), D = (X30, Z-20). Each
/// pass: to B (X30, Z5), cut to Z-18 (K2), run-out 2·J = 16 to X46 at
/// Z-20 (unclamped), retract to X40, return to Z5.
#[test]
fn g76_run_out_as_written_under_gsk988_only() {
    let src = "M3 S300\nG00 X40 Z5\nG76 P010000 Q100 R0 J8 K2\nG76 X30 Z-20 P1000 Q1000 F2\nM30\n";
    let pass = [
        (Role::Approach, Point::new(30_000, 5_000)),
        (Role::Cut, Point::new(30_000, -18_000)),
        (Role::RunOut, Point::new(46_000, -20_000)),
        (Role::Retract, Point::new(40_000, -20_000)),
        (Role::Return, Point::new(40_000, 5_000)),
    ];
    let got = run(src, &machine(ProfileName::Gsk980, &["R-RUNOUT=gsk988-only"])).unwrap();
    assert_eq!(ends(&got), [pass, pass].concat());
    // Default: clamped to X40, the retract left out.
    let got = run(src, &machine(ProfileName::Gsk980, &[])).unwrap();
    let clamped = [pass[0], pass[1], (Role::RunOut, Point::new(40_000, -20_000)), pass[4]];
    assert_eq!(ends(&got), [clamped, clamped].concat());
}

/// An unclamped run-out beyond the range tables is refused (R-RANGE):
/// X999 + 2·J with J = 999 999.999 mm.
#[test]
fn unclamped_run_out_beyond_the_range_is_refused() {
    let src = "M3 S300\nG00 X1000 Z5\nG92 X999 Z-20 F2 J999999.999 K2\nM30\n";
    let e = run(src, &machine(ProfileName::Gsk980, &["R-RUNOUT=gsk988-only"])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::OutOfRange { .. })), "{e:?}");
    assert!(run(src, &machine(ProfileName::Gsk980, &[])).is_ok());
}

/// An X-long G92 whose cut line rises towards A (s·R > 0).
/// A = (X60, Z0), C = (X20, Z-5), R = +10: external (X_A > X_C, s = +1),
/// B = X20 + 2·10 = X40 at Z0; U = -40 and R > 0 differ in sign and
/// |R| = 10 <= |U/2| = 20. |W| = 5 < |R| = 10: X is the long axis, Z the
/// short one. K = 1 along X (radius): the cut ends 2 (diameter) before
/// C's X, at X22, on the line B→C: Z = 0 + (-5)·(22 - 40)/(20 - 40) =
/// -4.5. J = 2 along Z towards A ("根据程序起点位置自动确定退尾方向"): from
/// C's Z-5 to Z-3, at C's X20. Then X back to X60 at Z-3 (③), Z to Z0 (④).
const G92_X_LONG: &str = "M3 S300\nG00 X60 Z0\nG92 X20 Z-5 R10 F2 J2 K1\nM30\n";

/// R-XRUNOUT `refuse` (default): the run-out ends at X20, Z-3, where the
/// cut line lies at X20 + 2·10·2/5 = X28: inside the material.
#[test]
fn x_long_run_out_into_the_work_refused_by_default() {
    let e = run(G92_X_LONG, &machine(ProfileName::Gsk980, &[])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::RunOutIntoWork { .. })), "{e:?}");
}

/// R-XRUNOUT `towards-start`: the moves worked out above.
#[test]
fn x_long_run_out_towards_start() {
    let got = run(G92_X_LONG, &machine(ProfileName::Gsk980, &["R-XRUNOUT=towards-start"])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(40_000, 0)),
            (Role::Cut, Point::new(22_000, -4_500)),
            (Role::RunOut, Point::new(20_000, -3_000)),
            (Role::Retract, Point::new(60_000, -3_000)),
            (Role::Return, Point::new(60_000, 0)),
        ]
    );
}

/// The 980TDi's G78 with E: "E：X 向旋进距离值，取值范围为-9999.9999~9999.9999
/// （单位：mm，半径值、无符号)".
fn g78_with_e(e: &str) -> String {
    format!("M3 S300\nG00 X80 Z10\nG78 P010245 Q150 R0.5 J1.5 K2 D2 E{e}\nG78 X60 Z-60 P3000 Q1800 F3\nM30\n")
}

/// R-E980 `refuse-negative` (default): "无符号" wins, E-1 is out of range
/// (0..), on the E word.
#[test]
fn negative_e_refused_by_default() {
    let e = read(&g78_with_e("-1"), &machine(ProfileName::Gsk980, &[])).unwrap_err();
    assert_eq!(e.word.as_deref(), Some("E-1"));
    assert!(matches!(e.kind, ErrorKind::OutOfRange { ref range } if range.starts_with("0..")), "{e}");
}

/// R-E980 `signed`: the range wins and E, having no direction ("无符号"),
/// is its magnitude (as 980TDi G92 note 10 for J and K: "J、K输入负值时，按
/// 正值处理"): E-1 cuts exactly the passes of E1 (R-LEADIN: each pass
/// screws in from 1 mm (radius) outside Bn, whole leads back in Z).
#[test]
fn negative_e_is_its_magnitude_under_signed() {
    let m = machine(ProfileName::Gsk980, &["R-E980=signed"]);
    let negative = run(&g78_with_e("-1"), &m).unwrap();
    let positive = run(&g78_with_e("1"), &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(negative, positive);
    assert!(negative.iter().any(|m| m.role == Role::LeadIn));
    // The first pass's lead-in start: X of B1 + 2·1, whole leads (F3) back
    // in Z: E = 1 <= 1 lead, so Z10 + 3 = Z13.
    let approach = negative[0].to;
    let lead_in_end = negative[1].to;
    assert_eq!(approach.x - lead_in_end.x, 2_000);
    assert_eq!(approach.z - lead_in_end.z, 3_000);
}

/// R-E980 concerns the 980TDi only: the 988TA's E stays unsigned.
#[test]
fn negative_e_still_refused_on_gsk988() {
    let src = "M3 S300\nG00 X80 Z10\nG76 P020560 Q0.15 R0.1 E-1\nG76 X60 Z-30 P2 Q0.5 F2\nM30\n";
    assert!(read(src, &machine(ProfileName::Gsk988, &["R-E980=signed"])).is_err());
}

/// The errors name the valid ids and values.
#[test]
fn unknown_reading_or_value_names_the_valid_ones() {
    let mut r = Readings::default();
    let e = r.apply_pair("R-NOPE=x").unwrap_err();
    assert_eq!(e.stable_kind(), "params:unknown_reading");
    assert_eq!(
        e.to_string(),
        "unknown reading `R-NOPE` (the selectable readings are R-RUNOUT, R-XRUNOUT, R-E980, R-HIGHSPEED, R-LCNC-READER, R-G92Q, R-G75ALLOW, R-G75P)"
    );
    let e = r.apply_pair("R-RUNOUT=sometimes").unwrap_err();
    assert_eq!(e.stable_kind(), "params:bad_reading");
    assert_eq!(
        e.to_string(),
        "reading R-RUNOUT has no value `sometimes` (its values are all-profiles, gsk988-only)"
    );
    let e = r.apply_pair("R-RUNOUT").unwrap_err();
    assert!(matches!(e, ParamsError::ReadingSyntax { .. }));
    assert_eq!(r, Readings::default());
}

/// `[readings]` in the parameter file, and the list of the C field.
#[test]
fn readings_from_the_parameter_file_and_a_list() {
    let mut m = Machine::new(ProfileName::Gsk980);
    m.apply_toml("[readings]\n\"R-RUNOUT\" = \"gsk988-only\"\n\"R-XRUNOUT\" = \"towards-start\"\n").unwrap();
    assert_eq!(
        m.readings.non_default(ProfileName::Gsk980),
        [("R-RUNOUT", "gsk988-only"), ("R-XRUNOUT", "towards-start")]
    );
    let e = m.apply_toml("[readings]\n\"R-E980\" = \"maybe\"\n").unwrap_err();
    assert_eq!(e.stable_kind(), "params:bad_reading");
    let e = m.apply_toml("readings = 3\n").unwrap_err();
    assert_eq!(e.stable_kind(), "params:bad_setting");
    let mut r = Readings::default();
    r.apply_list(" R-E980=signed , R-XRUNOUT=towards-start").unwrap();
    assert_eq!(r.non_default(ProfileName::Gsk980), [("R-XRUNOUT", "towards-start"), ("R-E980", "signed")]);
    assert!(Readings::default().non_default(ProfileName::Gsk988).is_empty());
}

/// `cycleref readings`: one line per reading, the default marked.
#[test]
fn listing() {
    let all = Listing { profile: None }.to_string();
    assert_eq!(all.lines().count(), TABLE.len());
    assert!(all.lines().next().unwrap().starts_with("R-RUNOUT\tall-profiles* | gsk988-only\t"));
    let gsk988 = Listing { profile: Some(ProfileName::Gsk988) }.to_string();
    assert!(!gsk988.contains("R-RUNOUT") && !gsk988.contains("R-E980") && gsk988.contains("R-XRUNOUT"));
    assert!(gsk988.contains("R-HIGHSPEED\tg92-rules* | refuse\t[gsk988]\t"), "{gsk988}");
}

/// The 988TA with parameter 5129 (THM) = 1, the high-speed threading mode,
/// and `readings` chosen.
fn high_speed(readings: &[&str]) -> Machine {
    let mut m = machine(ProfileName::Gsk988, readings);
    m.apply_toml("[parameters]\n5129 = 1\n").unwrap();
    m
}

/// A G76 (or G78) of the 988TA: A = (X80, Z10), D = (X60.64, Z-62), k =
/// 3.68, Δd = 1.8, Δdmin = 0.15, d = 0.1, a = 60° (P020060: m = 2, r = 0,
/// a = 60), F6, and the run-out words `jk`. Pass 1 (depth Δd = 1.8): X =
/// X_D + 2·(k - 1.8) = 60.64 + 3.76 = X64.4, on G76 at Z = 10 - round(1.8 ·
/// tan 30°) = 10 - round(1.03923) = Z8.961 (R-INFEED, right flank).
fn g76_high_speed(code: &str, jk: &str) -> String {
    format!("M3 S300\nG00 X80 Z10\n{code} P020060 Q0.15 R0.1\n{code} X60.64 Z-62 P3.68 Q1.8 F6 {jk}\nM30\n")
}

/// R-HIGHSPEED `g92-rules` (default): G92's high-speed rules (R-G92RUNOUT)
/// for G76's J and K (note 9: "存在 J、K 时退尾格式及相关注意事项同 G92").
/// K2 with J omitted: "省略 J 时，长轴方向按 K 退尾": the cut ends at Z-62 + 2
/// = Z-60; the short axis runs all the way to A's X (J' clamped at the
/// retract, (80 - 64.4)/2 = 7.8), so the run-out ends at (X80, Z-62), the
/// retract there is empty (R-ZERO) and Z returns to Z10. Under 5129 = 0
/// the same block has no run-out at all (normal mode: "省略 J 时，无退尾"):
/// the cut runs to Z-62, X rapids to X80, Z returns.
#[test]
fn g76_high_speed_k_only_under_g92_rules() {
    let src = g76_high_speed("G76", "K2");
    let got = run(&src, &high_speed(&[])).unwrap();
    assert_eq!(
        ends(&got[..4]),
        [
            (Role::Approach, Point::new(64_400, 8_961)),
            (Role::Cut, Point::new(64_400, -60_000)),
            (Role::RunOut, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
    // Pass 2 (depth round(1.8·√2) = round(2.5456) = 2.546): X = 60.64 +
    // 2·(3.68 - 2.546) = X62.908, Z = 10 - round(2.546·tan 30°) = 10 -
    // round(1.46993) = Z8.53; the same run-out to (X80, Z-62).
    assert_eq!(
        ends(&got[4..8]),
        [
            (Role::Approach, Point::new(62_908, 8_530)),
            (Role::Cut, Point::new(62_908, -60_000)),
            (Role::RunOut, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
    let normal = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        ends(&normal[..4]),
        [
            (Role::Approach, Point::new(64_400, 8_961)),
            (Role::Cut, Point::new(64_400, -62_000)),
            (Role::Retract, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
}

/// `g92-rules` with J1.5 and K omitted: "省略 K 时，长轴无退尾，短轴方向的退尾
/// 长度，固定为切削终点到起点的短轴轴向距离，与 J 是多少无关": the cut runs to
/// Z-62 and the rapid retract of step (3) takes X to A's X80 (J is
/// ignored). Under 5129 = 0 the normal mode's "省略 K 时，长轴无退尾，短轴方向
/// 按 J 值退尾" pulls out 2·1.5 = 3 along X by thread motion: X64.4 + 3 =
/// X67.4 at Z-62, then the rapid to X80.
#[test]
fn g76_high_speed_j_only_under_g92_rules() {
    let src = g76_high_speed("G76", "J1.5");
    let got = run(&src, &high_speed(&[])).unwrap();
    assert_eq!(
        ends(&got[..4]),
        [
            (Role::Approach, Point::new(64_400, 8_961)),
            (Role::Cut, Point::new(64_400, -62_000)),
            (Role::Retract, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
    let normal = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        ends(&normal[..5]),
        [
            (Role::Approach, Point::new(64_400, 8_961)),
            (Role::Cut, Point::new(64_400, -62_000)),
            (Role::RunOut, Point::new(67_400, -62_000)),
            (Role::Retract, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
}

/// G78 takes the same rules (5129 on the 988TA G78 page: "螺纹切削循环
/// G92，G76，G78 的模式"). G78's P(r) = 00 is the centre-line infeed: every
/// pass at the form centre, Z = 10 - round((k - d)·tan 30°) = 10 -
/// round(3.58·0.57735) = 10 - round(2.06691) = Z7.933; pass 1 at X64.4,
/// K2 as in the G76 case above.
#[test]
fn g78_high_speed_k_only_under_g92_rules() {
    let src = g76_high_speed("G78", "K2");
    let got = run(&src, &high_speed(&[])).unwrap();
    assert_eq!(
        ends(&got[..4]),
        [
            (Role::Approach, Point::new(64_400, 7_933)),
            (Role::Cut, Point::new(64_400, -60_000)),
            (Role::RunOut, Point::new(80_000, -62_000)),
            (Role::Return, Point::new(80_000, 10_000)),
        ]
    );
}

/// R-HIGHSPEED `refuse`: a G76 or G78 under 5129 = 1 is refused at its
/// block 2, naming the parameter and the reading.
#[test]
fn high_speed_refused_under_refuse() {
    for code in ["G76", "G78"] {
        let e = read(&g76_high_speed(code, "K2"), &high_speed(&["R-HIGHSPEED=refuse"])).unwrap_err();
        assert_eq!(e.line, 4);
        assert!(matches!(e.kind, ErrorKind::Parameter(_)), "{e}");
        assert!(e.to_string().contains("5129 = 1") && e.to_string().contains(code), "{e}");
    }
}

/// R-LCNC-READER `comment` (default on linuxcnc): `;` starts a comment to
/// the end of the line, as LinuxCNC's interpreter reads it (`rs274 -g` on
/// `G0 X20 Z2 ; approach` makes `STRAIGHT_TRAVERSE(20.0000, 0.0000,
/// 2.0000, …)` and nothing for the comment; cli/tests/linuxcnc.rs compares
/// a whole program with rs274). The block keeps its comment in its text,
/// as a `( )` comment. `end-of-block`: the text after `;` is read as the
/// next block, and `approach` is an address `A` without a number.
#[test]
fn semicolon_on_linuxcnc() {
    let src = "G18 G21 G7\nG0 X20 Z2 ; approach (no closing paren\n; a line of comment\nG0 X30;\nM2\n";
    let p = read(src, &machine(ProfileName::LinuxCnc, &[])).unwrap();
    let texts: Vec<String> = p.items.iter().map(|i| i.block().text_lossy().into_owned()).collect();
    assert!(texts.contains(&"G0 X20 Z2 ; approach (no closing paren".to_string()), "{texts:?}");
    let e = read(src, &machine(ProfileName::LinuxCnc, &["R-LCNC-READER=end-of-block"])).unwrap_err();
    assert_eq!(e.line, 2);
    assert!(matches!(e.kind, ErrorKind::Syntax(_)), "{e}");
    // The GSK profiles keep `;` as a block end ("；" or ";" between
    // blocks), whatever the reading: two moves on one line.
    let gsk = "M3 S300\nG00 X80;G00 Z10\nM30\n";
    let p = read(gsk, &machine(ProfileName::Gsk988, &["R-LCNC-READER=comment"])).unwrap();
    assert_eq!(p.items.iter().filter(|i| matches!(i, cycleref_spec::Item::Move(_))).count(), 2);
}

/// The 988TA G92 page's example with a start angle on its first block:
/// A = (X65, Z5), `G92 X58.7 Z-28 F3 J3 K1 Q90`, then the repeats `X57.7`
/// (no Q), `X57 Q45`, and after a G00 (another motion code ends the G92
/// mode, R-G92MODAL) `G92 X56.9 Z-28` (no Q). Each block is one pass; the
/// start angle of each pass's cut, in millidegrees, by reading R-G92Q.
const G92_Q: &str =
    "M3 S300\nG00 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1 Q90\nX57.7\nX57 Q45\nG00 X65 Z5\nG92 X56.9 Z-28\nM30\n";

fn cut_angles(moves: &[Move]) -> Vec<(i64, u64)> {
    moves
        .iter()
        .filter(|m| m.role == Role::Cut)
        .map(|m| match m.motion {
            cycleref::Motion::Thread { start_angle, .. } => (m.to.x, start_angle.rounded_millidegrees()),
            _ => panic!("a cut that is not a thread move: {m:?}"),
        })
        .collect()
}

/// R-G92Q `one-shot` (default): G32's rule, "非模态，省略时为 0°": the second
/// pass (X57.7) starts at 0°, a helix 90° (a quarter of the 3 mm lead,
/// 0.75 mm in Z) away from the first pass's, i.e. another groove; the
/// third at its own Q45.
#[test]
fn g92_q_one_shot_by_default() {
    let got = run(G92_Q, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(cut_angles(&got), [(58_700, 90_000), (57_700, 0), (57_000, 45_000), (56_900, 0)]);
}

/// R-G92Q `modal`: Q stays in force like the page's other words: X57.7
/// cuts at 90° (the first pass's groove), X57 at its own 45°, and the G92
/// after the G00 starts again at 0° (the modal values are cleared by
/// another motion code). Only the start angles differ from `one-shot`.
#[test]
fn g92_q_modal() {
    let got = run(G92_Q, &machine(ProfileName::Gsk988, &["R-G92Q=modal"])).unwrap();
    assert_eq!(cut_angles(&got), [(58_700, 90_000), (57_700, 90_000), (57_000, 45_000), (56_900, 0)]);
    let default = run(G92_Q, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(ends(&got), ends(&default));
}

/// The 980TDi's G75.1 (IS-C), with `readings`.
fn gsk980_is_c(readings: &[&str]) -> Machine {
    let mut m = machine(ProfileName::Gsk980, readings);
    m.apply_toml("increment = \"is-c\"\n").unwrap();
    m
}

/// A G75.1 groove (the sweep's example): S = (X50, Z30), Δi 3, Δk 5, depth
/// H-20, width D-10, flanks A45 B30, retract R0.5, and block 2's `extra`.
fn g75_allowance(extra: &str) -> String {
    format!("M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\nG75.1 R0.5 {extra}\nM30\n")
}

/// R-G75ALLOW `refuse-negative` (default): U "（…直径，无符号）" wins; U-0.2
/// is out of range (0..), on the U word. `magnitude`: the range
/// "-9999.9999~9999.9999(IS_C)" wins and U, having no direction, is its
/// magnitude, as the same page's I ("输入负值时当成正值处理"): U-0.2 cuts what
/// U0.2 cuts. The bottom is at S's X50 + H-20 = X30; with U0.2 (diameter)
/// the roughing's deepest point is X30 + 0.2 = X30.2 (IS-C: 302 000
/// increments), with U0 X30. W likewise.
#[test]
fn g75_negative_allowance() {
    let e = read(&g75_allowance("U-0.2"), &gsk980_is_c(&[])).unwrap_err();
    assert_eq!(e.word.as_deref(), Some("U-0.2"));
    let m = gsk980_is_c(&["R-G75ALLOW=magnitude"]);
    let negative = run(&g75_allowance("U-0.2 W-0.3"), &m).unwrap();
    let positive = run(&g75_allowance("U0.2 W0.3"), &gsk980_is_c(&[])).unwrap();
    assert_eq!(negative, positive);
    let deepest = |moves: &[Move]| moves.iter().map(|m| m.to.x).min().unwrap();
    assert_eq!(deepest(&run(&g75_allowance("U-0.2"), &m).unwrap()), 302_000);
    assert_eq!(deepest(&run(&g75_allowance(""), &gsk980_is_c(&[])).unwrap()), 300_000);
    assert!(read(&g75_allowance("W-0.3"), &gsk980_is_c(&[])).is_err());
}

/// A G75.1 with a 4 mm tool (I4), roughing and finishing (J1), D and E
/// (the inner bottom's corners) of 0.5, A and B (the outer ones) of no
/// size, and P written with two digits (`p`).
fn g75_p(p: &str) -> String {
    format!(
        "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10\nG75.1 R0.5 I4 J1 D0.5 E0.5 {p}\nM30\n"
    )
}

fn arcs(moves: &[Move]) -> usize {
    moves.iter().filter(|m| matches!(m.motion, cycleref::Motion::Arc { .. })).count()
}

/// R-G75P `right-aligned` (default): P11 = P0011, d = e = 1: the inner
/// bottom's corners D and E are rounds (R0.5), two arcs in the finishing
/// contour. `left-aligned`: "P 的第一位" is the first digit written, P11 =
/// P1100: a = b = 1 (A and B have no size, so they stay sharp) and d = e =
/// 0, chamfers at D and E: the moves of P1100, no arc.
#[test]
fn g75_p_digits() {
    let right = run(&g75_p("P11"), &gsk980_is_c(&[])).unwrap();
    assert_eq!(arcs(&right), 2);
    assert_eq!(right, run(&g75_p("P0011"), &gsk980_is_c(&[])).unwrap());
    let left = run(&g75_p("P11"), &gsk980_is_c(&["R-G75P=left-aligned"])).unwrap();
    assert_eq!(arcs(&left), 0);
    assert_eq!(left, run(&g75_p("P1100"), &gsk980_is_c(&[])).unwrap());
    // Four digits mean the same under both.
    assert_eq!(run(&g75_p("P0011"), &gsk980_is_c(&["R-G75P=left-aligned"])).unwrap(), right);
}
