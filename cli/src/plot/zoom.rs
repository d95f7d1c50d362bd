//! The panel zoomed on the first divergence of `cycleref plot --trace`.
//!
//! At the scale of a whole cycle a divergence of a few increments is
//! thinner than a line. This panel shows a window around our point of the
//! report's first divergence, a few times the difference wide each way
//! (at least [`MIN_HALF_WINDOW`] increments): our path in the window (rapids
//! dashed, the rest solid), the trace's path over it, every divergence in
//! the window marked (ours a ring, theirs a cross, the first larger), and
//! the report's words for the first divergence beside it.

use std::fmt::Write as _;

use cycleref::{Motion, Move, Point, Units, XMode};
use svg::node::element::{ClipPath, Group, Path, Rectangle, Text};

use super::canvas::{
    chars_to_edge, draw_axes, draw_marks, heading, num, unit_name, wrap, x_kind, Mapping, LEGEND_LEFT,
    PLOT_BOTTOM, PLOT_LEFT, PLOT_RIGHT, PLOT_TOP, POINT, RAPID, RAPID_DASH, TRACE,
};
use crate::check::Mark;

/// The smallest half-width of the window, in increments.
const MIN_HALF_WINDOW: i64 = 10;
/// The window is this many times the difference wide each way.
const WINDOW_FACTOR: i64 = 6;
/// Characters per line of the report's text in the legend column.
const WRAP: usize = 40;

/// Our path near the divergence: where the cycle starts, its moves, its
/// units and X mode.
pub(super) struct Ours<'a> {
    /// Where the tool is when the cycle starts.
    pub(super) from: Point,
    /// The cycle's moves.
    pub(super) moves: &'a [Move],
    /// The units of the coordinates.
    pub(super) units: Units,
    /// Diameter or radius X.
    pub(super) x_mode: XMode,
}

/// The zoomed panel of `marks[0]` (the first divergence), with the other
/// `marks` that fall in the window, our path `ours` and the trace's
/// points `theirs` (over the same cycle, when known) of the trace
/// `trace_name`.
pub(super) fn panel(
    name: &str,
    trace_name: &str,
    marks: &[&Mark],
    ours: &Ours<'_>,
    theirs: &[Point],
) -> Option<Group> {
    let first = marks.first()?;
    let centre = first.ours.or(first.theirs)?;
    let (dx, dz) = first.difference.unwrap_or((0, 0));
    let spread = i64::try_from(dx.unsigned_abs().max(dz.unsigned_abs())).unwrap_or(i64::MAX / 8);
    let half = spread.saturating_mul(WINDOW_FACTOR).max(MIN_HALF_WINDOW);
    let corners = [
        Point::new(centre.x.saturating_sub(half), centre.z.saturating_sub(half)),
        Point::new(centre.x.saturating_add(half), centre.z.saturating_add(half)),
    ];
    let map = Mapping::around(corners.into_iter(), ours.units.per_unit());
    let mut g = Group::new();
    let (sz, sx) = map.scales();
    let scales = if (sz / sx - 1.0).abs() < 0.02 {
        "X and Z to the same scale".to_string()
    } else {
        format!("X and Z to different scales (X stretched \u{d7}{:.1})", sx / sz)
    };
    g = heading(
        g,
        format!("{name} \u{2014} first divergence, zoomed"),
        format!("{half} increments each way around our point; {scales}"),
    );
    g = draw_axes(g, &map, unit_name(ours.units.unit), x_kind(ours.x_mode));
    // One zoomed panel a page: its clip path's id is unique.
    let id = "zoom-area";
    g = g.add(
        ClipPath::new().set("id", id).add(
            Rectangle::new()
                .set("x", PLOT_LEFT)
                .set("y", PLOT_TOP)
                .set("width", PLOT_RIGHT - PLOT_LEFT)
                .set("height", PLOT_BOTTOM - PLOT_TOP),
        ),
    );
    // Our path: rapids dashed grey, every other move solid black.
    let (mut rapids, mut cuts) = (String::new(), String::new());
    let mut at = ours.from;
    for m in ours.moves {
        let d = if m.motion == Motion::Rapid { &mut rapids } else { &mut cuts };
        let (x1, y1) = map.px(at);
        let (x2, y2) = map.px(m.to);
        let _ = write!(d, "M{} {}L{} {}", num(x1), num(y1), num(x2), num(y2));
        at = m.to;
    }
    let clip = format!("url(#{id})");
    for (d, colour, dash, width) in [(rapids, RAPID, Some(RAPID_DASH), 1.2), (cuts, POINT, None, 1.6)] {
        if d.is_empty() {
            continue;
        }
        let mut p = Path::new()
            .set("d", d)
            .set("fill", "none")
            .set("stroke", colour)
            .set("stroke-width", width)
            .set("clip-path", clip.as_str());
        if let Some(dash) = dash {
            p = p.set("stroke-dasharray", dash);
        }
        g = g.add(p);
    }
    if !theirs.is_empty() {
        let mut d = String::new();
        for (i, p) in theirs.iter().enumerate() {
            let (x, y) = map.px(*p);
            let _ = write!(d, "{}{} {}", if i == 0 { "M" } else { "L" }, num(x), num(y));
        }
        g = g.add(
            Path::new()
                .set("d", d)
                .set("fill", "none")
                .set("stroke", TRACE)
                .set("stroke-width", 1.4)
                .set("stroke-opacity", 0.85)
                .set("clip-path", clip.as_str()),
        );
    }
    g = draw_marks(g, &map, marks, true);
    // The legend column: what is drawn, then the report's words.
    let mut y = 90.0;
    for (text, colour) in [
        ("our path (rapids dashed)".to_string(), POINT),
        (format!("trace: {trace_name}"), TRACE),
        ("\u{25cb} ours  \u{d7} theirs  (1: the first divergence)".to_string(), TRACE),
    ] {
        for line in wrap(&text, chars_to_edge(LEGEND_LEFT, 12.0)) {
            g = g.add(
                Text::new(line)
                    .set("x", LEGEND_LEFT)
                    .set("y", num(y))
                    .set("font-size", 12)
                    .set("fill", colour),
            );
            y += 15.0;
        }
        y += 3.0;
    }
    y += 10.0;
    for line in first.text.iter().flat_map(|l| wrap(l, WRAP)) {
        g = g.add(
            Text::new(line)
                .set("x", LEGEND_LEFT)
                .set("y", num(y))
                .set("font-size", 11)
                .set("font-family", "DejaVu Sans Mono, monospace")
                .set("xml:space", "preserve")
                .set("fill", "#000000"),
        );
        y += 15.0;
        if y > PLOT_BOTTOM + 60.0 {
            break;
        }
    }
    Some(g)
}
