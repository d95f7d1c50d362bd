//! The fixed-point G75.1 engine: the radial trapezoidal groove cycle of
//! `docs/G75.md` (the definition the reference model `cycleref_spec::g75`
//! follows too) without heap, floating point, `unsafe` or panics, streamed
//! move by move.
//!
//! # Layout
//!
//! This module is the driver: [`expand_g75`] (every check, in order, then
//! the iterator) and [`G75Moves`] (approach, roughing, tail). The rest is
//! split by concern:
//!
//! * `exact`: the cycle's words in the local frame (`Geometry`), the
//!   interval enclosures of its values at 128 and 512 bits (`Enclosures`,
//!   `Region`), the named real quantities (`Quantity`) and their decisions
//!   (`Evaluator`: floor, ceil, nearest, sign; R-G75ROUND, R-G75TIE);
//! * `contour`: the rounded finishing profile and rough-contour vertices in
//!   local coordinates;
//! * `frame`: local to absolute coordinates, the range check, arc senses;
//! * `roughing`: layers, the peck count, the roughing range check and the
//!   roughing state machine;
//! * `tail`: the precomputed moves after the roughing;
//! * `profile`: the public [`GrooveProfile`] ([`groove_profile`]);
//! * `tests`: worked examples, sweeps and formulas against floats.
//!
//! The reference model is split the same way (`spec/src/g75/`).
//!
//! [`expand_g75`] computes the whole geometry and makes every check before
//! the first move; the [`G75Moves`] it returns then cannot fail. Errors come
//! in this order (reading R-G75ORDER):
//!
//! 1. [`G75Cycle::validate`];
//! 2. [`CycleError::OpeningBelowBottom`] under R-G75SLOPE `falls-towards-d`
//!    (y3 ≥ Y), then [`CycleError::CornerTooLarge`]: flank A, then the
//!    bottom, then flank B (§3);
//! 3. [`CycleError::GrooveNarrowerThanTool`] at the last layer (§7), for
//!    every J: the approach point A11 of step 1 needs layer 1's plunge
//!    range whatever J is (reading R-G75NARROW);
//! 4. [`CycleError::RidgesInLayers`] (§7, reading R-G75RIDGE): roughing
//!    (J0, J1) in more than one layer with Δk > w where layer 1's plunge
//!    range is wider than w;
//! 5. [`CycleError::TooManyPecks`] (§9), counted before any move, only when
//!    the cycle roughs (J0, J1): J2 makes no pecks (reading R-G75PECKS);
//! 6. [`CycleError::OutOfRange`] with [`Field::PassCoordinate`](crate::error::Field::PassCoordinate): the first
//!    coordinate of the emitted moves, in move order (each move's end X,
//!    end Z, then an arc's centre X, centre Z), beyond
//!    [`MAX_LENGTH`](crate::units::MAX_LENGTH); the value is the absolute coordinate, saturated to
//!    `i64` (reading R-G75RANGE).
//!
//! [`CycleError::UndecidedRounding`] comes from the first value that cannot
//! be decided even with reading R-G75TIE (below): only an enclosure that
//! still holds two rounding boundaries at 512 bits (a poisoned one, which
//! the magnitudes below rule out). Values are computed in the order: the
//! corner comparisons, the last layer's plunge range, layer 1's, `y_top`,
//! the other layers' (while counting pecks), the rough contour (J0, J1),
//! the finishing contour (J1, J2). Values that the chosen J does not use are not computed
//! (reading R-G75NEED): J0 never computes the finishing points, J2 never
//! the rough contour.
//!
//! # Exact rounding
//!
//! Every coordinate is rounded from the exact real value of its formula in
//! `docs/G75.md` §3–§8. The formula is first evaluated on the fast path
//! (reading R-FASTPATH, [`crate::engine::approx`]: 64-bit fixed point with
//! a rigorous error bound, decided only when no rounding boundary lies
//! within the bound; [`G75Moves::fast_path_stats`] counts its fallbacks),
//! then, if that does not decide, with the rigorous interval arithmetic of
//! [`crate::engine::real`]: at 128 fraction bits, and, only if that
//! interval does not decide the rounding, again from the same formula at
//! 512 fraction bits (reading R-G75ROUND). [`expand_g75_exact`] is the
//! engine with the fast path off, the same by construction (the tests
//! compare them). Exact inputs (right angles, 45°,
//! the other exact cases of §6) give exact point intervals, decided
//! exactly.
//!
//! R-G75TIE: a value still undecided at 512 bits whose enclosure holds
//! exactly one rounding boundary (an integer for floor and ceil, a
//! half-integer for nearest, 0 for a sign; inside or on an end) is taken
//! to lie on it: `floor(k) = ceil(k) = k`, the nearest of `k + 1/2` is
//! `k + 1`, the sign is 0 ([`Interval::round_tie`](crate::engine::real::Interval::round_tie), [`Interval::sign_tie`](crate::engine::real::Interval::sign_tie)). This is
//! how identities among irrational values are decided (a round on a 60°
//! flank, `tan 30°·sin 60° = 1/2`; a round whose `f·ρ` equals Δu,
//! `y_K1 = Y − 2Δu`). The rule is applied only to the 512-bit enclosure,
//! never to the 128-bit one, in `Evaluator::round`, `Evaluator::sign` and
//! `plunges_at` alike.
//!
//! The formulas are evaluated as written — in particular `((Y − Δu −
//! y)/f)·cot(a/2)` is 0 exactly at `y = Y − Δu` — so an expression is exact
//! in this engine exactly when it is exact in the reference model.
//!
//! # Magnitudes
//!
//! After `validate()`: `Y, d, Δu, Δw, w, Δi, Δk, Δv < 2^27`, corner sizes
//! `< 2^20`, `f ≤ 2`; every tangent or cotangent used is at most
//! `cot(0.00005°) < 2^21`; a chamfer's tangent length under R-G75CHAMFER
//! `axial-width`, `c / (cos θ1 + cos θ2)`, is below `c / cos 89.9999° <
//! 2^40`; `1 − tan L·cot b = sin(b − L)/(sin b·cos L) ≥
//! sin(0.0001°) > 2^-20` (under R-G75SLOPE `falls-towards-d` the divisor
//! is `1 + tan L·cot b ≥ 1`). So `(Y/f)·cot a < 2^47`, `u3 < 2^69`, `y3 =
//! −f·u3·tan L` has `|y3| = f·(…)·sin L·sin b / sin(b − L) < 2^70`, and no
//! formula exceeds `2^96`: far inside the `2^127` of an [`Interval`](crate::engine::real::Interval), so no
//! interval operation overflows (an overflow would poison the interval and
//! give `UndecidedRounding`, never a wrong value). Rounded values are kept
//! in `i128` until the range check has bounded every coordinate of a move
//! by `MAX_LENGTH < 2^30`; only then are they narrowed to `i64`. The peck
//! count is formed in `i128` (at most `2^71` pecks per plunge times `2^48`
//! plunges per layer before the limit stops the count).
//!
//! # Work and memory
//!
//! Up front: a fixed number of interval evaluations (about forty) plus two
//! per layer while counting pecks (at most `MAX_PECKS` layers, since every
//! layer has at least one peck). Per move: O(1); a layer change evaluates
//! the layer's plunge range again (a handful of 64-bit products on the fast
//! path; when they do not decide, the 128-bit context is rebuilt from the
//! words for that layer, and when 128 bits do not decide either, in
//! practice only for a boundary exactly on an integer (R-G75TIE), the
//! 512-bit one: a bounded amount of work). A [`G75Moves`] is a fixed-size
//! value (1 184 bytes on 64-bit targets: the precomputed tail of at most 22
//! moves, 24 bytes each with their arcs' centres kept apart, and the fast
//! path's values of the region's boundaries; the test
//! `size_of_the_iterator` bounds it). The interval contexts of the
//! fallback (several kilobytes) live in a `Fallback` on the stack of
//! [`expand_g75`], lent to the evaluator and never copied.
//!
//! [`expand_g75_planned`] keeps the part of an expansion that does not
//! depend on where the groove is ([`G75Plan`]: every decision of the
//! geometry in the local frame, and the alarms among them) and reuses it
//! for the next cycle with the same words but for its start point and the
//! point before it; only the range checks and the absolute moves are made
//! again (the tail's moves are kept in the plan in the local frame and
//! only placed); [`check_g75_planned`] makes the checks alone, with the
//! tail's range check one box's corners when they lie in the range.
//! [`expand_g75`] is the same function with no plan kept, so the
//! two agree by construction (the test `planned_expansion_is_the_plain_one`
//! compares them, alarms included). The reader's pipeline keeps one plan
//! per thread, so a program that cuts one groove at many places decides
//! its geometry once, not twice per groove (issue 33).
//!
//! # Readings added by this engine
//!
//! Where `docs/G75.md` leaves a detail open, the simplest reading is taken;
//! the reference model must match them (each is also cited in the code):
//!
//! * R-G75ORDER, R-G75NARROW, R-G75PECKS, R-G75RANGE, R-G75NEED: above.
//!   R-G75RANGE checks only emitted moves: a move left out as empty
//!   (R-G75ZERO) has no coordinate to check, not even an arc centre.
//! * R-G75ROLES: the step-8 rapids back to `y_top` and A11 are
//!   [`Role::Approach`]; the rapids of step 9 (to R0, back to A11) are
//!   [`Role::RoughContour`]; the two rapids of step 10 to F0 are
//!   [`Role::FinishContour`]; the three rapids back to S and the one to
//!   `from` are [`Role::Return`]. J0 goes from A11 (after step 9) straight
//!   to `from`.
//! * R-G75ARCDIR: the turning sense of a round is fixed by the geometry
//!   (see `Frame::clockwise`): convex corners r1, r2 are G02 exactly when
//!   `sx·sz < 0`, concave corners r3, r4 exactly when `sx·sz > 0`.
//! * R-G75KCHECK: no alarm beyond §7's. The check `K2.u ≤ K3.u` (or Q1, Q2)
//!   is the last layer's `A_Mf ≥ A_M1` itself (at `y = Y − Δu`, `left` is
//!   K2's formula and `right` K3's); `K1.u ≤ K2.u`, `K4.u ≥ K3.u` and
//!   `y_K1, y_K4 ≤ Y − Δu` hold for every cycle (the chords meet the
//!   flanks above the bottom). `y_K1` (`y_K4`) may lie at or above
//!   `y_top` when the corner covers most of its flank and Δu > 0; then
//!   (§8) K1 (K4) is not a vertex and R0 (R3) lies on the chord.
//! * R-G75ARCZERO: an arc whose rounded end is its start is left out like
//!   any empty move (`TailBuilder::go`, in the local frame), centre and all.
//! * R-G75PROFILE: [`groove_profile`] checks `validate()` and the corners
//!   only, keeps every point (none is left out as empty; K1 and K4 are
//!   vertices only below `y_top`, as in the rough contour), and range-checks
//!   its own points in its order.

