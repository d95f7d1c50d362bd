//! A program to run: its text, the machine it is read with, the engine, and
//! the failures a run can end in.
//!
//! The program's bytes are held once, as read; everything else is read
//! from them as it is needed (reading R-STREAM): [`Job::validate`] is the
//! first phase, which reads every block and checks every cycle, and the
//! writers read the program again to stream their output.

use std::io::{IsTerminal as _, Read as _};
use std::path::{Path, PathBuf};

use cycleref::{IncrementSystem, InputUnit, XMode};
use cycleref_spec::pipeline::{expand_at, Cycle, Engine, Moves, RunError, Summary};
use cycleref_spec::profile::QUnit;
use cycleref_spec::{Machine, ProfileName, Reader};

/// How a command ends when it does not succeed.
#[derive(Debug)]
pub enum Failure {
    /// An error for the user: printed on stderr, exit status 2.
    Message(String),
    /// The reader of the output went away (a closed pipe): the command
    /// stops quietly with exit status 0, as Unix filters do.
    BrokenPipe,
}

impl Failure {
    /// A failure with `message`.
    pub fn msg(message: impl Into<String>) -> Failure {
        Failure::Message(message.into())
    }

    /// A failure to write the output.
    #[must_use]
    pub fn output(e: &std::io::Error) -> Failure {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            Failure::BrokenPipe
        } else {
            Failure::Message(format!("cannot write the output: {e}"))
        }
    }
}

impl From<Failure> for String {
    fn from(f: Failure) -> String {
        match f {
            Failure::Message(m) => m,
            Failure::BrokenPipe => "the output pipe was closed".to_string(),
        }
    }
}

impl From<String> for Failure {
    fn from(s: String) -> Failure {
        Failure::Message(s)
    }
}

/// The control profile of the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    /// FANUC two-block G76.
    Fanuc,
    /// GSK 980TDi.
    Gsk980,
    /// GSK 988TA.
    Gsk988,
}

/// What the command line says about the program and the machine. An
/// option given here always wins over the parameter file; the file wins
/// over the profile's defaults.
#[derive(Clone, Debug, Default)]
pub struct Options {
    /// `--profile` (default: the file's `profile`, else gsk988).
    pub profile: Option<Profile>,
    /// `--increment`.
    pub increment: Option<IncrementSystem>,
    /// `--inch`.
    pub inch: bool,
    /// `--radius`.
    pub radius: bool,
    /// `--params`.
    pub params: Option<PathBuf>,
    /// `--engine`.
    pub engine: Engine,
    /// The program file; `None` or `-` for standard input.
    pub file: Option<PathBuf>,
}

/// The name standard input goes by in messages, titles and documents.
pub const STDIN_NAME: &str = "<stdin>";

/// A program read into memory with its machine, ready to run.
#[derive(Debug)]
pub struct Job {
    /// The file's name as given (standard input: [`STDIN_NAME`]).
    pub name: String,
    /// The program's bytes.
    pub source: Vec<u8>,
    /// The engine that expands the cycles.
    pub engine: Engine,
    /// The unit of Q in the nc output (the profile's G32 Q unit).
    pub q_unit: QUnit,
    /// The machine the program is read with.
    pub machine: Machine,
}

impl Job {
    /// Reads the program and the parameter file of `opts`.
    ///
    /// # Errors
    ///
    /// A file that cannot be read, standard input at a terminal (no
    /// program was given), or a parameter file that is not valid.
    pub fn load(opts: &Options) -> Result<Job, Failure> {
        let stdin = opts.file.as_deref().is_none_or(|f| f == Path::new("-"));
        let (name, source) = if stdin {
            let mut input = std::io::stdin();
            if input.is_terminal() {
                return Err(Failure::msg(
                    "no program: give a FILE, or `-` with the program on standard input (see --help)",
                ));
            }
            let mut s = Vec::new();
            input.read_to_end(&mut s).map_err(|e| Failure::msg(format!("{STDIN_NAME}: {e}")))?;
            (STDIN_NAME.to_string(), s)
        } else {
            let file = opts.file.as_deref().unwrap_or(Path::new("-"));
            let name = file.display().to_string();
            let s = std::fs::read(file).map_err(|e| Failure::msg(format!("{name}: {e}")))?;
            (name, s)
        };
        let machine = machine(opts)?;
        let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
        let q_unit = machine.profile.q_unit(bit);
        Ok(Job { name, source, engine: opts.engine, q_unit, machine })
    }

