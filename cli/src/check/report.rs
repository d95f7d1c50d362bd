//! The result of a comparison: the divergences counted (the first
//! `MAX_LISTED` kept) and written as text or JSON, or as the marks
//! `plot --trace` draws, each of our moves named in the manual's terms.

use std::fmt::Write as _;

use cycleref::{InputUnit, Lead, PassKind, Point, Role, Units};
use serde_json::{json, Value};

use super::{Context, Divergence, Kind, Step};
use crate::format::{fixed, kind_name};

/// A divergence as `plot --trace` draws it: where it is, and what the
/// report says of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mark {
    /// The line of our cycle it lies in (G76 block 2, G32, G75.1 block 2);
    /// `None` for a program block's move or a move only the trace makes.
    pub cycle_line: Option<usize>,
    /// Where our move ends, if we make it.
    pub ours: Option<Point>,
    /// Where the trace's move ends, if it makes one.
    pub theirs: Option<Point>,
    /// Theirs minus ours in increments (X, Z), when both make the move.
    pub difference: Option<(i128, i128)>,
    /// The report's lines for it (what, where, ours, theirs, difference).
    pub text: Vec<String>,
}

/// The most divergences a report lists; the count is always exact.
pub const MAX_LISTED: usize = 10_000;

/// The point a move ends at, in the manual's terms.
fn point_name(c: Context, kind: Kind) -> &'static str {
    match c {
        // LinuxCNC's own names of the moves (threading_pass, R-LCNC-PASS).
        Context::LinuxCnc { role, .. } => match role {
            Role::Approach => "pass start (\"back\" or \"in\")",
            Role::LeadIn => "entry taper (\"in\", \"angled in\")",
            Role::Cut => "end of \"over\"",
            Role::RunOut => "exit taper end (\"angled out\")",
            Role::Retract => "\"out\"",
            _ => "the block's X Z (end of the cycle)",
        },
        Context::G76 { role, .. }
        | Context::G32 { role, .. }
        | Context::G75 { role, .. }
        | Context::G92 { role, .. } => match role {
            Role::Approach => "Bn (pass start, or An before a lead-in)",
            Role::LeadIn => "Bn (end of the lead-in)",
            Role::Cut => "end of cut (run-out start)",
            Role::RunOut => "run-out end",
            Role::Retract => "E (retract end)",
            Role::Return => "A (start point)",
            Role::Peck(_) => "peck end (Bmn at the last peck)",
            Role::PeckRetract(_) => "retract e after a peck",
            Role::PlungeRetract(_) => "Amn (plunge start)",
            Role::Step(_) => "Amn (next plunge start)",
            Role::LayerChange(_) => "Am1 (layer start)",
            Role::RoughContour => "rough contour point",
            Role::FinishContour => "finishing contour point",
        },
        Context::Source { .. } => match kind {
            Kind::Rapid => "rapid end",
            _ => "end point",
        },
    }
}

/// The result of a comparison.
pub struct Report {
    units: Units,
    tolerance: u64,
    pub(super) ours_moves: usize,
    pub(super) theirs_moves: usize,
    /// The first [`MAX_LISTED`] divergences.
    divergences: Vec<Divergence>,
    /// How many there are.
    total: usize,
}

impl Report {
    pub(super) fn new(units: Units, tolerance: u64) -> Report {
        Report { units, tolerance, ours_moves: 0, theirs_moves: 0, divergences: Vec::new(), total: 0 }
    }

    /// Counts `found` and keeps those within the first [`MAX_LISTED`].
    pub(super) fn add(&mut self, found: Vec<Divergence>) {
        self.total += found.len();
        let room = MAX_LISTED.saturating_sub(self.divergences.len());
        self.divergences.extend(found.into_iter().take(room));
    }

