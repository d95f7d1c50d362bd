//! The words of a block as numbers: lengths in increments (with the
//! profile's rules for bare values and the range tables), counts, leads,
//! the G32 Q word.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::lex::{digits_value, POW10};

/// A length word in least increments of `units`, under `machine`'s
/// decimal-point rule (reading R-POINT): with a decimal point, or without
/// one on a GSK profile, the value is in mm (inch) and must be a whole
/// number of increments; without one on FANUC (unless calculator-type
/// input), it is the number of increments. The one home of the rule, used
/// by the program reader and by trace readers.
///
/// # Errors
///
/// A value finer than the increment or beyond the range tables.
#[inline]
pub fn length_word(
    machine: &Machine,
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
) -> Result<i64, ProgramError> {
    let bare = machine.profile.bare_length_is_increments && !machine.calculator_input;
    to_increments(units, block, w, bare)
}

/// The program's rule for a block's axis words, shared with the trace
/// readers: X with U, or Z with W, in one block is an error naming the
/// incremental word (absolute and incremental words for the same axis).
///
/// # Errors
///
/// Both words of one axis, or an axis word repeated.
pub fn check_axis_words(block: &Block<'_>) -> Result<(), ProgramError> {
    State::axis_words(block).map(|_| ())
}

pub(super) fn increment_text(units: Units) -> String {
    let unit = match units.unit {
        InputUnit::Metric => "mm",
        InputUnit::Inch => "inch",
    };
    let mut s = String::from("0.");
    for _ in 1..units.decimals() {
        s.push('0');
    }
    s.push('1');
    format!("{s} {unit}")
}

pub(super) fn range_err(units: Units, signed: bool) -> ErrorKind {
    let mut max = String::new();
    let _ = cycleref::units::write_fixed(&mut max, i128::from(MAX_LENGTH), units.decimals());
    ErrorKind::OutOfRange { range: if signed { format!("-{max}..{max}") } else { format!("0..{max}") } }
}

/// The bits ([`letter_bit`]) of the upper-case letters of `letters`.
#[inline(always)]
pub(super) fn letter_mask(letters: &str) -> u32 {
    // By bytes, not chars (issue 33: no UTF-8 decoding a letter): no byte
    // of a character outside ASCII is an upper-case ASCII letter, and such
    // a character has no bit either.
    letters.bytes().fold(0, |m, b| m | letter_bit(char::from(b)))
}

/// A length word in increments. `bare_increments` says what a value
/// without a decimal point means.
#[inline(always)]
pub(super) fn to_increments(
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
    bare_increments: bool,
) -> Result<i64, ProgramError> {
    match increments_short(units, w, bare_increments) {
        Some(v) => Ok(v),
        None => increments_usual(units, block, w, bare_increments),
    }
}

/// [`to_increments`] of the usual word, inlined where a block's axes are
/// read: a word the lexer kept the offsets of, whose value is read in
/// increments (a decimal point, or a profile whose bare values are
/// lengths), with no more decimals than the increment, at most 18
/// digits once scaled, within range; or a bare whole number of at most 18
/// digits where bare values are increments, within range (its digits, as
/// [`increments_slow`] reads it). `None` for any other (which
/// [`increments_usual`] reads); where this gives a value, that gives the
/// same ([`crate::lex::Number::scaled`]'s digits times 10^(decimals − their
/// decimals); issue 33: a call and a `Result` through memory per axis
/// word were a tenth of a reading).
#[inline(always)]
fn increments_short(units: Units, w: &Word<'_>, bare_increments: bool) -> Option<i64> {
    let (negative, int, frac) = w.parts()?;
    let Some(frac) = frac else {
        // A bare whole number: in increments as it is where bare values
        // are increments (`increments_slow`'s `integer`), else scaled
        // below. At most 18 digits: no overflow (issue 33: G76's P(k),
        // Q(Δd) and Q(Δdmin) went the long way).
        if bare_increments {
            if int.len() > 18 {
                return None;
            }
            let v = digits_value(int, &[]);
            return (v <= MAX_LENGTH).then_some(if negative { -v } else { v });
        }
        return increments_scaled(units, negative, int, &[]);
    };
    increments_scaled(units, negative, int, frac)
}

