//! The `cycleref` command: expands the cycles of an NC program into plain
//! moves, tabulates their passes, draws them, checks a vendor's toolpath
//! against them and writes conformance vectors.
//!
//! This file parses the arguments and maps outcomes to exit statuses; the
//! work is done by the `cycleref_cli` library.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, CommandFactory as _, Parser, Subcommand, ValueEnum};
use cycleref::IncrementSystem;
use cycleref_cli::{check, output, plot, vectors, Cause, Failure, Format, Job, Options, Profile};
use cycleref_spec::pipeline::Engine;

const EXIT_STATUS: &str = "Exit status: 0 success (check: the toolpaths agree), 1 check: they differ, \
                           2 an error (a message on stderr naming the file, line, word and rule; nothing \
                           on stdout). A closed output pipe ends the command quietly with status 0, \
                           except for check, whose status is its verdict even then.";

#[derive(Parser)]
#[command(
    name = "cycleref",
    version,
    about = "Reference expansion and checking of lathe thread-cutting and grooving cycles (G76, G78, G92, G32, G75.1; LinuxCNC's G76 and G33)",
    after_help = EXIT_STATUS
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print the program with every cycle replaced by plain blocks.
    #[command(after_help = EXIT_STATUS)]
    Expand {
        #[command(flatten)]
        common: Common,
        /// Output format: the program (nc), one JSON document (json), or one
        /// JSON object per cycle per line and a summary line (jsonl).
        #[arg(long, value_enum, default_value_t = FormatArg::Nc)]
        format: FormatArg,
    },
    /// Print a table of the passes of every cycle.
    #[command(after_help = EXIT_STATUS)]
    Passes {
        #[command(flatten)]
        common: Common,
    },
    /// Compare a vendor's toolpath (an expanded program or a CSV of moves)
    /// with ours, pass by pass. Exit 0 when they agree, 1 when they differ.
    #[command(after_help = EXIT_STATUS)]
    Check {
        #[command(flatten)]
        common: Common,
        /// The vendor's toolpath: plain G00/G01/G02/G03/G32 blocks, or a CSV
        /// of moves (`.csv`; see the README for the columns).
        #[arg(long, value_name = "TRACE")]
        trace: PathBuf,
        /// The trace's format [default: by its extension: `.csv` a CSV,
        /// `.canon` rs274's canonical output, anything else nc]. Needed for a
        /// CSV or canonical trace on standard input (`--trace -`).
        #[arg(long, value_enum, value_name = "FORMAT")]
        trace_format: Option<TraceFormatArg>,
        #[command(flatten)]
        compare: Compare,
        /// Report format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
    /// Write a corpus of conformance vectors (programs, parameters and the
    /// expected moves or error) as JSON files.
    #[command(after_help = EXIT_STATUS)]
    Vectors {
        /// Number of cases (125, the default, use every template).
        #[arg(long, default_value_t = 125)]
        count: u32,
        /// Seed of the generator: the same seed gives the same corpus.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output directory (created if missing; it must not be a file).
        #[arg(long)]
        out: PathBuf,
    },
    /// Run a vendor's outputs against a corpus of conformance vectors: one
    /// verdict per case (its trace agrees with the expected moves, or the
    /// expected refusal was made), a summary, and JUnit XML for CI. Exit 0
    /// when every case passes, 1 when one does not.
    #[command(after_help = EXIT_STATUS)]
    Conform {
        /// The corpus directory (`case-NNNN.json`, written by `cycleref
        /// vectors`), or with --pairs the list of pairs.
        corpus: PathBuf,
        /// The vendor's outcomes: `case-NNNN.nc`, `.csv` or `.canon` (a
        /// trace) or `case-NNNN.error` (a refusal, holding its message).
        #[arg(long, value_name = "DIR", required_unless_present_any = ["run", "pairs"], conflicts_with_all = ["run", "pairs"])]
        traces: Option<PathBuf>,
        /// A batch `check`: CORPUS is a list of programs and their traces,
        /// `PROGRAM TRACE [PROFILE]` a line (tab- or space-separated, paths
        /// relative to the list, `#` comments); each program must agree
        /// with its trace. A pair without a profile is read with --profile
        /// and --params.
        #[arg(long, conflicts_with = "run")]
        pairs: bool,
        /// With --pairs: the profile of a pair that names none [default:
        /// the parameter file's, else gsk988].
        #[arg(long, value_enum, requires = "pairs")]
        profile: Option<ProfileArg>,
        /// With --pairs: a parameter file for the pairs that name no profile.
        #[arg(long, value_name = "FILE", requires = "pairs")]
        params: Option<PathBuf>,
        /// With --pairs: a reading for every pair (repeatable, as for
        /// `check`; a vectors corpus carries its own machine).
        #[arg(long = "reading", value_name = "ID=VALUE", requires = "pairs")]
        readings: Vec<String>,
        /// A shell command run per case: `{program}` (the case's program
        /// file), `{params}` (its machine as a parameter file), `{profile}`
        /// and `{trace}` (where to write the trace) are replaced; exit
        /// status 0 gives a trace, any other a refusal. E.g. `--run
        /// 'my-sim --profile {profile} {program} > {trace}'`.
        #[arg(long, value_name = "TEMPLATE")]
        run: Option<String>,
        /// The format of the traces a --run command writes [default: nc]
        /// (a directory's traces go by their extension).
        #[arg(long, value_enum, value_name = "FORMAT")]
        trace_format: Option<TraceFormatArg>,
        #[command(flatten)]
        compare: Compare,
        /// Threads [default: the number of cores].
        #[arg(long, value_name = "N")]
        jobs: Option<usize>,
        /// Run part I of N of the corpus: the cases whose index is I modulo
        /// N (1-based), so that N machines share a corpus with no
        /// coordination.
        #[arg(long, value_name = "I/N", default_value = "1/1")]
        shard: String,
        /// Write JUnit XML (one testcase per case) to FILE.
        #[arg(long, value_name = "FILE")]
        junit: Option<PathBuf>,
    },
    /// Draw the toolpath of the program's cycles in the XZ plane as SVG.
    #[command(after_help = EXIT_STATUS)]
    Plot {
        #[command(flatten)]
        common: Common,
        /// Output file.
        #[arg(short, long)]
        output: PathBuf,
        /// A vendor's toolpath (as for `check`) to draw over ours.
        #[arg(long, value_name = "TRACE")]
        trace: Option<PathBuf>,
        /// Draw only the cycle whose block is at this line (either block
        /// of a G76, G78 or G75.1, or a G32 or G92 block); repeatable. Without it, the first 24
        /// cycles are drawn and stderr says how many were left out.
        #[arg(long = "line", value_name = "N")]
        lines: Vec<usize>,
    },
    /// List the selectable readings (issue 34): one line each, its id, its
    /// values with the default marked `*`, the profiles on which it changes
    /// anything, and the source of each value; tab-separated.
    Readings {
        /// List only the readings that change anything on this profile.
        #[arg(long, value_enum)]
        profile: Option<ProfileArg>,
    },
    /// Print a completion script for SHELL on standard output, e.g.
    /// `cycleref completions bash > /etc/bash_completion.d/cycleref`.
    Completions {
        /// The shell.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
    },
    /// Print a manual page (roff) on standard output: the command's, or a
    /// subcommand's (`cycleref man expand > cycleref-expand.1`). The
    /// repository keeps them in cli/man/.
    Man {
        /// The subcommand whose page to print.
        subcommand: Option<String>,
    },
}

