//! The program-level readers: [`read`] (every item in memory), [`Reader`]
//! (a program in memory, one item at a time, its subprograms found when a
//! call runs) and [`check_parameters`] (a machine's parameter file).

use cycleref::Units;

use super::line_reader::{LineReader, Step, SubprogramText};
use super::{Item, MainStart, Program, Subprograms};
use crate::error::ProgramError;
use crate::profile::Machine;

/// The count parameters of `machine` (P(m), P(a), P(r), the chamfer angle,
/// G78's infeed and depth modes), checked when the parameter file is read
/// by the rules a cycle applies when it reads them (reading R-PARAMS), so
/// that a bad value is reported against the file and its key, not the
/// first program line that happens to use it. Length parameters are
/// checked where they are used, in the program's unit then in force.
///
/// # Errors
///
/// The first parameter outside its range, named with its key and range
/// (the error's line is 0: it belongs to no line).
///
/// ```
/// use cycleref_spec::reader::check_parameters;
/// use cycleref_spec::{Machine, ProfileName};
/// let mut m = Machine::new(ProfileName::Gsk988);
/// assert!(check_parameters(&m).is_ok());
/// m.apply_toml("[parameters]\n5142 = 100\n").unwrap();
/// let e = check_parameters(&m).unwrap_err();
/// assert_eq!(e.kind.to_string(), "parameter: 5142 = 100 is outside 1..99");
/// ```
pub fn check_parameters(machine: &Machine) -> Result<(), ProgramError> {
    LineReader::new(machine).state.check_params()
}

/// Reads `source` with `machine`, collecting every item.
///
/// This holds the whole program in memory; [`Reader`] reads it one item at
/// a time in constant memory.
///
/// # Errors
///
/// The first [`ProgramError`] in program order.
pub fn read<'a>(source: &'a str, machine: &Machine) -> Result<Program<'a>, ProgramError> {
    let mut reader = Reader::new(source.as_bytes(), machine);
    let items = reader.by_ref().collect::<Result<Vec<_>, _>>()?;
    Ok(Program { items, units: reader.units() })
}

/// The items of a program, one at a time, in program order.
///
/// The reader is the program's meaning in one place: it keeps the modal
/// state the cycles depend on and resolves each cycle's words into its
/// typed parameters, validated
/// ([`G76Cycle::validate`](cycleref::G76Cycle::validate) and its twins).
/// Its memory is the modal state and the current block, whatever the
/// program's length; items borrow their text from the source.
///
/// After the first error it yields nothing more. A program is read in two
/// phases by the command (reading R-STREAM): the first pass reads every
/// item and checks every cycle, and only a program without error is read a
/// second time to write its output, so an error leaves no output behind.
///
/// ```
/// use cycleref_spec::reader::{Item, Reader};
/// use cycleref_spec::{Machine, ProfileName};
///
/// let program = b"M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
/// let machine = Machine::new(ProfileName::Gsk988);
/// let mut cycles = 0;
/// for item in Reader::new(program, &machine) {
///     if let Item::G76(call) = item? {
///         assert_eq!(call.cycle.thread_height, 3680);
///         cycles += 1;
///     }
/// }
/// assert_eq!(cycles, 1);
/// # Ok::<(), cycleref_spec::ProgramError>(())
/// ```
pub struct Reader<'a, 'm> {
    source: &'a [u8],
    reader: LineReader<'m>,
    /// Where the main program starts, found before its first block.
    main: Option<MainStart>,
    /// The program's subprograms, found when the first call runs.
    subprograms: Option<Subprograms<'a>>,
    finished: bool,
}

impl<'a, 'm> Reader<'a, 'm> {
    /// A reader of `source` (the program's bytes) with `machine`.
    #[must_use]
    pub fn new(source: &'a [u8], machine: &'m Machine) -> Reader<'a, 'm> {
        Reader { source, reader: LineReader::new(machine), main: None, subprograms: None, finished: false }
    }

    /// The units in force (fixed before the first motion, reading R-UNITS).
    #[must_use]
    pub fn units(&self) -> Units {
        self.reader.units()
    }
}

impl<'a> Iterator for Reader<'a, '_> {
    type Item = Result<Item<'a>, ProgramError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.finished {
            return None;
        }
        let main = *self.main.get_or_insert_with(|| {
            let main = match self.reader.subprogram_text() {
                SubprogramText::AroundMain => MainStart::of_text(self.source),
                SubprogramText::None | SubprogramText::WholeProgram => MainStart::default(),
            };
            self.reader.start_at(main);
            main
        });
        let piece = &self.source[main.offset..];
        loop {
            match self.reader.step(piece, self.subprograms) {
                Ok(Step::Item(item)) => return Some(Ok(item)),
                Ok(Step::Piece) => break,
                Ok(Step::Subprograms) => match self.reader.subprograms_in(self.source, main) {
                    Ok(subs) => self.subprograms = Some(subs),
                    Err(e) => {
                        self.finished = true;
                        return Some(Err(e));
                    }
                },
                Err(e) => {
                    self.finished = true;
                    return Some(Err(e));
                }
            }
        }
        if self.finished {
            return None;
        }
        self.finished = true;
        self.reader.finish().err().map(Err)
    }
}
