//! The native module `cycleref._cycleref` under the `cycleref` Python
//! package (python/cycleref/: the documented API, its types and stubs).
//!
//! Nothing here decides anything about programs or cycles: a program is a
//! [`Job`] of the command's library, read by the one pipeline
//! ([`cycleref_spec::pipeline`]) through [`Job::items`] and [`Job::expand`];
//! `check` is [`cycleref_cli::check`]; the vectors are
//! [`cycleref_cli::vectors::case_text`]. This module only turns the
//! results into Python values: lengths as `decimal.Decimal` built from the
//! fixed-point integers and the units' decimals (never through a float),
//! start angles as `fractions.Fraction`, and errors as the package's
//! exceptions with the command's message.
//!
//! The engine runs with the GIL released ([`Python::detach`]): a whole
//! program for `expand` and `check`, a batch of moves at a time for
//! `iter_moves`.

use std::collections::BTreeMap;
use std::collections::VecDeque;
use std::path::PathBuf;

use cycleref::{IncrementSystem, InputUnit, Motion, Move, Point, Role, Units};
use cycleref_cli::format::{flank_name, kind_name, lead_word, plunge_of, role_name};
use cycleref_cli::job::{Failure, Items, Job, Options, Profile};
use cycleref_spec::pipeline::{Cycle, Engine, Moves, RunError};
use cycleref_spec::ErrorKind;
use pyo3::create_exception;
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBytes, PyString, PyTuple, PyType};
use self_cell::self_cell;

create_exception!(
    cycleref,
    Error,
    PyValueError,
    "A program or trace that cycleref refuses (the base of ProgramError and CycleError)."
);
create_exception!(
    cycleref,
    ProgramError,
    Error,
    "The program reader refused a block: `line`, `word` (or None) and `rule` name it."
);
create_exception!(
    cycleref,
    CycleError,
    ProgramError,
    "A cycle raised its alarm: `line` is the line of the block that runs the cycle, `rule` is `cycle:NAME`."
);

/// The most moves `iter_moves` computes in one release of the GIL.
const BATCH: usize = 1024;

/// The most moves `expand()` returns: it holds every move as Python objects
/// (about 1 KB each), so a larger program is refused before any is built,
/// with a message that points to `iter_moves`, which has no such limit.
const MAX_EXPAND_MOVES: usize = 1_000_000;

/// The program argument: its text, or the path of its file.
enum Program {
    Text(Vec<u8>),
    File(PathBuf),
}

impl<'a, 'py> FromPyObject<'a, 'py> for Program {
    type Error = PyErr;

    fn extract(ob: Borrowed<'a, 'py, PyAny>) -> PyResult<Program> {
        if let Ok(s) = ob.cast::<PyString>() {
            return Ok(Program::Text(s.to_cow()?.as_bytes().to_vec()));
        }
        if let Ok(b) = ob.cast::<PyBytes>() {
            return Ok(Program::Text(b.as_bytes().to_vec()));
        }
        if let Ok(p) = ob.extract::<PathBuf>() {
            return Ok(Program::File(p));
        }
        Err(pyo3::exceptions::PyTypeError::new_err(
            "a program is its text (str or bytes) or the path of its file (os.PathLike)",
        ))
    }
}

/// The options every function takes, as the command's.
#[allow(clippy::too_many_arguments, clippy::fn_params_excessive_bools)]
fn options(
    profile: &str,
    increment: Option<&str>,
    inch: bool,
    radius: bool,
    params: Option<PathBuf>,
    readings: Option<BTreeMap<String, String>>,
    engine: &str,
) -> PyResult<Options> {
    let profile = match profile {
        "fanuc" => Profile::Fanuc,
        "gsk980" => Profile::Gsk980,
        "gsk988" => Profile::Gsk988,
        "linuxcnc" => Profile::LinuxCnc,
        p => {
            return Err(PyValueError::new_err(format!(
                "profile {p:?}: one of fanuc, gsk980, gsk988, linuxcnc"
            )))
        }
    };
    // None: the profile's own (IS-B; IS-C on linuxcnc).
    let increment = match increment {
        None => None,
        Some("is-b") => Some(IncrementSystem::IsB),
        Some("is-c") => Some(IncrementSystem::IsC),
        Some(i) => return Err(PyValueError::new_err(format!("increment {i:?}: one of is-b, is-c"))),
    };
    let engine = match engine {
        "impl" => Engine::Impl,
        "spec" => Engine::Spec,
        e => return Err(PyValueError::new_err(format!("engine {e:?}: one of impl, spec"))),
    };
    // `readings={"R-RUNOUT": "gsk988-only"}`: as `--reading ID=VALUE`,
    // winning over the parameter file's `[readings]`.
    let readings = readings.unwrap_or_default().into_iter().map(|(id, v)| format!("{id}={v}")).collect();
    Ok(Options { profile: Some(profile), increment, inch, radius, params, readings, engine, file: None })
}

