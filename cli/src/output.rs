//! The streaming writers of `expand` (nc, json, jsonl) and `passes`.
//!
//! Each writer is the second phase of a run (reading R-STREAM): the
//! program was read and every cycle checked by [`Job::validate`], so the
//! writer reads the program again and writes each block or move as it
//! comes, through one buffered writer. Memory is that of the reader and of
//! one cycle's engine, whatever the program's length. A failure while
//! writing is returned as it is; the caller decides what a closed pipe
//! means.

use std::cell::RefCell;
use std::io::{self, Write};

use cycleref::{Motion, Move, PassKind, Point, Role, Units};
use cycleref_spec::cycles::{MoveWords, PassComment, PassTable};
use cycleref_spec::pipeline::{Cycle, Moves};
use cycleref_spec::profile::QUnit;
use cycleref_spec::reader::{Item, PlainMove, Restore};

use crate::format::{arc_ik, flank_name, kind_name, q_word, Fixed, LeadText, RecentText, FIXED_BUF};
use crate::job::{Cause, Failure, Job};
use crate::json::ser::JsonSerializer;
use crate::json::{CycleJson, MovesDocument, StreamSeq, UnitsJson};

/// The format of `expand`'s output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// The program with each cycle replaced by plain blocks.
    Nc,
    /// One `cycleref-moves/1` document.
    Json,
    /// One JSON object per cycle per line, then a summary line.
    Jsonl,
}

/// Writes `job`'s expansion in `format` to `out`: first the whole program
/// is read and checked, then the output is streamed.
///
/// # Errors
///
/// The program's first error (nothing written), or a failure to write.
///
/// ```
/// use cycleref_cli::{output, Format, Job};
/// use cycleref_spec::pipeline::Engine;
/// use cycleref_spec::{Machine, ProfileName};
///
/// let text = b"M03 S500\nG00 X80 Z10\nG32 Z-20 F2\nG00 X90\n";
/// let job = Job::new("g32.nc", text.to_vec(), Machine::new(ProfileName::Gsk980), Engine::Impl);
/// let mut nc = Vec::new();
/// output::expand(&job, Format::Nc, &mut nc).map_err(String::from)?;
/// assert_eq!(String::from_utf8(nc).unwrap(), "M03 S500\nG00 X80 Z10\nG32 X80.000 Z-20.000 F2.0\nG00 X90\n");
/// // A program the reader refuses writes nothing.
/// let bad = Job::new("bad.nc", b"G32 Z-20 F2\n".to_vec(), Machine::new(ProfileName::Gsk980), Engine::Impl);
/// let mut nc = Vec::new();
/// assert!(output::expand(&bad, Format::Nc, &mut nc).is_err());
/// assert!(nc.is_empty());
/// # Ok::<(), String>(())
/// ```
pub fn expand<W: Write>(job: &Job, format: Format, out: W) -> Result<(), Failure> {
    let summary = job.validate()?;
    // Reading R-LONG988: a cycle whose lead no G32 block can carry.
    if let (Format::Nc, Some((line, code))) = (format, summary.lead_off_g32_axis) {
        return Err(Failure::with_kind(
            Cause::Usage,
            "usage:lead_not_writable",
            format!(
                "{}: line {line}, {code}: under reading R-LONG988=table the lead is along the axis the 988TA's \
                 table names (Z on an axial thread, X on a P1 face thread) while the other displacement of the \
                 cut is not shorter, and a G32 block of it would be read with the lead along that other axis \
                 (the longer displacement): the cycle cannot be written as plain blocks; ask for \
                 --format json, or --reading R-LONG988=displacement",
                job.name
            ),
        ));
    }
    let mut out = io::BufWriter::with_capacity(1 << 16, out);
    let written = match format {
        Format::Nc => nc(job, &mut out),
        Format::Json => json(job, summary.units, &mut out),
        Format::Jsonl => jsonl(job, summary.units, &mut out),
    };
    written.and_then(|()| out.flush()).map_err(|e| Failure::output(&e))
}

/// A reader error in the second phase: the first phase read the same
/// program without one, so this cannot happen short of a failing disk; it
/// is reported, never ignored.
fn phase_two(e: impl std::fmt::Display) -> io::Error {
    io::Error::other(format!("the program read differently the second time: {e}"))
}

