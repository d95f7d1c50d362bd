//! A program to run: its text, the machine it is read with, the engine, and
//! the failures a run can end in.
//!
//! A program in a regular file is read from the file a line at a time,
//! once per phase; a program from standard input or a pipe (which cannot
//! be read twice) is held in memory once, as read. Everything is read from
//! the text as it is needed (reading R-STREAM): [`Job::validate`] is the
//! first phase, which reads every block and checks every cycle, and the
//! writers read the program again ([`Job::items`]) to stream their output.
//! Memory is the longest line and the reader's modal state, whatever the
//! length of a program in a file.

use std::fmt;
use std::fs::File;
use std::io::{BufReader, IsTerminal as _, Read as _};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::SystemTime;

use cycleref::{IncrementSystem, InputUnit, Units, XMode};
use cycleref_spec::pipeline::{expand_at, Cycle, Engine, Moves, RunError, Summary, Validation};
use cycleref_spec::profile::QUnit;
use cycleref_spec::reader::{
    may_hold_return, Item, MainEnd, MainStart, MainStartFinder, Step, SubprogramText, Subprograms,
    MAX_SUBPROGRAM_TEXT,
};
use cycleref_spec::{LineReader, Machine, ProfileName, ProgramError};

pub use crate::failure::{Cause, Failure, OtherFailure, ProgramFailure};

/// The control profile of the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Profile {
    /// FANUC two-block G76.
    Fanuc,
    /// GSK 980TDi.
    Gsk980,
    /// GSK 988TA.
    Gsk988,
    /// LinuxCNC 2.9 (its one-block G76).
    LinuxCnc,
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
    /// `--reading ID=VALUE`, in order; applied after the parameter file's
    /// `[readings]`, so the command line wins.
    pub readings: Vec<String>,
    /// `--engine`.
    pub engine: Engine,
    /// The program file; `None` or `-` for standard input.
    pub file: Option<PathBuf>,
}

/// The readings of `machine` that differ from its profile's defaults
/// (issue 34), `(id, value)` in the order `cycleref readings` lists them:
/// what the `check` report and the JSON documents name.
#[must_use]
pub fn readings_in_force(machine: &Machine) -> Vec<(&'static str, &'static str)> {
    machine.readings.non_default(machine.profile.name)
}

/// The `readings` object of the JSON documents: `None` (the key left out)
/// under the defaults, so that their documents stay as they were.
#[must_use]
pub fn readings_json(
    readings: &[(&'static str, &'static str)],
) -> Option<std::collections::BTreeMap<&'static str, &'static str>> {
    (!readings.is_empty()).then(|| readings.iter().copied().collect())
}

/// The name standard input goes by in messages, titles and documents.
pub const STDIN_NAME: &str = "<stdin>";

