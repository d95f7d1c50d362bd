//! The templates of programs that must be refused: each breaks one rule of
//! the manual or of the reader, and its entry names the error kind it must
//! end in.
//!
//! Most start from a usual program ([`base`] for a G76,
//! [`g75_base`](grooves::g75_base) for a G75.1, or a G32 thread of
//! [`super::g32`]) and break one thing; where a template draws among
//! several ways to break the rule, the description of the case names the
//! one drawn. The G75.1 templates are in `refused/grooves.rs`.

use cycleref::{CycleError, InputUnit};
use cycleref_spec::{ErrorKind, ProfileName};

use super::g32::{g32, line32};
use super::g76::{g76_lines, g76_program, pmra, thread, Taper, Thread, G76};
use super::machine::{any_profile, decimal, gsk, head, MachineStyle, Param};
use super::{Draft, Expected, Refusal, Rng, Template};

mod grooves;

pub(super) use grooves::{
    G75_ALLOWANCE, G75_ANGLE, G75_CORNER, G75_LONE, G75_MISSING, G75_NARROW, G75_NO_DEPTH, G75_RIDGES,
    G75_SLOPE, G75_TOO_MANY_PECKS, G75_WORD,
};

// ---- G76, G32 and the reader ----

/// A usual one-G76 draft to break.
fn base(profile: ProfileName, rng: &mut Rng) -> (MachineStyle, Thread, G76) {
    let ctx = MachineStyle::new(profile, rng);
    let t = thread(rng, &ctx, Taper::Straight, (1, 3));
    let g = G76::usual(rng, &ctx);
    (ctx, t, g)
}

/// G76 block 2 without P(k).
pub(super) const MISSING_P: Template = Template {
    id: "missing-p",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:missing-p"],
    description: "G76 block 2 without P(k)",
    generate: missing_p,
};

fn missing_p(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(any_profile(rng), rng);
    g.omit = "P";
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// G76 block 2 without Q(Δd).
pub(super) const MISSING_Q: Template = Template {
    id: "missing-q",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:missing-q"],
    description: "G76 block 2 without Q(Δd)",
    generate: missing_q,
};

fn missing_q(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(any_profile(rng), rng);
    g.omit = "Q";
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// Note 6: Q(Δdmin) above P(k).
pub(super) const MIN_CUT: Template = Template {
    id: "min-cut-above-height",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::MinCutExceedsHeight { .. }))),
    tags: &["refuse:min-cut-above-height"],
    description: "G76 with Q(Δdmin) > P(k) (note 6)",
    generate: min_cut,
};

fn min_cut(rng: &mut Rng) -> Draft {
    let (mut ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.dmin = t.k + ctx.mm(rng.range(1, 500)).max(1);
    let from_params = rng.chance(30);
    if from_params {
        let name = ctx.param_name(|p| p.params.min_cut);
        ctx.params.insert(name, Param::Len(t.dmin));
        g.block1 = false;
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines).tag_if(from_params, "params:block1")
}

/// Note 6: R(d) above P(k).
pub(super) const ALLOWANCE: Template = Template {
    id: "allowance-above-height",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::AllowanceExceedsHeight { .. }))),
    tags: &["refuse:allowance-above-height"],
    description: "G76 with R(d) > P(k) (note 6)",
    generate: allowance,
};

fn allowance(rng: &mut Rng) -> Draft {
    let (mut ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.allowance = t.k + ctx.mm(rng.range(1, 500)).max(1);
    t.dmin = t.dmin.min(t.k);
    let from_params = rng.chance(30);
    if from_params {
        let name = ctx.param_name(|p| p.params.finishing_allowance);
        ctx.params.insert(name, Param::Len(t.allowance));
        let min = ctx.param_name(|p| p.params.min_cut);
        ctx.params.insert(min, Param::Len(t.dmin));
        g.block1 = false;
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines).tag_if(from_params, "params:block1")
}

/// Note 7: a run-out longer than the thread.
pub(super) const RUN_OUT_LONG: Template = Template {
    id: "run-out-too-long",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::RunOutTooLong { .. }))),
    tags: &["refuse:run-out-too-long"],
    description: "G76 whose run-out is longer than the thread (note 7)",
    generate: run_out_long,
};

