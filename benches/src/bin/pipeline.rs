//! `pipeline`: wall time and peak RSS of the release `cycleref` command on
//! generated programs of 1, 5 and 50 MB, optionally side by side with
//! another build (`--baseline PATH`).
//!
//! ```text
//! cargo build --release -p cycleref-cli
//! cargo run -p cycleref-benches --release --bin pipeline -- \
//!     [--new target/release/cycleref] [--baseline PATH] [--sizes 1,5,50] [--reps 3] \
//!     [--dir target/pipeline] [--timeout 120] [--mem-limit-mb 12288] [--no-append]
//! ```
//!
//! For each size it writes `prog-<N>mb.nc` (the mix of `corpus::program`),
//! `plain-<N>mb.nc` (the same without cycles: the reader alone) and
//! `trace-<N>mb.nc` (the new build's nc expansion, the trace of `check`)
//! into `--dir`, then runs every command `--reps` times, new build then
//! baseline, each in a fresh child reaped with `wait4`, whose rusage gives
//! that child's own peak RSS. Output goes to `/dev/null` (plot: a file).
//! Every run is under a time limit (`--timeout`, SIGKILL) and an
//! address-space limit (`--mem-limit-mb`, `RLIMIT_AS`): a run that exceeds
//! either, or fails, is recorded as "did not finish" and that command is
//! not run on that build again at this or larger sizes (the build of
//! aa225a9 needs more than 24 GB for `expand --format json` of the 50 MB
//! program). A command the
//! baseline does not have (`--format jsonl`, `plot --line`) is recorded as
//! unsupported.
//!
//! With each size's `expand nc` it runs the **bytes-out floor** (issue 33):
//! this binary as a child (`pipeline --floor SHAPE`, `floor::write_floor`),
//! writing as many moves of the same shape as the nc expansion holds to
//! `/dev/null`, no program read; it prints `expand nc / floor` and `check /
//! expand nc`.
//!
//! Then, unless `--peer-cycles 0`, the **peer benchmark** (issue 33): a
//! LinuxCNC program of `--peer-cycles` G76 cycles
//! (`corpus::linuxcnc_program`), LinuxCNC's `rs274 -g FILE` (`--rs274`,
//! default the `rs274` on `PATH`; skipped with a message when there is
//! none), `cycleref expand --profile linuxcnc FILE`, `cycleref check
//! --profile linuxcnc FILE --trace RS274.canon --tolerance 1` and the
//! floor of that expansion, alternating, in one run: it prints `rs274 /
//! expand` and `rs274 / check`. And unless `--g75-grooves 0`, a
//! **G75.1-heavy** program (`corpus::g75_program`): `expand` by the new
//! build, the baseline's when given, and the floor.
//!
//! Prints one markdown table (medians), the targets of issues 11 and 33,
//! and appends one row per program, command and build to
//! `benches/pipeline-history.csv` (see `benches/README.md`;
//! `cycleref_benches::pipeline_history`).
#![allow(unsafe_code)] // wait4, kill and setrlimit: the only way to a child's own rusage.

use std::fmt::Write as _;
use std::fs::{self, File};
use std::os::unix::process::CommandExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use cycleref_benches::corpus;
use cycleref_benches::floor::{self, Shape};
use cycleref_benches::pipeline_history::{self, Ratio, Row, Times, HEADER};

const USAGE: &str = "usage: pipeline [--new PATH] [--baseline PATH] [--sizes 1,5,50|none] [--reps 3]
                [--dir DIR] [--timeout SECS] [--mem-limit-mb MB] [--no-append]
                [--peer-cycles 2000] [--rs274 PATH] [--g75-grooves 2000]
       pipeline --floor SHAPE    (the bytes-out floor, to stdout)";

const HISTORY: &str = "benches/pipeline-history.csv";

/// The name of the floor's rows.
const FLOOR: &str = "bytes-out floor";

struct Args {
    new: PathBuf,
    baseline: Option<PathBuf>,
    sizes: Vec<usize>,
    reps: usize,
    dir: PathBuf,
    timeout: Duration,
    mem_limit_mb: u64,
    append: bool,
    /// G76 cycles of the LinuxCNC program; 0: no peer benchmark.
    peer_cycles: usize,
    /// LinuxCNC's `rs274`; `None`: the one on `PATH`.
    rs274: Option<PathBuf>,
    /// Grooves of the G75.1-heavy program; 0: none.
    g75_grooves: usize,
}

fn parse() -> Result<Args, String> {
    let mut a = Args {
        new: PathBuf::from("target/release/cycleref"),
        baseline: None,
        sizes: vec![1, 5, 50],
        reps: 3,
        dir: PathBuf::from("target/pipeline"),
        timeout: Duration::from_secs(120),
        mem_limit_mb: 12 * 1024,
        append: true,
        peer_cycles: 2_000,
        rs274: None,
        g75_grooves: 2_000,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--new" => a.new = value()?.into(),
            "--baseline" => a.baseline = Some(value()?.into()),
            "--sizes" => {
                a.sizes = value()?
                    .split(',')
                    .filter(|s| !s.is_empty() && *s != "none")
                    .map(|s| s.trim().parse().map_err(|e| format!("--sizes: {s}: {e}")))
                    .collect::<Result<_, _>>()?;
            }
            "--reps" => a.reps = value()?.parse().map_err(|e| format!("--reps: {e}"))?,
            "--dir" => a.dir = value()?.into(),
            "--timeout" => {
                a.timeout = Duration::from_secs(value()?.parse().map_err(|e| format!("--timeout: {e}"))?);
            }
            "--mem-limit-mb" => {
                a.mem_limit_mb = value()?.parse().map_err(|e| format!("--mem-limit-mb: {e}"))?
            }
            "--no-append" => a.append = false,
            "--peer-cycles" => a.peer_cycles = value()?.parse().map_err(|e| format!("--peer-cycles: {e}"))?,
            "--rs274" => a.rs274 = Some(value()?.into()),
            "--g75-grooves" => a.g75_grooves = value()?.parse().map_err(|e| format!("--g75-grooves: {e}"))?,
            "-h" | "--help" => return Err(String::new()),
            other => return Err(format!("unknown argument `{other}`")),
        }
    }
    if a.reps == 0 {
        return Err("--reps must be at least 1".into());
    }
    Ok(a)
}