use core::iter::FusedIterator;

mod contour;
mod exact;
mod frame;
mod profile;
mod roughing;
mod tail;
#[cfg(test)]
mod tests;

pub use profile::{groove_profile, GrooveProfile, ProfilePoint, ProfileSegment};

use contour::{finish_profile, rough_vertices, Local, LocalSegment};
use exact::{Evaluator, Fallback, Geometry, Region};
use frame::Frame;
use roughing::{check_peck_count, check_roughing, Layers, RoughStep, Roughing};
use tail::{Leg, LegKind, TailBuilder, TailRole, ARCS, TAIL};

use crate::engine::approx::Approx;
use crate::engine::arith::saturate_i64;
use crate::engine::linuxcnc::FastPathStats;
use crate::error::CycleError;
use crate::g75::G75Cycle;
use crate::moves::{Motion, Move, Role};
use crate::units::Length;

/// Which part of the path comes next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stage {
    /// Step 1: the rapid to A11.
    Approach,
    /// Steps 2–8.
    Rough,
    /// The precomputed tail.
    Tail,
    /// Nothing more.
    Done,
}

/// The moves of a G75.1 cycle, in order (`docs/G75.md` §8): an
/// [`Iterator`] of constant size made by [`expand_g75`]. It cannot fail:
/// every check was made before it was returned.
#[derive(Clone, Debug)]
pub struct G75Moves {
    /// Local to absolute coordinates.
    frame: Frame,
    /// The words in the local frame (a layer's plunge range needs them).
    geometry: Geometry,
    /// The roughing region's boundaries on the fast path (R-FASTPATH;
    /// `None` when it is off): a layer's plunge range falls back to 128
    /// and 512 bits from `geometry`.
    region: Option<Region<Approx>>,
    /// The values decided so far and the fast path's fallbacks.
    stats: FastPathStats,
    /// Which part of the path comes next.
    stage: Stage,
    /// Step 1, the rapid to A11, unless the tool is there already.
    approach: Option<Leg>,
    /// J0 or J1: the cycle roughs.
    roughs: bool,
    /// The roughing state.
    rough: Roughing,
    /// The tool's local position `(u, y)` during the roughing.
    at: (i64, i64),
    /// The precomputed moves after the roughing.
    tail: [Leg; TAIL],
    /// How many of `tail` are moves.
    tail_len: usize,
    /// The centres of the tail's arcs ([`LegKind::Arc`]).
    centres: [crate::units::Point; ARCS],
    /// The next move of `tail`.
    tail_next: usize,
    /// The plunges of the roughing (0 when the cycle does not rough).
    plunges: u64,
}