/// A program with its machine, ready to run.
#[derive(Debug)]
pub struct Job {
    /// The file's name as given (standard input: [`STDIN_NAME`]).
    pub name: String,
    /// Where the program's text is.
    text: Text,
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
        let (name, text) = if stdin {
            let mut input = std::io::stdin();
            if input.is_terminal() {
                return Err(Failure::usage(
                    "no program: give a FILE, or `-` with the program on standard input (see --help)",
                ));
            }
            let mut s = Vec::new();
            input.read_to_end(&mut s).map_err(|e| Failure::input(format!("{STDIN_NAME}: {e}")))?;
            (STDIN_NAME.to_string(), Text::Held(s))
        } else {
            open_named(opts.file.as_deref().unwrap_or(Path::new("-")))?
        };
        let machine = machine(opts)?;
        Ok(Job::with_text(name, text, machine, opts.engine))
    }

    /// A job over `source`, held in memory (for tests and library users).
    ///
    /// ```
    /// use cycleref_cli::Job;
    /// use cycleref_spec::pipeline::Engine;
    /// use cycleref_spec::{Machine, ProfileName};
    ///
    /// let text = b"M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
    /// let job = Job::new("m68.nc", text.to_vec(), Machine::new(ProfileName::Gsk988), Engine::Impl);
    /// // Both phases' reading: the whole program checked, its units known.
    /// let summary = job.validate().map_err(String::from)?;
    /// assert_eq!(summary.units.decimals(), 3);
    /// # Ok::<(), String>(())
    /// ```
    #[must_use]
    pub fn new(name: &str, source: Vec<u8>, machine: Machine, engine: Engine) -> Job {
        Job::with_text(name.to_string(), Text::Held(source), machine, engine)
    }

    /// A job over the program in the regular file at `path`, read from the
    /// file a line at a time in each phase (for library users; the
    /// command's [`Job::load`] does this for a FILE argument).
    ///
    /// # Errors
    ///
    /// The file cannot be opened.
    pub fn from_file(path: &Path, machine: Machine, engine: Engine) -> Result<Job, Failure> {
        let (name, text) = open_named(path)?;
        Ok(Job::with_text(name, text, machine, engine))
    }

    fn with_text(name: String, text: Text, machine: Machine, engine: Engine) -> Job {
        let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
        let q_unit = machine.profile.q_unit(bit);
        Job { name, text, engine, q_unit, machine }
    }

    /// The program's items, from its first block.
    ///
    /// # Errors
    ///
    /// The program's file cannot be opened again, or has changed since
    /// the command started.
    pub fn items(&self) -> Result<Items<'_>, Failure> {
        Items::new(&self.text, &self.machine).map_err(|e| self.read_failure(&e))
    }

    /// Calls `f` with each item of the program, in order, until it fails.
    ///
    /// # Errors
    ///
    /// The first error of reading (made into `E` by `read`) or of `f`.
    pub fn for_each_item<E>(
        &self,
        read: impl Fn(Failure) -> E,
        mut f: impl FnMut(&Item<'_>) -> Result<(), E>,
    ) -> Result<(), E> {
        let mut items = self.items().map_err(&read)?;
        while let Some(r) = items.next_with(&mut f) {
            r.map_err(|e| read(self.read_failure(&e)))??;
        }
        Ok(())
    }

    /// `e` as a failure naming the file.
    #[must_use]
    pub fn read_failure(&self, e: &ReadError) -> Failure {
        match e {
            ReadError::Run(run) => self.fail(run),
            _ => Failure::input(format!("{}: {e}", self.name)),
        }
    }

    /// The first phase: reads every block and checks every cycle.
    ///
    /// # Errors
    ///
    /// The first error in program order, named with the file.
    pub fn validate(&self) -> Result<Summary, Failure> {
        self.validate_run().map_err(|(failure, _)| failure)
    }

    /// The units the program's lengths are read in, found by reading only
    /// as far as they are settled (reading R-UNITS: G20/G21 only before
    /// the first motion), usually a few lines: in a valid program they are
    /// the [`Summary::units`] that [`Job::validate`] gives, without its
    /// reading of the whole program.
    ///
    /// # Errors
    ///
    /// When the program cannot be read as far, the first error of
    /// [`Job::validate`] (which is then run to find it).
    pub fn units(&self) -> Result<Units, Failure> {
        let Ok(mut items) = Items::new(&self.text, &self.machine) else {
            return self.validate().map(|s| s.units);
        };
        while !items.reader.units_settled() {
            match items.next_with(|_| ()) {
                None => break,
                Some(Ok(())) => {}
                Some(Err(_)) => return self.validate().map(|s| s.units),
            }
        }
        Ok(items.reader.units())
    }

    /// The first phase, as [`Job::validate`], with the program's error
    /// itself beside the command's message (for library users that report
    /// the line, word and rule in their own terms, such as the Python
    /// package): the error is `None` when the text could not be read.
    ///
    /// # Errors
    ///
    /// The first error in program order: the command's message, and the
    /// reader's error or cycle's alarm it comes from.
    pub fn validate_run(&self) -> Result<Summary, (Failure, Option<RunError>)> {
        match validate(&self.text, &self.machine, self.engine) {
            Ok(summary) => Ok(summary),
            Err(ReadError::Run(e)) => Err((
                match self.other_increment_hint(&e).or_else(|| self.other_profile_hint(&e)) {
                    Some(hint) => Failure::program(e.stable_kind(), format!("{}; {hint}", self.message(&e))),
                    None => self.fail(&e),
                },
                Some(e),
            )),
            Err(e) => Err((self.read_failure(&e), None)),
        }
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
        validate(&self.text, &other, self.engine).ok().map(|_| {
            format!(
                "the program is valid with the other increment system: was it written for --increment {flag}?"
            )
        })
    }

    /// When a cycle's alarm refuses the program and another profile reads
    /// the whole program without error (a FANUC program run with the
    /// default `gsk988`, whose G76 P reads P920 as 920 mm), a hint naming
    /// the profiles that accept it. The other GSK and FANUC profiles are
    /// tried with the job's increment system, unit and X mode, LinuxCNC
    /// with its own; only on this error path, one reading each.
    fn other_profile_hint(&self, e: &RunError) -> Option<String> {
        if !is_cycle_alarm(e) {
            return None;
        }
        let current = self.machine.profile.name;
        let accepting: Vec<String> = ProfileName::ALL
            .into_iter()
            .filter(|&name| name != current)
            .filter(|&name| {
                let mut other = Machine::new(name);
                if name != ProfileName::LinuxCnc && current != ProfileName::LinuxCnc {
                    other.increment = self.machine.increment;
                    other.unit = self.machine.unit;
                    other.x_mode = self.machine.x_mode;
                    other.calculator_input = self.machine.calculator_input;
                }
                other.pass_limit = self.machine.pass_limit;
                validate(&self.text, &other, self.engine).is_ok()
            })
            .map(|name| format!("--profile {name}"))
            .collect();
        (!accepting.is_empty()).then(|| {
            format!(
                "the program reads without error with {} (the profile decides how the cycle's words are read)",
                accepting.join(" or ")
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
        Failure::program(e.stable_kind(), self.message(e))
    }

    /// The message of `e`: the file, the error, and for a cycle's alarm
    /// the profile in force (an alarm depends on how the profile reads the
    /// cycle's words).
    fn message(&self, e: &RunError) -> String {
        if is_cycle_alarm(e) {
            format!("{}: {e} (profile {})", self.name, self.machine.profile.name)
        } else {
            format!("{}: {e}", self.name)
        }
    }
}

/// Whether `e` is a cycle's alarm (while the cycle was expanded, or as the
/// reader checked the cycle's words).
fn is_cycle_alarm(e: &RunError) -> bool {
    matches!(e, RunError::Cycle { .. })
        || matches!(e, RunError::Program(p) if matches!(p.kind, cycleref_spec::ErrorKind::Cycle(_)))
}

/// The first phase over `text` with `machine` and `engine`.
fn validate(text: &Text, machine: &Machine, engine: Engine) -> Result<Summary, ReadError> {
    let mut items = Items::new(text, machine)?;
    let mut validation = Validation::new(engine);
    while let Some(r) = items.next_with(|item| validation.item(item)) {
        r?.map_err(ReadError::Run)?;
    }
    Ok(validation.summary(items.reader.units()))
}

/// The program at `path`, with the name messages call it by.
fn open_named(path: &Path) -> Result<(String, Text), Failure> {
    let name = path.display().to_string();
    let text = Text::open(path).map_err(|e| Failure::input(format!("{name}: {e}")))?;
    Ok((name, text))
}

/// Where a program's text is.
#[derive(Debug)]
enum Text {
    /// In memory: standard input, a pipe, or a library caller's bytes.
    Held(Vec<u8>),
    /// In a regular file, read again in each phase. Its length and time of
    /// modification when the command started, and the digests of the
    /// pieces of the first reading that reached the end: every later
    /// reading compares each piece with them before it reads a block of it
    /// (reading R-CHANGED), so a file changed between or during the phases
    /// is an error, never an output that the first phase did not check.
    File {
        path: PathBuf,
        len: u64,
        modified: Option<SystemTime>,
        digests: OnceLock<Vec<u64>>,
        /// The digest of the subprograms' text (reading R-SUBPROGRAM) as
        /// the first reading to need it read it: a later reading compares
        /// it before it runs a block of a subprogram.
        subprograms: OnceLock<u64>,
        /// Where the main program starts (reading R-SUBPROGRAM), found by
        /// the first reading.
        main: OnceLock<MainStart>,
    },
}

/// The digest of one piece of a file (reading R-CHANGED): its length,
/// then its bytes eight at a time (little-endian, the last word padded with
/// zeros), each folded in by `h = (rotl(h, 5) ^ w) * K` with an odd `K`,
/// then mixed. It only has to tell whether a reading's piece is the bytes the
/// first reading checked, in one run, against accidental change (an editor
/// saving, a tool appending); it is not a defence against someone who means
/// to collide it (no 64-bit digest with public keys is: the SipHash-2-4 with
/// fixed keys it replaces fell to a birthday search of about 2^32 pieces
/// too). Each step is a bijection of `h` for a given word and of the word
/// for a given `h`, so two pieces of one length that differ in a single
/// aligned 8-byte word always have different digests; a piece of another
/// length is a change of the file's length, which is caught before (the
/// length and time of modification). About a byte an instruction where
/// SipHash took about three (4 % of one reading of the pipeline program,
/// issue 33).
fn piece_digest(piece: &[u8]) -> u64 {
    const K: u64 = 0x9E37_79B9_7F4A_7C15;
    let step = |h: u64, w: u64| (h.rotate_left(5) ^ w).wrapping_mul(K);
    let mut h = step(0, piece.len() as u64);
    let mut words = piece.chunks_exact(8);
    for c in &mut words {
        let mut w = [0_u8; 8];
        w.copy_from_slice(c);
        h = step(h, u64::from_le_bytes(w));
    }
    let tail = words.remainder();
    if !tail.is_empty() {
        let mut w = [0_u8; 8];
        w[..tail.len()].copy_from_slice(tail);
        h = step(h, u64::from_le_bytes(w));
    }
    // The final mix (a bijection): every bit of `h` reaches the low bits.
    h ^= h >> 29;
    h = h.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    h ^ (h >> 32)
}

impl Text {
    /// The text of the program at `path`: the file itself when it is a
    /// regular file, else (a pipe, a terminal, a device) its bytes, read
    /// once into memory.
    fn open(path: &Path) -> std::io::Result<Text> {
        let file = File::open(path)?;
        let meta = file.metadata()?;
        if meta.is_file() {
            return Ok(Text::File {
                path: path.to_path_buf(),
                len: meta.len(),
                modified: meta.modified().ok(),
                digests: OnceLock::new(),
                subprograms: OnceLock::new(),
                main: OnceLock::new(),
            });
        }
        let mut s = Vec::new();
        BufReader::new(file).read_to_end(&mut s)?;
        Ok(Text::Held(s))
    }
}

/// Why the program could not be read (in either phase).
#[derive(Debug)]
pub enum ReadError {
    /// The reader refused a block, or (first phase) a cycle raised its
    /// alarm.
    Run(RunError),
    /// The file could not be read.
    Io(std::io::Error),
    /// The file changed between the two phases.
    Changed,
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Run(e) => write!(f, "{e}"),
            ReadError::Io(e) => write!(f, "{e}"),
            ReadError::Changed => {
                f.write_str("the file changed while it was read (its two readings would differ); run again")
            }
        }
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ReadError::Run(e) => Some(e),
            ReadError::Io(e) => Some(e),
            ReadError::Changed => None,
        }
    }
}

