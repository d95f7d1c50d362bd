//! The fixed-point engine of LinuxCNC's G76 threading cycle: the moves of
//! the reference `cycleref_spec::linuxcnc::expand` (the authority), exactly,
//! without heap, floating point, `unsafe` or panics, streamed move by move.
//!
//! The cycle (readings R-LCNC-PASS, R-LCNC-EXACT, R-LCNC-TIE, R-LCNC-SYNC in
//! `docs/INTERPRETATIONS.md`): with the drive line X₀, σ = +1 external and
//! −1 internal, ξ = 2 in G7 and 1 in G8 and `t = tan Q` (Q negated towards
//! +Z), a pass at depth δ is "back" to `X₀ + σ(K − δ)` at `Z₀ − ζ` (`ζ =
//! (δ/ξ)·t`), "in" to `X₀ − σ(|I| + δ)`, "over" at the pitch to `Z + (K/ξ)·t
//! − ζ` and "out" back to `X₀ + σ(K − δ)`, with the taper moves of E and L;
//! rough passes at `δ_n = J·n^(1/R)` while `δ_n < K`, then `1 + H` passes
//! at K, then one rapid to the block's end point.
//!
//! # Exact rounding
//!
//! Every coordinate is the exact value rounded to the nearest increment,
//! ties away from zero, and `δ_n < K` is decided exactly, as in the
//! reference. The values are enclosed with the interval arithmetic of
//! [`crate::engine::real`]: `n^(1/R)` by [`power`] (an exact point when it
//! is an integer, as the reference's `Real::power` is exact then), `tan Q`
//! by [`tan`]. A decision is made at 128 fraction bits
//! ([`FAST`]), and only when that enclosure does not decide it, at 512
//! ([`SLOW`]) with reading R-G75TIE (an enclosure that still holds exactly
//! one boundary lies on it, [`Interval::round_tie`], [`Interval::sign_tie`]),
//! the reference's rule at its highest precision. The powers are computed
//! one limb wider (192 and 576 bits) and narrowed, so that the enclosures
//! are about as narrow as the reference's.
//!
//! Before either, the fast path of [`crate::engine::approx`] (reading
//! R-FASTPATH, issue 33): each value in 64-bit fixed point with a rigorous
//! error bound, rounded from there when no boundary lies within the bound
//! (nearly always: the 128- and 512-bit enclosures are computed only for a
//! pass with a value near a boundary, and then once for the whole pass).
//! [`expand_linuxcnc_exact`] is the same expansion without it, and
//! [`LinuxCncMoves::fast_path_stats`] counts its fallbacks.
//!
//! # Alarms before the first move
//!
//! [`expand_linuxcnc`] makes every check before the first move, in the
//! reference's order: [`LinuxCncG76::validate`]; the pass limit
//! ([`CycleError::TooManyPasses`] when `δ_(limit+1) < K`, reading R-LIMIT);
//! each rough pass's `δ_n < K` until a pass is not shallower; the
//! coordinates of the first rough pass and of the last, then the
//! full-depth pass's, so that a coordinate beyond the range table
//! ([`CycleError::OutOfRange`]) or an undecidable rounding
//! ([`CycleError::UndecidedRounding`], never seen) is refused up front.
//!
//! The first and the last rough pass stand for all of them (issue 33:
//! the coordinates of every pass were computed up front, and again when
//! the pass started). Every value of a pass is affine in its depth δ
//! (module documentation above), and `δ_1 < δ_2 < … < δ_last`: each
//! value of a pass lies between its values at the first and the last
//! pass, and its rounding, nondecreasing in the value, between theirs.
//! So when both are within the range table, so is every pass's; and the
//! reference refuses the same cycles (it computes every pass, and a
//! coordinate beyond the table is beyond it whichever pass it is in).
//! Rounding is exact (R-LCNC-EXACT) but for R-G75TIE, which takes a value
//! within 2^-512 of a boundary to lie on it: that keeps the roundings
//! nondecreasing too, as two passes' values are either equal (a
//! coefficient 0: the same exact value) or farther apart than that (δ
//! grows by at least `J·(n+1)^(1/R − 1)/R`, ≫ 2^-512, and t is 0 or at
//! least tan 0.00005°). An undecidable rounding needs an enclosure at 512
//! bits that holds two boundaries or overflows: none at the magnitudes
//! below. The iterator computes each rough pass's coordinates when the
//! pass starts (the full-depth pass's are kept); they are then within the
//! table, as above.
//!
//! # Magnitudes
//!
//! After `validate()`: X₀, Z₀, Z, I, J, K, E `< 2^30`, `|tan Q| ≤ tan
//! 89.9999° < 2^20`, and the pass limit keeps `n ≤ 2^32`, so `n^(1/R) ≤
//! 2^32` and `δ ≤ 2^62`: no interval exceeds `2^83`, far inside the
//! `2^127` of an [`Interval`]. Rounded values stay `i128` until the range
//! check. The taper pitch `P·√(ξ²E² + K²)/(ξE)` is computed exactly in
//! integers: `4A²S < 2^132` (A the pitch in 10⁻⁶, below `2^34`, S =
//! ξ²E² + K² below `2^63`) as a 256-bit product, its square root digit by
//! digit; the rounded pitch is below `10^19 < 2^64`.
//!
//! # Work and memory
//!
//! Up front: one power per rough pass and one for the limit check, on the
//! fast path (about 40 products of 64-bit words each, `ln n` read from a
//! table for `n < 256`), rarely at 192 bits and more rarely at 576, and
//! the coordinates of three passes; `tan Q` once on the fast path (from
//! its sine and cosine), and at 128 bits only once a value falls back.
//! Per move: O(1); a rough pass's start computes its power again and its
//! coordinates. A [`LinuxCncMoves`] is a
//! fixed-size value (the words with the fast path's `tan Q`, its 128-bit
//! enclosure once computed, the leads, the current pass's points and the
//! fast path's counts; the test `size_of_the_iterator` bounds it by 512
//! bytes).

use core::cmp::Ordering;
use core::iter::FusedIterator;

