//! G92, the single-pass thread-cutting cycle (the GSK 980TDi and 988TA G92
//! pages, FANUC's G92): one pass per block on G76's pass model.

use cycleref::{CycleError, G92Moves, LeadWord, Move, RunOut};

use super::{
    Annotations, BlocksPanel, CycleCall, Heading, MoveWords, NcStyle, Panel, PassComment, PassTable,
    ReferenceMoves, Region,
};
use crate::lex::Block;
use crate::pipeline::{Engine, Moves};
use crate::reader::G92Call;

impl<'a> CycleCall<'a> for G92Call<'a> {
    type EngineMoves = G92Moves;

    fn code(&self) -> &'static str {
        "G92"
    }

    fn block(&self) -> &Block<'a> {
        &self.block
    }

    frame_of_cycle!();

    // G92 is modal: the mode in force is its own, and every G92 block is
    // expanded (reading R-G92MODAL): nothing to restore.

    fn engine(&self) -> Result<G92Moves, CycleError> {
        cycleref::expand_g92(&self.cycle)
    }

    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError> {
        Ok(Box::new(crate::g92::moves(&self.cycle)?))
    }

    fn heading(&self, _moves: &Moves) -> Option<Heading> {
        Some(Heading::SinglePass { code: "G92", line: self.block.line, starts: self.cycle.starts })
    }

    fn annotations(&self) -> Annotations {
        Annotations::Starts
    }

    fn nc_style(&self) -> NcStyle {
        let passes = if self.cycle.starts > 1 { PassComment::Starts } else { PassComment::None };
        NcStyle { words: MoveWords::Fanuc, passes, plunges: false, contours: false }
    }

    fn pass_table(&self) -> PassTable {
        PassTable::Row {
            title: "G92 blocks",
            columns: ["line", "start", "B X", "B Z", "cut to X", "cut to Z", "run-out X", "run-out Z"],
            sync: None,
        }
    }

    fn regions(&self, _engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
        // No thread height either: the thread's crests stand above the cut
        // line, so the box runs from A's short-axis coordinate (open: our
        // approach, retract and return run on its edges) through the cut
        // line into the work, along the thread between A's and C's
        // long-axis coordinates. A face thread (P1) is the same with X and
        // Z exchanged.
        let c = &self.cycle;
        let far = 4 * i128::from(cycleref::units::MAX_LENGTH);
        let (a, e) = (c.start, c.end);
        let (a_short, a_long, c_short, c_long) =
            if c.face { (a.z, a.x, e.z, e.x) } else { (a.x, a.z, e.x, e.z) };
        let a_short = i128::from(a_short);
        let short = if a_short > i128::from(c_short) { (-far, a_short) } else { (a_short, far) };
        let (la, lc) = (i128::from(a_long), i128::from(c_long));
        let long = (la.min(lc), la.max(lc));
        let (x, z) = if c.face { (long, short) } else { (short, long) };
        out.push(Region { x_lo: x.0, x_hi: x.1, z_lo: z.0, z_hi: z.1 });
        Ok(())
    }

    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
        let c = &self.cycle;
        tag("g92");
        tag(if c.taper == 0 { "g92:straight" } else { "g92:taper" });
        // A face thread's long axis is X and its side is along Z.
        if !c.face {
            if (c.end.z - c.start.z).abs() <= c.taper.abs() {
                // Reading R-LONG988 `table`: Z long whatever the displacements.
                tag(if c.readings.long_axis_by_table { "g92:long-table" } else { "g92:x-long" });
            }
            tag(if c.start.x > c.end.x { "g92:external" } else { "g92:internal" });
        }
        tag(if c.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
        match c.run_out {
            RunOut::None => {}
            RunOut::Amounts { long: 0, .. } => tag("g92:pull-out"),
            RunOut::Amounts { .. } => tag("g92:run-out"),
            RunOut::Chamfer { .. } => tag("g92:chamfer"),
        }
        if c.starts > 1 {
            tag("g92:multi-start");
        }
        if c.face {
            tag("g92:face");
        }
        if !c.start_angle.is_zero() && !moves.is_empty() {
            tag("g92:q");
        }
    }

    fn panel(&self, _engine: Engine) -> Result<Panel, CycleError> {
        // The blocks of a program share one panel: a thread cut in several
        // G92 blocks (O0012) reads as one picture.
        Ok(Panel::Blocks(BlocksPanel {
            title: "G92",
            x_as_diameter: false,
            run_out: "run-out (J, K)",
            synchronises: "each pass of each start",
            rapids: Some("A \u{2192} B, retract, return to A"),
        }))
    }

    fn lead_off_g32_axis(&self) -> bool {
        // Under R-LONG988 `table`: Z long on a steep taper, X long on a steep
        // face thread (its Z travel |R| above its X travel as a radius,
        // reading R-G92FACE), where a G32 block of the cut is read with the
        // other axis long (R-G32LONG).
        let g = &self.cycle;
        let xf = g.x_mode.factor();
        g.readings.long_axis_by_table
            && if g.face {
                xf * g.taper.abs() > (g.end.x - g.start.x).abs()
            } else {
                (g.end.z - g.start.z).abs() <= g.taper.abs()
            }
    }
}
