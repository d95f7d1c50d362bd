//! Numbers and words: a [`Number`] as written after an address, and a
//! [`Word`] (an address letter and its number), both borrowed from the
//! program's text, with the exact readings of a number's digits (as a
//! `Decimal`, in least increments, as a whole number) that need no
//! allocation on the usual path.

use std::borrow::Cow;

use rust_decimal::Decimal;

/// A number as written after an address: a sign, digits, perhaps a
/// decimal point and more digits, borrowed from the program's text.
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Number<'a> {
    /// A leading minus sign.
    pub negative: bool,
    /// The digits and the decimal point, as written (`060.640`, `.5`, `6`):
    /// ASCII, kept as bytes (the lexer need not make a `str` of its line).
    digits: &'a [u8],
    /// Where the decimal point is in `digits`, if there is one.
    point: Option<u32>,
}

impl<'a> Number<'a> {
    /// A number from its parts: `digits` are ASCII digits with at most one
    /// `.` (the decimal point).
    #[must_use]
    pub fn new(negative: bool, digits: &'a str) -> Number<'a> {
        let point = digits.bytes().position(|b| b == b'.').and_then(|p| u32::try_from(p).ok());
        Number { negative, digits: digits.as_bytes(), point }
    }

    /// Digits before the decimal point, as written (leading zeros kept).
    #[must_use]
    pub fn int_digits(&self) -> &'a str {
        ascii(self.int_bytes())
    }

    /// Digits after the decimal point, when there is a decimal point.
    #[must_use]
    pub fn frac_digits(&self) -> Option<&'a str> {
        self.frac_bytes().map(ascii)
    }

    /// [`Number::int_digits`] as bytes.
    pub(crate) fn int_bytes(&self) -> &'a [u8] {
        match self.point {
            Some(p) => self.digits.get(..p as usize).unwrap_or_default(),
            None => self.digits,
        }
    }

    /// [`Number::frac_digits`] as bytes.
    pub(crate) fn frac_bytes(&self) -> Option<&'a [u8]> {
        self.point.map(|p| self.digits.get(p as usize + 1..).unwrap_or_default())
    }

    /// True when the number was written with a decimal point.
    #[must_use]
    pub fn has_point(&self) -> bool {
        self.point.is_some()
    }

    /// The exact value, with the scale as written (`2.50` has scale 2), or
    /// `None` when no [`Decimal`] holds it exactly.
    #[must_use]
    pub fn decimal(&self) -> Option<Decimal> {
        let frac = self.frac_bytes().unwrap_or_default();
        let int = self.int_bytes();
        // The usual case without an allocation: at most 28 decimals and a
        // mantissa below 2^96.
        let mut mantissa: u128 = 0;
        let mut fits = frac.len() <= 28;
        for &b in int.iter().chain(frac) {
            match mantissa.checked_mul(10).and_then(|m| m.checked_add(u128::from(b - b'0'))) {
                Some(m) if m < (1 << 96) => mantissa = m,
                _ => {
                    fits = false;
                    break;
                }
            }
        }
        if fits {
            let scale = u32::try_from(frac.len()).ok()?;
            let signed = i128::try_from(mantissa).ok()?;
            let mut d = Decimal::try_from_i128_with_scale(signed, scale).ok()?;
            d.set_sign_negative(self.negative);
            return Some(d);
        }
        // Beyond that, `from_str_exact` decides (it may still hold the
        // value by dropping trailing zeros, or refuse to round).
        let mut s = String::with_capacity(int.len() + frac.len() + 3);
        if self.negative {
            s.push('-');
        }
        s.push_str(if int.is_empty() { "0" } else { ascii(int) });
        if !frac.is_empty() {
            s.push('.');
            s.push_str(ascii(frac));
        }
        Decimal::from_str_exact(&s).ok()
    }

    /// The value in units of 10^-`decimals` (least increments), exactly,
    /// by integer arithmetic: `Some(Some(v))`; `Some(None)` when the value
    /// is finer than that; `None` when it has too many digits for this
    /// shortcut (more than 18 with the decimals), which [`Number::decimal`]
    /// then decides.
    #[must_use]
    pub fn scaled(&self, decimals: u32) -> Option<Option<i64>> {
        let d = decimals as usize;
        if let Some(short) =
            scaled_short(self.int_bytes(), self.frac_bytes().unwrap_or_default(), self.negative, d)
        {
            return Some(short);
        }
        let (int, frac) = self.significant();
        if frac.len() > d {
            return Some(None);
        }
        if int.len() + d > 18 {
            return None;
        }
        // At most 18 digits in all: no overflow.
        let v = digits_value(int, frac) * POW10[d - frac.len()];
        Some(Some(if self.negative { -v } else { v }))
    }

    /// The value times 10^`scale`, when that is a whole number that an
    /// `i128` holds (digits finer than 10^-`scale` give `None`, as does a
    /// value of more than 38 digits). `75.10` with scale 1 is 751.
    #[must_use]
    pub fn exact(&self, scale: u32) -> Option<i128> {
        let (int, frac) = self.significant();
        let d = scale as usize;
        if frac.len() > d {
            return None;
        }
        if int.len() + d <= 18 {
            // At most 18 digits: an i64 holds them (the usual case: G
            // codes, leads).
            let v = i128::from(digits_value(int, frac) * POW10[d - frac.len()]);
            return Some(if self.negative { -v } else { v });
        }
        let mut v: i128 = 0;
        for b in int.iter().copied().chain((0..d).map(|i| frac.get(i).copied().unwrap_or(b'0'))) {
            v = v.checked_mul(10)?.checked_add(i128::from(b - b'0'))?;
        }
        Some(if self.negative { -v } else { v })
    }

    /// True when the value is greater than zero (as [`Number::decimal`]
    /// compared with zero: a value no `Decimal` holds is not).
    #[must_use]
    pub fn is_positive(&self) -> bool {
        // Up to 19 digits and a point, `decimal` always holds the value.
        if self.digits.len() <= 20 {
            !self.negative && self.digits.iter().any(|b| matches!(b, b'1'..=b'9'))
        } else {
            self.decimal().is_some_and(|d| d > Decimal::ZERO)
        }
    }

    /// The digits before the point without leading zeros and the digits
    /// after it without trailing zeros.
    fn significant(&self) -> (&'a [u8], &'a [u8]) {
        let b = self.digits;
        let (mut int, mut frac): (&[u8], &[u8]) = match self.point {
            Some(p) => (b.get(..p as usize).unwrap_or_default(), b.get(p as usize + 1..).unwrap_or_default()),
            None => (b, &[]),
        };
        while let [b'0', rest @ ..] = int {
            int = rest;
        }
        while let [rest @ .., b'0'] = frac {
            frac = rest;
        }
        (int, frac)
    }

    /// The value when it is a whole number (a decimal point followed only by
    /// zeros counts as whole).
    #[must_use]
    pub fn integer(&self) -> Option<i64> {
        let (int, frac) = self.significant();
        if !frac.is_empty() {
            return None;
        }
        let mut v: i64 = 0;
        for &b in int {
            v = v.checked_mul(10)?.checked_add(i64::from(b - b'0'))?;
        }
        Some(if self.negative { -v } else { v })
    }
}