/// Expands a G75.1 cycle (`docs/G75.md`): the same error or the same moves
/// as the reference model.
///
/// # Errors
///
/// In this order (R-G75ORDER): [`G75Cycle::validate`]'s errors,
/// [`CycleError::OpeningBelowBottom`] (R-G75SLOPE `falls-towards-d`),
/// [`CycleError::CornerTooLarge`], [`CycleError::GrooveNarrowerThanTool`],
/// [`CycleError::RidgesInLayers`], [`CycleError::TooManyPecks`], [`CycleError::OutOfRange`] for a move
/// coordinate; [`CycleError::UndecidedRounding`] where a needed value cannot
/// be decided at 512 fraction bits even by R-G75TIE (an enclosure holding
/// two rounding boundaries).
///
/// Twin: `spec/src/g75/mod.rs`, `expand`.
pub fn expand_g75(c: &G75Cycle) -> Result<G75Moves, CycleError> {
    expand(c, true)
}

/// [`expand_g75`] with the fast path off: every value decided by the
/// interval arithmetic alone (128 bits, then 512), as before issue 33. The
/// same result by construction (reading R-FASTPATH); kept for the tests and
/// benchmarks that compare the two paths.
///
/// # Errors
///
/// Those of [`expand_g75`].
pub fn expand_g75_exact(c: &G75Cycle) -> Result<G75Moves, CycleError> {
    expand(c, false)
}