fn run_out_long(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, mut t, mut g) = base(profile, rng);
    match profile {
        // LinuxCnc: never drawn (any_profile draws FANUC and GSK profiles).
        ProfileName::Fanuc | ProfileName::LinuxCnc => {
            // The chamfer r × 0.1 × lead beyond a short thread.
            let dir = if t.d.1 < t.a.1 { -1 } else { 1 };
            t.w = ctx.mm(rng.range(3000, 6000));
            t.d.1 = t.a.1 + dir * t.w;
            g.p = Some(pmra(1, rng.range(90, 99), rng.pick(&[0, 29, 30, 55, 60])));
            g.incremental = false;
        }
        ProfileName::Gsk980 => {
            g.extra1 =
                vec![format!("J{}", ctx.num(ctx.mm(1000))), format!("K{}", ctx.num(t.w + ctx.mm(1000)))];
        }
        ProfileName::Gsk988 => {
            g.extra2 =
                vec![format!("J{}", ctx.num(ctx.mm(1000))), format!("K{}", ctx.num(t.w + ctx.mm(1000)))];
        }
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// Note 8: no spindle speed.
pub(super) const NO_SPINDLE: Template = Template {
    id: "no-spindle-speed",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::NoSpindleSpeed)),
    tags: &["refuse:no-spindle-speed"],
    description: "G76 or G32 without a spindle speed (note 8)",
    generate: no_spindle,
};

fn no_spindle(rng: &mut Rng) -> Draft {
    let (ctx, t, g) = base(any_profile(rng), rng);
    let mut lines = Vec::new();
    if ctx.g20 {
        lines.push("G20".to_string());
    }
    let variant = rng.range(0, 3);
    match variant {
        0 => {}
        1 => {
            lines.push("M03 S500".into());
            lines.push("M05".into());
        }
        2 => {
            lines.push("M03".into());
            lines.push("G50 S2000".into());
        }
        _ => lines.push("S500".into()),
    }
    lines.push(format!("G00 X{} Z{}", ctx.num(t.a.0), ctx.num(t.a.1)));
    let g32_variant = rng.chance(30);
    if g32_variant {
        lines.push(g32(&ctx, None, Some(t.d.1), std::slice::from_ref(&t.lead)));
    } else {
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    let why = ["no S and no M03", "the spindle stopped by M05", "G50 S alone (a clamp)", "no M03"]
        [usize::try_from(variant).unwrap_or(0)];
    let what = if g32_variant { "G32" } else { "G76" };
    Draft::new(ctx, lines).described(format!("{what} without a spindle speed: {why} (note 8)"))
}

/// G76 cannot cut a face thread.
pub(super) const FACE_THREAD: Template = Template {
    id: "g76-face-thread",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::FaceThread))),
    tags: &["refuse:g76-face-thread"],
    description: "G76 face thread: the end point has the Z of the start",
    generate: face_thread,
};

fn face_thread(rng: &mut Rng) -> Draft {
    let (ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.d.1 = t.a.1;
    g.incremental = rng.chance(50);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A G76 word outside its range table.
pub(super) const OUT_OF_RANGE: Template = Template {
    id: "out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:out-of-range"],
    description: "G76 with a value outside its range",
    generate: out_of_range,
};

fn out_of_range(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, mut t, mut g) = base(profile, rng);
    let big_f = if ctx.unit == InputUnit::Metric { "F10000" } else { "F10" };
    let mut variants: Vec<(&str, u8)> =
        vec![("P(m)(r)(a) of seven digits", 0), ("lead F beyond the range table", 1), ("P(k) = 0", 2)];
    match profile {
        ProfileName::Gsk988 => {
            variants.extend([
                ("L1000 starts", 3),
                ("infeed D3", 4),
                ("negative J", 5),
                ("m = 0 (01..99)", 6),
            ]);
        }
        // LinuxCnc: never drawn (any_profile draws FANUC and GSK profiles).
        ProfileName::Fanuc | ProfileName::LinuxCnc => variants.push(("m = 0 (01..99)", 6)),
        ProfileName::Gsk980 => {
            variants.extend([("negative K in block 1", 7), ("negative E in a G78 block 1 (R-E980)", 8)]);
        }
    }
    let (what, v) = rng.pick(&variants);
    match v {
        0 => g.p = Some(format!("1{}", pmra(1, 0, 60))),
        1 => t.lead = big_f.into(),
        2 => t.k = 0,
        3 => g.extra1.push("L1000".into()),
        4 => g.extra1.push("D3".into()),
        5 => g.extra2.push(format!("J-{}", ctx.num(ctx.mm(1000)))),
        6 => g.p = Some(pmra(0, 5, 60)),
        7 => g.extra1.push(format!("K-{}", ctx.num(ctx.mm(1000)))),
        // The 980TDi's G78 (its P: m the depth mode 0-1, r the infeed mode
        // 0-3): E "无符号" with the range "-9999.9999~9999.9999".
        _ => {
            g.p = Some(pmra(1, rng.range(0, 3), 60));
            g.extra1.push(format!("E-{}", ctx.num(ctx.mm(rng.range(300, 2000)))));
        }
    }
    let mut lines = g76_program(rng, &ctx, &t, &g);
    if v == 8 {
        lines = lines
            .into_iter()
            .map(|l| l.strip_prefix("G76").map_or(l.clone(), |rest| format!("G78{rest}")))
            .collect();
    }
    Draft::new(ctx, lines).described(format!("G76 with a value outside its range: {what}"))
}

