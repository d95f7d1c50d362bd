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
//!
//! ## How data flows through this module
//!
//! Two streams of steps meet in the alignment, a window at a time, and
//! only the divergences are kept:
//!
//! * `ours`: our steps, from the program's plain moves as the program
//!   reader resolves them (`Follow`) and its expanded cycles, each
//!   annotated, and the regions the cycles cut;
//! * `trace`: their steps, read as they are taken from an expanded
//!   program (by the program reader in its trace mode, and `Follow`), a CSV
//!   or LinuxCNC's canonical output;
//! * `align`: both streams made into groups (passes), and our groups
//!   aligned a window at a time with theirs by edit distance
//!   (`compare_streams` drives the whole comparison);
//! * `compare`: an aligned pair of groups compared move by move, each
//!   difference a divergence;
//! * `report`: the divergences counted and listed, written as text or
//!   JSON, or as the marks `plot --trace` draws.
//!
//! This module holds the types they share (`Kind`, `Context`, `Step`,
//! `Group`, `Divergence`) and the entry points: [`run`], [`check_bytes`],
//! [`check_bytes_as`], and for `plot --trace` the trace's points and the
//! marks of its divergences (`trace_points`, `marks`). Its errors are typed
//! (`error`): a trace's `TraceError` and a block's `StepError`, each printed
//! with the rule's stable kind.

mod align;
mod compare;
mod error;
mod fast_nc;
mod ours;
mod report;
#[cfg(test)]
mod test_steps;
mod trace;

use std::path::Path;

use cycleref::{Lead, Pass, Point, Role, StartAngle, Units};
use cycleref_spec::cycles::Annotations;

use crate::job::{Failure, Job};

use align::{compare_streams, StreamError};
pub use report::{Mark, Report, MAX_LISTED};
use trace::{format_of, open_trace, trace_steps};

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
    /// A move of one of our cycles: its G code, the line of the block
    /// that runs it, the move's role and pass, and what the cycle's moves
    /// carry ([`Annotations`]), which the report names them by.
    Cycle { code: &'static str, line: usize, role: Role, pass: Option<Pass>, annotations: Annotations },
}

/// The coordinate of an axis not known yet: a move made before the
/// position is known on both axes (no G50, and an X-only first move) is
/// kept with this for the other axis (reading R-CHECKPARTIAL). No length
/// within the range tables is this value, so it equals only itself and is
/// beyond every tolerance from any known coordinate.
pub(crate) const UNKNOWN: i64 = i64::MIN;

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

/// The trace at `trace` (a file, read by its extension) as the points its
/// moves reach, in order, with its name: what `plot --trace` draws.
///
/// # Errors
///
/// The trace cannot be opened, or is not of the program's dialect; each
/// point a trace error with its line.
pub(crate) fn trace_points<'m>(
    job: &'m Job,
    trace: &Path,
    units: Units,
) -> Result<(String, impl Iterator<Item = Result<Point, Failure>> + 'm), Failure> {
    let format = format_of(trace);
    let (name, source) = open_trace(trace, format).map_err(|e| e.failure(None))?;
    let steps = trace_steps(source, format, &job.machine, units).map_err(|e| e.failure(Some(&name)))?;
    let named = name.clone();
    let points = steps.map(move |s| s.map(|(step, _)| step.to).map_err(|e| e.failure(Some(&named))));
    Ok((name, points))
}

/// Where `job`'s program and the trace at `trace` diverge, at tolerance 0:
/// the marks `plot --trace` draws.
///
/// # Errors
///
/// As [`run`].
pub(crate) fn marks(job: &Job, trace: &Path, units: Units) -> Result<Vec<Mark>, Failure> {
    Ok(compare_file(job, trace, format_of(trace), units, 0, false)?.marks())
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

/// Runs the comparison of `job`'s program with the trace at `trace` (`-`:
/// standard input; `.csv`: a CSV).
///
/// # Errors
///
/// The program's first error, or the trace's, with its line.
pub fn run(job: &Job, trace: &Path, tolerance: u64) -> Result<Report, Failure> {
    run_as(job, trace, &CheckOptions { tolerance, ..CheckOptions::default() })
}

/// How [`run_as`] reads and compares the trace.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CheckOptions {
    /// The trace's format (`--trace-format`); `None`: by the file's
    /// extension (`.csv`, `.canon`, anything else an expanded program).
    /// Standard input (`-`) can be any of the three when it is given.
    pub format: Option<TraceFormat>,
    /// Largest difference, in least increments, still counted as equal.
    pub tolerance: u64,
    /// Compare only the moves inside cycles (`--cycles-only`): the
    /// program's own blocks are followed for the position but not
    /// expected in the trace, for a vendor who logs only a cycle's moves
    /// (reading R-CHECKCYCLES).
    pub cycles_only: bool,
}

