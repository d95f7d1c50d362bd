//! The tests of the interval arithmetic (moved from `real.rs`).

extern crate std;

use super::fixed::*;
use super::interval::*;
use super::limbs::*;
use super::power::*;
use super::trig::*;
use super::*;
use core::cmp::Ordering;
use std::string::String;
use std::vec::Vec;

/// `a <<= 1`; returns the bit shifted out.
fn limbs_shl1(a: &mut [u64]) -> bool {
    let mut carry = false;
    for x in a.iter_mut() {
        let out = *x >> 63 == 1;
        *x = (*x << 1) | u64::from(carry);
        carry = out;
    }
    carry
}

/// Bit `i` of `a`.
fn limbs_bit(a: &[u64], i: usize) -> bool {
    a.get(i / 64).is_some_and(|x| (x >> (i % 64)) & 1 == 1)
}

/// The bit-by-bit restoring division that `limbs_divmod` replaced: the
/// oracle of `divmod_matches_the_bitwise_division`.
fn limbs_divmod_bits(num: &[u64], den: &[u64], q: &mut [u64], rem: &mut [u64]) {
    for i in (0..limbs_bits(num)).rev() {
        limbs_shl1(rem);
        if limbs_bit(num, i) {
            rem[0] |= 1;
        }
        if limbs_cmp(rem, den) != Ordering::Less {
            limbs_sub(rem, den);
            q[i / 64] |= 1 << (i % 64);
        }
    }
}

/// A small deterministic generator (xorshift64*), so that the test
/// needs no dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A limb that is often an edge: 0, 1, all ones, a top bit alone.
    fn limb(&mut self) -> u64 {
        match self.next() % 8 {
            0 => 0,
            1 => u64::MAX,
            2 => 1 << 63,
            3 => 1,
            4 => u64::MAX - 1,
            _ => self.next(),
        }
    }
}

/// Knuth's algorithm D against the restoring division, on dividends and
/// divisors of every length up to the widest the engine divides (18
/// and 10 limbs), with limbs drawn to hit the rare add-back step (a
/// divisor of all-ones limbs and a top limb of 2^63) and the q̂ > 2^64
/// case (equal top limbs).
#[test]
fn divmod_matches_the_bitwise_division() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for case in 0..40_000 {
        let m = 1 + (case % 18);
        let n = 1 + (rng.next() as usize % 11);
        let mut num = [0_u64; 18];
        let mut den = [0_u64; 10];
        for x in num.iter_mut().take(m) {
            *x = rng.limb();
        }
        for x in den.iter_mut().take(n.min(10)) {
            *x = rng.limb();
        }
        if case % 7 == 0 {
            // Equal leading limbs: q̂ from the top two limbs exceeds 2^64 − 1.
            let dn = limbs_bits(&den).div_ceil(64);
            if dn > 0 && dn <= m {
                num[m - 1] = den[dn - 1];
            }
        }
        if limbs_bits(&den) == 0 {
            continue;
        }
        let (num, den) = (&num[..m], &den[..]);
        let (mut q1, mut r1) = ([0_u64; 18], [0_u64; 11]);
        let (mut q2, mut r2) = ([0_u64; 18], [0_u64; 11]);
        limbs_divmod(num, den, &mut q1[..m], &mut r1);
        limbs_divmod_bits(num, den, &mut q2[..m], &mut r2);
        assert_eq!((q1, r1), (q2, r2), "{num:x?} / {den:x?}");
        // q·den + r = num, and r < den, checked without the oracle.
        let mut back = [0_u64; 29];
        limbs_mul(&q1[..m], den, &mut back);
        assert!(!limbs_add(&mut back, &r1));
        assert_eq!(limbs_cmp(&back, num), Ordering::Equal);
        assert_eq!(limbs_cmp(&r1, den), Ordering::Less);
    }
}

