//! The panel of a G76 cycle in `cycleref plot`.
//!
//! The moves are sorted once ([`Panel::new`]) into rapids, run-outs,
//! lead-ins and the thread path of every pass; passes whose path coincides
//! with one already drawn (the starts of a multi-start thread, the
//! finishing passes after the first) are kept once with a count, and
//! identical rapid and run-out segments are drawn once, so the file stays
//! small for cycles of thousands of moves. The panel then draws the heading,
//! the axes, the paths, the points A, B, C and D of the manual and a legend
//! listing the passes with their depths; a vendor's trace, when given, is
//! drawn over it clipped to the plot area.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

use cycleref::{Motion, Move, PassKind, Point, Role};
use cycleref_spec::cycles::PassesPanel;
use svg::node::element::{Circle, Group, Line, Path, Text, Title};

use super::canvas::{
    chars_to_edge, draw_axes, heading, num, ramp, readings_entry, unit_name, wrap, x_kind, Mapping, FINISH,
    LEGEND_LEFT, PLOT_TOP, POINT, RAPID, RAPID_DASH, RUN_OUT,
};
use crate::format::{fixed, lead_word};

/// Lead-ins.
const LEAD_IN: &str = "#9467bd";
/// Rough passes listed one by one in the legend up to this count.
const LEGEND_PASSES: u32 = 8;

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
pub(super) struct Panel<'a> {
    name: &'a str,
    /// The cycle and its moves.
    drawn: &'a super::Drawn,
    /// Its starts and lead.
    info: &'a PassesPanel,
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
    /// The readings in force that differ from the defaults, which the
    /// legend names (issue 34).
    readings: Vec<(&'a str, &'a str)>,
}

impl<'a> Panel<'a> {
    /// The panel with its legend naming `readings` (the readings in force
    /// that differ from the defaults).
    pub(super) fn with_readings(self, readings: &[(&'a str, &'a str)]) -> Panel<'a> {
        Panel { readings: readings.to_vec(), ..self }
    }

    /// The panel of `drawn` drawn as `info` says, for the program `name`.
    /// `trace`: the points of a trace over this cycle, which the frame
    /// grows to hold (within reason: [`Mapping::around_both`]).
    pub(super) fn new(
        name: &'a str,
        drawn: &'a super::Drawn,
        info: &'a PassesPanel,
        trace: &[Point],
    ) -> Panel<'a> {
        let points = info.points;
        let per_unit = drawn.units.per_unit();
        let ours: Vec<Point> = points.iter().copied().chain(drawn.moves.iter().map(|m| m.to)).collect();
        let map = Mapping::around_both(&ours, trace, per_unit);

        let mut panel = Panel {
            name,
            drawn,
            info,
            map,
            points,
            direction: info.direction,
            side: info.side,
            rapids: Segments::default(),
            run_outs: Segments::default(),
            lead_ins: Segments::default(),
            passes: Vec::new(),
            rough_total: 0,
            rough_depths: BTreeMap::new(),
            finish_total: 0,
            finish_depth: None,
            readings: Vec::new(),
        };
        panel.trace(&drawn.moves);
        panel
    }

    /// Sorts the moves into rapids, run-outs, lead-ins and pass paths.
    fn trace(&mut self, moves: &[Move]) {
        let u = self.drawn.units;
        let start = self.drawn.from;
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
                    // G92 blocks have their own panel (`g32`).
                    PassKind::Single => {}
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

    /// The panel's drawing.
    pub(super) fn draw(&self) -> Group {
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
            Some(PassKind::Single) | None => (POINT.into(), 1.5),
        }
    }

    /// The trace `name` (its `points` over this cycle) over the toolpath
    /// ([`super::canvas::draw_trace`]); `index` is the panel's.
    pub(super) fn draw_overlay(&self, g: Group, name: &str, points: &[Point], index: usize) -> Group {
        super::canvas::draw_trace(g, &self.map, name, points, &format!("plot-area-{index}"))
    }

    /// The divergences `marks` of this cycle (`first`: the first of them
    /// is the report's first divergence).
    pub(super) fn draw_marks(&self, g: Group, marks: &[&crate::check::Mark], first: bool) -> Group {
        super::canvas::draw_marks(g, &self.map, marks, first)
    }

    fn draw_heading(&self, g: Group) -> Group {
        let c = self.info;
        let title = format!("{} \u{2014} {} at line {}", self.name, self.drawn.code, self.drawn.line);
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
        heading(g, title, sub)
    }

    fn draw_axes(&self, g: Group) -> Group {
        let d = self.drawn;
        draw_axes(g, &self.map, unit_name(d.units.unit), x_kind(d.x_mode))
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
                        fixed(p.x, self.drawn.units),
                        fixed(p.z, self.drawn.units)
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
        let u = self.drawn.units;
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
        if self.info.starts > 1 {
            g = g.add(
                text(format!("{} starts: their paths coincide", self.info.starts), y)
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
        if let Some((_, title, Some(list))) = readings_entry(&self.readings) {
            g = g.add(text(title, y));
            y += 15.0;
            for line in wrap(&list, chars_to_edge(tx, 11.0)) {
                g = g.add(text(line, y).set("font-size", 11).set("fill", "#555555"));
                y += 14.0;
            }
        }
        g
    }
}
