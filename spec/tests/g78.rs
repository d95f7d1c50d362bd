//! G78: golden tests worked by hand from the 980TDi and 988TA G78 pages
//! (manuals/gsk980tdi-g78.txt, manuals/gsk988ta-g78.txt), every infeed
//! mode and both depth modes, and the equality with G76 where the modes
//! coincide. Each expected point is derived in the comments; both engines
//! must give it.
//!
//! The common thread (the 988TA's example, "直螺纹示例"): A = X80 Z10, D =
//! X60 Z-60, k = 3, Δd = 1.8, Δdmin = 0.15, d = 0.5 (so k - d = 2.5), m =
//! 2 finishing passes, a = 45°, J1.5 K2, IS-B mm, diameter X. External
//! (s = +1), towards -Z (t = -1), straight (i = 0): C = (60, 10).
//!
//! * Decreasing depths: D1 = 1.8; D2 = min(2.5, round(1.8 √2) = 2.546) =
//!   2.5 (the figure's "1.8mm", "2.5mm", "0.5mm", "k=3mm").
//! * X of a pass at depth D: 60 + 2 (3 - D): 62.4, 61.0; finishing 60.
//! * tan 22.5° = 0.41421356…: right(1.8) = round(745.58) = 0.746, right(2.5)
//!   = round(1035.53) = 1.036 = zc; left(D) = 2 zc - right(D): left(1.8) =
//!   1.326, left(2.5) = 1.036.
//! * Z of a pass = 10 - shift. Every pass: cut to Z-58 (K2 before D), run-out
//!   to X + 3 (J1.5 radius) at Z-60, retract to X80, return to Z10.

use cycleref::{Flank, Move, PassKind, Role};
use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::profile::Machine;
use cycleref_spec::{read, ErrorKind, ProfileName};

/// The G76/G78 cycles of a program, each expanded by both engines (which
/// must agree).
fn cycles(src: &str, m: &Machine) -> Vec<(&'static str, Vec<Move>)> {
    let p = read(src, m).unwrap_or_else(|e| panic!("{e}"));
    p.items
        .iter()
        .filter_map(Cycle::of)
        .map(|c| {
            let ours: Vec<Move> = expand(c, Engine::Impl).unwrap_or_else(|e| panic!("{e}")).collect();
            let reference: Vec<Move> = expand(c, Engine::Spec).unwrap_or_else(|e| panic!("{e}")).collect();
            assert_eq!(ours, reference, "line {}", c.line());
            (c.code(), ours)
        })
        .collect()
}

/// The passes of a cycle: (kind, depth, flank, X, Z of the pass start).
fn passes(moves: &[Move]) -> Vec<(PassKind, i64, Flank, i64, i64)> {
    moves
        .iter()
        .filter(|m| m.role == Role::Approach)
        .map(|m| {
            let p = m.pass.expect("a pass");
            (p.kind, p.depth, p.flank, m.to.x, m.to.z)
        })
        .collect()
}

fn gsk988() -> Machine {
    Machine::new(ProfileName::Gsk988)
}

fn gsk980() -> Machine {
    Machine::new(ProfileName::Gsk980)
}

const HEAD: &str = "M3 S300\nG00 X80 Z10\n";

/// 988TA block 2 with the example's words.
fn g988(p: &str, block1_extra: &str) -> String {
    format!("{HEAD}G78 P{p} Q0.15 R0.5{block1_extra}\nG78 X60 Z-60 P3 Q1.8 F300 J1.5 K2\nG00 X80 Z10\nM30\n")
}

use Flank::{Centre, Left, Right};
use PassKind::{Finish, Rough};

/// The finishing passes: at depth 3, X60, from the last rough Z (zc).
const FINISH: [(PassKind, i64, Flank, i64, i64); 2] =
    [(Finish, 3_000, Centre, 60_000, 8_964), (Finish, 3_000, Centre, 60_000, 8_964)];

