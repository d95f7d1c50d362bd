//! The cursor of `cycleref_cursor_open`: a program's moves, one at a time,
//! in constant memory.
//!
//! ## Design
//!
//! The program reader ([`Reader`]) borrows the program text and the
//! machine, and the items it yields borrow the text too. A cursor outlives
//! the call that opened it and must not keep the caller's pointer, so it
//! owns a copy of the text and the machine ([`Source`]) and, beside them,
//! the reader that borrows them: a self-referential struct. It is built
//! with the `self_cell` crate ([`Reading`]), which keeps the owner on the
//! heap at a fixed address, drops the reader before the owner, and only
//! lends the reader out inside a closure, so that nothing borrowed from the
//! text escapes. This crate has no `unsafe` of its own for it. (The
//! alternatives were a hand-written struct with raw pointers, `Box` and a
//! `'static` reader, which is easy to get subtly wrong (a moved `Box`
//! asserts uniqueness, a field order decides the drop order), and
//! re-creating a reader from a saved position, which the reader cannot do:
//! its modal state is the whole program before the position.)
//!
//! The current cycle's moves are a [`pipeline::Moves`] (inside [`CycleMoves`]), which
//! owns its state (the cycle's resolved parameters and the engine's
//! iterator): it borrows nothing and sits beside the reader, taken from the
//! item inside the closure. So a cursor holds: the copy of the text, the
//! machine, the reader's modal state and current block, and one cycle's
//! iterator, whatever the program's length.
//!
//! ## Two phases
//!
//! [`CyclerefCursor::open`] runs the first phase of the command
//! ([`pipeline::validate`]: every block read, every cycle's alarms checked,
//! no move kept) on the caller's text before copying it, and refuses an
//! invalid program with the first error in program order: nothing is ever
//! delivered from a program that would fail later. [`CyclerefCursor::next_move`]
//! then reads the copy a second time, item by item, and cannot meet an
//! error (the same reader on the same bytes with the same machine).

use core::fmt;

use cycleref_spec::pipeline::{self, Engine};
use cycleref_spec::{Cycle, Machine, Reader};
use self_cell::self_cell;

use crate::{program_failure, run_failure, CycleMoves, CyclerefMove, Failure};

/// What a cursor owns: a copy of the program text and the machine it is
/// read with.
struct Source {
    text: Box<[u8]>,
    machine: Machine,
}

/// The reader of a [`Source`], borrowing its text and machine.
type SourceReader<'a> = Reader<'a, 'a>;

self_cell!(
    /// A [`Source`] and the reader that borrows it.
    struct Reading {
        owner: Source,

        #[covariant]
        dependent: SourceReader,
    }
);

/// A program being read move by move: an opaque handle made by
/// `cycleref_cursor_open` and freed by `cycleref_cursor_close`.
pub struct CyclerefCursor {
    /// The program and its reader, positioned after the current cycle.
    reading: Reading,
    /// The moves of the current cycle that are not taken yet.
    cycle: Option<CycleMoves>,
    /// Set when a call panicked: the reader may be half-updated, so every
    /// later call reports the panic again.
    poisoned: bool,
    /// The error of an earlier call, should one ever come after the open,
    /// which every later call reports again.
    failed: Option<Failure>,
}

impl fmt::Debug for CyclerefCursor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("CyclerefCursor")
            .field("program_len", &self.reading.borrow_owner().text.len())
            .field("cycle", &self.cycle)
            .field("poisoned", &self.poisoned)
            .field("failed", &self.failed)
            .finish_non_exhaustive()
    }
}

impl CyclerefCursor {
    /// Validates `text` with `machine` (the first phase), then copies it
    /// into a new cursor positioned before its first move.
    ///
    /// # Errors
    ///
    /// The first error of the program, in program order: the reader's
    /// (`PROGRAM_ERROR`) or a cycle's alarm (`CYCLE_ERROR`), with its line.
    pub(crate) fn open(text: &[u8], machine: Machine) -> Result<Box<CyclerefCursor>, Failure> {
        pipeline::validate(text, &machine, Engine::Impl).map_err(run_failure)?;
        let source = Source { text: text.into(), machine };
        let reading = Reading::new(source, |s| Reader::new(&s.text, &s.machine));
        Ok(Box::new(CyclerefCursor { reading, cycle: None, poisoned: false, failed: None }))
    }

