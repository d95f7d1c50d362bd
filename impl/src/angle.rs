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
    /// `index * 360° / starts`, in lowest terms. `starts` of 0 counts as 1;
    /// `index` is taken modulo `starts`.
    #[must_use]
    pub const fn of_start(index: u32, starts: u32) -> StartAngle {
        let den = if starts == 0 { 1 } else { starts };
        StartSpacing::new(den).angle(index % den)
    }

    /// `self + other`, reduced to one turn and to lowest terms: the angle of
    /// a start of a multi-start thread whose first start is at `self` (G92
    /// Q on the 988TA). Denominators are at most 10 and 999 (a Q word and
    /// a start spacing), so every value below fits `u64` with room to spare.
    #[must_use]
    pub const fn plus(self, other: StartAngle) -> StartAngle {
        let (an, ad) = (self.num as u64, if self.den == 0 { 1 } else { self.den as u64 });
        let (bn, bd) = (other.num as u64, if other.den == 0 { 1 } else { other.den as u64 });
        let den = ad * bd;
        let num = (an * bd + bn * ad) % (FULL_TURN_MILLIDEGREES * den);
        let g = gcd(num, den);
        // num / g < 360 000 × den / g and den / g ≤ 9 990: below 2^32.
        #[allow(clippy::cast_possible_truncation)]
        StartAngle { num: (num / g) as u32, den: (den / g) as u32 }
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

/// The spacing of the starts of an `L`-start thread, `360° / L` in lowest
/// terms, computed once so that each start's angle needs no division unless
/// it must be reduced (the engine asks for one angle per pass and start).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StartSpacing {
    /// `360 000 / gcd(360 000, L)`: thousandths of a degree per start, over `den`.
    step: u32,
    /// `L / gcd(360 000, L)`.
    den: u32,
}

impl StartSpacing {
    /// The spacing of `starts` starts (`starts` ≥ 1; 0 counts as 1).
    #[must_use]
    pub const fn new(starts: u32) -> StartSpacing {
        if starts <= 1 {
            // gcd(360 000, 1) = 1: one start (the common case) without
            // Stein's loop.
            return StartSpacing { step: FULL_TURN_MILLIDEGREES as u32, den: 1 };
        }
        let l = starts as u64;
        let g = gcd(FULL_TURN_MILLIDEGREES, l);
        // g divides both, so the quotients fit u32 (≤ 360 000 and ≤ L).
        #[allow(clippy::cast_possible_truncation)]
        StartSpacing { step: (FULL_TURN_MILLIDEGREES / g) as u32, den: (l / g) as u32 }
    }

    /// Records the iterations of the `gcd` in [`StartSpacing::new`]
    /// (`loop-counters`; a `const fn` cannot record itself).
    #[cfg(feature = "loop-counters")]
    pub fn record_new_gcd(starts: u32) {
        let l = if starts == 0 { 1 } else { starts as u64 };
        crate::loop_counters::GCD.record(gcd_counted(FULL_TURN_MILLIDEGREES, l).1);
    }

    /// Records the iterations of the `gcd` in [`StartSpacing::angle`]
    /// (`loop-counters`).
    #[cfg(feature = "loop-counters")]
    pub fn record_angle_gcd(self, index: u32) {
        if self.den != 1 {
            crate::loop_counters::GCD.record(gcd_counted(index as u64, self.den as u64).1);
        }
    }

    /// The angle of start `index` (0-based, below L): `index × step / den`,
    /// reduced by `gcd(index, den)` (`step` and `den` are coprime).
    #[must_use]
    pub const fn angle(self, index: u32) -> StartAngle {
        let g = if self.den == 1 { 1 } else { gcd(index as u64, self.den as u64) };
        let num = index as u64 * self.step as u64;
        if g == 1 {
            // index < L ≤ 999 and step ≤ 360 000 for a valid cycle; saturate otherwise.
            #[allow(clippy::cast_possible_truncation)]
            let n = if num > u32::MAX as u64 { u32::MAX } else { num as u32 };
            return StartAngle { num: n, den: self.den };
        }
        let n = num / g;
        #[allow(clippy::cast_possible_truncation)]
        let n = if n > u32::MAX as u64 { u32::MAX } else { n as u32 };
        #[allow(clippy::cast_possible_truncation)]
        let d = (self.den as u64 / g) as u32;
        StartAngle { num: n, den: d }
    }
}

/// Greatest common divisor by Stein's binary algorithm (no division: it runs
/// once per pass and start, on the engine's hot path); `gcd(0, 0)` is 1 so
/// that it can always divide.
const fn gcd(a: u64, b: u64) -> u64 {
    gcd_counted(a, b).0
}

/// [`gcd`] and the iterations of its loop (for `loop-counters`).
const fn gcd_counted(mut a: u64, mut b: u64) -> (u64, u32) {
    if a == 0 {
        return (if b == 0 { 1 } else { b }, 0);
    }
    if b == 0 {
        return (a, 0);
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    // At most 128 iterations: each halves b at least once or ends.
    let mut n = 0_u32;
    loop {
        n += 1;
        b >>= b.trailing_zeros();
        if a > b {
            let t = a;
            a = b;
            b = t;
        }
        b -= a;
        if b == 0 {
            return (a << shift, n);
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
        // Every start of every L against the plain reduction of j·360000/L.
        for l in 1..=999_u32 {
            let spacing = StartSpacing::new(l);
            for j in 0..l {
                let num = u64::from(j) * 360_000;
                let g = euclid(num, u64::from(l));
                let expected = StartAngle {
                    num: u32::try_from(num / g).unwrap(),
                    den: u32::try_from(u64::from(l) / g).unwrap(),
                };
                assert_eq!(spacing.angle(j), expected, "start {j} of {l}");
            }
        }
        assert_eq!(StartAngle::of_start(1, 7), StartAngle { num: 360_000, den: 7 });
    }
}
