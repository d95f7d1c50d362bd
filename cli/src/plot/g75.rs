//! The panel of a G75.1 groove cycle in `cycleref plot`.
//!
//! Drawn, bottom to top: the workpiece's surface line and the programmed
//! groove profile (filled light grey, with its chamfers and rounds), the
//! roughing region (the profile less the allowances, dotted), then the
//! toolpath: rapids dashed grey, pecks in a blue ramp by layer, the rough
//! contour orange, the finishing contour red (rounds as arcs). For a
//! grooving tool (I), the tool's cutting edge is drawn at the bottom of
//! every plunge as a translucent bar of the tool's width, so the width and
//! the ridges it leaves are visible.
//!
//! The profile and the roughing region are not a geometry of the drawing's
//! own ([`Groove::new`] asks the engine): the profile is the finishing path
//! (J2) of the same cycle run by the same engine for a pointed tool, and the
//! roughing region's outline is the engine's `groove_profile` (the vertices
//! the rough contour visits, without the tool width), so the drawing cannot
//! disagree with the expansion.

use std::fmt::Write as _;

use cycleref::{Motion, Move, Point, Role};
use cycleref_spec::pipeline::Cycle;
use cycleref_spec::reader::G75Call;
use svg::node::element::{Group, Path, Rectangle, Title};

use super::canvas::{
    draw_axes, draw_marks, heading, legend, num, ramp, readings_entry, scale_note, unit_name, x_kind,
    Mapping, Swatch, FINISH, RAPID, RAPID_DASH,
};
use crate::format::fixed;

/// Orange: the rough contour (step 9).
const ROUGH: &str = "#ff7f0e";
/// The groove's fill.
const GROOVE_FILL: &str = "#eeeeee";
/// The profile's outline.
const PROFILE: &str = "#222222";

/// What a G75.1 panel draws.
pub(super) struct Groove<'a> {
    /// The cycle.
    call: G75Call<'a>,
    /// Its moves.
    moves: Vec<Move>,
    /// The finishing contour of the same groove for a pointed tool (the
    /// programmed profile), from its start on the surface to its end.
    profile: Vec<Move>,
    /// The roughing region's outline (`cycleref::groove_profile`): R0, K1
    /// and K2 (or Q1), K3 and K4 (or Q2), R3, absolute, without the tool
    /// width.
    rough: Vec<Point>,
}

impl<'a> Groove<'a> {
    /// The panel of `call` with its `moves`: the profile and the roughing
    /// region are computed here by `job`'s engine (the module
    /// documentation says how).
    ///
    /// # Errors
    ///
    /// The engine's error for the pointed-tool run or the roughing region.
    pub(super) fn new(job: &crate::Job, call: G75Call<'a>, moves: Vec<Move>) -> Result<Self, crate::Failure> {
        let pointed = G75Call {
            cycle: cycleref::G75Cycle { tool_width: None, path: cycleref::PathType::Finish, ..call.cycle },
            ..call.clone()
        };
        let contour: Vec<Move> =
            job.expand(Cycle::G75(&pointed))?.filter(|m| m.role == Role::FinishContour).collect();
        let rough = cycleref::groove_profile(&call.cycle)
            .map_err(|error| {
                job.fail(&cycleref_spec::RunError::Cycle { line: call.block.line, code: "G75.1", error })
            })?
            .roughing()
            .to_vec();
        Ok(Groove { call, moves, profile: profile_from_contour(&contour), rough })
    }

    /// The panel's mapping: every point of the moves and the profile, and
    /// those of the trace `trace` that stray no further than their extent
    /// ([`Mapping::around_both`]).
    pub(super) fn map(&self, trace: &[Point]) -> Mapping {
        let c = &self.call.cycle;
        let ours: Vec<Point> = std::iter::once(c.from)
            .chain(std::iter::once(c.start))
            .chain(self.moves.iter().map(|m| m.to))
            .chain(self.profile.iter().map(|m| m.to))
            .collect();
        Mapping::around_both(&ours, trace, c.units.per_unit())
    }

    /// The line of block 2, where the cycle runs.
    pub(super) fn line(&self) -> usize {
        self.call.block.line
    }

