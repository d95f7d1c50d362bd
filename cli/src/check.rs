//! `cycleref check`: compares a vendor's toolpath with ours, pass by pass.
//!
//! Both toolpaths become lists of moves (kind, end point, and for thread
//! moves the lead, the start angle and where synchronisation starts). Ours
//! comes from the program's own motion blocks and the expansion of its
//! cycles, each move annotated with the cycle, pass and point it is in the
//! manual's terms; theirs from the trace, an expanded program or a CSV.
//!
//! What does not matter is ignored: blocks that do not move, number
//! formatting, N numbers and comments (the trace is read as words), and a
//! rapid split into an X move and a Z move (in either order). What matters is
//! compared strictly, within the tolerance: every thread and feed move's end
//! point, lead and start angle, where synchronisation starts, the rapid
//! points, and the order of the passes. The moves are grouped into passes
//! (a run of rapids and the cutting moves after it), and the groups are
//! aligned with an edit distance, so a missing or an extra pass is reported
//! as such instead of shifting every later comparison.

use std::fmt::Write as _;
use std::path::Path;

use cycleref::{InputUnit, Lead, LeadWord, Motion, Move, Pass, PassKind, Point, Role, StartAngle, Units};
use cycleref_spec::lex::{lex, Block};
use cycleref_spec::pipeline::Cycle;
use cycleref_spec::reader::{length_word, q_word, Item};
use cycleref_spec::{Machine, ProgramError};
use serde_json::{json, Value};

use crate::format::{fixed, kind_name};
use crate::Job;

/// How a move moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rapid,
    Feed,
    Thread,
    Arc,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Rapid => "rapid",
            Kind::Feed => "feed",
            Kind::Thread => "thread",
            Kind::Arc => "arc",
        }
    }
}

/// Where one of our moves comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Context {
    /// A motion block of the program itself.
    Source { line: usize },
    /// A G76 move.
    G76 { line: usize, pass: Pass, role: Role },
    /// A G32 move.
    G32 { line: usize, role: Role },
    /// A G75.1 move (line of block 2).
    G75 { line: usize, role: Role },
}

/// One move of either toolpath.
#[derive(Clone, Copy, Debug)]
struct Step {
    kind: Kind,
    to: Point,
    /// Lead of a thread move.
    lead: Option<Lead>,
    /// Start angle where synchronisation starts (thread moves).
    angle: StartAngle,
    /// True where the move starts a synchronised run.
    sync: bool,
    /// Our annotation, or the trace's line.
    context: Context,
}

/// Reads a trace or our own program's motion blocks: modal motion,
/// absolute/incremental words, the modal lead.
struct Tracker<'m> {
    machine: &'m Machine,
    units: Units,
    x: Option<i64>,
    z: Option<i64>,
    motion: Kind,
    lead: Option<Lead>,
    /// The previous move was a thread move (a continuous thread).
    in_thread: bool,
}

