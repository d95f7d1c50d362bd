//! The items the reader yields: a block echoed, a plain move, a cycle's
//! call with its resolved parameters, and the program they make.

#[allow(clippy::wildcard_imports)]
use super::*;

/// What the reader found in a program, in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item<'a> {
    /// A block that is not part of a cycle and commands no motion: echoed
    /// as written.
    Source(Block<'a>),
    /// A block of plain motion (G00-G03 with X, Z, U or W): echoed as
    /// written; the move it commands, from the reader's own modal state.
    Move(PlainMove<'a>),
    /// G76 block 1 (P Q R ...): sets modal values, produces no motion.
    G76Params(Block<'a>),
    /// G76 block 2: a cycle to expand.
    G76(G76Call<'a>),
    /// A G32 thread-cutting block.
    G32(G32Call<'a>),
    /// G75.1 block 1 (X Z P Q H D A B L): waits for its block 2.
    G75Params(Block<'a>),
    /// G75.1 block 2: a groove cycle to expand.
    G75(G75Call<'a>),
    /// A G92 thread-cutting cycle block (the first, or a repeat in G92
    /// mode): a cycle to expand.
    G92(G92Call<'a>),
    /// A LinuxCNC G76 block (the `linuxcnc` profile): a cycle to expand.
    LinuxCncG76(LinuxCncCall<'a>),
}

impl<'a> Item<'a> {
    /// The block the item was read from (for a cycle of two blocks, its
    /// second; block 1 is its own item).
    #[must_use]
    pub fn block(&self) -> &Block<'a> {
        match self {
            Item::Source(b) | Item::G76Params(b) | Item::G75Params(b) => b,
            Item::Move(m) => &m.block,
            Item::G76(c) => &c.block,
            Item::G32(c) => &c.block,
            Item::G75(c) => &c.block,
            Item::G92(c) => &c.block,
            Item::LinuxCncG76(c) => &c.block,
        }
    }
}

/// A block of plain motion as the reader resolves it: the one model of a
/// G00-G03 move, for `expand`'s echo, `check` (our program and a trace
/// alike) and `plot`.
///
/// An axis is `None` while no block has given it (reading R-CHECKPARTIAL:
/// a move before both axes are known moves along the one it gives).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PlainMove<'a> {
    /// The block.
    pub block: Block<'a>,
    /// G00, G01, G02 or G03 (modal: the mode in force).
    pub motion: MotionMode,
    /// X and Z before the block (increments, in `x_mode`).
    pub from: (Option<i64>, Option<i64>),
    /// X and Z after it: the absolute words, or the incremental ones added
    /// to `from`.
    pub to: (Option<i64>, Option<i64>),
    /// The X mode in force (the machine's, switched by G7/G8 on the
    /// linuxcnc profile).
    pub x_mode: XMode,
}

/// One LinuxCNC G76 block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinuxCncCall<'a> {
    /// The block.
    pub block: Block<'a>,
    /// The resolved cycle.
    pub cycle: LinuxCncG76,
}

impl LinuxCncCall<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> LinuxCncCall<'static> {
        LinuxCncCall { block: self.block.detached(), cycle: self.cycle }
    }
}

/// One G92 block of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G92Call<'a> {
    /// The block.
    pub block: Block<'a>,
    /// The resolved cycle.
    pub cycle: G92Cycle,
}

impl G92Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G92Call<'static> {
        G92Call { block: self.block.detached(), cycle: self.cycle }
    }
}

/// One G75.1 cycle of a program (its two blocks).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G75Call<'a> {
    /// Block 2 (R V U W I J A B D E P).
    pub block: Block<'a>,
    /// Line of block 1.
    pub params_line: usize,
    /// The resolved cycle.
    pub cycle: G75Cycle,
    /// Modal state to restore after the expansion.
    pub restore: Restore,
}

impl G75Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G75Call<'static> {
        G75Call {
            block: self.block.detached(),
            params_line: self.params_line,
            cycle: self.cycle,
            restore: self.restore,
        }
    }
}

