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
//! prunes the path). Every harness body starts with [`declare`], which
//! names all the covers the body may reach, also those inside branches;
//! [`cover`] records that a condition was satisfied, and refuses a message
//! that was not declared. An exhaustive run fails when a declared cover was
//! never satisfied (what `cargo kani` with uncoverable covers failing does:
//! see `.ci/kani-covers`), so no harness passes vacuously, not even through
//! a branch that is never taken; a sampled run reports every declared cover
//! with its count, zero included. A failing run's panic carries the
//! assertion's own message. Bodies must be deterministic given their
//! choices.

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
    /// Every sequence of choices like [`Mode::Exhaustive`], for a
    /// measurement rather than a proof: the covers are reported, not
    /// required (the unwind measurements of `proofs/tests/unwind.rs` run the
    /// worst cases of a window, where some covers cannot hold).
    Enumerate {
        /// Largest number of runs allowed.
        max_runs: u64,
    },
    /// This many runs in which every choice is drawn near an edge of its
    /// range: within 16 of its low end, within 16 of its high end, or, when
    /// the range holds 0, within 16 of 0, each a third of the time, from a
    /// fixed seed. The window's corners (every choice at an end) and its
    /// small values (where ties and exact cases live), which uniform
    /// samples of a wide range almost never draw.
    Edges {
        /// Number of runs.
        runs: u64,
        /// Seed of the generator.
        seed: u64,
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
    /// The most choices of more than one value that one run made: the
    /// symbolic words of the harness under Kani (a range of one value is a
    /// constant there, `verify::any_in`).
    pub symbolic: u64,
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
    edges: bool,
    /// Choices of more than one value in the current run.
    symbolic: u64,
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
/// `zero` is the offset of the value 0 when the range holds it (for
/// [`Mode::Edges`]); `word` is false for the low half of a 128-bit value,
/// which is one symbolic word with its high half.
fn choose(span: u64, zero: Option<u64>, word: bool) -> u64 {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        assert!(s.active, "shim::any_in called outside shim::check");
        if span > 0 && word {
            s.symbolic += 1;
        }
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
            let v = if s.edges {
                let r = splitmix(&mut s.rng);
                let near = (r >> 8) % 17;
                match r % 3 {
                    0 => near.min(span),
                    1 => span - near.min(span),
                    // Near 0, as an offset from the low end, when 0 is in
                    // range (the zero's offset is in `s.zero`), else uniform.
                    _ => match zero {
                        Some(z) => z.saturating_add(near).saturating_sub(8).min(span),
                        None => splitmix(&mut s.rng) % span.saturating_add(1).max(1),
                    },
                }
            } else if span == u64::MAX {
                splitmix(&mut s.rng)
            } else {
                splitmix(&mut s.rng) % (span + 1)
            };
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
    let zero = (lo <= 0 && 0 <= hi).then(|| lo.unsigned_abs());
    let off = choose(span, zero, true);
    // off <= span = hi - lo, so lo + off <= hi fits in i64.
    lo.wrapping_add_unsigned(off)
}

/// A value of `lo..=hi` over `u128`: `kani::any()` with `kani::assume`
/// under Kani. A span wider than `u64` is two choices (the high and the low
/// 64 bits), the values beyond the span pruned (as by `assume`).
pub fn any_u128_in(lo: u128, hi: u128) -> u128 {
    assert!(lo <= hi, "empty range {lo}..={hi}");
    lo + offset_u128(hi - lo, (lo == 0).then_some(0))
}

/// An offset in `0..=span`, `zero` the offset of the value 0 if in range.
fn offset_u128(span: u128, zero: Option<u128>) -> u128 {
    if let Ok(span) = u64::try_from(span) {
        u128::from(choose(span, zero.and_then(|z| u64::try_from(z).ok()), true))
    } else {
        #[allow(clippy::cast_possible_truncation)] // the low 64 bits, on purpose
        let (zero_high, zero_low) = (zero.map(|z| (z >> 64) as u64), zero.map(|z| z as u64));
        let high = u128::from(choose(u64::try_from(span >> 64).unwrap_or(u64::MAX), zero_high, true));
        let off = high << 64 | u128::from(choose(u64::MAX, zero_low, false));
        assume(off <= span);
        off
    }
}

/// A value of `lo..=hi` over `i128` ([`any_u128_in`] on the offsets).
pub fn any_i128_in(lo: i128, hi: i128) -> i128 {
    assert!(lo <= hi, "empty range {lo}..={hi}");
    let zero = (lo <= 0 && 0 <= hi).then(|| lo.unsigned_abs());
    lo.wrapping_add_unsigned(offset_u128(hi.abs_diff(lo), zero))
}

/// A `bool`.
pub fn any_bool() -> bool {
    choose(1, Some(0), true) == 1
}

/// Abandons the run when `cond` is false (`kani::assume`).
pub fn assume(cond: bool) {
    if !cond {
        std::panic::panic_any(Pruned);
    }
}

/// Declares the covers a harness body may reach (every `cover!` of the
/// body and of the functions it calls, also those in branches that a
/// domain may never take). Call it first in the body; Kani ignores it
/// (every `kani::cover` is a property there whether it is reached or not).
pub fn declare(covers: &[&'static str]) {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        if s.active {
            for &c in covers {
                s.covers.entry(c).or_insert(0);
            }
        }
    });
}

