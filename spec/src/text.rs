//! Decimal text of integers and fixed-point values, without `core::fmt`:
//! the one formatter of the nc writer's numbers (`cycleref-cli`'s
//! `format::put_fixed`) and of the `nc` headings' counts
//! ([`Heading`](crate::cycles::Heading)).

/// Room for any number [`put_fixed`] or [`encode_fixed`] writes: 20
/// digits, a point and a sign, with decimals up to 40.
pub const FIXED_BUF: usize = 64;

/// The decimal pairs `00` to `99`, for writing two digits a step.
const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// Writes the two digits of `d < 100` before `buf[i]`; returns the new start.
#[inline]
fn pair_before(buf: &mut [u8], i: usize, d: u64) -> usize {
    // d < 100 by the callers, so the index is below 200.
    #[allow(clippy::cast_possible_truncation)]
    let at = 2 * (d as usize);
    buf[i - 2..i].copy_from_slice(&PAIRS[at..at + 2]);
    i - 2
}

/// The length of the text [`put_fixed`] writes: the sign, the digits of
/// `mag` (at least `decimals + 1` of them: a zero before the point) and
/// the point when `decimals > 0`. `decimals` is at most 40.
///
/// ```
/// use cycleref_spec::text::fixed_len;
///
/// // `-22.868`: a sign, five digits and the point.
/// assert_eq!(fixed_len(true, 22_868, 3), 7);
/// // `0.005`: a zero before the point, then three decimals.
/// assert_eq!(fixed_len(false, 5, 3), 5);
/// ```
#[inline]
#[must_use]
pub fn fixed_len(negative: bool, mag: u64, decimals: u32) -> usize {
    let decimals = decimals.min(40);
    let digits = (mag.checked_ilog10().unwrap_or(0) + 1).max(decimals + 1);
    usize::from(negative) + digits as usize + usize::from(decimals > 0)
}

/// Fills `out`, exactly [`fixed_len`] bytes long, with the text of `mag /
/// 10^decimals` (a leading `-` when `negative`), from its end: two digits
/// a step.
#[inline]
fn fill_fixed(out: &mut [u8], negative: bool, mut mag: u64, decimals: u32) {
    let mut i = out.len();
    let decimals = decimals.min(40);
    let mut left = decimals;
    while left >= 2 {
        i = pair_before(out, i, mag % 100);
        mag /= 100;
        left -= 2;
    }
    if left == 1 {
        i -= 1;
        out[i] = b'0' + (mag % 10) as u8;
        mag /= 10;
    }
    if decimals > 0 {
        i -= 1;
        out[i] = b'.';
    }
    while mag >= 100 {
        i = pair_before(out, i, mag % 100);
        mag /= 100;
    }
    if mag >= 10 {
        pair_before(out, i, mag);
    } else {
        out[i - 1] = b'0' + mag as u8;
    }
    if negative {
        out[0] = b'-';
    }
}

/// The eight decimal digits of `n < 10^8`, leading zeros included, as the
/// bytes of a little-endian word: the most significant digit in the lowest
/// byte (first in memory), each byte 0 to 9. Four lanes at a time, with
/// no division: `n / 10^4` and `n % 10^4` in two 32-bit lanes, each split
/// by `x · 10486 >> 20 = ⌊x / 100⌋` (exact for `x < 10^4`) into two 16-bit
/// lanes, each of those by `y · 103 >> 10 = ⌊y / 10⌋` (exact for `y <
/// 100`) into two bytes. No product crosses its lane: `x · 10486 < 2^27`,
/// `y · 103 < 2^14`.
#[inline]
fn digits8(n: u32) -> u64 {
    let v = u64::from(n / 10_000) | (u64::from(n % 10_000) << 32);
    let q = ((v * 10_486) >> 20) & 0x0000_007F_0000_007F;
    let v = q | ((v - q * 100) << 16);
    let q = ((v * 103) >> 10) & 0x000F_000F_000F_000F;
    q | ((v - q * 10) << 8)
}

