//! The LinuxCNC G76 harnesses (`cycleref_proofs::linuxcnc`) under `cargo
//! test`: each over its Kani window exhaustively (every declared cover
//! satisfied) and sampled over a wider window; the loops they reach against
//! their unwind bounds; and, for each harness, engines broken on purpose in
//! the way its property forbids, each beside a control run of the real
//! engine over the same domain (the pattern of `mutants.rs`).

use std::cell::Cell;
use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};

use cycleref::linuxcnc::LinuxCncG76;
use cycleref::loop_counters::{self, SITES};
use cycleref::{CycleError, Motion, Move, PassKind, Point, Role};
use cycleref_proofs::linuxcnc::{
    lcnc_depth_monotonicity, lcnc_pass_moves, lcnc_spring_passes, lcnc_termination, LcncDomain,
};
use cycleref_proofs::shim::{check, Mode, Report};
use cycleref_proofs::windows::{unwind, LCNC_DEPTH_WINDOW, LCNC_PASS_WINDOW, LCNC_SPRING_WINDOW};

type Moves = std::vec::IntoIter<Move>;
type Engine<'a> = &'a dyn Fn(&LinuxCncG76) -> Result<Moves, CycleError>;
type Harness = fn(&LcncDomain, &dyn Fn(&LinuxCncG76) -> Result<Moves, CycleError>);

fn real(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    cycleref::expand_linuxcnc(c).map(Iterator::collect)
}

/// The real engine through the same adapter as the mutants.
fn control(c: &LinuxCncG76) -> Result<Moves, CycleError> {
    real(c).map(Vec::into_iter)
}

/// A wider window, sampled: J ≤ 20, K ≤ 60, R = p/q up to 3 with q ≤ 4,
/// |I| ≤ 50, X₀ within ±100, threads up to 200 long, every angle, H up to
/// 3, E up to 50 with every L, pass limit 40.
const WIDE: LcncDomain = LcncDomain {
    initial_depth: (1, 20),
    extra_depth: (1, 40),
    denominator: (1, 4),
    max_degression: 3,
    peak_offset: (1, 50),
    x0: (-100, 100),
    length: (1, 200),
    angle: (0, 3),
    spring_passes: (-1, 3),
    taper_distance: (0, 50),
    taper_bits: (0, 3),
    diameter: (0, 1),
    internal: (0, 1),
    towards_plus: (0, 1),
    pass_limit: 40,
};

const SAMPLE: Mode = Mode::Sample { runs: 3_000, seed: 0x6c63_6e63 };

fn exhaustive(name: &str, window: &LcncDomain, harness: Harness, max_runs: u64) -> Report {
    let r = check(name, Mode::Exhaustive { max_runs }, || harness(window, &control));
    eprintln!("{name}: {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
    r
}

fn sampled(name: &str, harness: Harness) {
    let r = check(name, SAMPLE, || harness(&WIDE, &control));
    eprintln!("{name} (sampled): {} runs, {} pruned, covers {:?}", r.runs, r.pruned, r.covers);
}

fn p1(d: &LcncDomain, e: Engine<'_>) {
    lcnc_depth_monotonicity(d, &e);
}
fn p2(d: &LcncDomain, e: Engine<'_>) {
    lcnc_termination(d, &e);
}
fn p3(d: &LcncDomain, e: Engine<'_>) {
    lcnc_spring_passes(d, &e);
}
fn p4(d: &LcncDomain, e: Engine<'_>) {
    lcnc_pass_moves(d, &e);
}

#[test]
fn depth_monotonicity_over_its_window() {
    let r = exhaustive("lcnc_depth_monotonicity", &LCNC_DEPTH_WINDOW, p1, 100_000);
    assert_eq!(r.runs, 17_316);
    sampled("lcnc_depth_monotonicity", p1);
}

#[test]
fn termination_over_its_window() {
    let r = exhaustive("lcnc_termination", &LCNC_DEPTH_WINDOW, p2, 100_000);
    assert_eq!(r.runs, 17_316);
    sampled("lcnc_termination", p2);
}

#[test]
fn spring_passes_over_their_window() {
    let r = exhaustive("lcnc_spring_passes", &LCNC_SPRING_WINDOW, p3, 200_000);
    assert!(r.runs > 0);
    sampled("lcnc_spring_passes", p3);
}

#[test]
fn pass_moves_over_their_window() {
    let r = exhaustive("lcnc_pass_moves", &LCNC_PASS_WINDOW, p4, 200_000);
    assert!(r.runs > 0);
    sampled("lcnc_pass_moves", p4);
}

/// The counts are process-wide: the measurement runs alone.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn lock() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// The largest count of every engine loop, and the most moves of one
/// cycle, when `harness` runs over every input of `window`.
fn maxima(name: &str, window: &LcncDomain, harness: Harness) -> BTreeMap<&'static str, u32> {
    loop_counters::reset();
    let most = Cell::new(0_u32);
    let counting = |c: &LinuxCncG76| {
        real(c).map(|v| {
            most.set(most.get().max(u32::try_from(v.len()).unwrap_or(u32::MAX)));
            v.into_iter()
        })
    };
    check(name, Mode::Enumerate { max_runs: 200_000 }, || harness(window, &counting));
    let mut m: BTreeMap<&'static str, u32> = SITES.iter().map(|s| (s.name, s.max())).collect();
    m.insert("harness: moves of one cycle", most.get());
    m
}

/// Every loop a harness reaches in its window runs fewer times than the
/// harness's `#[kani::unwind]`: the engine's (`cycleref::loop_counters`)
/// and the harness's own loop over the moves. The harness's other loops
/// are shorter: [`cycleref_proofs::linuxcnc::pow`] runs p ≤ 12 times, the
/// exact-root search n ≤ 12, a pass holds at most 6 moves.
#[test]
fn every_loop_stays_below_its_unwind_bound() {
    let _one = lock();
    let cases: [(&str, &LcncDomain, Harness); 4] = [
        ("lcnc_depth_monotonicity", &LCNC_DEPTH_WINDOW, p1),
        ("lcnc_termination", &LCNC_DEPTH_WINDOW, p2),
        ("lcnc_spring_passes", &LCNC_SPRING_WINDOW, p3),
        ("lcnc_pass_moves", &LCNC_PASS_WINDOW, p4),
    ];
    for (name, window, harness) in cases {
        let m = maxima(name, window, harness);
        let bound = unwind(name);
        eprintln!("{name}: unwind {bound}, loop maxima {m:?}");
        for (site, &n) in &m {
            // The harness's loop over the moves runs once more than the moves.
            let runs = if site.starts_with("harness") { n + 1 } else { n };
            assert!(runs < bound, "{name}: {site} runs {runs} times, unwind bound {bound}");
        }
    }
}
