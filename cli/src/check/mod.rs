//! `cycleref check`: compares a vendor's toolpath with ours, pass by pass.
//!
//! Both toolpaths become lists of moves (kind, start and end point, an
//! arc's centre, and for thread moves the lead, the start angle and where
//! synchronisation starts). Ours comes from the program's own motion blocks
//! and the expansion of its cycles, each move annotated with the cycle,
//! pass and point it is in the manual's terms; theirs from the trace, an
//! expanded program or a CSV.
//!
//! What does not matter is ignored: blocks that do not move, number
//! formatting, N numbers and comments (the trace is read as words), and a
//! rapid split into an X move and a Z move (in either order) whose corner
//! path stays out of the regions the cycles cut (reading R-CHECKSPLIT; a
//! split through them is a "rapid through the work"). What shapes the part
//! is compared strictly: the kind of every move (rapid, feed, arc clockwise,
//! arc counter-clockwise, thread), every end point and arc centre (within
//! the tolerance, the only thing it applies to), every thread move's lead,
//! where synchronisation starts and its start angle (exactly), the rapid
//! points, and the order of the passes. The moves are grouped into passes
//! (a run of rapids and the cutting moves after it), and the groups are
//! aligned with an edit distance, so a missing or an extra pass is reported
//! as such instead of shifting every later comparison; a rapid written for a
//! cutting move (or the reverse) splits (or joins) a pass, and the alignment
//! joins the pieces again to name that move.

use std::fmt::Write as _;
use std::path::Path;

use cycleref::units::MAX_LENGTH;
use cycleref::{
    InputUnit, Lead, LeadWord, Motion, Move, Pass, PassKind, Point, Role, StartAngle, Units, XMode,
};
use std::collections::VecDeque;
use std::io::BufRead;

use cycleref_spec::lex::{Block, Lexer, Word};
use cycleref_spec::pipeline::Cycle;
use cycleref_spec::pipeline::Moves;
use cycleref_spec::profile::Dialect;
use cycleref_spec::reader::{length_word, q_word, Item, MotionMode};
use cycleref_spec::Machine;
use rust_decimal::Decimal;
use serde_json::{json, Value};

use crate::format::{fixed, kind_name};
use crate::job::{Items, Job};

/// How a move moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rapid,
    Feed,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    Thread,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Rapid => "rapid",
            Kind::Feed => "feed",
            Kind::ArcCw => "arc-cw",
            Kind::ArcCcw => "arc-ccw",
            Kind::Thread => "thread",
        }
    }

    fn is_arc(self) -> bool {
        matches!(self, Kind::ArcCw | Kind::ArcCcw)
    }
}