/// Writes `mag / 10^decimals` as text, with a leading `-` when `negative`,
/// at the start of `out`, and returns its length ([`fixed_len`], at most
/// [`FIXED_BUF`] − 2). `decimals` is at most 40. Bytes of `out` after the
/// text may be overwritten (up to 16 bytes from its start).
///
/// The nc writer's hot path: every coordinate of every move is written by
/// it straight into the output buffer. A magnitude below 10^8 with at
/// most 7 decimals (every length the increment systems and the programs'
/// ranges give) has its eight digits made at once, four lanes a step, and
/// written with two stores, the point between; a longer one, digit pairs
/// from the last.
///
/// # Panics
///
/// When `out` is shorter than 16 bytes or than the text (the callers keep
/// [`FIXED_BUF`] bytes of room).
///
/// ```
/// use cycleref_spec::text::{put_fixed, FIXED_BUF};
///
/// let mut out = [0_u8; FIXED_BUF];
/// // X-22.868 of a G32 move (IS-B, three decimals).
/// let len = put_fixed(&mut out, true, 22_868, 3);
/// assert_eq!(&out[..len], b"-22.868");
/// let len = put_fixed(&mut out, false, 5, 3);
/// assert_eq!(&out[..len], b"0.005");
/// // Beyond 10^8 or 7 decimals, the digit pairs.
/// let len = put_fixed(&mut out, false, 123_456_789_012, 4);
/// assert_eq!(&out[..len], b"12345678.9012");
/// ```
#[inline]
pub fn put_fixed(out: &mut [u8], negative: bool, mag: u64, decimals: u32) -> usize {
    if mag >= 100_000_000 || decimals > 7 {
        return put_fixed_long(out, negative, mag, decimals);
    }
    // mag < 10^8: the cast keeps it.
    #[allow(clippy::cast_possible_truncation)]
    let digits = digits8(mag as u32);
    // The significant digits, at least one before the point: 1 to 8.
    let zeros = if digits == 0 { 8 } else { digits.trailing_zeros() / 8 };
    let count = (8 - zeros).max(decimals + 1);
    // Those digits, in ASCII, from the lowest byte.
    let text = (digits | 0x3030_3030_3030_3030) >> (8 * (8 - count));
    out[0] = b'-';
    let s = usize::from(negative);
    out[s..s + 8].copy_from_slice(&text.to_le_bytes());
    if decimals == 0 {
        return s + count as usize;
    }
    // 1 to 7 digits before the point, 1 to 7 after: the point and the
    // decimals over the text from the point on.
    let whole = count - decimals;
    let fraction = ((text >> (8 * whole)) << 8) | u64::from(b'.');
    let at = s + whole as usize;
    out[at..at + 8].copy_from_slice(&fraction.to_le_bytes());
    s + count as usize + 1
}

/// [`put_fixed`] of any magnitude and up to 40 decimals: the length first,
/// then digit pairs from the last.
#[cold]
#[inline(never)]
fn put_fixed_long(out: &mut [u8], negative: bool, mag: u64, decimals: u32) -> usize {
    let len = fixed_len(negative, mag, decimals);
    fill_fixed(&mut out[..len], negative, mag, decimals);
    len
}

/// Writes `v` in decimal at the start of `out` ([`put_fixed`] with no
/// decimals); returns its length. One digit is written as it is (the
/// usual counts of headings and comments: passes, starts, layers,
/// plunges; issue 33).
///
/// # Panics
///
/// When `out` is shorter than 21 bytes.
///
/// ```
/// use cycleref_spec::text::put_integer;
///
/// let mut out = [0_u8; 32];
/// let len = put_integer(&mut out, 18_862);
/// assert_eq!(&out[..len], b"18862");
/// let len = put_integer(&mut out, 7);
/// assert_eq!(&out[..len], b"7");
/// ```
#[inline]
pub fn put_integer(out: &mut [u8], v: u64) -> usize {
    match u8::try_from(v) {
        Ok(digit @ 0..=9) => {
            out[0] = b'0' + digit;
            1
        }
        _ => put_fixed(out, false, v, 0),
    }
}

