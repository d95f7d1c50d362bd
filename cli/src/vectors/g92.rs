//! G92 threads: the valid G92 templates and the features a G92 block
//! shows.
//!
//! A G92 program is written as the manuals' examples are: a first block
//! with the cut end, the lead and the run-out, then blocks giving only the
//! next X (the modal values repeat), each one pass of the same thread.

use std::collections::BTreeSet;

use cycleref::{LeadWord, Move, RunOut};
use cycleref_spec::reader::G92Call;

use super::tag;

// ---- what a G92 block shows ----

/// The features a valid G92 block shows.
pub(super) fn tags(call: &G92Call, moves: &[Move], tags: &mut BTreeSet<String>) {
    let c = &call.cycle;
    tag(tags, "g92");
    tag(tags, if c.taper == 0 { "g92:straight" } else { "g92:taper" });
    if (c.end.z - c.start.z).abs() <= c.taper.abs() {
        tag(tags, "g92:x-long");
    }
    tag(tags, if c.start.x > c.end.x { "g92:external" } else { "g92:internal" });
    tag(tags, if c.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
    match c.run_out {
        RunOut::None => {}
        RunOut::Amounts { long: 0, .. } => tag(tags, "g92:pull-out"),
        RunOut::Amounts { .. } => tag(tags, "g92:run-out"),
        RunOut::Chamfer { .. } => tag(tags, "g92:chamfer"),
    }
    if c.starts > 1 {
        tag(tags, "g92:multi-start");
    }
    if !c.start_angle.is_zero() && !moves.is_empty() {
        tag(tags, "g92:q");
    }
}
