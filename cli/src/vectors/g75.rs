//! G75.1 grooves (GSK 980TDi only): the groove and its two blocks, the
//! valid G75.1 templates, and the features a G75.1 shows.
//!
//! A [`Groove`] holds every word of the two blocks in increments, `None`
//! for a word left out; [`groove`] draws a sharp right-angled one clear of
//! the tool, and each template sets the angles, corners, layers, tool and
//! path type its feature needs. [`tags`] reads back what the expanded
//! cycle shows.

use std::fmt::Write as _;

use cycleref::IncrementSystem;
use cycleref_spec::ProfileName;

use super::machine::{head, MachineStyle};
use super::{Draft, Expected, Rng, Template};

/// One G75.1 cycle as written, in increments: X, P(Δi), H, V and U in
/// X-word units, R and the corner sizes radius values, the rest along Z.
#[derive(Clone)]
pub(super) struct Groove {
    /// Where the tool is before the cycle (it returns there).
    pub(super) from: (i64, i64),
    /// The start point S; a `None` coordinate is left out of block 1 (note
    /// 3: the current position).
    pub(super) start: (Option<i64>, Option<i64>),
    /// P(Δi), the radial peck.
    pub(super) peck: i64,
    /// Q(Δk), the axial step.
    pub(super) step: i64,
    /// H(h), signed: towards -X for an outer groove.
    pub(super) depth: i64,
    /// D(d), the bottom width, signed along Z.
    pub(super) width: i64,
    /// A, B, L as written, in degrees; `None`: left out (90°, 90°, 0°).
    pub(super) a: Option<String>,
    pub(super) b: Option<String>,
    pub(super) l: Option<String>,
    /// R(e), the retract after each peck.
    pub(super) retract: Option<i64>,
    /// V(Δv), the layer depth.
    pub(super) layer: Option<i64>,
    /// U(Δu), the X finishing allowance.
    pub(super) u: Option<i64>,
    /// W(Δw), the Z finishing allowance.
    pub(super) w: Option<i64>,
    /// I(r), the tool width.
    pub(super) tool: Option<i64>,
    /// J, the path type (0 rough, 1 rough and finish, 2 finish).
    pub(super) j: Option<u8>,
    /// A(r1), B(r2), D(r3), E(r4); `None`: left out.
    pub(super) corners: [Option<i64>; 4],
    /// P(a)(b)(d)(e) of block 2 as written.
    pub(super) digits: Option<String>,
    /// Block 1 words left out: any of `P`, `Q`, `H`, `D`.
    pub(super) omit: &'static str,
}

/// A sharp, right-angled groove of radial depth `h_um` and bottom width
/// `d_um` (microns of a radius), towards `sx` on X and `sz` on Z, with a
/// peck and a step that are replaced by the templates; S is on an outer
/// diameter for `sx < 0`, in a bore for `sx > 0`, and the tool stands clear
/// of it.
pub(super) fn groove(rng: &mut Rng, ctx: &MachineStyle, sx: i64, sz: i64, h_um: i64, d_um: i64) -> Groove {
    let xf = ctx.xf();
    let r0 = if sx < 0 { rng.range(150, 400) } else { rng.range(120, 300) } * 100;
    let zs = rng.range(-200, 200) * 100;
    let clear = rng.range(10, 50) * 100;
    let from_r = if sx < 0 { r0 + clear } else { r0 - clear };
    let from_z = zs - sz * rng.range(0, 50) * 100;
    Groove {
        from: (xf * ctx.mm(from_r), ctx.mm(from_z)),
        start: (Some(xf * ctx.mm(r0)), Some(ctx.mm(zs))),
        peck: xf * ctx.mm(h_um),
        step: ctx.mm(d_um).max(1),
        depth: sx * xf * ctx.mm(h_um),
        width: sz * ctx.mm(d_um),
        a: None,
        b: None,
        l: None,
        retract: None,
        layer: None,
        u: None,
        w: None,
        tool: None,
        j: None,
        corners: [None; 4],
        digits: None,
        omit: "",
    }
}

/// P(Δi) that cuts `h` radius increments in at most `n` pecks, in X-word
/// units, rounded up to 0.1 mm where the units allow.
pub(super) fn peck_for(ctx: &MachineStyle, h: i64, n: i64) -> i64 {
    let grain = ctx.mm(100).max(1);
    let per = (h + n - 1) / n.max(1);
    ctx.xf() * ((per + grain - 1) / grain * grain).max(1)
}

/// `microns` of a radius in increments, at least one.
pub(super) fn small(ctx: &MachineStyle, microns: i64) -> i64 {
    ctx.mm(microns).max(1)
}

/// A flank angle in degrees, as written.
fn angle(rng: &mut Rng, choices: &[&str]) -> Option<String> {
    Some(rng.pick(choices).to_string())
}

/// P(a)(b)(d)(e) for `round` (1 for a round, 0 for a chamfer, in the order
/// A B D E), with the leading zeros sometimes left out (reading R-G75P).
pub(super) fn corner_digits(rng: &mut Rng, round: [bool; 4]) -> String {
    let full: String = round.iter().map(|&r| if r { '1' } else { '0' }).collect();
    if rng.chance(50) {
        let trimmed = full.trim_start_matches('0');
        if trimmed.is_empty() {
            "0".into()
        } else {
            trimmed.into()
        }
    } else {
        full
    }
}

