//! Iteration counts of the engine's loops, for the proofs crate (feature
//! `loop-counters`, test-only; without it the crate-private counter is an
//! empty type whose methods do nothing, and this module exports nothing).
//!
//! Kani unrolls every loop up to a harness's `#[kani::unwind(N)]` and fails
//! when a loop can run N or more times. `cycleref-proofs` runs each harness
//! over its Kani window with this feature on and checks that the largest
//! count of each loop stays below the harness's bound. Each `Site` keeps
//! the largest number of iterations one execution of its loop made since
//! the last `reset`: counts are process-wide, so a measurement runs on
//! one thread.

#[cfg(feature = "loop-counters")]
use core::sync::atomic::{AtomicU32, Ordering};

/// A loop of the engine, with the largest iteration count seen.
#[cfg(feature = "loop-counters")]
#[derive(Debug)]
pub struct Site {
    /// `function: loop`.
    pub name: &'static str,
    max: AtomicU32,
}

#[cfg(feature = "loop-counters")]
impl Site {
    const fn new(name: &'static str) -> Site {
        Site { name, max: AtomicU32::new(0) }
    }

    /// The largest iteration count recorded since the last [`reset`].
    pub fn max(&self) -> u32 {
        self.max.load(Ordering::Relaxed)
    }

    /// Records one execution of the loop that made `iterations` iterations.
    pub fn record(&self, iterations: u32) {
        if iterations > self.max.load(Ordering::Relaxed) {
            self.max.fetch_max(iterations, Ordering::Relaxed);
        }
    }
}

/// `engine::arith::isqrt_floor`: Newton's loop on `u128` (x ≥ 2^64).
#[cfg(feature = "loop-counters")]
pub static ISQRT_U128: Site = Site::new("isqrt_floor: Newton on u128");
/// `engine::arith::isqrt_floor_u64`: Newton's loop on `u64`.
#[cfg(feature = "loop-counters")]
pub static ISQRT_U64: Site = Site::new("isqrt_floor_u64: Newton on u64");
/// `engine::arith::round_sqrt_near`: the guess and its corrections by one.
#[cfg(feature = "loop-counters")]
pub static ISQRT_NEAR: Site = Site::new("round_sqrt_near: guess and steps");
/// `engine::g76::check_pass_count`: the levels counted before any move.
#[cfg(feature = "loop-counters")]
pub static PASS_COUNT: Site = Site::new("check_pass_count: levels");
/// `G76Moves::plan_next`: stages skipped to the next planned pass.
#[cfg(feature = "loop-counters")]
pub static PLAN_NEXT: Site = Site::new("G76Moves::plan_next: stages");
/// `G76Moves::next`: passes and starts moved on to before the next move.
#[cfg(feature = "loop-counters")]
pub static G76_NEXT: Site = Site::new("G76Moves::next: passes and starts");
/// `G92Moves::next`: starts moved on to before the next move.
#[cfg(feature = "loop-counters")]
pub static G92_NEXT: Site = Site::new("G92Moves::next: starts");
/// `angle::gcd`: Stein's loop.
#[cfg(feature = "loop-counters")]
pub static GCD: Site = Site::new("angle::gcd: Stein");
/// `G32Block::validate`: the four coordinates.
#[cfg(feature = "loop-counters")]
pub static G32_VALIDATE: Site = Site::new("G32Block::validate: coordinates");