/// FANUC: P and Q take no decimal point.
pub(super) const FANUC_POINT: Template = Template {
    id: "fanuc-decimal-point",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::DecimalPointNotAllowed { .. })),
    tags: &["refuse:fanuc-decimal-point"],
    description: "FANUC: P or Q with a decimal point (P/Q in least increments)",
    generate: fanuc_point,
};

fn fanuc_point(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(ProfileName::Fanuc, rng);
    let variant = rng.range(0, 3);
    let mut lines;
    let what = match variant {
        0 => {
            lines = head(rng, &ctx, t.a);
            let mut b = g76_lines(&ctx, &t, &g);
            let dec = decimal(t.k, ctx.decimals(), true);
            let last = b.pop().unwrap_or_default();
            b.push(last.replacen(&format!(" P{}", t.k), &format!(" P{dec}"), 1));
            lines.extend(b);
            "P(k) with a decimal point"
        }
        1 => {
            lines = head(rng, &ctx, t.a);
            let mut b = g76_lines(&ctx, &t, &g);
            let dec = decimal(t.dmin.max(1), ctx.decimals(), true);
            b[0] = format!("G76 P{} Q{dec} R{}", g.p.clone().unwrap_or_default(), ctx.num(t.allowance));
            lines.extend(b);
            "Q(Δdmin) with a decimal point"
        }
        2 => {
            lines = head(rng, &ctx, t.a);
            g.p = Some(format!("{}.0", pmra(1, 0, 60)));
            lines.extend(g76_lines(&ctx, &t, &g));
            "P(m)(r)(a) with a decimal point"
        }
        _ => {
            lines = head(rng, &ctx, t.a);
            lines.push(g32(&ctx, None, Some(t.d.1), &[t.lead.clone(), "Q180.0".into()]));
            "G32 Q with a decimal point"
        }
    };
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("FANUC: {what} (P/Q in least increments)"))
}

/// P(m)(r)(a) in part where only the 980TDi allows it.
pub(super) const PARTIAL_P: Template = Template {
    id: "partial-p",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::PartialP)),
    tags: &["refuse:partial-p"],
    description: "P(m)(r)(a) written in part where the profile allows it only as a whole",
    generate: partial_p,
};

fn partial_p(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(rng.pick(&[ProfileName::Gsk988, ProfileName::Fanuc]), rng);
    g.p = Some(rng.pick(&["0560", "60", "560", "1060"]).to_string());
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A word the profile's G76 or G32 does not have.
pub(super) const ADDRESS: Template = Template {
    id: "address-not-in-profile",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::AddressNotInProfile { .. })),
    tags: &["refuse:address-not-in-profile"],
    description: "an address the profile does not have",
    generate: address,
};

