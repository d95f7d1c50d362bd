//! The LinuxCNC G76 harnesses (issue 15): the depths, the end of the
//! rough passes, the passes at full depth and the moves of a pass, checked
//! against LinuxCNC's rules (readings R-LCNC-PASS, R-LCNC-EXACT,
//! R-LCNC-TIE, R-LCNC-SYNC, R-LCNC-WORDS in `docs/INTERPRETATIONS.md`)
//! restated in integers from the block's words alone, never from the
//! engine or from the reference's `rust_decimal`/interval values.
//!
//! # The exact integer restatement
//!
//! The harness draws the degression as a fraction `R = p/q` (`1 ≤ R`, `p`,
//! `q` small, `10 000·p/q` an integer: R in the cycle's ten-thousandths).
//! Rough pass `n` is cut at the exact depth `δ_n = J·n^(1/R) = J·n^(q/p)`,
//! so `δ_n^p = J^p·n^q` is an integer and every question about `δ_n` is a
//! comparison of integers:
//!
//! * `δ_n < K` ⇔ `J^p·n^q < K^p` (R-LCNC-PASS: rough passes while `δ < K`;
//!   R-LCNC-TIE: `δ_n = K` exactly is no rough pass);
//! * a rounded value `d` of `δ_n/ξ` (nearest, ties away from zero,
//!   R-LCNC-EXACT; `δ_n > 0`): `d − ½ ≤ δ_n/ξ < d + ½` ⇔ `((2d − 1)ξ)^p ≤
//!   2^p·J^p·n^q < ((2d + 1)ξ)^p`;
//! * the cut X of the pass, `X_c − σδ_n` rounded (`X_c = X₀ − σ|I|`, the
//!   crest): with `e = σ(X_c − x)`, `(2e − 1)^p ≤ 2^p·J^p·n^q ≤ (2e + 1)^p`
//!   (both ends closed: a tie goes away from zero, which is up or down with
//!   the sign of the coordinate).
//!
//! `δ_n` strictly increases with `n` (`n^(q/p)` does), so rough passes
//! numbered 1, 2, 3, … in order have strictly increasing exact depths;
//! their rounded depths ([`Pass::depth`], `round(δ_n/ξ)`) can repeat (a
//! cut of 0) and the last one can equal the full-depth pass's
//! (`round(K/ξ)`): what holds exactly is non-decreasing depth, cut ≥ 0 and
//! `δ_n < K`, which [`lcnc_depth_monotonicity`] asserts.
//!
//! # Windows
//!
//! A window ([`LcncDomain`]) bounds J, K − J, R's denominator and its
//! largest value, |I|, X₀, the thread's length, Q (from [`ANGLES`]), H, E
//! and L, G7/G8, the side and the direction, and the pass limit, which
//! bounds the rough passes (beyond it the engine refuses the cycle,
//! R-LIMIT, which [`lcnc_termination`] checks against the same
//! restatement). Every integer of the restatement stays far inside `u128`
//! in the windows of `crate::windows` (p ≤ 12, q ≤ 4: `K^p ≤ 6^12`,
//! `((2d + 1)ξ)^p ≤ 26^12`) and in the tests' wider sampled window (`K ≤
//! 60`, 40 passes: below `2^96`); [`pow`] asserts it.

use cycleref::lead::{Lead, LeadWord};
use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
use cycleref::{
    CycleError, IncrementSystem, InputUnit, Motion, Move, Pass, PassKind, Point, Role, Units, XMode,
};

use crate::cover;
use crate::verify::{any_in, assume, declare};

/// Compound angles a window draws from (Q in ten-thousandths of a degree):
/// none, LinuxCNC's usual 29.5° either way, and 45° (`tan Q = 1`).
pub const ANGLES: [i32; 4] = [0, 295_000, -295_000, 450_000];

/// The pitch of every drawn cycle: P1.5.
pub const PITCH: Lead = Lead { word: LeadWord::K, mantissa: 15, scale: 1 };

/// The inputs of a LinuxCNC harness: inclusive ranges of the words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LcncDomain {
    /// J, increments of the X mode.
    pub initial_depth: (i64, i64),
    /// K − J.
    pub extra_depth: (i64, i64),
    /// q of R = p/q.
    pub denominator: (i64, i64),
    /// The largest R: p runs from q to `max_degression · q`.
    pub max_degression: i64,
    /// |I|.
    pub peak_offset: (i64, i64),
    /// X₀, the drive line.
    pub x0: (i64, i64),
    /// |Z − Z₀|.
    pub length: (i64, i64),
    /// Indices into [`ANGLES`].
    pub angle: (i64, i64),
    /// H.
    pub spring_passes: (i64, i64),
    /// E.
    pub taper_distance: (i64, i64),
    /// L: bit 1 entry, bit 2 exit.
    pub taper_bits: (i64, i64),
    /// 0: G8 (radius), 1: G7 (diameter).
    pub diameter: (i64, i64),
    /// 0: external (I < 0), 1: internal.
    pub internal: (i64, i64),
    /// 0: towards −Z, 1: towards +Z.
    pub towards_plus: (i64, i64),
    /// The machine's pass limit.
    pub pass_limit: u32,
}