#[derive(Args)]
struct Common {
    /// Control profile [default: the parameter file's `profile`, else gsk988].
    #[arg(long, value_enum)]
    profile: Option<ProfileArg>,
    /// Increment system [default: the parameter file's, else is-b].
    #[arg(long, value_enum)]
    increment: Option<Increment>,
    /// Inch input at program start (G20); G20/G21 in the program override it.
    #[arg(long)]
    inch: bool,
    /// X words are radii, not diameters.
    #[arg(long)]
    radius: bool,
    /// Parameter file (TOML), applied after the profile's defaults. An
    /// option given on the command line always wins over the file.
    #[arg(long, value_name = "FILE")]
    params: Option<PathBuf>,
    /// Choose a reading where the manuals leave a point open (repeatable),
    /// e.g. `--reading R-RUNOUT=gsk988-only`; it wins over the parameter
    /// file's `[readings]`. `cycleref readings` lists the ids and values.
    #[arg(long = "reading", value_name = "ID=VALUE")]
    readings: Vec<String>,
    /// Engine that expands the cycles: the fixed-point engine (`impl`) or
    /// the exact-decimal reference model (`spec`); both give the same output.
    #[arg(long, value_enum, default_value_t = EngineArg::Impl)]
    engine: EngineArg,
    /// Program file, or `-` for standard input (required when standard
    /// input is a terminal).
    file: Option<PathBuf>,
}

