//! The report's tables beside the main one: the floors, the peer and the
//! G75.1-heavy program, and the targets of issues 11 and 33, evaluated on
//! the medians.

use std::fmt::Write as _;

use cycleref_benches::pipeline_history::Ratio;

use crate::cells::{max, median, ratio, Cell, Entry};
use crate::commands::{COMMANDS, FLOOR};

/// The floors, the peer and the G75.1-heavy program: one row per command
/// with its ratio.
pub(crate) fn extra_table(
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
pub(crate) fn targets_33(entries: &[Entry], peer: &[Entry], g75: &[Entry], base: bool) -> String {
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
pub(crate) fn targets(results: &[(usize, Vec<Vec<Cell>>)], base: bool) -> String {
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
