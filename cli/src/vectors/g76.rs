//! G76 threads: the thread and the way a G76 is written, the valid G76
//! templates, and the features a G76 shows.
//!
//! A [`Thread`] is drawn in increments (start A, end D, taper, height,
//! depths, lead) so that A is clear of the thread; a [`G76`] says which
//! words its one or two blocks carry. A template draws both, changes what
//! its feature needs and writes the program; [`tags`] reads back from the
//! expanded cycle what it shows, which the template's entry may require.

use std::fmt::Write as _;

use cycleref::LeadWord;
use cycleref_spec::ProfileName;

use super::machine::{any_profile, head, MachineStyle, Param};
use super::{Draft, Expected, Rng, Template};

/// One G76 thread: geometry and schedule, in increments.
#[derive(Clone)]
pub(super) struct Thread {
    /// The start point A (X, Z).
    pub(super) a: (i64, i64),
    /// The thread end D (X, Z).
    pub(super) d: (i64, i64),
    /// R(i).
    pub(super) taper: i64,
    /// P(k), the thread height.
    pub(super) k: i64,
    /// Q(Δd), the first depth.
    pub(super) dd: i64,
    /// Q(Δdmin), the minimum cut.
    pub(super) dmin: i64,
    /// R(d), the finishing allowance.
    pub(super) allowance: i64,
    /// The lead word as written (`F1.5`).
    pub(super) lead: String,
    /// |W|, the thread's length along Z.
    pub(super) w: i64,
}

/// The taper a thread is drawn with.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Taper {
    /// No taper: R(i) = 0.
    Straight,
    /// A taper whose long axis is Z.
    ZLong,
    /// A steep taper whose long axis is X (|i| >= |W|).
    XLong,
    /// Any of them, straight most often.
    Any,
}

/// A random thread, external or internal, cut towards -Z or +Z; `rough`
/// is the range of the rough pass count the first depth aims at.
pub(super) fn thread(rng: &mut Rng, ctx: &MachineStyle, taper: Taper, rough: (i64, i64)) -> Thread {
    let xf = ctx.xf();
    let side = rng.sign();
    let dir = if rng.chance(70) { -1 } else { 1 };
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = (lead_inc * rng.range(55, 64) / 100).max(1);
    let allowance = if rng.chance(35) { 0 } else { k * rng.range(2, 8) / 100 };
    let n = rng.range(rough.0, rough.1).max(1);
    let root =
        i64::try_from(cycleref::engine::round_sqrt(u128::try_from(n * 10_000).unwrap_or(1))).unwrap_or(100);
    let dd = ((k - allowance) * 100 / root).max(1);
    let dmin = if rng.chance(40) { 0 } else { (dd * rng.range(5, 20) / 100).min(k) };
    let taper = match taper {
        Taper::Any => rng.pick(&[Taper::Straight, Taper::Straight, Taper::ZLong, Taper::XLong]),
        t => t,
    };
    let (w, i) = match taper {
        Taper::Straight | Taper::Any => (ctx.mm(rng.range(12_000, 40_000)), 0),
        Taper::ZLong => (ctx.mm(rng.range(15_000, 40_000)), rng.sign() * ctx.mm(rng.range(300, 3000))),
        Taper::XLong => {
            let w = ctx.mm(rng.range(4000, 9000));
            let extra = if rng.chance(15) { 0 } else { ctx.mm(rng.range(0, 6000)) };
            (w, rng.sign() * (w + extra))
        }
    };
    let clear = ctx.mm(rng.range(500, 3000));
    let min_root = if side > 0 { i.abs() + ctx.mm(4000) } else { k + i.abs() + clear + ctx.mm(4000) };
    let root = if side > 0 { ctx.mm(rng.range(8000, 35_000)) } else { ctx.mm(rng.range(15_000, 40_000)) };
    let root = root.max(min_root);
    let xd = xf * root;
    let xc = xd + xf * i;
    let xb = xc + side * xf * k;
    let crest_end = xd + side * xf * k;
    let xa = if side > 0 { xb.max(crest_end) + xf * clear } else { xb.min(crest_end) - xf * clear };
    let za = if dir < 0 { ctx.mm(rng.range(1000, 10_000)) } else { -(w + ctx.mm(rng.range(5000, 20_000))) };
    Thread { a: (xa, za), d: (xd, za + dir * w), taper: i, k, dd, dmin, allowance, lead, w }
}