/// The add-back step (D6), which random limbs almost never reach
/// (probability about 2/2^64): the cases of Hacker's Delight's `divmnu`
/// tests marked "add back required", with its 16-bit digits scaled to
/// 64 bits (0x8000 → 2^63, 0x7fff → 2^63 − 1, 0xffff → 2^64 − 1,
/// 0xfffe → 2^64 − 2), each checked against the restoring division and
/// counted.
#[test]
fn divmod_add_back() {
    const H: u64 = 1 << 63;
    const M: u64 = u64::MAX;
    let cases: [(&[u64], &[u64]); 3] =
        [(&[3, 0, H], &[1, 0, H >> 2]), (&[0, 0, H, H - 1], &[1, 0, H]), (&[0, M - 1, 0, H], &[M, 0, H])];
    let before = ADD_BACKS.load(core::sync::atomic::Ordering::Relaxed);
    for (num, den) in cases {
        let (mut q1, mut r1) = ([0_u64; 4], [0_u64; 4]);
        let (mut q2, mut r2) = ([0_u64; 4], [0_u64; 4]);
        let m = num.len();
        limbs_divmod(num, den, &mut q1[..m], &mut r1[..=den.len()]);
        limbs_divmod_bits(num, den, &mut q2[..m], &mut r2[..=den.len()]);
        assert_eq!((q1, r1), (q2, r2), "{num:x?} / {den:x?}");
    }
    let after = ADD_BACKS.load(core::sync::atomic::Ordering::Relaxed);
    assert!(after > before, "no case reached the add-back step");
}

type F = Fixed<FAST>;
type S = Fixed<SLOW>;

/// The interval contains `num / 10^digits` within one unit of the last
/// decimal, and is narrower than `10^-digits`: `lo·10^d ≤ num + 1`,
/// `hi·10^d ≥ num`, `(hi − lo)·10^d < 1`.
fn encloses_decimal<const N: usize>(iv: &Interval<N>, digits: &str) {
    let (int, frac) = digits.split_once('.').unwrap();
    let text: String = [int, frac].concat();
    let num: i128 = text.parse().unwrap();
    let scale = |x: &Fixed<N>| {
        let mut v = *x;
        for _ in 0..frac.len() {
            v = v.mul_int(10).unwrap();
        }
        v
    };
    let (lo, hi) = (scale(iv.lower()), scale(iv.upper()));
    assert!(lo.floor() <= num + 1, "lower end too high for {digits}");
    assert!(hi.ceil().unwrap() >= num, "upper end too low for {digits}");
    let width = hi.checked_sub(&lo).unwrap();
    assert_eq!(width.floor(), 0, "interval too wide for {digits}");
}

