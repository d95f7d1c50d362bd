//! The JSON writer of `expand --format json` and `jsonl`: a serde
//! [`Serializer`](serde::Serializer) that writes what `serde_json` writes,
//! byte for byte — pretty (two spaces, `": "`, as [`super::Pretty`]) or
//! compact (as `serde_json::to_writer`) — for a fraction of its work.
//!
//! Where the work goes (callgrind, a 1 MB program, issue 11): `serde_json`
//! writes each key and each string value in three or four writes, scanning
//! every byte for escapes, and a struct field in six or seven. Here a
//! field's line break, indentation, comma and opening quote are one write
//! from a table, its name a second, `": "` a third; a string needing no
//! escape (every string of the moves documents) is checked eight bytes a
//! step and written at once; integers are written two digits a step.
//!
//! Everything `serde_json` serializes is written the same way here, except
//! floats, which are handed to `serde_json` itself (the moves documents
//! have none), and map keys that are neither strings, integers, booleans
//! nor floats, which are an error in both.

use std::fmt;
use std::io;

use serde::ser::{self, Serialize};

use crate::format::{encode_fixed, FIXED_BUF};

/// Writes `value` as pretty JSON, exactly as `serde_json` with
/// [`super::Pretty`] (or `serde_json::to_writer_pretty`) would.
///
/// # Errors
///
/// A failure to write, as it came; an error raised while serializing (a
/// [`Serialize`] implementation's own, a map key that is not a string) as
/// [`io::ErrorKind::InvalidData`] with its message, as `serde_json`'s
/// errors convert into [`io::Error`].
pub fn to_writer_pretty<W: io::Write, T: ?Sized + Serialize>(out: W, value: &T) -> io::Result<()> {
    value.serialize(&mut JsonSerializer::<W, true>::new(out)).map_err(io::Error::from)
}

/// Writes `value` as compact JSON (no whitespace), exactly as
/// `serde_json::to_writer` would.
///
/// # Errors
///
/// As [`to_writer_pretty`].
pub fn to_writer_compact<W: io::Write, T: ?Sized + Serialize>(out: W, value: &T) -> io::Result<()> {
    value.serialize(&mut JsonSerializer::<W, false>::new(out)).map_err(io::Error::from)
}