fn with_finish(rough: &[(PassKind, i64, Flank, i64, i64)]) -> Vec<(PassKind, i64, Flank, i64, i64)> {
    rough.iter().copied().chain(FINISH).collect()
}

/// The page's example writes P020545: r = 05, outside the page's own range
/// of P(r) (0~4), so it is refused, naming the word and the range (reading
/// R-G78P). With r = 02 (right flank) the figure's passes follow, and they
/// are G76's D0 passes for the same words, move for move.
#[test]
fn gsk988_example_and_g76() {
    let m = gsk988();
    let e = read(&g988("020545", ""), &m).expect_err("r = 05 is refused");
    assert_eq!((e.line, e.word.as_deref()), (3, Some("P020545")));
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    assert!(e.to_string().contains("infeed mode r 00..04"), "{e}");

    let got = cycles(&g988("020245", ""), &m);
    assert_eq!(got.len(), 1);
    let (code, moves) = &got[0];
    assert_eq!(*code, "G78");
    assert_eq!(
        passes(moves),
        with_finish(&[(Rough, 1_800, Right, 62_400, 9_254), (Rough, 2_500, Right, 61_000, 8_964)])
    );
    // Pass 1 in full: cut to Z-58, run-out to X65.4 at Z-60, retract, return.
    let ends: Vec<(i64, i64)> = moves[..5].iter().map(|m| (m.to.x, m.to.z)).collect();
    assert_eq!(
        ends,
        [(62_400, 9_254), (62_400, -58_000), (65_400, -60_000), (80_000, -60_000), (80_000, 10_000)]
    );
    // G76 with the same words (D0; the chamfer digits r do not matter with J
    // and K given) cuts the same moves.
    let g76 = format!("{HEAD}G76 P020045 Q0.15 R0.5\nG76 X60 Z-60 P3 Q1.8 F300 J1.5 K2\nM30\n");
    let same = cycles(&g76, &m);
    assert_eq!(same[0].0, "G76");
    assert_eq!(&same[0].1, moves);
}

/// Every 988TA infeed mode on the example's thread (decreasing depths).
#[test]
fn gsk988_infeed_modes() {
    let m = gsk988();
    let rough = |r: &str| passes(&cycles(&g988(&format!("02{r}45"), ""), &m)[0].1);
    // r = 0, the centre line: every pass at zc.
    assert_eq!(
        rough("00"),
        with_finish(&[(Rough, 1_800, Centre, 62_400, 8_964), (Rough, 2_500, Centre, 61_000, 8_964)])
    );
    // r = 1, the left flank: 10 - left(D): 8.674, 8.964.
    assert_eq!(
        rough("01"),
        with_finish(&[(Rough, 1_800, Left, 62_400, 8_674), (Rough, 2_500, Left, 61_000, 8_964)])
    );
    // r = 3, right and centre in turn (G76 D1).
    assert_eq!(
        rough("03"),
        with_finish(&[(Rough, 1_800, Right, 62_400, 9_254), (Rough, 2_500, Centre, 61_000, 8_964)])
    );
    // r = 4, left and right in equal amounts (G76 D2): level 1 twice.
    assert_eq!(
        rough("04"),
        with_finish(&[
            (Rough, 1_800, Right, 62_400, 9_254),
            (Rough, 1_800, Left, 62_400, 8_674),
            (Rough, 2_500, Right, 61_000, 8_964)
        ])
    );
    // G76 D1 and D2 give the same passes as r = 3 and r = 4.
    for (r, d) in [("03", "1"), ("04", "2")] {
        let g76 = format!("{HEAD}G76 P020045 Q0.15 R0.5 D{d}\nG76 X60 Z-60 P3 Q1.8 F300 J1.5 K2\nM30\n");
        assert_eq!(cycles(&g76, &m)[0].1, cycles(&g988(&format!("02{r}45"), ""), &m)[0].1, "r = {r}, D{d}");
    }
}