fn address(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, t, mut g) = base(profile, rng);
    let one = ctx.num(ctx.mm(1000));
    let mut g32_word = None;
    let what = match profile {
        // LinuxCnc: never drawn (any_profile draws FANUC and GSK profiles).
        ProfileName::Fanuc | ProfileName::LinuxCnc => match rng.range(0, 3) {
            0 => {
                g.extra2.push(format!("J{one}"));
                "J in FANUC G76 block 2"
            }
            1 => {
                g.extra1.push("D1".into());
                "D in FANUC G76 block 1"
            }
            2 => {
                g.extra1.push("L2".into());
                "L in FANUC G76 block 1"
            }
            _ => {
                g32_word = Some(format!("J{one}"));
                "J in FANUC G32"
            }
        },
        ProfileName::Gsk980 => match rng.range(0, 2) {
            0 => {
                g.extra1.push(rng.pick(&["D1", "L2"]).into());
                "D or L in 980TDi G76 block 1"
            }
            1 => {
                g.extra1.push(format!("E{one}"));
                "E in 980TDi G76 block 1"
            }
            _ => {
                g.extra2.push(format!("K{one}"));
                "K in 980TDi G76 block 2 (it belongs to block 1)"
            }
        },
        ProfileName::Gsk988 => {
            g.extra1.push(format!("J{one}"));
            "J in 988TA G76 block 1 (it belongs to block 2)"
        }
    };
    let mut lines = head(rng, &ctx, t.a);
    match g32_word {
        Some(w) => lines.push(g32(&ctx, None, Some(t.d.1), &[t.lead.clone(), w])),
        None => lines.extend(g76_lines(&ctx, &t, &g)),
    }
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("an address the profile does not have: {what}"))
}

/// G32 without X or Z.
pub(super) const G32_NO_END: Template = Template {
    id: "g32-no-end-point",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:g32-no-end-point"],
    description: "G32 without an end point",
    generate: g32_no_end,
};

fn g32_no_end(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let mut lines = head(rng, &ctx, (ctx.xf() * l.r0, l.z0));
    lines.push(format!("G32 {}", l.lead));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// G32 with a zero lead.
pub(super) const G32_ZERO_LEAD: Template = Template {
    id: "g32-zero-lead",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g32-zero-lead"],
    description: "G32 with a zero lead",
    generate: g32_zero_lead,
};

fn g32_zero_lead(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let mut lines = head(rng, &ctx, (ctx.xf() * l.r0, l.z0));
    let zero = rng.pick(&["F0", "F0.0", "I0"]);
    lines.push(g32(&ctx, None, Some(l.z1), &[zero.into()]));
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("G32 with a zero lead {zero}"))
}

/// More rough passes than the pass limit.
pub(super) const TOO_MANY: Template = Template {
    id: "too-many-passes",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::TooManyPasses { .. }))),
    tags: &["refuse:too-many-passes"],
    description: "G76 needing more rough passes than the pass limit",
    generate: too_many,
};

fn too_many(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(any_profile(rng), rng);
    let limit = rng.range(2, 6);
    ctx.pass_limit = u32::try_from(limit).unwrap_or(2);
    let mut t = thread(rng, &ctx, Taper::Straight, (limit + 3, limit + 12));
    t.dmin = 0;
    let g = G76::usual(rng, &ctx);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines).described(format!("G76 needing more rough passes than the pass limit {limit}"))
}

/// A start point inside the thread.
pub(super) const START_INSIDE: Template = Template {
    id: "start-inside-thread",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::StartInsideThread))),
    tags: &["refuse:start-inside-thread"],
    description: "G76 whose start point lies inside the thread",
    generate: start_inside,
};

fn start_inside(rng: &mut Rng) -> Draft {
    let (ctx, mut t, g) = base(any_profile(rng), rng);
    let side = if t.a.0 > t.d.0 { 1 } else { -1 };
    t.a.0 = if rng.chance(30) { t.d.0 } else { t.d.0 + side * ctx.xf() * (t.k / 2).max(1) };
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A thread shorter than the flank shift of its passes.
pub(super) const TOO_SHORT: Template = Template {
    id: "thread-too-short",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::ThreadTooShort { .. }))),
    tags: &["refuse:thread-too-short"],
    description: "G76 so short that the flank shift of a pass reaches the thread end",
    generate: too_short,
};

fn too_short(rng: &mut Rng) -> Draft {
    let (ctx, mut t, mut g) = base(any_profile(rng), rng);
    let dir = if t.d.1 < t.a.1 { -1 } else { 1 };
    t.w = (t.k / 2).max(1);
    t.d.1 = t.a.1 + dir * t.w;
    g.p = Some(pmra(1, 0, rng.pick(&[60, 80, 90])));
    g.extra1.clear();
    g.extra2.clear();
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// A lead-in E where X is the long axis (GSK 988TA).
pub(super) const LEAD_IN_X: Template = Template {
    id: "lead-in-on-x-long-axis",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::LeadInOnXLongAxis))),
    tags: &["refuse:lead-in-on-x-long-axis"],
    description: "G76 lead-in E on a steep taper whose long axis is X",
    generate: lead_in_x,
};

