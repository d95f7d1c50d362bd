//! The proof harnesses: one function per property, shared by Kani and the
//! tests.
//!
//! Every harness takes a [`Domain`] (the inputs it may choose) and an
//! engine (a function from a cycle to its moves). The Kani proofs in
//! `proofs/src/kani_proofs.rs` (compiled only under `cfg(kani)`) call them with bounded domains and the real
//! engine; the tests in `proofs/tests/harnesses.rs` call them through the
//! shim, exhaustively over small domains and by sampling over the full
//! documented ranges; `proofs/tests/mutants.rs` calls them with engines
//! broken on purpose and checks that each harness catches its mutant.

use cycleref::lead::{Lead, LeadWord};
use cycleref::{
    CycleError, DepthMode, Flank, G76Cycle, IncrementSystem, Infeed, InputUnit, Motion, Move, PassKind,
    Point, Role, RunOut, Units, XMode,
};

use crate::cover;
use crate::verify::{any_in, any_u128_in, assume, declare};

/// The inputs a harness may choose: inclusive ranges in least increments
/// (radius), counts, degrees, and small codes for the discrete choices.
/// A range with `lo == hi` fixes the input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Domain {
    /// Thread height k.
    pub height: (i64, i64),
    /// First depth Δd.
    pub first_depth: (i64, i64),
    /// Minimum cut Δdmin (also capped at k).
    pub min_cut: (i64, i64),
    /// Finishing allowance d, as a range capped at k.
    pub allowance: (i64, i64),
    /// Tool angle a, degrees.
    pub tool_angle: (i64, i64),
    /// Finishing passes m.
    pub finishing: (i64, i64),
    /// Infeed mode: 0 = D0, 1 = D1, 2 = D2 (G76 and G78 r = 2, 3, 4), 3 =
    /// centre, 4 = left flank, 5 = alternating flanks (G78 r = 0, 1 and the
    /// 980TDi's r = 3).
    pub infeed: (i64, i64),
    /// Depth mode (G78): 0 = equal steps, 1 = decreasing (G76's only).
    pub depth_mode: (i64, i64),
    /// Starts L.
    pub starts: (i64, i64),
    /// 0 = external, 1 = internal.
    pub internal: (i64, i64),
    /// 0 = cutting towards -Z, 1 = towards +Z.
    pub positive_z: (i64, i64),
    /// Taper i.
    pub taper: (i64, i64),
    /// |W|, the thread length along Z.
    pub length: (i64, i64),
    /// Run-out: 0 none, 1 J/K amounts, 2 chamfer r, 3 chamfer r with K.
    pub run_out_kind: (i64, i64),
    /// Run-out amounts J and K.
    pub run_out: (i64, i64),
    /// Chamfer r, tenths of the lead.
    pub chamfer: (i64, i64),
    /// Chamfer angle, degrees.
    pub chamfer_angle: (i64, i64),
    /// Units code: bit 0 IS-C, bit 1 inch, bit 2 radius X (0..=7).
    pub units: (i64, i64),
    /// Rough pass limit of the generated cycles.
    pub pass_limit: u32,
    /// Lead-in E (radius increments); 0 is none.
    pub lead_in: (i64, i64),
    /// Lead: 0 = F2, 1 = F0.01, 2 = I8 (threads per inch), 3 = I2540 (the
    /// smallest lead, 0.0004 in); F is mm or inch per revolution as the
    /// units say.
    pub lead: (i64, i64),
    /// [`no_panic`] only: the start X it may set, as an invalid word, to
    /// any value in `-wild_x..=wild_x` (beyond the coordinate range in
    /// [`Domain::FULL`]).
    pub wild_x: i64,
}

impl Domain {
    /// The whole documented range (for sampling, and for Kani's no-overflow
    /// proof): every length up to 999 999 999 increments.
    pub const FULL: Domain = Domain {
        height: (1, 999_999_999),
        first_depth: (1, 999_999_999),
        min_cut: (0, 999_999_999),
        allowance: (0, 999_999_999),
        tool_angle: (0, 99),
        finishing: (0, 99),
        infeed: (0, 5),
        depth_mode: (0, 1),
        starts: (1, 999),
        internal: (0, 1),
        positive_z: (0, 1),
        taper: (-999_999_999, 999_999_999),
        length: (1, 999_999_999),
        run_out_kind: (0, 3),
        run_out: (0, 999_999_999),
        chamfer: (0, 99),
        chamfer_angle: (1, 89),
        units: (0, 7),
        pass_limit: 2_000,
        lead_in: (0, 999_999_999),
        lead: (0, 3),
        wild_x: 2_000_000_000,
    };