use crate::angle::StartAngle;
use crate::engine::approx::{self, Approx};
use crate::engine::real::{power, tan, Interval, Rounding, FAST, SLOW};
use crate::error::{CycleError, Field};
use crate::lead::{Lead, MAX_LEAD_SCALE};
use crate::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
use crate::moves::{Flank, Motion, Move, Pass, PassKind, Role};
use crate::units::{Length, Point, MAX_LENGTH};

/// Limbs at which the fast path computes a power (one more than [`FAST`]).
const FAST_POWER: usize = FAST + 1;

/// Limbs at which the slow path computes a power (one more than [`SLOW`]).
const SLOW_POWER: usize = SLOW + 1;

/// The depth of a pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Depth {
    /// Rough pass `n`: `J·n^(1/R)`.
    Rough(u64),
    /// K, the full depth.
    Full,
}

/// The words of the cycle that the passes' values are made of.
#[derive(Clone, Copy, Debug)]
struct Words {
    /// X₀, the drive line.
    x0: i64,
    /// Z₀, the Z before the block.
    z0: i64,
    /// Z of the block.
    z: i64,
    /// σ: +1 external, −1 internal.
    sigma: i64,
    /// |I|.
    i_abs: i64,
    /// J.
    j: i64,
    /// K.
    k: i64,
    /// ξ: 2 in G7, 1 in G8.
    xf: u64,
    /// R in ten-thousandths.
    degression: u32,
    /// |Q| in the angle unit of [`tan`] (0.00005°).
    tan_angle: u32,
    /// True when `t = −tan |Q|`.
    tan_negative: bool,
    /// The fast path (R-FASTPATH) is tried before the intervals.
    fast_path: bool,
    /// `t` on the fast path ([`approx::tan_of`] of the fast path's sine
    /// and cosine; unknown when the fast path is off).
    tan_quick: Approx,
    /// `Z + (K/ξ)·t` on the fast path, the same for every pass (computed
    /// once, as [`Words::quick_values`] would for each pass).
    z_over_quick: Approx,
}

/// Indices of the values of a pass.
const DEEPER: usize = 0; // δ − K
const X_BACK: usize = 1; // X₀ + σ(K − δ)
const X_CUT: usize = 2; // (X₀ − σ|I|) − σδ
const Z_START: usize = 3; // Z₀ − ζ
const Z_END: usize = 4; // Z + (K/ξ)·t − ζ
const RADIUS: usize = 5; // δ/ξ

impl Words {
    /// `t = ±tan |Q|` at the precision `N`.
    fn tan<const N: usize>(&self) -> Interval<N> {
        let t = tan::<N>(self.tan_angle);
        if self.tan_negative {
            t.neg()
        } else {
            t
        }
    }

    /// The values of a pass at depth `d` (indices [`DEEPER`] … [`RADIUS`]),
    /// with `t` the tangent at the same precision.
    ///
    /// Twin: `spec/src/linuxcnc.rs`, `expand` (the closure `pass`).
    fn values<const N: usize>(&self, d: &Interval<N>, t: &Interval<N>) -> [Interval<N>; 6] {
        let int = |v: i64| Interval::<N>::int(i128::from(v));
        let k = int(self.k);
        let s = self.sigma;
        let radius = d.div_int(self.xf);
        let zeta = radius.mul(t);
        [
            d.sub(&k),
            int(self.x0).add(&k.sub(d).mul_int(s)),
            int(self.x0 - s * self.i_abs).sub(&d.mul_int(s)),
            int(self.z0).sub(&zeta),
            int(self.z).add(&k.div_int(self.xf).mul(t)).sub(&zeta),
            radius,
        ]
    }

    /// `Z + (K/ξ)·t` on the fast path, the part of [`Z_END`] that is the
    /// same for every pass.
    fn z_over_quick(&self, t: &Approx) -> Approx {
        Approx::int(self.z).add(&Approx::int(self.k).div_int(self.xf).mul(t))
    }

    /// The values of a pass at depth `d` on the fast path (R-FASTPATH):
    /// the formulas of [`Words::values`], each with its error bound (`t`
    /// is `self.tan_quick`, and `Z + (K/ξ)·t` is `self.z_over_quick`).
    fn quick_values(&self, d: &Approx) -> [Approx; 6] {
        let k = Approx::int(self.k);
        let s = self.sigma;
        let radius = d.div_int(self.xf);
        let zeta = radius.mul(&self.tan_quick);
        [
            d.sub(&k),
            Approx::int(self.x0).add(&k.sub(d).mul_int(s)),
            Approx::int(self.x0 - s * self.i_abs).sub(&d.mul_int(s)),
            Approx::int(self.z0).sub(&zeta),
            self.z_over_quick.sub(&zeta),
            radius,
        ]
    }

    /// The depth on the fast path: `J·n^(1/R)` with its bound.
    fn depth_quick(&self, depth: Depth) -> Approx {
        match depth {
            Depth::Full => Approx::int(self.k),
            Depth::Rough(n) => approx::power(n, DEGRESSION_ONE, self.degression).mul_int(self.j),
        }
    }

    /// The sign of `δ − K` at `depth`, its count added to `stats`: on the
    /// fast path from the depth alone (the value [`Words::quick_values`]
    /// gives at [`DEEPER`]), else by the intervals as [`Values::sign`]
    /// decides it.
    fn deeper_sign(
        &self,
        depth: Depth,
        t: &mut Option<Interval<FAST>>,
        stats: &mut FastPathStats,
    ) -> Result<Ordering, CycleError> {
        let quick =
            if self.fast_path { self.depth_quick(depth).sub(&Approx::int(self.k)).sign() } else { None };
        stats.add(FastPathStats { values: 1, fallbacks: u64::from(quick.is_none()) });
        match quick {
            Some(o) => Ok(o),
            None => Values::new(self, t, depth).exact_sign(self, DEEPER),
        }
    }

    /// The depth at 128 fraction bits.
    fn depth_fast(&self, depth: Depth) -> Interval<FAST> {
        match depth {
            Depth::Full => Interval::int(i128::from(self.k)),
            Depth::Rough(n) => {
                let p = power::<FAST_POWER>(n, DEGRESSION_ONE, self.degression).at_precision::<FAST>();
                Interval::int(i128::from(self.j)).mul(&p)
            }
        }
    }

