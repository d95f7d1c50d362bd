//! Spindle start angles (the `Q` of G32 and the index of a multi-start thread).

/// A spindle start angle of `num / den` thousandths of a degree
/// (`0 <= num/den < 360000`), kept exact: the starts of an `L`-start thread
/// are `j * 360° / L` apart, which is not always a whole number of
/// thousandths (L = 7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StartAngle {
    /// Numerator in thousandths of a degree.
    pub num: u64,
    /// Denominator, at least 1; the fraction is in lowest terms.
    pub den: u32,
}

/// One full turn in thousandths of a degree.
pub const FULL_TURN_MILLIDEGREES: u64 = 360_000;

impl StartAngle {
    /// Zero degrees.
    pub const ZERO: StartAngle = StartAngle { num: 0, den: 1 };

    /// An angle of `millidegrees` thousandths of a degree (`G32 Q`).
    #[must_use]
    pub const fn from_millidegrees(millidegrees: u64) -> StartAngle {
        StartAngle { num: millidegrees % FULL_TURN_MILLIDEGREES, den: 1 }
    }

    /// The angle of start `index` (0-based) of an `starts`-start thread:
    /// `index * 360° / starts`, in lowest terms. `starts` of 0 counts as 1.
    #[must_use]
    pub const fn of_start(index: u32, starts: u32) -> StartAngle {
        let den = if starts == 0 { 1 } else { starts };
        let num = (index as u64 % den as u64) * FULL_TURN_MILLIDEGREES;
        let g = gcd(num, den as u64);
        // g divides den, so the quotient fits u32.
        #[allow(clippy::cast_possible_truncation)]
        let d = (den as u64 / g) as u32;
        StartAngle { num: num / g, den: d }
    }

    /// True for 0°.
    #[must_use]
    pub const fn is_zero(self) -> bool {
        self.num == 0
    }

    /// The angle rounded to the nearest thousandth of a degree (ties away
    /// from zero), which is what a `Q` word can express.
    #[must_use]
    pub const fn rounded_millidegrees(self) -> u64 {
        let d = self.den as u64;
        (2 * self.num + d) / (2 * d)
    }
}

const fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    if a == 0 {
        1
    } else {
        a
    }
}