/// Calls `f` with each item of `job`'s program (the second phase).
fn each_item(job: &Job, f: impl FnMut(&Item<'_>) -> io::Result<()>) -> io::Result<()> {
    job.for_each_item(
        |failure| match failure {
            Failure::Other(o) => phase_two(o.message),
            Failure::Program(p) => phase_two(p.message),
            Failure::BrokenPipe => io::ErrorKind::BrokenPipe.into(),
        },
        f,
    )
}

/// The moves of `cycle`, which the first phase expanded without alarm.
fn moves(job: &Job, cycle: Cycle<'_, '_>) -> io::Result<Moves> {
    job.expand(cycle).map_err(|f| match f {
        Failure::Other(o) => phase_two(o.message),
        Failure::Program(p) => phase_two(p.message),
        Failure::BrokenPipe => io::ErrorKind::BrokenPipe.into(),
    })
}

/// Whether an auxiliary word of a cycle block is executed after the
/// block's motion (reading R-AUXWORDS): the program stops and ends M00,
/// M01, M02 and M30. Every other M, and S and T, before it.
fn after_motion(w: &cycleref_spec::lex::Word<'_>) -> bool {
    w.letter == 'M' && matches!(w.number().integer(), Some(0 | 1 | 2 | 30))
}

/// The auxiliary words (M, S, T) of a cycle's block that run `after` its
/// motion or before it, in the block's order, as a block of their own
/// (reading R-AUXWORDS): a cycle is replaced by its moves, and these words
/// are kept where the control executes them.
fn nc_aux<W: Write>(out: &mut W, block: &cycleref_spec::lex::Block<'_>, after: bool) -> io::Result<()> {
    let mut first = true;
    for w in block.words.iter().filter(|w| matches!(w.letter, 'M' | 'S' | 'T') && after_motion(w) == after) {
        if !first {
            out.write_all(b" ")?;
        }
        out.write_all(w.text().as_bytes())?;
        first = false;
    }
    if first {
        Ok(())
    } else {
        out.write_all(b"\n")
    }
}

fn nc<W: Write>(job: &Job, out: &mut W) -> io::Result<()> {
    let t = &mut NcText::default();
    // The readings in force that differ from the defaults (issue 34),
    // named under each cycle's heading; empty under the defaults.
    let readings: Vec<String> =
        crate::job::readings_in_force(&job.machine).iter().map(|(id, v)| format!("{id}={v}")).collect();
    let readings = readings.join(", ");
    each_item(job, |item| {
        let cycle = Cycle::of(item);
        match item {
            Item::Source(b) | Item::Move(PlainMove { block: b, .. }) => {
                out.write_all(&b.text)?;
                return out.write_all(b"\n");
            }
            _ => nc_aux(out, item.block(), false)?,
        }
        if let Some(cycle) = cycle {
            let front_post = job.machine.readings.arc_names == cycleref_spec::readings::ArcNames::FrontPost;
            nc_cycle(out, t, cycle, moves(job, cycle)?, (job.q_unit, front_post), &readings)?;
        }
        nc_aux(out, item.block(), true)
    })
}

/// The NC blocks of one cycle (the `nc` format contract, in the README):
/// its heading, its moves in its words ([`MoveWords`]), each pass, start,
/// plunge and contour announced by a comment as the cycle's style asks
/// ([`NcStyle`]), then what restores the modal state the cycle changed.
/// `readings` (the non-default readings, `ID=VALUE, …`) is named on a
/// comment line after the heading when it is not empty; `front_post`:
/// reading R-G75ARC `front-post` (G02/G03 exchanged).
fn nc_cycle<W: Write>(
    out: &mut W,
    t: &mut NcText,
    cycle: Cycle<'_, '_>,
    moves: Moves,
    (q, front_post): (QUnit, bool),
    readings: &str,
) -> io::Result<()> {
    let u = cycle.units();
    let style = cycle.nc_style();
    if let Some(heading) = cycle.heading(&moves) {
        writeln!(out, "({heading})")?;
        if !readings.is_empty() {
            writeln!(out, "(readings: {readings})")?;
        }
    }
    let x_factor = cycle.x_mode().factor();
    let (mut pass, mut plunge, mut contour) = (None, None, None);
    let mut at = cycle.from();
    for m in moves {
        if let Some(p) = m.pass {
            nc_pass_comment(out, style.passes, p, &mut pass, u)?;
        }
        if style.plunges {
            if let Role::Peck(p) = m.role {
                if plunge != Some(p) {
                    plunge = Some(p);
                    writeln!(out, "(layer {} plunge {})", p.layer, p.number)?;
                }
            }
        }
        if style.contours {
            let name = match m.role {
                Role::RoughContour => Some("rough contour"),
                Role::FinishContour => Some("finishing contour"),
                _ => None,
            };
            if let Some(n) = name.filter(|_| name != contour) {
                writeln!(out, "({n})")?;
            }
            contour = name;
        }
        match style.words {
            MoveWords::Fanuc => nc_move(out, t, &m, u, q)?,
            MoveWords::LinuxCnc => nc_g33_move(out, t, &m, u)?,
            MoveWords::Groove => nc_groove_move(out, t, &m, at, (x_factor, front_post), u)?,
        }
        at = m.to;
    }
    restore(out, cycle.restore())
}

/// The comment before the first move of a pass, in `style`, when the pass
/// differs from `last` (the pass of the previous comment).
fn nc_pass_comment<W: Write>(
    out: &mut W,
    style: PassComment,
    p: cycleref::Pass,
    last: &mut Option<(PassKind, u32, u16)>,
    u: Units,
) -> io::Result<()> {
    let key = match style {
        PassComment::None => return Ok(()),
        PassComment::Full => (p.kind, p.number, p.start),
        PassComment::Numbered => (p.kind, p.number, 0),
        PassComment::Starts => (PassKind::Rough, 0, p.start),
    };
    if *last == Some(key) {
        return Ok(());
    }
    *last = Some(key);
    match style {
        PassComment::None => Ok(()),
        PassComment::Full => {
            // `(rough 1 start 1 depth 1.800 cut 1.800)`
            out.write_all(b"(")?;
            out.write_all(kind_name(p.kind).as_bytes())?;
            out.write_all(b" ")?;
            write_number(out, u64::from(p.number))?;
            out.write_all(b" start ")?;
            write_number(out, u64::from(p.start))?;
            out.write_all(b" depth ")?;
            write_fixed(out, Fixed::new(p.depth, u))?;
            out.write_all(b" cut ")?;
            write_fixed(out, Fixed::new(p.cut, u))?;
            out.write_all(b")\n")
        }
        PassComment::Numbered => {
            let kind = if p.kind == PassKind::Rough { "pass" } else { "full depth" };
            writeln!(out, "({kind} {})", p.number)
        }
        PassComment::Starts => writeln!(out, "(start {})", p.start),
    }
}

/// One move in LinuxCNC's words: `G33 X Z K` for a synchronised move (K
/// the distance per revolution along it, R-LCNC-SYNC), else as
/// [`nc_move`] writes it (LinuxCNC reads G00 as G0).
fn nc_g33_move<W: Write>(out: &mut W, t: &mut NcText, m: &Move, u: Units) -> io::Result<()> {
    let Motion::Thread { lead, .. } = m.motion else {
        return nc_move(out, t, m, u, QUnit::Degrees { wrap: false });
    };
    xz(out, t, b"G33 ", m.to, u)?;
    let text = t.lead.text(LeadText(lead));
    // The lead's text is "F…": K carries the same value.
    out.write_all(b" K")?;
    out.write_all(&text[1..])?;
    out.write_all(b"\n")
}

/// One G75.1 move: arcs with I/K, the rest as [`nc_move`]. Reading
/// R-G75ARC: G02 for an arc clockwise seen with +Z right and +X up
/// (`rear-post`), the codes exchanged under `front-post`.
fn nc_groove_move<W: Write>(
    out: &mut W,
    t: &mut NcText,
    m: &Move,
    from: Point,
    (x_factor, front_post): (i64, bool),
    u: Units,
) -> io::Result<()> {
    if let Motion::Arc { centre, clockwise } = m.motion {
        let (i, k) = arc_ik(from, centre, x_factor, u);
        let g = if clockwise != front_post { "G02" } else { "G03" };
        writeln!(out, "{g} X{} Z{} I{i} K{k}", Fixed::new(m.to.x, u), Fixed::new(m.to.z, u))
    } else {
        nc_move(out, t, m, u, QUnit::Millidegrees { no_point: true })
    }
}

/// Writes `v`'s text (the hot path of the nc writer: the number is encoded
/// on the stack and handed to the buffered writer, whose short writes are
/// copies into its buffer; no formatting machinery, no line assembled
/// first).
fn write_fixed<W: Write>(out: &mut W, v: Fixed) -> io::Result<()> {
    let mut buf = [0; FIXED_BUF];
    out.write_all(v.encode(&mut buf))
}

/// Writes `v` in decimal.
fn write_number<W: Write>(out: &mut W, v: u64) -> io::Result<()> {
    let mut buf = [0; FIXED_BUF];
    out.write_all(crate::format::encode_fixed(&mut buf, false, v, 0))
}

/// The texts the nc writer wrote last for the X and Z of a move and for a
/// lead ([`RecentText`]): most moves of a thread return to an X or a Z
/// written before, and every G32 block of a cycle has the same lead.
#[derive(Default)]
struct NcText {
    x: RecentText<Fixed>,
    z: RecentText<Fixed>,
    lead: RecentText<LeadText>,
}

/// Appends `head`, then `X` and `Z` of `to`.
#[inline]
fn xz<W: Write>(out: &mut W, t: &mut NcText, head: &[u8], to: Point, u: Units) -> io::Result<()> {
    out.write_all(head)?;
    out.write_all(b"X")?;
    out.write_all(t.x.text(Fixed::new(to.x, u)))?;
    out.write_all(b" Z")?;
    out.write_all(t.z.text(Fixed::new(to.z, u)))
}

/// One move as an NC block.
fn nc_move<W: Write>(out: &mut W, t: &mut NcText, m: &Move, u: Units, q: QUnit) -> io::Result<()> {
    match m.motion {
        Motion::Rapid => xz(out, t, b"G00 ", m.to, u)?,
        Motion::Feed => xz(out, t, b"G01 ", m.to, u)?,
        Motion::Thread { lead, start_angle, sync } => {
            xz(out, t, b"G32 ", m.to, u)?;
            out.write_all(b" ")?;
            out.write_all(t.lead.text(LeadText(lead)))?;
            // Q only where synchronisation starts: on a continuation block
            // the control ignores it (seed 002, Q rule 2).
            if sync && !start_angle.is_zero() {
                out.write_all(b" Q")?;
                out.write_all(q_word(start_angle, u, q).as_bytes())?;
            }
        }
        Motion::Arc { centre, clockwise } => {
            // Without the start point the centre is written absolute.
            xz(out, t, if clockwise { b"G02 " } else { b"G03 " }, m.to, u)?;
            out.write_all(b" (centre X")?;
            write_fixed(out, Fixed::new(centre.x, u))?;
            out.write_all(b" Z")?;
            write_fixed(out, Fixed::new(centre.z, u))?;
            out.write_all(b")")?;
        }
    }
    out.write_all(b"\n")
}

fn restore<W: Write>(out: &mut W, r: Restore) -> io::Result<()> {
    match r.motion {
        Some(g) => writeln!(out, "{}", g.code()),
        None => Ok(()),
    }
}

/// The cycles of `job`, each with its moves, as they are read.
fn cycle_documents(job: &Job) -> io::Result<impl Iterator<Item = io::Result<CycleJson>> + '_> {
    let mut items = job.items().map_err(|f| phase_two(String::from(f)))?;
    Ok(std::iter::from_fn(move || loop {
        let document =
            items.next_with(|item| Cycle::of(item).map(|c| moves(job, c).map(|m| CycleJson::new(c, m))));
        match document? {
            Ok(Some(document)) => return Some(document),
            Ok(None) => {}
            Err(e) => return Some(Err(phase_two(e))),
        }
    }))
}

