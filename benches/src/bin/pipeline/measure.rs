//! Measuring a child: each run of a command in a fresh child reaped with
//! `wait4` (its own rusage: wall and CPU time, peak RSS) under the time
//! and address-space limits, through a copy of this program (`--wrap`),
//! and the unmeasured runs (`run_to`).
#![allow(unsafe_code)] // wait4, kill and setrlimit: the only way to a child's own rusage.

use std::fs::{self, File};
use std::os::unix::process::CommandExt as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use crate::cells::Cell;

/// How one child run ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Outcome {
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
pub(crate) fn measure(
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
pub(crate) fn wrap(mut a: impl Iterator<Item = String>) -> Result<(), String> {
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

pub(crate) fn run_one(
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

/// Runs `bin args` once, unmeasured, with stdout to `out` (or captured
/// when `None`); its stdout when captured, an error when it fails.
pub(crate) fn run_to(bin: &Path, args: &[String], out: Option<&Path>) -> Result<String, String> {
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
