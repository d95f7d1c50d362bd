//! Text forms of moves: NC blocks, JSON and the pass table.

use std::fmt;

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

pub use cycleref_spec::text::{encode_fixed, fixed_len, put_fixed, FIXED_BUF};

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

/// A value whose text is written into a [`FIXED_BUF`] buffer, where the
/// value finds it cheapest: [`Fixed`] and [`LeadText`] (the JSON writers'
/// numbers).
///
/// ```
/// use cycleref_cli::format::{EncodeText, Fixed, FIXED_BUF};
/// use cycleref::Units;
///
/// let mut buf = [0_u8; FIXED_BUF];
/// // −12.5 mm at IS-B: −12 500 increments of 0.001 mm.
/// assert_eq!(Fixed::new(-12_500, Units::IS_B_METRIC).encode_text(&mut buf), b"-12.500");
/// ```
pub trait EncodeText: Copy + PartialEq {
    /// The text, written somewhere in `buf`.
    fn encode_text(self, buf: &mut [u8; FIXED_BUF]) -> &[u8];
}

impl EncodeText for Fixed {
    #[inline]
    fn encode_text(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        // At the start: no copy to the end (issue 33).
        let len = put_fixed(buf, self.value < 0, self.value.unsigned_abs(), self.decimals);
        &buf[..len]
    }
}

/// The lead word as programmed (`F6.0`, `F1.5`, `I20.0`), displayed without
/// an allocation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LeadText(pub cycleref::Lead);

impl LeadText {
    /// The text, written at the end of `buf`.
    pub fn encode(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        let mut text = [0; FIXED_BUF];
        let len = put_lead(&mut text, self.0, true);
        buf[FIXED_BUF - len..].copy_from_slice(&text[..len]);
        &buf[FIXED_BUF - len..]
    }
}

/// Writes the lead as programmed at the start of `out`, with its word
/// (`F6.0`, `F1.5`, `I20.0`) when `word`, else its value alone (`6.0`, the
/// K of a LinuxCNC G33); returns the length (at most [`FIXED_BUF`] − 3,
/// the lead's scale being at most 40). Always with a decimal point: on
/// FANUC a bare value may be read in other units.
///
/// # Panics
///
/// When `out` is shorter than the text (the callers keep [`FIXED_BUF`]
/// bytes of room).
#[inline]
pub fn put_lead(out: &mut [u8], lead: cycleref::Lead, word: bool) -> usize {
    let mut at = 0;
    if word {
        out[0] = match lead.word {
            LeadWord::F => b'F',
            LeadWord::I => b'I',
            LeadWord::K => b'K',
        };
        at = 1;
    }
    at += put_fixed(&mut out[at..], false, lead.mantissa, lead.scale);
    if lead.scale == 0 {
        out[at..at + 2].copy_from_slice(b".0");
        at += 2;
    }
    at
}

impl EncodeText for LeadText {
    #[inline]
    fn encode_text(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        let len = put_lead(buf, self.0, true);
        &buf[..len]
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

/// The value of a Q word for `angle` in the profile's unit, as `(v,
/// decimals)`, its text `v / 10^decimals` ([`put_fixed`]): whole
/// thousandths of a degree, or degrees with the increment system's
/// decimals (3 at IS-B, 4 at IS-C), rounded to nearest where the exact
/// angle has more digits (360°/7).
#[must_use]
pub fn q_value(angle: StartAngle, u: Units, q: QUnit) -> (u64, u32) {
    match q {
        QUnit::Millidegrees { .. } => (angle.rounded_millidegrees(), 0),
        QUnit::Degrees { .. } => {
            let decimals: u32 = match u.system {
                IncrementSystem::IsB => 3,
                IncrementSystem::IsC => 4,
            };
            // Units of 10^-decimals degree: num / den millidegrees × 10^(decimals - 3).
            let scale = u64::from(10_u32.pow(decimals - 3));
            let den = u64::from(angle.den);
            ((2 * u64::from(angle.num) * scale + den) / (2 * den), decimals)
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
/// (Z distance), as written in the nc format: I as `(v, decimals)`, its
/// text `v / 10^decimals`, with one more decimal than the increment when
/// X is a diameter and the distance is odd (half an increment: `dx × 5`);
/// K in increments.
pub fn arc_ik(from: Point, centre: Point, x_factor: i64, units: Units) -> ((i128, u32), i64) {
    let dx = centre.x - from.x;
    let i = if dx % x_factor == 0 {
        (i128::from(dx / x_factor), units.decimals())
    } else {
        (i128::from(dx) * 5, units.decimals() + 1)
    };
    (i, centre.z - from.z)
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

    proptest::proptest! {
        /// The nc writer's formatter ([`put_fixed`], in place, and
        /// [`encode_fixed`], at the end of a buffer) against the general
        /// one, `cycleref::units::write_fixed` (the standard library's
        /// formatting over `i128`): any value, with the edges (zero, the
        /// extremes of `i64`, one increment, values of nines that a carry
        /// would lengthen: 9.9995 at 4 decimals, 99.999, -0.001), 0 to 38
        /// decimals; and [`put_lead`] against [`LeadText`]'s text.
        #[test]
        fn put_fixed_is_the_general_formatting(
            v in proptest::prop_oneof![
                proptest::prelude::any::<i64>(),
                -2_000_000_i64..2_000_000,
                proptest::sample::select(vec![
                    0_i64, 1, -1, 9, 10, 99, 100, 99_995, 999_950, 99_999, -99_999, 9_999_999,
                    i64::MAX, i64::MIN, i64::MIN + 1, -1_000, 1_000,
                ]),
            ],
            decimals in 0_u32..=38,
            scale in 0_u32..=6,
            mantissa in proptest::prop_oneof![0_u64..100_000_000, proptest::prelude::any::<u64>()],
        ) {
            let mut want = String::new();
            cycleref::units::write_fixed(&mut want, i128::from(v), decimals).unwrap();
            let mut out = [0xAA_u8; FIXED_BUF];
            let len = put_fixed(&mut out, v < 0, v.unsigned_abs(), decimals);
            proptest::prop_assert_eq!(std::str::from_utf8(&out[..len]).unwrap(), want.as_str());
            proptest::prop_assert_eq!(len, fixed_len(v < 0, v.unsigned_abs(), decimals));
            let mut buf = [0; FIXED_BUF];
            proptest::prop_assert_eq!(
                std::str::from_utf8(encode_fixed(&mut buf, v < 0, v.unsigned_abs(), decimals)).unwrap(),
                want.as_str()
            );
            // The lead: its value with a point always, after its word.
            let lead = Lead { word: LeadWord::F, mantissa, scale };
            let mut value = String::new();
            cycleref::units::write_fixed(&mut value, i128::from(mantissa), scale).unwrap();
            let want = if scale == 0 { format!("F{value}.0") } else { format!("F{value}") };
            let len = put_lead(&mut out, lead, true);
            proptest::prop_assert_eq!(std::str::from_utf8(&out[..len]).unwrap(), want.as_str());
            proptest::prop_assert_eq!(LeadText(lead).to_string(), want.clone());
            let len = put_lead(&mut out, lead, false);
            proptest::prop_assert_eq!(std::str::from_utf8(&out[..len]).unwrap(), &want[1..]);
        }
    }
}