/// Equal steps (988TA D0, "等距离进刀的每次切削量为 Q(△d)") with Δd = 0.8:
/// 0.8, 1.6, 2.4, then k - d = 2.5 (its cut 0.1 below Δdmin: the last
/// level takes what remains). X: 64.4, 62.8, 61.2, 61.0. right(D): round(800
/// × 0.41421356) = 0.331, 0.663 (662.74), 0.994 (994.11), 1.036.
///
/// With D1 (decreasing, R-DEPTH: Dn = min(k - d, max(Nn, D(n-1) + Δdmin)),
/// Nn = round(0.8 √n), Δdmin = 0.15, k - d = 2.5), in increments:
///
/// | n | 800 √n | Nn | D(n-1) + 150 | Dn | X = 60 + 2 (3 - Dn) | right(Dn) = round(Dn tan 22.5°) | Z = 10 - right |
/// |---|---|---|---|---|---|---|---|
/// | 1 | 800 | 800 | - | 800 | 64.400 | 331.37 → 331 | 9.669 |
/// | 2 | 1131.37 | 1131 | 950 | 1131 | 63.738 | 468.48 → 468 | 9.532 |
/// | 3 | 1385.64 | 1386 | 1281 | 1386 | 63.228 | 574.10 → 574 | 9.426 |
/// | 4 | 1600 | 1600 | 1536 | 1600 | 62.800 | 662.74 → 663 | 9.337 |
/// | 5 | 1788.85 | 1789 | 1750 | 1789 | 62.422 | 741.03 → 741 | 9.259 |
/// | 6 | 1959.59 | 1960 | 1939 | 1960 | 62.080 | 811.86 → 812 | 9.188 |
/// | 7 | 2116.60 | 2117 | 2110 | 2117 | 61.766 | 876.89 → 877 | 9.123 |
/// | 8 | 2262.74 | 2263 | 2267 | 2267 | 61.466 | 939.02 → 939 | 9.061 |
/// | 9 | 2400 | 2400 | 2417 | 2417 | 61.166 | 1001.15 → 1001 | 8.999 |
/// | 10 | 2529.82 | 2530 | 2567 | min(2500, 2567) = 2500 | 61.000 | 1035.53 → 1036 | 8.964 |
///
/// From level 8 the minimum cut takes over (N8 = 2.263 < 2.117 + 0.15 =
/// 2.267) and stays (R-LINEAR: 2.417, not N9 = 2.4): an earlier comment
/// here listed 2.263 and 2.4, the law without Δdmin.
///
/// The lead: this test writes F3; the page's example writes F300, which
/// cycleref takes as written (GSK F without a decimal point is mm, R-POINT:
/// a 300 mm lead, inside the 988TA's F table 0.0001~9999; `g988` above uses
/// it), and which changes no pass point here since J and K are given.
#[test]
fn gsk988_equal_depths() {
    let m = gsk988();
    let src = format!("{HEAD}G78 P020245 Q0.15 R0.5 D0\nG78 X60 Z-60 P3 Q0.8 F3 J1.5 K2\nM30\n");
    assert_eq!(
        passes(&cycles(&src, &m)[0].1),
        with_finish(&[
            (Rough, 800, Right, 64_400, 9_669),
            (Rough, 1_600, Right, 62_800, 9_337),
            (Rough, 2_400, Right, 61_200, 9_006),
            (Rough, 2_500, Right, 61_000, 8_964)
        ])
    );
    let decreasing = format!("{HEAD}G78 P020245 Q0.15 R0.5 D1\nG78 X60 Z-60 P3 Q0.8 F3 J1.5 K2\nM30\n");
    assert_eq!(
        passes(&cycles(&decreasing, &m)[0].1),
        with_finish(&[
            (Rough, 800, Right, 64_400, 9_669),
            (Rough, 1_131, Right, 63_738, 9_532),
            (Rough, 1_386, Right, 63_228, 9_426),
            (Rough, 1_600, Right, 62_800, 9_337),
            (Rough, 1_789, Right, 62_422, 9_259),
            (Rough, 1_960, Right, 62_080, 9_188),
            (Rough, 2_117, Right, 61_766, 9_123),
            (Rough, 2_267, Right, 61_466, 9_061),
            (Rough, 2_417, Right, 61_166, 8_999),
            (Rough, 2_500, Right, 61_000, 8_964)
        ])
    );
}

