//! G76, the multiple thread-cutting cycle, and G78, GSK's enhanced one (a
//! front end on the same cycle): seed 004, seed 000, the GSK 980TDi and
//! 988TA pages.

use std::fmt;

use cycleref::{
    CycleError, DepthMode, G76Moves, Infeed, LeadWord, Motion, Move, PassKind, Point, Role, RunOut,
};

use super::{
    for_each_move, Annotations, CycleCall, Heading, MoveWords, NcStyle, Panel, PassComment, PassTable,
    PassesPanel, ReferenceMoves, Region,
};
use crate::lex::Block;
use crate::pipeline::{Engine, Moves};
use crate::reader::{G76Call, Multipass, Restore};
use crate::text::TextBuf;

/// The `nc` heading of a G76 or G78: `G76 line 4: 7 rough + 1 finish
/// passes x 1 start`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MultipassHeading {
    /// G76 or G78.
    pub code: &'static str,
    /// The line of block 2.
    pub line: usize,
    /// The rough passes of one start (reading R-LIMIT).
    pub rough_passes: u64,
    /// The finishing passes.
    pub finishing_passes: u32,
    /// The starts.
    pub starts: u32,
}

impl MultipassHeading {
    /// Appends the heading's text to `t` ([`Heading::text`]).
    pub fn put<const N: usize>(&self, t: &mut TextBuf<N>) {
        t.put(self.code.as_bytes());
        t.put(b" line ");
        t.integer(super::count(self.line));
        t.put(b": ");
        t.integer(self.rough_passes);
        t.put(b" rough + ");
        t.integer(u64::from(self.finishing_passes));
        t.put(b" finish passes x ");
        t.integer(u64::from(self.starts));
        t.put(if self.starts == 1 { b" start" } else { b" starts" });
    }
}

impl fmt::Display for MultipassHeading {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(Heading::Multipass(*self).text().as_str().ok_or(fmt::Error)?)
    }
}

impl G76Call<'_> {
    /// The fixed-point engine's alarm for this cycle, if any, without its
    /// moves: what [`CycleCall::engine`] raises
    /// ([`cycleref::engine::check_g76`]; the first phase of a run only
    /// checks, issue 33).
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    pub(crate) fn check_engine(&self) -> Result<(), CycleError> {
        cycleref::engine::check_g76(&self.cycle)
    }
}