    /// The next move of the program, or `None` at its end (and after).
    ///
    /// # Errors
    ///
    /// `PANIC` when this or an earlier call panicked. A program or cycle
    /// error cannot happen after [`CyclerefCursor::open`] succeeded (the
    /// same reader on the same bytes with the same machine); should one
    /// come all the same, it is returned with its status and line, and
    /// again by every later call.
    pub(crate) fn next_move(&mut self) -> Result<Option<CyclerefMove>, Failure> {
        if self.poisoned {
            return Err(Failure::new(
                crate::CyclerefStatus::Panic,
                0,
                "the cursor is unusable after a panic",
            ));
        }
        if let Some(f) = &self.failed {
            return Err(f.clone());
        }
        // Poisoned unless the step returns: a panic inside leaves it set.
        self.poisoned = true;
        let next = self.step();
        self.poisoned = false;
        if let Err(f) = &next {
            self.failed = Some(f.clone());
        }
        next
    }

    fn step(&mut self) -> Result<Option<CyclerefMove>, Failure> {
        loop {
            if let Some(m) = self.cycle.as_mut().and_then(Iterator::next) {
                return Ok(Some(m));
            }
            self.cycle = None;
            // The next item, turned into what the cursor keeps (the cycle's
            // moves, which borrow nothing) before the item goes.
            let cycle = &mut self.cycle;
            let more = self.reading.with_dependent_mut(|_, reader| match reader.next() {
                None => Ok(false),
                Some(Err(e)) => Err(program_failure(&e)),
                Some(Ok(item)) => {
                    if let Some(c) = Cycle::of(&item) {
                        *cycle = Some(CycleMoves::new(c)?);
                    }
                    Ok(true)
                }
            })?;
            if !more {
                return Ok(None);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CyclerefStatus;
    use cycleref_spec::ProfileName;

    /// A cursor on `text` without the first phase, as if validation had
    /// missed an error.
    fn unchecked(text: &str) -> CyclerefCursor {
        let source = Source { text: text.as_bytes().into(), machine: Machine::new(ProfileName::Gsk988) };
        let reading = Reading::new(source, |s| Reader::new(&s.text, &s.machine));
        CyclerefCursor { reading, cycle: None, poisoned: false, failed: None }
    }

    #[test]
    fn an_error_after_the_open_is_reported_and_repeated() {
        let cycle = "G76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\n";
        // The second cycle (block 2 on line 7) starts inside the thread
        // (A = X62): an alarm.
        let mut c = unchecked(&format!("G50 X100 Z50 M3 S300;\nG00 X80 Z10;\n{cycle}G00 X62;\n{cycle}"));
        for _ in 0..30 {
            assert!(c.next_move().unwrap().is_some());
        }
        for _ in 0..2 {
            let f = c.next_move().unwrap_err();
            assert_eq!((f.status, f.line), (CyclerefStatus::CycleError, 7), "{}", f.message);
        }
        // A reader's error likewise.
        let mut c = unchecked("G00 X80 Z10;\nG76 X60.64 Z-62 Q1.800 F6;\n");
        for _ in 0..2 {
            let f = c.next_move().unwrap_err();
            assert_eq!((f.status, f.line), (CyclerefStatus::ProgramError, 2), "{}", f.message);
        }
        // The open refuses both.
        let f = CyclerefCursor::open(
            b"G00 X80 Z10;\nG76 X60.64 Z-62 Q1.800 F6;\n",
            Machine::new(ProfileName::Gsk988),
        )
        .unwrap_err();
        assert_eq!(f.line, 2);
    }
}