impl From<ProgramError> for ReadError {
    fn from(e: ProgramError) -> ReadError {
        ReadError::Run(RunError::Program(e))
    }
}

/// The items of a program, read from its text one at a time: from the
/// held bytes, or from its file in pieces of whole lines (about
/// [`CHUNK`] bytes, or one line when a line is longer: that much in
/// memory, whatever the file's length).
///
/// An item borrows the piece it was read from, which a later one
/// overwrites; [`Items::next_with`] lends each item to a function that
/// makes of it what the caller keeps.
pub struct Items<'j> {
    reader: LineReader<'j>,
    input: Input<'j>,
    /// Where the main program starts (reading R-SUBPROGRAM).
    main: MainStart,
    /// The subprograms' text before the main program and after it, and
    /// the number of the first line after it, once a call has run (reading
    /// R-SUBPROGRAM): held, at most [`MAX_SUBPROGRAM_TEXT`] bytes.
    subprograms: Option<(Held<'j>, Held<'j>, usize)>,
    ended: bool,
}

/// Bytes borrowed from a held program, or read from its file.
enum Held<'j> {
    Borrowed(&'j [u8]),
    Owned(Vec<u8>),
}

impl Held<'_> {
    fn bytes(&self) -> &[u8] {
        match self {
            Held::Borrowed(b) => b,
            Held::Owned(v) => v,
        }
    }
}

