//! The JSON writer of the three documents (`cycleref-moves/1` of `expand
//! --format json` and `jsonl`, `cycleref-check/1` of `check --format
//! json`, `cycleref-vector/1` of `vectors`): a serde
//! [`Serializer`](serde::Serializer) that writes what `serde_json` writes,
//! byte for byte — pretty (two spaces, `": "`, as
//! [`Pretty`](super::Pretty)) or compact (as `serde_json::to_writer`) —
//! for a fraction of its work, and the corpus's layout of lines
//! ([`to_writer_lines`]).
//!
//! Where `serde_json`'s work went (callgrind, a 1 MB program, issue 11):
//! each key and each string value was three or four writes with every byte
//! scanned for escapes, a struct field six or seven writes, and each length
//! (`"64.400"`) was checked as UTF-8 to become a `&str`. Here:
//!
//! * the output is gathered in the serializer's own buffer and handed to
//!   the writer in blocks of 64 KiB (at the end of an element of an array
//!   or a value of a map), so a write is a copy into memory; bytes past
//!   the written ones may be overwritten, so a short piece of varying
//!   length is a copy of fixed size (`text::Buf`);
//! * a field's start (line break, indentation, quoted name and colon) is
//!   one look for room and copies of fixed size: the field names are
//!   constants where the derived code is inlined;
//! * a string or a field name is checked for escapes eight bytes a step
//!   and copied whole when it needs none (every string of the documents);
//! * lengths and leads ([`Fixed`](crate::format::Fixed),
//!   [`LeadText`](crate::format::LeadText)) are written as a newtype
//!   struct named [`PLAIN_TEXT`] holding their ASCII text: every other
//!   serializer writes the text as a string (a newtype struct is its
//!   value), this one copies it between quotes without the escape scan;
//! * integers are written two digits a step.
//!
//! The serializer keeps no state beyond the document it writes: no
//! thread-local, no table of names.
//!
//! The whole serde data model is written as `serde_json` writes it (the
//! tests hold the two to the same bytes): floats by `serde_json` itself
//! (the documents have none); a map key JSON cannot have is refused with
//! `serde_json`'s words; errors convert into [`io::Error`] as
//! `serde_json`'s do.

use std::fmt;
use std::io;

use serde::ser::{self, Serialize};

mod key;
mod text;

use key::KeySerializer;
use text::{needs_escape, push_contents, push_escaped, push_integer, push_line_break, Buf};

/// The name of the newtype struct whose value is a text that needs no
/// escape in JSON (ASCII digits, letters, `.`, `-`), serialized as a
/// string or as bytes: [`JsonSerializer`] copies it between quotes as it
/// is, serializing the value with a serializer that is not human-readable
/// (so that a length gives its bytes, not a `&str` checked as UTF-8). To
/// any other serializer the newtype struct is its value.
pub const PLAIN_TEXT: &str = "$cycleref::json::PlainText";

/// The name of the newtype struct ([`OneLine`]) whose value the corpus's
/// layout ([`to_writer_lines`]) writes on one line. To any other layout
/// and any other serializer it is its value.
pub const ONE_LINE: &str = "$cycleref::json::OneLine";

/// A value that the corpus's layout writes on one line (compact): a move,
/// a point, a list of tags, a flat object. Elsewhere it is written as its
/// value.
#[derive(Clone, Copy, Debug)]
pub struct OneLine<T>(pub T);

impl<T: Serialize> Serialize for OneLine<T> {
    #[inline]
    fn serialize<S: ser::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_newtype_struct(ONE_LINE, &self.0)
    }
}

/// Writes `value` as pretty JSON, exactly as `serde_json` with
/// [`Pretty`](super::Pretty) (or `serde_json::to_writer_pretty`) would.
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

