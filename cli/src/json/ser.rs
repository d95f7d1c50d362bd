//! The JSON writer of `expand --format json` and `jsonl`: a serde
//! [`Serializer`](serde::Serializer) that writes what `serde_json` writes,
//! byte for byte — pretty (two spaces, `": "`, as [`super::Pretty`]) or
//! compact (as `serde_json::to_writer`) — for a fraction of its work.
//!
//! Where `serde_json`'s work went (callgrind, a 1 MB program, issue 11):
//! each key and each string value was three or four writes with every byte
//! scanned for escapes, a struct field six or seven writes, and each length
//! (`"64.400"`) was checked as UTF-8 to become a `&str`. Here:
//!
//! * the output is gathered in the serializer's own buffer and handed to
//!   the writer in blocks of 64 KiB (at the end of an element of an array
//!   or a value of a map), so a write is a copy into a `Vec`;
//! * the start of a struct field — comma, line break, indentation, the
//!   quoted name and `": "` — is made once per name and level and kept
//!   (`FieldStart`): a field's start is then one copy of fixed size (the
//!   names are `&'static str`, so the name's address and length are its
//!   identity);
//! * a line break with its indentation is one copy of fixed size too;
//! * a string is checked for escapes eight bytes a step and copied whole
//!   when it needs none (every string of the moves documents);
//! * lengths and leads ([`Fixed`], [`LeadText`]) serialize through
//!   `collect_str`, which every serializer writes as a string; this one
//!   writes their ASCII digits straight into its buffer (see
//!   `serialize_plain`), without `&str`, UTF-8 check or escape scan;
//! * integers are written two digits a step ([`encode_fixed`]).
//!
//! The whole serde data model is written as `serde_json` writes it (the
//! tests hold the two to the same bytes): floats by `serde_json` itself
//! (the moves documents have none); a map key JSON cannot have is refused
//! with `serde_json`'s words; errors convert into [`io::Error`] as
//! `serde_json`'s do.

use std::cell::Cell;
use std::fmt;
use std::io;

use serde::ser::{self, Serialize};

use crate::format::{encode_fixed, Fixed, LeadText, FIXED_BUF};

/// Writes `value` as pretty JSON, exactly as `serde_json` with
/// [`super::Pretty`] (or `serde_json::to_writer_pretty`) would.
///
/// # Errors
///
/// As [`JsonSerializer::write`].
pub fn to_writer_pretty<W: io::Write, T: ?Sized + Serialize>(out: W, value: &T) -> io::Result<()> {
    let mut ser = JsonSerializer::<W, true>::new(out);
    ser.write(value)?;
    ser.finish()
}

/// Writes `value` as compact JSON (no whitespace), exactly as
/// `serde_json::to_writer` would.
///
/// # Errors
///
/// As [`JsonSerializer::write`].
pub fn to_writer_compact<W: io::Write, T: ?Sized + Serialize>(out: W, value: &T) -> io::Result<()> {
    let mut ser = JsonSerializer::<W, false>::new(out);
    ser.write(value)?;
    ser.finish()
}

