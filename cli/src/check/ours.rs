//! Our toolpath as a stream of steps: the program's own motion blocks, as
//! the program reader resolves them (`Follow`, which makes the steps of a
//! trace read by the same reader in its trace mode too), and its cycles'
//! expanded moves, each annotated with the cycle, pass and point it is.
//! Also the regions the cycles cut, against which a split rapid is judged
//! (reading R-CHECKSPLIT).

use std::cell::OnceCell;
use std::collections::VecDeque;

use cycleref::units::MAX_LENGTH;
use cycleref::{Motion, Move, Point, StartAngle, Units, XMode};
use cycleref_spec::cycles::{Annotations, Region};
use cycleref_spec::lex::{Block, Word};
use cycleref_spec::pipeline::{Cycle, Engine, Moves, OwnedCycle};
use cycleref_spec::profile::Dialect;
use cycleref_spec::reader::{length_word, G32Call, Item, MotionMode, PlainMove};
use cycleref_spec::Machine;
use rust_decimal::Decimal;

use super::error::StepError;
use super::{Context, Kind, Step, UNKNOWN};
use crate::job::{Cause, Failure, Items, Job};

/// The X distance of an I word in X-word increments: I is a radius, and
/// may have one more decimal than the increment when X is a diameter (the
/// `nc` contract, `format::arc_ik`).
fn arc_i(machine: &Machine, units: Units, b: &Block, w: &Word) -> Result<i64, StepError> {
    let f = machine.x_mode.factor();
    let n = &w.number();
    let bare = machine.profile.bare_length_is_increments && !machine.calculator_input;
    let out = || StepError::CentreOutOfRange { line: b.line, word: w.text().to_string() };
    let radius_increments = if !n.has_point() && bare {
        Decimal::from(n.integer().ok_or_else(out)?)
    } else {
        let d = n.decimal().ok_or_else(out)?;
        d.checked_mul(Decimal::from(units.per_unit())).ok_or_else(out)?
    };
    let dx = radius_increments.checked_mul(Decimal::from(f)).ok_or_else(out)?;
    if !dx.fract().is_zero() {
        return Err(StepError::CentreNotInIncrements { line: b.line, word: w.text().to_string() });
    }
    let dx = i64::try_from(dx.trunc()).map_err(|_| out())?;
    if dx.unsigned_abs() > 2 * MAX_LENGTH.unsigned_abs() {
        return Err(out());
    }
    Ok(dx)
}

/// Steps of the moves the program reader resolves, for our program and for
/// a trace alike (one reader, one model of a move: the reader's
/// [`PlainMove`] and [`G32Call`], and the engine's moves of our cycles).
/// It holds only where the tool is, as the check holds it: X as written on
/// the FANUC-style profiles, a diameter on the linuxcnc profile, whose
/// programs switch between G7 and G8 (reading R-CHECKLCNC).
pub(super) struct Follow<'m> {
    machine: &'m Machine,
    units: Units,
    linuxcnc: bool,
    /// The end of the latest step (or a cycle's start), as held.
    at: (Option<i64>, Option<i64>),
}

impl<'m> Follow<'m> {
    /// Reading R-G75ARC `front-post`: G02/G03 exchanged.
    fn front_post(&self) -> bool {
        self.machine.readings.arc_names == cycleref_spec::readings::ArcNames::FrontPost
    }