/// `mag / 10^decimals` as text, with a leading `-` when `negative`, written
/// at the end of `buf`; the text is returned. `decimals` is at most 40.
///
/// ```
/// use cycleref_spec::text::{encode_fixed, FIXED_BUF};
///
/// let mut buf = [0_u8; FIXED_BUF];
/// // Q1800 of a G76 block 2 at IS-B: Δd = 1.800.
/// assert_eq!(encode_fixed(&mut buf, false, 1_800, 3), b"1.800");
/// ```
#[inline]
pub fn encode_fixed(buf: &mut [u8; FIXED_BUF], negative: bool, mag: u64, decimals: u32) -> &[u8] {
    // By `put_fixed` (eight digits at once for the usual value) and one
    // copy to the end, not by the length first and digit pairs (issue 33:
    // the JSON writers' numbers).
    let mut text = [0; FIXED_BUF];
    let len = put_fixed(&mut text, negative, mag, decimals);
    let start = FIXED_BUF - len;
    buf[start..].copy_from_slice(&text[..len]);
    &buf[start..]
}

/// A short text built in place, without `core::fmt` and without an
/// allocation: the `nc` headings ([`Heading::text`](crate::cycles::Heading::text)).
/// What does not fit in its `N` bytes is left out (its writers keep their
/// texts shorter).
///
/// ```
/// use cycleref_spec::text::TextBuf;
///
/// let mut t = TextBuf::<64>::default();
/// t.put(b"G75.1 lines ");
/// t.integer(3);
/// t.put(b"-");
/// t.integer(4);
/// t.put(b": tool width I");
/// t.fixed(false, 3_000, 3);
/// assert_eq!(t.as_str(), Some("G75.1 lines 3-4: tool width I3.000"));
/// // What does not fit is left out.
/// let mut short = TextBuf::<4>::default();
/// short.put(b"G76");
/// short.put(b" P1");
/// assert_eq!(short.as_bytes(), b"G76");
/// ```
#[derive(Clone, Copy, Debug)]
pub struct TextBuf<const N: usize> {
    buf: [u8; N],
    len: usize,
}

impl<const N: usize> Default for TextBuf<N> {
    fn default() -> Self {
        TextBuf { buf: [0; N], len: 0 }
    }
}

impl<const N: usize> TextBuf<N> {
    /// Appends `bytes`.
    #[inline]
    pub fn put(&mut self, bytes: &[u8]) {
        if let Some(to) = self.buf.get_mut(self.len..self.len + bytes.len()) {
            to.copy_from_slice(bytes);
            self.len += bytes.len();
        }
    }

    /// Appends `v` in decimal ([`put_integer`]).
    #[inline]
    pub fn integer(&mut self, v: u64) {
        if let Some(to) = self.buf.get_mut(self.len..self.len + FIXED_BUF) {
            self.len += put_integer(to, v);
        } else {
            self.fixed(false, v, 0);
        }
    }

    /// Appends `mag / 10^decimals`, with a leading `-` when `negative`
    /// ([`put_fixed`]).
    #[inline]
    pub fn fixed(&mut self, negative: bool, mag: u64, decimals: u32) {
        // Straight into the buffer where it has room for any number (the
        // bytes after the text are not the text; issue 33: a number made
        // aside and copied was most of a heading).
        if let Some(to) = self.buf.get_mut(self.len..self.len + FIXED_BUF) {
            self.len += put_fixed(to, negative, mag, decimals);
            return;
        }
        let mut text = [0; FIXED_BUF];
        let len = put_fixed(&mut text, negative, mag, decimals);
        self.put(&text[..len]);
    }

    /// The text.
    #[must_use]
    pub fn as_bytes(&self) -> &[u8] {
        &self.buf[..self.len]
    }

