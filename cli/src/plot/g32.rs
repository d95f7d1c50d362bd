//! The panel of a program's G32 blocks in `cycleref plot`.
//!
//! G32 blocks are plain thread moves, usually many short ones cut pass by
//! pass, so all of a program's blocks share one panel: each block's thread
//! moves in a blue ramp by block order, its run-out green, and a circle
//! where the spindle synchronises (the start of a block that is not a
//! continuation of the one before). The moves between the blocks are the
//! program's own and are not drawn.

use cycleref::{Move, Role};
use cycleref_spec::reader::G32Call;
use svg::node::element::{Circle, Group, Title};

use super::canvas::{
    draw_axes, draw_marks, heading, legend, line, num, ramp, scale_note, unit_name, x_kind, Mapping, Swatch,
    POINT, RAPID, RUN_OUT,
};

/// The path of the block `call` with its `moves`, for the zoomed panel.
pub(super) fn ours<'a>(call: &G32Call<'_>, moves: &'a [Move]) -> super::zoom::Ours<'a> {
    let b = &call.g32;
    super::zoom::Ours { from: b.start, moves, units: b.units, x_mode: b.x_mode }
}

/// One panel with every G32 block of the program (`threads`, at least
/// one), with the divergences `marks` of a trace in them marked (`first_mark`:
/// the first of them is the report's first).
pub(super) fn panel(
    name: &str,
    threads: &[(G32Call<'_>, Vec<Move>)],
    marks: &[&crate::check::Mark],
    first_mark: bool,
) -> Group {
    let first = &threads[0].0;
    let per_unit = first.g32.units.per_unit();
    let points = threads.iter().flat_map(|(c, m)| std::iter::once(c.g32.start).chain(m.iter().map(|m| m.to)));
    let map = Mapping::around(points, per_unit);
    let lines = format!("lines {}-{}", first.block.line, threads[threads.len() - 1].0.block.line);
    let mut g = heading(
        Group::new(),
        format!("{name} \u{2014} G32 blocks ({lines})"),
        format!("{} block{}; {}", threads.len(), if threads.len() == 1 { "" } else { "s" }, scale_note(&map)),
    );
    let total = u32::try_from(threads.len()).unwrap_or(u32::MAX);
    let ramp_note = (total > 1).then(|| "light \u{2192} dark: first \u{2192} last block".to_string());
    g = legend(
        g,
        &[
            (
                Swatch::Line(&ramp(1, total.max(2)), 1.8, None),
                "thread (G32), one blue per block".into(),
                ramp_note,
            ),
            (Swatch::Line(RUN_OUT, 3.0, None), "run-out (J, K)".into(), None),
            (
                Swatch::Ring(POINT),
                "spindle synchronises".into(),
                Some("not continuing the block before".into()),
            ),
            (
                Swatch::Line(RAPID, 1.0, Some("2 3")),
                "the program's own moves".into(),
                Some("between the blocks: not drawn".into()),
            ),
        ],
    );
    g = draw_axes(g, &map, unit_name(first.g32.units.unit), x_kind(first.g32.x_mode));
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
                line(x1, y1, x2, y2)
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
    draw_marks(g, &map, marks, first_mark)
}
