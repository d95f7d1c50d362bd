//! Readings per control (issue 34): the points of docs/INTERPRETATIONS.md
//! that the sources leave open, each a typed choice with named values, its
//! source and its default per profile.
//!
//! A [`Readings`] value is part of the [`Machine`](crate::profile::Machine)
//! (`[readings]` in the parameter file, `--reading ID=VALUE` on the
//! command line, `readings=` in Python, `readings` in the C options). The
//! program reader resolves it against the profile
//! ([`Readings::for_cycle`]) into the [`CycleReadings`] every threading
//! cycle carries, so the engine and the exact reference take the same
//! value; R-E980 is applied by the reader itself (it only decides whether a
//! word is accepted).
//!
//! Only readings implemented in both engines are listed ([`TABLE`]).

use core::fmt;
use cycleref::readings::PassEnd;
use cycleref::{CycleReadings, G75Readings};

use crate::profile::{ParamsError, ProfileName};

/// Reading R-RUNOUT: which profiles clamp the short-axis run-out J at the
/// retract distance of a pass without run-out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RunOutClamp {
    /// `all-profiles` (default): 988TA G92 note 5 ("当螺纹短轴方向退尾长度大
    /// 于无退尾时的退刀距离时，系统默认短轴方向退尾长度为无退尾时的退刀距离")
    /// adopted for every profile: the 980TDi and FANUC pages are silent, and
    /// the clamp keeps the run-out between the work and the retract point.
    #[default]
    AllProfiles,
    /// `gsk988-only`: the clamp only where its page says it (gsk988); on
    /// fanuc and gsk980 J is made as written, beyond the X of A (Z long) or
    /// beyond A's Z (X long) when it is longer, and the retract comes back
    /// to A's X.
    Gsk988Only,
}

/// Reading R-XRUNOUT: an X-long run-out whose cut line rises towards A
/// (s·i > 0), along Z towards A, ends inside the material.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum XRunOut {
    /// `refuse` (default): refused with `run_out_into_work`; the retract
    /// after it would cut through the thread (found by the
    /// `no_rapid_in_thread` harness, issue 13).
    #[default]
    Refuse,
    /// `towards-start`: the run-out towards the start point as written
    /// ("根据程序起点位置自动确定退尾方向"; no page calls it an alarm).
    TowardsStart,
}

/// Reading R-E980: a negative lead-in E on the 980TDi's G78, whose page
/// gives E the range "-9999.9999~9999.9999" while calling it "无符号".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum E980 {
    /// `refuse-negative` (default): "无符号" wins; a negative E is
    /// `out_of_range`, as every other unsigned length.
    #[default]
    RefuseNegative,
    /// `signed`: the range wins; a negative E is accepted and, being
    /// without direction ("无符号"), made as its magnitude, as the 980TDi
    /// G92 page does for J and K (note 10: "J、K输入负值时，按正值处理").
    Signed,
}

/// Reading R-LONG988: the long axis of a 988TA G92 or G78 on a steep taper
/// (|i| ≥ |W|).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Long988 {
    /// `displacement`: by the displacements, Z when |W| > |i| (radius), as
    /// the 980TDi G92 page ("B 点与 C 点 Z 轴坐标差的绝对值大于 X 轴(半径值)坐标差
    /// 的绝对值时，Z 轴为长轴；反之，X 轴为长轴") and seed 000 for G76.
    Displacement,
    /// `table` (default on gsk988): the 988TA G92 page's table "长轴/短轴的
    /// 判断": "P = 0（轴向螺纹）长轴：横轴" (Z in G18), whatever the
    /// displacements; the 988TA replaced the 980TDi's displacement sentence
    /// with it.
    Table,
}

/// Reading R-G78LEFT: where a left-flank pass lies (G78 r = 1, the left
/// passes of G78 r = 4 and G76 D2 左右等量轮流, the 980TDi's G78 r = 3 交错).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G78Left {
    /// `mirror-form-centre` (default): the right flank mirrored about the
    /// centre line of the final form, `2 zc - round(Dn tan(a/2))`: every
    /// pass stays inside the form the finishing passes cut.
    #[default]
    MirrorFormCentre,
    /// `mirror-b`: the right flank mirrored about B, `-round(Dn tan(a/2))`
    /// from the Z of A, so that "Bn 点相对于 B 点 X 轴和 Z 轴的位移符合公式
    /// tg(a/2)=│Z 轴位移│/│X 轴位移│" holds on every left pass.
    MirrorB,
}

/// Reading R-INFEED (with R-G78ALT): which flank a level of the modes that
/// cut both flanks in turn starts on (G76 D2 and the 988TA's G78 r = 4
/// 左右轮流切入, the 980TDi's G78 r = 3 交错切入).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum InfeedOrder {
    /// `right-first` (default): D2 and r = 4 cut each level on the right
    /// flank then on the left, the last level once on the right; 交错 cuts
    /// odd levels on the right, even on the left. D2 starts on the flank D0
    /// cuts ("0：刀刃沿螺纹牙型右边切入（原 G76 切入方式）"); the figures that
    /// would say which of Bx1/Bx2 is left are lost.
    #[default]
    RightFirst,
    /// `left-first`: the sides in the order the names list them ("左右轮流",
    /// "左右两边轮流", read as "右中轮流" is read, right first): each level
    /// left then right, the last level of D2 / r = 4 once on the left; 交错
    /// odd levels on the left, even on the right. The mirror image of
    /// `right-first` about the left flanks' mirror line (R-G78LEFT).
    LeftFirst,
}

/// Reading R-G78CENTRE: where G78 r = 0's passes lie ("刀刃沿螺纹牙型中线切入").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G78Centre {
    /// `form-centre` (default): on the centre line of the final form of
    /// the other modes, `zc = round((k - d) tan(a/2))` from the Z of A.
    #[default]
    FormCentre,
    /// `under-b`: radial infeed under B, at the Z of A.
    UnderB,
}

/// Reading R-LEADIN: where the lead-in (旋进, E) starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LeadIn {
    /// `same-z` (default): E out along X at the Z of Bn, as seed 000 and
    /// the 988TA say ("快速移动到与切削起点 Bn 距离为 E 的位置", E "X 向旋进距离
    /// 值"); the screw-in is a thread move along X only.
    #[default]
    SameZ,
    /// `whole-leads`: E out along X from Bn and the smallest whole number
    /// of leads not shorter than E back along Z (the default before issue
    /// 34); the screw-in runs along Z, in phase with a pass without
    /// lead-in, but An is not at the distance E from Bn.
    WholeLeads,
}

/// Reading R-HIGHSPEED: a G76 or a G78 on the 988TA when parameter 5129
/// (THM) selects the high-speed threading mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum HighSpeed {
    /// `g92-rules` (default): the run-out words J and K take G92's
    /// high-speed rules (R-G92RUNOUT), as they take G92's normal-mode rules
    /// under 5129 = 0. G76 note 9: "存在 J、K 时退尾格式及相关注意事项同
    /// G92"; 5129 is "螺纹切削循环 G92,G76 的模式" (seed 000, the 988TA G76
    /// page) and "螺纹切削循环 G92，G76，G78 的模式" (the 988TA G78 page).
    #[default]
    G92Rules,
    /// `refuse`: the cycle is refused at its block 2, since no page spells
    /// out a G76 or G78 high-speed pass.
    Refuse,
}

/// Reading R-LCNC-READER: what `;` is in a program of the linuxcnc
/// profile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LcncSemicolon {
    /// `comment` (default): a comment to the end of the line, as LinuxCNC's
    /// interpreter reads it (`rs274 -g` on `G0 X20 Z2 ; approach` makes
    /// `STRAIGHT_TRAVERSE(20.0000, 0.0000, 2.0000, …)`; a `(` after the `;`
    /// is part of the comment). LinuxCNC's behaviour is the authority for
    /// the linuxcnc profile.
    #[default]
    Comment,
    /// `end-of-block`: `;` ends the block, as on the GSK profiles, so the
    /// text after it is read as the next block (a LinuxCNC `; comment` is
    /// then refused).
    EndOfBlock,
}

