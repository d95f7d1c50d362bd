//! Text forms of moves: NC blocks, JSON and the pass table.

use std::fmt;

use cycleref::units::write_fixed;
use cycleref::Point;
use cycleref::{Flank, IncrementSystem, LeadWord, PassKind, Role, StartAngle, Units};
use cycleref_spec::profile::QUnit;

/// `v` increments as a decimal with the increment's number of decimals.
pub fn fixed(v: i64, units: Units) -> String {
    Fixed::new(v, units).to_string()
}

/// A length in increments, displayed as a decimal with the increment's
/// number of decimals (`64.400`), without an allocation. Width and
/// alignment flags apply (`{:>12}`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fixed {
    value: i64,
    decimals: u32,
}

/// Room for any number [`encode_fixed`] writes: 20 digits, a point and a
/// sign, with decimals up to 40.
pub const FIXED_BUF: usize = 64;

/// The decimal pairs `00` to `99`, for writing two digits a step.
const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// Writes the two digits of `d < 100` before `buf[i]`; returns the new start.
fn pair_before(buf: &mut [u8; FIXED_BUF], i: usize, d: u64) -> usize {
    // d < 100 by the callers, so the index is below 200.
    #[allow(clippy::cast_possible_truncation)]
    let at = 2 * (d as usize);
    buf[i - 2..i].copy_from_slice(&PAIRS[at..at + 2]);
    i - 2
}

/// `mag / 10^decimals` as text, with a leading `-` when `negative`, written
/// at the end of `buf`; the text is returned. `decimals` is at most 40.
///
/// Two digits a step (the nc and JSON writers' hot path: every coordinate
/// of every move goes through it).
pub fn encode_fixed(buf: &mut [u8; FIXED_BUF], negative: bool, mut mag: u64, decimals: u32) -> &[u8] {
    let mut i = FIXED_BUF;
    let decimals = decimals.min(40);
    let mut left = decimals;
    while left >= 2 {
        i = pair_before(buf, i, mag % 100);
        mag /= 100;
        left -= 2;
    }
    if left == 1 {
        i -= 1;
        buf[i] = b'0' + (mag % 10) as u8;
        mag /= 10;
    }
    if decimals > 0 {
        i -= 1;
        buf[i] = b'.';
    }
    while mag >= 100 {
        i = pair_before(buf, i, mag % 100);
        mag /= 100;
    }
    if mag >= 10 {
        i = pair_before(buf, i, mag);
    } else {
        i -= 1;
        buf[i] = b'0' + mag as u8;
    }
    if negative {
        i -= 1;
        buf[i] = b'-';
    }
    &buf[i..]
}

impl Fixed {
    /// `value` increments of `units`.
    #[must_use]
    pub fn new(value: i64, units: Units) -> Fixed {
        Fixed { value, decimals: units.decimals() }
    }

    /// The text, written into `buf`.
    pub fn encode(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        encode_fixed(buf, self.value < 0, self.value.unsigned_abs(), self.decimals)
    }
}

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut buf = [0; FIXED_BUF];
        f.pad(std::str::from_utf8(self.encode(&mut buf)).map_err(|_| fmt::Error)?)
    }
}

/// A value whose text is written at the end of a [`FIXED_BUF`] buffer:
/// [`Fixed`] and [`LeadText`].
pub trait EncodeAtEnd: Copy + PartialEq {
    /// The text, written so that it ends at the end of `buf`.
    fn encode_at_end(self, buf: &mut [u8; FIXED_BUF]) -> &[u8];

    /// A hash of the value (equal values, equal hashes).
    fn hash(self) -> u64;
}

impl EncodeAtEnd for Fixed {
    fn encode_at_end(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        self.encode(buf)
    }

    fn hash(self) -> u64 {
        self.value.unsigned_abs() ^ u64::from(self.decimals)
    }
}

/// How many texts a [`RecentText`] keeps (a power of two).
const RECENT: usize = 8;

/// The texts last written for the values of one place of a line (the X of
/// a move, its lead), so that a value written again is copied, not encoded
/// again: the passes of a thread return to the same retract X, start Z and
/// end Z, and every G32 block of a cycle has the same lead. Each value has
/// one place, chosen by its hash (a direct-mapped cache: one comparison a
/// look-up); a value that finds another in its place takes it.
#[derive(Clone, Debug)]
pub struct RecentText<K> {
    keys: [Option<K>; RECENT],
    texts: [[u8; FIXED_BUF]; RECENT],
    starts: [usize; RECENT],
}

impl<K: EncodeAtEnd> RecentText<K> {
    /// Nothing written yet.
    #[must_use]
    pub fn new() -> RecentText<K> {
        RecentText { keys: [None; RECENT], texts: [[0; FIXED_BUF]; RECENT], starts: [FIXED_BUF; RECENT] }
    }