/// A drawn cycle and its degression as a fraction `p/q`.
#[derive(Clone, Copy, Debug)]
pub struct Drawn {
    /// The cycle.
    pub c: LinuxCncG76,
    /// p of R = p/q.
    pub p: u32,
    /// q of R = p/q.
    pub q: u32,
}

/// A cycle of window `d` (module docs). IS-C mm (LinuxCNC's profile
/// increment is 0.0001 mm; the unit changes no value of the engine), P1.5,
/// Z₀ = 0, the block's X that of the start (no X word).
pub fn any_lcnc(d: &LcncDomain) -> Drawn {
    let j = any_in(d.initial_depth.0, d.initial_depth.1);
    let k = j + any_in(d.extra_depth.0, d.extra_depth.1);
    let q = any_in(d.denominator.0, d.denominator.1);
    let p = any_in(q, d.max_degression * q);
    // R in ten-thousandths must be an integer (q = 3 only with 3 | p).
    assume((i64::from(DEGRESSION_ONE) * p) % q == 0);
    let degression = u32::try_from(i64::from(DEGRESSION_ONE) * p / q).unwrap_or(0);
    let i_abs = any_in(d.peak_offset.0, d.peak_offset.1);
    let x0 = any_in(d.x0.0, d.x0.1);
    let length = any_in(d.length.0, d.length.1);
    let angle = ANGLES.get(usize::try_from(any_in(d.angle.0, d.angle.1)).unwrap_or(0)).copied().unwrap_or(0);
    let spring_passes = i32::try_from(any_in(d.spring_passes.0, d.spring_passes.1)).unwrap_or(0);
    let taper_distance = any_in(d.taper_distance.0, d.taper_distance.1);
    let bits = any_in(d.taper_bits.0, d.taper_bits.1);
    let x_mode = if any_in(d.diameter.0, d.diameter.1) == 1 { XMode::Diameter } else { XMode::Radius };
    let internal = any_in(d.internal.0, d.internal.1) == 1;
    let towards_plus = any_in(d.towards_plus.0, d.towards_plus.1) == 1;
    let c = LinuxCncG76 {
        units: Units { system: IncrementSystem::IsC, unit: InputUnit::Metric },
        x_mode,
        start: Point::new(x0, 0),
        end: Point::new(x0, if towards_plus { length } else { -length }),
        pitch: PITCH,
        peak_offset: if internal { i_abs } else { -i_abs },
        initial_depth: j,
        degression,
        full_depth: k,
        compound_angle: angle,
        spring_passes,
        taper_distance,
        entry_taper: bits & 1 == 1,
        exit_taper: bits & 2 == 2,
        pass_limit: d.pass_limit,
    };
    Drawn { c, p: u32::try_from(p).unwrap_or(1), q: u32::try_from(q).unwrap_or(1) }
}

/// `b^e` in `u128`; asserts that it fits (the windows keep it far inside).
#[must_use]
pub fn pow(b: u128, e: u32) -> u128 {
    let mut v = 1_u128;
    for _ in 0..e {
        v = v.checked_mul(b).expect("the integer restatement stays within u128");
    }
    v
}

/// The exact restatement of a drawn cycle's depths (module docs).
#[derive(Clone, Copy, Debug)]
pub struct Depths {
    j: u128,
    k: u128,
    xf: u128,
    p: u32,
    q: u32,
}

impl Depths {
    /// The restatement of `d`'s words.
    #[must_use]
    pub fn of(d: &Drawn) -> Depths {
        let u = |v: i64| u128::from(v.unsigned_abs());
        Depths { j: u(d.c.initial_depth), k: u(d.c.full_depth), xf: u(d.c.x_mode.factor()), p: d.p, q: d.q }
    }

    /// `(2δ_n)^p = 2^p·J^p·n^q`.
    #[must_use]
    pub fn twice_depth_pow(&self, n: u64) -> u128 {
        pow(2 * self.j, self.p).checked_mul(pow(u128::from(n), self.q)).expect("within u128")
    }

    /// `δ_n < K`, exactly: `J^p·n^q < K^p`.
    #[must_use]
    pub fn below_full(&self, n: u64) -> bool {
        pow(self.j, self.p).checked_mul(pow(u128::from(n), self.q)).expect("within u128")
            < pow(self.k, self.p)
    }

    /// `δ_n = K` exactly (R-LCNC-TIE).
    #[must_use]
    pub fn at_full(&self, n: u64) -> bool {
        pow(self.j, self.p).checked_mul(pow(u128::from(n), self.q)).expect("within u128")
            == pow(self.k, self.p)
    }

    /// `d = round(δ_n/ξ)`, nearest, ties away from zero (`d ≥ 1`).
    #[must_use]
    pub fn is_rounded_radius(&self, n: u64, d: i64) -> bool {
        let Ok(d) = u128::try_from(d) else { return false };
        if d == 0 {
            return false;
        }
        let v = self.twice_depth_pow(n);
        pow((2 * d - 1) * self.xf, self.p) <= v && v < pow((2 * d + 1) * self.xf, self.p)
    }

