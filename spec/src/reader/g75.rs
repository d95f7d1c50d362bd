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

impl State<'_> {
    /// An angle word of G75.1 (A, B, L) in degrees, to 0.0001 degree; bare
    /// values are degrees ("A45 B30" in the seed's example). Range tables
    /// are checked by [`G75Cycle::validate`]; this refuses only what cannot
    /// be an angle at all.
    pub(super) fn g75_angle(&self, block: &Block<'_>, w: &Word<'_>) -> Result<u32, ProgramError> {
        let out = || {
            err(
                block,
                Some(w),
                ErrorKind::OutOfRange { range: "0..90 degrees (A, B: 0 < a <= 90; L: 0 <= L < 90)".into() },
            )
        };
        // The range table gives angles to 0.001 degree at IS-B and 0.0001
        // degree at IS-C.
        let decimals: u32 = match self.units.system {
            cycleref::IncrementSystem::IsB => 3,
            cycleref::IncrementSystem::IsC => 4,
        };
        match angle_units(&w.number(), decimals) {
            Ok(t) => Ok(t),
            Err(AngleFault::OutOfRange) => Err(out()),
            Err(AngleFault::NotInIncrements) => Err(err(
                block,
                Some(w),
                ErrorKind::NotInIncrements {
                    increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
                },
            )),
        }
    }

    /// A required length word of G75.1 block 1.
    pub(super) fn g75_required<'b, 'a>(
        block: &'b Block<'a>,
        letter: char,
        what: &'static str,
    ) -> Result<&'b Word<'a>, ProgramError> {
        block.get(letter)?.ok_or_else(|| {
            err(
                block,
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
        let second = ['R', 'V', 'U', 'W', 'I', 'J', 'E'].iter().any(|&c| block.has(c));
        let first = ['H', 'Q', 'X', 'Z', 'L'].iter().any(|&c| block.has(c));
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
        // Note 3: "凹槽起点（X，Z）忽略时，默认当前刀具位置为凹槽起点".
        let x = match block.get('X')? {
            Some(w) => self.length(block, w)?,
            None => x0,
        };
        let z = match block.get('Z')? {
            Some(w) => self.length(block, w)?,
            None => z0,
        };
        let p = Self::g75_required(block, 'P', "P(Δi) (radial peck)")?;
        let q = Self::g75_required(block, 'Q', "Q(Δk) (axial step)")?;
        let h = Self::g75_required(block, 'H', "H(h) (groove depth)")?;
        let d = Self::g75_required(block, 'D', "D(d) (bottom width)")?;
        // P and Q follow state parameter 182.7 like G76's (seed 001:
        // "可由状态参数 NO182.7 选择").
        let peck = self.pq_length(block, p)?;
        let step = self.pq_length(block, q)?;
        let depth = self.length(block, h)?;
        let width = self.length(block, d)?;
        let angle = |letter: char, default: u32| -> Result<u32, ProgramError> {
            match block.get(letter)? {
                Some(w) => self.g75_angle(block, w),
                None => Ok(default),
            }
        };
        Ok(G75Block1 {
            line: block.line,
            from: Point::new(x0, z0),
            start: Point::new(x, z),
            peck,
            step,
            depth,
            width,
            flank_a: angle('A', RIGHT_ANGLE)?,
            flank_b: angle('B', RIGHT_ANGLE)?,
            slope: angle('L', 0)?,
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
        let opt = |letter: char| -> Result<Option<i64>, ProgramError> {
            match block.get(letter)? {
                Some(w) => self.length(&block, w).map(Some),
                None => Ok(None),
            }
        };
        let retract = opt('R')?.unwrap_or(0);
        let layer = opt('V')?;
        // Reading R-G75ALLOW: U and W are "无符号" with a signed range;
        // under `magnitude` a negative one is its magnitude (as I below),
        // else the cycle's range check refuses it.
        let magnitude = self.machine.readings.g75_allowance == G75Allowance::Magnitude;
        let allowance = |v: i64| if magnitude { v.abs() } else { v };
        let allowance_x = opt('U')?.map_or(0, allowance);
        let allowance_z = opt('W')?.map_or(0, allowance);
        // "输入负值时当成正值处理": a negative I is its magnitude.
        let tool_width = opt('I')?.map(i64::abs);
        let path = match block.get('J')? {
            None => PathType::Rough,
            Some(w) => match Self::count(&block, w, 0, 2)? {
                0 => PathType::Rough,
                1 => PathType::RoughAndFinish,
                _ => PathType::Finish,
            },
        };
        let kinds = self.g75_corner_kinds(&block)?;
        let mut corners = [Corner::SHARP; 4];
        for (i, letter) in ['A', 'B', 'D', 'E'].into_iter().enumerate() {
            corners[i] = Corner { size: opt(letter)?.unwrap_or(0), kind: kinds[i] };
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
    pub(super) fn g75_corner_kinds(&self, block: &Block<'_>) -> Result<[CornerKind; 4], ProgramError> {
        let mut kinds = [CornerKind::Chamfer; 4];
        let Some(p) = block.get('P')? else {
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
    use super::*;

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
