//! G75.1, the radial trapezoidal groove cycle of the GSK 980TDi (seed 001,
//! `docs/G75.md`).

use std::cell::RefCell;
use std::fmt;

use cycleref::engine::g75::{check_g75_planned, expand_g75_planned, G75Plan};
use cycleref::g75::RIGHT_ANGLE;
use cycleref::units::Length;
use cycleref::{CornerKind, CycleError, G75Moves, Motion, Move, PathType, Point, Role};

use super::{
    Annotations, CycleCall, GroovePanel, Heading, NcStyle, Panel, PassTable, ReferenceMoves, Region,
};
use crate::lex::Block;
use crate::pipeline::{Engine, Moves};
use crate::reader::{G75Call, Restore};
use crate::text::TextBuf;

/// The `nc` heading of a G75.1: `G75.1 lines 3-4: J1 rough + finish, 2
/// layers, 9 plunges, tool width I3.000`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GrooveHeading {
    /// The line of block 1.
    pub params_line: usize,
    /// The line of block 2.
    pub line: usize,
    /// J: rough, rough and finish, or finish.
    pub path: PathType,
    /// The roughing layers.
    pub layers: u32,
    /// The plunges.
    pub plunges: u64,
    /// The tool's width I, or `None` for a pointed tool.
    pub tool_width: Option<Length>,
}

impl GrooveHeading {
    /// Appends the heading's text to `t` ([`Heading::text`]).
    pub fn put<const N: usize>(&self, t: &mut TextBuf<N>) {
        let path = match self.path {
            PathType::Rough => "J0 rough",
            PathType::RoughAndFinish => "J1 rough + finish",
            PathType::Finish => "J2 finish",
        };
        t.put(b"G75.1 lines ");
        t.integer(super::count(self.params_line));
        t.put(b"-");
        t.integer(super::count(self.line));
        t.put(b": ");
        t.put(path.as_bytes());
        t.put(b", ");
        t.integer(u64::from(self.layers));
        t.put(if self.layers == 1 { b" layer, " } else { b" layers, " });
        t.integer(self.plunges);
        t.put(if self.plunges == 1 { b" plunge, tool " } else { b" plunges, tool " });
        match self.tool_width {
            Some(w) => {
                t.put(b"width I");
                t.fixed(w.increments < 0, w.increments.unsigned_abs(), w.decimals);
            }
            None => t.put(b"pointed"),
        }
    }
}

impl fmt::Display for GrooveHeading {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(Heading::Groove(*self).text().as_str().ok_or(fmt::Error)?)
    }
}

thread_local! {
    /// The plan of the last groove expanded or checked on this thread by
    /// the fixed-point engine, reused when the next has the same words but
    /// for its position (both phases of a run, a program that cuts one
    /// groove at several places): the same moves and alarms as
    /// `expand_g75` by construction, one plan held at a time.
    static PLAN: RefCell<Option<G75Plan>> = const { RefCell::new(None) };
}

impl G75Call<'_> {
    /// The fixed-point engine's alarm for this cycle, if any, without its
    /// moves: what [`CycleCall::engine`] raises (the first phase of a run
    /// only checks, issue 33).
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    pub(crate) fn check_engine(&self) -> Result<(), CycleError> {
        PLAN.with(|plan| check_g75_planned(&self.cycle, &mut plan.borrow_mut()))
    }
}

