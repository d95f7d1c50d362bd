//! The G75.1 templates of programs that must be refused: most start from
//! a valid right-angled groove ([`g75_base`]) and break one rule of G75.1
//! or of the reader (a word left out, a lone block, an angle, slope,
//! allowance, corner or word out of range, a groove narrower than the
//! tool, ridges left between layers, H0, too many pecks).

use std::fmt::Write as _;

use cycleref::CycleError;
use cycleref_spec::{ErrorKind, ProfileName};

use crate::vectors::g75::{corner_digits, g75_lines, g75_program, groove, peck_for, small, Groove};
use crate::vectors::machine::{head, MachineStyle};
use crate::vectors::{Draft, Expected, Rng, Template};

/// A valid right-angled G75.1 draft to break: A and B left out (90°), a
/// pointed tool, one to three pecks and a few plunges, any J.
fn g75_base(rng: &mut Rng) -> (MachineStyle, Groove) {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(20, 60) * 100;
    let d_um = rng.range(30, 80) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 3));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    if rng.chance(60) {
        g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    }
    if rng.chance(50) {
        g.j = Some(u8::try_from(rng.range(0, 2)).unwrap_or(0));
    }
    (ctx, g)
}

/// The radial depth of `g` in radius increments, and the bottom width.
fn g75_size(ctx: &MachineStyle, g: &Groove) -> (i64, i64) {
    (g.depth.abs() / ctx.xf(), g.width.abs())
}

/// G75.1 block 1 without one of H, D, P, Q.
pub(in crate::vectors) const G75_MISSING: Template = Template {
    id: "g75-missing-word",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:g75-missing-word"],
    description: "G75.1 block 1 without one of P, Q, H, D (note 3: H, D, P and Q cannot be omitted)",
    generate: g75_missing,
};

fn g75_missing(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (letter, what) = rng.pick(&[("P", "P(Δi)"), ("Q", "Q(Δk)"), ("H", "H(h)"), ("D", "D(d)")]);
    g.omit = letter;
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
        .described(format!("G75.1 block 1 without {what} (note 3: H, D, P and Q cannot be omitted)"))
}

/// A G75.1 block without its other block.
pub(in crate::vectors) const G75_LONE: Template = Template {
    id: "g75-lone-block",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Missing { .. })),
    tags: &["refuse:g75-lone-block"],
    description: "a lone G75.1 block (note 3: always two blocks)",
    generate: g75_lone,
};

fn g75_lone(rng: &mut Rng) -> Draft {
    let (ctx, g) = g75_base(rng);
    let mut lines = head(rng, &ctx, g.from);
    let blocks = g75_lines(&ctx, &g);
    let mut block2 = blocks[1].clone();
    if g.retract.is_none() {
        // A block 2 needs one of its own words to be told from a block 1.
        let _ = write!(block2, " R{}", ctx.num(small(&ctx, 500)));
    }
    let what = match rng.range(0, 3) {
        0 => {
            lines.push(blocks[0].clone());
            lines.push(format!("G00 X{} Z{}", ctx.num(g.from.0), ctx.num(g.from.1)));
            lines.push("M30".into());
            "block 1 followed by another block"
        }
        1 => {
            lines.push(blocks[0].clone());
            "block 1 at the end of the program"
        }
        2 => {
            lines.push(block2);
            lines.push("M30".into());
            "block 2 without a block 1"
        }
        _ => {
            lines.push(block2);
            lines.push(blocks[0].clone());
            lines.push("M30".into());
            "block 2 before block 1"
        }
    };
    Draft::new(ctx, lines).described(format!("a lone G75.1 block: {what} (note 3: always two blocks)"))
}

/// A G75.1 angle outside its range.
pub(in crate::vectors) const G75_ANGLE: Template = Template {
    id: "g75-angle-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::AngleOutOfRange { .. }))),
    tags: &["refuse:g75-angle-out-of-range"],
    description: "G75.1 with an angle outside its range (0 < A, B <= 90, 0 <= L < 90)",
    generate: g75_angle,
};