    /// The depth at 512 fraction bits.
    fn depth_slow(&self, depth: Depth) -> Interval<SLOW> {
        match depth {
            Depth::Full => Interval::int(i128::from(self.k)),
            Depth::Rough(n) => {
                let p = power::<SLOW_POWER>(n, DEGRESSION_ONE, self.degression).at_precision::<SLOW>();
                Interval::int(i128::from(self.j)).mul(&p)
            }
        }
    }
}

/// How often the fast path (R-FASTPATH) decided a value, and how often it
/// fell back to the interval arithmetic: for the tests and benchmarks that
/// measure the fallback rate ([`LinuxCncMoves::fast_path_stats`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FastPathStats {
    /// Values decided (each sign of `δ − K` and each rounded coordinate).
    pub values: u64,
    /// Of those, the values the fast path left to the intervals.
    pub fallbacks: u64,
}

impl FastPathStats {
    fn add(&mut self, o: FastPathStats) {
        self.values = self.values.saturating_add(o.values);
        self.fallbacks = self.fallbacks.saturating_add(o.fallbacks);
    }
}

/// The values of one pass: on the fast path (R-FASTPATH), at 128 bits
/// once a decision needs them, and at 512 once the 128 bits do not decide.
struct Values<'t> {
    depth: Depth,
    /// `t` at 128 bits, once computed (kept for the cycle's other passes).
    tan: &'t mut Option<Interval<FAST>>,
    /// The values with their bounds (unknown when the fast path is off).
    quick: [Approx; 6],
    fast: Option<[Interval<FAST>; 6]>,
    slow: Option<[Interval<SLOW>; 6]>,
    stats: FastPathStats,
}

impl<'t> Values<'t> {
    fn new(w: &Words, t: &'t mut Option<Interval<FAST>>, depth: Depth) -> Values<'t> {
        let quick = if w.fast_path { w.quick_values(&w.depth_quick(depth)) } else { [Approx::UNKNOWN; 6] };
        Values { depth, tan: t, quick, fast: None, slow: None, stats: FastPathStats::default() }
    }

    /// Value `i` at 512 bits (the whole pass's values computed once).
    fn slow(&mut self, w: &Words, i: usize) -> Interval<SLOW> {
        let depth = self.depth;
        let slow = self.slow.get_or_insert_with(|| w.values(&w.depth_slow(depth), &w.tan::<SLOW>()));
        slow.get(i).copied().unwrap_or_else(Interval::poison)
    }

    /// Value `i` at 128 bits (the whole pass's values computed once).
    fn fast(&mut self, w: &Words, i: usize) -> Interval<FAST> {
        let depth = self.depth;
        let tan = &mut *self.tan;
        let fast = self.fast.get_or_insert_with(|| {
            let t = *tan.get_or_insert_with(|| w.tan::<FAST>());
            w.values(&w.depth_fast(depth), &t)
        });
        fast.get(i).copied().unwrap_or_else(Interval::poison)
    }

    fn quick(&self, i: usize) -> Approx {
        self.quick.get(i).copied().unwrap_or(Approx::UNKNOWN)
    }

    /// Counts one value, decided on the fast path or not.
    fn count(&mut self, decided: bool) {
        self.stats.values = self.stats.values.saturating_add(1);
        self.stats.fallbacks = self.stats.fallbacks.saturating_add(u64::from(!decided));
    }

    /// The sign of value `i`: on the fast path, else at 128 bits, else at
    /// 512 with R-G75TIE (as [`Words::deeper_sign`] decides `δ − K`).
    #[cfg(test)]
    fn sign(&mut self, w: &Words, i: usize) -> Result<Ordering, CycleError> {
        let quick = self.quick(i).sign();
        self.count(quick.is_some());
        match quick {
            Some(o) => Ok(o),
            None => self.exact_sign(w, i),
        }
    }

    /// The sign of value `i` by the intervals alone (at 128 bits, else at
    /// 512 with R-G75TIE).
    fn exact_sign(&mut self, w: &Words, i: usize) -> Result<Ordering, CycleError> {
        if let Some(o) = self.fast(w, i).sign() {
            return Ok(o);
        }
        self.slow(w, i).sign_tie().ok_or(CycleError::UndecidedRounding)
    }

    /// `floor(±v + 1/2)` of value `i` (negated when `negate`): at 128 bits,
    /// else at 512 with R-G75TIE.
    fn nearest(&mut self, w: &Words, i: usize, negate: bool) -> Result<i128, CycleError> {
        let f = self.fast(w, i);
        let f = if negate { f.neg() } else { f };
        if let Some(v) = f.round(Rounding::Nearest) {
            return Ok(v);
        }
        let s = self.slow(w, i);
        let s = if negate { s.neg() } else { s };
        s.round_tie(Rounding::Nearest).ok_or(CycleError::UndecidedRounding)
    }

    /// Value `i` rounded to the nearest integer, ties away from zero (the
    /// sign decided first, then the nearest of the magnitude), within the
    /// range table.
    ///
    /// Twin: `spec/src/linuxcnc.rs`, `round_away`.
    fn round_away(&mut self, w: &Words, i: usize) -> Result<i64, CycleError> {
        let quick = self.quick(i).round_half_away();
        self.count(quick.is_some());
        let r = if let Some(v) = quick {
            Some(v)
        } else if self.exact_sign(w, i)? == Ordering::Less {
            self.nearest(w, i, true)?.checked_neg()
        } else {
            Some(self.nearest(w, i, false)?)
        };
        r.and_then(|v| i64::try_from(v).ok()).filter(|v| v.unsigned_abs() <= MAX_LENGTH.unsigned_abs()).ok_or(
            CycleError::OutOfRange {
                field: Field::PassCoordinate,
                value: Length { increments: 0, decimals: 0 },
            },
        )
    }
}

/// The points of the pass at `depth`, its values' counts added to `stats`.
fn pass_points(
    w: &Words,
    t: &mut Option<Interval<FAST>>,
    depth: Depth,
    stats: &mut FastPathStats,
) -> Result<Points, CycleError> {
    let mut v = Values::new(w, t, depth);
    let p = Points::of(&mut v, w);
    stats.add(v.stats);
    p
}

/// The rounded points of one pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Points {
    x_back: i64,
    x_cut: i64,
    /// `x_cut + σK`: where the taper moves start and end.
    x_rise: i64,
    z_start: i64,
    z_end: i64,
    /// δ/ξ rounded: the pass's depth as a radius.
    radius: i64,
}