/// How one child run ended.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Outcome {
    /// Exit status 0: wall seconds, CPU seconds (user + system), peak RSS
    /// in MB.
    Done(f64, f64, f64),
    /// Killed at the time limit.
    Timeout,
    /// Another exit status or a signal (an allocation failure under the
    /// memory limit aborts): the status, or 128 + the signal.
    Failed(i32, f64),
}

/// Runs `bin args` through a fresh copy of this program (`--wrap`), which
/// runs it with [`measure_here`] and prints the outcome.
///
/// Why a wrapper: a child's `ru_maxrss` starts from the high-water RSS of
/// the address space it was spawned from (`posix_spawn` shares the
/// parent's until `exec`, `fork` copies its high-water mark), so a child
/// of this process, which holds the generated programs, would report at
/// least this process's peak. The wrapper is a few MB (the `--version`
/// row of the table shows that floor).
fn measure(
    bin: &Path,
    args: &[String],
    stderr_file: &Path,
    limits: Option<(Duration, u64)>,
) -> Result<Outcome, String> {
    let me = std::env::current_exe().map_err(|e| e.to_string())?;
    let (t, m) = limits.map_or((0, 0), |(t, m)| (t.as_secs(), m));
    let out = Command::new(me)
        .arg("--wrap")
        .arg(t.to_string())
        .arg(m.to_string())
        .arg(stderr_file)
        .arg(bin)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("--wrap: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let w: Vec<&str> = text.split_whitespace().collect();
    let num = |i: usize| {
        w.get(i).and_then(|v| v.parse::<f64>().ok()).ok_or_else(|| format!("--wrap said `{text}`"))
    };
    match w.first().copied() {
        Some("done") => Ok(Outcome::Done(num(1)?, num(2)?, num(3)?)),
        Some("timeout") => Ok(Outcome::Timeout),
        #[allow(clippy::cast_possible_truncation)]
        Some("failed") => Ok(Outcome::Failed(num(1)? as i32, num(2)?)),
        _ => Err(format!("--wrap failed: {text} {}", String::from_utf8_lossy(&out.stderr))),
    }
}

/// `--wrap SECS MB STDERR BIN ARGS...`: [`measure_here`], the outcome on
/// stdout (SECS or MB 0: no limit).
fn wrap(mut a: impl Iterator<Item = String>) -> Result<(), String> {
    let mut next = |what: &str| a.next().ok_or_else(|| format!("--wrap: no {what}"));
    let secs: u64 = next("time limit")?.parse().map_err(|e| format!("--wrap: {e}"))?;
    let mb: u64 = next("memory limit")?.parse().map_err(|e| format!("--wrap: {e}"))?;
    let stderr = PathBuf::from(next("stderr file")?);
    let bin = PathBuf::from(next("binary")?);
    let args: Vec<String> = a.collect();
    let limits = (secs > 0 || mb > 0).then_some((
        if secs > 0 { Duration::from_secs(secs) } else { Duration::MAX },
        if mb > 0 { mb } else { u64::MAX >> 20 },
    ));
    match measure_here(&bin, &args, &stderr, limits)? {
        Outcome::Done(w, c, r) => println!("done {w} {c} {r}"),
        Outcome::Timeout => println!("timeout"),
        Outcome::Failed(code, r) => println!("failed {code} {r}"),
    }
    Ok(())
}

/// Runs `bin args` with stdout to `/dev/null` and stderr to `stderr_file`,
/// under the limits when given; waits with `wait4` for its rusage.
fn measure_here(
    bin: &Path,
    args: &[String],
    stderr_file: &Path,
    limits: Option<(Duration, u64)>,
) -> Result<Outcome, String> {
    let mut cmd = Command::new(bin);
    cmd.args(args)
        .stdin(Stdio::null())
        .stdout(File::create("/dev/null").map_err(|e| e.to_string())?)
        .stderr(File::create(stderr_file).map_err(|e| e.to_string())?);
    if let Some((_, mb)) = limits {
        let bytes = mb.saturating_mul(1 << 20);
        // SAFETY: setrlimit is async-signal-safe and touches no memory of
        // the parent.
        unsafe {
            cmd.pre_exec(move || {
                let lim = libc::rlimit { rlim_cur: bytes, rlim_max: bytes };
                if libc::setrlimit(libc::RLIMIT_AS, &lim) == 0 {
                    Ok(())
                } else {
                    Err(std::io::Error::last_os_error())
                }
            });
        }
    }
    let start = Instant::now();
    let child = cmd.spawn().map_err(|e| format!("{}: {e}", bin.display()))?;
    let pid = libc::pid_t::try_from(child.id()).map_err(|e| e.to_string())?;
    let (tx, rx) = mpsc::channel::<()>();
    let timeout = limits.map(|(t, _)| t);
    let watchdog = std::thread::spawn(move || {
        let Some(t) = timeout else { return false };
        if rx.recv_timeout(t).is_err() {
            // SAFETY: plain syscall on the child's pid, which is not yet
            // reaped (the main thread is in wait4).
            unsafe { libc::kill(pid, libc::SIGKILL) };
            return true;
        }
        false
    });
    let mut status = 0;
    // SAFETY: rusage is plain old data; wait4 fills it.
    let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: pid is our child, the pointers are valid for the call.
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut ru) };
    let wall = start.elapsed().as_secs_f64();
    let _ = tx.send(());
    let killed = watchdog.join().unwrap_or(false);
    // The child is reaped: std must not wait for it again.
    drop(child);
    if r != pid {
        return Err(format!("wait4: {}", std::io::Error::last_os_error()));
    }
    // ru_maxrss is in KiB on Linux.
    #[allow(clippy::cast_precision_loss)]
    let rss = ru.ru_maxrss as f64 / 1024.0;
    #[allow(clippy::cast_precision_loss)]
    let tv = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    let cpu = tv(ru.ru_utime) + tv(ru.ru_stime);
    Ok(if killed {
        Outcome::Timeout
    } else if libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0 {
        Outcome::Done(wall, cpu, rss)
    } else if libc::WIFEXITED(status) {
        Outcome::Failed(libc::WEXITSTATUS(status), rss)
    } else {
        Outcome::Failed(128 + libc::WTERMSIG(status), rss)
    })
}

