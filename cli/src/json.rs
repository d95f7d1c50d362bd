//! The `cycleref-moves/1` document as typed values that serialize straight
//! into a writer (the `json` and `jsonl` output contracts in the README),
//! and the pieces the other two documents share with it.
//!
//! Every document is written by [`ser`], one serializer: `expand --format
//! json` and `jsonl` from these types; `check --format json`
//! (`cycleref-check/1`, [`crate::check`]'s report), whose moves have the
//! same point, angle, pass and plunge objects; and each case of `vectors`
//! (`cycleref-vector/1`, [`crate::vectors`]), whose expected moves are
//! these cycles, in the corpus's layout of lines ([`ser::to_writer_lines`]:
//! the values marked [`OneLine`] on one line). Fields are in the
//! contract's order; the moves of a cycle are taken from the engine as
//! they are written, so a cycle of a million moves costs no memory here.
//! The JSON Schemas of the three documents are in `docs/schemas/`.

use std::cell::{Cell, RefCell};
use std::io;

use cycleref::{InputUnit, Motion, Move, Pass, Point, Role, Units};
use cycleref_spec::pipeline::{Cycle, Moves};
use serde::ser::{Serialize, SerializeSeq, Serializer};

use crate::format::{flank_name, kind_name, plunge_of, role_name, EncodeText, Fixed, LeadText, FIXED_BUF};

pub mod ser;

pub use ser::OneLine;

/// A length (`"64.400"`): a string in every human-readable format (its
/// ASCII bytes in the others); [`ser`] copies its digits as they are
/// ([`ser::PLAIN_TEXT`]).
impl Serialize for Fixed {
    #[inline]
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_newtype_struct(ser::PLAIN_TEXT, &Plain(*self))
    }
}

/// A lead word (`"F6.0"`): as [`Fixed`].
impl Serialize for LeadText {
    #[inline]
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_newtype_struct(ser::PLAIN_TEXT, &Plain(*self))
    }
}

/// The value of a [`ser::PLAIN_TEXT`] newtype struct: `T`'s text, as a
/// string to a human-readable serializer, else as its ASCII bytes (which
/// is how [`ser`] takes it, without a UTF-8 check or an escape scan).
struct Plain<T>(T);

impl<T: EncodeText + std::fmt::Display> Serialize for Plain<T> {
    #[inline(always)]
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if s.is_human_readable() {
            s.collect_str(&self.0)
        } else {
            let mut buf = [0; FIXED_BUF];
            s.serialize_bytes(self.0.encode_text(&mut buf))
        }
    }
}

/// `{"unit": "mm", "decimals": 3}`.
#[derive(Clone, Copy, serde::Serialize)]
pub struct UnitsJson {
    unit: &'static str,
    decimals: u32,
}

impl UnitsJson {
    /// The units' description.
    #[must_use]
    pub fn new(u: Units) -> UnitsJson {
        UnitsJson {
            unit: match u.unit {
                InputUnit::Metric => "mm",
                InputUnit::Inch => "inch",
            },
            decimals: u.decimals(),
        }
    }
}

/// `{"x": "…", "z": "…"}`.
#[derive(serde::Serialize)]
pub(crate) struct PointJson {
    x: Fixed,
    z: Fixed,
}

impl PointJson {
    /// The JSON form of `p`.
    pub(crate) fn new(p: Point, u: Units) -> PointJson {
        PointJson { x: Fixed::new(p.x, u), z: Fixed::new(p.z, u) }
    }
}

/// `{"num": …, "den": …}`: a start angle in thousandths of a degree.
#[derive(serde::Serialize)]
pub(crate) struct AngleJson {
    pub(crate) num: u32,
    pub(crate) den: u32,
}

/// The pass a move belongs to: `{"kind", "number", "start", "depth",
/// "cut", "flank"}` (the moves document's and `check`'s).
#[derive(serde::Serialize)]
pub(crate) struct PassJson {
    kind: &'static str,
    number: u32,
    /// Absent in `check`'s moves of LinuxCNC's G76 (one start).
    #[serde(skip_serializing_if = "Option::is_none")]
    start: Option<u16>,
    depth: Fixed,
    cut: Fixed,
    flank: &'static str,
}

