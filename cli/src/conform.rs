//! `cycleref conform`: a vendor's outputs run against a corpus of
//! conformance vectors (`cycleref vectors`), one verdict per case, with a
//! summary and JUnit XML for CI systems.
//!
//! Each case (`case-NNNN.json`, schema `cycleref-vector/1`) holds a
//! program, its machine and what must happen: its moves, or a refusal.
//! The vendor's outcome for a case is either a trace (an expanded program,
//! a CSV or LinuxCNC's canonical output, compared with ours as `check`
//! compares it) or a refusal:
//!
//! * `--traces DIR`: the trace is `DIR/case-NNNN.nc`, `.csv` or `.canon`;
//!   a file `DIR/case-NNNN.error` (holding the vendor's message) says the
//!   vendor refused the program;
//! * `--run TEMPLATE`: a shell command run per case, with the placeholders
//!   `{program}` (the case's program, written to a file), `{params}` (its
//!   machine as a parameter file), `{profile}` and `{trace}` (where the
//!   command writes its trace); exit status 0 gives a trace, any other a
//!   refusal (its standard error is the message).
//!
//! * `--pairs`: the corpus is a list of programs and their traces, one
//!   pair a line (`PROGRAM TRACE [PROFILE]`, tab- or space-separated, `#`
//!   comments): a batch `check`, each program expected to read and each
//!   trace to agree with its expansion.
//!
//! A case passes when the trace agrees with the expected moves, or when a
//! refusal was expected and made. Case `i` depends only on the corpus, so
//! `--shard I/N` (the cases whose index is I modulo N, 1-based) splits a
//! corpus across machines with no coordination, and `--jobs` runs the
//! cases of a shard on that many threads. Memory does not grow with the
//! number of cases: verdicts are written as they come, in case order, and
//! the JUnit body goes to a file beside the report until the counts for
//! its header are known.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::fs;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Instant;

use cycleref_spec::pipeline::Engine;
use cycleref_spec::profile::ParamsError;
use cycleref_spec::{Machine, ProfileName};
use serde_json::Value;

use crate::check::{self, CheckOptions, TraceFormat};
use crate::job::{Cause, Failure, Job};

/// Where the vendor's outcome of each case comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcomes {
    /// A directory of `case-NNNN.nc|csv|canon` traces and
    /// `case-NNNN.error` refusals.
    Dir(PathBuf),
    /// A shell command run per case (the placeholders `{program}`,
    /// `{params}`, `{profile}`, `{trace}`).
    Run(String),
    /// The corpus is a list of program and trace pairs (a batch `check`):
    /// each program is read with the pair's profile (its defaults), or
    /// with `machine`, and must agree with its trace.
    Pairs {
        /// The machine of a pair that names no profile (the command's
        /// `--profile` and `--params`).
        machine: Box<Machine>,
    },
}

/// One part of a corpus split across machines: the cases whose 1-based
/// index `i` has `(i - 1) % count == index - 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// Which part, from 1.
    pub index: u32,
    /// How many parts.
    pub count: u32,
}

impl Shard {
    /// The whole corpus.
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Reads `I/N` (1 ≤ I ≤ N).
    ///
    /// # Errors
    ///
    /// [`ConformError::Shard`]: a text that is not `I/N` with 1 ≤ I ≤ N.
    pub fn parse(text: &str) -> Result<Shard, ConformError> {
        let bad = || ConformError::Shard { text: text.to_string() };
        let (i, n) = text.split_once('/').ok_or_else(bad)?;
        let (index, count) =
            (i.trim().parse::<u32>().map_err(|_| bad())?, n.trim().parse::<u32>().map_err(|_| bad())?);
        if index == 0 || index > count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }

    fn holds(self, case: u32) -> bool {
        case >= 1 && (case - 1) % self.count == self.index - 1
    }
}

/// What [`run`] does.
#[derive(Clone, Debug)]
pub struct ConformOptions {
    /// The corpus directory (`case-NNNN.json` files), or with
    /// [`Outcomes::Pairs`] the list of pairs.
    pub corpus: PathBuf,
    /// The vendor's outcomes.
    pub outcomes: Outcomes,
    /// The format of the traces a `--run` command writes (`None`: an
    /// expanded program, or by the file's extension in a directory).
    pub trace_format: Option<TraceFormat>,
    /// Largest difference, in least increments, still counted as equal.
    pub tolerance: u64,
    /// Compare only the moves inside cycles (as `check --cycles-only`).
    pub cycles_only: bool,
    /// The part of the corpus to run.
    pub shard: Shard,
    /// Threads (at least 1).
    pub jobs: usize,
    /// Where to write JUnit XML, if anywhere.
    pub junit: Option<PathBuf>,
}