/// The two blocks of a G75.1.
pub(super) fn g75_lines(ctx: &MachineStyle, g: &Groove) -> Vec<String> {
    let mut b1 = String::from("G75.1");
    if let Some(x) = g.start.0 {
        let _ = write!(b1, " X{}", ctx.num(x));
    }
    if let Some(z) = g.start.1 {
        let _ = write!(b1, " Z{}", ctx.num(z));
    }
    for (letter, v, pq) in
        [('P', g.peck, true), ('Q', g.step, true), ('H', g.depth, false), ('D', g.width, false)]
    {
        if !g.omit.contains(letter) {
            let _ = write!(b1, " {letter}{}", if pq { ctx.pq(v) } else { ctx.num(v) });
        }
    }
    for (letter, a) in [('A', &g.a), ('B', &g.b), ('L', &g.l)] {
        if let Some(a) = a {
            let _ = write!(b1, " {letter}{a}");
        }
    }
    let mut b2 = String::from("G75.1");
    for (letter, v) in [('R', g.retract), ('V', g.layer), ('U', g.u), ('W', g.w), ('I', g.tool)] {
        if let Some(v) = v {
            let _ = write!(b2, " {letter}{}", ctx.num(v));
        }
    }
    if let Some(j) = g.j {
        let _ = write!(b2, " J{j}");
    }
    for (letter, v) in ['A', 'B', 'D', 'E'].into_iter().zip(g.corners) {
        if let Some(v) = v {
            let _ = write!(b2, " {letter}{}", ctx.num(v));
        }
    }
    if let Some(p) = &g.digits {
        let _ = write!(b2, " P{p}");
    }
    vec![b1, b2]
}

/// The lines of a one-G75.1 program.
pub(super) fn g75_program(rng: &mut Rng, ctx: &MachineStyle, g: &Groove) -> Vec<String> {
    let mut lines = head(rng, ctx, g.from);
    lines.extend(g75_lines(ctx, g));
    if rng.chance(30) {
        let away = if g.depth < 0 { 1 } else { -1 };
        lines.push(format!(
            "G00 X{} Z{}",
            ctx.num(g.from.0 + away * ctx.xf() * ctx.mm(5000)),
            ctx.num(g.from.1 + ctx.mm(20_000))
        ));
    }
    lines.push("M30".into());
    lines
}

// ---- the valid G75.1 templates ----

/// The shape of seed 001's example.
pub(super) const SEED: Template = Template {
    id: "g75-seed",
    outcome: Expected::Valid(&["g75", "g75:angled", "g75:pecking", "g75:j0", "g75:-x", "g75:-z"]),
    tags: &["template:g75-seed"],
    description: "G75.1 shaped as seed 001's example O0008 (IS-C, A45 B30, pecks with a retract R)",
    generate: seed,
};

