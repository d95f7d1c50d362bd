//! SVG drawing of toolpaths (`cycleref plot`).
//!
//! Each cycle gets one panel, stacked vertically. A panel draws the toolpath
//! in the XZ plane as on a lathe drawing: Z horizontal (increasing to the
//! right), X vertical (increasing upwards). X is drawn as programmed: the
//! diameter when X words are diameters, the radius otherwise, so the tick
//! labels read like the X words of the program; the axis label says which.
//! The two axes have their own scales (threads are long and shallow), and the
//! panel's subtitle says so when they differ.
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
//!   (thread end) of the manual, with their coordinates in the legend.
//!
//! Passes whose path coincides with one already drawn (the starts of a
//! multi-start thread, the finishing passes after the first) are drawn once,
//! and identical rapid and run-out segments once, so the file stays small
//! for cycles of thousands of moves. The output depends only on the input:
//! no clock, no hash order, so the same program gives the same bytes.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use cycleref::{G76Cycle, InputUnit, Motion, Move, PassKind, Point, Role, XMode};
use cycleref_spec::reader::{G32Call, G76Call};
use svg::node::element::{Circle, Group, Line, Path, Rectangle, Text, Title};
use svg::Document;

use crate::format::{fixed, lead_word};

/// Width of the picture (px).
const WIDTH: f64 = 1200.0;
/// Height of one panel (px).
const PANEL_HEIGHT: f64 = 560.0;
/// Plot area within a panel.
pub(crate) const PLOT_LEFT: f64 = 90.0;
const PLOT_RIGHT: f64 = 880.0;
const PLOT_TOP: f64 = 72.0;
const PLOT_BOTTOM: f64 = 480.0;
/// Left edge of the legend.
const LEGEND_LEFT: f64 = 905.0;

pub(crate) const RAPID: &str = "#8c8c8c";
pub(crate) const RAPID_DASH: &str = "6 4";
pub(crate) const FINISH: &str = "#d62728";
const RUN_OUT: &str = "#2ca02c";
/// A vendor's trace drawn over the toolpath.
const TRACE: &str = "#d6278a";
const LEAD_IN: &str = "#9467bd";
const POINT: &str = "#000000";
const GRID: &str = "#e4e4e4";
/// Rough-pass ramp ends: first pass (light) and last pass (dark).
const RAMP_FIRST: (f64, f64, f64) = (107.0, 174.0, 214.0);
const RAMP_LAST: (f64, f64, f64) = (8.0, 48.0, 107.0);
/// Rough passes listed one by one in the legend up to this count.
const LEGEND_PASSES: u32 = 8;

