//! The unwind bounds of the Kani harnesses, checked here: every loop a
//! harness reaches must run fewer times than its `#[kani::unwind(N)]`
//! (Kani unrolls N times and fails its unwinding assertion otherwise).
//!
//! The engine's loops count their iterations (`cycleref::loop_counters`,
//! feature `loop-counters`, on for this crate's tests); the harness's own
//! loops run over the moves of one cycle, so an engine wrapper counts the
//! moves each expansion yields. Each harness runs over its Kani window
//! (`cycleref_proofs::windows`): sampled over the whole window, and
//! exhaustively over the window's worst cases, chosen by this argument: a
//! G76 cycle has at most 6 moves per pass and start (approach, lead-in,
//! cut, run-out, retract, return), and the
//! most rough passes are made with the largest k - d and the smallest cuts
//! (Δd ≤ 2, Δdmin ≤ 1) in D2; the other words change coordinates and which
//! moves are left out as empty (R-ZERO), never the number of passes. The
//! engine's own loops are bounded by the passes (the level count), by the
//! path steps of one pass, or by the input's magnitude (Newton, Stein),
//! which the worst cases and samples span. The G75.1 harnesses count the
//! G75.1 engine's loops too (iterator stages, roughing steps, the layers
//! of the peck count, contour points, and `engine::real`'s limb loops,
//! bit-by-bit division and Taylor series): enumerated at the window's
//! deepest, widest grooves with the smallest pecks and steps, and, for
//! `groove_no_panic`, at the most layers its window allows and the largest
//! grooves.
//!
//! The counts are process-wide: the measuring tests take one lock, so one
//! measures at a time.

use std::cell::Cell;
use std::collections::BTreeMap;
use std::rc::Rc;
use std::sync::Mutex;

use cycleref::loop_counters::{self, SITES};
use cycleref::{CycleError, G76Cycle, Move};
use cycleref_proofs::harness::{self, Domain, Engine};
use cycleref_proofs::shim::{self, Mode};
use cycleref_proofs::windows::{self, unwind};

/// The real engine, counting the moves of each expansion.
struct Counted {
    moves: Rc<Cell<u32>>,
}

struct CountedMoves {
    inner: cycleref::G76Moves,
    n: u32,
    max: Rc<Cell<u32>>,
}

impl Iterator for CountedMoves {
    type Item = Move;
    fn next(&mut self) -> Option<Move> {
        let m = self.inner.next();
        if m.is_some() {
            self.n += 1;
        }
        m
    }
}

impl Drop for CountedMoves {
    fn drop(&mut self) {
        self.max.set(self.max.get().max(self.n));
    }
}

impl Engine for Counted {
    type Moves = CountedMoves;
    fn expand(&self, c: &G76Cycle) -> Result<CountedMoves, CycleError> {
        cycleref::expand_g76(c).map(|inner| CountedMoves { inner, n: 0, max: Rc::clone(&self.moves) })
    }
}