/// Where one of our moves comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Context {
    /// A motion block of the program itself.
    Source { line: usize },
    /// A G76 or G78 move (`code`: which).
    G76 { code: &'static str, line: usize, pass: Pass, role: Role },
    /// A G32 move (or LinuxCNC's G33: `code`).
    G32 { code: &'static str, line: usize, role: Role },
    /// A move of LinuxCNC's G76 (the `linuxcnc` profile).
    LinuxCnc { line: usize, pass: Pass, role: Role },
    /// A G75.1 move (line of block 2).
    G75 { line: usize, role: Role },
    /// A G92 move, of start `start`.
    G92 { line: usize, start: u16, role: Role },
}

/// One move of either toolpath.
#[derive(Clone, Copy, Debug)]
struct Step {
    kind: Kind,
    /// Where the move starts, when known.
    from: Option<Point>,
    to: Point,
    /// The centre of an arc, absolute (X in X-word units).
    centre: Option<Point>,
    /// Lead of a thread move.
    lead: Option<Lead>,
    /// Start angle where synchronisation starts (thread moves).
    angle: StartAngle,
    /// True where the move starts a synchronised run.
    sync: bool,
    /// Our annotation, or the trace's line.
    context: Context,
}

/// G33's K as a lead: > 0, at most six decimals, kept with the fewest
/// decimals (as the reader keeps it).
fn k_lead(b: &Block, w: &Word) -> Result<Lead, String> {
    let bad = || at(b, Some(w), "K of G33 must be > 0 with at most 6 decimals");
    let d = w.number().decimal().ok_or_else(bad)?;
    let scaled = d.checked_mul(Decimal::from(1_000_000)).filter(|s| s.fract().is_zero()).ok_or_else(bad)?;
    let mut mantissa = u64::try_from(scaled).ok().filter(|m| *m > 0).ok_or_else(bad)?;
    let mut scale = 6;
    while scale > 0 && mantissa % 10 == 0 {
        mantissa /= 10;
        scale -= 1;
    }
    Ok(Lead { word: LeadWord::F, mantissa, scale })
}

/// A message naming a block's line and, when there is one, its word.
fn at(b: &Block, w: Option<&Word>, msg: &str) -> String {
    match w {
        Some(w) => format!("line {}, word `{}`: {msg}", b.line, w.text()),
        None => format!("line {}: {msg}", b.line),
    }
}

/// The lead of an F or I word, exactly as written.
fn lead_of(b: &Block, w: &Word, word: LeadWord) -> Result<Lead, String> {
    let bad =
        || at(b, Some(w), "the lead is outside every range table (F up to 9999, I from 0.0001 to 2540)");
    if w.number().negative {
        return Err(bad());
    }
    let n = w.number();
    let frac = n.frac_digits().unwrap_or_default().trim_end_matches('0');
    let mut mantissa: u64 = 0;
    for b in n.int_digits().bytes().chain(frac.bytes()) {
        mantissa =
            mantissa.checked_mul(10).and_then(|m| m.checked_add(u64::from(b - b'0'))).ok_or_else(bad)?;
    }
    let lead = Lead { word, mantissa, scale: u32::try_from(frac.len()).map_err(|_| bad())? };
    if lead.in_range() {
        Ok(lead)
    } else {
        Err(bad())
    }
}

/// The X distance of an I word in X-word increments: I is a radius, and
/// may have one more decimal than the increment when X is a diameter (the
/// `nc` contract, `format::arc_ik`).
fn arc_i(machine: &Machine, units: Units, b: &Block, w: &Word) -> Result<i64, String> {
    let f = machine.x_mode.factor();
    let n = &w.number();
    let bare = machine.profile.bare_length_is_increments && !machine.calculator_input;
    let out = || at(b, Some(w), "the arc centre distance is outside the range table");
    let radius_increments = if !n.has_point() && bare {
        Decimal::from(n.integer().ok_or_else(out)?)
    } else {
        let d = n.decimal().ok_or_else(out)?;
        d.checked_mul(Decimal::from(units.per_unit())).ok_or_else(out)?
    };
    let dx = radius_increments.checked_mul(Decimal::from(f)).ok_or_else(out)?;
    if !dx.fract().is_zero() {
        return Err(at(
            b,
            Some(w),
            "I is not a whole number of X increments (a radius; one more decimal than the increment only when X is a diameter)",
        ));
    }
    let dx = i64::try_from(dx.trunc()).map_err(|_| out())?;
    if dx.unsigned_abs() > 2 * MAX_LENGTH.unsigned_abs() {
        return Err(out());
    }
    Ok(dx)
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
    /// Reading a vendor's trace: every word must be one of a plain move.
    strict: bool,
    /// The linuxcnc profile: G7/G8 switch the X mode, G33 K is a thread,
    /// U and W are no incremental words, and X is held as a diameter
    /// (reading R-CHECKLCNC).
    linuxcnc: bool,
    /// The X mode in force (G7/G8 on the linuxcnc profile).
    x_mode: XMode,
}

impl<'m> Tracker<'m> {
    fn new(machine: &'m Machine, units: Units, strict: bool) -> Tracker<'m> {
        Tracker {
            machine,
            units,
            x: None,
            z: None,
            motion: Kind::Rapid,
            lead: None,
            in_thread: false,
            strict,
            linuxcnc: machine.profile.dialect == Dialect::LinuxCnc,
            x_mode: machine.x_mode,
        }
    }

    /// X as the check holds it: as written on the FANUC-style profiles; a
    /// diameter on the linuxcnc profile, whose programs switch between
    /// G7 and G8 (a radius doubles, exactly).
    fn held_x(&self, x: i64, mode: XMode) -> i64 {
        if self.linuxcnc && mode == XMode::Radius {
            x.saturating_mul(2)
        } else {
            x
        }
    }

    /// G7/G8 on the linuxcnc profile: the position kept in the old mode
    /// converts (an odd diameter has no radius in increments).
    fn switch_x_mode(&mut self, b: &Block, w: &Word, to: XMode) -> Result<(), String> {
        if to == self.x_mode {
            return Ok(());
        }
        if let Some(x) = self.x {
            self.x = Some(match to {
                XMode::Diameter => x.saturating_mul(2),
                XMode::Radius if x % 2 == 0 => x / 2,
                XMode::Radius => {
                    return Err(at(b, Some(w), "G8 after an odd diameter: its radius is no increment"))
                }
            });
        }
        self.x_mode = to;
        Ok(())
    }

    /// A G word of a trace: one of a plain move (`plain`, the profile's list
    /// `moves` naming them), and no change of the input unit.
    fn trace_g(&self, b: &Block, w: &Word, g: Option<i64>, plain: bool, moves: &str) -> Result<bool, String> {
        if !plain {
            return Err(at(
                b,
                Some(w),
                &format!("a trace holds plain {moves} blocks, not canned cycles or other modes"),
            ));
        }
        let unit = match self.units.unit {
            InputUnit::Metric => 21,
            InputUnit::Inch => 20,
        };
        if matches!(g, Some(20 | 21)) && g != Some(unit) {
            return Err(at(b, Some(w), "the trace changes the input unit; write it in the program's unit"));
        }
        Ok(true)
    }

    /// A trace's words that the check does not read are refused: they might
    /// shape the part (reading R-CHECKWORDS).
    fn strict_words(&self, b: &Block, motion: Kind) -> Result<(), String> {
        let dwell = b.all('G').any(|g| g.number().integer() == Some(4));
        for w in &b.words {
            let ok = match w.letter {
                'G' if self.linuxcnc => {
                    // `integer` is None for a code that is not whole.
                    let g = w.number().integer();
                    let plain = matches!(g, Some(0..=4 | 7 | 8 | 18 | 20 | 21 | 33 | 40 | 54..=59 | 61 | 64 | 90 | 94..=97));
                    self.trace_g(b, w, g, plain, "G0/G1/G2/G3/G33")?
                }
                'U' | 'W' | 'Q' | 'I' | 'J' if self.linuxcnc && motion == Kind::Thread => false,
                'U' | 'W' if self.linuxcnc => false,
                'F' if self.linuxcnc && motion == Kind::Thread => {
                    return Err(at(b, Some(w), "F in a G33 block (LinuxCNC: \"F word used with a g33/g33.1\")"))
                }
                'K' if self.linuxcnc && motion == Kind::Thread => true,
                'G' => {
                    let g = w.number().integer();
                    let plain = matches!(g, Some(0..=4 | 18 | 20 | 21 | 32 | 40 | 50 | 54..=59 | 96..=99));
                    self.trace_g(b, w, g, plain, "G00/G01/G02/G03/G32")?
                }
                'M' => {
                    if matches!(w.number().integer(), Some(98 | 99)) {
                        return Err(at(b, Some(w), "a trace holds plain moves, not subprogram calls"));
                    }
                    true
                }
                'X' | 'U' => true,
                'Z' | 'W' | 'F' | 'S' | 'T' => true,
                'P' => dwell,
                'Q' => motion == Kind::Thread,
                'I' => motion.is_arc() || motion == Kind::Thread,
                'J' | 'K' if motion == Kind::Thread => {
                    return Err(at(b, Some(w), "a trace holds plain moves; write the run-out as its own block"))
                }
                'K' => motion.is_arc(),
                'R' if motion.is_arc() => {
                    return Err(at(
                        b,
                        Some(w),
                        "an arc in a trace gives its centre as I and K: the centre R implies is in general not a \
                         point of the increment grid, so it cannot be compared exactly (reading R-CHECKARC)",
                    ))
                }
                _ => false,
            };
            if !ok {
                return Err(at(
                    b,
                    Some(w),
                    &format!("not a word of a plain {} move in a trace", motion.name()),
                ));
            }
        }
        Ok(())
    }

    /// The move of a block, if it moves.
    fn block(&mut self, b: &Block<'_>) -> Result<Option<Step>, String> {
        let pe = |e: cycleref_spec::ProgramError| e.to_string();
        if b.words.is_empty() {
            return Ok(None);
        }
        let mut g50 = false;
        let mut dwell = false;
        for w in b.all('G') {
            match w.number().integer() {
                Some(0) => self.motion = Kind::Rapid,
                Some(1) => self.motion = Kind::Feed,
                Some(2) => self.motion = Kind::ArcCw,
                Some(3) => self.motion = Kind::ArcCcw,
                Some(32) if !self.linuxcnc => self.motion = Kind::Thread,
                Some(33) if self.linuxcnc => self.motion = Kind::Thread,
                Some(7) if self.linuxcnc => self.switch_x_mode(b, w, XMode::Diameter)?,
                Some(8) if self.linuxcnc => self.switch_x_mode(b, w, XMode::Radius)?,
                Some(50) if !self.linuxcnc => g50 = true,
                Some(4) => dwell = true,
                _ => {}
            }
        }
        if self.strict {
            self.strict_words(b, self.motion)?;
        }
        if self.linuxcnc && self.motion == Kind::Thread {
            // G33's K: the distance per revolution along the move; every
            // G33 block gives it (LinuxCNC: "K word missing with g33/g33.1").
            let k = b.get('K').map_err(pe)?.ok_or_else(|| at(b, None, "a G33 block without K"))?;
            self.lead = Some(k_lead(b, k)?);
        }
        for letter in ['F', 'I'] {
            if self.linuxcnc && self.motion == Kind::Thread {
                break;
            }
            if let Some(w) = b.get(letter).map_err(pe)? {
                // I is an arc centre outside G32; F is shared with the feed.
                if letter == 'F' || self.motion == Kind::Thread {
                    let word = if letter == 'F' { LeadWord::F } else { LeadWord::I };
                    match lead_of(b, w, word) {
                        Ok(l) => self.lead = Some(l),
                        Err(e) if self.motion == Kind::Thread => return Err(e),
                        // A feed rate is not a lead; a thread later needs its own F.
                        Err(_) => self.lead = None,
                    }
                }
            }
        }
        let coord = |abs: char, inc: char, cur: Option<i64>| -> Result<Option<i64>, String> {
            if let Some(w) = b.get(abs).map_err(pe)? {
                return Ok(Some(length_word(self.machine, self.units, b, w).map_err(pe)?));
            }
            if let Some(w) = b.get(inc).map_err(pe)? {
                let d = length_word(self.machine, self.units, b, w).map_err(pe)?;
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
        let (u, w) = if self.linuxcnc { ('\0', '\0') } else { ('U', 'W') };
        let x = coord('X', u, self.x)?;
        let z = coord('Z', w, self.z)?;
        if g50 {
            (self.x, self.z) = (x, z);
            return Ok(None);
        }
        let from = (self.x, self.z);
        (self.x, self.z) = (x, z);
        let (Some(x), Some(z)) = (x, z) else {
            return Ok(None);
        };
        if from == (Some(x), Some(z)) {
            return Ok(None);
        }
        let to = Point::new(self.held_x(x, self.x_mode), z);
        let from = match from {
            (Some(fx), Some(fz)) => Some(Point::new(self.held_x(fx, self.x_mode), fz)),
            _ => None,
        };
        let kind = self.motion;
        let centre = if kind.is_arc() { Some(self.centre(b, from)?) } else { None };
        let sync = kind == Kind::Thread && !self.in_thread;
        let angle = match (kind, b.get('Q').map_err(pe)?) {
            (Kind::Thread, Some(w)) if sync && !self.linuxcnc => {
                q_word(self.machine, self.units, b, w).map_err(pe)?
            }
            _ => StartAngle::ZERO,
        };
        self.in_thread = kind == Kind::Thread;
        let lead = if kind == Kind::Thread { self.lead } else { None };
        Ok(Some(Step {
            kind,
            from,
            to,
            centre,
            lead,
            angle,
            sync,
            context: Context::Source { line: b.line },
        }))
    }

    /// An arc's centre from its I and K (an omitted one is 0); R is refused
    /// (reading R-CHECKARC), and an arc without I, K or R is an error.
    fn centre(&self, b: &Block, from: Option<Point>) -> Result<Point, String> {
        let pe = |e: cycleref_spec::ProgramError| e.to_string();
        let g = b.all('G').find(|g| matches!(g.number().integer(), Some(2 | 3)));
        if let Some(r) = b.get('R').map_err(pe)? {
            return Err(at(
                b,
                Some(r),
                "an arc is compared by its centre: give I and K (the centre R implies is in general not a point \
                 of the increment grid, reading R-CHECKARC)",
            ));
        }
        let (i, k) = (b.get('I').map_err(pe)?, b.get('K').map_err(pe)?);
        if i.is_none() && k.is_none() {
            return Err(at(b, g, "an arc without a centre: give I and K (reading R-CHECKARC)"));
        }
        let Some(from) = from else {
            return Err(at(
                b,
                g,
                "an arc whose start point is not known (no earlier block gives both X and Z)",
            ));
        };
        let dx = match i {
            Some(w) => arc_i(self.machine, self.units, b, w)?,
            None => 0,
        };
        let dz = match k {
            Some(w) => length_word(self.machine, self.units, b, w).map_err(pe)?,
            None => 0,
        };
        Ok(Point::new(from.x + dx, from.z + dz))
    }

    /// One of our expanded moves: the tracker follows it.
    fn inject(&mut self, m: &Move, context: Context, x_mode: XMode) -> Step {
        let from = match (self.x, self.z) {
            (Some(x), Some(z)) => Some(Point::new(self.held_x(x, self.x_mode), z)),
            _ => None,
        };
        // The cycle's moves are in the X mode of its block, which is the
        // one in force.
        self.x_mode = x_mode;
        self.x = Some(m.to.x);
        self.z = Some(m.to.z);
        let to = Point::new(self.held_x(m.to.x, x_mode), m.to.z);
        let centre_of = |c: Point| Point::new(self.held_x(c.x, x_mode), c.z);
        let (kind, lead, angle, sync, centre) = match m.motion {
            Motion::Rapid => (Kind::Rapid, None, StartAngle::ZERO, false, None),
            Motion::Feed => (Kind::Feed, None, StartAngle::ZERO, false, None),
            Motion::Thread { lead, start_angle, sync } => {
                (Kind::Thread, Some(lead), if sync { start_angle } else { StartAngle::ZERO }, sync, None)
            }
            Motion::Arc { centre, clockwise } => (
                if clockwise { Kind::ArcCw } else { Kind::ArcCcw },
                None,
                StartAngle::ZERO,
                false,
                Some(centre_of(centre)),
            ),
        };
        self.motion = kind;
        self.in_thread = kind == Kind::Thread;
        if let Some(l) = lead {
            self.lead = Some(l);
        }
        Step { kind, from, to, centre, lead, angle, sync, context }
    }

    /// The motion mode in force again after a one-shot cycle.
    fn restore(&mut self, motion: Option<MotionMode>) {
        self.motion = match motion {
            Some(MotionMode::G01) => Kind::Feed,
            Some(MotionMode::G02) => Kind::ArcCw,
            Some(MotionMode::G03) => Kind::ArcCcw,
            Some(MotionMode::G32) => Kind::Thread,
            // Never restored (every G92 block is expanded); G00 is what the
            // expansion leaves.
            Some(MotionMode::G92) => Kind::Rapid,
            Some(MotionMode::G00) | None => Kind::Rapid,
        };
    }
}

/// An open box `x_lo < x < x_hi`, `z_lo < z < z_hi` holding a region a
/// cycle cuts (reading R-CHECKSPLIT): a rapid must not pass through it.
#[derive(Clone, Copy, Debug)]
struct Region {
    x_lo: i128,
    x_hi: i128,
    z_lo: i128,
    z_hi: i128,
}

impl Region {
    fn spanning(points: &[(i128, i128)]) -> Option<Region> {
        let (&(x0, z0), rest) = points.split_first()?;
        let mut r = Region { x_lo: x0, x_hi: x0, z_lo: z0, z_hi: z0 };
        for &(x, z) in rest {
            r.x_lo = r.x_lo.min(x);
            r.x_hi = r.x_hi.max(x);
            r.z_lo = r.z_lo.min(z);
            r.z_hi = r.z_hi.max(z);
        }
        Some(r)
    }

    /// True when the straight path from `p` to `q` meets the open box. Only
    /// paths along one axis are decided (a split's legs are); a diagonal
    /// gives false.
    fn crossed_by(&self, p: Point, q: Point) -> bool {
        let (px, pz, qx, qz) = (i128::from(p.x), i128::from(p.z), i128::from(q.x), i128::from(q.z));
        if px == qx {
            self.x_lo < px && px < self.x_hi && pz.min(qz) < self.z_hi && pz.max(qz) > self.z_lo
        } else if pz == qz {
            self.z_lo < pz && pz < self.z_hi && px.min(qx) < self.x_hi && px.max(qx) > self.x_lo
        } else {
            false
        }
    }
}

/// The regions a cycle cuts (reading R-CHECKSPLIT).
fn regions_of(job: &Job, cycle: Cycle<'_, '_>) -> Result<Vec<Region>, String> {
    let mut out = Vec::new();
    {
        match cycle {
            Cycle::LinuxCnc(call) => {
                // The thread space (reading R-CHECKLCNC): between the peak
                // line X₀ − σ|I| and the full-depth cut, over the Z the
                // synchronised moves span; X as the check holds it on this
                // profile, a diameter.
                let c = &call.cycle;
                let f = i128::from(if c.x_mode == XMode::Radius { 2 } else { 1 });
                let sigma = i128::from(c.sigma());
                let x0 = i128::from(c.start.x);
                let peak = f * (x0 - sigma * i128::from(c.peak_offset.abs()));
                let root = f * (x0 - sigma * i128::from(c.peak_offset.abs() + c.full_depth));
                let mut prev = c.start;
                let mut zs: Vec<(i128, i128)> = Vec::new();
                for m in job.expand(cycle)? {
                    if matches!(m.motion, Motion::Thread { .. }) {
                        zs.push((peak, i128::from(prev.z)));
                        zs.push((root, i128::from(m.to.z)));
                    }
                    prev = m.to;
                }
                out.extend(Region::spanning(&zs));
            }
            Cycle::G76(call) => {
                let c = &call.cycle;
                let f = i128::from(c.x_mode.factor());
                let (dx, dz) = (i128::from(c.end.x), i128::from(c.end.z));
                let cx = dx + f * i128::from(c.taper);
                let side = if i128::from(c.start.x) >= cx { 1 } else { -1 };
                let crest = side * f * i128::from(c.thread_height);
                // The Z where the cut nearest D starts: the thread runs from
                // there to D (before it the tool is in the air: ours rapids
                // to every pass start).
                let moves: Vec<Move> = job.expand(Cycle::G76(call))?.collect();
                let mut prev = c.start;
                let mut zs: Option<i64> = None;
                for m in &moves {
                    if let Motion::Thread { sync: true, .. } = m.motion {
                        let nearer = zs.is_none_or(|z| (prev.z - c.end.z).abs() < (z - c.end.z).abs());
                        if nearer {
                            zs = Some(prev.z);
                        }
                    }
                    prev = m.to;
                }
                let zs = i128::from(zs.unwrap_or(c.start.z));
                out.extend(Region::spanning(&[(dx, dz), (cx, zs), (dx + crest, dz), (cx + crest, zs)]));
            }
            Cycle::G32(call) => {
                // No thread height: the box the cut itself spans (a taper's).
                let g = &call.g32;
                let moves: Vec<Move> = job.expand(Cycle::G32(call))?.collect();
                if let Some(cut) = moves.iter().find(|m| m.role == Role::Cut) {
                    let s = g.start;
                    out.extend(Region::spanning(&[
                        (i128::from(s.x), i128::from(s.z)),
                        (i128::from(cut.to.x), i128::from(cut.to.z)),
                    ]));
                }
            }
            Cycle::G92(call) => {
                // No thread height either: the thread's crests stand above
                // the cut line, so the box runs from A's short-axis
                // coordinate (open: our approach, retract and return run on
                // its edges) through the cut line into the work, along the
                // thread between A's and C's long-axis coordinates. A face
                // thread (P1) is the same with X and Z exchanged.
                let c = &call.cycle;
                let far = 4 * i128::from(cycleref::units::MAX_LENGTH);
                let (a, e) = (c.start, c.end);
                let (a_short, a_long, c_short, c_long) =
                    if c.face { (a.z, a.x, e.z, e.x) } else { (a.x, a.z, e.x, e.z) };
                let a_short = i128::from(a_short);
                let short = if a_short > i128::from(c_short) { (-far, a_short) } else { (a_short, far) };
                let (la, lc) = (i128::from(a_long), i128::from(c_long));
                let long = (la.min(lc), la.max(lc));
                let (x, z) = if c.face { (long, short) } else { (short, long) };
                out.push(Region { x_lo: x.0, x_hi: x.1, z_lo: z.0, z_hi: z.1 });
            }
            Cycle::G75(call) => {
                let c = &call.cycle;
                let p = cycleref::groove_profile(c)
                    .map_err(|e| format!("{}: line {}, G75.1: {e}", job.name, call.block.line))?;
                let f = i128::from(c.x_mode.factor());
                let mut pts = vec![(i128::from(c.start.x), i128::from(c.start.z))];
                let mut prev = c.start;
                for q in p.finishing() {
                    pts.push((i128::from(q.at.x), i128::from(q.at.z)));
                    if let cycleref::ProfileSegment::Arc { centre, .. } = q.segment {
                        // The round lies in its circle's box; the radius is
                        // at most |dx|/f + |dz| (rounded up).
                        let dx = (i128::from(prev.x) - i128::from(centre.x)).abs();
                        let dz = (i128::from(prev.z) - i128::from(centre.z)).abs();
                        let r = (dx + f - 1) / f + dz;
                        let (ox, oz) = (i128::from(centre.x), i128::from(centre.z));
                        pts.push((ox - f * r, oz - r));
                        pts.push((ox + f * r, oz + r));
                    }
                    prev = q.at;
                }
                out.extend(Region::spanning(&pts));
            }
        }
    }
    Ok(out)
}

/// The pass of a cycle's move that belongs to no pass (the return).
const NO_PASS: Pass =
    Pass { kind: PassKind::Rough, number: 0, start: 0, depth: 0, cut: 0, flank: cycleref::Flank::Right };

/// How many cycles' regions are kept for judging split rapids: the cycle
/// being compared and its neighbours.
const REGION_CYCLES: usize = 3;

/// The cycle whose moves are being taken.
struct Running {
    moves: Moves,
    /// The cycle's G code.
    code: &'static str,
    line: usize,
    /// G76 (annotated with its passes), G32, or G75.1.
    kind: RunningKind,
    /// The X mode of the cycle's moves.
    x_mode: XMode,
    /// For a one-shot cycle (G76, G75.1), the motion mode in force again
    /// after it; `None` for G32, which leaves its own mode.
    restore: Option<Option<MotionMode>>,
}

#[derive(Clone, Copy)]
enum RunningKind {
    G76,
    G32,
    G75,
    G92,
    LinuxCnc,
}

/// Our toolpath, a step at a time: the program's motion blocks and its
/// expanded cycles, each step with the number of the segment it belongs to
/// (a cycle, or the blocks between two cycles).
struct OurSteps<'j> {
    job: &'j Job,
    items: Items<'j>,
    tracker: Tracker<'j>,
    current: Option<Running>,
    segment: u32,
    /// The regions of the latest cycles.
    regions: VecDeque<Vec<Region>>,
}

impl<'j> OurSteps<'j> {
    fn new(job: &'j Job, units: Units) -> Result<OurSteps<'j>, String> {
        Ok(OurSteps {
            job,
            items: job.items()?,
            tracker: Tracker::new(&job.machine, units, false),
            current: None,
            segment: 0,
            regions: VecDeque::new(),
        })
    }

    fn step(&mut self) -> Option<Result<(Step, u32), String>> {
        loop {
            if let Some(run) = &mut self.current {
                if let Some(m) = run.moves.next() {
                    // A move to where the tool is, is no move, in our
                    // toolpath as in a trace (LinuxCNC's G76 ends with a
                    // rapid of no length when X is not programmed).
                    let t = &self.tracker;
                    if t.x_mode == run.x_mode && (t.x, t.z) == (Some(m.to.x), Some(m.to.z)) {
                        continue;
                    }
                    let (line, role) = (run.line, m.role);
                    let context = match run.kind {
                        RunningKind::G76 => {
                            Context::G76 { code: run.code, line, pass: m.pass.unwrap_or(NO_PASS), role }
                        }
                        RunningKind::G32 => Context::G32 { code: run.code, line, role },
                        RunningKind::LinuxCnc => {
                            Context::LinuxCnc { line, pass: m.pass.unwrap_or(NO_PASS), role }
                        }
                        RunningKind::G92 => Context::G92 { line, start: m.pass.map_or(1, |p| p.start), role },
                        RunningKind::G75 => Context::G75 { line, role },
                    };
                    return Some(Ok((self.tracker.inject(&m, context, run.x_mode), self.segment)));
                }
                // G76 and G75.1 are one-shot: the motion mode before them is
                // in force again.
                if let Some(motion) = run.restore {
                    self.tracker.restore(motion);
                }
                self.current = None;
                self.segment += 1;
                continue;
            }
            let (job, tracker, segment) = (self.job, &mut self.tracker, self.segment);
            let (regions, current) = (&mut self.regions, &mut self.current);
            let next = self.items.next_with(|item| -> Result<Option<(Step, u32)>, String> {
                let Some(cycle) = Cycle::of(item) else {
                    let Item::Source(b) = item else { return Ok(None) };
                    return match tracker.block(b) {
                        Ok(step) => Ok(step.map(|s| (s, segment))),
                        Err(e) => Err(format!("{}: {e}", job.name)),
                    };
                };
                let started = regions_of(job, cycle)?;
                let moves = job.expand(cycle)?;
                if regions.len() == REGION_CYCLES {
                    regions.pop_front();
                }
                regions.push_back(started);
                *current = Some(Running {
                    moves,
                    code: cycle.code(),
                    line: cycle.line(),
                    x_mode: match cycle {
                        Cycle::G76(c) => c.cycle.x_mode,
                        Cycle::G32(c) => c.g32.x_mode,
                        Cycle::G75(c) => c.cycle.x_mode,
                        Cycle::G92(c) => c.cycle.x_mode,
                        Cycle::LinuxCnc(c) => c.cycle.x_mode,
                    },
                    kind: match cycle {
                        Cycle::G76(_) => RunningKind::G76,
                        Cycle::G32(_) => RunningKind::G32,
                        Cycle::G75(_) => RunningKind::G75,
                        Cycle::G92(_) => RunningKind::G92,
                        Cycle::LinuxCnc(_) => RunningKind::LinuxCnc,
                    },
                    restore: (!matches!(cycle, Cycle::G32(_))).then(|| cycle.restore().motion),
                });
                Ok(None)
            });
            match next? {
                Ok(Ok(Some(step))) => return Some(Ok(step)),
                Ok(Ok(None)) => {
                    if self.current.is_some() {
                        self.segment += 1;
                    }
                }
                Ok(Err(e)) => return Some(Err(e)),
                Err(e) => return Some(Err(String::from(self.job.read_failure(&e)))),
            }
        }
    }
}

impl Iterator for OurSteps<'_> {
    type Item = Result<(Step, u32), String>;

    fn next(&mut self) -> Option<Self::Item> {
        self.step()
    }
}

/// The error of a trace's line `line` whose byte at offset `at` (from 0)
/// is not UTF-8.
fn not_utf8(line: usize, at: usize) -> String {
    format!("line {line}, byte {}: not UTF-8 text", at + 1)
}

/// One line of a trace read from a stream, checked to be UTF-8 (the
/// line end removed); `None` at the end.
fn trace_line<'b>(
    source: &mut dyn BufRead,
    buf: &'b mut Vec<u8>,
    line: usize,
) -> Option<Result<&'b str, String>> {
    buf.clear();
    match source.read_until(b'\n', buf) {
        Ok(0) => return None,
        Ok(_) => {}
        Err(e) => return Some(Err(format!("line {line}: {e}"))),
    }
    if buf.last() == Some(&b'\n') {
        buf.pop();
    }
    let text = match std::str::from_utf8(buf) {
        Ok(t) => t,
        Err(e) => return Some(Err(not_utf8(line, e.valid_up_to()))),
    };
    // A byte-order mark may start the first line.
    Some(Ok(if line == 1 { text.strip_prefix('\u{feff}').unwrap_or(text) } else { text }))
}

/// The vendor's toolpath from an expanded program, read in pieces of whole
/// lines (as the program is, `job::next_piece`), each checked to be UTF-8
/// at once and lexed a line at a time.
struct NcTrace<'t, 'm> {
    source: Box<dyn BufRead + 't>,
    /// The current piece (`..piece`) and what was read beyond it.
    buf: Vec<u8>,
    piece: usize,
    /// Where the next line starts in the piece.
    at: usize,
    eof: bool,
    /// Where the piece's first byte that is not UTF-8 is, if it has one:
    /// the line that holds it is an error when it is reached (not before:
    /// the lines above it are read as they would be without it).
    bad: Option<usize>,
    line: usize,
    tracker: Tracker<'m>,
    /// The steps of the current line (a line may hold several blocks).
    ready: VecDeque<Step>,
}

impl<'t, 'm> NcTrace<'t, 'm> {
    fn new(source: Box<dyn BufRead + 't>, tracker: Tracker<'m>) -> NcTrace<'t, 'm> {
        NcTrace {
            source,
            buf: Vec::new(),
            piece: 0,
            at: 0,
            eof: false,
            bad: None,
            line: 0,
            tracker,
            ready: VecDeque::new(),
        }
    }

    /// Reads lines until one moves; false at the end.
    fn fill(&mut self) -> Result<bool, String> {
        while self.ready.is_empty() {
            if self.at >= self.piece {
                match crate::job::next_piece(&mut *self.source, &mut self.buf, &mut self.piece, &mut self.eof)
                {
                    Ok(false) => return Ok(false),
                    Ok(true) => {}
                    Err(e) => return Err(format!("line {}: {e}", self.line + 1)),
                }
                self.at = 0;
                let piece = self.buf.get(..self.piece).unwrap_or_default();
                self.bad = std::str::from_utf8(piece).err().map(|e| e.valid_up_to());
            }
            let piece = self.buf.get(..self.piece).unwrap_or_default();
            let rest = piece.get(self.at..).unwrap_or_default();
            let (end, next) = match memchr::memchr(b'\n', rest) {
                Some(i) => (self.at + i, self.at + i + 1),
                None => (piece.len(), piece.len()),
            };
            self.line += 1;
            if let Some(bad) = self.bad.filter(|&b| b < end) {
                // A line end is ASCII: the line's own bytes decide, as
                // `from_utf8` of the line alone would.
                return Err(not_utf8(self.line, bad - self.at));
            }
            let mut text = piece.get(self.at..end).unwrap_or_default();
            self.at = next;
            // A byte-order mark may start the first line.
            if self.line == 1 {
                text = text.strip_prefix("\u{feff}".as_bytes()).unwrap_or(text);
            }
            for b in Lexer::at_line(text, self.line) {
                let b = b.map_err(|e| e.to_string())?;
                if let Some(s) = self.tracker.block(&b)? {
                    self.ready.push_back(s);
                }
            }
        }
        Ok(true)
    }
}

impl Iterator for NcTrace<'_, '_> {
    type Item = Result<(Step, u32), String>;

    fn next(&mut self) -> Option<Self::Item> {
        match self.fill() {
            Ok(true) => self.ready.pop_front().map(|s| Ok((s, 0))),
            Ok(false) => None,
            Err(e) => Some(Err(e)),
        }
    }
}

/// The columns a CSV trace may have.
const CSV_COLUMNS: [&str; 9] = ["motion", "x", "z", "lead", "q", "i", "k", "cx", "cz"];

/// The vendor's toolpath from a CSV with a header naming its columns
/// (`motion`, `x`, `z`; `lead`, `q`; `i`, `k` or `cx`, `cz` for arcs).
struct CsvTrace<'t, 'm> {
    source: Box<dyn BufRead + 't>,
    buf: Vec<u8>,
    line: usize,
    machine: &'m Machine,
    units: Units,
    cols: Vec<String>,
    cm: usize,
    cx: usize,
    cz: usize,
    cl: Option<usize>,
    cq: Option<usize>,
    ci: Option<usize>,
    ck: Option<usize>,
    ccx: Option<usize>,
    ccz: Option<usize>,
    here: Option<Point>,
    in_thread: bool,
}

impl<'t, 'm> CsvTrace<'t, 'm> {
    /// The trace after its header (an empty text has no header and no rows).
    fn new(
        mut source: Box<dyn BufRead + 't>,
        machine: &'m Machine,
        units: Units,
    ) -> Result<CsvTrace<'t, 'm>, String> {
        let mut buf = Vec::new();
        let mut cols = vec!["motion".to_string(), "x".into(), "z".into()];
        let mut h = 0;
        while let Some(l) = trace_line(&mut *source, &mut buf, h + 1) {
            let l = l?;
            if !l.trim().is_empty() {
                cols = Self::columns(h, l)?;
                break;
            }
            h += 1;
        }
        let col = |name: &str| cols.iter().position(|c| c == name);
        let (Some(cm), Some(cx), Some(cz)) = (col("motion"), col("x"), col("z")) else {
            return Err(format!(
                "CSV line {}: the header must name the columns motion, x and z (lead, q, i, k, cx and cz are optional)",
                h + 1
            ));
        };
        let (cl, cq, ci, ck, ccx, ccz) = (col("lead"), col("q"), col("i"), col("k"), col("cx"), col("cz"));
        Ok(CsvTrace {
            source,
            buf,
            line: h + 1,
            machine,
            units,
            cols,
            cm,
            cx,
            cz,
            cl,
            cq,
            ci,
            ck,
            ccx,
            ccz,
            here: None,
            in_thread: false,
        })
    }

    /// The columns the header at line `h` (0-based) names.
    fn columns(h: usize, header: &str) -> Result<Vec<String>, String> {
        let cols: Vec<String> = header.split(',').map(|c| c.trim().to_ascii_lowercase()).collect();
        for (n, c) in cols.iter().enumerate() {
            if !CSV_COLUMNS.contains(&c.as_str()) {
                return Err(format!(
                    "CSV line {}: unknown column `{c}` (the columns are {})",
                    h + 1,
                    CSV_COLUMNS.join(", ")
                ));
            }
            if cols[..n].contains(c) {
                return Err(format!("CSV line {}: the column `{c}` appears twice", h + 1));
            }
        }
        Ok(cols)
    }

    /// The step of CSV line `n` (1-based), if it moves.
    fn row(&mut self, n: usize, line: &str) -> Result<Option<Step>, String> {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() > self.cols.len() {
            return Err(format!("CSV line {n}: {} fields, the header names {}", f.len(), self.cols.len()));
        }
        let get = |c: Option<usize>| c.and_then(|c| f.get(c).copied()).filter(|s| !s.is_empty());
        let motion = get(Some(self.cm)).unwrap_or("");
        let kind = match motion.to_ascii_lowercase().as_str() {
            "rapid" | "g00" | "g0" => Kind::Rapid,
            "feed" | "g01" | "g1" => Kind::Feed,
            "thread" | "g32" => Kind::Thread,
            "arc-cw" | "g02" | "g2" => Kind::ArcCw,
            "arc-ccw" | "g03" | "g3" => Kind::ArcCcw,
            "arc" => {
                return Err(format!(
                    "CSV line {n}: motion `arc` needs a direction: arc-cw (G02) or arc-ccw (G03)"
                ))
            }
            _ => {
                return Err(format!(
                "CSV line {n}: unknown motion `{motion}` (rapid, feed, thread, arc-cw, arc-ccw; or G00, G01, \
                 G32, G02, G03)"
            ))
            }
        };
        let decimal = |s: &str, what: &str| -> Result<Decimal, String> {
            let ok = !s.is_empty()
                && s.trim_start_matches(['-', '+']).chars().all(|c| c.is_ascii_digit() || c == '.')
                && s.trim_start_matches(['-', '+']).chars().any(|c| c.is_ascii_digit());
            let d = if ok { Decimal::from_str_exact(s).ok() } else { None };
            d.ok_or_else(|| format!("CSV line {n}: {what} `{s}` is not a decimal"))
        };
        // A length in increments times `factor`, exact, within the range table.
        let length = |s: Option<&str>, what: &str, factor: i64| -> Result<i64, String> {
            let s = s.ok_or_else(|| format!("CSV line {n}: {what} is missing"))?;
            let out = || format!("CSV line {n}: {what} `{s}` is outside the range table");
            let v = decimal(s, what)?
                .checked_mul(Decimal::from(self.units.per_unit()))
                .and_then(|v| v.checked_mul(Decimal::from(factor)))
                .ok_or_else(out)?;
            if !v.fract().is_zero() {
                return Err(format!("CSV line {n}: {what} `{s}` is not a whole number of increments"));
            }
            let v = i64::try_from(v.trunc()).map_err(|_| out())?;
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() * factor.unsigned_abs() {
                return Err(out());
            }
            Ok(v)
        };
        let to = Point::new(length(get(Some(self.cx)), "x", 1)?, length(get(Some(self.cz)), "z", 1)?);
        let lead = match get(self.cl) {
            Some(s) if kind == Kind::Thread => Some(parse_lead(s).ok_or_else(|| {
                format!("CSV line {n}: lead `{s}` (write F6.0, I20 or 6.0, within the range tables)")
            })?),
            Some(s) => return Err(format!("CSV line {n}: lead `{s}` on a row that is not a thread move")),
            None if kind == Kind::Thread => return Err(format!("CSV line {n}: a thread row needs its lead")),
            None => None,
        };
        let angle = match get(self.cq) {
            Some(s) if kind == Kind::Thread => csv_angle(s, n)?,
            Some(s) => return Err(format!("CSV line {n}: q `{s}` on a row that is not a thread move")),
            None => StartAngle::ZERO,
        };
        let relative = get(self.ci).is_some() || get(self.ck).is_some();
        let absolute = get(self.ccx).is_some() || get(self.ccz).is_some();
        let centre = match (kind.is_arc(), relative, absolute) {
            (false, false, false) => None,
            (false, _, _) => {
                return Err(format!(
                    "CSV line {n}: an arc centre on a row that is not an arc (arc-cw or arc-ccw)"
                ))
            }
            (true, false, false) => {
                return Err(format!(
                    "CSV line {n}: an arc without a centre: give i and k, or cx and cz (reading R-CHECKARC)"
                ))
            }
            (true, true, true) => {
                return Err(format!("CSV line {n}: give the centre once: i and k, or cx and cz, not both"))
            }
            (true, true, false) => {
                let Some(p) = self.here else {
                    return Err(format!(
                    "CSV line {n}: i and k are from the arc's start, and no earlier row gives it (use cx, cz)"
                ));
                };
                let di = match get(self.ci) {
                    Some(s) => length(Some(s), "i", self.machine.x_mode.factor())?,
                    None => 0,
                };
                let dk = match get(self.ck) {
                    Some(s) => length(Some(s), "k", 1)?,
                    None => 0,
                };
                Some(Point::new(p.x + di, p.z + dk))
            }
            (true, false, true) => {
                Some(Point::new(length(get(self.ccx), "cx", 1)?, length(get(self.ccz), "cz", 1)?))
            }
        };
        if self.here == Some(to) {
            return Ok(None);
        }
        let from = self.here;
        self.here = Some(to);
        let sync = kind == Kind::Thread && !self.in_thread;
        self.in_thread = kind == Kind::Thread;
        let angle = if sync { angle } else { StartAngle::ZERO };
        Ok(Some(Step { kind, from, to, centre, lead, angle, sync, context: Context::Source { line: n } }))
    }
}

impl Iterator for CsvTrace<'_, '_> {
    type Item = Result<(Step, u32), String>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            self.line += 1;
            let mut buf = std::mem::take(&mut self.buf);
            let row = match trace_line(&mut *self.source, &mut buf, self.line)? {
                Err(e) => Err(e),
                Ok(line) if line.trim().is_empty() => Ok(None),
                Ok(line) => self.row(self.line, line),
            };
            self.buf = buf;
            match row {
                Ok(Some(s)) => return Some(Ok((s, 0))),
                Ok(None) => {}
                Err(e) => return Some(Err(e)),
            }
        }
    }
}