fn json<W: Write>(job: &Job, units: Units, out: &mut W) -> io::Result<()> {
    let doc = MovesDocument {
        format: "cycleref-moves/1",
        file: &job.name,
        units: UnitsJson::new(units),
        readings: crate::job::readings_json(&crate::job::readings_in_force(&job.machine)),
        cycles: StreamSeq(RefCell::new(Some(cycle_documents(job)?))),
    };
    let mut ser = JsonSerializer::<_, true>::new(&mut *out);
    ser.write_line(&doc)?;
    ser.finish()
}

/// The summary line of the jsonl format.
#[derive(serde::Serialize)]
struct JsonlSummary<'n> {
    format: &'static str,
    file: &'n str,
    units: UnitsJson,
    #[serde(skip_serializing_if = "Option::is_none")]
    readings: Option<std::collections::BTreeMap<&'static str, &'static str>>,
    cycles: usize,
    moves: u64,
}

fn jsonl<W: Write>(job: &Job, units: Units, out: &mut W) -> io::Result<()> {
    let (mut cycles, mut moves_total) = (0, 0_u64);
    let mut ser = JsonSerializer::<_, false>::new(&mut *out);
    each_item(job, |item| {
        let Some(c) = Cycle::of(item) else { return Ok(()) };
        // Counted as they are written: the summary line comes last.
        let document = CycleJson::new(c, moves(job, c)?);
        ser.write_line(&document)?;
        moves_total += document.moves_written();
        cycles += 1;
        Ok(())
    })?;
    let summary = JsonlSummary {
        format: "cycleref-moves-jsonl/1",
        file: &job.name,
        units: UnitsJson::new(units),
        readings: crate::job::readings_json(&crate::job::readings_in_force(&job.machine)),
        cycles,
        moves: moves_total,
    };
    ser.write_line(&summary)?;
    ser.finish()
}

