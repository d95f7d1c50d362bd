//! The modal state at work: what a block is ([`State::scan`], the G and
//! M codes, the modal values a block sets, the plain moves), the item it
//! makes, and the checks shared by the cycles (axis words, addresses, the
//! spindle, the machine's parameters).

use cycleref::lead::{Lead, LeadWord};
use cycleref::units::{Point, MAX_LENGTH};
use cycleref::InputUnit;
use rust_decimal::Decimal;

use super::g75::G75Block1;
use super::threads::G92Modal;
use super::words::letter_mask;
use super::{err, subprogram, Item, MotionMode, Multipass, PlainMove, State};
use crate::error::{ErrorKind, ProgramError};
use crate::lex::{letter_bit, Block, Word};
use crate::profile::Dialect;
use crate::readings::Spindle;

/// X, Z, U and W of a block.
type AxisWords<'b, 'a> =
    (Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>, Option<&'b Word<'a>>);

/// What [`State::scan`] found a block to be: the rest of its reading
/// takes the block itself.
#[derive(Debug)]
pub(super) enum Next {
    /// A block echoed as written: read in full.
    Source,
    /// A block of plain motion, read in full: the position it starts from
    /// (the state holds where it ends).
    Move((Option<i64>, Option<i64>)),
    /// A block of the LinuxCNC dialect (read by `linuxcnc_block`).
    LinuxCnc,
    /// G75.1 block 1: read in full, pending.
    G75Params,
    /// G75.1 block 2, after its block 1.
    G75(G75Block1),
    /// G76 (G78) block 1: read in full.
    G76Params,
    /// G76 (G78) block 2.
    G76(Multipass),
    /// A G32 block.
    G32,
    /// A G92 block.
    G92,
}

impl State<'_> {
    /// True when the reader follows subprogram calls: a program, not a
    /// trace (which holds no calls).
    pub(super) fn follows_calls(&self) -> bool {
        !self.trace
    }

    /// The machine's settings that no program can use (none at present:
    /// 5129 = 1, the 988TA's high-speed threading mode, is followed by G92
    /// and, under reading R-HIGHSPEED, by G76 and G78 or refused by their
    /// block 2).
    #[allow(clippy::unnecessary_wraps, clippy::unused_self)]
    pub(super) fn check_machine(&self) -> Result<(), ProgramError> {
        Ok(())
    }

    /// The count parameters a cycle reads when its block leaves a value
    /// out, checked by the same rules as there (reading R-PARAMS).
    pub(super) fn check_params(&self) -> Result<(), ProgramError> {
        let profile = &self.machine.profile;
        let p = &profile.params;
        self.param_count(p.finishing_passes, i64::from(profile.min_finishing_passes), 99)?;
        self.param_count(p.tool_angle, 0, 99)?;
        self.param_count(p.chamfer, 0, 99)?;
        if let Some(n) = p.chamfer_angle {
            self.param_count(n, 0, 89)?;
        }
        if let Some(g78) = profile.g78 {
            let last = i64::try_from(g78.infeeds.len()).unwrap_or(1) - 1;
            self.param_count(g78.infeed_param, 0, last)?;
            self.param_count(g78.depth_mode_param, 0, 1)?;
        }
        Ok(())
    }

    /// True when the 988TA's parameter 5129 (THM) selects the high-speed
    /// threading mode.
    pub(super) fn high_speed(&self) -> bool {
        self.high_speed
    }
}