    /// The listed divergences as a picture marks them (`plot --trace`), in
    /// order: the first is the report's first divergence.
    #[must_use]
    pub fn marks(&self) -> Vec<Mark> {
        self.divergences
            .iter()
            .map(|d| {
                let mut text = String::new();
                self.describe(d, &mut text);
                let cycle_line = d.ours.and_then(|s| match s.context {
                    Context::LinuxCnc { line, .. }
                    | Context::G76 { line, .. }
                    | Context::G32 { line, .. }
                    | Context::G75 { line, .. }
                    | Context::G92 { line, .. } => Some(line),
                    Context::Source { .. } => None,
                });
                let difference = match (&d.ours, &d.theirs) {
                    (Some(o), Some(t)) => Some(diff(o.to, t.to)),
                    _ => None,
                };
                Mark {
                    cycle_line,
                    ours: d.ours.map(|s| s.to),
                    theirs: d.theirs.map(|s| s.to),
                    difference,
                    text: text.lines().map(str::to_string).collect(),
                }
            })
            .collect()
    }

    /// True when the toolpaths agree within the tolerance.
    pub fn agree(&self) -> bool {
        self.total == 0
    }

    /// The number of divergences (all of them, listed or not).
    pub fn divergences(&self) -> usize {
        self.total
    }

    fn point(&self, p: Point) -> String {
        let axis = |v: i64| if v == super::UNKNOWN { "?".to_string() } else { fixed(v, self.units) };
        format!("X{} Z{}", axis(p.x), axis(p.z))
    }

    fn where_ours(&self, s: &Step) -> String {
        match s.context {
            Context::G76 { code, line, pass, .. } => format!(
                "{code} at line {line}, {} pass {} (start {}, depth {}, cut {})",
                kind_name(pass.kind),
                pass.number,
                pass.start,
                fixed(pass.depth, self.units),
                fixed(pass.cut, self.units)
            ),
            Context::G32 { code, line, .. } => format!("{code} at line {line}"),
            Context::LinuxCnc { line, pass, .. } => format!(
                "G76 (LinuxCNC) at line {line}, {} pass {} (depth {}, cut {})",
                if pass.kind == PassKind::Rough { "rough" } else { "full-depth" },
                pass.number,
                fixed(pass.depth, self.units),
                fixed(pass.cut, self.units)
            ),
            Context::G92 { line, start, .. } => format!("G92 at line {line}, start {start}"),
            Context::G75 { line, role } => match crate::format::plunge_of(role) {
                Some(p) => format!("G75.1 at line {line}, layer {} plunge {}", p.layer, p.number),
                None => format!("G75.1 at line {line}, {}", crate::format::role_name(role)),
            },
            Context::Source { line } => format!("program line {line}"),
        }
    }

    fn theirs_line(s: &Step) -> usize {
        match s.context {
            Context::Source { line } => line,
            Context::LinuxCnc { line, .. }
            | Context::G76 { line, .. }
            | Context::G32 { line, .. }
            | Context::G75 { line, .. }
            | Context::G92 { line, .. } => line,
        }
    }