    /// `e` is `δ_n` rounded to an integer either way at a half (`e ≥ 1`):
    /// `|e − δ_n| ≤ ½`.
    #[must_use]
    pub fn is_rounded_depth(&self, n: u64, e: i64) -> bool {
        let Ok(e) = u128::try_from(e) else { return false };
        if e == 0 {
            return false;
        }
        let v = self.twice_depth_pow(n);
        pow(2 * e - 1, self.p) <= v && v <= pow(2 * e + 1, self.p)
    }

    /// `|v − δ_n/ξ| ≤ ½` (`v ≥ 1`): `δ_n/ξ` rounded either way at a half.
    #[must_use]
    pub fn is_rounded_radius_either_way(&self, n: u64, v: i64) -> bool {
        let Ok(v) = u128::try_from(v) else { return false };
        if v == 0 {
            return false;
        }
        let w = self.twice_depth_pow(n);
        pow((2 * v - 1) * self.xf, self.p) <= w && w <= pow((2 * v + 1) * self.xf, self.p)
    }

    /// `|v − K/ξ| ≤ ½`: `K/ξ` rounded either way at a half.
    #[must_use]
    pub fn is_rounded_full_radius_either_way(&self, v: i64) -> bool {
        let Ok(v) = u128::try_from(v) else { return false };
        (2 * v * self.xf).abs_diff(2 * self.k) <= self.xf
    }

    /// `round(K/ξ)`, ties away from zero: the full depth as a radius.
    #[must_use]
    pub fn full_radius(&self) -> i64 {
        i64::try_from((2 * self.k + self.xf) / (2 * self.xf)).unwrap_or(i64::MAX)
    }
}

/// The passes of a stream of moves: each pass's information, as its first
/// move carries it, and a callback per pass. `None` when a move of a pass
/// has no pass information.
fn pass_changed(last: Option<Pass>, m: &Move) -> Option<Pass> {
    let p = m.pass?;
    match last {
        Some(l) if (l.kind, l.number) == (p.kind, p.number) => None,
        _ => Some(p),
    }
}

/// A cycle of window `d` ([`any_lcnc`]) as `engine` expands it, with the
/// exact restatement of its depths; `None`, the run pruned, when the engine
/// refuses it.
fn expanded<F, I>(d: &LcncDomain, engine: &F) -> Option<(Drawn, I, Depths)>
where
    F: Fn(&LinuxCncG76) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    let drawn = any_lcnc(d);
    match engine(&drawn.c) {
        Ok(moves) => Some((drawn, moves, Depths::of(&drawn))),
        Err(_) => {
            assume(false);
            None
        }
    }
}

/// True when `n^(q/p)` is an integer (`m^p = n^q` for some `m ≤ n`):
/// `δ_n = J·m` exactly, the case the engine holds as an exact point.
#[must_use]
pub fn is_exact_root(n: u64, p: u32, q: u32) -> bool {
    let target = pow(n.into(), q);
    let mut found = false;
    for m in 1..=n {
        found |= pow(m.into(), p) == target;
    }
    found
}

/// P1 for LinuxCNC: the rough passes' depths. Over [`any_lcnc`]`(d)`, for
/// every expanded cycle:
///
/// * rough passes come first, numbered 1, 2, 3, … in order (so their exact
///   depths `δ_n = J·n^(1/R)` strictly increase), each pass's moves
///   together and all carrying the same [`Pass`];
/// * every rough pass is shallower than K exactly (`J^p·n^q < K^p`);
/// * its depth is `round(δ_n/ξ)` (the integer bracket of the module docs),
///   never below the previous rough pass's and never above the full-depth
///   pass's `round(K/ξ)`; its cut is the difference to the previous pass's
///   depth (the depth for pass 1), so cut ≥ 0;
/// * its cut X is `X_c − σδ_n` rounded, and no pass cuts at a shallower X
///   than the one before.
///
/// Not asserted, because it is false: strictly increasing rounded depths (two
/// passes can round to the same depth: cover "two rough passes at the same
/// rounded depth") and a last rough depth below the full depth's (cover "a
/// rough pass at the full depth's rounded depth").
pub fn lcnc_depth_monotonicity<F, I>(d: &LcncDomain, engine: &F)
where
    F: Fn(&LinuxCncG76) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&[
        "three or more rough passes",
        "two rough passes at the same rounded depth",
        "a rough pass at the full depth's rounded depth",
        "an exact root beyond the first pass (δ_n/J an integer)",
        "a fractional R",
        "G7",
        "internal",
    ]);
    let Some((drawn, moves, r)) = expanded(d, engine) else { return };
    let c = drawn.c;
    let sigma = c.sigma();
    let crest = c.start.x - sigma * c.peak_offset.abs();
    let mut last: Option<Pass> = None;
    let mut rough = 0_u64;
    let mut finished = false;
    let mut depth = 0_i64;
    let mut cut_depth = 0_i64;
    for m in moves {
        if let Some(p) = pass_changed(last, &m) {
            if p.kind == PassKind::Rough {
                assert!(!finished, "rough passes come first");
                rough += 1;
                assert_eq!(u64::from(p.number), rough, "rough passes are numbered 1, 2, 3, … in order");
                assert!(r.below_full(rough), "a rough pass is shallower than K exactly");
                assert!(
                    rough == 1 || r.twice_depth_pow(rough) > r.twice_depth_pow(rough - 1),
                    "the exact rough depths strictly increase"
                );
                assert!(r.is_rounded_radius(rough, p.depth), "a rough depth is round(δ_n/ξ)");
                assert!(p.depth >= depth, "rough depths never decrease");
                assert_eq!(p.cut, p.depth - depth, "the cut is the depth less the previous pass's");
                assert!(p.cut >= 0, "a rough cut is never negative");
                assert!(p.depth <= r.full_radius(), "a rough depth is at most round(K/ξ)");
                cover!(rough > 1 && p.cut == 0, "two rough passes at the same rounded depth");
                cover!(p.depth == r.full_radius(), "a rough pass at the full depth's rounded depth");
                cover!(
                    rough > 1 && is_exact_root(rough, drawn.p, drawn.q),
                    "an exact root beyond the first pass (δ_n/J an integer)"
                );
                depth = p.depth;
            } else {
                finished = true;
            }
            last = Some(p);
        } else if m.pass.is_some() {
            assert_eq!(m.pass, last, "the moves of a pass carry the same pass information");
        }
        if m.role == Role::Cut && last.is_some_and(|p| p.kind == PassKind::Rough) {
            let e = sigma * (crest - m.to.x);
            assert!(r.is_rounded_depth(rough, e), "a rough pass cuts at X_c − σδ_n rounded");
            assert!(e >= cut_depth, "no rough pass cuts shallower than the one before");
            cut_depth = e;
        }
    }
    cover!(rough >= 3, "three or more rough passes");
    cover!(drawn.p % drawn.q != 0, "a fractional R");
    cover!(c.x_mode == XMode::Diameter, "G7");
    cover!(c.internal(), "internal");
}

