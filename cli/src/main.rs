//! The `cycleref` command: expands the cycles of an NC program into plain
//! moves, tabulates their passes and draws them.
//!
//! Exit status: 0 on success, 2 on any error (with a message naming the
//! file, line, word and rule on stderr, and nothing on stdout).
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod check;
mod format;
mod plot;
mod plot_g75;
mod vectors;

use std::fmt::Write as _;
use std::io::Read as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use cycleref::{CycleError, G32Block, G75Cycle, G76Cycle, IncrementSystem, InputUnit, Move, XMode};
use cycleref_spec::profile::QUnit;
use cycleref_spec::reader::Item;
use cycleref_spec::{read, Machine, ProfileName, Program};
use serde_json::json;

#[derive(Parser)]
#[command(
    name = "cycleref",
    version,
    about = "Reference expansion and checking of lathe thread-cutting cycles (G76, G32)"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print the program with every cycle replaced by plain blocks.
    Expand {
        #[command(flatten)]
        common: Common,
        /// Output format.
        #[arg(long, value_enum, default_value_t = Format::Nc)]
        format: Format,
    },
    /// Print a table of the passes of every cycle.
    Passes {
        #[command(flatten)]
        common: Common,
    },
    /// Compare a vendor's toolpath (an expanded program or a CSV of moves)
    /// with ours, pass by pass. Exit 0 when they agree, 1 when they differ.
    Check {
        #[command(flatten)]
        common: Common,
        /// The vendor's toolpath: plain G00/G01/G02/G03/G32 blocks, or a CSV
        /// of moves (`.csv`; see the README for the columns).
        #[arg(long, value_name = "TRACE")]
        trace: PathBuf,
        /// Largest difference, in least increments, still counted as equal.
        #[arg(long, default_value_t = 0)]
        tolerance: u64,
        /// Report format.
        #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
        format: ReportFormat,
    },
    /// Write a corpus of conformance vectors (programs, parameters and the
    /// expected moves or error) as JSON files.
    Vectors {
        /// Number of cases.
        #[arg(long, default_value_t = 100)]
        count: u32,
        /// Seed of the generator: the same seed gives the same corpus.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Output directory (created if missing).
        #[arg(long)]
        out: PathBuf,
    },
    /// Draw the toolpath of every cycle in the XZ plane as SVG.
    Plot {
        #[command(flatten)]
        common: Common,
        /// Output file.
        #[arg(short, long)]
        output: PathBuf,
        /// A vendor's toolpath (as for `check`) to draw over ours.
        #[arg(long, value_name = "TRACE")]
        trace: Option<PathBuf>,
    },
}

#[derive(Args)]
struct Common {
    /// Control profile.
    #[arg(long, value_enum, default_value_t = Profile::Gsk988)]
    profile: Profile,
    /// Increment system.
    #[arg(long, value_enum)]
    increment: Option<Increment>,
    /// Inch input at program start (G20); G20/G21 in the program override it.
    #[arg(long)]
    inch: bool,
    /// X words are radii, not diameters.
    #[arg(long)]
    radius: bool,
    /// Parameter file (TOML), applied after the profile's defaults.
    #[arg(long, value_name = "FILE")]
    params: Option<PathBuf>,
    /// Engine that expands the cycles: the fixed-point engine (`impl`) or
    /// the exact-decimal reference model (`spec`); both give the same output.
    #[arg(long, value_enum, default_value_t = Engine::Impl)]
    engine: Engine,
    /// Program file, or `-` for standard input.
    #[arg(default_value = "-")]
    file: PathBuf,
}

#[derive(Clone, Copy, ValueEnum)]
enum Profile {
    Fanuc,
    Gsk980,
    Gsk988,
}

#[derive(Clone, Copy, ValueEnum)]
enum Increment {
    #[value(name = "is-b")]
    IsB,
    #[value(name = "is-c")]
    IsC,
}

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum Engine {
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

#[derive(Clone, Copy, ValueEnum, PartialEq, Eq)]
enum Format {
    Nc,
    Json,
}

/// An error for the user: printed on stderr, exit status 2.
struct Failure(String);

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok((out, code)) => {
            print!("{out}");
            ExitCode::from(code)
        }
        Err(Failure(msg)) => {
            eprintln!("cycleref: {msg}");
            ExitCode::from(2)
        }
    }
}