/// [`expand_g75`], the fast path on or off.
fn expand(c: &G75Cycle, fast_path: bool) -> Result<G75Moves, CycleError> {
    c.validate()?;
    place(c, &G75Plan::of_valid(c, fast_path)?)
}

/// Expands a G75.1 cycle like [`expand_g75`], keeping in `plan` the part of
/// the work that does not depend on where the groove is (see [`G75Plan`]):
/// when `plan` holds the plan of a cycle with the same words but for its
/// start point and the point before it, that plan is used instead of being
/// computed again (a program that cuts one groove at several places
/// decides its geometry once). The same result as [`expand_g75`] by
/// construction: [`expand_g75`] is this function with an empty `plan`.
///
/// ```
/// use cycleref::engine::g75::expand_g75_planned;
/// use cycleref::examples::G75_SEED;
/// use cycleref::{expand_g75, Point};
///
/// let mut plan = None;
/// let moves: Vec<_> = expand_g75_planned(&G75_SEED, &mut plan)?.collect();
/// assert_eq!(moves, expand_g75(&G75_SEED)?.collect::<Vec<_>>());
/// // The same groove 5 mm further along Z: the plan is reused.
/// let mut moved = G75_SEED;
/// moved.start.z -= 5_000;
/// moved.from.z -= 5_000;
/// let again: Vec<_> = expand_g75_planned(&moved, &mut plan)?.collect();
/// assert_eq!(again, expand_g75(&moved)?.collect::<Vec<_>>());
/// # Ok::<(), cycleref::CycleError>(())
/// ```
///
/// # Errors
///
/// Those of [`expand_g75`], in its order.
pub fn expand_g75_planned(c: &G75Cycle, plan: &mut Option<G75Plan>) -> Result<G75Moves, CycleError> {
    place(c, planned(c, plan)?)
}

/// The alarm [`expand_g75_planned`] raises for `c`, if any, without making
/// its moves (the first phase of a run, which only checks: issue 33); the
/// plan kept as [`expand_g75_planned`] keeps it. The same result as
/// `expand_g75_planned(c, plan).map(drop)` (the test
/// `planned_expansion_is_the_plain_one` compares them).
///
/// ```
/// use cycleref::engine::g75::check_g75_planned;
/// use cycleref::examples::G75_SEED;
/// use cycleref::units::MAX_LENGTH;
/// use cycleref::{expand_g75, CycleError};
///
/// let mut plan = None;
/// assert_eq!(check_g75_planned(&G75_SEED, &mut plan), Ok(()));
/// // The same groove moved to the edge of the range: its width, towards
/// // −Z, leaves it, and the check names the same coordinate as the
/// // expansion.
/// let mut far = G75_SEED;
/// let dz = -MAX_LENGTH + 10 - far.start.z;
/// far.start.z += dz;
/// far.from.z += dz;
/// let alarm = expand_g75(&far).err();
/// assert!(matches!(alarm, Some(CycleError::OutOfRange { .. })));
/// assert_eq!(check_g75_planned(&far, &mut plan).err(), alarm);
/// ```
///
/// # Errors
///
/// Those of [`expand_g75`], in its order.
pub fn check_g75_planned(c: &G75Cycle, plan: &mut Option<G75Plan>) -> Result<(), CycleError> {
    planned(c, plan)?.check_placed(c)
}

