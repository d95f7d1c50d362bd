//! The proof harnesses under `cargo test`: each property exhaustively over a
//! small domain (small-scope checking) and by sampling over the documented
//! ranges. The domains are stated next to each test; the README's table
//! summarises them. A longer exhaustive run over larger domains:
//!
//! ```sh
//! cargo test -p cycleref-proofs --profile proofs --test harnesses -- --ignored
//! ```

use cycleref_proofs::harness::{self, Domain, FixedPoint};
use cycleref_proofs::shim::{check_and_print as check, Mode};
use cycleref_proofs::windows;

/// Exhaustive over every combination of the domain's choices.
fn exhaustive(max_runs: u64) -> Mode {
    Mode::Exhaustive { max_runs }
}

/// Random choices over the domain, with a fixed seed.
const SAMPLE: Mode = Mode::Sample { runs: 3_000, seed: 0x6376_7265_6672_6566 };

/// The schedule's inputs: k 1..=20, Δd 1..=20, Δdmin 0..=4, d 0..=k, all
/// three infeed modes (68 040 cycles).
const SCHEDULE: Domain = Domain::SCHEDULE;

/// Larger for the ignored run: k 1..=150, Δd 1..=150, Δdmin 0..=12, d 0..=k.
const SCHEDULE_WIDE: Domain = Domain {
    height: (1, 150),
    first_depth: (1, 150),
    min_cut: (0, 12),
    allowance: (0, 150),
    infeed: (0, 2),
    depth_mode: (1, 1),
    ..Domain::POINT
};

/// Geometry: every side, direction, infeed, tapers including X as the long
/// axis (|i| >= |W| = 40), every run-out kind (chamfers from r accepted
/// with the lead F0.01), F and I leads, IS-B/IS-C, mm/inch, over a small
/// schedule.
const GEOMETRY: Domain = Domain {
    height: (6, 8),
    first_depth: (3, 4),
    min_cut: (1, 1),
    allowance: (0, 1),
    tool_angle: (60, 60),
    finishing: (1, 1),
    infeed: (0, 2),
    depth_mode: (1, 1),
    internal: (0, 1),
    positive_z: (0, 1),
    taper: (-42, 42),
    length: (40, 40),
    run_out_kind: (0, 3),
    run_out: (1, 2),
    chamfer: (3, 3),
    chamfer_angle: (30, 30),
    units: (0, 3),
    lead: (1, 2),
    ..Domain::POINT
};

/// Sampling domain: the documented ranges ([`Domain::WIDE`]).
const WIDE: Domain = Domain::WIDE;

/// The harnesses check "no overflow" by the panic an overflow raises: the
/// profile must keep overflow checks on (dev does; `--profile proofs` is
/// release with them on; plain `--release` turns them off and fails here).
#[test]
fn overflow_checks_are_on() {
    let sum = std::panic::catch_unwind(|| std::hint::black_box(i64::MAX) + std::hint::black_box(1));
    assert!(sum.is_err(), "overflow checks are off: run the long proofs with --profile proofs");
}

#[test]
fn p1_depth_monotonicity() {
    // The schedule's domain has no lead-in, so no pass there loses its
    // approach: that cover is vacuous here, required over the Kani windows
    // (`tests/kani_windows.rs`) and met by the counterexample below.
    check("depth monotonicity", exhaustive(200_000), || harness::depth_monotonicity(&SCHEDULE, &FixedPoint));
    check("depth monotonicity (sampled)", SAMPLE, || harness::depth_monotonicity(&WIDE, &FixedPoint));
}

#[test]
fn p2_termination() {
    check("termination", exhaustive(200_000), || harness::termination(&SCHEDULE, &FixedPoint));
    check("termination (sampled)", SAMPLE, || harness::termination(&WIDE, &FixedPoint));
}

#[test]
fn p3_finishing() {
    let d = Domain { finishing: (0, 3), starts: (1, 3), ..SCHEDULE };
    let d = Domain { height: (1, 12), first_depth: (1, 12), allowance: (0, 12), ..d };
    check("finishing", exhaustive(400_000), || harness::finishing(&d, &FixedPoint));
    check("finishing (sampled)", SAMPLE, || harness::finishing(&WIDE, &FixedPoint));
}

#[test]
fn p4_run_out_direction() {
    check("run-out direction", exhaustive(2_000_000), || harness::run_out_direction(&GEOMETRY, &FixedPoint));
    check("run-out direction (sampled)", SAMPLE, || harness::run_out_direction(&WIDE, &FixedPoint));
}

