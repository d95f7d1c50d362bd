//! The bytes-out floor of `cycleref expand` nc (issue 33): a loop that
//! formats and writes as many moves, of the same shape, as an nc expansion
//! holds, with no program read and no cycle computed.
//!
//! [`Shape::of_nc`] counts the lines of an nc expansion (once, outside any
//! timing): the rapids (`G00 X… Z…`), the feeds (`G32|G33|G01 X… Z… F|K…`)
//! and every other line (comments, echoed blocks) with their bytes, and
//! takes the decimals of the coordinates and of the lead, the feed's G code
//! and the lead's word from the first move of each kind. [`write_floor`]
//! then writes that many lines: each move formatted from integers (a
//! varying X and Z, with the same decimals, a lead with the lead's), each
//! other line a constant comment, their bytes in total the same. The
//! `pipeline` binary runs it as a child (`pipeline --floor SHAPE`, stdout
//! to `/dev/null`), as it runs `cycleref expand`, and prints `expand nc /
//! floor`.

use std::fmt;
use std::io::{self, Write};
use std::str::FromStr;

/// What an nc expansion holds, line by line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Shape {
    /// `G00 X… Z…` (or `G0`, `G01`, `G1` without a lead) lines.
    pub rapids: u64,
    /// `G32|G33|G01 X… Z… F|K…` lines: a move with a lead or feed.
    pub feeds: u64,
    /// Every other line: comments, headings, echoed blocks.
    pub others: u64,
    /// The bytes of the other lines, line ends included.
    pub other_bytes: u64,
    /// Decimals of X and Z in the first move.
    pub decimals: u32,
    /// The G code of the first thread move (`G32`, `G33`), else of the
    /// first feed.
    pub feed_code: String,
    /// The word of the lead or feed (`F`, `K`).
    pub lead_word: char,
    /// Decimals of that word in the first thread move.
    pub lead_decimals: u32,
}

/// The decimals of a number's text (`64.400` → 3, `50` → 0).
fn decimals(number: &str) -> u32 {
    number.split_once('.').map_or(0, |(_, f)| u32::try_from(f.len()).unwrap_or(0))
}

/// Whether `word` is a letter and a number (`X-12.5`).
fn is_word(word: &str, letter: char) -> bool {
    word.strip_prefix(letter).is_some_and(|n| {
        let n = n.strip_prefix('-').unwrap_or(n);
        !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit() || b == b'.')
    })
}

impl Shape {
    /// Counts the lines of an nc expansion (see the module's
    /// documentation).
    #[must_use]
    pub fn of_nc(nc: &[u8]) -> Shape {
        let mut s = Shape {
            rapids: 0,
            feeds: 0,
            others: 0,
            other_bytes: 0,
            decimals: 3,
            feed_code: String::new(),
            lead_word: 'F',
            lead_decimals: 1,
        };
        let (mut seen_move, mut seen_thread) = (false, false);
        for raw in nc.split_inclusive(|&b| b == b'\n') {
            let line = std::str::from_utf8(raw).unwrap_or("").trim_end();
            let w: Vec<&str> = line.split_ascii_whitespace().collect();
            let code = w.first().copied().unwrap_or("");
            let moving = matches!(code, "G0" | "G00" | "G1" | "G01" | "G32" | "G33")
                && (w.len() == 3 || w.len() == 4)
                && is_word(w[1], 'X')
                && is_word(w[2], 'Z');
            let lead = w.get(3).filter(|l| moving && (is_word(l, 'F') || is_word(l, 'K')));
            if !moving || (w.len() == 4 && lead.is_none()) {
                s.others += 1;
                s.other_bytes += raw.len() as u64;
                continue;
            }
            if !seen_move {
                s.decimals = decimals(&w[1][1..]);
                seen_move = true;
            }
            match lead {
                None => s.rapids += 1,
                Some(l) => {
                    s.feeds += 1;
                    let thread = matches!(code, "G32" | "G33");
                    if s.feed_code.is_empty() || (thread && !seen_thread) {
                        s.feed_code = code.to_string();
                        s.lead_word = l.chars().next().unwrap_or('F');
                        s.lead_decimals = decimals(&l[1..]);
                        seen_thread |= thread;
                    }
                }
            }
        }
        if s.feed_code.is_empty() {
            s.feed_code = "G32".into();
        }
        s
    }

    /// All the lines.
    #[must_use]
    pub fn lines(&self) -> u64 {
        self.rapids + self.feeds + self.others
    }
}

