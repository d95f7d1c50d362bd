//! The program reader: modal state and the typed cycle parameters.
//!
//! This is the one home of the program's meaning. It tracks what the cycles
//! depend on (position, motion mode, lead, units, spindle, the modal values
//! of G76 block 1) and turns every G76 into a [`G76Cycle`] that both the
//! reference model ([`crate::g76`]) and the engine (`cycleref::engine`)
//! expand.
//!
//! The reader's parts: this file holds the `State` (the modal values)
//! and the errors the parts share; `reader/modal.rs` reads a block in the
//! state, `reader/line_reader.rs` is the [`LineReader`] driver,
//! `reader/program.rs` the program-level [`read`], [`Reader`] and
//! [`check_parameters`]; the cycles' blocks are in `reader/g76.rs`,
//! `reader/g75.rs`, `reader/threads.rs` (G32, G92) and
//! `reader/linuxcnc.rs`, the subprogram calls in `reader/calls.rs`, the
//! words as numbers in `reader/words.rs`, the items in `reader/items.rs`
//! and the trace mode in `reader/trace.rs`.

use cycleref::angle::StartAngle;
use cycleref::g32::{G32Block, G32RunOut};
use cycleref::g75::{Corner, CornerKind, G75Cycle, PathType, RIGHT_ANGLE};
use cycleref::g76::{DepthMode, G76Cycle, Infeed, RunOut};
use cycleref::g92::G92Cycle;
use cycleref::lead::{Lead, LeadWord, MAX_LEAD_SCALE};
use cycleref::linuxcnc::LinuxCncG76;
use cycleref::units::{Point, MAX_LENGTH};
use cycleref::{InputUnit, Units, XMode};
use rust_decimal::Decimal;

use crate::error::ErrorKind::NotInIncrements;
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{letter_bit, Block, Word};
use crate::profile::{G32Rules, Machine, PSplit, PqUnit, QUnit, RunOutRules};

mod calls;
mod g75;
mod g76;
mod items;
mod line_reader;
mod linuxcnc;
mod modal;
mod program;
mod threads;
mod trace;
mod words;

pub use calls::{
    may_hold_return, MainEnd, MainStart, MainStartFinder, SubprogramError, Subprograms,
    DEFAULT_SUBPROGRAM_BLOCK_LIMIT, DEFAULT_SUBPROGRAM_NESTING, LINUXCNC_SUBPROGRAM_NESTING,
    MAX_SUBPROGRAM_NESTING, MAX_SUBPROGRAM_TEXT,
};
pub use g76::{resolve_run_out, resolve_run_out_under};
pub use items::{
    G32Call, G75Call, G76Call, G92Call, Item, LinuxCncCall, MotionMode, Multipass, PlainMove, Program,
    Restore,
};
pub use line_reader::{LineReader, Step, SubprogramText};
pub use program::{check_parameters, read, Reader};
pub use threads::{resolve_g32_run_out, resolve_g32_run_out_under};
pub use words::{check_axis_words, length_word, q_word};
#[allow(clippy::wildcard_imports)]
use {g75::*, g76::*, threads::*, words::*};

#[derive(Debug)]
struct State<'m> {
    machine: &'m Machine,
    units: Units,
    x: Option<i64>,
    z: Option<i64>,
    moved: bool,
    motion: MotionMode,
    lead: Option<Lead>,
    speed: bool,
    spindle_on: bool,
    /// Block 1's modal values, of G76 and of G78 (each its own).
    modal: [G76Modal; 2],
    one_shot: G76OneShot,
    /// G32's modal J and K (seed 002: "J、K是模态代码 … 在执行非螺纹切削代码时取消").
    g32_j: Option<i64>,
    g32_k: Option<i64>,
    /// The start angle of the open continuous thread, if the previous block
    /// was a G32 block that leaves the synchronisation running.
    thread_run: Option<StartAngle>,
    /// G75.1 block 1 waiting for its block 2.
    g75_pending: Option<G75Block1>,
    /// G92's modal values (reading R-G92MODAL).
    g92: G92Modal,
    /// The X mode in force (the machine's, switched by G7/G8 on the
    /// linuxcnc profile).
    x_mode: XMode,
    /// LinuxCNC: G76 is the motion mode in force (a later block with X or
    /// Z runs it again and needs its words again, as the interpreter does).
    lcnc_g76: bool,
    /// LinuxCNC: G33 is the motion mode in force (likewise: every block
    /// needs its K).
    lcnc_g33: bool,
    /// LinuxCNC: the previous block with words was a G33 move, so the
    /// synchronisation runs on (R-LCNC-G33).
    lcnc_thread_run: bool,
    /// M02 or M30 has been read: the program has ended (reading
    /// R-PROGRAMEND).
    program_end: bool,
    /// Reading a trace ([`LineReader::for_trace`]): its rules as well.
    trace: bool,
    /// The unit of G76's P and Q under the machine's state parameter, read
    /// once: the machine does not change while it is read with (issue 33:
    /// a parameter looked up by name per P and Q word).
    pq_unit: PqUnit,
    /// The machine's parameter 5129 selects the high-speed threading mode
    /// (likewise read once).
    high_speed: bool,
}

/// Reading R-SUBPROGRAM: a subprogram call or return is refused, with its
/// line and word, until subprograms are expanded: an expansion that left
/// the call out, or read the subprogram where it stands in the file, would
/// not be the program the control runs.
fn subprogram(block: &Block<'_>, w: &Word<'_>) -> ProgramError {
    err(
        block,
        Some(w),
        ErrorKind::Unsupported(
            "a subprogram call or return (M98/M99) where no call is followed: a trace holds the moves as \
             the control ran them, and LinuxCNC calls subroutines with o-words, which are not followed yet \
             (reading R-SUBPROGRAM)"
                .into(),
        ),
    )
}

fn err(block: &Block<'_>, word: Option<&Word<'_>>, kind: ErrorKind) -> ProgramError {
    ProgramError { line: block.line, word: word.map(|w| w.text().into_owned()), kind }
}

/// A cycle's alarm found when its block 2 is read, placed where the value
/// it is about was written (reading R-ERRLINE): at block 1's line
/// (`params_line`) for a word of block 1, else at block 2 with its word
/// when block 2 has it.
fn cycle_err(block: &Block<'_>, params_line: Option<usize>, e: cycleref::CycleError) -> ProgramError {
    match (e.field(), params_line) {
        (Some(field), Some(line)) if field.in_block_1() => {
            ProgramError { line, word: None, kind: ErrorKind::Cycle(e) }
        }
        (Some(field), _) => {
            let letter = field.word().chars().next().unwrap_or(' ');
            let word = block.all(letter).next();
            err(block, word, ErrorKind::Cycle(e))
        }
        (None, _) => err(block, None, ErrorKind::Cycle(e)),
    }
}
