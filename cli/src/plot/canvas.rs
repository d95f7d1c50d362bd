//! The canvas every panel of `cycleref plot` is drawn on: the plot area,
//! the palette, the mapping from increments to pixels, the axes with their
//! grid and ticks, the heading, and the number format of the SVG.
//!
//! A panel is 1200 × 560 px. The plot area (Z to the right, X upwards)
//! lies between [`PLOT_LEFT`], [`PLOT_RIGHT`], [`PLOT_TOP`] and
//! [`PLOT_BOTTOM`], the legend (where a cycle has one) right of
//! [`LEGEND_LEFT`]. A [`Mapping`] fits a panel's points into the plot area
//! with a margin, each axis to its own scale. Every coordinate is written
//! by [`num`], to 0.1 px, so the same program gives the same bytes.

use cycleref::{InputUnit, Point, XMode};
use svg::node::element::{Circle, Group, Line, Rectangle, Text, Title};

/// Left edge of the plot area within a panel (px).
pub(super) const PLOT_LEFT: f64 = 90.0;
/// Right edge of the plot area (px).
pub(super) const PLOT_RIGHT: f64 = 880.0;
/// Top edge of the plot area (px).
pub(super) const PLOT_TOP: f64 = 72.0;
/// Bottom edge of the plot area (px).
pub(super) const PLOT_BOTTOM: f64 = 480.0;
/// Left edge of the legend.
pub(super) const LEGEND_LEFT: f64 = 905.0;
/// The width of a panel (px).
pub(super) const PANEL_WIDTH: f64 = 1200.0;

/// How many characters of `size`-px text fit between `x` and the panel's
/// right edge (less a 6 px margin), at 0.62 em a character: an upper bound
/// for the fonts the panels name (DejaVu Sans averages under 0.6 em), so
/// that a wrapped label never leaves the picture.
pub(super) fn chars_to_edge(x: f64, size: f64) -> usize {
    let fit = ((PANEL_WIDTH - 6.0 - x) / (0.62 * size)).floor().max(8.0);
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss, reason = "between 8 and a few hundred")]
    let n = fit as usize;
    n
}

/// `line` cut at spaces into pieces of at most `width` characters (a word
/// longer than that is cut too); continuation lines are indented.
pub(super) fn wrap(line: &str, width: usize) -> Vec<String> {
    let indent = line.len() - line.trim_start().len();
    let mut out = Vec::new();
    let mut current = " ".repeat(indent);
    let mut empty = true;
    let pieces = line.split_whitespace().flat_map(|word| {
        let chars: Vec<char> = word.chars().collect();
        chars
            .chunks(width.saturating_sub(indent + 2).max(1))
            .map(|c| c.iter().collect::<String>())
            .collect::<Vec<_>>()
    });
    for word in pieces {
        let word = word.as_str();
        if !empty && current.chars().count() + 1 + word.chars().count() > width {
            out.push(std::mem::replace(&mut current, " ".repeat(indent + 2)));
            empty = true;
        }
        if !empty {
            current.push(' ');
        }
        current.push_str(word);
        empty = false;
    }
    if !empty {
        out.push(current);
    }
    out
}

/// Rapids (G00), dashed with [`RAPID_DASH`].
pub(super) const RAPID: &str = "#8c8c8c";
/// The dash pattern of rapids.
pub(super) const RAPID_DASH: &str = "6 4";
/// Finishing passes and contours.
pub(super) const FINISH: &str = "#d62728";
/// Run-outs.
pub(super) const RUN_OUT: &str = "#2ca02c";
/// A vendor's trace drawn over the toolpath, and its divergences.
pub(super) const TRACE: &str = "#d6278a";
/// Marked points and their outlines.
pub(super) const POINT: &str = "#000000";
/// The grid of the plot area.
const GRID: &str = "#e4e4e4";
/// Rough-pass ramp ends: first pass (light) and last pass (dark).
const RAMP_FIRST: (f64, f64, f64) = (107.0, 174.0, 214.0);
const RAMP_LAST: (f64, f64, f64) = (8.0, 48.0, 107.0);

/// A pixel coordinate, to 0.1 px, without a trailing `.0` or a `-0`.
pub(super) fn num(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0 + 0.0;
    format!("{r}")
}

