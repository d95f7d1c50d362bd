//! The commands measured on a mixed program ([`COMMANDS`]), their
//! arguments over the program's [`Files`], the trace `check` reads, and
//! whether a build supports a command at all.

use std::fs::{self, File};
use std::path::{Path, PathBuf};
use std::process::Command;

use cycleref_benches::corpus;

use crate::measure::{measure, Outcome};

/// The name of the floor's rows.
pub(crate) const FLOOR: &str = "bytes-out floor";

/// The commands measured on one program, by name; `{prog}`, `{plain}`,
/// `{trace}`, `{line}`, `{svg}` are replaced.
pub(crate) const COMMANDS: [(&str, &str); 9] = [
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

pub(crate) fn command_args(template: &str, files: &Files) -> Vec<String> {
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

pub(crate) struct Files {
    pub(crate) prog: PathBuf,
    pub(crate) plain: PathBuf,
    pub(crate) trace: PathBuf,
    pub(crate) svg: PathBuf,
    pub(crate) line: usize,
}

/// Writes `bin`'s nc expansion of the program to the trace file.
pub(crate) fn write_trace(bin: &Path, files: &Files) -> Result<(), String> {
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
pub(crate) fn supports(bin: &Path, template: &str, dir: &Path) -> Result<bool, String> {
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