    /// The text of `key`: the one kept if it is the value in its place,
    /// else its text encoded (and kept there).
    #[inline]
    pub fn text(&mut self, key: K) -> &[u8] {
        // Fibonacci hashing: the top bits of the product spread values that
        // differ in their low digits over the places.
        #[allow(clippy::cast_possible_truncation)]
        let slot =
            (key.hash().wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - RECENT.trailing_zeros())) as usize;
        let slot = slot % RECENT;
        if self.keys[slot] != Some(key) {
            self.starts[slot] = FIXED_BUF - key.encode_at_end(&mut self.texts[slot]).len();
            self.keys[slot] = Some(key);
        }
        &self.texts[slot][self.starts[slot]..]
    }
}

impl<K: EncodeAtEnd> Default for RecentText<K> {
    fn default() -> Self {
        RecentText::new()
    }
}

/// The lead word as programmed (`F6.0`, `F1.5`, `I20.0`), displayed without
/// an allocation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LeadText(pub cycleref::Lead);

impl LeadText {
    /// The text, written into `buf`.
    pub fn encode(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        let lead = self.0;
        // Always with a decimal point: on FANUC a bare value may be read in
        // other units. Room for ".0" and the letter is kept at the end.
        let len = {
            let text = encode_fixed(buf, false, lead.mantissa, lead.scale);
            text.len()
        };
        let mut start = FIXED_BUF - len;
        if lead.scale == 0 {
            buf.copy_within(start.., start - 2);
            buf[FIXED_BUF - 2] = b'.';
            buf[FIXED_BUF - 1] = b'0';
            start -= 2;
        }
        start -= 1;
        buf[start] = match lead.word {
            LeadWord::F => b'F',
            LeadWord::I => b'I',
            LeadWord::K => b'K',
        };
        &buf[start..]
    }
}

impl EncodeAtEnd for LeadText {
    fn encode_at_end(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        self.encode(buf)
    }

    fn hash(self) -> u64 {
        self.0.mantissa ^ u64::from(self.0.scale)
    }
}

impl fmt::Display for LeadText {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut buf = [0; FIXED_BUF];
        f.pad(std::str::from_utf8(self.encode(&mut buf)).map_err(|_| fmt::Error)?)
    }
}

/// The lead word as programmed (`F6.0`, `F1.5`, `I20.0`).
pub fn lead_word(lead: cycleref::Lead) -> String {
    LeadText(lead).to_string()
}

/// The value of a Q word for `angle` in the profile's unit: whole
/// thousandths of a degree, or degrees with the increment system's
/// decimals (3 at IS-B, 4 at IS-C), rounded to nearest where the exact
/// angle has more digits (360°/7).
pub fn q_word(angle: StartAngle, u: Units, q: QUnit) -> String {
    match q {
        QUnit::Millidegrees { .. } => angle.rounded_millidegrees().to_string(),
        QUnit::Degrees { .. } => {
            let decimals: u32 = match u.system {
                IncrementSystem::IsB => 3,
                IncrementSystem::IsC => 4,
            };
            // Units of 10^-decimals degree: num / den millidegrees × 10^(decimals - 3).
            let scale = u64::from(10_u32.pow(decimals - 3));
            let den = u64::from(angle.den);
            let v = (2 * u64::from(angle.num) * scale + den) / (2 * den);
            let mut s = String::new();
            let _ = write_fixed(&mut s, i128::from(v), decimals);
            s
        }
    }
}

/// Name of a pass kind.
pub fn kind_name(k: PassKind) -> &'static str {
    match k {
        PassKind::Rough => "rough",
        PassKind::Finish => "finish",
        PassKind::Single => "single",
    }
}

/// Name of a role.
pub fn role_name(r: Role) -> &'static str {
    match r {
        Role::Approach => "approach",
        Role::LeadIn => "lead-in",
        Role::Cut => "cut",
        Role::RunOut => "run-out",
        Role::Retract => "retract",
        Role::Return => "return",
        Role::Peck(_) => "peck",
        Role::PeckRetract(_) => "peck-retract",
        Role::PlungeRetract(_) => "plunge-retract",
        Role::Step(_) => "step",
        Role::LayerChange(_) => "layer-change",
        Role::RoughContour => "rough-contour",
        Role::FinishContour => "finish-contour",
    }
}

/// The plunge a G75.1 move belongs to, if any.
pub fn plunge_of(r: Role) -> Option<cycleref::Plunge> {
    match r {
        Role::Peck(p) | Role::PeckRetract(p) | Role::PlungeRetract(p) | Role::Step(p) => Some(p),
        _ => None,
    }
}

/// An arc's I (X distance from the start to the centre, as a radius) and K
/// (Z distance), as written in the nc format: I may need one more decimal
/// than the increment when X is a diameter and the distance is odd.
pub fn arc_ik(from: Point, centre: Point, x_factor: i64, units: Units) -> (String, String) {
    let dx = centre.x - from.x;
    let i = if dx % x_factor == 0 {
        fixed(dx / x_factor, units)
    } else {
        // Half an increment: print dx * 5 with one more decimal.
        let mut s = String::new();
        let _ = write_fixed(&mut s, i128::from(dx) * 5, units.decimals() + 1);
        s
    };
    (i, fixed(centre.z - from.z, units))
}