/// `rapids,feeds,others,other_bytes,decimals,feed_code,lead_word,lead_decimals`:
/// the argument of `pipeline --floor`.
impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{},{},{},{},{},{},{},{}",
            self.rapids,
            self.feeds,
            self.others,
            self.other_bytes,
            self.decimals,
            self.feed_code,
            self.lead_word,
            self.lead_decimals
        )
    }
}

impl FromStr for Shape {
    type Err = String;

    fn from_str(s: &str) -> Result<Shape, String> {
        let f: Vec<&str> = s.split(',').collect();
        let bad = || format!("not a floor shape: `{s}`");
        if f.len() != 8 {
            return Err(bad());
        }
        let n = |i: usize| f[i].parse::<u64>().map_err(|_| bad());
        let d = |i: usize| f[i].parse::<u32>().ok().filter(|d| *d <= 9).ok_or_else(bad);
        let mut word = f[6].chars();
        let lead_word = word.next().filter(|_| word.next().is_none()).ok_or_else(bad)?;
        if !matches!(f[5], "G0" | "G00" | "G1" | "G01" | "G32" | "G33") {
            return Err(bad());
        }
        Ok(Shape {
            rapids: n(0)?,
            feeds: n(1)?,
            others: n(2)?,
            other_bytes: n(3)?,
            decimals: d(4)?,
            feed_code: f[5].to_string(),
            lead_word,
            lead_decimals: d(7)?,
        })
    }
}

/// Appends `v / 10^d` with `d` decimals (`-12345`, 3 → `-12.345`).
fn put_fixed(line: &mut Vec<u8>, v: i64, d: u32) {
    if v < 0 {
        line.push(b'-');
    }
    let u = v.unsigned_abs();
    let p = 10_u64.pow(d);
    let mut digits = [0_u8; 20];
    let mut i = digits.len();
    let mut int = u / p;
    loop {
        i -= 1;
        digits[i] = b'0' + (int % 10) as u8;
        int /= 10;
        if int == 0 {
            break;
        }
    }
    line.extend_from_slice(&digits[i..]);
    if d > 0 {
        line.push(b'.');
        let mut frac = u % p;
        let start = line.len();
        line.resize(start + d as usize, b'0');
        for k in (start..line.len()).rev() {
            line[k] = b'0' + (frac % 10) as u8;
            frac /= 10;
        }
    }
}