/// The moves of one pass of a cycle: back, in (or the entry taper's two
/// moves), over, the exit taper's move, out (R-LCNC-PASS).
#[must_use]
pub fn moves_per_pass(c: &LinuxCncG76) -> u64 {
    let tapered = c.taper_distance > 0;
    4 + u64::from(tapered && c.entry_taper) + u64::from(tapered && c.exit_taper)
}

/// P2 for LinuxCNC: where the rough passes end. Over [`any_lcnc`]`(d)`:
///
/// * the engine refuses the cycle with `TooManyPasses` exactly when pass
///   `limit + 1` would still be shallower than K (`J^p·(limit + 1)^q <
///   K^p`, R-LIMIT), else with `TooMuchWork` exactly when its N + 1 + H
///   pass paths exceed the limit (R-BUDGET), and expands every other cycle
///   of the window;
/// * the last rough pass N is shallower than K and the next would not be
///   (`J^p·N^q < K^p ≤ J^p·(N + 1)^q`, a tie `δ_(N+1) = K` included:
///   R-LCNC-TIE), N ≥ 1 (J < K);
/// * the cycle has N + 1 + H passes (none at full depth for H = −1), the
///   full-depth ones numbered 1 … 1 + H after the rough ones, each pass
///   [`moves_per_pass`] moves, then one return rapid to the block's end
///   point: `(N + 1 + H)·moves_per_pass + 1` moves.
pub fn lcnc_termination<F, I>(d: &LcncDomain, engine: &F)
where
    F: Fn(&LinuxCncG76) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&[
        "a single rough pass",
        "the next depth equals K exactly (R-LCNC-TIE)",
        "H = -1: no pass at full depth",
        "spring passes (H ≥ 1)",
        "refused: more rough passes than the limit",
        "refused: more pass paths than the limit (R-BUDGET)",
        "as many rough passes as the limit",
    ]);
    let drawn = any_lcnc(d);
    let c = drawn.c;
    let r = Depths::of(&drawn);
    let limit = u64::from(c.pass_limit);
    let over_limit = r.below_full(limit + 1);
    let h = u64::try_from(i64::from(c.spring_passes) + 1).unwrap_or(0);
    let moves = match engine(&c) {
        Ok(moves) => moves,
        Err(CycleError::TooMuchWork { pass_paths, limit: l }) => {
            // R-BUDGET: the rough passes fit the limit, the whole cycle
            // (N + 1 + H pass paths) does not. N found from the depths:
            // the last n with δ_n < K (N ≤ limit, as the cycle is not over
            // it; J < K, so N ≥ 1).
            assert!(!over_limit, "beyond the rough limit, TooManyPasses comes first");
            let mut n = 1_u64;
            while n <= limit && r.below_full(n + 1) {
                n += 1;
            }
            assert_eq!(l, c.pass_limit);
            assert_eq!(pass_paths, n + h, "the pass paths are N + 1 + H");
            assert!(pass_paths > limit, "only a cycle beyond the limit is refused");
            cover!(true, "refused: more pass paths than the limit (R-BUDGET)");
            return;
        }
        Err(e) => {
            assert!(
                over_limit && matches!(e, CycleError::TooManyPasses { .. }),
                "only a cycle beyond the pass limit is refused, with TooManyPasses: {e:?}"
            );
            cover!(true, "refused: more rough passes than the limit");
            return;
        }
    };
    assert!(!over_limit, "a cycle beyond the pass limit is refused");
    let mut last: Option<Pass> = None;
    let (mut rough, mut full, mut count, mut passes) = (0_u64, 0_u64, 0_u64, 0_u64);
    let mut returned = None;
    for m in moves {
        count += 1;
        assert!(returned.is_none(), "the return is the last move");
        if m.role == Role::Return {
            assert_eq!((m.motion, m.pass), (Motion::Rapid, None), "the return is a rapid outside the passes");
            returned = Some(m.to);
            continue;
        }
        if let Some(p) = pass_changed(last, &m) {
            passes += 1;
            match p.kind {
                PassKind::Rough => {
                    assert_eq!(full, 0, "rough passes come first");
                    rough += 1;
                    assert_eq!(u64::from(p.number), rough, "rough passes are numbered in order");
                }
                PassKind::Finish => {
                    full += 1;
                    assert_eq!(u64::from(p.number), full, "full-depth passes are numbered in order");
                }
                PassKind::Single => panic!("a LinuxCNC pass is rough or at full depth"),
            }
            last = Some(p);
        }
        assert!(m.pass.is_some(), "every move but the return belongs to a pass");
    }
    assert_eq!(returned, Some(c.end), "the cycle ends with a rapid to the block's end point");
    assert!(rough >= 1, "J < K: at least one rough pass");
    assert!(r.below_full(rough), "the last rough pass is shallower than K");
    assert!(!r.below_full(rough + 1), "the pass after the last rough pass would not be shallower than K");
    assert_eq!(full, h, "1 + H passes at full depth");
    assert_eq!(passes, rough + h, "N + 1 + H passes");
    assert!(passes <= limit, "an expanded cycle is within the limit (R-BUDGET)");
    assert_eq!(count, passes * moves_per_pass(&c) + 1, "each pass's moves and the return");
    cover!(rough == 1, "a single rough pass");
    cover!(r.at_full(rough + 1), "the next depth equals K exactly (R-LCNC-TIE)");
    cover!(c.spring_passes == -1, "H = -1: no pass at full depth");
    cover!(c.spring_passes >= 1, "spring passes (H ≥ 1)");
    cover!(rough == limit, "as many rough passes as the limit");
}