/// A line from pixel `(x1, y1)` to pixel `(x2, y2)`, its coordinates
/// written by [`num`]; the caller sets its stroke.
pub(super) fn line(x1: f64, y1: f64, x2: f64, y2: f64) -> Line {
    Line::new().set("x1", num(x1)).set("y1", num(y1)).set("x2", num(x2)).set("y2", num(y2))
}

/// Increments as a float in mm (inch).
#[allow(clippy::cast_precision_loss)]
fn units_of(v: i64, per_unit: i64) -> f64 {
    v as f64 / per_unit as f64
}

/// The name of the unit on the axes.
pub(super) fn unit_name(unit: InputUnit) -> &'static str {
    match unit {
        InputUnit::Metric => "mm",
        InputUnit::Inch => "inch",
    }
}

/// What the X axis shows: the diameter or the radius, as the X words.
pub(super) fn x_kind(x_mode: XMode) -> &'static str {
    match x_mode {
        XMode::Diameter => "diameter",
        XMode::Radius => "radius",
    }
}

/// The panel's title and, below it, its subtitle.
pub(super) fn heading(g: Group, title: String, sub: String) -> Group {
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
pub(super) fn ramp(number: u32, total: u32) -> String {
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

/// Scales from increments to pixels.
pub(super) struct Mapping {
    per_unit: i64,
    z_lo: f64,
    z_hi: f64,
    x_lo: f64,
    x_hi: f64,
}

impl Mapping {
    /// The mapping that shows every one of `points`, with a margin.
    pub(super) fn around(points: impl Iterator<Item = Point>, per_unit: i64) -> Mapping {
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

    /// The mapping around `ours` and the points of a `trace` that stray
    /// from them by no more than their larger extent (X or Z) each way
    /// (issue 35: the frame grows to hold both paths; a trace that runs
    /// away is clipped at the frame, not allowed to shrink our path to a
    /// dot).
    pub(super) fn around_both(ours: &[Point], trace: &[Point], per_unit: i64) -> Mapping {
        let (mut x_min, mut x_max, mut z_min, mut z_max) = (i64::MAX, i64::MIN, i64::MAX, i64::MIN);
        for p in ours {
            (x_min, x_max, z_min, z_max) = (x_min.min(p.x), x_max.max(p.x), z_min.min(p.z), z_max.max(p.z));
        }
        let reach = x_max.saturating_sub(x_min).max(z_max.saturating_sub(z_min)).max(1);
        let (dx, dz) = (reach, reach);
        let near = |p: &&Point| {
            (x_min.saturating_sub(dx)..=x_max.saturating_add(dx)).contains(&p.x)
                && (z_min.saturating_sub(dz)..=z_max.saturating_add(dz)).contains(&p.z)
        };
        Mapping::around(ours.iter().chain(trace.iter().filter(near)).copied(), per_unit)
    }

    fn px_z(&self, z: f64) -> f64 {
        PLOT_LEFT + (z - self.z_lo) / (self.z_hi - self.z_lo) * (PLOT_RIGHT - PLOT_LEFT)
    }

    fn px_x(&self, x: f64) -> f64 {
        PLOT_BOTTOM - (x - self.x_lo) / (self.x_hi - self.x_lo) * (PLOT_BOTTOM - PLOT_TOP)
    }

    /// The pixel of `p`.
    pub(super) fn px(&self, p: Point) -> (f64, f64) {
        (self.px_z(units_of(p.z, self.per_unit)), self.px_x(units_of(p.x, self.per_unit)))
    }

    /// Increments per unit (mm or inch).
    pub(super) fn per_unit(&self) -> i64 {
        self.per_unit
    }

    /// Pixels per unit along Z and along X.
    pub(super) fn scales(&self) -> (f64, f64) {
        (
            (PLOT_RIGHT - PLOT_LEFT) / (self.z_hi - self.z_lo),
            (PLOT_BOTTOM - PLOT_TOP) / (self.x_hi - self.x_lo),
        )
    }
}

/// The plot frame, grid, ticks and axis labels.
pub(super) fn draw_axes(mut g: Group, m: &Mapping, unit: &str, x_kind: &str) -> Group {
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
        let x = m.px_z(z);
        g = g
            .add(line(x, PLOT_TOP, x, PLOT_BOTTOM).set("stroke", GRID))
            .add(line(x, PLOT_BOTTOM, x, PLOT_BOTTOM + 5.0).set("stroke", "#333333"))
            .add(
                Text::new(format!("{:.*}", zdec, z + 0.0))
                    .set("x", num(x))
                    .set("y", PLOT_BOTTOM + 19.0)
                    .set("font-size", 12)
                    .set("text-anchor", "middle"),
            );
    }
    let (xs, xdec) = ticks(m.x_lo, m.x_hi, 8.0);
    for v in xs {
        let y = m.px_x(v);
        g = g
            .add(line(PLOT_LEFT, y, PLOT_RIGHT, y).set("stroke", GRID))
            .add(line(PLOT_LEFT - 5.0, y, PLOT_LEFT, y).set("stroke", "#333333"))
            .add(
                Text::new(format!("{:.*}", xdec, v + 0.0))
                    .set("x", PLOT_LEFT - 8.0)
                    .set("y", num(y))
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

/// The marks of the divergences `marks` on a panel mapped by `m`: at our
/// point a ring (the first divergence, `first`, a larger one with the
/// label "1"), at the trace's a cross, joined by a line; each with the
/// report's text as its tooltip. Points outside the plot area are not
/// drawn.
pub(super) fn draw_marks(mut g: Group, m: &Mapping, marks: &[&crate::check::Mark], first: bool) -> Group {
    let inside =
        |(x, y): (f64, f64)| (PLOT_LEFT..=PLOT_RIGHT).contains(&x) && (PLOT_TOP..=PLOT_BOTTOM).contains(&y);
    for (i, mark) in marks.iter().enumerate() {
        let big = first && i == 0;
        let tip = mark.text.join("\n");
        let ours = mark.ours.map(|p| m.px(p)).filter(|&p| inside(p));
        let theirs = mark.theirs.map(|p| m.px(p)).filter(|&p| inside(p));
        if let (Some((x1, y1)), Some((x2, y2))) = (ours, theirs) {
            g = g.add(line(x1, y1, x2, y2).set("stroke", TRACE).set("stroke-width", 1));
        }
        if let Some((x, y)) = ours {
            let r = if big { 9.0 } else { 4.0 };
            g = g.add(
                Circle::new()
                    .set("cx", num(x))
                    .set("cy", num(y))
                    .set("r", r)
                    .set("fill", "none")
                    .set("stroke", TRACE)
                    .set("stroke-width", if big { 2.5 } else { 1.5 })
                    .add(Title::new(tip.clone())),
            );
            if big {
                g = g.add(
                    Text::new("1")
                        .set("x", num(x + 11.0))
                        .set("y", num(y - 9.0))
                        .set("font-size", 13)
                        .set("font-weight", "bold")
                        .set("fill", TRACE),
                );
            }
        }
        if let Some((x, y)) = theirs {
            let h = if big { 6.0 } else { 3.0 };
            let d = format!(
                "M{} {}L{} {}M{} {}L{} {}",
                num(x - h),
                num(y - h),
                num(x + h),
                num(y + h),
                num(x - h),
                num(y + h),
                num(x + h),
                num(y - h)
            );
            g = g.add(
                svg::node::element::Path::new()
                    .set("d", d)
                    .set("stroke", TRACE)
                    .set("stroke-width", if big { 2.0 } else { 1.2 })
                    .add(Title::new(tip)),
            );
        }
    }
    g
}

/// What the axes' scales are, for a panel's subtitle: the same, or X
/// stretched (or squeezed) by a factor against Z.
pub(super) fn scale_note(m: &Mapping) -> String {
    let (sz, sx) = m.scales();
    if (sz / sx - 1.0).abs() < 0.02 {
        "X and Z to the same scale".to_string()
    } else {
        format!("X and Z to different scales (X stretched \u{d7}{:.1})", sx / sz)
    }
}

/// The sample drawn before a legend entry.
pub(super) enum Swatch<'s> {
    /// A line of this colour and width, dashed with the pattern if given.
    Line(&'s str, f64, Option<&'s str>),
    /// A filled block of this colour and opacity.
    Block(&'s str, f64),
    /// A ring of this colour.
    Ring(&'s str),
    /// Nothing (a note under the previous entry).
    None,
}

/// The legend entry naming the readings in force that differ from the
/// defaults (issue 34), as the nc output's `(readings: …)` comment does
/// (`crate::job::readings_in_force`, the one source of both), or `None`
/// under the defaults.
pub(super) fn readings_entry(readings: &[(&str, &str)]) -> Option<(Swatch<'static>, String, Option<String>)> {
    if readings.is_empty() {
        return None;
    }
    let list: Vec<String> = readings.iter().map(|(id, v)| format!("{id}={v}")).collect();
    Some((Swatch::None, "readings (not the defaults):".to_string(), Some(list.join(", "))))
}

/// A legend column right of the plot area: a title, then each entry's
/// swatch and text, and under it an optional note in small grey type.
pub(super) fn legend(mut g: Group, entries: &[(Swatch<'_>, String, Option<String>)]) -> Group {
    let (x0, x1, tx) = (LEGEND_LEFT, LEGEND_LEFT + 30.0, LEGEND_LEFT + 38.0);
    let mut y = PLOT_TOP + 8.0;
    g = g.add(
        Text::new("Legend").set("x", x0).set("y", num(y)).set("font-size", 13).set("font-weight", "bold"),
    );
    y += 20.0;
    for (swatch, text, note) in entries {
        g = match *swatch {
            Swatch::Line(colour, width, dash) => {
                let mut l = line(x0, y, x1, y).set("stroke", colour).set("stroke-width", width);
                if let Some(dash) = dash {
                    l = l.set("stroke-dasharray", dash);
                }
                g.add(l)
            }
            Swatch::Block(colour, opacity) => g.add(
                Rectangle::new()
                    .set("x", x0)
                    .set("y", num(y - 5.0))
                    .set("width", x1 - x0)
                    .set("height", 10)
                    .set("fill", colour)
                    .set("fill-opacity", opacity),
            ),
            Swatch::Ring(colour) => g.add(
                Circle::new()
                    .set("cx", num(x0 + 8.0))
                    .set("cy", num(y))
                    .set("r", 4)
                    .set("fill", "none")
                    .set("stroke", colour),
            ),
            Swatch::None => g,
        };
        // Each label wrapped to the panel's edge (issue 35: no text leaves
        // the picture).
        for line in wrap(text, chars_to_edge(tx, 12.0)) {
            g = g.add(Text::new(line).set("x", tx).set("y", num(y)).set("dy", "0.35em").set("font-size", 12));
            y += 15.0;
        }
        y += 1.0;
        if let Some(note) = note {
            for line in wrap(note, chars_to_edge(tx, 11.0)) {
                g = g.add(
                    Text::new(line)
                        .set("x", tx)
                        .set("y", num(y))
                        .set("dy", "0.35em")
                        .set("font-size", 11)
                        .set("fill", "#555555"),
                );
                y += 14.0;
            }
            y += 2.0;
        }
        y += 4.0;
    }
    g
}

/// The trace `name` (its `points` over a cycle) as a magenta polyline over
/// the toolpath, clipped to the plot area (clip path `clip_id`, unique in
/// the document), with a label: where it leaves our path, it shows.
pub(super) fn draw_trace(g: Group, m: &Mapping, name: &str, points: &[Point], clip_id: &str) -> Group {
    use std::fmt::Write as _;
    let mut d = String::new();
    for (i, p) in points.iter().enumerate() {
        let (x, y) = m.px(*p);
        let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, num(x), num(y));
    }
    let clip = svg::node::element::ClipPath::new().set("id", clip_id).add(
        Rectangle::new()
            .set("x", PLOT_LEFT)
            .set("y", PLOT_TOP)
            .set("width", PLOT_RIGHT - PLOT_LEFT)
            .set("height", PLOT_BOTTOM - PLOT_TOP),
    );
    g.add(clip)
        .add(
            svg::node::element::Path::new()
                .set("d", d)
                .set("fill", "none")
                .set("stroke", TRACE)
                .set("stroke-width", 1.2)
                .set("stroke-opacity", 0.85)
                .set("clip-path", format!("url(#{clip_id})"))
                .add(Title::new(format!("trace {name}"))),
        )
        .add(
            Text::new(format!("\u{2014} trace: {name}"))
                .set("x", PLOT_RIGHT)
                .set("y", 66)
                .set("text-anchor", "end")
                .set("font-size", 12)
                .set("fill", TRACE),
        )
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

    #[test]
    fn wraps_at_spaces_and_indents_continuations() {
        assert_eq!(
            wrap("  ours   thread X61.764 Z-59.000", 16),
            ["  ours thread", "    X61.764", "    Z-59.000"]
        );
        assert_eq!(wrap("short", 44), ["short"]);
        // A word longer than the width is cut (a long file name).
        assert_eq!(wrap("trace: /a/very/long/name.nc", 12), ["trace:", "  /a/very/lo", "  ng/name.nc"]);
    }
}