/// Writes `value` in the corpus's layout of lines (the vectors): pretty,
/// except that each value marked [`OneLine`] is written compact on the
/// line of its key — one move, one point, one list of tags a line.
///
/// # Errors
///
/// As [`JsonSerializer::write`].
pub fn to_writer_lines<W: io::Write, T: ?Sized + Serialize>(out: W, value: &T) -> io::Result<()> {
    let mut ser = JsonSerializer::lines(out);
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

/// The output is handed to the writer once the buffer holds this much (at
/// the end of an array's element or a map's value).
const FLUSH_AT: usize = 1 << 16;

/// A serde [`Serializer`](serde::Serializer) writing JSON to `W`: pretty
/// when `PRETTY`, else compact; pretty with `LINES`, in the corpus's layout
/// of lines ([`JsonSerializer::lines`]: each value marked [`OneLine`]
/// compact). The output is gathered in a buffer and
/// handed to `W` in blocks: call [`JsonSerializer::finish`] at the end
/// (dropping it writes what is left too, ignoring a failure).
pub struct JsonSerializer<W: io::Write, const PRETTY: bool, const LINES: bool = false> {
    out: W,
    buf: Buf,
    /// The number of arrays and objects open.
    level: usize,
    /// Within a value marked [`OneLine`], in the corpus's layout (`LINES`).
    one_line: bool,
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> JsonSerializer<W, PRETTY, LINES> {
    /// A serializer writing to `out`.
    pub fn new(out: W) -> Self {
        JsonSerializer { out, buf: Buf::with_capacity(FLUSH_AT + 4096), level: 0, one_line: false }
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
        let written = self.out.write_all(self.buf.as_slice());
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

    /// Whether what is written now is laid out on lines: the pretty form,
    /// outside a value written on one line.
    #[inline]
    fn pretty(&self) -> bool {
        PRETTY && !(LINES && self.one_line)
    }

    /// Opens an array or object with `open` (`[` or `{`); `empty` closes it
    /// at once with `close`.
    #[inline]
    fn open(&mut self, open: u8, close: u8, empty: bool) -> Compound<'_, W, PRETTY, LINES> {
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
    #[inline(always)]
    fn close(&mut self, state: State, close: u8) {
        if state == State::Empty {
            return;
        }
        self.level -= 1;
        if self.pretty() && state == State::Rest {
            push_line_break(&mut self.buf, false, self.level);
        }
        self.buf.push(close);
    }

    /// The start of an array's element: `,` unless `first`, and in the
    /// pretty form a line break and the indentation.
    #[inline(always)]
    fn element_start(&mut self, first: bool) {
        if self.pretty() {
            push_line_break(&mut self.buf, !first, self.level);
        } else if !first {
            self.buf.push(b',');
        }
    }

    /// The start of a field named `name`: `,` unless `first`, the line
    /// (pretty form), `"name"` and the colon.
    #[inline(always)]
    fn field_start(&mut self, name: &str, first: bool) {
        if self.pretty() {
            self.buf.pretty_field_start(!first, self.level, name.as_bytes());
        } else {
            if !first {
                self.buf.push(b',');
            }
            self.buf.key(name.as_bytes(), false);
        }
    }

    /// `s` as a JSON string, quoted.
    #[inline]
    fn string(&mut self, s: &[u8]) {
        if needs_escape(s) {
            self.buf.push(b'"');
            push_escaped(&mut self.buf, s);
            self.buf.push(b'"');
        } else {
            self.buf.quoted(s);
        }
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

    /// A [`PLAIN_TEXT`] value: its text between quotes, as it is.
    #[inline(always)]
    fn plain<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        value.serialize(KeySerializer { buf: &mut self.buf, plain: true, quoted: true })
    }

    /// A [`OneLine`] value: compact in the corpus's layout, else as it is.
    fn one_line<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        if !LINES || self.one_line {
            return value.serialize(self);
        }
        self.one_line = true;
        let written = value.serialize(&mut *self);
        self.one_line = false;
        written
    }
}

impl<W: io::Write> JsonSerializer<W, true, true> {
    /// A serializer writing to `out` in the corpus's layout of lines: pretty,
    /// each value marked [`OneLine`] compact on the line of its key.
    pub fn lines(out: W) -> Self {
        JsonSerializer::new(out)
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> Drop for JsonSerializer<W, PRETTY, LINES> {
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

impl<'a, W: io::Write, const PRETTY: bool, const LINES: bool> ser::Serializer
    for &'a mut JsonSerializer<W, PRETTY, LINES>
{
    type Ok = ();
    type Error = Error;
    type SerializeSeq = Compound<'a, W, PRETTY, LINES>;
    type SerializeTuple = Compound<'a, W, PRETTY, LINES>;
    type SerializeTupleStruct = Compound<'a, W, PRETTY, LINES>;
    type SerializeTupleVariant = Compound<'a, W, PRETTY, LINES>;
    type SerializeMap = Compound<'a, W, PRETTY, LINES>;
    type SerializeStruct = Compound<'a, W, PRETTY, LINES>;
    type SerializeStructVariant = Compound<'a, W, PRETTY, LINES>;

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

    #[inline(always)]
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, name: &'static str, value: &T) -> Result<()> {
        // The names are compared by their text; where the call is inlined
        // with a constant name the comparison is decided when compiling.
        if name == PLAIN_TEXT {
            self.plain(value)
        } else if name == ONE_LINE {
            self.one_line(value)
        } else {
            value.serialize(self)
        }
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
    fn serialize_seq(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY, LINES>> {
        Ok(self.open(b'[', b']', len == Some(0)))
    }

    fn serialize_tuple(self, len: usize) -> Result<Compound<'a, W, PRETTY, LINES>> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_struct(
        self,
        _name: &'static str,
        len: usize,
    ) -> Result<Compound<'a, W, PRETTY, LINES>> {
        self.serialize_seq(Some(len))
    }

    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<Compound<'a, W, PRETTY, LINES>> {
        self.variant_open(variant);
        self.serialize_seq(Some(len))
    }

    #[inline]
    fn serialize_map(self, len: Option<usize>) -> Result<Compound<'a, W, PRETTY, LINES>> {
        Ok(self.open(b'{', b'}', len == Some(0)))
    }

    #[inline]
    fn serialize_struct(self, _name: &'static str, len: usize) -> Result<Compound<'a, W, PRETTY, LINES>> {
        self.serialize_map(Some(len))
    }

    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        len: usize,
    ) -> Result<Compound<'a, W, PRETTY, LINES>> {
        self.variant_open(variant);
        self.serialize_map(Some(len))
    }

    /// `value`'s text as a JSON string, escaped as it is displayed.
    fn collect_str<T: ?Sized + fmt::Display>(self, value: &T) -> Result<()> {
        self.display(value)
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> JsonSerializer<W, PRETTY, LINES> {
    /// `value`'s `Display` as a JSON string, escaped as it is written.
    fn display<T: ?Sized + fmt::Display>(&mut self, value: &T) -> Result<()> {
        /// Escapes what `Display` writes.
        struct Escaping<'b>(&'b mut Buf);
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
pub struct Compound<'a, W: io::Write, const PRETTY: bool, const LINES: bool> {
    ser: &'a mut JsonSerializer<W, PRETTY, LINES>,
    state: State,
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> Compound<'_, W, PRETTY, LINES> {
    /// Whether the next element is the first; from now on it is not.
    #[inline]
    fn take_first(&mut self) -> bool {
        let first = self.state == State::First;
        self.state = State::Rest;
        first
    }

    /// A field named `name`: its start and its value.
    #[inline(always)]
    fn field<T: ?Sized + Serialize>(&mut self, name: &'static str, value: &T) -> Result<()> {
        let first = self.take_first();
        self.ser.field_start(name, first);
        value.serialize(&mut *self.ser)
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeSeq
    for Compound<'_, W, PRETTY, LINES>
{
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

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeTuple
    for Compound<'_, W, PRETTY, LINES>
{
    type Ok = ();
    type Error = Error;

    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }

    fn end(self) -> Result<()> {
        ser::SerializeSeq::end(self)
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeTupleStruct
    for Compound<'_, W, PRETTY, LINES>
{
    type Ok = ();
    type Error = Error;

    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<()> {
        ser::SerializeSeq::serialize_element(self, value)
    }

    fn end(self) -> Result<()> {
        ser::SerializeSeq::end(self)
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeTupleVariant
    for Compound<'_, W, PRETTY, LINES>
{
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

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeMap
    for Compound<'_, W, PRETTY, LINES>
{
    type Ok = ();
    type Error = Error;

    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Result<()> {
        let first = self.take_first();
        self.ser.element_start(first);
        self.ser.buf.push(b'"');
        key.serialize(KeySerializer { buf: &mut self.ser.buf, plain: false, quoted: false })?;
        let colon: &[u8] = if self.ser.pretty() { b"\": " } else { b"\":" };
        self.ser.buf.extend_from_slice(colon);
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

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeStruct
    for Compound<'_, W, PRETTY, LINES>
{
    type Ok = ();
    type Error = Error;

    #[inline(always)]
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Result<()> {
        self.field(key, value)
    }

    #[inline]
    fn end(self) -> Result<()> {
        self.ser.close(self.state, b'}');
        Ok(())
    }
}

impl<W: io::Write, const PRETTY: bool, const LINES: bool> ser::SerializeStructVariant
    for Compound<'_, W, PRETTY, LINES>
{
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

#[cfg(test)]
mod tests;
