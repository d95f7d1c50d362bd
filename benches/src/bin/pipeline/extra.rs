//! The benchmarks of issue 33 beside the mixed programs: the bytes-out
//! floor (this program as a child, `--floor SHAPE`), the peer benchmark
//! against LinuxCNC's `rs274` and the G75.1-heavy program.

use std::fs;
use std::path::{Path, PathBuf};

use cycleref_benches::corpus;
use cycleref_benches::floor::{self, Shape};

use crate::args::Args;
use crate::cells::{mib, ratio, Cell, Entry};
use crate::commands::FLOOR;
use crate::measure::{run_one, run_to};

/// `pipeline --floor SHAPE`: the bytes-out floor of that shape to stdout.
pub(crate) fn floor_main(shape: Option<String>) -> Result<(), String> {
    let shape: Shape = shape.ok_or("no shape")?.parse()?;
    floor::write_floor(&shape, std::io::stdout().lock()).map_err(|e| e.to_string())?;
    Ok(())
}

/// The floor's shape of an nc expansion in a file.
pub(crate) fn shape_of(nc: &Path) -> Result<Shape, String> {
    Ok(Shape::of_nc(&fs::read(nc).map_err(|e| format!("{}: {e}", nc.display()))?))
}

/// The arguments of the floor child for `shape`.
pub(crate) fn floor_args(shape: &Shape) -> Vec<String> {
    vec!["--floor".into(), shape.to_string()]
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

/// The least time, in seconds, that the rounds of one side-by-side
/// measurement take together: a round of short commands is repeated more
/// often than `--reps` says (see [`rounds`]).
const MIN_SIDE_BY_SIDE_SECS: f64 = 1.0;

/// The most rounds a side-by-side measurement runs, whatever its length.
const MAX_ROUNDS: usize = 200;

/// How many rounds a side-by-side measurement runs when its first round
/// took `first` seconds of wall time: `--reps`, or more when the round is
/// short, so that the rounds take at least [`MIN_SIDE_BY_SIDE_SECS`]
/// together (at most [`MAX_ROUNDS`]). A command of a few milliseconds
/// measured five times gives a median that one preempted run moves by a
/// third (the G75.1 program, about 10 ms, went 2.4-3.9x against the
/// baseline between four runs at one commit); the rounds still alternate,
/// so every ratio divides medians taken under the same load.
fn rounds(reps: usize, first: f64) -> usize {
    if first <= 0.0 || !first.is_finite() {
        return reps;
    }
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let wanted = (MIN_SIDE_BY_SIDE_SECS / first).ceil().min(MAX_ROUNDS as f64) as usize;
    reps.max(wanted)
}

/// Runs every `(bin, args)` job, alternating, into its cell: the commands
/// of one program, side by side, for as many rounds as [`rounds`] gives.
fn measure_side_by_side(
    args: &Args,
    label: &str,
    jobs: &[(&Path, Vec<String>, &str)],
) -> Result<Vec<Cell>, String> {
    let mut cells = vec![Cell::default(); jobs.len()];
    let limits = Some((args.timeout, args.mem_limit_mb));
    let mut reps = args.reps;
    let mut rep = 0;
    while rep < reps {
        let started = std::time::Instant::now();
        for ((bin, a, name), cell) in jobs.iter().zip(&mut cells) {
            if cell.status.is_some() {
                continue;
            }
            eprintln!("  {label} {name} #{}", rep + 1);
            run_one(bin, a, &args.dir.join("extra.err"), limits, cell)?;
        }
        if rep == 0 {
            reps = rounds(args.reps, started.elapsed().as_secs_f64());
        }
        rep += 1;
    }
    Ok(cells)
}

/// The peer benchmark of issue 33 (see the module's documentation); its
/// entries, or none and a note when `rs274` is not installed.
pub(crate) fn peer(args: &Args, notes: &mut Vec<String>) -> Result<Vec<Entry>, String> {
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
pub(crate) fn g75_heavy(args: &Args) -> Result<Vec<Entry>, String> {
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

#[cfg(test)]
mod tests {
    use super::rounds;

    #[test]
    fn short_rounds_are_repeated_until_a_second() {
        // The G75.1 round: about 10 + 5 + 35 ms = 0.05 s: 1 / 0.05 = 20 rounds.
        assert_eq!(rounds(5, 0.05), 20);
        // The peer round (rs274 0.6 s and ours): --reps as given.
        assert_eq!(rounds(5, 0.75), 5);
        assert_eq!(rounds(3, 0.3), 4);
        // Bounded, and a round that measured nothing keeps --reps.
        assert_eq!(rounds(5, 1e-6), 200);
        assert_eq!(rounds(5, 0.0), 5);
        assert_eq!(rounds(300, 0.001), 300);
    }
}