/// Runs a command: its standard output and exit status, or a failure
/// (exit status 2).
fn run(cli: Cli) -> Result<(String, u8), Failure> {
    let ok = |s: String| Ok((s, 0));
    match cli.command {
        Command::Expand { common, format } => {
            let job = Job::load(&common)?;
            match format {
                Format::Nc => ok(job.nc()?),
                Format::Json => ok(job.json()?),
            }
        }
        Command::Passes { common } => ok(Job::load(&common)?.passes()?),
        Command::Plot { common, output, trace } => {
            let job = Job::load(&common)?;
            let overlay = match trace {
                Some(t) => Some(check::overlay(&job, &t).map_err(Failure)?),
                None => None,
            };
            let svg = job.plot(overlay.as_ref())?;
            std::fs::write(&output, svg)
                .map_err(|e| Failure(format!("{}: cannot write: {e}", output.display())))?;
            ok(String::new())
        }
        Command::Check { common, trace, tolerance, format } => {
            let job = Job::load(&common)?;
            let report = check::run(&job, &trace, tolerance).map_err(Failure)?;
            let text = match format {
                ReportFormat::Text => report.text(),
                ReportFormat::Json => report.json(),
            };
            Ok((text, u8::from(!report.agree())))
        }
        Command::Vectors { count, seed, out } => ok(vectors::run(count, seed, &out).map_err(Failure)?),
    }
}

/// The finishing contour's moves without its first move (the rapid to the
/// contour's start, which becomes the profile's first point).
fn profile_from_contour(contour: &[Move]) -> Vec<Move> {
    let start = contour.iter().position(|m| m.motion != cycleref::Motion::Rapid).unwrap_or(0);
    let first = start.saturating_sub(1);
    contour[first..].to_vec()
}

/// A program read and ready to expand.
struct Job {
    name: String,
    program: Program,
    engine: Engine,
    /// The unit of Q in the nc output (the profile's G32 Q unit).
    q_unit: QUnit,
    /// The machine the program was read with.
    machine: Machine,
}

impl Job {
    fn load(c: &Common) -> Result<Job, Failure> {
        let name = c.file.display().to_string();
        let text = if name == "-" {
            let mut s = String::new();
            std::io::stdin().read_to_string(&mut s).map_err(|e| Failure(format!("stdin: {e}")))?;
            s
        } else {
            std::fs::read_to_string(&c.file).map_err(|e| Failure(format!("{name}: {e}")))?
        };
        let mut machine = Machine::new(match c.profile {
            Profile::Fanuc => ProfileName::Fanuc,
            Profile::Gsk980 => ProfileName::Gsk980,
            Profile::Gsk988 => ProfileName::Gsk988,
        });
        if let Some(p) = &c.params {
            let t = std::fs::read_to_string(p).map_err(|e| Failure(format!("{}: {e}", p.display())))?;
            machine.apply_toml(&t).map_err(|e| Failure(format!("{}: {e}", p.display())))?;
        }
        if let Some(i) = c.increment {
            machine.increment = match i {
                Increment::IsB => IncrementSystem::IsB,
                Increment::IsC => IncrementSystem::IsC,
            };
        }
        if c.inch {
            machine.unit = InputUnit::Inch;
        }
        if c.radius {
            machine.x_mode = XMode::Radius;
        }
        let program = read(&text, &machine).map_err(|e| Failure(format!("{name}: {e}")))?;
        let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
        let q_unit = machine.profile.q_unit(bit);
        Ok(Job { name, program, engine: c.engine, q_unit, machine })
    }

    fn expand(&self, cycle: &G76Cycle, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = match self.engine {
            Engine::Impl => cycleref::engine::expand_g76(cycle).map(Iterator::collect),
            Engine::Spec => cycleref_spec::g76::expand(cycle),
        };
        r.map_err(|e| Failure(format!("{}: line {line}, G76: {e}", self.name)))
    }

    fn expand_g32(&self, block: &G32Block, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = match self.engine {
            Engine::Impl => cycleref::expand_g32(block).map(Iterator::collect),
            Engine::Spec => cycleref_spec::g32::expand(block),
        };
        r.map_err(|e| Failure(format!("{}: line {line}, G32: {e}", self.name)))
    }

    fn expand_g75(&self, cycle: &G75Cycle, line: usize) -> Result<Vec<Move>, Failure> {
        let r: Result<Vec<Move>, CycleError> = match self.engine {
            Engine::Impl => cycleref::expand_g75(cycle).map(Iterator::collect),
            Engine::Spec => cycleref_spec::g75::expand(cycle),
        };
        r.map_err(|e| Failure(format!("{}: line {line}, G75.1: {e}", self.name)))
    }

    fn nc(&self) -> Result<String, Failure> {
        let mut out = String::new();
        for item in &self.program.items {
            match item {
                Item::Source(b) => {
                    let _ = writeln!(out, "{}", b.text);
                }
                Item::G76Params(_) => {}
                Item::G76(call) => {
                    let moves = self.expand(&call.cycle, call.block.line)?;
                    format::nc_cycle(&mut out, call, &moves, self.q_unit);
                }
                Item::G32(call) => {
                    let moves = self.expand_g32(&call.g32, call.block.line)?;
                    format::nc_moves(&mut out, &moves, call.g32.units, self.q_unit);
                }
                Item::G75Params(_) => {}
                Item::G75(call) => {
                    let moves = self.expand_g75(&call.cycle, call.block.line)?;
                    format::nc_groove(&mut out, call, &moves);
                }
            }
        }
        Ok(out)
    }