fn g75_angle(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let what = match rng.range(0, 4) {
        0 => {
            g.a = Some("0".into());
            "A0"
        }
        1 => {
            g.a = Some(rng.range(91, 180).to_string());
            "A above 90 degrees"
        }
        2 => {
            g.b = Some("0".into());
            "B0"
        }
        3 => {
            g.b = Some(rng.range(91, 180).to_string());
            "B above 90 degrees"
        }
        _ => {
            g.l = Some(rng.range(90, 120).to_string());
            "L of 90 degrees or more"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
        .described(format!("G75.1 with an angle outside its range: {what} (0 < A, B <= 90, 0 <= L < 90)"))
}

/// R-G75SLOPE: the slope L not below the flank angle B.
pub(in crate::vectors) const G75_SLOPE: Template = Template {
    id: "g75-slope-not-below-flank",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::SlopeNotBelowFlank { .. }))),
    tags: &["refuse:g75-slope-not-below-flank"],
    description: "G75.1 whose slope L is not below the flank angle B (R-G75SLOPE)",
    generate: g75_slope,
};

fn g75_slope(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let b = rng.pick(&[15, 20, 30, 45, 60, 75]);
    let l = if rng.chance(30) { b } else { rng.range(b + 1, 89) };
    g.b = Some(b.to_string());
    g.l = Some(l.to_string());
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
        .described(format!("G75.1 whose slope L{l} is not below the flank angle B{b} (R-G75SLOPE)"))
}

/// The allowance U at least the groove depth H.
pub(in crate::vectors) const G75_ALLOWANCE: Template = Template {
    id: "g75-allowance-exceeds-depth",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::AllowanceExceedsDepth { .. }))),
    tags: &["refuse:g75-allowance-exceeds-depth"],
    description: "G75.1 whose allowance U is at least the groove depth H",
    generate: g75_allowance,
};

fn g75_allowance(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let extra = if rng.chance(30) { 0 } else { ctx.xf() * small(&ctx, rng.range(1, 20) * 100) };
    g.u = Some(g.depth.abs() + extra);
    let lines = g75_program(rng, &ctx, &g);
    let what = if extra == 0 { "equal to" } else { "larger than" };
    Draft::new(ctx, lines).described(format!("G75.1 whose allowance U is {what} the groove depth H"))
}

/// Corners longer than their edge.
pub(in crate::vectors) const G75_CORNER: Template = Template {
    id: "g75-corner-too-large",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::CornerTooLarge { .. }))),
    tags: &["refuse:g75-corner-too-large"],
    description: "G75.1 with corners longer than their edge",
    generate: g75_corner,
};

fn g75_corner(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (h, d) = g75_size(&ctx, &g);
    // Square flanks: a chamfer or round of size c takes c of each edge.
    let (what, pair, edge) = match rng.range(0, 2) {
        0 => ("A(r1) and D(r3) longer than flank A", [0, 2], h),
        1 => ("D(r3) and E(r4) longer than the bottom", [2, 3], d),
        _ => ("E(r4) and B(r2) longer than flank B", [3, 1], h),
    };
    for i in pair {
        g.corners[i] = Some(edge * rng.range(55, 80) / 100 + 1);
    }
    if rng.chance(50) {
        let round = [rng.chance(50), rng.chance(50), rng.chance(50), rng.chance(50)];
        g.digits = Some(corner_digits(rng, round));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines).described(format!("G75.1 with corners {what}"))
}

/// A groove narrower than the tool.
pub(in crate::vectors) const G75_NARROW: Template = Template {
    id: "g75-groove-narrower-than-tool",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::GrooveNarrowerThanTool { .. }))),
    tags: &["refuse:g75-groove-narrower-than-tool"],
    description: "G75.1 groove narrower than the tool",
    generate: g75_narrow,
};

fn g75_narrow(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (_, d) = g75_size(&ctx, &g);
    let what = match rng.range(0, 2) {
        0 => {
            g.tool = Some(d + small(&ctx, rng.range(1, 20) * 100));
            "a tool I wider than the bottom D"
        }
        1 => {
            g.w = Some(d / 2 + small(&ctx, rng.range(1, 10) * 100));
            "an allowance W above half the bottom"
        }
        _ => {
            // The bottom corners fit (d/4 + d/4 <= d) but leave d/2 of it.
            g.corners[2] = Some(d / 4);
            g.corners[3] = Some(d / 4);
            g.tool = Some(d - 2 * (d / 4) + small(&ctx, rng.range(1, 10) * 100));
            "bottom corners D(r3) E(r4) leaving less than the tool's width"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines).described(format!("G75.1 groove narrower than the tool: {what}"))
}

/// R-G75RIDGE: layers with a step wider than the tool.
pub(in crate::vectors) const G75_RIDGES: Template = Template {
    id: "g75-ridges-in-layers",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::RidgesInLayers { .. }))),
    tags: &["refuse:g75-ridges-in-layers"],
    description: "G75.1 roughed in layers V with a step Q wider than the tool (R-G75RIDGE)",
    generate: g75_ridges,
};