impl Common {
    fn options(&self) -> Options {
        Options {
            profile: self.profile.map(|p| match p {
                ProfileArg::Fanuc => Profile::Fanuc,
                ProfileArg::Gsk980 => Profile::Gsk980,
                ProfileArg::Gsk988 => Profile::Gsk988,
                ProfileArg::LinuxCnc => Profile::LinuxCnc,
            }),
            increment: self.increment.map(|i| match i {
                Increment::IsB => IncrementSystem::IsB,
                Increment::IsC => IncrementSystem::IsC,
            }),
            inch: self.inch,
            radius: self.radius,
            params: self.params.clone(),
            readings: self.readings.clone(),
            engine: match self.engine {
                EngineArg::Impl => Engine::Impl,
                EngineArg::Spec => Engine::Spec,
            },
            file: self.file.clone(),
        }
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum ProfileArg {
    Fanuc,
    Gsk980,
    Gsk988,
    /// LinuxCNC 2.9's interpreter: G76 P Z I J R K Q H E L, G7/G8 (IS-C, radius X at start)
    #[value(name = "linuxcnc")]
    LinuxCnc,
}

#[derive(Clone, Copy, ValueEnum)]
enum Increment {
    #[value(name = "is-b")]
    IsB,
    #[value(name = "is-c")]
    IsC,
}

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum EngineArg {
    /// The fixed-point engine (cycleref::engine).
    Impl,
    /// The exact-decimal reference model (cycleref-spec).
    Spec,
}

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum ReportFormat {
    Text,
    Json,
}

/// How `check` and `conform` compare a trace with ours.
#[derive(Args)]
struct Compare {
    /// Largest difference, in least increments, still counted as equal.
    #[arg(long, default_value_t = 0)]
    tolerance: u64,
    /// Compare only the moves of the program's cycles: the trace logs a
    /// cycle's moves, not the program's own blocks.
    #[arg(long)]
    cycles_only: bool,
}

impl From<TraceFormatArg> for check::TraceFormat {
    fn from(f: TraceFormatArg) -> check::TraceFormat {
        match f {
            TraceFormatArg::Nc => check::TraceFormat::Nc,
            TraceFormatArg::Csv => check::TraceFormat::Csv,
            TraceFormatArg::Canon => check::TraceFormat::Rs274,
        }
    }
}

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum TraceFormatArg {
    /// An expanded program: plain G00/G01/G02/G03/G32 (G33) blocks.
    Nc,
    /// A CSV of moves with a header (see the README).
    Csv,
    /// LinuxCNC's canonical output (`rs274 -g`), with --profile linuxcnc.
    Canon,
}

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum FormatArg {
    Nc,
    Json,
    Jsonl,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => ExitCode::from(code),
        Err(Failure::BrokenPipe) => ExitCode::SUCCESS,
        // The stable kind first, as a compiler names its error codes, so
        // that a vendor's script matches it with the vectors' kinds
        // (`error[syntax]: …`, `error[trace]: …`).
        Err(failure) => {
            warn(&failure.to_string());
            ExitCode::from(2)
        }
    }
}

/// Writes `cycleref: {msg}` on standard error. A standard error that
/// cannot be written (closed, or a full disk) loses the message, never the
/// exit status: `eprintln!` would panic (exit 101).
fn warn(msg: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(err, "cycleref: {msg}").and_then(|()| err.flush());
}

/// Writes `text` on standard output.
fn print(text: &str) -> Result<(), Failure> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes()).and_then(|()| out.flush()).map_err(|e| Failure::output(&e))
}

