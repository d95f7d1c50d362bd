//! The result of a comparison: the divergences counted (the first
//! `MAX_LISTED` kept) and written as text or JSON, or as the marks
//! `plot --trace` draws, each of our moves named in the manual's terms.

use std::fmt::Write as _;

use cycleref::{Lead, Pass, PassKind, Point, Role, Units};
use cycleref_spec::cycles::Annotations;

use super::{Context, Divergence, Kind, Step};
use crate::format::{fixed, kind_name, plunge_of, role_name, Fixed, LeadText};
use crate::json::{ser, AngleJson, PassJson, PlungeJson, PointJson, UnitsJson};

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

/// The pass a cycle's move that belongs to no pass (the return) is
/// reported with.
const NO_PASS: Pass =
    Pass { kind: PassKind::Rough, number: 0, start: 0, depth: 0, cut: 0, flank: cycleref::Flank::Right };

/// The start of a multi-start single pass a move belongs to (1 when it
/// says none).
fn start_of(pass: Option<Pass>) -> u16 {
    pass.map_or(1, |p| p.start)
}

/// The point a move ends at, in the manual's terms.
fn point_name(c: Context, kind: Kind) -> &'static str {
    match c {
        // LinuxCNC's own names of the moves (threading_pass, R-LCNC-PASS).
        Context::Cycle { annotations: Annotations::LinuxCncPasses, role, .. } => match role {
            Role::Approach => "pass start (\"back\" or \"in\")",
            Role::LeadIn => "entry taper (\"in\", \"angled in\")",
            Role::Cut => "end of \"over\"",
            Role::RunOut => "exit taper end (\"angled out\")",
            Role::Retract => "\"out\"",
            _ => "the block's X Z (end of the cycle)",
        },
        Context::Cycle { role, .. } => match role {
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
    /// The readings in force that differ from the defaults (issue 34),
    /// `(id, value)`.
    readings: Vec<(&'static str, &'static str)>,
}

impl Report {
    pub(super) fn new(units: Units, tolerance: u64, readings: Vec<(&'static str, &'static str)>) -> Report {
        Report {
            units,
            tolerance,
            ours_moves: 0,
            theirs_moves: 0,
            divergences: Vec::new(),
            total: 0,
            readings,
        }
    }

    /// The line naming the non-default readings, `readings: ID=VALUE, …`,
    /// after the verdict; nothing under the defaults.
    fn readings_line(&self, out: &mut String) {
        if !self.readings.is_empty() {
            let list: Vec<String> = self.readings.iter().map(|(id, v)| format!("{id}={v}")).collect();
            let _ = writeln!(out, "readings: {}", list.join(", "));
        }
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
                    Context::Cycle { line, .. } => Some(line),
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
        let (code, line, role, pass, annotations) = match s.context {
            Context::Cycle { code, line, role, pass, annotations } => (code, line, role, pass, annotations),
            Context::Source { line } => return format!("program line {line}"),
        };
        let full = pass.unwrap_or(NO_PASS);
        match annotations {
            Annotations::Passes => format!(
                "{code} at line {line}, {} pass {} (start {}, depth {}, cut {})",
                kind_name(full.kind),
                full.number,
                full.start,
                fixed(full.depth, self.units),
                fixed(full.cut, self.units)
            ),
            Annotations::Roles => format!("{code} at line {line}"),
            Annotations::LinuxCncPasses => format!(
                "{code} (LinuxCNC) at line {line}, {} pass {} (depth {}, cut {})",
                if full.kind == PassKind::Rough { "rough" } else { "full-depth" },
                full.number,
                fixed(full.depth, self.units),
                fixed(full.cut, self.units)
            ),
            Annotations::Starts => format!("{code} at line {line}, start {}", start_of(pass)),
            Annotations::Plunges => match plunge_of(role) {
                Some(p) => format!("{code} at line {line}, layer {} plunge {}", p.layer, p.number),
                None => format!("{code} at line {line}, {}", role_name(role)),
            },
        }
    }

    fn theirs_line(s: &Step) -> usize {
        match s.context {
            Context::Source { line } | Context::Cycle { line, .. } => line,
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
            self.readings_line(&mut out);
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
        self.readings_line(&mut out);
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

    fn step_json(&self, s: &Step) -> StepJson {
        let u = self.units;
        // An axis not known yet (R-CHECKPARTIAL) is null.
        let axis = |v: i64| (v != super::UNKNOWN).then(|| Fixed::new(v, u));
        let thread = s.kind == Kind::Thread;
        let mut step = StepJson {
            motion: s.kind.name(),
            x: axis(s.to.x),
            z: axis(s.to.z),
            centre: s.centre.map(|c| PointJson::new(c, u)),
            lead: s.lead.map(LeadText),
            sync: thread.then_some(s.sync),
            start_angle_millidegrees: thread.then_some(AngleJson { num: s.angle.num, den: s.angle.den }),
            cycle: None,
            pass: None,
            start: None,
            point: Some(point_name(s.context, s.kind)),
            role: None,
            plunge: None,
            line: None,
        };
        let (code, line, role) = match s.context {
            Context::Cycle { code, line, role, pass, annotations } => {
                match annotations {
                    Annotations::Passes => step.pass = Some(PassJson::new(pass.unwrap_or(NO_PASS), u, true)),
                    // One start: the pass has none.
                    Annotations::LinuxCncPasses => {
                        step.pass = Some(PassJson::new(pass.unwrap_or(NO_PASS), u, false));
                    }
                    Annotations::Starts => step.start = Some(start_of(pass)),
                    Annotations::Plunges => {
                        step.plunge =
                            plunge_of(role).map(|p| PlungeJson { layer: p.layer, number: Some(p.number) });
                    }
                    Annotations::Roles => {}
                }
                (code, line, role)
            }
            Context::Source { line } => {
                step.point = None;
                step.line = Some(line);
                return step;
            }
        };
        step.cycle = Some(CycleRefJson { code, line });
        step.role = Some(role_name(role));
        step
    }

    fn divergence_json(&self, d: &Divergence) -> DivergenceJson {
        let both = d.ours.zip(d.theirs);
        let increments = |(dx, dz): (i128, i128)| IncrementsJson { x: sat(dx), z: sat(dz) };
        DivergenceJson {
            what: d.what,
            moves: d.moves,
            ours: d.ours.as_ref().map(|o| self.step_json(o)),
            theirs: d.theirs.as_ref().map(|t| self.step_json(t)),
            difference_increments: both.map(|(o, t)| increments(diff(o.to, t.to))),
            centre_difference_increments: both
                .and_then(|(o, t)| o.centre.zip(t.centre))
                .map(|(oc, tc)| increments(diff(oc, tc))),
        }
    }

    /// The JSON report (`cycleref-check/1`: the README, and
    /// `docs/schemas/cycleref-check-1.schema.json`).
    pub fn json(&self) -> String {
        let doc = CheckJson {
            format: "cycleref-check/1",
            agree: self.agree(),
            tolerance_increments: self.tolerance,
            units: UnitsJson::new(self.units),
            readings: crate::job::readings_json(&self.readings),
            moves: MoveCountsJson { ours: self.ours_moves, theirs: self.theirs_moves },
            divergences: self.divergences.iter().map(|d| self.divergence_json(d)).collect(),
            unlisted_divergences: (self.total > self.divergences.len())
                .then(|| self.total - self.divergences.len()),
        };
        let mut out = Vec::new();
        // Written into memory, of values that always serialize: no error.
        let _ = ser::to_writer_pretty(&mut out, &doc);
        out.push(b'\n');
        String::from_utf8(out).unwrap_or_default()
    }
}

/// The `cycleref-check/1` document.
#[derive(serde::Serialize)]
struct CheckJson {
    format: &'static str,
    agree: bool,
    tolerance_increments: u64,
    units: UnitsJson,
    /// The readings in force when they differ from the defaults.
    #[serde(skip_serializing_if = "Option::is_none")]
    readings: Option<std::collections::BTreeMap<&'static str, &'static str>>,
    moves: MoveCountsJson,
    divergences: Vec<DivergenceJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    unlisted_divergences: Option<usize>,
}

/// `{"ours": …, "theirs": …}`: the moves of each toolpath.
#[derive(serde::Serialize)]
struct MoveCountsJson {
    ours: usize,
    theirs: usize,
}

/// One divergence: what differs, our step and theirs, and by how much.
#[derive(serde::Serialize)]
struct DivergenceJson {
    what: &'static str,
    moves: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    ours: Option<StepJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    theirs: Option<StepJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    difference_increments: Option<IncrementsJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre_difference_increments: Option<IncrementsJson>,
}

/// `{"x": …, "z": …}` in increments (saturated to 64 bits).
#[derive(serde::Serialize)]
struct IncrementsJson {
    x: i64,
    z: i64,
}

/// `{"code": …, "line": …}`: the cycle a step belongs to.
#[derive(serde::Serialize)]
struct CycleRefJson {
    code: &'static str,
    line: usize,
}

/// One step of either toolpath: the move (as the moves document's, an
/// axis not known yet null), then where it belongs (its cycle, pass,
/// point and role, or its program line).
#[derive(serde::Serialize)]
struct StepJson {
    motion: &'static str,
    x: Option<Fixed>,
    z: Option<Fixed>,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre: Option<PointJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lead: Option<LeadText>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sync: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    start_angle_millidegrees: Option<AngleJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cycle: Option<CycleRefJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pass: Option<PassJson>,
    /// G92: the thread start.
    #[serde(skip_serializing_if = "Option::is_none")]
    start: Option<u16>,
    #[serde(skip_serializing_if = "Option::is_none")]
    point: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    role: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    plunge: Option<PlungeJson>,
    /// A step outside any cycle: its program line.
    #[serde(skip_serializing_if = "Option::is_none")]
    line: Option<usize>,
}

/// `q - p` per axis, exactly.
fn diff(p: Point, q: Point) -> (i128, i128) {
    (i128::from(q.x) - i128::from(p.x), i128::from(q.z) - i128::from(p.z))
}

fn sat(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}