/// [`increments_short`] of the digits `int` `.` `frac` scaled to the
/// increment.
#[inline(always)]
fn increments_scaled(units: Units, negative: bool, int: &[u8], frac: &[u8]) -> Option<i64> {
    let d = units.decimals() as usize;
    if int.len() + d > 18 || frac.len() > d {
        return None;
    }
    // At most 18 digits once scaled: no overflow. One product, not a
    // loop of them (issue 33).
    let v = digits_value(int, frac) * POW10[d - frac.len()];
    if v > MAX_LENGTH {
        return None;
    }
    Some(if negative { -v } else { v })
}

/// [`to_increments`] of a word [`increments_short`] does not read.
#[inline(never)]
fn increments_usual(
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
    bare_increments: bool,
) -> Result<i64, ProgramError> {
    // A value in increments within range.
    if !bare_increments || w.has_point() {
        if let Some(Some(v)) = w.scaled(units.decimals()) {
            if v.unsigned_abs() <= MAX_LENGTH.unsigned_abs() {
                return Ok(v);
            }
        }
    }
    increments_slow(units, block, w, bare_increments)
}

/// [`to_increments`] of every word, errors included.
#[inline(never)]
pub(super) fn increments_slow(
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
    bare_increments: bool,
) -> Result<i64, ProgramError> {
    let n = &w.number();
    let not_in_increments = || NotInIncrements { increment: increment_text(units) };
    // A value too large for any range table gets the range message, even
    // where it is too large for the arithmetic too; a value finer than the
    // increment gets the increment's.
    let v = if !n.has_point() && bare_increments {
        n.integer().ok_or_else(|| range_err(units, true))
    } else if let Some(v) = n.scaled(units.decimals()) {
        v.ok_or_else(not_in_increments)
    } else {
        match n.decimal() {
            // checked: a 28-digit value times 10^5 overflows a Decimal.
            Some(d) => match d.checked_mul(Decimal::from(units.per_unit())) {
                Some(scaled) if !scaled.fract().is_zero() => Err(not_in_increments()),
                Some(scaled) => i64::try_from(scaled.trunc()).map_err(|_| range_err(units, true)),
                None => Err(range_err(units, true)),
            },
            None => {
                let frac = n.frac_digits().unwrap_or_default().trim_end_matches('0');
                if frac.len() > units.decimals() as usize {
                    Err(not_in_increments())
                } else {
                    Err(range_err(units, true))
                }
            }
        }
    };
    let v = v.map_err(|kind| err(block, Some(w), kind))?;
    if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
        return Err(err(block, Some(w), range_err(units, true)));
    }
    Ok(v)
}