impl Points {
    /// The points of a pass, in the reference's order of decisions.
    fn of(v: &mut Values, w: &Words) -> Result<Points, CycleError> {
        let x_back = v.round_away(w, X_BACK)?;
        let x_cut = v.round_away(w, X_CUT)?;
        // |x_cut|, K < 2^30: no overflow.
        let x_rise = x_cut + w.sigma * w.k;
        let z_start = v.round_away(w, Z_START)?;
        let z_end = v.round_away(w, Z_END)?;
        let radius = v.round_away(w, RADIUS)?;
        Ok(Points { x_back, x_cut, x_rise, z_start, z_end, radius })
    }
}

/// The moves of a LinuxCNC G76 cycle, in order: an [`Iterator`] of
/// constant size made by [`expand_linuxcnc`], which has made every check;
/// it cannot fail.
///
/// # Example
///
/// The passes of `G8 G0 X14 Z2` then `G76 P1.5 Z-20 I-1 J0.2 R1.5 K0.92
/// Q29.5 H1 E1 L3` (mm): 9 rough passes (`0.2·n^(2/3) < 0.92` for `n ≤
/// 9`), then the full-depth pass and one spring pass, 6 moves each (back,
/// the two entry taper moves, over, the exit taper, out), and the return.
///
/// ```
/// use cycleref::linuxcnc::LinuxCncG76;
/// use cycleref::{expand_linuxcnc, Lead, LeadWord, PassKind, Point, Units, IncrementSystem, InputUnit, XMode};
/// let c = LinuxCncG76 {
///     units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
///     x_mode: XMode::Radius,
///     start: Point::new(140_000, 20_000), end: Point::new(140_000, -200_000),
///     pitch: Lead { word: LeadWord::F, mantissa: 15, scale: 1 },
///     peak_offset: -10_000, initial_depth: 2_000, degression: 15_000,
///     full_depth: 9_200, compound_angle: 295_000, spring_passes: 1,
///     taper_distance: 10_000, entry_taper: true, exit_taper: true,
///     pass_limit: 1_000_000,
/// };
/// let moves: Vec<_> = expand_linuxcnc(&c)?.collect();
/// assert_eq!(moves.len(), 11 * 6 + 1);
/// let depths: Vec<_> = moves.iter().step_by(6).filter_map(|m| m.pass).map(|p| (p.kind, p.depth)).collect();
/// // Pass 1 at J = 0.2, pass 2 at 0.2·2^(2/3) = 0.31748…, the last two at K.
/// assert_eq!(depths[..2], [(PassKind::Rough, 2_000), (PassKind::Rough, 3_175)]);
/// assert_eq!(depths[9..], [(PassKind::Finish, 9_200), (PassKind::Finish, 9_200)]);
/// # Ok::<(), cycleref::CycleError>(())
/// ```
#[derive(Clone, Debug)]
pub struct LinuxCncMoves {
    words: Words,
    /// `t` at 128 bits, once a value needed it.
    tan: Option<Interval<FAST>>,
    /// The pitch P.
    pitch: Lead,
    /// The pitch of the taper moves (P without a taper).
    taper_lead: Lead,
    /// E, signed with the direction (negative towards +Z).
    taper: i64,
    /// An entry taper (E > 0, L bit 1).
    entry: bool,
    /// An exit taper (E > 0, L bit 2).
    exit: bool,
    flank: Flank,
    /// The block's end point (the last move's).
    end: Point,
    /// The number of rough passes.
    rough: u64,
    /// The number of full-depth passes, `1 + H`.
    full: u64,
    /// The points at full depth (used only when `full > 0`).
    full_points: Points,
    /// The current pass, 1-based (0 before the first); rough passes first.
    pass: u64,
    /// The current pass's points and its pass information.
    current: Option<(Points, Pass)>,
    /// The next move of the current pass, 0-based.
    step: u8,
    /// The radius depth of the previous pass (0 before the first).
    last_depth: i64,
    /// The final rapid is made.
    done: bool,
    /// The fast path's counts so far (the checks before the first move
    /// included).
    stats: FastPathStats,
}

/// The pitch of LinuxCNC's taper moves, `P · √(ξ²E² + K²) / (ξE)` with K as
/// a radius (interp_convert.cc l.5757-5758), rounded to the nearest 10⁻⁶
/// (ties away from zero; reading R-LCNC-SYNC); P itself without a taper (E
/// = 0), as in LinuxCNC.
///
/// Computed exactly in integers: with `A` = P in 10⁻⁶ (below `2^34` for a
/// lead within its range), `S = ξ²E² + K²` (below `2^63`) and `B = ξE`,
/// the pitch is `round(A·√S/B) = floor((⌊√(4A²S)⌋ + B)/(2B))`, `4A²S <
/// 2^132` held in 256 bits and its square root taken digit by digit; the
/// result is below `10^19`.
///
/// Twin: `spec/src/linuxcnc.rs`, `taper_pitch`.
///
/// # Errors
///
/// [`LinuxCncG76::validate`] (the bounds above hold for a valid cycle).
///
/// # Example
///
/// P1.5, E1, K0.92 (G8, mm): `1.5·√(1 + 0.92²) = 2.0382345…`, as rs274
/// prints it:
///
/// ```
/// use cycleref::engine::linuxcnc::taper_pitch;
/// use cycleref::linuxcnc::LinuxCncG76;
/// use cycleref::{Lead, LeadWord, Point, Units, IncrementSystem, InputUnit, XMode};
/// let c = LinuxCncG76 {
///     units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
///     x_mode: XMode::Radius,
///     start: Point::new(140_000, 20_000), end: Point::new(140_000, -200_000),
///     pitch: Lead { word: LeadWord::F, mantissa: 15, scale: 1 },
///     peak_offset: -10_000, initial_depth: 2_000, degression: 15_000,
///     full_depth: 9_200, compound_angle: 295_000, spring_passes: 1,
///     taper_distance: 10_000, entry_taper: true, exit_taper: true,
///     pass_limit: 1_000_000,
/// };
/// assert_eq!(taper_pitch(&c)?, Lead { word: LeadWord::F, mantissa: 2_038_235, scale: 6 });
/// # Ok::<(), cycleref::CycleError>(())
/// ```
pub fn taper_pitch(c: &LinuxCncG76) -> Result<Lead, CycleError> {
    c.validate()?;
    taper_pitch_valid(c).ok_or(CycleError::LeadOutOfRange)
}

