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

use cycleref::{Motion, Role};
use cycleref_spec::cycles::BlocksPanel;
use svg::node::element::{Circle, Group, Title};

use super::canvas::{
    draw_axes, draw_marks, heading, legend, line, num, ramp, readings_entry, scale_note, unit_name, x_kind,
    Mapping, Swatch, POINT, RAPID, RAPID_DASH, RUN_OUT,
};

/// One panel with every block of one title (`info`) of the program
/// (`blocks`, at least one), with the divergences `marks` of a
/// trace in them marked (`first_mark`: the first of them is the report's
/// first).
pub(super) fn panel(
    name: &str,
    info: &BlocksPanel,
    blocks: &[super::Drawn],
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
        format!("{name} \u{2014} {} blocks ({lines})", info.title),
        format!("{} block{}; {}", blocks.len(), if blocks.len() == 1 { "" } else { "s" }, scale_note(&map)),
    );
    let total = u32::try_from(blocks.len()).unwrap_or(u32::MAX);
    let ramp_note = (total > 1).then(|| "light \u{2192} dark: first \u{2192} last block".to_string());
    let code = info.title;
    let first_blue = ramp(1, total.max(2));
    let mut entries = vec![
        (Swatch::Line(&first_blue, 1.8, None), format!("thread ({code}), one blue per block"), ramp_note),
        (Swatch::Line(RUN_OUT, 3.0, None), info.run_out.into(), None),
    ];
    entries.push((Swatch::Ring(POINT), "spindle synchronises".into(), Some(info.synchronises.into())));
    if let Some(path) = info.rapids {
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
        for m in &block.moves {
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
