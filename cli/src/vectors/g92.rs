//! G92 threads: the valid G92 templates and the features a G92 block
//! shows.
//!
//! A G92 program is written as the manuals' examples are: a first block
//! with the cut end, the lead and the run-out, then blocks giving only the
//! next X (the modal values repeat), each one pass of the same thread.

use std::fmt::Write as _;

use cycleref::CycleError;
use cycleref_spec::{ErrorKind, ProfileName};

use super::g32::{line32, Line32};
use super::machine::{any_profile, gsk, head, MachineStyle, Param};
use super::{Draft, Expected, Rng, Template};

/// A G92 block: `G92` (on the first block of the mode) and its words.
fn g92(first: bool, words: &[String]) -> String {
    let mut s = String::from(if first { "G92" } else { "" });
    for w in words {
        if !s.is_empty() {
            s.push(' ');
        }
        let _ = write!(s, "{w}");
    }
    s
}

/// A start point A clear of the thread `l` (radius values, the side of
/// `l`): `clear` beyond its crest at the start and at the end, on the Z of
/// its start.
fn start_point(ctx: &MachineStyle, l: &Line32, k: i64, clear: i64) -> (i64, i64) {
    let reach = if l.side > 0 { l.taper.max(0) } else { l.taper.min(0) };
    (ctx.xf() * (l.r0 + reach + l.side * (k + clear)), l.z0)
}

/// The start of a refused template's axial G92: its context on
/// `profile`, a G32-like thread line, the thread height k (0.6 × the lead)
/// and a start point A 1-3 mm clear of it. The draws are made in this
/// order, so the corpus stays what it was.
fn refused_start(rng: &mut Rng, profile: ProfileName) -> (MachineStyle, Line32, i64, (i64, i64)) {
    let ctx = MachineStyle::new(profile, rng);
    let l = line32(rng, &ctx, false);
    let k = l.lead_inc * 6 / 10;
    let a = start_point(&ctx, &l, k, ctx.mm(rng.range(1000, 3000)));
    (ctx, l, k, a)
}

/// The blocks of one thread cut in passes at the depths `depths` of a
/// thread `k` deep: the first names X, Z, R, the lead and `extra`; the
/// others only X (the rest is modal, R-G92MODAL). The cut end X of pass
/// n is the crest line's end less its depth.
fn passes_lines(ctx: &MachineStyle, l: &Line32, k: i64, depths: &[i64], extra: &[String]) -> Vec<String> {
    let xf = ctx.xf();
    let mut lines = Vec::new();
    for (n, depth) in depths.iter().enumerate() {
        // Radius of the crest at C (the end), less the pass's depth.
        let end_r = l.r0 + l.taper + l.side * (k - depth);
        let x = format!("X{}", ctx.num(xf * end_r));
        if n == 0 {
            let mut words = vec![x, format!("Z{}", ctx.num(l.z1))];
            if l.taper != 0 {
                // R: X of B minus X of C, radius.
                words.push(format!("R{}", ctx.num(-l.taper)));
            }
            words.push(l.lead.clone());
            words.extend(extra.iter().cloned());
            lines.push(g92(true, &words));
        } else {
            lines.push(x);
        }
    }
    lines
}

// ---- the valid G92 templates ----

/// A thread cut in three or four G92 blocks, the manuals' way.
pub(super) const PASSES: Template = Template {
    id: "g92-passes",
    // The draft requires g92:straight or g92:taper, as it drew.
    outcome: Expected::Valid(&["g92"]),
    tags: &["template:g92-passes", "rule:g92-modal"],
    description: "G92 thread cut in passes, blocks after the first giving only X",
    generate: passes,
};