/// The job of `program` with `opts` (a text is named `name` in messages).
fn job(program: Program, name: &str, opts: &Options) -> PyResult<Job> {
    if let Some(p) = &opts.params {
        opened(p)?;
    }
    let machine = cycleref_cli::job::machine(opts).map_err(|f| PyValueError::new_err(String::from(f)))?;
    match program {
        Program::Text(t) => Ok(Job::new(name, t, machine, opts.engine)),
        Program::File(p) => {
            opened(&p)?;
            Job::from_file(&p, machine, opts.engine).map_err(|f| PyOSError::new_err(String::from(f)))
        }
    }
}

/// A file that cannot be read as a program raises the `OSError` subclass of
/// its cause, with `errno`, `strerror` and `filename` set, as `open()` does
/// (`FileNotFoundError`, `PermissionError`, `IsADirectoryError`); an error
/// in what the file holds is a `ProgramError`.
fn opened(path: &std::path::Path) -> PyResult<()> {
    let os_error = |errno: i32, strerror: String| {
        PyOSError::new_err((errno, strerror, path.to_string_lossy().into_owned()))
    };
    let file = std::fs::File::open(path).map_err(|e| match e.raw_os_error() {
        Some(errno) => os_error(errno, strip_os_code(&e)),
        None => PyOSError::new_err(format!("{}: {e}", path.display())),
    })?;
    match file.metadata() {
        // EISDIR, as reading it would give.
        Ok(m) if m.is_dir() => Err(os_error(21, "Is a directory".to_owned())),
        _ => Ok(()),
    }
}

/// An I/O error's text without Rust's " (os error N)" suffix (Python
/// gives the number as `errno`).
fn strip_os_code(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.rfind(" (os error ") {
        Some(i) => text[..i].to_owned(),
        None => text,
    }
}

/// The Python exception of a failed first phase: the command's message,
/// with the line, word and rule of the error it comes from.
fn run_error(py: Python<'_>, failure: Failure, error: Option<RunError>) -> PyErr {
    let message = String::from(failure);
    let Some(error) = error else { return PyOSError::new_err(message) };
    // The stable kind the command prints as `error[KIND]` and the vectors
    // write.
    let rule = error.stable_kind();
    let (err, line, word) = match &error {
        RunError::Program(p) => {
            let err = if matches!(p.kind, ErrorKind::Cycle(_)) {
                CycleError::new_err(message)
            } else {
                ProgramError::new_err(message)
            };
            (err, p.line, p.word.clone())
        }
        RunError::Cycle { line, .. } => (CycleError::new_err(message), *line, None),
    };
    let value = err.value(py);
    let set = value
        .setattr("line", line)
        .and_then(|()| value.setattr("word", word))
        .and_then(|()| value.setattr("rule", rule));
    match set {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// A length of `decimals` decimals as `decimal.Decimal`, built from its
/// digits: `Decimal((sign, digits, -decimals))`.
fn decimal<'py>(py: Python<'py>, value: i64, decimals: u32) -> PyResult<Bound<'py, PyAny>> {
    static DECIMAL: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let digits: Vec<u8> = value.unsigned_abs().to_string().bytes().map(|b| b - b'0').collect();
    let exponent = -i64::from(decimals);
    let tuple = (u8::from(value < 0), PyTuple::new(py, digits)?, exponent);
    DECIMAL.import(py, "decimal", "Decimal")?.call1((tuple,))
}

