//! The writer against `serde_json` itself: the same bytes for generated
//! documents over the whole serde data model, pretty (with
//! [`Pretty`](crate::json::Pretty) and with `serde_json`'s own pretty
//! printer) and compact, and the same errors; and the corpus's layout.

use super::*;
use crate::format::{Fixed, LeadText};
use crate::json::Pretty;
use cycleref::{IncrementSystem, InputUnit, Lead, LeadWord, Units};
use proptest::prelude::*;
use serde::ser::{SerializeMap, SerializeSeq, SerializeStruct, SerializeStructVariant, Serializer};
use serde::ser::{SerializeTuple, SerializeTupleStruct, SerializeTupleVariant};

/// Field and variant names (`&'static str`, as serde gives them),
/// with every kind of character a name could hold, and one longer
/// than a line's fixed copy.
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
    /// Marked to be written on one line in the corpus's layout.
    OneLine(Box<Doc>),
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
            Doc::OneLine(v) => OneLine(v).serialize(s),
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
    prop_oneof![Just(0), Just(-1), Just(-10), Just(i64::MIN), Just(i64::MAX), any::<i64>(), (-1000_i64..1000)]
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
            1 => inner.clone().prop_map(|d| Doc::OneLine(Box::new(d))),
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

/// Deeper than the table of line prefixes, and longer than the buffer (handed over in blocks).
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
    // Each name at every level.
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

#[test]
fn lengths_and_leads_are_strings_through_other_serializers() {
    let mm = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };
    let length = Fixed::new(-5, mm);
    let lead = LeadText(Lead { word: LeadWord::F, mantissa: 6, scale: 0 });
    assert_eq!(serde_json::to_value(length).unwrap(), serde_json::json!("-0.005"));
    assert_eq!(serde_json::to_value(lead).unwrap(), serde_json::json!("F6.0"));
    assert_eq!(serde_json::to_string(&(length, lead)).unwrap(), r#"["-0.005","F6.0"]"#);
    assert_same(&(length, lead, Doc::Display(vec!["1.000".into()])));
    let mut out = Vec::new();
    to_writer_compact(&mut out, &(Doc::Display(vec!["a\"b".into()]), length, OneLine(lead))).unwrap();
    assert_eq!(String::from_utf8(out).unwrap(), r#"["a\"b","-0.005","F6.0"]"#);
}

/// The corpus's layout: pretty, with each value marked one-line compact
/// on its key's line, however deep, and a one-line value within another
/// (or at the top) as compact.
#[test]
fn the_lines_layout_writes_marked_values_on_one_line() {
    let mm = Units { system: IncrementSystem::IsB, unit: InputUnit::Metric };
    let point = || Doc::OneLine(Box::new(Doc::Struct(vec![(0, Some(Doc::Length(Fixed::new(64_400, mm))))])));
    let doc = Doc::Struct(vec![
        (1, Some(Doc::Str("rapid".into()))),
        (0, Some(point())),
        (2, Some(Doc::OneLine(Box::new(Doc::Seq(vec![point(), Doc::U8(1), Doc::Seq(vec![], true)], false))))),
        (
            3,
            Some(Doc::Seq(
                vec![point(), Doc::Struct(vec![(0, Some(Doc::Map(vec![], false)))]), Doc::Seq(vec![], false)],
                true,
            )),
        ),
    ]);
    let mut out = Vec::new();
    to_writer_lines(&mut out, &doc).unwrap();
    assert_eq!(
        String::from_utf8(out).unwrap(),
        "{\n  \"motion\": \"rapid\",\n  \"x\": {\"x\":\"64.400\"},\n  \"start_angle_millidegrees\": \
         [{\"x\":\"64.400\"},1,[]],\n  \"\": [\n    {\"x\":\"64.400\"},\n    {\n      \"x\": {}\n    },\n    []\n  ]\n}"
    );
    let mut out = Vec::new();
    to_writer_lines(&mut out, &point()).unwrap();
    assert_eq!(out, br#"{"x":"64.400"}"#);
    // Pretty and compact, the mark is nothing (as to serde_json).
    assert_same(&doc);
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