#[test]
fn fixed_point_basics() {
    let three = F::from_int(3);
    let two = F::from_int(2);
    assert_eq!(three.checked_add(&two).unwrap().floor(), 5);
    assert_eq!(two.checked_sub(&three).unwrap().floor(), -1);
    let m = F::from_int(-7);
    assert_eq!(m.floor(), -7);
    assert_eq!(m.ceil(), Some(-7));
    assert!(m.is_negative());
    assert_eq!(m.checked_neg().unwrap(), F::from_int(7));
    // 7 / 2 = 3.5: floor 3, ceil 4, exact.
    let q = F::from_int(7).div_round(&two, RoundDirection::Down).unwrap();
    assert_eq!(q, F::from_int(7).div_round(&two, RoundDirection::Up).unwrap());
    assert_eq!((q.floor(), q.ceil()), (3, Some(4)));
    // −7 / 2 = −3.5.
    let q = m.div_round(&two, RoundDirection::Down).unwrap();
    assert_eq!((q.floor(), q.ceil()), (-4, Some(-3)));
    // 1/3 is inexact: the two roundings differ by one unit.
    let d = F::from_int(1).div_round(&three, RoundDirection::Down).unwrap();
    let u = F::from_int(1).div_round(&three, RoundDirection::Up).unwrap();
    assert_eq!(u.checked_sub(&d).unwrap(), F::from_ulps(1));
    let d = F::from_int(-1).div_round(&three, RoundDirection::Down).unwrap();
    let u = F::from_int(-1).div_round(&three, RoundDirection::Up).unwrap();
    assert_eq!(u.checked_sub(&d).unwrap(), F::from_ulps(1));
    // Products: exact for dyadic results, one unit apart otherwise.
    let h = F::half();
    assert_eq!(h.mul_round(&h, RoundDirection::Down), h.mul_round(&h, RoundDirection::Up));
    assert_eq!(
        h.mul_round(&m, RoundDirection::Down).unwrap(),
        F::from_int(-7).div_small(2, RoundDirection::Down).unwrap()
    );
    let tiny = F::from_ulps(1);
    assert_eq!(tiny.mul_round(&tiny, RoundDirection::Down).unwrap(), F::zero());
    assert_eq!(tiny.mul_round(&tiny, RoundDirection::Up).unwrap(), tiny);
    let ntiny = tiny.checked_neg().unwrap();
    assert_eq!(ntiny.mul_round(&tiny, RoundDirection::Down).unwrap(), ntiny);
    assert_eq!(ntiny.mul_round(&tiny, RoundDirection::Up).unwrap(), F::zero());
    // Overflow is reported, not wrapped.
    let big = F::from_int(i128::MAX >> 1);
    assert!(big.checked_add(&big).is_some());
    let top = F::from_int(1 << 126);
    assert!(top.checked_add(&top).is_none());
    assert!(top.checked_neg().unwrap().checked_sub(&top).is_some());
    assert!(top.checked_neg().unwrap().checked_sub(&top).unwrap().checked_sub(&F::from_ulps(1)).is_none());
    assert!(big.mul_round(&two, RoundDirection::Down).is_some());
    assert!(big.mul_round(&three, RoundDirection::Down).is_none());
    assert!(big.mul_int(4).is_none());
    assert!(F::from_int(1).div_round(&F::zero(), RoundDirection::Up).is_none());
}

/// Division against multiplication on pseudo-random operands: the
/// quotient's two roundings bracket the exact one and are one unit apart
/// or equal, and q·b reproduces a within the rounding.
#[test]
fn division_brackets() {
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    };
    for _ in 0..2000 {
        let mut a = F::zero();
        let mut b = F::zero();
        for i in 0..FAST - 1 {
            a.l[i] = next();
            b.l[i] = next() >> (next() % 64);
        }
        a.l[FAST - 1] = next() >> 40;
        if next() % 2 == 0 {
            a = a.checked_neg().unwrap();
        }
        if b.is_zero() {
            continue;
        }
        let (Some(d), Some(u)) = (a.div_round(&b, RoundDirection::Down), a.div_round(&b, RoundDirection::Up))
        else {
            continue;
        };
        let gap = u.checked_sub(&d).unwrap();
        assert!(gap == F::zero() || gap == F::from_ulps(1));
        // d·b ≤ a ≤ u·b (b > 0), checked with exact products.
        let lo = d.mul_round(&b, RoundDirection::Down).unwrap();
        let hi = u.mul_round(&b, RoundDirection::Up).unwrap();
        assert_ne!(lo.cmp_signed(&a), Ordering::Greater);
        assert_ne!(hi.cmp_signed(&a), Ordering::Less);
    }
}