/// The counts of a run. It passed when every case passed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Cases run.
    pub cases: usize,
    /// The trace agreed, or the expected refusal was made.
    pub passed: usize,
    /// The trace differs from the expected moves.
    pub failed: usize,
    /// A refusal was expected, and a trace was given.
    pub refusal_missing: usize,
    /// A trace was expected, and the vendor refused the program.
    pub refusal_unexpected: usize,
    /// The case could not be run: no trace, an unreadable trace or case,
    /// a command that could not start.
    pub errors: usize,
}

impl Summary {
    /// True when every case passed.
    #[must_use]
    pub fn all_passed(&self) -> bool {
        self.passed == self.cases
    }
}

/// The verdict of one case.
#[derive(Clone, Debug, PartialEq, Eq)]
enum Verdict {
    Pass,
    /// The first lines of the report and its first divergence.
    Differ(String),
    /// The expected error kind.
    RefusalMissing(String),
    /// The vendor's message.
    RefusalUnexpected(String),
    Error(String),
}

struct CaseResult {
    id: String,
    description: String,
    verdict: Verdict,
    seconds: f64,
}

/// A case of the corpus.
struct Case {
    index: u32,
    source: Source,
}

/// Where a case is.
enum Source {
    /// A vector's file.
    Vector(PathBuf),
    /// A program, its trace, and perhaps a profile (a line of a list of
    /// pairs).
    Pair { program: PathBuf, trace: PathBuf, profile: Option<ProfileName> },
}

/// The cases of a list of pairs in `shard`, by line (case `i` is the
/// list's `i`-th pair). Paths are taken relative to the list's directory.
fn pairs(list: &Path, shard: Shard) -> Result<Vec<Case>, ConformError> {
    let text = fs::read_to_string(list).map_err(|e| ConformError::cannot_read(list, e))?;
    let dir = list.parent().unwrap_or(Path::new("."));
    let mut out = Vec::new();
    let mut index = 0_u32;
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or_default().trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = if line.contains('\t') {
            line.split('\t').map(str::trim).collect()
        } else {
            line.split_whitespace().collect()
        };
        let (program, trace, profile) = match fields.as_slice() {
            [p, t] => (p, t, None),
            [p, t, profile] => {
                let name =
                    ProfileName::ALL.into_iter().find(|x| x.to_string() == *profile).ok_or_else(|| {
                        ConformError::PairProfile {
                            list: list.display().to_string(),
                            line: n + 1,
                            profile: (*profile).to_string(),
                        }
                    })?;
                (p, t, Some(name))
            }
            _ => return Err(ConformError::PairFields { list: list.display().to_string(), line: n + 1 }),
        };
        index += 1;
        if shard.holds(index) {
            let source = Source::Pair { program: dir.join(program), trace: dir.join(trace), profile };
            out.push(Case { index, source });
        }
    }
    if index == 0 {
        return Err(ConformError::NoPairs { list: list.display().to_string() });
    }
    Ok(out)
}

/// The corpus's cases in `shard`, by index.
fn cases(corpus: &Path, shard: Shard) -> Result<Vec<Case>, ConformError> {
    let entries = fs::read_dir(corpus).map_err(|e| ConformError::cannot_read(corpus, e))?;
    let mut out = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|e| ConformError::cannot_read(corpus, e))?;
        let name = entry.file_name();
        let Some(name) = name.to_str() else { continue };
        let Some(digits) = name.strip_prefix("case-").and_then(|n| n.strip_suffix(".json")) else {
            continue;
        };
        let Ok(index) = digits.parse::<u32>() else { continue };
        if shard.holds(index) {
            out.push(Case { index, source: Source::Vector(entry.path()) });
        }
    }
    out.sort_by_key(|c| c.index);
    if out.is_empty() && shard == Shard::ALL {
        return Err(ConformError::NoCases { corpus: corpus.display().to_string() });
    }
    Ok(out)
}

/// A case as read from its file.
struct Vector {
    id: String,
    description: String,
    profile: String,
    machine_toml: String,
    program: String,
    /// The expected refusal's kind, or `None` for expected moves.
    refusal: Option<String>,
}

