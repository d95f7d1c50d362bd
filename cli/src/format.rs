//! Text forms of moves: NC blocks, JSON and the pass table.

use std::fmt::Write as _;

use cycleref::units::write_fixed;
use cycleref::{Flank, IncrementSystem, LeadWord, Motion, Move, PassKind, Role, StartAngle, Units};
use cycleref::{PathType, Point};
use cycleref_spec::profile::QUnit;
use cycleref_spec::reader::{G75Call, G76Call, Restore};
use serde_json::{json, Value};

/// `v` increments as a decimal with the increment's number of decimals.
pub fn fixed(v: i64, units: Units) -> String {
    let mut s = String::new();
    let _ = write_fixed(&mut s, i128::from(v), units.decimals());
    s
}

/// The lead word as programmed (`F6`, `F1.5`, `I20`).
pub fn lead_word(lead: cycleref::Lead) -> String {
    let letter = match lead.word {
        LeadWord::F => 'F',
        LeadWord::I => 'I',
    };
    let mut s = String::new();
    let _ = write_fixed(&mut s, i128::from(lead.mantissa), lead.scale);
    if lead.scale == 0 {
        // Always with a decimal point: on FANUC a bare value may be read in
        // other units.
        s.push_str(".0");
    }
    format!("{letter}{s}")
}

/// The value of a Q word for `angle` in the profile's unit: whole
/// thousandths of a degree, or degrees with the increment system's
/// decimals (3 at IS-B, 4 at IS-C), rounded to nearest where the exact
/// angle has more digits (360°/7).
pub fn q_word(angle: StartAngle, u: Units, q: QUnit) -> String {
    match q {
        QUnit::Millidegrees { .. } => angle.rounded_millidegrees().to_string(),
        QUnit::Degrees { .. } => {
            let decimals: u32 = match u.system {
                IncrementSystem::IsB => 3,
                IncrementSystem::IsC => 4,
            };
            // Units of 10^-decimals degree: num / den millidegrees × 10^(decimals - 3).
            let scale = u64::from(10_u32.pow(decimals - 3));
            let den = u64::from(angle.den);
            let v = (2 * u64::from(angle.num) * scale + den) / (2 * den);
            let mut s = String::new();
            let _ = write_fixed(&mut s, i128::from(v), decimals);
            s
        }
    }
}

/// Name of a pass kind.
pub fn kind_name(k: PassKind) -> &'static str {
    match k {
        PassKind::Rough => "rough",
        PassKind::Finish => "finish",
    }
}

/// Name of a role.
pub fn role_name(r: Role) -> &'static str {
    match r {
        Role::Approach => "approach",
        Role::LeadIn => "lead-in",
        Role::Cut => "cut",
        Role::RunOut => "run-out",
        Role::Retract => "retract",
        Role::Return => "return",
        Role::Peck(_) => "peck",
        Role::PeckRetract(_) => "peck-retract",
        Role::PlungeRetract(_) => "plunge-retract",
        Role::Step(_) => "step",
        Role::LayerChange(_) => "layer-change",
        Role::RoughContour => "rough-contour",
        Role::FinishContour => "finish-contour",
    }
}

/// The plunge a G75.1 move belongs to, if any.
pub fn plunge_of(r: Role) -> Option<cycleref::Plunge> {
    match r {
        Role::Peck(p) | Role::PeckRetract(p) | Role::PlungeRetract(p) | Role::Step(p) => Some(p),
        _ => None,
    }
}

/// An arc's I (X distance from the start to the centre, as a radius) and K
/// (Z distance), as written in the nc format: I may need one more decimal
/// than the increment when X is a diameter and the distance is odd.
pub fn arc_ik(from: Point, centre: Point, x_factor: i64, units: Units) -> (String, String) {
    let dx = centre.x - from.x;
    let i = if dx % x_factor == 0 {
        fixed(dx / x_factor, units)
    } else {
        // Half an increment: print dx * 5 with one more decimal.
        let mut s = String::new();
        let _ = write_fixed(&mut s, i128::from(dx) * 5, units.decimals() + 1);
        s
    };
    (i, fixed(centre.z - from.z, units))
}