#[test]
fn interval_decisions() {
    let p = Interval::<FAST>::int(5).div_int(2);
    assert!(p.is_point());
    assert_eq!(p.round(Rounding::Floor), Some(2));
    assert_eq!(p.round(Rounding::Ceil), Some(3));
    // Ties go up.
    assert_eq!(p.round(Rounding::Nearest), Some(3));
    let n = p.neg();
    assert_eq!(n.round(Rounding::Nearest), Some(-2));
    assert_eq!(n.round(Rounding::Floor), Some(-3));
    assert_eq!(n.round(Rounding::Ceil), Some(-2));
    // An interval straddling an integer decides nearest but not floor.
    let s = Interval::new(F::from_int(2).checked_sub(&F::from_ulps(1)).unwrap(), F::from_int(2));
    assert_eq!(s.round(Rounding::Floor), None);
    assert_eq!(s.round(Rounding::Ceil), Some(2));
    assert_eq!(s.round(Rounding::Nearest), Some(2));
    assert_eq!(s.sign(), Some(Ordering::Greater));
    let z = Interval::new(F::from_ulps(1).checked_neg().unwrap(), F::from_ulps(1));
    assert_eq!(z.sign(), None);
    assert_eq!(Interval::<FAST>::int(0).sign(), Some(Ordering::Equal));
    assert_eq!(Interval::<FAST>::int(-3).sign(), Some(Ordering::Less));
    assert_eq!(Interval::<FAST>::poison().round(Rounding::Floor), None);
    // Exact zero times anything is an exact zero.
    let third = Interval::<FAST>::int(1).div_int(3);
    assert!(!third.is_point());
    assert!(Interval::<FAST>::int(0).mul(&third).is_point());
    assert!(third.neg().mul(&Interval::int(0)).is_point());
    // Mixed signs.
    let m =
        Interval::new(F::from_int(-2), F::from_int(3)).mul(&Interval::new(F::from_int(-5), F::from_int(4)));
    assert_eq!((m.lower().floor(), m.upper().floor()), (-15, 12));
    // Division by an interval containing 0 is poisoned.
    assert!(!third.div(&z).is_valid());
}

/// R-G75TIE: one boundary in the enclosure decides on it; two do not.
#[test]
fn tie_decisions() {
    let ulp = F::from_ulps(1);
    let around = |v: F| Interval::new(v.checked_sub(&ulp).unwrap(), v.checked_add(&ulp).unwrap());
    let two = F::from_int(2);
    // An integer inside: floor and ceil give it.
    let i = around(two);
    assert_eq!((i.round(Rounding::Floor), i.round(Rounding::Ceil)), (None, None));
    assert_eq!(i.round_tie(Rounding::Floor), Some(2));
    assert_eq!(i.round_tie(Rounding::Ceil), Some(2));
    assert_eq!(i.round_tie(Rounding::Nearest), Some(2));
    // On an end: [2 − ulp, 2] and [2, 2 + ulp].
    let below = Interval::new(two.checked_sub(&ulp).unwrap(), two);
    assert_eq!(below.round(Rounding::Floor), None);
    assert_eq!(below.round_tie(Rounding::Floor), Some(2));
    let above = Interval::new(two, two.checked_add(&ulp).unwrap());
    assert_eq!(above.round(Rounding::Ceil), None);
    assert_eq!(above.round_tie(Rounding::Ceil), Some(2));
    // A half-integer: nearest goes up, on both sides of 0.
    let h = around(*Interval::<FAST>::int(3).div_int(2).lower());
    assert_eq!(h.round(Rounding::Nearest), None);
    assert_eq!(h.round_tie(Rounding::Nearest), Some(2));
    assert_eq!(h.round_tie(Rounding::Floor), Some(1));
    let nh = around(*Interval::<FAST>::int(-5).div_int(2).lower());
    assert_eq!(nh.round_tie(Rounding::Nearest), Some(-2));
    assert_eq!(nh.round_tie(Rounding::Ceil), Some(-2));
    // Two boundaries: refused.
    let wide = Interval::new(F::from_int(1), F::from_int(2));
    assert_eq!(wide.round_tie(Rounding::Floor), None);
    assert_eq!(wide.round_tie(Rounding::Ceil), None);
    let halves = Interval::new(
        F::from_int(1).checked_sub(&F::half()).unwrap(),
        F::from_int(1).checked_add(&F::half()).unwrap(),
    );
    assert_eq!(halves.round_tie(Rounding::Nearest), None);
    assert_eq!(halves.round_tie(Rounding::Floor), Some(1));
    assert_eq!(Interval::<FAST>::poison().round_tie(Rounding::Floor), None);
    // Signs: 0 inside or on an end is 0; decided signs stay.
    assert_eq!(around(F::zero()).sign_tie(), Some(Ordering::Equal));
    assert_eq!(Interval::new(F::zero(), ulp).sign_tie(), Some(Ordering::Equal));
    assert_eq!(Interval::new(ulp, two).sign_tie(), Some(Ordering::Greater));
    assert_eq!(Interval::<FAST>::int(-1).sign_tie(), Some(Ordering::Less));
    assert_eq!(Interval::<FAST>::poison().sign_tie(), None);
    // The identity tan 30°·sin 60° = 1/2 at 512 bits.
    let t = tan::<SLOW>(600_000).mul(&sin::<SLOW>(1_200_000));
    assert_eq!(t.round(Rounding::Nearest), None);
    assert_eq!(t.mul_int(2).round(Rounding::Floor), None);
    assert_eq!(t.mul_int(2).round_tie(Rounding::Floor), Some(1));
    assert_eq!(t.round_tie(Rounding::Nearest), Some(1));
}