/// A CSV start angle: thousandths of a degree, multiples of 0.1, below 360°.
fn csv_angle(s: &str, n: usize) -> Result<StartAngle, String> {
    let bad =
        || format!("CSV line {n}: q `{s}` must be 0 to 360000 thousandths of a degree, in steps of 0.1");
    if !s.chars().all(|c| c.is_ascii_digit() || c == '.') || !s.chars().any(|c| c.is_ascii_digit()) {
        return Err(bad());
    }
    let d = Decimal::from_str_exact(s).map_err(|_| bad())?;
    let tenths = d.checked_mul(Decimal::from(10)).ok_or_else(bad)?;
    if !tenths.fract().is_zero() || d > Decimal::from(360_000) {
        return Err(bad());
    }
    let t = u32::try_from(tenths.trunc()).map_err(|_| bad())?;
    Ok(if t % 10 == 0 {
        StartAngle::from_millidegrees(u64::from(t / 10))
    } else {
        StartAngle { num: t, den: 10 }
    })
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
    let digits = format!("{int}{frac}");
    let digits = digits.trim_start_matches('0');
    let mantissa = if digits.is_empty() { 0 } else { digits.parse().ok()? };
    let lead = Lead { word, mantissa, scale: u32::try_from(frac.len()).ok()? };
    lead.in_range().then_some(lead)
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

impl Group {
    fn len(&self) -> usize {
        self.rapids.len() + self.cuts.len()
    }

    /// This group and the next as one: the next one's rapids become moves
    /// among the cuts (a rapid written for a cutting move splits a pass).
    fn joined(&self, next: &Group) -> Group {
        let mut cuts = self.cuts.clone();
        cuts.extend_from_slice(&next.rapids);
        cuts.extend_from_slice(&next.cuts);
        Group { rapids: self.rapids.clone(), cuts }
    }
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

/// The two corners of a rapid from `p` to `q` split into an X and a Z move.
fn corners(p: Point, q: Point) -> [Point; 2] {
    [Point::new(q.x, p.z), Point::new(p.x, q.z)]
}

/// Compares a group of ours with a group of theirs; the differences.
fn compare(a: &Group, b: &Group, tol: i64, units: Units, regions: &[Region]) -> Vec<Divergence> {
    let mut out = Vec::new();
    let tol = i128::from(tol);
    let close = |p: Point, q: Point| {
        (i128::from(p.x) - i128::from(q.x)).abs() <= tol && (i128::from(p.z) - i128::from(q.z)).abs() <= tol
    };
    let through =
        |p: Point, c: Point, q: Point| regions.iter().any(|r| r.crossed_by(p, c) || r.crossed_by(c, q));
    let div = |what, o: &Step, t: &Step| Divergence { what, ours: Some(*o), theirs: Some(*t), moves: 1 };
    // Rapids: their points must be ours. A rapid of ours may be reached
    // through either corner of an X/Z split, and an X/Z split of ours may be
    // made in the other order, as long as the legs stay out of the regions
    // the cycles cut (R-CHECKSPLIT).
    let (ra, rb) = (&a.rapids, &b.rapids);
    let (mut i, mut j) = (0, 0);
    while i < ra.len() {
        let r = &ra[i];
        let Some(t) = rb.get(j) else {
            out.push(Divergence { what: "rapid point", ours: Some(*r), theirs: None, moves: 1 });
            i += 1;
            continue;
        };
        if close(t.to, r.to) {
            i += 1;
            j += 1;
            continue;
        }
        let then = |p: Point| rb.get(j + 1).is_some_and(|u| close(u.to, p));
        // A diagonal of ours, split by theirs.
        if let Some(p) = r.from.filter(|p| p.x != r.to.x && p.z != r.to.z) {
            if let Some(c) = corners(p, r.to).into_iter().find(|&c| close(t.to, c) && then(r.to)) {
                if through(p, c, r.to) {
                    out.push(div("rapid through the work", r, t));
                }
                i += 1;
                j += 2;
                continue;
            }
        }
        // A split of ours (r is the corner of `p` to the next), made in
        // the other order by theirs.
        if let (Some(p), Some(n)) = (r.from, ra.get(i + 1)) {
            let [c0, c1] = corners(p, n.to);
            let other = if r.to == c0 && c0 != p && c0 != n.to {
                Some(c1)
            } else if r.to == c1 && c1 != p && c1 != n.to {
                Some(c0)
            } else {
                None
            };
            if let Some(c) = other.filter(|&c| close(t.to, c) && then(n.to)) {
                if through(p, c, n.to) {
                    out.push(div("rapid through the work", r, t));
                }
                i += 2;
                j += 2;
                continue;
            }
        }
        let crossed = t.from.is_some_and(|p| regions.iter().any(|g| g.crossed_by(p, t.to)));
        out.push(div(if crossed { "rapid through the work" } else { "rapid point" }, r, t));
        i += 1;
        j += 1;
    }
    for t in rb.iter().skip(j) {
        out.push(Divergence { what: "extra rapid", ours: None, theirs: Some(*t), moves: 1 });
    }
    for (i, c) in a.cuts.iter().enumerate() {
        let Some(t) = b.cuts.get(i) else {
            out.push(Divergence { what: "missing move", ours: Some(*c), theirs: None, moves: 1 });
            continue;
        };
        if c.kind != t.kind && !(c.kind.is_arc() && t.kind.is_arc()) {
            out.push(div("kind of move", c, t));
            continue;
        }
        if c.kind != t.kind {
            out.push(div("arc direction", c, t));
        }
        if !close(c.to, t.to) {
            out.push(div("end point", c, t));
        }
        if let (Some(oc), Some(tc)) = (c.centre, t.centre) {
            if !close(oc, tc) {
                out.push(div("arc centre", c, t));
            }
        }
        if c.kind == Kind::Thread {
            if !same_lead(c.lead, t.lead, units) {
                out.push(div("lead", c, t));
            }
            if c.sync != t.sync {
                out.push(div("synchronisation", c, t));
            } else if c.sync && c.angle != t.angle {
                out.push(div("start angle", c, t));
            }
        }
    }
    for t in b.cuts.iter().skip(a.cuts.len()) {
        out.push(Divergence { what: "extra move", ours: None, theirs: Some(*t), moves: 1 });
    }
    out
}

/// True when the only differences are kinds of move: a rapid written for a
/// cutting move or the reverse, every point in its place.
fn only_kinds(d: &[Divergence]) -> bool {
    d.iter().all(|d| d.what == "kind of move")
}

/// The trace at `trace` as points to draw over the cycles drawn: for each
/// range of `ranges` (the indices of a drawn cycle's moves in our whole
/// toolpath, the first move being 0), the trace's moves whose index lies in
/// it, widened by a tenth (at least 16) each way so that a trace with a few
/// moves more or less still shows whole; at most
/// [`crate::plot::MAX_OVERLAY_POINTS`] a cycle. The trace is read as it is
/// taken, then again by [`run`] for the divergences to mark.
///
/// # Errors
///
/// The program's or the trace's first error; a trace on standard input
/// (`-`), which cannot be read twice.
pub fn overlay(
    job: &Job,
    trace: &Path,
    units: Units,
    cycles: &[(usize, usize, usize)],
) -> Result<crate::plot::Overlay, String> {
    if trace == Path::new("-") {
        return Err(
            "plot --trace reads the trace twice (to draw it, and to find where it diverges from ours): \
                    give it as a file, not `-`"
                .into(),
        );
    }
    let (name, source) = open_trace(trace)?;
    let widened: Vec<(usize, usize)> = cycles
        .iter()
        .map(|&(_, from, to)| {
            let slack = ((to - from) / 10).max(16);
            (from.saturating_sub(slack), to + slack)
        })
        .collect();
    let last = widened.iter().map(|r| r.1).max().unwrap_or(0);
    let mut per_cycle = vec![Vec::new(); cycles.len()];
    let mut dropped = 0_usize;
    for (i, step) in trace_steps(source, format_of(trace), &job.machine, units)
        .map_err(|e| format!("{name}: {e}"))?
        .enumerate()
    {
        let p = step.map_err(|e| format!("{name}: {e}"))?.0.to;
        if i > last {
            // The rest is read only for its errors.
            continue;
        }
        for (k, (from, to)) in widened.iter().enumerate() {
            if (*from..*to).contains(&i) {
                if per_cycle[k].len() < crate::plot::MAX_OVERLAY_POINTS {
                    per_cycle[k].push(p);
                } else {
                    dropped += 1;
                }
            }
        }
    }
    // Where they diverge: the comparison `check` makes, at tolerance 0.
    let marks = compare_file(job, trace, units, 0)?.marks();
    let lines = cycles.iter().map(|&(line, _, _)| line).collect();
    Ok(crate::plot::Overlay { name, per_cycle, lines, dropped, marks })
}

/// True when the trace at `trace` is a CSV (by its extension).
/// The format of a trace file, by its extension.
fn format_of(trace: &Path) -> TraceFormat {
    match trace.extension() {
        Some(e) if e.eq_ignore_ascii_case("csv") => TraceFormat::Csv,
        Some(e) if e.eq_ignore_ascii_case("canon") => TraceFormat::Rs274,
        _ => TraceFormat::Nc,
    }
}

/// The kinds of trace `check` reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TraceFormat {
    /// An expanded program (plain motion blocks).
    Nc,
    /// A CSV of moves.
    Csv,
    /// LinuxCNC's canonical output (`rs274 -g FILE < /dev/null > T.canon`),
    /// on the linuxcnc profile.
    Rs274,
}

/// The vendor's toolpath from LinuxCNC's canonical output (reading
/// R-CHECKLCNC): `STRAIGHT_TRAVERSE` is a rapid, `STRAIGHT_FEED` a feed,
/// or a thread move at the pitch of the `START_SPEED_FEED_SYNC` in force;
/// synchronisation starts at a thread move that follows no thread move
/// (LinuxCNC's planner waits for the index only then). X is printed as a
/// radius: the check holds it as a diameter on this profile.
struct CanonTrace<'t> {
    source: Box<dyn BufRead + 't>,
    buf: Vec<u8>,
    line: usize,
    units: Units,
    pitch: Option<Lead>,
    in_thread: bool,
    here: Option<Point>,
}