fn passes(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let taper = rng.chance(40);
    let l = line32(rng, &ctx, taper);
    let k = l.lead_inc * 6 / 10;
    let depths =
        if rng.chance(50) { vec![k / 2, k * 4 / 5, k] } else { vec![k / 3, k * 2 / 3, k * 9 / 10, k] };
    let run_out = ctx.profile != ProfileName::Fanuc && rng.chance(60);
    let extra = if run_out {
        vec![
            format!("J{}", ctx.num(ctx.mm(rng.range(500, 2000)))),
            format!("K{}", ctx.num(ctx.mm(rng.range(500, 3000)))),
        ]
    } else if ctx.profile == ProfileName::Gsk980 {
        // J0: none (note 5); without it No.19 decides.
        vec!["J0".to_string()]
    } else {
        vec![]
    };
    let a = start_point(&ctx, &l, k, ctx.mm(rng.range(2000, 5000)));
    let mut lines = head(rng, &ctx, a);
    lines.extend(passes_lines(&ctx, &l, k, &depths, &extra));
    lines.push("M30".into());
    let what = if taper { "taper" } else { "straight" };
    let side = if l.side > 0 { "external" } else { "internal" };
    Draft::new(ctx, lines)
        .described(format!("G92 {what} {side} thread cut in {} blocks, X only after the first", depths.len()))
        .requiring(if taper { &["g92:taper"] } else { &["g92:straight"] })
        .tag_if(run_out, "g92:run-out")
}

/// The 980TDi's run-out notes, block by block (J and K modal).
pub(super) const RUNOUT_980: Template = Template {
    id: "g92-run-out-gsk980",
    outcome: Expected::Valid(&["g92:run-out", "g92:chamfer", "g92:multi-start"]),
    tags: &[
        "template:g92-run-out-gsk980",
        "rule:g92-gsk980-jk",
        "rule:g92-gsk980-k0",
        "rule:g92-gsk980-j0",
        "rule:g92-gsk980-no19",
        "rule:g92-modal",
    ],
    description:
        "GSK 980TDi G92 two-start thread, run-out notes: J and K; K0 (K = J); J0 (none); after G00, \
                  J and K omitted (No.19)",
    generate: runout_980,
};