impl<'m> Tracker<'m> {
    fn new(machine: &'m Machine, units: Units) -> Tracker<'m> {
        Tracker { machine, units, x: None, z: None, motion: Kind::Rapid, lead: None, in_thread: false }
    }

    /// The move of a block, if it moves.
    fn block(&mut self, b: &Block<'_>) -> Result<Option<Step>, ProgramError> {
        if b.words.is_empty() {
            return Ok(None);
        }
        let mut g50 = false;
        let mut dwell = false;
        for w in b.all('G') {
            match w.number.integer() {
                Some(0) => self.motion = Kind::Rapid,
                Some(1) => self.motion = Kind::Feed,
                Some(2 | 3) => self.motion = Kind::Arc,
                Some(32) => self.motion = Kind::Thread,
                Some(50) => g50 = true,
                Some(4) => dwell = true,
                _ => {}
            }
        }
        for letter in ['F', 'I'] {
            if let Some(w) = b.get(letter)? {
                // I is an arc centre outside G32; F is shared with the feed.
                if letter == 'F' || self.motion == Kind::Thread {
                    let frac = w.number.frac_digits().unwrap_or_default();
                    let frac = frac.trim_end_matches('0');
                    let digits = format!("{}{frac}", w.number.int_digits());
                    let mantissa = digits.trim_start_matches('0').parse().unwrap_or(0);
                    let word = if letter == 'F' { LeadWord::F } else { LeadWord::I };
                    self.lead = Some(Lead { word, mantissa, scale: u32::try_from(frac.len()).unwrap_or(0) });
                }
            }
        }
        let coord = |abs: char, inc: char, cur: Option<i64>| -> Result<Option<i64>, ProgramError> {
            if let Some(w) = b.get(abs)? {
                return Ok(Some(length_word(self.machine, self.units, b, w)?));
            }
            if let Some(w) = b.get(inc)? {
                let d = length_word(self.machine, self.units, b, w)?;
                return Ok(cur.map(|c| c + d));
            }
            Ok(cur)
        };
        let moved = ['X', 'Z', 'U', 'W'].iter().any(|&c| b.has(c));
        if dwell || !moved {
            if b.words.iter().any(|w| w.letter != 'F' && w.letter != 'G') {
                self.in_thread = false;
            }
            return Ok(None);
        }
        let x = coord('X', 'U', self.x)?;
        let z = coord('Z', 'W', self.z)?;
        if g50 {
            (self.x, self.z) = (x, z);
            return Ok(None);
        }
        let from = (self.x, self.z);
        (self.x, self.z) = (x, z);
        let (Some(x), Some(z)) = (x, z) else {
            return Ok(None);
        };
        let to = Point::new(x, z);
        if from == (Some(x), Some(z)) {
            return Ok(None);
        }
        let kind = self.motion;
        let sync = kind == Kind::Thread && !self.in_thread;
        let angle = match (kind, b.get('Q')?) {
            (Kind::Thread, Some(w)) if sync => q_word(self.machine, self.units, b, w)?,
            _ => StartAngle::ZERO,
        };
        self.in_thread = kind == Kind::Thread;
        let lead = if kind == Kind::Thread { self.lead } else { None };
        Ok(Some(Step { kind, to, lead, angle, sync, context: Context::Source { line: b.line } }))
    }

    /// One of our expanded moves: the tracker follows it.
    fn inject(&mut self, m: &Move, context: Context) -> Step {
        self.x = Some(m.to.x);
        self.z = Some(m.to.z);
        let (kind, lead, angle, sync) = match m.motion {
            Motion::Rapid => (Kind::Rapid, None, StartAngle::ZERO, false),
            Motion::Feed => (Kind::Feed, None, StartAngle::ZERO, false),
            Motion::Thread { lead, start_angle, sync } => {
                (Kind::Thread, Some(lead), if sync { start_angle } else { StartAngle::ZERO }, sync)
            }
            Motion::Arc { .. } => (Kind::Arc, None, StartAngle::ZERO, false),
        };
        self.motion = kind;
        self.in_thread = kind == Kind::Thread;
        if let Some(l) = lead {
            self.lead = Some(l);
        }
        Step { kind, to: m.to, lead, angle, sync, context }
    }
}

/// Our toolpath: the program's motion blocks and its expanded cycles.
fn ours(job: &Job, machine: &Machine) -> Result<Vec<Step>, String> {
    let program = job.program()?;
    let mut t = Tracker::new(machine, program.units);
    let mut out = Vec::new();
    for item in &program.items {
        match item {
            Item::Source(b) => {
                if let Some(s) = t.block(b).map_err(|e| format!("{}: {e}", job.name))? {
                    out.push(s);
                }
            }
            Item::G76Params(_) => {}
            Item::G76(call) => {
                let line = call.block.line;
                for m in job.expand(Cycle::G76(call))? {
                    let pass = m.pass.unwrap_or(Pass {
                        kind: PassKind::Rough,
                        number: 0,
                        start: 0,
                        depth: 0,
                        cut: 0,
                        flank: cycleref::Flank::Right,
                    });
                    out.push(t.inject(&m, Context::G76 { line, pass, role: m.role }));
                }
                // G76 is one-shot: the motion mode before it is in force again.
                t.motion = match call.restore.motion {
                    Some("G01") => Kind::Feed,
                    Some("G02" | "G03") => Kind::Arc,
                    Some("G32") => Kind::Thread,
                    _ => Kind::Rapid,
                };
            }
            Item::G32(call) => {
                let line = call.block.line;
                for m in job.expand(Cycle::G32(call))? {
                    out.push(t.inject(&m, Context::G32 { line, role: m.role }));
                }
            }
            Item::G75Params(_) => {}
            Item::G75(call) => {
                let line = call.block.line;
                for m in job.expand(Cycle::G75(call))? {
                    out.push(t.inject(&m, Context::G75 { line, role: m.role }));
                }
                t.motion = match call.restore.motion {
                    Some("G01") => Kind::Feed,
                    Some("G02" | "G03") => Kind::Arc,
                    Some("G32") => Kind::Thread,
                    _ => Kind::Rapid,
                };
            }
        }
    }
    Ok(out)
}

/// The vendor's toolpath from an expanded program.
fn theirs_nc(text: &str, machine: &Machine, units: Units) -> Result<Vec<Step>, String> {
    let blocks = lex(text).map_err(|e| e.to_string())?;
    let mut t = Tracker::new(machine, units);
    let mut out = Vec::new();
    for b in &blocks {
        for w in &b.words {
            if w.letter == 'G'
                && !matches!(
                    w.number.integer(),
                    Some(0..=4 | 18 | 20 | 21 | 32 | 40 | 50 | 54..=59 | 96..=99)
                )
            {
                return Err(format!(
                    "line {}: `{}`: a trace holds plain G00/G01/G02/G03/G32 blocks, not canned cycles",
                    b.line,
                    w.text()
                ));
            }
            let g32_here = b.all('G').any(|g| g.number.integer() == Some(32));
            if (w.letter == 'J' || w.letter == 'K') && (t.motion == Kind::Thread || g32_here) {
                return Err(format!(
                    "line {}: `{}`: a trace holds plain moves; write the run-out as its own block",
                    b.line,
                    w.text()
                ));
            }
        }
        if let Some(s) = t.block(b).map_err(|e| e.to_string())? {
            out.push(s);
        }
    }
    Ok(out)
}

/// The vendor's toolpath from a CSV with a header `motion,x,z[,lead][,q]`.
fn theirs_csv(text: &str, units: Units) -> Result<Vec<Step>, String> {
    let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty());
    let Some((_, header)) = lines.next() else {
        return Err("the CSV trace is empty".into());
    };
    let cols: Vec<String> = header.split(',').map(|c| c.trim().to_ascii_lowercase()).collect();
    let col = |name: &str| cols.iter().position(|c| c == name);
    let (Some(cm), Some(cx), Some(cz)) = (col("motion"), col("x"), col("z")) else {
        return Err("the CSV header must name the columns motion, x and z (lead and q are optional)".into());
    };
    let (cl, cq) = (col("lead"), col("q"));
    let mut out = Vec::new();
    let mut at: Option<Point> = None;
    let mut in_thread = false;
    for (i, line) in lines {
        let n = i + 1;
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let get = |c: usize| f.get(c).copied().unwrap_or("");
        let kind = match get(cm).to_ascii_lowercase().as_str() {
            "rapid" | "g00" | "g0" => Kind::Rapid,
            "feed" | "g01" | "g1" => Kind::Feed,
            "thread" | "g32" => Kind::Thread,
            "arc" | "g02" | "g03" | "g2" | "g3" => Kind::Arc,
            other => {
                return Err(format!("CSV line {n}: unknown motion `{other}` (rapid, feed, thread, arc)"))
            }
        };
        let length = |s: &str, what: &str| -> Result<i64, String> {
            let d = rust_decimal::Decimal::from_str_exact(s)
                .map_err(|_| format!("CSV line {n}: {what} `{s}` is not a decimal"))?;
            let v = d
                .checked_mul(rust_decimal::Decimal::from(units.per_unit()))
                .ok_or_else(|| format!("CSV line {n}: {what} `{s}` is out of range"))?;
            if !v.fract().is_zero() {
                return Err(format!("CSV line {n}: {what} `{s}` is not a whole number of increments"));
            }
            i64::try_from(v.trunc()).map_err(|_| format!("CSV line {n}: {what} `{s}` is out of range"))
        };
        let to = Point::new(length(get(cx), "x")?, length(get(cz), "z")?);
        let lead = match cl.map(get).filter(|s| !s.is_empty()) {
            Some(s) => Some(
                parse_lead(s).ok_or_else(|| format!("CSV line {n}: lead `{s}` (write F6.0, I20 or 6.0)"))?,
            ),
            None => None,
        };
        let angle = match cq.map(get).filter(|s| !s.is_empty()) {
            Some(s) => {
                let d = rust_decimal::Decimal::from_str_exact(s).map_err(|_| {
                    format!("CSV line {n}: q `{s}` is not a decimal (thousandths of a degree)")
                })?;
                let tenths = d
                    .checked_mul(rust_decimal::Decimal::from(10))
                    .ok_or_else(|| format!("CSV line {n}: q `{s}` out of range"))?;
                if !tenths.fract().is_zero() || d.is_sign_negative() {
                    return Err(format!(
                        "CSV line {n}: q `{s}` must be a multiple of 0.1 thousandth of a degree"
                    ));
                }
                let t = u32::try_from(tenths.trunc())
                    .map_err(|_| format!("CSV line {n}: q `{s}` out of range"))?;
                if t % 10 == 0 {
                    StartAngle::from_millidegrees(u64::from(t / 10))
                } else {
                    StartAngle { num: t, den: 10 }
                }
            }
            None => StartAngle::ZERO,
        };
        if at == Some(to) {
            continue;
        }
        at = Some(to);
        let sync = kind == Kind::Thread && !in_thread;
        in_thread = kind == Kind::Thread;
        let angle = if sync { angle } else { StartAngle::ZERO };
        out.push(Step { kind, to, lead, angle, sync, context: Context::Source { line: n } });
    }
    Ok(out)
}

