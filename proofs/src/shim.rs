//! A stand-in for Kani's `any`, `assume` and `cover` that runs the same
//! harness bodies under `cargo test`.
//!
//! Under `cargo kani` (cfg `kani`) the harnesses call the real `kani` crate
//! and the solver covers every input at once. Here the [`check`] driver runs
//! a harness body many times:
//!
//! * [`Mode::Exhaustive`] enumerates every sequence of choices the body
//!   makes (small-scope checking): each [`any_in`] is a choice point, and
//!   the driver walks all of them depth first, so dependent domains (a
//!   range that depends on an earlier choice) are enumerated exactly;
//! * [`Mode::Sample`] draws each choice uniformly at random from its range
//!   (a fixed seed, so a failure can be replayed), over the full documented
//!   ranges that the solver would cover.
//!
//! [`assume`] with a false condition abandons the current run (as Kani
//! prunes the path); [`cover`] records that a condition was reachable, and
//! the driver fails if a cover was never satisfied, so no harness passes
//! vacuously. Bodies must be deterministic given their choices.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// How [`check`] drives a harness.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Every sequence of choices, up to this many runs (the driver fails if
    /// the domain is larger, so a domain never silently shrinks).
    Exhaustive {
        /// Largest number of runs allowed.
        max_runs: u64,
    },
    /// This many runs with random choices from a fixed seed.
    Sample {
        /// Number of runs.
        runs: u64,
        /// Seed of the generator.
        seed: u64,
    },
}

/// What [`check`] saw.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Report {
    /// Runs of the body.
    pub runs: u64,
    /// Runs abandoned by a false [`assume`].
    pub pruned: u64,
    /// Each cover message and how many runs satisfied it.
    pub covers: BTreeMap<&'static str, u64>,
}

struct Choice {
    value: u64,
    hi: u64,
}

#[derive(Default)]
struct State {
    active: bool,
    exhaustive: bool,
    /// Choices of the current run (exhaustive: replayed prefix + new ones).
    trail: Vec<Choice>,
    /// Position in `trail` of the next choice.
    next: usize,
    rng: u64,
    covers: BTreeMap<&'static str, u64>,
}

thread_local! {
    static STATE: RefCell<State> = RefCell::new(State::default());
}

/// Payload of the panic that abandons a run on a false [`assume`].
struct Pruned;

fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A value in `lo..=hi` (as `u64` offsets): the next choice of the run.
fn choose(span: u64) -> u64 {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        assert!(s.active, "shim::any_in called outside shim::check");
        if s.exhaustive {
            let i = s.next;
            s.next += 1;
            if i < s.trail.len() {
                s.trail[i].value
            } else {
                s.trail.push(Choice { value: 0, hi: span });
                0
            }
        } else {
            let v = if span == u64::MAX { splitmix(&mut s.rng) } else { splitmix(&mut s.rng) % (span + 1) };
            // Recorded so that a failure can report the run's choices.
            s.trail.push(Choice { value: v, hi: span });
            v
        }
    })
}

/// A value of `lo..=hi`: `kani::any()` with `kani::assume(lo <= v && v <=
/// hi)` under Kani.
pub fn any_in(lo: i64, hi: i64) -> i64 {
    assert!(lo <= hi, "empty range {lo}..={hi}");
    let span = hi.abs_diff(lo);
    let off = choose(span);
    // off <= span = hi - lo, so lo + off <= hi fits in i64.
    lo.wrapping_add_unsigned(off)
}

/// A `bool`.
pub fn any_bool() -> bool {
    choose(1) == 1
}

/// Abandons the run when `cond` is false (`kani::assume`).
pub fn assume(cond: bool) {
    if !cond {
        std::panic::panic_any(Pruned);
    }
}

/// Records that `cond` was reachable (`kani::cover`): [`check`] fails when a
/// cover message was never satisfied.
pub fn cover(cond: bool, msg: &'static str) {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        let n = s.covers.entry(msg).or_insert(0);
        if cond {
            *n += 1;
        }
    });
}

