//! G75.1, the GSK 980TDi radial groove cycle: its two blocks.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::lex::Number;
use crate::readings::{G75Allowance, G75PDigits};

/// The values of a G75.1 block 1, kept until block 2 arrives.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct G75Block1 {
    /// Its line.
    pub(super) line: usize,
    pub(super) from: Point,
    pub(super) start: Point,
    pub(super) peck: i64,
    pub(super) step: i64,
    pub(super) depth: i64,
    pub(super) width: i64,
    pub(super) flank_a: u32,
    pub(super) flank_b: u32,
    pub(super) slope: u32,
}

/// True when `block` programs G75.1.
pub(super) fn is_g75_1(block: &Block<'_>) -> bool {
    block.all('G').any(|w| is_751(&w.number()))
}

/// True when the number of a G word is 75.1 (`n.exact(1) == Some(751)`:
/// `75.1`, `075.10`, …), the usual spelling `75.1` decided by its bytes
/// (issue 33; the test `g75_1_by_bytes_and_by_value`).
pub(super) fn is_751(n: &Number<'_>) -> bool {
    (!n.negative && n.int_bytes() == b"75" && n.frac_bytes() == Some(b"1")) || n.exact(1) == Some(751)
}

pub(super) fn lone_g75(line: usize) -> ProgramError {
    ProgramError {
        line,
        word: None,
        kind: ErrorKind::Missing {
            what: "the second G75.1 block (R V U W I J A B D E P)",
            rule: "G75.1 always takes two blocks, note 3: 必须有两行 G75.1 代码",
        },
    }
}

/// The words of a G75.1 block by letter: [`Block::get`] in one look-up
/// each (issue 33: block 1's nine words looked up one letter at a time,
/// a search of the words each, were a third of its reading). The same
/// answers as [`Block::get`]: the word with the letter, `None`, or, for a
/// letter more than once, [`Block::get`]'s error.
struct Letters<'b, 'a> {
    block: &'b Block<'a>,
    /// The word of each letter `A`..=`Z`.
    words: [Option<&'b Word<'a>>; 26],
    /// The letters there more than once ([`Block::get`] answers them).
    repeated: u32,
}

impl<'b, 'a> Letters<'b, 'a> {
    #[inline(always)]
    fn of(block: &'b Block<'a>) -> Letters<'b, 'a> {
        let mut words = [None; 26];
        for w in &block.words {
            // An upper-case letter (the others have no bit, as in
            // `Block::get`: they are never found).
            if let Some(slot) = (w.letter as usize).checked_sub('A' as usize).and_then(|i| words.get_mut(i)) {
                if slot.is_none() && letter_bit(w.letter) != 0 {
                    *slot = Some(w);
                }
            }
        }
        Letters { block, words, repeated: block.words.letter_masks().1 }
    }

    /// [`Block::get`] of `letter` (an upper-case letter).
    #[inline(always)]
    fn get(&self, letter: char) -> Result<Option<&'b Word<'a>>, ProgramError> {
        if self.repeated & letter_bit(letter) != 0 {
            return self.block.get(letter);
        }
        Ok(self.words.get((letter as usize).wrapping_sub('A' as usize)).copied().flatten())
    }
}