enum Input<'j> {
    Held(&'j [u8]),
    Lines {
        file: File,
        /// The file's path, to read its subprograms.
        path: &'j Path,
        /// The digest of its subprograms, to compare or to set.
        subprograms: &'j OnceLock<u64>,
        /// The bytes read from the file and not yet consumed: the piece
        /// (whole lines) first, then the start of the next line.
        buf: Vec<u8>,
        /// Where the piece ends in `buf`.
        piece: usize,
        /// The file has no more bytes.
        eof: bool,
        /// The piece is finished: the next item needs the next piece.
        next: bool,
        /// The digests of the first complete reading, to compare each piece
        /// with, or to set when this reading is the first to end.
        recorded: &'j OnceLock<Vec<u64>>,
        /// The digests of this reading's pieces, while none are recorded.
        digests: Vec<u64>,
        /// How many pieces this reading has compared.
        pieces: usize,
    },
}

/// How many bytes [`Items`] reads from a file at a time.
pub const CHUNK: usize = 1 << 16;

/// The bytes of an unfinished line a piece's vector holds room for beside
/// [`CHUNK`] before it grows ([`next_piece`]).
const PIECE_SLACK: usize = 4096;

/// The longest line a program or trace read from a file may have (reading
/// R-LINEEND): a longer one is an error naming it, so that memory does not
/// grow with a line (a 1 GB line held 980 MB). No control's block is
/// anywhere near it.
pub const MAX_LINE: usize = 1 << 20;