/// A failure of [`JsonSerializer`].
#[derive(Debug)]
pub enum Error {
    /// The writer failed.
    Io(io::Error),
    /// A [`Serialize`] implementation failed (`serde::ser::Error::custom`).
    Custom(String),
    /// A map key that JSON cannot have: it is not a string, an integer, a
    /// boolean, a char or a finite float (`serde_json`'s words).
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

/// The deepest level whose line prefix comes from [`LINE_PREFIXES`]; deeper
/// levels are written a piece at a time.
const TABLE_LEVELS: usize = 32;

/// A line prefix of [`LINE_PREFIXES`]: room for `,`, `\n`, two spaces a
/// level and `"`.
const PREFIX_ROOM: usize = 3 + 2 * TABLE_LEVELS;

/// For each level: `,\n`, two spaces a level, `"` — the start of every
/// element and field after the first in the pretty form (the first starts
/// one byte later, without the comma; a value that is not a key stops
/// before the quote).
const LINE_PREFIXES: [[u8; PREFIX_ROOM]; TABLE_LEVELS] = line_prefixes();

const fn line_prefixes() -> [[u8; PREFIX_ROOM]; TABLE_LEVELS] {
    let mut table = [[b' '; PREFIX_ROOM]; TABLE_LEVELS];
    let mut level = 0;
    while level < TABLE_LEVELS {
        table[level][0] = b',';
        table[level][1] = b'\n';
        table[level][2 + 2 * level] = b'"';
        level += 1;
    }
    table
}

/// What a byte becomes in a JSON string: 0 itself; `u` the `\u00XX` form;
/// any other the letter after the backslash (serde_json's table: the
/// controls, `"` and `\`; DEL and non-ASCII bytes pass through).
static ESCAPE: [u8; 256] = escapes();

const fn escapes() -> [u8; 256] {
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
}

/// Whether some byte of `s` needs an escape: eight bytes a step (a byte
/// below 0x20, `"` or `\`), then the rest one by one.
#[inline]
fn needs_escape(s: &[u8]) -> bool {
    const LOW: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let mut chunks = s.chunks_exact(8);
    for chunk in &mut chunks {
        let mut word = [0; 8];
        word.copy_from_slice(chunk);
        let v = u64::from_le_bytes(word);
        // A zero byte of x has the high bit set in (x - LOW) & !x & HIGH;
        // a byte below 0x20 has it in (v - 0x20…) & !v.
        let quote = v ^ (LOW * u64::from(b'"'));
        let backslash = v ^ (LOW * u64::from(b'\\'));
        let found = (v.wrapping_sub(LOW * 0x20) & !v)
            | (quote.wrapping_sub(LOW) & !quote)
            | (backslash.wrapping_sub(LOW) & !backslash);
        if found & HIGH != 0 {
            return true;
        }
    }
    chunks.remainder().iter().any(|&b| ESCAPE[usize::from(b)] != 0)
}

/// Writes the contents of a JSON string for `s` (without the quotes).
#[inline]
fn write_contents<W: io::Write>(out: &mut W, s: &str) -> io::Result<()> {
    let bytes = s.as_bytes();
    if !needs_escape(bytes) {
        return out.write_all(bytes);
    }
    write_escaped(out, bytes)
}

/// The slow path of [`write_contents`]: runs without an escape are written
/// whole, each escape as serde_json writes it.
#[cold]
fn write_escaped<W: io::Write>(out: &mut W, bytes: &[u8]) -> io::Result<()> {
    const HEX: &[u8; 16] = b"0123456789abcdef";
    let mut start = 0;
    for (i, &b) in bytes.iter().enumerate() {
        let escape = ESCAPE[usize::from(b)];
        if escape == 0 {
            continue;
        }
        out.write_all(&bytes[start..i])?;
        start = i + 1;
        if escape == b'u' {
            out.write_all(&[b'\\', b'u', b'0', b'0', HEX[usize::from(b >> 4)], HEX[usize::from(b & 0xF)]])?;
        } else {
            out.write_all(&[b'\\', escape])?;
        }
    }
    out.write_all(&bytes[start..])
}

/// The decimal text of `mag` (with `-` when `negative`) as serde_json
/// writes integers.
#[inline]
fn write_integer<W: io::Write>(out: &mut W, negative: bool, mag: u64) -> io::Result<()> {
    let mut buf = [0; FIXED_BUF];
    out.write_all(encode_fixed(&mut buf, negative, mag, 0))
}

/// A serde [`Serializer`](serde::Serializer) writing JSON to `W`: pretty
/// when `PRETTY`, else compact. Build it with [`JsonSerializer::new`], or
/// use [`to_writer_pretty`] and [`to_writer_compact`].
pub struct JsonSerializer<W, const PRETTY: bool> {
    out: W,
    /// The number of arrays and objects open.
    level: usize,
}

impl<W: io::Write, const PRETTY: bool> JsonSerializer<W, PRETTY> {
    /// A serializer writing to `out`.
    pub fn new(out: W) -> Self {
        JsonSerializer { out, level: 0 }
    }

    /// The writer.
    pub fn into_inner(self) -> W {
        self.out
    }

    /// Opens an array or object with `open` (`[` or `{`); `empty` closes it
    /// at once with `close`.
    #[inline]
    fn open(&mut self, open: u8, close: u8, empty: bool) -> Result<Compound<'_, W, PRETTY>> {
        if empty {
            self.out.write_all(&[open, close])?;
            return Ok(Compound { ser: self, state: State::Empty });
        }
        self.out.write_all(&[open])?;
        self.level += 1;
        Ok(Compound { ser: self, state: State::First })
    }

    /// Closes what [`Self::open`] opened with `close`: in the pretty form
    /// on a line of its own when it has an element.
    #[inline]
    fn close(&mut self, state: State, close: u8) -> Result<()> {
        match state {
            State::Empty => Ok(()),
            State::First => {
                self.level -= 1;
                Ok(self.out.write_all(&[close])?)
            }
            State::Rest => {
                self.level -= 1;
                self.closing_line()?;
                Ok(self.out.write_all(&[close])?)
            }
        }
    }