#[test]
fn exact_trigonometric_cases() {
    assert!(sin::<FAST>(0).is_point() && sin::<FAST>(0).round(Rounding::Floor) == Some(0));
    assert_eq!(sin::<FAST>(600_000), Interval::half());
    assert_eq!(sin::<FAST>(RIGHT), Interval::int(1));
    assert_eq!(cos::<FAST>(0), Interval::int(1));
    assert_eq!(cos::<FAST>(1_200_000), Interval::half());
    assert_eq!(cos::<FAST>(RIGHT), Interval::int(0));
    assert_eq!(tan::<FAST>(0), Interval::int(0));
    assert_eq!(tan::<FAST>(900_000), Interval::int(1));
    assert_eq!(cot::<FAST>(900_000), Interval::int(1));
    assert_eq!(cot::<FAST>(RIGHT), Interval::int(0));
    assert!(!tan::<FAST>(RIGHT).is_valid());
    assert!(!cot::<FAST>(0).is_valid());
    assert_eq!(tan_cot::<SLOW>(900_000), (Interval::int(1), Interval::int(1)));
    // Non-exact values are proper intervals.
    assert!(!sin::<FAST>(1_200_000).is_point());
    assert!(!cos::<FAST>(600_000).is_point());
    assert!(!tan::<FAST>(600_000).is_point());
}

#[test]
fn trigonometric_values() {
    // 1° = 20 000 units of 0.00005°.
    encloses_decimal(&sin::<FAST>(20_000), "0.017452406437283512819418978516316");
    encloses_decimal(&sin::<SLOW>(20_000), "0.017452406437283512819418978516316");
    encloses_decimal(&cos::<FAST>(900_000), "0.70710678118654752440084436210484");
    encloses_decimal(&sin::<FAST>(900_000), "0.70710678118654752440084436210484");
    encloses_decimal(&cos::<SLOW>(900_000), "0.70710678118654752440084436210484");
    // 45° together: one series for both.
    let (s, c) = sin_cos::<FAST>(900_000);
    encloses_decimal(&s, "0.70710678118654752440084436210484");
    encloses_decimal(&c, "0.70710678118654752440084436210484");
    let (s, c) = sin_cos::<SLOW>(900_000);
    encloses_decimal(&s, "0.70710678118654752440084436210484");
    encloses_decimal(&c, "0.70710678118654752440084436210484");
    // sin 60° = cos 30° = √3/2, tan 30° = 1/√3, tan 60° = √3.
    encloses_decimal(&sin::<FAST>(1_200_000), "0.86602540378443864676372317075293");
    encloses_decimal(&cos::<SLOW>(600_000), "0.86602540378443864676372317075293");
    encloses_decimal(&tan::<FAST>(600_000), "0.57735026918962576450914878050195");
    encloses_decimal(&cot::<SLOW>(600_000), "1.7320508075688772935274463415058");
    // Near the ends of the range: cot 0.0001° and tan 89.99995°.
    encloses_decimal(&cot::<FAST>(2), "572957.79513024143235064998");
    encloses_decimal(&tan::<FAST>(RIGHT - 1), "1145915.59026135552932729735");
    // sin 30° from the series agrees with the exact 1/2.
    let s = sin_cos_series::<FAST>(600_000).0;
    // ... but the series alone cannot decide its rounding: that is why
    // the exact cases exist.
    assert_eq!(s.round(Rounding::Nearest), None);
    assert!(s.lower().floor() == 0 && s.upper().ceil() == Some(1));
    // Widths: the fast path keeps more than 118 bits, the slow more than 500.
    let w = |iv: &Interval<FAST>| iv.upper().checked_sub(iv.lower()).unwrap();
    assert!(w(&sin::<FAST>(123_457)).cmp_signed(&Fixed::from_ulps(1 << 10)) == Ordering::Less);
    let ws = sin::<SLOW>(123_457);
    let ws = ws.upper().checked_sub(ws.lower()).unwrap();
    assert!(ws.cmp_signed(&Fixed::from_ulps(1 << 10)) == Ordering::Less);
    // sin² + cos² = 1 within the widths.
    for k in [1, 7, 20_000, 333_333, 900_001, 1_799_999] {
        let (s, c) = sin_cos::<FAST>(k);
        let one = s.mul(&s).add(&c.mul(&c));
        assert_eq!(one.round(Rounding::Nearest), Some(1));
        assert!(one.lower().floor() <= 1 && one.upper().ceil() >= Some(1));
    }
}

