//! A plain `f64` implementation of the G76 formulas, of the kind a control
//! might use: the **benchmark baseline**, not a reference.
//!
//! Lengths are `f64` millimetres (inches); nothing is exact:
//!
//! * depth schedule `D(n) = min(k - d, max(round(Δd √n), D(n-1) +
//!   max(Δdmin, inc)))` with [`f64::sqrt`] and [`f64::round`], each depth
//!   rounded to the increment (`round(x / inc) × inc`, computed as
//!   `round(x × per_unit) / per_unit` so that equal decimals give equal
//!   doubles and the schedule stops on `k - d`);
//! * Z shift `D × tan(a / 2)` in `f64`, **not** rounded to the increment;
//! * pass start Bn, end on the line D–E, and the run-out by explicit J/K
//!   (a chamfer run-out `r` is turned into J/K once, in
//!   [`FloatCycle::from_cycle`]); the run-out start on the cut line is
//!   interpolated in `f64`, not rounded;
//! * moves carry what the engine's moves carry, as a control would hold
//!   them: kind, X (X-word units) and Z, the lead and the spindle start
//!   angle (degrees) as `f64`, and the pass (rough or finishing, number,
//!   start, depth and cut in `f64`), so that the comparison with the engine
//!   measures the arithmetic, not a difference in what is produced.
//!
//! It may therefore differ from the reference model and the engine in the
//! last digit (a Z shift or a run-out start by up to half an increment,
//! more if an `f64` rounding lands on a tie), and in rare cases in the
//! number of levels or moves. Only what the benchmarks need is modelled:
//! straight or tapered threads with Z as the long axis, infeed D0, no
//! lead-in, any number of starts (every start repeats the same path, as
//! the reference does, with the start angle `360° × start / L`). There is
//! no pass limit and no alarm check beyond what [`FloatCycle::from_cycle`]
//! refuses.

use cycleref::g76::{G76Cycle, Infeed, RunOut};
use cycleref::lead::LeadWord;
use cycleref::units::InputUnit;

/// How the tool moves to a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MoveKind {
    /// Rapid (G00).
    Rapid,
    /// Thread cutting synchronised with the spindle (G32).
    Thread,
}

/// A candidate point of a pass path: `(kind, x, z)`.
type PathPoint = (MoveKind, f64, f64);

/// One move, with the annotations of the engine's `Move` in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatMove {
    /// Rapid or thread.
    pub kind: MoveKind,
    /// X in X-word units (mm or inch).
    pub x: f64,
    /// Z (mm or inch).
    pub z: f64,
    /// Lead, mm (inch) per revolution.
    pub lead: f64,
    /// Spindle start angle, degrees.
    pub start_angle: f64,
    /// A finishing pass (else rough).
    pub finish: bool,
    /// Pass number among its kind.
    pub number: u32,
    /// 1-based start.
    pub start: u16,
    /// Depth of the pass, radius.
    pub depth: f64,
    /// Cut of the pass, radius.
    pub cut: f64,
}

/// A G76 cycle in `f64` units (mm or inch), as a control would hold it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatCycle {
    /// Increments per mm (inch): 1000 for IS-B metric.
    pub per_unit: f64,
    /// X-word units per radius unit: 2 for diameter X, 1 for radius X.
    pub xf: f64,
    /// A: (X, Z).
    pub start: (f64, f64),
    /// D: (X, Z).
    pub end: (f64, f64),
    /// R(i): taper, radius.
    pub taper: f64,
    /// P(k): thread height, radius.
    pub height: f64,
    /// Q(Δd): first depth, radius.
    pub first_depth: f64,
    /// `max(Δdmin, one increment)`, radius.
    pub min_cut: f64,
    /// `k - d`: depth of the last rough level, radius.
    pub last: f64,
    /// P(m): finishing passes.
    pub finishing_passes: u32,
    /// `tan(a / 2)`.
    pub tan_half: f64,
    /// L: number of starts.
    pub starts: u32,
    /// Run-out `(J, K)`: short-axis travel (radius) and long-axis length.
    pub run_out: Option<(f64, f64)>,
    /// Lead, mm (inch) per revolution.
    pub lead: f64,
    /// d: finishing allowance, radius.
    pub allowance: f64,
}