/// The error of reading a piece of a file for a line longer than [`MAX_LINE`]; the
/// caller names the line.
#[derive(Debug)]
pub struct LineTooLong;

impl fmt::Display for LineTooLong {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "the line is longer than {MAX_LINE} bytes (1 MiB), the most a line may have")
    }
}

impl std::error::Error for LineTooLong {}

/// The next piece of whole lines into `buf`, after dropping the piece
/// before it: `Ok(false)` when the source has no more. A piece is at
/// least [`CHUNK`] bytes read (fewer at the end), cut after its last line
/// end, or one whole line when a line is longer.
pub(crate) fn next_piece<R: std::io::Read + ?Sized>(
    file: &mut R,
    buf: &mut Vec<u8>,
    piece: &mut usize,
    eof: &mut bool,
) -> std::io::Result<bool> {
    buf.drain(..*piece);
    *piece = 0;
    // The bytes before `searched` hold no line end.
    let mut searched = 0;
    loop {
        // The piece ends after the last line end read so far (reading
        // R-LINEEND: LF, CR LF or a lone CR; never between CR and LF).
        if let Some(end) = cycleref_spec::lex::last_line_end(buf, searched, *eof) {
            *piece = end;
            return Ok(true);
        }
        // A last CR may still be a line end once the next byte is known.
        searched = buf.len() - usize::from(buf.last() == Some(&b'\r'));
        if buf.len() > MAX_LINE {
            return Err(std::io::Error::new(std::io::ErrorKind::InvalidData, LineTooLong));
        }
        if *eof {
            // The last line, without a line end.
            *piece = buf.len();
            return Ok(!buf.is_empty());
        }
        let have = buf.len();
        // Read into the vector's spare room, not into zeros written first
        // (zeroing each chunk was 2 % of a reading, issue 33): up to CHUNK
        // bytes, fewer only at the end of the source (`read_to_end` of the
        // `take` reads until it has them or the source has no more, retrying
        // an interrupted read). The end is only where a read gives nothing
        // at the time the next piece is wanted: a short read is not the end,
        // so that bytes written to the file since (a tool appending) are
        // read and seen as a change (R-CHANGED), as before issue 33.
        // Room for CHUNK bytes after the piece's unfinished line, in a
        // vector that keeps its size from piece to piece: `reserve`'s
        // doubling made it 128 KiB from the second piece on, which the
        // allocator maps afresh for every reading (33 page faults, each
        // about 3 µs on this machine, and a map and an unmap: issue 33's
        // short programs pay them three times).
        if buf.capacity() - buf.len() < CHUNK {
            buf.reserve_exact(CHUNK + PIECE_SLACK);
        }
        let n = std::io::Read::take(&mut *file, CHUNK as u64)
            .read_to_end(buf)
            .inspect_err(|_| buf.truncate(have))?;
        *eof = n == 0;
    }
}