/// Writes the pass tables of `job`, reading the program once: each cycle's
/// table in program order, and the consecutive single-block threads of one
/// kind (G32, G33, G92) as the rows of one table ([`PassTable`]).
///
/// # Errors
///
/// The program's first error (nothing written), or a failure to write.
pub fn passes<W: Write>(job: &Job, out: W) -> Result<(), Failure> {
    if job.validate()?.cycles == 0 {
        // No cycle, no table: the program is not read again.
        return Ok(());
    }
    let mut out = io::BufWriter::with_capacity(1 << 16, out);
    // The title of the table of single-block threads being written.
    let mut rows: Option<&'static str> = None;
    let written = each_item(job, |item| {
        let Some(cycle) = Cycle::of(item) else { return Ok(()) };
        let table = cycle.pass_table();
        let title = match table {
            PassTable::Row { title, .. } => Some(title),
            _ => None,
        };
        if rows.is_some() && rows != title {
            out.write_all(b"\n")?;
        }
        let moves = moves(job, cycle)?;
        match table {
            PassTable::Passes => pass_rows(&mut out, job, cycle, moves),
            PassTable::LinuxCncPasses => linuxcnc_rows(&mut out, job, cycle, moves),
            PassTable::Plunges => plunge_rows(&mut out, job, cycle, moves),
            PassTable::Row { title, columns, sync } => {
                if rows != Some(title) {
                    thread_heading(&mut out, title, &job.name, columns)?;
                }
                thread_rows(&mut out, cycle, moves, sync)
            }
        }?;
        rows = title;
        Ok(())
    })
    .and_then(|()| if rows.is_some() { out.write_all(b"\n") } else { Ok(()) })
    .and_then(|()| out.flush());
    written.map_err(|e| Failure::output(&e))
}