fn parse_lead(s: &str) -> Option<Lead> {
    let (word, v) = match s.chars().next()? {
        'F' | 'f' => (LeadWord::F, &s[1..]),
        'I' | 'i' => (LeadWord::I, &s[1..]),
        _ => (LeadWord::F, s),
    };
    let (int, frac) = v.split_once('.').unwrap_or((v, ""));
    let frac = frac.trim_end_matches('0');
    if !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit()) || int.is_empty() && frac.is_empty() {
        return None;
    }
    let mantissa = format!("{int}{frac}").trim_start_matches('0').parse().unwrap_or(0);
    Some(Lead { word, mantissa, scale: u32::try_from(frac.len()).ok()? })
}

/// True when two leads are the same rate (F6 and F6.000; an F and an I of
/// the same value).
fn same_lead(a: Option<Lead>, b: Option<Lead>, units: Units) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => {
            let (ra, rb) = (a.increments_per_rev(units), b.increments_per_rev(units));
            ra.num.checked_mul(rb.den) == rb.num.checked_mul(ra.den)
        }
        (None, None) => true,
        _ => false,
    }
}

/// A pass-sized piece of a toolpath: a run of rapids (possibly empty) and
/// the cutting moves after it.
#[derive(Clone, Debug)]
struct Group {
    rapids: Vec<Step>,
    cuts: Vec<Step>,
}

