//! G78 threads: the valid G78 templates (GSK's enhanced multiple
//! thread-cutting cycle, a front end on G76's cycle) and its refusal. The
//! features a G78 shows are read by `g76::tags`, which names the cycle by
//! its code.
//!
//! A G78 is written with G76's thread ([`super::g76::thread`]) and its
//! blocks ([`super::g76::g76_lines`]) renamed: the words are the same per
//! profile, what differs is their meaning (P's r is the infeed mode; the
//! 980TDi's m the depth mode and D the finishing passes; the 988TA's D the
//! depth mode).

use cycleref::CycleError;
use cycleref_spec::{ErrorKind, ProfileName};

use super::g76::{g76_program, pmra, thread, Taper, Thread, G76};
use super::machine::{gsk, MachineStyle};
use super::{Draft, Expected, Rng, Template};

/// The lines of a one-G78 program with block 1's `p` and extra words.
fn g78_program(
    rng: &mut Rng,
    ctx: &MachineStyle,
    straight: bool,
    p: String,
    extra1: Vec<String>,
) -> Vec<String> {
    g78_program_with(rng, ctx, straight, p, extra1, |_, _| {})
}

/// As [`g78_program`], with `change` applied to the thread and the blocks
/// before they are written (a refusal breaks one thing there).
fn g78_program_with(
    rng: &mut Rng,
    ctx: &MachineStyle,
    straight: bool,
    p: String,
    extra1: Vec<String>,
    change: impl FnOnce(&mut Thread, &mut G76),
) -> Vec<String> {
    let mut t = thread(rng, ctx, if straight { Taper::Straight } else { Taper::ZLong }, (2, 6));
    let mut g = G76::usual(rng, ctx);
    g.p = Some(p);
    g.extra1 = extra1;
    let j = ctx.mm(rng.range(300, 1500));
    let run_out = vec![format!("J{}", ctx.num(j)), format!("K{}", ctx.num(2 * j))];
    if ctx.profile == ProfileName::Gsk980 {
        g.extra1.extend(run_out);
    } else {
        g.extra2.extend(run_out);
    }
    change(&mut t, &mut g);
    g76_program(rng, ctx, &t, &g)
        .into_iter()
        .map(|l| l.strip_prefix("G76").map_or(l.clone(), |rest| format!("G78{rest}")))
        .collect()
}

/// The 988TA: every infeed mode P(r) 0-4, decreasing or equal depths (D).
pub(super) const GSK988: Template = Template {
    id: "g78-gsk988",
    outcome: Expected::Valid(&["g78"]),
    tags: &["template:g78-gsk988", "rule:g78-p-infeed", "rule:g78-gsk988-d"],
    description: "GSK 988TA G78: P(m)(r)(a) with r the infeed mode 0-4, D the depth mode",
    generate: gsk988,
};

fn gsk988(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let r = rng.range(0, 4);
    let depth = rng.range(0, 1);
    let p = pmra(rng.range(1, 2), r, rng.pick(&[29, 30, 55, 60]));
    let straight = rng.chance(60);
    let lines = g78_program(rng, &ctx, straight, p, vec![format!("D{depth}")]);
    let modes = ["centre", "left flank", "right flank", "right and centre", "left and right"];
    let depths = if depth == 0 { "equal" } else { "decreasing" };
    Draft::new(ctx, lines).described(format!(
        "GSK 988TA G78, infeed r = {r} ({}), {depths} depths",
        modes[usize::try_from(r).unwrap_or(0)]
    ))
}

/// The 980TDi: its own P (m the depth mode, r 0-3) and D (finishing
/// passes), here the alternating flanks (r = 3) with equal depths.
pub(super) const GSK980: Template = Template {
    id: "g78-gsk980",
    outcome: Expected::Valid(&["g78", "g78:alternating", "g78:equal"]),
    tags: &["template:g78-gsk980", "rule:g78-p-infeed", "rule:g78-gsk980-m", "rule:g78-gsk980-d"],
    description: "GSK 980TDi G78: P(m)(r)(a) with m = 0 (equal depths) and r = 3 (flanks in turn), D the \
                  finishing passes, J/K in block 1",
    generate: gsk980,
};

