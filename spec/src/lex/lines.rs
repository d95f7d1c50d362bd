//! Lines, comments and o-words: where a line ends (CR, LF or CR LF), a
//! LinuxCNC o-word line, where a comment ends, and trimming white space
//! off a block's text, all on bytes (a comment may hold another encoding
//! than UTF-8).

/// A LinuxCNC o-word line (reading R-SUBPROGRAM): `o` and a number or a
/// `<name>`, then its keyword (`sub`, `endsub`, `call`, `return`, …) and
/// the rest of the line, spaces before them skipped. The number is as
/// written (`0100` and `100` are one label, as `rs274` reads them); the
/// name is lower case (`rs274` reads `o<MySub>` and `o<mysub>` alike).
#[must_use]
pub fn oword(line: &[u8]) -> Option<(OLabel, &[u8], &[u8])> {
    let skip = |b: &[u8]| -> usize { b.iter().take_while(|c| matches!(c, b' ' | b'\t')).count() };
    let mut i = skip(line);
    if !matches!(line.get(i), Some(b'o' | b'O')) {
        return None;
    }
    i += 1;
    i += skip(&line[i..]);
    let label = match line.get(i) {
        Some(b'<') => {
            let end = i + 1 + line[i + 1..].iter().position(|&b| b == b'>')?;
            let name = std::str::from_utf8(&line[i + 1..end]).ok()?.to_ascii_lowercase();
            i = end + 1;
            OLabel::Name(name)
        }
        Some(b'0'..=b'9') => {
            let n = line[i..].iter().take_while(|b| b.is_ascii_digit()).count();
            let number = std::str::from_utf8(&line[i..i + n]).ok()?.parse::<u64>().ok()?;
            i += n;
            OLabel::Number(number)
        }
        _ => return None,
    };
    i += skip(&line[i..]);
    let k = line[i..].iter().take_while(|b| b.is_ascii_alphabetic()).count();
    Some((label, &line[i..i + k], &line[i + k..]))
}

/// The label of a LinuxCNC o-word.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum OLabel {
    /// `o100`.
    Number(u64),
    /// `o<name>`, lower case.
    Name(String),
}

impl std::fmt::Display for OLabel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OLabel::Number(n) => write!(f, "o{n}"),
            OLabel::Name(s) => write!(f, "o<{s}>"),
        }
    }
}

/// The first line of `rest` without its line end, and the bytes to skip
/// to the next line: a line ends at `\n`, `\r\n` or a `\r` not followed
/// by `\n` (reading R-LINEEND: CR, LF and CR LF are all line ends, as the
/// controls' editors write them).
///
/// ```
/// use cycleref_spec::lex::split_line;
/// assert_eq!(split_line(b"G00 X1\r\nG01"), (&b"G00 X1"[..], 8));
/// assert_eq!(split_line(b"G00 X1\rG01"), (&b"G00 X1"[..], 7));
/// assert_eq!(split_line(b"G00 X1\nG01"), (&b"G00 X1"[..], 7));
/// assert_eq!(split_line(b"G00 X1"), (&b"G00 X1"[..], 6));
/// ```
#[inline]
#[must_use]
pub fn split_line(rest: &[u8]) -> (&[u8], usize) {
    // memchr2: a line end is found many bytes a step (a byte loop here was
    // a sixth of the reader's time).
    match memchr::memchr2(b'\n', b'\r', rest) {
        Some(i) => (&rest[..i], i + line_end_len(rest, i)),
        None => (rest, rest.len()),
    }
}

/// The length of the line end (`\n` or `\r`) at `i` of `text`: 2 for
/// `\r\n`, else 1 (reading R-LINEEND).
#[inline(always)]
pub(super) fn line_end_len(text: &[u8], i: usize) -> usize {
    if text[i] == b'\r' && text.get(i + 1) == Some(&b'\n') {
        2
    } else {
        1
    }
}

/// Where a piece of whole lines may end in `buf` (the offset after its
/// last line end at or after `from`), or `None` when none is known yet: a
/// `\r` as the very last byte read may be the first half of a `\r\n`, so
/// it ends a line only at the end of the text (`eof`).
#[must_use]
pub fn last_line_end(buf: &[u8], from: usize, eof: bool) -> Option<usize> {
    let mut hay = buf.get(from..)?;
    loop {
        let i = memchr::memrchr2(b'\n', b'\r', hay)?;
        if hay[i] == b'\r' && from + i + 1 == buf.len() && !eof {
            hay = &hay[..i];
            continue;
        }
        return Some(from + i + 1);
    }
}

/// A line of the program.
#[derive(Clone, Copy, Debug)]
pub(super) struct Line<'a> {
    /// Offset of the line's first byte in the source.
    pub(super) start: usize,
    pub(super) bytes: &'a [u8],
}

pub(super) const FULL_SEMI: &[u8] = "；".as_bytes();
pub(super) const FULL_OPEN: &[u8] = "（".as_bytes();
const FULL_CLOSE: &[u8] = "）".as_bytes();

