//! The text of a map key, and of a plain text (a length, a lead).

use std::fmt;
use std::io;

use serde::ser::{self, Serialize};

use super::text::{push_contents, push_integer, Buf};
use super::{Error, Result};

/// Writes the text of a map key, or of a [`PLAIN_TEXT`](super::PLAIN_TEXT)
/// value, between the quotes its caller writes: as serde_json writes a
/// key, strings escaped, numbers and booleans as their text, any other
/// kind an error. A plain text's string or bytes are copied as they are
/// (they need no escape): to a plain text it is a serializer that is not
/// human-readable, so a length gives its ASCII bytes.
pub(super) struct KeySerializer<'b> {
    /// Where the text goes.
    pub(super) buf: &'b mut Buf,
    /// A plain text: a string is copied without the escape scan.
    pub(super) plain: bool,
    /// A plain text written with its quotes (the caller writes none).
    pub(super) quoted: bool,
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
    /// A plain text is taken as bytes (see [`crate::json`]'s `Plain`).
    fn is_human_readable(&self) -> bool {
        !self.plain
    }

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

    #[inline]
    fn serialize_str(self, v: &str) -> Result<()> {
        if self.plain {
            if self.quoted {
                self.buf.quoted(v.as_bytes());
            } else {
                self.buf.extend_from_slice(v.as_bytes());
            }
        } else {
            push_contents(self.buf, v.as_bytes());
        }
        Ok(())
    }

    /// A plain text's ASCII bytes, as they are; a key cannot be bytes.
    #[inline(always)]
    fn serialize_bytes(self, v: &[u8]) -> Result<()> {
        if self.plain {
            if self.quoted {
                self.buf.quoted(v);
            } else {
                self.buf.extend_from_slice(v);
            }
            Ok(())
        } else {
            Err(Error::KeyMustBeAString)
        }
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