fn read_vector(path: &Path) -> Result<Vector, ConformError> {
    let text = fs::read_to_string(path).map_err(|e| ConformError::cannot_read(path, e))?;
    let v: Value = serde_json::from_str(&text)
        .map_err(|error| ConformError::NotJson { path: path.display().to_string(), error })?;
    let field = |field: &'static str| -> Result<String, ConformError> {
        v.get(field)
            .and_then(Value::as_str)
            .map(str::to_owned)
            .ok_or_else(|| ConformError::VectorField { path: path.display().to_string(), field })
    };
    if v.get("schema").and_then(Value::as_str) != Some("cycleref-vector/1") {
        return Err(ConformError::VectorSchema { path: path.display().to_string() });
    }
    let refusal = v.pointer("/expect/error/kind").and_then(Value::as_str).map(str::to_owned);
    if refusal.is_none() && v.pointer("/expect/moves").is_none() {
        return Err(ConformError::VectorExpect { path: path.display().to_string() });
    }
    Ok(Vector {
        id: field("id")?,
        description: field("description")?,
        profile: field("profile")?,
        machine_toml: field("machine_toml")?,
        program: field("program")?,
        refusal,
    })
}

/// The vendor's outcome of a case.
enum Outcome {
    Trace(PathBuf, Option<TraceFormat>),
    Refused(String),
}

/// At most this much of a vendor's message is kept.
const MESSAGE_CHARS: usize = 400;

/// A vendor's message on one line: its first line that is not blank, cut
/// to [`MESSAGE_CHARS`], `…` marking what was left out.
fn short(text: &str) -> String {
    let text = text.trim();
    let first = text.lines().map(str::trim).find(|l| !l.is_empty()).unwrap_or_default();
    let mut out: String = first.chars().take(MESSAGE_CHARS).collect();
    if out.len() < text.len() {
        out.push('…');
    }
    out
}

/// A path as one word of a POSIX shell command.
fn quoted(path: &Path) -> String {
    format!("'{}'", path.display().to_string().replace('\'', r"'\''"))
}

/// The case's outcome from the vendor: `work` is a directory for this
/// case's files (`--run`).
fn outcome(options: &ConformOptions, v: &Vector, work: &Path) -> Result<Outcome, ConformError> {
    match &options.outcomes {
        Outcomes::Pairs { .. } => Err(ConformError::VectorInPairs { id: v.id.clone() }),
        Outcomes::Dir(dir) => {
            let error = dir.join(format!("{}.error", v.id));
            let traces: Vec<(PathBuf, TraceFormat)> =
                [("nc", TraceFormat::Nc), ("csv", TraceFormat::Csv), ("canon", TraceFormat::Rs274)]
                    .into_iter()
                    .map(|(ext, f)| (dir.join(format!("{}.{ext}", v.id)), f))
                    .filter(|(p, _)| p.exists())
                    .collect();
            match (error.exists(), traces.as_slice()) {
                (true, []) => {
                    let message =
                        fs::read_to_string(&error).map_err(|e| ConformError::cannot_read(&error, e))?;
                    Ok(Outcome::Refused(short(&message)))
                }
                (false, [(p, f)]) => Ok(Outcome::Trace(p.clone(), Some(*f))),
                (false, []) => {
                    Err(ConformError::NoOutcome { id: v.id.clone(), dir: dir.display().to_string() })
                }
                _ => Err(ConformError::TwoOutcomes { id: v.id.clone(), dir: dir.display().to_string() }),
            }
        }
        Outcomes::Run(template) => {
            let ext = if v.profile == "linuxcnc" { "ngc" } else { "nc" };
            let program = work.join(format!("{}.{ext}", v.id));
            let params = work.join(format!("{}.toml", v.id));
            let trace = work.join(format!("{}-trace.{}", v.id, trace_extension(options.trace_format)));
            fs::write(&program, &v.program).map_err(|e| ConformError::cannot_write(&program, e))?;
            fs::write(&params, &v.machine_toml).map_err(|e| ConformError::cannot_write(&params, e))?;
            let command = template
                .replace("{program}", &quoted(&program))
                .replace("{params}", &quoted(&params))
                .replace("{profile}", &v.profile)
                .replace("{trace}", &quoted(&trace));
            let out = Command::new("sh")
                .arg("-c")
                .arg(&command)
                .stdin(Stdio::null())
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .output();
            // The case's files go once the command is done: the work
            // directory holds the cases in progress, not the corpus.
            let _ = fs::remove_file(&program);
            let _ = fs::remove_file(&params);
            let out = out.map_err(|error| ConformError::CannotRun { command: command.clone(), error })?;
            if out.status.success() {
                if !trace.exists() {
                    return Err(ConformError::NoTrace { command });
                }
                Ok(Outcome::Trace(trace, options.trace_format))
            } else {
                let code = out.status.code().map_or_else(|| "a signal".to_owned(), |c| format!("status {c}"));
                Ok(Outcome::Refused(short(&format!("({code}) {}", String::from_utf8_lossy(&out.stderr)))))
            }
        }
    }
}

