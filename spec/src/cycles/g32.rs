//! G32, constant-lead thread cutting (seed 002, the GSK 980TDi and 988TA
//! G32 pages), and LinuxCNC's G33, the same synchronised move.

use cycleref::{CycleError, G32Moves, G32RunOut, LeadWord, Move, Point, Role, Units, XMode};

use super::{
    for_each_move, Annotations, BlocksPanel, CycleCall, Heading, MoveWords, NcStyle, Panel, PassComment,
    PassTable, ReferenceMoves, Region,
};
use crate::lex::Block;
use crate::pipeline::{Engine, Moves};
use crate::reader::G32Call;

impl<'a> CycleCall<'a> for G32Call<'a> {
    type EngineMoves = G32Moves;

    fn code(&self) -> &'static str {
        self.code
    }

    fn block(&self) -> &Block<'a> {
        &self.block
    }

    fn start(&self) -> Point {
        self.g32.start
    }

    fn units(&self) -> Units {
        self.g32.units
    }

    fn x_mode(&self) -> XMode {
        self.g32.x_mode
    }

    fn engine(&self) -> Result<G32Moves, CycleError> {
        cycleref::expand_g32(&self.g32)
    }

    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError> {
        Ok(Box::new(crate::g32::expand(&self.g32)?.into_iter()))
    }

    fn heading(&self, _moves: &Moves) -> Option<Heading> {
        None
    }

    fn annotations(&self) -> Annotations {
        Annotations::Roles
    }

    fn nc_style(&self) -> NcStyle {
        // LinuxCNC's G33 is written in LinuxCNC's words (R-LCNC-SYNC).
        let words = if self.code == "G33" { MoveWords::LinuxCnc } else { MoveWords::Fanuc };
        NcStyle { words, passes: PassComment::None, plunges: false, contours: false }
    }

    fn pass_table(&self) -> PassTable {
        PassTable::Row {
            title: if self.code == "G33" { "G33 blocks" } else { "G32 blocks" },
            columns: ["line", "sync", "from X", "from Z", "cut to X", "cut to Z", "run-out X", "run-out Z"],
            sync: Some(self.g32.sync),
        }
    }

    fn regions(&self, engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
        // No thread height: the box the cut itself spans (a taper's). A
        // straight thread's box has no width: it is widened by one
        // increment across the thread (to each side), so that a rapid leg
        // along the cut line itself (a Z-first retract dragging the tool
        // back along the thread just cut) meets it, while our approach and
        // retract, which end on its edges, do not.
        let mut cut = None;
        for_each_move(self, engine, |m| {
            if cut.is_none() && m.role == Role::Cut {
                cut = Some(m.to);
            }
        })?;
        if let Some(cut) = cut {
            let s = self.g32.start;
            let region = Region::spanning(&[
                (i128::from(s.x), i128::from(s.z)),
                (i128::from(cut.x), i128::from(cut.z)),
            ]);
            out.extend(region.map(Region::widened_where_flat));
        }
        Ok(())
    }

    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
        let b = &self.g32;
        tag("g32");
        let (dx, dz) = (b.end.x - b.start.x, b.end.z - b.start.z);
        tag(if dx == 0 {
            "g32:straight"
        } else if dz == 0 {
            "g32:face"
        } else {
            "g32:taper"
        });
        if dx != 0 && dz != 0 && dz.abs() * b.x_mode.factor() <= dx.abs() {
            tag("g32:x-long");
        }
        tag(if b.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
        match b.run_out {
            G32RunOut::None => {}
            G32RunOut::Amounts { long: 0, .. } => tag("g32:pull-out"),
            G32RunOut::Amounts { .. } => tag("g32:run-out"),
        }
        if !b.sync {
            tag("g32:continuous");
        }
        if b.sync && !b.start_angle.is_zero() && !moves.is_empty() {
            tag("g32:q");
        }
    }

    fn panel(&self, _engine: Engine) -> Result<Panel, CycleError> {
        // The blocks of a program share one panel; G33 (the `linuxcnc`
        // profile) with X as a diameter, as `check` holds it.
        Ok(Panel::Blocks(BlocksPanel {
            title: self.code,
            x_as_diameter: self.code == "G33",
            run_out: "run-out (J, K)",
            synchronises: "not continuing the block before",
            rapids: None,
        }))
    }
}