/// An address letter and its number.
///
/// A word is its text and its letter (24 bytes, so that a block's words sit
/// inline and move cheaply); its [`Number`] is read from the text when it is
/// asked for. Two words are equal when their letters and texts are (where
/// the lexer found the number is not part of a word's value).
#[derive(Clone, Copy)]
pub struct Word<'a> {
    /// The address, upper case.
    pub letter: char,
    /// The word as written, from its letter to its last digit (spaces
    /// between the letter and the number kept): ASCII, kept as bytes (the
    /// lexer need not make a `str` of its line).
    pub(super) raw: &'a [u8],
    /// Where the number's digits start in `raw` (after the spaces and the
    /// sign), or [`SLOW`] when `raw` is too long for a byte: the lexer
    /// knows it, so [`Word::number`] need not look again. These three
    /// fields fill what would be padding: a word stays 24 bytes.
    pub(super) at: u8,
    /// Where the decimal point is in the digits, or [`SLOW`] for none.
    pub(super) point: u8,
    /// A leading minus sign.
    pub(super) negative: bool,
}

impl PartialEq for Word<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.letter == other.letter && self.raw == other.raw
    }
}

impl Eq for Word<'_> {}

impl std::fmt::Debug for Word<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Word").field("letter", &self.letter).field("raw", &ascii(self.raw)).finish()
    }
}

/// 10^k for k up to 18.
pub(crate) const POW10: [i64; 19] = {
    let mut p = [1_i64; 19];
    let mut k = 1;
    while k < 19 {
        p[k] = p[k - 1] * 10;
        k += 1;
    }
    p
};

/// `bytes`, ASCII by construction (a word's text, a number's digits), as
/// a `str`.
fn ascii(bytes: &[u8]) -> &str {
    std::str::from_utf8(bytes).unwrap_or_default()
}

impl std::fmt::Debug for Number<'_> {
    /// The digits as text (they are kept as bytes).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Number")
            .field("negative", &self.negative)
            .field("digits", &ascii(self.digits))
            .field("point", &self.point)
            .finish()
    }
}

/// The value of the decimal digits `int` then `frac` read as one whole
/// number (the point dropped): the one reading of a number's digits of the
/// fast paths (lengths, leads, scaled values). Its callers pass at most 18
/// digits in all, so it cannot overflow. Two loops, not a chained iterator,
/// whose fold was not inlined (issue 33: 70 instructions an axis word).
#[inline(always)]
pub(crate) fn digits_value(int: &[u8], frac: &[u8]) -> i64 {
    let mut v = 0_i64;
    for &b in int {
        v = v * 10 + i64::from(b - b'0');
    }
    for &b in frac {
        v = v * 10 + i64::from(b - b'0');
    }
    v
}