/// Writes the NC blocks of one expanded G75.1 cycle: a comment per layer
/// and per plunge, then its moves (the `nc` format contract).
pub fn nc_groove(out: &mut String, call: &G75Call, moves: &[Move]) {
    let c = &call.cycle;
    let u = c.units;
    let layers = moves.iter().filter_map(|m| plunge_of(m.role)).map(|p| p.layer).max().unwrap_or(0);
    let plunges = moves.iter().filter(|m| matches!(m.role, Role::PlungeRetract(_))).count();
    let path = match c.path {
        PathType::Rough => "J0 rough",
        PathType::RoughAndFinish => "J1 rough + finish",
        PathType::Finish => "J2 finish",
    };
    let _ = writeln!(
        out,
        "(G75.1 lines {}-{}: {path}, {layers} layer{} {plunges} plunge{}, tool {})",
        call.params_line,
        call.block.line,
        if layers == 1 { "," } else { "s," },
        if plunges == 1 { "" } else { "s" },
        match c.tool_width {
            Some(w) => format!("width I{}", fixed(w, u)),
            None => "pointed".to_string(),
        }
    );
    let mut current: Option<cycleref::Plunge> = None;
    let mut contour = None;
    let mut at = c.from;
    for m in moves {
        if let Role::Peck(p) = m.role {
            if current != Some(p) {
                current = Some(p);
                let _ = writeln!(out, "(layer {} plunge {})", p.layer, p.number);
            }
        }
        let name = match m.role {
            Role::RoughContour => Some("rough contour"),
            Role::FinishContour => Some("finishing contour"),
            _ => None,
        };
        if name.is_some() && name != contour {
            let _ = writeln!(out, "({})", name.unwrap_or_default());
        }
        contour = name;
        nc_arc_or_move(out, m, at, c.x_mode.factor(), u);
        at = m.to;
    }
    restore(out, &call.restore);
}

/// One G75.1 move: arcs with I/K, the rest as [`nc_move`].
fn nc_arc_or_move(out: &mut String, m: &Move, from: Point, x_factor: i64, u: Units) {
    if let Motion::Arc { centre, clockwise } = m.motion {
        let (i, k) = arc_ik(from, centre, x_factor, u);
        let g = if clockwise { "G02" } else { "G03" };
        let _ = writeln!(out, "{g} X{} Z{} I{i} K{k}", fixed(m.to.x, u), fixed(m.to.z, u));
    } else {
        nc_move(out, m, u, QUnit::Millidegrees { no_point: true });
    }
}

/// Name of a flank position.
pub fn flank_name(f: Flank) -> &'static str {
    match f {
        Flank::Right => "right",
        Flank::Centre => "centre",
        Flank::Left => "left",
    }
}

/// Writes the NC blocks of one expanded cycle (the `nc` format contract,
/// documented in the README).
pub fn nc_cycle(out: &mut String, call: &G76Call, moves: &[Move], q: QUnit) {
    let u = call.cycle.units;
    let rough = moves.iter().filter_map(|m| m.pass).filter(|p| p.kind == PassKind::Rough);
    let rough_passes = rough.map(|p| p.number).max().unwrap_or(0);
    let _ = writeln!(
        out,
        "(G76 line {}: {} rough + {} finish passes x {} start{})",
        call.block.line,
        rough_passes,
        call.cycle.finishing_passes,
        call.cycle.starts,
        if call.cycle.starts == 1 { "" } else { "s" }
    );
    let mut current = None;
    for m in moves {
        if let Some(p) = m.pass {
            let key = (p.kind, p.number, p.start);
            if current != Some(key) {
                current = Some(key);
                let _ = writeln!(
                    out,
                    "({} {} start {} depth {} cut {})",
                    kind_name(p.kind),
                    p.number,
                    p.start,
                    fixed(p.depth, u),
                    fixed(p.cut, u)
                );
            }
        }
        nc_move(out, m, u, q);
    }
    restore(out, &call.restore);
}