impl State<'_> {
    /// The item of `block` once [`State::scan`] has said what it is.
    pub(super) fn item<'a>(&mut self, next: Next, block: Block<'a>) -> Result<Item<'a>, ProgramError> {
        match next {
            Next::Source => Ok(Item::Source(block)),
            Next::Move(from) => Ok(Item::Move(self.plain_move(block, from))),
            Next::LinuxCnc => self.linuxcnc_block(block),
            Next::G75Params => Ok(Item::G75Params(block)),
            Next::G75(first) => self.g75_block2(first, block).map(Item::G75),
            Next::G76Params => Ok(Item::G76Params(block)),
            Next::G76(code) => self.g76_block2(block, code).map(Item::G76),
            Next::G32 => self.g32_block(block).map(Item::G32),
            Next::G92 => self.g92_block(block).map(Item::G92),
        }
    }

    /// Reads `block` in the modal state as far as deciding its item: all
    /// of it for a block that is not a cycle's (most are), which then
    /// moves once, into its item.
    pub(super) fn scan(&mut self, block: &Block<'_>) -> Result<Next, ProgramError> {
        if self.machine.profile.dialect == Dialect::LinuxCnc {
            return Ok(Next::LinuxCnc);
        }
        #[cfg(test)]
        let plain = !tests::GENERAL_ONLY.with(std::cell::Cell::get);
        #[cfg(not(test))]
        let plain = true;
        if plain {
            if let Some(next) = self.scan_plain(block) {
                return Ok(next);
            }
        }
        self.scan_general(block)
    }

    /// [`State::scan`] of the usual block of a program (not a trace): no
    /// words, or only G00-G03, F, X, Z, U and W, none twice, in the mode
    /// G00-G03, read without an error (the lead by
    /// [`lead_short`](State::lead_short), the axes by the general
    /// [`axis`](State::axis)). It decides before it changes the state and
    /// then changes it as [`scan_general`](State::scan_general) does, in
    /// its order; `None`, the state untouched, for any other block, which
    /// `scan_general` reads. Held equal to it by the proptest in this
    /// module's tests (issue 33: a move's modal reading was a sixth of a
    /// reading).
    #[inline(always)]
    pub(super) fn scan_plain(&mut self, block: &Block<'_>) -> Option<Next> {
        const PLAIN: u32 = letter_bit('G')
            | letter_bit('F')
            | letter_bit('X')
            | letter_bit('Z')
            | letter_bit('U')
            | letter_bit('W');
        let (present, repeated) = block.words.letter_masks();
        if present & !PLAIN != 0 || repeated != 0 || self.trace {
            return None;
        }
        if present == 0 {
            // No words (a comment): nothing changes.
            return Some(Next::Source);
        }
        let (mut g, mut f, mut slots) = (None, None, [None; 6]);
        for w in &block.words {
            match w.letter {
                'G' => g = Some(w),
                'F' => f = Some(w),
                // U to Z (V and Y are not there).
                l => *slots.get_mut((l as usize).wrapping_sub('U' as usize))? = Some(w),
            }
        }
        let [uw, _, ww, xw, _, zw] = slots;
        let motion = match g {
            Some(w) => Some(MotionMode::plain(w.integer()?)?),
            None => None,
        };
        if !matches!(
            motion.unwrap_or(self.motion),
            MotionMode::G00 | MotionMode::G01 | MotionMode::G02 | MotionMode::G03
        ) {
            return None;
        }
        let lead = match f {
            Some(w) => Some(self.lead_short(w)?),
            None => None,
        };
        if xw.is_some() && uw.is_some() || zw.is_some() && ww.is_some() {
            return None;
        }
        let x = self.axis(block, xw, uw, self.x).ok()?;
        let z = self.axis(block, zw, ww, self.z).ok()?;
        // Decided: the changes of `scan_general`, in its order.
        self.thread_run = None;
        if motion.is_some() {
            self.g32_j = None;
            self.g32_k = None;
        }
        if lead.is_some() {
            self.lead = lead;
        }
        if let Some(m) = motion {
            self.g92 = G92Modal::default();
            self.motion = m;
        }
        if xw.is_none() && zw.is_none() && uw.is_none() && ww.is_none() {
            return Some(Next::Source);
        }
        self.g32_j = None;
        self.g32_k = None;
        let from = (self.x, self.z);
        self.x = x;
        self.z = z;
        self.moved = true;
        Some(Next::Move(from))
    }

    /// [`State::scan`] of any block, with every rule and every error.
    fn scan_general(&mut self, block: &Block<'_>) -> Result<Next, ProgramError> {
        // G codes of the block.
        let mut g76: Option<Multipass> = None;
        let mut g75 = false;
        let mut g50 = false;
        let mut g04 = false;
        let mut motion = None;
        // The G word of a canned cycle (refused in a trace).
        let mut cycle_word = None;
        for w in block.all('G') {
            let whole = w.integer();
            if matches!(whole, Some(76 | 78 | 92)) || (whole.is_none() && super::g75::is_751(&w.number())) {
                cycle_word = cycle_word.or(Some(w));
            }
            match whole {
                Some(c @ 0..=3) => motion = MotionMode::plain(c),
                Some(32) => motion = Some(MotionMode::G32),
                Some(92) => motion = Some(MotionMode::G92),
                Some(4) => g04 = true,
                Some(50) => g50 = true,
                Some(76) => g76 = Some(Multipass::G76),
                Some(78) => {
                    if self.machine.profile.g78.is_none() {
                        return Err(err(
                            block,
                            Some(w),
                            ErrorKind::Unsupported(format!(
                                "G78 on the {} profile (G78 is GSK's enhanced thread-cutting cycle: use the \
                                 gsk980 or gsk988 profile)",
                                self.machine.profile.name
                            )),
                        ));
                    }
                    g76 = Some(Multipass::G78);
                }
                Some(20) => self.set_unit(block, w, InputUnit::Inch)?,
                Some(21) => self.set_unit(block, w, InputUnit::Metric)?,
                Some(18 | 40 | 54..=59 | 96 | 97 | 98 | 99) => {}
                None if super::g75::is_751(&w.number()) => {
                    if !self.machine.profile.g75_1 {
                        return Err(err(
                            block,
                            Some(w),
                            ErrorKind::Unsupported(format!(
                                "G75.1 on the {} profile (G75.1 is a GSK 980TDi cycle: use the gsk980 \
                                 profile)",
                                self.machine.profile.name
                            )),
                        ));
                    }
                    g75 = true;
                }
                _ => {
                    let code = w.number().decimal().unwrap_or(Decimal::NEGATIVE_ONE);
                    return Err(err(
                        block,
                        Some(w),
                        ErrorKind::Unsupported(format!(
                            "G{code} (the reader models G00-G04, G18, G20/G21, G32, G40, G50, G54-G59, \
                             G75.1, G76, G92 (the thread-cutting cycle), G96-G99)"
                        )),
                    ));
                }
            }
        }
        // M codes and S.
        for w in block.all('M') {
            match w.integer() {
                Some(3 | 4) => self.spindle_on = true,
                Some(5) => self.spindle_on = false,
                Some(98 | 99) => return Err(subprogram(block, w)),
                // A trace goes on after it: its moves are compared.
                Some(2 | 30) => self.program_end = !self.trace,
                _ => {}
            }
        }
        if self.trace {
            let m = motion.unwrap_or(self.motion);
            self.trace_block(block, cycle_word, m, m == MotionMode::G32, g04)?;
        }
        if let Some(s) = block.get('S')? {
            // Reading R-SPINDLE: `G50 S` alone clamps the spindle speed; with X/Z
            // (the manuals' "G50 X100 Z50 M3 S300") S is the speed.
            let clamp = g50 && !block.has('X') && !block.has('Z');
            if !clamp && s.number().is_positive() {
                self.speed = true;
            }
        }
        if !block.words.is_empty() {
            // Continuity needs consecutive G32 blocks (a comment line does not count).
            let thread_block = motion.unwrap_or(self.motion) == MotionMode::G32
                && g76.is_none()
                && !g50
                && !g04
                && ['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c));
            if !thread_block {
                self.thread_run = None;
                // Seed 002: J and K are cancelled by a non-thread motion.
                if motion.is_some_and(|m| m != MotionMode::G32) || g76.is_some() || g75 {
                    self.g32_j = None;
                    self.g32_k = None;
                }
            }
        }
        if g75 {
            if motion.is_some() || g76.is_some() || g50 || g04 {
                return Err(err(
                    block,
                    None,
                    ErrorKind::Unsupported("another G code of group 00/01 in the same block as G75.1".into()),
                ));
            }
            return match self.g75_pending.take() {
                None => {
                    self.g75_pending = Some(self.g75_block1(block)?);
                    Ok(Next::G75Params)
                }
                Some(first) => Ok(Next::G75(first)),
            };
        }
        if let Some(code) = g76 {
            if motion.is_some() {
                return Err(err(
                    block,
                    None,
                    ErrorKind::Unsupported(format!("a motion G code in the same block as {}", code.code())),
                ));
            }
            return if ['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c)) {
                Ok(Next::G76(code))
            } else {
                self.g76_block1(block, code)?;
                Ok(Next::G76Params)
            };
        }
        if let Some(f) = block.get('F')? {
            // The usual lead in one reading of its digits (a lead within
            // its range table is positive); any other as before.
            if let Some(lead) = self.lead_short(f) {
                self.lead = Some(lead);
            } else if f.number().is_positive() {
                self.lead =
                    Some(self.lead(block, f).unwrap_or(Lead { word: LeadWord::F, mantissa: 0, scale: 0 }));
            }
        }
        if let Some(m) = motion {
            if m != MotionMode::G92 {
                // Reading R-G92MODAL: another motion code ends the G92 mode.
                self.g92 = G92Modal::default();
            }
            self.motion = m;
        }
        if matches!(motion, Some(MotionMode::G32 | MotionMode::G92))
            && !g04
            && !g50
            && !['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c))
        {
            let rule = if motion == Some(MotionMode::G32) {
                "G32 cuts to an end point"
            } else {
                "G92 cuts to its cut end point C"
            };
            return Err(err(block, None, ErrorKind::Missing { what: "X(U) Z(W) (the end point)", rule }));
        }
        if g04 {
            return Ok(Next::Source);
        }
        let (xw, zw, uw, ww) = Self::axis_words(block)?;
        if g50 {
            if uw.is_some() || ww.is_some() {
                return Err(err(block, uw.or(ww), ErrorKind::Unsupported("U/W in G50".into())));
            }
            if let Some(w) = xw {
                self.x = Some(self.length(block, w)?);
            }
            if let Some(w) = zw {
                self.z = Some(self.length(block, w)?);
            }
            return Ok(Next::Source);
        }
        if xw.is_some() || zw.is_some() || uw.is_some() || ww.is_some() {
            if self.motion == MotionMode::G32 {
                return Ok(Next::G32);
            }
            if self.motion == MotionMode::G92 {
                return Ok(Next::G92);
            }
            self.g32_j = None;
            self.g32_k = None;
            let from = (self.x, self.z);
            self.x = self.axis(block, xw, uw, self.x)?;
            self.z = self.axis(block, zw, ww, self.z)?;
            self.moved = true;
            return Ok(Next::Move(from));
        }
        Ok(Next::Source)
    }

    /// The move of a plain block from `from` to where the state now holds
    /// the tool.
    pub(super) fn plain_move<'a>(&self, block: Block<'a>, from: (Option<i64>, Option<i64>)) -> PlainMove<'a> {
        PlainMove { block, motion: self.motion, from, to: (self.x, self.z), x_mode: self.x_mode }
    }

    /// True once the unit can no longer change (reading R-UNITS): after
    /// the first motion, or once a position is known (G50).
    pub(super) fn units_settled(&self) -> bool {
        self.moved || self.x.is_some() || self.z.is_some()
    }

    /// G20/G21 (reading R-UNITS): the unit may change only before the
    /// first motion.
    pub(super) fn set_unit(
        &mut self,
        block: &Block<'_>,
        w: &Word<'_>,
        unit: InputUnit,
    ) -> Result<(), ProgramError> {
        if self.trace {
            return self.trace_unit(block, w, unit);
        }
        if unit != self.units.unit {
            if self.units_settled() {
                return Err(err(block, Some(w), ErrorKind::UnitChangeAfterMotion));
            }
            self.units.unit = unit;
        }
        Ok(())
    }

    #[inline(always)]
    pub(super) fn axis(
        &self,
        block: &Block<'_>,
        abs: Option<&Word<'_>>,
        inc: Option<&Word<'_>>,
        cur: Option<i64>,
    ) -> Result<Option<i64>, ProgramError> {
        if let Some(w) = abs {
            return Ok(Some(self.length(block, w)?));
        }
        if let Some(w) = inc {
            let d = self.length(block, w)?;
            let c = cur.ok_or_else(|| err(block, Some(w), ErrorKind::PositionUnknown))?;
            let v = c + d;
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                return Err(err(block, Some(w), self.range_err(true)));
            }
            return Ok(Some(v));
        }
        Ok(cur)
    }

    /// X, Z, U and W of a block; X with U or Z with W is an error.
    #[inline(always)]
    pub(super) fn axis_words<'b, 'a>(block: &'b Block<'a>) -> Result<AxisWords<'b, 'a>, ProgramError> {
        if !['X', 'Z', 'U', 'W'].iter().any(|&c| block.has(c)) {
            return Ok((None, None, None, None));
        }
        let (xw, zw, uw, ww) = if ['X', 'Z', 'U', 'W'].iter().any(|&c| block.words.repeats(c)) {
            // `get` names the repeated word.
            (block.get('X')?, block.get('Z')?, block.get('U')?, block.get('W')?)
        } else {
            // The usual case: one pass over the words, each put in the
            // slot of its letter, U to Z (V and Y unused).
            let mut slots = [None; 6];
            for w in &block.words {
                if let Some(slot) = slots.get_mut((w.letter as usize).wrapping_sub('U' as usize)) {
                    *slot = Some(w);
                }
            }
            let [uw, _, ww, xw, _, zw] = slots;
            (xw, zw, uw, ww)
        };
        if xw.is_some() && uw.is_some() || zw.is_some() && ww.is_some() {
            return Err(err(
                block,
                uw.or(ww),
                ErrorKind::Unsupported("absolute and incremental words for the same axis".into()),
            ));
        }
        Ok((xw, zw, uw, ww))
    }

    /// The end point X(U) Z(W) of a block that starts at `from`.
    #[inline(always)]
    pub(super) fn end_point(&self, block: &Block<'_>, from: Point) -> Result<Point, ProgramError> {
        let (xw, zw, uw, ww) = Self::axis_words(block)?;
        let x = self.axis(block, xw, uw, Some(from.x))?.unwrap_or(from.x);
        let z = self.axis(block, zw, ww, Some(from.z))?.unwrap_or(from.z);
        Ok(Point::new(x, z))
    }

    pub(super) fn check_spindle(&self, block: &Block<'_>) -> Result<(), ProgramError> {
        // A trace is a log of moves: it need not hold the spindle's words.
        // Reading R-SPINDLE: the spindle running too (M03/M04 since the
        // last M05), unless `speed-only`.
        let running = self.spindle_on || self.machine.readings.spindle == Spindle::SpeedOnly;
        if self.trace || (self.speed && running) {
            Ok(())
        } else {
            Err(err(block, None, ErrorKind::NoSpindleSpeed))
        }
    }

    /// Every word of `block` has an address of `allowed` or `extra`.
    #[inline(always)]
    pub(super) fn check_addresses(
        &self,
        block: &Block<'_>,
        cycle: &'static str,
        allowed: &str,
        extra: &str,
    ) -> Result<(), ProgramError> {
        // `allowed` is a literal where this is inlined: its mask is folded
        // (issue 33: the lists' masks were most of the check).
        self.check_addresses_in(block, cycle, allowed, extra, letter_mask(allowed))
    }

    /// [`State::check_addresses`] given `allowed`'s mask.
    fn check_addresses_in(
        &self,
        block: &Block<'_>,
        cycle: &'static str,
        allowed: &str,
        extra: &str,
        allowed_mask: u32,
    ) -> Result<(), ProgramError> {
        // Most words are upper-case letters of the lists: a bit test each;
        // the lists themselves are read for any other.
        let listed = allowed_mask | letter_mask(extra);
        for w in &block.words {
            if letter_bit(w.letter) & listed != 0 {
                continue;
            }
            if !allowed.contains(w.letter) && !extra.contains(w.letter) {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::AddressNotInProfile { cycle, profile: self.machine.profile.name.to_string() },
                ));
            }
        }
        Ok(())
    }

    /// P(k) or Q(Δd) of G76 block 2: required, in the profile's P/Q unit,
    /// 1..=the profile's range table.
    pub(super) fn depth_word(
        &self,
        block: &Block<'_>,
        letter: char,
        what: &'static str,
        rule: &'static str,
    ) -> Result<i64, ProgramError> {
        let max = self.machine.profile.max_depth_increments;
        let w = block.get(letter)?.ok_or_else(|| err(block, None, ErrorKind::Missing { what, rule }))?;
        let v = self.pq_length(block, w)?;
        if v == 0 || v > max {
            return Err(err(
                block,
                Some(w),
                ErrorKind::OutOfRange { range: format!("1..{max} least increments") },
            ));
        }
        Ok(v)
    }
}