/// [`taper_pitch`] of a validated cycle; `None` (unreachable after
/// `validate()`) when a bound of its documentation does not hold.
fn taper_pitch_valid(c: &LinuxCncG76) -> Option<Lead> {
    if c.taper_distance <= 0 {
        return Some(c.pitch);
    }
    let xf = u128::from(c.x_mode.factor().unsigned_abs());
    let e = u128::from(c.taper_distance.unsigned_abs());
    let k = u128::from(c.full_depth.unsigned_abs());
    let s = xf.checked_mul(e)?.checked_pow(2)?.checked_add(k.checked_pow(2)?)?;
    let scale = MAX_LEAD_SCALE;
    let a =
        u128::from(c.pitch.mantissa).checked_mul(10_u128.checked_pow(scale - c.pitch.scale.min(scale))?)?;
    let b = xf.checked_mul(e)?;
    let (hi, lo) = mul_wide(a.checked_mul(a)?.checked_mul(4)?, s);
    let root = isqrt_wide(hi, lo)?;
    let v = root.checked_add(b)? / b.checked_mul(2)?;
    // The word of the pitch (K, as LinuxCNC writes a G33's).
    Some(Lead { word: c.pitch.word, mantissa: u64::try_from(v).unwrap_or(u64::MAX), scale })
}

/// The full product `x·y` of two `u128` as (high, low) halves.
pub(crate) const fn mul_wide(x: u128, y: u128) -> (u128, u128) {
    const M: u128 = u64::MAX as u128;
    let (x1, x0) = (x >> 64, x & M);
    let (y1, y0) = (y >> 64, y & M);
    // Each partial product is below 2^128; mid below 3·2^64.
    let (ll, lh, hl, hh) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    let mid = (ll >> 64) + (lh & M) + (hl & M);
    let lo = (ll & M) | (mid << 64);
    let hi = hh + (lh >> 64) + (hl >> 64) + (mid >> 64);
    (hi, lo)
}

/// `⌊√(hi·2^128 + lo)⌋`, digit by digit (two bits at a time, at most 128
/// steps: from the highest pair of bits that is not zero),
/// for `hi < 2^120`: the root stays below `2^124` and the remainder, at
/// most twice the root, below `2^125`, so nothing overflows; `None` for a
/// larger `hi`.
fn isqrt_wide(hi: u128, lo: u128) -> Option<u128> {
    if hi >> 120 != 0 {
        return None;
    }
    // The pairs above the highest that is not zero leave the root and the
    // remainder 0: the digits start at that pair.
    let top = if hi != 0 { 255 - hi.leading_zeros() } else { 127_u32.saturating_sub(lo.leading_zeros()) };
    let (mut root, mut rem) = (0_u128, 0_u128);
    let mut loops = crate::loop_counters::count!(LCNC_ISQRT);
    for i in (0..=top / 2).rev() {
        loops.tick();
        let pair = if i >= 64 { (hi >> (2 * (i - 64))) & 3 } else { (lo >> (2 * i)) & 3 };
        // Invariant: rem = prefix − root² ≤ 2·root.
        rem = (rem << 2) | pair;
        let trial = (root << 2) | 1;
        root <<= 1;
        if rem >= trial {
            rem -= trial;
            root |= 1;
        }
    }
    Some(root)
}

/// Expands a LinuxCNC G76 cycle: checks it completely, then streams its
/// moves.
///
/// The result equals `cycleref_spec::linuxcnc::expand(cycle)` exactly: the
/// same error, or an iterator of the same moves in the same order (module
/// documentation).
///
/// # Errors
///
/// In the reference's order: [`LinuxCncG76::validate`];
/// [`CycleError::TooManyPasses`] when more than the cycle's `pass_limit`
/// rough passes would be cut; [`CycleError::OutOfRange`] for a pass
/// coordinate beyond the range table; [`CycleError::UndecidedRounding`]
/// (never seen: R-G75TIE decides a value that 512 fraction bits cannot
/// tell from a boundary).
///
/// # Example
///
/// `G8 G0 X10 Z1` then `G76 P1 Z-10 I-0.5 J0.1 K0.3 R1 Q0 H0` (mm): depths
/// 0.1 and 0.2, then one pass at K = 0.3, four moves each, and the return:
///
/// ```
/// use cycleref::linuxcnc::LinuxCncG76;
/// use cycleref::{expand_linuxcnc, Lead, LeadWord, Point, Role, Units, IncrementSystem, InputUnit, XMode};
/// let c = LinuxCncG76 {
///     units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
///     x_mode: XMode::Radius,
///     start: Point::new(100_000, 10_000),
///     end: Point::new(100_000, -100_000),
///     pitch: Lead { word: LeadWord::F, mantissa: 1, scale: 0 },
///     peak_offset: -5_000, initial_depth: 1_000, degression: 10_000,
///     full_depth: 3_000, compound_angle: 0, spring_passes: 0,
///     taper_distance: 0, entry_taper: false, exit_taper: false,
///     pass_limit: 1_000_000,
/// };
/// let moves: Vec<_> = expand_linuxcnc(&c)?.map(|m| (m.role, m.to.x, m.to.z)).collect();
/// assert_eq!(moves.len(), 3 * 4 + 1);
/// assert_eq!(moves[..4], [
///     (Role::Approach, 102_000, 10_000), // back: X0 + (K − 0.1)
///     (Role::Approach, 94_000, 10_000),  // in: X0 − (0.5 + 0.1)
///     (Role::Cut, 94_000, -100_000),     // over
///     (Role::Retract, 102_000, -100_000), // out
/// ]);
/// assert_eq!(moves[12], (Role::Return, 100_000, -100_000));
/// # Ok::<(), cycleref::CycleError>(())
/// ```
///
/// Twin: `spec/src/linuxcnc.rs`, `expand`.
pub fn expand_linuxcnc(c: &LinuxCncG76) -> Result<LinuxCncMoves, CycleError> {
    expand(c, true)
}

