//! LinuxCNC's G76 (the `linuxcnc` profile): a valid template over its
//! words and a refused one over the interpreter's own refusals.
//!
//! A program is written as LinuxCNC's documentation writes one: the plane,
//! the unit and the X mode (G7 or G8) first, the spindle, a G0 to the
//! drive line, the one-block G76, and a G0 away.

use cycleref::{CycleError, Field, IncrementSystem, InputUnit, XMode};
use cycleref_spec::{ErrorKind, ProfileName};

use super::machine::MachineStyle;
use super::{Draft, Expected, Rng, Template};

/// A linuxcnc machine (IS-C, the profile's own) and the program's unit and
/// X mode: G20 or G21 and G7 or G8 are written in the program.
fn ctx(rng: &mut Rng) -> MachineStyle {
    let mut ctx = MachineStyle::new(ProfileName::LinuxCnc, rng);
    ctx.increment = IncrementSystem::IsC;
    ctx.unit = if rng.chance(25) { InputUnit::Inch } else { InputUnit::Metric };
    ctx.g20 = ctx.unit == InputUnit::Inch;
    ctx.x = if rng.chance(50) { XMode::Diameter } else { XMode::Radius };
    ctx.calculator_input = false;
    ctx.bare = false;
    ctx.params.clear();
    ctx
}

/// The words of one G76 and the program around it.
struct Words {
    x0: i64,
    z0: i64,
    z: i64,
    /// Signed I, and J and K, in X units.
    i: i64,
    j: i64,
    k: i64,
    /// R and Q as written (None: left out).
    r: Option<&'static str>,
    q: Option<&'static str>,
    h: Option<i64>,
    /// E in increments and L.
    e: Option<(i64, i64)>,
    p: &'static str,
}

/// A G76 of a few passes (at most 5 rough, so that a case stays small).
fn words(ctx: &MachineStyle, rng: &mut Rng) -> Words {
    let xf = ctx.xf();
    let internal = rng.chance(30);
    let towards_plus = rng.chance(25);
    let x0 = xf * ctx.mm(rng.range(8_000, 30_000));
    let z0 = ctx.mm(rng.range(0, 5_000));
    let length = ctx.mm(rng.range(8_000, 40_000));
    let z = if towards_plus { z0 + length } else { z0 - length };
    let j = xf * ctx.mm(rng.range(100, 300));
    // The ratio K/J keeps J·n^(1/R) below K for at most five passes.
    let (r, max_ratio_tenths) = match rng.range(0, 3) {
        0 => (None, 50),
        1 => (Some("1"), 50),
        2 => (Some("1.5"), 30),
        _ => (Some("2"), 23),
    };
    let k = j * rng.range(12, max_ratio_tenths) / 10;
    let i_abs = xf * ctx.mm(rng.range(100, 1_000));
    let q = rng.pick(&[None, Some("29.5"), Some("30"), Some("0"), Some("-1")]);
    let h = rng.pick(&[None, Some(0), Some(1)]);
    let e = if rng.chance(40) { Some((ctx.mm(rng.range(500, 2_000)), rng.range(0, 3))) } else { None };
    let p = rng.pick(&["1", "1.5", "2", "0.8"]);
    Words { x0, z0, z, i: if internal { i_abs } else { -i_abs }, j, k, r, q, h, e, p }
}

/// The program of `w`, `g76` the G76 block as it stands (a refusal may
/// change it).
fn program(ctx: &MachineStyle, w: &Words, g76: &str, spindle: bool) -> Vec<String> {
    let mut lines = vec![format!(
        "G18 {} {}",
        if ctx.unit == InputUnit::Inch { "G20" } else { "G21" },
        if ctx.x == XMode::Diameter { "G7" } else { "G8" }
    )];
    if spindle {
        lines.push("M3 S500".into());
    }
    lines.push(format!("G0 X{} Z{}", ctx.num(w.x0), ctx.num(w.z0)));
    lines.push(g76.to_string());
    lines.push(format!("G0 X{} Z{}", ctx.num(w.x0), ctx.num(w.z0)));
    lines.push("M5".into());
    lines.push("M2".into());
    lines
}

/// The G76 block of `w`, leaving out the words of `omit`.
fn g76_block(ctx: &MachineStyle, w: &Words, omit: &[char]) -> String {
    let mut s = String::from("G76");
    let mut word = |letter: char, value: String| {
        if !omit.contains(&letter) {
            s.push(' ');
            s.push(letter);
            s.push_str(&value);
        }
    };
    word('P', w.p.to_string());
    word('Z', ctx.num(w.z));
    word('I', ctx.num(w.i));
    word('J', ctx.num(w.j));
    if let Some(r) = w.r {
        word('R', r.to_string());
    }
    word('K', ctx.num(w.k));
    if let Some(q) = w.q {
        word('Q', q.to_string());
    }
    if let Some(h) = w.h {
        word('H', h.to_string());
    }
    if let Some((e, l)) = w.e {
        word('E', ctx.num(e));
        word('L', l.to_string());
    }
    s
}

/// LinuxCNC's G76 over its words: G7 and G8, mm and inch, external and
/// internal, both directions, R, Q (with -1 for 0), H, E and L.
pub(super) const G76: Template = Template {
    id: "linuxcnc-g76",
    outcome: Expected::Valid(&["linuxcnc"]),
    tags: &["template:linuxcnc-g76", "rule:lcnc-pass"],
    description: "LinuxCNC G76 P Z I J R K Q H E L (the linuxcnc profile)",
    generate: g76,
};

fn g76(rng: &mut Rng) -> Draft {
    let ctx = ctx(rng);
    let w = words(&ctx, rng);
    let block = g76_block(&ctx, &w, &[]);
    let lines = program(&ctx, &w, &block, true);
    Draft::new(ctx, lines)
}

/// The interpreter's refusals of a G76, in its words: a missing P, I, J or
/// K, I = 0, J = 0, K <= J, the spindle not turning.
pub(super) const REFUSED: Template = Template {
    id: "linuxcnc-g76-refused",
    outcome: Expected::Refused(|k| {
        matches!(
            k,
            ErrorKind::Missing { .. }
                | ErrorKind::Cycle(CycleError::WordOutOfRange {
                    field: Field::PeakOffset | Field::InitialDepth | Field::FullDepth,
                    ..
                })
        )
    }),
    tags: &["refuse:linuxcnc-g76"],
    description: "LinuxCNC G76 refused as the interpreter refuses it",
    generate: refused,
};

fn refused(rng: &mut Rng) -> Draft {
    let ctx = ctx(rng);
    let mut w = words(&ctx, rng);
    let (what, block, spindle) = match rng.range(0, 5) {
        0 => ("P missing (\"P word missing with G76\")", g76_block(&ctx, &w, &['P']), true),
        1 => {
            let letter = rng.pick(&['I', 'J', 'K']);
            ("I, J or K missing (\"I J or K words missing with G76\")", g76_block(&ctx, &w, &[letter]), true)
        }
        2 => {
            w.i = 0;
            ("I0 (\"In G76, I must not be 0\")", g76_block(&ctx, &w, &[]), true)
        }
        3 => {
            w.k = w.j;
            ("K = J (\"In G76, K must be greater than J\")", g76_block(&ctx, &w, &[]), true)
        }
        _ => ("no M3/M4 (\"Chosen spindle (0) not turning in G76\")", g76_block(&ctx, &w, &[]), false),
    };
    let lines = program(&ctx, &w, &block, spindle);
    Draft::new(ctx, lines).described(format!("LinuxCNC G76 refused: {what}"))
}