fn lead_in_x(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::XLong, (1, 3));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 2000)))));
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// G32 to where the tool is.
pub(super) const G32_NO_MOTION: Template = Template {
    id: "g32-no-motion",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::NoMotion))),
    tags: &["refuse:g32-no-motion"],
    description: "G32 whose end point is the current position",
    generate: g32_no_motion,
};

fn g32_no_motion(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let x0 = ctx.xf() * l.r0;
    let mut lines = head(rng, &ctx, (x0, l.z0));
    if rng.chance(50) {
        lines.push(g32(&ctx, Some(x0), Some(l.z0), std::slice::from_ref(&l.lead)));
    } else {
        lines.push(format!("G32 U0 W0 {}", l.lead));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A G32 run-out K longer than the move (GSK).
pub(super) const G32_RUN_OUT_LONG: Template = Template {
    id: "g32-run-out-too-long",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::RunOutTooLong { .. }))),
    tags: &["refuse:g32-run-out-too-long"],
    description: "G32 run-out K longer than the move (988TA G32 note 4)",
    generate: g32_run_out_long,
};

fn g32_run_out_long(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(gsk(rng), rng);
    let taper = rng.chance(30);
    let l = line32(rng, &ctx, taper);
    let xf = ctx.xf();
    let mut lines = head(rng, &ctx, (xf * l.r0, l.z0));
    let words = vec![
        l.lead.clone(),
        format!("J{}", ctx.num(l.side * ctx.mm(1000))),
        format!("K{}", ctx.num(l.len + ctx.mm(rng.range(1, 3000)))),
    ];
    let x1 = (l.taper != 0).then_some(xf * (l.r0 + l.taper));
    lines.push(g32(&ctx, x1, Some(l.z1), &words));
    lines.push("M30".into());
    Draft::new(ctx, lines)
}

/// A value finer than the least increment.
pub(super) const NOT_IN_INCREMENTS: Template = Template {
    id: "not-in-increments",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::NotInIncrements { .. })),
    tags: &["refuse:not-in-increments"],
    description: "G76 with a value finer than the least increment",
    generate: not_in_increments,
};

fn not_in_increments(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (mut ctx, t, g) = base(profile, rng);
    ctx.bare = false;
    let mut lines = head(rng, &ctx, t.a);
    let mut b = g76_lines(&ctx, &t, &g);
    let what = if profile == ProfileName::Gsk980 && ctx.pq_in_increments() && rng.chance(50) {
        let last = b.pop().unwrap_or_default();
        b.push(last.replacen(&format!(" P{}", t.k), &format!(" P{}.5", t.k), 1));
        "P(k) in increments with a fraction"
    } else {
        // One digit finer than the increment on Z of the start.
        let fine = decimal(t.a.1 * 10 + 3, ctx.decimals() + 1, true);
        lines.pop();
        lines.push(format!("G00 X{} Z{fine}", ctx.num(t.a.0)));
        "a coordinate finer than the least increment"
    };
    lines.extend(b);
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("G76 with {what}"))
}

/// A move or cycle before the position is known.
pub(super) const POSITION_UNKNOWN: Template = Template {
    id: "position-unknown",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::PositionUnknown)),
    tags: &["refuse:position-unknown"],
    description: "a move or cycle before any position is known",
    generate: position_unknown,
};

fn position_unknown(rng: &mut Rng) -> Draft {
    let (ctx, t, g) = base(any_profile(rng), rng);
    let mut lines = Vec::new();
    if ctx.g20 {
        lines.push("G20".to_string());
    }
    lines.push("M03 S500".into());
    let variant = rng.range(0, 2);
    let what = match variant {
        0 => {
            lines.extend(g76_lines(&ctx, &t, &g));
            "G76 before any position is known"
        }
        1 => {
            lines.push(format!("G00 U{} W{}", ctx.num(ctx.mm(10_000)), ctx.num(ctx.mm(-5000))));
            "an incremental move before any position is known"
        }
        _ => {
            lines.push(g32(&ctx, None, Some(t.d.1), std::slice::from_ref(&t.lead)));
            "G32 before any position is known"
        }
    };
    lines.push("M30".into());
    Draft::new(ctx, lines).described(what.into())
}