fn trace_extension(format: Option<TraceFormat>) -> &'static str {
    match format {
        Some(TraceFormat::Csv) => "csv",
        Some(TraceFormat::Rs274) => "canon",
        Some(TraceFormat::Nc) | None => "nc",
    }
}

/// The machine of a case: its profile, then its parameter file.
fn machine(v: &Vector) -> Result<Machine, ConformError> {
    let profile = ProfileName::ALL
        .into_iter()
        .find(|p| p.to_string() == v.profile)
        .ok_or_else(|| ConformError::VectorProfile { profile: v.profile.clone() })?;
    let mut m = Machine::new(profile);
    m.apply_toml(&v.machine_toml).map_err(ConformError::MachineToml)?;
    Ok(m)
}

/// Runs one case.
fn run_case(options: &ConformOptions, case: &Case, work: &Path) -> CaseResult {
    let started = Instant::now();
    let (id, description, verdict) = match &case.source {
        Source::Vector(path) => match read_vector(path) {
            Err(e) => (format!("case-{:04}", case.index), String::new(), Verdict::Error(e.to_string())),
            Ok(v) => {
                let verdict = judge_vector(options, &v, work);
                (v.id, v.description, verdict)
            }
        },
        Source::Pair { program, trace, profile } => {
            let machine = match (profile, &options.outcomes) {
                (Some(p), _) => Machine::new(*p),
                (None, Outcomes::Pairs { machine }) => (**machine).clone(),
                (None, _) => Machine::new(ProfileName::Gsk988),
            };
            let verdict = match Job::from_file(program, machine, Engine::Impl) {
                Ok(job) => judge(options, &job, (trace.clone(), options.trace_format)),
                Err(e) => Verdict::Error(String::from(e)),
            };
            (program.display().to_string(), format!("trace {}", trace.display()), verdict)
        }
    };
    CaseResult { id, description, verdict, seconds: started.elapsed().as_secs_f64() }
}

fn judge_vector(options: &ConformOptions, v: &Vector, work: &Path) -> Verdict {
    let outcome = match outcome(options, v, work) {
        Ok(o) => o,
        Err(e) => return Verdict::Error(e.to_string()),
    };
    let trace = match (outcome, &v.refusal) {
        (Outcome::Refused(_), Some(_)) => return Verdict::Pass,
        (Outcome::Refused(message), None) => return Verdict::RefusalUnexpected(message),
        (Outcome::Trace(..), Some(kind)) => return Verdict::RefusalMissing(kind.clone()),
        (Outcome::Trace(path, format), None) => (path, format),
    };
    let machine = match machine(v) {
        Ok(m) => m,
        Err(e) => return Verdict::Error(format!("{}: {e}", v.id)),
    };
    let job = Job::new(&format!("{}.nc", v.id), v.program.clone().into_bytes(), machine, Engine::Impl);
    let verdict = judge(options, &job, (trace.0.clone(), trace.1));
    if matches!(options.outcomes, Outcomes::Run(_)) {
        let _ = fs::remove_file(&trace.0);
    }
    verdict
}

/// The verdict of `job`'s program against the trace at `trace` (in its
/// format, or by its extension).
fn judge(options: &ConformOptions, job: &Job, trace: (PathBuf, Option<TraceFormat>)) -> Verdict {
    let check =
        CheckOptions { format: trace.1, tolerance: options.tolerance, cycles_only: options.cycles_only };
    match check::run_as(job, &trace.0, &check) {
        Ok(report) if report.agree() => Verdict::Pass,
        Ok(report) => {
            let head = report.text().lines().next().unwrap_or_default().to_owned();
            Verdict::Differ(match report.first_divergence() {
                Some(first) => format!("{head}; first: {}", first.replace('\n', " ")),
                None => head,
            })
        }
        Err(e) => Verdict::Error(e.to_string()),
    }
}