    fn json(&self) -> Result<String, Failure> {
        let mut cycles = Vec::new();
        for item in &self.program.items {
            match item {
                Item::G76(call) => {
                    let moves = self.expand(&call.cycle, call.block.line)?;
                    let u = call.cycle.units;
                    cycles.push(json!({
                        "cycle": "G76",
                        "line": call.block.line,
                        "params_line": call.params_line,
                        "start": {"x": format::fixed(call.cycle.start.x, u), "z": format::fixed(call.cycle.start.z, u)},
                        "moves": moves.iter().map(|m| format::move_json(m, u)).collect::<Vec<_>>(),
                    }));
                }
                Item::G32(call) => {
                    let moves = self.expand_g32(&call.g32, call.block.line)?;
                    let u = call.g32.units;
                    let s = call.g32.start;
                    cycles.push(json!({
                        "cycle": "G32",
                        "line": call.block.line,
                        "start": {"x": format::fixed(s.x, u), "z": format::fixed(s.z, u)},
                        "moves": moves.iter().map(|m| format::move_json(m, u)).collect::<Vec<_>>(),
                    }));
                }
                Item::G75(call) => {
                    let moves = self.expand_g75(&call.cycle, call.block.line)?;
                    let c = &call.cycle;
                    let u = c.units;
                    let fx =
                        |p: cycleref::Point| json!({"x": format::fixed(p.x, u), "z": format::fixed(p.z, u)});
                    cycles.push(json!({
                        "cycle": "G75.1",
                        "line": call.block.line,
                        "params_line": call.params_line,
                        "from": fx(c.from),
                        "start": fx(c.start),
                        "moves": moves.iter().map(|m| format::move_json(m, u)).collect::<Vec<_>>(),
                    }));
                }
                Item::Source(_) | Item::G76Params(_) | Item::G75Params(_) => {}
            }
        }
        let doc = json!({
            "format": "cycleref-moves/1",
            "file": self.name,
            "units": {
                "unit": match self.program.units.unit { InputUnit::Metric => "mm", InputUnit::Inch => "inch" },
                "decimals": self.program.units.decimals(),
            },
            "cycles": cycles,
        });
        let mut s = serde_json::to_string_pretty(&doc).map_err(|e| Failure(e.to_string()))?;
        s.push('\n');
        Ok(s)
    }

    fn passes(&self) -> Result<String, Failure> {
        let mut out = String::new();
        for call in self.program.cycles() {
            let moves = self.expand(&call.cycle, call.block.line)?;
            let u = call.cycle.units;
            let _ = writeln!(out, "G76 at line {} ({}):", call.block.line, self.name);
            let _ = writeln!(
                out,
                "{:>6} {:>6} {:>5} {:>6} {:>12} {:>12} {:>14} {:>14}",
                "pass", "kind", "start", "flank", "depth", "cut", "X", "Z"
            );
            for m in moves.iter().filter(|m| m.role == cycleref::Role::Approach) {
                let Some(p) = m.pass else { continue };
                // The pass start Bn is where the approach ends unless a lead-in follows.
                let bn = moves
                    .iter()
                    .skip_while(|n| !std::ptr::eq(*n, m))
                    .find(|n| n.role == cycleref::Role::LeadIn)
                    .filter(|n| n.pass == Some(p))
                    .map_or(m.to, |n| n.to);
                let _ = writeln!(
                    out,
                    "{:>6} {:>6} {:>5} {:>6} {:>12} {:>12} {:>14} {:>14}",
                    p.number,
                    format::kind_name(p.kind),
                    p.start,
                    format::flank_name(p.flank),
                    format::fixed(p.depth, u),
                    format::fixed(p.cut, u),
                    format::fixed(bn.x, u),
                    format::fixed(bn.z, u)
                );
            }
            out.push('\n');
        }
        for call in self.program.grooves() {
            self.groove_table(&mut out, call)?;
        }
        let threads: Vec<_> = self.program.threads().collect();
        if !threads.is_empty() {
            let _ = writeln!(out, "G32 blocks ({}):", self.name);
            let _ = writeln!(
                out,
                "{:>6} {:>5} {:>14} {:>14} {:>14} {:>14} {:>14} {:>14}",
                "line", "sync", "from X", "from Z", "cut to X", "cut to Z", "run-out X", "run-out Z"
            );
            for call in threads {
                let moves = self.expand_g32(&call.g32, call.block.line)?;
                let u = call.g32.units;
                let cut =
                    moves.iter().find(|m| m.role == cycleref::Role::Cut).map_or(call.g32.start, |m| m.to);
                let run_out = moves.iter().find(|m| m.role == cycleref::Role::RunOut);
                let (rx, rz) = run_out.map_or(("-".into(), "-".into()), |m| {
                    (format::fixed(m.to.x, u), format::fixed(m.to.z, u))
                });
                let _ = writeln!(
                    out,
                    "{:>6} {:>5} {:>14} {:>14} {:>14} {:>14} {:>14} {:>14}",
                    call.block.line,
                    if call.g32.sync { "yes" } else { "no" },
                    format::fixed(call.g32.start.x, u),
                    format::fixed(call.g32.start.z, u),
                    format::fixed(cut.x, u),
                    format::fixed(cut.z, u),
                    rx,
                    rz
                );
            }
            out.push('\n');
        }
        Ok(out)
    }

