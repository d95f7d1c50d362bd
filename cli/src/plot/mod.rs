//! SVG drawing of toolpaths (`cycleref plot`).
//!
//! Each cycle gets one panel, stacked vertically: every G76 cycle in
//! order, then one panel with all the G32 blocks, one with all the G92
//! blocks, then every G75.1 cycle.
//! A panel draws the toolpath in the XZ plane as on a lathe drawing: Z
//! horizontal (increasing to the right), X vertical (increasing upwards).
//! X is drawn as programmed: the diameter when X words are diameters, the
//! radius otherwise, so the tick labels read like the X words of the
//! program; the axis label says which. The two axes have their own scales
//! (threads are long and shallow), and the G76 panel's subtitle says so
//! when they differ.
//!
//! What is drawn:
//!
//! * rapids (G00) as dashed grey lines;
//! * the thread cut of every pass in its own colour: rough passes on a ramp
//!   from light blue (first, shallowest) to dark blue (last, deepest),
//!   finishing passes in red;
//! * run-outs (退尾) as thick green lines and lead-ins (旋进) as thick purple
//!   lines;
//! * the points A (start), B (depth reference), C (thread start) and D
//!   (thread end) of the manual, with their coordinates in the legend;
//! * for G75.1, the groove's profile and roughing region under the pecks
//!   and contours;
//! * in every panel's legend, the readings in force that differ from the
//!   defaults (issue 34), from the source the nc output's `(readings: …)`
//!   comment names them from (`crate::job::readings_in_force`).
//!
//! The modules: `canvas` holds what every panel shares (the plot
//! area, the palette, the mapping from increments to pixels, the axes, the
//! heading, the number format); `g76`, `g32` (G32 and G92 blocks) and
//! `g75` draw their cycle's panel on it; this module reads the program ([`run`]) and stacks the
//! panels into the page. The output depends only on the input: no clock,
//! no hash order, so the same program gives the same bytes.

use std::collections::BTreeSet;

use cycleref::Move;
use cycleref_spec::reader::{G32Call, G76Call, G92Call, LinuxCncCall};
use svg::node::element::{Group, Line, Rectangle};
use svg::Document;

use canvas::num;
pub use overlay::Overlay;

mod canvas;
mod g75;
mod g76;
mod overlay;
mod threads;
mod zoom;

/// Width of the picture (px).
const WIDTH: f64 = 1200.0;
/// Height of one panel (px).
const PANEL_HEIGHT: f64 = 560.0;