impl State<'_> {
    pub(super) fn to_increments(
        &self,
        block: &Block<'_>,
        w: &Word<'_>,
        bare_increments: bool,
    ) -> Result<i64, ProgramError> {
        to_increments(self.units, block, w, bare_increments)
    }

    pub(super) fn range_err(&self, signed: bool) -> ErrorKind {
        range_err(self.units, signed)
    }

    /// A length word (reading R-POINT: FANUC bare values are increments).
    #[inline(always)]
    pub(super) fn length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        length_word(self.machine, self.units, block, w)
    }

    #[inline(always)]
    pub(super) fn unsigned_length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        let v = self.length(block, w)?;
        if v < 0 {
            return Err(err(block, Some(w), self.range_err(false)));
        }
        Ok(v)
    }

    /// P(k), Q(Δd), Q(Δdmin): unit by the profile's state parameter.
    #[inline(always)]
    pub(super) fn pq_length(&self, block: &Block<'_>, w: &Word<'_>) -> Result<i64, ProgramError> {
        // The state parameter's unit, read when the reading started.
        let v = match self.pq_unit {
            PqUnit::IncrementsNoPoint => {
                // The word's own readings, not its number made (issue 33).
                if w.has_point() {
                    return Err(err(
                        block,
                        Some(w),
                        ErrorKind::DecimalPointNotAllowed {
                            rule: "P(k), Q(Δd) and Q(Δdmin) of G76 are given in least increments",
                        },
                    ));
                }
                self.to_increments(block, w, true)?
            }
            PqUnit::Increments => {
                let v = w.integer().ok_or_else(|| {
                    err(
                        block,
                        Some(w),
                        ErrorKind::NotInIncrements {
                            increment: "the state parameter selects least increments for P and Q".into(),
                        },
                    )
                })?;
                if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
                    return Err(err(block, Some(w), self.range_err(false)));
                }
                v
            }
            PqUnit::Length => self.to_increments(block, w, false)?,
        };
        if v < 0 {
            return Err(err(block, Some(w), self.range_err(false)));
        }
        Ok(v)
    }

    pub(super) fn count(block: &Block<'_>, w: &Word<'_>, lo: i64, hi: i64) -> Result<u32, ProgramError> {
        match w.number().integer() {
            Some(v) if (lo..=hi).contains(&v) && !w.number().has_point() => {
                Ok(u32::try_from(v).unwrap_or(u32::MAX))
            }
            _ => {
                Err(err(block, Some(w), ErrorKind::OutOfRange { range: format!("whole number {lo}..{hi}") }))
            }
        }
    }

    /// The lead of an F or I word `w` (its range table, at most
    /// [`MAX_LEAD_SCALE`] decimals).
    pub(super) fn lead(&self, block: &Block<'_>, w: &Word<'_>) -> Result<Lead, ProgramError> {
        match self.lead_short(w) {
            Some(lead) => Ok(lead),
            None => self.lead_general(block, w),
        }
    }

    /// The range table of a lead word in the units in force: its bounds in
    /// units of 10^-[`MAX_LEAD_SCALE`] (6 decimals), and its text.
    fn lead_range(&self, word: LeadWord) -> (i128, i128, &'static str) {
        // Range tables of seed 000: F 0.0001..9999 mm / 0.00001..9.99 inch;
        // I 0.0001..254 (metric) / 0.0001..100 (inch).
        match (word, self.units.unit) {
            // K is LinuxCNC's and never read here (`word` is F or I).
            (LeadWord::F | LeadWord::K, InputUnit::Metric) => (100, 9_999_000_000, "F 0.0001..9999 mm"),
            (LeadWord::F | LeadWord::K, InputUnit::Inch) => (10, 9_990_000, "F 0.00001..9.99 inch"),
            (LeadWord::I, InputUnit::Metric) => (100, 254_000_000, "I 0.0001..254 threads per inch"),
            (LeadWord::I, InputUnit::Inch) => (100, 100_000_000, "I 0.0001..100 threads per inch"),
        }
    }

    /// [`State::lead`] of the usual lead, in one reading of its digits: a
    /// word the lexer kept the offsets of, not negative, at most 12 digits
    /// before the point and [`MAX_LEAD_SCALE`] after it (trailing zeros
    /// dropped), within its range table. `None` for any other, which
    /// [`State::lead_general`] reads (and whose errors it makes); where
    /// this gives a lead, that gives the same (the value and mantissa of
    /// the same digits; issue 33: an F word's digits were read three
    /// times).
    #[inline(always)]
    pub(super) fn lead_short(&self, w: &Word<'_>) -> Option<Lead> {
        /// 10^(MAX_LEAD_SCALE - scale), by scale.
        const TO_MICRO: [u64; MAX_LEAD_SCALE as usize + 1] = [1_000_000, 100_000, 10_000, 1_000, 100, 10, 1];
        let (negative, int, frac) = w.parts()?;
        let mut frac = frac.unwrap_or_default();
        while let [rest @ .., b'0'] = frac {
            frac = rest;
        }
        if negative || frac.len() > MAX_LEAD_SCALE as usize || int.len() > 12 {
            return None;
        }
        // At most 18 digits: no overflow, in the mantissa or the value.
        let mantissa = digits_value(int, frac).unsigned_abs();
        let scale = frac.len();
        let word = if w.letter == 'F' { LeadWord::F } else { LeadWord::I };
        let value = i128::from(mantissa * TO_MICRO[scale]);
        let (lo, hi, _) = self.lead_range(word);
        (lo..=hi).contains(&value).then_some(Lead { word, mantissa, scale: scale as u32 })
    }

    /// [`State::lead`] of any word, with every error.
    #[inline(never)]
    fn lead_general(&self, block: &Block<'_>, w: &Word<'_>) -> Result<Lead, ProgramError> {
        let n = &w.number();
        let word = if w.letter == 'F' { LeadWord::F } else { LeadWord::I };
        let mut frac = n.frac_bytes().unwrap_or_default();
        while let [rest @ .., b'0'] = frac {
            frac = rest;
        }
        let scale = u32::try_from(frac.len()).unwrap_or(u32::MAX);
        let out = |range: &str| err(block, Some(w), ErrorKind::OutOfRange { range: range.into() });
        let (lo, hi, range) = self.lead_range(word);
        // Finer than 10^-6: said so (it is no range of a table that is
        // wrong but the decimals; issue 30 found 6).
        if scale > MAX_LEAD_SCALE {
            return Err(out(&format!(
                "{range}, with at most {MAX_LEAD_SCALE} decimals (this lead has {scale})"
            )));
        }
        // Beyond an i128: outside the table.
        let value = n.exact(MAX_LEAD_SCALE).ok_or_else(|| out(range))?;
        if n.negative || value < lo || value > hi || scale > MAX_LEAD_SCALE {
            return Err(out(range));
        }
        // Within the range table and MAX_LEAD_SCALE, the digits fit a u64.
        let mantissa = n.int_bytes().iter().chain(frac).fold(0_u64, |m, b| m * 10 + u64::from(b - b'0'));
        Ok(Lead { word, mantissa, scale })
    }
}

