//! The depth schedule one step at a time (`cycleref_proofs::schedule`):
//! exhaustively over a small window, sampled at large values, against
//! schedules broken on purpose (with the real schedule as their control),
//! and the engine's up-front pass count against the closed form of the
//! minimum-cut phase.

use cycleref::engine::schedule::Schedule;
use cycleref::G76Cycle;
use cycleref_proofs::harness::PLAIN_CYCLE;
use cycleref_proofs::schedule::{schedule_step, ScheduleDomain};
use cycleref_proofs::shim::{self, check_and_print as check, Mode};

/// The exhaustive window: Δd ≤ 20, Δdmin ≤ 3, k - d ≤ 40, every depth ≤
/// k - d, every level ≤ the depth, both phases (1 974 560 states; the
/// ones that satisfy the invariant are stepped).
pub const WINDOW: ScheduleDomain =
    ScheduleDomain { first_depth: (1, 20), min_cut: (0, 3), last: (0, 40), depth: (0, 40), level: (0, 40) };

const REAL: fn(&mut Schedule) -> Option<i64> = Schedule::next_level;

#[test]
fn every_step_of_the_window() {
    let r =
        check("schedule step", Mode::Exhaustive { max_runs: 2_000_000 }, || schedule_step(&WINDOW, &REAL));
    assert_eq!(r.runs, 1_974_560);
}