/// [`Number::scaled`] of the digits `int` `.` `frac` (leading and trailing
/// zeros included) when they are short enough to need no care: at most 18
/// digits, and at most 18 once scaled by 10^`d` (so no overflow); `None`
/// otherwise, for the caller's longer way (which drops the zeros first).
/// The one shortcut of [`Number::scaled`] and [`Word::scaled`].
#[inline]
fn scaled_short(int: &[u8], frac: &[u8], negative: bool, d: usize) -> Option<Option<i64>> {
    if int.len() + frac.len() > 18 || int.len() + d > 18 {
        return None;
    }
    let v = digits_value(int, frac);
    let v = if frac.len() <= d {
        v * POW10[d - frac.len()]
    } else if v % POW10[frac.len() - d] == 0 {
        // Finer digits that are all zeros (`1.50000`, d = 3).
        v / POW10[frac.len() - d]
    } else {
        return Some(None);
    };
    Some(Some(if negative { -v } else { v }))
}

/// A word's number as [`Word::parts`] gives it: the sign, the digits before
/// the point, and those after it (`None` for no point).
pub(crate) type Parts<'a> = (bool, &'a [u8], Option<&'a [u8]>);

/// "Not known": see [`Word`].
pub(super) const SLOW: u8 = u8::MAX;

impl<'a> Word<'a> {
    /// A word from `raw`, the text it was read from: an address letter,
    /// perhaps spaces or tabs, a sign, digits with at most one `.`.
    #[must_use]
    pub fn new(letter: char, raw: &'a str) -> Word<'a> {
        Word { letter, raw: raw.as_bytes(), at: SLOW, point: SLOW, negative: false }
    }

    /// The value.
    #[must_use]
    #[inline]
    pub fn number(&self) -> Number<'a> {
        if self.at != SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            let point = (self.point != SLOW).then_some(u32::from(self.point));
            return Number { negative: self.negative, digits, point };
        }
        self.number_slow()
    }

    /// [`Word::number`] read from the text (a word made by [`Word::new`],
    /// or one too long for the lexer's offsets).
    fn number_slow(&self) -> Number<'a> {
        let rest = ascii(self.raw.get(1..).unwrap_or_default()).trim_start_matches([' ', '\t']);
        match rest.as_bytes().first() {
            Some(b'-') => Number::new(true, rest.get(1..).unwrap_or_default()),
            Some(b'+') => Number::new(false, rest.get(1..).unwrap_or_default()),
            _ => Number::new(false, rest),
        }
    }

    /// The sign, the digits before the point and those after it (`None`
    /// for no point) where the lexer found them, or `None` for a word whose
    /// offsets it did not keep ([`SLOW`]): the caller then reads
    /// [`Word::number`].
    #[inline(always)]
    pub(crate) fn parts(&self) -> Option<Parts<'a>> {
        if self.at == SLOW {
            return None;
        }
        let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
        if self.point == SLOW {
            return Some((self.negative, digits, None));
        }
        let p = usize::from(self.point);
        Some((
            self.negative,
            digits.get(..p).unwrap_or_default(),
            Some(digits.get(p + 1..).unwrap_or_default()),
        ))
    }

    /// [`Number::scaled`] of [`Word::number`], without making the number
    /// on the usual path (where the lexer found the digits and the point).
    #[inline]
    pub(crate) fn scaled(&self, decimals: u32) -> Option<Option<i64>> {
        if self.at != SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            let (int, frac): (&[u8], &[u8]) = if self.point == SLOW {
                (digits, &[])
            } else {
                let p = usize::from(self.point);
                (digits.get(..p).unwrap_or_default(), digits.get(p + 1..).unwrap_or_default())
            };
            if let Some(short) = scaled_short(int, frac, self.negative, decimals as usize) {
                return Some(short);
            }
        }
        self.number().scaled(decimals)
    }

    /// [`Number::integer`] of [`Word::number`], without making the number
    /// for a word of at most 18 digits without a point (a G or M code).
    #[inline(always)]
    pub(crate) fn integer(&self) -> Option<i64> {
        if self.at != SLOW && self.point == SLOW {
            let digits = self.raw.get(usize::from(self.at)..).unwrap_or_default();
            if digits.len() <= 18 {
                let mut v = 0_i64;
                for &b in digits {
                    v = v * 10 + i64::from(b - b'0');
                }
                return Some(if self.negative { -v } else { v });
            }
        }
        self.number().integer()
    }

    /// True when the word's number has a decimal point.
    #[inline]
    pub(crate) fn has_point(&self) -> bool {
        if self.at == SLOW {
            self.number().has_point()
        } else {
            self.point != SLOW
        }
    }

    /// The word as written, without the spaces inside it (for messages).
    #[must_use]
    pub fn text(&self) -> Cow<'a, str> {
        let raw = ascii(self.raw);
        if raw.bytes().any(|b| b == b' ' || b == b'\t') {
            Cow::Owned(raw.chars().filter(|c| !c.is_whitespace()).collect())
        } else {
            Cow::Borrowed(raw)
        }
    }
}