/// A pass coordinate beyond the range table.
pub(super) const PASS_OUT_OF_RANGE: Template = Template {
    id: "pass-coordinate-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::OutOfRange { .. }))),
    tags: &["refuse:pass-coordinate-out-of-range"],
    description: "G76 taper whose thread start X(D) + i lies outside the range table",
    generate: pass_out_of_range,
};

fn pass_out_of_range(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let max = cycleref::units::MAX_LENGTH;
    // Internal steep taper: X of C = X(D) + xf·i lies beyond the range table.
    let xd = rng.range(600_000_000, 900_000_000);
    let i = (max - xd) / xf + rng.range(1, 1_000_000);
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = (lead_inc * 6 / 10).max(1);
    let za = ctx.mm(rng.range(1000, 5000));
    let t = Thread {
        a: (xf * ctx.mm(rng.range(10_000, 40_000)), za),
        d: (xd, za - ctx.mm(rng.range(5000, 20_000))),
        taper: i,
        k,
        dd: (k / 2).max(1),
        dmin: 0,
        allowance: 0,
        lead,
        w: 0,
    };
    let g = G76 {
        block1: true,
        p: Some(pmra(1, 0, 60)),
        extra1: vec![],
        extra2: vec![],
        omit: "",
        incremental: false,
        show_r: true,
    };
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::new(ctx, lines)
}

/// G20/G21 after the first motion.
pub(super) const UNIT_CHANGE: Template = Template {
    id: "unit-change-after-motion",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::UnitChangeAfterMotion)),
    tags: &["refuse:unit-change-after-motion"],
    description: "G20 or G21 after the first motion",
    generate: unit_change,
};

fn unit_change(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(any_profile(rng), rng);
    ctx.g20 = false;
    let l = line32(rng, &ctx, false);
    let mut lines =
        vec!["M03 S500".to_string(), format!("G00 X{} Z{}", ctx.num(ctx.xf() * l.r0), ctx.num(l.z0))];
    let code = if ctx.unit == InputUnit::Metric { "G20" } else { "G21" };
    lines.push(code.into());
    lines.push(g32(&ctx, None, Some(l.z1), std::slice::from_ref(&l.lead)));
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("{code} after the first motion"))
}

/// What the reader refuses besides: syntax, a duplicate address, an unsupported G code.
pub(super) const MISC: Template = Template {
    id: "reader",
    // Each variant aims at one of these kinds (`Draft::refused_as`).
    outcome: Expected::Refused(|k| {
        matches!(k, ErrorKind::Syntax(_) | ErrorKind::Duplicate | ErrorKind::Unsupported(_))
    }),
    tags: &["refuse:reader"],
    description: "a program the reader refuses",
    generate: misc,
};

fn misc(rng: &mut Rng) -> Draft {
    let variant = rng.range(0, 3);
    let profile = if variant == 3 { ProfileName::Gsk988 } else { any_profile(rng) };
    let (ctx, t, g) = base(profile, rng);
    let mut lines = head(rng, &ctx, t.a);
    let (what, kind): (&str, Refusal) = match variant {
        0 => {
            lines.push(format!("G00 X{} (retract", ctx.num(t.a.0)));
            ("a comment that is not closed", |k| matches!(k, ErrorKind::Syntax(_)))
        }
        1 => {
            lines.push(format!("G00 X{} X{}", ctx.num(t.a.0), ctx.num(t.a.0 + ctx.mm(1000))));
            ("the same address twice in a block", |k| matches!(k, ErrorKind::Duplicate))
        }
        2 => {
            lines.push("G71 U1 R0.5".into());
            ("a G code the reader does not model (G71)", |k| matches!(k, ErrorKind::Unsupported(_)))
        }
        _ => {
            // 5129 = 1 (high-speed mode) was refused here before reading
            // R-HIGHSPEED gave G76 and G78 G92's high-speed rules; the
            // 988TA's own G74 (end-face peck drilling) stays outside the
            // model.
            lines.push(format!("G74 R{}", ctx.num(ctx.mm(500))));
            ("a 988TA G code the reader does not model (G74)", |k| matches!(k, ErrorKind::Unsupported(_)))
        }
    };
    lines.extend(g76_lines(&ctx, &t, &g));
    lines.push("M30".into());
    Draft::new(ctx, lines).described(format!("a program the reader refuses: {what}")).refused_as(kind)
}