/// splitmix64, for the sampled states.
fn next(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A value in `lo..=hi`.
fn pick(state: &mut u64, lo: i64, hi: i64) -> i64 {
    lo + i64::try_from(next(state) % (hi - lo + 1).unsigned_abs()).unwrap_or(0)
}

/// States at large values: a random state satisfying the invariant is too
/// rare to draw, so each sample fixes Δd, Δdmin, k - d and n at random
/// (Δd, Δdmin, k - d up to 999 999 999, n ≤ Δd², Δd √n ≤ 999 999 999) and enumerates the depths
/// within 2 below and 4 above `Δd √n` (from `f64`, a hint only: the
/// harness checks every state by its squares) in both phases: the law
/// state and, where the last step of the law is below m, minimum-cut
/// states. Returns the steps taken (states that satisfy the invariant).
fn sampled(samples: u32, seed: u64, step: &dyn Fn(&mut Schedule) -> Option<i64>) -> u64 {
    let mut rng = seed;
    let mut stepped = 0;
    let mut covers = std::collections::BTreeMap::new();
    for _ in 0..samples {
        let scale = [30, 1_000, 1_000_000, 999_999_999][usize::try_from(next(&mut rng) % 4).unwrap_or(0)];
        let q = pick(&mut rng, 1, scale);
        // Δd √n ≤ 999 999 999 (a depth within k - d's range).
        let n = pick(&mut rng, 1, (q * q).min((999_999_999 / q).pow(2)));
        #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
        let hint = (q as f64 * (n as f64).sqrt()).round() as i64;
        // Half the samples with a small Δdmin (law levels beyond D + m),
        // half with any Δdmin ≤ Δd; k - d near the depth (the end) or far.
        let small = next(&mut rng) % 2 == 0;
        let min_cut = pick(&mut rng, 0, if small { 3 } else { q });
        let reach = if next(&mut rng) % 2 == 0 { 6 } else { 2 * q + 6 };
        let last = pick(&mut rng, (hint - 2).max(n), (hint + reach).min(999_999_999)).max(0);
        let d = ScheduleDomain {
            first_depth: (q, q),
            min_cut: (min_cut, min_cut),
            last: (last, last),
            depth: ((hint - 2).max(0), hint + 4),
            level: (n, n),
        };
        let r = shim::check("schedule step (sampled)", Mode::Enumerate { max_runs: 100 }, || {
            schedule_step(&d, &step);
        });
        stepped += r.runs - r.pruned;
        for (c, k) in r.covers {
            *covers.entry(c).or_insert(0) += k;
        }
    }
    eprintln!("schedule step (sampled): {samples} samples, {stepped} states stepped, covers {covers:?}");
    stepped
}

#[test]
fn sampled_steps_at_large_values() {
    assert!(sampled(20_000, 0x7363_6865_6475_6c65, &REAL) > 20_000);
}

/// An external D0 thread of k, Δd, Δdmin, d (metric IS-B, radius X).
fn cycle(k: i64, first_depth: i64, min_cut: i64, finishing_allowance: i64) -> G76Cycle {
    G76Cycle { thread_height: k, first_depth, min_cut, finishing_allowance, ..PLAIN_CYCLE }
}

/// The engine's up-front count (`rough_pass_count`, D0: one pass per
/// level) is the levels the schedule makes, and the minimum-cut phase
/// makes `ceil((k - d - D) / m)` of them from the depth D where it takes
/// over: every Δd ≤ 20, Δdmin ≤ 4, k ≤ 40, d ≤ k (the engine's count where Δdmin ≤ k, as `validate()` requires).
#[test]
fn pass_count_is_the_closed_form() {
    let mut switched = 0;
    for q in 1..=20 {
        for min_cut in 0..=4 {
            for k in 1..=40 {
                for d in 0..=k {
                    let last = k - d;
                    let m = min_cut.max(1);
                    let mut s = Schedule::resume(q, min_cut, last, 0, 0, false).expect("in range");
                    let (mut levels, mut from) = (0_i64, None);
                    let mut depth = 0;
                    while let Some(next) = s.next_level() {
                        if s.min_phase() && from.is_none() {
                            from = Some((levels, depth));
                        }
                        levels += 1;
                        depth = next;
                    }
                    assert_eq!(depth, last);
                    if let Some((before, at)) = from {
                        switched += 1;
                        assert_eq!(
                            levels - before,
                            (last - at + m - 1) / m,
                            "Δd {q}, Δdmin {min_cut}, k - d {last}"
                        );
                    }
                    if min_cut <= k {
                        let c = cycle(k, q, min_cut, d);
                        let count = cycleref::engine::rough_pass_count(&c).expect("a valid cycle");
                        assert_eq!(count, levels.unsigned_abs(), "{c:?}");
                    }
                }
            }
        }
    }
    assert!(switched > 10_000, "{switched}");
}

/// The mutants' window: Δd ≤ 12, k - d ≤ 30 (523 776 states; every cover
/// satisfied on the real schedule).
const MUTANT_WINDOW: ScheduleDomain = ScheduleDomain { first_depth: (1, 12), last: (0, 30), ..WINDOW };

/// `mutant` must fail the harness on `expected` over the window where the
/// real schedule passes.
fn caught(mutant: impl Fn(&mut Schedule) -> Option<i64>, expected: &str) {
    let mode = Mode::Exhaustive { max_runs: 523_776 };
    let w = MUTANT_WINDOW;
    let r = shim::caught(mode, || schedule_step(&w, &REAL), || schedule_step(&w, &mutant), expected);
    eprintln!("control: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
}

/// The real step, then `f(before, after, depth)` may replace the state and
/// the depth it returns.
fn after(
    f: impl Fn(Schedule, Schedule, i64) -> Option<(Schedule, i64)>,
) -> impl Fn(&mut Schedule) -> Option<i64> {
    move |s| {
        let before = *s;
        let next = s.next_level()?;
        match f(before, *s, next) {
            Some((changed, depth)) => {
                *s = changed;
                Some(depth)
            }
            None => Some(next),
        }
    }
}

#[test]
fn a_repeated_level_is_caught() {
    // The second level cut again at the first level's depth.
    caught(
        after(|before, s, _| {
            (s.level() == 2)
                .then(|| (s.with_state(2, before.depth(), s.min_phase()).expect("in range"), before.depth()))
        }),
        "the depth strictly increases from level to level",
    );
}

#[test]
fn a_minimum_cut_phase_of_one_increment_is_caught() {
    // Once the minimum cut has taken over, each level adds one increment
    // instead of m = max(Δdmin, 1).
    caught(
        after(|before, s, _| {
            (s.min_phase() && before.depth() + 1 < s.depth()).then(|| {
                let depth = before.depth() + 1;
                (s.with_state(s.level(), depth, true).expect("in range"), depth)
            })
        }),
        "every cut is at least m = max(Δdmin, 1), or what remains to k - d",
    );
}

#[test]
fn a_law_level_off_by_one_is_caught() {
    // A level by the law one increment deeper than round(Δd √n).
    caught(
        after(|before, s, next| {
            (!s.min_phase() && next > before.depth() + 1).then(|| {
                let depth = next + 1;
                s.with_state(s.level(), depth, false).map(|t| (t, depth))
            })?
        }),
        "D(n) = min(k - d, max(round(Δd √n), D(n-1) + m))",
    );
}

#[test]
fn a_schedule_past_k_minus_d_is_caught() {
    // The last level reported one increment beyond k - d.
    caught(
        after(|_, s, next| {
            // The state cannot hold a depth beyond k - d: it stays at k - d.
            let at_the_end = s.with_state(s.level(), next + 1, s.min_phase()).is_none();
            at_the_end.then_some((s, next + 1))
        }),
        "no level deeper than k - d",
    );
}