/// Records that `cond` was reachable (`kani::cover`): [`check`] fails when a
/// declared cover was never satisfied in an exhaustive run.
///
/// # Panics
///
/// When `msg` was not [`declare`]d by the body (the declaration must list
/// every cover, so that a cover that is never reached still counts).
pub fn cover(cond: bool, msg: &'static str) {
    let declared = STATE.with(|s| {
        let mut s = s.borrow_mut();
        if !s.active {
            return true;
        }
        match s.covers.get_mut(msg) {
            Some(n) => {
                if cond {
                    *n += 1;
                }
                true
            }
            None => false,
        }
    });
    assert!(declared, "cover {msg:?} is not declared by the harness (shim::declare)");
}

/// The message of a panic payload (`panic!`/`assert!` with a message).
fn message(payload: &(dyn std::any::Any + Send)) -> &str {
    if let Some(s) = payload.downcast_ref::<String>() {
        s
    } else if let Some(s) = payload.downcast_ref::<&'static str>() {
        s
    } else {
        "a panic without a message"
    }
}

/// Runs `body` in `mode` and returns what it saw.
///
/// # Panics
///
/// When the body fails an assertion (with the choices of the failing run
/// and the assertion's own message), when an exhaustive domain exceeds its
/// run budget, or when a declared [`cover`] was never satisfied in an
/// exhaustive run.
pub fn check(name: &str, mode: Mode, body: impl Fn()) -> Report {
    let mut report = Report::default();
    STATE.with(|s| {
        *s.borrow_mut() = State {
            active: true,
            exhaustive: matches!(mode, Mode::Exhaustive { .. } | Mode::Enumerate { .. }),
            edges: matches!(mode, Mode::Edges { .. }),
            rng: match mode {
                Mode::Sample { seed, .. } | Mode::Edges { seed, .. } => seed,
                Mode::Exhaustive { .. } | Mode::Enumerate { .. } => 0,
            },
            ..State::default()
        }
    });
    quiet_pruning();
    let outcome = catch_unwind(AssertUnwindSafe(|| loop {
        STATE.with(|s| {
            let mut s = s.borrow_mut();
            s.next = 0;
            s.symbolic = 0;
            if !s.exhaustive {
                s.trail.clear();
            }
        });
        let run = catch_unwind(AssertUnwindSafe(&body));
        report.runs += 1;
        report.symbolic = report.symbolic.max(STATE.with(|s| s.borrow().symbolic));
        if let Err(payload) = run {
            if payload.downcast_ref::<Pruned>().is_some() {
                report.pruned += 1;
            } else {
                let trail: Vec<u64> = STATE.with(|s| s.borrow().trail.iter().map(|c| c.value).collect());
                let why = message(payload.as_ref());
                panic!("{name}: the harness failed at run {} with choices {trail:?}: {why}", report.runs);
            }
        }
        let more = match mode {
            Mode::Sample { runs, .. } | Mode::Edges { runs, .. } => report.runs < runs,
            Mode::Exhaustive { max_runs } | Mode::Enumerate { max_runs } => {
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
    // Exhaustive: every declared cover must be satisfied in the domain (as
    // `cargo kani` is run: an unsatisfiable or unreachable cover fails).
    // Sampled: rare covers may be missed by chance, so only the non-vacuity
    // above is required; every declared cover is reported with its count.
    if matches!(mode, Mode::Exhaustive { .. }) {
        let missed: Vec<_> = report.covers.iter().filter(|(_, n)| **n == 0).map(|(m, _)| *m).collect();
        assert!(missed.is_empty(), "{name}: cover conditions never satisfied: {missed:?}");
    }
    report
}

/// [`check`], then one line on standard error with what it saw: `name`,
/// the runs, the pruned runs and each cover's count (what the test binaries
/// print after every check, `cargo test -- --nocapture` to see it).
///
/// # Panics
///
/// As [`check`].
pub fn check_and_print(name: &str, mode: Mode, body: impl Fn()) -> Report {
    let r = check(name, mode, body);
    eprintln!("{name}: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
    r
}

/// Runs one harness body on the real engine (`control`) and on an engine
/// broken on purpose (`mutant`), both in `mode`: the control must pass (so
/// every declared cover is satisfied in an exhaustive mode), the mutant
/// must fail with `expected` in the failing assertion's own message, not
/// merely in the check's name, which every failure carries. Returns the
/// control's report.
///
/// # Panics
///
/// When the control fails, the mutant passes, or the mutant fails another
/// assertion than the one `expected` names.
pub fn caught(mode: Mode, control: impl Fn(), mutant: impl Fn(), expected: &str) -> Report {
    let report = check("control", mode, control);
    let failure = catch_unwind(AssertUnwindSafe(|| check("mutant", mode, mutant)))
        .expect_err("the harness must catch the mutant");
    let text = message(failure.as_ref());
    let (head, why) = text.split_once("]: ").unwrap_or((text, ""));
    assert!(head.starts_with("mutant: the harness failed at run"), "not a failing run: {text}");
    assert!(why.contains(expected), "caught by another check than {expected:?}: {text}");
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
            declare(&["eight"]);
            let a = any_in(0, 9);
            assume(a % 2 == 0);
            cover(a == 8, "eight");
        });
        assert_eq!((r.runs, r.pruned, r.covers["eight"]), (10, 5, 1));
    }

    #[test]
    #[should_panic(expected = "never satisfied: [\"impossible\"]")]
    fn unreachable_cover_fails() {
        check("vacuous", Mode::Exhaustive { max_runs: 50 }, || {
            declare(&["impossible"]);
            let a = any_in(0, 9);
            cover(a > 9, "impossible");
        });
    }

    #[test]
    #[should_panic(expected = "never satisfied: [\"in a branch never taken\"]")]
    fn a_cover_in_a_branch_never_taken_fails() {
        check("untaken", Mode::Exhaustive { max_runs: 50 }, || {
            declare(&["in a branch never taken", "reached"]);
            let a = any_in(0, 9);
            cover(true, "reached");
            if a > 9 {
                cover(true, "in a branch never taken");
            }
        });
    }

    #[test]
    #[should_panic(expected = "cover \"stray\" is not declared")]
    fn an_undeclared_cover_fails() {
        check("undeclared", Mode::Exhaustive { max_runs: 50 }, || {
            let a = any_in(0, 3);
            cover(a == 1, "stray");
        });
    }

    #[test]
    fn a_sample_reports_every_declared_cover() {
        let r = check("sampled", Mode::Sample { runs: 20, seed: 1 }, || {
            declare(&["never", "always"]);
            let a = any_in(0, 9);
            cover(a > 9, "never");
            cover(a <= 9, "always");
        });
        assert_eq!((r.covers["never"], r.covers["always"]), (0, 20));
    }

    #[test]
    fn a_failure_carries_the_assertion_text_and_the_choices() {
        let failure = catch_unwind(|| {
            check("fails", Mode::Exhaustive { max_runs: 100 }, || {
                let a = any_in(0, 9);
                let b = any_in(0, 1);
                assert!(a != 7 || b != 1, "seven and one together");
            })
        })
        .expect_err("the harness must fail");
        // Runs in order (a, b): (0,0) (0,1) (1,0) ... (7,1) is the 16th.
        assert_eq!(
            message(failure.as_ref()),
            "fails: the harness failed at run 16 with choices [7, 1]: seven and one together"
        );
    }

    #[test]
    fn edges_draw_near_the_ends_and_zero_and_words_are_counted() {
        let seen = RefCell::new(std::collections::BTreeSet::new());
        let r = check("edges", Mode::Edges { runs: 3_000, seed: 3 }, || {
            let a = any_in(-1_000, 1_000);
            let fixed = any_in(4, 4);
            let b = any_i128_in(i128::MIN, i128::MAX);
            seen.borrow_mut().insert((a, fixed, b));
        });
        let seen = seen.into_inner();
        let a: std::collections::BTreeSet<i64> = seen.iter().map(|v| v.0).collect();
        // Within 16 of -1 000, of 0 and of 1 000, the ends themselves too.
        assert!(a.iter().all(|v| (v + 1_000) <= 16 || v.abs() <= 16 || 1_000 - v <= 16), "{a:?}");
        assert!(a.contains(&-1_000) && a.contains(&0) && a.contains(&1_000), "{a:?}");
        assert!(seen.iter().all(|v| v.1 == 4));
        assert!(seen.iter().any(|v| v.2 == i128::MIN) && seen.iter().any(|v| v.2 == 0));
        // Two ranges of more than one value, the 128-bit one drawn in two
        // halves: two symbolic words.
        assert_eq!(r.symbolic, 2);
    }

    #[test]
    #[should_panic(expected = "more than 5 runs")]
    fn budget_is_enforced() {
        check("big", Mode::Exhaustive { max_runs: 5 }, || {
            let _ = any_in(0, 9);
        });
    }
}
