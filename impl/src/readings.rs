//! The readings of the manuals that a threading cycle's moves depend on and
//! that the sources leave open (docs/INTERPRETATIONS.md, issue 34), as the
//! cycle carries them: the program reader resolves each reading chosen for
//! the machine (`cycleref_spec::readings`) against the control profile and
//! puts the result here, so that the engine and the exact reference take
//! the same value.
//!
//! [`CycleReadings::DEFAULT`] is the reading of every point that the cycles
//! had before readings were selectable: the moves of a cycle carrying it are
//! those of the cycles before issue 34. The program reader resolves each
//! profile's own defaults, which differ from it for R-END and R-LONG988
//! (docs/INTERPRETATIONS.md).

/// Reading R-END: where each pass of a G76 or G78 cycle ends when it is
/// shifted along Z (seed 000 "执行过程" (4), 988TA and 980TDi G76 step ②).
/// For a pass without shift the three coincide; on a straight thread
/// `travel-i` and `parallel` do, and `translated` ends the shift beyond D.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PassEnd {
    /// `travel-i`: the pass ends on the line D–E (Z of D) at X of D plus
    /// the pass's depth below the crest: X travels exactly i from Bn, and
    /// the pass is not parallel to C→D when it is shifted. The reading of
    /// the cycles before issue 34.
    #[default]
    TravelI,
    /// `parallel`: the pass runs parallel to C→D until it meets the line
    /// D–E (Z of D) (980TDi and 988TA G76 step ②: "沿平行于 C→D 的方向螺纹切削
    /// 到与 D→E 相交处"); the end's X is rounded to the nearest increment.
    Parallel,
    /// `translated`: the pass is C→D translated to Bn, Z travel W and X
    /// travel i (seed 000 and 988TA G78 step (4): "本轮切削终点与螺纹切入点在
    /// Z 轴方向的移动量为 W，X 轴方向的移动量为 i"): it ends shift beyond D
    /// along Z.
    Translated,
}