impl CanonTrace<'_> {
    /// A printed length in increments (X doubled: a diameter).
    fn increments(&self, v: Decimal, factor: i64, what: &str) -> Result<i64, String> {
        let scaled = v
            .checked_mul(Decimal::from(self.units.per_unit() * factor))
            .filter(|s| s.fract().is_zero())
            .ok_or_else(|| format!("line {}: {what} {v} is not a whole number of increments", self.line))?;
        i64::try_from(scaled)
            .ok()
            .filter(|v| v.unsigned_abs() <= MAX_LENGTH.unsigned_abs())
            .ok_or_else(|| format!("line {}: {what} {v} is beyond the range table", self.line))
    }

    fn step(&mut self) -> Result<Option<Step>, String> {
        loop {
            self.line += 1;
            let text = match trace_line(&mut *self.source, &mut self.buf, self.line) {
                None => return Ok(None),
                Some(t) => t?.to_string(),
            };
            let call = cycleref_spec::rs274::call(&text, self.line).map_err(|e| e.to_string())?;
            match call {
                Some(cycleref_spec::rs274::CanonCall::StartSync { pitch }) => {
                    let bad =
                        || format!("line {}: pitch {pitch} is not a lead of at most 6 decimals", self.line);
                    let mut mantissa = pitch
                        .checked_mul(Decimal::from(1_000_000))
                        .filter(|s| s.fract().is_zero())
                        .and_then(|s| u64::try_from(s).ok())
                        .filter(|m| *m > 0)
                        .ok_or_else(bad)?;
                    let mut scale = 6;
                    while scale > 0 && mantissa % 10 == 0 {
                        mantissa /= 10;
                        scale -= 1;
                    }
                    self.pitch = Some(Lead { word: LeadWord::F, mantissa, scale });
                }
                Some(cycleref_spec::rs274::CanonCall::StopSync) => self.pitch = None,
                Some(cycleref_spec::rs274::CanonCall::Motion { rapid, x, z }) => {
                    let to = Point::new(self.increments(x, 2, "X")?, self.increments(z, 1, "Z")?);
                    let from = self.here.replace(to);
                    if from == Some(to) {
                        continue;
                    }
                    let kind = match (rapid, self.pitch) {
                        (true, _) => Kind::Rapid,
                        (false, None) => Kind::Feed,
                        (false, Some(_)) => Kind::Thread,
                    };
                    let sync = kind == Kind::Thread && !self.in_thread;
                    self.in_thread = kind == Kind::Thread;
                    let lead = if kind == Kind::Thread { self.pitch } else { None };
                    let context = Context::Source { line: self.line };
                    return Ok(Some(Step {
                        kind,
                        from,
                        to,
                        centre: None,
                        lead,
                        angle: StartAngle::ZERO,
                        sync,
                        context,
                    }));
                }
                None => {}
            }
        }
    }
}