/// Text as XML character data or an attribute value: escaped, with the
/// control characters XML 1.0 cannot hold left out.
fn xml(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\n' => out.push_str("&#10;"),
            '\t' => out.push_str("&#9;"),
            c if c.is_control() => {}
            c => out.push(c),
        }
    }
    out
}

/// The JUnit `<testcase>` of a result.
fn testcase(r: &CaseResult) -> String {
    let mut out = format!(
        "    <testcase classname=\"cycleref.conform\" name=\"{}\" time=\"{:.6}\"",
        xml(&r.id),
        r.seconds
    );
    let inner = match &r.verdict {
        Verdict::Pass => None,
        Verdict::Differ(m) => Some(("failure", "differ", m.clone())),
        Verdict::RefusalMissing(kind) => Some((
            "failure",
            "refusal-missing",
            format!("the program must be refused ({kind}), and a trace was given"),
        )),
        Verdict::RefusalUnexpected(m) => {
            Some(("failure", "refusal-unexpected", format!("a valid program was refused: {m}")))
        }
        Verdict::Error(m) => Some(("error", "error", m.clone())),
    };
    match inner {
        None => out.push_str("/>\n"),
        Some((tag, kind, message)) => {
            let _ = write!(
                out,
                ">\n      <{tag} type=\"{kind}\" message=\"{}\">{}</{tag}>\n    </testcase>\n",
                xml(&message),
                xml(&r.description)
            );
        }
    }
    out
}

/// The line of the summary for a case that did not pass.
fn failure_line(r: &CaseResult) -> Option<String> {
    let what = match &r.verdict {
        Verdict::Pass => return None,
        Verdict::Differ(m) => format!("FAIL {}: {m}", r.id),
        Verdict::RefusalMissing(kind) => {
            format!("FAIL {}: the program must be refused ({kind}), and a trace was given", r.id)
        }
        Verdict::RefusalUnexpected(m) => format!("FAIL {}: a valid program was refused: {m}", r.id),
        Verdict::Error(m) => format!("ERROR {}: {m}", r.id),
    };
    Some(format!("{what} ({})", r.description))
}

