//! Readings per control (issue 34): each selectable reading's non-default
//! value on a program whose moves are worked by hand from the manual's
//! words (the arithmetic in the comments), the default unchanged, both
//! engines equal under every value, and the errors naming the valid ids
//! and values. IS-B metric, X as a diameter; J, K and E are radius values.

use cycleref::readings::PassEnd;
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
/// screws in from 1 mm (radius) outside Bn, at its Z).
#[test]
fn negative_e_is_its_magnitude_under_signed() {
    let m = machine(ProfileName::Gsk980, &["R-E980=signed"]);
    let negative = run(&g78_with_e("-1"), &m).unwrap();
    let positive = run(&g78_with_e("1"), &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(negative, positive);
    assert!(negative.iter().any(|m| m.role == Role::LeadIn));
    // The first pass's lead-in start: X of B1 + 2·1 at B1's Z (R-LEADIN
    // `same-z`); under `whole-leads`, E = 1 <= 1 lead (F3): Z + 3.
    let approach = negative[0].to;
    let lead_in_end = negative[1].to;
    assert_eq!(approach.x - lead_in_end.x, 2_000);
    assert_eq!(approach.z, lead_in_end.z);
    let whole =
        run(&g78_with_e("-1"), &machine(ProfileName::Gsk980, &["R-E980=signed", "R-LEADIN=whole-leads"]))
            .unwrap();
    assert_eq!(whole[0].to.z - whole[1].to.z, 3_000);
}

/// R-E980 concerns the 980TDi only: the 988TA's E stays unsigned.
#[test]
fn negative_e_still_refused_on_gsk988() {
    let src = "M3 S300\nG00 X80 Z10\nG76 P020560 Q0.15 R0.1 E-1\nG76 X60 Z-30 P2 Q0.5 F2\nM30\n";
    assert!(read(src, &machine(ProfileName::Gsk988, &["R-E980=signed"])).is_err());
}

/// The pass starts Bn of a cycle: where each approach (or lead-in) ends.
fn starts(moves: &[Move]) -> Vec<Point> {
    let mut out = Vec::new();
    for (i, m) in moves.iter().enumerate() {
        if m.role == Role::Approach && moves.get(i + 1).is_none_or(|n| n.role != Role::LeadIn) {
            out.push(m.to);
        }
        if m.role == Role::LeadIn {
            out.push(m.to);
        }
    }
    out
}

/// A small G78 on the 988TA, `G78 P01r60 Q0.1 R0.2` / `G78 X30 Z-20 P1 Q0.5
/// F2` from A = (X40, Z5): m = 1 finishing pass, a = 60°, Δdmin = 0.1,
/// d = 0.2, k = 1, Δd = 0.5 (mm, radius). External (X40 > X30), t = -1
/// (Z5 → Z-20), B = (X32, Z5).
///
/// Levels (R-DEPTH, increments of 0.001 mm): round(500·√1) = 500;
/// round(500·√2) = round(707.107) = 707; round(500·√3) = round(866.025) =
/// 866 ≥ k - d = 800, so 800. Bn's X = X30 + 2·(k - Dn): X31, X30.586,
/// X30.4, and X30 for the finishing pass at k.
/// Right shifts round(Dn·tan 30°), tan 30° = 0.577350: 500 → 288.675 →
/// 289; 707 → 408.186 → 408; 800 → 461.880 → 462 = zc. Bn's Z = Z5 - shift.
fn small_g78(r: u32) -> String {
    format!("M3 S300\nG00 X40 Z5\nG78 P01{r:02}60 Q0.1 R0.2\nG78 X30 Z-20 P1 Q0.5 F2\nM30\n")
}

/// R-G78LEFT on G78 r = 1 (左边切入). `mirror-form-centre` (default): the
/// left shift is 2·zc - right = 924 - 289 = 635, 924 - 408 = 516, 924 -
/// 462 = 462; the finishing pass at the last rough pass's Z, 462.
/// `mirror-b`: -289, -408, -462 (beyond the Z of A, on the far side of B),
/// the finishing pass at -462: |Z shift| / depth = tan 30° on every rough
/// pass, up to the rounding.
#[test]
fn g78_left_flank_mirrored_about_b() {
    let src = small_g78(1);
    let default = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        starts(&default),
        [
            Point::new(31_000, 4_365),
            Point::new(30_586, 4_484),
            Point::new(30_400, 4_538),
            Point::new(30_000, 4_538),
        ]
    );
    let b = run(&src, &machine(ProfileName::Gsk988, &["R-G78LEFT=mirror-b"])).unwrap();
    assert_eq!(
        starts(&b),
        [
            Point::new(31_000, 5_289),
            Point::new(30_586, 5_408),
            Point::new(30_400, 5_462),
            Point::new(30_000, 5_462),
        ]
    );
}

/// R-G78LEFT on G78 r = 4 (左右等量轮流): right then left at the first two
/// levels, the last level once on the right (zc), the finishing pass
/// there. Right shifts 289, 408, 462 under either value; the left ones
/// 635, 516 by default, -289, -408 under `mirror-b`. The same mode is
/// G76's D2 (seed 000), which the reading moves alike.
#[test]
fn g78_alternate_flanks_mirrored_about_b() {
    let src = small_g78(4);
    let z = |shifts: [i64; 6]| shifts.map(|s| 5_000 - s);
    let x = [31_000, 31_000, 30_586, 30_586, 30_400, 30_000];
    let points = |zs: [i64; 6]| x.iter().zip(zs).map(|(&x, z)| Point::new(x, z)).collect::<Vec<_>>();
    let default = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(starts(&default), points(z([289, 635, 408, 516, 462, 462])));
    let b = run(&src, &machine(ProfileName::Gsk988, &["R-G78LEFT=mirror-b"])).unwrap();
    assert_eq!(starts(&b), points(z([289, -289, 408, -408, 462, 462])));
    // G76 D2 on the 988TA: the same passes (G76's P(r) is the chamfer: 00).
    let g76 = "M3 S300\nG00 X40 Z5\nG76 P010060 Q0.1 R0.2 D2\nG76 X30 Z-20 P1 Q0.5 F2\nM30\n";
    let g76 = run(g76, &machine(ProfileName::Gsk988, &["R-G78LEFT=mirror-b"])).unwrap();
    assert_eq!(starts(&g76), points(z([289, -289, 408, -408, 462, 462])));
}

/// R-INFEED `left-first` on G78 r = 4 and G76 D2 (左右等量轮流, "左右" read in
/// the order it names the sides): each level left then right, the last
/// level once on the left (the flank its level starts on), the finishing
/// pass at the last rough pass's Z. Right shifts 289, 408, 462 as above;
/// left ones 2·462 - right = 635, 516, 462 (`mirror-form-centre`): the
/// passes 635, 289, 516, 408, 462, finishing 462. Under `mirror-b` the
/// left ones are -289, -408, -462: passes -289, 289, -408, 408, -462 and
/// the finishing pass at -462, the mirror image about B of the
/// `right-first` passes under `mirror-b` (289, -289, 408, -408, 462, 462)
/// but for the finishing pass, which follows the last rough pass.
#[test]
fn alternate_flanks_left_first() {
    let src = small_g78(4);
    let z = |shifts: [i64; 6]| shifts.map(|s| 5_000 - s);
    let x = [31_000, 31_000, 30_586, 30_586, 30_400, 30_000];
    let points = |zs: [i64; 6]| x.iter().zip(zs).map(|(&x, z)| Point::new(x, z)).collect::<Vec<_>>();
    let left_first = run(&src, &machine(ProfileName::Gsk988, &["R-INFEED=left-first"])).unwrap();
    assert_eq!(starts(&left_first), points(z([635, 289, 516, 408, 462, 462])));
    let both = machine(ProfileName::Gsk988, &["R-INFEED=left-first", "R-G78LEFT=mirror-b"]);
    let b = run(&src, &both).unwrap();
    assert_eq!(starts(&b), points(z([-289, 289, -408, 408, -462, -462])));
    let g76 = "M3 S300\nG00 X40 Z5\nG76 P010060 Q0.1 R0.2 D2\nG76 X30 Z-20 P1 Q0.5 F2\nM30\n";
    assert_eq!(starts(&run(g76, &both).unwrap()), points(z([-289, 289, -408, 408, -462, -462])));
}