/// The error of [`next_piece`] reading line `line` (the first not yet
/// read): a line too long names it; any other is the file's.
fn piece_error(e: std::io::Error, line: usize) -> ReadError {
    if e.get_ref().is_some_and(|e| e.is::<LineTooLong>()) {
        let kind = cycleref_spec::ErrorKind::Syntax(format!("this line: {LineTooLong}"));
        return ProgramError { line, word: None, kind }.into();
    }
    ReadError::Io(e)
}

/// Where the main program of the file at `path` starts (reading
/// R-SUBPROGRAM): a byte search for `M99` over the file first, and only
/// where one may be, the reader's rules over it again.
fn main_start_of_file(path: &Path) -> Result<MainStart, ReadError> {
    let (mut buf, mut piece, mut eof) = (Vec::new(), 0, false);
    let mut file = File::open(path).map_err(ReadError::Io)?;
    loop {
        match next_piece(&mut file, &mut buf, &mut piece, &mut eof) {
            Ok(true) if may_hold_return(&buf[..piece]) => break,
            Ok(true) => {}
            Ok(false) => return Ok(MainStart::default()),
            // The reading reports the line, with its number.
            Err(e) if e.get_ref().is_some_and(|e| e.is::<LineTooLong>()) => return Ok(MainStart::default()),
            Err(e) => return Err(ReadError::Io(e)),
        }
    }
    let mut file = File::open(path).map_err(ReadError::Io)?;
    let (mut buf, mut piece, mut eof) = (Vec::new(), 0, false);
    let mut finder = MainStartFinder::default();
    loop {
        match next_piece(&mut file, &mut buf, &mut piece, &mut eof) {
            Ok(true) => {
                if let Some(main) = finder.feed(&buf[..piece]) {
                    return Ok(main);
                }
            }
            Ok(false) => return Ok(finder.finish()),
            Err(e) if e.get_ref().is_some_and(|e| e.is::<LineTooLong>()) => return Ok(finder.finish()),
            Err(e) => return Err(ReadError::Io(e)),
        }
    }
}