#[test]
fn p5_no_overcut() {
    let d = Domain {
        run_out_kind: (0, 0),
        units: (0, 0),
        taper: (-3, 3),
        tool_angle: (0, 99),
        lead: (0, 0),
        lead_in: (0, 1),
        ..GEOMETRY
    };
    check("no overcut", exhaustive(2_000_000), || harness::no_overcut(&d, &FixedPoint));
    check("no overcut (sampled)", SAMPLE, || harness::no_overcut(&WIDE, &FixedPoint));
}

#[test]
fn p6_equivalence() {
    let d = Domain { height: (1, 10), first_depth: (1, 10), min_cut: (0, 3), allowance: (0, 10), ..SCHEDULE };
    check("equivalence (schedule)", exhaustive(200_000), || harness::equivalence(&d, &FixedPoint));
    let g = Domain { tool_angle: (0, 99), units: (0, 7), ..GEOMETRY };
    check("equivalence (geometry)", Mode::Sample { runs: 20_000, seed: 7 }, || {
        harness::equivalence(&g, &FixedPoint)
    });
    check("equivalence (sampled)", SAMPLE, || harness::equivalence(&WIDE, &FixedPoint));
    // The integer restatement under Kani (`g76_exact`) against the decimal
    // reference where the windows above do not reach: X long axes (|W|
    // from 1), lead-ins, chamfered run-outs, I leads, every unit code.
    check("equivalence (X long)", SAMPLE, || harness::equivalence(&windows::NO_RAPID_WINDOW, &FixedPoint));
    check("equivalence (full range)", SAMPLE, || harness::equivalence(&Domain::FULL, &FixedPoint));
}

#[test]
fn p7_no_panic() {
    check("no panic (sampled, full range)", Mode::Sample { runs: 20_000, seed: 11 }, || {
        harness::no_panic(&Domain::FULL, &FixedPoint, 200)
    });
    check("no panic (sampled, wide)", SAMPLE, || harness::no_panic(&WIDE, &FixedPoint, 100_000));
}

#[test]
fn p8_isqrt_rounds() {
    let sqrt = cycleref::engine::round_sqrt;
    check("isqrt (exhaustive 0..=2^20)", exhaustive(1 << 21), || harness::isqrt_rounds(0, 1 << 20, sqrt));
    // The contract's range, x < 2^62 (`windows::ISQRT_WINDOW`): every call
    // the engine makes (the depth law's Δd²·n), checked at each call in
    // these tests (feature `contract-checks`).
    let (lo, hi) = windows::ISQRT_WINDOW;
    check("isqrt (sampled window)", Mode::Sample { runs: 200_000, seed: 3 }, || {
        harness::isqrt_rounds(lo, hi, sqrt)
    });
    check("isqrt (window edges)", Mode::Edges { runs: 200_000, seed: 4 }, || {
        harness::isqrt_rounds(lo, hi, sqrt)
    });
}

#[test]
#[ignore = "long run: several minutes with --profile proofs; see README"]
fn long_exhaustive() {
    let started = std::time::Instant::now();
    check("depth monotonicity (wide)", exhaustive(200_000_000), || {
        harness::depth_monotonicity(&SCHEDULE_WIDE, &FixedPoint)
    });
    check("termination (wide)", exhaustive(200_000_000), || {
        harness::termination(&SCHEDULE_WIDE, &FixedPoint)
    });
    let f = Domain {
        height: (1, 40),
        first_depth: (1, 40),
        allowance: (0, 40),
        finishing: (0, 4),
        starts: (1, 3),
        ..SCHEDULE
    };
    check("finishing (wide)", exhaustive(200_000_000), || harness::finishing(&f, &FixedPoint));
    let eq =
        Domain { height: (1, 60), first_depth: (1, 60), min_cut: (0, 6), allowance: (0, 60), ..SCHEDULE };
    check("equivalence (wide)", exhaustive(200_000_000), || harness::equivalence(&eq, &FixedPoint));
    let g = Domain {
        height: (6, 12),
        taper: (-90, 90),
        finishing: (0, 2),
        units: (0, 7),
        tool_angle: (29, 31),
        length: (80, 80),
        ..GEOMETRY
    };
    check("run-out direction (wide)", exhaustive(200_000_000), || {
        harness::run_out_direction(&g, &FixedPoint)
    });
    let o = Domain {
        height: (1, 30),
        first_depth: (1, 30),
        allowance: (0, 30),
        tool_angle: (0, 99),
        length: (200, 200),
        run_out_kind: (0, 0),
        units: (0, 0),
        taper: (0, 0),
        lead: (0, 0),
        lead_in: (0, 1),
        ..GEOMETRY
    };
    check("no overcut (wide)", exhaustive(200_000_000), || harness::no_overcut(&o, &FixedPoint));
    check("isqrt (exhaustive 0..=2^30)", exhaustive((1 << 30) + 2), || {
        harness::isqrt_rounds(0, 1 << 30, cycleref::engine::round_sqrt)
    });
    eprintln!("long exhaustive run: {:.0?}", started.elapsed());
}