/// Reading R-G92Q: whether the start angle Q of the 988TA's G92 carries
/// over to the next G92 block.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G92StartAngle {
    /// `one-shot` (default): G32's rule, to which the G92 page refers Q
    /// ("取值单位与范围请参考 G32"; 988TA G32 Q: "非模态，省略时为 0°"): a
    /// G92 block without Q starts at 0°.
    #[default]
    OneShot,
    /// `modal`: Q stays in force until another Q or another motion code,
    /// as every other word of the G92 page ("R … 模态值", J, K "模态指令",
    /// L "模态参数", P "模态指令"); the page states no modality for Q.
    Modal,
}

/// Reading R-G75ALLOW: a negative finishing allowance U or W of the
/// 980TDi's G75.1, whose page gives each a signed range while calling it
/// "无符号".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Allowance {
    /// `refuse-negative` (default): "无符号" wins, a negative U or W is
    /// `out_of_range` (as R-E980's default for the same contradiction).
    #[default]
    RefuseNegative,
    /// `magnitude`: the range "-99999.999~99999.999" wins and the value,
    /// having no direction, is its magnitude, as the same page does for I
    /// ("输入负值时当成正值处理").
    Magnitude,
}

/// Reading R-G75P: which corner each digit of the 980TDi G75.1's
/// P(a)(b)(d)(e) sets when fewer than four digits are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75PDigits {
    /// `right-aligned` (default): the last digit is e, so leading zeros may
    /// be dropped (P11 = P0011), as a number's value and as the 980TDi's
    /// own P(m)(r)(a) ("地址P输入1位或2位数时取值为a").
    #[default]
    RightAligned,
    /// `left-aligned`: "P 的第一位" is the first digit written (P11 =
    /// P1100); the missing digits are 0 (chamfer).
    LeftAligned,
}

/// Reading R-NOROUGH: whether a G76 or G78 with d = k (nothing left to
/// rough, k - d = 0) cuts a rough pass.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NoRough {
    /// `none`: no rough pass, the m finishing passes at the Z of B (the
    /// reading before issue 34; the pass at depth 0 cuts only the crest
    /// line).
    None,
    /// `one-at-zero` (default on every profile): one rough pass at depth
    /// k - d = 0, at B (shift 0), then the finishing passes. 988TA and
    /// 980TDi steps ①-⑧ always cut a first rough pass ("⑤ … 如果切深大于
    /// 或等于（k-d），按切深（k-d）进刀到 Bf 点，转⑥执行最后一次螺纹粗车"), R(d)
    /// is measured from the last rough pass Bf ("螺纹精车切入点 Be 与最后一次
    /// 螺纹粗车切入点 Bf 的 X 轴绝对坐标的差值"), and DOMAIN decision 3 says
    /// "if Δd >= k - d there is exactly one rough pass, at k - d".
    #[default]
    OneAtZero,
}

/// Reading R-DEPTH: the depth of a rough level of G76 (and G78 递减) once
/// the minimum cut Δdmin takes over.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DepthLaw {
    /// `previous-plus-min` (default, DOMAIN decision 3, normative): `Dn =
    /// min(k - d, max(round(Δd √n), D(n-1) + max(Δdmin, 1)))`: seed 000
    /// 注意 1 "下一刀的 X 轴切深 … = 最小切削量 + 前一刀的切深", the 980TDi
    /// "以△dmin 作为本次以及后续粗车的切削量，后续的进刀深度将不再按公式计算".
    #[default]
    PreviousPlusMin,
    /// `formula`: `Dn = min(k - d, max(round(Δd √n), round(Δd √(n-1)) +
    /// Δdmin, D(n-1) + 1))`: the 988TA G76 step (5) and the 980TDi step ⑤
    /// "切深取（√n×△d）、（√(n-1)×△d+△dmin）中的较大值", the 988TA's Q(Δdmin)
    /// "以△dmin 作为本次粗车的切削量，即：本次螺纹切深为 √(n-1)×△d+△dmin"; the
    /// last term keeps every level at least one increment deeper.
    Formula,
}

/// Reading R-STARTS: the order of the passes of a multi-start G76 or G78.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum StartsOrder {
    /// `pass-major` (default): every pass for all starts, 0°, 360°/L, …,
    /// before the next pass: the starts stay at the same depth, so no crest
    /// between two starts is thinned by a start that is ahead.
    #[default]
    PassMajor,
    /// `start-major`: all passes of start 1 (rough and finishing), then
    /// all of start 2, …: each start cut as a single-start thread at its
    /// angle. The same moves in another order; no page gives the order
    /// (seed 000 L: "螺纹头数"; 988TA G32 Q: "指定 Q 的不同值可以切削出多头螺纹").
    StartMajor,
}

/// Reading R-G92HS-NOK: the 988TA's high-speed G92 (5129 = 1) with K
/// omitted ("省略 K 时，长轴无退尾，短轴方向的退尾长度，固定为切削终点到起点的短轴
/// 轴向距离，与 J 是多少无关"); G76 and G78 take it under R-HIGHSPEED
/// `g92-rules`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G92HighSpeedNoK {
    /// `rapid-retract` (default): no run-out; the "退尾长度" to the start's
    /// short-axis coordinate is step (3)'s rapid retract ("高速 G92：X 轴以
    /// 快速移动速度退刀 … 返回到 X 轴绝对坐标与起点相同处 D").
    #[default]
    RapidRetract,
    /// `pull-out-to-start`: a "退尾" is a thread move, as the normal mode's
    /// "短轴方向按 J 值退尾": the cut end pulls out along the short axis by
    /// thread motion all the way to the start's short-axis coordinate,
    /// whatever J is (J = 0 included); the rapid retract is then empty.
    PullOutToStart,
}

/// Reading R-G92HS-NOJ: the short axis of the 988TA's high-speed G92
/// (5129 = 1) with J omitted ("省略 J 时，长轴方向按 K 退尾", nothing said
/// of the short axis).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G92HighSpeedNoJ {
    /// `to-start` (default): the short axis all the way to the start's
    /// short-axis coordinate (J' clamped at the retract, 988TA G92 note 5),
    /// as the K-omitted sentence fixes it for the other word.
    #[default]
    ToStart,
    /// `by-parameter`: the short axis from 5130/5131, J = round(5130 · 0.1
    /// · F · tan θ), as the 980TDi G92 note 3 says with the same first
    /// clause ("省略J时，长轴方向按K退尾，短轴方向按№.19号参数设定值退尾");
    /// 5130 = 0 gives no run-out (J = 0).
    ByParameter,
}

/// Reading R-G92JK988: a negative J or K on the 988TA's G92, whose page
/// calls them "（半径值，不带方向）" and gives no range table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G92JK988 {
    /// `refuse-negative` (default): without direction, a negative value is
    /// `out_of_range`, as the 988TA G76/G78 range table ("J、K 0～999999.999").
    #[default]
    RefuseNegative,
    /// `magnitude`: made as its magnitude, as the 980TDi G92 note 10 ("J、
    /// K输入负值时，按正值处理") and R-E980's `signed`.
    Magnitude,
}

/// Reading R-G32RUNOUT (gsk988): a G32 with J ≠ 0 and K = 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G32KZero {
    /// `pull-out` (default): K = 0 read as K omitted, "（2）只省略 K（J≠0）时，
    /// 长轴无退尾，短轴按 J 值退尾": a pull-out of J along the short axis.
    #[default]
    PullOut,
    /// `none`: no run-out, as the same manual's G92 normal mode ("J≠0，
    /// K=0 时，无退尾"), to which G76 note 9 sends the run-out rules.
    None,
}

/// Reading R-CHAMFERANGLE: the axis the chamfer angle θ (5131, "退尾角度",
/// "倒角角度") is measured from, on a run-out by the chamfer amount.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ChamferAngle {
    /// `from-long-axis` (default): J = round(K · tan θ).
    #[default]
    FromLongAxis,
    /// `from-short-axis`: J = round(K · tan(90° - θ)).
    FromShortAxis,
}