/// The commands measured on one program, by name; `{prog}`, `{plain}`,
/// `{trace}`, `{line}`, `{svg}` are replaced.
const COMMANDS: [(&str, &str); 9] = [
    ("passes plain (reader)", "passes {plain}"),
    ("expand plain (reader)", "expand {plain}"),
    ("expand nc", "expand {prog}"),
    ("expand json", "expand --format json {prog}"),
    ("expand jsonl", "expand --format jsonl {prog}"),
    ("passes", "passes {prog}"),
    ("check", "check {prog} --trace {trace}"),
    ("plot --line", "plot {prog} --line {line} -o {svg}"),
    ("(nothing: bare start)", "--version"),
];

fn command_args(template: &str, files: &Files) -> Vec<String> {
    let mut args: Vec<String> = template
        .split(' ')
        .map(|w| match w {
            "{prog}" => files.prog.display().to_string(),
            "{plain}" => files.plain.display().to_string(),
            "{trace}" => files.trace.display().to_string(),
            "{svg}" => files.svg.display().to_string(),
            "{line}" => files.line.to_string(),
            w => w.to_string(),
        })
        .collect();
    if args[0] != "--version" {
        args.splice(1..1, corpus::PROFILE_ARGS.iter().map(|s| (*s).to_string()));
    }
    args
}

struct Files {
    prog: PathBuf,
    plain: PathBuf,
    trace: PathBuf,
    svg: PathBuf,
    line: usize,
}

/// The figures of one command on one program by one build.
#[derive(Clone, Debug, Default)]
struct Cell {
    times: Vec<f64>,
    cpu: Vec<f64>,
    rss: Vec<f64>,
    /// Set when the command did not finish or is unsupported.
    status: Option<String>,
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    match s.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => s[n / 2],
        n => (s[n / 2 - 1] + s[n / 2]) / 2.0,
    }
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NAN, f64::max)
}

impl Cell {
    fn done(&self) -> bool {
        self.status.is_none() && !self.times.is_empty()
    }
    fn time(&self) -> String {
        match &self.status {
            Some(s) => s.clone(),
            None => secs(median(&self.times)),
        }
    }
    fn cpu(&self) -> String {
        if self.done() {
            secs(median(&self.cpu))
        } else {
            "–".into()
        }
    }
    fn mem(&self) -> String {
        if self.done() {
            format!("{:.1}", median(&self.rss))
        } else {
            "–".into()
        }
    }
}