fn groups(steps: &[Step]) -> Vec<Group> {
    let mut out: Vec<Group> = Vec::new();
    for s in steps {
        let new = match out.last() {
            None => true,
            Some(g) => s.kind == Kind::Rapid && !g.cuts.is_empty(),
        };
        if new {
            out.push(Group { rapids: Vec::new(), cuts: Vec::new() });
        }
        if let Some(g) = out.last_mut() {
            if s.kind == Kind::Rapid {
                g.rapids.push(*s);
            } else {
                g.cuts.push(*s);
            }
        }
    }
    out
}

/// One difference between the toolpaths.
#[derive(Clone, Debug)]
struct Divergence {
    /// What differs.
    what: &'static str,
    /// Our move (None for an extra move in the trace).
    ours: Option<Step>,
    /// Their move (None for a missing one).
    theirs: Option<Step>,
    /// For a missing or extra pass: how many moves.
    moves: usize,
}

/// Compares a group of ours with a group of theirs; the differences.
fn compare(a: &Group, b: &Group, tol: i64, units: Units) -> Vec<Divergence> {
    let mut out = Vec::new();
    let close = |p: Point, q: Point| (p.x - q.x).abs() <= tol && (p.z - q.z).abs() <= tol;
    // Rapids: their points must be ours, each of ours possibly reached
    // through one corner of an X-then-Z or Z-then-X split.
    let mut j = 0;
    let mut prev_ours: Option<Point> = None;
    let mut prev_theirs: Option<Point> = None;
    for r in &a.rapids {
        match b.rapids.get(j) {
            Some(t) if close(t.to, r.to) => j += 1,
            Some(t) => {
                let corner = match (prev_ours, prev_theirs) {
                    (Some(p), Some(_)) => {
                        close(t.to, Point::new(r.to.x, p.z)) || close(t.to, Point::new(p.x, r.to.z))
                    }
                    _ => false,
                };
                if corner && b.rapids.get(j + 1).is_some_and(|u| close(u.to, r.to)) {
                    j += 2;
                } else {
                    out.push(Divergence { what: "rapid point", ours: Some(*r), theirs: Some(*t), moves: 1 });
                    j += 1;
                }
            }
            None => out.push(Divergence { what: "rapid point", ours: Some(*r), theirs: None, moves: 1 }),
        }
        prev_ours = Some(r.to);
        prev_theirs = b.rapids.get(j.saturating_sub(1)).map(|t| t.to);
    }
    for t in b.rapids.iter().skip(j) {
        out.push(Divergence { what: "extra rapid", ours: None, theirs: Some(*t), moves: 1 });
    }
    for (i, c) in a.cuts.iter().enumerate() {
        let Some(t) = b.cuts.get(i) else {
            out.push(Divergence { what: "missing move", ours: Some(*c), theirs: None, moves: 1 });
            continue;
        };
        if c.kind != t.kind {
            out.push(Divergence { what: "kind of move", ours: Some(*c), theirs: Some(*t), moves: 1 });
        } else if !close(c.to, t.to) {
            out.push(Divergence { what: "end point", ours: Some(*c), theirs: Some(*t), moves: 1 });
        }
        if c.kind == Kind::Thread && t.kind == Kind::Thread {
            if !same_lead(c.lead, t.lead, units) {
                out.push(Divergence { what: "lead", ours: Some(*c), theirs: Some(*t), moves: 1 });
            }
            if c.sync != t.sync {
                out.push(Divergence { what: "synchronisation", ours: Some(*c), theirs: Some(*t), moves: 1 });
            } else if c.sync && c.angle != t.angle {
                out.push(Divergence { what: "start angle", ours: Some(*c), theirs: Some(*t), moves: 1 });
            }
        }
    }
    for t in b.cuts.iter().skip(a.cuts.len()) {
        out.push(Divergence { what: "extra move", ours: None, theirs: Some(*t), moves: 1 });
    }
    out
}