/// The plan of `c` after [`G75Cycle::validate`]: `plan` when it fits `c`,
/// else made anew and kept in `plan`.
fn planned<'p>(c: &G75Cycle, plan: &'p mut Option<G75Plan>) -> Result<&'p G75Plan, CycleError> {
    match plan {
        // `c.validate()`: the plan's words passed it (a plan is kept only
        // below), and its checks of the words come after those of the
        // position, which are left (issue 33).
        Some(p) if p.fits(c) => c.validate_position()?,
        _ => {
            c.validate()?;
            // A failed plan leaves nothing behind: the next cycle plans again.
            *plan = None;
            *plan = Some(G75Plan::of_valid(c, true)?);
        }
    }
    plan.as_ref().ok_or(CycleError::UndecidedRounding)
}

/// The part of a G75.1 expansion that depends only on the groove's words,
/// not on where it is: every decision of the geometry (the corners, the
/// plunge ranges, `y_top`, the peck count, the rough and finishing contours
/// in the local frame), with the alarms among them (R-G75ORDER 1–5 and
/// `UndecidedRounding`). Its position (the start point and the point before
/// the cycle) adds only the range checks and the absolute moves
/// (R-G75RANGE), made for each cycle. [`expand_g75_planned`] keeps one.
#[derive(Clone, Debug)]
pub struct G75Plan {
    /// The cycle it was made for, its start point and the point before it
    /// at the origin.
    key: G75Cycle,
    /// The fast path was on.
    fast_path: bool,
    /// The words in the local frame.
    geometry: Geometry,
    /// The fast path's region (`None`: off).
    region: Option<Region<Approx>>,
    /// The decisions made and the fast path's fallbacks.
    stats: FastPathStats,
    /// The layers.
    layers: Layers,
    /// Layer 1's plunge range.
    first: (i128, i128),
    /// The top of layer 1.
    y_top: i128,
    /// The plunges of the roughing (0: J2).
    plunges: u64,
    /// The moves after the roughing, in the local frame (R-G75ZERO
    /// applied: a move is empty wherever the groove is).
    tail: TailBuilder,
    /// The corners of the box of every local point that placing the plan
    /// maps and range-checks (A11, the tail's ends and centres, the
    /// position after the tail): when both map into the range, so does
    /// every point (X and Z are monotone in y and u).
    reach: (Local, Local),
}

impl G75Plan {
    /// The cycle `c` with its position taken out: what a plan depends on.
    fn key_of(c: &G75Cycle) -> G75Cycle {
        let origin = crate::units::Point::new(0, 0);
        G75Cycle { from: origin, start: origin, ..*c }
    }

    /// True when this plan is that of `c` (its words but for the position).
    fn fits(&self, c: &G75Cycle) -> bool {
        self.fast_path && self.key == G75Plan::key_of(c)
    }

    /// The plan of a cycle that passed [`G75Cycle::validate`], every
    /// geometric check in the order of R-G75ORDER.
    fn of_valid(c: &G75Cycle, fast_path: bool) -> Result<G75Plan, CycleError> {
        let mut fallback = Fallback::default();
        let mut ev = Evaluator::corners_checked(c, fast_path, &mut fallback)?;
        let g = ev.g;
        let layers = Layers::new(c, &g);
        let rough_bottom = layers.rough_bottom;
        // R-G75PLUNGE: the last layer is the narrowest (left grows, right
        // shrinks with depth); R-G75NARROW: checked for every J. This is also
        // the check K2.u ≤ K3.u (or Q1/Q2): at y = Y − Δu, left is K2's formula
        // and right K3's plus w.
        let (last_first, last_last) = ev.plunges(rough_bottom)?;
        if last_last < last_first {
            return Err(CycleError::GrooveNarrowerThanTool { tool_width: Length::new(g.w, c.units) });
        }
        let y1 = layers.bottom(1);
        let (a11, a1f) = if layers.count == 1 { (last_first, last_last) } else { ev.plunges(y1)? };
        // R-G75RIDGE: layered roughing with a step wider than the tool leaves
        // ridges in layer 1 that the next layer's rapids would cross (refused
        // unless the reading is `as-written`).
        if !c.readings.ridges_as_written
            && c.path.roughs()
            && layers.count >= 2
            && c.step > g.w
            && a1f - a11 > i128::from(g.w)
        {
            return Err(CycleError::RidgesInLayers {
                step: Length::new(c.step, c.units),
                tool_width: Length::new(g.w, c.units),
            });
        }
        // Layer tops: y_top = floor(y3), or 0 when the opening falls
        // (R-G75LAYER, R-G75SLOPE).
        let y_top = ev.y_top()?;

        // §9, only when roughing (R-G75PECKS).
        let roughs = c.path.roughs();
        let plunges = if roughs {
            check_peck_count(&mut ev, c, &layers, y_top, (a11, a1f), (last_first, last_last))?
        } else {
            0
        };
        // R-G75NEED: the rough contour only for J0/J1, the finishing profile
        // only for J1/J2.
        let rough_pts = if roughs { Some(rough_vertices(&mut ev, y_top)?) } else { None };
        let finish_pts = if c.path.finishes() { Some(finish_profile(&mut ev)?) } else { None };
        let tail =
            tail_of(&Frame::new(c), &g, &layers, roughs, last_last, (a11, y_top), rough_pts, finish_pts);
        let a11_local = (a11, y_top);
        let mut reach = (a11_local, a11_local);
        let legs = tail.legs.iter().take(tail.len).map(|l| l.to);
        for p in legs.chain(tail.centres.iter().take(tail.arcs).copied()).chain([tail.at]) {
            reach.0 = (reach.0 .0.min(p.0), reach.0 .1.min(p.1));
            reach.1 = (reach.1 .0.max(p.0), reach.1 .1.max(p.1));
        }
        Ok(G75Plan {
            key: G75Plan::key_of(c),
            fast_path,
            geometry: g,
            region: ev.quick.map(|q| q.r),
            stats: ev.stats,
            layers,
            first: (a11, a1f),
            y_top,
            plunges,
            tail,
            reach,
        })
    }