impl State<'_> {
    /// An angle word of G75.1 (A, B, L) in degrees, to 0.0001 degree; bare
    /// values are degrees ("A45 B30" in the seed's example). Range tables
    /// are checked by [`G75Cycle::validate`]; this refuses only what cannot
    /// be an angle at all.
    #[inline(always)]
    pub(super) fn g75_angle(&self, block: &Block<'_>, w: &Word<'_>) -> Result<u32, ProgramError> {
        // The range table gives angles to 0.001 degree at IS-B and 0.0001
        // degree at IS-C.
        let decimals: u32 = match self.units.system {
            cycleref::IncrementSystem::IsB => 3,
            cycleref::IncrementSystem::IsC => 4,
        };
        angle_units(&w.number(), decimals).map_err(|fault| angle_err(block, w, fault, decimals))
    }

    /// The angle word `letter` of `words` ([`State::g75_angle`]), or
    /// `default` when it is not there (inlined: issue 33).
    #[inline(always)]
    fn g75_angle_or(&self, words: &Letters<'_, '_>, letter: char, default: u32) -> Result<u32, ProgramError> {
        match words.get(letter)? {
            Some(w) => self.g75_angle(words.block, w),
            None => Ok(default),
        }
    }

    /// The length word `letter` of `words`, if there (inlined: issue 33).
    #[inline(always)]
    fn g75_length(&self, words: &Letters<'_, '_>, letter: char) -> Result<Option<i64>, ProgramError> {
        match words.get(letter)? {
            Some(w) => self.length(words.block, w).map(Some),
            None => Ok(None),
        }
    }

    /// A required length word of G75.1 block 1.
    #[inline(always)]
    fn g75_required<'b, 'a>(
        words: &Letters<'b, 'a>,
        letter: char,
        what: &'static str,
    ) -> Result<&'b Word<'a>, ProgramError> {
        words.get(letter)?.ok_or_else(|| {
            err(
                words.block,
                None,
                ErrorKind::Missing {
                    what,
                    rule: "G75.1 block 1 needs H, D, P and Q; only they cannot be omitted (note 3)",
                },
            )
        })
    }

    /// G75.1 block 1: `X Z P(Δi) Q(Δk) H(h) D(d) A(∠a) B(∠b) L(∠p)` (seed 001).
    pub(super) fn g75_block1<'a>(&self, block: &Block<'a>) -> Result<G75Block1, ProgramError> {
        // A block 2 where a block 1 is due (R-G75PAIR): it has block-2 words
        // and none of block 1's required ones.
        let present = block.words.letter_masks().0;
        let second = present & letter_mask("RVUWIJE") != 0;
        let first = present & letter_mask("HQXZL") != 0;
        if second && !first {
            return Err(err(
                block,
                None,
                ErrorKind::Missing {
                    what: "the first G75.1 block (X Z P Q H D A B L) before this one",
                    rule: "G75.1 always takes two blocks, note 3: 必须有两行 G75.1 代码",
                },
            ));
        }
        self.check_addresses(block, "G75.1 block 1", "GXZPQHDABLMST", "")?;
        let (Some(x0), Some(z0)) = (self.x, self.z) else {
            return Err(err(block, None, ErrorKind::PositionUnknown));
        };
        let words = Letters::of(block);
        // Note 3: "凹槽起点（X，Z）忽略时，默认当前刀具位置为凹槽起点".
        let x = match words.get('X')? {
            Some(w) => self.length(block, w)?,
            None => x0,
        };
        let z = match words.get('Z')? {
            Some(w) => self.length(block, w)?,
            None => z0,
        };
        let p = Self::g75_required(&words, 'P', "P(Δi) (radial peck)")?;
        let q = Self::g75_required(&words, 'Q', "Q(Δk) (axial step)")?;
        let h = Self::g75_required(&words, 'H', "H(h) (groove depth)")?;
        let d = Self::g75_required(&words, 'D', "D(d) (bottom width)")?;
        // P and Q follow state parameter 182.7 like G76's (seed 001:
        // "可由状态参数 NO182.7 选择").
        let peck = self.pq_length(block, p)?;
        let step = self.pq_length(block, q)?;
        let depth = self.length(block, h)?;
        let width = self.length(block, d)?;
        Ok(G75Block1 {
            line: block.line,
            from: Point::new(x0, z0),
            start: Point::new(x, z),
            peck,
            step,
            depth,
            width,
            flank_a: self.g75_angle_or(&words, 'A', RIGHT_ANGLE)?,
            flank_b: self.g75_angle_or(&words, 'B', RIGHT_ANGLE)?,
            slope: self.g75_angle_or(&words, 'L', 0)?,
        })
    }

    /// G75.1 block 2: `R(e) V(Δv) U(Δu) W(Δw) I(r) J A(r1) B(r2) D(r3) E(r4)
    /// P(a)(b)(d)(e)` (seed 001).
    pub(super) fn g75_block2<'a>(
        &mut self,
        first: G75Block1,
        block: Block<'a>,
    ) -> Result<G75Call<'a>, ProgramError> {
        self.check_addresses(&block, "G75.1 block 2", "GRVUWIJABDEPMST", "")?;
        let words = Letters::of(&block);
        let retract = self.g75_length(&words, 'R')?.unwrap_or(0);
        let layer = self.g75_length(&words, 'V')?;
        // Reading R-G75ALLOW: U and W are "无符号" with a signed range;
        // under `magnitude` a negative one is its magnitude (as I below),
        // else the cycle's range check refuses it.
        let magnitude = self.machine.readings.g75_allowance == G75Allowance::Magnitude;
        let allowance = |v: i64| if magnitude { v.abs() } else { v };
        let allowance_x = self.g75_length(&words, 'U')?.map_or(0, allowance);
        let allowance_z = self.g75_length(&words, 'W')?.map_or(0, allowance);
        // "输入负值时当成正值处理": a negative I is its magnitude.
        let tool_width = self.g75_length(&words, 'I')?.map(i64::abs);
        let path = match words.get('J')? {
            None => PathType::Rough,
            Some(w) => match Self::count(&block, w, 0, 2)? {
                0 => PathType::Rough,
                1 => PathType::RoughAndFinish,
                _ => PathType::Finish,
            },
        };
        let kinds = self.g75_corner_kinds(&block, words.get('P')?)?;
        let mut corners = [Corner::SHARP; 4];
        for (i, letter) in ['A', 'B', 'D', 'E'].into_iter().enumerate() {
            corners[i] = Corner { size: self.g75_length(&words, letter)?.unwrap_or(0), kind: kinds[i] };
        }
        let cycle = G75Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            from: first.from,
            start: first.start,
            peck: first.peck,
            step: first.step,
            depth: first.depth,
            width: first.width,
            flank_a: first.flank_a,
            flank_b: first.flank_b,
            slope: first.slope,
            retract,
            layer,
            allowance_x,
            allowance_z,
            tool_width,
            path,
            corners,
            readings: self.machine.readings.for_g75(),
        };
        cycle.validate().map_err(|e| cycle_err(&block, Some(first.line), e))?;
        let restore = self.restore();
        // Step 10: the tool ends where it was before the cycle.
        self.moved = true;
        Ok(G75Call { block, params_line: first.line, cycle, restore })
    }

    /// Reading R-G75P: the digits of P(a)(b)(d)(e) are read from the right
    /// (e is the last digit), so leading zeros may be dropped (P11 rounds
    /// D and E), or under `left-aligned` from the left ("P 的第一位" the
    /// first written: P11 rounds A and B); each digit is 0 (chamfer) or 1
    /// (round); omitted: chamfers.
    /// `p`: the block's P word.
    pub(super) fn g75_corner_kinds(
        &self,
        block: &Block<'_>,
        p: Option<&Word<'_>>,
    ) -> Result<[CornerKind; 4], ProgramError> {
        let mut kinds = [CornerKind::Chamfer; 4];
        let Some(p) = p else {
            return Ok(kinds);
        };
        let bad = || {
            err(
                block,
                Some(p),
                ErrorKind::OutOfRange { range: "P(a)(b)(d)(e): up to four digits, each 0 or 1".into() },
            )
        };
        if p.number().has_point() || p.number().negative {
            return Err(bad());
        }
        let digits = p.number().int_digits().as_bytes();
        if digits.len() > 4 || digits.iter().any(|&c| c != b'0' && c != b'1') {
            return Err(bad());
        }
        let kind = |c: u8| if c == b'1' { CornerKind::Round } else { CornerKind::Chamfer };
        if self.machine.readings.g75_p == G75PDigits::LeftAligned {
            for (i, &c) in digits.iter().enumerate() {
                kinds[i] = kind(c);
            }
        } else {
            for (i, &c) in digits.iter().rev().enumerate() {
                kinds[3 - i] = kind(c);
            }
        }
        Ok(kinds)
    }
}