fn secs(s: f64) -> String {
    if s < 1.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn run_one(
    bin: &Path,
    args: &[String],
    stderr: &Path,
    limits: Option<(Duration, u64)>,
    cell: &mut Cell,
) -> Result<(), String> {
    match measure(bin, args, stderr, limits)? {
        Outcome::Done(t, cpu, m) => {
            cell.times.push(t);
            cell.cpu.push(cpu);
            cell.rss.push(m);
        }
        Outcome::Timeout => {
            cell.status = Some(format!("DNF (killed at {} s)", limits.map_or(0, |l| l.0.as_secs())));
        }
        Outcome::Failed(code, m) => {
            let msg = fs::read_to_string(stderr).unwrap_or_default();
            let first = msg.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
            let how = match code {
                134 => "SIGABRT".to_string(),
                137 => "SIGKILL".to_string(),
                c if c > 128 => format!("signal {}", c - 128),
                c => format!("exit {c}"),
            };
            cell.status = Some(format!("DNF ({how} at {m:.0} MB)"));
            eprintln!("  {} {}: {how}: {first}", bin.display(), args.join(" "));
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let mut raw = std::env::args().skip(1);
    let first = raw.next();
    if first.as_deref() == Some("--floor") {
        return match floor_main(raw.next()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("pipeline --floor: {e}");
                ExitCode::from(2)
            }
        };
    }
    if first.as_deref() == Some("--wrap") {
        return match wrap(raw) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("pipeline: {e}");
                ExitCode::from(2)
            }
        };
    }
    let args = match parse() {
        Ok(a) => a,
        Err(e) => {
            if !e.is_empty() {
                eprintln!("pipeline: {e}");
            }
            eprintln!("{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("pipeline: {e}");
            ExitCode::from(2)
        }
    }
}

/// Writes `bin`'s nc expansion of the program to the trace file.
fn write_trace(bin: &Path, files: &Files) -> Result<(), String> {
    let mut expand = Command::new(bin);
    expand.arg("expand").args(corpus::PROFILE_ARGS).arg(&files.prog);
    let out = expand.stdout(File::create(&files.trace).map_err(|e| e.to_string())?).status();
    if out.is_ok_and(|s| s.success()) {
        Ok(())
    } else {
        Err(format!("{}: expand of {} failed", bin.display(), files.prog.display()))
    }
}

/// Whether `bin` accepts `args` on a tiny program (the baseline may lack
/// `--format jsonl` or `plot --line`).
fn supports(bin: &Path, template: &str, dir: &Path) -> Result<bool, String> {
    let g = corpus::program(2_000, true);
    let files = Files {
        prog: dir.join("probe.nc"),
        plain: dir.join("probe-plain.nc"),
        trace: dir.join("probe-trace.nc"),
        svg: dir.join("probe.svg"),
        line: g.last_g76_line,
    };
    fs::write(&files.prog, &g.text).map_err(|e| e.to_string())?;
    fs::write(&files.plain, corpus::program(2_000, false).text).map_err(|e| e.to_string())?;
    write_trace(bin, &files)?;
    let a = command_args(template, &files);
    Ok(matches!(measure(bin, &a, &dir.join("probe.err"), None)?, Outcome::Done(..) | Outcome::Failed(1, _)))
}

/// One row of the history: a command's cell on a program, with the ratio
/// the row carries.
struct Entry {
    /// The program's size, MiB.
    size_mb: f64,
    /// `new`, `baseline`, `floor`, `peer`.
    build: String,
    command: String,
    cell: Cell,
    ratio: Option<Ratio>,
}

impl Entry {
    fn new(size_mb: f64, build: &str, command: &str, cell: Cell) -> Entry {
        Entry { size_mb, build: build.into(), command: command.into(), cell, ratio: None }
    }

    fn row(&self, date: &str, commit: &str) -> Row {
        let c = &self.cell;
        Row {
            date: date.into(),
            commit: commit.into(),
            build: self.build.clone(),
            size_mb: self.size_mb,
            command: self.command.clone(),
            reps: c.times.len(),
            times: c.done().then(|| Times {
                median_s: median(&c.times),
                min_s: c.times.iter().copied().fold(f64::INFINITY, f64::min),
                median_cpu_s: median(&c.cpu),
                median_rss_mb: median(&c.rss),
                max_rss_mb: max(&c.rss),
            }),
            status: c.status.clone().unwrap_or_else(|| "ok".into()),
            ratio: self.ratio.clone(),
        }
    }
}

/// `a / b` of two cells' medians, named `of`, when both finished.
fn ratio(of: &str, a: &Cell, b: &Cell) -> Option<Ratio> {
    (a.done() && b.done()).then(|| Ratio {
        of: of.into(),
        wall: median(&a.times) / median(&b.times),
        cpu: median(&a.cpu) / median(&b.cpu),
    })
}

fn mib(bytes: usize) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let b = bytes as f64;
    b / 1_048_576.0
}

/// `pipeline --floor SHAPE`: the bytes-out floor of that shape to stdout.
fn floor_main(shape: Option<String>) -> Result<(), String> {
    let shape: Shape = shape.ok_or("no shape")?.parse()?;
    floor::write_floor(&shape, std::io::stdout().lock()).map_err(|e| e.to_string())?;
    Ok(())
}

/// The floor's shape of an nc expansion in a file.
fn shape_of(nc: &Path) -> Result<Shape, String> {
    Ok(Shape::of_nc(&fs::read(nc).map_err(|e| format!("{}: {e}", nc.display()))?))
}

/// The arguments of the floor child for `shape`.
fn floor_args(shape: &Shape) -> Vec<String> {
    vec!["--floor".into(), shape.to_string()]
}

/// Runs `bin args` once, unmeasured, with stdout to `out` (or captured
/// when `None`); its stdout when captured, an error when it fails.
fn run_to(bin: &Path, args: &[String], out: Option<&Path>) -> Result<String, String> {
    let mut cmd = Command::new(bin);
    cmd.args(args).stdin(Stdio::null()).stderr(Stdio::null());
    let what = || format!("{} {}", bin.display(), args.join(" "));
    if let Some(path) = out {
        cmd.stdout(File::create(path).map_err(|e| format!("{}: {e}", path.display()))?);
        let status = cmd.status().map_err(|e| format!("{}: {e}", what()))?;
        return if status.success() {
            Ok(String::new())
        } else {
            Err(format!("{} failed ({status})", what()))
        };
    }
    let o = cmd.output().map_err(|e| format!("{}: {e}", what()))?;
    if o.status.success() {
        Ok(String::from_utf8_lossy(&o.stdout).into_owned())
    } else {
        Err(format!("{} failed ({}): {}", what(), o.status, String::from_utf8_lossy(&o.stdout)))
    }
}

/// `rs274`: `--rs274`, else the first on `PATH`.
fn find_rs274(args: &Args) -> Option<PathBuf> {
    if let Some(p) = &args.rs274 {
        return p.is_file().then(|| p.clone());
    }
    std::env::var_os("PATH")
        .map(|p| std::env::split_paths(&p).map(|d| d.join("rs274")).find(|f| f.is_file()))
        .unwrap_or_default()
}

/// Runs every `(bin, args)` job `reps` times, alternating, into its cell:
/// the commands of one program, side by side.
fn measure_side_by_side(
    args: &Args,
    label: &str,
    jobs: &[(&Path, Vec<String>, &str)],
) -> Result<Vec<Cell>, String> {
    let mut cells = vec![Cell::default(); jobs.len()];
    let limits = Some((args.timeout, args.mem_limit_mb));
    for rep in 0..args.reps {
        for ((bin, a, name), cell) in jobs.iter().zip(&mut cells) {
            if cell.status.is_some() {
                continue;
            }
            eprintln!("  {label} {name} #{}", rep + 1);
            run_one(bin, a, &args.dir.join("extra.err"), limits, cell)?;
        }
    }
    Ok(cells)
}