    /// The alarm that placing this plan for `c` (a cycle it
    /// [fits](G75Plan::fits), or the one it was made for) raises, if any:
    /// [`place`]'s, without making the moves. When the box of the points
    /// it maps lies in the range, only the roughing's check (R-G75RANGE,
    /// after A11's and before the tail's) can fail; else [`place`] decides.
    fn check_placed(&self, c: &G75Cycle) -> Result<(), CycleError> {
        let frame = Frame::new(c);
        if frame.point(self.reach.0).is_ok() && frame.point(self.reach.1).is_ok() {
            if c.path.roughs() {
                check_roughing(c, &frame, self.y_top, self.first, &self.layers)?;
            }
            Ok(())
        } else {
            place(c, self).map(|_| ())
        }
    }
}

/// The moves after the roughing in the local frame (steps 8–10), from
/// where the roughing ends (or A11 when the cycle does not rough).
#[allow(clippy::too_many_arguments)]
fn tail_of(
    frame: &Frame,
    g: &Geometry,
    layers: &Layers,
    roughs: bool,
    last_last: i128,
    a11_local: Local,
    rough_pts: Option<([contour::RoughLocal; 6], usize)>,
    finish_pts: Option<([contour::ProfileLocal; 8], usize)>,
) -> TailBuilder {
    let y_top = a11_local.1;
    let w = i128::from(g.w);
    let top_last = if layers.count >= 2 { i128::from(layers.bottom(layers.count - 1)) } else { y_top };
    let mut b = TailBuilder::new(if roughs { (last_last, top_last) } else { a11_local });
    if let Some((v, n)) = rough_pts {
        // Step 8: back along X to y_top and along Z to A11.
        b.rapid((b.at.0, y_top), TailRole::Approach);
        b.rapid(a11_local, TailRole::Approach);
        // Step 9: rapid to R0, feeds along the contour, rapid back to A11.
        let mut loops = crate::loop_counters::count!(G75_CONTOUR);
        for (i, p) in v.iter().take(n).enumerate() {
            loops.tick();
            let to = if p.far { (p.at.0 - w, p.at.1) } else { p.at };
            if i == 0 {
                b.rapid(to, TailRole::RoughContour);
            } else {
                b.feed(to, TailRole::RoughContour);
            }
        }
        b.rapid(a11_local, TailRole::RoughContour);
    }
    if let Some((pts, n)) = finish_pts {
        // Step 10: along Z to F0's u at y_top, along X to F0, the contour.
        let shift = |p: Local, far: bool| if far { (p.0 - w, p.1) } else { p };
        let mut loops = crate::loop_counters::count!(G75_CONTOUR);
        for (i, p) in pts.iter().take(n).enumerate() {
            loops.tick();
            let to = shift(p.at, p.far);
            match p.seg {
                LocalSegment::Start => {
                    if i == 0 {
                        // Along X to min(y_top, F0's y) first: F0 lies
                        // above y_top only when the opening falls
                        // (R-G75SLOPE), where T1s is above S.
                        let y_in = y_top.min(to.1);
                        b.rapid((b.at.0, y_in), TailRole::FinishContour);
                        b.rapid((to.0, y_in), TailRole::FinishContour);
                        b.rapid(to, TailRole::FinishContour);
                    }
                }
                LocalSegment::Line => b.feed(to, TailRole::FinishContour),
                LocalSegment::Arc { centre, convex } => {
                    let cw = frame.clockwise(convex);
                    b.go(to, Some((shift(centre, p.far), cw)), true, TailRole::FinishContour);
                }
            }
        }
        // Back: along X to min(y_top, y_end), along Z to u = 0, along X to S.
        let end = b.at;
        let y_back = y_top.min(end.1);
        b.rapid((end.0, y_back), TailRole::Return);
        b.rapid((0, y_back), TailRole::Return);
        b.rapid((0, 0), TailRole::Return);
    }
    b
}

