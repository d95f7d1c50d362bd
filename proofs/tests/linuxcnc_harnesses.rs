//! The LinuxCNC G76 harnesses (`cycleref_proofs::linuxcnc`) under `cargo
//! test`: each over its Kani window exhaustively (every declared cover
//! satisfied) and sampled over a wider window; the loops they reach against
//! their unwind bounds; and, for each harness, engines broken on purpose in
//! the way its property forbids, each beside a control run of the real
//! engine over the same domain (the pattern of `mutants.rs`).

use std::cell::Cell;
use std::collections::BTreeMap;

use cycleref::linuxcnc::LinuxCncG76;
use cycleref::loop_counters::{self, SITES};
use cycleref::{CycleError, Motion, Move, PassKind, Role};
use cycleref_proofs::linuxcnc::{
    lcnc_depth_monotonicity, lcnc_pass_moves, lcnc_spring_passes, lcnc_termination, LcncDomain,
};
use cycleref_proofs::shim::{self, check, check_and_print, Mode, Report};
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
    let _one = lock();
    check_and_print(name, Mode::Exhaustive { max_runs }, || harness(window, &control))
}

fn sampled(name: &str, harness: Harness) {
    let _one = lock();
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

/// The loop counts are process-wide: every run of this file takes this
/// lock, so that the measurement sees its windows alone.
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

/// Runs `harness` over `window` exhaustively on the real engine (the
/// control: passes, every cover satisfied) and on `mutant`, which must fail
/// on the assertion whose text contains `expected`.
fn caught(
    window: &LcncDomain,
    harness: Harness,
    mutant: impl Fn(&LinuxCncG76) -> Result<Moves, CycleError>,
    expected: &str,
) {
    let _one = lock();
    let mode = Mode::Exhaustive { max_runs: 200_000 };
    let r = shim::caught(mode, || harness(window, &control), || harness(window, &mutant), expected);
    eprintln!("control: {} runs, {} pruned", r.runs, r.pruned);
}

/// The real engine's moves, changed by `f` (the cycle and the whole list).
fn mutant(
    f: impl Fn(&LinuxCncG76, Vec<Move>) -> Vec<Move>,
) -> impl Fn(&LinuxCncG76) -> Result<Moves, CycleError> {
    move |c| real(c).map(|v| f(c, v).into_iter())
}

/// LinuxCNC's own binary64 behaviour at an exact tie (R-LCNC-TIE):
/// `pow(8, 1/1.5)` falls a hair short of 4, so where `δ_(N+1) = K` exactly
/// it cuts one more rough pass, at (within printing) full depth. The
/// mutant inserts that pass: the full-depth pass's moves as rough pass
/// N + 1, before the full-depth passes.
fn binary64_tie(c: &LinuxCncG76, v: Vec<Move>) -> Vec<Move> {
    let rough = v.iter().filter_map(|m| m.pass).filter(|p| p.kind == PassKind::Rough).map(|p| p.number).max();
    let Some(n) = rough else { return v };
    // Only at a tie: the exact depth of pass n + 1 is K (J·(n+1)^(1/R)).
    let r = f64::from(c.degression) / 10_000.0;
    let next = c.initial_depth as f64 * f64::from(n + 1).powf(1.0 / r);
    if (next - c.full_depth as f64).abs() > 1e-9 {
        return v;
    }
    let full: Vec<Move> = v
        .iter()
        .filter(|m| m.pass.is_some_and(|p| p.kind == PassKind::Finish && p.number == 1))
        .copied()
        .collect();
    if full.is_empty() {
        return v;
    }
    let mut out = Vec::with_capacity(v.len() + full.len());
    let mut done = false;
    for m in v {
        if !done && m.pass.is_none_or(|p| p.kind == PassKind::Finish) {
            out.extend(full.iter().map(|f| Move {
                pass: f.pass.map(|p| cycleref::Pass { kind: PassKind::Rough, number: n + 1, ..p }),
                ..*f
            }));
            done = true;
        }
        out.push(m);
    }
    out
}

#[test]
fn the_binary64_extra_pass_at_a_tie_is_caught_by_depth_monotonicity() {
    caught(&LCNC_DEPTH_WINDOW, p1, mutant(binary64_tie), "a rough pass is shallower than K exactly");
}

#[test]
fn the_binary64_extra_pass_at_a_tie_is_caught_by_termination() {
    caught(&LCNC_DEPTH_WINDOW, p2, mutant(binary64_tie), "the last rough pass is shallower than K");
}

/// A depth label in X units: `Pass::depth` left a diameter in G7.
#[test]
fn a_diameter_depth_label_is_caught_by_depth_monotonicity() {
    let e = mutant(|c, v| {
        let xf = c.x_mode.factor();
        v.into_iter()
            .map(|mut m| {
                if let Some(p) = m.pass.as_mut() {
                    p.depth *= xf;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_DEPTH_WINDOW, p1, e, "a rough depth is round(δ_n/ξ)");
}

/// The last rough pass's cut one increment short of its depth (a
/// truncated instead of a rounded X).
#[test]
fn a_shallow_cut_x_is_caught_by_depth_monotonicity() {
    let e = mutant(|c, v| {
        let sigma = c.sigma();
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::Cut && m.pass.is_some_and(|p| p.kind == PassKind::Rough && p.number == 2) {
                    m.to.x += sigma;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_DEPTH_WINDOW, p1, e, "rounded");
}

/// Rough passes while `δ ≤ K − J` (one pass short where the last is
/// within J of K): the last rough pass dropped from cycles of three or more.
#[test]
fn a_pass_short_is_caught_by_termination() {
    let e = mutant(|_, v| {
        let n = v.iter().filter_map(|m| m.pass).filter(|p| p.kind == PassKind::Rough).map(|p| p.number).max();
        match n {
            Some(n) if n >= 3 => v
                .into_iter()
                .filter(|m| !m.pass.is_some_and(|p| p.kind == PassKind::Rough && p.number == n))
                .collect(),
            _ => v,
        }
    });
    caught(&LCNC_DEPTH_WINDOW, p2, e, "the pass after the last rough pass would not be shallower than K");
}

/// H ignored: always exactly one pass at full depth.
#[test]
fn h_ignored_is_caught_by_termination() {
    let e = mutant(|_, v| {
        v.into_iter()
            .filter(|m| !m.pass.is_some_and(|p| p.kind == PassKind::Finish && p.number > 1))
            .collect()
    });
    caught(&LCNC_DEPTH_WINDOW, p2, e, "1 + H passes at full depth");
}

/// The spring passes cut one increment deeper than the full-depth pass.
#[test]
fn a_deeper_spring_pass_is_caught_by_spring_passes() {
    let e = mutant(|c, v| {
        let sigma = c.sigma();
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::Cut && m.pass.is_some_and(|p| p.kind == PassKind::Finish && p.number > 1) {
                    m.to.x -= sigma;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_SPRING_WINDOW, p3, e, "a spring pass repeats the full-depth pass");
}

/// The compound shift not cancelled at full depth: the deepest pass's end
/// one increment past Z (as an engine that rounds ζ and (K/ξ)·t apart
/// would be, where they round differently).
#[test]
fn the_deepest_pass_off_z_is_caught_by_spring_passes() {
    let e = mutant(|c, v| {
        let t = if c.end.z > c.start.z { 1 } else { -1 };
        v.into_iter()
            .map(|mut m| {
                if matches!(m.role, Role::Cut | Role::RunOut | Role::Retract)
                    && m.pass.is_some_and(|p| p.kind == PassKind::Finish)
                {
                    m.to.z += t;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_SPRING_WINDOW, p3, e, "the deepest pass's");
}

/// The entry taper's moves made rapids (a rapid into the thread).
#[test]
fn an_entry_taper_as_rapids_is_caught_by_pass_moves() {
    let e = mutant(|_, v| {
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::LeadIn {
                    m.motion = Motion::Rapid;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_PASS_WINDOW, p4, e, "never rapids");
}

/// The out rapid leaves the groove diagonally: one increment back along Z
/// (a retract to the next pass's start Z in one move).
#[test]
fn a_diagonal_out_is_caught_by_pass_moves() {
    let e = mutant(|c, v| {
        let t = if c.end.z > c.start.z { 1 } else { -1 };
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::Retract {
                    m.to.z -= t;
                }
                m
            })
            .collect()
    });
    caught(&LCNC_PASS_WINDOW, p4, e, "a rapid from inside the thread region runs along X alone, outwards");
}

/// The exit taper at P instead of the taper pitch (R-LCNC-SYNC).
#[test]
fn an_exit_taper_at_p_is_caught_by_pass_moves() {
    let e = mutant(|c, v| {
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::RunOut {
                    if let Motion::Thread { lead, .. } = &mut m.motion {
                        *lead = c.pitch;
                    }
                }
                m
            })
            .collect()
    });
    caught(&LCNC_PASS_WINDOW, p4, e, "the exit taper continues the synchronisation at the taper pitch");
}

/// The entry taper's first move 100 increments away from the work (beyond
/// the back X): a taper that does not start K above the cut.
#[test]
fn an_entry_taper_beyond_the_cut_is_caught_by_pass_moves() {
    let e = mutant(|c, v| {
        let sigma = c.sigma();
        v.into_iter()
            .map(|mut m| {
                if m.role == Role::LeadIn && m.motion != Motion::Rapid {
                    if let Motion::Thread { sync: true, .. } = m.motion {
                        m.to.x += sigma * 100;
                    }
                }
                m
            })
            .collect()
    });
    caught(&LCNC_PASS_WINDOW, p4, e, "the entry taper starts K above the cut");
}

/// Q not negated for a thread towards +Z (l.5740-5742 left out): the
/// compound shift runs against the thread there. The mutant mirrors every
/// pass's start Z about Z₀ on threads towards +Z (the back and the in),
/// as an engine that takes tan Q with the programmed sign would place
/// them.
#[test]
fn a_compound_shift_the_wrong_way_is_caught_by_pass_moves() {
    let e = mutant(|c, v| {
        let towards_plus = c.end.z > c.start.z;
        let mut first_of_pass = true;
        let mut z_s = c.start.z;
        v.into_iter()
            .map(|mut m| {
                if towards_plus && m.role == Role::Approach {
                    if first_of_pass {
                        z_s = m.to.z;
                    }
                    if m.to.z == z_s {
                        m.to.z = 2 * c.start.z - m.to.z;
                    }
                }
                first_of_pass = m.role == Role::Retract;
                m
            })
            .collect()
    });
    caught(&LCNC_PASS_WINDOW, p4, e, "the compound shift runs along the thread for Q > 0");
}
