//! SVG drawing of toolpaths (`cycleref plot`).
//!
//! Each cycle says how it is drawn ([`Panel`], from its module in
//! `cycleref_spec::cycles`); the panels are stacked vertically: every
//! cycle with a panel of its own and the manual's points (G76, G78) in
//! order, then one panel per title of the single-block cycles that share
//! one (all the G32 blocks, all the G92 blocks, …), then every groove
//! (G75.1).
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
//! heading, the number format); `g76` ([`Panel::Passes`]), `threads`
//! ([`Panel::Blocks`]) and `g75` ([`Panel::Groove`]) draw their kind of
//! panel on it; this module reads the program ([`run`]) and stacks the
//! panels into the page. The output depends only on the input: no clock,
//! no hash order, so the same program gives the same bytes.

use std::collections::BTreeSet;

use cycleref::{Move, Point, Units, XMode};
use cycleref_spec::cycles::{BlocksPanel, GroovePanel, Panel, PassesPanel};
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

/// A cycle drawn: what every panel needs of it beside what its
/// [`Panel`] says, and its moves.
#[derive(Clone, Debug)]
struct Drawn {
    /// The G code.
    code: &'static str,
    /// The line of the block that runs the cycle.
    line: usize,
    /// The line of its block 1, if any.
    params_line: Option<usize>,
    /// Where the tool is when the cycle starts.
    from: Point,
    /// The cycle's start point.
    start: Point,
    /// The units of its lengths.
    units: Units,
    /// Its X mode, as drawn.
    x_mode: XMode,
    /// Its moves.
    moves: Vec<Move>,
}

impl Drawn {
    /// The path, for the zoomed panel.
    fn ours(&self) -> zoom::Ours<'_> {
        zoom::Ours { from: self.from, moves: &self.moves, units: self.units, x_mode: self.x_mode }
    }
}

/// The panels of a program, in the order drawn: each cycle with a panel
/// of its own ([`Panel::Passes`]), the panels shared by blocks
/// ([`Panel::Blocks`], one per title, in the registry's order of their
/// cycles), each groove ([`Panel::Groove`]).
#[derive(Default)]
struct Panels {
    passes: Vec<(Drawn, PassesPanel)>,
    /// Per title: the registry index of its cycles, the panel, its blocks.
    blocks: Vec<(usize, BlocksPanel, Vec<Drawn>)>,
    grooves: Vec<(Drawn, GroovePanel)>,
}

impl Panels {
    fn is_empty(&self) -> bool {
        self.passes.is_empty() && self.blocks.is_empty() && self.grooves.is_empty()
    }

    /// Adds `drawn`, a cycle of registry index `kind` drawn as `panel`.
    fn add(&mut self, kind: usize, panel: Panel, mut drawn: Drawn) {
        match panel {
            Panel::Passes(p) => self.passes.push((drawn, p)),
            Panel::Groove(g) => self.grooves.push((drawn, g)),
            Panel::Blocks(b) => {
                if b.x_as_diameter && drawn.x_mode == XMode::Radius {
                    drawn.from.x = drawn.from.x.saturating_mul(2);
                    drawn.start.x = drawn.start.x.saturating_mul(2);
                    for m in &mut drawn.moves {
                        m.to.x = m.to.x.saturating_mul(2);
                    }
                }
                if b.x_as_diameter {
                    drawn.x_mode = XMode::Diameter;
                }
                match self.blocks.iter_mut().find(|(_, p, _)| p.title == b.title) {
                    Some((_, _, blocks)) => blocks.push(drawn),
                    None => {
                        let at = self.blocks.partition_point(|(k, _, _)| *k <= kind);
                        self.blocks.insert(at, (kind, b, vec![drawn]));
                    }
                }
            }
        }
    }

    /// Every cycle drawn, in panel order.
    fn drawn(&self) -> impl Iterator<Item = &Drawn> {
        self.passes
            .iter()
            .map(|(d, _)| d)
            .chain(self.blocks.iter().flat_map(|(_, _, b)| b))
            .chain(self.grooves.iter().map(|(d, _)| d))
    }
}