/// A manual page: clap's sections (name, synopsis, description, options,
/// subcommands, version) with the command's own between them: EXIT
/// STATUS, and the page's sections of [`MAN_SECTIONS`] (trace formats,
/// examples).
fn man_page(page: clap::Command, subcommand: Option<&str>) -> std::io::Result<Vec<u8>> {
    let has_args = page.get_arguments().any(|a| !a.is_hide_set());
    let has_subcommands = page.get_subcommands().next().is_some();
    let man = clap_mangen::Man::new(page);
    let mut out = Vec::new();
    man.render_title(&mut out)?;
    man.render_name_section(&mut out)?;
    man.render_synopsis_section(&mut out)?;
    man.render_description_section(&mut out)?;
    if has_args {
        man.render_options_section(&mut out)?;
    }
    if has_subcommands {
        man.render_subcommands_section(&mut out)?;
    }
    let sections = std::iter::once(("EXIT STATUS", EXIT_STATUS)).chain(
        MAN_SECTIONS.iter().filter(|(page, _, _)| *page == subcommand.unwrap_or("")).map(|&(_, h, t)| (h, t)),
    );
    for (heading, text) in sections {
        writeln!(out, ".SH \"{heading}\"")?;
        for paragraph in text.split("\n\n") {
            // A paragraph of lines starting with `$ ` is an example:
            // shown as written, one line each.
            if paragraph.starts_with("$ ") {
                writeln!(out, ".PP\n.nf\n.RS 4")?;
                for line in paragraph.lines() {
                    writeln!(out, "{}", roff_text(line))?;
                }
                writeln!(out, ".RE\n.fi")?;
            } else {
                writeln!(out, ".PP\n{}", roff_text(&paragraph.replace('\n', " ")))?;
            }
        }
    }
    man.render_version_section(&mut out)?;
    Ok(out)
}

/// Text as roff: backslashes and hyphens escaped, a line that would start
/// with a control character guarded.
fn roff_text(line: &str) -> String {
    let text = line.replace('\\', "\\e").replace('-', "\\-");
    if text.starts_with('.') || text.starts_with('\'') {
        format!("\\&{text}")
    } else {
        text
    }
}