/// A tool angle P(a), 60 degrees most often.
fn tool_angle(rng: &mut Rng) -> i64 {
    rng.pick(&[0, 29, 30, 55, 60, 60, 60, 80])
}

/// P(m)(r)(a) as six digits.
pub(super) fn pmra(m: i64, r: i64, a: i64) -> String {
    format!("{m:02}{r:02}{a:02}")
}

/// A usual P(m)(r)(a): m 1..2 (0..2 on the 980TDi), r 0..10, a.
fn random_pmra(rng: &mut Rng, ctx: &MachineStyle) -> String {
    let m = if ctx.profile == ProfileName::Gsk980 && rng.chance(15) { 0 } else { rng.range(1, 2) };
    let r = if rng.chance(40) { 0 } else { rng.range(1, 10) };
    pmra(m, r, tool_angle(rng))
}

/// How a G76 is written.
#[derive(Clone)]
pub(super) struct G76 {
    /// Whether block 1 is written (else its values come from the
    /// parameters or an earlier block 1).
    pub(super) block1: bool,
    /// P(m)(r)(a) of block 1 as written; `None`: left out.
    pub(super) p: Option<String>,
    /// Further words of block 1.
    pub(super) extra1: Vec<String>,
    /// Further words of block 2.
    pub(super) extra2: Vec<String>,
    /// Block 2 words left out: any of `P`, `Q`, `F`, `R`.
    pub(super) omit: &'static str,
    /// U/W instead of X/Z in block 2.
    pub(super) incremental: bool,
    /// R(i) written even when it is 0.
    pub(super) show_r: bool,
}

impl G76 {
    /// Both blocks, no P(m)(r)(a) and no other words.
    fn plain() -> G76 {
        G76 {
            block1: true,
            p: None,
            extra1: Vec::new(),
            extra2: Vec::new(),
            omit: "",
            incremental: false,
            show_r: false,
        }
    }

    /// Both blocks with a usual P(m)(r)(a), absolute or incremental.
    pub(super) fn usual(rng: &mut Rng, ctx: &MachineStyle) -> G76 {
        G76 {
            block1: true,
            p: Some(random_pmra(rng, ctx)),
            extra1: Vec::new(),
            extra2: Vec::new(),
            omit: "",
            incremental: rng.chance(20),
            show_r: rng.chance(30),
        }
    }
}

/// The one or two blocks of a G76.
pub(super) fn g76_lines(ctx: &MachineStyle, t: &Thread, g: &G76) -> Vec<String> {
    let mut out = Vec::new();
    if g.block1 {
        let mut s = String::from("G76");
        if let Some(p) = &g.p {
            let _ = write!(s, " P{p}");
        }
        let _ = write!(s, " Q{} R{}", ctx.pq(t.dmin), ctx.num(t.allowance));
        for w in &g.extra1 {
            let _ = write!(s, " {w}");
        }
        out.push(s);
    }
    let mut s = String::from("G76");
    if g.incremental {
        let _ = write!(s, " U{} W{}", ctx.num(t.d.0 - t.a.0), ctx.num(t.d.1 - t.a.1));
    } else {
        let _ = write!(s, " X{} Z{}", ctx.num(t.d.0), ctx.num(t.d.1));
    }
    if (g.show_r || t.taper != 0) && !g.omit.contains('R') {
        let _ = write!(s, " R{}", ctx.num(t.taper));
    }
    if !g.omit.contains('P') {
        let _ = write!(s, " P{}", ctx.pq(t.k));
    }
    if !g.omit.contains('Q') {
        let _ = write!(s, " Q{}", ctx.pq(t.dd));
    }
    if !g.omit.contains('F') {
        let _ = write!(s, " {}", t.lead);
    }
    for w in &g.extra2 {
        let _ = write!(s, " {w}");
    }
    out.push(s);
    out
}