/// The 980TDi's format: `G78 P(m)(r)(a) Q(Δdmin) R(d) J K D L E` with m
/// the depth mode, r the infeed (0-3), D the finishing passes; P and Q of
/// block 2 and Q(Δdmin) in increments (No.182.7 = 0). The example's thread
/// with m = 1 (decreasing), r = 2: the same passes as the 988TA's.
#[test]
fn gsk980_format() {
    let m = gsk980();
    let src = format!("{HEAD}G78 P010245 Q150 R0.5 J1.5 K2 D2\nG78 X60 Z-60 P3000 Q1800 F3\nM30\n");
    assert_eq!(
        passes(&cycles(&src, &m)[0].1),
        with_finish(&[(Rough, 1_800, Right, 62_400, 9_254), (Rough, 2_500, Right, 61_000, 8_964)])
    );
}

/// The 980TDi's r = 3 (交错切入, reading R-G78ALT): one pass a level, odd
/// levels on the right flank, even levels on the left. With m = 0 (equal
/// steps) and Δd = 0.8: levels 0.8 (right, Z 10 - 0.331), 1.6 (left, 2.072 -
/// 0.663 = 1.409: Z 8.591), 2.4 (right, Z 9.006), 2.5 (left, 2.072 - 1.036:
/// Z 8.964).
#[test]
fn gsk980_alternating_flanks_with_equal_depths() {
    let m = gsk980();
    let src = format!("{HEAD}G78 P000345 Q150 R0.5 J1.5 K2 D2\nG78 X60 Z-60 P3000 Q800 F3\nM30\n");
    assert_eq!(
        passes(&cycles(&src, &m)[0].1),
        with_finish(&[
            (Rough, 800, Right, 64_400, 9_669),
            (Rough, 1_600, Left, 62_800, 8_591),
            (Rough, 2_400, Right, 61_200, 9_006),
            (Rough, 2_500, Left, 61_000, 8_964)
        ])
    );
}