/// The moves of a validated cycle `c` from its plan: the range checks in
/// move order (R-G75RANGE) and the absolute moves.
fn place(c: &G75Cycle, plan: &G75Plan) -> Result<G75Moves, CycleError> {
    let g = plan.geometry;
    let frame = Frame::new(c);
    let layers = plan.layers;
    let rough_bottom = layers.rough_bottom;
    let (a11, a1f) = plan.first;
    let y1 = layers.bottom(1);
    let y_top = plan.y_top;
    let roughs = c.path.roughs();
    let plunges = plan.plunges;

    // R-G75RANGE, in move order. Step 1: the approach to A11.
    let a11_local = (a11, y_top);
    let a11_abs = frame.point(a11_local)?;
    if roughs {
        check_roughing(c, &frame, y_top, (a11, a1f), &layers)?;
    }
    // The tail: each leg's end, then its arc's centre. Every point placed
    // here lies in the box of `plan.reach`: when its corners are in the
    // range, so is every point, placed without a check each (issue 33);
    // else each is checked, in move order.
    let t = &plan.tail;
    let boxed = frame.point(plan.reach.0).is_ok() && frame.point(plan.reach.1).is_ok();
    let place_point = |p: Local| if boxed { Ok(frame.point_in_range(p)) } else { frame.point(p) };
    let mut legs = [Leg { kind: LegKind::Rapid, to: c.from, role: TailRole::Return }; TAIL];
    let mut centres = [c.from; ARCS];
    let mut len = 0;
    for (slot, l) in legs.iter_mut().zip(t.legs.iter().take(t.len)) {
        let to = place_point(l.to)?;
        if let LegKind::Arc { centre, .. } = l.kind {
            let i = usize::from(centre);
            if let (Some(at), Some(&local)) = (centres.get_mut(i), t.centres.get(i)) {
                *at = place_point(local)?;
            }
        }
        *slot = Leg { kind: l.kind, to, role: l.role };
        len += 1;
    }
    // Step 10's end: back to the point before the cycle, in one move. The
    // tail's end is local; `from` may lie anywhere in range.
    let end_abs = place_point(t.at)?;
    if end_abs != c.from {
        if let Some(slot) = legs.get_mut(len) {
            *slot = Leg { kind: LegKind::Rapid, to: c.from, role: TailRole::Return };
            len += 1;
        }
    }

    let approach =
        (a11_abs != c.from).then_some(Leg { kind: LegKind::Rapid, to: a11_abs, role: TailRole::Approach });
    let rough = Roughing {
        // layers ≤ MAX_PECKS when roughing; 1 otherwise is never read.
        layers: u32::try_from(layers.count).unwrap_or(u32::MAX),
        m: 1,
        rough_bottom,
        dv: layers.dv,
        di: c.peck,
        dk: c.step,
        ex: g.f * c.retract,
        peck_as_written: c.readings.peck_retract_as_written,
        equal_layers: layers.equal,
        prev_top: saturate_i64(y_top),
        top: saturate_i64(y_top),
        bottom: y1,
        first: saturate_i64(a11),
        last: saturate_i64(a1f),
        u: saturate_i64(a11),
        n: 1,
        target: saturate_i64(y_top).saturating_add(c.peck),
        depth: saturate_i64(y_top),
        sub: RoughStep::Peck,
    };
    Ok(G75Moves {
        frame,
        geometry: g,
        region: plan.region,
        stats: plan.stats,
        stage: Stage::Approach,
        approach,
        roughs,
        rough,
        at: (saturate_i64(a11), saturate_i64(y_top)),
        tail: legs,
        tail_len: len,
        centres,
        tail_next: 0,
        plunges,
    })
}

impl G75Moves {
    /// The roughing's layers M and plunges, counted before the first move
    /// (the count of §9, R-G75PECK): the number of distinct layers and of
    /// [`Role::PlungeRetract`] moves the cycle makes; `(0, 0)` when it does
    /// not rough (J2).
    #[must_use]
    pub fn layers_and_plunges(&self) -> (u32, u64) {
        if self.roughs {
            (self.rough.layers, self.plunges)
        } else {
            (0, 0)
        }
    }
}

impl Iterator for G75Moves {
    type Item = Move;

    fn next(&mut self) -> Option<Move> {
        // The roughing's moves (most of a groove's) first; the other
        // stages out of line, so that the per-move path stays small
        // (issue 33).
        if self.stage == Stage::Rough {
            if let Some(m) = self.next_rough() {
                return Some(m);
            }
            self.stage = Stage::Tail;
        }
        self.next_other()
    }
}