/// Reading R-MODAL for E: whether the lead-in E (988TA G76/G78 block 1,
/// 980TDi G78 block 1) carries over to the next cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LeadInModal {
    /// `one-shot` (default): E applies to the next block 2 only, with D
    /// and L, whose omission gives their defaults (seed 000 "未输入时，以右
    /// 边切入方式", "省略 L 时默认为单头螺纹").
    #[default]
    OneShot,
    /// `modal`: E is a block-1 word like Q(Δdmin) and R(d), which persist;
    /// no page gives E a default for its omission.
    Modal,
}

/// Reading R-G32LONG at the tie: the long axis of a G32 whose X travel as
/// a radius equals its Z travel, where seed 002's "位移量 … 较大的坐标轴称为长轴" decides nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G32LongTie {
    /// `tie-x` (default): X, as G76's and G92's "反之，X 轴为长轴".
    #[default]
    TieX,
    /// `tie-z`: Z. The path is the same at exactly 45°; only the axes of
    /// the run-out words change (K along the long axis, J along the short).
    TieZ,
}

/// Reading R-G75RIDGE: layered roughing (V) of the 980TDi's G75.1 whose
/// step Δk is wider than the tool, so that a layer's plunges leave ridges
/// the next layer's rapids cross.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Ridges {
    /// `refuse` (default): refused with `ridges_in_layers`: the page says
    /// its path is approximate, "代码大致走刀过程（从安全角度考虑，实际走刀路径
    /// 存在部分偏差）", and does not give the deviation that would keep the
    /// rapids out of the ridges.
    #[default]
    Refuse,
    /// `as-written`: steps ②⑦⑧ as written (no page calls it an alarm): the
    /// roughing path of every other groove, its rapids across the ridges.
    AsWritten,
}

/// Reading R-G75PECK: the retract e after a peck of the 980TDi's G75.1
/// when e exceeds the depth cut so far in the plunge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75PeckRetract {
    /// `clamped` (default): the retract ends at the plunge's start Amn at
    /// the highest, so the tool stays in the space the plunge has cut; the
    /// next feed is then shorter than Δi/2 + e.
    #[default]
    Clamped,
    /// `as-written`: step ④ "径向(X 轴)快速移动退刀 e" and step ⑤ "X 轴再次切削
    /// 进给(Δi/2+e)" as written: the retract is e even above Amn.
    AsWritten,
}

/// Reading R-SPINDLE: what a thread block (G32, G92, G76, G78) needs of
/// the spindle on the FANUC-style profiles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Spindle {
    /// `speed-and-running` (default): a speed S > 0 and the spindle running
    /// (M03/M04 since the last M05): the 988TA G92's "如果无速度信号反馈到
    /// 系统…时，产生报警" alarms a stopped spindle, and DOMAIN lists "no
    /// spindle speed commanded" among the alarms.
    #[default]
    SpeedAndRunning,
    /// `speed-only`: a speed S > 0 suffices: 988TA G76 note 8 / G32 note 7
    /// "如果没有指令主轴速度，产生报警" speaks of the commanded speed only.
    SpeedOnly,
}

/// Reading R-G75LAYER: how V(Δv), "单次切削循环时的最大允许切深距离（分层次进行
/// 切削，单层最大深度）", divides the roughing depth D = Y − Δu (from S's
/// level) of the 980TDi's G75.1.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Layers {
    /// `full-then-remainder` (default): layers Δv deep, the last the
    /// remainder (G75's own 分层: each Δv, then what is left).
    #[default]
    FullThenRemainder,
    /// `equal`: ceil(D/Δv) layers of equal depth, "最大" (maximum) allowing
    /// less than Δv; in increments each D div M, the first D mod M one
    /// increment deeper.
    Equal,
}

/// Reading R-G75CHAMFER: what the size of a G75.1 chamfer corner, "A(r1)：
/// 外底起点处的倒棱宽度" (and B(r2), D(r3), E(r4)), measures. The chamfer is
/// symmetric under both (equal legs t along its two edges from the virtual
/// sharp corner); rounds (radius) are the same under both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Chamfer {
    /// `equal-legs` (default): the legs are the size c (as `,C` on G01).
    #[default]
    EqualLegs,
    /// `axial-width`: "宽度" is the chamfer's extent along Z: the legs are
    /// `c / (cos θ1 + cos θ2)`, θ1, θ2 the angles of its two edges to the
    /// Z axis.
    AxialWidth,
}

/// Reading R-G75SLOPE: which way the opening of the 980TDi's G75.1 slopes,
/// "L(∠p)：斜面的角度，斜面与底边延长线形成的夹角" (the direction is not said).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Slope {
    /// `rises-towards-d` (default): the line through S at L rises away
    /// from the bottom in D's direction: deepest at flank B; L < B.
    #[default]
    RisesTowardsD,
    /// `falls-towards-d`: the line through S at L falls towards the bottom
    /// in D's direction: deepest at flank A; L < A, and the opening must
    /// meet flank B above the bottom.
    FallsTowardsD,
}

/// Reading R-LCNC-G7: a G7 or G8 in a LinuxCNC G76 block that changes the
/// X mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LcncG7 {
    /// `refuse` (default): the block is refused (program G7/G8 on a line of
    /// its own): the cycle LinuxCNC cuts is not the one its words describe.
    #[default]
    Refuse,
    /// `as-interpreter`: as LinuxCNC's `convert_lathe_diameter_mode` does
    /// (interp_convert.cc l.2773-2777): switching to G7 halves I, J and K
    /// once more before the cycle's own halving (a quarter of the words as
    /// radii), switching to G8 doubles them.
    AsInterpreter,
}

/// Reading R-G75ARC: which code names an arc of G75.1's rounds in the nc
/// output and in an nc trace `check` reads. An output convention: the
/// moves (`Motion::Arc`'s `clockwise`, seen with +Z right and +X up) are
/// the same under both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ArcNames {
    /// `rear-post` (default): G02 clockwise seen with +Z right and +X up
    /// (the view of a rear-post lathe, +X away from the operator). The
    /// sources are silent (no G02 page).
    #[default]
    RearPost,
    /// `front-post`: the codes exchanged, as a front-post lathe's control
    /// names the same arc (its +X towards the operator mirrors the view).
    FrontPost,
}

/// Reading R-SIDE: a G76 (or G78) start point A inside the thread's crest
/// (between C and B, or inside D's crest: s·(X_A − X_B) < 0 or
/// s·(X_A − X_D − s·xf·k) < 0). The side itself is read from A against C
/// ("根据程序起点位置自动确定退尾方向"), and A on C's X, which gives no
/// side, is refused under both values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum StartSide {
    /// `refuse-inside` (default): refused with `start_inside_thread`:
    /// seed 004's advice "螺纹切削循环起始点坐标X向，在切削外螺纹时，应比螺纹
    /// 大径大" and the retract of step ⑦ ("X 轴快速移动到 E 点"), which would
    /// run inside the work. The text does not decide (no page lists A's
    /// position among its alarms).
    #[default]
    RefuseInside,
    /// `accept`: no page calls it an alarm; the moves are the cycle's own
    /// formulas with A where it is (A → Bn, the cut, the retract to E at the
    /// X of A, the return along Z), so the retract and the return may run
    /// through the crest that has just been cut.
    Accept,
}