/// P3 for LinuxCNC: the passes at full depth. Over [`any_lcnc`]`(d)`, the
/// 1 + H passes after the rough ones:
///
/// * each is at depth `round(K/ξ)` (ties away from zero), its cut the
///   difference to the last rough pass's depth for the first and 0 after;
/// * its cut ("over", and the entry taper's end) is at `X₀ − σ(|I| + K)`
///   exactly, its "out" rapid returns to `X₀` (`X₀ + σ(K − K)`), an exit
///   taper climbs to the crest `X₀ − σ|I|`;
/// * the deepest pass ends exactly at the programmed Z (the compound shift
///   cancels at δ = K, R-LCNC-PASS): its last synchronised move (the over,
///   or the exit taper) ends at Z and its out rapid stays at Z;
/// * every full-depth pass repeats the first one's moves exactly (spring
///   passes), apart from the pass information's number and cut.
pub fn lcnc_spring_passes<F, I>(d: &LcncDomain, engine: &F)
where
    F: Fn(&LinuxCncG76) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&[
        "spring passes (H ≥ 1)",
        "with a compound angle",
        "with an exit taper",
        "with an entry taper",
        "internal",
        "towards +Z",
        "G7 with an odd K (the radius depth rounded up)",
        "the first full-depth pass cuts nothing (a rough pass at its depth)",
    ]);
    let Some((drawn, moves, r)) = expanded(d, engine) else { return };
    let c = drawn.c;
    let sigma = c.sigma();
    let (x0, k, i_abs) = (c.start.x, c.full_depth, c.peak_offset.abs());
    let x_cut = x0 - sigma * (i_abs + k);
    let exit = c.taper_distance > 0 && c.exit_taper;
    let entry = c.taper_distance > 0 && c.entry_taper;
    let per_pass = usize::try_from(moves_per_pass(&c)).unwrap_or(0);
    let mut last: Option<Pass> = None;
    let mut depth = 0_i64;
    let mut full = 0_u64;
    // The first full-depth pass's moves (at most six), to compare the others with.
    let mut first = [None::<(Motion, Point, Role)>; 6];
    let mut step = 0_usize;
    for m in moves {
        if let Some(p) = pass_changed(last, &m) {
            if p.kind == PassKind::Finish {
                full += 1;
                assert_eq!(p.depth, r.full_radius(), "a full-depth pass is at round(K/ξ)");
                let cut = if full == 1 { p.depth - depth } else { 0 };
                assert_eq!(p.cut, cut, "the first full-depth pass cuts to K, the spring passes nothing");
                cover!(
                    full == 1 && cut == 0,
                    "the first full-depth pass cuts nothing (a rough pass at its depth)"
                );
                step = 0;
            }
            depth = p.depth;
            last = Some(p);
        }
        if !m.pass.is_some_and(|p| p.kind == PassKind::Finish) {
            continue;
        }
        let slot = first.get_mut(step).expect("a pass has at most six moves");
        let this = (m.motion, m.to, m.role);
        if full == 1 {
            *slot = Some(this);
        } else {
            assert_eq!(*slot, Some(this), "a spring pass repeats the full-depth pass");
        }
        step += 1;
        match m.role {
            Role::Cut => {
                assert_eq!(m.to.x, x_cut, "the full-depth cut is at X₀ − σ(|I| + K)");
                if !exit {
                    assert_eq!(m.to.z, c.end.z, "the deepest pass's over ends at Z");
                }
            }
            Role::LeadIn if step == 3 => {
                assert_eq!(m.to.x, x_cut, "the entry taper ends at X₀ − σ(|I| + K)");
            }
            Role::RunOut => {
                assert_eq!(
                    m.to,
                    Point::new(x0 - sigma * i_abs, c.end.z),
                    "the deepest pass's exit taper ends at the crest at Z"
                );
            }
            Role::Retract => {
                assert_eq!(m.to, Point::new(x0, c.end.z), "the deepest pass's out is at X₀ and Z");
                assert_eq!(step, per_pass, "the out is a pass's last move");
            }
            _ => {}
        }
    }
    let h = u64::try_from(i64::from(c.spring_passes) + 1).unwrap_or(0);
    assert_eq!(full, h, "1 + H passes at full depth");
    cover!(c.spring_passes >= 1, "spring passes (H ≥ 1)");
    cover!(h > 0 && c.compound_angle != 0, "with a compound angle");
    cover!(h > 0 && exit, "with an exit taper");
    cover!(h > 0 && entry, "with an entry taper");
    cover!(h > 0 && c.internal(), "internal");
    cover!(h > 0 && c.end.z > c.start.z, "towards +Z");
    cover!(
        h > 0 && c.x_mode == XMode::Diameter && k % 2 == 1,
        "G7 with an odd K (the radius depth rounded up)"
    );
}