/// Draws the cycles as an SVG document, one panel per cycle.
///
/// # Errors
///
/// A message when there is no cycle to draw or a cycle has no geometry.
pub(crate) fn svg(
    name: &str,
    cycles: &[(G76Call<'_>, Vec<Move>)],
    threads: &[(G32Call<'_>, Vec<Move>)],
    grooves: &[crate::plot_g75::Groove<'_>],
    overlay: Option<&Overlay>,
) -> Result<String, String> {
    if cycles.is_empty() && threads.is_empty() && grooves.is_empty() {
        return Err(format!("{name}: no G76 cycle, G32 block or G75.1 cycle to plot"));
    }
    let panels = cycles.len() + usize::from(!threads.is_empty()) + grooves.len();
    let height = PANEL_HEIGHT * count(panels);
    let mut doc = Document::new()
        .set("width", WIDTH)
        .set("height", height)
        .set("viewBox", (0, 0, WIDTH, height))
        .set("font-family", "DejaVu Sans, Helvetica, Arial, sans-serif")
        .add(Rectangle::new().set("width", "100%").set("height", "100%").set("fill", "#ffffff"));
    for (index, (call, moves)) in cycles.iter().enumerate() {
        let panel = Panel::new(name, call, moves)?;
        let mut group = panel.draw();
        if let Some(o) = overlay {
            group = panel.draw_overlay(group, o, index);
        }
        if index > 0 {
            let top = PANEL_HEIGHT * count(index);
            group = group.set("transform", format!("translate(0 {})", num(top)));
            doc = doc.add(
                Line::new()
                    .set("x1", 0)
                    .set("x2", WIDTH)
                    .set("y1", num(top))
                    .set("y2", num(top))
                    .set("stroke", "#bbbbbb"),
            );
        }
        doc = doc.add(group);
    }
    if !threads.is_empty() {
        let top = PANEL_HEIGHT * count(cycles.len());
        let mut group = g32_panel(name, threads);
        if !cycles.is_empty() {
            group = group.set("transform", format!("translate(0 {})", num(top)));
        }
        doc = doc.add(group);
    }
    let before = cycles.len() + usize::from(!threads.is_empty());
    for (i, groove) in grooves.iter().enumerate() {
        let top = PANEL_HEIGHT * count(before + i);
        let mut group = groove.draw(name);
        if before + i > 0 {
            group = group.set("transform", format!("translate(0 {})", num(top)));
            doc = doc.add(
                Line::new()
                    .set("x1", 0)
                    .set("x2", WIDTH)
                    .set("y1", num(top))
                    .set("y2", num(top))
                    .set("stroke", "#bbbbbb"),
            );
        }
        doc = doc.add(group);
    }
    Ok(format!("{doc}\n"))
}

/// One panel with every G32 block of the program: thread moves in a blue
/// ramp by block, run-outs green, the start of each synchronised run marked.
/// The moves between the blocks are the program's own and are not drawn.
fn g32_panel(name: &str, threads: &[(G32Call<'_>, Vec<Move>)]) -> Group {
    let first = &threads[0].0;
    let per_unit = first.g32.units.per_unit();
    let points = threads.iter().flat_map(|(c, m)| std::iter::once(c.g32.start).chain(m.iter().map(|m| m.to)));
    let map = Mapping::around(points, per_unit);
    let unit = match first.g32.units.unit {
        InputUnit::Metric => "mm",
        InputUnit::Inch => "inch",
    };
    let x_kind = match first.g32.x_mode {
        XMode::Diameter => "diameter",
        XMode::Radius => "radius",
    };
    let lines = format!("lines {}-{}", first.block.line, threads[threads.len() - 1].0.block.line);
    let mut g = Group::new()
        .add(
            Text::new(format!("{name} \u{2014} G32 blocks ({lines})"))
                .set("x", PLOT_LEFT)
                .set("y", 28)
                .set("font-size", 17)
                .set("font-weight", "bold")
                .set("fill", "#000000"),
        )
        .add(
            Text::new(format!(
                "{} block{}; blue: thread, green: run-out, circles: where the spindle synchronises",
                threads.len(),
                if threads.len() == 1 { "" } else { "s" }
            ))
            .set("x", PLOT_LEFT)
            .set("y", 50)
            .set("font-size", 12)
            .set("fill", "#444444"),
        );
    g = draw_axes(g, &map, unit, x_kind);
    let total = u32::try_from(threads.len()).unwrap_or(u32::MAX);
    for (i, (call, moves)) in threads.iter().enumerate() {
        let mut at = call.g32.start;
        if call.g32.sync {
            let (x, y) = map.px(at);
            g = g.add(
                Circle::new()
                    .set("cx", num(x))
                    .set("cy", num(y))
                    .set("r", 4)
                    .set("fill", "none")
                    .set("stroke", POINT)
                    .add(Title::new(format!("line {}: synchronisation starts", call.block.line))),
            );
        }
        for m in moves {
            let (x1, y1) = map.px(at);
            let (x2, y2) = map.px(m.to);
            let run_out = m.role == Role::RunOut;
            let colour =
                if run_out { RUN_OUT.to_string() } else { ramp(u32::try_from(i + 1).unwrap_or(1), total) };
            g = g.add(
                Line::new()
                    .set("x1", num(x1))
                    .set("y1", num(y1))
                    .set("x2", num(x2))
                    .set("y2", num(y2))
                    .set("stroke", colour)
                    .set("stroke-width", if run_out { 3.0 } else { 1.8 })
                    .add(Title::new(format!(
                        "line {}: {}",
                        call.block.line,
                        crate::format::role_name(m.role)
                    ))),
            );
            at = m.to;
        }
    }
    g
}

/// `n` as a float (counts here are far below 2^52).
#[allow(clippy::cast_precision_loss)]
fn count(n: usize) -> f64 {
    n as f64
}

/// A pixel coordinate, to 0.1 px, without a trailing `.0` or a `-0`.
pub(crate) fn num(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0 + 0.0;
    format!("{r}")
}

/// Increments as a float in mm (inch).
#[allow(clippy::cast_precision_loss)]
fn units_of(v: i64, per_unit: i64) -> f64 {
    v as f64 / per_unit as f64
}

/// A "nice" tick step (1, 2 or 5 times a power of ten) giving about
/// `target` ticks over `span`.
fn tick_step(span: f64, target: f64) -> f64 {
    let raw = span / target;
    let mag = 10_f64.powf(raw.log10().floor());
    let norm = raw / mag;
    let nice = if norm < 1.5 {
        1.0
    } else if norm < 3.0 {
        2.0
    } else if norm < 7.0 {
        5.0
    } else {
        10.0
    };
    nice * mag
}

/// Decimals needed to print multiples of `step`.
#[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
fn step_decimals(step: f64) -> usize {
    let d = -step.log10().floor();
    if d > 0.0 {
        d as usize
    } else {
        0
    }
}

/// The ticks of `[lo, hi]` with the step for about `target` ticks.
#[allow(clippy::cast_possible_truncation)]
fn ticks(lo: f64, hi: f64, target: f64) -> (Vec<f64>, usize) {
    let step = tick_step(hi - lo, target);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    #[allow(clippy::cast_precision_loss)]
    let values = (first..=last).map(|i| i as f64 * step).collect();
    (values, step_decimals(step))
}

/// Colour of rough pass `number` of `total` on the ramp.
pub(crate) fn ramp(number: u32, total: u32) -> String {
    let t = if total <= 1 { 1.0 } else { f64::from(number.saturating_sub(1)) / f64::from(total - 1) };
    let mix = |a: f64, b: f64| -> u8 {
        let v = (a + (b - a) * t).round().clamp(0.0, 255.0);
        // The clamp keeps the value in u8 range.
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let byte = v as u8;
        byte
    };
    format!(
        "#{:02x}{:02x}{:02x}",
        mix(RAMP_FIRST.0, RAMP_LAST.0),
        mix(RAMP_FIRST.1, RAMP_LAST.1),
        mix(RAMP_FIRST.2, RAMP_LAST.2)
    )
}

/// Path data of line segments, drawing each distinct segment once and
/// joining segments that continue one another.
#[derive(Default)]
struct Segments {
    d: String,
    seen: BTreeSet<(i64, i64, i64, i64)>,
    pen: Option<Point>,
}

impl Segments {
    /// Adds the segment `from`-`to`; with `anchor`, the segment is drawn
    /// from its end nearer the anchor, so that dashed segments sharing that
    /// end (the retracts of all passes end on the X of A) dash in step.
    fn add(&mut self, from: Point, to: Point, anchor: Option<Point>, map: &Mapping) {
        let (from, to) = match anchor {
            Some(a) if distance(to, a) < distance(from, a) => (to, from),
            _ => (from, to),
        };
        if from == to || !self.seen.insert((from.x, from.z, to.x, to.z)) {
            return;
        }
        if self.pen != Some(from) {
            let (x, y) = map.px(from);
            let _ = write!(self.d, "M{} {}", num(x), num(y));
        }
        let (x, y) = map.px(to);
        let _ = write!(self.d, "L{} {}", num(x), num(y));
        self.pen = Some(to);
    }
}

/// Manhattan distance in increments.
fn distance(p: Point, q: Point) -> u64 {
    p.x.abs_diff(q.x).saturating_add(p.z.abs_diff(q.z))
}

/// A vendor's toolpath to draw over ours (`cycleref plot --trace`).
pub struct Overlay {
    /// The trace's name, for the label.
    pub name: String,
    /// For each G76 cycle drawn, in order, the trace's points in order (in
    /// increments) that correspond to its moves (`check::overlay`).
    pub per_cycle: Vec<Vec<Point>>,
    /// Points left out beyond [`MAX_OVERLAY_POINTS`] a cycle.
    pub dropped: usize,
}

/// The most trace points drawn over one cycle.
pub const MAX_OVERLAY_POINTS: usize = 50_000;

/// Scales from increments to pixels.
pub(crate) struct Mapping {
    per_unit: i64,
    z_lo: f64,
    z_hi: f64,
    x_lo: f64,
    x_hi: f64,
}

impl Mapping {
    /// The mapping that shows every one of `points`, with a margin.
    pub(crate) fn around(points: impl Iterator<Item = Point>, per_unit: i64) -> Mapping {
        let (mut x_min, mut x_max, mut z_min, mut z_max) = (i64::MAX, i64::MIN, i64::MAX, i64::MIN);
        for p in points {
            x_min = x_min.min(p.x);
            x_max = x_max.max(p.x);
            z_min = z_min.min(p.z);
            z_max = z_max.max(p.z);
        }
        let (z_lo, z_hi) = padded(units_of(z_min, per_unit), units_of(z_max, per_unit), 0.07);
        let (x_lo, x_hi) = padded(units_of(x_min, per_unit), units_of(x_max, per_unit), 0.08);
        Mapping { per_unit, z_lo, z_hi, x_lo, x_hi }
    }

    fn px_z(&self, z: f64) -> f64 {
        PLOT_LEFT + (z - self.z_lo) / (self.z_hi - self.z_lo) * (PLOT_RIGHT - PLOT_LEFT)
    }

    fn px_x(&self, x: f64) -> f64 {
        PLOT_BOTTOM - (x - self.x_lo) / (self.x_hi - self.x_lo) * (PLOT_BOTTOM - PLOT_TOP)
    }

    pub(crate) fn px(&self, p: Point) -> (f64, f64) {
        (self.px_z(units_of(p.z, self.per_unit)), self.px_x(units_of(p.x, self.per_unit)))
    }

    /// Increments per unit (mm or inch).
    pub(crate) fn per_unit(&self) -> i64 {
        self.per_unit
    }

    /// Pixels per unit along Z and along X.
    pub(crate) fn scales(&self) -> (f64, f64) {
        (
            (PLOT_RIGHT - PLOT_LEFT) / (self.z_hi - self.z_lo),
            (PLOT_BOTTOM - PLOT_TOP) / (self.x_hi - self.x_lo),
        )
    }
}

/// The thread path of one pass (or of several with the same path).
struct PassPath {
    kind: Option<PassKind>,
    number: u32,
    d: String,
    pen: Option<Point>,
    tooltip: String,
    /// Other passes (and starts) that follow exactly the same path.
    also: u32,
}

/// One cycle, ready to draw.
struct Panel<'a> {
    name: &'a str,
    call: &'a G76Call<'a>,
    map: Mapping,
    /// A, B, C, D.
    points: [Point; 4],
    /// +1 when the cut goes towards +Z.
    direction: i64,
    /// +1 for an external thread (A outside C), -1 for an internal one.
    side: i64,
    rapids: Segments,
    run_outs: Segments,
    lead_ins: Segments,
    passes: Vec<PassPath>,
    rough_total: u32,
    rough_depths: BTreeMap<u32, i64>,
    finish_total: u32,
    finish_depth: Option<i64>,
}

impl<'a> Panel<'a> {
    fn new(name: &'a str, call: &'a G76Call<'a>, moves: &[Move]) -> Result<Panel<'a>, String> {
        let c: &G76Cycle = &call.cycle;
        let line = call.block.line;
        let g = cycleref_spec::g76::geometry(c).map_err(|e| format!("{name}: line {line}, G76: {e}"))?;
        let xf = c.x_mode.factor();
        // C: Z of A, X of D plus i; B: X of C plus k towards A (spec::g76::geometry).
        let c_x = c.end.x + xf * c.taper;
        let b_x = c_x + g.side * xf * c.thread_height;
        let points = [c.start, Point::new(b_x, c.start.z), Point::new(c_x, c.start.z), c.end];
        let per_unit = c.units.per_unit();

        let map = Mapping::around(points.iter().copied().chain(moves.iter().map(|m| m.to)), per_unit);

        let mut panel = Panel {
            name,
            call,
            map,
            points,
            direction: g.direction,
            side: g.side,
            rapids: Segments::default(),
            run_outs: Segments::default(),
            lead_ins: Segments::default(),
            passes: Vec::new(),
            rough_total: 0,
            rough_depths: BTreeMap::new(),
            finish_total: 0,
            finish_depth: None,
        };
        panel.trace(moves);
        Ok(panel)
    }

    /// Sorts the moves into rapids, run-outs, lead-ins and pass paths.
    fn trace(&mut self, moves: &[Move]) {
        let u = self.call.cycle.units;
        let start = self.call.cycle.start;
        let mut at = start;
        // Index in `passes` of each (kind, number, start).
        let mut index: BTreeMap<(u8, u32, u16), usize> = BTreeMap::new();
        for m in moves {
            let from = at;
            at = m.to;
            if let Some(p) = m.pass {
                match p.kind {
                    PassKind::Rough => {
                        self.rough_total = self.rough_total.max(p.number);
                        self.rough_depths.insert(p.number, p.depth);
                    }
                    PassKind::Finish => {
                        self.finish_total = self.finish_total.max(p.number);
                        self.finish_depth = Some(p.depth);
                    }
                }
            }
            match (m.motion, m.role) {
                (Motion::Rapid, _) => self.rapids.add(from, m.to, Some(start), &self.map),
                (_, Role::RunOut) => self.run_outs.add(from, m.to, None, &self.map),
                (_, Role::LeadIn) => self.lead_ins.add(from, m.to, None, &self.map),
                _ => {
                    let key = match m.pass {
                        Some(p) => (u8::from(p.kind == PassKind::Finish), p.number, p.start),
                        None => (2, 0, 0),
                    };
                    let i = *index.entry(key).or_insert_with(|| {
                        let tooltip = match m.pass {
                            Some(p) => format!(
                                "{} pass {}, start {}, depth {}, cut {}",
                                crate::format::kind_name(p.kind),
                                p.number,
                                p.start,
                                fixed(p.depth, u),
                                fixed(p.cut, u)
                            ),
                            None => "thread".into(),
                        };
                        self.passes.push(PassPath {
                            kind: m.pass.map(|p| p.kind),
                            number: m.pass.map_or(0, |p| p.number),
                            d: String::new(),
                            pen: None,
                            tooltip,
                            also: 0,
                        });
                        self.passes.len() - 1
                    });
                    let path = &mut self.passes[i];
                    if path.pen != Some(from) {
                        let (x, y) = self.map.px(from);
                        let _ = write!(path.d, "M{} {}", num(x), num(y));
                    }
                    let (x, y) = self.map.px(m.to);
                    let _ = write!(path.d, "L{} {}", num(x), num(y));
                    path.pen = Some(m.to);
                }
            }
        }
        // Draw each distinct path once.
        let mut first: BTreeMap<String, usize> = BTreeMap::new();
        let mut kept = Vec::new();
        for path in std::mem::take(&mut self.passes) {
            if let Some(&k) = first.get(&path.d) {
                let earlier: &mut PassPath = &mut kept[k];
                earlier.also += 1;
                continue;
            }
            first.insert(path.d.clone(), kept.len());
            kept.push(path);
        }
        self.passes = kept;
    }

    fn unit(&self) -> &'static str {
        match self.call.cycle.units.unit {
            InputUnit::Metric => "mm",
            InputUnit::Inch => "inch",
        }
    }

    fn draw(&self) -> Group {
        let mut g = Group::new();
        g = self.draw_heading(g);
        g = self.draw_axes(g);
        if !self.rapids.d.is_empty() {
            g = g.add(
                Path::new()
                    .set("d", self.rapids.d.as_str())
                    .set("fill", "none")
                    .set("stroke", RAPID)
                    .set("stroke-width", 1)
                    .set("stroke-dasharray", RAPID_DASH)
                    .add(Title::new("rapids (G00)")),
            );
        }
        for path in &self.passes {
            let (colour, width) = self.pass_style(path.kind, path.number);
            let mut tooltip = path.tooltip.clone();
            if path.also > 0 {
                let _ = write!(tooltip, " (and {} more on the same path)", path.also);
            }
            g = g.add(
                Path::new()
                    .set("d", path.d.as_str())
                    .set("fill", "none")
                    .set("stroke", colour)
                    .set("stroke-width", width)
                    .set("stroke-linejoin", "round")
                    .add(Title::new(tooltip)),
            );
        }
        for (seg, colour, title) in
            [(&self.lead_ins, LEAD_IN, "lead-in"), (&self.run_outs, RUN_OUT, "run-out")]
        {
            if !seg.d.is_empty() {
                g = g.add(
                    Path::new()
                        .set("d", seg.d.as_str())
                        .set("fill", "none")
                        .set("stroke", colour)
                        .set("stroke-width", 3)
                        .set("stroke-linecap", "round")
                        .add(Title::new(title)),
                );
            }
        }
        g = self.draw_points(g);
        self.draw_legend(g)
    }

    fn pass_style(&self, kind: Option<PassKind>, number: u32) -> (String, f64) {
        match kind {
            Some(PassKind::Rough) => (ramp(number, self.rough_total), 1.5),
            Some(PassKind::Finish) => (FINISH.into(), 2.0),
            None => (POINT.into(), 1.5),
        }
    }

    /// The trace as a magenta polyline over the toolpath, clipped to the
    /// plot area, with a label: where it leaves our path, it shows.
    fn draw_overlay(&self, g: Group, o: &Overlay, index: usize) -> Group {
        let mut d = String::new();
        for (i, p) in o.per_cycle.get(index).into_iter().flatten().enumerate() {
            let (x, y) = self.map.px(*p);
            let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, num(x), num(y));
        }
        let id = format!("plot-area-{index}");
        let clip = svg::node::element::ClipPath::new().set("id", id.as_str()).add(
            Rectangle::new()
                .set("x", PLOT_LEFT)
                .set("y", PLOT_TOP)
                .set("width", PLOT_RIGHT - PLOT_LEFT)
                .set("height", PLOT_BOTTOM - PLOT_TOP),
        );
        g.add(clip)
            .add(
                Path::new()
                    .set("d", d)
                    .set("fill", "none")
                    .set("stroke", TRACE)
                    .set("stroke-width", 1.2)
                    .set("stroke-opacity", 0.85)
                    .set("clip-path", format!("url(#{id})"))
                    .add(Title::new(format!("trace {}", o.name))),
            )
            .add(
                Text::new(format!("\u{2014} trace: {}", o.name))
                    .set("x", PLOT_RIGHT)
                    .set("y", 66)
                    .set("text-anchor", "end")
                    .set("font-size", 12)
                    .set("fill", TRACE),
            )
    }

    fn draw_heading(&self, g: Group) -> Group {
        let c = &self.call.cycle;
        let title = format!("{} \u{2014} G76 at line {}", self.name, self.call.block.line);
        let (sz, sx) = self.map.scales();
        let scales = if (sz / sx - 1.0).abs() < 0.02 {
            "X and Z to the same scale".to_string()
        } else {
            format!("X and Z to different scales (X stretched \u{d7}{:.1})", sx / sz)
        };
        let sub = format!(
            "{} thread, {} rough + {} finishing pass{} \u{d7} {} start{}, lead {}; {}",
            if self.side > 0 { "external" } else { "internal" },
            self.rough_total,
            self.finish_total,
            if self.finish_total == 1 { "" } else { "es" },
            c.starts,
            if c.starts == 1 { "" } else { "s" },
            lead_word(c.lead),
            scales
        );
        g.add(
            Text::new(title)
                .set("x", PLOT_LEFT)
                .set("y", 28)
                .set("font-size", 17)
                .set("font-weight", "bold")
                .set("fill", "#000000"),
        )
        .add(Text::new(sub).set("x", PLOT_LEFT).set("y", 50).set("font-size", 12).set("fill", "#444444"))
    }

    fn draw_axes(&self, g: Group) -> Group {
        let x_kind = match self.call.cycle.x_mode {
            XMode::Diameter => "diameter",
            XMode::Radius => "radius",
        };
        draw_axes(g, &self.map, self.unit(), x_kind)
    }

    fn draw_points(&self, mut g: Group) -> Group {
        const NAMES: [&str; 4] = ["A", "B", "C", "D"];
        // A, B and C share the Z of A: label them on the side away from the
        // thread, D on the other side; push labels apart vertically.
        let mut labels: Vec<(f64, f64, usize)> = Vec::new();
        for (i, p) in self.points.iter().enumerate() {
            let (x, y) = self.map.px(*p);
            g = g.add(
                Circle::new()
                    .set("cx", num(x))
                    .set("cy", num(y))
                    .set("r", 4)
                    .set("fill", "#ffffff")
                    .set("stroke", POINT)
                    .set("stroke-width", 2)
                    .add(Title::new(format!(
                        "{} X{} Z{}",
                        NAMES[i],
                        fixed(p.x, self.call.cycle.units),
                        fixed(p.z, self.call.cycle.units)
                    ))),
            );
            labels.push((x, y, i));
        }
        let (start_side, end_side) = if self.direction < 0 { (1.0, -1.0) } else { (-1.0, 1.0) };
        let mut start_labels: Vec<(f64, f64, usize)> = labels[..3].to_vec();
        start_labels.sort_by(|a, b| a.1.total_cmp(&b.1));
        for k in 1..start_labels.len() {
            let min = start_labels[k - 1].1 + 16.0;
            if start_labels[k].1 < min {
                start_labels[k].1 = min;
            }
        }
        let mut placed: Vec<(f64, f64, usize, f64)> =
            start_labels.into_iter().map(|(x, y, i)| (x, y, i, start_side)).collect();
        placed.push((labels[3].0, labels[3].1, 3, end_side));
        for (x, y, i, side) in placed {
            g = g.add(
                Text::new(NAMES[i])
                    .set("x", num(x + side * 9.0))
                    .set("y", num(y))
                    .set("dy", "0.35em")
                    .set("font-size", 15)
                    .set("font-weight", "bold")
                    .set("text-anchor", if side > 0.0 { "start" } else { "end" })
                    .set("fill", POINT),
            );
        }
        g
    }

    fn draw_legend(&self, mut g: Group) -> Group {
        let u = self.call.cycle.units;
        let mut y = PLOT_TOP + 8.0;
        let x0 = LEGEND_LEFT;
        let x1 = LEGEND_LEFT + 30.0;
        let tx = LEGEND_LEFT + 38.0;
        let text = |s: String, y: f64| {
            Text::new(s).set("x", tx).set("y", num(y)).set("dy", "0.35em").set("font-size", 12)
        };
        let swatch = |colour: &str, width: f64, y: f64| {
            Line::new()
                .set("x1", x0)
                .set("x2", x1)
                .set("y1", num(y))
                .set("y2", num(y))
                .set("stroke", colour.to_string())
                .set("stroke-width", width)
        };
        g = g.add(
            Text::new("Legend").set("x", x0).set("y", num(y)).set("font-size", 13).set("font-weight", "bold"),
        );
        y += 20.0;
        g = g
            .add(swatch(RAPID, 1.0, y).set("stroke-dasharray", RAPID_DASH))
            .add(text("rapid (G00)".into(), y));
        y += 20.0;
        if self.rough_total == 0 {
            g = g.add(text("rough passes (none)".into(), y));
            y += 20.0;
        } else if self.rough_total <= LEGEND_PASSES {
            for (&n, &depth) in &self.rough_depths {
                g = g
                    .add(swatch(&ramp(n, self.rough_total), 1.5, y))
                    .add(text(format!("rough pass {n}, depth {}", fixed(depth, u)), y));
                y += 18.0;
            }
            y += 2.0;
        } else {
            // A ramp swatch: the colours of the passes side by side.
            let steps = 6_u32;
            for s in 0..steps {
                let a = x0 + 30.0 * f64::from(s) / f64::from(steps);
                let b = x0 + 30.0 * f64::from(s + 1) / f64::from(steps);
                let n = 1 + s * (self.rough_total - 1) / (steps - 1);
                g = g.add(
                    Line::new()
                        .set("x1", num(a))
                        .set("x2", num(b))
                        .set("y1", num(y))
                        .set("y2", num(y))
                        .set("stroke", ramp(n, self.rough_total))
                        .set("stroke-width", 3),
                );
            }
            g = g.add(text(format!("rough passes 1\u{2013}{}", self.rough_total), y));
            y += 16.0;
            let first = self.rough_depths.values().next().copied().unwrap_or(0);
            let last = self.rough_depths.values().next_back().copied().unwrap_or(0);
            g = g.add(
                text(
                    format!("light \u{2192} dark: depth {} \u{2192} {}", fixed(first, u), fixed(last, u)),
                    y,
                )
                .set("font-size", 11)
                .set("fill", "#555555"),
            );
            y += 22.0;
        }
        let finish = match (self.finish_total, self.finish_depth) {
            (0, _) | (_, None) => "finishing passes (none)".to_string(),
            (1, Some(d)) => format!("finishing pass, depth {}", fixed(d, u)),
            (n, Some(d)) => format!("finishing passes 1\u{2013}{n}, depth {}", fixed(d, u)),
        };
        g = g.add(swatch(FINISH, 2.0, y)).add(text(finish, y));
        y += 20.0;
        let run_out = if self.run_outs.d.is_empty() { "run-out (none)" } else { "run-out" };
        g = g.add(swatch(RUN_OUT, 3.0, y)).add(text(run_out.into(), y));
        y += 20.0;
        let lead_in = if self.lead_ins.d.is_empty() { "lead-in (none)" } else { "lead-in" };
        g = g.add(swatch(LEAD_IN, 3.0, y)).add(text(lead_in.into(), y));
        y += 20.0;
        if self.call.cycle.starts > 1 {
            g = g.add(
                text(format!("{} starts: their paths coincide", self.call.cycle.starts), y)
                    .set("font-size", 11)
                    .set("fill", "#555555"),
            );
            y += 20.0;
        }
        y += 8.0;
        const MEANING: [(&str, &str); 4] = [
            ("A", "start point"),
            ("B", "depth reference (depth 0)"),
            ("C", "thread start, final depth"),
            ("D", "thread end"),
        ];
        for (p, (letter, meaning)) in self.points.iter().zip(MEANING) {
            g = g
                .add(
                    Circle::new()
                        .set("cx", x0 + 15.0)
                        .set("cy", num(y))
                        .set("r", 4)
                        .set("fill", "#ffffff")
                        .set("stroke", POINT)
                        .set("stroke-width", 2),
                )
                .add(
                    Text::new(letter)
                        .set("x", x0 + 24.0)
                        .set("y", num(y))
                        .set("dy", "0.35em")
                        .set("font-size", 12)
                        .set("font-weight", "bold"),
                )
                .add(text(meaning.into(), y));
            y += 15.0;
            g = g.add(
                text(format!("X{} Z{}", fixed(p.x, u), fixed(p.z, u)), y)
                    .set("font-size", 11)
                    .set("fill", "#555555"),
            );
            y += 20.0;
        }
        g
    }
}

/// The plot frame, grid, ticks and axis labels.
pub(crate) fn draw_axes(mut g: Group, m: &Mapping, unit: &str, x_kind: &str) -> Group {
    g = g.add(
        Rectangle::new()
            .set("x", PLOT_LEFT)
            .set("y", PLOT_TOP)
            .set("width", PLOT_RIGHT - PLOT_LEFT)
            .set("height", PLOT_BOTTOM - PLOT_TOP)
            .set("fill", "none")
            .set("stroke", "#333333"),
    );
    let (zs, zdec) = ticks(m.z_lo, m.z_hi, 10.0);
    for z in zs {
        let x = num(m.px_z(z));
        g = g
            .add(
                Line::new()
                    .set("x1", x.as_str())
                    .set("x2", x.as_str())
                    .set("y1", PLOT_TOP)
                    .set("y2", PLOT_BOTTOM)
                    .set("stroke", GRID),
            )
            .add(
                Line::new()
                    .set("x1", x.as_str())
                    .set("x2", x.as_str())
                    .set("y1", PLOT_BOTTOM)
                    .set("y2", PLOT_BOTTOM + 5.0)
                    .set("stroke", "#333333"),
            )
            .add(
                Text::new(format!("{:.*}", zdec, z + 0.0))
                    .set("x", x.as_str())
                    .set("y", PLOT_BOTTOM + 19.0)
                    .set("font-size", 12)
                    .set("text-anchor", "middle"),
            );
    }
    let (xs, xdec) = ticks(m.x_lo, m.x_hi, 8.0);
    for v in xs {
        let y = num(m.px_x(v));
        g = g
            .add(
                Line::new()
                    .set("x1", PLOT_LEFT)
                    .set("x2", PLOT_RIGHT)
                    .set("y1", y.as_str())
                    .set("y2", y.as_str())
                    .set("stroke", GRID),
            )
            .add(
                Line::new()
                    .set("x1", PLOT_LEFT - 5.0)
                    .set("x2", PLOT_LEFT)
                    .set("y1", y.as_str())
                    .set("y2", y.as_str())
                    .set("stroke", "#333333"),
            )
            .add(
                Text::new(format!("{:.*}", xdec, v + 0.0))
                    .set("x", PLOT_LEFT - 8.0)
                    .set("y", y.as_str())
                    .set("dy", "0.35em")
                    .set("font-size", 12)
                    .set("text-anchor", "end"),
            );
    }
    let mid_y = num((PLOT_TOP + PLOT_BOTTOM) / 2.0);
    g.add(
        Text::new(format!("Z ({})", unit))
            .set("x", num((PLOT_LEFT + PLOT_RIGHT) / 2.0))
            .set("y", PLOT_BOTTOM + 42.0)
            .set("font-size", 13)
            .set("text-anchor", "middle"),
    )
    .add(
        Text::new(format!("X ({x_kind}, {})", unit))
            .set("x", 24)
            .set("y", mid_y.as_str())
            .set("font-size", 13)
            .set("text-anchor", "middle")
            .set("transform", format!("rotate(-90 24 {mid_y})")),
    )
}

/// `[lo, hi]` widened by `fraction` of its span on each side (by half a
/// unit when the span is empty).
fn padded(lo: f64, hi: f64, fraction: f64) -> (f64, f64) {
    let span = hi - lo;
    if span > 0.0 {
        (lo - span * fraction, hi + span * fraction)
    } else {
        (lo - 0.5, hi + 0.5)
    }
}

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
    job.validate()?;
    let text = job.text()?;
    let mut cycles = Vec::new();
    let mut threads = Vec::new();
    let mut grooves = Vec::new();
    let (mut total, mut drawn) = (0_usize, 0_usize);
    // Where each G76 cycle drawn lies in the whole toolpath, by move index.
    let (mut position, mut ranges) = (0_usize, Vec::new());
    let mut found = BTreeSet::new();
    for item in cycleref_spec::Reader::new(&text, &job.machine) {
        let item = item.map_err(|e| job.fail(&e.into()))?;
        let Some(cycle) = Cycle::of(&item) else {
            // A block that moves is one move of the toolpath (as `check`
            // counts them; approximately: a block to where the tool is
            // counts too, which the overlay's slack absorbs).
            if let Item::Source(b) = &item {
                position += usize::from(['X', 'Z', 'U', 'W'].iter().any(|&c| b.has(c)));
            }
            continue;
        };
        total += 1;
        let wanted = if lines.is_empty() {
            drawn < MAX_CYCLES
        } else {
            let block1 = match cycle {
                Cycle::G75(c) => Some(c.params_line),
                _ => None,
            };
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
            continue;
        }
        drawn += 1;
        let moves: Vec<Move> = job.expand(cycle)?.collect();
        let from = position;
        position += moves.len();
        match item {
            Item::G76(call) => {
                ranges.push((from, position));
                cycles.push((call, moves));
            }
            Item::G32(call) => threads.push((call, moves)),
            Item::G75(call) => {
                // The profile is the finishing path of the same groove for a
                // pointed tool; the roughing region's outline is the
                // engine's profile of it (plot_g75's module documentation).
                let pointed = cycleref_spec::reader::G75Call {
                    cycle: cycleref::G75Cycle {
                        tool_width: None,
                        path: cycleref::PathType::Finish,
                        ..call.cycle
                    },
                    ..call.clone()
                };
                let profile: Vec<Move> =
                    job.expand(Cycle::G75(&pointed))?.filter(|m| m.role == Role::FinishContour).collect();
                let rough = cycleref::groove_profile(&call.cycle)
                    .map_err(|e| {
                        crate::Failure::msg(format!("{}: line {}, G75.1: {e}", job.name, call.block.line))
                    })?
                    .roughing()
                    .to_vec();
                grooves.push((call, moves, profile_from_contour(&profile), rough));
            }
            Item::Source(_) | Item::G76Params(_) | Item::G75Params(_) => {}
        }
    }
    if let Some(missing) = lines.iter().find(|l| !found.contains(*l)) {
        return Err(crate::Failure::msg(format!(
            "{}: --line {missing}: no G76, G32 or G75.1 block at that line",
            job.name
        )));
    }
    let panels: Vec<_> = grooves
        .iter()
        .map(|(call, moves, profile, rough)| crate::plot_g75::Groove {
            call,
            moves,
            profile: profile.clone(),
            rough: rough.clone(),
        })
        .collect();
    // The trace, read now: for each G76 cycle drawn, its moves at the same
    // places in the toolpath.
    let overlay = match trace {
        Some(t) => Some(crate::check::overlay(job, t, &ranges)?),
        None => None,
    };
    let svg =
        svg(&job.name, &cycles, &threads, &panels, overlay.as_ref()).map_err(crate::Failure::Message)?;
    // Only when cycles were left out by the limit: cycles picked with
    // `--line` are what was asked for.
    let note = (lines.is_empty() && drawn < total).then(|| {
        format!(
            "{}: drew {drawn} of {total} cycles (at most {MAX_CYCLES} without --line); pick others with \
             --line N, N the line of a G76 or G75.1 block or of a G32 block (repeatable)",
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

/// The finishing contour's moves without its first move (the rapid to the
/// contour's start, which becomes the profile's first point).
fn profile_from_contour(contour: &[Move]) -> Vec<Move> {
    let start = contour.iter().position(|m| m.motion != Motion::Rapid).unwrap_or(0);
    let first = start.saturating_sub(1);
    contour[first..].to_vec()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_ticks() {
        let (v, d) = ticks(-67.0, 15.0, 10.0);
        assert_eq!(d, 0);
        assert_eq!(v.first().copied(), Some(-60.0));
        assert_eq!(v.last().copied(), Some(10.0));
        let (v, d) = ticks(0.12, 0.93, 8.0);
        assert_eq!(d, 1);
        assert_eq!(v.len(), 8);
    }

    #[test]
    fn ramp_ends() {
        assert_eq!(ramp(1, 5), "#6baed6");
        assert_eq!(ramp(5, 5), "#08306b");
        assert_eq!(ramp(1, 1), "#08306b");
    }

    #[test]
    fn numbers() {
        assert_eq!(num(-0.01), "0");
        assert_eq!(num(12.345), "12.3");
        assert_eq!(num(7.0), "7");
    }
}