    /// Sampling domain: the documented ranges for the depth words, with
    /// lengths chosen so that most cycles expand (pass limit 2000), G76's
    /// infeed modes and depths.
    pub const WIDE: Domain = Domain {
        finishing: (0, 5),
        infeed: (0, 2),
        depth_mode: (1, 1),
        starts: (1, 4),
        taper: (-300_000_000, 300_000_000),
        lead_in: (0, 1_000_000),
        ..Domain::FULL
    };

    /// The schedule's inputs, small enough to enumerate: k 1..=20, Δd 1..=20,
    /// Δdmin 0..=4, d 0..=k, all three infeed modes.
    pub const SCHEDULE: Domain = Domain {
        height: (1, 20),
        first_depth: (1, 20),
        min_cut: (0, 4),
        allowance: (0, 20),
        infeed: (0, 2),
        depth_mode: (1, 1),
        ..Domain::POINT
    };

    /// A small domain: fixed typical values (metric IS-B, diameter, external,
    /// towards -Z, straight, D0, one start, no run-out, a = 60), to be
    /// widened field by field by each harness.
    pub const POINT: Domain = Domain {
        height: (10, 10),
        first_depth: (4, 4),
        min_cut: (1, 1),
        allowance: (1, 1),
        tool_angle: (60, 60),
        finishing: (1, 1),
        infeed: (0, 0),
        depth_mode: (1, 1),
        starts: (1, 1),
        internal: (0, 0),
        positive_z: (0, 0),
        taper: (0, 0),
        length: (500, 500),
        run_out_kind: (0, 0),
        run_out: (1, 1),
        chamfer: (5, 5),
        chamfer_angle: (45, 45),
        units: (0, 0),
        pass_limit: 10_000,
        lead_in: (0, 0),
        lead: (0, 0),
        wild_x: 2,
    };
}

/// An engine under test: the moves of a cycle, or its alarm.
pub trait Engine {
    /// The moves.
    type Moves: Iterator<Item = Move>;
    /// Expands `c`.
    ///
    /// # Errors
    ///
    /// The cycle's alarm.
    fn expand(&self, c: &G76Cycle) -> Result<Self::Moves, CycleError>;
}

/// The fixed-point engine, `cycleref::engine::expand_g76`.
#[derive(Clone, Copy, Debug, Default)]
pub struct FixedPoint;

impl Engine for FixedPoint {
    type Moves = cycleref::engine::G76Moves;
    fn expand(&self, c: &G76Cycle) -> Result<Self::Moves, CycleError> {
        cycleref::engine::expand_g76(c)
    }
}

impl<F, I> Engine for F
where
    F: Fn(&G76Cycle) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    type Moves = I;
    fn expand(&self, c: &G76Cycle) -> Result<I, CycleError> {
        self(c)
    }
}

/// A plain G76 cycle for the tests to build theirs on: IS-B metric, radius
/// X, an external straight thread from X10 Z1 to X5 Z-20, F2, one start,
/// k 1.000, Δd 0.400, Δdmin 0.100, d 0.050, one finishing pass, 60°, D0
/// (the right flank), decreasing depths, no lead-in, no run-out, pass
/// limit 1 000. A test names the words it depends on and takes the others
/// from here: `G76Cycle { thread_height: 4, ..PLAIN_CYCLE }`.
pub const PLAIN_CYCLE: G76Cycle = G76Cycle {
    units: Units::IS_B_METRIC,
    x_mode: XMode::Radius,
    start: Point::new(10_000, 1_000),
    end: Point::new(5_000, -20_000),
    taper: 0,
    thread_height: 1_000,
    first_depth: 400,
    min_cut: 100,
    finishing_allowance: 50,
    finishing_passes: 1,
    tool_angle: 60,
    infeed: Infeed::RightFlank,
    depth_mode: DepthMode::Decreasing,
    lead_in: 0,
    starts: 1,
    lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
    run_out: RunOut::None,
    pass_limit: 1_000,
    readings: cycleref::CycleReadings::DEFAULT,
};