impl G75Moves {
    /// Calls `f` with each move that [`Iterator::next`] would give, in
    /// order, until `f` fails: the same moves (by the same steps: the
    /// roughing's `next_rough`, the other stages' `next_other`), taken by
    /// a loop that `f` is inlined into, with no `Option` of each move
    /// handed back through a call (issue 33: the `nc` writer's groove
    /// loop). The test `walked_moves_are_the_iterated_ones` compares the
    /// two over generated grooves.
    ///
    /// ```
    /// use cycleref::examples::G75_SEED;
    /// use cycleref::expand_g75;
    ///
    /// let mut walked = Vec::new();
    /// expand_g75(&G75_SEED)?.try_for_each_move(|m| {
    ///     walked.push(m);
    ///     Ok::<(), ()>(())
    /// }).expect("no error");
    /// assert_eq!(walked, expand_g75(&G75_SEED)?.collect::<Vec<_>>());
    /// # Ok::<(), cycleref::CycleError>(())
    /// ```
    ///
    /// # Errors
    ///
    /// The first error `f` returns (the moves after it are not taken).
    #[inline]
    pub fn try_for_each_move<E>(&mut self, mut f: impl FnMut(Move) -> Result<(), E>) -> Result<(), E> {
        loop {
            // One call of `f`, so that it is inlined here; the roughing's
            // and the tail's steps inlined too.
            let next = match self.stage {
                Stage::Rough => self.next_rough(),
                Stage::Tail => self.next_tail(),
                Stage::Approach | Stage::Done => None,
            };
            let m = match next {
                Some(m) => m,
                None => {
                    if self.stage == Stage::Rough {
                        self.stage = Stage::Tail;
                    }
                    match self.next_other() {
                        Some(m) => m,
                        None => return Ok(()),
                    }
                }
            };
            f(m)?;
        }
    }

    /// [`Iterator::next`] in the stages other than the roughing: the
    /// approach (then the roughing), the tail, the end.
    #[inline(never)]
    fn next_other(&mut self) -> Option<Move> {
        let mut loops = crate::loop_counters::count!(G75_NEXT);
        loop {
            loops.tick();
            match self.stage {
                Stage::Approach => {
                    self.stage = if self.roughs { Stage::Rough } else { Stage::Tail };
                    if let Some(l) = self.approach {
                        return Some(Move {
                            motion: Motion::Rapid,
                            to: l.to,
                            role: l.role.role(),
                            pass: None,
                        });
                    }
                }
                Stage::Rough => match self.next_rough() {
                    Some(m) => return Some(m),
                    None => self.stage = Stage::Tail,
                },
                Stage::Tail => return self.next_tail(),
                Stage::Done => return None,
            }
        }
    }

    /// The next move of the tail, or `None` (the stage then `Done`).
    #[inline(always)]
    fn next_tail(&mut self) -> Option<Move> {
        let Some(leg) = self.tail.get(self.tail_next).filter(|_| self.tail_next < self.tail_len) else {
            self.stage = Stage::Done;
            return None;
        };
        self.tail_next += 1;
        let motion = match leg.kind {
            LegKind::Rapid => Motion::Rapid,
            LegKind::Feed => Motion::Feed,
            LegKind::Arc { centre, clockwise } => Motion::Arc {
                centre: self.centres.get(usize::from(centre)).copied().unwrap_or(leg.to),
                clockwise,
            },
        };
        let role: Role = leg.role.role();
        Some(Move { motion, to: leg.to, role, pass: None })
    }
}

impl FusedIterator for G75Moves {}

impl G75Moves {
    /// How many values this expansion has decided so far (up front, and
    /// for each layer reached) and how many of them the fast path left to
    /// the interval arithmetic (reading R-FASTPATH).
    ///
    /// ```
    /// use cycleref::engine::g75::expand_g75_exact;
    /// use cycleref::examples::G75_SEED;
    /// use cycleref::expand_g75;
    ///
    /// let mut fast = expand_g75(&G75_SEED)?;
    /// let moves: Vec<_> = fast.by_ref().collect();
    /// // The same moves with the fast path off.
    /// assert_eq!(moves, expand_g75_exact(&G75_SEED)?.collect::<Vec<_>>());
    /// let s = fast.fast_path_stats();
    /// assert!(s.values > 0);
    /// assert_eq!(s.fallbacks, 0);
    /// # Ok::<(), cycleref::CycleError>(())
    /// ```
    #[must_use]
    pub fn fast_path_stats(&self) -> FastPathStats {
        self.stats
    }
}
