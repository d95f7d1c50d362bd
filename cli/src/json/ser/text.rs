//! The bytes of JSON text: the serializer's buffer, strings escaped as
//! `serde_json` escapes them, integers, and the line breaks of the pretty
//! layout.

use std::io;

use crate::format::{put_fixed, FIXED_BUF};

/// The serializer's output before it is handed to the writer: a block of
/// bytes and how many of them are written. Bytes past the written ones
/// may be overwritten freely, so a short piece of text of varying length
/// is written as a copy of fixed size of which only its length counts (a
/// line break with its indentation, a field's name and colon): a few
/// moves of registers instead of a call of `memcpy`.
pub(super) struct Buf {
    /// Always zeroed or written: `len` of them count.
    bytes: Vec<u8>,
    len: usize,
}

impl Buf {
    /// An empty buffer with room for `n` bytes (more when written).
    pub(super) fn with_capacity(n: usize) -> Buf {
        Buf { bytes: vec![0; n], len: 0 }
    }

    /// The written bytes.
    #[inline]
    pub(super) fn as_slice(&self) -> &[u8] {
        &self.bytes[..self.len]
    }

    /// The number of written bytes.
    #[inline]
    pub(super) fn len(&self) -> usize {
        self.len
    }

    /// Whether nothing is written.
    #[inline]
    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Forgets the written bytes (the room stays).
    #[inline]
    pub(super) fn clear(&mut self) {
        self.len = 0;
    }

    /// The bytes after the written ones, at least `n` of them.
    #[inline(always)]
    fn room(&mut self, n: usize) -> &mut [u8] {
        if self.bytes.len() - self.len < n {
            self.grow(n);
        }
        &mut self.bytes[self.len..]
    }

    /// Makes room for `n` more bytes: twice the room, or what is needed.
    #[cold]
    #[inline(never)]
    fn grow(&mut self, n: usize) {
        let size = (2 * self.bytes.len()).max(self.len + n);
        self.bytes.resize(size, 0);
    }

    /// Appends `b`.
    #[inline(always)]
    pub(super) fn push(&mut self, b: u8) {
        self.room(1)[0] = b;
        self.len += 1;
    }

    /// Appends `s`.
    #[inline(always)]
    pub(super) fn extend_from_slice(&mut self, s: &[u8]) {
        self.room(s.len())[..s.len()].copy_from_slice(s);
        self.len += s.len();
    }

    /// Appends the first `n` bytes of `chunk` (`n` ≤ `N`) by a copy of all
    /// of it.
    #[inline(always)]
    pub(super) fn extend_prefix<const N: usize>(&mut self, chunk: &[u8; N], n: usize) {
        self.room(N)[..N].copy_from_slice(chunk);
        self.len += n.min(N);
    }

    /// Appends `"name": ` (`"name":` when not `pretty`): one copy of
    /// `name` and of the quotes and colon around it when the name needs
    /// no escape (where the name is a constant, copies of fixed size).
    #[inline(always)]
    pub(super) fn key(&mut self, name: &[u8], pretty: bool) {
        if needs_escape(name) {
            self.push(b'"');
            push_escaped(self, name);
            self.extend_from_slice(if pretty { b"\": " } else { b"\":" });
            return;
        }
        let n = name.len();
        let room = self.room(n + 4);
        room[0] = b'"';
        room[1..=n].copy_from_slice(name);
        room[n + 1..n + 4].copy_from_slice(b"\": ");
        self.len += n + if pretty { 4 } else { 3 };
    }
}

impl Buf {
    /// Appends, in the pretty layout, `,` when `comma`, a line break and
    /// the indentation of `level`, and `"name": `: with one look for room
    /// and, where the name is a constant, copies of fixed size only.
    #[inline(always)]
    pub(super) fn pretty_field_start(&mut self, comma: bool, level: usize, name: &[u8]) {
        let skip = usize::from(!comma);
        let end = 2 + 2 * level;
        if end > CHUNK || needs_escape(name) {
            push_line_break(self, comma, level);
            self.key(name, true);
            return;
        }
        let n = name.len();
        let room = self.room(CHUNK + n + 4);
        room[..CHUNK].copy_from_slice(&LINE[skip..skip + CHUNK]);
        let at = end - skip;
        room[at] = b'"';
        room[at + 1..=at + n].copy_from_slice(name);
        room[at + n + 1..at + n + 4].copy_from_slice(b"\": ");
        self.len += at + n + 4;
    }