/// The 980TDi's figures ("代码轨迹：(下图轨迹均为递减式进刀)"): P(r)=0 "从牙型
/// 中间切入", P(r)=1 "左边切入" and P(r)=3 "左右两边轮流切入", all with m = 1
/// (递减式进刀, "与 G76 进刀方式相同"), on the gsk980 profile (P(k), Q(Δd),
/// Q(Δdmin) in increments, No.182.7 = 0).
///
/// `G78 P1r60 Q150 R0.5 J1.5 K2 D1` / `G78 X60 Z-60 P3000 Q1000 F3` from A
/// = X80 Z10: k = 3, Δd = 1, Δdmin = 0.15, d = 0.5 (k - d = 2.5), a = 60°,
/// one finishing pass (D1). External, towards -Z, straight: C = (60, 10).
///
/// Depths (R-DEPTH, increments): round(1000 √n) = 1000, 1414 (1414.21; ≥
/// 1000 + 150), 1732 (1732.05; ≥ 1564), 2000 (≥ 1882), 2236 (2236.07; ≥
/// 2150), 2449 (2449.49; ≥ 2386), then round(1000 √7) = 2646 ≥ 2500 =
/// k - d: seven levels. X = 60 + 2 (3 - D): 64, 63.172, 62.536, 62, 61.528,
/// 61.102, 61.
///
/// tan 30° = 0.57735027: right(D) = round(D tan 30°) = 577 (577.35), 816
/// (816.37), 1000 (999.97), 1155 (1154.70), 1291 (1290.96), 1414
/// (1413.93), 1443 (1443.38) = zc. left(D) = 2 zc - right(D) = 2886 -
/// right: 2309, 2070, 1886, 1731, 1595, 1472, 1443 (R-G78INFEED). Z = 10 -
/// shift: right 9.423, 9.184, 9.000, 8.845, 8.709, 8.586, 8.557; left
/// 7.691, 7.930, 8.114, 8.269, 8.405, 8.528, 8.557; centre 8.557 on every
/// level. The finishing pass: depth 3, X60, Z of the last rough pass
/// (8.557), centre.
///
/// r = 3 (R-G78ALT): one pass a level, odd levels right, even left:
/// 9.423, 7.930, 9.000, 8.269, 8.709, 8.528, 8.557 (level 7, right: zc).
///
/// The r = 3 figure's dimension labels survive in the extraction only as
/// fragments ("△d", "2 2 2", "2 +2 2", "2△d"); what they can and cannot
/// say about R-G78ALT is written in that reading.
#[test]
fn gsk980_figures() {
    let m = gsk980();
    let run = |r: u8| {
        let src = format!(
            "{HEAD}G78 P1{r:02}60 Q150 R0.5 J1.5 K2 D1\nG78 X60 Z-60 P3000 Q1000 F3\nG00 X80 Z10\nM30\n"
        );
        passes(&cycles(&src, &m)[0].1)
    };
    let depths = [1_000, 1_414, 1_732, 2_000, 2_236, 2_449, 2_500];
    let xs = [64_000, 63_172, 62_536, 62_000, 61_528, 61_102, 61_000];
    let right = [9_423, 9_184, 9_000, 8_845, 8_709, 8_586, 8_557];
    let left = [7_691, 7_930, 8_114, 8_269, 8_405, 8_528, 8_557];
    let finish = (Finish, 3_000, Centre, 60_000, 8_557);
    let want = |flank: &dyn Fn(usize) -> (Flank, i64)| {
        let mut v: Vec<_> = (0..7)
            .map(|i| {
                let (f, z) = flank(i);
                (Rough, depths[i], f, xs[i], z)
            })
            .collect();
        v.push(finish);
        v
    };
    // r = 0: the centre line.
    assert_eq!(run(0), want(&|_| (Centre, 8_557)));
    // r = 1: the left flank.
    assert_eq!(run(1), want(&|i| (Left, left[i])));
    // r = 3: right on levels 1, 3, 5, 7, left on 2, 4, 6.
    assert_eq!(run(3), want(&|i| if i % 2 == 0 { (Right, right[i]) } else { (Left, left[i]) }));
    // r = 2, the right flank, for completeness: G76's D0.
    assert_eq!(run(2), want(&|i| (Right, right[i])));
}

/// The parameters when block 1 is absent: the infeed mode (No.062, 5144)
/// and the depth mode (No.061, 5145). By default right flank and decreasing
/// (reading R-PARAM): G76's D0. 5144 = 0 makes it the centre line.
#[test]
fn parameters_when_words_are_omitted() {
    let mut m = gsk988();
    let src = format!("{HEAD}G78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nM30\n");
    // The defaults: 5142 = 1 finishing pass, 5140 = 5141 = 0 (k - d = 3),
    // 5143 = 60° (tan 30° = 0.57735027). Levels round(1.8 √n): 1.8, 2.546
    // (2.5456), then min(3, 3.118) = 3. X: 62.4, 60.908, 60. right(D):
    // round(1039.23) = 1.039, round(1469.93) = 1.470, round(1732.05) = 1.732
    // = zc; Z = 10 - right: 8.961, 8.530, 8.268.
    let p = passes(&cycles(&src, &m)[0].1);
    assert_eq!(
        p,
        [
            (Rough, 1_800, Right, 62_400, 8_961),
            (Rough, 2_546, Right, 60_908, 8_530),
            (Rough, 3_000, Right, 60_000, 8_268),
            (Finish, 3_000, Centre, 60_000, 8_268)
        ]
    );
    m.apply_toml("[parameters]\n5144 = 0\n5145 = 0\n").unwrap();
    let p = passes(&cycles(&src, &m)[0].1);
    // Equal steps of 1.8: 1.8, then min(3, 3.6) = 3; both on the centre line.
    assert_eq!(
        p,
        [
            (Rough, 1_800, Centre, 62_400, 8_268),
            (Rough, 3_000, Centre, 60_000, 8_268),
            (Finish, 3_000, Centre, 60_000, 8_268)
        ]
    );
}