/// One G32 block of a program (or LinuxCNC's G33, the same one
/// synchronised move: [`G32Call::code`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G32Call<'a> {
    /// `G32`, or `G33` on the linuxcnc profile, whose lead is the distance
    /// per revolution along the move (reading R-LCNC-SYNC).
    pub code: &'static str,
    /// The block.
    pub block: Block<'a>,
    /// The resolved block.
    pub g32: G32Block,
}

impl G32Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G32Call<'static> {
        G32Call { code: self.code, block: self.block.detached(), g32: self.g32 }
    }
}

/// Which multiple thread-cutting cycle a [`G76Call`] is: G76, or GSK's
/// enhanced G78, a front end on the same cycle (its infeed and depth modes
/// are in [`G76Cycle`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Multipass {
    /// G76, the multiple thread-cutting cycle.
    G76,
    /// G78, the GSK 980TDi's and 988TA's enhanced multiple thread-cutting
    /// cycle (增强型螺纹切削循环).
    G78,
}

impl Multipass {
    /// The G code as the manuals write it.
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            Multipass::G76 => "G76",
            Multipass::G78 => "G78",
        }
    }
}

/// One G76 or G78 cycle of a program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct G76Call<'a> {
    /// G76 or G78.
    pub code: Multipass,
    /// Block 2 (the one with X(U) Z(W)).
    pub block: Block<'a>,
    /// Line of the block 1 whose values are in force, if any.
    pub params_line: Option<usize>,
    /// The resolved cycle.
    pub cycle: G76Cycle,
    /// What to program after the expansion to give the following blocks
    /// the modal state they had before the cycle.
    pub restore: Restore,
}

impl G76Call<'_> {
    /// The call with its block [detached](Block::detached) from the text.
    #[must_use]
    pub fn detached(&self) -> G76Call<'static> {
        G76Call {
            code: self.code,
            block: self.block.detached(),
            params_line: self.params_line,
            cycle: self.cycle,
            restore: self.restore,
        }
    }
}

/// Modal state to restore after an expanded cycle, whose last block leaves
/// G00 and the lead in F.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Restore {
    /// The motion G code in force before the cycle when it was not G00
    /// (G76 is a one-shot code; the expansion ends with G00). The F register
    /// needs no restoring: the expansion writes the lead exactly as the
    /// cycle programmed or inherited it (reading R-NCOUT).
    pub motion: Option<MotionMode>,
}

/// A program read with a machine.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Program<'a> {
    /// The blocks and cycles, in order.
    pub items: Vec<Item<'a>>,
    /// The units in force for the cycles (fixed before the first motion).
    pub units: Units,
}

impl<'a> Program<'a> {
    /// The G32 blocks of the program.
    pub fn threads(&self) -> impl Iterator<Item = &G32Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G32(c) => Some(c),
            _ => None,
        })
    }

    /// The G75.1 cycles of the program.
    pub fn grooves(&self) -> impl Iterator<Item = &G75Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G75(c) => Some(c),
            _ => None,
        })
    }

    /// The cycles of the program.
    pub fn cycles(&self) -> impl Iterator<Item = &G76Call<'a>> {
        self.items.iter().filter_map(|i| match i {
            Item::G76(c) => Some(c),
            _ => None,
        })
    }
}

/// A motion G code of group 01, as the reader keeps it modal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MotionMode {
    /// G00, rapid.
    G00,
    /// G01, linear feed.
    G01,
    /// G02, clockwise arc.
    G02,
    /// G03, counter-clockwise arc.
    G03,
    /// G32, thread cutting.
    G32,
    /// G92, the thread-cutting cycle (modal: a block with X(U) or Z(W)
    /// repeats it).
    G92,
}

impl MotionMode {
    /// The G code as written (`G01`).
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            MotionMode::G00 => "G00",
            MotionMode::G01 => "G01",
            MotionMode::G02 => "G02",
            MotionMode::G03 => "G03",
            MotionMode::G32 => "G32",
            MotionMode::G92 => "G92",
        }
    }

    /// The motion of G00-G03, which every dialect reads alike (`None` for
    /// another code): one home for both readers' tables.
    #[must_use]
    pub fn plain(code: i64) -> Option<MotionMode> {
        match code {
            0 => Some(MotionMode::G00),
            1 => Some(MotionMode::G01),
            2 => Some(MotionMode::G02),
            3 => Some(MotionMode::G03),
            _ => None,
        }
    }
}