/// The peer benchmark of issue 33 (see the module's documentation); its
/// entries, or none and a note when `rs274` is not installed.
fn peer(args: &Args, notes: &mut Vec<String>) -> Result<Vec<Entry>, String> {
    let n = args.peer_cycles;
    if n == 0 {
        return Ok(Vec::new());
    }
    let Some(rs274) = find_rs274(args) else {
        let msg = format!(
            "peer benchmark skipped: LinuxCNC's `rs274` is not installed{} (Debian: apt-get install \
             --no-install-recommends linuxcnc-uspace)",
            args.rs274.as_ref().map_or(String::new(), |p| format!(" at {}", p.display()))
        );
        eprintln!("pipeline: {msg}");
        notes.push(msg);
        return Ok(Vec::new());
    };
    let text = corpus::linuxcnc_program(n);
    let prog = args.dir.join(format!("linuxcnc-{n}.ngc"));
    let canon = args.dir.join(format!("linuxcnc-{n}.canon"));
    let nc = args.dir.join(format!("linuxcnc-{n}.nc"));
    fs::write(&prog, &text).map_err(|e| format!("{}: {e}", prog.display()))?;
    let p = prog.display().to_string();
    run_to(&rs274, &["-g".into(), p.clone()], Some(&canon))?;
    let lcnc = |cmd: &str| -> Vec<String> {
        std::iter::once(cmd.to_string())
            .chain(corpus::LINUXCNC_ARGS.iter().map(|s| (*s).to_string()))
            .collect()
    };
    let mut expand = lcnc("expand");
    expand.push(p.clone());
    let mut check = lcnc("check");
    check.extend([
        p.clone(),
        "--trace".into(),
        canon.display().to_string(),
        "--tolerance".into(),
        "1".into(),
    ]);
    run_to(&args.new, &expand, Some(&nc))?;
    // Once, unmeasured: they agree, and how many moves.
    let verdict = run_to(&args.new, &check, None)?;
    let shape = shape_of(&nc)?;
    let label = format!("linuxcnc {n} G76");
    eprintln!("{label}: {} bytes; check: {}", text.len(), verdict.trim());
    notes.push(format!("{label} (`{}`): {}", prog.display(), verdict.trim()));
    let rs_args = vec!["-g".to_string(), p];
    let me = std::env::current_exe().map_err(|e| e.to_string())?;
    let jobs = [
        (rs274.as_path(), rs_args, "rs274 -g"),
        (args.new.as_path(), expand, "expand"),
        (args.new.as_path(), check, "check --trace canon"),
        (me.as_path(), floor_args(&shape), FLOOR),
    ];
    let cells = measure_side_by_side(args, &label, &jobs)?;
    let size = mib(text.len());
    let name = |c: &str| format!("{label}: {c}");
    let mut e = vec![
        Entry::new(size, "peer", &name("rs274 -g"), cells[0].clone()),
        Entry::new(size, "new", &name("expand"), cells[1].clone()),
        Entry::new(size, "new", &name("check --trace canon"), cells[2].clone()),
        Entry::new(size, "floor", &name(FLOOR), cells[3].clone()),
    ];
    e[1].ratio = ratio("rs274 -g / expand", &cells[0], &cells[1]);
    e[2].ratio = ratio("rs274 -g / check --trace canon", &cells[0], &cells[2]);
    e[3].ratio = ratio(&format!("expand / {FLOOR}"), &cells[1], &cells[3]);
    Ok(e)
}

/// The G75.1-heavy program: `expand` by the new build, the baseline's,
/// and the floor of the new build's expansion.
fn g75_heavy(args: &Args) -> Result<Vec<Entry>, String> {
    let n = args.g75_grooves;
    if n == 0 {
        return Ok(Vec::new());
    }
    let text = corpus::g75_program(n);
    let prog = args.dir.join(format!("g75-{n}.nc"));
    let nc = args.dir.join(format!("g75-{n}-expanded.nc"));
    fs::write(&prog, &text).map_err(|e| format!("{}: {e}", prog.display()))?;
    let expand: Vec<String> = std::iter::once("expand".to_string())
        .chain(corpus::PROFILE_ARGS.iter().map(|s| (*s).to_string()))
        .chain([prog.display().to_string()])
        .collect();
    run_to(&args.new, &expand, Some(&nc))?;
    let shape = shape_of(&nc)?;
    let label = format!("G75.1 {n} grooves");
    eprintln!("{label}: {} bytes, nc expansion {} lines", text.len(), shape.lines());
    let me = std::env::current_exe().map_err(|e| e.to_string())?;
    let mut jobs =
        vec![(args.new.as_path(), expand.clone(), "expand"), (me.as_path(), floor_args(&shape), FLOOR)];
    if let Some(b) = &args.baseline {
        jobs.push((b.as_path(), expand, "expand (baseline)"));
    }
    let cells = measure_side_by_side(args, &label, &jobs)?;
    let size = mib(text.len());
    let name = |c: &str| format!("{label}: {c}");
    let mut e = vec![
        Entry::new(size, "new", &name("expand"), cells[0].clone()),
        Entry::new(size, "floor", &name(FLOOR), cells[1].clone()),
    ];
    e[1].ratio = ratio(&format!("expand / {FLOOR}"), &cells[0], &cells[1]);
    if let Some(base) = cells.get(2) {
        e[0].ratio = ratio("expand (baseline) / expand", base, &cells[0]);
        e.push(Entry::new(size, "baseline", &name("expand"), base.clone()));
    }
    Ok(e)
}