/// [`expand_linuxcnc`] with the fast path off: every value decided by the
/// interval arithmetic alone, as before issue 33. The same result by
/// construction (reading R-FASTPATH); kept for the tests and benchmarks
/// that compare the two paths.
///
/// # Errors
///
/// Those of [`expand_linuxcnc`].
pub fn expand_linuxcnc_exact(c: &LinuxCncG76) -> Result<LinuxCncMoves, CycleError> {
    expand(c, false)
}

/// [`expand_linuxcnc`], the fast path on or off.
fn expand(c: &LinuxCncG76, fast_path: bool) -> Result<LinuxCncMoves, CycleError> {
    c.validate()?;
    let towards_plus = c.end.z > c.start.z;
    // l.5740-5742: Q negated for a thread towards +Z.
    let q = if towards_plus { -c.compound_angle } else { c.compound_angle };
    let words = Words {
        x0: c.start.x,
        z0: c.start.z,
        z: c.end.z,
        sigma: c.sigma(),
        i_abs: c.peak_offset.abs(),
        j: c.initial_depth,
        k: c.full_depth,
        xf: c.x_mode.factor().unsigned_abs(),
        degression: c.degression,
        // |Q| < 90° (validate): below 1 800 000 units of 0.00005°.
        tan_angle: q.unsigned_abs() * 2,
        tan_negative: q < 0,
        fast_path,
        tan_quick: Approx::UNKNOWN,
        z_over_quick: Approx::UNKNOWN,
    };
    let mut words = words;
    if fast_path {
        // t = ±tan |Q| from the fast path's sine and cosine of |Q|.
        let (sin, cos) = approx::sin_cos(words.tan_angle);
        let t = approx::tan_of(words.tan_angle, &sin, &cos);
        words.tan_quick = if words.tan_negative { t.neg() } else { t };
        words.z_over_quick = words.z_over_quick(&words.tan_quick);
    }
    let mut t = None;
    // Reading R-LIMIT for LinuxCNC: refuse before a move when pass limit + 1
    // would still be shallower than K.
    let limit = u64::from(c.pass_limit);
    let mut stats = FastPathStats::default();
    let beyond = words.deeper_sign(Depth::Rough(limit + 1), &mut t, &mut stats)?;
    if beyond == Ordering::Less {
        return Err(CycleError::TooManyPasses { passes: limit, exact: false, limit: c.pass_limit });
    }
    // The rough passes, as the reference finds them (l.5775-5790): each
    // pass's `δ_n < K`, until a pass is not shallower than K; the
    // coordinates of the first pass and of the last (module
    // documentation: those of every pass lie between them).
    let mut n = 1_u64;
    {
        let mut loops = crate::loop_counters::count!(LCNC_PASSES);
        // δ_(limit+1) ≥ K was decided above by the same computation, so
        // the loop ends by n = limit + 1; the bound is a safeguard.
        while n <= limit + 1 {
            loops.tick();
            if words.deeper_sign(Depth::Rough(n), &mut t, &mut stats)? != Ordering::Less {
                break;
            }
            if n == 1 {
                pass_points(&words, &mut t, Depth::Rough(1), &mut stats)?;
            }
            n += 1;
        }
    }
    if n > 2 {
        pass_points(&words, &mut t, Depth::Rough(n - 1), &mut stats)?;
    }
    let full = u64::try_from(i64::from(c.spring_passes) + 1).unwrap_or(0);
    // Reading R-BUDGET: the rough passes and the 1 + H at full depth
    // within the pass limit (H up to 2^31 would otherwise be unbounded).
    let pass_paths = (n - 1).saturating_add(full);
    if pass_paths > limit {
        return Err(CycleError::TooMuchWork { pass_paths, limit: c.pass_limit });
    }
    let full_points = if full > 0 {
        pass_points(&words, &mut t, Depth::Full, &mut stats)?
    } else {
        Points { x_back: 0, x_cut: 0, x_rise: 0, z_start: 0, z_end: 0, radius: 0 }
    };
    let tapered = c.taper_distance > 0;
    let taper_lead = taper_pitch_valid(c).ok_or(CycleError::LeadOutOfRange)?;
    let flank = match c.compound_angle.cmp(&0) {
        Ordering::Equal => Flank::Centre,
        Ordering::Greater => Flank::Right,
        Ordering::Less => Flank::Left,
    };
    Ok(LinuxCncMoves {
        words,
        tan: t,
        pitch: c.pitch,
        taper_lead,
        // l.5760: the taper distance changes sign with the direction.
        taper: if towards_plus { -c.taper_distance } else { c.taper_distance },
        entry: tapered && c.entry_taper,
        exit: tapered && c.exit_taper,
        flank,
        end: c.end,
        rough: n - 1,
        full,
        full_points,
        pass: 0,
        current: None,
        step: 0,
        last_depth: 0,
        done: false,
        stats,
    })
}

impl LinuxCncMoves {
    /// How many values the fast path (reading R-FASTPATH) decided so far,
    /// and how many it left to the interval arithmetic: the checks made by
    /// [`expand_linuxcnc`] and the passes started since.
    #[must_use]
    pub const fn fast_path_stats(&self) -> FastPathStats {
        self.stats
    }