/// The result of a comparison.
pub struct Report {
    units: Units,
    tolerance: u64,
    ours_moves: usize,
    theirs_moves: usize,
    divergences: Vec<Divergence>,
}

/// The trace at `trace` as points to draw over our toolpath.
pub fn overlay(job: &Job, trace: &Path) -> Result<crate::plot::Overlay, String> {
    let steps = read_trace(job, trace)?;
    Ok(crate::plot::Overlay {
        name: trace.display().to_string(),
        points: steps.iter().map(|s| s.to).collect(),
    })
}

fn read_trace(job: &Job, trace: &Path) -> Result<Vec<Step>, String> {
    let text = std::fs::read_to_string(trace).map_err(|e| format!("{}: {e}", trace.display()))?;
    let units = job.validate()?.units;
    let is_csv = trace.extension().is_some_and(|e| e.eq_ignore_ascii_case("csv"));
    if is_csv { theirs_csv(&text, units) } else { theirs_nc(&text, &job.machine, units) }
        .map_err(|e| format!("{}: {e}", trace.display()))
}

/// Runs the comparison of `job`'s program with the trace at `trace`.
pub fn run(job: &Job, trace: &Path, tolerance: u64) -> Result<Report, String> {
    let units = job.validate()?.units;
    let ours = ours(job, &job.machine)?;
    let theirs = read_trace(job, trace)?;
    let tol = i64::try_from(tolerance).unwrap_or(i64::MAX);
    let (ga, gb) = (groups(&ours), groups(&theirs));
    let divergences = align(&ga, &gb, tol, units);
    Ok(Report { units, tolerance, ours_moves: ours.len(), theirs_moves: theirs.len(), divergences })
}

