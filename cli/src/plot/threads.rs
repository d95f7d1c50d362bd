//! The panels of a program's single-block threads in `cycleref plot`: one
//! panel with every G32 (or G33) block, one with every G92 block, one with
//! every LinuxCNC G76 (drawn with X as a diameter, as `check` holds it on
//! that profile, reading R-CHECKLCNC).
//!
//! G32 blocks are plain thread moves, usually many short ones cut pass by
//! pass; a G92 block is one pass of a thread whose next blocks cut it
//! deeper (the 980TDi's example O0012 cuts one thread in four G92
//! blocks). So all of a program's blocks of one kind share one panel: each
//! block's thread moves in a blue ramp by block order (light: first,
//! shallowest; dark: last), its run-out green, its rapids (G92) dashed
//! grey, and a circle where the spindle synchronises (G32: the start of a
//! block that is not a continuation of the one before; G92: every pass of
//! every start). The program's own moves between the blocks are not drawn.

use cycleref::{Motion, Move, Point, Role, Units, XMode};
use cycleref_spec::reader::{G32Call, G92Call, LinuxCncCall};
use svg::node::element::{Circle, Group, Title};

use super::canvas::{
    draw_axes, draw_marks, heading, legend, line, num, ramp, readings_entry, scale_note, unit_name, x_kind,
    Mapping, Swatch, POINT, RAPID, RAPID_DASH, RUN_OUT,
};

/// One single-block thread to draw: a G32 or a G92 block and its moves.
#[derive(Clone, Copy, Debug)]
pub(super) struct BlockPath<'a> {
    /// The block's line.
    pub(super) line: usize,
    /// Where the tool is when the block starts.
    pub(super) from: Point,
    /// The block's units.
    pub(super) units: Units,
    /// Diameter or radius X.
    pub(super) x_mode: XMode,
    /// The moves.
    pub(super) moves: &'a [Move],
}

impl<'a> BlockPath<'a> {
    /// A G32 block.
    pub(super) fn g32(call: &G32Call<'_>, moves: &'a [Move]) -> BlockPath<'a> {
        let b = &call.g32;
        BlockPath { line: call.block.line, from: b.start, units: b.units, x_mode: b.x_mode, moves }
    }

    /// A G92 block.
    pub(super) fn g92(call: &G92Call<'_>, moves: &'a [Move]) -> BlockPath<'a> {
        let c = &call.cycle;
        BlockPath { line: call.block.line, from: c.start, units: c.units, x_mode: c.x_mode, moves }
    }

    /// A LinuxCNC G76 (the `linuxcnc` profile), its X doubled to a
    /// diameter when the block is in G8, as `check` holds it (reading
    /// R-CHECKLCNC), so that a trace's marks fall on it.
    pub(super) fn linuxcnc(call: &LinuxCncCall<'_>, moves: &'a [Move]) -> BlockPath<'a> {
        let c = &call.cycle;
        let from = Point::new(c.start.x * (2 / c.x_mode.factor()), c.start.z);
        BlockPath { line: call.block.line, from, units: c.units, x_mode: XMode::Diameter, moves }
    }

    /// A G33 block (the `linuxcnc` profile), X as [`BlockPath::linuxcnc`]'s.
    pub(super) fn g33(call: &G32Call<'_>, moves: &'a [Move]) -> BlockPath<'a> {
        let b = &call.g32;
        let from = Point::new(b.start.x * (2 / b.x_mode.factor()), b.start.z);
        BlockPath { line: call.block.line, from, units: b.units, x_mode: XMode::Diameter, moves }
    }

    /// The path, for the zoomed panel.
    pub(super) fn ours(self) -> super::zoom::Ours<'a> {
        super::zoom::Ours { from: self.from, moves: self.moves, units: self.units, x_mode: self.x_mode }
    }
}

