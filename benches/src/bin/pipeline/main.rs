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
//! expand nc`. The sides of each ratio run in one alternation (each
//! repetition runs `expand nc`, `expand json`, `check`, then the floor), so
//! that a change of the machine's load during the run falls on both sides
//! alike (`json / nc` is issue 11's ratio).
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
//! build, the baseline's when given, and the floor. These side-by-side
//! rounds repeat more often than `--reps` when a round is short (until
//! they take a second together; `extra.rs`, `rounds`).
//!
//! Prints one markdown table (medians), the targets of issues 11 and 33,
//! and appends one row per program, command and build to
//! `benches/pipeline-history.csv` (see `benches/README.md`;
//! `cycleref_benches::pipeline_history`).
//!
//! This file holds `main` and the run of the mixed programs; the command
//! line is in `args.rs`, the measured children in `measure.rs`, the
//! figures in `cells.rs`, the commands in `commands.rs`, the floor, peer
//! and G75.1 benchmarks in `extra.rs` and the other tables in `report.rs`.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;
use std::process::{Command, ExitCode};

use cycleref_benches::corpus;
use cycleref_benches::pipeline_history::{self, Row, HEADER};

mod args;
mod cells;
mod commands;
mod extra;
mod measure;
mod report;

use args::{parse, Args, USAGE};
use cells::{median, ratio, Cell, Entry};
use commands::{command_args, supports, write_trace, Files, COMMANDS, FLOOR};
use extra::{floor_args, floor_main, g75_heavy, peer, shape_of};
use measure::{run_one, wrap};
use report::{extra_table, targets, targets_33};

const HISTORY: &str = "benches/pipeline-history.csv";

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
    let json_index = COMMANDS.iter().position(|(n, _)| *n == "expand json").unwrap_or(0);
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
        for c in 0..COMMANDS.len() {
            // The two sides of a ratio run in one alternation, so that a
            // change of the machine's load between them cannot make the
            // ratio: `expand json` and `check` run beside `expand nc` (and
            // the floor), not in loops of their own.
            let group: &[usize] = if c == check_index || c == json_index {
                continue;
            } else if c == nc_index {
                &[nc_index, json_index, check_index]
            } else {
                &[c]
            };
            for rep in 0..args.reps {
                for &g in group {
                    let (name, template) = COMMANDS[g];
                    let a = command_args(template, &files);
                    for (b, (build, bin)) in builds.iter().enumerate() {
                        let cell = &mut cells[b][g];
                        if !support[b][g] {
                            cell.status = Some("unsupported".into());
                            continue;
                        }
                        if gave_up[b][g] && cell.status.is_none() {
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
                            gave_up[b][g] = true;
                        }
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
    let _ = writeln!(
        table,
        "Medians of {} runs each (the peer and G75.1 programs: {} and {} rounds), {date}, commit {commit}.\n",
        args.reps,
        peer.first().map_or(0, |e| e.cell.times.len()),
        g75.first().map_or(0, |e| e.cell.times.len()),
    );
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