/// Runs the cases of `options.shard`, writing each case that does not pass
/// to `out` as it is decided (in case order) and then the summary line;
/// writes the JUnit XML file when asked.
///
/// # Errors
///
/// The corpus cannot be listed, the work directory or the JUnit file
/// cannot be written, or `out` fails (not a closed pipe: the writing
/// stops, the run goes on).
///
/// ```
/// use cycleref_cli::conform::{run, ConformOptions, Outcomes, Shard};
///
/// let dir = std::env::temp_dir().join(format!("cycleref-conform-doc-{}", std::process::id()));
/// let corpus = dir.join("corpus");
/// cycleref_cli::vectors::run(5, 1, &corpus)?;
/// // A vendor with no outcomes yet: every case is an error.
/// std::fs::create_dir_all(dir.join("traces"))?;
/// let options = ConformOptions {
///     corpus,
///     outcomes: Outcomes::Dir(dir.join("traces")),
///     trace_format: None,
///     tolerance: 0,
///     cycles_only: false,
///     shard: Shard::ALL,
///     jobs: 2,
///     junit: None,
/// };
/// let mut out = Vec::new();
/// let summary = run(&options, &mut out).map_err(String::from)?;
/// assert_eq!((summary.cases, summary.errors, summary.passed), (5, 5, 0));
/// assert!(!summary.all_passed());
/// assert!(String::from_utf8(out)?.starts_with("ERROR case-0001: no outcome"));
/// std::fs::remove_dir_all(&dir)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn run(options: &ConformOptions, out: &mut dyn Write) -> Result<Summary, Failure> {
    let pairs_run = matches!(options.outcomes, Outcomes::Pairs { .. });
    let cases =
        if pairs_run { pairs(&options.corpus, options.shard) } else { cases(&options.corpus, options.shard) }
            .map_err(|e| Failure::with_kind(Cause::Corpus, e.stable_kind(), e.to_string()))?;
    let work = std::env::temp_dir().join(format!("cycleref-conform-{}", std::process::id()));
    if matches!(options.outcomes, Outcomes::Run(_)) {
        fs::create_dir_all(&work)
            .map_err(|e| Failure::new(Cause::Output, format!("{}: {e}", work.display())))?;
    }
    let body_path = options.junit.as_ref().map(|p| p.with_extension("cycleref-part"));
    let mut body = match &body_path {
        Some(p) => Some(BufWriter::new(
            fs::File::create(p).map_err(|e| Failure::new(Cause::Output, format!("{}: {e}", p.display())))?,
        )),
        None => None,
    };
    let mut summary = Summary::default();
    // The verdict is the exit status: a closed output pipe stops the
    // writing, not the run (nothing may turn a failure into status 0).
    let mut closed = false;
    let next = AtomicUsize::new(0);
    let jobs = options.jobs.max(1).min(cases.len().max(1));
    let result = std::thread::scope(|scope| -> Result<(), Failure> {
        let (send, receive) = mpsc::channel::<(usize, CaseResult)>();
        for _ in 0..jobs {
            let send = send.clone();
            let (next, cases, work) = (&next, &cases, &work);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                if send.send((i, run_case(options, case, work))).is_err() {
                    break;
                }
            });
        }
        drop(send);
        // Results arrive in any order; they are written in case order, so
        // only those ahead of the next one wait (at most about `jobs`).
        let mut waiting = BTreeMap::new();
        let mut due = 0_usize;
        for (i, r) in receive {
            waiting.insert(i, r);
            while let Some(r) = waiting.remove(&due) {
                due += 1;
                summary.cases += 1;
                match r.verdict {
                    Verdict::Pass => summary.passed += 1,
                    Verdict::Differ(_) => summary.failed += 1,
                    Verdict::RefusalMissing(_) => summary.refusal_missing += 1,
                    Verdict::RefusalUnexpected(_) => summary.refusal_unexpected += 1,
                    Verdict::Error(_) => summary.errors += 1,
                }
                if let Some(line) = failure_line(&r) {
                    say(&mut *out, &mut closed, &line)?;
                }
                if let Some(b) = &mut body {
                    b.write_all(testcase(&r).as_bytes())
                        .map_err(|e| Failure::new(Cause::Output, format!("the JUnit file: {e}")))?;
                }
            }
        }
        Ok(())
    });
    if matches!(options.outcomes, Outcomes::Run(_)) {
        let _ = fs::remove_dir_all(&work);
    }
    result?;
    if let (Some(path), Some(part), Some(b)) = (&options.junit, &body_path, body) {
        write_junit(path, part, b, &summary, &options.corpus)
            .map_err(|e| Failure::new(Cause::Output, format!("{}: {e}", path.display())))?;
    }
    let shard = if options.shard == Shard::ALL {
        String::new()
    } else {
        format!(" (shard {}/{})", options.shard.index, options.shard.count)
    };
    let line = format!(
        "{}: {} cases{shard}: {} passed, {} failed, {} refusal{} expected but not made, {} refusal{} not \
         expected, {} error{}",
        if pairs_run { "conform --pairs" } else { "conform" },
        summary.cases,
        summary.passed,
        summary.failed,
        summary.refusal_missing,
        if summary.refusal_missing == 1 { "" } else { "s" },
        summary.refusal_unexpected,
        if summary.refusal_unexpected == 1 { "" } else { "s" },
        summary.errors,
        if summary.errors == 1 { "" } else { "s" },
    );
    say(out, &mut closed, &line)?;
    if !closed {
        out.flush()
            .or_else(|e| if e.kind() == io::ErrorKind::BrokenPipe { Ok(()) } else { Err(e) })
            .map_err(|e| Failure::output(&e))?;
    }
    Ok(summary)
}

/// Writes `line` unless the output was closed; a closed pipe is noted in
/// `closed`, any other error is the command's.
fn say(out: &mut dyn Write, closed: &mut bool, line: &str) -> Result<(), Failure> {
    if *closed {
        return Ok(());
    }
    match writeln!(out, "{line}") {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
            *closed = true;
            Ok(())
        }
        Err(e) => Err(Failure::output(&e)),
    }
}