/// Aligns the groups by edit distance (a match costs 0, a substitution 1,
/// a missing or extra group 1) and lists the differences in our order.
fn align(a: &[Group], b: &[Group], tol: i64, units: Units) -> Vec<Divergence> {
    let (n, m) = (a.len(), b.len());
    // Beyond this size a quadratic table is too big: compare in order.
    if n.saturating_mul(m) > 25_000_000 {
        let mut out = Vec::new();
        for i in 0..n.max(m) {
            match (a.get(i), b.get(i)) {
                (Some(x), Some(y)) => out.extend(compare(x, y, tol, units)),
                (Some(x), None) => out.push(missing(x)),
                (None, Some(y)) => out.push(extra(y)),
                (None, None) => {}
            }
        }
        return out;
    }
    let equal: Vec<Vec<bool>> =
        a.iter().map(|x| b.iter().map(|y| compare(x, y, tol, units).is_empty()).collect()).collect();
    let mut cost = vec![vec![0_u32; m + 1]; n + 1];
    for (i, row) in cost.iter_mut().enumerate() {
        row[0] = u32::try_from(i).unwrap_or(u32::MAX);
    }
    for (j, c) in cost[0].iter_mut().enumerate() {
        *c = u32::try_from(j).unwrap_or(u32::MAX);
    }
    for i in 1..=n {
        for j in 1..=m {
            let sub = cost[i - 1][j - 1] + u32::from(!equal[i - 1][j - 1]);
            cost[i][j] = sub.min(cost[i - 1][j] + 1).min(cost[i][j - 1] + 1);
        }
    }
    // Walk back.
    let (mut i, mut j) = (n, m);
    let mut ops = Vec::new();
    // Walking back, a missing or extra group is preferred over a match of
    // equal cost: when passes repeat (finishing passes), the one reported
    // missing is the last, where a trace that stops early stops.
    while i > 0 || j > 0 {
        if i > 0 && cost[i][j] == cost[i - 1][j] + 1 {
            ops.push((Some(i - 1), None));
            i -= 1;
        } else if i > 0 && j > 0 && cost[i][j] == cost[i - 1][j - 1] + u32::from(!equal[i - 1][j - 1]) {
            ops.push((Some(i - 1), Some(j - 1)));
            i -= 1;
            j -= 1;
        } else {
            ops.push((None, Some(j - 1)));
            j -= 1;
        }
    }
    ops.reverse();
    let mut out = Vec::new();
    for op in ops {
        match op {
            (Some(x), Some(y)) => out.extend(compare(&a[x], &b[y], tol, units)),
            (Some(x), None) => out.push(missing(&a[x])),
            (None, Some(y)) => out.push(extra(&b[y])),
            (None, None) => {}
        }
    }
    out
}