/// G32's Q as a start angle, in the profile's unit (reading R-G32Q): the one
/// home of the rule, used by the program reader and by trace readers.
///
/// # Errors
///
/// A value outside 0..360°, finer than the unit, or a decimal point where
/// the profile forbids one.
pub fn q_word(
    machine: &Machine,
    units: Units,
    block: &Block<'_>,
    w: &Word<'_>,
) -> Result<StartAngle, ProgramError> {
    let bit = machine.profile.params.pq_unit.map_or(0, |p| machine.int_param(p));
    let out = |range: &str| err(block, Some(w), ErrorKind::OutOfRange { range: range.into() });
    if w.number().negative {
        return Err(out("0..360 degrees"));
    }
    match machine.profile.q_unit(bit) {
        QUnit::Millidegrees { no_point } => {
            if no_point && w.number().has_point() {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::DecimalPointNotAllowed { rule: "Q of G32 is given in 0.001 degree" },
                ));
            }
            match w.number().integer() {
                Some(v) if (0..=360_000).contains(&v) => {
                    Ok(StartAngle::from_millidegrees(u64::try_from(v).unwrap_or(0)))
                }
                _ => Err(out("0..360000 thousandths of a degree, whole")),
            }
        }
        QUnit::Degrees { wrap } => {
            let d = w.number().decimal().ok_or_else(|| out("0..360 degrees"))?;
            let decimals = match units.system {
                cycleref::IncrementSystem::IsB => 3,
                cycleref::IncrementSystem::IsC => 4,
            };
            let ten_thousandths =
                d.checked_mul(Decimal::from(10_000)).ok_or_else(|| out("0..360 degrees"))?;
            if d.scale() > decimals || !ten_thousandths.fract().is_zero() {
                return Err(err(
                    block,
                    Some(w),
                    ErrorKind::NotInIncrements {
                        increment: format!("0.{}1 degree", "0".repeat(decimals as usize - 1)),
                    },
                ));
            }
            let mut t: u64 = u64::try_from(ten_thousandths.trunc()).map_err(|_| out("0..360 degrees"))?;
            if t > 3_600_000 {
                if wrap {
                    t %= 3_600_000;
                } else {
                    return Err(out("0..360 degrees"));
                }
            }
            // t / 10 thousandths of a degree, in lowest terms.
            Ok(if t % 10 == 0 {
                StartAngle::from_millidegrees(t / 10)
            } else {
                StartAngle { num: u32::try_from(t).unwrap_or(u32::MAX), den: 10 }
            })
        }
    }
}