fn point<'py>(py: Python<'py>, p: Point, d: u32) -> PyResult<Bound<'py, PyTuple>> {
    PyTuple::new(py, [decimal(py, p.x, d)?, decimal(py, p.z, d)?])
}

/// A move as the tuple `cycleref.Move` is made of: `(cycle, line, motion,
/// x, z, centre, role, lead, start_angle_millidegrees, sync, pass, plunge)`.
fn move_tuple<'py>(
    py: Python<'py>,
    code: &str,
    line: usize,
    m: &Move,
    u: Units,
) -> PyResult<Bound<'py, PyTuple>> {
    static FRACTION: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    let d = u.decimals();
    let none = || py.None().into_bound(py);
    let (motion, centre, lead, angle, sync) = match m.motion {
        Motion::Rapid => ("rapid", none(), none(), none(), none()),
        Motion::Feed => ("feed", none(), none(), none(), none()),
        Motion::Thread { lead, start_angle, sync } => (
            "thread",
            none(),
            lead_word(lead).into_pyobject(py)?.into_any(),
            FRACTION.import(py, "fractions", "Fraction")?.call1((start_angle.num, start_angle.den))?,
            sync.into_pyobject(py)?.to_owned().into_any(),
        ),
        Motion::Arc { centre, clockwise } => (
            if clockwise { "arc-cw" } else { "arc-ccw" },
            point(py, centre, d)?.into_any(),
            none(),
            none(),
            none(),
        ),
    };
    let pass = match m.pass {
        Some(p) => (
            kind_name(p.kind),
            p.number,
            p.start,
            decimal(py, p.depth, d)?,
            decimal(py, p.cut, d)?,
            flank_name(p.flank),
        )
            .into_pyobject(py)?
            .into_any(),
        None => none(),
    };
    let plunge = match m.role {
        Role::LayerChange(l) => (l, py.None()).into_pyobject(py)?.into_any(),
        r => match plunge_of(r) {
            Some(p) => (p.layer, p.number).into_pyobject(py)?.into_any(),
            None => none(),
        },
    };
    PyTuple::new(
        py,
        [
            code.into_pyobject(py)?.into_any(),
            line.into_pyobject(py)?.into_any(),
            motion.into_pyobject(py)?.into_any(),
            decimal(py, m.to.x, d)?,
            decimal(py, m.to.z, d)?,
            centre,
            role_name(m.role).into_pyobject(py)?.into_any(),
            lead,
            angle,
            sync,
            pass,
            plunge,
        ],
    )
}

/// One cycle of `expand`, computed with the GIL released.
struct CycleData {
    code: &'static str,
    line: usize,
    params_line: Option<usize>,
    from: Option<Point>,
    start: Point,
    units: Units,
    moves: Vec<Move>,
}

fn unit_name(u: Units) -> &'static str {
    match u.unit {
        InputUnit::Metric => "mm",
        InputUnit::Inch => "inch",
    }
}

/// Why [`expand_job`] failed.
enum ExpandFailure {
    /// The program's own failure (the command's), with its error.
    Run(Failure, Option<RunError>),
    /// More moves than [`MAX_EXPAND_MOVES`]: the message.
    TooManyMoves(String),
}

impl ExpandFailure {
    fn into_py(self, py: Python<'_>) -> PyErr {
        match self {
            ExpandFailure::Run(f, e) => run_error(py, f, e),
            ExpandFailure::TooManyMoves(message) => Error::new_err(message),
        }
    }
}

/// Every cycle of `job` with its moves (both phases of the command).
fn expand_job(job: &Job) -> Result<(Units, Vec<CycleData>), ExpandFailure> {
    let units = job.validate_run().map_err(|(f, e)| ExpandFailure::Run(f, e))?.units;
    let mut cycles = Vec::new();
    let mut total = 0_usize;
    job.for_each_item(
        |f| ExpandFailure::Run(f, None),
        |item| {
            let Some(cycle) = Cycle::of(item) else { return Ok(()) };
            let (params_line, from, start) = (cycle.params_line(), cycle.tool_before_start(), cycle.start());
            // Expanded once, and held only up to the limit: a program beyond
            // it is refused once the move past the limit is reached.
            let mut moves = Vec::new();
            for m in job.expand(cycle).map_err(|f| ExpandFailure::Run(f, None))? {
                total += 1;
                if total > MAX_EXPAND_MOVES {
                    return Err(ExpandFailure::TooManyMoves(format!(
                        "{}: line {}: the expansion exceeds {MAX_EXPAND_MOVES} moves by this {}; expand() \
                         returns at most {MAX_EXPAND_MOVES}: use iter_moves(), which streams them",
                        job.name,
                        cycle.line(),
                        cycle.code()
                    )));
                }
                moves.push(m);
            }
            cycles.push(CycleData {
                code: cycle.code(),
                line: cycle.line(),
                params_line,
                from,
                start,
                units: cycle.units(),
                moves,
            });
            Ok(())
        },
    )?;
    Ok((units, cycles))
}