impl PassJson {
    /// The JSON form of `p`, with its start when `with_start`.
    pub(crate) fn new(p: Pass, u: Units, with_start: bool) -> PassJson {
        PassJson {
            kind: kind_name(p.kind),
            number: p.number,
            start: with_start.then_some(p.start),
            depth: Fixed::new(p.depth, u),
            cut: Fixed::new(p.cut, u),
            flank: flank_name(p.flank),
        }
    }
}

/// The G75.1 plunge (`{"layer", "number"}`) or layer (`{"layer"}`) a
/// move belongs to.
#[derive(serde::Serialize)]
pub(crate) struct PlungeJson {
    pub(crate) layer: u32,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) number: Option<u32>,
}

/// One move (the `json` contract's move object).
#[derive(serde::Serialize)]
pub struct MoveJson {
    motion: &'static str,
    x: Fixed,
    z: Fixed,
    #[serde(skip_serializing_if = "Option::is_none")]
    centre: Option<PointJson>,
    role: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    lead: Option<LeadText>,
    #[serde(skip_serializing_if = "Option::is_none")]
    start_angle_millidegrees: Option<AngleJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sync: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pass: Option<PassJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    plunge: Option<PlungeJson>,
}

impl MoveJson {
    /// The JSON form of `m`.
    #[must_use]
    pub fn new(m: &Move, u: Units) -> MoveJson {
        let (motion, centre, lead, angle, sync) = match m.motion {
            Motion::Rapid => ("rapid", None, None, None, None),
            Motion::Feed => ("feed", None, None, None, None),
            Motion::Thread { lead, start_angle, sync } => (
                "thread",
                None,
                Some(LeadText(lead)),
                Some(AngleJson { num: start_angle.num, den: start_angle.den }),
                Some(sync),
            ),
            Motion::Arc { centre, clockwise } => (
                if clockwise { "arc-cw" } else { "arc-ccw" },
                Some(PointJson::new(centre, u)),
                None,
                None,
                None,
            ),
        };
        let plunge = match m.role {
            Role::LayerChange(l) => Some(PlungeJson { layer: l, number: None }),
            r => plunge_of(r).map(|p| PlungeJson { layer: p.layer, number: Some(p.number) }),
        };
        MoveJson {
            motion,
            x: Fixed::new(m.to.x, u),
            z: Fixed::new(m.to.z, u),
            centre,
            role: role_name(m.role),
            lead,
            start_angle_millidegrees: angle,
            sync,
            pass: m.pass.map(|p| PassJson::new(p, u, true)),
            plunge,
        }
    }
}

/// The moves of a cycle, serialized as they are taken from the engine.
/// It serializes once: the moves are consumed.
pub struct MovesJson {
    moves: RefCell<Option<Moves>>,
    units: Units,
    /// How many moves were written.
    written: Cell<u64>,
}

impl Serialize for MovesJson {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(None)?;
        if let Some(moves) = self.moves.borrow_mut().take() {
            for m in moves {
                seq.serialize_element(&OneLine(MoveJson::new(&m, self.units)))?;
                self.written.set(self.written.get() + 1);
            }
        }
        seq.end()
    }
}

/// One cycle with its moves (the `json` contract's cycle object).
#[derive(serde::Serialize)]
pub struct CycleJson {
    cycle: &'static str,
    line: usize,
    /// G76: the line of block 1 or null; G75.1: block 1's line; G32: absent.
    #[serde(skip_serializing_if = "Option::is_none")]
    params_line: Option<Option<usize>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    from: Option<OneLine<PointJson>>,
    start: OneLine<PointJson>,
    moves: MovesJson,
}

impl CycleJson {
    /// The JSON form of `cycle`, whose moves are `moves`.
    #[must_use]
    pub fn new(cycle: Cycle<'_, '_>, moves: Moves) -> CycleJson {
        let u = cycle.units();
        CycleJson {
            cycle: cycle.code(),
            line: cycle.line(),
            // Present (null when block 1 came from the parameters) for the
            // cycles of two blocks only.
            params_line: cycle.has_params_block().then(|| cycle.params_line()),
            from: cycle.tool_before_start().map(|p| OneLine(PointJson::new(p, u))),
            start: OneLine(PointJson::new(cycle.start(), u)),
            moves: MovesJson { moves: RefCell::new(Some(moves)), units: u, written: Cell::new(0) },
        }
    }