/// Runs `body` in `mode` and returns what it saw.
///
/// # Panics
///
/// When the body fails an assertion (with the choices of the failing run
/// in the message), when an exhaustive domain exceeds its run budget, or
/// when a [`cover`] was never satisfied.
pub fn check(name: &str, mode: Mode, body: impl Fn()) -> Report {
    let mut report = Report::default();
    STATE.with(|s| {
        *s.borrow_mut() = State {
            active: true,
            exhaustive: matches!(mode, Mode::Exhaustive { .. }),
            rng: match mode {
                Mode::Sample { seed, .. } => seed,
                Mode::Exhaustive { .. } => 0,
            },
            ..State::default()
        }
    });
    quiet_pruning();
    let outcome = catch_unwind(AssertUnwindSafe(|| loop {
        STATE.with(|s| {
            let mut s = s.borrow_mut();
            s.next = 0;
            if !s.exhaustive {
                s.trail.clear();
            }
        });
        let run = catch_unwind(AssertUnwindSafe(&body));
        report.runs += 1;
        if let Err(payload) = run {
            if payload.downcast_ref::<Pruned>().is_some() {
                report.pruned += 1;
            } else {
                let trail: Vec<u64> = STATE.with(|s| s.borrow().trail.iter().map(|c| c.value).collect());
                panic!("{name}: the harness failed at run {} with choices {trail:?}", report.runs);
            }
        }
        let more = match mode {
            Mode::Sample { runs, .. } => report.runs < runs,
            Mode::Exhaustive { max_runs } => {
                let advanced = STATE.with(|s| {
                    let mut s = s.borrow_mut();
                    // The choices beyond the ones this run made are stale.
                    let used = s.next;
                    s.trail.truncate(used);
                    while let Some(last) = s.trail.last_mut() {
                        if last.value < last.hi {
                            last.value += 1;
                            return true;
                        }
                        s.trail.pop();
                    }
                    false
                });
                if advanced {
                    assert!(report.runs < max_runs, "{name}: the domain has more than {max_runs} runs");
                }
                advanced
            }
        };
        if !more {
            break;
        }
    }));
    let covers = STATE.with(|s| {
        let mut s = s.borrow_mut();
        s.active = false;
        std::mem::take(&mut s.covers)
    });
    if let Err(p) = outcome {
        std::panic::resume_unwind(p);
    }
    report.covers = covers;
    assert!(report.pruned < report.runs, "{name}: every run was pruned by assume: the check is vacuous");
    // Exhaustive: every cover must be reachable in the domain (Kani reports
    // an unsatisfiable cover). Sampled: rare covers may be missed by chance,
    // so only the non-vacuity above is required; the counts are reported.
    if matches!(mode, Mode::Exhaustive { .. }) {
        let missed: Vec<_> = report.covers.iter().filter(|(_, n)| **n == 0).map(|(m, _)| *m).collect();
        assert!(missed.is_empty(), "{name}: cover conditions never satisfied: {missed:?}");
    }
    report
}

/// Installs, once, a panic hook that stays silent for the [`assume`]
/// pruning panics and defers to the previous hook for every other panic.
fn quiet_pruning() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if info.payload().downcast_ref::<Pruned>().is_none() {
                previous(info);
            }
        }));
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exhaustive_enumerates_dependent_domains_exactly() {
        let seen = RefCell::new(Vec::new());
        let r = check("pairs", Mode::Exhaustive { max_runs: 100 }, || {
            let a = any_in(0, 3);
            let b = any_in(0, a);
            seen.borrow_mut().push((a, b));
        });
        // (0,0) (1,0) (1,1) (2,0..2) (3,0..3): 1 + 2 + 3 + 4 = 10 runs.
        assert_eq!(r.runs, 10);
        let mut v = seen.into_inner();
        v.sort_unstable();
        v.dedup();
        assert_eq!(v.len(), 10);
    }

    #[test]
    fn assume_prunes_and_cover_counts() {
        let r = check("prune", Mode::Exhaustive { max_runs: 100 }, || {
            let a = any_in(0, 9);
            assume(a % 2 == 0);
            cover(a == 8, "eight");
        });
        assert_eq!((r.runs, r.pruned, r.covers["eight"]), (10, 5, 1));
    }

    #[test]
    #[should_panic(expected = "never satisfied")]
    fn unreachable_cover_fails() {
        check("vacuous", Mode::Exhaustive { max_runs: 50 }, || {
            let a = any_in(0, 9);
            cover(a > 9, "impossible");
        });
    }

    #[test]
    #[should_panic(expected = "the harness failed")]
    fn failures_are_reported() {
        check("fails", Mode::Exhaustive { max_runs: 100 }, || {
            let a = any_in(0, 9);
            assert!(a != 7);
        });
    }

    #[test]
    #[should_panic(expected = "more than 5 runs")]
    fn budget_is_enforced() {
        check("big", Mode::Exhaustive { max_runs: 5 }, || {
            let _ = any_in(0, 9);
        });
    }
}