    pub(super) fn new(machine: &'m Machine, units: Units) -> Follow<'m> {
        Follow { machine, units, linuxcnc: machine.profile.dialect == Dialect::LinuxCnc, at: (None, None) }
    }

    /// X as the check holds it (a radius doubles, exactly, on linuxcnc).
    fn held_x(&self, x: i64, mode: XMode) -> i64 {
        if self.linuxcnc && mode == XMode::Radius {
            x.saturating_mul(2)
        } else {
            x
        }
    }

    fn held(&self, (x, z): (Option<i64>, Option<i64>), mode: XMode) -> (Option<i64>, Option<i64>) {
        (x.map(|x| self.held_x(x, mode)), z)
    }

    /// The step of a block of plain motion; `None` for a block to where the
    /// tool is. A move before both axes are known is kept, with the axis
    /// not yet known as `UNKNOWN` (reading R-CHECKPARTIAL): it is compared
    /// on the axis it gives, and never dropped.
    pub(super) fn plain(&mut self, m: &PlainMove<'_>) -> Result<Option<Step>, StepError> {
        let (from, to) = (self.held(m.from, m.x_mode), self.held(m.to, m.x_mode));
        self.at = to;
        if from == to {
            return Ok(None);
        }
        let from = match from {
            (Some(x), Some(z)) => Some(Point::new(x, z)),
            _ => None,
        };
        let kind = match m.motion {
            MotionMode::G00 => Kind::Rapid,
            MotionMode::G01 => Kind::Feed,
            // Reading R-G75ARC: under `front-post` the trace's G02 is
            // counter-clockwise seen with +Z right and +X up.
            MotionMode::G02 if self.front_post() => Kind::ArcCcw,
            MotionMode::G03 if self.front_post() => Kind::ArcCw,
            MotionMode::G02 => Kind::ArcCw,
            MotionMode::G03 => Kind::ArcCcw,
            // The reader makes G32 and G92 blocks cycles, never plain
            // moves; were one given, it is refused, not compared as
            // something else.
            MotionMode::G32 | MotionMode::G92 => {
                return Err(StepError::ThreadNotPlain { line: m.block.line });
            }
        };
        let centre = if kind.is_arc() { Some(self.centre(&m.block, from)?) } else { None };
        Ok(Some(Step {
            kind,
            from,
            to: Point::new(to.0.unwrap_or(UNKNOWN), to.1.unwrap_or(UNKNOWN)),
            centre,
            lead: None,
            angle: StartAngle::ZERO,
            sync: false,
            context: Context::Source { line: m.block.line },
        }))
    }

    /// The step of a thread block of a trace (a G32 or G33 without
    /// run-out: the reader's trace mode refuses J and K).
    pub(super) fn thread(&mut self, call: &G32Call<'_>) -> Step {
        let g = &call.g32;
        let (from, to) = (g.start, g.end);
        let to = Point::new(self.held_x(to.x, g.x_mode), to.z);
        self.at = (Some(to.x), Some(to.z));
        Step {
            kind: Kind::Thread,
            from: Some(Point::new(self.held_x(from.x, g.x_mode), from.z)),
            to,
            centre: None,
            lead: Some(g.lead),
            angle: if g.sync { g.start_angle } else { StartAngle::ZERO },
            sync: g.sync,
            context: Context::Source { line: call.block.line },
        }
    }

    /// A cycle of ours starts at `from` (its block's start).
    fn start_cycle(&mut self, from: Point, x_mode: XMode) {
        self.at = (Some(self.held_x(from.x, x_mode)), Some(from.z));
    }

    /// An arc's centre from its I and K (an omitted one is 0); R is refused
    /// (reading R-CHECKARC), and an arc without I, K or R is an error.
    fn centre(&self, b: &Block, from: Option<Point>) -> Result<Point, StepError> {
        let pe = StepError::Program;
        let g = b.all('G').find(|g| matches!(g.number().integer(), Some(2 | 3)));
        if let Some(r) = b.get('R').map_err(pe)? {
            return Err(StepError::ArcByRadius { line: b.line, word: r.text().to_string() });
        }
        let (i, k) = (b.get('I').map_err(pe)?, b.get('K').map_err(pe)?);
        let word = || g.map(|g| g.text().to_string());
        if i.is_none() && k.is_none() {
            return Err(StepError::ArcWithoutCentre { line: b.line, word: word() });
        }
        let Some(from) = from else {
            return Err(StepError::ArcStartUnknown { line: b.line, word: word() });
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

    /// One of our expanded moves, in the X mode of its cycle's block;
    /// `None` for a move to where the tool is (LinuxCNC's G76 ends with a
    /// rapid of no length when X is not programmed).
    fn cycle_move(&mut self, m: &Move, context: Context, x_mode: XMode) -> Option<Step> {
        let to = Point::new(self.held_x(m.to.x, x_mode), m.to.z);
        let from = match self.at {
            (Some(x), Some(z)) => Some(Point::new(x, z)),
            _ => None,
        };
        if from == Some(to) {
            return None;
        }
        self.at = (Some(to.x), Some(to.z));
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
        Some(Step { kind, from, to, centre, lead, angle, sync, context })
    }
}

/// One of our latest cycles, and the regions it cuts (reading
/// R-CHECKSPLIT).
pub(super) enum RecentCycle {
    /// A cycle of the program: its regions are found when a split rapid
    /// first needs them, by the engine in use, and kept.
    Lazy {
        /// The cycle, detached from the program's text.
        cycle: Box<OwnedCycle>,
        /// The engine that expands it.
        engine: Engine,
        /// Its regions once found; `None` inside when they cannot be.
        regions: OnceCell<Option<Vec<Region>>>,
    },
    /// Regions given as they are.
    #[cfg(test)]
    Known(Vec<Region>),
}

impl RecentCycle {
    /// The regions the cycle cuts; `None` when they cannot be found (the
    /// cycle's alarm, which its expansion, made first, would have raised:
    /// not expected). A split rapid is then judged to go through the work:
    /// an unknown region never turns a difference into agreement.
    fn regions(&self) -> Option<&[Region]> {
        match self {
            RecentCycle::Lazy { cycle, engine, regions } => regions
                .get_or_init(|| {
                    let mut out = Vec::new();
                    cycle.cycle().regions(*engine, &mut out).ok().map(|()| out)
                })
                .as_deref(),
            #[cfg(test)]
            RecentCycle::Known(r) => Some(r),
        }
    }
}

/// The regions of our latest cycles, which a split rapid must stay out of
/// (reading R-CHECKSPLIT).
#[derive(Clone, Copy)]
pub(super) struct Regions<'r>(pub(super) &'r VecDeque<RecentCycle>);

impl Regions<'_> {
    /// True when `hit` holds for a region, or when a cycle's regions could
    /// not be found.
    pub(super) fn any(&self, hit: impl Fn(&Region) -> bool) -> bool {
        self.0.iter().any(|c| c.regions().is_none_or(|rs| rs.iter().any(&hit)))
    }
}

/// How many cycles' regions are kept for judging split rapids: the cycle
/// being compared and its neighbours.
const REGION_CYCLES: usize = 3;

/// The cycle whose moves are being taken.
struct Running {
    moves: Moves,
    /// The cycle's G code.
    code: &'static str,
    line: usize,
    /// What the cycle's moves carry besides their role.
    annotations: Annotations,
    /// The X mode of the cycle's moves.
    x_mode: XMode,
}

/// Our toolpath, a step at a time: the program's motion blocks and its
/// expanded cycles, each step with the number of the segment it belongs to
/// (a cycle, or the blocks between two cycles).
pub(super) struct OurSteps<'j> {
    job: &'j Job,
    items: Items<'j>,
    follow: Follow<'j>,
    current: Option<Running>,
    segment: u32,
    /// The latest cycles, whose regions split rapids are judged against.
    pub(super) recent: VecDeque<RecentCycle>,
    /// Only the cycles' moves are steps (reading R-CHECKCYCLES); the
    /// program's own blocks only move the tool.
    cycles_only: bool,
}