/// The offset after the comment that starts before `from`, whose bytes are
/// opaque: it ends at the first `)` or `）`. `None` when the comment is not
/// closed before the end of `line` or a line end (`\n`, `\r`): a line holds
/// none ([`split_line`]), and the lexer's reading of a line's first block
/// straight from the text (`Lexer::first_segment_fast`) stops there.
pub(super) fn comment_end(line: &[u8], from: usize) -> Option<usize> {
    // One table look-up a byte (issue 33); the bytes it marks decide.
    const STOP: [bool; 256] = {
        let mut t = [false; 256];
        t[b')' as usize] = true;
        t[0xEF] = true;
        t[b'\n' as usize] = true;
        t[b'\r' as usize] = true;
        t
    };
    let mut i = from;
    while let Some(&b) = line.get(i) {
        if STOP[usize::from(b)] {
            match b {
                b')' => return Some(i + 1),
                b'\n' | b'\r' => return None,
                _ if line[i..].starts_with(FULL_CLOSE) => return Some(i + FULL_CLOSE.len()),
                _ => {}
            }
        }
        i += 1;
    }
    None
}

/// The UTF-8 character at the start of `bytes`, if they start with one.
pub(super) fn decode(bytes: &[u8]) -> Option<char> {
    let len = match *bytes.first()? {
        b @ 0x00..=0x7F => return Some(char::from(b)),
        0xC2..=0xDF => 2,
        0xE0..=0xEF => 3,
        0xF0..=0xF4 => 4,
        _ => return None,
    };
    std::str::from_utf8(bytes.get(..len)?).ok()?.chars().next()
}

/// The UTF-8 character that ends `bytes`, if they end with one.
fn decode_last(bytes: &[u8]) -> Option<char> {
    if let Some(&b) = bytes.last().filter(|b| b.is_ascii()) {
        return Some(char::from(b));
    }
    (1..=4.min(bytes.len())).find_map(|n| {
        let tail = &bytes[bytes.len() - n..];
        std::str::from_utf8(tail).ok().and_then(|s| {
            let mut cs = s.chars();
            let c = cs.next_back()?;
            (c.len_utf8() == n).then_some(c)
        })
    })
}

/// `bytes` without leading and trailing white space (as `str::trim`).
#[inline]
pub(super) fn trim(bytes: &[u8]) -> &[u8] {
    // The usual block: neither end is white space (a printable ASCII
    // character is not).
    match (bytes.first(), bytes.last()) {
        (Some(f), Some(l)) if f.is_ascii_graphic() && l.is_ascii_graphic() => bytes,
        // A comment after a `;` and its space (`; (finish)`): the spaces
        // off its start, when a printable ASCII character follows them.
        (Some(b' '), Some(l)) if l.is_ascii_graphic() => {
            let i = bytes.iter().position(|&b| b != b' ').unwrap_or(bytes.len());
            match bytes.get(i) {
                Some(f) if f.is_ascii_graphic() => &bytes[i..],
                _ => trim_ends(bytes),
            }
        }
        _ => trim_ends(bytes),
    }
}

/// [`trim`] of text that may start or end with white space.
fn trim_ends(mut bytes: &[u8]) -> &[u8] {
    // The usual case: ASCII white space (as `char::is_whitespace`) at the
    // ends; the loops below take any other.
    let ascii_space = |b: &u8| matches!(b, b' ' | b'\t' | b'\n' | b'\x0b' | b'\x0c' | b'\r');
    while let [b, rest @ ..] = bytes {
        if !ascii_space(b) {
            break;
        }
        bytes = rest;
    }
    while let [rest @ .., b] = bytes {
        if !ascii_space(b) {
            break;
        }
        bytes = rest;
    }
    // Both ends ASCII (and not white space, after the loops above): no
    // other white space can stand at either end.
    if bytes.first().is_none_or(u8::is_ascii) && bytes.last().is_none_or(u8::is_ascii) {
        return bytes;
    }
    while let Some(c) = decode(bytes).filter(|c| c.is_whitespace()) {
        bytes = &bytes[c.len_utf8()..];
    }
    while let Some(c) = decode_last(bytes).filter(|c| c.is_whitespace()) {
        bytes = &bytes[..bytes.len() - c.len_utf8()];
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::trim;

    /// `trim` against `str::trim` (the definition it follows: white space
    /// as `char::is_whitespace`), on every pairing of a start and an end
    /// drawn from ASCII and other white space and text, ASCII or not.
    #[test]
    fn trim_is_str_trim() {
        let ends = ["", " ", "\t", "\r", "\u{3000}", "\u{a0}", " \u{3000} ", "\u{2003}\t"];
        let middles = ["", "G01 X1", "（注）", "\u{3000}", "X1\u{3000}Z2", "é", "a"];
        for start in ends {
            for middle in middles {
                for end in ends {
                    let text = format!("{start}{middle}{end}");
                    assert_eq!(trim(text.as_bytes()), text.trim().as_bytes(), "{text:?}");
                }
            }
        }
        // A comment after `; ` (the spaces off its start only), by hand.
        assert_eq!(trim(b" (finish 1)"), b"(finish 1)");
        assert_eq!(trim(b"   X1 (c)"), b"X1 (c)");
        assert_eq!(trim(b"   "), b"");
        // Bytes that are not UTF-8 stay (a GBK comment, reading R-ENCODING).
        assert_eq!(trim(b" (\xd6\xd0) "), b"(\xd6\xd0)");
        assert_eq!(trim(b"\xd6\xd0"), b"\xd6\xd0");
    }
}