#[allow(clippy::too_many_lines)]
fn run(args: &Args) -> Result<(), String> {
    fs::create_dir_all(&args.dir).map_err(|e| format!("{}: {e}", args.dir.display()))?;
    let builds: Vec<(&str, &Path)> = std::iter::once(("new", args.new.as_path()))
        .chain(args.baseline.as_deref().map(|b| ("baseline", b)))
        .collect();
    for (_, b) in &builds {
        if !b.is_file() {
            return Err(format!("{}: no such binary (cargo build --release -p cycleref-cli)", b.display()));
        }
    }
    // support[build][command]
    let mut support = vec![vec![true; COMMANDS.len()]; builds.len()];
    if !args.sizes.is_empty() {
        for (b, (_, bin)) in builds.iter().enumerate() {
            for (c, (_, t)) in COMMANDS.iter().enumerate() {
                support[b][c] = supports(bin, t, &args.dir)?;
            }
        }
    }
    let me = std::env::current_exe().map_err(|e| e.to_string())?;
    let date = utc_now();
    let commit = git_commit();
    let mut table = String::new();
    let mut entries: Vec<Entry> = Vec::new();
    // Commands a build did not finish at a smaller size.
    let mut gave_up = vec![vec![false; COMMANDS.len()]; builds.len()];
    let mut results: Vec<(usize, Vec<Vec<Cell>>)> = Vec::new();
    // The floor of each mixed program (issue 33).
    let mut floors: Vec<Entry> = Vec::new();
    let nc_index = COMMANDS.iter().position(|(n, _)| *n == "expand nc").unwrap_or(0);
    let check_index = COMMANDS.iter().position(|(n, _)| *n == "check").unwrap_or(0);
    for &mb in &args.sizes {
        let g = corpus::program(mb << 20, true);
        let plain = corpus::program(mb << 20, false);
        let files = Files {
            prog: args.dir.join(format!("prog-{mb}mb.nc")),
            plain: args.dir.join(format!("plain-{mb}mb.nc")),
            trace: args.dir.join(format!("trace-{mb}mb.nc")),
            svg: args.dir.join(format!("plot-{mb}mb.svg")),
            line: g.last_g76_line,
        };
        fs::write(&files.prog, &g.text).map_err(|e| e.to_string())?;
        fs::write(&files.plain, &plain.text).map_err(|e| e.to_string())?;
        write_trace(&args.new, &files)?;
        let trace_len = fs::metadata(&files.trace).map_or(0, |m| m.len());
        let shape = shape_of(&files.trace)?;
        eprintln!(
            "{mb} MB: {} bytes, {} lines, {} G76, {} G32 blocks, {} G75.1; nc expansion {:.1} MB, {} lines \
             ({} rapids, {} feeds)",
            g.text.len(),
            g.lines,
            g.g76,
            g.g32,
            g.g75,
            trace_len as f64 / 1048576.0,
            shape.lines(),
            shape.rapids,
            shape.feeds
        );
        let mut cells = vec![vec![Cell::default(); COMMANDS.len()]; builds.len()];
        let mut floor_cell = Cell::default();
        for (c, (name, template)) in COMMANDS.iter().enumerate() {
            let a = command_args(template, &files);
            for rep in 0..args.reps {
                for (b, (build, bin)) in builds.iter().enumerate() {
                    let cell = &mut cells[b][c];
                    if !support[b][c] {
                        cell.status = Some("unsupported".into());
                        continue;
                    }
                    if gave_up[b][c] && cell.status.is_none() {
                        cell.status = Some("skipped (DNF on a smaller program)".into());
                    }
                    if cell.status.is_some() {
                        continue;
                    }
                    let limits = Some((args.timeout, args.mem_limit_mb));
                    let err = args.dir.join(format!("{build}.err"));
                    eprintln!("  {mb} MB {build} {name} #{}", rep + 1);
                    run_one(bin, &a, &err, limits, cell)?;
                    if cell.status.is_some() {
                        gave_up[b][c] = true;
                    }
                }
                // The floor beside `expand nc`, in the same alternation.
                if c == nc_index && floor_cell.status.is_none() {
                    eprintln!("  {mb} MB {FLOOR} #{}", rep + 1);
                    let limits = Some((args.timeout, args.mem_limit_mb));
                    run_one(&me, &floor_args(&shape), &args.dir.join("floor.err"), limits, &mut floor_cell)?;
                }
            }
        }
        #[allow(clippy::cast_precision_loss)]
        let size = mb as f64;
        for (b, (build, _)) in builds.iter().enumerate() {
            for (c, (name, _)) in COMMANDS.iter().enumerate() {
                let mut e = Entry::new(size, build, name, cells[b][c].clone());
                if c == nc_index {
                    e.ratio = ratio(&format!("expand nc / {FLOOR}"), &cells[b][c], &floor_cell);
                } else if c == check_index {
                    e.ratio = ratio("check / expand nc", &cells[b][c], &cells[b][nc_index]);
                }
                entries.push(e);
            }
        }
        floors.push(Entry::new(size, "floor", FLOOR, floor_cell));
        results.push((mb, cells));
    }
    let mut notes = Vec::new();
    let peer = peer(args, &mut notes)?;
    let g75 = g75_heavy(args)?;

    // The table.
    let base = builds.len() > 1;
    let _ = writeln!(table, "Medians of {} runs each, {date}, commit {commit}.\n", args.reps);
    if !results.is_empty() {
        if base {
            let _ = writeln!(
                table,
                "| size | command | new wall | new CPU | new RSS MB | baseline wall | baseline CPU | baseline RSS MB | baseline/new wall | baseline/new CPU | baseline/new RSS |"
            );
            let _ = writeln!(table, "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        } else {
            let _ = writeln!(table, "| size | command | wall | CPU | RSS MB |");
            let _ = writeln!(table, "|---:|---|---:|---:|---:|");
        }
    }
    for (mb, cells) in &results {
        for (c, (name, _)) in COMMANDS.iter().enumerate() {
            let n = &cells[0][c];
            if base {
                let o = &cells[1][c];
                let (rt, rc, rm) = if n.done() && o.done() {
                    (
                        format!("{:.1}×", median(&o.times) / median(&n.times)),
                        format!("{:.1}×", median(&o.cpu) / median(&n.cpu)),
                        format!("{:.1}×", median(&o.rss) / median(&n.rss)),
                    )
                } else {
                    ("–".into(), "–".into(), "–".into())
                };
                let _ = writeln!(
                    table,
                    "| {mb} MB | {name} | {} | {} | {} | {} | {} | {} | {rt} | {rc} | {rm} |",
                    n.time(),
                    n.cpu(),
                    n.mem(),
                    o.time(),
                    o.cpu(),
                    o.mem()
                );
            } else {
                let _ = writeln!(table, "| {mb} MB | {name} | {} | {} | {} |", n.time(), n.cpu(), n.mem());
            }
        }
    }
    let extra: Vec<&Entry> = peer.iter().chain(&g75).collect();
    table.push_str(&extra_table(&results, &floors, &extra, &notes));
    if !results.is_empty() {
        table.push_str(&targets(&results, base));
    }
    table.push_str(&targets_33(&entries, &peer, &g75, base));
    print!("{table}");

    entries.extend(floors);
    entries.extend(peer);
    entries.extend(g75);
    if args.append {
        append_history(&entries.iter().map(|e| e.row(&date, &commit)).collect::<Vec<_>>())?;
        eprintln!("appended to {HISTORY}");
    }
    Ok(())
}

/// Appends the rows to [`HISTORY`], giving an old file the new header.
fn append_history(rows: &[Row]) -> Result<(), String> {
    let path = Path::new(HISTORY);
    let here = |e: std::io::Error| format!("{HISTORY}: {e} (run from the workspace root)");
    let old = if path.is_file() { fs::read_to_string(path).map_err(here)? } else { String::new() };
    let mut text = if old.is_empty() {
        format!("{HEADER}\n")
    } else {
        pipeline_history::upgrade_header(&old).unwrap_or(old)
    };
    if !text.ends_with('\n') {
        text.push('\n');
    }
    for r in rows {
        text.push_str(&r.to_csv());
        text.push('\n');
    }
    fs::write(path, text).map_err(here)
}

/// The floors, the peer and the G75.1-heavy program: one row per command
/// with its ratio.
fn extra_table(
    results: &[(usize, Vec<Vec<Cell>>)],
    floors: &[Entry],
    extra: &[&Entry],
    notes: &[String],
) -> String {
    let mut s = String::new();
    if extra.is_empty() && notes.is_empty() {
        return s;
    }
    let _ = writeln!(s, "\nFloors, the peer and G75.1 (issue 33):\n");
    for n in notes {
        let _ = writeln!(s, "* {n}");
    }
    if extra.is_empty() && floors.is_empty() {
        return s;
    }
    if !notes.is_empty() {
        s.push('\n');
    }
    let _ = writeln!(s, "| program | build | command | wall | CPU | RSS MB | ratio | wall | CPU |");
    let _ = writeln!(s, "|---|---|---|---:|---:|---:|---|---:|---:|");
    let nc_index = COMMANDS.iter().position(|(n, _)| *n == "expand nc").unwrap_or(0);
    let check_index = COMMANDS.iter().position(|(n, _)| *n == "check").unwrap_or(0);
    let row = |s: &mut String, program: &str, build: &str, command: &str, c: &Cell, r: Option<Ratio>| {
        let (of, w, cpu) = r.map_or_else(
            || ("".into(), "–".into(), "–".into()),
            |r| (r.of, format!("{:.2}×", r.wall), format!("{:.2}×", r.cpu)),
        );
        let _ = writeln!(
            s,
            "| {program} | {build} | {command} | {} | {} | {} | {of} | {w} | {cpu} |",
            c.time(),
            c.cpu(),
            c.mem()
        );
    };
    for ((mb, cells), fl) in results.iter().zip(floors) {
        let program = format!("{mb} MB");
        let nc = &cells[0][nc_index];
        let check = &cells[0][check_index];
        row(&mut s, &program, "new", "expand nc", nc, ratio(&format!("expand nc / {FLOOR}"), nc, &fl.cell));
        row(&mut s, &program, "new", "check", check, ratio("check / expand nc", check, nc));
        row(&mut s, &program, "floor", FLOOR, &fl.cell, None);
    }
    for e in extra {
        let (program, command) = e.command.split_once(": ").unwrap_or(("", &e.command));
        let program = format!("{program} ({:.2} MB)", e.size_mb);
        row(&mut s, &program, &e.build, command, &e.cell, e.ratio.clone());
    }
    s
}

/// Issue 33's targets of the pipeline: `expand nc` within 3× of its floor,
/// `check` within 2× of `expand nc`, `expand --profile linuxcnc` 10× and
/// `check` 5× faster than `rs274 -g`, the G75.1-heavy program 5× faster
/// than the baseline. Met when both the wall and the CPU ratio are.
fn targets_33(entries: &[Entry], peer: &[Entry], g75: &[Entry], base: bool) -> String {
    if entries.is_empty() && peer.is_empty() && g75.is_empty() {
        return String::new();
    }
    let mut s = String::from("\nTargets (issue 33):\n\n");
    let verdict = |ok: bool| if ok { "met" } else { "**missed**" };
    let mut line = |what: String, r: Option<&Ratio>, ok: &dyn Fn(f64) -> bool, want: &str| {
        let _ = match r {
            Some(r) => writeln!(
                s,
                "* {what}: {} wall {:.2}×, CPU {:.2}× ({want}): {}",
                r.of,
                r.wall,
                r.cpu,
                verdict(ok(r.wall) && ok(r.cpu))
            ),
            None => writeln!(s, "* {what}: not measured ({want})"),
        };
    };
    for e in entries.iter().filter(|e| e.build == "new" && e.command == "expand nc") {
        line(format!("{} MB expand nc", e.size_mb), e.ratio.as_ref(), &|r| r <= 3.0, "≤ 3× the floor");
    }
    for e in entries.iter().filter(|e| e.build == "new" && e.command == "check") {
        line(format!("{} MB check", e.size_mb), e.ratio.as_ref(), &|r| r <= 2.0, "≤ 2× expand nc");
    }
    fn find<'a>(v: &'a [Entry], build: &str, suffix: &str) -> Option<&'a Ratio> {
        v.iter().find(|e| e.build == build && e.command.ends_with(suffix)).and_then(|e| e.ratio.as_ref())
    }
    if !peer.is_empty() {
        line(
            "LinuxCNC expand".into(),
            find(peer, "new", ": expand"),
            &|r| r >= 10.0,
            "≥ 10× faster than rs274",
        );
        line(
            "LinuxCNC check".into(),
            find(peer, "new", ": check --trace canon"),
            &|r| r >= 5.0,
            "≥ 5× faster than rs274",
        );
    }
    if !g75.is_empty() {
        if base {
            line(
                "G75.1-heavy expand".into(),
                find(g75, "new", ": expand"),
                &|r| r >= 5.0,
                "≥ 5× faster than the baseline",
            );
        } else {
            let _ = writeln!(
                s,
                "* G75.1-heavy expand: no --baseline, not evaluated (≥ 5× faster than the binary of the issue's \
                 commit, 6457e19)"
            );
        }
    }
    s
}