/// G78's depth mode from its digit (980TDi P(m), 988TA D, parameters No.061
/// and 5145): 0 equal steps (等距离进刀), 1 decreasing (递减式进刀).
pub(super) fn depth_mode(v: u32) -> DepthMode {
    if v == 0 {
        DepthMode::Equal
    } else {
        DepthMode::Decreasing
    }
}

#[cfg(test)]
mod tests {
    //! The inlined readings of the usual lead and length word held equal
    //! to the general ones wherever they give a value.

    use cycleref::{IncrementSystem, InputUnit, Units};
    use proptest::prelude::*;

    use super::{increments_short, increments_usual};
    use crate::lex::Lexer;
    use crate::reader::LineReader;
    use crate::{Machine, ProfileName};

    /// Words as a program may write them: every sign, leading and trailing
    /// zeros, no digits before or after the point, long numbers, spaces
    /// between the letter and the number (which the lexer keeps no
    /// offsets for past a byte).
    fn word() -> impl Strategy<Value = String> {
        prop_oneof![
            "[FIXZUW] {0,2}[-+]?[0-9]{0,8}(\\.[0-9]{0,9})?",
            "[FIXZ][-+]?0{0,20}[0-9]{0,22}(\\.[0-9]{0,12}0{0,20})?",
            "[FX] {250,260}[0-9]{1,3}\\.[0-9]",
            "[FX]0{255,258}\\.5",
        ]
    }

    fn units() -> impl Strategy<Value = Units> {
        (any::<bool>(), any::<bool>()).prop_map(|(c, inch)| Units {
            system: if c { IncrementSystem::IsC } else { IncrementSystem::IsB },
            unit: if inch { InputUnit::Inch } else { InputUnit::Metric },
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        #[test]
        fn short_readings_are_the_general_ones(text in word(), units in units(), bare in any::<bool>()) {
            let Some(Ok(block)) = Lexer::new(text.as_bytes()).next() else { return Ok(()) };
            let machine = Machine::new(ProfileName::Gsk988);
            let mut state = LineReader::new(&machine).state;
            state.units = units;
            for w in block.words.iter() {
                if let Some(lead) = state.lead_short(w) {
                    prop_assert_eq!(Ok(lead), state.lead_general(&block, w), "{}", text);
                }
                if let Some(v) = increments_short(units, w, bare) {
                    prop_assert_eq!(Ok(v), increments_usual(units, &block, w, bare), "{}", text);
                }
            }
        }
    }

    #[test]
    fn short_readings_read_the_usual_words() {
        let machine = Machine::new(ProfileName::Gsk988);
        let state = LineReader::new(&machine).state;
        let block = Lexer::new(b"X-60.64 Z.5 F6 F0.150")
            .next()
            .and_then(Result::ok)
            .unwrap_or_else(|| unreachable!());
        let w = |i: usize| &block.words[i];
        // IS-B metric: 0.001 mm.
        assert_eq!(increments_short(Units::IS_B_METRIC, w(0), false), Some(-60_640));
        assert_eq!(increments_short(Units::IS_B_METRIC, w(1), true), Some(500));
        // F6: 6 mm, mantissa 6, no decimals; F0.150: 0.15 mm.
        assert_eq!(state.lead_short(w(2)).map(|l| (l.mantissa, l.scale)), Some((6, 0)));
        assert_eq!(state.lead_short(w(3)).map(|l| (l.mantissa, l.scale)), Some((15, 2)));
        // Bare whole numbers where bare values are increments: G76's
        // P3680 is 3 680 increments (3.68 mm at IS-B), Q-0150 is -150;
        // where they are lengths, P3680 is 3 680 mm.
        let block = Lexer::new(b"P3680 Q-0150").next().and_then(Result::ok).unwrap_or_else(|| unreachable!());
        assert_eq!(increments_short(Units::IS_B_METRIC, &block.words[0], true), Some(3680));
        assert_eq!(increments_short(Units::IS_B_METRIC, &block.words[1], true), Some(-150));
        assert_eq!(increments_short(Units::IS_B_METRIC, &block.words[0], false), Some(3_680_000));
    }
}