const PASS_ROW: [&str; 8] = ["pass", "kind", "start", "flank", "depth", "cut", "X", "Z"];

/// The table of a cycle's passes ([`PassTable::Passes`]: G76, G78).
fn pass_rows<W: Write>(out: &mut W, job: &Job, cycle: Cycle<'_, '_>, moves: Moves) -> io::Result<()> {
    let u = cycle.units();
    writeln!(out, "{} at line {} ({}):", cycle.code(), cycle.line(), job.name)?;
    let [a, b, c, d, e, f, g, h] = PASS_ROW;
    writeln!(out, "{a:>6} {b:>6} {c:>5} {d:>6} {e:>12} {f:>12} {g:>14} {h:>14}")?;
    let mut moves = moves.peekable();
    while let Some(m) = moves.next() {
        if m.role != Role::Approach {
            continue;
        }
        let Some(p) = m.pass else { continue };
        // The pass start Bn is where the approach ends, unless a lead-in
        // of the same pass follows: then where that ends.
        let bn = moves.peek().filter(|n| n.role == Role::LeadIn && n.pass == Some(p)).map_or(m.to, |n| n.to);
        writeln!(
            out,
            "{:>6} {:>6} {:>5} {:>6} {:>12} {:>12} {:>14} {:>14}",
            p.number,
            kind_name(p.kind),
            p.start,
            flank_name(p.flank),
            Fixed::new(p.depth, u),
            Fixed::new(p.cut, u),
            Fixed::new(bn.x, u),
            Fixed::new(bn.z, u)
        )?;
    }
    out.write_all(b"\n")
}

