//! Spindle start angles (the `Q` of G32 and the index of a multi-start thread).

/// A spindle start angle of `num / den` thousandths of a degree
/// (`0 <= num/den < 360000`), kept exact: the starts of an `L`-start thread
/// are `j * 360° / L` apart, which is not always a whole number of
/// thousandths (L = 7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StartAngle {
    /// Numerator in thousandths of a degree (below 360 000 × 999).
    pub num: u32,
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
        // Below 360 000 after the reduction, so it fits u32.
        #[allow(clippy::cast_possible_truncation)]
        let num = (millidegrees % FULL_TURN_MILLIDEGREES) as u32;
        StartAngle { num, den: 1 }
    }

    /// The angle of start `index` (0-based) of an `starts`-start thread:
    /// `index * 360° / starts`, in lowest terms. `starts` of 0 counts as 1.
    #[must_use]
    pub const fn of_start(index: u32, starts: u32) -> StartAngle {
        let den = if starts == 0 { 1 } else { starts };
        let num = (index as u64 % den as u64) * FULL_TURN_MILLIDEGREES;
        let g = gcd(num, den as u64);
        // g divides den, so the quotient fits u32; num / g < 360 000 × den
        // with den = starts ≤ 999 for a valid cycle, below 2^32, and
        // saturates otherwise.
        #[allow(clippy::cast_possible_truncation)]
        let d = (den as u64 / g) as u32;
        let n = num / g;
        #[allow(clippy::cast_possible_truncation)]
        let n = if n > u32::MAX as u64 { u32::MAX } else { n as u32 };
        StartAngle { num: n, den: d }
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
        (2 * self.num as u64 + d) / (2 * d)
    }
}

/// Greatest common divisor by Stein's binary algorithm (no division: it runs
/// once per pass and start, on the engine's hot path); `gcd(0, 0)` is 1 so
/// that it can always divide.
const fn gcd(mut a: u64, mut b: u64) -> u64 {
    if a == 0 {
        return if b == 0 { 1 } else { b };
    }
    if b == 0 {
        return a;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            let t = a;
            a = b;
            b = t;
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn euclid(a: u64, b: u64) -> u64 {
        if b == 0 {
            if a == 0 {
                1
            } else {
                a
            }
        } else {
            euclid(b, a % b)
        }
    }

    #[test]
    fn binary_gcd_equals_euclid() {
        for a in 0..400_u64 {
            for b in 0..400_u64 {
                assert_eq!(gcd(a * 900, b), euclid(a * 900, b), "{a} {b}");
            }
        }
        assert_eq!(gcd(998 * 360_000, 999), 9);
        assert_eq!(StartAngle::of_start(3, 8), StartAngle { num: 135_000, den: 1 });
        assert_eq!(StartAngle::of_start(1, 7), StartAngle { num: 360_000, den: 7 });
    }
}