fn runout_980(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    ctx.params.insert("19", Param::Int(rng.range(1, 20)));
    let taper = rng.chance(30);
    let l = line32(rng, &ctx, taper);
    let k = l.lead_inc * 6 / 10;
    let (j, kk) = (ctx.mm(rng.range(300, 1500)), ctx.mm(rng.range(500, 2500)));
    let a = start_point(&ctx, &l, k, ctx.mm(rng.range(2000, 4000)));
    let mut lines = head(rng, &ctx, a);
    let jk = [format!("J{}", ctx.num(j)), format!("K{}", ctx.num(kk))];
    let mut first = jk.to_vec();
    first.push("L2".into());
    let mut blocks = passes_lines(&ctx, &l, k, &[k / 2, k * 3 / 4, k], &first);
    // Block 2: K0 (K = J); block 3: J0 (none).
    blocks[1].push_str(" K0");
    blocks[2].push_str(" J0");
    lines.extend(blocks);
    // The mode ends; a new G92 without J, K: No.19's chamfer.
    lines.push(format!("G00 X{} Z{}", ctx.num(a.0), ctx.num(a.1)));
    lines.extend(passes_lines(&ctx, &l, k, &[k], &[]));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// The 988TA's normal-mode rules (THM = 0).
pub(super) const RUNOUT_988: Template = Template {
    id: "g92-run-out-gsk988",
    outcome: Expected::Valid(&["g92:run-out", "g92:pull-out", "g92:chamfer"]),
    tags: &[
        "template:g92-run-out-gsk988",
        "rule:g92-gsk988-jk",
        "rule:g92-gsk988-j-only",
        "rule:g92-gsk988-k-only",
        "rule:g92-gsk988-5130",
    ],
    description:
        "GSK 988TA G92 normal mode: J and K; J only (a pull-out along X at C); K only (none); J and K \
                  omitted (5130, 5131)",
    generate: runout_988,
};

fn runout_988(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    ctx.params.insert("5130", Param::Int(rng.range(1, 20)));
    ctx.params.insert("5131", Param::Int(rng.pick(&[0, 30, 45, 60])));
    let l = line32(rng, &ctx, false);
    let k = l.lead_inc * 6 / 10;
    run_out_variants(rng, ctx, &l, k, true)
}

/// One G92 at depth `k` of thread `l` for each run-out variant: J and K, J
/// only, K only and, with `neither`, none; the first straight after the
/// head, each later one from a G00 back to A (which ends the mode and its
/// J, K); then M30.
fn run_out_variants(rng: &mut Rng, ctx: MachineStyle, l: &Line32, k: i64, neither: bool) -> Draft {
    let (j, kk) = (ctx.mm(rng.range(300, 1500)), ctx.mm(rng.range(500, 2500)));
    let a = start_point(&ctx, l, k, ctx.mm(rng.range(2000, 4000)));
    let mut lines = head(rng, &ctx, a);
    let mut variants: Vec<Vec<String>> = vec![
        vec![format!("J{}", ctx.num(j)), format!("K{}", ctx.num(kk))],
        vec![format!("J{}", ctx.num(j))],
        vec![format!("K{}", ctx.num(kk))],
    ];
    if neither {
        variants.push(vec![]);
    }
    for (n, words) in variants.iter().enumerate() {
        if n > 0 {
            lines.push(format!("G00 X{} Z{}", ctx.num(a.0), ctx.num(a.1)));
        }
        lines.extend(passes_lines(&ctx, l, k, &[k], words));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// Multi-start G92 on the 988TA, the first start at Q (the 980TDi's L is
/// in its run-out template).
pub(super) const MULTI_START: Template = Template {
    id: "g92-multi-start",
    outcome: Expected::Valid(&["g92:multi-start", "g92:q", "g92:internal"]),
    tags: &["template:g92-multi-start", "rule:starts"],
    description: "GSK 988TA G92 internal multi-start thread: each start a full pass from A, the first at Q, \
                  the others 360/L apart",
    generate: multi_start,
};

fn multi_start(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let l = line32(rng, &ctx, false);
    let k = l.lead_inc * 6 / 10;
    let starts = rng.range(2, 4);
    let extra = vec![format!("L{starts}"), format!("Q{}", ctx.q(rng.pick(&[15_000, 30_000, 90_000])))];
    let mut lines = head(rng, &ctx, start_point(&ctx, &l, k, ctx.mm(3000)));
    lines.extend(passes_lines(&ctx, &l, k, &[k / 2, k], &extra));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A face thread (988TA P1): the cut along X at a Z, the infeed along Z.
pub(super) const FACE: Template = Template {
    id: "g92-face",
    outcome: Expected::Valid(&["g92:face"]),
    tags: &["template:g92-face", "rule:g92-face"],
    description:
        "GSK 988TA G92 P1 face thread cut in two blocks (Z only in the second), J along Z, K along X",
    generate: face,
};

fn face(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let xf = ctx.xf();
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = lead_inc * 6 / 10;
    let outer = ctx.mm(rng.range(30_000, 45_000));
    let inner = ctx.mm(rng.range(6_000, 15_000));
    let inward = rng.chance(70);
    let (x0, x1) = if inward { (outer, inner) } else { (inner, outer) };
    let dir = rng.sign();
    let z_face = ctx.mm(rng.range(-2000, 2000));
    let clear = ctx.mm(rng.range(2000, 4000));
    // A on the dir side of the face; each pass's cut end lies deeper into
    // the face, away from A.
    let a = (xf * x0, z_face + dir * (k + clear));
    let mut lines = head(rng, &ctx, a);
    let j = ctx.mm(rng.range(300, 1500));
    let kk = ctx.mm(rng.range(500, 2000));
    lines.push(format!(
        "G92 X{} Z{} {lead} J{} K{} P1",
        ctx.num(xf * x1),
        ctx.num(z_face + dir * (k / 2)),
        ctx.num(j),
        ctx.num(kk)
    ));
    lines.push(format!("Z{}", ctx.num(z_face)));
    lines.push("M30".into());
    let what = if inward { "towards the centre" } else { "outwards" };
    Draft::new(ctx, lines).described(format!("GSK 988TA G92 P1 face thread in two blocks, cut {what}"))
}

/// The 988TA's high-speed mode (THM, 5129 = 1, R-G92RUNOUT).
pub(super) const HIGH_SPEED: Template = Template {
    id: "g92-high-speed",
    outcome: Expected::Valid(&["g92:run-out"]),
    tags: &["template:g92-high-speed", "rule:g92-gsk988-high-speed"],
    description:
        "GSK 988TA G92 high-speed mode (5129 = 1): J and K; J only (no run-out, the rapid retract); \
                  K only (K along Z, X out to the start's X)",
    generate: high_speed,
};

fn high_speed(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    ctx.params.insert("5129", Param::Int(1));
    let taper = rng.chance(30);
    let l = line32(rng, &ctx, taper);
    let k = l.lead_inc * 6 / 10;
    run_out_variants(rng, ctx, &l, k, false)
}

/// A steep taper on the 980TDi: X the long axis.
pub(super) const X_LONG: Template = Template {
    id: "g92-x-long",
    outcome: Expected::Valid(&["g92:x-long", "g92:taper", "g92:external"]),
    tags: &["template:g92-x-long", "rule:long-axis"],
    description: "G92 steep taper, |R| >= |W|, the cut line falling away from the start point: X the long \
                  axis, the run-out K along X and J along Z",
    generate: x_long,
};

/// A steep taper on the 988TA: Z the long axis by its table (R-LONG988
/// `table`), either slope.
pub(super) const LONG_TABLE: Template = Template {
    id: "g92-long-table",
    outcome: Expected::Valid(&["g92:long-table", "g92:taper"]),
    tags: &["template:g92-long-table", "rule:long-axis"],
    description:
        "GSK 988TA G92 steep taper, |R| >= |W|: Z the long axis by the 988TA's table (\"P = 0（轴向螺纹）\
                  长轴：横轴\", R-LONG988), the run-out K along Z and J along X",
    generate: long_table,
};

fn long_table(rng: &mut Rng) -> Draft {
    let rising = rng.chance(50);
    steep(rng, ProfileName::Gsk988, rising)
}

fn x_long(rng: &mut Rng) -> Draft {
    steep(rng, ProfileName::Gsk980, false)
}

/// A steep taper whose X travel (radius) exceeds its Z travel, with a run-out
/// J K: its cut line falls away from A towards C (the radius grows towards
/// C on an external thread), so the run-out along Z towards A ends in the
/// air, or, `rising`, the other slope, which R-XRUNOUT refuses.
/// On the 988TA its table makes Z the long axis whatever the slope
/// (R-LONG988 `table`): the run-out is along X, out of the work.
fn steep(rng: &mut Rng, profile: ProfileName, rising: bool) -> Draft {
    let ctx = MachineStyle::new(profile, rng);
    let mut l = line32(rng, &ctx, false);
    l.len = ctx.mm(rng.range(2000, 5000));
    l.z1 = l.z0 + l.dir * l.len;
    let slope = if rising { -l.side } else { l.side };
    l.taper = slope * (l.len + ctx.mm(rng.range(100, 4000)));
    l.r0 = l.r0.max(l.taper.abs() + ctx.mm(8000));
    let k = l.lead_inc * 6 / 10;
    let extra = vec![
        format!("J{}", ctx.num(ctx.mm(rng.range(300, 1000)))),
        format!("K{}", ctx.num(ctx.mm(rng.range(300, 1500)))),
    ];
    let mut lines = head(rng, &ctx, start_point(&ctx, &l, k, ctx.mm(3000)));
    lines.extend(passes_lines(&ctx, &l, k, &[k / 2, k], &extra));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

// ---- the refused G92 templates ----

/// R against U beyond the manual's condition |R| <= |U/2|.
pub(super) const TAPER_BEYOND: Template = Template {
    id: "g92-taper-beyond-start",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::TaperBeyondStart { .. }))),
    tags: &["refuse:g92-taper-beyond-start"],
    description:
        "G92 whose R and U differ in sign with |R| > |U/2|: the cut start B lies beyond the start point",
    generate: taper_beyond,
};

fn taper_beyond(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, l, k, a) = refused_start(rng, profile);
    let xf = ctx.xf();
    // C at the crest; R towards A, one increment to 2 mm beyond A (radius).
    let c_r = l.r0 + l.side * k;
    let gap = a.0 / xf - c_r;
    let r = gap + l.side * ctx.mm(rng.range(1, 2000)).max(1);
    let mut lines = head(rng, &ctx, a);
    lines.push(g92(
        true,
        &[
            format!("X{}", ctx.num(xf * c_r)),
            format!("Z{}", ctx.num(l.z1)),
            format!("R{}", ctx.num(r)),
            l.lead.clone(),
        ],
    ));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A cut end on the X of the start point.
pub(super) const NO_INFEED: Template = Template {
    id: "g92-no-infeed",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::NoInfeed))),
    tags: &["refuse:g92-no-infeed"],
    description: "G92 whose cut end has the X of the start point (U0): no side for the run-out and retract",
    generate: no_infeed,
};