/// Draws the cycles as an SVG document, one panel per cycle, for the
/// program `name`, its legends naming `readings` (those in force that
/// differ from the defaults).
///
/// # Errors
///
/// A message when there is no cycle to draw or a cycle has no geometry.
fn svg(
    name: &str,
    panels: &Panels,
    overlay: Option<&Overlay>,
    readings: &[(&str, &str)],
) -> Result<String, crate::Failure> {
    if panels.is_empty() {
        return Err(crate::Failure::usage(format!(
            "{name}: no G76 cycle, G32 or G33 block, G92 block or G75.1 cycle to plot"
        )));
    }
    let marks: Vec<&crate::check::Mark> = overlay.map_or(Vec::new(), |o| o.marks.iter().collect());
    let first_line = marks.first().and_then(|m| m.cycle_line);
    // The zoomed panel of the first divergence, drawn last.
    let zoomed = overlay.and_then(|o| {
        let first = marks.first()?;
        // Our path of the cycle it lies in, and the trace's points there.
        let line = first.cycle_line;
        let (ours, theirs) = match panels.drawn().find(|d| Some(d.line) == line) {
            Some(d) => (d.ours(), line.map_or(&[][..], |l| o.points_for(l))),
            // A divergence outside the cycles drawn: its marks alone, in
            // the first panel's units.
            None => {
                let any = panels.drawn().next()?.ours();
                (zoom::Ours { from: first.ours.or(first.theirs)?, moves: &[], ..any }, &[][..])
            }
        };
        zoom::panel(name, o.short_name(), &marks, &ours, theirs)
    });
    let count_of = panels.passes.len() + panels.blocks.len() + panels.grooves.len();
    let height = PANEL_HEIGHT * count(count_of + usize::from(zoomed.is_some()));
    let mut doc = Document::new()
        .set("width", WIDTH)
        .set("height", height)
        .set("viewBox", (0, 0, WIDTH, height))
        .set("font-family", "DejaVu Sans, Helvetica, Arial, sans-serif")
        .add(Rectangle::new().set("width", "100%").set("height", "100%").set("fill", "#ffffff"));
    let mut slot = 0;
    for (index, (drawn, p)) in panels.passes.iter().enumerate() {
        let trace = overlay.map_or(&[][..], |o| o.points_for(drawn.line));
        let panel = g76::Panel::new(name, drawn, p, trace).with_readings(readings);
        let mut group = panel.draw();
        if let Some(o) = overlay {
            group = panel.draw_overlay(group, o.short_name(), o.points_for(drawn.line), index);
            let line = Some(drawn.line);
            let here: Vec<&crate::check::Mark> =
                marks.iter().copied().filter(|m| m.cycle_line == line).take(MAX_MARKS).collect();
            group = panel.draw_marks(group, &here, first_line == line);
        }
        doc = place(doc, group, slot, true);
        slot += 1;
    }
    for (_, p, blocks) in &panels.blocks {
        let here: Vec<&crate::check::Mark> = marks
            .iter()
            .copied()
            .filter(|m| blocks.iter().any(|b| m.cycle_line == Some(b.line)))
            .take(MAX_MARKS)
            .collect();
        let first = blocks.iter().any(|b| first_line == Some(b.line));
        doc = place(doc, threads::panel(name, p, blocks, &here, first, readings), slot, true);
        slot += 1;
    }
    for (i, (drawn, p)) in panels.grooves.iter().enumerate() {
        let groove = g75::Groove::new(drawn, p);
        let line = Some(drawn.line);
        let here: Vec<&crate::check::Mark> =
            marks.iter().copied().filter(|m| m.cycle_line == line).take(MAX_MARKS).collect();
        let trace = overlay.map_or(&[][..], |o| o.points_for(drawn.line));
        let mut group = groove.draw(name, &here, first_line == line, trace, readings);
        if let Some(o) = overlay {
            let clip = format!("groove-area-{i}");
            group = canvas::draw_trace(group, &groove.map(trace), o.short_name(), trace, &clip);
        }
        doc = place(doc, group, slot, true);
        slot += 1;
    }
    if let Some(group) = zoomed {
        doc = place(doc, group, slot, true);
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
    let mut panels = Panels::default();
    let (mut total, mut drawn) = (0_usize, 0_usize);
    // Each cycle drawn: its line, and where it lies in the whole toolpath,
    // by move index.
    let (mut position, mut ranges) = (0_usize, Vec::new());
    let mut found = BTreeSet::new();
    // The program is read as everywhere (a file a line at a time); the
    // cycles drawn are kept, their moves held.
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
            // Counted first, then held: a cycle too long to draw is refused
            // before any of it is held (memory stays bounded whatever the
            // number of passes and starts). A drawn cycle is expanded twice,
            // at most MAX_CYCLES of them without `--line`.
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
            let panel = cycle.panel(job.engine).map_err(|error| {
                job.fail(&cycleref_spec::RunError::Cycle { line: cycle.line(), code: cycle.code(), error })
            })?;
            let d = Drawn {
                code: cycle.code(),
                line: cycle.line(),
                params_line: cycle.params_line(),
                from: cycle.from(),
                start: cycle.start(),
                units: cycle.units(),
                x_mode: cycle.x_mode(),
                moves,
            };
            panels.add(cycle.index(), panel, d);
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
    let svg = svg(&job.name, &panels, overlay.as_ref(), &readings)?;
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
