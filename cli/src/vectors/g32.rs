//! G32 threads: the blocks of a G32 thread, the valid G32 templates, and
//! the features a G32 block shows.
//!
//! A G32 program is written block by block as a programmer would: a
//! [`Line32`] is one thread (start, end, taper, lead) and the templates cut
//! it in passes, as a face thread, with the profile's run-out rules or as a
//! continuous thread of several blocks; [`tags`] reads back what each
//! expanded block shows.

use std::fmt::Write as _;

use cycleref_spec::ProfileName;

use super::machine::{any_profile, head, MachineStyle};
use super::{Draft, Expected, Rng, Template};

/// A G32 block.
pub(super) fn g32(ctx: &MachineStyle, x: Option<i64>, z: Option<i64>, words: &[String]) -> String {
    let mut s = String::from("G32");
    if let Some(x) = x {
        let _ = write!(s, " X{}", ctx.num(x));
    }
    if let Some(z) = z {
        let _ = write!(s, " Z{}", ctx.num(z));
    }
    for w in words {
        let _ = write!(s, " {w}");
    }
    s
}

/// One G32 thread in increments, radial values as radii.
pub(super) struct Line32 {
    /// +1 external (the crest outside the root), -1 internal.
    pub(super) side: i64,
    /// +1 when the cut goes towards +Z.
    pub(super) dir: i64,
    /// The radius at the start.
    pub(super) r0: i64,
    /// Z at the start.
    pub(super) z0: i64,
    /// Z at the end.
    pub(super) z1: i64,
    /// The length along Z.
    pub(super) len: i64,
    /// The radial change from start to end (0: straight).
    pub(super) taper: i64,
    /// The lead word as written.
    pub(super) lead: String,
    /// The lead in increments.
    pub(super) lead_inc: i64,
}

/// A random G32 thread, straight or (with `taper`) tapered.
pub(super) fn line32(rng: &mut Rng, ctx: &MachineStyle, taper: bool) -> Line32 {
    let side = rng.sign();
    let dir = if rng.chance(70) { -1 } else { 1 };
    let (lead, lead_inc) = ctx.lead(rng, None);
    let len = ctx.mm(rng.range(15_000, 40_000));
    let r0 = if side > 0 { ctx.mm(rng.range(10_000, 30_000)) } else { ctx.mm(rng.range(20_000, 35_000)) };
    let z0 = if dir < 0 { ctx.mm(rng.range(2000, 5000)) } else { -(len + ctx.mm(rng.range(2000, 5000))) };
    let taper = if taper { rng.sign() * ctx.mm(rng.range(500, 3000)) } else { 0 };
    Line32 { side, dir, r0, z0, z1: z0 + dir * len, len, taper, lead, lead_inc }
}

/// "external" or "internal".
fn side_text(side: i64) -> &'static str {
    if side > 0 {
        "external"
    } else {
        "internal"
    }
}

// ---- the valid G32 templates ----

/// A thread cut in passes by hand.
pub(super) const PASSES: Template = Template {
    id: "g32-passes",
    // The draft requires g32:straight or g32:taper, as it drew.
    outcome: Expected::Valid(&[]),
    tags: &["template:g32-passes", "lead-modal"],
    description: "G32 thread cut in passes, the lead modal",
    generate: passes,
};

fn passes(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let taper = rng.chance(50);
    let l = line32(rng, &ctx, taper);
    let xf = ctx.xf();
    let k = l.lead_inc * 6 / 10;
    let depths = if rng.chance(50) { vec![k / 2, k] } else { vec![k / 2, k * 4 / 5, k] };
    let crest = l.r0 + l.side * k;
    let clear = ctx.mm(rng.range(2000, 5000));
    let retract =
        xf * (if l.side > 0 { crest + l.taper.max(0) + clear } else { crest + l.taper.min(0) - clear });
    let incremental = rng.chance(40);
    let mut lines = Vec::new();
    for (n, depth) in depths.iter().enumerate() {
        let r = crest - l.side * depth;
        if n == 0 {
            lines.extend(head(rng, &ctx, (xf * r, l.z0)));
        } else {
            lines.push(format!("X{}", ctx.num(xf * r)));
        }
        let lead = if n == 0 { vec![l.lead.clone()] } else { vec![] };
        let x_end = (l.taper != 0).then_some(xf * (r + l.taper));
        if incremental {
            let mut s = String::from("G32");
            if let Some(x) = x_end {
                let _ = write!(s, " X{}", ctx.num(x));
            }
            let _ = write!(s, " W{}", ctx.num(l.z1 - l.z0));
            for w in &lead {
                let _ = write!(s, " {w}");
            }
            lines.push(s);
        } else {
            lines.push(g32(&ctx, x_end, Some(l.z1), &lead));
        }
        lines.push(format!("G00 X{}", ctx.num(retract)));
        if incremental {
            lines.push(format!("W{}", ctx.num(l.z0 - l.z1)));
        } else {
            lines.push(format!("Z{}", ctx.num(l.z0)));
        }
    }
    lines.push("M30".into());
    let what = if taper { "taper" } else { "straight" };
    Draft::new(ctx, lines)
        .described(format!(
            "G32 {what} {} thread cut in {} passes, the lead modal",
            side_text(l.side),
            depths.len()
        ))
        .requiring(if taper { &["g32:taper"] } else { &["g32:straight"] })
}