#[cfg(test)]
pub(super) mod tests {
    //! The modal reading of the usual block held equal to the general one.

    use std::cell::Cell;

    use proptest::prelude::*;

    use crate::reader::{LineReader, Step};
    use crate::{Machine, ProfileName};

    thread_local! {
        /// Set: every block is read by `scan_general` alone (and by
        /// `LineReader::step`'s general reading).
        pub(in crate::reader) static GENERAL_ONLY: Cell<bool> = const { Cell::new(false) };
        /// How many blocks `LineReader::step_plain` has read.
        pub(in crate::reader) static PLAIN_STEPS: Cell<usize> = const { Cell::new(0) };
        /// How many blocks `LineReader::step_plain` has read and left to
        /// `LineReader::item_of`.
        pub(in crate::reader) static LEXED_STEPS: Cell<usize> = const { Cell::new(0) };
    }

    /// Every step of reading `program` with `profile`: the item or the
    /// error, and the reader's state after it, as text.
    pub(in crate::reader) fn read(program: &str, profile: ProfileName, general: bool) -> Vec<String> {
        read_pieces(&[program], profile, general)
    }

    /// [`read`] of a program given a piece at a time (each piece until it
    /// has no more, as a file is read a line at a time).
    pub(in crate::reader) fn read_pieces(
        pieces: &[&str],
        profile: ProfileName,
        general: bool,
    ) -> Vec<String> {
        GENERAL_ONLY.with(|g| g.set(general));
        let machine = Machine::new(profile);
        let mut reader = LineReader::new(&machine);
        let mut out = Vec::new();
        'pieces: for piece in pieces {
            loop {
                let step = reader.step(piece.as_bytes(), None);
                let piece_end = matches!(step, Ok(Step::Piece));
                let end = matches!(step, Ok(Step::Subprograms) | Err(_));
                out.push(format!("{step:?} {:?}", reader.state));
                if end {
                    break 'pieces;
                }
                if piece_end {
                    break;
                }
            }
        }
        out.push(format!("{:?}", reader.finish()));
        GENERAL_ONLY.with(|g| g.set(false));
        out
    }

    /// A line's end and what may stand before it: nothing, `;`, a comment
    /// after a `;`, another block after a `;`, spaces (every line end of
    /// reading R-LINEEND).
    pub(in crate::reader) fn ending() -> impl Strategy<Value = String> {
        let tail = prop_oneof![
            6 => Just(""),
            3 => Just(";"),
            1 => Just("; (finish 1)"),
            1 => Just(";X1"),
            1 => Just(" ; "),
            1 => Just(" (c)"),
            1 => Just("\t"),
        ];
        let end = prop_oneof![4 => Just("\n"), 1 => Just("\r\n"), 1 => Just("\r")];
        (tail, end).prop_map(|(t, e)| format!("{t}{e}"))
    }

    /// Lines the general step alone reads among the usual ones: blank, `%`,
    /// N, lower case, an M word, a G76 block, a comment not closed, a
    /// space after a letter.
    fn other_line() -> impl Strategy<Value = String> {
        proptest::sample::select(vec![
            "",
            "%",
            "N10 G01 X1",
            "g01 x21.5 z-3",
            "G01 X1 M05",
            "G76 P020560 Q150 R0.1",
            "G76 X60.64 Z-40 P3680 Q1800 F6",
            "G01 X1 (open",
            "G01 X 1",
            "O0100",
            "M30",
        ])
        .prop_map(str::to_string)
    }

    /// G76 and G32 lines, well formed or not, that the fast step reads and
    /// leaves to `LineReader::item_of`: block 1 and block 2 words, each
    /// perhaps twice, missing or in lower case, with numbers out of range,
    /// with a point or a sign where none belongs, comments between words,
    /// a space after a letter, an M word (which the general step reads).
    fn thread_line() -> impl Strategy<Value = String> {
        let word = prop_oneof![
            3 => "[PQR]-?[0-9]{1,7}(\\.[0-9]{0,3})?",
            3 => "[XZUW]-?[0-9]{1,3}(\\.[0-9]{0,3})?",
            2 => "F(0\\.[0-9]{1,4}|[0-9]{1,2}|0)",
            1 => "[DLEJKIST][0-9]{1,3}",
            1 => "(p|q|r|x|z|f)[0-9]{1,4}",
            1 => "\\(c\\)|P 1|M0[35]|Q|R\\.|G32|G76",
        ];
        let head = prop_oneof![4 => Just("G76"), 1 => Just("G32"), 1 => Just("g76"), 1 => Just("G78"), 1 => Just("")];
        (
            head,
            proptest::collection::vec(word, 0..7),
            prop_oneof![Just(" "), Just(""), Just("  "), Just("\t")],
        )
            .prop_map(|(h, w, sep)| format!("{h}{sep}{}", w.join(sep)))
    }

    /// Lines of a program: the usual moves (every letter of the fast
    /// reading, in any order, twice, with other G codes, values out of
    /// range or finer than the increment, leads out of the table,
    /// incremental moves before a position is known) and the blocks that
    /// change what they mean (G32, G92, G50, G04, M, S, T, G20/G21).
    fn line() -> impl Strategy<Value = String> {
        let word = prop_oneof![
            4 => "[XZUW]-?[0-9]{1,4}(\\.[0-9]{0,5})?",
            2 => "G0?[0-3]",
            1 => "G(1\\.0|4|04|20|21|32|50|92|96|97|98|99|01\\.5|-1)",
            2 => "F(0\\.[0-9]{1,7}|[0-9]{1,5}|-1|0)",
            1 => "[MSTIKJV][0-9]{1,3}",
            1 => "X9{9}|Z-9{9}\\.9|U0\\.0001",
        ];
        prop_oneof![
            8 => proptest::collection::vec(word, 0..5).prop_map(|w| w.join(" ")),
            1 => Just("(note)".to_string()),
            1 => Just("M03 S500".to_string()),
            1 => Just("G50 X100 Z50".to_string()),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        #[test]
        fn plain_scans_are_the_general_ones(lines in proptest::collection::vec(line(), 0..16), p in 0_usize..3) {
            let profile = [ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::Fanuc][p];
            let program = lines.join("\n");
            prop_assert_eq!(read(&program, profile, false), read(&program, profile, true), "{}", program);
        }

        /// The same with every line end, `;` and comments after it, the
        /// lines the fast step gives up on, and the program read a line a
        /// piece as well as whole.
        #[test]
        fn plain_steps_are_the_general_ones(
            lines in proptest::collection::vec(
                (prop_oneof![4 => line(), 2 => thread_line(), 1 => other_line()], ending()),
                0..16,
            ),
            p in 0_usize..3,
        ) {
            let profile = [ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::Fanuc][p];
            let pieces: Vec<String> = lines.iter().map(|(l, e)| format!("{l}{e}")).collect();
            let program = pieces.concat();
            prop_assert_eq!(read(&program, profile, false), read(&program, profile, true), "{:?}", program);
            let pieces: Vec<&str> = pieces.iter().map(String::as_str).collect();
            prop_assert_eq!(
                read_pieces(&pieces, profile, false),
                read_pieces(&pieces, profile, true),
                "{:?}",
                program
            );
        }
    }

    /// The fast step is reached: a line's first block of the usual moves'
    /// words, or of none, is read by `step_plain`, a comment after its `;`
    /// included; not a line with other words, nor a block after a `;`,
    /// nor a blank line (read with the line after it).
    #[test]
    fn plain_step_reads_the_usual_lines() {
        let program = "G50 X100 Z50;\nM03 S500\n(part 0)\nG00 X80 Z10;\r\nG01 X21.001 Z-3.25 F0.15; (finish 1)\nU-2\rG01 Z-9;X24\n\nX30\nN10 X1\n";
        PLAIN_STEPS.with(|n| n.set(0));
        let fast = read(program, ProfileName::Gsk980, false);
        // Lines 3 to 7 (`(part 0)`, `G00 X80 Z10;`, `G01 ... ; (finish 1)`,
        // `U-2`, `G01 Z-9`); not `X24` after it on line 7, nor line 9,
        // `X30`, read with the blank line before it.
        assert_eq!(PLAIN_STEPS.with(Cell::get), 5);
        assert_eq!(fast, read(program, ProfileName::Gsk980, true));
    }

    /// A G76 line, a G32 line and an S word are read by `step_plain` and
    /// given to `item_of` (not read again by the general step); an M word
    /// is not.
    #[test]
    fn plain_step_reads_the_thread_lines() {
        let program = "G00 X80 Z10\nM03 S500\nG76 P020560 Q150 R0.1;\nG76 X60.64 Z-40 P3680 Q1800 F6;\nS600\nG32 W-5 F1\nM05\n";
        LEXED_STEPS.with(|n| n.set(0));
        let fast = read(program, ProfileName::Gsk980, false);
        // Lines 3 to 6: both G76 blocks, S600 and the G32 block.
        assert_eq!(LEXED_STEPS.with(Cell::get), 4);
        assert_eq!(fast, read(program, ProfileName::Gsk980, true));
    }

    /// The fast reading is reached: the usual moves are read by
    /// `scan_plain` (its state untouched by `scan_general` below), and a
    /// block it does not read is not.
    #[test]
    fn plain_scan_reads_the_usual_moves() {
        let machine = Machine::new(ProfileName::Gsk980);
        let mut state = LineReader::new(&machine).state;
        let blocks: Vec<_> =
            crate::lex::lex("G00 X80 Z10\nG01 X21.001 Z-3.25 F0.15\nU-2\n(c)\nM03 S500\nG32 W-5 F1")
                .unwrap_or_default();
        let read: Vec<bool> = blocks.iter().map(|b| state.scan_plain(b).is_some()).collect();
        assert_eq!(read, [true, true, true, true, false, false]);
        // X80 (IS-B, 0.001 mm): 80 000; U-2 from X21.001: 19 001.
        assert_eq!((state.x, state.z), (Some(19_001), Some(-3_250)));
    }
}