fn gsk980(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let p = pmra(0, 3, rng.pick(&[29, 30, 55, 60]));
    let d = rng.range(0, 2);
    let straight = rng.chance(60);
    let lines = g78_program(rng, &ctx, straight, p, vec![format!("D{d}")]);
    Draft::new(ctx, lines)
}

/// P(r) beyond the profile's infeed modes (the 988TA's own example writes
/// P020545: r = 05).
pub(super) const INFEED_RANGE: Template = Template {
    id: "g78-infeed-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g78-infeed-out-of-range"],
    description: "G78 whose P(r) is not an infeed mode of the profile (988TA 0-4, 980TDi 0-3), as the \
                  988TA's example P020545",
    generate: infeed_range,
};

fn infeed_range(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(gsk(rng), rng);
    let (m, r) = if ctx.profile == ProfileName::Gsk988 { (2, rng.range(5, 9)) } else { (1, rng.range(4, 9)) };
    let p = pmra(m, r, 45);
    let lines = g78_program(rng, &ctx, true, p, vec![]);
    Draft::new(ctx, lines)
}

/// The 980TDi's P(m), the depth mode, above 1 ("P(m)：切深选择 0：等距离进刀；1：
/// 递减式进刀").
pub(super) const GSK980_M: Template = Template {
    id: "g78-gsk980-depth-mode",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g78-gsk980-depth-mode"],
    description: "GSK 980TDi G78 whose P(m), the depth mode, is 2 or more (0 equal, 1 decreasing)",
    generate: gsk980_m,
};

fn gsk980_m(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let p = pmra(rng.range(2, 9), rng.range(0, 3), 60);
    let lines = g78_program(rng, &ctx, true, p, vec![]);
    Draft::new(ctx, lines)
}

/// The 988TA's D, the depth mode, above 1 ("切深选择（取值范围为：0~1）").
pub(super) const GSK988_D: Template = Template {
    id: "g78-gsk988-depth-mode",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::OutOfRange { .. })),
    tags: &["refuse:g78-gsk988-depth-mode"],
    description: "GSK 988TA G78 whose D, the depth mode, is 2 or more (0 equal, 1 decreasing)",
    generate: gsk988_d,
};

fn gsk988_d(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let p = pmra(rng.range(1, 2), rng.range(0, 4), 60);
    let d = rng.range(2, 9);
    let lines = g78_program(rng, &ctx, true, p, vec![format!("D{d}")]);
    Draft::new(ctx, lines)
}

/// A G78 whose end point has the Z of the start ("G78 代码可加工直螺纹和锥螺纹
/// 不能加工端面螺纹").
pub(super) const FACE_THREAD: Template = Template {
    id: "g78-face-thread",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::FaceThread))),
    tags: &["refuse:g78-face-thread"],
    description: "G78 face thread: the end point has the Z of the start",
    generate: face_thread,
};

fn face_thread(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(gsk(rng), rng);
    let (m, r) = if ctx.profile == ProfileName::Gsk988 { (2, rng.range(0, 4)) } else { (1, rng.range(0, 3)) };
    let incremental = rng.chance(50);
    let lines = g78_program_with(rng, &ctx, true, pmra(m, r, 60), vec![], |t, g| {
        t.d.1 = t.a.1;
        g.incremental = incremental;
    });
    Draft::new(ctx, lines)
}

/// G78 block 2 without P(k) or Q(Δd) ("未输入 P(k)时，系统报警", "未输入△d 时，系统
/// 报警").
pub(super) const MISSING: Template = Template {
    id: "g78-missing-word",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:g78-missing-word"],
    description: "G78 block 2 without P(k) or Q(Δd)",
    generate: missing,
};

fn missing(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(gsk(rng), rng);
    let (m, r) = if ctx.profile == ProfileName::Gsk988 { (2, rng.range(0, 4)) } else { (1, rng.range(0, 3)) };
    let omit = if rng.chance(50) { "P" } else { "Q" };
    let lines = g78_program_with(rng, &ctx, true, pmra(m, r, 60), vec![], |_, g| g.omit = omit);
    let what = if omit == "P" { "P(k)" } else { "Q(Δd)" };
    Draft::new(ctx, lines).described(format!("G78 block 2 without {what}"))
}