impl FloatCycle {
    /// The `f64` form of `c`, or `None` for what this baseline does not
    /// model: infeed D1/D2, a lead-in, an X long axis, a start point on or
    /// inside the thread, a zero lead.
    #[must_use]
    pub fn from_cycle(c: &G76Cycle) -> Option<FloatCycle> {
        if c.infeed != Infeed::RightFlank || c.lead_in != 0 || c.lead.mantissa == 0 {
            return None;
        }
        let per_unit = to_f64(c.units.per_unit());
        let mm = |v: i64| to_f64(v) / per_unit;
        let xf = to_f64(c.x_mode.factor());
        let start = (mm(c.start.x), mm(c.start.z));
        let end = (mm(c.end.x), mm(c.end.z));
        let taper = mm(c.taper);
        if (end.1 - start.1).abs() <= taper.abs() || start.0 == end.0 + xf * taper {
            return None;
        }
        let run_out = match c.run_out {
            RunOut::None => None,
            RunOut::Amounts { short, long } => Some((mm(short), mm(long))),
            RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
                let lead = lead_units(c);
                let chamfer = round_to(f64::from(tenths_of_lead) * 0.1 * lead, per_unit);
                let short = round_to(chamfer * f64::from(angle_degrees).to_radians().tan(), per_unit);
                Some((short, long.map_or(chamfer, mm)))
            }
        };
        Some(FloatCycle {
            per_unit,
            xf,
            start,
            end,
            taper,
            height: mm(c.thread_height),
            first_depth: mm(c.first_depth),
            min_cut: mm(c.min_cut.max(1)),
            last: mm(c.thread_height - c.finishing_allowance),
            finishing_passes: c.finishing_passes,
            tan_half: (f64::from(c.tool_angle) / 2.0).to_radians().tan(),
            starts: c.starts,
            run_out: run_out.filter(|&(j, _)| j != 0.0),
            lead: lead_units(c),
            allowance: mm(c.finishing_allowance),
        })
    }

    /// Depth of the next rough level after `previous` (level `n`, 1-based).
    #[inline]
    #[must_use]
    pub fn next_depth(&self, n: u64, previous: f64) -> f64 {
        // n < 2^53: exact.
        #[allow(clippy::cast_precision_loss)]
        let law = self.first_depth * (n as f64).sqrt();
        round_to(law.max(previous + self.min_cut), self.per_unit).min(self.last)
    }

    /// Writes the rough depth schedule into `out` (cleared first).
    pub fn rough_depths(&self, out: &mut Vec<f64>) {
        out.clear();
        let mut depth = 0.0;
        let mut n = 0;
        while depth < self.last {
            n += 1;
            depth = self.next_depth(n, depth);
            out.push(depth);
        }
    }

    /// Writes every move of the cycle into `out` (cleared first) and
    /// returns their number.
    pub fn expand_into(&self, out: &mut Vec<FloatMove>) -> usize {
        out.clear();
        let mut depth = 0.0;
        let mut n = 0;
        while depth < self.last {
            n += 1;
            let previous = depth;
            depth = self.next_depth(n, depth);
            let path = self.path(depth, depth * self.tan_half);
            let pass = PassInfo {
                finish: false,
                number: u32::try_from(n).unwrap_or(u32::MAX),
                depth,
                cut: depth - previous,
            };
            for start in 0..self.starts {
                path.push_into(self, pass, start, out);
            }
        }
        let centre = self.last * self.tan_half;
        for m in 1..=self.finishing_passes {
            let path = self.path(self.height, centre);
            let cut = if m == 1 { self.allowance } else { 0.0 };
            let pass = PassInfo { finish: true, number: m, depth: self.height, cut };
            for start in 0..self.starts {
                path.push_into(self, pass, start, out);
            }
        }
        out.len()
    }

    /// The moves of the cycle, one at a time.
    #[must_use]
    pub fn moves(&self) -> FloatMoves {
        let mut it = FloatMoves {
            c: *self,
            n: 0,
            depth: 0.0,
            finishing: 0,
            start: 0,
            path: [(MoveKind::Rapid, 0.0, 0.0); 5],
            pass: PassInfo { finish: false, number: 0, depth: 0.0, cut: 0.0 },
            len: 0,
            step: 0,
            done: false,
        };
        it.next_pass();
        it
    }

    /// The path of a pass at `depth`, shifted `shift` along Z.
    fn path(&self, depth: f64, shift: f64) -> Path {
        let (a, d) = (self.start, self.end);
        let xf = self.xf;
        let c_x = d.0 + xf * self.taper;
        let s = if a.0 > c_x { 1.0 } else { -1.0 };
        let t = if d.1 > a.1 { 1.0 } else { -1.0 };
        let sink = s * xf * (self.height - depth);
        let bn = (c_x + sink, a.1 + t * shift);
        let end = (d.0 + sink, d.1);
        let mut moves = [(MoveKind::Rapid, bn.0, bn.1); 5];
        let len;
        let last = match self.run_out {
            None => {
                moves[1] = (MoveKind::Thread, end.0, end.1);
                len = 2;
                end
            }
            Some((j, k)) => {
                let zr = end.1 - t * k;
                let xr = bn.0 + (end.0 - bn.0) * (zr - bn.1) / (end.1 - bn.1);
                let jx = (xf * j).min(s * (a.0 - end.0));
                let last = (end.0 + s * jx, end.1);
                moves[1] = (MoveKind::Thread, xr, zr);
                moves[2] = (MoveKind::Thread, last.0, last.1);
                len = 3;
                last
            }
        };
        moves[len] = (MoveKind::Rapid, a.0, last.1);
        moves[len + 1] = (MoveKind::Rapid, a.0, a.1);
        Path { moves, len: len + 2 }
    }
}

