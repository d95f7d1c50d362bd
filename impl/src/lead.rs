//! The thread lead, kept exactly as programmed.
//!
//! A lead is a rate (travel of the long axis per spindle revolution), not a
//! position, so it is never rounded to the increment: `F` is a decimal in
//! mm (inch) per revolution, `I` is threads per inch and gives
//! `25.4 / I` mm (or `1 / I` inch) per revolution, which is generally not a
//! terminating decimal. [`Lead::increments_per_rev`] gives the exact ratio.

use crate::units::{InputUnit, Units};

/// Which word programmed the lead.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LeadWord {
    /// `F`: lead in mm (inch) per revolution along the long axis.
    F,
    /// `I`: threads per inch along the long axis.
    I,
    /// `K`: LinuxCNC's pitch, the distance per revolution along the move
    /// (`G33 K`, and the G76 pitch `P` its passes are cut with): read as
    /// `F` is, and written as LinuxCNC writes it.
    K,
}

/// A programmed lead: `mantissa / 10^scale` of the word [`LeadWord`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Lead {
    /// `F`, `I` or (LinuxCNC) `K`.
    pub word: LeadWord,
    /// Digits of the programmed value without the decimal point.
    pub mantissa: u64,
    /// Number of decimals of the programmed value.
    pub scale: u32,
}

/// An exact non-negative rational `num / den` (`den > 0`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ratio {
    /// Numerator.
    pub num: u128,
    /// Denominator, never zero for a valid lead.
    pub den: u128,
}

/// Largest number of decimals a lead word may carry (`F0.00001` inch).
pub const MAX_LEAD_SCALE: u32 = 6;

impl Lead {
    /// Lead in least increments of `units` per spindle revolution, exactly.
    ///
    /// `F`: `mantissa * 10^decimals / 10^scale`.
    /// `I` metric: `25.4 mm / I` = `254 * 10^decimals * 10^scale / (10 * mantissa)`.
    /// `I` inch: `1 inch / I` = `10^decimals * 10^scale / mantissa`.
    ///
    /// The denominator is zero only for a zero `I`, which the reader rejects.
    #[must_use]
    pub fn increments_per_rev(self, units: Units) -> Ratio {
        let inc = 10_u128.pow(units.decimals());
        let sc = 10_u128.pow(self.scale.min(MAX_LEAD_SCALE));
        let m = u128::from(self.mantissa);
        match (self.word, units.unit) {
            (LeadWord::F | LeadWord::K, _) => Ratio { num: m * inc, den: sc },
            (LeadWord::I, InputUnit::Metric) => Ratio { num: 254 * inc * sc, den: 10 * m },
            (LeadWord::I, InputUnit::Inch) => Ratio { num: inc * sc, den: m },
        }
    }

    /// True when the lead is zero (`F0` or `I0`): no thread can be cut.
    #[must_use]
    pub const fn is_zero(self) -> bool {
        self.mantissa == 0
    }

    /// True when the value is inside the widest range table of the manuals:
    /// `F` at most 9999 (mm or inch) per revolution, `I` from 0.0001 to 2540
    /// threads per inch (988TA: "0.0001 < I < 2540"), with at most
    /// [`MAX_LEAD_SCALE`] decimals. The reader applies the tighter table of
    /// the unit; this bound is what the engines rely on.
    #[must_use]
    pub const fn in_range(self) -> bool {
        if self.scale > MAX_LEAD_SCALE || self.mantissa == 0 {
            return false;
        }
        let one = 10_u64.pow(self.scale);
        match self.word {
            LeadWord::F | LeadWord::K => self.mantissa <= 9999 * one,
            // I >= 0.0001 and I <= 2540.
            LeadWord::I => self.mantissa as u128 * 10_000 >= one as u128 && self.mantissa <= 2540 * one,
        }
    }

    /// The run-out chamfer `round(r × 0.1 × lead)` in increments of
    /// `units`, exactly, ties away from zero (seed 000 P(r): "单位: 0.1×L").
    /// For a lead [`in_range`](Self::in_range) every product fits `u128`.
    #[must_use]
    pub fn chamfer_increments(self, tenths_of_lead: u32, units: Units) -> u128 {
        let r = self.increments_per_rev(units);
        let num = u128::from(tenths_of_lead).saturating_mul(r.num);
        let den = r.den.saturating_mul(10);
        if den == 0 {
            return u128::MAX;
        }
        (num + den / 2) / den
    }
}