/// The passes of a LinuxCNC G76 ([`PassTable::LinuxCncPasses`]): one row
/// per pass with its depth below the peak and its cut (radius), the X of
/// the cut, and the Z where the pass starts and ends (both shifted by the
/// compound angle, reading R-LCNC-PASS).
fn linuxcnc_rows<W: Write>(out: &mut W, job: &Job, cycle: Cycle<'_, '_>, moves: Moves) -> io::Result<()> {
    let u = cycle.units();
    writeln!(out, "{} (LinuxCNC) at line {} ({}):", cycle.code(), cycle.line(), job.name)?;
    let heading = ["pass", "kind", "flank", "depth", "cut", "X", "Z from", "Z to"];
    let [a, b, c, d, e, f, g, h] = heading;
    writeln!(out, "{a:>6} {b:>6} {c:>6} {d:>12} {e:>12} {f:>14} {g:>14} {h:>14}")?;
    // (pass, Z of its first move, X of its cut)
    let mut open: Option<(cycleref::Pass, i64, i64)> = None;
    for m in moves {
        let Some(p) = m.pass else { continue };
        let entry = open.get_or_insert((p, m.to.z, m.to.x));
        if m.role == Role::Cut {
            entry.2 = m.to.x;
        }
        if m.role == Role::Retract {
            writeln!(
                out,
                "{:>6} {:>6} {:>6} {:>12} {:>12} {:>14} {:>14} {:>14}",
                p.number,
                if p.kind == PassKind::Rough { "rough" } else { "full" },
                flank_name(p.flank),
                Fixed::new(p.depth, u),
                Fixed::new(p.cut, u),
                Fixed::new(entry.2, u),
                Fixed::new(entry.1, u),
                Fixed::new(m.to.z, u)
            )?;
            open = None;
        }
    }
    out.write_all(b"\n")
}

/// The layers and plunges of a G75.1 cycle ([`PassTable::Plunges`]): one
/// row per plunge with its Z, the X it starts from (Amn), the X it reaches
/// (Bmn) and its pecks.
fn plunge_rows<W: Write>(out: &mut W, job: &Job, cycle: Cycle<'_, '_>, moves: Moves) -> io::Result<()> {
    let u = cycle.units();
    let first = cycle.params_line().unwrap_or(cycle.line());
    writeln!(out, "{} at lines {}-{} ({}):", cycle.code(), first, cycle.line(), job.name)?;
    writeln!(
        out,
        "{:>6} {:>7} {:>14} {:>14} {:>14} {:>6}",
        "layer", "plunge", "Z", "from X (Amn)", "to X (Bmn)", "pecks"
    )?;
    let row = |out: &mut W, r: &Option<(cycleref::Plunge, Point, Point, u32)>| -> io::Result<()> {
        if let Some((p, start, bottom, pecks)) = r {
            writeln!(
                out,
                "{:>6} {:>7} {:>14} {:>14} {:>14} {:>6}",
                p.layer,
                p.number,
                Fixed::new(start.z, u),
                Fixed::new(start.x, u),
                Fixed::new(bottom.x, u),
                pecks
            )?;
        }
        Ok(())
    };
    let mut at = cycle.from();
    let mut current: Option<(cycleref::Plunge, Point, Point, u32)> = None;
    let (mut rough, mut finish) = (0, 0);
    for m in moves {
        if let Role::Peck(p) = m.role {
            match &mut current {
                Some((q, _, bottom, pecks)) if *q == p => {
                    *bottom = m.to;
                    *pecks += 1;
                }
                _ => {
                    row(out, &current)?;
                    current = Some((p, at, m.to, 1));
                }
            }
        }
        if m.motion != Motion::Rapid {
            rough += usize::from(m.role == Role::RoughContour);
            finish += usize::from(m.role == Role::FinishContour);
        }
        at = m.to;
    }
    row(out, &current)?;
    if rough > 0 {
        writeln!(out, "rough contour (step 9): {rough} cutting moves")?;
    }
    if finish > 0 {
        writeln!(out, "finishing contour (step 10): {finish} cutting moves")?;
    }
    out.write_all(b"\n")
}