/// The candidate moves of one pass.
#[derive(Clone, Copy, Debug)]
struct Path {
    moves: [PathPoint; 5],
    len: usize,
}

/// The pass a path belongs to.
#[derive(Clone, Copy, Debug)]
struct PassInfo {
    finish: bool,
    number: u32,
    depth: f64,
    cut: f64,
}

impl FloatCycle {
    /// The annotated move of a path point.
    #[inline]
    fn annotate(&self, p: PathPoint, pass: PassInfo, start: u32) -> FloatMove {
        FloatMove {
            kind: p.0,
            x: p.1,
            z: p.2,
            lead: self.lead,
            start_angle: 360.0 * f64::from(start) / f64::from(self.starts),
            finish: pass.finish,
            number: pass.number,
            start: u16::try_from(start + 1).unwrap_or(u16::MAX),
            depth: pass.depth,
            cut: pass.cut,
        }
    }
}

impl Path {
    /// Appends the moves that move, from A.
    fn push_into(&self, c: &FloatCycle, pass: PassInfo, start: u32, out: &mut Vec<FloatMove>) {
        let mut at = c.start;
        for &m in &self.moves[..self.len] {
            if (m.1, m.2) != at {
                at = (m.1, m.2);
                out.push(c.annotate(m, pass, start));
            }
        }
    }
}

/// The moves of a [`FloatCycle`], in order (see [`FloatCycle::moves`]).
#[derive(Clone, Debug)]
pub struct FloatMoves {
    c: FloatCycle,
    /// Rough levels so far.
    n: u64,
    /// Depth of the current rough level.
    depth: f64,
    /// Finishing passes so far.
    finishing: u32,
    /// Current start, 0-based.
    start: u32,
    path: [PathPoint; 5],
    pass: PassInfo,
    len: usize,
    step: usize,
    done: bool,
}

impl FloatMoves {
    fn next_pass(&mut self) {
        let p = if self.depth < self.c.last {
            self.n += 1;
            let previous = self.depth;
            self.depth = self.c.next_depth(self.n, self.depth);
            let number = u32::try_from(self.n).unwrap_or(u32::MAX);
            self.pass = PassInfo { finish: false, number, depth: self.depth, cut: self.depth - previous };
            self.c.path(self.depth, self.depth * self.c.tan_half)
        } else if self.finishing < self.c.finishing_passes {
            self.finishing += 1;
            let cut = if self.finishing == 1 { self.c.allowance } else { 0.0 };
            self.pass = PassInfo { finish: true, number: self.finishing, depth: self.c.height, cut };
            self.c.path(self.c.height, self.c.last * self.c.tan_half)
        } else {
            self.done = true;
            return;
        };
        self.path = p.moves;
        self.len = p.len;
        self.start = 0;
        self.step = 0;
    }
}

impl Iterator for FloatMoves {
    type Item = FloatMove;

    #[inline]
    fn next(&mut self) -> Option<FloatMove> {
        loop {
            if self.done {
                return None;
            }
            if self.step < self.len {
                let m = self.path[self.step];
                let at = if self.step == 0 {
                    self.c.start
                } else {
                    (self.path[self.step - 1].1, self.path[self.step - 1].2)
                };
                self.step += 1;
                if (m.1, m.2) != at {
                    return Some(self.c.annotate(m, self.pass, self.start));
                }
                continue;
            }
            self.start += 1;
            if self.start < self.c.starts {
                self.step = 0;
            } else {
                self.next_pass();
            }
        }
    }
}