/// A face thread.
pub(super) const FACE: Template = Template {
    id: "g32-face",
    outcome: Expected::Valid(&["g32:face"]),
    tags: &["template:g32-face"],
    description: "G32 face thread (X only)",
    generate: face,
};

fn face(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let (lead, lead_inc) = ctx.lead(rng, None);
    let outer = ctx.mm(rng.range(30_000, 45_000));
    let inner = ctx.mm(rng.range(6000, 15_000));
    let inward = rng.chance(70);
    let (r0, r1) = if inward { (outer, inner) } else { (inner, outer) };
    let dir = rng.sign();
    let z_face = ctx.mm(rng.range(-2000, 2000));
    let k = lead_inc * 6 / 10;
    let clear = ctx.mm(2000);
    let mut lines = Vec::new();
    let runout = ctx.profile != ProfileName::Fanuc && rng.chance(60);
    for (n, depth) in [k / 2, k].iter().enumerate() {
        let z = z_face + dir * depth;
        if n == 0 {
            lines.extend(head(rng, &ctx, (xf * r0, z)));
        } else {
            lines.push(format!("Z{}", ctx.num(z)));
        }
        let mut words = Vec::new();
        if n == 0 {
            words.push(lead.clone());
        }
        if runout {
            // J along Z (away from the face), K along X (radius).
            words.push(format!("J{}", ctx.num(-dir * ctx.mm(rng.range(300, 1500)))));
            words.push(format!("K{}", ctx.num(ctx.mm(rng.range(500, 2000)))));
        }
        if rng.chance(50) {
            lines.push(g32(&ctx, Some(xf * r1), None, &words));
        } else {
            let mut s = format!("G32 U{} W0", ctx.num(xf * (r1 - r0)));
            for w in &words {
                let _ = write!(s, " {w}");
            }
            lines.push(s);
        }
        lines.push(format!("G00 Z{}", ctx.num(z_face - dir * clear)));
        lines.push(format!("X{}", ctx.num(xf * r0)));
    }
    lines.push("M30".into());
    let what = if inward { "towards the centre" } else { "outwards" };
    Draft::new(ctx, lines)
        .described(format!("G32 face thread (X only), cut {what}"))
        .tag_if(runout, "g32:face-run-out")
}

/// G32 blocks with run-out, one per rule of the profile, each cut from the
/// same start (G00 between them cancels J and K), then one without J/K.
fn runout_program(rng: &mut Rng, ctx: &MachineStyle, l: &Line32, variants: &[Vec<String>]) -> Vec<String> {
    let xf = ctx.xf();
    let x1 = (l.taper != 0).then_some(xf * (l.r0 + l.taper));
    let clear = ctx.mm(rng.range(3000, 5000));
    let reach = l.taper.abs().max(ctx.mm(2000));
    let retract = xf * (l.r0 + l.side * (reach + clear)).max(ctx.mm(1000));
    let mut lines = head(rng, ctx, (xf * l.r0, l.z0));
    for (n, words) in variants.iter().chain(std::iter::once(&Vec::new())).enumerate() {
        if n > 0 {
            lines.push(format!("X{}", ctx.num(xf * l.r0)));
        }
        let mut words = words.clone();
        if n == 0 {
            words.push(l.lead.clone());
        }
        lines.push(g32(ctx, x1, Some(l.z1), &words));
        lines.push(format!("G00 X{}", ctx.num(retract)));
        lines.push(format!("Z{}", ctx.num(l.z0)));
    }
    lines.push("M30".into());
    lines
}

/// The GSK 980TDi G32 run-out rules.
pub(super) const RUNOUT_980: Template = Template {
    id: "g32-run-out-gsk980",
    outcome: Expected::Valid(&["g32:run-out"]),
    tags: &[
        "template:g32-run-out-gsk980",
        "rule:g32-gsk980-jk",
        "rule:g32-gsk980-k-omitted",
        "rule:g32-gsk980-k0",
        "rule:g32-gsk980-j0",
        "rule:g32-jk-cancelled",
    ],
    description: "GSK 980TDi G32 thread, run-out rules of seed 002",
    generate: runout_980,
};