/// [`run`] with its options.
///
/// # Errors
///
/// The program's first error, or the trace's, with its line.
pub fn run_as(job: &Job, trace: &Path, options: &CheckOptions) -> Result<Report, Failure> {
    if trace == Path::new("-") && job.name == crate::job::STDIN_NAME {
        job.validate()?;
        return Err(Failure::usage("the program and the trace cannot both come from standard input"));
    }
    let units = job.units()?;
    let format = options.format.unwrap_or_else(|| format_of(trace));
    compare_file(job, trace, format, units, options.tolerance, options.cycles_only)
        .map_err(|e| program_error_first(job, e))
}

/// `check` in one phase (reading R-STREAM): its report is written only
/// after the comparison, so no validation phase is needed for "nothing
/// half-written". The comparison reads the whole program in order and
/// expands every cycle as the validation would, so it meets the program's
/// first error exactly where the validation does; an error of the trace
/// (or of opening it) may come first, and then the validation is run after
/// all, so that a program error still wins and every message is the one a
/// validation phase first would have given.
fn program_error_first(job: &Job, e: Failure) -> Failure {
    match job.validate() {
        Err(program) => program,
        Ok(_) => e,
    }
}

/// What [`run`] does once it has the program's `units`.
fn compare_file(
    job: &Job,
    trace: &Path,
    format: TraceFormat,
    units: Units,
    tolerance: u64,
    cycles_only: bool,
) -> Result<Report, Failure> {
    let (name, source) = open_trace(trace, format).map_err(|e| e.failure(None))?;
    compare_streams(job, source, format, units, tolerance, cycles_only).map_err(|e| match e {
        StreamError::Ours(e) => e,
        StreamError::Theirs(e) => e.failure(Some(&name)),
    })
}

/// The comparison of `job`'s program with a trace given as bytes (`.nc`
/// text, or CSV when `is_csv`): what `run` does after opening the file.
/// The fuzz target `check_trace` and the property tests call it.
///
/// # Errors
///
/// Our expansion's error, or the trace's, with its line.
///
/// ```
/// use cycleref_cli::{check, Job};
/// use cycleref_spec::pipeline::Engine;
/// use cycleref_spec::{Machine, ProfileName};
///
/// let text = b"M03 S500\nG00 X80 Z10\nG32 Z-20 F2\nG00 X90\n";
/// let job = Job::new("g32.nc", text.to_vec(), Machine::new(ProfileName::Gsk980), Engine::Impl);
/// let same = check::check_bytes(&job, b"G00 X80 Z10\nG32 Z-20 F2\nG00 X90\n", false, 0)?;
/// assert!(same.agree());
/// // The thread cut at another lead.
/// let lead = check::check_bytes(&job, b"G00 X80 Z10\nG32 Z-20 F2.1\nG00 X90\n", false, 0)?;
/// assert_eq!((lead.agree(), lead.divergences()), (false, 1));
/// assert!(lead.first_divergence().unwrap().contains("(lead)"));
/// # Ok::<(), cycleref_cli::Failure>(())
/// ```
pub fn check_bytes(job: &Job, bytes: &[u8], is_csv: bool, tolerance: u64) -> Result<Report, Failure> {
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
) -> Result<Report, Failure> {
    let units = job.units()?;
    compare_streams(job, Box::new(bytes), format, units, tolerance, false)
        .map_err(|e| match e {
            StreamError::Ours(e) => e,
            StreamError::Theirs(e) => e.failure(None),
        })
        .map_err(|e| program_error_first(job, e))
}