/// The pitch of the taper moves, restated: `m` (in 10⁻⁶) is `P·√(ξ²E² +
/// K²)/(ξE)` rounded to the nearest, i.e. `((2m − 1)B)² ≤ 4A²S < ((2m +
/// 1)B)²` with `A` = P in 10⁻⁶, `S = ξ²E² + K²`, `B = ξE` (R-LCNC-SYNC).
#[must_use]
pub fn is_taper_pitch(c: &LinuxCncG76, lead: Lead) -> bool {
    if lead.word != c.pitch.word || lead.scale != 6 {
        return false;
    }
    let xf = u128::from(c.x_mode.factor().unsigned_abs());
    let e = u128::from(c.taper_distance.unsigned_abs());
    let k = u128::from(c.full_depth.unsigned_abs());
    let a = u128::from(c.pitch.mantissa) * pow(10, 6 - c.pitch.scale);
    let (s, b, m) = (xf * xf * e * e + k * k, xf * e, u128::from(lead.mantissa));
    let v = 4 * a * a * s;
    m >= 1 && pow((2 * m - 1) * b, 2) <= v && v < pow((2 * m + 1) * b, 2)
}

/// P4 for LinuxCNC: the moves of a pass (R-LCNC-PASS, R-LCNC-SYNC). Over
/// [`any_lcnc`]`(d)`, with `σ`, the crest `X_c = X₀ − σ|I|`, `t` the sign
/// of `Z − Z₀` and, for each pass, its back X `x_b` and start Z `z_s`
/// (from its first move), its cut X `x_c` and end Z `z_e` (from its out):
///
/// * the pass starts at `z_s = Z₀ − ζ` (ζ = (δ/ξ)·tan Q, Q negated towards
///   +Z): at Z₀ for Q = 0; shifted along the thread (`t(z_s − Z₀) ≥ 0`) for
///   Q > 0 and against it for Q < 0; at ±45° (`tan Q = 1`) by `δ/ξ` rounded
///   (the restatement's bracket, either way at a half);
/// * the pass is: back, a rapid; then either "in", a rapid along X alone at
///   `z_s` down to `x_c`, or with an entry taper (E > 0, L bit 1) two
///   synchronised moves, to `(x_c + σK, z_s)` and to `(x_c, z_s + tE)`;
///   over, synchronised at P, at `x_c`, to `z_e`, or with an exit taper to
///   `z_e − tE` and then a synchronised move at the taper pitch to `(x_c +
///   σK, z_e)`; out, a rapid along X alone at `z_e` to `x_b`;
/// * synchronised moves are never rapids: the taper moves and the over are
///   thread moves (the taper's at the taper pitch, restated by
///   [`is_taper_pitch`]; the over's at P), the first of a pass starts the
///   synchronisation and the others continue it; every rapid is a back, an
///   in, an out or the return;
/// * the tapers end inside the thread: their points lie between the back X
///   and the cut X (`σx_c ≤ σx ≤ σx_b`) and, when the pass runs at least E
///   in the thread's direction (`t(z_e − z_s) ≥ E`), within its Z span
///   (with both tapers and `2E ≤ t(z_e − z_s)`, the over runs from the
///   entry's end towards the exit's start); a longer E, or a pass that runs
///   backwards because the compound shift `(K/ξ)·tan Q` exceeds the thread's
///   length, is cut as LinuxCNC cuts it, the taper along the programmed
///   direction (cover "a taper longer than the pass");
/// * no rapid crosses into the thread region (deeper than the crest, `σ(x −
///   X_c) < 0`) except the "in" rapid of a non-tapered pass: every other
///   rapid ends at or outside the crest, and a rapid that starts deeper (an
///   out after the over, without an exit taper) runs along X alone,
///   outwards, out of the groove it cut; the return goes to the block's end
///   point (l.5791; here its X is X₀, outside the crest).
pub fn lcnc_pass_moves<F, I>(d: &LcncDomain, engine: &F)
where
    F: Fn(&LinuxCncG76) -> Result<I, CycleError>,
    I: Iterator<Item = Move>,
{
    declare(&[
        "an entry taper",
        "an exit taper",
        "both tapers",
        "L bits without E: no taper",
        "a taper longer than the pass",
        "tapers on an internal thread",
        "tapers towards +Z",
        "an in rapid down to the cut",
        "an out rapid from the cut (no exit taper)",
        "an exit taper ending on the crest",
        "a pass that runs backwards (the compound shift beyond the thread)",
        "a compound shift against the thread (Q < 0)",
        "a 45° compound shift",
    ]);
    let Some((drawn, moves, depths)) = expanded(d, engine) else { return };
    let c = drawn.c;
    let sigma = c.sigma();
    let t = if c.end.z > c.start.z { 1 } else { -1 };
    let crest = c.start.x - sigma * c.peak_offset.abs();
    let entry = c.taper_distance > 0 && c.entry_taper;
    let exit = c.taper_distance > 0 && c.exit_taper;
    let e = t * c.taper_distance;
    let k = sigma * c.full_depth;
    let taper_ok = |m: &Move| match m.motion {
        Motion::Thread { lead, .. } => is_taper_pitch(&c, lead),
        _ => false,
    };
    // The moves of the current pass (at most six), checked when it ends.
    let mut pass = [Move { motion: Motion::Rapid, to: c.start, role: Role::Return, pass: None }; 6];
    let mut len = 0_usize;
    let mut at = c.start;
    let mut last: Option<Pass> = None;
    let check_pass = |moves: &[Move], from: Point| {
        // The rapids and the thread region.
        let mut prev = from;
        for (i, m) in moves.iter().enumerate() {
            let synchronised = matches!(m.role, Role::LeadIn | Role::Cut | Role::RunOut);
            assert_eq!(
                synchronised,
                matches!(m.motion, Motion::Thread { .. }),
                "the synchronised moves (tapers, over) are thread moves, never rapids, and the others rapids"
            );
            if m.motion == Motion::Rapid {
                let is_in = i == 1 && !entry;
                if !is_in {
                    assert!(
                        sigma * (m.to.x - crest) >= 0,
                        "a rapid other than in ends at or outside the crest"
                    );
                }
                if sigma * (prev.x - crest) < 0 {
                    assert!(
                        prev.z == m.to.z && sigma * (m.to.x - prev.x) > 0,
                        "a rapid from inside the thread region runs along X alone, outwards"
                    );
                }
            }
            prev = m.to;
        }
        // The compound shift of the pass's start (R-LCNC-PASS): ζ = (δ/ξ)·tan Q
        // along the thread for Q > 0 (Q is negated towards +Z, and so is
        // the shift's sign in Z), against it for Q < 0, none for Q = 0.
        let z_s = moves.first().map_or(c.start.z, |m| m.to.z);
        let shift = t * (z_s - c.start.z);
        let q_sign = i64::from(c.compound_angle.signum());
        if q_sign == 0 {
            assert_eq!(shift, 0, "without a compound angle every pass starts at Z₀");
        } else {
            assert!(
                q_sign * shift >= 0,
                "the compound shift runs along the thread for Q > 0, against it for Q < 0"
            );
            cover!(q_sign < 0 && shift < 0, "a compound shift against the thread (Q < 0)");
            cover!(c.compound_angle.unsigned_abs() == 450_000 && shift != 0, "a 45° compound shift");
            if c.compound_angle.unsigned_abs() == 450_000 {
                // tan 45° = 1: |ζ| = δ/ξ rounded either way at a half.
                let info = moves.first().and_then(|m| m.pass);
                let exact = match info {
                    Some(Pass { kind: PassKind::Rough, number, .. }) => {
                        depths.is_rounded_radius_either_way(u64::from(number), shift.abs())
                    }
                    _ => depths.is_rounded_full_radius_either_way(shift.abs()),
                };
                assert!(exact, "at 45° the compound shift is the depth as a radius, rounded");
            }
        }
        let n = moves.len();
        assert_eq!(n, usize::try_from(moves_per_pass(&c)).unwrap_or(0), "a pass's moves (R-LCNC-PASS)");
        let (back, out) = (moves[0], moves[n - 1]);
        let (x_b, z_s, z_e) = (back.to.x, back.to.z, out.to.z);
        let over = moves[if entry { 3 } else { 2 }];
        let x_c = over.to.x;
        let over_z = if exit { z_e - e } else { z_e };
        assert_eq!((back.motion, back.role), (Motion::Rapid, Role::Approach), "back is a rapid");
        assert_eq!(
            (out.motion, out.role, out.to.x),
            (Motion::Rapid, Role::Retract, x_b),
            "out is a rapid to the back X"
        );
        assert_eq!((over.role, over.to), (Role::Cut, Point::new(x_c, over_z)), "over runs at the cut X");
        assert!(
            matches!(over.motion, Motion::Thread { lead, sync, .. } if lead == c.pitch && sync != entry),
            "over is synchronised at P, starting the synchronisation without an entry taper"
        );
        assert!(sigma * (x_b - x_c) > 0, "the cut X is deeper than the back X");
        // The pass's length in the thread's direction (negative when the
        // compound shift K/ξ·t exceeds the thread: the pass runs backwards).
        let span = t * (z_e - z_s);
        let inside = |z: i64| t * (z - z_s) >= 0 && t * (z_e - z) >= 0;
        let between = |x: i64| sigma * (x - x_c) >= 0 && sigma * (x_b - x) >= 0;
        if entry {
            let (a, b) = (moves[1], moves[2]);
            assert_eq!((a.role, b.role), (Role::LeadIn, Role::LeadIn), "the entry taper's two moves");
            assert_eq!(
                a.to,
                Point::new(x_c + k, z_s),
                "the entry taper starts K above the cut at the start Z"
            );
            assert_eq!(b.to, Point::new(x_c, z_s + e), "the entry taper ends at the cut X, E along Z");
            assert!(
                taper_ok(&a) && taper_ok(&b),
                "the entry taper's moves are synchronised at the taper pitch"
            );
            assert!(
                matches!(
                    (a.motion, b.motion),
                    (Motion::Thread { sync: true, .. }, Motion::Thread { sync: false, .. })
                ),
                "the entry taper starts the synchronisation"
            );
            assert!(
                between(a.to.x) && between(b.to.x),
                "the entry taper stays between the back X and the cut X"
            );
            if c.taper_distance <= span {
                assert!(inside(a.to.z) && inside(b.to.z), "the entry taper stays within the pass's Z span");
            }
        } else {
            let a = moves[1];
            assert_eq!((a.motion, a.role), (Motion::Rapid, Role::Approach), "in is a rapid");
            assert_eq!((back.to.z, a.to), (z_s, Point::new(x_c, z_s)), "in runs along X alone to the cut X");
            cover!(sigma * (a.to.x - crest) < 0, "an in rapid down to the cut");
        }
        if exit {
            let x = moves[n - 2];
            assert_eq!(
                (x.role, x.to),
                (Role::RunOut, Point::new(x_c + k, z_e)),
                "the exit taper climbs K to the end Z"
            );
            assert!(
                taper_ok(&x) && matches!(x.motion, Motion::Thread { sync: false, .. }),
                "the exit taper continues the synchronisation at the taper pitch"
            );
            assert!(between(x.to.x), "the exit taper stays between the back X and the cut X");
            if c.taper_distance <= span {
                assert!(inside(over_z), "the exit taper starts within the pass's Z span");
            }
            cover!(x.to.x == crest, "an exit taper ending on the crest");
        } else {
            cover!(sigma * (over.to.x - crest) < 0, "an out rapid from the cut (no exit taper)");
        }
        if entry && exit && 2 * c.taper_distance <= span {
            assert!(t * (over_z - (z_s + e)) >= 0, "with both tapers the over runs forwards");
        }
        cover!(c.taper_distance > span && (entry || exit), "a taper longer than the pass");
        cover!(span < 0, "a pass that runs backwards (the compound shift beyond the thread)");
    };
    for m in moves {
        if m.role == Role::Return {
            if len > 0 {
                check_pass(pass.get(..len).unwrap_or(&[]), at);
                at = pass.get(len - 1).map_or(at, |m| m.to);
                len = 0;
            }
            assert_eq!(
                (m.motion, m.to),
                (Motion::Rapid, c.end),
                "the return is a rapid to the block's end point"
            );
            assert!(sigma * (m.to.x - crest) >= 0, "the return ends outside the crest (no X word)");
            continue;
        }
        if let Some(p) = pass_changed(last, &m) {
            if len > 0 {
                check_pass(pass.get(..len).unwrap_or(&[]), at);
                at = pass.get(len - 1).map_or(at, |m| m.to);
            }
            len = 0;
            last = Some(p);
        }
        let slot = pass.get_mut(len).expect("a pass has at most six moves");
        *slot = m;
        len += 1;
    }
    cover!(entry && !exit, "an entry taper");
    cover!(exit && !entry, "an exit taper");
    cover!(entry && exit, "both tapers");
    cover!(c.taper_distance == 0 && (c.entry_taper || c.exit_taper), "L bits without E: no taper");
    cover!((entry || exit) && c.internal(), "tapers on an internal thread");
    cover!((entry || exit) && t > 0, "tapers towards +Z");
}