    /// How many of the cycle's moves were written (all of them once the
    /// document is): `jsonl`'s summary counts them as they go, without
    /// walking the cycle again.
    #[must_use]
    pub fn moves_written(&self) -> u64 {
        self.moves.written.get()
    }
}

/// A sequence serialized from an iterator of serializable values, taken
/// as they are written. It serializes once.
pub struct StreamSeq<I>(pub RefCell<Option<I>>);

impl<I, T, E> Serialize for StreamSeq<I>
where
    I: Iterator<Item = Result<T, E>>,
    T: Serialize,
    E: std::fmt::Display,
{
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(None)?;
        if let Some(items) = self.0.borrow_mut().take() {
            for item in items {
                let item = item.map_err(serde::ser::Error::custom)?;
                seq.serialize_element(&item)?;
            }
        }
        seq.end()
    }
}

/// The `cycleref-moves/1` document.
#[derive(serde::Serialize)]
pub struct MovesDocument<'n, C> {
    /// Always `cycleref-moves/1`.
    pub format: &'static str,
    /// The program's name.
    pub file: &'n str,
    /// The units of every length.
    pub units: UnitsJson,
    /// The readings in force when they differ from the defaults (issue
    /// 34); left out otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub readings: Option<std::collections::BTreeMap<&'static str, &'static str>>,
    /// The cycles.
    pub cycles: C,
}

/// `"\n"` and the indentation of up to 31 levels of two spaces.
const NEWLINE_INDENT: &[u8; 63] = b"\n                                                              ";

/// serde_json's pretty format (two spaces, `": "`), byte for byte, with
/// each line break and its indentation written at once, as a
/// `serde_json::ser::Formatter`. The commands write with [`ser`] since
/// issue 11; this is the reference its tests hold it to (and the way to
/// write these documents with `serde_json` itself).
#[derive(Clone, Debug, Default)]
pub struct Pretty {
    level: usize,
    has_value: bool,
}

impl Pretty {
    /// `first`: a new line; otherwise `,` and a new line; then the indentation.
    fn line<W: ?Sized + io::Write>(&self, w: &mut W, first: bool) -> io::Result<()> {
        if !first {
            w.write_all(b",")?;
        }
        self.newline(w)
    }

    fn newline<W: ?Sized + io::Write>(&self, w: &mut W) -> io::Result<()> {
        let n = 1 + 2 * self.level;
        match NEWLINE_INDENT.get(..n) {
            Some(s) => w.write_all(s),
            None => {
                w.write_all(b"\n")?;
                (0..self.level).try_for_each(|_| w.write_all(b"  "))
            }
        }
    }
}

impl serde_json::ser::Formatter for Pretty {
    #[inline]
    fn begin_array<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.level += 1;
        self.has_value = false;
        w.write_all(b"[")
    }

    #[inline]
    fn end_array<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.level -= 1;
        if self.has_value {
            self.newline(w)?;
        }
        w.write_all(b"]")
    }

    #[inline]
    fn begin_array_value<W: ?Sized + io::Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.line(w, first)
    }

    #[inline]
    fn end_array_value<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        self.has_value = true;
        Ok(())
    }

    #[inline]
    fn begin_object<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.level += 1;
        self.has_value = false;
        w.write_all(b"{")
    }

    #[inline]
    fn end_object<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.level -= 1;
        if self.has_value {
            self.newline(w)?;
        }
        w.write_all(b"}")
    }

    #[inline]
    fn begin_object_key<W: ?Sized + io::Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.line(w, first)
    }

    #[inline]
    fn begin_object_value<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        w.write_all(b": ")
    }

    #[inline]
    fn end_object_value<W: ?Sized + io::Write>(&mut self, _w: &mut W) -> io::Result<()> {
        self.has_value = true;
        Ok(())
    }
}