impl<'j> Items<'j> {
    fn new(text: &'j Text, machine: &'j Machine) -> Result<Items<'j>, ReadError> {
        let mut reader = LineReader::new(machine);
        let follows = reader.subprogram_text() == SubprogramText::AroundMain;
        let (input, main) = match text {
            Text::Held(bytes) => {
                (Input::Held(bytes), if follows { MainStart::of_text(bytes) } else { MainStart::default() })
            }
            Text::File { path, len, modified, digests, subprograms, main } => {
                let mut file = File::open(path).map_err(ReadError::Io)?;
                let meta = file.metadata().map_err(ReadError::Io)?;
                if meta.len() != *len || meta.modified().ok() != *modified {
                    return Err(ReadError::Changed);
                }
                let main = match main.get() {
                    Some(m) => *m,
                    None if follows => {
                        let found = main_start_of_file(path)?;
                        *main.get_or_init(|| found)
                    }
                    None => MainStart::default(),
                };
                if main.offset > 0 {
                    use std::io::Seek as _;
                    file.seek(std::io::SeekFrom::Start(main.offset as u64)).map_err(ReadError::Io)?;
                }
                let input = Input::Lines {
                    file,
                    path,
                    subprograms,
                    buf: Vec::new(),
                    piece: 0,
                    eof: false,
                    next: true,
                    recorded: digests,
                    digests: Vec::new(),
                    pieces: 0,
                };
                (input, main)
            }
        };
        reader.start_at(main);
        Ok(Items { reader, input, main, subprograms: None, ended: false })
    }

    /// The next item, made into what the caller keeps by `f`; `None` after
    /// the last item or after an error.
    pub fn next_with<T>(&mut self, f: impl FnOnce(&Item<'_>) -> T) -> Option<Result<T, ReadError>> {
        if self.ended {
            return None;
        }
        loop {
            if let Input::Lines {
                file, buf, piece, eof, next: next @ true, recorded, digests, pieces, ..
            } = &mut self.input
            {
                match next_piece(file, buf, piece, eof) {
                    Ok(false) => {
                        // Reading R-CHANGED: as many pieces as recorded (a
                        // truncated file has fewer); or this reading is the
                        // first complete one, and its digests are recorded.
                        let same = match recorded.get() {
                            Some(r) => r.len() == *pieces,
                            None => {
                                let _ = recorded.set(std::mem::take(digests));
                                true
                            }
                        };
                        if !same {
                            self.ended = true;
                            return Some(Err(ReadError::Changed));
                        }
                        return self.end();
                    }
                    Ok(true) => {
                        *next = false;
                        let d = piece_digest(&buf[..*piece]);
                        match recorded.get() {
                            // The piece before any block of it is read.
                            Some(r) if r.get(*pieces) != Some(&d) => {
                                self.ended = true;
                                return Some(Err(ReadError::Changed));
                            }
                            Some(_) => {}
                            None => digests.push(d),
                        }
                        *pieces += 1;
                    }
                    Err(e) => {
                        self.ended = true;
                        return Some(Err(piece_error(e, self.reader.lines_read() + 1)));
                    }
                }
            }
            let piece: &[u8] = match &self.input {
                Input::Held(bytes) => &bytes[self.main.offset..],
                Input::Lines { buf, piece, .. } => &buf[..*piece],
            };
            let subs = self.subprograms.as_ref().map(|(before, after, after_line)| Subprograms {
                before: before.bytes(),
                after: after.bytes(),
                after_line: *after_line,
            });
            // The item is lent where it was returned: it does not move.
            let wants_subprograms = match self.reader.step(piece, subs) {
                Ok(Step::Item(ref item)) => return Some(Ok(f(item))),
                Ok(Step::Subprograms) => true,
                Ok(Step::Piece) => false,
                Err(e) => {
                    self.ended = true;
                    return Some(Err(e.into()));
                }
            };
            if wants_subprograms {
                match self.load_subprograms() {
                    Ok(s) => self.subprograms = Some(s),
                    Err(e) => {
                        self.ended = true;
                        return Some(Err(e));
                    }
                }
                continue;
            }
            // The piece is finished.
            match &mut self.input {
                Input::Held(_) => return self.end(),
                Input::Lines { next, .. } => *next = true,
            }
        }
    }

    /// The subprograms of the program (reading R-SUBPROGRAM): the text
    /// before the main program's start and after its end, from the held
    /// bytes, or read from the file again (a second handle: the reading in
    /// progress keeps its place), at most [`MAX_SUBPROGRAM_TEXT`] bytes of
    /// it (one more, to tell a longer text). A file's text must be the
    /// same bytes in every reading (reading R-CHANGED).
    #[allow(clippy::type_complexity, reason = "the fields of Items::subprograms, filled once")]
    fn load_subprograms(&self) -> Result<(Held<'j>, Held<'j>, usize), ReadError> {
        let main = self.main;
        let (path, recorded) = match &self.input {
            Input::Held(bytes) => {
                let s = self.reader.subprograms_in(bytes, main)?;
                return Ok((Held::Borrowed(s.before), Held::Borrowed(s.after), s.after_line));
            }
            Input::Lines { path, subprograms, .. } => (*path, *subprograms),
        };
        let mut file = File::open(path).map_err(ReadError::Io)?;
        if self.reader.subprogram_text() == SubprogramText::WholeProgram {
            // LinuxCNC: the whole program, whose definitions stand anywhere.
            let mut whole = Vec::new();
            (&mut file)
                .take(MAX_SUBPROGRAM_TEXT as u64 + 1)
                .read_to_end(&mut whole)
                .map_err(ReadError::Io)?;
            Subprograms::whole(&whole)?;
            let digest = piece_digest(&whole);
            if *recorded.get_or_init(|| digest) != digest {
                return Err(ReadError::Changed);
            }
            return Ok((Held::Owned(whole), Held::Owned(Vec::new()), 0));
        }
        let mut before = Vec::new();
        (&mut file)
            .take(main.offset.min(MAX_SUBPROGRAM_TEXT + 1) as u64)
            .read_to_end(&mut before)
            .map_err(ReadError::Io)?;
        if main.offset > MAX_SUBPROGRAM_TEXT {
            Subprograms { before: &before, ..Subprograms::default() }.check_length()?;
        }
        {
            use std::io::Seek as _;
            file.seek(std::io::SeekFrom::Start(main.offset as u64)).map_err(ReadError::Io)?;
        }
        let (mut buf, mut piece, mut eof) = (Vec::new(), 0, false);
        let mut end = MainEnd::after(main.lines_before);
        let (after, after_line) = loop {
            match next_piece(&mut file, &mut buf, &mut piece, &mut eof) {
                Ok(true) => {}
                Ok(false) => break (Vec::new(), end.line + 1),
                Err(e) => return Err(piece_error(e, end.line + 1)),
            }
            if let Some(at) = end.feed(&buf[..piece])? {
                let mut text = buf.split_off(at);
                let more = (MAX_SUBPROGRAM_TEXT + 1).saturating_sub(text.len() + before.len());
                (&mut file).take(more as u64).read_to_end(&mut text).map_err(ReadError::Io)?;
                break (text, end.line + 1);
            }
        };
        Subprograms { before: &before, after: &after, after_line }.check_length()?;
        let digest = piece_digest(&before) ^ piece_digest(&after).rotate_left(1);
        if *recorded.get_or_init(|| digest) != digest {
            return Err(ReadError::Changed);
        }
        Ok((Held::Owned(before), Held::Owned(after), after_line))
    }

    /// The end of the text.
    fn end<T>(&mut self) -> Option<Result<T, ReadError>> {
        self.ended = true;
        self.reader.finish().err().map(|e| Err(e.into()))
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
        Profile::LinuxCnc => ProfileName::LinuxCnc,
    });
    let mut machine = Machine::new(flag.unwrap_or(ProfileName::Gsk988));
    if let Some(p) = &opts.params {
        let t = std::fs::read_to_string(p)
            .map_err(|e| Failure::new(Cause::Params, format!("{}: {e}", p.display())))?;
        let applied =
            if flag.is_some() { machine.apply_toml_keeping_profile(&t) } else { machine.apply_toml(&t) };
        applied.map_err(|e| {
            Failure::with_kind(Cause::Params, e.stable_kind(), format!("{}: {e}", p.display()))
        })?;
        // Reading R-PARAMS: a bad value is the file's error, named by key.
        cycleref_spec::reader::check_parameters(&machine)
            .map_err(|e| Failure::new(Cause::Params, format!("{}: {}", p.display(), e.kind)))?;
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
    for pair in &opts.readings {
        machine
            .readings
            .apply_pair(pair)
            .map_err(|e| Failure::new(Cause::Params, format!("--reading {pair}: {e}")))?;
    }
    Ok(machine)
}