/// The readings chosen for a machine. [`Readings::default`] is the
/// project's reading of every point on every profile: where a reading's
/// default depends on the profile (R-END, R-LONG988) its field is `None`
/// until a value is chosen, and [`Readings::for_cycle`] takes the
/// profile's ([`ReadingEntry::default_on`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Readings {
    /// R-RUNOUT.
    pub run_out: RunOutClamp,
    /// R-XRUNOUT.
    pub x_run_out: XRunOut,
    /// R-E980.
    pub e980: E980,
    /// R-END; `None`: the profile's default.
    pub pass_end: Option<PassEnd>,
    /// R-LONG988; `None`: the profile's default.
    pub long988: Option<Long988>,
    /// R-G78LEFT.
    pub g78_left: G78Left,
    /// R-G78CENTRE.
    pub g78_centre: G78Centre,
    /// R-LEADIN.
    pub lead_in: LeadIn,
    /// R-INFEED (and R-G78ALT): the order of the flanks.
    pub infeed_order: InfeedOrder,
    /// R-HIGHSPEED.
    pub high_speed: HighSpeed,
    /// R-LCNC-READER.
    pub lcnc_semicolon: LcncSemicolon,
    /// R-G92Q.
    pub g92_q: G92StartAngle,
    /// R-G75ALLOW.
    pub g75_allowance: G75Allowance,
    /// R-G75P.
    pub g75_p: G75PDigits,
    /// R-NOROUGH.
    pub no_rough: NoRough,
    /// R-DEPTH.
    pub depth_law: DepthLaw,
    /// R-STARTS.
    pub starts_order: StartsOrder,
    /// R-G92HS-NOK.
    pub g92_hs_no_k: G92HighSpeedNoK,
    /// R-G92HS-NOJ.
    pub g92_hs_no_j: G92HighSpeedNoJ,
    /// R-G92JK988.
    pub g92_jk988: G92JK988,
    /// R-G32RUNOUT (gsk988's K = 0).
    pub g32_k_zero: G32KZero,
    /// R-CHAMFERANGLE.
    pub chamfer_angle: ChamferAngle,
    /// R-MODAL (E).
    pub lead_in_modal: LeadInModal,
    /// R-G32LONG (the tie).
    pub g32_long_tie: G32LongTie,
    /// R-SIDE: an A inside the thread's crest.
    pub start_side: StartSide,
    /// R-G75RIDGE: ridges in layered roughing.
    pub g75_ridges: G75Ridges,
    /// R-G75PECK: the retract after a peck.
    pub g75_peck: G75PeckRetract,
    /// R-SPINDLE: what a thread block needs of the spindle.
    pub spindle: Spindle,
    /// R-G75LAYER: the depths of the layers.
    pub g75_layers: G75Layers,
    /// R-G75ARC: G02/G03 in the nc output and nc traces.
    pub arc_names: ArcNames,
    /// R-G75CHAMFER: what a chamfer corner's size measures.
    pub g75_chamfer: G75Chamfer,
    /// R-G75SLOPE: which way the opening slopes.
    pub g75_slope: G75Slope,
    /// R-LCNC-G7: a G7/G8 that changes the X mode in a G76 block.
    pub lcnc_g7: LcncG7,
}

/// One value of a reading: its name and where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadingValue {
    /// The name scripts use (`--reading ID=NAME`).
    pub name: &'static str,
    /// Its source and reason, in one line.
    pub source: &'static str,
}

/// One selectable reading.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadingEntry {
    /// The id of docs/INTERPRETATIONS.md.
    pub id: &'static str,
    /// What it decides, in a few words.
    pub point: &'static str,
    /// Its values, the default first unless the default depends on the
    /// profile or was changed on the text, the reading before issue 34
    /// kept first ([`ReadingEntry::default_on`]: R-END, R-LONG988,
    /// R-NOROUGH).
    pub values: &'static [ReadingValue],
    /// The profiles on which the choice changes anything.
    pub profiles: &'static [ProfileName],
}

impl ReadingEntry {
    /// The default value on `profile`: the first value, except where the
    /// evidence decides another (docs/INTERPRETATIONS.md, R-END and
    /// R-LONG988 per profile, R-NOROUGH on every profile).
    #[must_use]
    pub fn default_on(&self, profile: ProfileName) -> &'static str {
        match self.id {
            "R-END" => pass_end_name(default_pass_end(profile)),
            "R-LONG988" => long988_name(default_long988(profile)),
            // Decided on the text (docs/INTERPRETATIONS.md, R-NOROUGH): the
            // first value is the reading before issue 34.
            "R-NOROUGH" => "one-at-zero",
            _ => self.values.first().map_or("", |v| v.name),
        }
    }

    fn names(&self) -> String {
        self.values.iter().map(|v| v.name).collect::<Vec<_>>().join(", ")
    }
}

/// R-END's default on `profile`, decided on the text
/// (docs/INTERPRETATIONS.md, R-END): `parallel` on every profile. The
/// 980TDi G76 page (the FANUC two-block format) and the 988TA G76 page,
/// step ②: "沿平行于 C→D 的方向螺纹切削到与 D→E 相交处"; seed 000 and the
/// 988TA G78 page define D's long-axis coordinate as the end of the cut
/// ("如果有螺纹退尾，切削终点长轴方向为螺纹切削终点"), which a pass
/// translated by its shift (`translated`, their step (4) read literally)
/// would overrun on every thread, straight ones included.
fn default_pass_end(_profile: ProfileName) -> PassEnd {
    PassEnd::Parallel
}

fn pass_end_name(v: PassEnd) -> &'static str {
    match v {
        PassEnd::TravelI => "travel-i",
        PassEnd::Parallel => "parallel",
        PassEnd::Translated => "translated",
    }
}

/// R-LONG988's default on `profile`: the 988TA G92 page's table, "P = 0
/// （轴向螺纹）长轴：横轴", on gsk988 (elsewhere the reading changes
/// nothing).
fn default_long988(profile: ProfileName) -> Long988 {
    match profile {
        ProfileName::Gsk988 => Long988::Table,
        _ => Long988::Displacement,
    }
}

fn long988_name(v: Long988) -> &'static str {
    match v {
        Long988::Displacement => "displacement",
        Long988::Table => "table",
    }
}

const GSK: &[ProfileName] = &[ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988];

/// The profiles with G78 (and the 988TA's G76 D modes and E).
const GSK_G78: &[ProfileName] = &[ProfileName::Gsk980, ProfileName::Gsk988];