/// One row of a single-block thread table (G32, G92): the block's line, a
/// five-wide column, then three points (X and Z each), the last one `-`
/// when absent.
fn thread_row<W: Write>(
    out: &mut W,
    line: usize,
    second: &str,
    points: [Point; 2],
    last: Option<Point>,
    u: Units,
) -> io::Result<()> {
    let (rx, rz) = last.map_or(("-".into(), "-".into()), |p: Point| {
        (Fixed::new(p.x, u).to_string(), Fixed::new(p.z, u).to_string())
    });
    let [a, b] = points;
    writeln!(
        out,
        "{line:>6} {second:>5} {:>14} {:>14} {:>14} {:>14} {rx:>14} {rz:>14}",
        Fixed::new(a.x, u),
        Fixed::new(a.z, u),
        Fixed::new(b.x, u),
        Fixed::new(b.z, u),
    )
}

/// The heading of a single-block thread table.
fn thread_heading<W: Write>(out: &mut W, title: &str, name: &str, columns: [&str; 8]) -> io::Result<()> {
    writeln!(out, "{title} ({name}):")?;
    let [a, b, c, d, e, f, g, h] = columns;
    writeln!(out, "{a:>6} {b:>5} {c:>14} {d:>14} {e:>14} {f:>14} {g:>14} {h:>14}")
}

/// The rows of one single-block thread ([`PassTable::Row`]), a row per
/// start: where the cut starts (the end of the approach, or the cycle's
/// start when it has none), where the cut ends and where the run-out ends;
/// the second column is the block's synchronisation when `sync` gives it,
/// else the start's number.
fn thread_rows<W: Write>(
    out: &mut W,
    cycle: Cycle<'_, '_>,
    moves: Moves,
    sync: Option<bool>,
) -> io::Result<()> {
    let (line, u, a) = (cycle.line(), cycle.units(), cycle.start());
    let mut row = |start: u16, b: Point, cut: Point, run_out: Option<Point>| {
        let second = match sync {
            Some(true) => "yes".to_string(),
            Some(false) => "no".to_string(),
            None => start.to_string(),
        };
        thread_row(out, line, &second, [b, cut], run_out, u)
    };
    // (start, B, end of the first cut, end of the first run-out); a cut
    // left out (K = |W|: the whole thread is run-out) ends at B.
    let mut current: Option<(u16, Point, Option<Point>, Option<Point>)> = None;
    for m in moves {
        let start = m.pass.map_or(1, |p| p.start);
        if let Some((s, b, cut, r)) = current.filter(|(s, ..)| *s != start) {
            row(s, b, cut.unwrap_or(b), r)?;
            current = None;
        }
        let entry = current.get_or_insert((start, a, None, None));
        match m.role {
            Role::Approach => entry.1 = m.to,
            Role::Cut if entry.2.is_none() => entry.2 = Some(m.to),
            Role::RunOut if entry.3.is_none() => entry.3 = Some(m.to),
            _ => {}
        }
    }
    match current {
        Some((s, b, cut, r)) => row(s, b, cut.unwrap_or(b), r),
        // A G32 block without moves: its row still stands.
        None if sync.is_some() => row(1, a, a, None),
        None => Ok(()),
    }
}