/// The error of the angle word `w` refused for `fault` ([`State::g75_angle`]).
#[cold]
#[inline(never)]
fn angle_err(block: &Block<'_>, w: &Word<'_>, fault: AngleFault, decimals: u32) -> ProgramError {
    match fault {
        AngleFault::OutOfRange => err(
            block,
            Some(w),
            ErrorKind::OutOfRange { range: "0..90 degrees (A, B: 0 < a <= 90; L: 0 <= L < 90)".into() },
        ),
        AngleFault::NotInIncrements => err(
            block,
            Some(w),
            ErrorKind::NotInIncrements {
                increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
            },
        ),
    }
}

/// Why a G75.1 angle word is refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AngleFault {
    /// Negative, or beyond 360 degrees.
    OutOfRange,
    /// Finer than 10^-`decimals` degree.
    NotInIncrements,
}

/// An angle word's value in 0.0001 degree, given to `decimals` (3 or 4)
/// decimals at most. The usual word (at most 18 digits, none finer than
/// the increment) in integers (issue 33), else by [`angle_units_decimal`]:
/// the same value and refusals (the test `angles_by_integers_and_decimals`).
fn angle_units(n: &Number<'_>, decimals: u32) -> Result<u32, AngleFault> {
    // The usual word, whole degrees in one to three digits ("A45"): v·10^4.
    let int = n.int_bytes();
    if !n.negative && n.frac_bytes().is_none() && (1..=3).contains(&int.len()) {
        let t = int.iter().fold(0, |v, &b| v * 10 + u32::from(b - b'0')) * 10_000;
        return if t <= 4 * RIGHT_ANGLE { Ok(t) } else { Err(AngleFault::OutOfRange) };
    }
    if n.int_bytes().len() + n.frac_bytes().map_or(0, <[u8]>::len) <= 18 {
        if let Some(v) = n.exact(decimals) {
            if n.negative && v != 0 {
                return Err(AngleFault::OutOfRange);
            }
            let t = v * if decimals == 3 { 10 } else { 1 };
            return match u32::try_from(t) {
                Ok(t) if t <= 4 * RIGHT_ANGLE => Ok(t),
                _ => Err(AngleFault::OutOfRange),
            };
        }
    }
    angle_units_decimal(n, decimals)
}