    /// Move `step` (0-based) of the pass with points `p`, if the pass has
    /// that many: back, in (or the entry taper's two moves), over (to the
    /// exit taper's start, then its move), out.
    ///
    /// Twin: `spec/src/linuxcnc.rs`, `expand` (the closure `pass`).
    fn pass_move(&self, p: &Points, info: Pass, step: u8) -> Option<Move> {
        let thread = |lead, sync| Motion::Thread { lead, start_angle: StartAngle::ZERO, sync };
        let over_z = if self.exit { p.z_end + self.taper } else { p.z_end };
        // Back (0), in or the entry taper's two moves, then over (at
        // `over`), the exit taper's move (when there is one) and out.
        let over = if self.entry { 3 } else { 2 };
        let (motion, to, role) = match step {
            0 => (Motion::Rapid, Point::new(p.x_back, p.z_start), Role::Approach),
            1 if self.entry => (thread(self.taper_lead, true), Point::new(p.x_rise, p.z_start), Role::LeadIn),
            2 if self.entry => {
                (thread(self.taper_lead, false), Point::new(p.x_cut, p.z_start - self.taper), Role::LeadIn)
            }
            1 => (Motion::Rapid, Point::new(p.x_cut, p.z_start), Role::Approach),
            s if s == over => (thread(self.pitch, !self.entry), Point::new(p.x_cut, over_z), Role::Cut),
            s if s == over + 1 && self.exit => {
                (thread(self.taper_lead, false), Point::new(p.x_rise, p.z_end), Role::RunOut)
            }
            s if s == over + 1 + u8::from(self.exit) => {
                (Motion::Rapid, Point::new(p.x_back, p.z_end), Role::Retract)
            }
            _ => return None,
        };
        Some(Move { motion, to, role, pass: Some(info) })
    }

    /// Starts pass `number` (1-based, rough passes first); `None` after the
    /// last pass.
    fn start_pass(&mut self, number: u64) -> Option<(Points, Pass)> {
        let (points, kind, count) = if number <= self.rough {
            let mut v = Values::new(&self.words, &mut self.tan, Depth::Rough(number));
            // Computed without error in expand_linuxcnc (the same
            // computation): the `?` is unreachable.
            let points = Points::of(&mut v, &self.words).ok()?;
            self.stats.add(v.stats);
            (points, PassKind::Rough, number)
        } else if number - self.rough <= self.full {
            (self.full_points, PassKind::Finish, number - self.rough)
        } else {
            return None;
        };
        let info = Pass {
            kind,
            number: u32::try_from(count).unwrap_or(u32::MAX),
            start: 1,
            depth: points.radius,
            cut: points.radius - self.last_depth,
            flank: self.flank,
        };
        self.last_depth = points.radius;
        Some((points, info))
    }
}

impl Iterator for LinuxCncMoves {
    type Item = Move;

    fn next(&mut self) -> Option<Move> {
        let mut loops = crate::loop_counters::count!(LCNC_NEXT);
        // At most two rounds: the current pass's next move, or the next
        // pass's first (every pass has at least four moves).
        while !self.done {
            loops.tick();
            if let Some((p, info)) = self.current {
                if let Some(m) = self.pass_move(&p, info, self.step) {
                    self.step = self.step.saturating_add(1);
                    return Some(m);
                }
            }
            let next = self.pass.saturating_add(1);
            self.pass = next;
            self.step = 0;
            self.current = self.start_pass(next);
            if self.current.is_none() {
                // l.5791: to the block's end point, even of zero length.
                self.done = true;
                return Some(Move { motion: Motion::Rapid, to: self.end, role: Role::Return, pass: None });
            }
        }
        None
    }
}