impl<'a> CycleCall<'a> for G75Call<'a> {
    // Boxed: the largest of the engines' iterators.
    type EngineMoves = Box<G75Moves>;

    fn code(&self) -> &'static str {
        "G75.1"
    }

    fn block(&self) -> &Block<'a> {
        &self.block
    }

    fn params_line(&self) -> Option<usize> {
        Some(self.params_line)
    }

    fn has_params_block(&self) -> bool {
        true
    }

    frame_of_cycle!();

    /// S, from which the cycle rapids to A.
    fn tool_before_start(&self) -> Option<Point> {
        Some(self.cycle.from)
    }

    fn restore(&self) -> Restore {
        self.restore
    }

    fn engine(&self) -> Result<Box<G75Moves>, CycleError> {
        // Boxed where they are made: the moves (a kilobyte) are not
        // copied out of the plan's closure and its result again (issue 33).
        PLAN.with(|plan| expand_g75_planned(&self.cycle, &mut plan.borrow_mut()).map(Box::new))
    }

    fn reference(&self) -> Result<Box<dyn ReferenceMoves>, CycleError> {
        Ok(Box::new(crate::g75::moves(&self.cycle)?))
    }

    fn layers_and_plunges(moves: &Box<G75Moves>) -> Option<(u32, u64)> {
        Some(moves.layers_and_plunges())
    }

    fn heading(&self, moves: &Moves) -> Option<Heading> {
        // The layers and plunges as the engine counted them before its
        // first move; the reference's, counted on a copy of its moves.
        let (layers, plunges) = moves.layers_and_plunges().unwrap_or_else(|| count_plunges(moves.clone()));
        let c = &self.cycle;
        Some(Heading::Groove(GrooveHeading {
            params_line: self.params_line,
            line: self.block.line,
            path: c.path,
            layers,
            plunges,
            tool_width: c.tool_width.map(|w| Length::new(w, c.units)),
        }))
    }

    fn annotations(&self) -> Annotations {
        Annotations::Plunges
    }

    fn nc_style(&self) -> NcStyle {
        NcStyle::GROOVE
    }

    fn pass_table(&self) -> PassTable {
        PassTable::Plunges
    }

    fn regions(&self, _engine: Engine, out: &mut Vec<Region>) -> Result<(), CycleError> {
        // The finishing profile's box, with each round's circle's box.
        let c = &self.cycle;
        let p = cycleref::groove_profile(c)?;
        let f = i128::from(c.x_mode.factor());
        let mut pts = vec![(i128::from(c.start.x), i128::from(c.start.z))];
        let mut prev = c.start;
        for q in p.finishing() {
            pts.push((i128::from(q.at.x), i128::from(q.at.z)));
            if let cycleref::ProfileSegment::Arc { centre, .. } = q.segment {
                // The round lies in its circle's box; the radius is at most
                // |dx|/f + |dz| (rounded up).
                let dx = (i128::from(prev.x) - i128::from(centre.x)).abs();
                let dz = (i128::from(prev.z) - i128::from(centre.z)).abs();
                let r = (dx + f - 1) / f + dz;
                let (ox, oz) = (i128::from(centre.x), i128::from(centre.z));
                pts.push((ox - f * r, oz - r));
                pts.push((ox + f * r, oz + r));
            }
            prev = q.at;
        }
        out.extend(Region::spanning(&pts));
        Ok(())
    }

    fn tags(&self, moves: &[Move], tag: &mut dyn FnMut(&'static str)) {
        let c = &self.cycle;
        tag("g75");
        tag(if c.depth < 0 { "g75:-x" } else { "g75:+x" });
        tag(if c.width < 0 { "g75:-z" } else { "g75:+z" });
        if c.flank_a != RIGHT_ANGLE || c.flank_b != RIGHT_ANGLE {
            tag("g75:angled");
        }
        if c.slope > 0 {
            tag("g75:slope");
        }
        tag(match c.path {
            PathType::Rough => "g75:j0",
            PathType::RoughAndFinish => "g75:j1",
            PathType::Finish => "g75:j2",
        });
        if c.allowance_x > 0 || c.allowance_z > 0 {
            tag("g75:allowances");
        }
        if c.tool_width.is_some_and(|w| w > 0) {
            tag("g75:tool-width");
        }
        if moves.iter().any(|m| matches!(m.role, Role::LayerChange(_))) {
            tag("g75:layers");
        }
        if moves.iter().any(|m| matches!(m.role, Role::PeckRetract(_))) {
            tag("g75:pecking");
        }
        if c.corners.iter().any(|k| k.size > 0) {
            tag("g75:corners");
        }
        if c.path.finishes() && c.corners.iter().any(|k| k.size > 0 && k.kind == CornerKind::Chamfer) {
            tag("g75:chamfers");
        }
        if moves.iter().any(|m| matches!(m.motion, Motion::Arc { .. })) {
            tag("g75:arcs");
        }
    }

    fn panel(&self, engine: Engine) -> Result<Panel, CycleError> {
        // The programmed profile is the finishing path (J2) of the same
        // groove for a pointed tool, by the same engine; the roughing
        // region, the engine's profile's roughing vertices.
        let c = &self.cycle;
        let pointed = G75Call {
            cycle: cycleref::G75Cycle { tool_width: None, path: PathType::Finish, ..*c },
            ..self.clone()
        };
        let profile = crate::pipeline::expand(crate::Cycle::G75(&pointed), engine)?
            .filter(|m| m.role == Role::FinishContour)
            .collect();
        let roughing = cycleref::groove_profile(c)?.roughing().to_vec();
        Ok(Panel::Groove(GroovePanel {
            tool_width: c.tool_width,
            width_direction: c.axial_sign(),
            profile,
            roughing,
        }))
    }
}

/// The roughing's layers (the deepest layer of a plunge) and plunges (its
/// [`Role::PlungeRetract`] moves) of a groove's `moves`.
pub fn count_plunges(moves: impl Iterator<Item = Move>) -> (u32, u64) {
    let (mut layers, mut plunges) = (0, 0);
    for m in moves {
        if let Role::Peck(p) | Role::PeckRetract(p) | Role::PlungeRetract(p) | Role::Step(p) = m.role {
            layers = layers.max(p.layer);
        }
        plunges += u64::from(matches!(m.role, Role::PlungeRetract(_)));
    }
    (layers, plunges)
}