impl<'j> OurSteps<'j> {
    pub(super) fn new(job: &'j Job, units: Units, cycles_only: bool) -> Result<OurSteps<'j>, Failure> {
        Ok(OurSteps {
            job,
            items: job.items()?,
            follow: Follow::new(&job.machine, units),
            current: None,
            segment: 0,
            recent: VecDeque::new(),
            cycles_only,
        })
    }

    fn step(&mut self) -> Option<Result<(Step, u32), Failure>> {
        loop {
            if let Some(run) = &mut self.current {
                if let Some(m) = run.moves.next() {
                    let (line, role) = (run.line, m.role);
                    let context = Context::Cycle {
                        code: run.code,
                        line,
                        role,
                        pass: m.pass,
                        annotations: run.annotations,
                    };
                    // A move to where the tool is, is no move, in our
                    // toolpath as in a trace.
                    match self.follow.cycle_move(&m, context, run.x_mode) {
                        Some(step) => return Some(Ok((step, self.segment))),
                        None => continue,
                    }
                }
                self.current = None;
                self.segment += 1;
                continue;
            }
            let (job, follow, segment, cycles_only) =
                (self.job, &mut self.follow, self.segment, self.cycles_only);
            let (recent, current) = (&mut self.recent, &mut self.current);
            let next = self.items.next_with(|item| -> Result<Option<(Step, u32)>, Failure> {
                let Some(cycle) = Cycle::of(item) else {
                    let Item::Move(m) = item else { return Ok(None) };
                    return match follow.plain(m) {
                        Ok(step) => Ok(step.filter(|_| !cycles_only).map(|s| (s, segment))),
                        Err(e) => Err(Failure::with_kind(
                            Cause::Check,
                            e.stable_kind(),
                            format!("{}: {e}", job.name),
                        )),
                    };
                };
                let moves = job.expand(cycle)?;
                follow.start_cycle(cycle.from(), cycle.x_mode());
                if recent.len() == REGION_CYCLES {
                    recent.pop_front();
                }
                // Its regions are found only if a split rapid needs them:
                // most comparisons never do, and the cycle is expanded once.
                recent.push_back(RecentCycle::Lazy {
                    cycle: Box::new(cycle.detached()),
                    engine: job.engine,
                    regions: OnceCell::new(),
                });
                *current = Some(Running {
                    moves,
                    code: cycle.code(),
                    line: cycle.line(),
                    x_mode: cycle.x_mode(),
                    annotations: cycle.annotations(),
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
                Err(e) => return Some(Err(self.job.read_failure(&e))),
            }
        }
    }
}

impl Iterator for OurSteps<'_> {
    type Item = Result<(Step, u32), Failure>;

    fn next(&mut self) -> Option<Self::Item> {
        self.step()
    }
}