    /// Appends `s` between quotes (`s` needs no escape).
    #[inline(always)]
    pub(super) fn quoted(&mut self, s: &[u8]) {
        let n = s.len();
        let room = self.room(n + 2);
        room[0] = b'"';
        copy_short(&mut room[1..=n], s);
        room[n + 1] = b'"';
        self.len += n + 2;
    }
}

/// `dst.copy_from_slice(src)`; from 4 to 16 bytes (a length, a lead, a
/// role) as two copies of fixed size that overlap, not a call of `memcpy`.
#[inline(always)]
fn copy_short(dst: &mut [u8], src: &[u8]) {
    let n = src.len();
    if (8..=16).contains(&n) {
        dst[..8].copy_from_slice(&src[..8]);
        dst[n - 8..].copy_from_slice(&src[n - 8..]);
    } else if (4..8).contains(&n) {
        dst[..4].copy_from_slice(&src[..4]);
        dst[n - 4..].copy_from_slice(&src[n - 4..]);
    } else {
        dst.copy_from_slice(src);
    }
}

impl io::Write for Buf {
    fn write(&mut self, s: &[u8]) -> io::Result<usize> {
        self.extend_from_slice(s);
        Ok(s.len())
    }

    fn write_all(&mut self, s: &[u8]) -> io::Result<()> {
        self.extend_from_slice(s);
        Ok(())
    }

    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

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
#[inline(always)]
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
pub(super) fn push_contents(buf: &mut Buf, s: &[u8]) {
    if needs_escape(s) {
        push_escaped(buf, s);
    } else {
        buf.extend_from_slice(s);
    }
}

/// The slow path of [`push_contents`]: runs without an escape are copied
/// whole, each escape written as serde_json writes it.
#[cold]
pub(super) fn push_escaped(buf: &mut Buf, s: &[u8]) {
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
/// serde_json writes integers ([`put_fixed`]).
#[inline]
pub(super) fn push_integer(buf: &mut Buf, negative: bool, mag: u64) {
    if !negative && mag < 10 {
        // mag < 10: one digit.
        #[allow(clippy::cast_possible_truncation)]
        buf.push(b'0' + mag as u8);
    } else {
        let mut digits = [0; FIXED_BUF];
        let len = put_fixed(&mut digits, negative, mag, 0);
        buf.extend_from_slice(&digits[..len]);
    }
}

/// Appends `,` when `comma`, a line break and the indentation of `level`
/// levels of two spaces: one copy of fixed size up to 31 levels.
#[inline(always)]
pub(super) fn push_line_break(buf: &mut Buf, comma: bool, level: usize) {
    let skip = usize::from(!comma);
    let end = 2 + 2 * level;
    if end <= CHUNK {
        let mut chunk = [0; CHUNK];
        chunk.copy_from_slice(&LINE[skip..skip + CHUNK]);
        buf.extend_prefix(&chunk, end - skip);
    } else if end <= LINE.len() {
        buf.extend_from_slice(&LINE[skip..end]);
    } else {
        buf.extend_from_slice(&LINE[skip..2]);
        (0..level).for_each(|_| buf.extend_from_slice(b"  "));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Quoted texts of every length from 0 to 40, written one after the
    /// other (a fixed copy past the end must not spoil what follows), and
    /// a buffer grown from nothing.
    #[test]
    fn quoted_texts_and_field_starts_are_written_whole() {
        let mut buf = Buf::with_capacity(0);
        let mut want = Vec::new();
        let text: Vec<u8> = (0..40).map(|i| b'a' + (i % 26)).collect();
        for n in 0..=40 {
            buf.quoted(&text[..n]);
            want.push(b'"');
            want.extend_from_slice(&text[..n]);
            want.push(b'"');
            for level in [0, 1, 30, 31, 32, 70] {
                buf.pretty_field_start(n % 2 == 0, level, &text[..n]);
                if n % 2 == 0 {
                    want.push(b',');
                }
                want.push(b'\n');
                want.extend(std::iter::repeat_n(b' ', 2 * level));
                want.push(b'"');
                want.extend_from_slice(&text[..n]);
                want.extend_from_slice(b"\": ");
            }
        }
        assert_eq!(String::from_utf8_lossy(buf.as_slice()), String::from_utf8_lossy(&want));
    }
}