/// The 980TDi's parameters when G78's words are omitted (the page: "未输入
/// m 时，以系统数据参数№.061 的值作为切深方式选择", "未输入 r 时 … №.062",
/// "未输入 a 时 … №.058", "未输入 Q(△dmin)时 … №.059", "未输入 R(d)时 …
/// №.060"; the finishing passes No.057, reading R-G78WORDS), set through
/// `Machine::apply_toml` to values other than the defaults (R-PARAM: 57 =
/// 1, 58 = 60, 59 = 60 = 0, 61 = 1, 62 = 2).
///
/// The thread: A = X80 Z10, `G78 X60 Z-60 P3000 Q800 F3` (k = 3, Δd = 0.8,
/// increments), no J/K (block 1 absent: No.19 = 0, no run-out). a = 29°
/// from No.058: tan 14.5° = 0.25861758.
///
/// 1. No block 1; 57 = 2, 58 = 29, 59 = 0.2, 60 = 0.3, 61 = 0 (equal), 62 =
///    1 (left). k - d = 2.7; equal steps of max(0.8, 0.2) = 0.8: 0.8, 1.6,
///    2.4, then min(2.7, 3.2) = 2.7. X = 60 + 2 (3 - D): 64.4, 62.8, 61.2,
///    60.6. right(D) = round(D tan 14.5°): 207 (206.89), 414 (413.79), 621
///    (620.68), 698 (698.27) = zc; left = 2·698 - right: 1189, 982, 775,
///    698; Z = 10 - left: 8.811, 9.018, 9.225, 9.302. Two finishing passes
///    at depth 3, X60, Z9.302.
/// 2. No block 1; as 1 but 57 = 0 (no finishing pass), 61 = 1 (decreasing),
///    62 = 3 (flanks in turn, R-G78ALT). round(800 √n): 800, 1131 (≥ 1000),
///    1386 (≥ 1331), 1600 (≥ 1586), then N5 = 1789 < 1600 + 200: the
///    minimum cut takes over, 1800, 2000, 2200, 2400, 2600, then min(2700,
///    2800) = 2700: ten levels. X: 64.4, 63.738, 63.228, 62.8, 62.4, 62.0,
///    61.6, 61.2, 60.8, 60.6. right: 207, 292 (292.50), 358 (358.44), 414,
///    466 (465.51), 517 (517.24), 569 (568.96), 621, 672 (672.41), 698;
///    odd levels right (Z = 10 - right), even left (Z = 10 - (1396 -
///    right)): 9.793, 8.896, 9.642, 9.018, 9.534, 9.121, 9.431, 9.225,
///    9.328, 9.302.
/// 3. Block 1 `G78 R0.5 D1` (P and Q omitted) with 1's parameters: d = 0.5
///    and one finishing pass from the block, the rest from 58, 59, 61, 62.
///    k - d = 2.5: 0.8, 1.6, 2.4, 2.5; X 64.4, 62.8, 61.2, 61.0; zc =
///    round(646.54) = 647; left = 1294 - right: 1087, 880, 673, 647; Z
///    8.913, 9.120, 9.327, 9.353; one finishing pass at X60 Z9.353.
#[test]
fn gsk980_parameters_when_words_are_omitted() {
    let body = "G78 X60 Z-60 P3000 Q800 F3\nG00 X80 Z10\nM30\n";
    let params = |m57: u8, m61: u8, m62: u8| {
        let mut m = gsk980();
        m.apply_toml(&format!(
            "[parameters]\n57 = {m57}\n58 = 29\n59 = \"0.2\"\n60 = \"0.3\"\n61 = {m61}\n62 = {m62}\n"
        ))
        .unwrap();
        m
    };
    let m = params(2, 0, 1);
    assert_eq!(
        passes(&cycles(&format!("{HEAD}{body}"), &m)[0].1),
        [
            (Rough, 800, Left, 64_400, 8_811),
            (Rough, 1_600, Left, 62_800, 9_018),
            (Rough, 2_400, Left, 61_200, 9_225),
            (Rough, 2_700, Left, 60_600, 9_302),
            (Finish, 3_000, Centre, 60_000, 9_302),
            (Finish, 3_000, Centre, 60_000, 9_302),
        ]
    );

    let m = params(0, 1, 3);
    assert_eq!(
        passes(&cycles(&format!("{HEAD}{body}"), &m)[0].1),
        [
            (Rough, 800, Right, 64_400, 9_793),
            (Rough, 1_131, Left, 63_738, 8_896),
            (Rough, 1_386, Right, 63_228, 9_642),
            (Rough, 1_600, Left, 62_800, 9_018),
            (Rough, 1_800, Right, 62_400, 9_534),
            (Rough, 2_000, Left, 62_000, 9_121),
            (Rough, 2_200, Right, 61_600, 9_431),
            (Rough, 2_400, Left, 61_200, 9_225),
            (Rough, 2_600, Right, 60_800, 9_328),
            (Rough, 2_700, Left, 60_600, 9_302),
        ]
    );

    let m = params(2, 0, 1);
    assert_eq!(
        passes(&cycles(&format!("{HEAD}G78 R0.5 D1\n{body}"), &m)[0].1),
        [
            (Rough, 800, Left, 64_400, 8_913),
            (Rough, 1_600, Left, 62_800, 9_120),
            (Rough, 2_400, Left, 61_200, 9_327),
            (Rough, 2_500, Left, 61_000, 9_353),
            (Finish, 3_000, Centre, 60_000, 9_353),
        ]
    );
}