fn first_step(g: &Group) -> Option<Step> {
    g.cuts.first().or(g.rapids.last()).copied()
}

fn missing(g: &Group) -> Divergence {
    Divergence {
        what: "missing pass",
        ours: first_step(g),
        theirs: None,
        moves: g.rapids.len() + g.cuts.len(),
    }
}

fn extra(g: &Group) -> Divergence {
    Divergence { what: "extra pass", ours: None, theirs: first_step(g), moves: g.rapids.len() + g.cuts.len() }
}

/// The point a move ends at, in the manual's terms.
fn point_name(c: Context, kind: Kind) -> &'static str {
    match c {
        Context::G76 { role, .. } | Context::G32 { role, .. } | Context::G75 { role, .. } => match role {
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

impl Report {
    /// True when the toolpaths agree within the tolerance.
    pub fn agree(&self) -> bool {
        self.divergences.is_empty()
    }

    fn point(&self, p: Point) -> String {
        format!("X{} Z{}", fixed(p.x, self.units), fixed(p.z, self.units))
    }

    fn where_ours(&self, s: &Step) -> String {
        match s.context {
            Context::G76 { line, pass, .. } => format!(
                "G76 at line {line}, {} pass {} (start {}, depth {}, cut {})",
                kind_name(pass.kind),
                pass.number,
                pass.start,
                fixed(pass.depth, self.units),
                fixed(pass.cut, self.units)
            ),
            Context::G32 { line, .. } => format!("G32 at line {line}"),
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
            Context::G76 { line, .. } | Context::G32 { line, .. } | Context::G75 { line, .. } => line,
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
                    _ => {
                        let _ = writeln!(out, "  ours   {} {}", o.kind.name(), self.point(o.to));
                        let _ = writeln!(
                            out,
                            "  theirs {} {} (trace line {})",
                            t.kind.name(),
                            self.point(t.to),
                            Self::theirs_line(t)
                        );
                        let _ = writeln!(
                            out,
                            "  difference: X {} Z {} increments",
                            t.to.x - o.to.x,
                            t.to.z - o.to.z
                        );
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
            self.divergences.len(),
            if self.divergences.len() == 1 { "" } else { "s" },
            self.tolerance,
            self.ours_moves,
            self.theirs_moves
        );
        let _ = writeln!(out, "\nfirst divergence:");
        if let Some(d) = self.divergences.first() {
            self.describe(d, &mut out);
        }
        if self.divergences.len() > 1 {
            let _ = writeln!(out, "\nall divergences:");
            for d in &self.divergences {
                self.describe(d, &mut out);
            }
        }
        out
    }

    fn step_json(&self, s: &Step) -> Value {
        let mut v = json!({
            "motion": s.kind.name(),
            "x": fixed(s.to.x, self.units),
            "z": fixed(s.to.z, self.units),
        });
        if let Some(l) = s.lead {
            v["lead"] = json!(crate::format::lead_word(l));
        }
        if s.kind == Kind::Thread {
            v["sync"] = json!(s.sync);
            v["start_angle_millidegrees"] = json!({"num": s.angle.num, "den": s.angle.den});
        }
        match s.context {
            Context::G76 { line, pass, role } => {
                v["cycle"] = json!({"code": "G76", "line": line});
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
            Context::G32 { line, role } => {
                v["cycle"] = json!({"code": "G32", "line": line});
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
                    v["difference_increments"] = json!({"x": t.to.x - o.to.x, "z": t.to.z - o.to.z});
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
        let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
        s.push('\n');
        s
    }
}