impl Iterator for CanonTrace<'_> {
    type Item = Result<(Step, u32), String>;

    fn next(&mut self) -> Option<Self::Item> {
        self.step().transpose().map(|r| r.map(|s| (s, 0)))
    }
}

/// The trace's name and a buffered reader of it (`-`: standard input).
fn open_trace(trace: &Path) -> Result<(String, Box<dyn BufRead>), String> {
    if trace == Path::new("-") {
        return Ok((crate::job::STDIN_NAME.to_string(), Box::new(std::io::stdin().lock())));
    }
    let file = std::fs::File::open(trace).map_err(|e| format!("{}: {e}", trace.display()))?;
    Ok((trace.display().to_string(), Box::new(std::io::BufReader::with_capacity(1 << 16, file))))
}

/// Steps with their segments, read as they are taken.
type TraceSteps<'t> = Box<dyn Iterator<Item = Result<(Step, u32), String>> + 't>;

/// The vendor's steps, read as they are taken from `source`: an expanded
/// program, or a CSV. The text must be UTF-8 (a byte-order mark is
/// skipped).
fn trace_steps<'t, 'm: 't>(
    source: Box<dyn BufRead + 't>,
    format: TraceFormat,
    machine: &'m Machine,
    units: Units,
) -> Result<TraceSteps<'t>, String> {
    Ok(if format == TraceFormat::Rs274 {
        if machine.profile.dialect != Dialect::LinuxCnc {
            return Err("an rs274 trace (.canon) is LinuxCNC's: compare it with --profile linuxcnc".into());
        }
        Box::new(CanonTrace {
            source,
            buf: Vec::new(),
            line: 0,
            units,
            pitch: None,
            in_thread: false,
            here: None,
        })
    } else if format == TraceFormat::Csv {
        Box::new(CsvTrace::new(source, machine, units)?)
    } else {
        Box::new(NcTrace::new(source, Tracker::new(machine, units, true)))
    })
}