/// The JUnit file: its header with the counts, the body written as the
/// cases were decided, its end; written beside it and renamed, so a
/// reader never sees half a file.
fn write_junit(
    path: &Path,
    part: &Path,
    body: BufWriter<fs::File>,
    s: &Summary,
    corpus: &Path,
) -> io::Result<()> {
    body.into_inner().map_err(io::IntoInnerError::into_error)?.sync_all()?;
    let failures = s.failed + s.refusal_missing + s.refusal_unexpected;
    let tmp = path.with_extension("cycleref-tmp");
    let mut f = BufWriter::new(fs::File::create(&tmp)?);
    writeln!(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>")?;
    writeln!(
        f,
        "<testsuites name=\"cycleref conform\" tests=\"{}\" failures=\"{failures}\" errors=\"{}\">",
        s.cases, s.errors
    )?;
    writeln!(
        f,
        "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{failures}\" errors=\"{}\" skipped=\"0\">",
        xml(&corpus.display().to_string()),
        s.cases,
        s.errors
    )?;
    io::copy(&mut fs::File::open(part)?, &mut f)?;
    writeln!(f, "  </testsuite>\n</testsuites>")?;
    f.into_inner().map_err(io::IntoInnerError::into_error)?.sync_all()?;
    fs::remove_file(part)?;
    fs::rename(&tmp, path)
}

/// Why a corpus, a list of pairs or a case cannot be read or run, or a
/// `--shard` is not one. Each variant names the file (and line, or field)
/// it is about; `Display` is the message.
#[derive(Debug)]
#[non_exhaustive]
pub enum ConformError {
    /// A `--shard` that is not `I/N` with 1 ≤ I ≤ N.
    Shard {
        /// The text given.
        text: String,
    },
    /// A file or directory that cannot be read (the corpus, the list of
    /// pairs, a case, a vendor's `.error` file).
    CannotRead {
        /// The path.
        path: String,
        /// Why.
        error: io::Error,
    },
    /// A case's file that cannot be written for `--run`.
    CannotWrite {
        /// The path.
        path: String,
        /// Why.
        error: io::Error,
    },
    /// A line of the list of pairs that names no profile of cycleref's.
    PairProfile {
        /// The list.
        list: String,
        /// The line.
        line: usize,
        /// The profile named.
        profile: String,
    },
    /// A line of the list of pairs of fewer than two or more than three
    /// fields.
    PairFields {
        /// The list.
        list: String,
        /// The line.
        line: usize,
    },
    /// A list of pairs without one.
    NoPairs {
        /// The list.
        list: String,
    },
    /// A corpus directory without a case.
    NoCases {
        /// The directory.
        corpus: String,
    },
    /// A case's file that is not JSON.
    NotJson {
        /// The path.
        path: String,
        /// Why.
        error: serde_json::Error,
    },
    /// A case without one of its text fields.
    VectorField {
        /// The path.
        path: String,
        /// The field (`id`, `program`, ...).
        field: &'static str,
    },
    /// A file that is not a `cycleref-vector/1` case.
    VectorSchema {
        /// The path.
        path: String,
    },
    /// A case whose `expect` holds neither moves nor an error.
    VectorExpect {
        /// The path.
        path: String,
    },
    /// A case whose profile is none of cycleref's.
    VectorProfile {
        /// The profile named.
        profile: String,
    },
    /// A case whose `machine_toml` cannot be applied.
    MachineToml(ParamsError),
    /// A vector in a run of pairs.
    VectorInPairs {
        /// The case's id.
        id: String,
    },
    /// No outcome for a case in the vendor's directory.
    NoOutcome {
        /// The case's id.
        id: String,
        /// The directory.
        dir: String,
    },
    /// More than one outcome for a case in the vendor's directory.
    TwoOutcomes {
        /// The case's id.
        id: String,
        /// The directory.
        dir: String,
    },
    /// The `--run` command cannot be started.
    CannotRun {
        /// The command.
        command: String,
        /// Why.
        error: io::Error,
    },
    /// The `--run` command exited 0 without writing its trace.
    NoTrace {
        /// The command.
        command: String,
    },
}

impl ConformError {
    fn cannot_read(path: &Path, error: io::Error) -> ConformError {
        ConformError::CannotRead { path: path.display().to_string(), error }
    }

    fn cannot_write(path: &Path, error: io::Error) -> ConformError {
        ConformError::CannotWrite { path: path.display().to_string(), error }
    }

    /// The stable kind: `usage:bad_shard`, or `corpus:` and the rule
    /// (`corpus:cannot_read`, `corpus:cannot_write`, `corpus:pair_profile`,
    /// `corpus:pair_fields`, `corpus:no_pairs`, `corpus:no_cases`,
    /// `corpus:not_json`, `corpus:vector_field`, `corpus:vector_schema`,
    /// `corpus:vector_expect`, `corpus:vector_profile`,
    /// `corpus:machine_toml`, `corpus:vector_in_pairs`,
    /// `corpus:no_outcome`, `corpus:two_outcomes`, `corpus:cannot_run`,
    /// `corpus:no_trace`).
    #[must_use]
    pub fn stable_kind(&self) -> &'static str {
        match self {
            ConformError::Shard { .. } => "usage:bad_shard",
            ConformError::CannotRead { .. } => "corpus:cannot_read",
            ConformError::CannotWrite { .. } => "corpus:cannot_write",
            ConformError::PairProfile { .. } => "corpus:pair_profile",
            ConformError::PairFields { .. } => "corpus:pair_fields",
            ConformError::NoPairs { .. } => "corpus:no_pairs",
            ConformError::NoCases { .. } => "corpus:no_cases",
            ConformError::NotJson { .. } => "corpus:not_json",
            ConformError::VectorField { .. } => "corpus:vector_field",
            ConformError::VectorSchema { .. } => "corpus:vector_schema",
            ConformError::VectorExpect { .. } => "corpus:vector_expect",
            ConformError::VectorProfile { .. } => "corpus:vector_profile",
            ConformError::MachineToml(_) => "corpus:machine_toml",
            ConformError::VectorInPairs { .. } => "corpus:vector_in_pairs",
            ConformError::NoOutcome { .. } => "corpus:no_outcome",
            ConformError::TwoOutcomes { .. } => "corpus:two_outcomes",
            ConformError::CannotRun { .. } => "corpus:cannot_run",
            ConformError::NoTrace { .. } => "corpus:no_trace",
        }
    }
}