fn no_infeed(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, l, _, a) = refused_start(rng, profile);
    let mut lines = head(rng, &ctx, a);
    let x = if rng.chance(50) { format!("X{}", ctx.num(a.0)) } else { format!("U{}", ctx.num(0)) };
    lines.push(g92(true, &[x, format!("Z{}", ctx.num(l.z1)), l.lead.clone()]));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// An X-long thread whose cut line rises towards the start point, with a
/// run-out: J along Z towards A would end in the work (R-XRUNOUT).
pub(super) const RUN_OUT_INTO_WORK: Template = Template {
    id: "g92-run-out-into-work",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::RunOutIntoWork { .. }))),
    tags: &["refuse:run-out-into-work"],
    description:
        "G92 steep taper on the 980TDi (X the long axis) rising towards the start point, with a run-out \
                  J: along Z towards A it would end in the work",
    generate: run_out_into_work,
};

fn run_out_into_work(rng: &mut Rng) -> Draft {
    steep(rng, ProfileName::Gsk980, true)
}

/// K along the long axis longer than the thread (988TA note 4, R-SHORT).
pub(super) const RUN_OUT_LONG: Template = Template {
    id: "g92-run-out-too-long",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::RunOutTooLong { .. }))),
    tags: &["refuse:g92-run-out-too-long"],
    description: "G92 whose run-out K along the long axis is longer than the thread (988TA note 4)",
    generate: run_out_long,
};