/// A failure of [`JsonSerializer`].
#[derive(Debug)]
pub enum Error {
    /// The writer failed.
    Io(io::Error),
    /// A [`Serialize`] implementation failed (`serde::ser::Error::custom`).
    Custom(String),
    /// A map key that JSON cannot have: not a string, an integer, a
    /// boolean, a char or a float (`serde_json`'s words).
    KeyMustBeAString,
    /// A float map key that is not finite (`serde_json`'s words).
    FloatKeyMustBeFinite,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Io(e) => fmt::Display::fmt(e, f),
            Error::Custom(m) => f.write_str(m),
            Error::KeyMustBeAString => f.write_str("key must be a string"),
            Error::FloatKeyMustBeFinite => f.write_str("float key must be finite (got NaN or +/-inf)"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl ser::Error for Error {
    #[cold]
    fn custom<T: fmt::Display>(msg: T) -> Error {
        Error::Custom(msg.to_string())
    }
}

impl From<io::Error> for Error {
    fn from(e: io::Error) -> Error {
        Error::Io(e)
    }
}

impl From<Error> for io::Error {
    /// A failure to write is returned as it came; any other error is
    /// [`io::ErrorKind::InvalidData`] with the error's message, as
    /// `serde_json`'s errors convert.
    fn from(e: Error) -> io::Error {
        match e {
            Error::Io(e) => e,
            other => io::Error::new(io::ErrorKind::InvalidData, other.to_string()),
        }
    }
}

type Result<T> = std::result::Result<T, Error>;

/// A text of ASCII digits, letters, `.` and `-`: nothing in it needs an
/// escape in JSON.
#[derive(Clone, Copy, Debug)]
pub(crate) enum PlainText {
    /// A length.
    Length(Fixed),
    /// A lead word.
    Lead(LeadText),
}

impl PlainText {
    fn encode(self, buf: &mut [u8; FIXED_BUF]) -> &[u8] {
        match self {
            PlainText::Length(f) => f.encode(buf),
            PlainText::Lead(l) => l.encode(buf),
        }
    }
}

thread_local! {
    /// The text offered by [`serialize_plain`] while it runs, with the
    /// address of the value it is the text of.
    static OFFERED: Cell<Option<(usize, PlainText)>> = const { Cell::new(None) };
}

/// The address of `value`, its identity while it is borrowed.
fn address_of<T: ?Sized>(value: &T) -> usize {
    std::ptr::from_ref(value).cast::<()>().addr()
}

/// Serializes `value`, whose `Display` is `text`, as a string with
/// `collect_str`: every serializer writes it as the string `value`
/// displays (`serde_json`, `serde_json::Value`, any other). While the call
/// runs `text` is offered, tagged with `value`'s address, and
/// [`JsonSerializer`]'s `collect_str` takes it: it writes the digits
/// without formatting machinery, UTF-8 check or escape scan.
pub(crate) fn serialize_plain<S: ser::Serializer, D: fmt::Display>(
    value: &D,
    text: PlainText,
    s: S,
) -> std::result::Result<S::Ok, S::Error> {
    OFFERED.set(Some((address_of(value), text)));
    let written = s.collect_str(value);
    OFFERED.set(None);
    written
}

/// The output is handed to the writer once the buffer holds this much (at
/// the end of an array's element or a map's value).
const FLUSH_AT: usize = 1 << 16;

/// The size of the fixed copies: a line prefix or a field start of up to
/// this many bytes is copied as a block of this size, then cut to length.
const CHUNK: usize = 64;

/// `,`, a line break and the indentation of levels up to 63: a line prefix
/// is a slice of it (without the comma for the first element).
const LINE: [u8; 130] = {
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
fn needs_escape(s: &[u8]) -> bool {
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
#[inline]
fn push_contents(buf: &mut Vec<u8>, s: &[u8]) {
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
/// serde_json writes integers.
#[inline]
fn push_integer(buf: &mut Vec<u8>, negative: bool, mag: u64) {
    if !negative && mag < 10 {
        // mag < 10: one digit.
        #[allow(clippy::cast_possible_truncation)]
        buf.push(b'0' + mag as u8);
    } else {
        let mut digits = [0; FIXED_BUF];
        buf.extend_from_slice(encode_fixed(&mut digits, negative, mag, 0));
    }
}

/// The start of a struct field, made once per name and level: `,`, in the
/// pretty form a line break and the indentation, then `"name": ` (`"name":`
/// compact). The first field of an object starts one byte later.
#[derive(Clone, Copy)]
struct FieldStart {
    /// The name's address and length (a `&'static str`: they identify it).
    name: (usize, usize),
    level: usize,
    len: usize,
    bytes: [u8; CHUNK],
}

/// A slot of the field-start table that holds nothing.
const NO_FIELD_START: FieldStart = FieldStart { name: (0, usize::MAX), level: 0, len: 0, bytes: [0; CHUNK] };

/// The number of slots of the field-start table (a power of two).
const FIELD_START_SLOTS: usize = 128;

/// The slot of a name's field start at a level.
#[inline]
fn field_start_slot(name: (usize, usize), level: usize) -> usize {
    let h = (name.0 ^ level.rotate_right(8)).wrapping_mul(0x9E37_79B9_7F4A_7C15_u64 as usize);
    h >> (usize::BITS - FIELD_START_SLOTS.trailing_zeros())
}

/// A serde [`Serializer`](serde::Serializer) writing JSON to `W`: pretty
/// when `PRETTY`, else compact. The output is gathered in a buffer and
/// handed to `W` in blocks: call [`JsonSerializer::finish`] at the end
/// (dropping it writes what is left too, ignoring a failure).
pub struct JsonSerializer<W: io::Write, const PRETTY: bool> {
    out: W,
    buf: Vec<u8>,
    /// The number of arrays and objects open.
    level: usize,
    field_starts: Box<[FieldStart; FIELD_START_SLOTS]>,
}

impl<W: io::Write, const PRETTY: bool> JsonSerializer<W, PRETTY> {
    /// A serializer writing to `out`.
    pub fn new(out: W) -> Self {
        JsonSerializer {
            out,
            buf: Vec::with_capacity(FLUSH_AT + 4096),
            level: 0,
            field_starts: Box::new([NO_FIELD_START; FIELD_START_SLOTS]),
        }
    }

    /// Serializes `value`.
    ///
    /// # Errors
    ///
    /// A failure to write, as it came; an error raised while serializing
    /// (a [`Serialize`] implementation's own, a map key that is not a
    /// string) as [`io::ErrorKind::InvalidData`] with its message, as
    /// `serde_json`'s errors convert into [`io::Error`].
    pub fn write<T: ?Sized + Serialize>(&mut self, value: &T) -> io::Result<()> {
        value.serialize(&mut *self)?;
        self.flush_if_full()
    }

    /// Serializes `value`, then a line break (a line of `jsonl`).
    ///
    /// # Errors
    ///
    /// As [`Self::write`].
    pub fn write_line<T: ?Sized + Serialize>(&mut self, value: &T) -> io::Result<()> {
        value.serialize(&mut *self)?;
        self.buf.push(b'\n');
        self.flush_if_full()
    }

    /// Hands what is left to the writer (the writer itself is not flushed).
    ///
    /// # Errors
    ///
    /// A failure to write.
    pub fn finish(mut self) -> io::Result<()> {
        self.flush()
    }

    fn flush(&mut self) -> io::Result<()> {
        let written = self.out.write_all(&self.buf);
        self.buf.clear();
        written
    }

    #[inline]
    fn flush_if_full(&mut self) -> io::Result<()> {
        if self.buf.len() >= FLUSH_AT {
            self.flush()
        } else {
            Ok(())
        }
    }

    /// Opens an array or object with `open` (`[` or `{`); `empty` closes it
    /// at once with `close`.
    #[inline]
    fn open(&mut self, open: u8, close: u8, empty: bool) -> Compound<'_, W, PRETTY> {
        if empty {
            self.buf.extend_from_slice(&[open, close]);
            return Compound { ser: self, state: State::Empty };
        }
        self.buf.push(open);
        self.level += 1;
        Compound { ser: self, state: State::First }
    }

    /// Closes what [`Self::open`] opened with `close`: in the pretty form
    /// on a line of its own when it has an element.
    #[inline]
    fn close(&mut self, state: State, close: u8) {
        if state == State::Empty {
            return;
        }
        self.level -= 1;
        if PRETTY && state == State::Rest {
            self.line_break(false);
        }
        self.buf.push(close);
    }

    /// Pretty form: `,` when `comma`, a line break and the indentation of
    /// this level.
    #[inline]
    fn line_break(&mut self, comma: bool) {
        let skip = usize::from(!comma);
        let end = 2 + 2 * self.level;
        if end <= CHUNK {
            let at = self.buf.len();
            self.buf.extend_from_slice(&LINE[skip..skip + CHUNK]);
            self.buf.truncate(at + end - skip);
        } else if end <= LINE.len() {
            self.buf.extend_from_slice(&LINE[skip..end]);
        } else {
            self.buf.extend_from_slice(&LINE[skip..2]);
            (0..self.level).for_each(|_| self.buf.extend_from_slice(b"  "));
        }
    }

    /// The start of an array's element: `,` unless `first`, and in the
    /// pretty form a line break and the indentation.
    #[inline]
    fn element_start(&mut self, first: bool) {
        if PRETTY {
            self.line_break(!first);
        } else if !first {
            self.buf.push(b',');
        }
    }

    /// The start of a field named `name`: `,` unless `first`, the line
    /// (pretty form), `"name"` and the colon.
    #[inline]
    fn field_start(&mut self, name: &'static str, first: bool) {
        let id = (name.as_ptr().addr(), name.len());
        let slot = field_start_slot(id, self.level);
        let start = &self.field_starts[slot];
        if start.name == id && start.level == self.level {
            let skip = usize::from(first);
            let at = self.buf.len();
            self.buf.extend_from_slice(&start.bytes[skip..skip + CHUNK - 1]);
            self.buf.truncate(at + start.len - skip);
        } else {
            self.new_field_start(name, first, slot);
        }
    }

    /// [`Self::field_start`] for a name not in the table: the start is
    /// made and kept, when it fits.
    #[inline(never)]
    fn new_field_start(&mut self, name: &'static str, first: bool, slot: usize) {
        let mut bytes = Vec::with_capacity(CHUNK);
        if PRETTY {
            let end = 2 + 2 * self.level;
            bytes.extend_from_slice(&LINE[..end.min(LINE.len())]);
            (LINE.len()..end).step_by(2).for_each(|_| bytes.extend_from_slice(b"  "));
            bytes.push(b'"');
            push_contents(&mut bytes, name.as_bytes());
            bytes.extend_from_slice(b"\": ");
        } else {
            bytes.extend_from_slice(b",\"");
            push_contents(&mut bytes, name.as_bytes());
            bytes.extend_from_slice(b"\":");
        }
        self.buf.extend_from_slice(&bytes[usize::from(first)..]);
        if bytes.len() <= CHUNK {
            let mut start = FieldStart {
                name: (name.as_ptr().addr(), name.len()),
                level: self.level,
                len: bytes.len(),
                bytes: [0; CHUNK],
            };
            start.bytes[..bytes.len()].copy_from_slice(&bytes);
            self.field_starts[slot] = start;
        }
    }

    /// `s` as a JSON string, quoted.
    #[inline]
    fn string(&mut self, s: &[u8]) {
        self.buf.reserve(s.len() + 2);
        self.buf.push(b'"');
        push_contents(&mut self.buf, s);
        self.buf.push(b'"');
    }

    /// `text` quoted: it needs no escape.
    #[inline]
    fn plain(&mut self, text: PlainText) {
        let mut digits = [0; FIXED_BUF];
        let len = text.encode(&mut digits).len();
        // The text is at the end of `digits`, with room before it (at
        // most 42 bytes) for the opening quote.
        let start = FIXED_BUF - len - 1;
        digits[start] = b'"';
        self.buf.extend_from_slice(&digits[start..]);
        self.buf.push(b'"');
    }

    /// `{"variant": ` — the opening of an enum variant with data.
    fn variant_open(&mut self, variant: &'static str) {
        self.buf.push(b'{');
        self.level += 1;
        self.field_start(variant, true);
    }

    /// The closing `}` of [`Self::variant_open`].
    fn variant_close(&mut self) {
        self.close(State::Rest, b'}');
    }

    /// A float, as serde_json writes it (`null` when not finite).
    fn float<F: Serialize>(&mut self, v: F) -> Result<()> {
        serde_json::to_writer(&mut self.buf, &v).map_err(|e| Error::Io(e.into()))
    }
}

impl<W: io::Write, const PRETTY: bool> Drop for JsonSerializer<W, PRETTY> {
    /// Hands what is left to the writer, as a dropped `BufWriter` does.
    fn drop(&mut self) {
        if !self.buf.is_empty() {
            let _ = self.flush();
        }
    }
}

/// How far an array or object is written.
#[derive(Clone, Copy, PartialEq, Eq)]
enum State {
    /// Opened and closed at once (its length was 0).
    Empty,
    /// Open, nothing in it yet.
    First,
    /// Open, with an element.
    Rest,
}

impl<'a, W: io::Write, const PRETTY: bool> ser::Serializer for &'a mut JsonSerializer<W, PRETTY> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Compound<'a, W, PRETTY>;
    type SerializeTuple = Compound<'a, W, PRETTY>;
    type SerializeTupleStruct = Compound<'a, W, PRETTY>;
    type SerializeTupleVariant = Compound<'a, W, PRETTY>;
    type SerializeMap = Compound<'a, W, PRETTY>;
    type SerializeStruct = Compound<'a, W, PRETTY>;
    type SerializeStructVariant = Compound<'a, W, PRETTY>;

    #[inline]
    fn serialize_bool(self, v: bool) -> Result<()> {
        self.buf.extend_from_slice(if v { b"true" } else { b"false" });
        Ok(())
    }

    fn serialize_i8(self, v: i8) -> Result<()> {
        self.serialize_i64(v.into())
    }

    fn serialize_i16(self, v: i16) -> Result<()> {
        self.serialize_i64(v.into())
    }

    fn serialize_i32(self, v: i32) -> Result<()> {
        self.serialize_i64(v.into())
    }

    #[inline]
    fn serialize_i64(self, v: i64) -> Result<()> {
        push_integer(&mut self.buf, v < 0, v.unsigned_abs());
        Ok(())
    }

    fn serialize_i128(self, v: i128) -> Result<()> {
        Ok(io::Write::write_fmt(&mut self.buf, format_args!("{v}"))?)
    }

    #[inline]
    fn serialize_u8(self, v: u8) -> Result<()> {
        self.serialize_u64(v.into())
    }

    #[inline]
    fn serialize_u16(self, v: u16) -> Result<()> {
        self.serialize_u64(v.into())
    }

    #[inline]
    fn serialize_u32(self, v: u32) -> Result<()> {
        self.serialize_u64(v.into())
    }

    #[inline]
    fn serialize_u64(self, v: u64) -> Result<()> {
        push_integer(&mut self.buf, false, v);
        Ok(())
    }

    fn serialize_u128(self, v: u128) -> Result<()> {
        Ok(io::Write::write_fmt(&mut self.buf, format_args!("{v}"))?)
    }

    fn serialize_f32(self, v: f32) -> Result<()> {
        self.float(v)
    }

    fn serialize_f64(self, v: f64) -> Result<()> {
        self.float(v)
    }

    fn serialize_char(self, v: char) -> Result<()> {
        self.serialize_str(v.encode_utf8(&mut [0; 4]))
    }

    #[inline]
    fn serialize_str(self, v: &str) -> Result<()> {
        self.string(v.as_bytes());
        Ok(())
    }

    /// An array of the bytes' values, as serde_json writes bytes.
    fn serialize_bytes(self, v: &[u8]) -> Result<()> {
        use ser::SerializeSeq as _;
        let mut seq = self.serialize_seq(Some(v.len()))?;
        for b in v {
            seq.serialize_element(b)?;
        }
        seq.end()
    }

    fn serialize_none(self) -> Result<()> {
        self.serialize_unit()
    }

    #[inline]
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<()> {
        value.serialize(self)
    }

    fn serialize_unit(self) -> Result<()> {
        self.buf.extend_from_slice(b"null");
        Ok(())
    }

    fn serialize_unit_struct(self, _name: &'static str) -> Result<()> {
        self.serialize_unit()
    }

    fn serialize_unit_variant(self, _name: &'static str, _index: u32, variant: &'static str) -> Result<()> {
        self.serialize_str(variant)
    }

    #[inline]
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _name: &'static str, value: &T) -> Result<()> {
        value.serialize(self)
    }

    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<()> {
        self.variant_open(variant);
        value.serialize(&mut *self)?;
        self.variant_close();
        Ok(())
    }

    #[inline]
    fn serialize_seq(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY>> {
        Ok(self.open(b'[', b']', len == Some(0)))
    }

    fn serialize_tuple(self, len: usize) -> Result<Compound<'a, W, PRETTY>> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_struct(self, _name: &'static str, len: usize) -> Result<Compound<'a, W, PRETTY>> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<Compound<'a, W, PRETTY>> {
        self.variant_open(variant);
        self.serialize_seq(Some(len))
    }

    #[inline]
    fn serialize_map(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY>> {
        Ok(self.open(b'{', b'}', len == Some(0)))
    }

    #[inline]
    fn serialize_struct(self, _name: &'static str, len: usize) -> Result<Compound<'a, W, PRETTY>> {
        self.serialize_map(Some(len))
    }

    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<Compound<'a, W, PRETTY>> {
        self.variant_open(variant);
        self.serialize_map(Some(len))
    }

    /// `value`'s text as a JSON string: the text `serialize_plain`
    /// offers for `value` as it is, any other escaped as it is displayed.
    #[inline]
    fn collect_str<T: ?Sized + fmt::Display>(self, value: &T) -> Result<()> {
        if let Some((at, text)) = OFFERED.get() {
            if at == address_of(value) {
                self.plain(text);
                return Ok(());
            }
        }
        self.display(value)
    }
}

impl<W: io::Write, const PRETTY: bool> JsonSerializer<W, PRETTY> {
    /// `value`'s `Display` as a JSON string, escaped as it is written.
    fn display<T: ?Sized + fmt::Display>(&mut self, value: &T) -> Result<()> {
        /// Escapes what `Display` writes.
        struct Escaping<'b>(&'b mut Vec<u8>);
        impl fmt::Write for Escaping<'_> {
            fn write_str(&mut self, s: &str) -> fmt::Result {
                push_contents(self.0, s.as_bytes());
                Ok(())
            }
        }
        self.buf.push(b'"');
        fmt::write(&mut Escaping(&mut self.buf), format_args!("{value}"))
            .map_err(|_| Error::Custom("a Display implementation returned an error".to_string()))?;
        self.buf.push(b'"');
        Ok(())
    }
}

/// An array or object being written (serde's `SerializeSeq`,
/// `SerializeMap`, `SerializeStruct` and the others).
pub struct Compound<'a, W: io::Write, const PRETTY: bool> {
    ser: &'a mut JsonSerializer<W, PRETTY>,
    state: State,
}