    /// Our path, for the zoomed panel: where the tool is when the cycle
    /// starts, and its moves.
    pub(super) fn path(&self) -> super::zoom::Ours<'_> {
        let c = &self.call.cycle;
        super::zoom::Ours { from: c.from, moves: &self.moves, units: c.units, x_mode: c.x_mode }
    }

    /// The panel's drawing, with the divergences `marks` of a trace in
    /// this cycle marked (`first`: the first of them is the report's first).
    pub(super) fn draw(
        &self,
        name: &str,
        marks: &[&crate::check::Mark],
        first: bool,
        trace: &[Point],
        readings: &[(&str, &str)],
    ) -> Group {
        let c = &self.call.cycle;
        let u = c.units;
        let map = self.map(trace);
        let tool = match c.tool_width {
            Some(w) => format!("grooving tool I{}", fixed(w, u)),
            None => "pointed tool (no I)".to_string(),
        };
        let mut g = heading(
            Group::new(),
            format!("{name} \u{2014} G75.1 at lines {}-{}", self.call.params_line, self.call.block.line),
            format!("{tool}; {}", scale_note(&map)),
        );
        let layers_total = self
            .moves
            .iter()
            .filter_map(|m| crate::format::plunge_of(m.role))
            .map(|p| p.layer)
            .max()
            .unwrap_or(1);
        let peck_colour = ramp(1, layers_total.max(2));
        let mut entries = vec![
            (Swatch::Block(GROOVE_FILL, 1.0), "the programmed groove profile".to_string(), None),
            (
                Swatch::Line(PROFILE, 1.0, Some("2 3")),
                "less the allowances U, W".to_string(),
                Some("the roughing region".to_string()),
            ),
            (
                Swatch::Line(&peck_colour, 1.6, None),
                "pecks (steps 1-8)".to_string(),
                (layers_total > 1).then(|| format!("light \u{2192} dark: layer 1 \u{2192} {layers_total}")),
            ),
            (Swatch::Line(ROUGH, 2.0, None), "rough contour (step 9)".to_string(), None),
            (Swatch::Line(FINISH, 2.0, None), "finishing contour (step 10)".to_string(), None),
            (Swatch::Line(RAPID, 1.0, Some(RAPID_DASH)), "rapid (G00)".to_string(), None),
        ];
        if let Some(w) = c.tool_width.filter(|&w| w > 0) {
            entries.push((
                Swatch::Block("#1f77b4", 0.25),
                format!("tool edge, I{} wide", fixed(w, u)),
                Some("at each plunge bottom".to_string()),
            ));
            entries.push((
                Swatch::None,
                "paths are the tool's start-side corner:".to_string(),
                Some("far-side moves run I inside the profile".to_string()),
            ));
        }
        entries.extend(readings_entry(readings));
        g = legend(g, &entries);
        g = draw_axes(g, &map, unit_name(u.unit), x_kind(c.x_mode));
        let x_factor = c.x_mode.factor();
        // The groove: the profile closed along the surface.
        if let Some(first) = self.profile.first() {
            let mut d = String::new();
            let (x, y) = map.px(first.to);
            let _ = write!(d, "M{} {}", num(x), num(y));
            let mut at = first.to;
            for m in &self.profile[1..] {
                segment(&mut d, &map, at, m, x_factor);
                at = m.to;
            }
            let closed = format!("{d}Z");
            g = g.add(Path::new().set("d", closed).set("fill", GROOVE_FILL).set("stroke", "none")).add(
                Path::new()
                    .set("d", d)
                    .set("fill", "none")
                    .set("stroke", PROFILE)
                    .set("stroke-width", 2.2)
                    .add(Title::new("the programmed groove profile")),
            );
        }
        if let Some((first, rest)) = self.rough.split_first() {
            let (x, y) = map.px(*first);
            let mut d = format!("M{} {}", num(x), num(y));
            for p in rest {
                let (x, y) = map.px(*p);
                let _ = write!(d, " L{} {}", num(x), num(y));
            }
            g = g.add(
                Path::new()
                    .set("d", d)
                    .set("fill", "none")
                    .set("stroke", PROFILE)
                    .set("stroke-width", 1)
                    .set("stroke-dasharray", "2 3")
                    .add(Title::new("the groove less the allowances U/W (roughing region)")),
            );
        }
        let layers = layers_total;
        let mut at = c.from;
        let mut rapids = String::new();
        let mut bars = Group::new();
        for (i, m) in self.moves.iter().enumerate() {
            if m.motion == Motion::Rapid {
                let (x1, y1) = map.px(at);
                let (x2, y2) = map.px(m.to);
                let _ = write!(rapids, "M{} {}L{} {}", num(x1), num(y1), num(x2), num(y2));
            } else {
                let (colour, width) = match m.role {
                    Role::Peck(p) => (ramp(p.layer, layers), 1.6),
                    Role::RoughContour => (ROUGH.to_string(), 2.0),
                    _ => (FINISH.to_string(), 2.0),
                };
                let mut d = String::new();
                let (x, y) = map.px(at);
                let _ = write!(d, "M{} {}", num(x), num(y));
                segment(&mut d, &map, at, m, x_factor);
                g = g.add(
                    Path::new()
                        .set("d", d)
                        .set("fill", "none")
                        .set("stroke", colour)
                        .set("stroke-width", width)
                        .add(Title::new(format!(
                            "{} to X{} Z{}",
                            crate::format::role_name(m.role),
                            fixed(m.to.x, u),
                            fixed(m.to.z, u)
                        ))),
                );
            }
            // The tool's edge at the bottom of each plunge (the last peck).
            if let (Role::Peck(p), Some(w)) = (m.role, c.tool_width) {
                let last =
                    !matches!(self.moves.get(i + 1).map(|n| n.role), Some(Role::PeckRetract(q)) if q == p);
                if last && w > 0 {
                    let far = Point::new(m.to.x, m.to.z + c.axial_sign() * w);
                    let (x1, y1) = map.px(m.to);
                    let (x2, _) = map.px(far);
                    bars = bars.add(
                        Rectangle::new()
                            .set("x", num(x1.min(x2)))
                            .set("y", num(y1 - 3.0))
                            .set("width", num((x2 - x1).abs().max(0.5)))
                            .set("height", 6)
                            .set("fill", "#1f77b4")
                            .set("fill-opacity", 0.25)
                            .add(Title::new(format!("layer {} plunge {}: tool edge", p.layer, p.number))),
                    );
                }
            }
            at = m.to;
        }
        let g = g.add(bars).add(
            Path::new()
                .set("d", rapids)
                .set("fill", "none")
                .set("stroke", RAPID)
                .set("stroke-width", 1)
                .set("stroke-dasharray", RAPID_DASH),
        );
        draw_marks(g, &map, marks, first)
    }
}