fn run_out_long(rng: &mut Rng) -> Draft {
    let profile = gsk(rng);
    let (ctx, l, k, a) = refused_start(rng, profile);
    let extra = [
        format!("J{}", ctx.num(ctx.mm(rng.range(300, 1000)))),
        format!("K{}", ctx.num(l.len + ctx.mm(rng.range(1, 2000)).max(1))),
    ];
    let mut lines = head(rng, &ctx, a);
    lines.extend(passes_lines(&ctx, &l, k, &[k], &extra));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// An axial G92 whose cut end has the Z of the start point (980TDi "也不能
/// 加工端面螺纹"; on the 988TA a face thread needs P1).
pub(super) const FACE_THREAD: Template = Template {
    id: "g92-face-thread",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::FaceThread))),
    tags: &["refuse:g92-face-thread"],
    description: "axial G92 whose cut end has the Z of the start point (W0): a face thread",
    generate: face_thread,
};

fn face_thread(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, l, k, a) = refused_start(rng, profile);
    let x = format!("X{}", ctx.num(ctx.xf() * (l.r0 + l.side * (k / 2))));
    let z = if rng.chance(50) { format!("Z{}", ctx.num(a.1)) } else { format!("W{}", ctx.num(0)) };
    let mut lines = head(rng, &ctx, a);
    lines.push(g92(true, &[x, z, l.lead.clone()]));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// The start of a 988TA P1 face thread: A at X `x0`, the face at `z_face`,
/// A on the `dir` side of it.
fn face_start(rng: &mut Rng, ctx: &MachineStyle) -> (String, i64, i64, i64, i64) {
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = lead_inc * 6 / 10;
    let x0 = ctx.mm(rng.range(30_000, 45_000));
    let dir = rng.sign();
    let z_face = ctx.mm(rng.range(-2000, 2000));
    (lead, k, x0, dir, z_face + dir * (k + ctx.mm(rng.range(2000, 4000))))
}