#[test]
fn logarithms_and_exponentials() {
    // ln 2, ln 10, e, e^(1/2), e^20 (published constants; the helper
    // checks the enclosure holds the digits and is narrower than them).
    encloses_decimal(&ln::<FAST>(2), "0.693147180559945309417232121458");
    encloses_decimal(&ln::<SLOW>(2), "0.69314718055994530941723212145817656807");
    encloses_decimal(&ln::<FAST>(10), "2.302585092994045684017991454684");
    encloses_decimal(&ln::<SLOW>(1_000_000_007), "20.723265843946411131661923206492610601");
    encloses_decimal(&exp(&Interval::<FAST>::int(1)), "2.718281828459045235360287471352");
    encloses_decimal(&exp(&Interval::<SLOW>::half()), "1.6487212707001281468486507878141635716");
    encloses_decimal(&exp(&Interval::<FAST>::int(20)), "485165195.409790277969106830");
    assert_eq!(ln::<FAST>(1), Interval::int(0));
    assert!(!ln::<FAST>(0).is_valid() && !ln::<FAST>(1 << 63).is_valid());
    assert!(ln::<FAST>((1 << 63) - 1).is_valid());
    // exp(ln n) = n within the widths, at both precisions.
    for n in [3_u64, 1000, 4_294_967_297] {
        assert_eq!(exp(&ln::<FAST>(n)).round(Rounding::Nearest), Some(i128::from(n)));
        assert_eq!(exp(&ln::<SLOW>(n)).round(Rounding::Nearest), Some(i128::from(n)));
    }
    // Outside the domain, and too large a result: poisoned.
    assert!(!exp(&Interval::<FAST>::int(-1)).is_valid());
    assert!(!exp(&Interval::<FAST>::poison()).is_valid());
    assert!(!exp(&Interval::<FAST>::int(100)).is_valid());
    assert!(exp(&Interval::<FAST>::int(87)).is_valid());
    // The widths: the fast power of a value below 2^33 keeps about 80
    // bits, the slow one about 460.
    let w = |iv: &Interval<FAST>| iv.upper().checked_sub(iv.lower()).unwrap();
    let p = power::<FAST>(4_294_967_297, 10_000, 10_001);
    assert!(w(&p).cmp_signed(&F::from_ulps(1 << 50)) == Ordering::Less);
    let p = power::<SLOW>(4_294_967_297, 10_000, 10_001);
    let ws = p.upper().checked_sub(p.lower()).unwrap();
    assert!(ws.cmp_signed(&S::from_ulps(1 << 50)) == Ordering::Less);
}