/// Random run-out words J/K for the profile (none on FANUC): for the
/// 980TDi in block 1, for the 988TA in block 2.
fn random_jk(rng: &mut Rng, ctx: &MachineStyle, g: &mut G76) {
    let j = ctx.mm(rng.range(300, 2000));
    let k = ctx.mm(rng.range(500, 3000));
    let words = match rng.range(0, 3) {
        0 => vec![],
        1 => vec![format!("J{}", ctx.num(j))],
        _ => vec![format!("J{}", ctx.num(j)), format!("K{}", ctx.num(k))],
    };
    match ctx.profile {
        // LinuxCnc: never drawn (the vectors draw FANUC and GSK profiles).
        ProfileName::Fanuc | ProfileName::LinuxCnc => {}
        ProfileName::Gsk980 => g.extra1.extend(words),
        ProfileName::Gsk988 => g.extra2.extend(words),
    }
}

/// The lines of a one-G76 program.
pub(super) fn g76_program(rng: &mut Rng, ctx: &MachineStyle, t: &Thread, g: &G76) -> Vec<String> {
    let mut lines = head(rng, ctx, t.a);
    lines.extend(g76_lines(ctx, t, g));
    lines.push("M30".into());
    lines
}

// ---- the valid G76 templates ----

/// G76 with the profile's usual words.
pub(super) const BASIC: Template = Template {
    id: "g76-basic",
    outcome: Expected::Valid(&[]),
    tags: &["template:g76-basic"],
    description: "G76 with the profile's usual words",
    generate: basic,
};

fn basic(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// G76 infeed D1 (GSK 988TA).
pub(super) const D1: Template = Template {
    id: "g76-d1",
    outcome: Expected::Valid(&["infeed:D1"]),
    tags: &["template:g76-d1"],
    description: "G76 infeed D1: right flank and centre alternately",
    generate: |rng| infeed(rng, 1),
};

/// G76 infeed D2 (GSK 988TA).
pub(super) const D2: Template = Template {
    id: "g76-d2",
    outcome: Expected::Valid(&["infeed:D2"]),
    tags: &["template:g76-d2"],
    description: "G76 infeed D2: left and right flanks alternately, equal amounts",
    generate: |rng| infeed(rng, 2),
};

/// A GSK 988TA G76 with the infeed word D`mode`.
fn infeed(rng: &mut Rng, mode: i64) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("D{mode}"));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// G76 with a lead-in E (GSK 988TA).
pub(super) const LEAD_IN: Template = Template {
    id: "g76-lead-in",
    outcome: Expected::Valid(&["lead-in"]),
    tags: &["template:g76-lead-in"],
    description: "G76 with a lead-in E (screw-in to each pass start)",
    generate: lead_in,
};

fn lead_in(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let taper = if rng.chance(70) { Taper::Straight } else { Taper::ZLong };
    let t = thread(rng, &ctx, taper, (2, 4));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 3000)))));
    if rng.chance(40) {
        g.extra1.push(format!("D{}", rng.range(0, 2)));
    }
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A multi-start thread L (GSK 988TA).
pub(super) const MULTI_START: Template = Template {
    id: "g76-multi-start",
    outcome: Expected::Valid(&["multi-start"]),
    tags: &["template:g76-multi-start"],
    description: "G76 multi-start thread L (starts 360/L degrees apart)",
    generate: multi_start,
};

fn multi_start(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::Any, (1, 2));
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(1, rng.range(0, 5), tool_angle(rng)));
    g.extra1.push(format!("L{}", rng.pick(&[2, 3, 3, 4, 7])));
    if rng.chance(30) && t.taper.abs() < t.w {
        g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 2000)))));
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A thread with one rough level and one finishing pass, for programs of
/// several cycles.
fn small_thread(rng: &mut Rng, ctx: &MachineStyle) -> Thread {
    let mut t = thread(rng, ctx, Taper::Straight, (1, 1));
    t.dd = t.k;
    t
}

/// The GSK 980TDi run-out notes, one cycle each.
pub(super) const RUNOUT_980: Template = Template {
    id: "g76-runout-gsk980",
    outcome: Expected::Valid(&["run-out:chamfer", "run-out:chamfer+k", "run-out:amounts", "run-out:none"]),
    tags: &[
        "template:g76-runout-gsk980",
        "rule:gsk980-note1",
        "rule:gsk980-note2",
        "rule:gsk980-note3",
        "rule:gsk980-note4",
        "rule:jk-one-shot",
    ],
    description: "GSK 980TDi G76 run-out notes 1-4: five cycles, J/K one-shot in block 1",
    generate: runout_980,
};