impl<'a> CycleCall<'a> for G76Call<'a> {
    type EngineMoves = G76Moves;

    fn code(&self) -> &'static str {
        self.code.code()
    }

    fn block(&self) -> &Block<'a> {
        &self.block
    }

    fn params_line(&self) -> Option<usize> {
        self.params_line
    }

    fn has_params_block(&self) -> bool {
        true
    }

    frame_of_cycle!();

    fn restore(&self) -> Restore {
        self.restore
    }

    fn engine(&self) -> Result<G76Moves, CycleError> {
        cycleref::expand_g76(&self.cycle)
    }

    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError> {
        Ok(Box::new(crate::g76::moves(&self.cycle)?))
    }

    fn rough_passes(moves: &G76Moves) -> Option<u64> {
        Some(moves.rough_passes())
    }

    fn heading(&self, moves: &Moves) -> Option<Heading> {
        // The heading counts the rough passes, found before any move
        // (reading R-LIMIT) as both engines find it: the engine's iterator
        // keeps its count, the reference's is counted again; the cycle
        // expanded, so it has a count.
        let rough_passes = match moves.rough_passes() {
            Some(n) => n,
            None => cycleref::engine::rough_pass_count(&self.cycle).unwrap_or(0),
        };
        Some(Heading::Multipass(MultipassHeading {
            code: self.code.code(),
            line: self.block.line,
            rough_passes,
            finishing_passes: self.cycle.finishing_passes,
            starts: self.cycle.starts,
        }))
    }

    fn annotations(&self) -> Annotations {
        Annotations::Passes
    }

    fn nc_style(&self) -> NcStyle {
        NcStyle { words: MoveWords::Fanuc, passes: PassComment::Full, plunges: false, contours: false }
    }

    fn pass_table(&self) -> PassTable {
        PassTable::Passes
    }

    fn regions(&self, engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
        // X between the root line C–D and the crest line; Z strictly between
        // D and the Z where the cut nearest D starts (R-CHECKSPLIT).
        let c = &self.cycle;
        let f = i128::from(c.x_mode.factor());
        let (dx, dz) = (i128::from(c.end.x), i128::from(c.end.z));
        let cx = dx + f * i128::from(c.taper);
        let side = if i128::from(c.start.x) >= cx { 1 } else { -1 };
        let crest = side * f * i128::from(c.thread_height);
        // The Z where the cut nearest D starts: the thread runs from there
        // to D (before it the tool is in the air: ours rapids to every pass
        // start). Streamed, in constant memory (the cycle may have millions
        // of passes across its starts).
        let mut prev = c.start;
        let mut zs: Option<i64> = None;
        for_each_move(self, engine, |m| {
            if let Motion::Thread { sync: true, .. } = m.motion {
                let nearer = zs.is_none_or(|z| (prev.z - c.end.z).abs() < (z - c.end.z).abs());
                if nearer {
                    zs = Some(prev.z);
                }
            }
            prev = m.to;
        })?;
        let zs = i128::from(zs.unwrap_or(c.start.z));
        out.extend(Region::spanning(&[(dx, dz), (cx, zs), (dx + crest, dz), (cx + crest, zs)]));
        Ok(())
    }

    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
        let c = &self.cycle;
        let g78 = self.code == Multipass::G78;
        tag(if g78 { "g78" } else { "g76" });
        if g78 {
            tag(match c.infeed {
                Infeed::Centre => "g78:centre",
                Infeed::LeftFlank => "g78:left",
                Infeed::RightFlank => "g78:right",
                Infeed::RightCentre => "g78:right-centre",
                Infeed::LeftRight => "g78:left-right",
                Infeed::Alternating => "g78:alternating",
            });
            tag(if c.depth_mode == DepthMode::Equal { "g78:equal" } else { "g78:decreasing" });
        }
        let xc = c.end.x + c.x_mode.factor() * c.taper;
        tag(if c.start.x > xc { "thread:external" } else { "thread:internal" });
        tag(if c.end.z < c.start.z { "direction:-z" } else { "direction:+z" });
        let w = (c.end.z - c.start.z).abs();
        tag(if c.taper == 0 {
            "taper:straight"
        } else if w > c.taper.abs() {
            "taper:z-long"
        } else if c.readings.long_axis_by_table {
            // Reading R-LONG988 `table` (a 988TA G78): Z long all the same.
            "taper:long-table"
        } else {
            "taper:x-long"
        });
        tag(if c.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
        if !g78 {
            tag(match c.infeed {
                Infeed::RightFlank => "infeed:D0",
                Infeed::RightCentre => "infeed:D1",
                Infeed::LeftRight => "infeed:D2",
                // G76's D has no other modes: only G78's P(r) selects these.
                Infeed::Centre | Infeed::LeftFlank | Infeed::Alternating => "infeed:g78-only",
            });
        }
        if c.lead_in > 0 {
            tag("lead-in");
        }
        if c.starts > 1 {
            tag("multi-start");
        }
        match c.run_out {
            RunOut::None => tag("run-out:none"),
            RunOut::Amounts { long: 0, .. } => tag("run-out:pull-out"),
            RunOut::Amounts { .. } => tag("run-out:amounts"),
            RunOut::Chamfer { long, angle_degrees, .. } => {
                tag(if long.is_some() { "run-out:chamfer+k" } else { "run-out:chamfer" });
                if angle_degrees != 45 {
                    tag("run-out:chamfer-angle");
                }
            }
        }
        match c.finishing_passes {
            0 => tag("finish:none"),
            1 => {}
            _ => tag("finish:multiple"),
        }
        // The rough levels of start 1, in order (D2 cuts two passes per level).
        let mut levels: Vec<i64> = Vec::new();
        for m in moves.iter().filter(|m| m.role == Role::Approach) {
            if let Some(p) = m.pass.filter(|p| p.kind == PassKind::Rough && p.start == 1) {
                if levels.last() != Some(&p.depth) {
                    levels.push(p.depth);
                }
            }
        }
        let target = c.thread_height - c.finishing_allowance;
        if target == 0 {
            tag("schedule:d-equals-k");
        }
        if levels.len() == 1 {
            tag("schedule:one-pass");
        }
        let q = u128::try_from(c.first_depth).unwrap_or(0);
        let law = |n: usize| {
            i64::try_from(cycleref::engine::round_sqrt(q * q * u128::try_from(n).unwrap_or(0)))
                .unwrap_or(i64::MAX)
        };
        let step = c.min_cut.max(1);
        for n in 2..=levels.len() {
            let clamp = levels[n - 2] + step;
            if c.depth_mode == DepthMode::Decreasing && c.min_cut > 0 && law(n) < clamp && clamp < target {
                tag("schedule:min-cut");
            }
        }
        if !levels.is_empty() && law(levels.len()) == target && c.depth_mode == DepthMode::Decreasing {
            tag("schedule:exact-k-d");
        }
    }

    fn panel(&self, _engine: Engine) -> Result<Panel, CycleError> {
        let c = &self.cycle;
        let g = crate::g76::geometry(c)?;
        let xf = c.x_mode.factor();
        // C: the Z of A, the X of D plus i; B: the X of C plus k towards A
        // (crate::g76::geometry).
        let c_x = c.end.x + xf * c.taper;
        let b_x = c_x + g.side * xf * c.thread_height;
        let points = [c.start, Point::new(b_x, c.start.z), Point::new(c_x, c.start.z), c.end];
        Ok(Panel::Passes(PassesPanel {
            points,
            direction: g.direction,
            side: g.side,
            starts: c.starts,
            lead: c.lead,
        }))
    }

    fn lead_off_g32_axis(&self) -> bool {
        // A G78 under R-LONG988 `table`: Z long on a steep taper.
        let g = &self.cycle;
        g.readings.long_axis_by_table && (g.end.z - g.start.z).abs() <= g.taper.abs()
    }
}
