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
//!   ([`FieldStart`]): a field's start is then one copy of fixed size (the
//!   names are `&'static str`, so the name's address and length are its
//!   identity);
//! * a line break with its indentation is one copy of fixed size too;
//! * a string is checked for escapes eight bytes a step and copied whole
//!   when it needs none (every string of the moves documents);
//! * lengths and leads ([`Fixed`], [`LeadText`]) serialize through
//!   `collect_str`, which every serializer writes as a string; this one
//!   writes their ASCII digits straight into its buffer (see
//!   [`serialize_plain`]), without `&str`, UTF-8 check or escape scan;
//! * integers are written two digits a step ([`encode_fixed`]).
//!
//! Everything `serde_json` serializes is written the same way here, except
//! floats, which are handed to `serde_json` itself (the moves documents
//! have none), and map keys that are neither strings, integers, booleans
//! nor floats, which are an error in both.

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

    /// `value`'s text as a JSON string: the text [`serialize_plain`]
    /// offers for `value` as it is, any other escaped as it is displayed.
    #[inline]
    fn collect_str<T: ?Sized + fmt::Display>(self, value: &T) -> Result<()> {
        if let Some((at, text)) = OFFERED.get() {
            if at == address_of(value) {
                let mut digits = [0; FIXED_BUF];
                self.string(text.encode(&mut digits));
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
