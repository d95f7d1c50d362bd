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

use cycleref_spec::{ErrorKind, ProfileName};

use super::g76::{g76_program, pmra, thread, Taper, G76};
use super::machine::{gsk, Ctx};
use super::{Draft, Expected, Rng, Template};

/// The lines of a one-G78 program with block 1's `p` and extra words.
fn g78_program(rng: &mut Rng, ctx: &Ctx, straight: bool, p: String, extra1: Vec<String>) -> Vec<String> {
    let t = thread(rng, ctx, if straight { Taper::Straight } else { Taper::ZLong }, (2, 6));
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
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
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
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
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
    let ctx = Ctx::new(gsk(rng), rng);
    let (m, r) = if ctx.profile == ProfileName::Gsk988 { (2, rng.range(5, 9)) } else { (1, rng.range(4, 9)) };
    let p = pmra(m, r, 45);
    let lines = g78_program(rng, &ctx, true, p, vec![]);
    Draft::new(ctx, lines)
}