/// What a threading cycle (G76, G78, G92) does at the points its manuals
/// leave open, resolved for the cycle's control profile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CycleReadings {
    /// Reading R-RUNOUT: the short-axis run-out J is clamped to the retract
    /// distance of a pass without run-out (the X of A on a Z-long thread,
    /// the Z travel back to A on an X-long one), as 988TA G92 note 5 says
    /// ("当螺纹短轴方向退尾长度大于无退尾时的退刀距离时，系统默认短轴方向退尾长度为无
    /// 退尾时的退刀距离"). `false`: J as written, beyond the retract point when
    /// it is longer (R-RUNOUT `gsk988-only` on a profile other than gsk988,
    /// whose pages are silent).
    pub clamp_run_out: bool,
    /// Reading R-XRUNOUT: an X-long run-out along Z towards A on a thread
    /// whose cut line rises towards A (s·i > 0) is refused
    /// ([`crate::CycleError::RunOutIntoWork`]) when `false`, made as
    /// written when `true` ("根据程序起点位置自动确定退尾方向", R-XRUNOUT
    /// `towards-start`).
    pub x_run_out_towards_start: bool,
    /// Reading R-END: where each pass of a G76 or G78 cycle ends (G92's
    /// single pass has no shift: every value gives the same moves).
    pub pass_end: PassEnd,
    /// Reading R-LONG988 `table` on a 988TA G92 or G78: Z is the long axis
    /// of an axial thread whatever the displacements (988TA G92 "长轴/短轴的
    /// 判断": "P = 0（轴向螺纹）长轴：横轴"). `false`: the long axis by the
    /// displacements, |W| > |i| for Z (R-LONG).
    pub long_axis_by_table: bool,
    /// Reading R-G78LEFT: a left-flank pass (G78 r = 1, the left passes of
    /// G78 r = 4 and G76 D2 左右等量轮流, and of the 980TDi's G78 r = 3
    /// 交错) is the right flank mirrored about the centre line of the final
    /// form, `2 zc - round(Dn tan(a/2))`, when `false`
    /// (`mirror-form-centre`); mirrored about B, `-round(Dn tan(a/2))`,
    /// when `true` (`mirror-b`: "Bn 点相对于 B 点 X 轴和 Z 轴的位移符合公式
    /// tg(a/2)=│Z 轴位移│/│X 轴位移│" on every left pass).
    pub left_mirror_b: bool,
    /// Reading R-G78CENTRE: the passes of G78 r = 0 ("刀刃沿螺纹牙型中线切入")
    /// are at the Z of A shifted `zc = round((k - d) tan(a/2))` when `false`
    /// (`form-centre`), under B (shift 0, radial infeed) when `true`
    /// (`under-b`).
    pub centre_under_b: bool,
    /// Reading R-LEADIN: the lead-in start An of a pass (E, "X 向旋进距离值")
    /// is E out along X at the Z of Bn when `true` (`same-z`, the default:
    /// "快速移动到与切削起点 Bn 距离为 E 的位置"), the screw-in then a thread
    /// move along X only; E out along X from Bn and whole leads back along
    /// Z when `false` (`whole-leads`).
    pub lead_in_same_z: bool,
    /// Reading R-INFEED (with R-G78ALT): the modes that cut both flanks in
    /// turn (G76 D2 and G78 r = 4 左右轮流, the 980TDi's G78 r = 3 交错)
    /// start each level on the right flank when `false` (`right-first`),
    /// on the left when `true` (`left-first`, the sides in the order
    /// "左右" names them). The single last level of D2 / r = 4 takes the
    /// flank its level starts on, so that `left-first` is the mirror image
    /// of `right-first` about the left flanks' mirror line.
    pub left_first: bool,
    /// Reading R-NOROUGH: a cycle with d = k (nothing left to rough) cuts
    /// one rough pass at depth k - d = 0, at B (shift 0), before its
    /// finishing passes when `true` (`one-at-zero`: 988TA and 980TDi
    /// steps ①-⑧ always cut a first rough pass, and DOMAIN decision 3
    /// "if Δd >= k - d there is exactly one rough pass, at k - d"); no
    /// rough pass when `false` (`none`, the reading before issue 34).
    pub one_rough_at_zero: bool,
    /// Reading R-DEPTH: the rough depths of G76 and G78 递减 follow the
    /// 988TA page's formula when `true` (`formula`, step (5) "切深取（√n×△d）、
    /// （√(n-1)×△d+△dmin）中的较大值"): `D(n) = min(k - d, max(round(Δd √n),
    /// round(Δd √(n-1)) + m, D(n-1) + 1))`; DOMAIN decision 3 when `false`
    /// (`previous-plus-min`, the default): `min(k - d, max(round(Δd √n),
    /// D(n-1) + m))`, `m = max(Δdmin, 1)`. G78's equal steps are not
    /// concerned.
    pub depth_formula: bool,
    /// Reading R-STARTS: the order of the passes of a multi-start G76 or
    /// G78 (L > 1). Every pass for all starts before the next pass when
    /// `false` (`pass-major`, the default); all passes of start 1 (rough
    /// and finishing), then all of start 2, … when `true` (`start-major`).
    /// The same moves, in another order; no page gives the order.
    pub start_major: bool,
    /// Reading R-CHAMFERANGLE: the chamfer angle θ of a run-out by the
    /// chamfer amount (parameter 5131, "退尾角度") is measured from the long
    /// axis when `false` (`from-long-axis`, J = round(K·tan θ)), from the
    /// short axis when `true` (`from-short-axis`, J = round(K·tan(90° -
    /// θ))). At 45° (5131 = 0) both give J = K.
    pub chamfer_from_short_axis: bool,
    /// Reading R-G32LONG at the tie: a G32 whose X travel as a radius
    /// equals its Z travel has X as its long axis when `false` (`tie-x`),
    /// Z when `true` (`tie-z`): K then runs along Z and J along X. The
    /// path is the same (45°).
    pub g32_tie_z: bool,
    /// Reading R-SIDE: a start point A inside the thread's crest (between C
    /// and B, or inside D's crest) is refused
    /// ([`crate::CycleError::StartInsideThread`]) when `false`
    /// (`refuse-inside`); accepted when `true` (`accept`: no page lists A's
    /// position among its alarms), the moves the cycle's own formulas with
    /// A where it is. A on the X of C, which gives no side, is refused
    /// either way.
    pub accept_start_inside: bool,
}