fn seed(rng: &mut Rng) -> Draft {
    let mut ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    // The seed's example is written for IS-C (P30000 is 3 mm).
    ctx.increment = IncrementSystem::IsC;
    let h_um = rng.range(60, 100) * 100;
    let d_um = rng.range(60, 120) * 100;
    let mut g = groove(rng, &ctx, -1, -1, h_um, d_um);
    g.a = Some("45".into());
    g.b = Some("30".into());
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(3, 6));
    g.step = small(&ctx, rng.range(d_um / 200, d_um / 100) * 100);
    g.retract = Some(small(&ctx, rng.range(2, 10) * 100));
    let with_tool = rng.chance(30);
    if with_tool {
        g.tool = Some(small(&ctx, rng.range(20, 40) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    let what =
        if with_tool { "with the grooving tool's width I" } else { "as written, a pointed tool (R-G75SEED)" };
    Draft::new(ctx, lines).described(format!(
        "G75.1 shaped as seed 001's example O0008 (IS-C, A45 B30, pecks with a retract R), {what}"
    ))
}

/// A square groove in layers with allowances and a grooving tool.
pub(super) const SQUARE: Template = Template {
    id: "g75-square",
    outcome: Expected::Valid(&["g75:layers", "g75:allowances", "g75:tool-width", "g75:j1"]),
    tags: &["template:g75-square"],
    description:
        "G75.1 square groove in two layers V, allowances U W, a grooving tool I, rough and finish J1",
    generate: square,
};

fn square(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let xf = ctx.xf();
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let w_um = rng.range(20, 40) * 100;
    let d_um = w_um + rng.range(15, 40) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    let h = ctx.mm(h_um);
    // Two layers: V is 55-75 % of the depth, U at most 10 %.
    g.layer = Some(xf * (h * rng.range(55, 75) / 100).max(1));
    g.u = Some(xf * small(&ctx, rng.range(1, 3) * 100));
    g.w = Some(small(&ctx, rng.range(1, 3) * 100));
    g.tool = Some(small(&ctx, w_um));
    g.step = (ctx.mm(w_um) * rng.range(80, 100) / 100).max(1);
    g.peck = peck_for(&ctx, h, rng.range(1, 2));
    if rng.chance(80) {
        g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    }
    g.j = Some(1);
    if rng.chance(50) {
        g.corners[0] = Some(small(&ctx, rng.range(2, 5) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}

/// A trapezoid with chamfers and rounds at its corners.
pub(super) const CORNERS: Template = Template {
    id: "g75-corners",
    outcome: Expected::Valid(&["g75:angled", "g75:corners", "g75:arcs", "g75:chamfers", "g75:j1"]),
    tags: &["template:g75-corners"],
    description: "G75.1 trapezoidal groove with chamfers and rounds at its corners (P digits), rough and \
                  finish J1",
    generate: corners,
};

fn corners(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let with_tool = rng.chance(50);
    let w_um = if with_tool { rng.range(15, 25) * 100 } else { 0 };
    let d_um = w_um + rng.range(25, 45) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    g.a = angle(rng, &["45", "60", "62.5", "70", "75", "80"]);
    g.b = angle(rng, &["45", "60", "75", "80", "90"]);
    // One corner a round and another a chamfer, the other two either or none.
    let round_at = rng.index(4);
    let chamfer_at = (round_at + 1 + rng.index(3)) % 4;
    let mut round = [false; 4];
    for (i, corner) in g.corners.iter_mut().enumerate() {
        let set = i == round_at || i == chamfer_at || rng.chance(50);
        *corner = set.then(|| small(&ctx, rng.range(2, 8) * 100));
        round[i] = i == round_at || (i != chamfer_at && rng.chance(50));
    }
    g.digits = Some(corner_digits(rng, round));
    g.j = Some(1);
    g.tool = with_tool.then(|| small(&ctx, w_um));
    g.step = if with_tool {
        (ctx.mm(w_um) * rng.range(80, 100) / 100).max(1)
    } else {
        small(&ctx, rng.range(15, 30) * 100)
    };
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 2));
    g.retract = Some(small(&ctx, rng.range(2, 5) * 100));
    if rng.chance(40) {
        g.u = Some(ctx.xf() * small(&ctx, rng.range(1, 2) * 100));
        g.w = Some(small(&ctx, rng.range(1, 2) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}

/// The opening on a slope L.
pub(super) const SLOPE: Template = Template {
    id: "g75-slope",
    outcome: Expected::Valid(&["g75:slope", "g75:j2"]),
    tags: &["template:g75-slope"],
    description: "G75.1 groove whose opening lies on a slope L, finishing contour only (J2)",
    generate: slope,
};

fn slope(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let with_tool = rng.chance(40);
    let w_um = if with_tool { rng.range(15, 25) * 100 } else { 0 };
    let d_um = w_um + rng.range(25, 50) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    // Every B offered is steeper than every L (R-G75SLOPE: L < B).
    g.l = angle(rng, &["5", "7.5", "10", "15", "20", "30"]);
    if rng.chance(60) {
        g.b = angle(rng, &["45", "60", "75", "90"]);
    }
    if rng.chance(50) {
        g.a = angle(rng, &["60", "75", "90"]);
    }
    let mut round = [false; 4];
    for (i, corner) in g.corners.iter_mut().enumerate() {
        if rng.chance(40) {
            *corner = Some(small(&ctx, rng.range(2, 6) * 100));
            round[i] = rng.chance(50);
        }
    }
    if g.corners.iter().any(Option::is_some) && rng.chance(80) {
        g.digits = Some(corner_digits(rng, round));
    }
    g.tool = with_tool.then(|| small(&ctx, w_um));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 3));
    g.j = Some(2);
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}

/// An internal groove from the current position.
pub(super) const INTERNAL: Template = Template {
    id: "g75-internal",
    outcome: Expected::Valid(&["g75:+x", "g75:+z", "g75:j0", "g75:pecking"]),
    tags: &["template:g75-internal", "rule:g75-start-omitted"],
    description: "G75.1 internal groove towards +Z from the current position (X/Z of block 1 left out), \
                  roughing J0",
    generate: internal,
};

fn internal(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let h_um = rng.range(20, 50) * 100;
    let d_um = rng.range(30, 60) * 100;
    let mut g = groove(rng, &ctx, 1, 1, h_um, d_um);
    // The tool stands at S: block 1 leaves X, Z or both out (note 3).
    let (xs, zs) = (g.start.0.unwrap_or(0), g.start.1.unwrap_or(0));
    match rng.range(0, 3) {
        0 => {
            g.from.0 = xs;
            g.start.0 = None;
        }
        1 => {
            g.from.1 = zs;
            g.start.1 = None;
        }
        _ => {
            g.from = (xs, zs);
            g.start = (None, None);
        }
    }
    if rng.chance(50) {
        g.a = angle(rng, &["60", "75", "90"]);
        g.b = angle(rng, &["60", "75", "90"]);
    }
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(2, 3));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    if rng.chance(50) {
        g.j = Some(0);
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::new(ctx, lines)
}

// ---- what a G75.1 shows ----