#[test]
fn integer_roots() {
    assert_eq!(integer_root(1, 2), Some(1));
    assert_eq!(integer_root(u64::MAX, 2), None);
    assert_eq!(integer_root(4_294_967_295 * 4_294_967_295, 2), Some(4_294_967_295));
    assert_eq!(integer_root(1 << 62, 62), Some(2));
    assert_eq!(integer_root(1 << 62, 63), None);
    assert_eq!(integer_root(3_486_784_401, 20), Some(3));
    assert_eq!(integer_root(3_486_784_402, 20), None);
    assert_eq!(
        (gcd_u32(10_000, 15_000), gcd_u32(0, 0), gcd_u32(7, 0), gcd_u32(u32::MAX, u32::MAX - 1)),
        (5_000, 1, 7, 1)
    );
}

#[test]
fn changes_of_precision() {
    let third = Interval::<SLOW>::int(-1).div_int(3);
    let fast: Interval<FAST> = third.at_precision();
    // The narrowed enclosure holds the wider one.
    let back: Interval<SLOW> = fast.at_precision();
    assert_ne!(back.lower().cmp_signed(third.lower()), Ordering::Greater);
    assert_ne!(back.upper().cmp_signed(third.upper()), Ordering::Less);
    assert_eq!(fast, Interval::<FAST>::int(-1).div_int(3));
    // Exact values stay exact both ways; poison stays poison.
    assert_eq!(Interval::<SLOW>::int(-5).div_int(4).at_precision::<FAST>(), Interval::int(-5).div_int(4));
    assert!(!Interval::<SLOW>::poison().at_precision::<FAST>().is_valid());
    let big = Interval::<FAST>::int(i128::MAX >> 1);
    assert_eq!(big.at_precision::<SLOW>().at_precision::<FAST>(), big);
}

/// `atan(1/m)` enclosed by its alternating series at the precision `N`.
fn atan_inv<const N: usize>(m: u64) -> Interval<N> {
    let m2 = m * m;
    let mut power = Interval::<N>::int(1).div_int(m); // 1/m^(2j+1)
    let mut sum = power;
    let mut j: u64 = 1;
    loop {
        power = power.div_int(m2);
        let term = power.div_int(2 * j + 1);
        if term.upper().cmp_signed(&Fixed::from_ulps(4)) != Ordering::Greater {
            let hi = *term.upper();
            return sum.add(&Interval::new(hi.checked_neg().unwrap(), hi));
        }
        sum = if j % 2 == 1 { sum.sub(&term) } else { sum.add(&term) };
        j += 1;
    }
}

/// The hard-coded digits of π against Machin's formula at 704 fraction
/// bits: all 640 bits of [`PI_FRACTION`] are decided and equal.
#[test]
fn pi_matches_machin() {
    const N: usize = 13; // 704 fraction bits
    let machin = atan_inv::<N>(5).mul_int(16).sub(&atan_inv::<N>(239).mul_int(4));
    assert!(machin.is_valid());
    let words = |x: &Fixed<N>| -> Vec<u64> {
        // Fraction limbs 10..=1 (most significant first) hold bits 1..640.
        (0..10).map(|i| x.limbs()[Fixed::<N>::FRAC - 1 - i]).collect()
    };
    assert_eq!(machin.lower().floor(), 3);
    assert_eq!(machin.upper().floor(), 3);
    assert_eq!(words(machin.lower()), PI_FRACTION.to_vec());
    assert_eq!(words(machin.upper()), PI_FRACTION.to_vec());
    // And pi() at both engine precisions encloses it.
    let p = pi::<SLOW>();
    assert_eq!(p.upper().checked_sub(p.lower()).unwrap(), Fixed::from_ulps(1));
    assert_eq!(
        p.lower().limbs()[..8],
        [
            PI_FRACTION[7],
            PI_FRACTION[6],
            PI_FRACTION[5],
            PI_FRACTION[4],
            PI_FRACTION[3],
            PI_FRACTION[2],
            PI_FRACTION[1],
            PI_FRACTION[0]
        ]
    );
    encloses_decimal(&pi::<FAST>(), "3.14159265358979323846264338327950288");
    let _ = S::zero();
}