/// Name of a flank position.
pub fn flank_name(f: Flank) -> &'static str {
    match f {
        Flank::Right => "right",
        Flank::Centre => "centre",
        Flank::Left => "left",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cycleref::{IncrementSystem, InputUnit, Lead};

    #[test]
    fn fixed_and_lead_text_match_the_written_forms() {
        let mm = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };
        let inch_c = Units { system: IncrementSystem::IsC, unit: InputUnit::Inch };
        for (v, u, text) in [
            (64_400, mm, "64.400"),
            (-5, mm, "-0.005"),
            (0, mm, "0.000"),
            (-59_000, mm, "-59.000"),
            (i64::MAX, mm, "9223372036854775.807"),
            (i64::MIN, mm, "-9223372036854775.808"),
            (1, inch_c, "0.00001"),
        ] {
            assert_eq!(Fixed::new(v, u).to_string(), text);
        }
        assert_eq!(format!("{:>8}|{:<7}|", Fixed::new(1_800, mm), Fixed::new(-5, mm)), "   1.800|-0.005 |");
        for (word, mantissa, scale, text) in [
            (LeadWord::F, 6, 0, "F6.0"),
            (LeadWord::F, 15, 1, "F1.5"),
            (LeadWord::I, 20, 0, "I20.0"),
            (LeadWord::F, 1, 6, "F0.000001"),
        ] {
            assert_eq!(LeadText(Lead { word, mantissa, scale }).to_string(), text);
        }
    }

    /// `RecentText` gives the text a fresh encoding gives, whatever came
    /// before: values that repeat (as a thread's retract X does), values
    /// that share a place and push each other out, the same value in other
    /// units, and leads.
    #[test]
    fn recent_text_is_the_text_of_the_value_asked_for() {
        let mm = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };
        let inch = Units { system: IncrementSystem::IsC, unit: InputUnit::Inch };
        let mut recent = RecentText::<Fixed>::new();
        let mut x = 0x2545_F491_4F6C_DD1D_u64;
        let pool: Vec<i64> =
            (0..40).map(|i| (i * 7_919 - 130_000) * if i % 3 == 0 { -1 } else { 1 }).collect();
        for step in 0..50_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Mostly values from a small pool (hits and collisions), some
            // fresh ones, both units.
            let v = if step % 5 == 0 { i64::try_from(x >> 1).unwrap() } else { pool[(x % 40) as usize] };
            let u = if x & (1 << 40) == 0 { mm } else { inch };
            let want = Fixed::new(v, u).to_string();
            assert_eq!(std::str::from_utf8(recent.text(Fixed::new(v, u))).unwrap(), want, "{v}");
        }
        let mut leads = RecentText::<LeadText>::new();
        for (word, mantissa, scale, text) in [
            (LeadWord::F, 6, 0, "F6.0"),
            (LeadWord::F, 6, 0, "F6.0"),
            (LeadWord::I, 6, 0, "I6.0"),
            (LeadWord::F, 60, 1, "F6.0"),
            (LeadWord::F, 15, 1, "F1.5"),
            (LeadWord::F, 6, 0, "F6.0"),
        ] {
            let got = leads.text(LeadText(Lead { word, mantissa, scale }));
            assert_eq!(std::str::from_utf8(got).unwrap(), text);
        }
    }

    /// `encode_fixed` against the standard library's integer formatting:
    /// the integer part `mag / 10^d` and the fraction `mag % 10^d` padded
    /// to `d` digits, for every digit count, both signs, 0 to 19 decimals
    /// and the edges (0, 9, 10, 99, 100, u64::MAX).
    #[test]
    fn encode_fixed_matches_the_standard_formatting() {
        let mut values = vec![0_u64, 1, 9, 10, 11, 99, 100, 101, 999, 1_000, u64::MAX, u64::MAX - 1];
        let mut x = 0x9E37_79B9_7F4A_7C15_u64;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Every magnitude from 1 to 20 digits.
            values.push(x >> (x % 64));
        }
        for &mag in &values {
            for decimals in 0..=19_u32 {
                for negative in [false, true] {
                    let p = 10_u128.pow(decimals);
                    let (int, frac) = (u128::from(mag) / p, u128::from(mag) % p);
                    let sign = if negative { "-" } else { "" };
                    let want = if decimals == 0 {
                        format!("{sign}{int}")
                    } else {
                        format!("{sign}{int}.{frac:0width$}", width = decimals as usize)
                    };
                    let mut buf = [0; FIXED_BUF];
                    let got = encode_fixed(&mut buf, negative, mag, decimals);
                    assert_eq!(std::str::from_utf8(got).unwrap(), want, "{mag} {decimals}");
                }
            }
        }
        // The widest: 40 decimals of u64::MAX (20 digits, zero-padded).
        let mut buf = [0; FIXED_BUF];
        let got = encode_fixed(&mut buf, true, u64::MAX, 40);
        assert_eq!(got, b"-0.0000000000000000000018446744073709551615");
    }
}