/// Writes the floor of `shape` to `out` through a 64 KiB `BufWriter` (the
/// command's): the rapids, the feeds, then the other lines. Returns the
/// bytes written.
///
/// # Errors
///
/// Any error of `out`.
pub fn write_floor<W: Write>(shape: &Shape, out: W) -> io::Result<u64> {
    let mut out = io::BufWriter::with_capacity(1 << 16, out);
    let mut bytes = 0_u64;
    let unit = 10_i64.pow(shape.decimals);
    let mut line = Vec::with_capacity(96);
    // X over 40 … 80 and Z over −60 … +10, in steps that are not round.
    let x = |i: u64| 40 * unit + i64::try_from(i.wrapping_mul(7_919) % 40_000).unwrap_or(0) * unit / 1_000;
    let z = |i: u64| 10 * unit - i64::try_from(i.wrapping_mul(104_729) % 70_000).unwrap_or(0) * unit / 1_000;
    for i in 0..shape.rapids {
        line.clear();
        line.extend_from_slice(b"G00 X");
        put_fixed(&mut line, x(i), shape.decimals);
        line.extend_from_slice(b" Z");
        put_fixed(&mut line, z(i), shape.decimals);
        line.push(b'\n');
        out.write_all(&line)?;
        bytes += line.len() as u64;
    }
    let lead_unit = 10_i64.pow(shape.lead_decimals);
    for i in 0..shape.feeds {
        line.clear();
        line.extend_from_slice(shape.feed_code.as_bytes());
        line.extend_from_slice(b" X");
        put_fixed(&mut line, x(i), shape.decimals);
        line.extend_from_slice(b" Z");
        put_fixed(&mut line, z(i), shape.decimals);
        line.push(b' ');
        let mut word = [0_u8; 4];
        line.extend_from_slice(shape.lead_word.encode_utf8(&mut word).as_bytes());
        put_fixed(
            &mut line,
            lead_unit + i64::try_from(i % 5).unwrap_or(0) * lead_unit / 2,
            shape.lead_decimals,
        );
        line.push(b'\n');
        out.write_all(&line)?;
        bytes += line.len() as u64;
    }
    // `others` comments of equal length (the first `rem` one byte longer),
    // `other_bytes` in all; at least `()` and the line end.
    if let Some(each) = shape.other_bytes.checked_div(shape.others) {
        let each = each.max(3);
        let rem = shape.other_bytes.saturating_sub(each * shape.others);
        let comment = |len: u64| {
            let mut c = vec![b'-'; usize::try_from(len).unwrap_or(3)];
            let n = c.len();
            (c[0], c[n - 2], c[n - 1]) = (b'(', b')', b'\n');
            c
        };
        let (long, short) = (comment(each + 1), comment(each));
        for i in 0..shape.others {
            let c = if i < rem { &long } else { &short };
            out.write_all(c)?;
            bytes += c.len() as u64;
        }
    }
    out.flush()?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    const NC: &str = "O0100
G50 X100 Z50
(G76 line 7: 4 rough + 2 finish passes x 1 start)
(rough 1 start 1 depth 1.800 cut 1.800)
G00 X64.400 Z8.961
G32 X64.400 Z-37.000 F6.0
G32 X70.400 Z-40.000 F6.0
G00 X80.000 Z-40.000
G00 X80.000 Z10.000
G00 X100 Z50
G01 X20.000 Z-0.5 F0.2
G01 Z-9.003
X24.004
G00 X22.5 Z-6.002
";

    #[test]
    fn counts_the_lines_of_an_expansion() {
        let s = Shape::of_nc(NC.as_bytes());
        assert_eq!((s.rapids, s.feeds, s.others), (5, 3, 6));
        assert_eq!(s.lines(), NC.lines().count() as u64);
        let other: u64 =
            ["O0100", "G50 X100 Z50", "G01 Z-9.003", "X24.004"].iter().map(|l| l.len() as u64 + 1).sum();
        let comments = NC.lines().filter(|l| l.starts_with('(')).map(|l| l.len() as u64 + 1).sum::<u64>();
        assert_eq!(s.other_bytes, other + comments);
        assert_eq!((s.decimals, s.feed_code.as_str(), s.lead_word, s.lead_decimals), (3, "G32", 'F', 1));
    }

    #[test]
    fn linuxcnc_shape() {
        let nc =
            "(pass 1)\nG00 X23.5400 Z1.9151\nG33 X21.5400 Z1.9151 K2.038235\nG33 X19.7000 Z-18.5644 K1.5\n";
        let s = Shape::of_nc(nc.as_bytes());
        assert_eq!((s.rapids, s.feeds, s.others), (1, 2, 1));
        assert_eq!((s.decimals, s.feed_code.as_str(), s.lead_word, s.lead_decimals), (4, "G33", 'K', 6));
    }

    #[test]
    fn argument_round_trip_and_refusals() {
        let s = Shape::of_nc(NC.as_bytes());
        assert_eq!(s.to_string().parse::<Shape>(), Ok(s.clone()));
        for bad in
            ["", "1,2,3", "1,2,3,4,3,G32,F", "1,2,3,4,3,G32,FF,1", "1,2,3,4,3,M30,F,1", "1,2,x,4,3,G32,F,1"]
        {
            assert!(bad.parse::<Shape>().is_err(), "{bad}");
        }
    }

    #[test]
    fn the_floor_has_the_shape_it_was_given() {
        for nc in [NC, "(pass 1)\nG00 X23.5400 Z1.9151\nG33 X21.5400 Z1.9151 K2.038235\n(a)\n"] {
            let s = Shape::of_nc(nc.as_bytes());
            let mut out = Vec::new();
            let n = write_floor(&s, &mut out).expect("writes");
            assert_eq!(n, out.len() as u64);
            assert_eq!(Shape::of_nc(&out), s, "{}", String::from_utf8_lossy(&out));
        }
        // A large shape: every line a move or a comment of the given bytes.
        let big = Shape {
            rapids: 5_000,
            feeds: 3_000,
            others: 777,
            other_bytes: 777 * 31 + 5,
            ..Shape::of_nc(NC.as_bytes())
        };
        let mut out = Vec::new();
        write_floor(&big, &mut out).expect("writes");
        assert_eq!(Shape::of_nc(&out), big);
    }

    #[test]
    fn fixed_point_text() {
        let text = |v, d| {
            let mut l = Vec::new();
            put_fixed(&mut l, v, d);
            String::from_utf8(l).expect("ascii")
        };
        assert_eq!(text(-12_345, 3), "-12.345");
        assert_eq!(text(64_400, 3), "64.400");
        assert_eq!(text(5, 4), "0.0005");
        assert_eq!(text(0, 0), "0");
        assert_eq!(text(2_038_235, 6), "2.038235");
    }
}