impl std::fmt::Display for ConformError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        const PAIR: &str = "(`PROGRAM TRACE [PROFILE]`)";
        match self {
            ConformError::Shard { text } => {
                write!(f, "--shard {text:?}: give I/N with 1 <= I <= N, e.g. 2/4")
            }
            ConformError::CannotRead { path, error } | ConformError::CannotWrite { path, error } => {
                write!(f, "{path}: {error}")
            }
            ConformError::PairProfile { list, line, profile } => {
                write!(f, "{list}: line {line}: {profile:?} is none of cycleref's profiles {PAIR}")
            }
            ConformError::PairFields { list, line } => {
                write!(f, "{list}: line {line}: a pair is two or three fields {PAIR}")
            }
            ConformError::NoPairs { list } => {
                write!(f, "{list}: no pairs (`PROGRAM TRACE [PROFILE]` a line)")
            }
            ConformError::NoCases { corpus } => {
                write!(f, "{corpus}: no case-NNNN.json files (write a corpus with `cycleref vectors`)")
            }
            ConformError::NotJson { path, error } => write!(f, "{path}: {error}"),
            ConformError::VectorField { path, field } => {
                write!(f, "{path}: no text field `{field}` (a cycleref-vector/1 case?)")
            }
            ConformError::VectorSchema { path } => write!(f, "{path}: not a cycleref-vector/1 case"),
            ConformError::VectorExpect { path } => {
                write!(f, "{path}: `expect` holds neither moves nor an error")
            }
            ConformError::VectorProfile { profile } => write!(f, "profile {profile:?} is none of cycleref's"),
            ConformError::MachineToml(e) => write!(f, "machine_toml: {e}"),
            ConformError::VectorInPairs { id } => write!(f, "{id}: a vector in a run of pairs"),
            ConformError::NoOutcome { id, dir } => {
                write!(f, "no outcome: none of {id}.nc, {id}.csv, {id}.canon or {id}.error in {dir}")
            }
            ConformError::TwoOutcomes { id, dir } => write!(f, "more than one outcome for {id} in {dir}"),
            ConformError::CannotRun { command, error } => write!(f, "cannot run `sh -c {command}`: {error}"),
            ConformError::NoTrace { command } => {
                write!(f, "the command exited 0 but wrote no trace to {{trace}}: {command}")
            }
        }
    }
}

impl std::error::Error for ConformError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ConformError::CannotRead { error, .. }
            | ConformError::CannotWrite { error, .. }
            | ConformError::CannotRun { error, .. } => Some(error),
            ConformError::NotJson { error, .. } => Some(error),
            ConformError::MachineToml(e) => Some(e),
            _ => None,
        }
    }
}
