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
use cycleref_spec::cycles::{MoveWords, NcStyle, PassComment, PassTable, HEADING_BUF};
use cycleref_spec::pipeline::{Cycle, Moves};
use cycleref_spec::profile::QUnit;
use cycleref_spec::reader::{Item, PlainMove, Restore};

use crate::format::{arc_ik, flank_name, kind_name, put_fixed, put_lead, q_value, Fixed, FIXED_BUF};
use crate::job::{Cause, Failure, Job};
use crate::json::ser::JsonSerializer;
use crate::json::{CycleJson, MovesDocument, StreamSeq, UnitsJson};
use cycleref_spec::text::put_integer;

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
    if format == Format::Nc {
        let mut out = NcOut::new(out);
        return nc(job, &mut out).and_then(|()| out.flush()).map_err(|e| Failure::output(&e));
    }
    let mut out = io::BufWriter::with_capacity(1 << 16, out);
    let written = match format {
        Format::Nc => unreachable!("written above"),
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
///
/// Before the motion of a LinuxCNC G76 block (`x_mode_words`), its G7 or
/// G8 comes first: the X mode the cycle was read in (a G7/G8 that changes
/// it is read under R-LCNC-G7 `as-interpreter`; one that does not is kept
/// as written), so that the expansion read again is in the same mode.
fn nc_aux<W: Write>(
    out: &mut NcOut<W>,
    block: &cycleref_spec::lex::Block<'_>,
    after: bool,
    x_mode_words: bool,
) -> io::Result<()> {
    // The usual cycle block has none of them: decided by the block's
    // letters, without a look at its words (issue 33: a G75.1 block's nine
    // words were searched twice a block).
    let x_mode_here = x_mode_words && !after;
    if !(block.has('M') || block.has('S') || block.has('T') || x_mode_here && block.has('G')) {
        return Ok(());
    }
    let mut first = true;
    let x_mode = |w: &&cycleref_spec::lex::Word<'_>| {
        x_mode_here && w.letter == 'G' && matches!(w.number().integer(), Some(7 | 8))
    };
    let aux =
        |w: &&cycleref_spec::lex::Word<'_>| matches!(w.letter, 'M' | 'S' | 'T') && after_motion(w) == after;
    for w in block.words.iter().filter(x_mode).chain(block.words.iter().filter(aux)) {
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

fn nc<W: Write>(job: &Job, out: &mut NcOut<W>) -> io::Result<()> {
    // The readings in force that differ from the defaults (issue 34),
    // named under each cycle's heading; empty under the defaults.
    let readings: Vec<String> =
        crate::job::readings_in_force(&job.machine).iter().map(|(id, v)| format!("{id}={v}")).collect();
    let readings = readings.join(", ");
    let front_post = job.machine.readings.arc_names == cycleref_spec::readings::ArcNames::FrontPost;
    let t = &mut NcText::default();
    each_item(job, |item| {
        let cycle = Cycle::of(item);
        match item {
            Item::Source(b) | Item::Move(PlainMove { block: b, .. }) => return out.text_line(&b.text),
            _ => nc_aux(out, item.block(), false, matches!(item, Item::LinuxCncG76(_)))?,
        }
        if let Some(cycle) = cycle {
            nc_cycle(out, t, cycle, moves(job, cycle)?, (job.q_unit, front_post), &readings)?;
        }
        nc_aux(out, item.block(), true, false)
    })
}

/// The NC blocks of one cycle (the `nc` format contract, in the README):
/// its heading, its moves in its words ([`MoveWords`]), each pass, start,
/// plunge and contour announced by a comment as the cycle's style asks
/// ([`NcStyle`](cycleref_spec::cycles::NcStyle)), then what restores the
/// modal state the cycle changed. `readings` (the non-default readings,
/// `ID=VALUE, …`) is named on a comment line after the heading when it is
/// not empty; `front_post`: reading R-G75ARC `front-post` (G02/G03
/// exchanged).
fn nc_cycle<W: Write>(
    out: &mut NcOut<W>,
    t: &mut NcText,
    cycle: Cycle<'_, '_>,
    moves: Moves,
    (q, front_post): (QUnit, bool),
    readings: &str,
) -> io::Result<()> {
    let u = cycle.units();
    let style = cycle.nc_style();
    if let Some(heading) = cycle.heading(&moves) {
        let text = heading.text();
        out.line(|l| {
            l.put(b"(");
            l.put(text.as_bytes());
            l.put(b")\n");
        })?;
        if !readings.is_empty() {
            writeln!(out, "(readings: {readings})")?;
        }
    }
    let x_factor = cycle.x_mode().factor();
    if style.words == MoveWords::Fanuc && !style.plunges && !style.contours {
        // G76, G78, G92, G32: a pass comment and the move, the style's
        // other questions answered once for the cycle rather than at
        // every move (issue 33: they were a fifth of the loop).
        let mut pass = None;
        moves.try_for_each_move(|m| {
            if let Some(p) = m.pass {
                // The comment only where the pass changes (most moves are
                // of the pass before): decided here, without a call.
                let key = pass_key(style.passes, p);
                if key.is_some() && pass != key {
                    pass = key;
                    nc_pass_line(out, style.passes, p, u)?;
                }
            }
            nc_move(out, t, &m, u, q)
        })?;
        return restore(out, cycle.restore());
    }
    let mut s = NcCycleState { pass: None, plunge: None, contour: 0, at: cycle.from() };
    let words = (u, q, x_factor, front_post);
    if style == NcStyle::GROOVE {
        // G75.1: the same body with the style a constant, its questions
        // answered when the loop is compiled (issue 33).
        // The closure holds the words by value, so that they stay in
        // registers across the loop's writes.
        let (out, t, s) = (&mut *out, &mut *t, &mut s);
        moves.try_for_each_move(
            #[inline(always)]
            move |m| nc_styled_move(out, t, s, &m, NcStyle::GROOVE, words),
        )?;
    } else {
        moves.try_for_each_move(|m| nc_styled_move(out, t, &mut s, &m, style, words))?;
    }
    restore(out, cycle.restore())
}

/// What the `nc` writer keeps between the moves of a cycle: the pass,
/// plunge and contour of the last comment, and where the tool is.
struct NcCycleState {
    pass: Option<(PassKind, u32, u16)>,
    plunge: Option<cycleref::Plunge>,
    /// The contour of the last move: 0 none, 1 rough, 2 finishing.
    contour: u8,
    at: Point,
}

/// One move of a cycle in `style`, with the comments before it (pass,
/// plunge, contour): [`nc_cycle`]'s loop body, inlined into each of its
/// loops. `words`: the units, the unit of Q, the X factor and reading
/// R-G75ARC `front-post`.
#[inline(always)]
fn nc_styled_move<W: Write>(
    out: &mut NcOut<W>,
    t: &mut NcText,
    s: &mut NcCycleState,
    m: &Move,
    style: NcStyle,
    (u, q, x_factor, front_post): (Units, QUnit, i64, bool),
) -> io::Result<()> {
    if let Some(p) = m.pass {
        nc_pass_comment(out, style.passes, p, &mut s.pass, u)?;
    }
    if style.plunges {
        if let Role::Peck(p) = m.role {
            if s.plunge != Some(p) {
                s.plunge = Some(p);
                out.line(|l| {
                    l.put(b"(layer ");
                    l.number(u64::from(p.layer));
                    l.put(b" plunge ");
                    l.number(u64::from(p.number));
                    l.put(b")\n");
                })?;
            }
        }
    }
    if style.contours {
        // The contour as a code (0: none), compared and kept in one byte.
        let (contour, name): (u8, &[u8]) = match m.role {
            Role::RoughContour => (1, b"rough contour"),
            Role::FinishContour => (2, b"finishing contour"),
            _ => (0, b""),
        };
        if contour != 0 && contour != s.contour {
            out.line(|l| {
                l.put(b"(");
                l.put(name);
                l.put(b")\n");
            })?;
        }
        s.contour = contour;
    }
    match style.words {
        MoveWords::Fanuc => nc_move(out, t, m, u, q)?,
        MoveWords::LinuxCnc => nc_g33_move(out, t, m, u)?,
        MoveWords::Groove => nc_groove_move(out, t, m, s.at, (x_factor, front_post), u)?,
    }
    s.at = m.to;
    Ok(())
}

/// The comment before the first move of a pass, in `style`, when the pass
/// differs from `last` (the pass of the previous comment).
fn nc_pass_comment<W: Write>(
    out: &mut NcOut<W>,
    style: PassComment,
    p: cycleref::Pass,
    last: &mut Option<(PassKind, u32, u16)>,
    u: Units,
) -> io::Result<()> {
    let Some(key) = pass_key(style, p) else {
        return Ok(());
    };
    if *last == Some(key) {
        return Ok(());
    }
    *last = Some(key);
    nc_pass_line(out, style, p, u)
}

/// What tells the passes of `style` apart (a comment where it changes), or
/// `None` when `style` writes none.
#[inline(always)]
fn pass_key(style: PassComment, p: cycleref::Pass) -> Option<(PassKind, u32, u16)> {
    match style {
        PassComment::None => None,
        PassComment::Full => Some((p.kind, p.number, p.start)),
        PassComment::Numbered => Some((p.kind, p.number, 0)),
        PassComment::Starts => Some((PassKind::Rough, 0, p.start)),
    }
}

/// The comment of pass `p` in `style` ([`nc_pass_comment`]).
fn nc_pass_line<W: Write>(
    out: &mut NcOut<W>,
    style: PassComment,
    p: cycleref::Pass,
    u: Units,
) -> io::Result<()> {
    let d = u.decimals();
    out.line(|l| match style {
        PassComment::None => {}
        PassComment::Full => {
            // `(rough 1 start 1 depth 1.800 cut 1.800)`
            l.put(b"(");
            l.put(kind_name(p.kind).as_bytes());
            l.put(b" ");
            l.number(u64::from(p.number));
            l.put(b" start ");
            l.number(u64::from(p.start));
            l.put(b" depth ");
            l.fixed(p.depth, d);
            l.put(b" cut ");
            l.fixed(p.cut, d);
            l.put(b")\n");
        }
        PassComment::Numbered => {
            l.put(if p.kind == PassKind::Rough { b"(pass " } else { b"(full depth " });
            l.number(u64::from(p.number));
            l.put(b")\n");
        }
        PassComment::Starts => {
            l.put(b"(start ");
            l.number(u64::from(p.start));
            l.put(b")\n");
        }
    })
}

/// One move in LinuxCNC's words: `G33 X Z K` for a synchronised move (K
/// the distance per revolution along it, R-LCNC-SYNC), else as
/// [`nc_move`] writes it (LinuxCNC reads G00 as G0).
fn nc_g33_move<W: Write>(out: &mut NcOut<W>, t: &mut NcText, m: &Move, u: Units) -> io::Result<()> {
    let Motion::Thread { lead, .. } = m.motion else {
        return nc_move(out, t, m, u, QUnit::Degrees { wrap: false });
    };
    out.line(|l| {
        l.xz(t, b"G33 X", m.to, u.decimals());
        // The lead's value, in the word K.
        l.put(b" K");
        l.lead_value(lead);
        l.put(b"\n");
    })
}

/// One G75.1 move: arcs with I/K, the rest as [`nc_move`]. Reading
/// R-G75ARC: G02 for an arc clockwise seen with +Z right and +X up
/// (`rear-post`), the codes exchanged under `front-post`.
#[inline(always)]
fn nc_groove_move<W: Write>(
    out: &mut NcOut<W>,
    t: &mut NcText,
    m: &Move,
    from: Point,
    (x_factor, front_post): (i64, bool),
    u: Units,
) -> io::Result<()> {
    let Motion::Arc { centre, clockwise } = m.motion else {
        // Most of a groove's moves: [`nc_move`]'s words inlined here
        // (issue 33: its call was a tenth of a groove's move).
        return out.line(
            #[inline(always)]
            |l| nc_move_words(l, t, m, u, QUnit::Millidegrees { no_point: true }),
        );
    };
    nc_arc(out, t, m.to, (from, centre, clockwise), (x_factor, front_post), u)
}

/// A G75.1 arc from `from` around `centre` to `to`: [`nc_groove_move`]'s,
/// out of line (a few moves of a groove).
#[inline(never)]
fn nc_arc<W: Write>(
    out: &mut NcOut<W>,
    t: &mut NcText,
    to: Point,
    (from, centre, clockwise): (Point, Point, bool),
    (x_factor, front_post): (i64, bool),
    u: Units,
) -> io::Result<()> {
    let d = u.decimals();
    let ((i, i_decimals), k) = arc_ik(from, centre, x_factor, u);
    out.line(|l| {
        l.xz(t, if clockwise != front_post { b"G02 X" } else { b"G03 X" }, to, d);
        l.put(b" I");
        l.fixed_wide(i, i_decimals);
        l.put(b" K");
        l.fixed(k, d);
        l.put(b"\n");
    })
}

/// One move as an NC block (a function of its own, as the G76 writer's
/// loop calls it: inlined there, the loop's code is slower).
#[inline(never)]
fn nc_move<W: Write>(out: &mut NcOut<W>, t: &mut NcText, m: &Move, u: Units, q: QUnit) -> io::Result<()> {
    out.line(|l| nc_move_words(l, t, m, u, q))
}

/// [`nc_move`]'s block written into `l`: the one home of a move's words,
/// inlined where a writer calls it.
#[inline(always)]
fn nc_move_words(l: &mut Line<'_>, t: &mut NcText, m: &Move, u: Units, q: QUnit) {
    let d = u.decimals();
    match m.motion {
        Motion::Rapid => l.xz(t, b"G00 X", m.to, d),
        Motion::Feed => l.xz(t, b"G01 X", m.to, d),
        Motion::Thread { lead, start_angle, sync } => {
            l.xz(t, b"G32 X", m.to, d);
            l.put(b" ");
            t.lead(l, lead);
            // Q only where synchronisation starts: on a continuation
            // block the control ignores it (seed 002, Q rule 2).
            if sync && !start_angle.is_zero() {
                l.put(b" Q");
                let (v, decimals) = q_value(start_angle, u, q);
                l.unsigned(v, decimals);
            }
        }
        Motion::Arc { centre, clockwise } => {
            // Without the start point the centre is written absolute.
            l.xz(t, if clockwise { b"G02 X" } else { b"G03 X" }, m.to, d);
            l.put(b" (centre X");
            l.fixed(centre.x, d);
            l.put(b" Z");
            l.fixed(centre.z, d);
            l.put(b")");
        }
    }
    l.put(b"\n");
}

fn restore<W: Write>(out: &mut NcOut<W>, r: Restore) -> io::Result<()> {
    match r.motion {
        Some(g) => out.line(|l| {
            l.put(g.code().as_bytes());
            l.put(b"\n");
        }),
        None => Ok(()),
    }
}

/// The texts the nc writer wrote last for the X or the Z of a move (a
/// thread's passes return to the same retract X and start and end Z: most
/// coordinates were written before): [`RECENT`] places, each value in
/// the one its hash chooses (one comparison a look-up); a value that finds
/// another in its place takes it. Every place always holds a value and its
/// text with `decimals` decimals (at first, and after the decimals change,
/// 0's), so that a look-up compares one integer. A text is kept at the
/// start of 32 bytes and copied whole (a copy of constant length, no call),
/// the line then advanced by its length.
#[derive(Clone)]
struct Recent {
    /// The decimals of every text kept.
    decimals: u32,
    keys: [i64; RECENT],
    lens: [u8; RECENT],
    texts: [[u8; 32]; RECENT],
}

impl Default for Recent {
    fn default() -> Recent {
        let mut r = Recent { decimals: 0, keys: [0; RECENT], lens: [0; RECENT], texts: [[0; 32]; RECENT] };
        r.empty(0);
        r
    }
}

/// The places of a [`Recent`]: 32, so that a G75.1 groove's plunges, which
/// return to 14 or so X values (each peck's depth and retract), find each
/// of them kept (issue 33: with eight places most of a groove's X texts
/// were formatted again, a third of its writer's work).
const RECENT: usize = 32;

/// The X and Z texts of [`Recent`], and the text of the lead last
/// written with its word (every G32 block of a cycle has the same lead).
#[derive(Clone, Default)]
struct NcText {
    x: Recent,
    z: Recent,
    lead: Option<(cycleref::Lead, [u8; 32], usize)>,
}

impl NcText {
    /// Writes the lead word ([`put_lead`]) into `l`, from the kept text
    /// when it is the same lead.
    #[inline(always)]
    fn lead(&mut self, l: &mut Line<'_>, lead: cycleref::Lead) {
        // Kept only when its text fits in 32 bytes: a word, at most 20
        // digits, a point and ".0" with at most 8 decimals.
        if lead.scale > 8 {
            return l.lead(lead);
        }
        let (_, text, len) = match &mut self.lead {
            Some(kept) if kept.0 == lead => kept,
            kept => {
                let mut text = [0; 32];
                let len = put_lead(&mut text, lead, true);
                kept.insert((lead, text, len))
            }
        };
        l.buf[l.at..l.at + 32].copy_from_slice(text);
        // At most 32 (the `min` only tells the compiler so: the line's
        // later writes then need no bounds check).
        l.at += (*len).min(32);
    }
}

impl Recent {
    /// Every place 0 with `decimals` decimals (at most 9).
    #[cold]
    fn empty(&mut self, decimals: u32) {
        let mut zero = [0; 32];
        // At most 1 + 9 = 10 bytes.
        let len = put_fixed(&mut zero, false, 0, decimals);
        self.decimals = decimals;
        self.keys = [0; RECENT];
        self.lens = [u8::try_from(len).unwrap_or(32); RECENT];
        self.texts = [zero; RECENT];
    }

    /// Writes `v` with `decimals` into `l`, from the kept text when it is
    /// there.
    #[inline]
    fn put(&mut self, l: &mut Line<'_>, v: i64, decimals: u32) {
        // A text longer than 32 bytes is never kept (decimals above 9;
        // the increment systems have at most 5).
        if decimals > 9 {
            // At most FIXED_BUF bytes (the `min` bounds `at` for the
            // compiler, as below).
            let n = put_fixed(&mut l.buf[l.at..], v < 0, v.unsigned_abs(), decimals);
            l.at += n.min(FIXED_BUF);
            return;
        }
        if decimals != self.decimals {
            self.empty(decimals);
        }
        // Fibonacci hashing: the top bits of the product spread values
        // that differ in their low digits over the places.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let slot = ((v as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 59) as usize % RECENT;
        if self.keys[slot] != v {
            // At most 1 + 19 + 1 + 9 = 30 bytes.
            let len = put_fixed(&mut self.texts[slot], v < 0, v.unsigned_abs(), decimals);
            self.lens[slot] = u8::try_from(len).unwrap_or(32);
            self.keys[slot] = v;
        }
        l.buf[l.at..l.at + 32].copy_from_slice(&self.texts[slot]);
        // At most 30: the `min` only tells the compiler that `at` stays
        // small, so that the line's later writes need no bounds check.
        l.at += usize::from(self.lens[slot]).min(32);
    }
}

/// How many bytes the nc writer gathers before it hands them to its
/// output.
const NC_CAPACITY: usize = 1 << 16;

/// The room a line written by [`NcOut::line`] may take: the longest, a
/// G02 with a centre or an arc with I and K, has four numbers of at most
/// [`FIXED_BUF`] bytes each and fewer than 40 other bytes; a heading,
/// [`HEADING_BUF`] bytes and its parentheses.
const LINE_ROOM: usize = 8 * FIXED_BUF;
const _: () = assert!(HEADING_BUF + 3 <= LINE_ROOM);

/// The nc writer's buffered output (the hot path of `expand`: about six
/// lines a cycle's pass, a move a line). Each line is written straight
/// into the buffer by [`NcOut::line`], its numbers by
/// [`put_fixed`](crate::format::put_fixed) in place, so that a move is
/// one bounds check and no copy; other text goes through [`Write`]. The
/// buffer is handed on when it holds more than [`NC_CAPACITY`] bytes, and
/// when dropped (as `BufWriter` does: what was written before a failure
/// of the reader still reaches the output).
struct NcOut<W: Write> {
    inner: W,
    /// [`NC_CAPACITY`] bytes and the room of one line more.
    buf: Box<[u8; NC_CAPACITY + LINE_ROOM]>,
    /// The bytes of `buf` written.
    len: usize,
}

impl<W: Write> NcOut<W> {
    fn new(inner: W) -> NcOut<W> {
        let buf = vec![0; NC_CAPACITY + LINE_ROOM].into_boxed_slice().try_into();
        NcOut { inner, buf: buf.unwrap_or_else(|_| unreachable!("the length is the array's")), len: 0 }
    }

    /// Hands the bytes written to the output.
    fn flush_buf(&mut self) -> io::Result<()> {
        let len = std::mem::take(&mut self.len);
        self.inner.write_all(&self.buf[..len])
    }

    /// Writes a line of at most [`LINE_ROOM`] bytes with `f`, in place
    /// (inlined into every caller: the writers' loops).
    #[inline(always)]
    fn line(&mut self, f: impl FnOnce(&mut Line<'_>)) -> io::Result<()> {
        let mut start = self.len;
        if start > NC_CAPACITY {
            self.flush_buf()?;
            start = 0;
        }
        // LINE_ROOM bytes of room from `start` on (`start` at most
        // NC_CAPACITY: no bounds check), the line's offsets from 0, so
        // that a move's writes, of bounded lengths, need no check either.
        let window = &mut self.buf[start..start + LINE_ROOM];
        let Ok(buf) = <&mut [u8; LINE_ROOM]>::try_from(window) else { unreachable!("LINE_ROOM bytes") };
        let mut line = Line { buf, at: 0 };
        f(&mut line);
        self.len = start + line.at;
        Ok(())
    }

    /// Writes `text` and a line end (a block of the program as it is).
    #[inline]
    fn text_line(&mut self, text: &[u8]) -> io::Result<()> {
        if text.len() < LINE_ROOM {
            self.line(|l| {
                l.put(text);
                l.put(b"\n");
            })
        } else {
            self.write_all(text)?;
            self.write_all(b"\n")
        }
    }
}

impl<W: Write> Write for NcOut<W> {
    fn write(&mut self, bytes: &[u8]) -> io::Result<usize> {
        self.write_all(bytes)?;
        Ok(bytes.len())
    }

    #[inline]
    fn write_all(&mut self, bytes: &[u8]) -> io::Result<()> {
        if self.len + bytes.len() > self.buf.len() {
            self.flush_buf()?;
            if bytes.len() > NC_CAPACITY {
                return self.inner.write_all(bytes);
            }
        }
        self.buf[self.len..self.len + bytes.len()].copy_from_slice(bytes);
        self.len += bytes.len();
        Ok(())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.flush_buf()?;
        self.inner.flush()
    }
}

impl<W: Write> Drop for NcOut<W> {
    fn drop(&mut self) {
        // As BufWriter: an error here has no one to be reported to (the
        // run's own error, if any, is reported).
        let _ = self.flush_buf();
    }
}

/// One line being written into [`NcOut`]'s buffer, from `at` on.
struct Line<'b> {
    buf: &'b mut [u8; LINE_ROOM],
    at: usize,
}

impl Line<'_> {
    #[inline]
    fn put(&mut self, bytes: &[u8]) {
        self.buf[self.at..self.at + bytes.len()].copy_from_slice(bytes);
        self.at += bytes.len();
    }

    /// `v` increments with `decimals` decimals.
    #[inline]
    fn fixed(&mut self, v: i64, decimals: u32) {
        self.at += put_fixed(&mut self.buf[self.at..], v < 0, v.unsigned_abs(), decimals);
    }

    /// `v / 10^decimals`.
    #[inline]
    fn unsigned(&mut self, v: u64, decimals: u32) {
        self.at += put_fixed(&mut self.buf[self.at..], false, v, decimals);
    }

    /// `v` in decimal ([`put_integer`]).
    #[inline]
    fn number(&mut self, v: u64) {
        self.at += put_integer(&mut self.buf[self.at..], v);
    }

    /// `v / 10^decimals`, where `v` may be wider than 64 bits (an arc's I
    /// of half an increment, ×5 with one decimal more).
    fn fixed_wide(&mut self, v: i128, decimals: u32) {
        match u64::try_from(v.unsigned_abs()) {
            Ok(mag) => self.at += put_fixed(&mut self.buf[self.at..], v < 0, mag, decimals),
            Err(_) => {
                let mut s = String::new();
                let _ = cycleref::units::write_fixed(&mut s, v, decimals);
                self.put(s.as_bytes());
            }
        }
    }

    /// `head` (`G00 X`), then X and Z of `to` with `decimals` (their
    /// texts through `t`).
    #[inline]
    fn xz(&mut self, t: &mut NcText, head: &[u8], to: Point, decimals: u32) {
        self.put(head);
        t.x.put(self, to.x, decimals);
        self.put(b" Z");
        t.z.put(self, to.z, decimals);
    }

    /// The lead's value as programmed (`6.0`, `1.5`: [`put_lead`]).
    #[inline]
    fn lead_value(&mut self, lead: cycleref::Lead) {
        self.at += put_lead(&mut self.buf[self.at..], lead, false);
    }

    /// The lead word as programmed (`F6.0`, `I20.0`: [`put_lead`]).
    #[inline]
    fn lead(&mut self, lead: cycleref::Lead) {
        self.at += put_lead(&mut self.buf[self.at..], lead, true);
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