/// `expand`: `(unit, decimals, [(code, line, params_line, from, start,
/// [move tuple])])`.
#[pyfunction]
#[pyo3(signature = (program, *, profile="gsk988", increment=None, inch=false, radius=false, params=None, readings=None, engine="impl", name="<string>"))]
#[allow(clippy::too_many_arguments, clippy::fn_params_excessive_bools)]
fn expand<'py>(
    py: Python<'py>,
    program: Program,
    profile: &str,
    increment: Option<&str>,
    inch: bool,
    radius: bool,
    params: Option<PathBuf>,
    readings: Option<BTreeMap<String, String>>,
    engine: &str,
    name: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    let opts = options(profile, increment, inch, radius, params, readings, engine)?;
    let job = job(program, name, &opts)?;
    let (units, cycles) = py.detach(|| expand_job(&job)).map_err(|e| e.into_py(py))?;
    let mut out = Vec::with_capacity(cycles.len());
    for c in cycles {
        let d = c.units.decimals();
        let moves = c
            .moves
            .iter()
            .map(|m| move_tuple(py, c.code, c.line, m, c.units))
            .collect::<PyResult<Vec<_>>>()?;
        let from = match c.from {
            Some(p) => point(py, p, d)?.into_any(),
            None => py.None().into_bound(py),
        };
        out.push((c.code, c.line, c.params_line, from, point(py, c.start, d)?, moves).into_pyobject(py)?);
    }
    (unit_name(units), units.decimals(), out).into_pyobject(py)
}

self_cell!(
    /// A job and the reader of its items, which borrows it.
    struct Reading {
        owner: Job,

        #[covariant]
        dependent: Items,
    }
);