/// Runs the comparison of `job`'s program with the trace at `trace` (`-`:
/// standard input; `.csv`: a CSV).
///
/// # Errors
///
/// The program's first error, or the trace's, with its line.
pub fn run(job: &Job, trace: &Path, tolerance: u64) -> Result<Report, String> {
    if trace == Path::new("-") && job.name == crate::job::STDIN_NAME {
        job.validate()?;
        return Err("the program and the trace cannot both come from standard input".into());
    }
    let units = job.units()?;
    compare_file(job, trace, units, tolerance).map_err(|e| program_error_first(job, e))
}

/// `check` in one phase (reading R-STREAM): its report is written only
/// after the comparison, so no validation phase is needed for "nothing
/// half-written". The comparison reads the whole program in order and
/// expands every cycle as the validation would, so it meets the program's
/// first error exactly where the validation does; an error of the trace
/// (or of opening it) may come first, and then the validation is run after
/// all, so that a program error still wins and every message is the one a
/// validation phase first would have given.
fn program_error_first(job: &Job, e: String) -> String {
    match job.validate() {
        Err(program) => program.into(),
        Ok(_) => e,
    }
}

/// What [`run`] does once it has the program's `units`.
fn compare_file(job: &Job, trace: &Path, units: Units, tolerance: u64) -> Result<Report, String> {
    let (name, source) = open_trace(trace)?;
    compare_streams(job, source, format_of(trace), units, tolerance).map_err(|e| match e {
        StreamError::Ours(e) => e,
        StreamError::Theirs(e) => format!("{name}: {e}"),
    })
}