fn runout_980(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk980, rng);
    let taper = rng.chance(50);
    let l = line32(rng, &ctx, taper);
    let (j, k) = (ctx.mm(rng.range(300, 2000)), ctx.mm(rng.range(500, 3000)));
    let (jt, njt, kt) = (ctx.num(l.side * j), ctx.num(-l.side * j), ctx.num(k));
    let variants = [
        vec![format!("J{jt}"), format!("K{kt}")],
        vec![format!("J{jt}")],
        vec![format!("J{njt}"), "K0".into()],
        vec!["J0".into(), format!("K{kt}")],
    ];
    let lines = runout_program(rng, &ctx, &l, &variants);
    let shape = if taper { "taper" } else { "straight" };
    Draft::new(ctx, lines).described(format!(
        "GSK 980TDi G32 {shape} thread, run-out rules of seed 002: J and K, K omitted (K = |J|), J \
         negative with K0 (K = |J|), J0 (none), then J and K cancelled by G00"
    ))
}

/// The GSK 988TA G32 run-out rules on a steep taper.
pub(super) const RUNOUT_988: Template = Template {
    id: "g32-run-out-gsk988",
    outcome: Expected::Valid(&["g32:run-out", "g32:pull-out", "g32:x-long"]),
    tags: &[
        "template:g32-run-out-gsk988",
        "rule:g32-gsk988-jk",
        "rule:g32-gsk988-j-only",
        "rule:g32-jk-cancelled",
    ],
    description: "GSK 988TA G32 steep taper (X the long axis): J and K, J only (a pull-out along Z), then J \
                  and K cancelled by G00",
    generate: runout_988,
};

fn runout_988(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(ProfileName::Gsk988, rng);
    let mut l = line32(rng, &ctx, false);
    // Steep: the X travel (radius) at least the Z travel; K along X, J along Z.
    l.len = ctx.mm(rng.range(3000, 6000));
    l.z1 = l.z0 + l.dir * l.len;
    l.taper = -l.side * (l.len + if rng.chance(20) { 0 } else { ctx.mm(rng.range(0, 5000)) });
    l.r0 = l.r0.max(l.taper.abs() + ctx.mm(8000));
    let (j, k) = (ctx.mm(rng.range(300, 2000)), ctx.mm(rng.range(500, 2500)));
    let jt = ctx.num(-l.dir * j);
    let variants = [vec![format!("J{jt}"), format!("K{}", ctx.num(k))], vec![format!("J{jt}")]];
    let lines = runout_program(rng, &ctx, &l, &variants);
    Draft::new(ctx, lines)
}

/// A continuous thread of three blocks, two starts.
pub(super) const CONTINUOUS: Template = Template {
    id: "g32-continuous",
    outcome: Expected::Valid(&["g32:continuous", "g32:q"]),
    tags: &["template:g32-continuous", "g32:multi-start"],
    description:
        "G32 continuous thread of three blocks (taper in, straight, taper out), cut twice with Q 180 \
                  degrees apart",
    generate: continuous,
};

fn continuous(rng: &mut Rng) -> Draft {
    let ctx = MachineStyle::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let l = line32(rng, &ctx, false);
    let rise = ctx.mm(rng.range(500, 2000));
    let seg = l.len / 4;
    let (r_in, r_mid) = (l.r0, l.r0 + l.side * rise);
    let z = [l.z0 + l.dir * seg, l.z0 + l.dir * 3 * seg, l.z1];
    let q1 = rng.pick(&[0, 45_000, 90_000, 120_000, 270_000]);
    let wrap = ctx.profile == ProfileName::Gsk988 && rng.chance(40);
    let qtext = |q: i64| {
        if wrap {
            ctx.q(q + 360_000)
        } else {
            ctx.q(q)
        }
    };
    let runout_end = ctx.profile != ProfileName::Fanuc && rng.chance(50);
    let retract = xf * (r_mid + l.side * ctx.mm(4000)).max(ctx.mm(1000));
    let mut lines = head(rng, &ctx, (xf * r_in, l.z0));
    for (start, q) in [q1, (q1 + 180_000) % 360_000].into_iter().enumerate() {
        if start == 1 {
            lines.push(format!("X{}", ctx.num(xf * r_in)));
        }
        let mut first = vec![];
        if start == 0 {
            first.push(l.lead.clone());
        }
        if q != 0 || wrap {
            first.push(format!("Q{}", qtext(q)));
        }
        lines.push(g32(&ctx, Some(xf * r_mid), Some(z[0]), &first));
        let ignored = if rng.chance(40) { vec![format!("Q{}", ctx.q(30_000))] } else { vec![] };
        lines.push(g32(&ctx, None, Some(z[1]), &ignored));
        let last = if runout_end { vec![format!("J{}", ctx.num(l.side * ctx.mm(1000)))] } else { vec![] };
        lines.push(g32(&ctx, Some(xf * r_in), Some(z[2]), &last));
        lines.push(format!("G00 X{}", ctx.num(retract)));
        lines.push(format!("Z{}", ctx.num(l.z0)));
    }
    lines.push("M30".into());
    Draft::new(ctx, lines).tag_if(wrap, "g32:q-wrap")
}

// ---- what a G32 block shows ----