/// The largest loop counts of one harness: each engine site and the moves.
#[derive(Default)]
struct Maxima(BTreeMap<&'static str, u32>);

impl Maxima {
    fn take(&mut self, moves: u32) {
        for s in SITES {
            let e = self.0.entry(s.name).or_insert(0);
            *e = (*e).max(s.max());
        }
        let e = self.0.entry("harness: moves of one cycle").or_insert(0);
        *e = (*e).max(moves);
    }

    /// Fails when a loop reaches the harness's bound; returns the largest count.
    fn check(&self, harness: &str) -> u32 {
        self.check_against(harness, unwind(harness))
    }

    fn check_against(&self, harness: &str, bound: u32) -> u32 {
        eprintln!("{harness}: unwind {bound}, loop maxima {:?}", self.0);
        for (site, &n) in &self.0 {
            assert!(n < bound, "{harness}: {site} runs {n} times, unwind bound {bound}");
        }
        self.0.values().copied().max().unwrap_or(0)
    }
}

/// Runs `body` with the counting engine in `mode` and adds the counts.
fn measure(maxima: &mut Maxima, name: &str, mode: Mode, body: impl Fn(&Counted)) {
    loop_counters::reset();
    let e = Counted { moves: Rc::new(Cell::new(0)) };
    let r = shim::check(name, mode, || body(&e));
    eprintln!("  {name}: {} runs, {} pruned", r.runs, r.pruned);
    maxima.take(e.moves.get());
}

const SAMPLE: Mode = Mode::Sample { runs: 20_000, seed: 0x756e_7769_6e64 };

/// The worst cases of a G76 window (see the module docs): the largest k,
/// d ≤ 1, the smallest cuts, the most finishing passes and starts, every
/// infeed mode, side, direction, taper, run-out kind and unit code.
fn worst(w: &Domain) -> Domain {
    Domain {
        height: (w.height.1, w.height.1),
        first_depth: (w.first_depth.0, w.first_depth.0 + 1),
        min_cut: (w.min_cut.0, w.min_cut.0 + 1),
        allowance: (w.allowance.0, w.allowance.0 + 1),
        finishing: (w.finishing.1, w.finishing.1),
        starts: (w.starts.1, w.starts.1),
        length: (w.length.1, w.length.1),
        run_out: (w.run_out.1, w.run_out.1),
        chamfer: (w.chamfer.1, w.chamfer.1),
        chamfer_angle: (45, 45),
        tool_angle: (60, 60),
        // A lead-in adds one move per pass; the lead changes coordinates only.
        lead_in: (w.lead_in.1, w.lead_in.1),
        lead: (w.lead.0, w.lead.0),
        ..*w
    }
}

/// The counts are process-wide: one measurement at a time.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

fn lock() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn g76_maxima(name: &str, window: &Domain, body: impl Fn(&Domain, &Counted)) -> Maxima {
    let mut m = Maxima::default();
    measure(&mut m, &format!("{name} (sampled window)"), SAMPLE, |e| body(window, e));
    let w = worst(window);
    measure(&mut m, &format!("{name} (worst cases)"), Mode::Enumerate { max_runs: 2_000_000 }, |e| {
        body(&w, e)
    });
    m
}

fn g76(name: &str, window: &Domain, body: impl Fn(&Domain, &Counted)) -> u32 {
    g76_maxima(name, window, body).check(name)
}

/// The check fails when a loop reaches the bound: P1's window has a cycle
/// of 78 moves (6 moves × 13 passes, counted by hand in `windows.rs`), so
/// a bound of 78 is one short.
#[test]
#[should_panic(expected = "depth_monotonicity: harness: moves of one cycle runs 78 times, unwind bound 78")]
fn a_loop_reaching_its_bound_fails() {
    let _one = lock();
    let m = g76_maxima("depth_monotonicity", &windows::G76_WINDOW, harness::depth_monotonicity);
    m.check_against("depth_monotonicity", 78);
}

#[test]
fn every_loop_stays_below_its_harness_unwind_bound() {
    let _one = lock();
    // The harnesses split per infeed mode, each over its own window and
    // against its own bound (the D2 windows have the most passes).
    for (code, suffix) in windows::INFEED_MODES {
        let depth = windows::depth_window(code);
        g76(&format!("depth_monotonicity_{suffix}"), &depth, harness::depth_monotonicity);
        g76(&format!("termination_{suffix}"), &depth, harness::termination);
        g76(
            &format!("no_overcut_{suffix}"),
            &windows::flank_window(windows::G76_WINDOW, code),
            harness::no_overcut,
        );
        g76(
            &format!("no_rapid_in_thread_{suffix}"),
            &windows::flank_window(windows::NO_RAPID_WINDOW, code),
            cycleref_proofs::thread::no_rapid_in_thread,
        );
        // The engine's side; the integer restatement's moves below. The
        // decimal reference's loops (rust_decimal) are not counted: Kani
        // does not run it (`harness::equivalence`).
        let name = format!("equivalence_{suffix}");
        let window = windows::equivalence_window(code);
        let mut m = g76_maxima(&name, &window, harness::equivalence);
        let most = exact_reference_moves(&window);
        m.0.insert("harness: moves of the integer reference", most);
        m.check(&name);
    }
    g76("run_out_direction", &windows::RUN_OUT_KANI_WINDOW, harness::run_out_direction);
    g76("finishing", &windows::FINISHING_KANI_WINDOW, harness::finishing);
}

/// The moves of `g76_exact::expand` (P6's other side under Kani, compared
/// move by move with the engine's) over a window: sampled, and at its
/// worst cases.
fn exact_reference_moves(window: &Domain) -> u32 {
    let most = Cell::new(0_usize);
    let body = |d: &Domain| {
        if let Ok(v) = cycleref_proofs::g76_exact::expand(&harness::any_cycle(d)) {
            most.set(most.get().max(v.len()));
        }
    };
    shim::check("equivalence: integer reference (sampled)", SAMPLE, || body(window));
    let w = worst(window);
    shim::check("equivalence: integer reference (worst)", Mode::Enumerate { max_runs: 2_000_000 }, || {
        body(&w)
    });
    u32::try_from(most.get()).unwrap_or(u32::MAX)
}

/// The G75.1 harnesses: the moves of one groove (what their loops run
/// over) and the G75.1 engine's own loops (`cycleref::loop_counters`: the
/// stages and roughing steps of the iterator, the layers counted, the
/// contour points, and `engine::real`'s limb loops, bit-by-bit division and
/// Taylor series), sampled over the window and enumerated at its deepest,
/// widest grooves with the smallest pecks and steps. `groove_no_panic`
/// (every documented input) is sampled.
#[test]
fn groove_loops_stay_below_the_unwind_bounds() {
    let _one = lock();
    use cycleref_proofs::groove::{self, GrooveDomain, GrooveEngine, Moves};
    struct CountedGroove(Cell<usize>);
    impl GrooveEngine for CountedGroove {
        fn expand(&self, c: &cycleref::G75Cycle) -> Result<Moves, CycleError> {
            let v: Moves = cycleref::expand_g75(c)?.collect();
            self.0.set(self.0.get().max(v.len()));
            Ok(v)
        }
    }
    let w = windows::GROOVE_WINDOW;
    let worst = GrooveDomain {
        depth: (w.depth.1, w.depth.1),
        width: (w.width.1, w.width.1),
        peck: (1, 1),
        step: (1, 1),
        corner_kinds: (0, 0),
        signs: (0, 0),
        units: (0, 0),
        ..w
    };
    let material = cycleref_proofs::bodies::GROOVE_MATERIAL_WINDOW;
    type Body = fn(&GrooveDomain, &CountedGroove);
    let harnesses: [(&str, GrooveDomain, Body); 5] = [
        ("groove_pecks_and_steps", w, groove::groove_pecks_and_steps),
        ("groove_layers", w, groove::groove_layers),
        ("groove_inside", w, groove::groove_inside),
        ("groove_finish_is_profile", w, groove::groove_finish_is_profile),
        ("groove_material", material, groove::groove_material),
    ];
    for (name, window, body) in harnesses {
        loop_counters::reset();
        let e = CountedGroove(Cell::new(0));
        let r = shim::check(name, SAMPLE, || body(&window, &e));
        eprintln!("  {name} (sampled window): {} runs, {} pruned", r.runs, r.pruned);
        let worst = GrooveDomain {
            depth: (window.depth.1, window.depth.1),
            width: (window.width.1, window.width.1),
            peck: (window.peck.0, window.peck.0),
            step: (window.step.0, window.step.0),
            tool_width: window.tool_width,
            path: window.path,
            layer: window.layer,
            allowance_x: window.allowance_x,
            allowance_z: window.allowance_z,
            corner: window.corner,
            units: window.units,
            ..worst
        };
        let r = shim::check(name, Mode::Enumerate { max_runs: 1_000_000 }, || body(&worst, &e));
        eprintln!("  {name} (worst cases): {} runs, {} pruned", r.runs, r.pruned);
        let mut m = Maxima::default();
        m.take(u32::try_from(e.0.get()).unwrap_or(u32::MAX));
        m.check(name);
    }
    groove_no_panic_maxima().check("groove_no_panic");
}

/// `groove_equivalence`: its whole Kani window enumerated (884 736
/// grooves), the engine's loops counting (`cycleref::loop_counters`), and
/// the moves on both sides the harness compares, the engine's and the
/// integer restatement's (`g75_exact::expand`, the other side under Kani).
/// The restatement's own loops are bounded by its moves: every layer it
/// counts has a plunge, every plunge a peck move (from the layer top to a
/// deeper bottom), and its contour loops run over at most 6 and 7 points.
/// The `num-bigint` reference is not run here: Kani does not execute it.
#[test]
fn groove_equivalence_stays_below_its_unwind_bound() {
    let _one = lock();
    use cycleref_proofs::g75_exact;
    use cycleref_proofs::groove;
    let window = windows::GROOVE_EQUIVALENCE_WINDOW;
    loop_counters::reset();
    let (engine, restated) = (Cell::new(0_usize), Cell::new(0_usize));
    let r = shim::check("groove_equivalence (window)", Mode::Enumerate { max_runs: 900_000 }, || {
        let c = groove::any_groove(&window);
        cycleref_proofs::verify::assume(g75_exact::is_square(&c));
        if let Ok(moves) = cycleref::expand_g75(&c) {
            engine.set(engine.get().max(moves.count()));
        }
        if let Ok(moves) = g75_exact::expand(&c) {
            restated.set(restated.get().max(moves.len()));
        }
    });
    eprintln!("  groove_equivalence (window): {} runs, {} pruned", r.runs, r.pruned);
    assert_eq!(r.runs, 884_736, "the whole window");
    let mut m = Maxima::default();
    m.take(u32::try_from(engine.get()).unwrap_or(u32::MAX));
    m.0.insert("harness: moves of the integer reference", u32::try_from(restated.get()).unwrap_or(u32::MAX));
    assert_eq!(engine.get(), restated.get(), "both sides have the same longest path");
    let most = m.check("groove_equivalence");
    assert_eq!(most + 1, windows::unwind("groove_equivalence"), "the bound is one above the largest loop");
}

/// The loop maxima of `groove_no_panic` over its Kani window (every
/// documented input of at most `GROOVE_NO_PANIC_LAYERS` layers, the first
/// `GROOVE_NO_PANIC_MOVES` moves): sampled over the window, and at the
/// worst cases of its loops: the most layers (the peck count's layer loop
/// runs once per layer: grooves of one plunge, Δv = 1 and 2, |H| around
/// the window's limit, so that the limit itself is reached and the next
/// layer pruned), and the largest grooves at extreme angles (the largest
/// dividends of the bit-by-bit division). The harness's own loop counts
/// the moves it looks at.
fn groove_no_panic_maxima() -> Maxima {
    use cycleref_proofs::groove::{self, GrooveDomain};
    use windows::{GROOVE_NO_PANIC_LAYERS as LAYERS, GROOVE_NO_PANIC_MOVES as MOVES, GROOVE_NO_PANIC_WINDOW};
    loop_counters::reset();
    let mut m = Maxima::default();
    let looked_at = Cell::new(0_usize);
    let body = |d: &GrooveDomain| {
        let n = groove::groove_no_panic(d, MOVES, Some(LAYERS));
        looked_at.set(looked_at.get().max(n));
    };
    let r = shim::check("groove_no_panic", Mode::Sample { runs: 20_000, seed: 0x0067_3735 }, || {
        body(&GROOVE_NO_PANIC_WINDOW);
    });
    eprintln!("  groove_no_panic (sampled window): {} runs, {} pruned", r.runs, r.pruned);
    // The layer loop's worst: the most layers, one peck each (P ≥ Δv, one
    // plunge). |H| = 2·LAYERS + 2 with Δv = 2 and |H| = LAYERS + 2 with
    // Δv = 1 are beyond the window (pruned).
    for (depth, layer) in [((LAYERS - 2, LAYERS + 2), (1, 1)), ((2 * LAYERS - 2, 2 * LAYERS + 2), (2, 2))] {
        let d = GrooveDomain::layers_only(depth, (2, 3), layer);
        let r = shim::check("groove_no_panic", Mode::Enumerate { max_runs: 1_000 }, || body(&d));
        eprintln!("  groove_no_panic (most layers, V{}): {} runs, {} pruned", layer.0, r.runs, r.pruned);
    }
    // The division's and the series' worst: the largest grooves at the
    // flank and slope extremes (the largest magnitudes enter the dividends).
    let large = GrooveDomain {
        depth: (99_999_999, 99_999_999),
        width: (99_999_999, 99_999_999),
        peck: (99_999_999, 99_999_999),
        step: (99_999_999, 99_999_999),
        layer: (0, 0),
        allowance_x: (0, 0),
        allowance_z: (0, 0),
        tool_width: (-1, 99_999_999),
        corner: (999_999, 999_999),
        corner_kinds: (0, 15),
        flank: (1, 3),
        slope: (899_997, 899_999),
        path: (0, 2),
        signs: (0, 0),
        units: (0, 7),
        ..GROOVE_NO_PANIC_WINDOW
    };
    let r = shim::check("groove_no_panic", Mode::Sample { runs: 5_000, seed: 7 }, || body(&large));
    eprintln!("  groove_no_panic (large, extreme angles): {} runs, {} pruned", r.runs, r.pruned);
    m.take(u32::try_from(looked_at.get()).unwrap_or(u32::MAX));
    m
}

/// The window's layer limit is reached and not exceeded: the peck count's
/// loop runs exactly `GROOVE_NO_PANIC_LAYERS` times at the worst cases,
/// and the harness looks at `GROOVE_NO_PANIC_MOVES` moves.
#[test]
fn groove_no_panic_reaches_its_layer_limit() {
    let _one = lock();
    let m = groove_no_panic_maxima();
    let layers = u32::try_from(windows::GROOVE_NO_PANIC_LAYERS).expect("a small limit");
    assert_eq!(m.0.get("g75 roughing: layers counted"), Some(&layers));
    assert_eq!(m.0.get("harness: moves of one cycle"), Some(&8));
    assert!(m.0.get("real::limbs_divmod: quotient limbs").is_some_and(|&n| n > 0), "{:?}", m.0);
}

/// The G75.1 engine's loops are held to the bound too: `groove_no_panic`'s
/// layer loop runs 1 152 times at the window's most layers, so a bound of
/// 1 152 is one short.
#[test]
#[should_panic(expected = "groove_no_panic: g75 roughing: layers counted runs 1152 times, unwind bound 1152")]
fn a_groove_loop_reaching_its_bound_fails() {
    let _one = lock();
    groove_no_panic_maxima().check_against("groove_no_panic", 1_152);
}

/// P7 over the documented ranges: sampled, and enumerated at the extremes
/// that drive each loop (the smallest cuts and Δd = k / 10 against the
/// largest k for the pass count, which stops past the limit; the largest
/// Δd for Newton; every start count 1..=999 for Stein's gcd).
#[test]
fn no_panic_stays_below_its_unwind_bound() {
    let _one = lock();
    let w = windows::NO_PANIC_WINDOW;
    let n = windows::NO_PANIC_MOVES;
    let mut m = Maxima::default();
    measure(&mut m, "no_panic (sampled window)", SAMPLE, |e| harness::no_panic(&w, e, n));
    let fixed = Domain {
        tool_angle: (60, 60),
        finishing: (99, 99),
        starts: (999, 999),
        taper: (0, 0),
        length: (999_999_999, 999_999_999),
        run_out: (999_999_999, 999_999_999),
        chamfer: (99, 99),
        chamfer_angle: (45, 45),
        units: (0, 7),
        // An invalid start X is refused before any loop: two values suffice.
        wild_x: 2,
        // A lead-in adds a move (and some are refused before the count);
        // the lead changes coordinates only.
        lead_in: (0, 1),
        lead: (0, 0),
        ..w
    };
    let small_cuts = Domain {
        height: (999_999_998, 999_999_999),
        first_depth: (1, 2),
        min_cut: (0, 1),
        allowance: (0, 1),
        ..fixed
    };
    let large_first = Domain {
        height: (999_999_998, 999_999_999),
        first_depth: (999_999_998, 999_999_999),
        min_cut: (0, 1),
        allowance: (0, 1),
        ..fixed
    };
    // Δd = k / 10: the law alone makes about 100 levels, so the count runs
    // past the limit.
    let by_law = Domain { first_depth: (100_000_000, 100_000_001), ..large_first };
    let starts = Domain { starts: (1, 999), units: (0, 0), run_out_kind: (0, 0), ..Domain::POINT };
    let starts = Domain { pass_limit: w.pass_limit, ..starts };
    for (name, d) in [
        ("small cuts", small_cuts),
        ("large first depth", large_first),
        ("levels by the law past the limit", by_law),
        ("every start count", starts),
    ] {
        measure(&mut m, &format!("no_panic ({name})"), Mode::Enumerate { max_runs: 2_000_000 }, |e| {
            harness::no_panic(&d, e, n);
        });
    }
    m.check("no_panic");
}

/// `round_sqrt` counting its Newton iterations.
fn counting_sqrt(x: u128) -> u128 {
    cycleref::engine::record_isqrt(x);
    cycleref::engine::round_sqrt(x)
}

/// `isqrt_floor` counting its Newton iterations.
fn counting_floor(x: u128) -> u128 {
    cycleref::engine::record_isqrt(x);
    cycleref::engine::isqrt_floor(x)
}

/// The Newton loop of `isqrt_floor` over the contracts' window, `x < 2^62`
/// (`windows::ISQRT_WINDOW`, the window of the `proof_for_contract`
/// harnesses of `isqrt_floor`, and of `round_sqrt` without its stub):
/// sampled and at the edges; every `x < 2^16`; every `x` within 2 of each
/// power of two, where Newton's start `2^ceil(bits/2)` is farthest from
/// the root; and the top of the window.
fn newton_maxima(body: fn(u128, u128, fn(u128) -> u128), f: fn(u128) -> u128) -> Maxima {
    let (lo, hi) = windows::ISQRT_WINDOW;
    let mut m = Maxima::default();
    measure(&mut m, "isqrt (sampled window)", Mode::Sample { runs: 200_000, seed: 5 }, |_| body(lo, hi, f));
    measure(&mut m, "isqrt (window edges)", Mode::Edges { runs: 200_000, seed: 6 }, |_| body(lo, hi, f));
    measure(&mut m, "isqrt (x < 2^16)", Mode::Enumerate { max_runs: 1 << 17 }, |_| body(0, (1 << 16) - 1, f));
    for bits in 17..62 {
        let p = 1_u128 << bits;
        measure(&mut m, "isqrt (near 2^bits)", Mode::Enumerate { max_runs: 16 }, |_| body(p - 2, p + 2, f));
    }
    measure(&mut m, "isqrt (at the top)", Mode::Enumerate { max_runs: 16 }, |_| body(hi - 4, hi, f));
    m
}

#[test]
fn isqrt_stays_below_its_unwind_bound() {
    let _one = lock();
    newton_maxima(harness::isqrt_rounds, counting_sqrt).check("isqrt_rounds");
    newton_maxima(cycleref_proofs::contracts::isqrt_floor, counting_floor).check("isqrt_floor_contract");
}

/// `round_sqrt_near` counting the iterations of its loop.
fn counting_near(x: u128, guess: u128) -> u128 {
    cycleref::engine::record_isqrt_near(x, guess);
    cycleref::engine::round_sqrt_near(x, guess)
}

/// The loop of `round_sqrt_near` (the guess, then at most `NEAR_STEPS`
/// corrections; Newton's method is `round_sqrt`'s, stubbed in its
/// `proof_for_contract`) over its window: sampled, and every guess near
/// the root of small values, where it runs longest.
#[test]
fn round_sqrt_near_stays_below_its_unwind_bound() {
    let _one = lock();
    let (x, guess) = windows::ISQRT_NEAR_WINDOW;
    let body = cycleref_proofs::contracts::round_sqrt_near;
    let mut m = Maxima::default();
    measure(&mut m, "round_sqrt_near (sampled window)", Mode::Sample { runs: 100_000, seed: 7 }, |_| {
        body(x.0, x.1, guess, counting_near);
    });
    measure(&mut m, "round_sqrt_near (small, near)", Mode::Enumerate { max_runs: 50_000 }, |_| {
        body(0, 1 << 10, (0, 40), counting_near);
    });
    let most = m.check("round_sqrt_near_contract");
    // The guess and NEAR_STEPS corrections, each checked: reached.
    assert_eq!(most, cycleref::engine::arith::NEAR_STEPS + 1, "the loop's longest run");
}

/// The G32 run-out harness: every block within 3 increments exhaustively
/// (all units, run-outs), and sampled over its window.
#[test]
fn g32_stays_below_its_unwind_bound() {
    let _one = lock();
    let (reach, run_out) = windows::G32_WINDOW;
    let moves = Rc::new(Cell::new(0_u32));
    let counting = |b: &cycleref::G32Block| {
        cycleref::expand_g32(b).map(|it| {
            let v: Vec<Move> = it.collect();
            let n = u32::try_from(v.len()).unwrap_or(u32::MAX);
            moves.set(moves.get().max(n));
            v.into_iter()
        })
    };
    let mut m = Maxima::default();
    measure(&mut m, "g32 (sampled window)", SAMPLE, |_| harness::g32_run_out(reach, run_out, &counting));
    measure(&mut m, "g32 (within 3)", Mode::Enumerate { max_runs: 5_000_000 }, |_| {
        harness::g32_run_out(3, 2, &counting);
    });
    m.take(moves.get());
    m.check("g32_run_out");
    let mut m = Maxima::default();
    measure(&mut m, "g32 no rapid (sampled window)", SAMPLE, |_| {
        cycleref_proofs::thread::g32_no_rapid(reach, run_out, &counting);
    });
    measure(&mut m, "g32 no rapid (within 3)", Mode::Enumerate { max_runs: 5_000_000 }, |_| {
        cycleref_proofs::thread::g32_no_rapid(3, 2, &counting);
    });
    m.take(moves.get());
    m.check("g32_no_rapid");
}

/// `g92_pass`: its window sampled and, exhaustively, every block within 3
/// increments with two starts (the most moves: 5 a start).
#[test]
fn g92_stays_below_its_unwind_bound() {
    let _one = lock();
    let (reach, run_out, starts) = windows::G92_WINDOW;
    let moves = Rc::new(Cell::new(0_u32));
    let counting = |c: &cycleref::G92Cycle| {
        cycleref::expand_g92(c).map(|it| {
            let v: Vec<Move> = it.collect();
            let n = u32::try_from(v.len()).unwrap_or(u32::MAX);
            moves.set(moves.get().max(n));
            v.into_iter()
        })
    };
    let mut m = Maxima::default();
    measure(&mut m, "g92 (sampled window)", SAMPLE, |_| {
        cycleref_proofs::g92::g92_pass(reach, run_out, starts, &counting);
    });
    measure(&mut m, "g92 (within 2)", Mode::Enumerate { max_runs: 5_000_000 }, |_| {
        cycleref_proofs::g92::g92_pass(2, 2, starts, &counting);
    });
    m.take(moves.get());
    let most = m.check("g92_pass");
    assert_eq!(moves.get(), 10, "two starts of five moves");
    assert!(most >= 10);
}

#[test]
fn the_kani_attributes_are_the_bounds_checked_here() {
    let src = include_str!("../src/kani_proofs.rs");
    let mut found = BTreeMap::new();
    let mut pending = None;
    for line in src.lines().map(str::trim) {
        if let Some(n) = line.strip_prefix("#[kani::unwind(").and_then(|r| r.strip_suffix(")]")) {
            pending = Some(n.replace('_', "").parse::<u32>().expect("a number"));
        }
        if let Some(rest) = line.strip_prefix("fn ") {
            let name = rest.split('(').next().unwrap_or_default();
            found.insert(name.to_owned(), pending.take());
        }
    }
    let all = cycleref_proofs::catalogue::harnesses();
    for h in &all {
        assert_eq!(
            found.get(&h.name),
            Some(&Some(h.unwind)),
            "{}: #[kani::unwind] in kani_proofs.rs",
            h.name
        );
    }
    assert_eq!(found.len(), all.len(), "every Kani harness is in the catalogue: {found:?}");
}

/// The one-step schedule harness: its only loop is Newton's, in the law's
/// `round_sqrt`, on `Δd²(n + 1)`. Over the exhaustive window of
/// `tests/schedule.rs`, and at the largest roots a law state can take
/// (`Δd √n` up to 999 999 999, so `Δd² n < 2^60`: Newton on `u64`) for Δd
/// from 1 to 999 999 999 and the levels that go with them.
#[test]
fn schedule_step_stays_below_its_unwind_bound() {
    use cycleref_proofs::schedule::{schedule_step, ScheduleDomain};
    let _one = lock();
    let step = cycleref::engine::schedule::Schedule::next_level;
    let mut m = Maxima::default();
    let small = ScheduleDomain {
        first_depth: (1, 20),
        min_cut: (0, 3),
        last: (0, 40),
        depth: (0, 40),
        level: (0, 40),
    };
    measure(&mut m, "schedule_step (small window)", Mode::Enumerate { max_runs: 2_000_000 }, |_| {
        schedule_step(&small, &step);
    });
    let max = 999_999_999_i64;
    for q in [1, 2, 3, 1_000, 31_622, 999_999, 999_999_998, max] {
        // n ≤ min(Δd², (MAX / Δd)²): the largest level of a law state.
        let n = (q * q).min((max / q).pow(2));
        for level in [1, n / 2 + 1, n] {
            #[allow(clippy::cast_precision_loss, clippy::cast_possible_truncation)]
            let hint = (q as f64 * (level as f64).sqrt()).round() as i64;
            let d = ScheduleDomain {
                first_depth: (q, q),
                min_cut: (0, 1),
                last: (max, max),
                depth: (hint - 2, hint + 2),
                level: (level, level),
            };
            measure(&mut m, "schedule_step (largest roots)", Mode::Enumerate { max_runs: 100 }, |_| {
                schedule_step(&d, &step);
            });
        }
    }
    m.check("schedule_step");
}