/// The comparison of `job`'s program with a trace given as bytes (`.nc`
/// text, or CSV when `is_csv`): what `run` does after opening the file.
/// The fuzz target `check_trace` and the property tests call it.
///
/// # Errors
///
/// Our expansion's error, or the trace's, with its line.
pub fn check_bytes(job: &Job, bytes: &[u8], is_csv: bool, tolerance: u64) -> Result<Report, String> {
    let format = if is_csv { TraceFormat::Csv } else { TraceFormat::Nc };
    check_bytes_as(job, bytes, format, tolerance)
}

/// [`check_bytes`] with the trace's format named, LinuxCNC's canonical
/// output included (the fuzz target `check_canon` calls it).
///
/// # Errors
///
/// Our expansion's error, or the trace's, with its line.
pub fn check_bytes_as(
    job: &Job,
    bytes: &[u8],
    format: TraceFormat,
    tolerance: u64,
) -> Result<Report, String> {
    let units = job.units()?;
    compare_streams(job, Box::new(bytes), format, units, tolerance)
        .map_err(|e| match e {
            StreamError::Ours(e) | StreamError::Theirs(e) => e,
        })
        .map_err(|e| program_error_first(job, e))
}

/// Whose toolpath an error comes from.
enum StreamError {
    Ours(String),
    Theirs(String),
}

/// The most moves in one group: a pass longer than this (a program of a
/// million G01 blocks is one "pass") is compared in pieces of this size.
const GROUP_MOVES: usize = 4096;

/// The most groups of ours aligned at once: a cycle with more passes is
/// aligned in windows of this many.
const WINDOW_GROUPS: usize = 512;

/// The most cells of an alignment table (beyond, groups are compared in
/// order): 512 groups of ours against 1024 of theirs.
const MAX_CELLS: usize = 1 << 19;

/// The most divergences a report lists; the count is always exact.
pub const MAX_LISTED: usize = 10_000;

/// Steps made into groups (a run of rapids and the cutting moves after
/// it), each with its owner: the segment of its first cutting move, or of
/// its first rapid.
struct Grouper<I> {
    steps: I,
    next: Option<(Step, u32)>,
    /// Steps taken so far.
    count: usize,
    /// Groups given back once compared, emptied, to be filled again: a
    /// group's two vectors are allocated once, not once per pass (most
    /// of `check`'s allocations were these). At most [`SPARE_GROUPS`].
    spare: Vec<Group>,
}

/// The most emptied groups a [`Grouper`] keeps for reuse: a window and
/// the trace's groups read ahead of it, so memory stays that of one
/// window.
const SPARE_GROUPS: usize = 2 * WINDOW_GROUPS + 16;

/// The most moves an emptied group may have room for and still be kept:
/// a pass has a handful; a group grown to thousands (a long run of plain
/// moves, up to [`GROUP_MOVES`]) is dropped, so that reused groups never
/// hold more room than the passes they carry need.
const SPARE_ROOM: usize = 64;

impl<I: Iterator<Item = Result<(Step, u32), String>>> Grouper<I> {
    fn new(steps: I) -> Grouper<I> {
        Grouper { steps, next: None, count: 0, spare: Vec::new() }
    }

    /// Takes back a group that was compared, to fill it again.
    fn recycle(&mut self, mut g: Group) {
        if self.spare.len() < SPARE_GROUPS && g.rapids.capacity() + g.cuts.capacity() <= SPARE_ROOM {
            g.rapids.clear();
            g.cuts.clear();
            self.spare.push(g);
        }
    }

    fn pull(&mut self) -> Option<Result<(Step, u32), String>> {
        let s = self.next.take().map(Ok).or_else(|| self.steps.next());
        if matches!(s, Some(Ok(_))) {
            self.count += 1;
        }
        s
    }

    fn group(&mut self) -> Option<Result<(Group, u32), String>> {
        let mut g = self.spare.pop().unwrap_or(Group { rapids: Vec::new(), cuts: Vec::new() });
        let (mut rapid_owner, mut cut_owner) = (None, None);
        loop {
            let (s, seg) = match self.pull() {
                None if g.len() == 0 => return None,
                None => break,
                Some(Err(e)) => return Some(Err(e)),
                Some(Ok(v)) => v,
            };
            let full = g.cuts.len() >= GROUP_MOVES || g.rapids.len() >= GROUP_MOVES;
            if g.len() > 0 && ((s.kind == Kind::Rapid && !g.cuts.is_empty()) || full) {
                self.next = Some((s, seg));
                self.count -= 1;
                break;
            }
            if s.kind == Kind::Rapid {
                rapid_owner.get_or_insert(seg);
                g.rapids.push(s);
            } else {
                cut_owner.get_or_insert(seg);
                g.cuts.push(s);
            }
        }
        Some(Ok((g, cut_owner.or(rapid_owner).unwrap_or(0))))
    }
}

/// Compares our toolpath with the trace's, both read as they are taken:
/// our groups are aligned a cycle (at most [`WINDOW_GROUPS`] groups) at a
/// time with the trace's next groups, of which the alignment takes what it
/// matches and leaves the rest for the next window (reading R-CHECKSTREAM).
fn compare_streams(
    job: &Job,
    trace: Box<dyn BufRead + '_>,
    format: TraceFormat,
    units: Units,
    tolerance: u64,
) -> Result<Report, StreamError> {
    let tol = i64::try_from(tolerance).unwrap_or(i64::MAX);
    let mut ours = Grouper::new(OurSteps::new(job, units).map_err(StreamError::Ours)?);
    let steps = trace_steps(trace, format, &job.machine, units).map_err(StreamError::Theirs)?;
    let mut theirs = Grouper::new(steps);
    let mut report = Report::new(units, tolerance);
    let mut pending: VecDeque<Group> = VecDeque::new();
    let mut lookahead: Option<(Group, u32)> = None;
    // Reused from window to window, as the groups are.
    let mut window = Vec::new();
    let mut regions: Vec<Region> = Vec::new();
    loop {
        // Our next window: the groups of one owner.
        let mut owner = None;
        loop {
            let next = match lookahead.take() {
                Some(g) => g,
                None => match ours.group() {
                    None => break,
                    Some(r) => r.map_err(StreamError::Ours)?,
                },
            };
            if owner.is_some_and(|o| o != next.1) || window.len() == WINDOW_GROUPS {
                lookahead = Some(next);
                break;
            }
            owner = Some(next.1);
            window.push(next.0);
        }
        if window.is_empty() {
            break;
        }
        let want = window.len() + window.len().max(16);
        while pending.len() < want {
            match theirs.group() {
                None => break,
                Some(r) => pending.push_back(r.map_err(StreamError::Theirs)?.0),
            }
        }
        regions.clear();
        regions.extend(ours.steps.regions.iter().flatten().copied());
        let next = lookahead.as_ref().map(|(g, _)| g);
        let (divergences, taken) = align(&window, pending.make_contiguous(), tol, units, &regions, next);
        for g in pending.drain(..taken) {
            theirs.recycle(g);
        }
        for g in window.drain(..) {
            ours.recycle(g);
        }
        report.add(divergences);
    }
    // What the trace has beyond our last move.
    for g in pending.drain(..) {
        report.add(vec![extra(&g)]);
    }
    while let Some(g) = theirs.group() {
        report.add(vec![extra(&g.map_err(StreamError::Theirs)?.0)]);
    }
    if theirs.count == 0 {
        return Err(StreamError::Theirs("the trace has no moves (reading R-CHECKEMPTY)".into()));
    }
    report.ours_moves = ours.count;
    report.theirs_moves = theirs.count;
    Ok(report)
}

/// One step of the alignment.
#[derive(Clone, Copy)]
enum Op {
    /// Our group i against their group j.
    Pair(usize, usize),
    /// Our groups i.. (p of them) joined against their groups j.. (q).
    Join {
        i: usize,
        p: usize,
        j: usize,
        q: usize,
    },
    Missing(usize),
    Extra(usize),
}

/// The joins tried: one group of ours against two of theirs, two against
/// one, two against two (a rapid written for a cutting move splits a pass
/// or moves a pass boundary; the reverse joins them).
const JOINS: [(usize, usize); 3] = [(1, 2), (2, 1), (2, 2)];

/// Groups joined into one: the later groups' rapids become moves among
/// the cuts.
fn joined(gs: &[Group]) -> Group {
    let mut out = Group { rapids: Vec::new(), cuts: Vec::new() };
    for (n, g) in gs.iter().enumerate() {
        out = if n == 0 { g.clone() } else { out.joined(g) };
    }
    out
}