/// One panel with every block of one kind (`code`: G32 or G92) of the
/// program (`blocks`, at least one), with the divergences `marks` of a
/// trace in them marked (`first_mark`: the first of them is the report's
/// first).
pub(super) fn panel(
    name: &str,
    code: &str,
    blocks: &[BlockPath<'_>],
    marks: &[&crate::check::Mark],
    first_mark: bool,
    readings: &[(&str, &str)],
) -> Group {
    let first = &blocks[0];
    let points = blocks.iter().flat_map(|b| std::iter::once(b.from).chain(b.moves.iter().map(|m| m.to)));
    let map = Mapping::around(points, first.units.per_unit());
    let lines = format!("lines {}-{}", first.line, blocks[blocks.len() - 1].line);
    let mut g = heading(
        Group::new(),
        format!("{name} \u{2014} {code} blocks ({lines})"),
        format!("{} block{}; {}", blocks.len(), if blocks.len() == 1 { "" } else { "s" }, scale_note(&map)),
    );
    let total = u32::try_from(blocks.len()).unwrap_or(u32::MAX);
    let ramp_note = (total > 1).then(|| "light \u{2192} dark: first \u{2192} last block".to_string());
    // G92 and LinuxCNC's G76 draw their rapids; they synchronise at every
    // pass.
    let g92 = code == "G92" || code == "G76 (LinuxCNC)";
    let first_blue = ramp(1, total.max(2));
    let mut entries = vec![
        (Swatch::Line(&first_blue, 1.8, None), format!("thread ({code}), one blue per block"), ramp_note),
        (
            Swatch::Line(RUN_OUT, 3.0, None),
            if g92 && code != "G92" { "exit taper (E, L bit 2)" } else { "run-out (J, K)" }.into(),
            None,
        ),
    ];
    let ring = if code == "G92" {
        "each pass of each start"
    } else if g92 {
        "each pass"
    } else {
        "not continuing the block before"
    };
    entries.push((Swatch::Ring(POINT), "spindle synchronises".into(), Some(ring.into())));
    if g92 {
        let path = if code == "G92" {
            "A \u{2192} B, retract, return to A"
        } else {
            "\"back\", \"in\", \"out\", to the end point"
        };
        entries.push((Swatch::Line(RAPID, 1.0, Some(RAPID_DASH)), "rapid (G00)".into(), Some(path.into())));
    }
    entries.push((
        Swatch::Line(RAPID, 1.0, Some("2 3")),
        "the program's own moves".into(),
        Some("between the blocks: not drawn".into()),
    ));
    entries.extend(readings_entry(readings));
    g = legend(g, &entries);
    g = draw_axes(g, &map, unit_name(first.units.unit), x_kind(first.x_mode));
    for (i, block) in blocks.iter().enumerate() {
        let mut at = block.from;
        for m in block.moves {
            if let Motion::Thread { sync: true, .. } = m.motion {
                let (x, y) = map.px(at);
                g = g.add(
                    Circle::new()
                        .set("cx", num(x))
                        .set("cy", num(y))
                        .set("r", 4)
                        .set("fill", "none")
                        .set("stroke", POINT)
                        .add(Title::new(format!("line {}: synchronisation starts", block.line))),
                );
            }
            let (x1, y1) = map.px(at);
            let (x2, y2) = map.px(m.to);
            let title = Title::new(format!("line {}: {}", block.line, crate::format::role_name(m.role)));
            let segment = line(x1, y1, x2, y2);
            g = g.add(if m.motion == Motion::Rapid {
                segment
                    .set("stroke", RAPID)
                    .set("stroke-width", 1.0)
                    .set("stroke-dasharray", RAPID_DASH)
                    .add(title)
            } else {
                let run_out = m.role == Role::RunOut;
                let colour = if run_out {
                    RUN_OUT.to_string()
                } else {
                    ramp(u32::try_from(i + 1).unwrap_or(1), total)
                };
                segment.set("stroke", colour).set("stroke-width", if run_out { 3.0 } else { 1.8 }).add(title)
            });
            at = m.to;
        }
    }
    draw_marks(g, &map, marks, first_mark)
}