/// The alarms: FANUC has no G78; the 980TDi's r stops at 3 and its m (the
/// depth mode) at 1; the 988TA's D (depth mode) is 0 or 1; G78 cannot cut
/// face threads (W0).
#[test]
fn alarms() {
    let e = read(&format!("{HEAD}G78 X60 Z-60 P3 Q1.8 F3\n"), &Machine::new(ProfileName::Fanuc)).unwrap_err();
    assert!(matches!(e.kind, ErrorKind::Unsupported(_)) && e.to_string().contains("G78"), "{e}");
    let e = read(&format!("{HEAD}G78 P010445 Q150 R0.5\n"), &gsk980()).unwrap_err();
    assert!(e.to_string().contains("infeed mode r 00..03"), "{e}");
    let e = read(&format!("{HEAD}G78 P020245 Q150 R0.5\n"), &gsk980()).unwrap_err();
    assert!(e.to_string().contains("depth mode"), "{e}");
    let e = read(&format!("{HEAD}G78 P020245 Q0.15 R0.5 D2\n"), &gsk988()).unwrap_err();
    assert_eq!(e.word.as_deref(), Some("D2"));
    let face = format!("{HEAD}G78 X60 W0 P3 Q1.8 F3\n");
    let e = read(&face, &gsk988()).expect_err("a face thread is refused");
    assert!(matches!(e.kind, ErrorKind::Cycle(cycleref::CycleError::FaceThread)), "{e}");
}