impl<W: io::Write, const PRETTY: bool> Compound<'_, W, PRETTY> {
    /// Whether the next element is the first; from now on it is not.
    #[inline]
    fn take_first(&mut self) -> bool {
        let first = self.state == State::First;
        self.state = State::Rest;
        first
    }

    /// A field named `name`: its start and its value.
    #[inline]
    fn field<T: ?Sized + Serialize>(&mut self, name: &'static str, value: &T) -> Result<()> {
        let first = self.take_first();
        self.ser.field_start(name, first);
        value.serialize(&mut *self.ser)
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeSeq for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    #[inline]
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        let first = self.take_first();
        self.ser.element_start(first);
        value.serialize(&mut *self.ser)?;
        Ok(self.ser.flush_if_full()?)
    }

    #[inline]
    fn end(self) -> Result<()> {
        self.ser.close(self.state, b']');
        Ok(())
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeTuple for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }

    fn end(self) -> Result<()> {
        ser::SerializeSeq::end(self)
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeTupleStruct for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }

    fn end(self) -> Result<()> {
        ser::SerializeSeq::end(self)
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeTupleVariant for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }

    fn end(self) -> Result<()> {
        self.ser.close(self.state, b']');
        self.ser.variant_close();
        Ok(())
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeMap for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Result<()> {
        let first = self.take_first();
        self.ser.element_start(first);
        self.ser.buf.push(b'"');
        key.serialize(KeySerializer { buf: &mut self.ser.buf })?;
        self.ser.buf.extend_from_slice(if PRETTY { b"\": " } else { b"\":" });
        Ok(())
    }

    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        value.serialize(&mut *self.ser)?;
        Ok(self.ser.flush_if_full()?)
    }

    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}');
        Ok(())
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeStruct for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    #[inline]
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Result<()> {
        self.field(key, value)
    }

    #[inline]
    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}');
        Ok(())
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeStructVariant for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Result<()> {
        self.field(key, value)
    }

    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}');
        self.ser.variant_close();
        Ok(())
    }
}