/// Aligns the groups by edit distance (a match costs 0, a substitution 1,
/// a missing or extra group 1, a join of groups that differ only in kinds
/// of move 1) and lists the differences in our order, with the number of
/// their groups taken. When our toolpath goes on with `next`, the
/// alignment may stop before the end of theirs, and the rest belongs to
/// what follows: it stops where the cost plus 1 when their next group is
/// not `next` is least (the fewest groups at equal cost). Without `next`
/// it takes all of `b`.
fn align(
    a: &[Group],
    b: &[Group],
    tol: i64,
    units: Units,
    regions: &[Region],
    next: Option<&Group>,
) -> (Vec<Divergence>, usize) {
    let free_end = next.is_some();
    let (n, m) = (a.len(), b.len());
    let cmp = |x: &Group, y: &Group| compare(x, y, tol, units, regions);
    // Beyond this size the table is too big: compare in order.
    if (n + 1).saturating_mul(m + 1) > MAX_CELLS {
        let mut out = Vec::new();
        let end = if free_end { n.min(m) } else { m };
        for i in 0..n.max(end) {
            match (a.get(i), b.get(i).filter(|_| i < end)) {
                (Some(x), Some(y)) => out.extend(cmp(x, y)),
                (Some(x), None) => out.push(missing(x)),
                (None, Some(y)) => out.push(extra(y)),
                (None, None) => {}
            }
        }
        return (out, end);
    }
    // The usual case first: every group of ours met in order, and theirs
    // resumes with our next group (or ends with ours).
    let in_order = n <= m
        && a.iter().zip(b).all(|(x, y)| cmp(x, y).is_empty())
        && match next {
            Some(o) => b.get(n).is_none_or(|t| cmp(o, t).is_empty()),
            None => n == m,
        };
    if in_order {
        return (Vec::new(), n);
    }
    let w = m + 1;
    let equal: Vec<bool> =
        a.iter().flat_map(|x| b.iter().map(move |y| (x, y))).map(|(x, y)| cmp(x, y).is_empty()).collect();
    let eq = |i: usize, j: usize| equal[i * m + j];
    // A join of our groups i..i+p with their j..j+q, only where the sizes
    // fit (the cheap test first).
    let join = |i: usize, p: usize, j: usize, q: usize| {
        let (x, y) = (&a[i..i + p], &b[j..j + q]);
        x.iter().map(Group::len).sum::<usize>() == y.iter().map(Group::len).sum::<usize>()
            && x[0].rapids.len() == y[0].rapids.len()
            && only_kinds(&cmp(&joined(x), &joined(y)))
    };
    let mut cost = vec![0_u32; (n + 1) * w];
    // The join that reached a cell: 0 none, k + 1 for JOINS[k].
    let mut via = vec![0_u8; (n + 1) * w];
    for i in 0..=n {
        for j in 0..=m {
            let c = if i == 0 || j == 0 {
                u32::try_from(i + j).unwrap_or(u32::MAX / 2)
            } else {
                let sub = cost[(i - 1) * w + j - 1] + u32::from(!eq(i - 1, j - 1));
                let mut c = sub.min(cost[(i - 1) * w + j] + 1).min(cost[i * w + j - 1] + 1);
                for (k, (p, q)) in JOINS.into_iter().enumerate() {
                    if i >= p && j >= q && cost[(i - p) * w + j - q] + 1 < c && join(i - p, p, j - q, q) {
                        via[i * w + j] = u8::try_from(k + 1).unwrap_or(0);
                        c = cost[(i - p) * w + j - q] + 1;
                    }
                }
                c
            };
            cost[i * w + j] = c;
        }
    }
    // Where it ends in theirs: all of it, or (free end) the fewest groups
    // at the least cost.
    let resumes = |j: usize| match (b.get(j), next) {
        (Some(t), Some(o)) => cmp(o, t).is_empty(),
        _ => true,
    };
    let end = if free_end {
        (0..=m).min_by_key(|&j| (cost[n * w + j] + u32::from(!resumes(j)), j)).unwrap_or(m)
    } else {
        m
    };
    // Walk back.
    let (mut i, mut j) = (n, end);
    let mut ops = Vec::new();
    // Walking back, a missing or extra group is preferred over a match of
    // equal cost: when passes repeat (finishing passes), the one reported
    // missing is the last, where a trace that stops early stops.
    while i > 0 || j > 0 {
        if let Some(&(p, q)) = via[i * w + j].checked_sub(1).and_then(|k| JOINS.get(usize::from(k))) {
            ops.push(Op::Join { i: i - p, p, j: j - q, q });
            i -= p;
            j -= q;
        } else if i > 0 && cost[i * w + j] == cost[(i - 1) * w + j] + 1 {
            ops.push(Op::Missing(i - 1));
            i -= 1;
        } else if i > 0
            && j > 0
            && cost[i * w + j] == cost[(i - 1) * w + j - 1] + u32::from(!eq(i - 1, j - 1))
        {
            ops.push(Op::Pair(i - 1, j - 1));
            i -= 1;
            j -= 1;
        } else {
            ops.push(Op::Extra(j - 1));
            j -= 1;
        }
    }
    ops.reverse();
    let mut out = Vec::new();
    for op in ops {
        match op {
            Op::Pair(x, y) => out.extend(cmp(&a[x], &b[y])),
            Op::Join { i, p, j, q } => out.extend(cmp(&joined(&a[i..i + p]), &joined(&b[j..j + q]))),
            Op::Missing(x) => out.push(missing(&a[x])),
            Op::Extra(y) => out.push(extra(&b[y])),
        }
    }
    (out, end)
}

fn first_step(g: &Group) -> Option<Step> {
    g.cuts.first().or(g.rapids.last()).copied()
}

fn missing(g: &Group) -> Divergence {
    Divergence { what: "missing pass", ours: first_step(g), theirs: None, moves: g.len() }
}

fn extra(g: &Group) -> Divergence {
    Divergence { what: "extra pass", ours: None, theirs: first_step(g), moves: g.len() }
}

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
    ours_moves: usize,
    theirs_moves: usize,
    /// The first [`MAX_LISTED`] divergences.
    divergences: Vec<Divergence>,
    /// How many there are.
    total: usize,
}

impl Report {
    fn new(units: Units, tolerance: u64) -> Report {
        Report { units, tolerance, ours_moves: 0, theirs_moves: 0, divergences: Vec::new(), total: 0 }
    }

    /// Counts `found` and keeps those within the first [`MAX_LISTED`].
    fn add(&mut self, found: Vec<Divergence>) {
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
        format!("X{} Z{}", fixed(p.x, self.units), fixed(p.z, self.units))
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
        let mut v = json!({
            "motion": s.kind.name(),
            "x": fixed(s.to.x, self.units),
            "z": fixed(s.to.z, self.units),
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

#[cfg(test)]
mod tests {
    use super::*;

    const MM: Units = Units { system: cycleref::IncrementSystem::IsB, unit: InputUnit::Metric };

    fn step(kind: Kind, x: i64, z: i64, line: usize) -> Step {
        let lead = (kind == Kind::Thread).then_some(Lead { word: LeadWord::F, mantissa: 2, scale: 0 });
        Step {
            kind,
            from: None,
            to: Point::new(x, z),
            centre: None,
            lead,
            angle: StartAngle::ZERO,
            sync: kind == Kind::Thread,
            context: Context::Source { line },
        }
    }

    /// A pass at depth `x`: a rapid to its start and one thread move.
    fn pass(x: i64) -> Group {
        Group { rapids: vec![step(Kind::Rapid, x, 10, 1)], cuts: vec![step(Kind::Thread, x, -30, 2)] }
    }

    fn whats(d: &[Divergence]) -> Vec<&'static str> {
        d.iter().map(|d| d.what).collect()
    }

    #[test]
    fn equal_groups_agree_and_take_as_many() {
        let ours = [pass(100), pass(90), pass(80)];
        let theirs = [pass(100), pass(90), pass(80), pass(70)];
        // Our next group is theirs after the three: they agree, three taken.
        let (d, taken) = align(&ours, &theirs, 0, MM, &[], Some(&pass(70)));
        assert_eq!((whats(&d), taken), (vec![], 3));
        // Without a next group, all of theirs is taken: one extra pass.
        let (d, taken) = align(&ours, &theirs, 0, MM, &[], None);
        assert_eq!((whats(&d), taken), (vec!["extra pass"], 4));
    }

    #[test]
    fn a_missing_pass_is_one_divergence_not_a_shift() {
        let ours = [pass(100), pass(90), pass(80), pass(70)];
        let theirs = [pass(100), pass(80), pass(70)];
        let (d, taken) = align(&ours, &theirs, 0, MM, &[], None);
        assert_eq!((whats(&d), taken), (vec!["missing pass"], 3));
        assert_eq!(d[0].ours.map(|s| s.to), Some(Point::new(90, -30)));
    }

    #[test]
    fn a_window_stops_where_the_trace_resumes_with_our_next_group() {
        // Our window's last pass is missing from the trace, which goes on
        // with our next window's first pass: the window takes two groups and
        // reports the missing pass, instead of pairing it with the next
        // window's pass (a substitution, then an extra pass later).
        let ours = [pass(100), pass(90), pass(80)];
        let next = pass(500);
        let theirs = [pass(100), pass(90), pass(500), pass(490)];
        let (d, taken) = align(&ours, &theirs, 0, MM, &[], Some(&next));
        assert_eq!((whats(&d), taken), (vec!["missing pass"], 2));
    }

    #[test]
    fn a_changed_end_point_is_named_within_the_tolerance() {
        let ours = [pass(100)];
        let mut moved = pass(100);
        moved.cuts[0].to = Point::new(100, -31);
        let (d, _) = align(&ours, std::slice::from_ref(&moved), 0, MM, &[], None);
        assert_eq!(whats(&d), vec!["end point"]);
        let (d, _) = align(&ours, std::slice::from_ref(&moved), 1, MM, &[], None);
        assert!(d.is_empty());
    }

    #[test]
    fn long_runs_are_grouped_in_pieces() {
        // One rapid and GROUP_MOVES + 5 feeds: two groups, the second of 5.
        let steps = std::iter::once(Ok((step(Kind::Rapid, 0, 0, 1), 0))).chain(
            (1..=GROUP_MOVES + 5).map(|i| Ok((step(Kind::Feed, 0, -i64::try_from(i).unwrap_or(0), 2), 0))),
        );
        let mut g = Grouper::new(steps);
        let first = g.group().and_then(Result::ok).map(|(g, _)| (g.rapids.len(), g.cuts.len()));
        let second = g.group().and_then(Result::ok).map(|(g, _)| (g.rapids.len(), g.cuts.len()));
        assert_eq!((first, second), (Some((1, GROUP_MOVES)), Some((0, 5))));
        assert!(g.group().is_none());
        assert_eq!(g.count, GROUP_MOVES + 6);
    }
}