/// Appends the path data of move `m` from `at`: a line, or for an arc an
/// elliptical arc (the two axes have their own scales; X is drawn as
/// programmed, so a radius `r` spans `r·x_factor` X units).
fn segment(d: &mut String, map: &Mapping, at: Point, m: &Move, x_factor: i64) {
    let (x, y) = map.px(m.to);
    match m.motion {
        Motion::Arc { centre, clockwise } => {
            let dz = (at.z - centre.z) as f64;
            let dr = (at.x - centre.x) as f64 / x_factor as f64;
            let r = (dz * dz + dr * dr).sqrt();
            let (sz, sx) = map.scales();
            let per = map.per_unit() as f64;
            let rx = r / per * sz;
            let ry = r * x_factor as f64 / per * sx;
            // The picture's y grows downwards, so clockwise on the drawing
            // (Z right, X up) is SVG's sweep flag 1.
            let sweep = u8::from(clockwise);
            let _ = write!(d, "A{} {} 0 0 {sweep} {} {}", num(rx), num(ry), num(x), num(y));
        }
        _ => {
            let _ = write!(d, "L{} {}", num(x), num(y));
        }
    }
}

/// The finishing contour's moves without its first move (the rapid to the
/// contour's start, which becomes the profile's first point).
fn profile_from_contour(contour: &[Move]) -> Vec<Move> {
    let start = contour.iter().position(|m| m.motion != Motion::Rapid).unwrap_or(0);
    let first = start.saturating_sub(1);
    contour[first..].to_vec()
}