/// Writes a map key's text between the quotes that the map writes (as
/// serde_json: strings escaped, numbers and booleans as their text, any
/// other kind an error).
struct KeySerializer<'b> {
    buf: &'b mut Vec<u8>,
}

impl KeySerializer<'_> {
    fn float<F: Serialize>(self, v: F, finite: bool) -> Result<()> {
        if !finite {
            return Err(Error::FloatKeyMustBeFinite);
        }
        serde_json::to_writer(self.buf, &v).map_err(|e| Error::Io(e.into()))
    }
}

impl ser::Serializer for KeySerializer<'_> {
    type Ok = ();
    type Error = Error;
    type SerializeSeq = ser::Impossible<(), Error>;
    type SerializeTuple = ser::Impossible<(), Error>;
    type SerializeTupleStruct = ser::Impossible<(), Error>;
    type SerializeTupleVariant = ser::Impossible<(), Error>;
    type SerializeMap = ser::Impossible<(), Error>;
    type SerializeStruct = ser::Impossible<(), Error>;
    type SerializeStructVariant = ser::Impossible<(), Error>;

    fn serialize_bool(self, v: bool) -> Result<()> {
        self.buf.extend_from_slice(if v { b"true" } else { b"false" });
        Ok(())
    }

    fn serialize_i8(self, v: i8) -> Result<()> {
        self.serialize_i64(v.into())
    }

    fn serialize_i16(self, v: i16) -> Result<()> {
        self.serialize_i64(v.into())
    }

    fn serialize_i32(self, v: i32) -> Result<()> {
        self.serialize_i64(v.into())
    }

    fn serialize_i64(self, v: i64) -> Result<()> {
        push_integer(self.buf, v < 0, v.unsigned_abs());
        Ok(())
    }

    fn serialize_i128(self, v: i128) -> Result<()> {
        Ok(io::Write::write_fmt(self.buf, format_args!("{v}"))?)
    }

    fn serialize_u8(self, v: u8) -> Result<()> {
        self.serialize_u64(v.into())
    }

    fn serialize_u16(self, v: u16) -> Result<()> {
        self.serialize_u64(v.into())
    }

    fn serialize_u32(self, v: u32) -> Result<()> {
        self.serialize_u64(v.into())
    }

    fn serialize_u64(self, v: u64) -> Result<()> {
        push_integer(self.buf, false, v);
        Ok(())
    }

    fn serialize_u128(self, v: u128) -> Result<()> {
        Ok(io::Write::write_fmt(self.buf, format_args!("{v}"))?)
    }

    fn serialize_f32(self, v: f32) -> Result<()> {
        self.float(v, v.is_finite())
    }

    fn serialize_f64(self, v: f64) -> Result<()> {
        self.float(v, v.is_finite())
    }

    fn serialize_char(self, v: char) -> Result<()> {
        self.serialize_str(v.encode_utf8(&mut [0; 4]))
    }

    fn serialize_str(self, v: &str) -> Result<()> {
        push_contents(self.buf, v.as_bytes());
        Ok(())
    }

    fn serialize_bytes(self, _v: &[u8]) -> Result<()> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_none(self) -> Result<()> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<()> {
        value.serialize(self)
    }

    fn serialize_unit(self) -> Result<()> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_unit_struct(self, _name: &'static str) -> Result<()> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_unit_variant(self, _name: &'static str, _index: u32, variant: &'static str) -> Result<()> {
        self.serialize_str(variant)
    }

    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _name: &'static str, value: &T) -> Result<()> {
        value.serialize(self)
    }

    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _value: &T,
    ) -> Result<()> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_seq(self, _len: Option<usize>) -> Result<Self::SerializeSeq> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_tuple(self, _len: usize) -> Result<Self::SerializeTuple> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_tuple_struct(self, _name: &'static str, _len: usize) -> Result<Self::SerializeTupleStruct> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeTupleVariant> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_map(self, _len: Option<usize>) -> Result<Self::SerializeMap> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_struct(self, _name: &'static str, _len: usize) -> Result<Self::SerializeStruct> {
        Err(Error::KeyMustBeAString)
    }

    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        _variant: &'static str,
        _len: usize,
    ) -> Result<Self::SerializeStructVariant> {
        Err(Error::KeyMustBeAString)
    }

    fn collect_str<T: ?Sized + fmt::Display>(self, value: &T) -> Result<()> {
        // The quotes are the map's: only the escaped text is written here.
        push_contents(self.buf, value.to_string().as_bytes());
        Ok(())
    }
}

