//! LinuxCNC's G76 threading cycle (`G76 P Z I J R K Q H E L`, the
//! `linuxcnc` profile; readings R-LCNC-*).

use cycleref::{CycleError, LinuxCncMoves, Motion, Move, XMode};

use super::{
    for_each_move, Annotations, BlocksPanel, CycleCall, Heading, MoveWords, NcStyle, Panel, PassComment,
    PassTable, ReferenceMoves, Region,
};
use crate::lex::Block;
use crate::pipeline::{Engine, Moves};
use crate::reader::LinuxCncCall;

impl<'a> CycleCall<'a> for LinuxCncCall<'a> {
    type EngineMoves = LinuxCncMoves;

    fn code(&self) -> &'static str {
        "G76"
    }

    fn block(&self) -> &Block<'a> {
        &self.block
    }

    frame_of_cycle!();

    // LinuxCNC's G76 is modal, but a later block that would repeat it is
    // refused by the reader (its words are needed again), so the
    // expansion's G0 is what the following blocks see: nothing to restore.

    fn engine(&self) -> Result<LinuxCncMoves, CycleError> {
        cycleref::expand_linuxcnc(&self.cycle)
    }

    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError> {
        Ok(Box::new(crate::linuxcnc::moves(&self.cycle)?))
    }

    fn heading(&self, _moves: &Moves) -> Option<Heading> {
        Some(Heading::Named { code: "G76", line: self.block.line, name: "LinuxCNC threading cycle" })
    }

    fn annotations(&self) -> Annotations {
        Annotations::LinuxCncPasses
    }

    fn nc_style(&self) -> NcStyle {
        NcStyle { words: MoveWords::LinuxCnc, passes: PassComment::Numbered, plunges: false, contours: false }
    }

    fn pass_table(&self) -> PassTable {
        PassTable::LinuxCncPasses
    }

    fn regions(&self, engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
        // The thread space (reading R-CHECKLCNC): between the peak line
        // X₀ − σ|I| and the full-depth cut, over the Z the synchronised
        // moves span; X as the check holds it on this profile, a diameter.
        let c = &self.cycle;
        let f = i128::from(if c.x_mode == XMode::Radius { 2 } else { 1 });
        let sigma = i128::from(c.sigma());
        let x0 = i128::from(c.start.x);
        let peak = f * (x0 - sigma * i128::from(c.peak_offset.abs()));
        let root = f * (x0 - sigma * i128::from(c.peak_offset.abs() + c.full_depth));
        // Streamed: the span of the thread moves' Z, in constant memory
        // whatever the number of passes.
        let mut prev = c.start;
        let mut span: Option<(i128, i128)> = None;
        for_each_move(self, engine, |m| {
            if matches!(m.motion, Motion::Thread { .. }) {
                for z in [i128::from(prev.z), i128::from(m.to.z)] {
                    span = Some(span.map_or((z, z), |(lo, hi)| (lo.min(z), hi.max(z))));
                }
            }
            prev = m.to;
        })?;
        if let Some((lo, hi)) = span {
            out.extend(Region::spanning(&[(peak, lo), (root, hi)]));
        }
        Ok(())
    }

    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
        let c = &self.cycle;
        tag("linuxcnc");
        tag(if c.internal() { "linuxcnc:internal" } else { "linuxcnc:external" });
        tag(if c.x_mode == XMode::Diameter { "linuxcnc:g7" } else { "linuxcnc:g8" });
        if c.end.z > c.start.z {
            tag("linuxcnc:towards-plus-z");
        }
        if c.degression > cycleref::linuxcnc::DEGRESSION_ONE {
            tag("linuxcnc:degression");
        }
        if c.compound_angle != 0 {
            tag("linuxcnc:compound-angle");
        }
        if c.spring_passes > 0 {
            tag("linuxcnc:spring-passes");
        }
        if c.taper_distance > 0 && (c.entry_taper || c.exit_taper) {
            tag("linuxcnc:taper-ends");
        }
        if moves.is_empty() {
            tag("linuxcnc:no-moves");
        }
    }

    fn panel(&self, _engine: Engine) -> Result<Panel, CycleError> {
        // X as a diameter, as `check` holds it on this profile (reading
        // R-CHECKLCNC).
        Ok(Panel::Blocks(BlocksPanel {
            title: "G76 (LinuxCNC)",
            x_as_diameter: true,
            run_out: "exit taper (E, L bit 2)",
            synchronises: "each pass",
            rapids: Some("\"back\", \"in\", \"out\", to the end point"),
        }))
    }
}