fn runout_980(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let t = small_thread(rng, &ctx);
    let r = rng.range(2, 9);
    let a = tool_angle(rng);
    let j = ctx.mm(rng.range(300, 2000));
    let k = ctx.mm(rng.range(500, 3000));
    let (jt, kt) = (ctx.num(j), ctx.num(k));
    let mut lines = head(rng, &ctx, t.a);
    // Notes 1 (J, K omitted: chamfer by P(r)), 2 (J omitted, K given: J by
    // P(r)), 3 (K omitted: K = J), 4 (J = 0: none), then J and K.
    let variants: [Vec<String>; 5] = [
        vec![],
        vec![format!("K{kt}")],
        vec![format!("J{jt}")],
        vec!["J0".to_string(), format!("K{kt}")],
        vec![format!("J{jt}"), format!("K{kt}")],
    ];
    for words in &variants {
        let g = G76 { p: Some(pmra(1, r, a)), extra1: words.clone(), ..G76::plain() };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// The GSK 988TA run-out rules, J/K modal in block 2.
pub(super) const RUNOUT_988: Template = Template {
    id: "g76-runout-gsk988",
    outcome: Expected::Valid(&["run-out:chamfer", "run-out:pull-out", "run-out:amounts", "run-out:none"]),
    tags: &[
        "template:g76-runout-gsk988",
        "rule:gsk988-chamfer",
        "rule:gsk988-j-only",
        "rule:gsk988-jk-modal",
        "rule:gsk988-k0",
        "rule:gsk988-j0",
        "rule:jk-modal",
        "block1-modal",
    ],
    description: "GSK 988TA G76 run-out rules, J/K modal in block 2: never programmed (chamfer), J only \
                  (pull-out), K added (J and K), K0 (none), J0 (none)",
    generate: runout_988,
};

fn runout_988(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let t = small_thread(rng, &ctx);
    let r = rng.range(2, 9);
    let a = tool_angle(rng);
    let (jt, kt) = (ctx.num(ctx.mm(rng.range(300, 2000))), ctx.num(ctx.mm(rng.range(500, 3000))));
    let mut lines = head(rng, &ctx, t.a);
    let steps: [Vec<String>; 5] = [
        vec![],
        vec![format!("J{jt}")],
        vec![format!("K{kt}")],
        vec!["K0".into()],
        vec!["J0".into(), format!("K{kt}")],
    ];
    for (n, words) in steps.iter().enumerate() {
        let g = G76 { block1: n == 0, p: Some(pmra(1, r, a)), extra2: words.clone(), ..G76::plain() };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// GSK 988TA: K without J.
pub(super) const RUNOUT_988_K_ONLY: Template = Template {
    id: "g76-runout-gsk988-k",
    outcome: Expected::Valid(&["run-out:none", "run-out:amounts"]),
    tags: &["template:g76-runout-gsk988-k", "rule:gsk988-k-only", "rule:gsk988-jk", "rule:jk-modal"],
    description: "GSK 988TA G76: K without J (no run-out, although r is set), then J and K, then both modal",
    generate: runout_988_k_only,
};

fn runout_988_k_only(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let t = small_thread(rng, &ctx);
    let (jt, kt) = (ctx.num(ctx.mm(rng.range(300, 2000))), ctx.num(ctx.mm(rng.range(500, 3000))));
    let mut lines = head(rng, &ctx, t.a);
    let p = pmra(1, rng.range(2, 9), tool_angle(rng));
    for (n, words) in
        [vec![format!("K{kt}")], vec![format!("J{jt}"), format!("K{kt}")], vec![]].iter().enumerate()
    {
        let g = G76 { block1: n == 0, p: Some(p.clone()), extra2: words.clone(), ..G76::plain() };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// The run-out chamfer at another angle than 45 degrees.
pub(super) const CHAMFER: Template = Template {
    id: "g76-chamfer",
    outcome: Expected::Valid(&["run-out:chamfer", "run-out:chamfer-angle"]),
    tags: &["template:g76-chamfer", "params:block1", "params:chamfer-5130"],
    description:
        "G76 run-out by the chamfer at the angle of parameter 5131: r from parameter 5130, then from \
                  P(m)(r)(a)",
    generate: chamfer,
};

fn chamfer(rng: &mut Rng) -> Draft {
    let profile = rng.pick(&[ProfileName::Fanuc, ProfileName::Gsk988]);
    let mut ctx = MachineStyle::new(profile, rng);
    ctx.params.insert("5131", Param::Int(rng.pick(&[30, 60, 20])));
    let t = thread(rng, &ctx, Taper::Any, (1, 2));
    // Cycle 1: r from parameter 5130 (no block 1, Δdmin and d from 5140
    // and 5141); cycle 2: r from P(m)(r)(a) of a block 1.
    ctx.params.insert("5130", Param::Int(rng.range(3, 15)));
    ctx.params.insert("5140", Param::Len(t.dmin));
    ctx.params.insert("5141", Param::Len(t.allowance));
    let mut g = G76::usual(rng, &ctx);
    g.block1 = false;
    let mut lines = head(rng, &ctx, t.a);
    lines.extend(g76_lines(&ctx, &t, &g));
    g.block1 = true;
    g.p = Some(pmra(rng.range(1, 2), rng.range(3, 15), tool_angle(rng)));
    lines.extend(g76_lines(&ctx, &t, &g));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A steep taper: X the long axis.
pub(super) const X_LONG: Template = Template {
    id: "g76-x-long",
    outcome: Expected::Valid(&["taper:x-long"]),
    tags: &["template:g76-x-long"],
    description: "G76 steep taper, X the long axis (|i| >= |W|)",
    generate: x_long,
};

fn x_long(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::XLong, (2, 4));
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(rng.range(1, 2), rng.range(0, 3), rng.pick(&[0, 29, 30, 55, 60])));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A taper thread, Z the long axis.
pub(super) const TAPER: Template = Template {
    id: "g76-taper",
    outcome: Expected::Valid(&["taper:z-long"]),
    tags: &["template:g76-taper"],
    description: "G76 taper thread R(i), Z the long axis",
    generate: taper,
};

fn taper(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::ZLong, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A one-pass schedule.
pub(super) const ONE_PASS: Template = Template {
    id: "g76-one-pass",
    outcome: Expected::Valid(&["schedule:one-pass"]),
    tags: &["template:g76-one-pass"],
    description: "G76 one-pass schedule: Q(Δd) >= k - d gives a single rough level",
    generate: one_pass,
};

fn one_pass(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 1));
    t.dd = t.k - t.allowance + if rng.chance(40) { 0 } else { rng.range(1, t.k) };
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// Rough cuts clamped to Q(Δdmin).
pub(super) const MIN_CUT: Template = Template {
    id: "g76-min-cut",
    outcome: Expected::Valid(&["schedule:min-cut"]),
    tags: &["template:g76-min-cut"],
    description: "G76 Q(Δdmin) clamping: later rough cuts are Δdmin deep",
    generate: min_cut,
};

fn min_cut(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 1));
    // k - d about 3 Δd and Δdmin about 0.35 Δd: the law's steps fall below
    // Δdmin from the third level on.
    let q = ((t.k - t.allowance) * 10 / rng.range(25, 35)).max(1);
    t.dd = q;
    t.dmin = (q * rng.range(30, 45) / 100).max(1);
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// The depth law's last level exactly k - d.
pub(super) const EXACT: Template = Template {
    id: "g76-exact-k-d",
    outcome: Expected::Valid(&["schedule:exact-k-d"]),
    tags: &["template:g76-exact-k-d"],
    description: "G76 whose depth law lands exactly on k - d",
    generate: exact,
};

fn exact(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (2, 4));
    // k - d = round(Δd √n) exactly.
    let n = rng.range(2, 5);
    let q = t.dd;
    let level =
        i64::try_from(cycleref::engine::round_sqrt(u128::try_from(q * q * n).unwrap_or(0))).unwrap_or(q);
    t.k = level + t.allowance;
    t.dmin = 0;
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// R(d) = P(k): finishing passes only.
pub(super) const D_EQUALS_K: Template = Template {
    id: "g76-d-equals-k",
    outcome: Expected::Valid(&["schedule:d-equals-k"]),
    tags: &["template:g76-d-equals-k"],
    description: "G76 with R(d) = P(k): no rough pass, finishing passes only",
    generate: d_equals_k,
};

fn d_equals_k(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 2));
    t.allowance = t.k;
    t.dmin = t.dmin.min(t.k);
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(rng.range(1, 3), rng.range(0, 5), tool_angle(rng)));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// The lead in threads per inch.
pub(super) const I_LEAD: Template = Template {
    id: "g76-i-lead",
    outcome: Expected::Valid(&["lead:I"]),
    tags: &["template:g76-i-lead"],
    description: "G76 with the lead in threads per inch (I)",
    generate: i_lead,
};

fn i_lead(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (2, 4));
    t.lead = ctx.lead(rng, Some(LeadWord::I)).0;
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// Values from the parameters, then from a modal block 1.
pub(super) const PARAMS_MODAL: Template = Template {
    id: "g76-params-modal",
    outcome: Expected::Valid(&[]),
    tags: &["template:g76-params-modal", "params:block1", "block1-modal", "lead-modal"],
    description: "G76 values from the parameters, then from a block 1 that stays in force; the lead is modal",
    generate: params_modal,
};

/// Cycle 1 from the parameters (no block 1), cycle 2 with a block 1,
/// cycle 3 with the modal values of that block 1 and the modal lead.
fn params_modal(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(any_profile(rng), rng);
    let t = small_thread(rng, &ctx);
    let p = ctx.profile_data();
    let names = &p.params;
    ctx.params.insert(names.finishing_passes, Param::Int(rng.range(1, 2)));
    ctx.params.insert(names.tool_angle, Param::Int(tool_angle(rng)));
    ctx.params.insert(names.chamfer, Param::Int(rng.range(0, 8)));
    ctx.params.insert(names.min_cut, Param::Len(t.dmin));
    ctx.params.insert(names.finishing_allowance, Param::Len(t.allowance));
    let mut lines = head(rng, &ctx, t.a);
    let mut g = G76 { block1: false, ..G76::plain() };
    lines.extend(g76_lines(&ctx, &t, &g));
    let mut t2 = t.clone();
    t2.allowance = 0;
    g.block1 = true;
    g.p = Some(pmra(1, rng.range(0, 5), tool_angle(rng)));
    lines.extend(g76_lines(&ctx, &t2, &g));
    g.block1 = false;
    g.omit = "F";
    lines.extend(g76_lines(&ctx, &t2, &g));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// FANUC, every length in least increments.
pub(super) const FANUC_BARE: Template = Template {
    id: "fanuc-bare",
    outcome: Expected::Valid(&[]),
    tags: &["template:fanuc-style"],
    description: "FANUC G76 with every length in least increments, no decimal point",
    generate: |rng| fanuc_style(rng, false),
};

/// FANUC, calculator-type input.
pub(super) const FANUC_CALC: Template = Template {
    id: "fanuc-calc",
    outcome: Expected::Valid(&[]),
    tags: &["template:fanuc-style"],
    description: "FANUC G76 with calculator-type input: lengths without a decimal point are mm (inch)",
    generate: |rng| fanuc_style(rng, true),
};

/// A FANUC G76 with calculator-type input (`calc`) or with bare lengths.
fn fanuc_style(rng: &mut Rng, calc: bool) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Fanuc, rng);
    ctx.calculator_input = calc;
    ctx.bare = !calc;
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let g = G76::usual(rng, &ctx);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// GSK 980TDi P(m)(r)(a) in part.
pub(super) const PARTIAL_P: Template = Template {
    id: "gsk980-partial-p",
    outcome: Expected::Valid(&["finish:none"]),
    tags: &["template:gsk980-partial-p", "p:partial"],
    description: "GSK 980TDi P(m)(r)(a) written in part (note 4): m = 0, then a alone, then r and a",
    generate: partial_p,
};

fn partial_p(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let t = small_thread(rng, &ctx);
    let mut lines = head(rng, &ctx, t.a);
    let a = tool_angle(rng);
    let r = rng.range(0, 9);
    // P(m)(r)(a) with m = 0 (00..99 on the 980TDi), then "P(a)" and "P(r)(a)" alone.
    let ps = [pmra(0, r, a), format!("{a:02}"), format!("{:02}{:02}", rng.range(0, 9), tool_angle(rng))];
    for p in ps {
        let g = G76 { p: Some(p), ..G76::plain() };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

// ---- what a G76 shows ----