/// R-INFEED `left-first` on the 980TDi's G78 r = 3 (交错切入, "P(r)=3：左右两边
/// 轮流切入"): one pass a level, odd levels on the left, even on the right.
/// The 980TDi's P(m) is the depth mode (01 递减式), its Q Δd: `G78 P010360 Q100
/// R0.1` / `G78 X60 Z-30 P1000 Q500 F2` from (X80, Z10): k = 1, Δd = 0.5,
/// Δdmin = 0.1, d = 0.1, a = 60°. Levels round(500·√n): 500, 707, 866, then
/// 900 = k - d (round(500·√4) = 1000 ≥ 900). Right shifts round(Dn·tan
/// 30°): 288.675 → 289, 408.186 → 408, 499.985 → 500, 519.615 → 520 = zc;
/// lefts 2·520 - right: 751, 632, 540, 520.
/// `right-first`: R289, L632, R500, L520 (Z9.711, Z9.368, Z9.5, Z9.48);
/// `left-first`: L751, R408, L540, R520 (Z9.249, Z9.592, Z9.46, Z9.48);
/// the finishing pass at 520. X = X60 + 2·(1 - Dn): X61, X60.586,
/// X60.268, X60.2, X60.
#[test]
fn g78_interleaved_left_first() {
    let src = "M3 S300\nG00 X80 Z10\nG78 P010360 Q100 R0.1\nG78 X60 Z-30 P1000 Q500 F2\nM30\n";
    let x = [61_000, 60_586, 60_268, 60_200, 60_000];
    let pts = |zs: [i64; 5]| x.iter().zip(zs).map(|(&x, s)| Point::new(x, 10_000 - s)).collect::<Vec<_>>();
    let default = run(src, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(starts(&default), pts([289, 632, 500, 520, 520]));
    let left_first = run(src, &machine(ProfileName::Gsk980, &["R-INFEED=left-first"])).unwrap();
    assert_eq!(starts(&left_first), pts([751, 408, 540, 520, 520]));
}

/// R-G78CENTRE on G78 r = 0 (中线切入): `form-centre` (default) cuts every
/// pass at zc = 462 (Z4.538); `under-b` radially under B, at Z5, the
/// finishing pass too (the last rough pass's Z). r = 3 (右中轮流) keeps its
/// centre passes at zc: the reading concerns r = 0.
#[test]
fn g78_centre_under_b() {
    let src = small_g78(0);
    let x = [31_000, 30_586, 30_400, 30_000];
    let default = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(starts(&default), x.map(|x| Point::new(x, 4_538)));
    let b = run(&src, &machine(ProfileName::Gsk988, &["R-G78CENTRE=under-b"])).unwrap();
    assert_eq!(starts(&b), x.map(|x| Point::new(x, 5_000)));
    // The first approach is along X only.
    assert_eq!(b[0].to, Point::new(31_000, 5_000));
    // r = 3: right 289, centre 462, right 462 (level 3), finishing 462.
    let src = small_g78(3);
    let right_centre = run(&src, &machine(ProfileName::Gsk988, &["R-G78CENTRE=under-b"])).unwrap();
    assert_eq!(right_centre, run(&src, &machine(ProfileName::Gsk988, &[])).unwrap());
    assert_eq!(
        starts(&right_centre),
        [
            Point::new(31_000, 4_711),
            Point::new(30_586, 4_538),
            Point::new(30_400, 4_538),
            Point::new(30_000, 4_538),
        ]
    );
}

/// R-LEADIN on the 988TA's G76 with E: `G76 P010000 Q0.1 R0 E0.5` /
/// `G76 X30 Z-20 P1 Q1 F2` from A = (X40, Z5): a = 0 (no shift), k = 1,
/// Δd = 1, d = 0: one rough pass at depth 1 and one finishing pass at k,
/// both from Bn = (X30, Z5); r = 0: no run-out. E = 0.5 (radius): the
/// lead-in starts at X30 + 2·0.5 = X31.
/// `same-z` (default): An = (X31, Z5), "与切削起点 Bn 距离为 E 的位置", and the
/// screw-in to Bn is a thread move along X only. `whole-leads`: N =
/// ceil(0.5 / 2) = 1 lead, Lz = 2: An = (X31, Z5 + 2) = (X31, Z7).
#[test]
fn lead_in_at_the_z_of_bn() {
    let src = "M3 S300\nG00 X40 Z5\nG76 P010000 Q0.1 R0 E0.5\nG76 X30 Z-20 P1 Q1 F2\nM30\n";
    let pass = |an: Point| {
        [
            (Role::Approach, an),
            (Role::LeadIn, Point::new(30_000, 5_000)),
            (Role::Cut, Point::new(30_000, -20_000)),
            (Role::Retract, Point::new(40_000, -20_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    };
    let whole = run(src, &machine(ProfileName::Gsk988, &["R-LEADIN=whole-leads"])).unwrap();
    let back = pass(Point::new(31_000, 7_000));
    assert_eq!(ends(&whole), [back, back].concat());
    let same = run(src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(same, run(src, &machine(ProfileName::Gsk988, &["R-LEADIN=same-z"])).unwrap());
    let at_bn = pass(Point::new(31_000, 5_000));
    assert_eq!(ends(&same), [at_bn, at_bn].concat());
    assert!(matches!(same[1].motion, cycleref::Motion::Thread { sync: true, .. }));
}

/// A left pass beyond the Z of A under `mirror-b` is range-checked
/// (R-RANGE): A at Z999999.8, the deepest left pass at Z999999.8 + 0.462
/// = Z1000000.262, beyond Z999999.999; by default the left passes lie
/// towards D (Z999999.8 - 0.635 …) and the cycle is made.
#[test]
fn left_pass_beyond_the_range_is_refused() {
    let src = "M3 S300\nG00 X40 Z999999.8\nG78 P010160 Q0.1 R0.2\nG78 X30 Z999970 P1 Q0.5 F2\nM30\n";
    assert!(run(src, &machine(ProfileName::Gsk988, &[])).is_ok());
    let e = run(src, &machine(ProfileName::Gsk988, &["R-G78LEFT=mirror-b"])).unwrap_err();
    let ErrorKind::Cycle(CycleError::OutOfRange { value, .. }) = e else { panic!("{e:?}") };
    assert_eq!(value.increments, 1_000_000_262);
}

/// The errors name the valid ids and values.
#[test]
fn unknown_reading_or_value_names_the_valid_ones() {
    let mut r = Readings::default();
    let e = r.apply_pair("R-NOPE=x").unwrap_err();
    assert_eq!(e.stable_kind(), "params:unknown_reading");
    assert_eq!(
        e.to_string(),
        "unknown reading `R-NOPE` (the selectable readings are R-RUNOUT, R-XRUNOUT, R-E980, R-END, R-LONG988, \
         R-HIGHSPEED, R-G78LEFT, R-G78CENTRE, R-LEADIN, R-INFEED, R-LCNC-READER, R-G92Q, R-G75ALLOW, R-G75P, R-NOROUGH, R-DEPTH, R-STARTS, R-G92HS-NOK, R-G92HS-NOJ, R-G92JK988, R-G32RUNOUT, R-CHAMFERANGLE, R-MODAL, R-G32LONG, \
         R-SIDE, R-G75RIDGE, R-G75PECK, R-SPINDLE, R-G75LAYER, R-G75ARC, R-G75CHAMFER, R-G75SLOPE, R-LCNC-G7)"
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

/// R-END on a small taper, 980TDi G76 (P, Q in increments): A = (X40, Z5),
/// D = (X30, Z-15), i = -1 (radius): C = X30 + 2·(-1) = X28 < X40, external
/// (s = +1); W = -20 (t = -1), |W| = 20 > |i| = 1: Z long. k = 1, Δd = 0.6,
/// Δdmin = 0.1, d = 0, m = 1, a = 60 (tan 30° = 0.5773503), r = 0 and no
/// J, K: no run-out (980TDi note 4 via P(r) = 0).
///
/// Levels (R-DEPTH): round(0.6·√1) = 0.600; round(0.6·√2 = 0.8485) =
/// 0.849 ≥ 0.600 + 0.1; 0.6·√3 = 1.039 ≥ k - d = 1: 1.000. Shifts
/// round(Dn·tan 30°): 0.346 (0.3464), 0.490 (0.4902), 0.577 (0.5774);
/// the finishing pass at k = 1 from the last rough Z (shift 0.577).
/// Bn = (X28 + 2·(1 - Dn), Z5 - shift): (28.800, 4.654), (28.302, 4.510),
/// (28.000, 4.423), finishing (28.000, 4.423).
const END_TAPER: &str = "M3 S300\nG00 X40 Z5\nG76 P010060 Q100 R0\nG76 X30 Z-15 R-1 P1000 Q600 F2\nM30\n";

/// The four passes of [`END_TAPER`] given each pass's cut end (X, Z):
/// approach to Bn, cut, retract to X40 at the end's Z, return to A.
fn end_taper_passes(cut_ends: [(i64, i64); 4]) -> Vec<(Role, Point)> {
    let bn = [(28_800, 4_654), (28_302, 4_510), (28_000, 4_423), (28_000, 4_423)];
    bn.iter()
        .zip(cut_ends)
        .flat_map(|(&(bx, bz), (ex, ez))| {
            [
                (Role::Approach, Point::new(bx, bz)),
                (Role::Cut, Point::new(ex, ez)),
                (Role::Retract, Point::new(40_000, ez)),
                (Role::Return, Point::new(40_000, 5_000)),
            ]
        })
        .collect()
}

/// R-END `parallel` (default on every profile): the line through Bn
/// parallel to C→D (X +2, Z -20) meets D–E (Z-15) at X = X30 +
/// 2·(1 - Dn) + 2·i·shift/|W| = X30 + 2·(1 - Dn) - shift/10: 30.8 -
/// 0.0346 = 30.7654, rounded 30.765; 30.302 - 0.049 = 30.253; 30.0 -
/// 0.0577 = 29.9423, rounded 29.942 (twice).
#[test]
fn pass_end_parallel_by_default() {
    let want = end_taper_passes([(30_765, -15_000), (30_253, -15_000), (29_942, -15_000), (29_942, -15_000)]);
    assert_eq!(ends(&run(END_TAPER, &machine(ProfileName::Gsk980, &[])).unwrap()), want);
    assert_eq!(ends(&run(END_TAPER, &machine(ProfileName::Gsk980, &["R-END=parallel"])).unwrap()), want);
    assert_eq!(Readings::default().for_cycle(ProfileName::Gsk988, false).pass_end, PassEnd::Parallel);
    assert_eq!(Readings::default().for_cycle(ProfileName::Fanuc, false).pass_end, PassEnd::Parallel);
}

/// R-END `travel-i` (the reading before issue 34): X travels exactly i =
/// 2·(-1) → +2 on the diameter from Bn to Z-15: 28.8 + 2 = 30.8, 30.302,
/// 30.0, 30.0.
#[test]
fn pass_end_travel_i() {
    let got = run(END_TAPER, &machine(ProfileName::Gsk980, &["R-END=travel-i"])).unwrap();
    let want = end_taper_passes([(30_800, -15_000), (30_302, -15_000), (30_000, -15_000), (30_000, -15_000)]);
    assert_eq!(ends(&got), want);
}

/// R-END `translated`: Bn + C→D, X travel i (+2), Z travel W (-20):
/// (30.8, 4.654 - 20 = -15.346), (30.302, -15.490), (30.0, -15.577) twice:
/// each pass ends its shift beyond D.
#[test]
fn pass_end_translated() {
    let got = run(END_TAPER, &machine(ProfileName::Gsk980, &["R-END=translated"])).unwrap();
    let want = end_taper_passes([(30_800, -15_346), (30_302, -15_490), (30_000, -15_577), (30_000, -15_577)]);
    assert_eq!(ends(&got), want);
    // On a straight thread (R0) too: the first pass, Bn (X30.8, Z4.654),
    // ends at Z4.654 - 20 = Z-15.346 on X30.8; `parallel` ends at Z-15.
    let straight = END_TAPER.replace("R-1 ", "");
    let got = run(&straight, &machine(ProfileName::Gsk980, &["R-END=translated"])).unwrap();
    assert_eq!(got[1].to, Point::new(30_800, -15_346));
    let got = run(&straight, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(got[1].to, Point::new(30_800, -15_000));
}

/// R-END `parallel` with a run-out, Z long: [`END_TAPER`] with J0.5 K1
/// (980TDi block 1). Pass 1: the cut stops K = 1 before Z-15, at Z-14, on
/// the exact parallel line: X = 28.8 + 2·(-14 - 4.654)/(-20) = 28.8 +
/// 1.8654 = 30.6654 → 30.665 (not on the line from Bn to the rounded end);
/// the run-out J = 0.5, 1.0 on the diameter, from the pass's end X30.765:
/// X31.765 at Z-15.
#[test]
fn pass_end_parallel_with_run_out() {
    let src = END_TAPER.replace("R0\n", "R0 J0.5 K1.0\n");
    let got = run(&src, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(
        ends(&got[..5]),
        [
            (Role::Approach, Point::new(28_800, 4_654)),
            (Role::Cut, Point::new(30_665, -14_000)),
            (Role::RunOut, Point::new(31_765, -15_000)),
            (Role::Retract, Point::new(40_000, -15_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    );
}

/// R-END `parallel` on a steep taper, X long: A = (X40, Z2), D = (X20,
/// Z-2), i = -6: C = X20 - 12 = X8, external; |i| = 6 ≥ |W| = 4. k = Δd =
/// 1, d = 0: one rough pass at depth 1 and one finishing pass, both at Bn
/// = (X8 + 2·0, Z2 - 0.577) = (X8, Z1.423). The end on D–E: X20 + 2·(-6)·
/// 0.577/4 = 20 - 1.731 = X18.269. K = 0.5 along X: the cut stops 1.0 (on
/// the diameter) before it, at X17.269, on the parallel line (X +12, Z -4):
/// Z = 1.423 - 4·(17.269 - 8)/12 = 1.423 - 3.08967 = -1.66667 → -1.667. J
/// = 0.5 along Z towards A: from Z-2 to Z-1.5 at X18.269.
const END_X_LONG: &str =
    "M3 S300\nG00 X40 Z2\nG76 P010060 Q100 R0 J0.5 K0.5\nG76 X20 Z-2 R-6 P1000 Q1000 F2\nM30\n";

#[test]
fn pass_end_parallel_x_long() {
    let got = run(END_X_LONG, &machine(ProfileName::Gsk980, &[])).unwrap();
    let pass = [
        (Role::Approach, Point::new(8_000, 1_423)),
        (Role::Cut, Point::new(17_269, -1_667)),
        (Role::RunOut, Point::new(18_269, -1_500)),
        (Role::Retract, Point::new(40_000, -1_500)),
        (Role::Return, Point::new(40_000, 2_000)),
    ];
    assert_eq!(ends(&got), [pass, pass].concat());
    // The pass travels 6·(4 - 0.577)/4 = 5.1345 along X (radius): K5.134
    // fits (the cut ends at X18.269 - 10.268 = X8.001), K5.135 is longer
    // than the pass (note 7, R-SHORT), the length given floored.
    let fits = END_X_LONG.replace("K0.5", "K5.134");
    assert_eq!(run(&fits, &machine(ProfileName::Gsk980, &[])).unwrap()[1].to, Point::new(8_001, 1_423));
    let long = END_X_LONG.replace("K0.5", "K5.135");
    let e = run(&long, &machine(ProfileName::Gsk980, &[])).unwrap_err();
    let ErrorKind::Cycle(CycleError::RunOutTooLong { run_out, length }) = e else { panic!("{e:?}") };
    assert_eq!((run_out.increments, length.increments), (5_135, 5_134));
    // travel-i: the pass travels |i| = 6, so K5.135 fits.
    assert!(run(&long, &machine(ProfileName::Gsk980, &["R-END=travel-i"])).is_ok());
}

/// R-LONG988 `table` (default on gsk988): [`G92_X_LONG`] on the 988TA, Z
/// long whatever the displacements ("P = 0（轴向螺纹）长轴：横轴"). K = 1
/// along Z: the cut stops at Z-5 + 1 = Z-4 on the line B→C, X = 40 + (20 -
/// 40)·(-4)/(-5) = 40 - 16 = X24; J = 2 along X, 4 on the diameter, away
/// from the work from C's X20 (within the retract to X60): X24 at Z-5.
/// Then X60 at Z-5 (③) and Z0 (④).
#[test]
fn long_axis_by_the_988ta_table() {
    let got = run(G92_X_LONG, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(40_000, 0)),
            (Role::Cut, Point::new(24_000, -4_000)),
            (Role::RunOut, Point::new(24_000, -5_000)),
            (Role::Retract, Point::new(60_000, -5_000)),
            (Role::Return, Point::new(60_000, 0)),
        ]
    );
    // `displacement`: X long, the run-out along Z into the work (R-XRUNOUT).
    let e = run(G92_X_LONG, &machine(ProfileName::Gsk988, &["R-LONG988=displacement"])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::RunOutIntoWork { .. })), "{e:?}");
    // Only the 988TA has the table: on the 980TDi `table` changes nothing.
    let e = run(G92_X_LONG, &machine(ProfileName::Gsk980, &["R-LONG988=table"])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::RunOutIntoWork { .. })), "{e:?}");
}

/// R-LONG988 covers the 988TA's G78 and G92, not its G76 (seed 000 gives
/// G76 the displacement rule): a steep taper (|i| = 6 ≥ |W| = 4) with a
/// lead-in E is Z long for G78 under `table`, so E is accepted; as a G76,
/// or as a G78 under `displacement`, it is X long and E is refused
/// (`LeadInOnXLongAxis`).
#[test]
fn long_axis_table_applies_to_g78_not_g76() {
    let g = |code: &str| {
        format!("M3 S300\nG00 X40 Z2\n{code} P010260 Q0.1 R0 E0.5\n{code} X20 Z-2 R-6 P1 Q1 F2\nM30\n")
    };
    let steep =
        |e: Result<Vec<Move>, ErrorKind>| matches!(e, Err(ErrorKind::Cycle(CycleError::LeadInOnXLongAxis)));
    assert!(run(&g("G78"), &machine(ProfileName::Gsk988, &[])).is_ok());
    assert!(steep(run(&g("G78"), &machine(ProfileName::Gsk988, &["R-LONG988=displacement"]))));
    assert!(steep(run(&g("G76").replace("P010260", "P010060"), &machine(ProfileName::Gsk988, &[]))));
}

/// The defaults per profile, and `cycleref readings` marking them.
#[test]
fn end_and_long988_defaults_and_listing() {
    let r = Readings::default();
    assert!(r.for_cycle(ProfileName::Gsk988, true).long_axis_by_table);
    assert!(!r.for_cycle(ProfileName::Gsk988, false).long_axis_by_table);
    assert!(!r.for_cycle(ProfileName::Gsk980, true).long_axis_by_table);
    assert_eq!(r.get_on("R-LONG988", ProfileName::Gsk988), Some("table"));
    assert_eq!(r.get_on("R-LONG988", ProfileName::Fanuc), Some("displacement"));
    assert_eq!(r.get_on("R-END", ProfileName::Fanuc), Some("parallel"));
    // Choosing the default is not a difference to name; the other value is.
    let mut m = machine(ProfileName::Gsk988, &["R-END=parallel", "R-LONG988=table"]);
    assert!(m.readings.non_default(ProfileName::Gsk988).is_empty());
    m.readings.apply_pair("R-END=travel-i").unwrap();
    assert_eq!(m.readings.non_default(ProfileName::Gsk988), [("R-END", "travel-i")]);
    let all = Listing { profile: None }.to_string();
    assert!(all.contains("\nR-END\ttravel-i | parallel* | translated\t[fanuc,gsk980,gsk988]\t"), "{all}");
    assert!(all.contains("\nR-LONG988\tdisplacement | table*\t[gsk988]\t"), "{all}");
    let gsk980 = Listing { profile: Some(ProfileName::Gsk980) }.to_string();
    assert!(gsk980.contains("R-END") && !gsk980.contains("R-LONG988"));
}

/// R-NOROUGH (sweep entry 4), gsk988: `G00 X80 Z10` / `G76 P010060 Q0
/// R0.5` / `G76 X60 Z-60 P0.5 Q0.2 F2`: d = k = 0.5, so k - d = 0; m = 1,
/// r = 00 (no run-out: J and K not programmed, K = 0 × 0.1 × 2 = 0), a =
/// 60. B = X60 + 2·0.5 = X61 at Z10 (C = D's X, i = 0).
const NO_ROUGH: &str = "M3 S300\nG00 X80 Z10\nG76 P010060 Q0 R0.5\nG76 X60 Z-60 P0.5 Q0.2 F2\nM30\n";

/// `one-at-zero` (default): steps ①-④ cut a first rough pass ("① 从起点快速
/// 移动到 B1"), and step ⑤ stops the roughing at depth k - d = 0 ("如果切深
/// 大于或等于（k-d），按切深（k-d）进刀到 Bf 点"): one rough pass at depth 0,
/// shift round(0 × tan 30°) = 0, at B = (X61, Z10), cut to Z-60 (X61: no
/// taper), ③ X to E = X80, ④ Z to A; then ⑨ the finishing pass at depth
/// k = 0.5 from the Z of the last rough pass (Z10): X60.
#[test]
fn no_rough_one_pass_at_zero_by_default() {
    let finishing = [
        (Role::Approach, Point::new(60_000, 10_000)),
        (Role::Cut, Point::new(60_000, -60_000)),
        (Role::Retract, Point::new(80_000, -60_000)),
        (Role::Return, Point::new(80_000, 10_000)),
    ];
    let mut rough = vec![
        (Role::Approach, Point::new(61_000, 10_000)),
        (Role::Cut, Point::new(61_000, -60_000)),
        (Role::Retract, Point::new(80_000, -60_000)),
        (Role::Return, Point::new(80_000, 10_000)),
    ];
    let got = run(NO_ROUGH, &machine(ProfileName::Gsk988, &[])).unwrap();
    rough.extend(finishing);
    assert_eq!(ends(&got), rough);
    assert_eq!(got[0].pass.map(|p| (p.depth, p.cut)), Some((0, 0)));
    // `none`: the finishing pass alone.
    let got = run(NO_ROUGH, &machine(ProfileName::Gsk988, &["R-NOROUGH=none"])).unwrap();
    assert_eq!(ends(&got), finishing);
    // The default is `one-at-zero` on every profile with G76.
    let r = Readings::default();
    for p in [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988] {
        assert_eq!(r.get_on("R-NOROUGH", p), Some("one-at-zero"));
        assert!(r.for_cycle(p, false).one_rough_at_zero);
    }
}

/// R-DEPTH `formula` (sweep entry 3), gsk988 IS-B: `G00 X80 Z10` / `G76
/// P010060 Q0.3 R0` / `G76 X60 Z-60 P3 Q1 F6`: Δd = 1000, Δdmin = 300,
/// k - d = 3000 (increments of 0.001 mm), P(m) = 01: one finishing pass.
/// By hand, Nn = round(1000 √n) and the larger of Nn and N(n-1) + 300
/// (step (5)):
///
/// | n | Nn | N(n-1) + 300 | Dn |
/// |---|---|---|---|
/// | 1 | 1000 | 0 + 300 | 1000 |
/// | 2 | 1414 (1414.21) | 1300 | 1414 |
/// | 3 | 1732 (1732.05) | 1714 | 1732 |
/// | 4 | 2000 | 2032 | 2032 |
/// | 5 | 2236 (2236.07) | 2300 | 2300 |
/// | 6 | 2449 (2449.49) | 2536 | 2536 |
/// | 7 | 2646 (2645.75) | 2749 | 2749 |
/// | 8 | 2828 (2828.43) | 2946 | 2946 |
/// | 9 | 3000 | 3128 | min(3000, 3128) = 3000, k - d |
///
/// 9 levels. DOMAIN decision 3 (`previous-plus-min`, the default) adds 300
/// to the previous depth once the minimum cut takes over at n = 4: 1000,
/// 1414, 1732, 2032, 2332, 2632, 2932, then 3000: 8 levels.
const DEPTH_988: &str = "M3 S300\nG00 X80 Z10\nG76 P010060 Q0.3 R0\nG76 X60 Z-60 P3 Q1 F6\nM30\n";

fn rough_depths(moves: &[Move]) -> Vec<i64> {
    let mut out: Vec<i64> = Vec::new();
    for p in moves.iter().filter_map(|m| m.pass) {
        if p.kind == cycleref::moves::PassKind::Rough && out.last() != Some(&p.depth) {
            out.push(p.depth);
        }
    }
    out
}

#[test]
fn depth_formula_on_gsk988() {
    let formula = run(DEPTH_988, &machine(ProfileName::Gsk988, &["R-DEPTH=formula"])).unwrap();
    assert_eq!(rough_depths(&formula), [1000, 1414, 1732, 2032, 2300, 2536, 2749, 2946, 3000]);
    let default = run(DEPTH_988, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(rough_depths(&default), [1000, 1414, 1732, 2032, 2332, 2632, 2932, 3000]);
    // The same words on the 980TDi (P and Q in increments without a
    // point: P3000 Q1000, Q300) follow the formula too; on fanuc the value
    // changes nothing (seed 004: "以固定增量d min … 直至粗加工结束").
    let gsk980 = DEPTH_988.replace("Q0.3", "Q300").replace("P3 Q1", "P3000 Q1000");
    let got = run(&gsk980, &machine(ProfileName::Gsk980, &["R-DEPTH=formula"])).unwrap();
    assert_eq!(rough_depths(&got), [1000, 1414, 1732, 2032, 2300, 2536, 2749, 2946, 3000]);
    // FANUC: a coordinate without a decimal point is in increments.
    let fanuc = "M3 S300\nG00 X80. Z10.\nG76 P010060 Q300 R0\nG76 X60. Z-60. P3000 Q1000 F6.\nM30\n";
    let a = run(fanuc, &machine(ProfileName::Fanuc, &["R-DEPTH=formula"])).unwrap();
    let b = run(fanuc, &machine(ProfileName::Fanuc, &[])).unwrap();
    assert_eq!(a, b);
    assert_eq!(rough_depths(&a), [1000, 1414, 1732, 2032, 2332, 2632, 2932, 3000]);
}

/// `round(√x)`, by bisection on its definition `(2s - 1)² ≤ 4x < (2s +
/// 1)²` (independent of the crates' kernels).
fn nearest_root(x: u128) -> u128 {
    // x < 2^62 here: the root is below 2^31.
    let (mut lo, mut hi) = (0_u128, 1_u128 << 32);
    // The largest s with (2s - 1)² ≤ 4x.
    while lo < hi {
        let mid = (lo + hi).div_ceil(2);
        if (2 * mid - 1) * (2 * mid - 1) <= 4 * x {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo
}

/// The levels of the `formula` schedule counted one by one.
fn formula_levels_by_hand(q: i64, dmin: i64, last: i64) -> u64 {
    let q2 = u128::from(q.unsigned_abs()).pow(2);
    let law = |n: u64| i64::try_from(nearest_root(q2 * u128::from(n))).unwrap();
    // The sweep's words: Δdmin itself, and D(n-1) + 1.
    let (mut depth, mut n) = (0_i64, 0_u64);
    while depth < last {
        n += 1;
        depth = last.min(law(n).max(law(n - 1) + dmin).max(depth + 1));
    }
    n
}

/// R-DEPTH `formula`'s closed-form count (R-LIMIT) against counting the
/// levels one by one: every Δd ≤ 30, Δdmin ≤ 10, k - d ≤ 200, and sampled
/// large values.
#[test]
fn depth_formula_count_is_exact() {
    for q in 1..=30_i64 {
        for dmin in 0..=10_i64 {
            for last in 1..=200_i64 {
                let got = cycleref_spec::g76::formula_level_count(q, dmin.max(1), last);
                assert_eq!(got, formula_levels_by_hand(q, dmin, last), "Δd {q} Δdmin {dmin} k-d {last}");
            }
        }
    }
    for q in [1_i64, 3, 100, 1000, 31_623, 999_999_999] {
        for dmin in [0_i64, 5, 300] {
            for last in [999_i64, 4_321, 100_000] {
                let got = cycleref_spec::g76::formula_level_count(q, dmin.max(1), last);
                assert_eq!(got, formula_levels_by_hand(q, dmin, last), "Δd {q} Δdmin {dmin} k-d {last}");
            }
        }
    }
}

/// R-STARTS (sweep entry 7), gsk988 `G00 X80 Z10` / `G76 P010060 Q0.1
/// R0.1 L2` / `G76 X60 Z-30 P1 Q0.5 F2`: k - d = 0.9, Δd = 0.5, Δdmin =
/// 0.1: levels round(500 √n) = 500, 707, 866, then 1000 → 900 (k - d): 4
/// rough passes and m = 1 finishing pass, each for starts 1 and 2 (0° and
/// 180°).
const TWO_STARTS: &str = "M3 S300\nG00 X80 Z10\nG76 P010060 Q0.1 R0.1 L2\nG76 X60 Z-30 P1 Q0.5 F2\nM30\n";

/// The passes in cutting order: (rough?, number, start), once a pass.
fn pass_order(moves: &[Move]) -> Vec<(bool, u32, u16)> {
    let mut out: Vec<(bool, u32, u16)> = Vec::new();
    for p in moves.iter().filter_map(|m| m.pass) {
        let key = (p.kind == cycleref::moves::PassKind::Rough, p.number, p.start);
        if out.last() != Some(&key) {
            out.push(key);
        }
    }
    out
}

/// `pass-major` (default): each pass for both starts before the next;
/// `start-major`: the five passes of start 1, then those of start 2. The
/// moves of each pass of each start are the same under both.
#[test]
fn starts_order() {
    let pass_major = run(TWO_STARTS, &machine(ProfileName::Gsk988, &[])).unwrap();
    let start_major = run(TWO_STARTS, &machine(ProfileName::Gsk988, &["R-STARTS=start-major"])).unwrap();
    let (r, f) = (true, false);
    assert_eq!(
        pass_order(&pass_major),
        [
            (r, 1, 1),
            (r, 1, 2),
            (r, 2, 1),
            (r, 2, 2),
            (r, 3, 1),
            (r, 3, 2),
            (r, 4, 1),
            (r, 4, 2),
            (f, 1, 1),
            (f, 1, 2)
        ]
    );
    assert_eq!(
        pass_order(&start_major),
        [
            (r, 1, 1),
            (r, 2, 1),
            (r, 3, 1),
            (r, 4, 1),
            (f, 1, 1),
            (r, 1, 2),
            (r, 2, 2),
            (r, 3, 2),
            (r, 4, 2),
            (f, 1, 2)
        ]
    );
    let of = |moves: &[Move], key: (bool, u32, u16)| -> Vec<Move> {
        moves
            .iter()
            .filter(|m| {
                m.pass.is_some_and(|p| (p.kind == cycleref::moves::PassKind::Rough, p.number, p.start) == key)
            })
            .copied()
            .collect()
    };
    for key in pass_order(&pass_major) {
        assert_eq!(of(&pass_major, key), of(&start_major, key), "{key:?}");
    }
    assert_eq!(pass_major.len(), start_major.len());
}

/// The 988TA under 5129 (THM) = 1 with `extra` parameters and `readings`.
fn high_speed_with(params: &str, readings: &[&str]) -> Machine {
    let mut m = machine(ProfileName::Gsk988, readings);
    m.apply_toml(&format!("[parameters]\n5129 = 1\n{params}")).unwrap();
    m
}

/// The 988TA G92 example's first block without K (`G92 X58.7 Z-28 F3 J3`
/// from A = (X65, Z5)) in the high-speed mode (5129 = 1): "省略 K 时，长轴无
/// 退尾，短轴方向的退尾长度，固定为切削终点到起点的短轴轴向距离，与 J 是多少无关".
/// R-G92HS-NOK `rapid-retract` (default): the cut to C (X58.7, Z-28), then
/// step (3)'s "X 轴以快速移动速度退刀 … 返回到 X 轴绝对坐标与起点相同处" to
/// X65, Z back to Z5. `pull-out-to-start`: the 退尾 from C by thread
/// motion along X to the start's X65 ((65 - 58.7)/2 = 3.15 of radius,
/// whatever J: J0 gives the same), the rapid retract then empty (R-ZERO).
#[test]
fn g92_high_speed_without_k() {
    let src = |j: &str| format!("M3 S300\nG00 X65 Z5\nG92 X58.7 Z-28 F3 {j}\nM30\n");
    let rapid = run(&src("J3"), &high_speed_with("", &[])).unwrap();
    assert_eq!(
        ends(&rapid),
        [
            (Role::Approach, Point::new(58_700, 5_000)),
            (Role::Cut, Point::new(58_700, -28_000)),
            (Role::Retract, Point::new(65_000, -28_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    let m = high_speed_with("", &["R-G92HS-NOK=pull-out-to-start"]);
    let pulled = run(&src("J3"), &m).unwrap();
    assert_eq!(
        ends(&pulled),
        [
            (Role::Approach, Point::new(58_700, 5_000)),
            (Role::Cut, Point::new(58_700, -28_000)),
            (Role::RunOut, Point::new(65_000, -28_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    assert!(matches!(pulled[2].motion, cycleref::Motion::Thread { .. }));
    assert_eq!(run(&src("J0"), &m).unwrap(), pulled);
    // The normal mode is not concerned: "省略 K 时，长轴无退尾，短轴方向按 J 值
    // 退尾", X58.7 + 2·3 = X64.7.
    let normal = run(&src("J3"), &machine(ProfileName::Gsk988, &["R-G92HS-NOK=pull-out-to-start"])).unwrap();
    assert_eq!(normal[2].to, Point::new(64_700, -28_000));
}

/// The same block with K1 and J omitted in the high-speed mode: "省略 J 时，
/// 长轴方向按 K 退尾". R-G92HS-NOJ `to-start` (default): the cut ends K = 1
/// before C, at Z-27, and the short axis runs to the start's X65
/// (J' clamped at the retract, 3.15). `by-parameter` with 5130 = 10 and
/// 5131 = 0 (45°, "当参数 5131（退尾角度）设置为零时，长轴和短轴以 45°角退尾"),
/// as the 980TDi note 3 "短轴方向按№.19号参数设定值退尾": J = round(10 · 0.1 ·
/// 3 · tan 45°) = 3.000, the run-out to X58.7 + 2·3 = X64.7 at Z-28, then
/// the rapid to X65. With 5130 = 0, J = 0: no run-out, the cut to C.
#[test]
fn g92_high_speed_without_j() {
    let src = "M3 S300\nG00 X65 Z5\nG92 X58.7 Z-28 F3 K1\nM30\n";
    let params = "5130 = 10\n5131 = 0\n";
    let to_start = run(src, &high_speed_with(params, &[])).unwrap();
    assert_eq!(
        ends(&to_start),
        [
            (Role::Approach, Point::new(58_700, 5_000)),
            (Role::Cut, Point::new(58_700, -27_000)),
            (Role::RunOut, Point::new(65_000, -28_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    let by_parameter = run(src, &high_speed_with(params, &["R-G92HS-NOJ=by-parameter"])).unwrap();
    assert_eq!(
        ends(&by_parameter),
        [
            (Role::Approach, Point::new(58_700, 5_000)),
            (Role::Cut, Point::new(58_700, -27_000)),
            (Role::RunOut, Point::new(64_700, -28_000)),
            (Role::Retract, Point::new(65_000, -28_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    let none = run(src, &high_speed_with("5130 = 0\n", &["R-G92HS-NOJ=by-parameter"])).unwrap();
    assert_eq!(none[1].to, Point::new(58_700, -28_000));
}

/// R-G92JK988 on the 988TA's G92 (normal mode): J, K "（半径值，不带方向）".
/// `refuse-negative` (default): J-3 is out of range. `magnitude` (as the
/// 980TDi note 10 "J、K输入负值时，按正值处理"): J-3 K-1 is the page's example
/// J3 K1: the cut to Z-28 + 1 = Z-27, the run-out to X58.7 + 2·3 = X64.7
/// at Z-28, the retract to X65, Z back to Z5.
#[test]
fn g92_negative_j_k_on_gsk988() {
    let src = "M3 S300\nG00 X65 Z5\nG92 X58.7 Z-28 F3 J-3 K-1\nM30\n";
    let e = run(src, &machine(ProfileName::Gsk988, &[])).unwrap_err();
    assert!(matches!(e, ErrorKind::OutOfRange { .. }), "{e}");
    let got = run(src, &machine(ProfileName::Gsk988, &["R-G92JK988=magnitude"])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(58_700, 5_000)),
            (Role::Cut, Point::new(58_700, -27_000)),
            (Role::RunOut, Point::new(64_700, -28_000)),
            (Role::Retract, Point::new(65_000, -28_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    let positive = "M3 S300\nG00 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nM30\n";
    assert_eq!(got, run(positive, &machine(ProfileName::Gsk988, &[])).unwrap());
}

/// R-G32RUNOUT on the 988TA, `G32 Z-20 F2 J1 K0` from X30 Z0. `pull-out`
/// (default, K = 0 read as "只省略 K（J≠0）时，长轴无退尾，短轴按 J 值退尾"): the
/// cut to Z-20, then a pull-out of J = 1 (radius) along X to X32. `none`
/// (the G92 normal mode's "J≠0，K=0 时，无退尾"): the cut to Z-20 only.
#[test]
fn g32_k_zero_on_gsk988() {
    let src = "M3 S300\nG00 X30 Z0\nG32 Z-20 F2 J1 K0\nM30\n";
    let pulled = run(src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        ends(&pulled),
        [(Role::Cut, Point::new(30_000, -20_000)), (Role::RunOut, Point::new(32_000, -20_000))]
    );
    let none = run(src, &machine(ProfileName::Gsk988, &["R-G32RUNOUT=none"])).unwrap();
    assert_eq!(ends(&none), [(Role::Cut, Point::new(30_000, -20_000))]);
}

/// R-CHAMFERANGLE on the 988TA's G92 without J and K ("按参数 5130（倒角量）和
/// 参数 5131（退尾角度）确定退尾"): 5130 = 10, F2, so K = 10 · 0.1 · 2 =
/// 2.000; 5131 = 30. A = (X40, Z5), C = (X30, Z-20). `from-long-axis`
/// (default): J = round(2 · tan 30°) = round(1.1547) = 1.155; the cut to Z-18,
/// the run-out to X30 + 2·1.155 = X32.31 at Z-20. `from-short-axis`: J =
/// round(2 · tan 60°) = round(3.4641) = 3.464, to X30 + 2·3.464 = X36.928.
/// Both below the retract (40 - 30)/2 = 5: no clamp. The same on fanuc
/// (G76's r and 5131).
#[test]
fn chamfer_angle_axis() {
    let src = "M3 S300\nG00 X40 Z5\nG92 X30 Z-20 F2\nM30\n";
    let m = |readings: &[&str]| {
        let mut m = machine(ProfileName::Gsk988, readings);
        m.apply_toml("[parameters]\n5130 = 10\n5131 = 30\n").unwrap();
        m
    };
    let pass = |x: i64| {
        [
            (Role::Approach, Point::new(30_000, 5_000)),
            (Role::Cut, Point::new(30_000, -18_000)),
            (Role::RunOut, Point::new(x, -20_000)),
            (Role::Retract, Point::new(40_000, -20_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    };
    assert_eq!(ends(&run(src, &m(&[])).unwrap()), pass(32_310));
    assert_eq!(ends(&run(src, &m(&["R-CHAMFERANGLE=from-short-axis"])).unwrap()), pass(36_928));
}

/// R-G92FACE under R-LONG988 `table` (the 988TA default): the P1 face
/// thread `G92 X61 Z1 F3 P1` from A = (X65, Z5) has 2 of X travel
/// (radius) and 2.001 along Z. The table ("P = 1（端面螺纹）长轴 纵轴") makes X
/// long whatever the displacements, so it is made: B on A's X65 at the Z
/// of C plus R, 1 - 2.001 = Z-1.001 (Z is the short axis, "锥度 R 决定了锥螺纹
/// 起点短轴的位置"); the cut from B to C (X61, Z1) with the lead F3 along X;
/// Z back to A's Z5 (step (3) on the short axis), X back to X65 (step
/// (4) on the long axis). Under `displacement` it is refused
/// (SteepFaceThread), as before.
#[test]
fn steep_face_thread_under_the_table() {
    let src = "M3 S300\nG0 X65 Z5\nG92 X61 Z1 R-2.001 F3 P1\nM30\n";
    let got = run(src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(65_000, -1_001)),
            (Role::Cut, Point::new(61_000, 1_000)),
            (Role::Retract, Point::new(61_000, 5_000)),
            (Role::Return, Point::new(65_000, 5_000)),
        ]
    );
    assert!(matches!(got[1].motion, cycleref::Motion::Thread { .. }));
    let e = run(src, &machine(ProfileName::Gsk988, &["R-LONG988=displacement"])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::SteepFaceThread { .. })), "{e}");
}

/// R-MODAL for E on the 988TA's G76 (the program of `lead_in_at_the_z_of_bn`
/// twice, the second block 1 without E). `one-shot` (default): the second
/// cycle has no lead-in, its passes approach Bn = (X30, Z5) directly.
/// `modal`: E0.5 stays in force like Q and R, and the second cycle's
/// passes start at An = (X31, Z5) with the screw-in to Bn, as the first.
#[test]
fn lead_in_e_modal() {
    let cycle = "G76 X30 Z-20 P1 Q1 F2\n";
    let src =
        format!("M3 S300\nG00 X40 Z5\nG76 P010000 Q0.1 R0 E0.5\n{cycle}G76 P010000 Q0.1 R0\n{cycle}M30\n");
    let with_e = [
        (Role::Approach, Point::new(31_000, 5_000)),
        (Role::LeadIn, Point::new(30_000, 5_000)),
        (Role::Cut, Point::new(30_000, -20_000)),
        (Role::Retract, Point::new(40_000, -20_000)),
        (Role::Return, Point::new(40_000, 5_000)),
    ];
    let without = [
        (Role::Approach, Point::new(30_000, 5_000)),
        (Role::Cut, Point::new(30_000, -20_000)),
        (Role::Retract, Point::new(40_000, -20_000)),
        (Role::Return, Point::new(40_000, 5_000)),
    ];
    let one_shot = run(&src, &machine(ProfileName::Gsk988, &[])).unwrap();
    assert_eq!(ends(&one_shot), [&with_e[..], &with_e, &without, &without].concat());
    let modal = run(&src, &machine(ProfileName::Gsk988, &["R-MODAL=modal"])).unwrap();
    assert_eq!(ends(&modal), [with_e, with_e, with_e, with_e].concat());
}

/// R-G32LONG at the tie on the 980TDi: `G32 U-20 W-10 F2 J1 K1` from (X40,
/// Z0): 10 of X travel as a radius, 10 along Z. Both values stop the cut
/// on the line at (X22, Z-9): `tie-x` K = 1 (radius) before X20 along X,
/// 20 + 2·1 = X22, Z = -10·(22 - 40)/(-20) = -9; `tie-z` K = 1 before
/// Z-10, X = 40 - 20·9/10 = 22. The run-out (seed 002: J "带正负方向" along
/// the short axis): `tie-x` J along Z, to (X20, Z-10 + 1) = (X20, Z-9);
/// `tie-z` J along X (radius), to (X20 + 2·1, Z-10) = (X22, Z-10).
#[test]
fn g32_tie() {
    let src = "M3 S300\nG00 X40 Z0\nG32 U-20 W-10 F2 J1 K1\nM30\n";
    let x = run(src, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(
        ends(&x),
        [(Role::Cut, Point::new(22_000, -9_000)), (Role::RunOut, Point::new(20_000, -9_000))]
    );
    let z = run(src, &machine(ProfileName::Gsk980, &["R-G32LONG=tie-z"])).unwrap();
    assert_eq!(
        ends(&z),
        [(Role::Cut, Point::new(22_000, -9_000)), (Role::RunOut, Point::new(22_000, -10_000))]
    );
}

/// R-SIDE on the sweep's program (docs/readings-sweep.md entry 1), gsk988
/// IS-B: A = (X61, Z10); D = (X60, Z-30), i = 0, so C = (X60, Z10); A lies
/// outside C (61 > 60): external, s = +1. k = 1 mm, so B = X60 + 2·1 =
/// X62 and the crest at D is X62 too: A lies inside the crest.
/// P010060: m = 1 finishing pass, r = 0 (no run-out), a = 60°; Q0 (Δdmin
/// 0, so the least cut is one increment), R0 (d = 0); Q0.5: Δd = 500
/// increments, k - d = 1000.
///
/// Depths (seed 000 "X 轴切深: √n × Q(Δd)"): round(500·√1) = 500,
/// round(500·√2) = round(707.1) = 707, round(500·√3) = round(866.03) =
/// 866, round(500·√4) = 1000 = k - d. Z shifts along the right flank
/// (D0), round(Dn·tan 30°), tan 30° = 0.57735: 288.68 → 289, 408.19 →
/// 408, 499.99 → 500, 577.35 → 577, towards D (W < 0): Z10 - shift.
/// Bn's X = X of C + 2·(k - Dn): 61.000, 60.586, 60.268, 60.000. The
/// passes run parallel to C→D (R-END `parallel`, i = 0) to Z-30, the
/// retract to E (X of A, 61) and the return to A along Z (step ⑦ "X 轴快
/// 速移动到 E 点", ⑧ "Z 轴快速移动到 A 点"); pass 1 ends at X61 already, so
/// its retract does not move (R-ZERO). The finishing pass takes the last
/// rough pass's Z ("精车 Z 轴起切点与最后一刀粗车一致").
#[test]
fn start_inside_the_crest() {
    let src = "M3 S300\nG00 X61 Z10\nG76 P010060 Q0 R0\nG76 X60 Z-30 P1 Q0.5 F2\nM30\n";
    let e = run(src, &machine(ProfileName::Gsk988, &[])).unwrap_err();
    assert_eq!(e, ErrorKind::Cycle(CycleError::StartInsideThread));
    let got = run(src, &machine(ProfileName::Gsk988, &["R-SIDE=accept"])).unwrap();
    let pass = |x: i64, z: i64| {
        [
            (Role::Approach, Point::new(x, z)),
            (Role::Cut, Point::new(x, -30_000)),
            (Role::Retract, Point::new(61_000, -30_000)),
            (Role::Return, Point::new(61_000, 10_000)),
        ]
    };
    let mut want =
        vec![(Role::Approach, Point::new(61_000, 9_711)), (Role::Cut, Point::new(61_000, -30_000))];
    want.push((Role::Return, Point::new(61_000, 10_000)));
    for (x, z) in [(60_586, 9_592), (60_268, 9_500), (60_000, 9_423), (60_000, 9_423)] {
        want.extend(pass(x, z));
    }
    assert_eq!(ends(&got), want);
    // A on the X of C gives no side: refused under either value.
    let on_c = src.replace("X61 Z10", "X60 Z10");
    let e = run(&on_c, &machine(ProfileName::Gsk988, &["R-SIDE=accept"])).unwrap_err();
    assert_eq!(e, ErrorKind::Cycle(CycleError::StartInsideThread));
}

/// Each move as (rapid?, X, Z).
fn kinds(moves: &[Move]) -> Vec<(bool, i64, i64)> {
    moves.iter().map(|m| (m.motion == cycleref::Motion::Rapid, m.to.x, m.to.z)).collect()
}

/// R-G75RIDGE on the sweep's program (docs/readings-sweep.md entry 36),
/// 980TDi IS-C (0.0001 mm): S = (X50, Z30), P30000 = Δi 3 (diameter, 1.5
/// of radius a peck), Q50000 = Δk 5, H-20 (bottom X30), D-10 (towards -Z,
/// far flank Z20), 90° flanks, R0.5 (e, radius: 1 on the diameter), V8
/// (layers to X42, X34, X30), I4, J0 (rough only), from X60 Z40.
///
/// Plunges (R-G75TOOL, R-G75PLUNGE): the start-side corner at Z30, the
/// last where the tool's far side meets flank B, Z20 + 4 = Z24; steps ⑤⑦:
/// Z30, Z30 - 5 = Z25, then Z20 is past Amf so "Z 轴快速移动至 Amf 点":
/// Z24. The plunges at Z30 (tool over Z30..Z26) and Z25 (Z25..Z21) leave
/// a ridge Z26..Z25: Δk 5 > I 4 with three layers, refused by default
/// (`ridges_in_layers`). `as-written` makes steps ②⑦⑧ as written.
///
/// Pecks of a layer from its top T to its bottom: feed T - 3, retract +1
/// (e), feed (Δi/2 + e) deeper, …, the last feed clamped at the bottom,
/// then the rapid back to T (step ⑥). Layer 1, T = X50, bottom X42: 47,
/// 48, 44, 45, 42, 50. Layer 2, T = X42, bottom X34: 39, 40, 36, 37, 34,
/// 42. Layer 3, T = X34, bottom X30: 31, 32, 30, 34. Between plunges the
/// axial rapid at T (step ⑦); between layers Z back to Z30 at the old T,
/// then down to the new T (step ②). In layer 2 the rapid from Z30 to Z25
/// at X42 runs the tool's body across the ridge Z26..Z25 left above X42:
/// the move `refuse` prevents. Then the rough contour (step ⑨, J0): back
/// up to X50 at Z24, to Z30, the feeds around the region X30 Z30, X30
/// Z24, X50 Z24, the rapid to Z30 and the return to X60 Z40 (step ⑩).
#[test]
fn g75_ridges_as_written() {
    let src = "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10\nG75.1 R0.5 V8 I4\nM30\n";
    let e = run(src, &gsk980_is_c(&[])).unwrap_err();
    assert!(matches!(e, ErrorKind::Cycle(CycleError::RidgesInLayers { .. })), "{e:?}");
    let got = run(src, &gsk980_is_c(&["R-G75RIDGE=as-written"])).unwrap();
    let mm = |v: i64| v * 10_000;
    let mut want = vec![(true, mm(50), mm(30))];
    let pecks = |top: i64, bottom: i64| -> Vec<(bool, i64)> {
        let (mut out, mut at) = (Vec::new(), top);
        loop {
            at = (at - 3).max(bottom);
            out.push((false, at));
            if at == bottom {
                break;
            }
            at += 1;
            out.push((true, at));
            at -= 1;
        }
        out.push((true, top));
        out
    };
    let mut previous_top = None;
    for (top, bottom) in [(50, 42), (42, 34), (34, 30)] {
        if let Some(previous) = previous_top {
            // Step ②: Z back to Z30 at the old top, then down to this top.
            want.push((true, mm(previous), mm(30)));
            want.push((true, mm(top), mm(30)));
        }
        previous_top = Some(top);
        for (n, z) in [30, 25, 24].into_iter().enumerate() {
            if n > 0 {
                want.push((true, mm(top), mm(z)));
            }
            want.extend(pecks(top, bottom).into_iter().map(|(rapid, x)| (rapid, mm(x), mm(z))));
        }
    }
    want.extend([
        (true, mm(50), mm(24)),
        (true, mm(50), mm(30)),
        (false, mm(30), mm(30)),
        (false, mm(30), mm(24)),
        (false, mm(50), mm(24)),
        (true, mm(50), mm(30)),
        (true, mm(60), mm(40)),
    ]);
    assert_eq!(kinds(&got), want);
}

/// R-G75PECK (docs/readings-sweep.md entry 37), 980TDi IS-C, from X60
/// Z40: S = (X50, Z30), P10000 = Δi 1 (diameter: Δi/2 = 0.5 of radius a
/// peck), Q40000 = Δk 4, H-4 (bottom X46), D-8 (far flank Z22), I4, R1 (e
/// = 1 of radius, 2 on the diameter), one layer, J0.
///
/// Plunges: Z30, then Z30 - 4 = Z26 = Z22 + I4 = Amf. Pecks (step ③ "切削
/// 进给 Δi/2", ⑤ "再次切削进给(Δi/2+e)"): ends X50 - 1·j, X49, X48, X47 and
/// X46 (the bottom, then ⑥ back to Amn X50). Retracts (④ "快速移动退刀 e"):
/// X49 + 2 = X51, X48 + 2 = X50, X47 + 2 = X49. The first is above Amn
/// (X50): `clamped` (default) stops it at X50 and the next feed is 2 on
/// the diameter; `as-written` goes to X51 and the next feed is the written
/// Δi/2 + e = 0.5 + 1 = 1.5 of radius (X51 → X48). The peck ends are the
/// same under both. Then the step ⑦ to Z26 at X50, the same pecks, and
/// the rough contour X46 Z30, X46 Z26, X50 Z26, back to Z30 and X60 Z40.
#[test]
fn g75_peck_retract_as_written() {
    let src = "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P10000 Q40000 H-4 D-8\nG75.1 R1 I4\nM30\n";
    let mm = |v: i64| v * 10_000;
    let want = |first_retract: i64| {
        let mut want = vec![(true, mm(50), mm(30))];
        for (n, z) in [30, 26].into_iter().enumerate() {
            if n > 0 {
                want.push((true, mm(50), mm(z)));
            }
            for (rapid, x) in [
                (false, 49),
                (true, first_retract),
                (false, 48),
                (true, 50),
                (false, 47),
                (true, 49),
                (false, 46),
            ] {
                want.push((rapid, mm(x), mm(z)));
            }
            want.push((true, mm(50), mm(z)));
        }
        want.extend([
            (true, mm(50), mm(30)),
            (false, mm(46), mm(30)),
            (false, mm(46), mm(26)),
            (false, mm(50), mm(26)),
            (true, mm(50), mm(30)),
            (true, mm(60), mm(40)),
        ]);
        want
    };
    assert_eq!(kinds(&run(src, &gsk980_is_c(&[])).unwrap()), want(50));
    assert_eq!(kinds(&run(src, &gsk980_is_c(&["R-G75PECK=as-written"])).unwrap()), want(51));
}

/// R-G75PECK `as-written` near the end of the range (R-RANGE): the same
/// groove at S = X99999.9 (999 999 000 at IS-C): the first retract, X of
/// the first peck + 2 = S + 1 (10 000 increments), is 1 000 009 000,
/// beyond 999 999 999: refused there, by both engines alike; `clamped`
/// stays within it.
#[test]
fn g75_peck_retract_beyond_the_range() {
    let src = "M3 S300\nG00 X99999.9 Z40\nG75.1 X99999.9 Z30 P10000 Q40000 H-4 D-8\nG75.1 R1 I4\nM30\n";
    assert!(run(src, &gsk980_is_c(&[])).is_ok());
    let e = run(src, &gsk980_is_c(&["R-G75PECK=as-written"])).unwrap_err();
    let ErrorKind::Cycle(CycleError::OutOfRange { value, .. }) = e else { panic!("{e:?}") };
    assert_eq!(value.increments, 1_000_009_000);
}

/// R-SPINDLE (docs/readings-sweep.md entry 13): [`G92_LONG_J`] without its
/// M3, on the 980TDi. `speed-and-running` (default): S300 was commanded
/// but the spindle was never started, refused on the G92 block (line 3)
/// with `no_spindle_speed`. `speed-only` ("如果没有指令主轴速度，产生报警"
/// speaks of the commanded speed only): the moves of the program with M3,
/// worked in `run_out_clamped_by_default` (X30 Z5, X30 Z-18, X40 Z-20, X40
/// Z5). Without S (or after `S0`) it is refused under both; an M05 stops
/// the spindle, which only `speed-and-running` looks at.
#[test]
fn spindle_speed_only() {
    let stopped = G92_LONG_J.replace("M3 S300", "S300");
    let e = read(&stopped, &machine(ProfileName::Gsk980, &[])).unwrap_err();
    assert_eq!((e.kind.clone(), e.line), (ErrorKind::NoSpindleSpeed, 3));
    let m = machine(ProfileName::Gsk980, &["R-SPINDLE=speed-only"]);
    let got = run(&stopped, &m).unwrap();
    assert_eq!(got, run(G92_LONG_J, &machine(ProfileName::Gsk980, &[])).unwrap());
    assert_eq!(
        ends(&got),
        [
            (Role::Approach, Point::new(30_000, 5_000)),
            (Role::Cut, Point::new(30_000, -18_000)),
            (Role::RunOut, Point::new(40_000, -20_000)),
            (Role::Return, Point::new(40_000, 5_000)),
        ]
    );
    let m05 = G92_LONG_J.replace("G00 X40 Z5", "M05\nG00 X40 Z5");
    assert_eq!(read(&m05, &machine(ProfileName::Gsk980, &[])).unwrap_err().kind, ErrorKind::NoSpindleSpeed);
    assert!(run(&m05, &m).is_ok());
    let no_speed = G92_LONG_J.replace("M3 S300", "M3");
    let e = read(&no_speed, &m).unwrap_err();
    assert_eq!((e.kind, e.line), (ErrorKind::NoSpindleSpeed, 3));
}

/// R-G75LAYER on the sweep's numbers (docs/readings-sweep.md entry 34:
/// depth 10 mm, V4), 980TDi IS-B, from X60 Z40: S = (X50, Z30), H-10 (D =
/// 10 000 increments on the diameter, bottom X40), D-6 (far flank Z24),
/// I3: plunges Z30 and Z24 + 3 = Z27 (= Z30 - Q3); P4000: Δi 4 ≥ every
/// layer, one peck a plunge; R omitted (no retract); J0.
///
/// `full-then-remainder` (default): M = ceil(10/4) = 3, bottoms 4, 8, 10:
/// X46, X42, X40. `equal`: M = 3 layers of 10 000 / 3: q = 3 333, r = 1,
/// the first layer one increment deeper: bottoms 3 334, 6 667, 10 000:
/// X46.666, X43.333, X40. Each layer: the plunge at Z30 and back (⑥),
/// the step to Z27 and its plunge and back; between layers Z30 at the old
/// top then down to the new (②); after the last, up to X50 at Z27, Z30,
/// the rough contour X40 Z30, X40 Z27, X50 Z27, Z30 and X60 Z40.
#[test]
fn g75_equal_layers() {
    let src = "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P4000 Q3000 H-10 D-6\nG75.1 V4 I3\nM30\n";
    let want = |bottoms: [i64; 3]| {
        let mut want = vec![(true, 50_000, 30_000)];
        let (mut previous_top, mut top) = (None, 50_000);
        for bottom in bottoms {
            if let Some(previous) = previous_top {
                // Step ②: Z30 at the old top, then down to this top.
                want.extend([(true, previous, 30_000), (true, top, 30_000)]);
            }
            want.extend([
                (false, bottom, 30_000),
                (true, top, 30_000),
                (true, top, 27_000),
                (false, bottom, 27_000),
                (true, top, 27_000),
            ]);
            (previous_top, top) = (Some(top), bottom);
        }
        want.extend([
            (true, 50_000, 27_000),
            (true, 50_000, 30_000),
            (false, 40_000, 30_000),
            (false, 40_000, 27_000),
            (false, 50_000, 27_000),
            (true, 50_000, 30_000),
            (true, 60_000, 40_000),
        ]);
        want
    };
    assert_eq!(kinds(&run(src, &machine(ProfileName::Gsk980, &[])).unwrap()), want([46_000, 42_000, 40_000]));
    let equal = run(src, &machine(ProfileName::Gsk980, &["R-G75LAYER=equal"])).unwrap();
    assert_eq!(kinds(&equal), want([46_666, 43_333, 40_000]));
}

/// R-G75LAYER `equal` near the end of the range (R-RANGE), 980TDi IS-C:
/// S = X-99999.89 (-999 998 900), H-0.25 (D = 2 500), V0.1 (Δv 1 000):
/// M = 3. Default bottoms 1 000, 2 000, 2 500: layer 2's first peck, at
/// 1 000 + Δi (P1000) = 2 000, is X -1 000 000 900, the first coordinate out of
/// range. `equal`: q = 833, r = 1, bottoms 834, 1 667, 2 500: layer 2's
/// first peck from 834 to min(1 834, 1 667) = 1 667, X -1 000 000 567.
/// Both engines refuse at the same coordinate.
#[test]
fn g75_equal_layers_beyond_the_range() {
    let src =
        "M3 S300\nG00 X-99999.89 Z40\nG75.1 X-99999.89 Z30 P1000 Q5000 H-0.25 D-1\nG75.1 V0.1 I0.5\nM30\n";
    for (reading, want) in
        [("R-G75LAYER=full-then-remainder", -1_000_000_900), ("R-G75LAYER=equal", -1_000_000_567)]
    {
        let e = run(src, &gsk980_is_c(&[reading])).unwrap_err();
        let ErrorKind::Cycle(CycleError::OutOfRange { value, .. }) = e else { panic!("{e:?}") };
        assert_eq!(value.increments, want);
    }
}

/// R-G75CHAMFER on the manual's example groove (seed 001: S = (X50, Z30),
/// H-20, D-10, A45, B30), 980TDi IS-B, from X60 Z40, J2 (finishing only),
/// a 1 mm chamfer at each of the four corners (A1 B1 D1 E1, P0000). Local
/// frame (docs/G75.md §2): u towards -Z from Z30, y towards -X from X50 on
/// the diameter (f = 2): Y = 20 000, Y/f = 10 000, d = 10 000, cot 45° = 1,
/// cot 30° = √3, L = 0: P1 = (10 000, Y), P2 = (20 000, Y), P3 = (20 000 +
/// 10 000·√3, 0) = (37 320.508, 0).
///
/// `equal-legs` (default): t = 1 000 at every corner. `axial-width`: the
/// chamfer's extent along Z is 1 000, t·(cos θ1 + cos θ2) = 1 000:
/// t1 = t3 = 1 000/(1 + cos 45°) = 1 000·(2 − √2) = 585.786,
/// t2 = t4 = 1 000/(1 + cos 30°) = 1 000·(4 − 2√3) = 535.898.
///
/// Points (nearest), axial-width:
/// T1s = (−t1, 0) = (−585.786, 0): Z30.586;
/// T1a = (t1·cos 45°, 2·t1·sin 45°) = (1 000·(√2 − 1), 2 000·(√2 − 1)) =
///   (414.214, 828.427): X49.172 Z29.586;
/// T3a = (10 000 − 414.214, 20 000 − 828.427) = (9 585.786, 19 171.573):
///   X30.828 Z20.414;
/// T3b = (10 000 + 585.786, 20 000): X30 Z19.414 (Z extent T3a → T3b 1);
/// T4b = (20 000 − 535.898, 20 000): X30 Z10.536;
/// T4c = (20 000 + t4·cos 30°, 20 000 − 2·t4·sin 30°) = (20 464.102,
///   19 464.102): X30.536 Z9.536;
/// T2b = (37 320.508 − 464.102, 2·t2·sin 30°) = (36 856.406, 535.898):
///   X49.464 Z-6.856;
/// T2s = (37 320.508 + 535.898, 0) = (37 856.406, 0): X50 Z-7.856.
/// A11 = (ceil(left(Y)), 0), left(Y) = chord3 = P1.u + t3 = 10 585.786:
/// u 10 586, Z19.414.
///
/// Equal legs: T1s Z31, T1a (707.107, 1 414.214) X48.586 Z29.293, T3a
/// (9 292.893, 18 585.786) X31.414 Z20.707, T3b Z19, T4b Z11, T4c
/// (20 866.025, 19 000) X31 Z9.134, T2b (36 454.483, 1 000) X49 Z-6.454,
/// T2s (38 320.508, 0) X50 Z-8.321; A11 Z19.
///
/// Moves: rapid to A11 (X50), rapid along Z to T1s (X50), feeds through
/// the seven points, rapid along Z to Z30 (S), rapid to X60 Z40.
#[test]
fn g75_chamfer_axial_width() {
    let src = "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\n\
               G75.1 R0.5 J2 A1 B1 D1 E1 P0000\nM30\n";
    let want = |a11: i64, t1s: i64, feeds: [(i64, i64); 7]| {
        let mut want = vec![(true, 50_000, a11), (true, 50_000, t1s)];
        want.extend(feeds.map(|(x, z)| (false, x, z)));
        want.extend([(true, 50_000, 30_000), (true, 60_000, 40_000)]);
        want
    };
    let default = run(src, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(
        kinds(&default),
        want(
            19_000,
            31_000,
            [
                (48_586, 29_293),
                (31_414, 20_707),
                (30_000, 19_000),
                (30_000, 11_000),
                (31_000, 9_134),
                (49_000, -6_454),
                (50_000, -8_321)
            ]
        )
    );
    let axial = run(src, &machine(ProfileName::Gsk980, &["R-G75CHAMFER=axial-width"])).unwrap();
    assert_eq!(
        kinds(&axial),
        want(
            19_414,
            30_586,
            [
                (49_172, 29_586),
                (30_828, 20_414),
                (30_000, 19_414),
                (30_000, 10_536),
                (30_536, 9_536),
                (49_464, -6_856),
                (50_000, -7_856)
            ]
        )
    );
    // Rounds have no width: the same under both.
    let rounds = src.replace("P0000", "P1111");
    assert_eq!(
        run(&rounds, &machine(ProfileName::Gsk980, &[])).unwrap(),
        run(&rounds, &machine(ProfileName::Gsk980, &["R-G75CHAMFER=axial-width"])).unwrap()
    );
}

/// R-G75CHAMFER's corner alarms at their edge (docs/G75.md §3, the same
/// comparisons of tangent lengths): 980TDi IS-B, S = (X50, Z30), H-10 (Y/f
/// = 5 000), D-4 (d = 4 000), A90, B60, D(r3) 2, E(r4) 3 (chamfers). The
/// bottom alarm is t3 + t4 > d.
///
/// `equal-legs`: t3 + t4 = 2 000 + 3 000 = 5 000 > 4 000: CornerTooLarge
/// (bottom). `axial-width`: t3 = 2 000/(1 + cos 90°) = 2 000, t4 =
/// 3 000/(1 + cos 60°) = 2 000: t3 + t4 = 4 000 = d, the corners meet:
/// accepted (the single plunge at u = t3 = 2 000 = d − t4, Z28); E3.001:
/// t4 = 3 001/1.5 = 2 000.667 > 2 000: CornerTooLarge (bottom).
///
/// Flank A (t1 + t3 > (Y/f)/sin a), with a slope: H-2 (Y/f = 1 000), D-5,
/// A90 B90 L60, A(r1) 0.3, D(r3) 0.4. `axial-width`: t1 = 300/(cos 90° +
/// cos 60°) = 600, t3 = 400/(1 + 0) = 400: t1 + t3 = 1 000 = 1 000/sin 90°:
/// accepted; D0.401: 1 001 > 1 000, CornerTooLarge (flank A). `equal-legs`
/// accepts both (700 and 701).
#[test]
fn g75_chamfer_axial_width_corner_limits() {
    use cycleref::GrooveEdge;
    let axial = machine(ProfileName::Gsk980, &["R-G75CHAMFER=axial-width"]);
    let default = machine(ProfileName::Gsk980, &[]);
    let too_large = |src: &str, m: &Machine, edge: GrooveEdge| {
        let e = run(src, m).unwrap_err();
        assert_eq!(e, ErrorKind::Cycle(CycleError::CornerTooLarge { edge }), "{src}");
    };
    let bottom = |e: &str| {
        format!(
            "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P1000 Q1000 H-10 D-4 A90 B60\nG75.1 D2 E{e} P0000\nM30\n"
        )
    };
    too_large(&bottom("3"), &default, GrooveEdge::Bottom);
    let meet = run(&bottom("3"), &axial).unwrap();
    let pecks: Vec<Point> = meet.iter().filter(|m| matches!(m.role, Role::Peck(_))).map(|m| m.to).collect();
    assert!(pecks.iter().all(|p| p.z == 28_000), "{pecks:?}");
    assert_eq!(pecks.last(), Some(&Point::new(40_000, 28_000)));
    too_large(&bottom("3.001"), &axial, GrooveEdge::Bottom);
    let flank = |r3: &str| {
        format!(
            "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P1000 Q1000 H-2 D-5 A90 B90 L60\nG75.1 J2 A0.3 D{r3} P0000\nM30\n"
        )
    };
    assert!(run(&flank("0.4"), &axial).is_ok());
    too_large(&flank("0.401"), &axial, GrooveEdge::FlankA);
    assert!(run(&flank("0.4"), &default).is_ok());
    assert!(run(&flank("0.401"), &default).is_ok());
}

/// R-G75SLOPE `falls-towards-d`, 980TDi IS-B, from X60 Z40: S = (X50,
/// Z30), H-10 (Y = 10 000 on the diameter, Y/f = 5 000), D-4 (d = 4 000),
/// A90 B60 L30, J2, a 0.5 mm chamfer at A(r1) and a 0.5 mm round at B(r2)
/// (P0100). Local frame: u towards -Z from Z30, y towards -X from X50 (f =
/// 2). cot 90° = 0, cot 60° = 1/√3, tan 30° = 1/√3: P1 = (0, 10 000), P2 =
/// (4 000, 10 000).
///
/// Falling (y = +f·u·tan L): u3 = (4 000 + 5 000/√3)/(1 + tan 30°·cot 60°)
/// = (4 000 + 2 886.751)·3/4 = 5 165.064, y3 = 2·u3/√3 = 5 964.102 < Y
/// (the opening meets flank B above the bottom). r1 (chamfer) t1 = 500:
/// T1s = (−500·cos 30°, −2·500·sin 30°) = (−433.013, −500): X50.5 Z30.433;
/// T1a = (0, 1 000): X49 Z30. r2 (round ρ = 500): t2 = 500·tan((60° +
/// 30°)/2) = 500: T2b = (u3 − 500·cos 60°, y3 + 2·500·sin 60°) =
/// (4 915.064, 6 830.127): X43.170 Z25.085; T2s = (u3 + 500·cos 30°, y3 +
/// 2·500·sin 30°) = (5 598.076, 6 464.102): X43.536 Z24.402; C2 = T2b +
/// 500·(sin 60°, 2·cos 60°) = (5 348.076, 7 330.127): X42.670 Z24.652. The
/// round turns as the default's (cross product ρ²·sin(b + L) > 0; sx·sz =
/// +1: G03, R-G75ARCDIR).
///
/// Moves: y_top = 0 (S is the opening's highest point); A11 = (ceil(left(Y)),
/// 0) = (0, 0): rapid to X50 Z30; along X to min(0, −500): X50.5, along Z
/// to Z30.433 (T1s); feeds to T1a, P1 (X40 Z30), P2 (X40 Z26), T2b, the
/// arc to T2s; back along X to min(0, 6 464) = 0: X50 Z24.402, along Z to
/// Z30; rapid to X60 Z40.
///
/// Rising (default): u3 = 6 886.751/(1 − 1/3) = 10 330.127, y3 =
/// −11 928.203, y_top = −11 929 (X61.929); T1s = (−433.013, +500): X49.5
/// Z30.433; t2 = 500·tan 15° = 133.975: T2b = (10 263.140, −11 696.152):
/// X61.696 Z19.737; T2s = (10 446.152, −12 062.178): X62.062 Z19.554; C2 =
/// (10 696.152, −11 196.152): X61.196 Z19.304.
#[test]
fn g75_slope_falls_towards_d() {
    let src = "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P1000 Q1000 H-10 D-4 A90 B60 L30\n\
               G75.1 J2 A0.5 B0.5 P0100\nM30\n";
    let arcs = |moves: &[Move]| -> Vec<(Point, bool)> {
        moves
            .iter()
            .filter_map(|m| match m.motion {
                cycleref::Motion::Arc { centre, clockwise } => Some((centre, clockwise)),
                _ => None,
            })
            .collect()
    };
    let falls = run(src, &machine(ProfileName::Gsk980, &["R-G75SLOPE=falls-towards-d"])).unwrap();
    assert_eq!(
        kinds(&falls),
        [
            (true, 50_000, 30_000),
            (true, 50_500, 30_000),
            (true, 50_500, 30_433),
            (false, 49_000, 30_000),
            (false, 40_000, 30_000),
            (false, 40_000, 26_000),
            (false, 43_170, 25_085),
            (false, 43_536, 24_402),
            (true, 50_000, 24_402),
            (true, 50_000, 30_000),
            (true, 60_000, 40_000),
        ]
    );
    assert_eq!(arcs(&falls), [(Point::new(42_670, 24_652), false)]);
    let rises = run(src, &machine(ProfileName::Gsk980, &[])).unwrap();
    assert_eq!(
        kinds(&rises),
        [
            (true, 61_929, 30_000),
            (true, 61_929, 30_433),
            (true, 49_500, 30_433),
            (false, 49_000, 30_000),
            (false, 40_000, 30_000),
            (false, 40_000, 26_000),
            (false, 61_696, 19_737),
            (false, 62_062, 19_554),
            (true, 62_062, 30_000),
            (true, 50_000, 30_000),
            (true, 60_000, 40_000),
        ]
    );
    assert_eq!(arcs(&rises), [(Point::new(61_196, 19_304), false)]);
}

/// R-G75SLOPE's alarms at their edges, 980TDi IS-B, S = (X50, Z30).
///
/// L < A under `falls-towards-d` (flank A must go down from S below the
/// falling opening), L < B under `rises-towards-d`: A30 B90 L30 is refused
/// falling (`slope_not_below_flank_a`) and accepted rising; A90 B30 L45 the
/// other way round.
///
/// The opening must meet flank B above the bottom, y3 < Y: A90 B90 L45, H-8
/// (Y = 8 000), D-4: u3 = 4 000/(1 + 1·0) = 4 000, y3 = 2·4 000·tan 45° =
/// 8 000 = Y: refused (`opening_below_bottom`, flank B would have no
/// length); D-3.999: y3 = 7 998 < 8 000, accepted.
///
/// CornerTooLarge on flank B with the falling y3: H-8 D-3, A90 B90 L45:
/// y3 = 6 000, flank B = ((8 000 − 6 000)/2)/sin 90° = 1 000; E(r4) 0.6
/// and B(r2) 0.4 chamfers (equal legs): 600 + 400 = 1 000, accepted; B0.401
/// refused (flank B). Rising, y3 = −6 000 and flank B is 7 000 long: both
/// accepted.
#[test]
fn g75_slope_falls_alarms() {
    use cycleref::GrooveEdge;
    let falls = machine(ProfileName::Gsk980, &["R-G75SLOPE=falls-towards-d"]);
    let rises = machine(ProfileName::Gsk980, &[]);
    let groove = |words: &str, block2: &str| {
        format!("M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P1000 Q1000 {words}\nG75.1 J2 {block2}\nM30\n")
    };
    let a30 = groove("H-8 D-4 A30 B90 L30", "");
    let e = run(&a30, &falls).unwrap_err();
    assert_eq!(e, ErrorKind::Cycle(CycleError::SlopeNotBelowFlankA { slope: 300_000, flank_a: 300_000 }));
    assert!(run(&a30, &rises).is_ok());
    let b30 = groove("H-8 D-1 A90 B30 L45", "");
    assert!(run(&b30, &falls).is_ok());
    let e = run(&b30, &rises).unwrap_err();
    assert_eq!(e, ErrorKind::Cycle(CycleError::SlopeNotBelowFlank { slope: 450_000, flank_b: 300_000 }));
    let edge = groove("H-8 D-4 A90 B90 L45", "");
    assert_eq!(run(&edge, &falls).unwrap_err(), ErrorKind::Cycle(CycleError::OpeningBelowBottom));
    assert!(run(&edge, &rises).is_ok());
    assert!(run(&groove("H-8 D-3.999 A90 B90 L45", ""), &falls).is_ok());
    let corners = |r2: &str| groove("H-8 D-3 A90 B90 L45", &format!("B{r2} E0.6 P0000"));
    assert!(run(&corners("0.4"), &falls).is_ok());
    assert_eq!(
        run(&corners("0.401"), &falls).unwrap_err(),
        ErrorKind::Cycle(CycleError::CornerTooLarge { edge: GrooveEdge::FlankB })
    );
    assert!(run(&corners("0.401"), &rises).is_ok());
}

/// R-LCNC-G7: from G8 (radius) at X10 Z2, `G7 G76 P1.5 Z-10 I-2 J0.6
/// K1.84`; and from G7 (diameter) at X20 Z2, `G8 G76 P1.5 Z-10 I-1 J0.3
/// K0.92`. Under `as-interpreter` LinuxCNC's `convert_lathe_diameter_mode`
/// (interp_convert.cc l.2773-2777) halves I, J and K when the block
/// switches to G7 (then the cycle halves them again as diameters, l.5724-
/// 5728): as radii I = −0.5, J = 0.15, K = 0.46; pass 1 (depth J) goes out
/// to X0 + K − J = 10 + 0.31 = 10.31 and in to X0 + I − J = 10 − 0.65 =
/// 9.35 (radii; `rs274 -g` prints STRAIGHT_TRAVERSE(10.3100, …) then
/// (9.3500, …)), written in G7 as the diameters 20.62 and 18.70. Switching
/// to G8 doubles them: I = −2, J = 0.6, K = 1.84 as radii from X10 (radius
/// of X20): out 10 + 1.24 = 11.24, in 10 − 2.6 = 7.40. The default refuses
/// both blocks; a word whose half is no increment is refused.
#[test]
fn x_mode_switch_in_a_linuxcnc_g76() {
    let to_g7 = "G18 G8 G21\nG0 X10 Z2\nM3 S500\nG7 G76 P1.5 Z-10 I-2 J0.6 K1.84\nM2\n";
    let to_g8 = "G18 G7 G21\nG0 X20 Z2\nM3 S500\nG8 G76 P1.5 Z-10 I-1 J0.3 K0.92\nM2\n";
    let lcnc = machine(ProfileName::LinuxCnc, &[]);
    for src in [to_g7, to_g8] {
        let e = read(src, &lcnc).unwrap_err();
        assert_eq!(e.line, 4);
        assert!(matches!(e.kind, ErrorKind::Unsupported(_)), "{e}");
    }
    let interp = machine(ProfileName::LinuxCnc, &["R-LCNC-G7=as-interpreter"]);
    // 0.0001 mm increments.
    let first_two = |src: &str| -> Vec<(Role, Point)> { ends(&run(src, &interp).unwrap())[..2].to_vec() };
    assert_eq!(
        first_two(to_g7),
        [(Role::Approach, Point::new(206_200, 20_000)), (Role::Approach, Point::new(187_000, 20_000))]
    );
    assert_eq!(
        first_two(to_g8),
        [(Role::Approach, Point::new(112_400, 20_000)), (Role::Approach, Point::new(74_000, 20_000))]
    );
    let odd = "G18 G8 G21\nG0 X10 Z2\nM3 S500\nG7 G76 P1.5 Z-10 I-2 J0.0001 K1.84\nM2\n";
    let e = read(odd, &interp).unwrap_err();
    assert_eq!((e.line, e.word.as_deref()), (4, Some("J0.0001")), "{e}");
    assert!(matches!(e.kind, ErrorKind::NotInIncrements { .. }), "{e}");
}