impl CycleReadings {
    /// The readings a typed cycle built without the reader takes, the same
    /// on every profile: J clamped, X-long run-outs into the work refused,
    /// X travelling i on every pass (R-END `travel-i`) and the long axis by
    /// the displacements (both the readings before issue 34: the reader
    /// resolves each profile's own, `parallel`, and `table` on gsk988),
    /// left flanks mirrored about the form's centre line, G78's centre line
    /// at `zc`, the lead-in at the Z of Bn (R-LEADIN `same-z`, the default on
    /// every profile), each level of the alternating modes right flank first
    /// (R-INFEED `right-first`), no rough pass when d = k (R-NOROUGH
    /// `none`, the reading before issue 34: the reader resolves
    /// `one-at-zero`, the default on every profile), the depths of DOMAIN
    /// decision 3 (R-DEPTH `previous-plus-min`), every pass for all starts
    /// before the next (R-STARTS `pass-major`), the chamfer angle from the long axis
    /// (R-CHAMFERANGLE `from-long-axis`), a G32's tie X long (R-G32LONG
    /// `tie-x`), an A inside the crest refused (R-SIDE `refuse-inside`).
    pub const DEFAULT: CycleReadings = CycleReadings {
        clamp_run_out: true,
        x_run_out_towards_start: false,
        pass_end: PassEnd::TravelI,
        long_axis_by_table: false,
        left_mirror_b: false,
        centre_under_b: false,
        lead_in_same_z: true,
        left_first: false,
        one_rough_at_zero: false,
        depth_formula: false,
        start_major: false,
        chamfer_from_short_axis: false,
        g32_tie_z: false,
        accept_start_inside: false,
    };
}

impl Default for CycleReadings {
    fn default() -> CycleReadings {
        CycleReadings::DEFAULT
    }
}

/// What a G75.1 cycle (the 980TDi's trapezoid groove, seed 001) does at the
/// points its page leaves open (docs/INTERPRETATIONS.md, issue 34),
/// resolved by the program reader; each is decided once for the cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct G75Readings {
    /// Reading R-G75RIDGE: layered roughing whose step Δk is wider than the
    /// tool (ridges between a layer's plunges) is refused
    /// ([`crate::CycleError::RidgesInLayers`]) when `false` (`refuse`);
    /// made as steps ②⑦⑧ write it when `true` (`as-written`: no page calls
    /// it an alarm), the rapids of the next layers then crossing the
    /// ridges.
    pub ridges_as_written: bool,
    /// Reading R-G75PECK: the retract e after a peck is clamped at the
    /// plunge's start (Amn) when `false` (`clamped`); made as step ④
    /// writes it when `true` (`as-written`: "径向(X 轴)快速移动退刀 e", even
    /// above Amn, so the next feed is the written Δi/2 + e). The ends of
    /// the pecks are the same under both.
    pub peck_retract_as_written: bool,
    /// Reading R-G75LAYER: the layers of V(Δv) are Δv deep from S's level,
    /// the last taking the remainder, when `false` (`full-then-remainder`);
    /// `M = ceil(D/Δv)` layers of equal depth when `true` (`equal`), D =
    /// Y − Δu in increments: each D div M deep, the first D mod M one
    /// increment deeper, so the bottom of layer m is `m·(D div M) + min(m,
    /// D mod M)`.
    pub equal_layers: bool,
    /// Reading R-G75CHAMFER: a chamfer corner of size c has legs c along
    /// both its edges from the virtual sharp corner when `false`
    /// (`equal-legs`); its extent along Z is c when `true` (`axial-width`):
    /// the legs are `c / (cos θ1 + cos θ2)`, θ1, θ2 its edges' angles to the
    /// Z axis (r1: a and L, r2: b and L, r3: a and 0, r4: b and 0). Rounds
    /// are the same under both.
    pub chamfer_axial_width: bool,
    /// Reading R-G75SLOPE: the opening (the line through S at L) rises
    /// towards −y (away from the bottom) in D's direction when `false`
    /// (`rises-towards-d`: the groove deepest at flank B, L < B); falls
    /// towards +y in D's direction when `true` (`falls-towards-d`: deepest
    /// at flank A, L < A, and the opening must meet flank B above the
    /// bottom).
    pub slope_falls_towards_d: bool,
}

impl G75Readings {
    /// The reading of every point before readings were selectable, the
    /// default on the gsk980 profile: ridges in layers refused, the peck
    /// retract clamped at the plunge's start, layers Δv deep and the last
    /// the remainder, chamfers of equal legs, the opening rising towards D.
    pub const DEFAULT: G75Readings = G75Readings {
        ridges_as_written: false,
        peck_retract_as_written: false,
        equal_layers: false,
        chamfer_axial_width: false,
        slope_falls_towards_d: false,
    };
}

impl Default for G75Readings {
    fn default() -> G75Readings {
        G75Readings::DEFAULT
    }
}