/// `engine::real`: every loop over the limbs of a number or a scratch
/// buffer (add, sub, increment, negation, comparison, products, small
/// division, shifts, bit length, copies, π's digits) and over the four
/// products of an interval product (the largest count of any one of them).
#[cfg(feature = "loop-counters")]
pub static REAL_LIMBS: Site = Site::new("real: limb loops");
/// `engine::real::limbs_divmod`: the quotient limbs of the long division
/// (Knuth's algorithm D) and, counted apart, the corrections of each
/// estimated limb (at most two).
#[cfg(feature = "loop-counters")]
pub static REAL_DIVMOD: Site = Site::new("real::limbs_divmod: quotient limbs");
/// `engine::real::series`: the terms of a Taylor series (sine or cosine).
#[cfg(feature = "loop-counters")]
pub static REAL_SERIES: Site = Site::new("real::series: terms");
/// `engine::real::ln`: the terms of an atanh series.
#[cfg(feature = "loop-counters")]
pub static REAL_LN: Site = Site::new("real::atanh2: terms");
/// `engine::real::exp`: the halvings of the argument, the terms of the
/// Taylor series and the squarings (the largest of the three).
#[cfg(feature = "loop-counters")]
pub static REAL_EXP: Site = Site::new("real::exp: halvings, terms, squarings");
/// `engine::real::power`: the integer root search and the gcd.
#[cfg(feature = "loop-counters")]
pub static REAL_ROOT: Site = Site::new("real::power: root search, gcd");
/// `engine::linuxcnc`: the passes checked before the first move.
#[cfg(feature = "loop-counters")]
pub static LCNC_PASSES: Site = Site::new("expand_linuxcnc: passes checked");
/// `LinuxCncMoves::next`: passes moved on to before the next move.
#[cfg(feature = "loop-counters")]
pub static LCNC_NEXT: Site = Site::new("LinuxCncMoves::next: passes");
/// `engine::linuxcnc::taper_pitch`: the bit pairs of the wide square root.
#[cfg(feature = "loop-counters")]
pub static LCNC_ISQRT: Site = Site::new("linuxcnc::isqrt_wide: bit pairs");
/// `engine::g75::roughing`: the layers whose pecks are counted.
#[cfg(feature = "loop-counters")]
pub static G75_LAYERS: Site = Site::new("g75 roughing: layers counted");
/// `G75Moves::next_rough`: roughing steps skipped to the next move.
#[cfg(feature = "loop-counters")]
pub static G75_ROUGH_NEXT: Site = Site::new("G75Moves::next_rough: steps");
/// `G75Moves::next`: stages skipped to the next move.
#[cfg(feature = "loop-counters")]
pub static G75_NEXT: Site = Site::new("G75Moves::next: stages");
/// `engine::g75`: the points of the rough and finishing contours (the
/// tail's legs and the public profile).
#[cfg(feature = "loop-counters")]
pub static G75_CONTOUR: Site = Site::new("g75: contour points");

/// Every site.
#[cfg(feature = "loop-counters")]
pub static SITES: [&Site; 22] = [
    &ISQRT_U128,
    &ISQRT_U64,
    &ISQRT_NEAR,
    &PASS_COUNT,
    &PLAN_NEXT,
    &G76_NEXT,
    &G92_NEXT,
    &GCD,
    &G32_VALIDATE,
    &REAL_LIMBS,
    &REAL_DIVMOD,
    &REAL_SERIES,
    &REAL_LN,
    &REAL_EXP,
    &REAL_ROOT,
    &G75_LAYERS,
    &G75_ROUGH_NEXT,
    &G75_NEXT,
    &G75_CONTOUR,
    &LCNC_PASSES,
    &LCNC_NEXT,
    &LCNC_ISQRT,
];

/// Clears every site's largest count.
#[cfg(feature = "loop-counters")]
pub fn reset() {
    for s in SITES {
        s.max.store(0, Ordering::Relaxed);
    }
}

/// Counts the iterations of one execution of a loop (not `const`: the
/// `const fn` kernels count in a local and their callers record).
#[derive(Debug)]
pub(crate) struct Count {
    #[cfg(feature = "loop-counters")]
    site: &'static Site,
    #[cfg(feature = "loop-counters")]
    n: u32,
}

impl Count {
    /// Starts counting for the loop `site`.
    #[cfg(feature = "loop-counters")]
    #[inline]
    pub(crate) fn new(site: &'static Site) -> Count {
        Count { site, n: 0 }
    }

    /// One more iteration.
    #[inline]
    pub(crate) fn tick(&mut self) {
        #[cfg(feature = "loop-counters")]
        {
            self.n = self.n.saturating_add(1);
        }
    }
}

#[cfg(feature = "loop-counters")]
impl Drop for Count {
    fn drop(&mut self) {
        self.site.record(self.n);
    }
}

/// A `Count` for `site` (the name of a `Site` static); without the
/// feature the site is not named, so it needs not exist.
macro_rules! count {
    ($site:ident) => {{
        #[cfg(feature = "loop-counters")]
        let c = $crate::loop_counters::Count::new(&$crate::loop_counters::$site);
        #[cfg(not(feature = "loop-counters"))]
        let c = $crate::loop_counters::Count {};
        c
    }};
}
pub(crate) use count;