impl FusedIterator for LinuxCncMoves {}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::units::XMode;

    fn cycle() -> LinuxCncG76 {
        crate::examples::LINUXCNC_TAPER
    }

    #[test]
    fn size_of_the_iterator() {
        let size = core::mem::size_of::<LinuxCncMoves>();
        std::println!("size_of::<LinuxCncMoves>() = {size}");
        assert!(size <= 512, "LinuxCncMoves is {size} bytes");
    }

    #[test]
    fn wide_square_root() {
        for x in [0_u128, 1, 2, 3, 4, 15, 16, 17, u128::from(u64::MAX), u128::MAX] {
            let r = isqrt_wide(0, x).unwrap();
            // r² ≤ x < (r + 1)², checked without overflow (isqrt_floor's
            // contract covers x < 2^62 only).
            assert!(crate::engine::contracts::isqrt_floor_ensures(x, r), "{x}");
        }
        // (2^66 + 5)² = 2^132 + 10·2^66 + 25, and one less.
        let r = (1_u128 << 66) + 5;
        let (hi, lo) = mul_wide(r, r);
        assert_eq!((hi, lo), (16, (10_u128 << 66) + 25));
        assert_eq!(isqrt_wide(hi, lo), Some(r));
        assert_eq!(isqrt_wide(hi, lo - 1), Some(r - 1));
        assert_eq!(isqrt_wide(1 << 120, 0), None);
        let (hi, lo) = mul_wide(u128::MAX, u128::MAX);
        assert_eq!((hi, lo), (u128::MAX - 1, 1));
        // r² ≤ x < (r + 1)² over values of every length (the digits start
        // at the highest pair that is not zero).
        let mut state = 0x9e37_79b9_7f4a_7c15_u128;
        for bits in 0..248_u32 {
            state = state.wrapping_mul(0x2545_f491_4f6c_dd1d).wrapping_add(0x1405_7b7e_f767_814f);
            let (hi, lo) = if bits >= 128 {
                ((state >> 1) >> (255 - bits), state)
            } else {
                (0, (state | 1) >> (127 - bits))
            };
            let r = isqrt_wide(hi, lo).unwrap();
            let le = |a: (u128, u128), b: (u128, u128)| a.0 < b.0 || (a.0 == b.0 && a.1 <= b.1);
            assert!(le(mul_wide(r, r), (hi, lo)), "{bits}");
            assert!(!le(mul_wide(r + 1, r + 1), (hi, lo)), "{bits}");
        }
    }

    #[test]
    fn taper_pitch_at_the_range_tables_ends() {
        let mut c = cycle();
        // The largest pitch over the shortest taper and the deepest thread:
        // 9999·√(1 + 999 999 999²) ≈ 9.999e12 mm, still a u64 in 10⁻⁶.
        c.pitch = Lead { word: crate::lead::LeadWord::K, mantissa: 9999, scale: 0 };
        c.taper_distance = 1;
        c.initial_depth = 1;
        c.full_depth = MAX_LENGTH;
        c.x_mode = XMode::Diameter;
        let p = taper_pitch(&c).unwrap();
        // ξ = 2: 9999·√(4 + K²)/2, K = 999 999 999 (in 10⁻⁶; Python's
        // math.isqrt on the same formula).
        assert_eq!(p.mantissa, 4_999_499_995_000_500_010);
        c.x_mode = XMode::Radius;
        // ξ = 1: 9999·√(1 + K²), the largest of all.
        assert_eq!(taper_pitch(&c).unwrap().mantissa, 9_998_999_990_001_000_005);
        c.taper_distance = MAX_LENGTH;
        c.full_depth = MAX_LENGTH;
        // 9999·√2 = 14140.721410…
        assert_eq!(taper_pitch(&c).unwrap().mantissa, 14_140_721_410);
        c.taper_distance = 0;
        assert_eq!(taper_pitch(&c).unwrap(), c.pitch);
    }

    /// The 512-bit path with R-G75TIE gives the points the 128-bit path
    /// gives: every fast enclosure widened by one unit on each side (so
    /// that none decides) leaves the decisions to the slow values.
    #[test]
    fn slow_path_gives_the_same_points() {
        use crate::engine::real::Fixed;
        let one = Fixed::<FAST>::from_int(1);
        let widen = |v: &Interval<FAST>| {
            Interval::new(v.lower().checked_sub(&one).unwrap(), v.upper().checked_add(&one).unwrap())
        };
        let mut c = cycle();
        for variant in 0..4 {
            c.peak_offset = if variant % 2 == 0 { -10_000 } else { 10_000 };
            c.x_mode = if variant < 2 { XMode::Radius } else { XMode::Diameter };
            c.end.z = if variant == 3 { 300_000 } else { -200_000 };
            let mut m = expand_linuxcnc_exact(&c).unwrap();
            let w = m.words;
            for depth in [Depth::Rough(1), Depth::Rough(2), Depth::Rough(7), Depth::Full] {
                let normal = Points::of(&mut Values::new(&w, &mut m.tan, depth), &w).unwrap();
                let mut v = Values::new(&w, &mut m.tan, depth);
                v.fast(&w, 0);
                for f in v.fast.iter_mut().flatten() {
                    *f = widen(f);
                }
                assert_eq!(v.fast(&w, X_BACK).round(Rounding::Nearest), None);
                let slow = Points::of(&mut v, &w).unwrap();
                assert!(v.slow.is_some());
                assert_eq!(slow, normal, "{variant} {depth:?}");
            }
        }
        // An exact value on a boundary: the sign of J·8^(2/3) − 4J at 512
        // bits is 0 whether the power is held exact or not.
        c.initial_depth = 1_000;
        c.full_depth = 4_000;
        let mut m = expand_linuxcnc_exact(&c).unwrap();
        let mut v = Values::new(&m.words, &mut m.tan, Depth::Rough(8));
        assert_eq!(v.sign(&m.words, DEEPER), Ok(Ordering::Equal));
        let fast = v.fast.as_mut().unwrap();
        fast[DEEPER] = widen(&fast[DEEPER]);
        assert_eq!(v.sign(&m.words, DEEPER), Ok(Ordering::Equal));
        // On the fast path, J·8^(2/3) − 4J is enclosed, not exact: left to
        // the intervals (a tie of R-LCNC-TIE).
        let mut m = expand_linuxcnc(&c).unwrap();
        let mut v = Values::new(&m.words, &mut m.tan, Depth::Rough(8));
        assert_eq!(v.sign(&m.words, DEEPER), Ok(Ordering::Equal));
        assert_eq!(v.stats, FastPathStats { values: 1, fallbacks: 1 });
    }

    /// Every rough pass's coordinates lie between the first rough pass's
    /// and the last's (what the checks before the first move rely on),
    /// in both X modes, both directions, external and internal, with and
    /// without a compound angle, on the fast path and off it.
    #[test]
    fn first_and_last_rough_passes_bound_the_others() {
        let mut c = cycle();
        c.degression = 12_345;
        c.initial_depth = 500;
        for variant in 0..16 {
            c.peak_offset = if variant % 2 == 0 { -10_000 } else { 10_000 };
            c.x_mode = if variant & 2 == 0 { XMode::Radius } else { XMode::Diameter };
            c.end.z = if variant & 4 == 0 { -200_000 } else { 300_000 };
            c.compound_angle = if variant & 8 == 0 { 295_000 } else { 0 };
            for fast in [true, false] {
                let mut m = if fast { expand_linuxcnc(&c) } else { expand_linuxcnc_exact(&c) }.unwrap();
                let w = m.words;
                let points = |n, t: &mut Option<Interval<FAST>>| {
                    let p = Points::of(&mut Values::new(&w, t, Depth::Rough(n)), &w).unwrap();
                    [p.x_back, p.x_cut, p.x_rise, p.z_start, p.z_end, p.radius]
                };
                assert!(m.rough > 2, "{variant}");
                let (first, last) = (points(1, &mut m.tan), points(m.rough, &mut m.tan));
                for n in 2..m.rough {
                    let p = points(n, &mut m.tan);
                    for i in 0..6 {
                        let (lo, hi) = (first[i].min(last[i]), first[i].max(last[i]));
                        assert!((lo..=hi).contains(&p[i]), "{variant} {fast} pass {n} value {i}");
                    }
                }
            }
        }
    }

    #[test]
    fn moves_of_a_taper_pass() {
        let moves: std::vec::Vec<Move> = expand_linuxcnc(&cycle()).unwrap().collect();
        // 9 rough passes, 2 at full depth, 6 moves each, and the return.
        assert_eq!(moves.len(), 11 * 6 + 1);
        assert_eq!(moves.last().map(|m| m.role), Some(Role::Return));
    }
}