/// The sections of the manual pages beyond clap's: (page, heading, text),
/// the page `""` for `cycleref` itself. Paragraphs are separated by a blank
/// line; a paragraph of `$ ` lines is an example.
const MAN_SECTIONS: &[(&str, &str, &str)] = &[
    (
        "",
        "EXAMPLES",
        "$ cycleref expand --profile gsk988 examples/gsk988-m68x6.nc\n\
         $ cycleref check --profile gsk988 --trace vendor.nc examples/gsk988-m68x6.nc\n\
         $ cycleref vectors --count 500 --seed 7 --out corpus\n\
         $ cycleref conform corpus --run 'my-sim {program} > {trace}' --junit conform.xml\n\n\
         See cycleref-expand(1), cycleref-check(1), cycleref-conform(1) and the README for the nc and json \
         contracts, the profiles and the parameter file.",
    ),
    (
        "expand",
        "EXAMPLES",
        "$ cycleref expand --profile gsk988 examples/gsk988-m68x6.nc > m68.nc\n\
         $ cycleref expand --profile fanuc --format json prog.nc | jq '.cycles[0].moves | length'\n\
         $ cycleref expand --profile linuxcnc --format jsonl part.ngc\n\
         $ cat prog.nc | cycleref expand --params machine.toml -\n\n\
         The nc output is the program with every cycle replaced by plain blocks, each pass headed by a \
         comment; it reads back as itself (expand of the expansion is the expansion).",
    ),
    ("passes", "EXAMPLES", "$ cycleref passes --profile gsk980 examples/gsk980-g78.nc"),
    (
        "check",
        "TRACE FORMATS",
        "nc (any extension but .csv and .canon): an expanded program, plain G00/G01/G02/G03 and G32 (G33 on \
         linuxcnc) blocks, read by the program reader in its trace mode: arcs give their centre as I and K, \
         a thread's lead as F or I and its start angle as Q; a canned cycle, R, G41/G42, a J or K on a \
         thread move, or any word that is not part of a plain move is an error naming the line and word.\n\n\
         csv (.csv, or --trace-format csv): a header row naming the columns, then one move a row: motion \
         (rapid, feed, thread, arc-cw, arc-ccw), x, z, and as needed lead, q, i and k (or cx and cz); see \
         the README.\n\n\
         canon (.canon, or --trace-format canon, with --profile linuxcnc): LinuxCNC's canonical output, \
         rs274 -g FILE < /dev/null; every call is read or refused by name.\n\n\
         The moves outside the cycles (the program's own G00 blocks) are compared too, unless \
         --cycles-only.",
    ),
    (
        "check",
        "EXAMPLES",
        "$ cycleref check --profile gsk988 --trace vendor.nc examples/gsk988-m68x6.nc\n\
         $ cycleref check --profile gsk980 --trace log.csv --format json prog.nc > report.json\n\
         $ rs274 -g part.ngc < /dev/null > part.canon\n\
         $ cycleref check --profile linuxcnc --trace part.canon --tolerance 1 part.ngc\n\
         $ my-logger | cycleref check --trace - --trace-format csv --cycles-only prog.nc",
    ),
    (
        "conform",
        "OUTCOMES",
        "With --traces DIR, case-NNNN.nc, .csv or .canon is the vendor's trace of case NNNN and \
         case-NNNN.error (holding the message) its refusal. With --run, the command's exit status 0 gives \
         the trace it wrote to {trace}, any other a refusal. A case passes when the trace agrees with the \
         expected moves or the expected refusal was made.",
    ),
    (
        "conform",
        "EXAMPLES",
        "$ cycleref vectors --count 10000 --seed 42 --out corpus\n\
         $ cycleref conform corpus --traces outputs --junit conform.xml\n\
         $ cycleref conform corpus --run 'my-sim --profile {profile} {program} > {trace}' --shard 2/4\n\
         $ cycleref conform pairs.txt --pairs --profile fanuc --junit check.xml",
    ),
    ("vectors", "EXAMPLES", "$ cycleref vectors --count 125 --seed 1 --out vectors"),
    (
        "readings",
        "EXAMPLES",
        "$ cycleref readings --profile gsk980\n\
         $ cycleref expand --profile gsk980 --reading R-RUNOUT=gsk988-only prog.nc",
    ),
    (
        "plot",
        "EXAMPLES",
        "$ cycleref plot --profile gsk988 examples/gsk988-m68x6.nc -o m68.svg\n\
         $ cycleref plot --profile gsk988 --trace vendor.nc --line 5 prog.nc -o overlay.svg",
    ),
    (
        "completions",
        "EXAMPLES",
        "$ cycleref completions bash > ~/.local/share/bash-completion/completions/cycleref",
    ),
    ("man", "EXAMPLES", "$ cycleref man check | man -l -"),
];