/// [`angle_units`] by exact decimals.
fn angle_units_decimal(n: &Number<'_>, decimals: u32) -> Result<u32, AngleFault> {
    let d = n.decimal().ok_or(AngleFault::OutOfRange)?;
    if d.is_sign_negative() && !d.is_zero() {
        return Err(AngleFault::OutOfRange);
    }
    let t = d.checked_mul(Decimal::from(10_000)).ok_or(AngleFault::OutOfRange)?;
    if d.normalize().scale() > decimals || !t.fract().is_zero() {
        return Err(AngleFault::NotInIncrements);
    }
    let t = u32::try_from(t.trunc()).map_err(|_| AngleFault::OutOfRange)?;
    if t > 4 * RIGHT_ANGLE {
        return Err(AngleFault::OutOfRange);
    }
    Ok(t)
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::reader::modal::tests::{ending, read, read_pieces};
    use crate::ProfileName;

    /// G75.1 lines, well formed or not: block 1 and block 2 words, each
    /// perhaps twice or missing, values out of range or finer than the
    /// increment, other spellings of 75.1 and other G codes, a comment
    /// between words, an M word (which the general step reads).
    fn g75_line() -> impl Strategy<Value = String> {
        let word = prop_oneof![
            4 => "[XZHDPQ]-?[0-9]{1,5}(\\.[0-9]{0,4})?",
            3 => "[ABL][0-9]{1,3}(\\.[0-9]{0,4})?",
            3 => "[RVUWIE]-?[0-9]{1,2}(\\.[0-9]{0,4})?",
            2 => "J[0-3]|P[01]{1,5}|S500|T0101|F0\\.1",
            1 => "\\(c\\)|M03|G01|G04|G75\\.1|x30|K1",
        ];
        let head = prop_oneof![
            8 => Just("G75.1"),
            1 => Just("G075.10"),
            1 => Just("g75.1"),
            1 => Just("G75"),
            1 => Just("G75.2"),
            1 => Just(""),
        ];
        (head, proptest::collection::vec(word, 0..10), prop_oneof![Just(" "), Just("")])
            .prop_map(|(h, w, sep)| format!("{h}{sep}{}", w.join(sep)))
    }

    /// The pairs of the usual programs: a position, block 1, block 2.
    fn g75_pair() -> impl Strategy<Value = Vec<String>> {
        (
            prop_oneof![Just("G00 X60 Z30"), Just("G00 X90 Z12"), Just("G50 X100 Z50"), Just("(c)")],
            prop_oneof![
                Just("G75.1 X50 Z30 P3000 Q5000 H-20 D-10 A45 B30".to_string()),
                Just("G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10".to_string()),
                Just("G75.1 X30 Z0 P2000 Q3000 H-6 D-8".to_string()),
                g75_line(),
            ],
            prop_oneof![
                Just("G75.1 R0.5 I4 J1".to_string()),
                Just("G75.1 R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111".to_string()),
                Just("G75.1 R0.5".to_string()),
                g75_line(),
            ],
        )
            .prop_map(|(a, b, c)| vec![a.to_string(), b, c])
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]

        /// G75.1 blocks read by the short step (block 1, which it leaves
        /// to `item_of`) as the general step reads them, whole and a line a piece, with every
        /// line end, comments and other blocks between block 1 and 2.
        #[test]
        fn g75_steps_are_the_general_ones(
            pairs in proptest::collection::vec(
                (g75_pair(), proptest::collection::vec(ending(), 3), prop_oneof![
                    6 => Just(""),
                    1 => Just("(between)\n"),
                    1 => Just("G01 X1\n"),
                    1 => Just("M05\n"),
                    1 => Just("\n"),
                ]),
                0..5,
            ),
            p in 0_usize..3,
        ) {
            let profile = [ProfileName::Gsk980, ProfileName::Gsk980, ProfileName::Gsk988][p];
            let mut pieces = vec!["M03 S500\n".to_string()];
            for (lines, ends, between) in &pairs {
                pieces.push(format!("{}{}", lines[0], ends[0]));
                pieces.push(format!("{}{}", lines[1], ends[1]));
                if !between.is_empty() {
                    pieces.push((*between).to_string());
                }
                pieces.push(format!("{}{}", lines[2], ends[2]));
            }
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

        /// [`Letters::get`] is [`Block::get`] for every letter, over
        /// G75.1 lines (repeated letters, lower case, comments).
        #[test]
        fn letters_are_block_get(line in g75_line()) {
            if let Ok(blocks) = crate::lex::lex(&line) {
                for block in &blocks {
                    let words = Letters::of(block);
                    for letter in 'A'..='Z' {
                        prop_assert_eq!(words.get(letter), block.get(letter), "{} {}", line, letter);
                    }
                }
            }
        }
    }

    /// `is_751` is `exact(1) == Some(751)` over the spellings of 75.1 and
    /// its neighbours.
    #[test]
    fn g75_1_by_bytes_and_by_value() {
        let texts = [
            "75.1", "075.1", "75.10", "0075.100", "75.", "75", "75.01", "751", "7.51", ".751", "75.11",
            "76.1", "75.2", "", ".", "0.1", "750.1",
        ];
        for t in texts {
            for negative in [false, true] {
                let n = Number::new(negative, t);
                assert_eq!(is_751(&n), n.exact(1) == Some(751), "{negative} {t}");
            }
        }
        // By hand: 75.1 and 075.10 are G75.1; -75.1 and 75.01 are not.
        assert!(is_751(&Number::new(false, "75.1")) && is_751(&Number::new(false, "075.10")));
        assert!(!is_751(&Number::new(true, "75.1")) && !is_751(&Number::new(false, "75.01")));
    }

    /// The integer reading of an angle word gives what the decimal one
    /// gives, over words of every shape: signs, points, leading and
    /// trailing zeros, digits finer than the increment, the 360-degree
    /// limit, 18 and 19 digits and more.
    #[test]
    fn angles_by_integers_and_decimals() {
        let mut texts: Vec<String> = [
            "",
            ".",
            "0",
            "00",
            "0.",
            ".0",
            "45",
            "45.",
            "45.0",
            "045.500",
            "30.25",
            "0.001",
            "0.0001",
            "0.00010",
            "0.00001",
            "89.9999",
            "90",
            "359.9999",
            "360",
            "360.0000",
            "360.0001",
            "360.001",
            "361",
            "4294967296",
            "429496.7296",
            "1.23456",
            "0.0005",
            "7.0000000000000000000",
            "000000000000000045.5",
            "0000000000000000045.5",
            "123456789012345678",
            "1234567890123456789",
            "99999999999999999999999999999999",
            "0.000000000000000000000000000001",
        ]
        .iter()
        .map(|s| (*s).to_string())
        .collect();
        // Every value 0 … 400 degrees in steps of 0.3217 (to 4 decimals) at
        // several widths.
        let mut v: u64 = 0;
        while v <= 4_000_000 {
            texts.push(format!("{}.{:04}", v / 10_000, v % 10_000));
            texts.push(format!("{}.{:03}", v / 10_000, (v % 10_000) / 10));
            texts.push(format!("{}", v / 10_000));
            v += 3_217;
        }
        for t in &texts {
            for negative in [false, true] {
                let n = Number::new(negative, t);
                for decimals in [3, 4] {
                    assert_eq!(
                        angle_units(&n, decimals),
                        angle_units_decimal(&n, decimals),
                        "{negative} {t} {decimals}"
                    );
                }
            }
        }
        // The cases by hand: 45.5 degrees is 455 000 units; 0.0001 degree
        // is 1 at IS-C and finer than IS-B's 0.001.
        assert_eq!(angle_units(&Number::new(false, "45.5"), 3), Ok(455_000));
        assert_eq!(angle_units(&Number::new(false, "0.0001"), 4), Ok(1));
        assert_eq!(angle_units(&Number::new(false, "0.0001"), 3), Err(AngleFault::NotInIncrements));
        assert_eq!(angle_units(&Number::new(true, "1"), 3), Err(AngleFault::OutOfRange));
        assert_eq!(angle_units(&Number::new(false, "360.0001"), 4), Err(AngleFault::OutOfRange));
    }
}
