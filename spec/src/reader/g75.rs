//! G75.1, the GSK 980TDi radial groove cycle: its two blocks.

#[allow(clippy::wildcard_imports)]
use super::*;
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
    block.all('G').any(|w| w.number().exact(1) == Some(751))
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
        let d = w.number().decimal().ok_or_else(out)?;
        if d.is_sign_negative() && !d.is_zero() {
            return Err(out());
        }
        // The range table gives angles to 0.001 degree at IS-B and 0.0001
        // degree at IS-C.
        let decimals: u32 = match self.units.system {
            cycleref::IncrementSystem::IsB => 3,
            cycleref::IncrementSystem::IsC => 4,
        };
        let t = d.checked_mul(Decimal::from(10_000)).ok_or_else(out)?;
        if d.normalize().scale() > decimals || !t.fract().is_zero() {
            return Err(err(
                block,
                Some(w),
                ErrorKind::NotInIncrements {
                    increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
                },
            ));
        }
        let t = u32::try_from(t.trunc()).map_err(|_| out())?;
        if t > 4 * RIGHT_ANGLE {
            return Err(out());
        }
        Ok(t)
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