/// The writer against `serde_json` itself: the same bytes for generated
/// documents over the whole serde data model, pretty (with
/// [`super::Pretty`] and with `serde_json`'s own pretty printer) and
/// compact, and the same errors.
#[cfg(test)]
mod tests {
    use super::*;
    use crate::json::Pretty;
    use cycleref::{IncrementSystem, InputUnit, Lead, LeadWord, Units};
    use proptest::prelude::*;
    use serde::ser::{SerializeMap, SerializeSeq, SerializeStruct, SerializeStructVariant, Serializer};
    use serde::ser::{SerializeTuple, SerializeTupleStruct, SerializeTupleVariant};

    /// Field and variant names (`&'static str`, as serde gives them),
    /// with every kind of character a name could hold, and one longer
    /// than a kept field start.
    const NAMES: [&str; 12] = [
        "x",
        "motion",
        "start_angle_millidegrees",
        "",
        "with \"quote\"",
        "back\\slash",
        "tab\there",
        "ctl\u{1}\u{1f}\u{0}",
        "ünïcødé ✓",
        "line\nbreak\r",
        "del\u{7f}",
        "a_field_name_so_long_that_its_start_with_the_indentation_is_over_sixty_four_bytes",
    ];

    /// A map key of each kind JSON accepts.
    #[derive(Clone, Debug)]
    enum Key {
        Str(String),
        U64(u64),
        I64(i64),
        I128(i128),
        U8(u8),
        Bool(bool),
        Char(char),
        F64(f64),
        Variant(usize),
        Newtype(String),
    }

