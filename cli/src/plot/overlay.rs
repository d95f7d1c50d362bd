//! A vendor's trace drawn over our cycles (`cycleref plot --trace`): its
//! points over each cycle drawn, and the divergences `check` finds.

use std::path::Path;

use cycleref::{Point, Units};

use super::MAX_OVERLAY_POINTS;
use crate::check::{marks, trace_points, Mark};
use crate::job::{Failure, Job};

/// A vendor's toolpath to draw over ours (`cycleref plot --trace`).
pub struct Overlay {
    /// The trace's name, for the label.
    pub name: String,
    /// For each cycle drawn, in order, the trace's points in order (in
    /// increments) that correspond to its moves (`check::overlay`).
    pub per_cycle: Vec<Vec<Point>>,
    /// The line of each of those cycles (G76 and G75.1: block 2).
    pub lines: Vec<usize>,
    /// Points left out beyond [`MAX_OVERLAY_POINTS`] a cycle.
    pub dropped: usize,
    /// The divergences `check` finds between the program and the trace,
    /// the first first: each G76 panel marks those in its cycle, and a last
    /// panel is zoomed on the first.
    pub marks: Vec<Mark>,
}

impl Overlay {
    /// The trace's points over the cycle at `line`.
    pub(super) fn points_for(&self, line: usize) -> &[Point] {
        let i = self.lines.iter().position(|&l| l == line);
        i.and_then(|i| self.per_cycle.get(i)).map_or(&[], Vec::as_slice)
    }

    /// The trace's name as a legend shows it: its file name.
    pub(super) fn short_name(&self) -> &str {
        std::path::Path::new(&self.name).file_name().and_then(|n| n.to_str()).unwrap_or(&self.name)
    }
}

/// The trace at `trace` as points to draw over the cycles drawn: for each
/// range of `ranges` (the indices of a drawn cycle's moves in our whole
/// toolpath, the first move being 0), the trace's moves whose index lies in
/// it, widened by a tenth (at least 16) each way so that a trace with a few
/// moves more or less still shows whole; at most
/// [`MAX_OVERLAY_POINTS`] a cycle. The trace is read as it is
/// taken, then again by [`check::run`](crate::check::run) for the divergences to mark.
///
/// # Errors
///
/// The program's or the trace's first error; a trace on standard input
/// (`-`), which cannot be read twice.
pub(super) fn overlay(
    job: &Job,
    trace: &Path,
    units: Units,
    cycles: &[(usize, usize, usize)],
) -> Result<Overlay, Failure> {
    if trace == Path::new("-") {
        return Err(Failure::usage(
            "plot --trace reads the trace twice (to draw it, and to find where it diverges from ours): \
                    give it as a file, not `-`",
        ));
    }
    // Read twice: only a regular file gives the same bytes both times (a
    // FIFO or /dev/stdin would hang or look empty the second time).
    match std::fs::metadata(trace) {
        Ok(m) if m.is_file() => {}
        Ok(_) => {
            return Err(Failure::usage(format!(
                "{}: plot --trace reads the trace twice (to draw it, and to find where it diverges from \
                 ours): give a regular file, not a pipe or a device",
                trace.display()
            )))
        }
        // As `check` names a trace it cannot open (`trace:cannot_open`).
        Err(e) => {
            return Err(Failure::with_kind(
                crate::job::Cause::Trace,
                "trace:cannot_open",
                format!("{}: {e}", trace.display()),
            ))
        }
    }
    let (name, points) = trace_points(job, trace, units)?;
    let widened: Vec<(usize, usize)> = cycles
        .iter()
        .map(|&(_, from, to)| {
            let slack = ((to - from) / 10).max(16);
            (from.saturating_sub(slack), to + slack)
        })
        .collect();
    let last = widened.iter().map(|r| r.1).max().unwrap_or(0);
    let mut per_cycle = vec![Vec::new(); cycles.len()];
    let mut dropped = 0_usize;
    for (i, p) in points.enumerate() {
        let p = p?;
        if i > last {
            // The rest is read only for its errors.
            continue;
        }
        for (k, (from, to)) in widened.iter().enumerate() {
            if (*from..*to).contains(&i) {
                if per_cycle[k].len() < MAX_OVERLAY_POINTS {
                    per_cycle[k].push(p);
                } else {
                    dropped += 1;
                }
            }
        }
    }
    // Where they diverge: the comparison `check` makes, at tolerance 0.
    let marks = marks(job, trace, units)?;
    let lines = cycles.iter().map(|&(line, _, _)| line).collect();
    Ok(Overlay { name, per_cycle, lines, dropped, marks })
}
