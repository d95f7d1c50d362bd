//! `track`: run the G76 benchmarks, append the per-pass figures to
//! `benches/history.csv` and fail on a regression.
//!
//! ```text
//! cargo run -p cycleref-benches --release --bin track [-- --skip-bench] [--no-append]
//! ```
//!
//! * runs `cargo bench -p cycleref-benches --bench g76` (unless
//!   `--skip-bench`, which reuses `target/criterion`);
//! * reads the medians, prints the markdown table of the latest figures and
//!   issue 33's targets (engine/f64 ≤ 1.0 on m68x6, passes_1000 and
//!   8_start), met or missed, one line per case (the exit status is the
//!   regression check's, not the targets');
//! * compares the ratios with the last row of each case of the committed
//!   `benches/history.csv` (`git show HEAD:…`; the working copy when the
//!   file is not committed yet);
//! * appends one row per case (unless `--no-append`);
//! * exits 1 when a ratio regressed by more than 25 %, 2 on an error.

#![forbid(unsafe_code)]

use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

use cycleref_benches::track::{self, Row, HEADER};

const USAGE: &str = "usage: track [--skip-bench] [--no-append]

  --skip-bench  reuse the results under target/criterion instead of running
                cargo bench -p cycleref-benches --bench g76
  --no-append   only compare with the history; do not append to benches/history.csv";

fn main() -> ExitCode {
    let mut skip_bench = false;
    let mut append = true;
    for arg in std::env::args().skip(1) {
        match arg.as_str() {
            "--skip-bench" => skip_bench = true,
            "--no-append" => append = false,
            "-h" | "--help" => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            other => {
                eprintln!("track: unknown argument `{other}`\n{USAGE}");
                return ExitCode::from(2);
            }
        }
    }
    match run(skip_bench, append) {
        Ok(regressions) if regressions.is_empty() => ExitCode::SUCCESS,
        Ok(regressions) => {
            eprintln!("track: {} regression(s) beyond 25%:", regressions.len());
            for r in &regressions {
                eprintln!("  {r}");
            }
            ExitCode::from(1)
        }
        Err(e) => {
            eprintln!("track: {e}");
            ExitCode::from(2)
        }
    }
}

/// The benches crate directory (holds `history.csv`).
fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The workspace root.
fn workspace_dir() -> PathBuf {
    crate_dir().parent().map_or_else(crate_dir, Path::to_path_buf)
}

/// Criterion's output directory: `$CARGO_TARGET_DIR/criterion` or
/// `<workspace>/target/criterion`.
fn criterion_dir() -> PathBuf {
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| workspace_dir().join("target"), PathBuf::from);
    target.join("criterion")
}

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).current_dir(crate_dir()).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).into_owned())
}

/// Short hash of HEAD, `-dirty` when the working tree has changes.
fn commit() -> String {
    let hash =
        git(&["rev-parse", "--short", "HEAD"]).map_or_else(|| "unknown".into(), |s| s.trim().to_string());
    let dirty = git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.trim().is_empty());
    if dirty {
        format!("{hash}-dirty")
    } else {
        hash
    }
}

fn run(skip_bench: bool, append: bool) -> Result<Vec<String>, String> {
    if !skip_bench {
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        eprintln!("track: cargo bench -p cycleref-benches --bench g76");
        let status = Command::new(cargo)
            .args(["bench", "-p", "cycleref-benches", "--bench", "g76"])
            .current_dir(workspace_dir())
            // Criterion's report goes to stderr: stdout is for the table.
            .stdout(std::io::stderr())
            .status()
            .map_err(|e| format!("cannot run cargo bench: {e}"))?;
        if !status.success() {
            return Err(format!("cargo bench failed ({status})"));
        }
    }
    let results = track::collect(&criterion_dir())?;
    let figures = track::figures(&results)?;
    let date = track::utc_now();
    let commit = commit();
    println!("{}", track::markdown(&figures, &date, &commit));
    let targets = track::engine_targets(&figures);
    let met = targets.iter().filter(|t| t.met).count();
    eprintln!(
        "track: issue 33's engine targets (engine/f64 <= {:.1}): {met} of {} met{}",
        track::ENGINE_OVER_F64_TARGET,
        targets.len(),
        targets
            .iter()
            .filter(|t| !t.met)
            .map(|t| format!("; {} {:.2}x", t.case, t.engine_over_f64))
            .collect::<String>()
    );

    let history = crate_dir().join("history.csv");
    let (baseline, source) = match git(&["show", "HEAD:./history.csv"]) {
        Some(text) => (track::parse_history(&text), "committed benches/history.csv"),
        None => (
            fs::read_to_string(&history).map(|t| track::parse_history(&t)).unwrap_or_default(),
            "benches/history.csv (working copy; not committed yet)",
        ),
    };
    let rows = Row::of_run(&figures, &date, &commit);
    let regressions = track::regressions(&rows, &baseline);
    if baseline.is_empty() {
        eprintln!("track: no baseline rows in {source}; nothing to compare");
    } else {
        eprintln!("track: compared with the last rows of {source}");
    }
    if append {
        let exists = history.is_file() && fs::metadata(&history).is_ok_and(|m| m.len() > 0);
        let mut file = fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(&history)
            .map_err(|e| format!("{}: {e}", history.display()))?;
        let mut text = String::new();
        if !exists {
            text.push_str(HEADER);
            text.push('\n');
        }
        for row in &rows {
            text.push_str(&row.to_csv());
            text.push('\n');
        }
        file.write_all(text.as_bytes()).map_err(|e| format!("{}: {e}", history.display()))?;
        eprintln!("track: appended {} rows to {}", rows.len(), history.display());
    }
    Ok(regressions)
}