    fn describe(&self, d: &Divergence, out: &mut String) {
        match (&d.ours, &d.theirs) {
            (Some(o), Some(t)) => {
                let _ =
                    writeln!(out, "{}: {} ({})", self.where_ours(o), point_name(o.context, o.kind), d.what);
                match d.what {
                    "lead" => {
                        let lead = |l: Option<Lead>| l.map_or("none".into(), crate::format::lead_word);
                        let _ = writeln!(out, "  ours   {} {}", self.point(o.to), lead(o.lead));
                        let _ = writeln!(
                            out,
                            "  theirs {} {} (trace line {})",
                            self.point(t.to),
                            lead(t.lead),
                            Self::theirs_line(t)
                        );
                    }
                    "start angle" | "synchronisation" => {
                        let ang = |s: &Step| {
                            if s.sync {
                                format!(
                                    "synchronises at {}/{} thousandths of a degree",
                                    s.angle.num, s.angle.den
                                )
                            } else {
                                "continues the synchronised run".into()
                            }
                        };
                        let _ = writeln!(out, "  ours   {} {}", self.point(o.to), ang(o));
                        let _ = writeln!(
                            out,
                            "  theirs {} {} (trace line {})",
                            self.point(t.to),
                            ang(t),
                            Self::theirs_line(t)
                        );
                    }
                    "arc centre" => {
                        let c = |s: &Step| s.centre.map_or("none".into(), |c| self.point(c));
                        let _ =
                            writeln!(out, "  ours   {} {} centre {}", o.kind.name(), self.point(o.to), c(o));
                        let _ = writeln!(
                            out,
                            "  theirs {} {} centre {} (trace line {})",
                            t.kind.name(),
                            self.point(t.to),
                            c(t),
                            Self::theirs_line(t)
                        );
                        if let (Some(oc), Some(tc)) = (o.centre, t.centre) {
                            let (dx, dz) = diff(oc, tc);
                            let _ = writeln!(out, "  difference of the centres: X {dx} Z {dz} increments");
                        }
                    }
                    _ => {
                        let _ = writeln!(out, "  ours   {} {}", o.kind.name(), self.point(o.to));
                        let _ = writeln!(
                            out,
                            "  theirs {} {} (trace line {})",
                            t.kind.name(),
                            self.point(t.to),
                            Self::theirs_line(t)
                        );
                        let (dx, dz) = diff(o.to, t.to);
                        let _ = writeln!(out, "  difference: X {dx} Z {dz} increments");
                    }
                }
            }
            (Some(o), None) => {
                let _ = writeln!(
                    out,
                    "{}: {} ({} move{} not in the trace), first: {} {}",
                    self.where_ours(o),
                    d.what,
                    d.moves,
                    if d.moves == 1 { "" } else { "s" },
                    point_name(o.context, o.kind),
                    self.point(o.to)
                );
            }
            (None, Some(t)) => {
                let _ = writeln!(
                    out,
                    "trace line {}: {} ({} move{} we do not make), first {} {}",
                    Self::theirs_line(t),
                    d.what,
                    d.moves,
                    if d.moves == 1 { "" } else { "s" },
                    t.kind.name(),
                    self.point(t.to)
                );
            }
            (None, None) => {}
        }
    }

    /// The first divergence as the text report describes it (`None` when
    /// the toolpaths agree).
    #[must_use]
    pub fn first_divergence(&self) -> Option<String> {
        let d = self.divergences.first()?;
        let mut out = String::new();
        self.describe(d, &mut out);
        Some(out.trim_end().to_owned())
    }

    /// The text report.
    pub fn text(&self) -> String {
        let mut out = String::new();
        if self.agree() {
            let _ = writeln!(
                out,
                "AGREE: {} moves of ours, {} of the trace, within {} increment{}",
                self.ours_moves,
                self.theirs_moves,
                self.tolerance,
                if self.tolerance == 1 { "" } else { "s" }
            );
            return out;
        }
        let _ = writeln!(
            out,
            "DIFFER: {} divergence{} (tolerance {} increments; {} moves of ours, {} of the trace)",
            self.total,
            if self.total == 1 { "" } else { "s" },
            self.tolerance,
            self.ours_moves,
            self.theirs_moves
        );
        let _ = writeln!(out, "\nfirst divergence:");
        if let Some(d) = self.divergences.first() {
            self.describe(d, &mut out);
        }
        if self.total > 1 {
            let _ = writeln!(out, "\nall divergences:");
            for d in &self.divergences {
                self.describe(d, &mut out);
            }
        }
        if self.total > self.divergences.len() {
            let _ = writeln!(
                out,
                "\n... and {} more divergences, not listed (a report lists the first {MAX_LISTED})",
                self.total - self.divergences.len()
            );
        }
        out
    }