fn g75_ridges(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (h, d) = g75_size(&ctx, &g);
    // Two to four layers; a tool (or a pointed one) under half the bottom,
    // so that layer 1 has plunges more than its width apart.
    g.layer = Some(ctx.xf() * (h * rng.range(30, 60) / 100).max(1));
    let tool = if rng.chance(30) { 0 } else { (d * rng.range(20, 40) / 100).max(1) };
    g.tool = (tool > 0).then_some(tool);
    g.step = tool + small(&ctx, rng.range(1, 10) * 100);
    g.j = rng.chance(50).then(|| u8::try_from(rng.range(0, 1)).unwrap_or(0));
    let lines = g75_program(rng, &ctx, &g);
    let what = if tool > 0 { "the tool I" } else { "a pointed tool" };
    Draft::new(ctx, lines)
        .described(format!("G75.1 roughed in layers V with a step Q wider than {what} (R-G75RIDGE)"))
}

/// A G75.1 word outside the manual's range.
pub(in crate::vectors) const G75_WORD: Template = Template {
    id: "g75-word-out-of-range",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::WordOutOfRange { .. }))),
    tags: &["refuse:g75-word-out-of-range"],
    description: "G75.1 with a word outside the manual's range",
    generate: g75_word,
};

fn g75_word(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let units = ctx.units();
    let over = rng.range(1, 1000);
    let what = match rng.range(0, 6) {
        0 => {
            g.retract = Some(cycleref::g75::max_small(units) + over);
            "R(e) above 99.999 (99.9999 at IS-C)"
        }
        1 => {
            g.u = Some(-ctx.xf() * small(&ctx, rng.range(1, 5) * 100));
            "a negative U (unsigned)"
        }
        2 => {
            g.w = Some(-small(&ctx, rng.range(1, 5) * 100));
            "a negative W (unsigned)"
        }
        3 => {
            g.layer = Some(0);
            "V0"
        }
        4 => {
            g.corners[rng.index(4)] = Some(cycleref::g75::max_small(units) + over);
            "a corner size above 99.999 (99.9999 at IS-C)"
        }
        5 => {
            if rng.chance(50) {
                g.peck = 0;
                "P0"
            } else {
                g.step = 0;
                "Q0"
            }
        }
        _ => {
            g.depth = g.depth.signum() * (cycleref::g75::max_size(units) + over);
            "H beyond 9999.999 (9999.9999 at IS-C)"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines).described(format!("G75.1 with a word outside the manual's range: {what}"))
}

/// G75.1 with H0.
pub(in crate::vectors) const G75_NO_DEPTH: Template = Template {
    id: "g75-no-depth",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::NoGrooveDepth))),
    tags: &["refuse:g75-no-depth"],
    description: "G75.1 with H0",
    generate: g75_no_depth,
};

fn g75_no_depth(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    g.depth = 0;
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}

/// More pecks than the engine's limit.
pub(in crate::vectors) const G75_TOO_MANY_PECKS: Template = Template {
    id: "g75-too-many-pecks",
    outcome: Expected::Refused(|k| matches!(k, ErrorKind::Cycle(CycleError::TooManyPecks { .. }))),
    tags: &["refuse:g75-too-many-pecks"],
    description: "G75.1 needing more than a million pecks (P and Q of one or two increments)",
    generate: g75_too_many_pecks,
};

fn g75_too_many_pecks(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    // Pecks of one or two increments into a depth of 2000 or more of them,
    // at a thousand plunges or more: above MAX_PECKS (10^6).
    g.peck = rng.range(1, 2);
    g.step = rng.range(1, 2);
    g.depth = g.depth.signum() * g.peck * rng.range(2000, 4000);
    g.width = g.width.signum() * g.step * rng.range(1000, 2000);
    g.j = rng.chance(50).then(|| u8::try_from(rng.range(0, 1)).unwrap_or(0));
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}