    /// The start of an element or field: `,` unless `first`; in the pretty
    /// form a line break and the indentation of this level; `"` when
    /// `quote` (a key follows).
    #[inline]
    fn element_start(&mut self, first: bool, quote: bool) -> io::Result<()> {
        if PRETTY {
            let skip = usize::from(first);
            match LINE_PREFIXES.get(self.level) {
                Some(prefix) => {
                    let end = 2 + 2 * self.level + usize::from(quote);
                    self.out.write_all(&prefix[skip..end])
                }
                None => {
                    self.out.write_all(&b",\n"[skip..])?;
                    (0..self.level).try_for_each(|_| self.out.write_all(b"  "))?;
                    if quote {
                        self.out.write_all(b"\"")?;
                    }
                    Ok(())
                }
            }
        } else {
            match (first, quote) {
                (true, false) => Ok(()),
                (true, true) => self.out.write_all(b"\""),
                (false, false) => self.out.write_all(b","),
                (false, true) => self.out.write_all(b",\""),
            }
        }
    }

    /// In the pretty form, a line break and the indentation of this level
    /// (before a closing bracket); nothing in the compact form.
    #[inline]
    fn closing_line(&mut self) -> io::Result<()> {
        if PRETTY {
            self.element_start(true, false)
        } else {
            Ok(())
        }
    }

    /// The end of a key: `": "` (pretty) or `":"`.
    #[inline]
    fn key_end(&mut self) -> io::Result<()> {
        self.out.write_all(if PRETTY { b"\": " } else { b"\":" })
    }

    /// `s` as a JSON string, quoted.
    #[inline]
    fn string(&mut self, s: &str) -> io::Result<()> {
        let bytes = s.as_bytes();
        if needs_escape(bytes) {
            self.out.write_all(b"\"")?;
            write_escaped(&mut self.out, bytes)?;
        } else {
            self.out.write_all(b"\"")?;
            self.out.write_all(bytes)?;
        }
        self.out.write_all(b"\"")
    }

    /// `{"variant": ` — the opening of an enum variant with data.
    fn variant_open(&mut self, variant: &str) -> Result<()> {
        self.out.write_all(b"{")?;
        self.level += 1;
        self.element_start(true, true)?;
        write_contents(&mut self.out, variant)?;
        Ok(self.key_end()?)
    }

    /// The closing `}` of [`Self::variant_open`].
    fn variant_close(&mut self) -> Result<()> {
        self.level -= 1;
        self.closing_line()?;
        Ok(self.out.write_all(b"}")?)
    }

    /// A float, as serde_json writes it (`null` when not finite).
    fn float<F: Serialize>(&mut self, v: F) -> Result<()> {
        serde_json::to_writer(&mut self.out, &v).map_err(|e| Error::Io(e.into()))
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

    fn serialize_bool(self, v: bool) -> Result<()> {
        Ok(self.out.write_all(if v { b"true" } else { b"false" })?)
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
        Ok(write_integer(&mut self.out, v < 0, v.unsigned_abs())?)
    }

    fn serialize_i128(self, v: i128) -> Result<()> {
        Ok(write!(self.out, "{v}")?)
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

    #[inline]
    fn serialize_u64(self, v: u64) -> Result<()> {
        Ok(write_integer(&mut self.out, false, v)?)
    }

    fn serialize_u128(self, v: u128) -> Result<()> {
        Ok(write!(self.out, "{v}")?)
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
        Ok(self.string(v)?)
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
        Ok(self.out.write_all(b"null")?)
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
        self.variant_open(variant)?;
        value.serialize(&mut *self)?;
        self.variant_close()
    }

    #[inline]
    fn serialize_seq(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY>> {
        self.open(b'[', b']', len == Some(0))
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
        self.variant_open(variant)?;
        self.serialize_seq(Some(len))
    }

    #[inline]
    fn serialize_map(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY>> {
        self.open(b'{', b'}', len == Some(0))
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
        self.variant_open(variant)?;
        self.serialize_map(Some(len))
    }

    /// `value`'s text as a JSON string, escaped as it is written.
    fn collect_str<T: ?Sized + fmt::Display>(self, value: &T) -> Result<()> {
        /// Escapes what `Display` writes; keeps the writer's error.
        struct Escaping<'w, W> {
            out: &'w mut W,
            error: Option<io::Error>,
        }
        impl<W: io::Write> fmt::Write for Escaping<'_, W> {
            fn write_str(&mut self, s: &str) -> fmt::Result {
                write_contents(self.out, s).map_err(|e| {
                    self.error = Some(e);
                    fmt::Error
                })
            }
        }
        self.out.write_all(b"\"")?;
        let mut escaping = Escaping { out: &mut self.out, error: None };
        if fmt::write(&mut escaping, format_args!("{value}")).is_err() {
            return Err(match escaping.error {
                Some(e) => Error::Io(e),
                None => Error::Custom("a Display implementation returned an error".to_string()),
            });
        }
        Ok(self.out.write_all(b"\"")?)
    }
}

/// An array or object being written (serde's `SerializeSeq`,
/// `SerializeMap`, `SerializeStruct` and the others).
pub struct Compound<'a, W, const PRETTY: bool> {
    ser: &'a mut JsonSerializer<W, PRETTY>,
    state: State,
}

impl<W: io::Write, const PRETTY: bool> Compound<'_, W, PRETTY> {
    /// The start of the next element or field (`quote`: a key follows).
    #[inline]
    fn next(&mut self, quote: bool) -> io::Result<()> {
        let first = self.state == State::First;
        self.state = State::Rest;
        self.ser.element_start(first, quote)
    }