/// Draws the cycles as an SVG document, one panel per cycle, for the
/// program `name`, its legends naming `readings` (those in force that
/// differ from the defaults).
///
/// # Errors
///
/// A message when there is no cycle to draw or a cycle has no geometry.
fn svg(
    (name, readings): (&str, &[(&str, &str)]),
    cycles: &[(G76Call<'_>, Vec<Move>)],
    threads: &[(G32Call<'_>, Vec<Move>)],
    g92s: &[(G92Call<'_>, Vec<Move>)],
    lcncs: &[(LinuxCncCall<'_>, Vec<Move>)],
    grooves: &[g75::Groove<'_>],
    overlay: Option<&Overlay>,
) -> Result<String, crate::Failure> {
    if cycles.is_empty() && threads.is_empty() && g92s.is_empty() && lcncs.is_empty() && grooves.is_empty() {
        return Err(crate::Failure::usage(format!(
            "{name}: no G76 cycle, G32 or G33 block, G92 block or G75.1 cycle to plot"
        )));
    }
    // G33 (the linuxcnc profile) is drawn with X as a diameter, as check
    // holds it.
    let thread_code = threads.first().map_or("G32", |(c, _)| c.code);
    let threads: Vec<threads::BlockPath<'_>> = threads
        .iter()
        .map(
            |(c, m)| {
                if c.code == "G33" {
                    threads::BlockPath::g33(c, m)
                } else {
                    threads::BlockPath::g32(c, m)
                }
            },
        )
        .collect();
    let g92s: Vec<threads::BlockPath<'_>> = g92s.iter().map(|(c, m)| threads::BlockPath::g92(c, m)).collect();
    let lcncs: Vec<threads::BlockPath<'_>> =
        lcncs.iter().map(|(c, m)| threads::BlockPath::linuxcnc(c, m)).collect();
    let marks: Vec<&crate::check::Mark> = overlay.map_or(Vec::new(), |o| o.marks.iter().collect());
    let first_line = marks.first().and_then(|m| m.cycle_line);
    // The zoomed panel of the first divergence, drawn last.
    let zoomed = overlay.and_then(|o| {
        let first = marks.first()?;
        // Our path of the cycle it lies in, and the trace's points there.
        let line = first.cycle_line;
        let ours = cycles
            .iter()
            .find(|(c, _)| Some(c.block.line) == line)
            .map(|(c, moves)| g76::ours(c, moves))
            .or_else(|| {
                threads.iter().chain(&g92s).chain(&lcncs).find(|b| Some(b.line) == line).map(|b| b.ours())
            })
            .or_else(|| grooves.iter().find(|g| Some(g.line()) == line).map(g75::Groove::path));
        let (ours, theirs) = match ours {
            Some(ours) => (ours, line.map_or(&[][..], |l| o.points_for(l))),
            // A divergence outside the cycles drawn: its marks alone, in
            // the first panel's units.
            None => {
                let any = cycles
                    .first()
                    .map(|(c, m)| g76::ours(c, m))
                    .or_else(|| threads.first().or(g92s.first()).or(lcncs.first()).map(|b| b.ours()))
                    .or_else(|| grooves.first().map(g75::Groove::path))?;
                (zoom::Ours { from: first.ours.or(first.theirs)?, moves: &[], ..any }, &[][..])
            }
        };
        zoom::panel(name, o.short_name(), &marks, &ours, theirs)
    });
    let panels = cycles.len()
        + usize::from(!threads.is_empty())
        + usize::from(!g92s.is_empty())
        + usize::from(!lcncs.is_empty())
        + grooves.len()
        + usize::from(zoomed.is_some());
    let height = PANEL_HEIGHT * count(panels);
    let mut doc = Document::new()
        .set("width", WIDTH)
        .set("height", height)
        .set("viewBox", (0, 0, WIDTH, height))
        .set("font-family", "DejaVu Sans, Helvetica, Arial, sans-serif")
        .add(Rectangle::new().set("width", "100%").set("height", "100%").set("fill", "#ffffff"));
    for (index, (call, moves)) in cycles.iter().enumerate() {
        let trace = overlay.map_or(&[][..], |o| o.points_for(call.block.line));
        let panel = g76::Panel::new(name, call, moves, trace)?.with_readings(readings);
        let mut group = panel.draw();
        if let Some(o) = overlay {
            group = panel.draw_overlay(group, o.short_name(), o.points_for(call.block.line), index);
            let line = Some(call.block.line);
            let here: Vec<&crate::check::Mark> =
                marks.iter().copied().filter(|m| m.cycle_line == line).take(MAX_MARKS).collect();
            group = panel.draw_marks(group, &here, first_line == line);
        }
        doc = place(doc, group, index, true);
    }
    let mut before = cycles.len();
    for (code, blocks) in [(thread_code, &threads), ("G92", &g92s), ("G76 (LinuxCNC)", &lcncs)] {
        if blocks.is_empty() {
            continue;
        }
        let here: Vec<&crate::check::Mark> = marks
            .iter()
            .copied()
            .filter(|m| blocks.iter().any(|b| m.cycle_line == Some(b.line)))
            .take(MAX_MARKS)
            .collect();
        let first = blocks.iter().any(|b| first_line == Some(b.line));
        doc = place(doc, threads::panel(name, code, blocks, &here, first, readings), before, true);
        before += 1;
    }
    for (i, groove) in grooves.iter().enumerate() {
        let line = Some(groove.line());
        let here: Vec<&crate::check::Mark> =
            marks.iter().copied().filter(|m| m.cycle_line == line).take(MAX_MARKS).collect();
        let trace = overlay.map_or(&[][..], |o| o.points_for(groove.line()));
        let mut group = groove.draw(name, &here, first_line == line, trace, readings);
        if let Some(o) = overlay {
            let clip = format!("groove-area-{i}");
            group = canvas::draw_trace(group, &groove.map(trace), o.short_name(), trace, &clip);
        }
        doc = place(doc, group, before + i, true);
    }
    if let Some(group) = zoomed {
        doc = place(doc, group, before + grooves.len(), true);
    }
    Ok(format!("{doc}\n"))
}

/// Adds the panel `group` to `doc` in panel slot `slot` (0 at the top):
/// below the first, moved down to its slot, with a grey rule above it when
/// `rule` is set.
fn place(mut doc: Document, group: Group, slot: usize, rule: bool) -> Document {
    if slot == 0 {
        return doc.add(group);
    }
    let top = num(PANEL_HEIGHT * count(slot));
    let group = group.set("transform", format!("translate(0 {top})"));
    if rule {
        doc = doc.add(
            Line::new()
                .set("x1", 0)
                .set("x2", WIDTH)
                .set("y1", top.as_str())
                .set("y2", top.as_str())
                .set("stroke", "#bbbbbb"),
        );
    }
    doc.add(group)
}

/// `n` as a float (counts here are far below 2^52).
#[allow(clippy::cast_precision_loss)]
fn count(n: usize) -> f64 {
    n as f64
}

/// The most divergences marked on one panel.
pub const MAX_MARKS: usize = 500;

/// The most trace points drawn over one cycle.
pub const MAX_OVERLAY_POINTS: usize = 50_000;

/// The most moves a drawn cycle may have: a drawing of more is unreadable,
/// and its moves are held while it is drawn (about 100 bytes each).
pub const MAX_DRAWN_MOVES: usize = 200_000;

/// The most cycles `plot` draws when no `--line` picks them: beyond this
/// a drawing is no longer a picture a person can read (and its file grows
/// with every panel). Counted: each G76 and G75.1 cycle and each G32 block.
pub const MAX_CYCLES: usize = 24;

/// The moves of a LinuxCNC block with X as a diameter, as `check` holds it
/// on that profile (reading R-CHECKLCNC): doubled when the block is in G8.
fn as_diameter(mut moves: Vec<Move>, x_mode: cycleref::XMode) -> Vec<Move> {
    if x_mode == cycleref::XMode::Radius {
        for m in &mut moves {
            m.to.x = m.to.x.saturating_mul(2);
        }
    }
    moves
}

/// Draws `job`'s cycles: those whose line (block 2 of G76 and G75.1,
/// either block of G75.1, the G32 block) is in `lines`, or without
/// `lines`, the first [`MAX_CYCLES`]. Returns the SVG document and, when
/// that limit left cycles out (never with `lines`), a note for the user
/// saying how many and how to pick others.
///
/// # Errors
///
/// The program's first error, a line of `lines` with no cycle, or nothing
/// to draw.
pub fn run(
    job: &crate::Job,
    lines: &[usize],
    trace: Option<&std::path::Path>,
) -> Result<(String, Option<String>), crate::Failure> {
    use cycleref_spec::pipeline::Cycle;
    use cycleref_spec::reader::Item;
    let units = job.validate()?.units;
    let mut cycles = Vec::new();
    let mut threads = Vec::new();
    let mut g92s = Vec::new();
    let mut lcncs = Vec::new();
    let mut grooves = Vec::new();
    let (mut total, mut drawn) = (0_usize, 0_usize);
    // Where each G76 cycle drawn lies in the whole toolpath, by move index.
    // Each cycle drawn: its line, and where it lies in the whole toolpath,
    // by move index.
    let (mut position, mut ranges) = (0_usize, Vec::new());
    let mut found = BTreeSet::new();
    // The program is read as everywhere (a file a line at a time); the
    // cycles drawn are kept, detached from the line they were read from.
    job.for_each_item(
        |f| f,
        |item| {
            let Some(cycle) = Cycle::of(item) else {
                // A block that moves is one move of the toolpath, as `check`
                // counts them (the reader's plain move; a block to where
                // the tool is, is none).
                if let Item::Move(m) = item {
                    position += usize::from(m.from != m.to);
                }
                return Ok(());
            };
            total += 1;
            let wanted = if lines.is_empty() {
                drawn < MAX_CYCLES
            } else {
                // A cycle of two blocks is picked by either line (G76 and
                // G78 by the block 1 whose values it uses).
                let block1 = cycle.params_line();
                let mut hit = false;
                for l in [Some(cycle.line()), block1].into_iter().flatten() {
                    if lines.contains(&l) {
                        found.insert(l);
                        hit = true;
                    }
                }
                hit
            };
            if !wanted {
                position += job.expand(cycle)?.count();
                return Ok(());
            }
            drawn += 1;
            // Counted first, streamed: a cycle too long to draw is refused
            // before any of it is held (memory stays bounded whatever the
            // number of passes and starts).
            let count = job.expand(cycle)?.count();
            if count > MAX_DRAWN_MOVES {
                return Err(crate::Failure::usage(format!(
                    "{}: line {}: the {} has {count} moves; plot draws cycles of at most {MAX_DRAWN_MOVES} \
                     moves (expand and check have no such limit)",
                    job.name,
                    cycle.line(),
                    cycle.code()
                )));
            }
            let moves: Vec<Move> = job.expand(cycle)?.collect();
            let from = position;
            position += moves.len();
            ranges.push((cycle.line(), from, position));
            match &item {
                Item::G76(call) => cycles.push((call.detached(), moves)),
                Item::G32(call) if call.code == "G33" => {
                    let moves = as_diameter(moves, call.g32.x_mode);
                    threads.push((call.detached(), moves));
                }
                Item::G32(call) => threads.push((call.detached(), moves)),
                Item::G92(call) => g92s.push((call.detached(), moves)),
                Item::G75(call) => grooves.push(g75::Groove::new(job, call.detached(), moves)?),
                Item::LinuxCncG76(call) => {
                    let moves = as_diameter(moves, call.cycle.x_mode);
                    lcncs.push((call.detached(), moves));
                }
                Item::Source(_) | Item::Move(_) | Item::G76Params(_) | Item::G75Params(_) => {}
            }
            Ok(())
        },
    )?;
    if let Some(missing) = lines.iter().find(|l| !found.contains(*l)) {
        return Err(crate::Failure::usage(format!(
            "{}: --line {missing}: no G76, G32, G92 or G75.1 block at that line",
            job.name
        )));
    }
    // The trace, read now: for each cycle drawn, its moves at the same
    // places in the toolpath.
    let overlay = match trace {
        Some(t) => Some(overlay::overlay(job, t, units, &ranges)?),
        None => None,
    };
    // The readings the legends name: those the nc output's headings name.
    let readings = crate::job::readings_in_force(&job.machine);
    let svg = svg((&job.name, &readings), &cycles, &threads, &g92s, &lcncs, &grooves, overlay.as_ref())?;
    // Only when cycles were left out by the limit: cycles picked with
    // `--line` are what was asked for.
    let note = (lines.is_empty() && drawn < total).then(|| {
        format!(
            "{}: drew {drawn} of {total} cycles (at most {MAX_CYCLES} without --line); pick others with \
             --line N, N the line of a G76 or G75.1 block or of a G32 or G92 block (repeatable)",
            job.name
        )
    });
    let dropped = overlay.as_ref().map_or(0, |o| o.dropped);
    let note = match (note, dropped) {
        (note, 0) => note,
        (note, n) => Some(format!(
            "{}{}: the trace's first {MAX_OVERLAY_POINTS} points over each cycle are drawn, {n} more are not",
            note.map_or(String::new(), |s| s + "\n"),
            job.name
        )),
    };
    Ok((svg, note))
}