    /// The text, when it is UTF-8 (whatever its writers appended was).
    #[must_use]
    pub fn as_str(&self) -> Option<&str> {
        std::str::from_utf8(self.as_bytes()).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::Strategy;

    /// The text of `mag / 10^decimals` by the standard library's integer
    /// formatting: the integer part and the fraction padded to `decimals`
    /// digits.
    fn reference(negative: bool, mag: u64, decimals: u32) -> String {
        // 10^20 > u64::MAX: from 20 decimals on, all of `mag` is fraction.
        let (int, frac) = match 10_u128.checked_pow(decimals) {
            Some(p) if decimals < 20 => (u128::from(mag) / p, u128::from(mag) % p),
            _ => (0, u128::from(mag)),
        };
        let sign = if negative { "-" } else { "" };
        if decimals == 0 {
            format!("{sign}{int}")
        } else {
            format!("{sign}{int}.{frac:0width$}", width = decimals as usize)
        }
    }

    fn put(negative: bool, mag: u64, decimals: u32) -> String {
        let mut out = [0xAA_u8; FIXED_BUF];
        let len = put_fixed(&mut out, negative, mag, decimals);
        assert_eq!(len, fixed_len(negative, mag, decimals), "{negative} {mag} {decimals}");
        String::from_utf8(out[..len].to_vec()).unwrap()
    }

    #[test]
    fn digits8_are_the_eight_digits() {
        // 12345678: the most significant digit in the lowest byte.
        assert_eq!(digits8(12_345_678).to_le_bytes(), [1, 2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(digits8(0), 0);
        assert_eq!(digits8(99_999_999).to_le_bytes(), [9; 8]);
        assert_eq!(digits8(10_000).to_le_bytes(), [0, 0, 0, 1, 0, 0, 0, 0]);
    }

    /// Every value of the fast path's edges, every decimal count, both
    /// signs: the digit counts 1 to 20 around each power of ten, zero
    /// (negative zero too, written `-0.000` as the long path writes it),
    /// and the long path's widest text.
    #[test]
    fn put_fixed_matches_the_standard_formatting_at_the_edges() {
        let mut values = vec![0_u64, 1, 9, 99_999_999, 100_000_000, 100_000_001, u64::MAX, u64::MAX - 1];
        for k in 1..20 {
            let p = 10_u64.pow(k);
            values.extend([p - 1, p, p + 1, p.saturating_mul(5)]);
        }
        for &mag in &values {
            for decimals in 0..=40_u32 {
                for negative in [false, true] {
                    assert_eq!(put(negative, mag, decimals), reference(negative, mag, decimals));
                }
            }
        }
        assert_eq!(put(true, u64::MAX, 40), "-0.0000000000000000000018446744073709551615");
        assert_eq!(put(false, 64_400, 3), "64.400");
        assert_eq!(put(true, 5, 3), "-0.005");
        assert_eq!(put(false, 0, 5), "0.00000");
        let mut out = [0; 21];
        let len = put_integer(&mut out, u64::MAX);
        assert_eq!(&out[..len], b"18446744073709551615");
    }

    proptest::proptest! {
        /// [`put_fixed`] (both paths) and [`encode_fixed`] against the
        /// standard library's formatting of the exact integer and scale:
        /// any magnitude, magnitudes of each digit count below 10^9 (the
        /// fast path and its edge), 0 to 40 decimals, both signs.
        #[test]
        fn put_fixed_is_the_standard_formatting(
            mag in proptest::prop_oneof![
                proptest::prelude::any::<u64>(),
                0_u64..1_000,
                0_u64..100_000,
                0_u64..1_000_000_000,
                (0_u32..64).prop_map(|shift| u64::MAX >> shift),
            ],
            decimals in proptest::prop_oneof![0_u32..=8, 0_u32..=40],
            negative in proptest::prelude::any::<bool>(),
        ) {
            let want = reference(negative, mag, decimals);
            proptest::prop_assert_eq!(put(negative, mag, decimals), want.clone());
            let mut buf = [0; FIXED_BUF];
            proptest::prop_assert_eq!(
                std::str::from_utf8(encode_fixed(&mut buf, negative, mag, decimals)).unwrap(),
                want.as_str()
            );
        }
    }
}