/// The state of a [`MoveIter`]: the program's reader, positioned after the
/// current cycle, and that cycle's moves not taken yet.
struct Stream {
    reading: Reading,
    cycle: Option<(&'static str, usize, Units, Moves)>,
    ended: bool,
}

impl Stream {
    /// Up to [`BATCH`] next moves into `out`.
    fn fill(&mut self, out: &mut VecDeque<(&'static str, usize, Units, Move)>) -> Result<(), Failure> {
        while out.len() < BATCH && !self.ended {
            if let Some((code, line, units, moves)) = &mut self.cycle {
                if let Some(m) = moves.next() {
                    out.push_back((code, *line, *units, m));
                    continue;
                }
            }
            self.cycle = None;
            let cycle = &mut self.cycle;
            let next = self.reading.with_dependent_mut(|job, items| {
                items.next_with(|item| match Cycle::of(item) {
                    Some(c) => job.expand(c).map(|m| Some((c.code(), c.line(), c.units(), m))),
                    None => Ok(None),
                })
            });
            match next {
                None => self.ended = true,
                Some(Err(e)) => {
                    self.ended = true;
                    return Err(self.reading.borrow_owner().read_failure(&e));
                }
                Some(Ok(r)) => *cycle = r?,
            }
        }
        Ok(())
    }
}

/// The moves of a program, one at a time: holds the program (its text,
/// or its file, read a line at a time) and at most one cycle's engine and
/// [`BATCH`] moves, whatever the program's length.
#[pyclass(module = "cycleref._cycleref")]
struct MoveIter {
    stream: Stream,
    ready: VecDeque<(&'static str, usize, Units, Move)>,
    /// An error met after the moves in `ready`: raised once they are taken.
    failed: Option<String>,
}

#[pymethods]
impl MoveIter {
    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__<'py>(&mut self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyTuple>>> {
        if self.ready.is_empty() {
            if let Some(message) = self.failed.take() {
                // Raised once, after the moves made before it; then the
                // iterator is exhausted.
                return Err(Error::new_err(message));
            }
            if !self.stream.ended {
                let (stream, ready) = (&mut self.stream, &mut self.ready);
                if let Err(f) = py.detach(|| stream.fill(ready)) {
                    self.stream.ended = true;
                    let message = String::from(f);
                    if self.ready.is_empty() {
                        return Err(Error::new_err(message));
                    }
                    self.failed = Some(message);
                }
            }
        }
        match self.ready.pop_front() {
            Some((code, line, units, m)) => move_tuple(py, code, line, &m, units).map(Some),
            None => Ok(None),
        }
    }
}

/// `iter_moves`: checks the whole program first (the command's first
/// phase), then an iterator over its moves.
#[pyfunction]
#[pyo3(signature = (program, *, profile="gsk988", increment=None, inch=false, radius=false, params=None, readings=None, engine="impl", name="<string>"))]
#[allow(clippy::too_many_arguments, clippy::fn_params_excessive_bools)]
fn iter_moves(
    py: Python<'_>,
    program: Program,
    profile: &str,
    increment: Option<&str>,
    inch: bool,
    radius: bool,
    params: Option<PathBuf>,
    readings: Option<BTreeMap<String, String>>,
    engine: &str,
    name: &str,
) -> PyResult<MoveIter> {
    let opts = options(profile, increment, inch, radius, params, readings, engine)?;
    let job = job(program, name, &opts)?;
    py.detach(|| job.validate_run()).map_err(|(f, e)| run_error(py, f, e))?;
    let reading = Reading::try_new(job, |j| j.items()).map_err(|f| PyOSError::new_err(String::from(f)))?;
    Ok(MoveIter {
        stream: Stream { reading, cycle: None, ended: false },
        ready: VecDeque::new(),
        failed: None,
    })
}

/// `check`: `(agree, divergences, text report, JSON report)`.
#[pyfunction]
#[pyo3(signature = (program, trace, *, tolerance=0, csv=false, profile="gsk988", increment=None, inch=false, radius=false, params=None, readings=None, engine="impl", name="<string>"))]
#[allow(clippy::too_many_arguments, clippy::fn_params_excessive_bools)]
fn check(
    py: Python<'_>,
    program: Program,
    trace: Program,
    tolerance: u64,
    csv: bool,
    profile: &str,
    increment: Option<&str>,
    inch: bool,
    radius: bool,
    params: Option<PathBuf>,
    readings: Option<BTreeMap<String, String>>,
    engine: &str,
    name: &str,
) -> PyResult<(bool, usize, String, String)> {
    let opts = options(profile, increment, inch, radius, params, readings, engine)?;
    let job = job(program, name, &opts)?;
    // The program's own errors are raised with their line, word and rule.
    py.detach(|| job.validate_run()).map_err(|(f, e)| run_error(py, f, e))?;
    if let Program::File(path) = &trace {
        opened(path)?;
    }
    let report = py
        .detach(|| match &trace {
            Program::Text(bytes) => cycleref_cli::check::check_bytes(&job, bytes, csv, tolerance),
            Program::File(path) => cycleref_cli::check::run(&job, path, tolerance),
        })
        .map_err(|f| Error::new_err(String::from(f)))?;
    Ok((report.agree(), report.divergences(), report.text(), report.json()))
}

/// `vectors`: the text of case `index` of the corpus of `seed`.
#[pyfunction]
fn vector_case(py: Python<'_>, seed: u64, index: u32) -> PyResult<String> {
    py.detach(|| cycleref_cli::vectors::case_text(seed, index))
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// The native module.
#[pymodule]
fn _cycleref(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    // The package's version: the crates' (0.2.0), one number for all.
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("Error", py.get_type::<Error>())?;
    m.add("ProgramError", py.get_type::<ProgramError>())?;
    m.add("CycleError", py.get_type::<CycleError>())?;
    m.add_function(wrap_pyfunction!(expand, m)?)?;
    m.add_function(wrap_pyfunction!(iter_moves, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(vector_case, m)?)?;
    m.add_class::<MoveIter>()?;
    Ok(())
}
