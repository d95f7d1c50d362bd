//! How a command ends when it does not succeed: [`Failure`], each with
//! its stable kind (`error[KIND]: MESSAGE`).

use std::borrow::Cow;
use std::fmt;

/// How a command ends when it does not succeed.
#[derive(Debug)]
pub enum Failure {
    /// An error that is not the program's (its input, the parameter file,
    /// a trace, the arguments, the output): printed as `error[KIND]:
    /// MESSAGE`, exit status 2.
    Other(Box<OtherFailure>),
    /// An error of the program read (the reader's or a cycle's alarm):
    /// printed as `error[KIND]: MESSAGE`, exit status 2. `kind` is the
    /// stable kind the conformance vectors, Python and C name
    /// (`cycle:too_many_passes`, `syntax`).
    Program(Box<ProgramFailure>),
    /// The reader of the output went away (a closed pipe): the command
    /// stops quietly with exit status 0, as Unix filters do.
    BrokenPipe,
}

/// An error of the program read, with its stable kind ([`Failure::Program`]).
#[derive(Debug)]
pub struct ProgramFailure {
    /// The stable kind ([`cycleref_spec::RunError::stable_kind`]).
    pub kind: String,
    /// The message, naming the file, line and word.
    pub message: String,
}

/// An error that is not the program's, with what it is about
/// ([`Failure::Other`]).
#[derive(Debug)]
pub struct OtherFailure {
    /// What the error is about.
    pub cause: Cause,
    /// The stable kind printed: the cause's ([`Cause::stable_kind`],
    /// `trace`), or the rule's within it when it is known
    /// (`trace:not_a_decimal`, `params:unknown_key`).
    pub kind: Cow<'static, str>,
    /// The message, naming the file (and line) it is about.
    pub message: String,
}

/// What an error that is not the program's is about; its stable kind
/// ([`Cause::stable_kind`]), or the rule's within it
/// ([`OtherFailure::kind`]), is printed before the message.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Cause {
    /// The program cannot be read (a missing file, standard input).
    Input,
    /// The output cannot be written.
    Output,
    /// The parameter file cannot be read or applied.
    Params,
    /// The trace `check` compares cannot be read, or says what it cannot.
    Trace,
    /// The arguments ask for what cannot be done.
    Usage,
    /// A corpus of vectors or a list of pairs `conform` reads.
    Corpus,
    /// The generator of conformance vectors (its output directory, or an
    /// engine that disagrees with the reference).
    Vectors,
    /// A block of the program `check` cannot compare (an arc by R, an arc
    /// without a centre: reading R-CHECKARC).
    Check,
}

impl Cause {
    /// The stable kind: `input`, `output`, `params`, `trace`, `usage`,
    /// `corpus`, `vectors`, `check`.
    #[must_use]
    pub fn stable_kind(self) -> &'static str {
        match self {
            Cause::Input => "input",
            Cause::Output => "output",
            Cause::Params => "params",
            Cause::Trace => "trace",
            Cause::Usage => "usage",
            Cause::Corpus => "corpus",
            Cause::Check => "check",
            Cause::Vectors => "vectors",
        }
    }
}

impl Failure {
    /// A failure of the program read: its stable kind and message.
    #[must_use]
    pub fn program(kind: String, message: String) -> Failure {
        Failure::Program(Box::new(ProgramFailure { kind, message }))
    }

    /// A failure about `cause`, with `message`; its kind is the cause's.
    pub fn new(cause: Cause, message: impl Into<String>) -> Failure {
        Failure::with_kind(cause, cause.stable_kind(), message)
    }

    /// A failure about `cause` whose rule is known: its stable kind `kind`
    /// (`trace:not_a_decimal`, the cause's kind, a colon and the rule's
    /// name), with `message`.
    pub fn with_kind(
        cause: Cause,
        kind: impl Into<Cow<'static, str>>,
        message: impl Into<String>,
    ) -> Failure {
        Failure::Other(Box::new(OtherFailure { cause, kind: kind.into(), message: message.into() }))
    }

    /// A failure to read the program.
    pub fn input(message: impl Into<String>) -> Failure {
        Failure::new(Cause::Input, message)
    }

    /// A failure of the trace.
    pub fn trace(message: impl Into<String>) -> Failure {
        Failure::new(Cause::Trace, message)
    }

    /// A request that cannot be done.
    pub fn usage(message: impl Into<String>) -> Failure {
        Failure::new(Cause::Usage, message)
    }

    /// A failure to write the output.
    #[must_use]
    pub fn output(e: &std::io::Error) -> Failure {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            Failure::BrokenPipe
        } else {
            Failure::new(Cause::Output, format!("cannot write the output: {e}"))
        }
    }

    /// The stable kind (`syntax`, `cycle:too_many_passes`,
    /// `trace:not_a_decimal`, `input`, ...), as the command prints it: `error[KIND]: MESSAGE`.
    #[must_use]
    pub fn kind(&self) -> &str {
        match self {
            Failure::Other(o) => &o.kind,
            Failure::Program(p) => &p.kind,
            Failure::BrokenPipe => "output",
        }
    }

    /// The message, without the kind.
    #[must_use]
    pub fn message(&self) -> &str {
        match self {
            Failure::Other(o) => &o.message,
            Failure::Program(p) => &p.message,
            Failure::BrokenPipe => "the output pipe was closed",
        }
    }
}

impl fmt::Display for Failure {
    /// `error[KIND]: MESSAGE`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "error[{}]: {}", self.kind(), self.message())
    }
}

impl std::error::Error for Failure {}

impl From<Failure> for String {
    /// The message, without the kind.
    fn from(f: Failure) -> String {
        match f {
            Failure::Other(o) => o.message,
            Failure::Program(p) => p.message,
            Failure::BrokenPipe => "the output pipe was closed".to_string(),
        }
    }
}