    /// A job over `source` (for tests and library users).
    #[must_use]
    pub fn new(name: &str, source: Vec<u8>, machine: Machine, engine: Engine) -> Job {
        let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
        let q_unit = machine.profile.q_unit(bit);
        Job { name: name.to_string(), source, engine, q_unit, machine }
    }

    /// A reader of the program, from its first block.
    #[must_use]
    pub fn reader(&self) -> Reader<'_, '_> {
        Reader::new(&self.source, &self.machine)
    }

    /// The first phase: reads every block and checks every cycle.
    ///
    /// # Errors
    ///
    /// The first error in program order, named with the file.
    pub fn validate(&self) -> Result<Summary, Failure> {
        cycleref_spec::pipeline::validate(&self.source, &self.machine, self.engine).map_err(|e| {
            match self.other_increment_hint(&e) {
                Some(hint) => Failure::Message(format!("{}: {e}; {hint}", self.name)),
                None => self.fail(&e),
            }
        })
    }

    /// When a G76 start lies inside the thread (the usual sign of lengths
    /// read in the wrong increment system: P(k) in increments at IS-B
    /// where the program was written for IS-C) and the whole program is
    /// valid with the other increment system, a hint saying so.
    fn other_increment_hint(&self, e: &RunError) -> Option<String> {
        let inside = match e {
            RunError::Cycle { error, .. } => *error == cycleref::CycleError::StartInsideThread,
            RunError::Program(p) => {
                p.kind == cycleref_spec::ErrorKind::Cycle(cycleref::CycleError::StartInsideThread)
            }
        };
        if !inside {
            return None;
        }
        let mut other = self.machine.clone();
        let (flag, system) = match other.increment {
            IncrementSystem::IsB => ("is-c", IncrementSystem::IsC),
            IncrementSystem::IsC => ("is-b", IncrementSystem::IsB),
        };
        other.increment = system;
        cycleref_spec::pipeline::validate(&self.source, &other, self.engine).ok().map(|_| {
            format!(
                "the program is valid with the other increment system: was it written for --increment {flag}?"
            )
        })
    }

    /// The moves of `cycle` by the job's engine.
    ///
    /// # Errors
    ///
    /// The cycle's alarm, named with the file and line.
    pub fn expand(&self, cycle: Cycle<'_, '_>) -> Result<Moves, Failure> {
        expand_at(cycle, self.engine).map_err(|e| self.fail(&e))
    }

    /// `e` as a failure naming the file.
    #[must_use]
    pub fn fail(&self, e: &RunError) -> Failure {
        Failure::Message(format!("{}: {e}", self.name))
    }
}

/// The machine of `opts`: the profile's defaults, then the parameter file,
/// then every option given on the command line.
///
/// # Errors
///
/// A parameter file that cannot be read or is not valid.
pub fn machine(opts: &Options) -> Result<Machine, Failure> {
    let flag = opts.profile.map(|p| match p {
        Profile::Fanuc => ProfileName::Fanuc,
        Profile::Gsk980 => ProfileName::Gsk980,
        Profile::Gsk988 => ProfileName::Gsk988,
    });
    let mut machine = Machine::new(flag.unwrap_or(ProfileName::Gsk988));
    if let Some(p) = &opts.params {
        let t = std::fs::read_to_string(p).map_err(|e| Failure::msg(format!("{}: {e}", p.display())))?;
        let applied =
            if flag.is_some() { machine.apply_toml_keeping_profile(&t) } else { machine.apply_toml(&t) };
        applied.map_err(|e| Failure::msg(format!("{}: {e}", p.display())))?;
    }
    if let Some(i) = opts.increment {
        machine.increment = i;
    }
    if opts.inch {
        machine.unit = InputUnit::Inch;
    }
    if opts.radius {
        machine.x_mode = XMode::Radius;
    }
    Ok(machine)
}