    /// The layers and plunges of a G75.1 cycle: one row per plunge with its
    /// Z, the X it starts from (Amn), the X it reaches (Bmn) and its pecks.
    fn groove_table(&self, out: &mut String, call: &cycleref_spec::reader::G75Call) -> Result<(), Failure> {
        let moves = self.expand_g75(&call.cycle, call.block.line)?;
        let u = call.cycle.units;
        let _ = writeln!(out, "G75.1 at lines {}-{} ({}):", call.params_line, call.block.line, self.name);
        let _ = writeln!(
            out,
            "{:>6} {:>7} {:>14} {:>14} {:>14} {:>6}",
            "layer", "plunge", "Z", "from X (Amn)", "to X (Bmn)", "pecks"
        );
        let mut at = call.cycle.from;
        let mut row: Option<(cycleref::Plunge, cycleref::Point, cycleref::Point, u32)> = None;
        let flush =
            |out: &mut String, row: &Option<(cycleref::Plunge, cycleref::Point, cycleref::Point, u32)>| {
                if let Some((p, start, bottom, pecks)) = row {
                    let _ = writeln!(
                        out,
                        "{:>6} {:>7} {:>14} {:>14} {:>14} {:>6}",
                        p.layer,
                        p.number,
                        format::fixed(start.z, u),
                        format::fixed(start.x, u),
                        format::fixed(bottom.x, u),
                        pecks
                    );
                }
            };
        for m in &moves {
            if let cycleref::Role::Peck(p) = m.role {
                match &mut row {
                    Some((q, _, bottom, pecks)) if *q == p => {
                        *bottom = m.to;
                        *pecks += 1;
                    }
                    _ => {
                        flush(out, &row);
                        row = Some((p, at, m.to, 1));
                    }
                }
            }
            at = m.to;
        }
        flush(out, &row);
        let contours = [
            (cycleref::Role::RoughContour, "rough contour (step 9)"),
            (cycleref::Role::FinishContour, "finishing contour (step 10)"),
        ];
        for (role, name) in contours {
            let n = moves.iter().filter(|m| m.role == role && m.motion != cycleref::Motion::Rapid).count();
            if n > 0 {
                let _ = writeln!(out, "{name}: {n} cutting moves");
            }
        }
        out.push('\n');
        Ok(())
    }

    fn plot(&self, overlay: Option<&plot::Overlay>) -> Result<String, Failure> {
        let mut cycles = Vec::new();
        for call in self.program.cycles() {
            let moves = self.expand(&call.cycle, call.block.line)?;
            cycles.push((call.clone(), moves));
        }
        let mut threads = Vec::new();
        for call in self.program.threads() {
            let moves = self.expand_g32(&call.g32, call.block.line)?;
            threads.push((call.clone(), moves));
        }
        let mut outlines = Vec::new();
        for call in self.program.grooves() {
            let moves = self.expand_g75(&call.cycle, call.block.line)?;
            // The profile is the finishing path of the same groove for a
            // pointed tool; the roughing region's outline is the engine's
            // profile of it (plot_g75's module documentation).
            let pointed = G75Cycle { tool_width: None, path: cycleref::PathType::Finish, ..call.cycle };
            let profile = self.expand_g75(&pointed, call.block.line)?;
            let profile: Vec<Move> =
                profile.into_iter().filter(|m| m.role == cycleref::Role::FinishContour).collect();
            let rough = cycleref::groove_profile(&call.cycle)
                .map_err(|e| Failure(format!("{}: line {}, G75.1: {e}", self.name, call.block.line)))?
                .roughing()
                .to_vec();
            outlines.push((call, moves, profile, rough));
        }
        let grooves: Vec<_> = outlines
            .iter()
            .map(|(call, moves, profile, rough)| plot_g75::Groove {
                call,
                moves,
                profile: profile_from_contour(profile),
                rough: rough.clone(),
            })
            .collect();
        plot::svg(&self.name, &cycles, &threads, &grooves, overlay).map_err(Failure)
    }
}
