//! Our toolpath as a stream of steps: the program's own motion blocks,
//! read by `Tracker` (which reads an expanded program given as the trace
//! too, strictly), and its cycles' expanded moves, each annotated with the
//! cycle, pass and point it is. Also the regions the cycles cut, against
//! which a split rapid is judged (reading R-CHECKSPLIT).

use std::collections::VecDeque;

use cycleref::units::MAX_LENGTH;
use cycleref::{
    InputUnit, Lead, LeadWord, Motion, Move, Pass, PassKind, Point, Role, StartAngle, Units, XMode,
};
use cycleref_spec::lex::{Block, Word};
use cycleref_spec::pipeline::{Cycle, Moves};
use cycleref_spec::profile::Dialect;
use cycleref_spec::reader::{length_word, q_word, Item, MotionMode};
use cycleref_spec::Machine;
use rust_decimal::Decimal;

use super::{Context, Kind, Step, UNKNOWN};
use crate::job::{Items, Job};

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
pub(super) struct Tracker<'m> {
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
    pub(super) fn new(machine: &'m Machine, units: Units, strict: bool) -> Tracker<'m> {
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
    pub(super) fn block(&mut self, b: &Block<'_>) -> Result<Option<Step>, String> {
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
        if !self.linuxcnc {
            // The program's own rule (one home: the reader): X with U, or Z
            // with W, is an error, in a trace as in a program.
            cycleref_spec::reader::check_axis_words(b).map_err(pe)?;
        }
        let coord = |abs: char, inc: char, cur: Option<i64>| -> Result<Option<i64>, String> {
            if let Some(w) = b.get(abs).map_err(pe)? {
                return Ok(Some(length_word(self.machine, self.units, b, w).map_err(pe)?));
            }
            if let Some(w) = b.get(inc).map_err(pe)? {
                let d = length_word(self.machine, self.units, b, w).map_err(pe)?;
                // An incremental word needs the position, as in a program
                // (the reader's PositionUnknown).
                let Some(c) = cur else {
                    return Err(at(
                        b,
                        Some(w),
                        "the trace moves by an incremental word before its start point is known: give a G50 \
                         or a first G00 X Z",
                    ));
                };
                return Ok(Some(c + d));
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
        if from == (x, z) {
            return Ok(None);
        }
        // A move before both axes are known is kept, with the axis not yet
        // known as `UNKNOWN` (reading R-CHECKPARTIAL): it is compared on the
        // axis it gives, and never dropped.
        let to = Point::new(x.map_or(UNKNOWN, |x| self.held_x(x, self.x_mode)), z.unwrap_or(UNKNOWN));
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
pub(super) struct Region {
    x_lo: i128,
    x_hi: i128,
    z_lo: i128,
    z_hi: i128,
}

impl Region {
    pub(super) fn spanning(points: &[(i128, i128)]) -> Option<Region> {
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

    /// The box with a dimension of no extent widened by one increment to
    /// each side (the cut line of a straight or face thread).
    fn widened_where_flat(mut self) -> Region {
        if self.x_lo == self.x_hi {
            self.x_lo -= 1;
            self.x_hi += 1;
        }
        if self.z_lo == self.z_hi {
            self.z_lo -= 1;
            self.z_hi += 1;
        }
        self
    }

    /// True when the straight path from `p` to `q` meets the open box. Only
    /// paths along one axis are decided (a split's legs are); a diagonal
    /// gives false.
    pub(super) fn crossed_by(&self, p: Point, q: Point) -> bool {
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
                // Streamed: the span of the thread moves' Z, in constant
                // memory whatever the number of passes.
                let mut prev = c.start;
                let mut span: Option<(i128, i128)> = None;
                for m in job.expand(cycle)? {
                    if matches!(m.motion, Motion::Thread { .. }) {
                        for z in [i128::from(prev.z), i128::from(m.to.z)] {
                            span = Some(span.map_or((z, z), |(lo, hi)| (lo.min(z), hi.max(z))));
                        }
                    }
                    prev = m.to;
                }
                if let Some((lo, hi)) = span {
                    out.extend(Region::spanning(&[(peak, lo), (root, hi)]));
                }
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
                // Streamed, in constant memory (the cycle may have
                // millions of passes across its starts).
                let mut prev = c.start;
                let mut zs: Option<i64> = None;
                for m in job.expand(Cycle::G76(call))? {
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
                // A straight thread's box has no width: it is widened by
                // one increment across the thread (to each side), so that
                // a rapid leg along the cut line itself (a Z-first retract
                // dragging the tool back along the thread just cut) meets
                // it, while our approach and retract, which end on its
                // edges, do not.
                if let Some(cut) = job.expand(Cycle::G32(call))?.find(|m| m.role == Role::Cut) {
                    let s = g.start;
                    let region = Region::spanning(&[
                        (i128::from(s.x), i128::from(s.z)),
                        (i128::from(cut.to.x), i128::from(cut.to.z)),
                    ]);
                    out.extend(region.map(Region::widened_where_flat));
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
pub(super) struct OurSteps<'j> {
    job: &'j Job,
    items: Items<'j>,
    tracker: Tracker<'j>,
    current: Option<Running>,
    segment: u32,
    /// The regions of the latest cycles.
    pub(super) regions: VecDeque<Vec<Region>>,
    /// Only the cycles' moves are steps (reading R-CHECKCYCLES); the
    /// program's own blocks only move the tracker.
    cycles_only: bool,
}

impl<'j> OurSteps<'j> {
    pub(super) fn new(job: &'j Job, units: Units, cycles_only: bool) -> Result<OurSteps<'j>, String> {
        Ok(OurSteps {
            job,
            items: job.items()?,
            tracker: Tracker::new(&job.machine, units, false),
            current: None,
            segment: 0,
            regions: VecDeque::new(),
            cycles_only,
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
            let (job, tracker, segment, cycles_only) =
                (self.job, &mut self.tracker, self.segment, self.cycles_only);
            let (regions, current) = (&mut self.regions, &mut self.current);
            let next = self.items.next_with(|item| -> Result<Option<(Step, u32)>, String> {
                let Some(cycle) = Cycle::of(item) else {
                    let Item::Source(b) = item else { return Ok(None) };
                    return match tracker.block(b) {
                        Ok(step) => Ok(step.filter(|_| !cycles_only).map(|s| (s, segment))),
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