/// Every selectable reading, in the order `cycleref readings` lists them.
pub const TABLE: &[ReadingEntry] = &[
    ReadingEntry {
        id: "R-RUNOUT",
        point: "the clamp of the short-axis run-out J at the retract (988TA G92 note 5)",
        values: &[
            ReadingValue {
                name: "all-profiles",
                source: "988TA G92 note 5 adopted for every profile; the 980TDi and FANUC pages are silent",
            },
            ReadingValue {
                name: "gsk988-only",
                source: "only the 988TA page says it: J as written on fanuc and gsk980",
            },
        ],
        profiles: &[ProfileName::Fanuc, ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-XRUNOUT",
        point: "an X-long run-out towards A when s*i > 0 (into the work)",
        values: &[
            ReadingValue {
                name: "refuse",
                source: "run_out_into_work: the retract after it would cut the thread",
            },
            ReadingValue {
                name: "towards-start",
                source: "\"根据程序起点位置自动确定退尾方向\" as written; no page calls it an alarm",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-E980",
        point: "a negative lead-in E on the 980TDi's G78",
        values: &[
            ReadingValue { name: "refuse-negative", source: "980TDi G78: E \"无符号\" (unsigned)" },
            ReadingValue {
                name: "signed",
                source: "980TDi G78: E \"-9999.9999~9999.9999\"; made as |E| like G92 note 10's J and K",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-END",
        point: "where each pass of G76 and G78 ends on a taper, its start shifted along Z",
        values: &[
            ReadingValue {
                name: "travel-i",
                source: "X travels exactly i from Bn to the line D-E (Z of D); parallel to C->D in no source",
            },
            ReadingValue {
                name: "parallel",
                source: "980TDi and 988TA G76 step 2: \"沿平行于 C→D 的方向螺纹切削到与 D→E 相交处\"; the end's X rounded (default)",
            },
            ReadingValue {
                name: "translated",
                source: "seed 000 and 988TA G78 step (4): \"Z 轴方向的移动量为 W，X 轴方向的移动量为 i\": C->D moved to Bn, ending shift beyond D",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-LONG988",
        point: "the long axis of a 988TA G92 or G78 on a steep taper (|i| >= |W|)",
        values: &[
            ReadingValue {
                name: "displacement",
                source: "Z when |W| > |i| (radius), as the 980TDi G92 page and seed 000 for G76",
            },
            ReadingValue {
                name: "table",
                source: "988TA G92 \"P = 0（轴向螺纹）长轴：横轴\": Z whatever the displacements (default); such a cycle cannot be written as G32 blocks (expand refuses it)",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-HIGHSPEED",
        point: "G76 and G78 under 5129 = 1 (the 988TA's high-speed threading mode)",
        values: &[
            ReadingValue {
                name: "g92-rules",
                source: "988TA G76 note 9 \"存在 J、K 时退尾格式及相关注意事项同 G92\"; 5129 \"G92，G76，G78 的模式\": G92's high-speed J/K rules",
            },
            ReadingValue {
                name: "refuse",
                source: "no page spells out a high-speed G76 or G78 pass: refused at block 2",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G78LEFT",
        point: "where a left-flank pass lies (G78 r=1, the left passes of G78 r=3/r=4 and G76 D2)",
        values: &[
            ReadingValue {
                name: "mirror-form-centre",
                source: "the right flank mirrored about the form's centre line zc: every pass inside the final form",
            },
            ReadingValue {
                name: "mirror-b",
                source: "mirrored about B: \"Bn 点相对于 B 点 … tg(a/2)=│Z 轴位移│/│X 轴位移│\" on every left pass",
            },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-G78CENTRE",
        point: "where G78 r=0's passes lie (\"刀刃沿螺纹牙型中线切入\")",
        values: &[
            ReadingValue { name: "form-centre", source: "the centre line of the other modes' final form, zc from A" },
            ReadingValue { name: "under-b", source: "radial infeed under B, at the Z of A" },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-LEADIN",
        point: "where the lead-in E starts (旋进)",
        values: &[
            ReadingValue {
                name: "same-z",
                source: "\"与切削起点 Bn 距离为 E 的位置\", E \"X 向旋进距离值\": E out along X at Bn's Z",
            },
            ReadingValue {
                name: "whole-leads",
                source: "E out along X, whole leads back along Z (no page gives a Z length): in phase, An not E from Bn",
            },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-INFEED",
        point: "which flank a level starts on in G76 D2, G78 r=4 (左右轮流) and the 980TDi's G78 r=3 (交错)",
        values: &[
            ReadingValue {
                name: "right-first",
                source: "D2 starts on D0's flank (\"右边切入（原 G76 切入方式）\"); the figures naming Bx1/Bx2 are lost",
            },
            ReadingValue {
                name: "left-first",
                source: "the sides in the names' order, \"左右轮流\", \"左右两边轮流\" (as \"右中轮流\" is read right first)",
            },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-LCNC-READER",
        point: "`;` in a linuxcnc program",
        values: &[
            ReadingValue {
                name: "comment",
                source: "LinuxCNC's interpreter: `;` starts a comment to the end of the line (rs274 -g)",
            },
            ReadingValue {
                name: "end-of-block",
                source: "`;` ends the block, as on the GSK profiles: a `; comment` is refused",
            },
        ],
        profiles: &[ProfileName::LinuxCnc],
    },
    ReadingEntry {
        id: "R-G92Q",
        point: "whether the 988TA G92's start angle Q carries over to the next G92 block",
        values: &[
            ReadingValue {
                name: "one-shot",
                source: "988TA G92 Q \"取值单位与范围请参考 G32\"; G32 Q \"非模态，省略时为 0°\"",
            },
            ReadingValue {
                name: "modal",
                source: "every other 988TA G92 word is modal (R, J, K, L, P); the page states none for Q",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G75ALLOW",
        point: "a negative finishing allowance U or W of the 980TDi's G75.1",
        values: &[
            ReadingValue { name: "refuse-negative", source: "980TDi G75.1: U, W \"无符号\" (unsigned)" },
            ReadingValue {
                name: "magnitude",
                source: "980TDi G75.1: U, W \"-99999.999~99999.999\"; made as |U|, |W| like I (\"输入负值时当成正值处理\")",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75P",
        point: "the corners of a G75.1 P(a)(b)(d)(e) written with fewer than four digits",
        values: &[
            ReadingValue {
                name: "right-aligned",
                source: "P is a number: the last digit is e, leading zeros dropped (as the 980TDi's P(m)(r)(a))",
            },
            ReadingValue {
                name: "left-aligned",
                source: "\"P 的第一位\" is the first digit written: P11 sets a and b",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-NOROUGH",
        point: "a G76 or G78 with d = k (nothing left to rough)",
        values: &[
            ReadingValue {
                name: "none",
                source: "no rough pass, the finishing passes at B's Z (before issue 34; a pass at depth 0 cuts the crest line only)",
            },
            ReadingValue {
                name: "one-at-zero",
                source: "988TA/980TDi steps ①-⑧ always cut a first rough pass, to Bf at k-d; DOMAIN decision 3 \"if Δd >= k - d there is exactly one rough pass, at k - d\"",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-DEPTH",
        point: "the depth of a rough level of G76 and G78 递减 once the minimum cut takes over",
        values: &[
            ReadingValue {
                name: "previous-plus-min",
                source: "DOMAIN decision 3: D(n-1) + Δdmin (seed 000 注意 1 \"最小切削量 + 前一刀的切深\"; 980TDi \"本次以及后续粗车\")",
            },
            ReadingValue {
                name: "formula",
                source: "988TA/980TDi step (5) \"切深取（√n×△d）、（√(n-1)×△d+△dmin）中的较大值\" on every level",
            },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-STARTS",
        point: "the order of the passes of a multi-start G76 or G78 (L > 1)",
        values: &[
            ReadingValue {
                name: "pass-major",
                source: "every pass for all starts before the next pass: the starts stay at one depth (no page gives the order)",
            },
            ReadingValue {
                name: "start-major",
                source: "all passes of start 1, then of start 2, …: each start a single-start thread at its angle (no page gives the order)",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-G92HS-NOK",
        point: "the 988TA's high-speed G92 (5129 = 1) with K omitted",
        values: &[
            ReadingValue {
                name: "rapid-retract",
                source: "step (3) \"高速 G92：X 轴以快速移动速度退刀…返回到 X 轴绝对坐标与起点相同处\": no run-out",
            },
            ReadingValue {
                name: "pull-out-to-start",
                source: "\"短轴方向的退尾长度，固定为切削终点到起点的短轴轴向距离\": a 退尾 by thread motion to the start's X",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G92HS-NOJ",
        point: "the short axis of the 988TA's high-speed G92 (5129 = 1) with J omitted",
        values: &[
            ReadingValue {
                name: "to-start",
                source: "\"省略 J 时，长轴方向按 K 退尾\" says nothing of J: the short axis to the start's X (note 5's clamp)",
            },
            ReadingValue {
                name: "by-parameter",
                source: "as the 980TDi G92 note 3 \"省略J时，长轴方向按K退尾，短轴方向按№.19号参数设定值退尾\": J from 5130/5131",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G92JK988",
        point: "a negative J or K on the 988TA's G92 (\"半径值，不带方向\", no range table)",
        values: &[
            ReadingValue {
                name: "refuse-negative",
                source: "without direction; the 988TA G76/G78 range table \"J、K 0～999999.999\"",
            },
            ReadingValue {
                name: "magnitude",
                source: "made as |J|, |K| like the 980TDi G92 note 10 \"J、K输入负值时，按正值处理\"",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G32RUNOUT",
        point: "a 988TA G32 with J != 0 and K = 0",
        values: &[
            ReadingValue {
                name: "pull-out",
                source: "988TA G32 \"只省略 K（J≠0）时，长轴无退尾，短轴按 J 值退尾\": K = 0 read as K omitted",
            },
            ReadingValue {
                name: "none",
                source: "988TA G92 normal mode \"J≠0，K=0 时，无退尾\": no run-out",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-CHAMFERANGLE",
        point: "the axis the chamfer angle 5131 is measured from (run-out by the chamfer amount)",
        values: &[
            ReadingValue {
                name: "from-long-axis",
                source: "J = round(K tan θ); the text does not decide (5131 \"倒角角度\", \"退尾角度\"; only 45° is pinned)",
            },
            ReadingValue { name: "from-short-axis", source: "J = round(K tan(90° - θ))" },
        ],
        profiles: &[ProfileName::Fanuc, ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-MODAL",
        point: "whether the lead-in E of a G76/G78 block 1 carries over to the next cycle",
        values: &[
            ReadingValue {
                name: "one-shot",
                source: "E in the list with D and L, which apply to the next block 2 only (seed 000)",
            },
            ReadingValue {
                name: "modal",
                source: "E a block-1 word like Q(Δdmin) and R(d), which persist; no page gives E a default",
            },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-G32LONG",
        point: "the long axis of a G32 whose X travel (radius) equals its Z travel",
        values: &[
            ReadingValue {
                name: "tie-x",
                source: "X, as G76's and G92's \"反之，X 轴为长轴\"; seed 002 \"较大的坐标轴\" decides no tie",
            },
            ReadingValue { name: "tie-z", source: "Z: the path is the same at 45°, J and K change axes" },
        ],
        profiles: GSK_G78,
    },
    ReadingEntry {
        id: "R-SIDE",
        point: "a G76/G78 start point A inside the thread's crest (between C and B, or inside D's crest)",
        values: &[
            ReadingValue {
                name: "refuse-inside",
                source: "seed 004 \"起始点坐标X向…应比螺纹大径大\"; the retract to E would run inside the work",
            },
            ReadingValue {
                name: "accept",
                source: "no page lists A's position among its alarms: the cycle's formulas with A where it is",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-G75RIDGE",
        point: "G75.1 layers (V) with a step Q(Δk) wider than the tool: ridges the next layer's rapids cross",
        values: &[
            ReadingValue {
                name: "refuse",
                source: "\"代码大致走刀过程（从安全角度考虑，实际走刀路径存在部分偏差）\": the safe path is not given",
            },
            ReadingValue {
                name: "as-written",
                source: "steps ②⑦⑧ as written; no page calls it an alarm: the rapids cross the ridges",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75PECK",
        point: "the G75.1 retract e after a peck when e exceeds the depth the plunge has cut",
        values: &[
            ReadingValue {
                name: "clamped",
                source: "the retract ends at the plunge's start Amn at the highest (the next feed shorter than Δi/2+e)",
            },
            ReadingValue {
                name: "as-written",
                source: "steps ④⑤ \"快速移动退刀 e\", \"再次切削进给(Δi/2+e)\" as written, even above Amn",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-SPINDLE",
        point: "what a thread block (G32, G92, G76, G78) needs of the spindle",
        values: &[
            ReadingValue {
                name: "speed-and-running",
                source: "S > 0 and M03/M04 since the last M05: 988TA G92 \"如果无速度信号反馈到系统…时，产生报警\"",
            },
            ReadingValue {
                name: "speed-only",
                source: "S > 0 suffices: 988TA G76 note 8, G32 note 7 \"如果没有指令主轴速度，产生报警\"",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-G75LAYER",
        point: "the depths of G75.1's layers V(Δv) (\"单层最大深度\")",
        values: &[
            ReadingValue {
                name: "full-then-remainder",
                source: "layers Δv deep from S's level, the last the remainder (G75's 分层)",
            },
            ReadingValue {
                name: "equal",
                source: "\"最大\" allows less: ceil(D/Δv) equal layers, the first D mod M one increment deeper",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75ARC",
        point: "which of G02/G03 names a G75.1 round's arc in the nc output and in check's nc traces",
        values: &[
            ReadingValue {
                name: "rear-post",
                source: "G02 clockwise seen with +Z right and +X up; the sources are silent (no G02 page)",
            },
            ReadingValue {
                name: "front-post",
                source: "the codes exchanged, as a front-post lathe names the same arc (+X towards the operator)",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75CHAMFER",
        point: "what the size of a G75.1 chamfer corner A(r1) B(r2) D(r3) E(r4) (\"倒棱宽度\") measures",
        values: &[
            ReadingValue {
                name: "equal-legs",
                source: "legs c along both edges from the virtual sharp corner, as ,C on G01",
            },
            ReadingValue {
                name: "axial-width",
                source: "\"宽度\" as the extent along Z: the symmetric chamfer whose Z extent is c",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75SLOPE",
        point: "which way G75.1's opening slopes at L (\"斜面与底边延长线形成的夹角\")",
        values: &[
            ReadingValue {
                name: "rises-towards-d",
                source: "rising away from the bottom in D's direction: H at S, deepest at flank B; L < B",
            },
            ReadingValue {
                name: "falls-towards-d",
                source: "falling in D's direction (the direction is not said): deepest at flank A; L < A",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-LCNC-G7",
        point: "a G7/G8 that changes the X mode in a G76 block",
        values: &[
            ReadingValue {
                name: "refuse",
                source: "the cycle LinuxCNC cuts is not the one its words describe: program G7/G8 on its own line",
            },
            ReadingValue {
                name: "as-interpreter",
                source: "interp_convert.cc l.2773-2777: to G7 halves I, J, K once more (a quarter), to G8 doubles them",
            },
        ],
        profiles: &[ProfileName::LinuxCnc],
    },
];

impl Readings {
    /// The value of reading `id`, by name; `None` for an unknown id, and
    /// for a reading whose default depends on the profile while it is not
    /// chosen ([`Readings::get_on`] gives the profile's).
    #[must_use]
    pub fn get(&self, id: &str) -> Option<&'static str> {
        let v = match id {
            "R-RUNOUT" => match self.run_out {
                RunOutClamp::AllProfiles => "all-profiles",
                RunOutClamp::Gsk988Only => "gsk988-only",
            },
            "R-XRUNOUT" => match self.x_run_out {
                XRunOut::Refuse => "refuse",
                XRunOut::TowardsStart => "towards-start",
            },
            "R-E980" => match self.e980 {
                E980::RefuseNegative => "refuse-negative",
                E980::Signed => "signed",
            },
            "R-END" => pass_end_name(self.pass_end?),
            "R-LONG988" => long988_name(self.long988?),
            "R-INFEED" => match self.infeed_order {
                InfeedOrder::RightFirst => "right-first",
                InfeedOrder::LeftFirst => "left-first",
            },
            "R-G78LEFT" => match self.g78_left {
                G78Left::MirrorFormCentre => "mirror-form-centre",
                G78Left::MirrorB => "mirror-b",
            },
            "R-G78CENTRE" => match self.g78_centre {
                G78Centre::FormCentre => "form-centre",
                G78Centre::UnderB => "under-b",
            },
            "R-LEADIN" => match self.lead_in {
                LeadIn::SameZ => "same-z",
                LeadIn::WholeLeads => "whole-leads",
            },
            "R-HIGHSPEED" => match self.high_speed {
                HighSpeed::G92Rules => "g92-rules",
                HighSpeed::Refuse => "refuse",
            },
            "R-LCNC-READER" => match self.lcnc_semicolon {
                LcncSemicolon::Comment => "comment",
                LcncSemicolon::EndOfBlock => "end-of-block",
            },
            "R-G92Q" => match self.g92_q {
                G92StartAngle::OneShot => "one-shot",
                G92StartAngle::Modal => "modal",
            },
            "R-G75ALLOW" => match self.g75_allowance {
                G75Allowance::RefuseNegative => "refuse-negative",
                G75Allowance::Magnitude => "magnitude",
            },
            "R-G75P" => match self.g75_p {
                G75PDigits::RightAligned => "right-aligned",
                G75PDigits::LeftAligned => "left-aligned",
            },
            "R-NOROUGH" => match self.no_rough {
                NoRough::None => "none",
                NoRough::OneAtZero => "one-at-zero",
            },
            "R-DEPTH" => match self.depth_law {
                DepthLaw::PreviousPlusMin => "previous-plus-min",
                DepthLaw::Formula => "formula",
            },
            "R-STARTS" => match self.starts_order {
                StartsOrder::PassMajor => "pass-major",
                StartsOrder::StartMajor => "start-major",
            },
            "R-G92HS-NOK" => match self.g92_hs_no_k {
                G92HighSpeedNoK::RapidRetract => "rapid-retract",
                G92HighSpeedNoK::PullOutToStart => "pull-out-to-start",
            },
            "R-G92HS-NOJ" => match self.g92_hs_no_j {
                G92HighSpeedNoJ::ToStart => "to-start",
                G92HighSpeedNoJ::ByParameter => "by-parameter",
            },
            "R-G92JK988" => match self.g92_jk988 {
                G92JK988::RefuseNegative => "refuse-negative",
                G92JK988::Magnitude => "magnitude",
            },
            "R-G32RUNOUT" => match self.g32_k_zero {
                G32KZero::PullOut => "pull-out",
                G32KZero::None => "none",
            },
            "R-CHAMFERANGLE" => match self.chamfer_angle {
                ChamferAngle::FromLongAxis => "from-long-axis",
                ChamferAngle::FromShortAxis => "from-short-axis",
            },
            "R-MODAL" => match self.lead_in_modal {
                LeadInModal::OneShot => "one-shot",
                LeadInModal::Modal => "modal",
            },
            "R-G32LONG" => match self.g32_long_tie {
                G32LongTie::TieX => "tie-x",
                G32LongTie::TieZ => "tie-z",
            },
            "R-SIDE" => match self.start_side {
                StartSide::RefuseInside => "refuse-inside",
                StartSide::Accept => "accept",
            },
            "R-G75RIDGE" => match self.g75_ridges {
                G75Ridges::Refuse => "refuse",
                G75Ridges::AsWritten => "as-written",
            },
            "R-G75PECK" => match self.g75_peck {
                G75PeckRetract::Clamped => "clamped",
                G75PeckRetract::AsWritten => "as-written",
            },
            "R-SPINDLE" => match self.spindle {
                Spindle::SpeedAndRunning => "speed-and-running",
                Spindle::SpeedOnly => "speed-only",
            },
            "R-G75LAYER" => match self.g75_layers {
                G75Layers::FullThenRemainder => "full-then-remainder",
                G75Layers::Equal => "equal",
            },
            "R-G75ARC" => match self.arc_names {
                ArcNames::RearPost => "rear-post",
                ArcNames::FrontPost => "front-post",
            },
            "R-G75CHAMFER" => match self.g75_chamfer {
                G75Chamfer::EqualLegs => "equal-legs",
                G75Chamfer::AxialWidth => "axial-width",
            },
            "R-G75SLOPE" => match self.g75_slope {
                G75Slope::RisesTowardsD => "rises-towards-d",
                G75Slope::FallsTowardsD => "falls-towards-d",
            },
            "R-LCNC-G7" => match self.lcnc_g7 {
                LcncG7::Refuse => "refuse",
                LcncG7::AsInterpreter => "as-interpreter",
            },
            _ => return None,
        };
        Some(v)
    }

    /// The value of reading `id` in force on `profile`, by name: the
    /// chosen one, else the profile's default.
    #[must_use]
    pub fn get_on(&self, id: &str, profile: ProfileName) -> Option<&'static str> {
        let entry = TABLE.iter().find(|e| e.id == id)?;
        Some(self.get(id).unwrap_or_else(|| entry.default_on(profile)))
    }

    /// Sets reading `id` to the value named `value`.
    ///
    /// # Errors
    ///
    /// [`ParamsError::UnknownReading`] naming the ids, or
    /// [`ParamsError::BadReading`] naming the reading's values.
    pub fn set(&mut self, id: &str, value: &str) -> Result<(), ParamsError> {
        let Some(entry) = TABLE.iter().find(|e| e.id == id) else {
            return Err(ParamsError::UnknownReading { id: id.to_string(), known: known_ids() });
        };
        let bad = || ParamsError::BadReading { id: entry.id, value: value.to_string(), valid: entry.names() };
        match (entry.id, value) {
            ("R-RUNOUT", "all-profiles") => self.run_out = RunOutClamp::AllProfiles,
            ("R-RUNOUT", "gsk988-only") => self.run_out = RunOutClamp::Gsk988Only,
            ("R-XRUNOUT", "refuse") => self.x_run_out = XRunOut::Refuse,
            ("R-XRUNOUT", "towards-start") => self.x_run_out = XRunOut::TowardsStart,
            ("R-E980", "refuse-negative") => self.e980 = E980::RefuseNegative,
            ("R-E980", "signed") => self.e980 = E980::Signed,
            ("R-END", "travel-i") => self.pass_end = Some(PassEnd::TravelI),
            ("R-END", "parallel") => self.pass_end = Some(PassEnd::Parallel),
            ("R-END", "translated") => self.pass_end = Some(PassEnd::Translated),
            ("R-LONG988", "displacement") => self.long988 = Some(Long988::Displacement),
            ("R-LONG988", "table") => self.long988 = Some(Long988::Table),
            ("R-INFEED", "right-first") => self.infeed_order = InfeedOrder::RightFirst,
            ("R-INFEED", "left-first") => self.infeed_order = InfeedOrder::LeftFirst,
            ("R-G78LEFT", "mirror-form-centre") => self.g78_left = G78Left::MirrorFormCentre,
            ("R-G78LEFT", "mirror-b") => self.g78_left = G78Left::MirrorB,
            ("R-G78CENTRE", "form-centre") => self.g78_centre = G78Centre::FormCentre,
            ("R-G78CENTRE", "under-b") => self.g78_centre = G78Centre::UnderB,
            ("R-LEADIN", "same-z") => self.lead_in = LeadIn::SameZ,
            ("R-LEADIN", "whole-leads") => self.lead_in = LeadIn::WholeLeads,
            ("R-HIGHSPEED", "g92-rules") => self.high_speed = HighSpeed::G92Rules,
            ("R-HIGHSPEED", "refuse") => self.high_speed = HighSpeed::Refuse,
            ("R-LCNC-READER", "comment") => self.lcnc_semicolon = LcncSemicolon::Comment,
            ("R-LCNC-READER", "end-of-block") => self.lcnc_semicolon = LcncSemicolon::EndOfBlock,
            ("R-G92Q", "one-shot") => self.g92_q = G92StartAngle::OneShot,
            ("R-G92Q", "modal") => self.g92_q = G92StartAngle::Modal,
            ("R-G75ALLOW", "refuse-negative") => self.g75_allowance = G75Allowance::RefuseNegative,
            ("R-G75ALLOW", "magnitude") => self.g75_allowance = G75Allowance::Magnitude,
            ("R-G75P", "right-aligned") => self.g75_p = G75PDigits::RightAligned,
            ("R-G75P", "left-aligned") => self.g75_p = G75PDigits::LeftAligned,
            ("R-NOROUGH", "none") => self.no_rough = NoRough::None,
            ("R-NOROUGH", "one-at-zero") => self.no_rough = NoRough::OneAtZero,
            ("R-DEPTH", "previous-plus-min") => self.depth_law = DepthLaw::PreviousPlusMin,
            ("R-DEPTH", "formula") => self.depth_law = DepthLaw::Formula,
            ("R-STARTS", "pass-major") => self.starts_order = StartsOrder::PassMajor,
            ("R-STARTS", "start-major") => self.starts_order = StartsOrder::StartMajor,
            ("R-G92HS-NOK", "rapid-retract") => self.g92_hs_no_k = G92HighSpeedNoK::RapidRetract,
            ("R-G92HS-NOK", "pull-out-to-start") => self.g92_hs_no_k = G92HighSpeedNoK::PullOutToStart,
            ("R-G92HS-NOJ", "to-start") => self.g92_hs_no_j = G92HighSpeedNoJ::ToStart,
            ("R-G92HS-NOJ", "by-parameter") => self.g92_hs_no_j = G92HighSpeedNoJ::ByParameter,
            ("R-G92JK988", "refuse-negative") => self.g92_jk988 = G92JK988::RefuseNegative,
            ("R-G92JK988", "magnitude") => self.g92_jk988 = G92JK988::Magnitude,
            ("R-G32RUNOUT", "pull-out") => self.g32_k_zero = G32KZero::PullOut,
            ("R-G32RUNOUT", "none") => self.g32_k_zero = G32KZero::None,
            ("R-CHAMFERANGLE", "from-long-axis") => self.chamfer_angle = ChamferAngle::FromLongAxis,
            ("R-CHAMFERANGLE", "from-short-axis") => self.chamfer_angle = ChamferAngle::FromShortAxis,
            ("R-MODAL", "one-shot") => self.lead_in_modal = LeadInModal::OneShot,
            ("R-MODAL", "modal") => self.lead_in_modal = LeadInModal::Modal,
            ("R-G32LONG", "tie-x") => self.g32_long_tie = G32LongTie::TieX,
            ("R-G32LONG", "tie-z") => self.g32_long_tie = G32LongTie::TieZ,
            ("R-SIDE", "refuse-inside") => self.start_side = StartSide::RefuseInside,
            ("R-SIDE", "accept") => self.start_side = StartSide::Accept,
            ("R-G75RIDGE", "refuse") => self.g75_ridges = G75Ridges::Refuse,
            ("R-G75RIDGE", "as-written") => self.g75_ridges = G75Ridges::AsWritten,
            ("R-G75PECK", "clamped") => self.g75_peck = G75PeckRetract::Clamped,
            ("R-G75PECK", "as-written") => self.g75_peck = G75PeckRetract::AsWritten,
            ("R-SPINDLE", "speed-and-running") => self.spindle = Spindle::SpeedAndRunning,
            ("R-SPINDLE", "speed-only") => self.spindle = Spindle::SpeedOnly,
            ("R-G75LAYER", "full-then-remainder") => self.g75_layers = G75Layers::FullThenRemainder,
            ("R-G75LAYER", "equal") => self.g75_layers = G75Layers::Equal,
            ("R-G75ARC", "rear-post") => self.arc_names = ArcNames::RearPost,
            ("R-G75ARC", "front-post") => self.arc_names = ArcNames::FrontPost,
            ("R-G75CHAMFER", "equal-legs") => self.g75_chamfer = G75Chamfer::EqualLegs,
            ("R-G75CHAMFER", "axial-width") => self.g75_chamfer = G75Chamfer::AxialWidth,
            ("R-G75SLOPE", "rises-towards-d") => self.g75_slope = G75Slope::RisesTowardsD,
            ("R-G75SLOPE", "falls-towards-d") => self.g75_slope = G75Slope::FallsTowardsD,
            ("R-LCNC-G7", "refuse") => self.lcnc_g7 = LcncG7::Refuse,
            ("R-LCNC-G7", "as-interpreter") => self.lcnc_g7 = LcncG7::AsInterpreter,
            _ => return Err(bad()),
        }
        Ok(())
    }

    /// Applies `ID=VALUE` pairs separated by commas (the C options field;
    /// blanks around each pair are ignored, an empty text sets nothing).
    ///
    /// # Errors
    ///
    /// [`ParamsError::ReadingSyntax`] for a pair without `=`, else as
    /// [`Readings::set`].
    pub fn apply_list(&mut self, text: &str) -> Result<(), ParamsError> {
        for pair in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            self.apply_pair(pair)?;
        }
        Ok(())
    }

    /// Applies one `ID=VALUE` (`--reading`).
    ///
    /// # Errors
    ///
    /// As [`Readings::apply_list`].
    pub fn apply_pair(&mut self, pair: &str) -> Result<(), ParamsError> {
        let Some((id, value)) = pair.split_once('=') else {
            return Err(ParamsError::ReadingSyntax { text: pair.to_string() });
        };
        self.set(id.trim(), value.trim())
    }

    /// The readings whose value differs from the default on `profile`, as
    /// `(id, value)` in [`TABLE`]'s order: what the `check` report and the
    /// JSON documents name.
    #[must_use]
    pub fn non_default(&self, profile: ProfileName) -> Vec<(&'static str, &'static str)> {
        TABLE
            .iter()
            .filter_map(|e| {
                let v = self.get(e.id)?;
                (v != e.default_on(profile)).then_some((e.id, v))
            })
            .collect()
    }

    /// True when `;` starts a comment to the end of the line in a program
    /// of a LinuxCNC dialect (`lcnc`), reading R-LCNC-READER `comment`.
    #[must_use]
    pub fn semicolon_comments(&self, lcnc: bool) -> bool {
        lcnc && self.lcnc_semicolon == LcncSemicolon::Comment
    }

    /// What a threading cycle of `profile` does under these readings: a
    /// G92 or a G78 (`long_axis_table_applies`: the cycles R-LONG988 is
    /// about) or a G76 (seed 000 gives G76 the displacement rule: "C 点与 D
    /// 点 Z 轴坐标差的绝对值大于 X 轴坐标差的绝对值 … 时，Z 轴为长轴").
    #[must_use]
    pub fn for_cycle(&self, profile: ProfileName, long_axis_table_applies: bool) -> CycleReadings {
        let pass_end = self.pass_end.unwrap_or(default_pass_end(profile));
        let long988 = self.long988.unwrap_or(default_long988(profile));
        CycleReadings {
            clamp_run_out: self.run_out == RunOutClamp::AllProfiles || profile == ProfileName::Gsk988,
            x_run_out_towards_start: self.x_run_out == XRunOut::TowardsStart,
            pass_end,
            long_axis_by_table: profile == ProfileName::Gsk988
                && long_axis_table_applies
                && long988 == Long988::Table,
            left_mirror_b: self.g78_left == G78Left::MirrorB,
            centre_under_b: self.g78_centre == G78Centre::UnderB,
            lead_in_same_z: self.lead_in == LeadIn::SameZ,
            left_first: self.infeed_order == InfeedOrder::LeftFirst,
            one_rough_at_zero: self.no_rough == NoRough::OneAtZero,
            // R-DEPTH: the formula is the GSK pages' (988TA, 980TDi step
            // (5)); the FANUC notes (seed 004) give only the fixed
            // increment "以固定增量d min … 直至粗加工结束", so fanuc keeps
            // DOMAIN decision 3 under either value.
            depth_formula: self.depth_law == DepthLaw::Formula
                && matches!(profile, ProfileName::Gsk980 | ProfileName::Gsk988),
            start_major: self.starts_order == StartsOrder::StartMajor,
            chamfer_from_short_axis: self.chamfer_angle == ChamferAngle::FromShortAxis,
            g32_tie_z: self.g32_long_tie == G32LongTie::TieZ,
            accept_start_inside: self.start_side == StartSide::Accept,
        }
    }
}

impl Readings {
    /// What a G75.1 cycle does under these readings (the 980TDi's page;
    /// on another profile the reader refuses G75.1).
    #[must_use]
    pub fn for_g75(&self) -> G75Readings {
        G75Readings {
            ridges_as_written: self.g75_ridges == G75Ridges::AsWritten,
            peck_retract_as_written: self.g75_peck == G75PeckRetract::AsWritten,
            equal_layers: self.g75_layers == G75Layers::Equal,
            chamfer_axial_width: self.g75_chamfer == G75Chamfer::AxialWidth,
            slope_falls_towards_d: self.g75_slope == G75Slope::FallsTowardsD,
        }
    }
}

fn known_ids() -> String {
    TABLE.iter().map(|e| e.id).collect::<Vec<_>>().join(", ")
}

/// `cycleref readings`: one line per reading of [`TABLE`], its id, its
/// values with the default on `profile` marked `*` (without a profile,
/// `*` where the value is the default on every profile the reading changes
/// anything on, `*fanuc,gsk980` where only on those), the profiles it
/// changes anything on, and each value's source.
pub struct Listing {
    /// The profile whose defaults are marked.
    pub profile: Option<ProfileName>,
}

impl fmt::Display for Listing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for e in TABLE {
            if let Some(p) = self.profile {
                if !e.profiles.contains(&p) {
                    continue;
                }
            }
            // The default marked `*`; without a profile, where the defaults
            // differ between the reading's profiles, followed by the
            // profiles it is the default on.
            let on: Vec<ProfileName> = self.profile.map_or_else(|| e.profiles.to_vec(), |p| vec![p]);
            let values: Vec<String> = e
                .values
                .iter()
                .map(|v| {
                    let defaults: Vec<String> =
                        on.iter().filter(|p| e.default_on(**p) == v.name).map(ToString::to_string).collect();
                    if defaults.is_empty() {
                        v.name.to_string()
                    } else if defaults.len() == on.len() {
                        format!("{}*", v.name)
                    } else {
                        format!("{}*{}", v.name, defaults.join(","))
                    }
                })
                .collect();
            let profiles: Vec<String> = e.profiles.iter().map(ToString::to_string).collect();
            let sources: Vec<String> = e.values.iter().map(|v| format!("{}: {}", v.name, v.source)).collect();
            writeln!(
                f,
                "{}\t{}\t[{}]\t{}",
                e.id,
                values.join(" | "),
                profiles.join(","),
                sources.join("; ")
            )?;
        }
        Ok(())
    }
}