/// The alarms of the pages' word list, each on its line and word.
///
/// * P(k), Q(Δd) omitted: "未输入 P(k)时，系统报警", "未输入△d 时，系统报警" (both
///   pages): `Missing` at block 2 (line 4, no single word to blame), on both
///   GSK profiles.
/// * 980TDi: "G78 代码可加工直螺纹和锥螺纹不能加工端面螺纹": W0 is `FaceThread`
///   at its block 2; "D： 精车次数，取值范围为 0~99" and "L：螺纹头数，取值的范围是：
///   1～99": D100 and L100 are `OutOfRange` on block 1 (line 3), the word
///   named; D99 and L99 are accepted.
/// * 988TA: "P（m） 螺纹精车次数 01～99" (reading R-PSPLIT: m 01..99 on the
///   988TA, 00..99 on the 980TDi, where m is the depth mode 0-1, R-G78P):
///   P000245 (m = 00) is `OutOfRange` on P; on the 980TDi the same P is m =
///   0, equal depths, and is accepted.
#[test]
fn alarms_of_the_word_list() {
    let missing = |src: &str, m: &Machine, what: &str| {
        let e = read(src, m).expect_err("refused");
        assert_eq!((e.line, e.word.as_deref()), (4, None), "{e}");
        let ErrorKind::Missing { what: w, .. } = e.kind else { panic!("{e}") };
        assert!(w.contains(what), "{e}");
    };
    let (m980, m988) = (gsk980(), gsk988());
    // 980TDi: P(k) and Q(Δd) in increments (No.182.7 = 0).
    missing(&format!("{HEAD}G78 P010245 Q150 R0.5\nG78 X60 Z-60 Q1800 F3\n"), &m980, "P(k)");
    missing(&format!("{HEAD}G78 P010245 Q150 R0.5\nG78 X60 Z-60 P3000 F3\n"), &m980, "Q(");
    // 988TA: in mm (3401#6 = 0).
    missing(&format!("{HEAD}G78 P020245 Q0.15 R0.5\nG78 X60 Z-60 Q1.8 F3 J1.5 K2\n"), &m988, "P(k)");
    missing(&format!("{HEAD}G78 P020245 Q0.15 R0.5\nG78 X60 Z-60 P3 F3 J1.5 K2\n"), &m988, "Q(");

    // 980TDi face thread: W0 (the end point has the Z of A).
    let e = read(&format!("{HEAD}G78 P010245 Q150 R0.5\nG78 X60 W0 P3000 Q1800 F3\n"), &m980)
        .expect_err("a face thread is refused");
    assert_eq!((e.line, e.word.as_deref()), (4, None), "{e}");
    assert!(matches!(e.kind, ErrorKind::Cycle(cycleref::CycleError::FaceThread)), "{e}");

    // 980TDi D and L beyond 99.
    for word in ["D100", "L100"] {
        let e = read(&format!("{HEAD}G78 P010245 Q150 R0.5 {word}\nG78 X60 Z-60 P3000 Q1800 F3\n"), &m980)
            .expect_err(word);
        assert_eq!((e.line, e.word.as_deref()), (3, Some(word)), "{e}");
        assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    }
    let ok = format!("{HEAD}G78 P010245 Q150 R0.5 D99 L99\nG78 X60 Z-60 P3000 Q1800 F3 \n");
    assert!(read(&ok, &m980).is_ok());

    // 988TA m = 00: outside 01~99.
    let e = read(&format!("{HEAD}G78 P000245 Q0.15 R0.5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\n"), &m988)
        .expect_err("m = 00 is refused on the 988TA");
    assert_eq!((e.line, e.word.as_deref()), (3, Some("P000245")), "{e}");
    assert!(matches!(e.kind, ErrorKind::OutOfRange { .. }), "{e}");
    assert!(read(&format!("{HEAD}G78 P000245 Q150 R0.5\nG78 X60 Z-60 P3000 Q1800 F3\n"), &m980).is_ok());
}
