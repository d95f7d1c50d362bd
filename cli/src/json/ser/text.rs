//! The bytes of JSON text: strings escaped as `serde_json` escapes them,
//! integers, and the line breaks of the pretty layout.

use crate::format::{encode_fixed, FIXED_BUF};

/// The size of the fixed copies: a line prefix of up to this many bytes is
/// copied as a block of this size, then cut to length.
pub(super) const CHUNK: usize = 64;

/// `,`, a line break and the indentation of levels up to 63: a line prefix
/// is a slice of it (without the comma for the first element).
pub(super) const LINE: [u8; 130] = {
    let mut line = [b' '; 130];
    line[0] = b',';
    line[1] = b'\n';
    line
};

/// What a byte becomes in a JSON string: 0 itself; `u` the `\u00XX` form;
/// any other the letter after the backslash (serde_json's table: the
/// controls, `"` and `\`; DEL and non-ASCII bytes pass through).
static ESCAPE: [u8; 256] = {
    let mut table = [0_u8; 256];
    let mut b = 0;
    while b < 0x20 {
        table[b] = b'u';
        b += 1;
    }
    table[0x08] = b'b';
    table[0x09] = b't';
    table[0x0A] = b'n';
    table[0x0C] = b'f';
    table[0x0D] = b'r';
    table[b'"' as usize] = b'"';
    table[b'\\' as usize] = b'\\';
    table
};

/// Whether some byte of `s` needs an escape (below 0x20, `"` or `\`):
/// eight bytes a step, then the rest one by one.
#[inline]
pub(super) fn needs_escape(s: &[u8]) -> bool {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let mut chunks = s.chunks_exact(8);
    for chunk in &mut chunks {
        let mut word = [0; 8];
        word.copy_from_slice(chunk);
        let v = u64::from_le_bytes(word);
        // A byte of x below n (n ≤ 0x80) sets its high bit in
        // (x - n·ONES) & !x & HIGH; a byte equal to c is a zero byte of
        // x ^ c·ONES, below 1. A borrow only runs on from a byte that is
        // itself found, so no byte is found wrongly.
        let quote = v ^ (ONES * u64::from(b'"'));
        let backslash = v ^ (ONES * u64::from(b'\\'));
        let found = (v.wrapping_sub(ONES * 0x20) & !v)
            | (quote.wrapping_sub(ONES) & !quote)
            | (backslash.wrapping_sub(ONES) & !backslash);
        if found & HIGH != 0 {
            return true;
        }
    }
    chunks.remainder().iter().any(|&b| ESCAPE[usize::from(b)] != 0)
}

/// Appends the contents of a JSON string for `s` (without the quotes).
#[inline(always)]
pub(super) fn push_contents(buf: &mut Vec<u8>, s: &[u8]) {
    if needs_escape(s) {
        push_escaped(buf, s);
    } else {
        buf.extend_from_slice(s);
    }
}

/// The slow path of [`push_contents`]: runs without an escape are copied
/// whole, each escape written as serde_json writes it.
#[cold]
fn push_escaped(buf: &mut Vec<u8>, s: &[u8]) {
    const HEX: &[u8; 16] = b"0123456789abcdef";
    let mut start = 0;
    for (i, &b) in s.iter().enumerate() {
        let escape = ESCAPE[usize::from(b)];
        if escape == 0 {
            continue;
        }
        buf.extend_from_slice(&s[start..i]);
        start = i + 1;
        if escape == b'u' {
            buf.extend_from_slice(&[
                b'\\',
                b'u',
                b'0',
                b'0',
                HEX[usize::from(b >> 4)],
                HEX[usize::from(b & 0xF)],
            ]);
        } else {
            buf.extend_from_slice(&[b'\\', escape]);
        }
    }
    buf.extend_from_slice(&s[start..]);
}

/// Appends the decimal text of `mag`, with `-` when `negative`, as
/// serde_json writes integers (two digits a step, [`encode_fixed`]).
#[inline]
pub(super) fn push_integer(buf: &mut Vec<u8>, negative: bool, mag: u64) {
    if !negative && mag < 10 {
        // mag < 10: one digit.
        #[allow(clippy::cast_possible_truncation)]
        buf.push(b'0' + mag as u8);
    } else {
        let mut digits = [0; FIXED_BUF];
        buf.extend_from_slice(encode_fixed(&mut digits, negative, mag, 0));
    }
}

/// Appends `,` when `comma`, a line break and the indentation of `level`
/// levels of two spaces: one copy of fixed size up to 31 levels.
#[inline(always)]
pub(super) fn push_line_break(buf: &mut Vec<u8>, comma: bool, level: usize) {
    let skip = usize::from(!comma);
    let end = 2 + 2 * level;
    if end <= CHUNK {
        // A copy of fixed size, then cut: the length is hidden from the
        // optimizer, which would otherwise make the copy one of variable
        // size (a call of `memcpy` for a few bytes).
        let at = buf.len();
        buf.extend_from_slice(&LINE[skip..skip + CHUNK]);
        buf.truncate(std::hint::black_box(at + end - skip));
    } else if end <= LINE.len() {
        buf.extend_from_slice(&LINE[skip..end]);
    } else {
        buf.extend_from_slice(&LINE[skip..2]);
        (0..level).for_each(|_| buf.extend_from_slice(b"  "));
    }
}