/// A 988TA P1 face thread whose cut end has the X of the start point.
pub(super) const NO_THREAD_LENGTH: Template = Template {
    id: "g92-no-thread-length",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::NoThreadLength))),
    tags: &["refuse:g92-no-thread-length"],
    description: "GSK 988TA G92 P1 face thread whose cut end has the X of the start point (U0): no length",
    generate: no_thread_length,
};

fn no_thread_length(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let (lead, k, x0, dir, za) = face_start(rng, &ctx);
    let a = (ctx.xf() * x0, za);
    let mut lines = head(rng, &ctx, a);
    let x = if rng.chance(50) { format!("X{}", ctx.num(a.0)) } else { format!("U{}", ctx.num(0)) };
    lines.push(format!("G92 {x} Z{} {lead} P1", ctx.num(za - dir * (k + ctx.mm(2000)))));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A 988TA P1 face thread whose Z travel |R| exceeds its X travel (radius).
pub(super) const STEEP_FACE: Template = Template {
    id: "g92-steep-face-thread",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::SteepFaceThread { .. }))),
    tags: &["refuse:g92-steep-face-thread"],
    description: "GSK 988TA G92 P1 face thread whose taper R along Z exceeds its X travel (radius), under \
                  R-LONG988=displacement: Z would be its long axis (R-G92FACE; under the default `table` it is \
                  made with X long)",
    generate: steep_face,
};

fn steep_face(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    // The refusal is R-LONG988 `displacement`'s: under `table` (the
    // default) the 988TA's table makes X long whatever the displacements.
    ctx.readings.long988 = Some(cycleref_spec::readings::Long988::Displacement);
    let (lead, k, x0, dir, za) = face_start(rng, &ctx);
    let xf = ctx.xf();
    let a = (xf * x0, za);
    // A short X travel (radius), and R beyond it, away from A along Z.
    let travel = ctx.mm(rng.range(1000, 3000));
    let x1 = x0 - travel;
    let r = -dir * (travel + ctx.mm(rng.range(1, 2000)).max(1));
    let mut lines = head(rng, &ctx, a);
    lines.push(format!(
        "G92 X{} Z{} R{} {lead} P1",
        ctx.num(xf * x1),
        ctx.num(za - dir * (k + ctx.mm(2000))),
        ctx.num(r)
    ));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// L outside the profile's range (980TDi 1～99, 988TA 1～999).
pub(super) const STARTS_RANGE: Template = Template {
    id: "g92-starts-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g92-starts-out-of-range"],
    description: "G92 whose L is outside the profile's range (980TDi 1-99, 988TA 1-999)",
    generate: starts_range,
};

fn starts_range(rng: &mut Rng) -> Draft {
    let profile = gsk(rng);
    let (ctx, l, k, a) = refused_start(rng, profile);
    let over = if ctx.profile == ProfileName::Gsk980 { rng.range(100, 999) } else { rng.range(1000, 9999) };
    let starts = if rng.chance(25) { 0 } else { over };
    let mut lines = head(rng, &ctx, a);
    lines.extend(passes_lines(&ctx, &l, k, &[k], &[format!("L{starts}")]));
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("G92 with L{starts}, outside the profile's range"))
}

/// The 988TA's P (thread type) other than 0 and 1.
pub(super) const P_RANGE: Template = Template {
    id: "g92-p-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g92-p-out-of-range"],
    description: "GSK 988TA G92 whose P (thread type: 0 axial, 1 face) is 2 or more",
    generate: p_range,
};

fn p_range(rng: &mut Rng) -> Draft {
    let (ctx, l, k, a) = refused_start(rng, ProfileName::Gsk988);
    let mut lines = head(rng, &ctx, a);
    lines.extend(passes_lines(&ctx, &l, k, &[k], &[format!("P{}", rng.range(2, 9))]));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

// ---- what a G92 block shows ----