/// `x` rounded to the increment `1 / per_unit`, half away from zero.
#[inline]
fn round_to(x: f64, per_unit: f64) -> f64 {
    (x * per_unit).round() / per_unit
}

/// An integer in increments as `f64` (exact below 2^53; every length of a
/// valid cycle is below 2^30).
#[allow(clippy::cast_precision_loss)]
fn to_f64(v: i64) -> f64 {
    v as f64
}

/// The lead in mm (inch) per revolution.
fn lead_units(c: &G76Cycle) -> f64 {
    let value = to_f64(i64::try_from(c.lead.mantissa).unwrap_or(i64::MAX))
        / 10_f64.powi(i32::try_from(c.lead.scale).unwrap_or(0));
    match (c.lead.word, c.units.unit) {
        (LeadWord::F | LeadWord::K, _) => value,
        (LeadWord::I, InputUnit::Metric) => 25.4 / value,
        (LeadWord::I, InputUnit::Inch) => 1.0 / value,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cases;
    use cycleref::moves::Motion;

    /// The engine's moves as `(kind, x, z)` in increments.
    fn engine(c: &G76Cycle) -> Vec<(MoveKind, i64, i64)> {
        cycleref::expand_g76(c)
            .expect("engine expands")
            .map(|m| {
                let kind = match m.motion {
                    Motion::Thread { .. } => MoveKind::Thread,
                    Motion::Rapid | Motion::Feed | Motion::Arc { .. } => MoveKind::Rapid,
                };
                (kind, m.to.x, m.to.z)
            })
            .collect()
    }

    /// Asserts that the `f64` moves of `c` are the engine's within `tol`
    /// increments, and that the buffer and the iterator agree exactly.
    fn agree(c: &G76Cycle, tol: f64) {
        let f = FloatCycle::from_cycle(c).expect("modelled");
        let mut buf = Vec::new();
        let n = f.expand_into(&mut buf);
        assert_eq!(n, buf.len());
        let streamed: Vec<FloatMove> = f.moves().collect();
        assert_eq!(streamed, buf, "iterator and buffer differ");
        let e = engine(c);
        assert_eq!(buf.len(), e.len(), "move count");
        for (i, (fm, em)) in buf.iter().zip(&e).enumerate() {
            assert_eq!(fm.kind, em.0, "kind of move {i}");
            #[allow(clippy::cast_precision_loss)]
            let (ex, ez) = (em.1 as f64, em.2 as f64);
            let (dx, dz) = ((fm.x * f.per_unit - ex).abs(), (fm.z * f.per_unit - ez).abs());
            assert!(dx <= tol && dz <= tol, "move {i}: f64 {fm:?}, engine {em:?} increments");
        }
    }

    #[test]
    fn m68x6_within_one_increment() {
        agree(&cases::m68x6(), 1.0);
    }

    #[test]
    fn benchmark_cases_within_one_increment() {
        agree(&cases::passes_1000(), 1.0);
        agree(&cases::eight_start(), 1.0);
        for n in [10, 100, 1_000, 10_000] {
            agree(&cases::flat(n), 1.0);
        }
    }

    #[test]
    fn schedule_matches_engine_depths() {
        let c = cases::passes_1000();
        let f = FloatCycle::from_cycle(&c).unwrap();
        let mut depths = Vec::new();
        f.rough_depths(&mut depths);
        let engine: Vec<i64> = cycleref::expand_g76(&c)
            .unwrap()
            .filter(|m| m.role == cycleref::Role::Approach)
            .filter_map(|m| m.pass.filter(|p| p.kind == cycleref::PassKind::Rough).map(|p| p.depth))
            .collect();
        assert_eq!(depths.len(), engine.len());
        for (d, e) in depths.iter().zip(&engine) {
            #[allow(clippy::cast_precision_loss)]
            let e = *e as f64;
            assert!((d * f.per_unit - e).abs() < 1e-6, "{d} vs {e}");
        }
    }

    #[test]
    fn refuses_what_it_does_not_model() {
        let mut c = cases::m68x6();
        c.infeed = Infeed::LeftRight;
        assert!(FloatCycle::from_cycle(&c).is_none());
        let mut c = cases::m68x6();
        c.lead_in = 1_000;
        assert!(FloatCycle::from_cycle(&c).is_none());
    }
}