/// P4's Kani window (`windows::NO_RAPID_WINDOW`) reaches every cover P4
/// declares, "run-out with X long" included (helper-10 found it unreachable
/// in `G76_WINDOW`, whose threads are at least 20 increments long against
/// tapers of ±6), so `--fail-uncoverable` can pass.
#[test]
fn p4_kani_window_reaches_every_cover() {
    let r = check("run-out direction (Kani window)", Mode::Sample { runs: 30_000, seed: 4 }, || {
        harness::run_out_direction(&cycleref_proofs::windows::NO_RAPID_WINDOW, &FixedPoint);
    });
    for (name, hits) in &r.covers {
        assert!(*hits > 0, "{name} is not reached in P4's Kani window");
    }
    assert!(r.covers.get("run-out with X long").is_some_and(|&n| n > 0), "{:?}", r.covers);
}

/// The counterexample of issue 32 to P1 over its own Kani window: k = 6,
/// Δd = 2, Δdmin = 1, d = 2, m = 1, centre infeed, equal depths, towards
/// +Z, taper 3, |W| = 32, run-out J0 K4, E = 3, lead I2540, IS-B inch
/// radius X. The first pass's approach has no length and is dropped
/// (R-ZERO), so a pass finder keyed on the approach lost pass 1 and P1
/// failed on "cut annotation" (2 against 4). Every harness that walks the
/// passes runs on it. The lead-in start An = (X_B1 + E, Z_B1) (R-LEADIN
/// `same-z`, the default since issue 34) is A: X_B1 = X_C + (k - 2), that
/// is X_C + 4, and with E = 3 that is X_C + 7, the crest plus one, X_A;
/// a = 0 puts B1 at Z_A. (Issue 32 found it with a = 95 under
/// `whole-leads`: the centre shift zc = round(4·tan 47.5°) = 4 equal to the
/// lead back.)
const APPROACH_DROPPED: Domain = Domain {
    height: (6, 6),
    first_depth: (2, 2),
    min_cut: (1, 1),
    allowance: (2, 2),
    tool_angle: (0, 0),
    finishing: (1, 1),
    infeed: (3, 3),
    depth_mode: (0, 0),
    starts: (1, 1),
    internal: (0, 0),
    positive_z: (1, 1),
    taper: (3, 3),
    length: (32, 32),
    run_out_kind: (1, 1),
    run_out: (0, 4),
    units: (6, 6),
    pass_limit: 16,
    lead_in: (3, 3),
    lead: (3, 3),
    ..Domain::POINT
};

#[test]
fn a_pass_whose_approach_is_dropped_is_still_a_pass() {
    use cycleref::{PassKind, Role};
    // The cycle itself, by hand: J0 K4 is the one draw of (short, long)
    // = (0, 4) of the run-out range.
    let c = cycleref_proofs::shim::check("the counterexample", Mode::Enumerate { max_runs: 100 }, || {
        let c = harness::any_cycle(&APPROACH_DROPPED);
        if let cycleref::RunOut::Amounts { short: 0, long: 4 } = c.run_out {
            let moves: Vec<_> = cycleref::engine::expand_g76(&c).expect("expands").collect();
            // Pass 1 (rough, depth 2 = Δd·1 of the equal steps) has no
            // approach: the tool is already at its start.
            let first = moves.first().expect("moves");
            assert_eq!(first.pass.map(|p| (p.kind, p.number, p.depth)), Some((PassKind::Rough, 1, 2)));
            assert_ne!(first.role, Role::Approach, "the first pass's approach is dropped");
            let roughs = moves
                .iter()
                .filter(|m| m.role == Role::Cut && m.pass.is_some_and(|p| p.kind == PassKind::Rough))
                .count();
            assert_eq!(roughs, 2, "two rough levels: 2 and 4 = k - d");
        }
    });
    assert!(c.runs > 1);
    let r = check("P1", Mode::Enumerate { max_runs: 100 }, || {
        harness::depth_monotonicity(&APPROACH_DROPPED, &FixedPoint);
    });
    assert!(r.covers["a rough pass whose approach is dropped"] > 0);
    for (name, body) in [
        ("P2", harness::termination as fn(&Domain, &FixedPoint)),
        ("P3", harness::finishing),
        ("P5", harness::no_overcut),
    ] {
        cycleref_proofs::shim::check(name, Mode::Enumerate { max_runs: 100 }, || {
            body(&APPROACH_DROPPED, &FixedPoint)
        });
    }
}