    /// A field named `key`: its line, `"key": ` and its value.
    #[inline]
    fn field<T: ?Sized + Serialize>(&mut self, key: &str, value: &T) -> Result<()> {
        self.next(true)?;
        write_contents(&mut self.ser.out, key)?;
        self.ser.key_end()?;
        value.serialize(&mut *self.ser)
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeSeq for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    #[inline]
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        self.next(false)?;
        value.serialize(&mut *self.ser)
    }

    #[inline]
    fn end(self) -> Result<()> {
        self.ser.close(self.state, b']')
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
        self.ser.close(self.state, b']')?;
        self.ser.variant_close()
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeMap for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Result<()> {
        self.next(true)?;
        key.serialize(KeySerializer { out: &mut self.ser.out })?;
        Ok(self.ser.key_end()?)
    }

    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        value.serialize(&mut *self.ser)
    }

    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}')
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
        self.ser.close(self.state, b'}')
    }
}

impl<W: io::Write, const PRETTY: bool> ser::SerializeStructVariant for Compound<'_, W, PRETTY> {
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Result<()> {
        self.field(key, value)
    }

    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}')?;
        self.ser.variant_close()
    }
}

/// Writes a map key's text between the quotes that the map writes (as
/// serde_json: strings escaped, numbers and booleans as their text, any
/// other kind an error).
struct KeySerializer<'w, W> {
    out: &'w mut W,
}

impl<W: io::Write> KeySerializer<'_, W> {
    fn integer(self, negative: bool, mag: u64) -> Result<()> {
        Ok(write_integer(self.out, negative, mag)?)
    }
}

impl<W: io::Write> ser::Serializer for KeySerializer<'_, W> {
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
        Ok(self.out.write_all(if v { b"true" } else { b"false" })?)
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
        self.integer(v < 0, v.unsigned_abs())
    }

    fn serialize_i128(self, v: i128) -> Result<()> {
        Ok(write!(self.out, "{v}")?)
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
        self.integer(false, v)
    }

    fn serialize_u128(self, v: u128) -> Result<()> {
        Ok(write!(self.out, "{v}")?)
    }

    fn serialize_f32(self, v: f32) -> Result<()> {
        if !v.is_finite() {
            return Err(Error::FloatKeyMustBeFinite);
        }
        serde_json::to_writer(self.out, &v).map_err(|e| Error::Io(e.into()))
    }

    fn serialize_f64(self, v: f64) -> Result<()> {
        if !v.is_finite() {
            return Err(Error::FloatKeyMustBeFinite);
        }
        serde_json::to_writer(self.out, &v).map_err(|e| Error::Io(e.into()))
    }

    fn serialize_char(self, v: char) -> Result<()> {
        self.serialize_str(v.encode_utf8(&mut [0; 4]))
    }

    fn serialize_str(self, v: &str) -> Result<()> {
        Ok(write_contents(self.out, v)?)
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
        let text = value.to_string();
        self.serialize_str(&text)
    }
}