    fn step_json(&self, s: &Step) -> Value {
        // An axis not known yet (R-CHECKPARTIAL) is null.
        let axis = |v: i64| if v == super::UNKNOWN { Value::Null } else { json!(fixed(v, self.units)) };
        let mut v = json!({
            "motion": s.kind.name(),
            "x": axis(s.to.x),
            "z": axis(s.to.z),
        });
        if let Some(c) = s.centre {
            v["centre"] = json!({"x": fixed(c.x, self.units), "z": fixed(c.z, self.units)});
        }
        if let Some(l) = s.lead {
            v["lead"] = json!(crate::format::lead_word(l));
        }
        if s.kind == Kind::Thread {
            v["sync"] = json!(s.sync);
            v["start_angle_millidegrees"] = json!({"num": s.angle.num, "den": s.angle.den});
        }
        match s.context {
            Context::G76 { code, line, pass, role } => {
                v["cycle"] = json!({"code": code, "line": line});
                v["pass"] = json!({
                    "kind": kind_name(pass.kind), "number": pass.number, "start": pass.start,
                    "depth": fixed(pass.depth, self.units), "cut": fixed(pass.cut, self.units),
                });
                v["point"] = json!(point_name(s.context, s.kind));
                v["role"] = json!(crate::format::role_name(role));
            }
            Context::G75 { line, role } => {
                v["cycle"] = json!({"code": "G75.1", "line": line});
                v["point"] = json!(point_name(s.context, s.kind));
                v["role"] = json!(crate::format::role_name(role));
                if let Some(p) = crate::format::plunge_of(role) {
                    v["plunge"] = json!({"layer": p.layer, "number": p.number});
                }
            }
            Context::G92 { line, start, role } => {
                v["cycle"] = json!({"code": "G92", "line": line});
                v["start"] = json!(start);
                v["point"] = json!(point_name(s.context, s.kind));
                v["role"] = json!(crate::format::role_name(role));
            }
            Context::LinuxCnc { line, pass, role } => {
                v["cycle"] = json!({"code": "G76", "line": line});
                v["pass"] = json!({
                    "kind": kind_name(pass.kind), "number": pass.number,
                    "depth": fixed(pass.depth, self.units), "cut": fixed(pass.cut, self.units),
                });
                v["point"] = json!(point_name(s.context, s.kind));
                v["role"] = json!(crate::format::role_name(role));
            }
            Context::G32 { code, line, role } => {
                v["cycle"] = json!({"code": code, "line": line});
                v["point"] = json!(point_name(s.context, s.kind));
                v["role"] = json!(crate::format::role_name(role));
            }
            Context::Source { line } => v["line"] = json!(line),
        }
        v
    }

    /// The JSON report (schema in the README).
    pub fn json(&self) -> String {
        let divs: Vec<Value> = self
            .divergences
            .iter()
            .map(|d| {
                let mut v = json!({"what": d.what, "moves": d.moves});
                if let Some(o) = &d.ours {
                    v["ours"] = self.step_json(o);
                }
                if let Some(t) = &d.theirs {
                    v["theirs"] = self.step_json(t);
                }
                if let (Some(o), Some(t)) = (&d.ours, &d.theirs) {
                    let (dx, dz) = diff(o.to, t.to);
                    v["difference_increments"] = json!({"x": sat(dx), "z": sat(dz)});
                    if let (Some(oc), Some(tc)) = (o.centre, t.centre) {
                        let (dx, dz) = diff(oc, tc);
                        v["centre_difference_increments"] = json!({"x": sat(dx), "z": sat(dz)});
                    }
                }
                v
            })
            .collect();
        let doc = json!({
            "format": "cycleref-check/1",
            "agree": self.agree(),
            "tolerance_increments": self.tolerance,
            "units": {"unit": match self.units.unit { InputUnit::Metric => "mm", InputUnit::Inch => "inch" }, "decimals": self.units.decimals()},
            "moves": {"ours": self.ours_moves, "theirs": self.theirs_moves},
            "divergences": divs,
        });
        let mut doc = doc;
        if self.total > self.divergences.len() {
            doc["unlisted_divergences"] = json!(self.total - self.divergences.len());
        }
        let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
        s.push('\n');
        s
    }
}

/// `q - p` per axis, exactly.
fn diff(p: Point, q: Point) -> (i128, i128) {
    (i128::from(q.x) - i128::from(p.x), i128::from(q.z) - i128::from(p.z))
}

fn sat(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}