/// Runs a command: its exit status, or a failure.
fn run(cli: Cli) -> Result<u8, Failure> {
    match cli.command {
        Command::Expand { common, format } => {
            let job = Job::load(&common.options())?;
            let format = match format {
                FormatArg::Nc => Format::Nc,
                FormatArg::Json => Format::Json,
                FormatArg::Jsonl => Format::Jsonl,
            };
            output::expand(&job, format, std::io::stdout().lock())?;
            Ok(0)
        }
        Command::Completions { shell } => {
            let mut text = Vec::new();
            clap_complete::generate(shell, &mut Cli::command(), "cycleref", &mut text);
            print(&String::from_utf8_lossy(&text))?;
            Ok(0)
        }
        Command::Man { subcommand } => {
            let mut command = Cli::command();
            command.build();
            let page = match &subcommand {
                None => command,
                Some(name) => {
                    let found = command.get_subcommands().find(|c| c.get_name() == name.as_str()).cloned();
                    let sub = found.ok_or_else(|| Failure::usage(format!("man: no subcommand `{name}`")))?;
                    // The page's title is `cycleref-<name>`, as the main
                    // page's list of subcommands names it.
                    let title = format!("cycleref-{name}");
                    sub.name(title.clone()).bin_name(title).version(env!("CARGO_PKG_VERSION"))
                }
            };
            let text = man_page(page, subcommand.as_deref()).map_err(|e| Failure::output(&e))?;
            print(&String::from_utf8_lossy(&text))?;
            Ok(0)
        }
        Command::Readings { profile } => {
            let profile = profile.map(|p| match p {
                ProfileArg::Fanuc => cycleref_spec::ProfileName::Fanuc,
                ProfileArg::Gsk980 => cycleref_spec::ProfileName::Gsk980,
                ProfileArg::Gsk988 => cycleref_spec::ProfileName::Gsk988,
                ProfileArg::LinuxCnc => cycleref_spec::ProfileName::LinuxCnc,
            });
            print(&cycleref_spec::readings::Listing { profile }.to_string())?;
            Ok(0)
        }
        Command::Passes { common } => {
            output::passes(&Job::load(&common.options())?, std::io::stdout().lock())?;
            Ok(0)
        }
        Command::Plot { common, output, trace, lines } => {
            let job = Job::load(&common.options())?;
            let (svg, note) = plot::run(&job, &lines, trace.as_deref())?;
            std::fs::write(&output, svg).map_err(|e| {
                Failure::new(Cause::Output, format!("{}: cannot write: {e}", output.display()))
            })?;
            if let Some(note) = note {
                warn(&note);
            }
            Ok(0)
        }
        Command::Check { common, trace, trace_format, compare, format } => {
            let job = Job::load(&common.options())?;
            let options = check::CheckOptions {
                format: trace_format.map(Into::into),
                tolerance: compare.tolerance,
                cycles_only: compare.cycles_only,
            };
            let report = check::run_as(&job, &trace, &options)?;
            // The verdict is decided before the report is written, and the
            // exit status carries it whatever becomes of the report: a
            // closed pipe (`check … | head -1`) stops the writing quietly
            // and keeps the status (1 for DIFFER); any other write error
            // (a full disk) is status 2 with its message.
            let verdict = u8::from(!report.agree());
            match print(&match format {
                ReportFormat::Text => report.text(),
                ReportFormat::Json => report.json(),
            }) {
                Ok(()) | Err(Failure::BrokenPipe) => Ok(verdict),
                Err(e) => Err(e),
            }
        }
        Command::Conform {
            corpus,
            traces,
            run,
            pairs,
            profile,
            params,
            readings,
            trace_format,
            compare,
            jobs,
            shard,
            junit,
        } => {
            let outcomes = match (traces, run, pairs) {
                (_, _, true) => {
                    let common = Common {
                        profile,
                        increment: None,
                        inch: false,
                        radius: false,
                        params,
                        readings,
                        engine: EngineArg::Impl,
                        file: None,
                    };
                    cycleref_cli::conform::Outcomes::Pairs {
                        machine: Box::new(cycleref_cli::job::machine(&common.options())?),
                    }
                }
                (Some(dir), _, false) => cycleref_cli::conform::Outcomes::Dir(dir),
                (None, Some(template), false) => cycleref_cli::conform::Outcomes::Run(template),
                (None, None, false) => {
                    return Err(Failure::usage("give --traces DIR, --run TEMPLATE or --pairs"))
                }
            };
            let options = cycleref_cli::conform::ConformOptions {
                corpus,
                outcomes,
                trace_format: trace_format.map(Into::into),
                tolerance: compare.tolerance,
                cycles_only: compare.cycles_only,
                shard: cycleref_cli::conform::Shard::parse(&shard)
                    .map_err(|e| Failure::with_kind(Cause::Usage, e.stable_kind(), e.to_string()))?,
                jobs: jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from)),
                junit,
            };
            let summary = cycleref_cli::conform::run(&options, &mut std::io::stdout().lock())?;
            Ok(u8::from(!summary.all_passed()))
        }
        Command::Vectors { count, seed, out } => {
            print(
                &vectors::run(count, seed, &out)
                    .map_err(|e| Failure::with_kind(Cause::Vectors, e.stable_kind(), e.to_string()))?,
            )?;
            Ok(0)
        }
    }
}