/// Writes moves without pass comments (G32 blocks).
pub fn nc_moves(out: &mut String, moves: &[Move], u: Units, q: QUnit) {
    for m in moves {
        nc_move(out, m, u, q);
    }
}

/// One move as an NC block.
fn nc_move(out: &mut String, m: &Move, u: Units, q: QUnit) {
    {
        let x = fixed(m.to.x, u);
        let z = fixed(m.to.z, u);
        match m.motion {
            Motion::Rapid => {
                let _ = writeln!(out, "G00 X{x} Z{z}");
            }
            Motion::Feed => {
                let _ = writeln!(out, "G01 X{x} Z{z}");
            }
            Motion::Thread { lead, start_angle, sync } => {
                let _ = write!(out, "G32 X{x} Z{z} {}", lead_word(lead));
                // Q only where synchronisation starts: on a continuation
                // block the control ignores it (seed 002, Q rule 2).
                if sync && !start_angle.is_zero() {
                    let _ = write!(out, " Q{}", q_word(start_angle, u, q));
                }
                out.push('\n');
            }
            Motion::Arc { centre, clockwise } => {
                // Without the start point the centre is written absolute.
                let g = if clockwise { "G02" } else { "G03" };
                let _ =
                    writeln!(out, "{g} X{x} Z{z} (centre X{} Z{})", fixed(centre.x, u), fixed(centre.z, u));
            }
        }
    }
}

fn restore(out: &mut String, r: &Restore) {
    if let Some(g) = r.motion {
        let _ = writeln!(out, "{g}");
    }
}

/// One move as JSON (the `json` format contract).
pub fn move_json(m: &Move, units: Units) -> Value {
    let mut v = json!({
        "role": role_name(m.role),
        "x": fixed(m.to.x, units),
        "z": fixed(m.to.z, units),
    });
    let obj = v.as_object_mut().expect("object");
    match m.motion {
        Motion::Rapid => {
            obj.insert("motion".into(), json!("rapid"));
        }
        Motion::Feed => {
            obj.insert("motion".into(), json!("feed"));
        }
        Motion::Thread { lead, start_angle, sync } => {
            obj.insert("motion".into(), json!("thread"));
            obj.insert("lead".into(), json!(lead_word(lead)));
            obj.insert(
                "start_angle_millidegrees".into(),
                json!({"num": start_angle.num, "den": start_angle.den}),
            );
            obj.insert("sync".into(), json!(sync));
        }
        Motion::Arc { centre, clockwise } => {
            obj.insert("motion".into(), json!(if clockwise { "arc-cw" } else { "arc-ccw" }));
            obj.insert("centre".into(), json!({"x": fixed(centre.x, units), "z": fixed(centre.z, units)}));
        }
    }
    if let Some(p) = plunge_of(m.role) {
        obj.insert("plunge".into(), json!({"layer": p.layer, "number": p.number}));
    }
    if let Role::LayerChange(l) = m.role {
        obj.insert("plunge".into(), json!({"layer": l}));
    }
    if let Some(p) = m.pass {
        obj.insert(
            "pass".into(),
            json!({
                "kind": kind_name(p.kind),
                "number": p.number,
                "start": p.start,
                "depth": fixed(p.depth, units),
                "cut": fixed(p.cut, units),
                "flank": flank_name(p.flank),
            }),
        );
    }
    // Keep a stable key order: motion first.
    let mut ordered = serde_json::Map::new();
    for key in
        ["motion", "x", "z", "centre", "role", "lead", "start_angle_millidegrees", "sync", "pass", "plunge"]
    {
        if let Some(val) = obj.remove(key) {
            ordered.insert(key.into(), val);
        }
    }
    Value::Object(ordered)
}