    impl Serialize for Key {
        fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
            match self {
                Key::Str(v) => s.serialize_str(v),
                Key::U64(v) => s.serialize_u64(*v),
                Key::I64(v) => s.serialize_i64(*v),
                Key::I128(v) => s.serialize_i128(*v),
                Key::U8(v) => s.serialize_u8(*v),
                Key::Bool(v) => s.serialize_bool(*v),
                Key::Char(v) => s.serialize_char(*v),
                Key::F64(v) => s.serialize_f64(*v),
                Key::Variant(i) => s.serialize_unit_variant("Key", 0, NAMES[*i]),
                Key::Newtype(v) => s.serialize_newtype_struct("Key", v),
            }
        }
    }

    /// A value of the serde data model.
    #[derive(Clone, Debug)]
    enum Doc {
        Bool(bool),
        U8(u8),
        U16(u16),
        U32(u32),
        U64(u64),
        I8(i8),
        I16(i16),
        I32(i32),
        I64(i64),
        I128(i128),
        U128(u128),
        F32(f32),
        F64(f64),
        Char(char),
        Str(String),
        /// Written by `collect_str`, one `write_str` per piece.
        Display(Vec<String>),
        Bytes(Vec<u8>),
        Length(Fixed),
        Lead(LeadText),
        None,
        Some(Box<Doc>),
        Unit,
        UnitStruct,
        UnitVariant(usize),
        Newtype(Box<Doc>),
        NewtypeVariant(usize, Box<Doc>),
        /// Elements, and whether the length is given.
        Seq(Vec<Doc>, bool),
        Tuple(Vec<Doc>),
        TupleStruct(Vec<Doc>),
        TupleVariant(usize, Vec<Doc>),
        /// Entries, and whether the length is given.
        Map(Vec<(Key, Doc)>, bool),
        /// Fields by name; a field without a value is skipped.
        Struct(Vec<(usize, Option<Doc>)>),
        StructVariant(usize, Vec<(usize, Doc)>),
    }

    /// Displays its pieces one `write_str` each.
    struct Pieces<'a>(&'a [String]);

    impl fmt::Display for Pieces<'_> {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            self.0.iter().try_for_each(|p| f.write_str(p))
        }
    }

    impl Serialize for Doc {
        fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
            match self {
                Doc::Bool(v) => s.serialize_bool(*v),
                Doc::U8(v) => s.serialize_u8(*v),
                Doc::U16(v) => s.serialize_u16(*v),
                Doc::U32(v) => s.serialize_u32(*v),
                Doc::U64(v) => s.serialize_u64(*v),
                Doc::I8(v) => s.serialize_i8(*v),
                Doc::I16(v) => s.serialize_i16(*v),
                Doc::I32(v) => s.serialize_i32(*v),
                Doc::I64(v) => s.serialize_i64(*v),
                Doc::I128(v) => s.serialize_i128(*v),
                Doc::U128(v) => s.serialize_u128(*v),
                Doc::F32(v) => s.serialize_f32(*v),
                Doc::F64(v) => s.serialize_f64(*v),
                Doc::Char(v) => s.serialize_char(*v),
                Doc::Str(v) => s.serialize_str(v),
                Doc::Display(pieces) => s.collect_str(&Pieces(pieces)),
                Doc::Bytes(v) => s.serialize_bytes(v),
                Doc::Length(v) => v.serialize(s),
                Doc::Lead(v) => v.serialize(s),
                Doc::None => s.serialize_none(),
                Doc::Some(v) => s.serialize_some(v),
                Doc::Unit => s.serialize_unit(),
                Doc::UnitStruct => s.serialize_unit_struct("Unit"),
                Doc::UnitVariant(i) => s.serialize_unit_variant("Doc", 1, NAMES[*i]),
                Doc::Newtype(v) => s.serialize_newtype_struct("Newtype", v),
                Doc::NewtypeVariant(i, v) => s.serialize_newtype_variant("Doc", 2, NAMES[*i], v),
                Doc::Seq(items, sized) => {
                    let mut seq = s.serialize_seq(sized.then_some(items.len()))?;
                    items.iter().try_for_each(|v| seq.serialize_element(v))?;
                    seq.end()
                }
                Doc::Tuple(items) => {
                    let mut t = s.serialize_tuple(items.len())?;
                    items.iter().try_for_each(|v| t.serialize_element(v))?;
                    t.end()
                }
                Doc::TupleStruct(items) => {
                    let mut t = s.serialize_tuple_struct("Tuple", items.len())?;
                    items.iter().try_for_each(|v| t.serialize_field(v))?;
                    t.end()
                }
                Doc::TupleVariant(i, items) => {
                    let mut t = s.serialize_tuple_variant("Doc", 3, NAMES[*i], items.len())?;
                    items.iter().try_for_each(|v| t.serialize_field(v))?;
                    t.end()
                }
                Doc::Map(entries, sized) => {
                    let mut m = s.serialize_map(sized.then_some(entries.len()))?;
                    for (k, v) in entries {
                        if matches!(k, Key::Str(_)) {
                            m.serialize_entry(k, v)?;
                        } else {
                            m.serialize_key(k)?;
                            m.serialize_value(v)?;
                        }
                    }
                    m.end()
                }
                Doc::Struct(fields) => {
                    let len = fields.iter().filter(|(_, v)| v.is_some()).count();
                    let mut st = s.serialize_struct("Struct", len)?;
                    for (i, v) in fields {
                        match v {
                            Some(v) => st.serialize_field(NAMES[*i], v)?,
                            None => st.skip_field(NAMES[*i])?,
                        }
                    }
                    st.end()
                }
                Doc::StructVariant(i, fields) => {
                    let mut st = s.serialize_struct_variant("Doc", 4, NAMES[*i], fields.len())?;
                    fields.iter().try_for_each(|(i, v)| st.serialize_field(NAMES[*i], v))?;
                    st.end()
                }
            }
        }
    }

    /// Strings rich in what JSON escapes: every control character, `"`,
    /// `\`, DEL, non-ASCII of every UTF-8 length; short and longer than
    /// the eight-byte steps.
    fn text() -> impl Strategy<Value = String> {
        let c = prop_oneof![
            3 => (0x20_u8..0x7f).prop_map(char::from),
            2 => (0_u8..0x20).prop_map(char::from),
            1 => prop_oneof![Just('"'), Just('\\'), Just('\u{7f}'), Just('é'), Just('✓'), Just('🦀')],
            1 => any::<char>(),
        ];
        prop::collection::vec(c, 0..40).prop_map(String::from_iter)
    }

    fn u64_edges() -> impl Strategy<Value = u64> {
        prop_oneof![
            Just(0),
            Just(9),
            Just(10),
            Just(99),
            Just(100),
            Just(u64::from(u32::MAX)),
            Just(u64::MAX),
            any::<u64>(),
            (0_u64..1000)
        ]
    }

    fn i64_edges() -> impl Strategy<Value = i64> {
        prop_oneof![
            Just(0),
            Just(-1),
            Just(-10),
            Just(i64::MIN),
            Just(i64::MAX),
            any::<i64>(),
            (-1000_i64..1000)
        ]
    }

    fn units() -> impl Strategy<Value = Units> {
        (
            prop_oneof![Just(IncrementSystem::IsB), Just(IncrementSystem::IsC)],
            prop_oneof![Just(InputUnit::Metric), Just(InputUnit::Inch)],
        )
            .prop_map(|(system, unit)| Units { system, unit })
    }

    fn key() -> impl Strategy<Value = Key> {
        prop_oneof![
            4 => text().prop_map(Key::Str),
            1 => u64_edges().prop_map(Key::U64),
            1 => i64_edges().prop_map(Key::I64),
            1 => any::<i128>().prop_map(Key::I128),
            1 => any::<u8>().prop_map(Key::U8),
            1 => any::<bool>().prop_map(Key::Bool),
            1 => any::<char>().prop_map(Key::Char),
            1 => prop::num::f64::NORMAL.prop_map(Key::F64),
            1 => (0..NAMES.len()).prop_map(Key::Variant),
            1 => text().prop_map(Key::Newtype),
        ]
    }

    fn leaf() -> impl Strategy<Value = Doc> {
        prop_oneof![
            1 => any::<bool>().prop_map(Doc::Bool),
            1 => any::<u8>().prop_map(Doc::U8),
            1 => any::<u16>().prop_map(Doc::U16),
            1 => prop_oneof![Just(u32::MAX), any::<u32>()].prop_map(Doc::U32),
            1 => u64_edges().prop_map(Doc::U64),
            1 => any::<i8>().prop_map(Doc::I8),
            1 => any::<i16>().prop_map(Doc::I16),
            1 => prop_oneof![Just(i32::MIN), any::<i32>()].prop_map(Doc::I32),
            1 => i64_edges().prop_map(Doc::I64),
            1 => prop_oneof![Just(i128::MIN), Just(i128::MAX), any::<i128>()].prop_map(Doc::I128),
            1 => prop_oneof![Just(u128::MAX), any::<u128>()].prop_map(Doc::U128),
            1 => any::<f32>().prop_map(Doc::F32),
            1 => prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(-0.0), any::<f64>()].prop_map(Doc::F64),
            1 => any::<char>().prop_map(Doc::Char),
            4 => text().prop_map(Doc::Str),
            1 => prop::collection::vec(text(), 0..4).prop_map(Doc::Display),
            1 => prop::collection::vec(any::<u8>(), 0..6).prop_map(Doc::Bytes),
            2 => (i64_edges(), units()).prop_map(|(v, u)| Doc::Length(Fixed::new(v, u))),
            1 => (any::<bool>(), u64_edges(), 0_u32..10).prop_map(|(i, mantissa, scale)| {
                let word = if i { LeadWord::I } else { LeadWord::F };
                Doc::Lead(LeadText(Lead { word, mantissa, scale }))
            }),
            1 => Just(Doc::None),
            1 => Just(Doc::Unit),
            1 => Just(Doc::UnitStruct),
            1 => (0..NAMES.len()).prop_map(Doc::UnitVariant),
        ]
    }

    fn doc() -> impl Strategy<Value = Doc> {
        leaf().prop_recursive(6, 96, 8, |inner| {
            let name = 0..NAMES.len();
            prop_oneof![
                1 => inner.clone().prop_map(|d| Doc::Some(Box::new(d))),
                1 => inner.clone().prop_map(|d| Doc::Newtype(Box::new(d))),
                1 => (name.clone(), inner.clone()).prop_map(|(i, d)| Doc::NewtypeVariant(i, Box::new(d))),
                1 => (prop::collection::vec(inner.clone(), 0..6), any::<bool>()).prop_map(|(v, s)| Doc::Seq(v, s)),
                1 => prop::collection::vec(inner.clone(), 0..4).prop_map(Doc::Tuple),
                1 => prop::collection::vec(inner.clone(), 0..4).prop_map(Doc::TupleStruct),
                1 => (name.clone(), prop::collection::vec(inner.clone(), 0..4)).prop_map(|(i, v)| Doc::TupleVariant(i, v)),
                1 => (prop::collection::vec((key(), inner.clone()), 0..5), any::<bool>())
                    .prop_map(|(v, s)| Doc::Map(v, s)),
                3 => prop::collection::vec((name.clone(), prop::option::weighted(0.8, inner.clone())), 0..6)
                    .prop_map(Doc::Struct),
                1 => (name.clone(), prop::collection::vec((name, inner), 0..4)).prop_map(|(i, v)| Doc::StructVariant(i, v)),
            ]
        })
    }

    /// `value` by serde_json: pretty with [`Pretty`], pretty by its own
    /// printer, compact.
    fn by_serde_json<T: ?Sized + Serialize>(value: &T) -> [Vec<u8>; 3] {
        let mut pretty = Vec::new();
        value.serialize(&mut serde_json::Serializer::with_formatter(&mut pretty, Pretty::default())).unwrap();
        [pretty, serde_json::to_vec_pretty(value).unwrap(), serde_json::to_vec(value).unwrap()]
    }

    /// `value` by this writer: pretty, compact.
    fn by_us<T: ?Sized + Serialize>(value: &T) -> [Vec<u8>; 2] {
        let (mut pretty, mut compact) = (Vec::new(), Vec::new());
        to_writer_pretty(&mut pretty, value).unwrap();
        to_writer_compact(&mut compact, value).unwrap();
        [pretty, compact]
    }

    fn assert_same<T: ?Sized + Serialize + fmt::Debug>(value: &T) {
        let [pretty, pretty_serde, compact] = by_serde_json(value);
        let [ours_pretty, ours_compact] = by_us(value);
        let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
        assert_eq!(text(&pretty), text(&pretty_serde), "Pretty is serde_json's pretty format");
        assert_eq!(text(&ours_pretty), text(&pretty), "pretty: {value:?}");
        assert_eq!(text(&ours_compact), text(&compact), "compact: {value:?}");
        assert_eq!(ours_pretty, pretty);
        assert_eq!(ours_compact, compact);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        #[test]
        fn generated_documents_are_written_as_serde_json_writes_them(d in doc()) {
            assert_same(&d);
        }
    }

    #[test]
    fn every_byte_and_char_class_is_escaped_as_serde_json_escapes_it() {
        let mut all = String::new();
        for c in (0_u32..0x300).chain([0x2028, 0x2029, 0xFFFD, 0x1F980]).filter_map(char::from_u32) {
            all.push(c);
            // Alone, at each offset of an eight-byte step, and in a run.
            assert_same(&c.to_string());
            assert_same(&format!("{}{c}", "x".repeat(c as usize % 9)));
            assert_same(&Doc::Char(c));
        }
        assert_same(&all);
        assert_same(&"");
        assert_same(&"\"\\\"\\");
        // Keys as well as values.
        let map: std::collections::BTreeMap<String, u8> = all.chars().map(|c| (c.to_string(), 1)).collect();
        assert_same(&map);
    }

    #[test]
    fn integer_edges_are_written_as_serde_json_writes_them() {
        for v in [0, 1, 9, 10, 99, 100, 101, 999, 1000, u64::from(u32::MAX), u64::MAX - 1, u64::MAX] {
            assert_same(&v);
            assert_same(&[Doc::U32(u32::try_from(v).unwrap_or(u32::MAX)), Doc::U64(v)]);
        }
        for v in [i64::MIN, i64::MIN + 1, -100, -10, -9, -1, 0, i64::MAX] {
            assert_same(&v);
        }
        assert_same(&[i128::MIN, i128::MAX, 0]);
        assert_same(&[u128::MAX, 0]);
        assert_same(&(u8::MAX, i8::MIN, u16::MAX, i16::MIN, i32::MIN, usize::MAX));
    }

    /// Deeper than the table of line prefixes and than the kept field
    /// starts, and longer than the buffer (handed over in blocks).
    #[test]
    fn deep_and_long_documents_are_written_as_serde_json_writes_them() {
        let mut deep = Doc::Str("bottom".into());
        for level in 0..80 {
            deep = if level % 2 == 0 {
                Doc::Struct(vec![(level % NAMES.len(), Some(deep)), (1, Some(Doc::U8(1)))])
            } else {
                Doc::Seq(vec![Doc::Unit, deep], level % 3 == 0)
            };
        }
        assert_same(&deep);
        // Each name at every level (a kept field start is for one level).
        let nested = (0..NAMES.len()).map(|name| {
            (0..30).fold(Doc::Bool(true), |d, _| Doc::Struct(vec![(name, Some(d)), (0, Some(Doc::Unit))]))
        });
        assert_same(&nested.collect::<Vec<_>>());
        let row = Doc::Struct(vec![
            (1, Some(Doc::Str("rapid".into()))),
            (
                0,
                Some(Doc::Length(Fixed::new(
                    -64_400,
                    Units { system: IncrementSystem::IsB, unit: InputUnit::Metric },
                ))),
            ),
            (2, Some(Doc::Struct(vec![(0, Some(Doc::U32(7))), (3, None)]))),
        ]);
        let long = Doc::Seq(vec![row; 20_000], false);
        assert_same(&long);
    }

    /// A kept field start is for its name at its level, whatever slot it
    /// is found in.
    #[test]
    fn a_kept_field_start_is_used_at_its_own_level_only() {
        static NAME: &str = "x";
        let id = (NAME.as_ptr().addr(), NAME.len());
        let mut ser = JsonSerializer::<Vec<u8>, true>::new(Vec::new());
        ser.level = 1;
        ser.field_start(NAME, false);
        assert_eq!(ser.buf, b",\n  \"x\": ");
        ser.field_starts[field_start_slot(id, 3)] = ser.field_starts[field_start_slot(id, 1)];
        ser.level = 3;
        ser.buf.clear();
        ser.field_start(NAME, true);
        assert_eq!(ser.buf, b"\n      \"x\": ");
        ser.buf.clear();
    }

    #[test]
    fn lengths_and_leads_are_strings_through_other_serializers() {
        let mm = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };
        let length = Fixed::new(-5, mm);
        let lead = LeadText(Lead { word: LeadWord::F, mantissa: 6, scale: 0 });
        assert_eq!(serde_json::to_value(length).unwrap(), serde_json::json!("-0.005"));
        assert_eq!(serde_json::to_value(lead).unwrap(), serde_json::json!("F6.0"));
        assert_eq!(serde_json::to_string(&(length, lead)).unwrap(), r#"["-0.005","F6.0"]"#);
        // A text offered to another serializer is withdrawn.
        assert!(OFFERED.get().is_none());
        assert_same(&(length, lead, Doc::Display(vec!["1.000".into()])));
        // An offered text is written only for the value it was offered with.
        OFFERED.set(Some((address_of(&length), PlainText::Length(length))));
        let mut out = Vec::new();
        to_writer_compact(&mut out, &(Doc::Display(vec!["a\"b".into()]), length)).unwrap();
        assert!(OFFERED.get().is_none());
        assert_eq!(String::from_utf8(out).unwrap(), r#"["a\"b","-0.005"]"#);
    }

    /// A writer that fails with `kind` once `room` bytes are taken.
    struct Failing {
        room: usize,
        kind: io::ErrorKind,
    }

    impl io::Write for Failing {
        fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
            if self.room == 0 {
                return Err(self.kind.into());
            }
            let n = buf.len().min(self.room);
            self.room -= n;
            Ok(n)
        }

        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn errors_convert_into_io_errors_as_serde_json_errors_do() {
        let long = Doc::Seq(vec![Doc::Str("x".repeat(100)); 2_000], true);
        for kind in [io::ErrorKind::BrokenPipe, io::ErrorKind::StorageFull, io::ErrorKind::Other] {
            for room in [0, 10, 70_000] {
                let e = to_writer_pretty(Failing { room, kind }, &long).unwrap_err();
                assert_eq!(e.kind(), kind);
                let e = to_writer_compact(Failing { room, kind }, &long).unwrap_err();
                assert_eq!(e.kind(), kind);
            }
        }
        /// Fails as a `StreamSeq` does when an item is an error.
        struct Refusing;
        impl Serialize for Refusing {
            fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(None)?;
                seq.serialize_element(&1)?;
                Err(serde::ser::Error::custom("the program read differently the second time: x"))
            }
        }
        let theirs = io::Error::from(serde_json::to_writer(Vec::new(), &Refusing).unwrap_err());
        let ours = to_writer_compact(Vec::new(), &Refusing).unwrap_err();
        assert_eq!((ours.kind(), ours.to_string()), (theirs.kind(), theirs.to_string()));
        // Keys JSON cannot have: both refuse, with the same words.
        key_refused((), "key must be a string");
        key_refused(vec![1], "key must be a string");
        key_refused(None::<u8>, "key must be a string");
        key_refused(Doc::NewtypeVariant(0, Box::new(Doc::Unit)), "key must be a string");
        key_refused(f64::NAN, "float key must be finite (got NaN or +/-inf)");
        key_refused(f32::NEG_INFINITY, "float key must be finite (got NaN or +/-inf)");
    }

    /// `{key: 0}` is refused by serde_json and by this writer, with `words`.
    fn key_refused<K: Serialize>(key: K, words: &str) {
        struct OneEntry<K>(K);
        impl<K: Serialize> Serialize for OneEntry<K> {
            fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                let mut m = s.serialize_map(Some(1))?;
                m.serialize_entry(&self.0, &0)?;
                m.end()
            }
        }
        let entry = OneEntry(key);
        let theirs = io::Error::from(serde_json::to_writer(Vec::new(), &entry).unwrap_err());
        for ours in [to_writer_pretty(Vec::new(), &entry), to_writer_compact(Vec::new(), &entry)] {
            let ours = ours.unwrap_err();
            assert_eq!(ours.to_string(), words);
            assert_eq!((ours.kind(), ours.to_string()), (theirs.kind(), theirs.to_string()));
        }
    }
}