/// The targets of issue 11, evaluated on the medians.
fn targets(results: &[(usize, Vec<Vec<Cell>>)], base: bool) -> String {
    let mut s = String::from("\nTargets (issue 11):\n\n");
    let idx = |name: &str| COMMANDS.iter().position(|(n, _)| *n == name).unwrap_or(0);
    let verdict = |ok: bool| if ok { "met" } else { "**missed**" };
    for (mb, cells) in results {
        let n = &cells[0];
        let (nc, json) = (&n[idx("expand nc")], &n[idx("expand json")]);
        if nc.done() && json.done() {
            let r = median(&json.times) / median(&nc.times);
            let rc = median(&json.cpu) / median(&nc.cpu);
            let _ = writeln!(
                s,
                "* {mb} MB: json/nc wall {r:.2}×, CPU {rc:.2}× (≤ 3×): {}",
                verdict(r <= 3.0 && rc <= 3.0)
            );
        }
        if base {
            for (name, want) in [
                ("expand nc", Some(5.0)),
                ("expand json", Some(20.0)),
                ("check", Some(5.0)),
                // The reader alone: `passes` of a program without cycles
                // reads it (four times: validation, then the G76, G75.1
                // and G32 tables; aa225a9 once) and writes nothing.
                ("passes plain (reader)", Some(10.0)),
                // The reader twice (validation, then the stream) and the
                // program echoed: shown, not a target of its own.
                ("expand plain (reader)", None),
            ] {
                let (a, b) = (&n[idx(name)], &cells[1][idx(name)]);
                if a.done() && b.done() {
                    let r = median(&b.times) / median(&a.times);
                    let rc = median(&b.cpu) / median(&a.cpu);
                    let target = match want {
                        Some(want) => format!("(≥ {want}×): {}", verdict(r >= want && rc >= want)),
                        None => String::from("(two readings and the echo; no target of its own)"),
                    };
                    let _ = writeln!(s, "* {mb} MB: {name} {r:.1}× faster wall, {rc:.1}× CPU {target}");
                } else if a.done() {
                    let _ = writeln!(s, "* {mb} MB: {name}: baseline {}", b.time());
                }
            }
        }
    }
    // RSS: at most 64 MB on the largest program, growth < 10 % from the
    // 5 MB to the 50 MB one.
    if let Some((mb, cells)) = results.iter().max_by_key(|(mb, _)| *mb) {
        let five = results.iter().find(|(m, _)| *m == 5);
        for (c, (name, _)) in COMMANDS.iter().enumerate().take(COMMANDS.len() - 1) {
            let cell = &cells[0][c];
            if !cell.done() {
                continue;
            }
            let peak = max(&cell.rss);
            let mut line = format!("* RSS {name} at {mb} MB: {peak:.1} MB (≤ 64): {}", verdict(peak <= 64.0));
            if let Some((_, f)) = five.filter(|_| *mb != 5) {
                if f[0][c].done() {
                    let g = peak / max(&f[0][c].rss) - 1.0;
                    let _ =
                        write!(line, "; growth from 5 MB {:+.1}% (< 10%): {}", g * 100.0, verdict(g < 0.10));
                }
            }
            s.push_str(&line);
            s.push('\n');
        }
    }
    s
}

fn git_commit() -> String {
    let out = |args: &[&str]| {
        Command::new("git").args(args).output().ok().filter(|o| o.status.success()).map(|o| o.stdout)
    };
    let hash = out(&["rev-parse", "--short", "HEAD"])
        .map(|o| String::from_utf8_lossy(&o).trim().to_string())
        .unwrap_or_else(|| "unknown".into());
    let dirty = out(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|o| !o.is_empty());
    if dirty {
        format!("{hash}-dirty")
    } else {
        hash
    }
}

fn utc_now() -> String {
    Command::new("date")
        .args(["-u", "+%Y-%m-%dT%H:%M:%SZ"])
        .output()
        .ok()
        .map_or_else(|| "unknown".into(), |o| String::from_utf8_lossy(&o.stdout).trim().to_string())
}