/// A cycle of the domain: an external or internal thread, either
/// direction, with A clear of the crest by one increment.
///
/// The depth words (k, Δd, Δdmin, d) are chosen first, in that order, so the
/// enumeration of a small domain walks the schedule's inputs fastest.
///
/// *Readings pinned.* Every cycle takes `CycleReadings::DEFAULT`: R-RUNOUT
/// clamped, R-XRUNOUT `refuse`, R-END `travel-i`, R-LONG displacement (no
/// R-LONG988 `table`), R-G78LEFT `mirror-form-centre`, R-G78CENTRE
/// `form-centre`, R-LEADIN `same-z`, R-INFEED `right-first`, R-NOROUGH
/// `none`, R-DEPTH `previous-plus-min`, R-STARTS `pass-major`. The
/// harnesses do not take the readings as inputs because several
/// properties are stated for these values and are false, by design, under
/// the others (each checked through the shim with an engine that swaps
/// the reading in): P1's depths strictly increasing from 0 fail under
/// R-NOROUGH `one-at-zero` (the pass at depth 0 with d = k cuts 0), its
/// "every rough cut is at least min(Δdmin, what remains)" under R-DEPTH
/// `formula` (its cuts after the first clamped level fall below Δdmin,
/// which is what tells it apart), and P3's "no rough pass after a
/// finishing pass" under R-STARTS `start-major` (each start begins again
/// at the first level); P5 measures every pass against
/// zc, the finishing Z under these values only (R-G78LEFT `mirror-b` and
/// R-G78CENTRE `under-b` move the finishing passes with the last rough
/// pass, R-FINISH); P6's
/// integer restatement (`crate::g76_exact`) restates R-LEADIN's two values
/// and the others at these values only. Each reading's other values are
/// held instead by the differential tests, which compare the engine with
/// the decimal reference under every combination of every reading
/// (`proofs/tests/engine_equals_spec.rs`,
/// `engine_equals_spec_under_every_reading`), and by the hand-worked tests
/// of `spec/tests/readings.rs`. A symbolic bit per reading would also
/// double Kani's paths through the schedule and the pass planning for
/// each reading.
pub fn any_cycle(d: &Domain) -> G76Cycle {
    let pick = |r: (i64, i64)| any_in(r.0, r.1);
    let count = |r: (i64, i64)| u32::try_from(any_in(r.0, r.1)).unwrap_or(0);
    let k = pick(d.height);
    let first_depth = pick(d.first_depth);
    let min_cut = any_in(d.min_cut.0.min(k), d.min_cut.1.min(k));
    let allowance = any_in(d.allowance.0.min(k), d.allowance.1.min(k));
    let finishing = count(d.finishing);
    let tool_angle = count(d.tool_angle);
    let infeed = match pick(d.infeed) {
        0 => Infeed::RightFlank,
        1 => Infeed::RightCentre,
        2 => Infeed::LeftRight,
        3 => Infeed::Centre,
        4 => Infeed::LeftFlank,
        _ => Infeed::Alternating,
    };
    let depth_mode = if pick(d.depth_mode) == 0 { DepthMode::Equal } else { DepthMode::Decreasing };
    let starts = count(d.starts);
    let internal = pick(d.internal) == 1;
    let positive_z = pick(d.positive_z) == 1;
    let taper = pick(d.taper);
    let length = pick(d.length);
    let run_out = match pick(d.run_out_kind) {
        0 => RunOut::None,
        1 => RunOut::Amounts { short: pick(d.run_out), long: pick(d.run_out) },
        2 => RunOut::Chamfer {
            tenths_of_lead: count(d.chamfer),
            angle_degrees: count(d.chamfer_angle),
            long: None,
        },
        _ => RunOut::Chamfer {
            tenths_of_lead: count(d.chamfer),
            angle_degrees: count(d.chamfer_angle),
            long: Some(pick(d.run_out)),
        },
    };
    let lead_in = pick(d.lead_in);
    let lead = match pick(d.lead) {
        0 => Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        1 => Lead { word: LeadWord::F, mantissa: 1, scale: 2 },
        2 => Lead { word: LeadWord::I, mantissa: 8, scale: 0 },
        _ => Lead { word: LeadWord::I, mantissa: 2540, scale: 0 },
    };
    let (units, x_mode) = units_of(pick(d.units));
    let xf = x_mode.factor();
    let s = if internal { -1 } else { 1 };
    let t = if positive_z { 1 } else { -1 };
    // D at X 150 000 000 increments (room for internal threads towards the
    // axis), A beyond the crest at both ends by one increment.
    let end = Point::new(150_000_000 * xf, 0);
    let c_x = end.x + xf * taper;
    let crest = if s > 0 { c_x.max(end.x) + xf * k } else { c_x.min(end.x) - xf * k };
    let start = Point::new(crest + s, end.z - t * length);
    G76Cycle {
        units,
        x_mode,
        start,
        end,
        taper,
        thread_height: k,
        first_depth,
        min_cut,
        finishing_allowance: allowance,
        finishing_passes: finishing,
        tool_angle,
        infeed,
        depth_mode,
        lead_in,
        starts,
        lead,
        run_out,
        pass_limit: d.pass_limit,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// A pass of a move stream, as [`Passes`] finds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PassView {
    /// Rough, finishing or single.
    pub kind: PassKind,
    /// The pass's number among its kind.
    pub number: u32,
    /// The thread start.
    pub start: u32,
    /// The infeed position.
    pub flank: Flank,
    /// The annotated depth.
    pub depth: i64,
    /// The annotated cut.
    pub cut: i64,
    /// The pass start Bn: where the pass's approach (and lead-in) end, or,
    /// when the pass has neither (an approach of no length is dropped,
    /// R-ZERO), where the tool stood when the pass began.
    pub bn: Point,
    /// Whether the pass has an approach move of its own.
    pub approached: bool,
}

/// The passes of a move stream, found by their annotation: a pass begins
/// with the first move whose `(kind, number, start)` differs from the
/// previous annotated move's, whatever its role, or with an approach or
/// lead-in that follows the current pass's cut (a pass repeated with its
/// annotation is two passes). (Finding passes by their
/// approach lost a pass whose approach has no length and is dropped: the
/// counterexample of issue 32, `proofs/tests/harnesses.rs`.) Streams: one
/// pass is held while its leading approach and lead-in are read, so a
/// harness keeps no `Vec` of moves or passes.
pub struct Passes<I> {
    moves: I,
    at: Point,
    open: Option<PassView>,
    leading: bool,
}

impl<I: Iterator<Item = Move>> Passes<I> {
    /// The passes of `moves`, a cycle that starts with the tool at `start`.
    pub fn new(moves: I, start: Point) -> Self {
        Passes { moves, at: start, open: None, leading: false }
    }
}

impl<I: Iterator<Item = Move>> Iterator for Passes<I> {
    type Item = PassView;

    fn next(&mut self) -> Option<PassView> {
        for m in self.moves.by_ref() {
            let before = self.at;
            self.at = m.to;
            let Some(p) = m.pass else { continue };
            // A new pass: another annotation, or an approach or lead-in
            // after the pass has cut (the same pass cut again).
            let leading_role = matches!(m.role, Role::Approach | Role::LeadIn);
            let same = (self.leading || !leading_role)
                && self
                    .open
                    .is_some_and(|o| (o.kind, o.number, o.start) == (p.kind, p.number, u32::from(p.start)));
            let mut done = None;
            if !same {
                done = self.open.take();
                self.open = Some(PassView {
                    kind: p.kind,
                    number: p.number,
                    start: u32::from(p.start),
                    flank: p.flank,
                    depth: p.depth,
                    cut: p.cut,
                    bn: before,
                    approached: false,
                });
                self.leading = true;
            }
            if let Some(open) = self.open.as_mut() {
                match m.role {
                    Role::Approach | Role::LeadIn if self.leading => {
                        open.bn = m.to;
                        open.approached |= m.role == Role::Approach;
                    }
                    _ => self.leading = false,
                }
            }
            if done.is_some() {
                return done;
            }
        }
        self.open.take()
    }
}

fn passes<I: Iterator<Item = Move>>(moves: I, c: &G76Cycle) -> Passes<I> {
    Passes::new(moves, c.start)
}

/// Whether the inclusive range `r` holds `v`: a cover that only a window
/// holding `v` can satisfy is written `cover!(cond || !window_has(..), ..)`.
#[must_use]
pub const fn window_has(r: (i64, i64), v: i64) -> bool {
    r.0 <= v && v <= r.1
}

fn expand_ok<E: Engine>(engine: &E, c: &G76Cycle) -> Option<E::Moves> {
    match engine.expand(c) {
        Ok(m) => Some(m),
        Err(_) => {
            assume(false);
            None
        }
    }
}

/// Property 1, depth monotonicity: rough depths strictly increase from
/// level to level in every infeed mode (the only pass that repeats a depth
/// is the left pass of a D2 level, right after that level's right pass and
/// with its cut); every rough cut is at least min(Δdmin, what remains to
/// k - d) and at least one increment; cuts by the √n law never grow by more
/// than the one increment that rounding can add (the exact law cuts
/// Δd(√n - √(n-1)) strictly decrease; rounding moves each depth by at most
/// ½).
pub fn depth_monotonicity<E: Engine>(d: &Domain, engine: &E) {
    declare(&[
        "three or more rough levels",
        "minimum cut in force",
        "a D2 left pass",
        "a rough pass whose approach is dropped",
    ]);
    let c = any_cycle(d);
    let Some(moves) = expand_ok(engine, &c) else { return };
    let min = c.min_cut.max(1);
    let last = c.thread_height - c.finishing_allowance;
    let mut previous = 0;
    let mut previous_cut = i64::MAX;
    let mut previous_flank = None;
    let mut levels = 0_u64;
    let mut d2_left = false;
    let mut dropped = false;
    for p in passes(moves, &c).filter(|p| p.kind == PassKind::Rough && p.start == 1) {
        if c.infeed == Infeed::LeftRight && p.flank == Flank::Left {
            let repeats = previous_flank == Some(Flank::Right) && levels > 0 && p.depth == previous;
            assert!(repeats, "a D2 left pass repeats its level's right pass");
            assert_eq!(p.cut, previous_cut, "a D2 left pass cuts what its right pass cut");
            previous_flank = Some(Flank::Left);
            d2_left = true;
            continue;
        }
        levels += 1;
        dropped |= !p.approached;
        assert!(p.depth > previous, "rough depths must strictly increase");
        assert_eq!(p.cut, p.depth - previous, "cut annotation");
        assert!(p.cut >= min.min(last - previous), "cut below min(Δdmin, remainder)");
        assert!(p.cut >= 1);
        // p.depth = round(Δd √levels), from its definition (2s - 1)² ≤ 4x <
        // (2s + 1)² (no square root: an independent restatement of the law).
        let x4 = 4 * u128::from(c.first_depth.unsigned_abs()).pow(2) * u128::from(levels);
        let s2 = 2 * u128::from(p.depth.unsigned_abs());
        let by_law = (s2 - 1).pow(2) <= x4 && x4 < (s2 + 1).pow(2);
        if by_law && p.depth < last {
            assert!(p.cut <= previous_cut.saturating_add(1), "a law cut grew by more than rounding");
        }
        previous_cut = p.cut;
        previous = p.depth;
        previous_flank = Some(p.flank);
    }
    // One call site per cover (Kani reports each): vacuous where the
    // window has no D2 (the harnesses split per infeed mode).
    cover!(d2_left || !window_has(d.infeed, 2), "a D2 left pass");
    // A pass whose approach has no length (R-ZERO), the blind spot of the
    // finder keyed on approaches (issue 32). Only with a lead-in: without
    // one the approach ends at Bn, inside the crest, and A lies beyond it.
    // In D0 and D2 the first pass starts on the right flank and no rough
    // pass of the Kani windows was seen to lose its approach (0 of 3·10^7
    // samples of each window, none at the edges), so a window of D0 or D2
    // alone does not require it either.
    let may_drop = d.lead_in.1 > 0 && (d.infeed.0 != d.infeed.1 || !matches!(d.infeed.0, 0 | 2));
    cover!(dropped || !may_drop, "a rough pass whose approach is dropped");
    cover!(levels >= 3, "three or more rough levels");
    cover!(c.min_cut > 1 && levels >= 2, "minimum cut in force");
}

/// Property 2, termination at k - d: the rough schedule ends with its last
/// depth exactly k - d (none when d = k), and the number of levels f obeys
/// the bound derived in docs/INTERPRETATIONS.md: (f - 1)·max(Δdmin, 1) <
/// k - d and 4(f - 1)Δd² < (2(k - d) + 1)².
pub fn termination<E: Engine>(d: &Domain, engine: &E) {
    declare(&["a single rough pass", "no rough pass (d = k)", "four or more levels"]);
    let c = any_cycle(d);
    let Some(moves) = expand_ok(engine, &c) else { return };
    let last = c.thread_height - c.finishing_allowance;
    // One depth per level: every rough pass of start 1 but the left passes
    // of D2 (no dedup, so that a repeated level counts).
    let mut f = 0_i64;
    let mut deepest = None;
    for p in passes(moves, &c) {
        if p.kind != PassKind::Rough
            || p.start != 1
            || c.infeed == Infeed::LeftRight && p.flank == Flank::Left
        {
            continue;
        }
        assert!(deepest.is_none_or(|v| p.depth > v), "a rough level repeats or goes back");
        deepest = Some(p.depth);
        f += 1;
    }
    if last == 0 {
        assert_eq!(f, 0, "d = k: nothing to rough");
    } else {
        assert_eq!(deepest, Some(last), "the last rough depth is k - d");
        let m = c.min_cut.max(1);
        assert!((f - 1) * m < last, "more levels than the minimum cut allows");
        let dd = i128::from(c.first_depth);
        let bound = i128::from(2 * last + 1);
        assert!(4 * i128::from(f - 1) * dd * dd < bound * bound, "more levels than the law allows");
    }
    cover!(f == 1 && last > 0, "a single rough pass");
    cover!(last == 0, "no rough pass (d = k)");
    cover!(f >= 4, "four or more levels");
}

/// Property 3, finishing: exactly m passes (per start) at depth k, the first
/// cutting d and the rest nothing, all from the last rough pass's Z.
pub fn finishing<E: Engine>(d: &Domain, engine: &E) {
    declare(&["several finishing passes with d > 0"]);
    let c = any_cycle(d);
    let Some(moves) = expand_ok(engine, &c) else { return };
    // Streamed: every rough pass comes before the first finishing pass, so
    // the last rough Z is known when the finishing passes begin.
    let mut last_rough_z = None;
    let mut finish = 0_u64;
    let xf = c.x_mode.factor();
    for p in passes(moves, &c) {
        match p.kind {
            PassKind::Rough => {
                assert_eq!(finish, 0, "a rough pass after a finishing pass");
                last_rough_z = Some(p.bn.z);
            }
            PassKind::Finish => {
                let number = finish / u64::from(c.starts) + 1;
                finish += 1;
                assert_eq!(
                    u64::from(p.number),
                    number,
                    "finishing passes numbered in order, every start in turn"
                );
                assert_eq!(p.depth, c.thread_height, "finishing at depth k");
                assert_eq!(
                    p.cut,
                    if number == 1 { c.finishing_allowance } else { 0 },
                    "finishing cut: d, then 0"
                );
                assert_eq!(p.bn.z, last_rough_z.unwrap_or(c.start.z), "finishing Z = last rough Z");
                assert_eq!(p.bn.x, c.end.x + xf * c.taper, "finishing at the thread start C");
            }
            PassKind::Single => panic!("G76 has no single pass"),
        }
    }
    assert_eq!(finish, u64::from(c.finishing_passes) * u64::from(c.starts), "m finishing passes per start");
    cover!(c.finishing_passes >= 2 && c.finishing_allowance > 0, "several finishing passes with d > 0");
}

/// Property 4, run-out direction: every run-out ends away from the work
/// (towards the side of A) and never beyond E; with Z long it ends on the
/// end line Z(D) displaced along X, with X long on X of the cut's end
/// displaced along Z.
pub fn run_out_direction<E: Engine>(d: &Domain, engine: &E) {
    declare(&[
        "external run-out, Z long",
        "internal run-out, Z long",
        "run-out with X long",
        "run-out on a taper",
        "a chamfered run-out",
        "an I lead",
    ]);
    let c = any_cycle(d);
    let Some(moves) = expand_ok(engine, &c) else { return };
    let xf = c.x_mode.factor();
    let s = if c.start.x > c.end.x + xf * c.taper { 1 } else { -1 };
    let t = (c.end.z - c.start.z).signum();
    let z_long = (c.end.z - c.start.z).abs() > c.taper.abs();
    let mut at = c.start;
    let mut seen = 0;
    for m in moves {
        if m.role == Role::RunOut {
            seen += 1;
            let p = m.pass.expect("annotated");
            let cut_end_x = c.end.x + s * xf * (c.thread_height - p.depth);
            assert!(matches!(m.motion, Motion::Thread { .. }), "the run-out is cut under synchronisation");
            if z_long {
                assert_eq!(m.to.z, c.end.z, "a Z-long run-out ends on the end line");
                assert!(s * (m.to.x - cut_end_x) > 0, "run-out towards the work");
                assert!(s * (c.start.x - m.to.x) >= 0, "run-out beyond E");
            } else {
                assert_eq!(m.to.x, cut_end_x, "an X-long run-out ends at X of the cut's end");
                assert!(t * (c.end.z - m.to.z) > 0, "run-out away from A's side");
                assert!(t * (m.to.z - c.start.z) >= 0, "run-out beyond A");
            }
            let _ = at;
        }
        at = m.to;
    }
    cover!(seen > 0 && z_long && s > 0, "external run-out, Z long");
    cover!(seen > 0 && z_long && s < 0, "internal run-out, Z long");
    cover!(seen > 0 && !z_long, "run-out with X long");
    cover!(seen > 0 && c.taper != 0, "run-out on a taper");
    cover!(seen > 0 && matches!(c.run_out, RunOut::Chamfer { .. }), "a chamfered run-out");
    cover!(seen > 0 && c.lead.word == LeadWord::I, "an I lead");
}

/// Property 5, no overcut: no pass's tool tip lies outside the final thread
/// form (the tool's V at depth k centred on the finishing Z) by more than
/// one increment: |shift - zc| <= round((k - Dn) tan(a/2)) + 1.
pub fn no_overcut<E: Engine>(d: &Domain, engine: &E) {
    declare(&["D2 with a flank angle", "D1 with a flank angle", "with a lead-in"]);
    let c = any_cycle(d);
    let Some(moves) = expand_ok(engine, &c) else { return };
    let t = (c.end.z - c.start.z).signum();
    // The reference's exact rounded product (its own tangent table, integer
    // arithmetic), not the engine's.
    let room_at = |depth: i64| cycleref_spec::tan::mul_tan_round(depth, c.tool_angle).unwrap_or(0);
    let zc = room_at(c.thread_height - c.finishing_allowance);
    let mut worst = 0;
    for p in passes(moves, &c) {
        let shift = t * (p.bn.z - c.start.z);
        let room = room_at(c.thread_height - p.depth);
        assert!((shift - zc).abs() <= room + 1, "a pass lies outside the final form");
        assert!(shift >= 0, "a pass starts behind A");
        worst = worst.max((shift - zc).abs() - room);
    }
    // Vacuous where the window has no D2 (no D1): the harnesses split per
    // infeed mode, and each cover is one call site under Kani.
    cover!(
        (c.infeed == Infeed::LeftRight || !window_has(d.infeed, 2)) && c.tool_angle > 0,
        "D2 with a flank angle"
    );
    cover!(
        (c.infeed == Infeed::RightCentre || !window_has(d.infeed, 1)) && c.tool_angle > 0,
        "D1 with a flank angle"
    );
    cover!(c.lead_in > 0, "with a lead-in");
}

/// Property 6, equivalence: the engine's moves (or alarm) equal the
/// reference model's.
///
/// The reference is `cycleref_spec::g76::expand`, in exact decimals
/// (`rust_decimal`). Under Kani the engine is compared with its restatement
/// in integers, [`crate::g76_exact::expand`] (the same steps on whole
/// increments, with the reference's integer kernels), so that Kani does not
/// execute `rust_decimal` symbolically; under `cargo test` the engine is
/// compared with both, and the restatement with the decimal reference, so
/// the restatement is itself held to the reference on every cycle run here.
pub fn equivalence<E: Engine>(d: &Domain, engine: &E) {
    declare(&["a cycle that expands"]);
    let c = any_cycle(d);
    let ours = engine.expand(&c).map(Iterator::collect::<Vec<_>>);
    let exact = crate::g76_exact::expand(&c);
    #[cfg(not(kani))]
    {
        let reference = cycleref_spec::g76::expand(&c);
        assert_eq!(ours, reference, "engine and reference differ for {c:?}");
        assert_eq!(exact, reference, "the integer restatement and the reference differ for {c:?}");
    }
    assert_eq!(ours, exact, "engine and reference differ (the reference in integers) for {c:?}");
    cover!(ours.is_ok(), "a cycle that expands");
}

/// Property 7, no overflow and no panic: for any cycle in the domain,
/// valid or not, the engine returns an error or moves, and every move is
/// inside the documented coordinate range. (Kani checks overflow and panics
/// on every path; here a panic fails the run.)
pub fn no_panic<E: Engine>(d: &Domain, engine: &E, max_moves: usize) {
    declare(&["a cycle that expands", "a cycle that is refused"]);
    let mut c = any_cycle(d);
    // Also invalid words: a negative or zero where the range tables forbid.
    match any_in(0, 5) {
        0 => c.thread_height = any_in(-5, 0),
        1 => c.min_cut = any_in(-5, -1),
        2 => c.starts = 0,
        3 => c.start.x = any_in(-d.wild_x, d.wild_x),
        _ => {}
    }
    match engine.expand(&c) {
        Ok(moves) => {
            for m in moves.take(max_moves) {
                let inside = m.to.x.abs() <= cycleref::units::MAX_LENGTH
                    && m.to.z.abs() <= cycleref::units::MAX_LENGTH;
                assert!(inside, "a move outside the coordinate range: {m:?} of {c:?}");
            }
            cover!(true, "a cycle that expands");
        }
        Err(_) => cover!(true, "a cycle that is refused"),
    }
}

/// Property 8, the contract of `round_sqrt` (its `proof_for_contract`
/// under Kani): the integer square root rounds to nearest exactly, s =
/// round(√x) satisfies (2s - 1)² <= 4x < (2s + 1)², on the domain `x in
/// lo..=hi` within the contract's range `x < 2^62` (under Kani
/// `windows::ISQRT_WINDOW`, that whole range). The contract's predicate
/// (`cycleref::engine::contracts::round_sqrt_ensures`) is asserted, and
/// the property restated here independently where it fits `u128`.
pub fn isqrt_rounds(lo: u128, hi: u128, sqrt: fn(u128) -> u128) {
    declare(&["rounded up", "rounded down"]);
    let x = any_u128_in(lo, hi);
    assume(cycleref::engine::contracts::sqrt_requires(x));
    let s = sqrt(x);
    assert!(cycleref::engine::contracts::round_sqrt_ensures(x, s), "round(√x): the contract of round_sqrt");
    if x < 1 << 124 {
        // (2s - 1)^2 <= 4x < (2s + 1)^2 in u128: 4x < 2^126, and s <= 2^62
        // once the contract holds.
        let four_x = 4 * x;
        let lower = (2 * s).saturating_sub(1);
        assert!(s == 0 || lower * lower <= four_x, "round(√x) too large");
        assert!(four_x < (2 * s + 1) * (2 * s + 1), "round(√x) too small");
    }
    cover!(x > 1 && s.checked_mul(s).is_none_or(|sq| sq > x), "rounded up");
    cover!(x > 1 && s.checked_mul(s).is_some_and(|sq| sq < x), "rounded down");
}

/// The units and X mode of a unit code: bit 0 IS-C, bit 1 inch, bit 2
/// radius X (0..=7), as every harness and test draws them.
#[must_use]
pub fn units_of(code: i64) -> (Units, XMode) {
    let units = Units {
        system: if code & 1 == 1 { IncrementSystem::IsC } else { IncrementSystem::IsB },
        unit: if code & 2 == 2 { InputUnit::Inch } else { InputUnit::Metric },
    };
    (units, if code & 4 == 4 { XMode::Radius } else { XMode::Diameter })
}

/// A G32 block of a small domain: start and end within `reach` increments
/// of the origin (any direction, straight, tapered, face), a run-out with
/// `|J|, K <= run_out`, IS-B/IS-C, mm/inch, diameter/radius. The readings
/// are pinned at their defaults (`CycleReadings::DEFAULT`, R-G32LONG
/// `tie-x`); [`g32_run_out`] restates the long axis under either value of
/// the tie, and `proofs/tests/g32.rs` checks `tie-z` against the reference.
pub fn any_g32(reach: i64, run_out: i64) -> cycleref::G32Block {
    use cycleref::{G32Block, G32RunOut, StartAngle};
    let (units, x_mode) = units_of(any_in(0, 7));
    let start = Point::new(any_in(-reach, reach), any_in(-reach, reach));
    let end = Point::new(any_in(-reach, reach), any_in(-reach, reach));
    let run_out = if any_in(0, 1) == 1 {
        G32RunOut::Amounts { short: any_in(-run_out, run_out), long: any_in(0, run_out) }
    } else {
        G32RunOut::None
    };
    G32Block {
        units,
        x_mode,
        start,
        end,
        lead: Lead { word: LeadWord::F, mantissa: 15, scale: 1 },
        run_out,
        start_angle: StartAngle::ZERO,
        sync: any_in(0, 1) == 1,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// Property 4 for G32: every run-out ends at the end's long-axis coordinate
/// displaced exactly J (with its sign) along the short axis, and starts
/// exactly K before the end along the long axis, in the cutting direction;
/// the cut and the run-out are thread moves and only the first may
/// synchronise.
pub fn g32_run_out<F, I>(reach: i64, run_out: i64, engine: &F)
where
    F: Fn(&cycleref::G32Block) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&["Z long, J outwards", "Z long, J inwards", "face thread with run-out", "pull-out only"]);
    use cycleref::G32RunOut;
    let b = any_g32(reach, run_out);
    // The reader never makes a run-out with J = 0 (all profiles: none).
    assume(!matches!(b.run_out, G32RunOut::Amounts { short: 0, .. }));
    let Ok(moves) = engine(&b) else {
        assume(false);
        return;
    };
    // Streamed (no `Vec` under Kani): the count, the first and the last end.
    let xf = b.x_mode.factor();
    let (dx, dz) = (b.end.x - b.start.x, b.end.z - b.start.z);
    // Reading R-G32LONG: the tie is Z under `tie-z`.
    let z_long = xf * dz.abs() > dx.abs() || (b.readings.g32_tie_z && xf * dz.abs() == dx.abs());
    let (mut count, mut first, mut last) = (0_usize, None, None);
    for m in moves {
        let Motion::Thread { sync, .. } = m.motion else { panic!("G32 moves are thread moves") };
        assert_eq!(sync, b.sync && count == 0, "only the first move may synchronise");
        first = first.or(Some(m.to));
        last = Some(m.to);
        count += 1;
    }
    match b.run_out {
        G32RunOut::None => {
            assert_eq!(count, 1);
            assert_eq!(first, Some(b.end));
        }
        G32RunOut::Amounts { short, long } => {
            let last = last.expect("a run-out");
            let run_start = if count == 2 { first.expect("a cut") } else { b.start };
            if z_long {
                assert_eq!(last, Point::new(b.end.x + xf * short, b.end.z), "run-out end: J along X");
                assert_eq!(run_start.z, b.end.z - dz.signum() * long, "run-out start: K before the end");
            } else {
                assert_eq!(last, Point::new(b.end.x, b.end.z + short), "run-out end: J along Z");
                assert_eq!(run_start.x, b.end.x - dx.signum() * xf * long, "run-out start: K before the end");
            }
            cover!(z_long && short > 0, "Z long, J outwards");
            cover!(z_long && short < 0, "Z long, J inwards");
            cover!(!z_long && dz == 0, "face thread with run-out");
            cover!(long == 0, "pull-out only");
        }
    }
}
