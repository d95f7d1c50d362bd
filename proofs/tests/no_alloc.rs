//! The engine does not allocate: a counting global allocator sees no
//! allocation while `expand_g76` (or `expand_linuxcnc`) checks a cycle and
//! its iterator yields every move.
//!
//! (`cycleref` is `#![no_std]` without `alloc`, so it cannot allocate; this
//! test checks the same thing at run time, for the whole call path.)
//!
//! A global allocator needs `unsafe impl GlobalAlloc`: this test file is
//! the one place in the workspace that allows `unsafe` (the workspace lint
//! is `deny`, every library crate has `#![forbid(unsafe_code)]`).
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use cycleref::engine::expand_g76;
use cycleref::g76::{G76Cycle, Infeed};
use cycleref::lead::{Lead, LeadWord};
use cycleref::units::Point;

thread_local! {
    /// Allocations made by this thread while counting.
    static COUNT: Cell<Option<u64>> = const { Cell::new(None) };
}

/// The system allocator, counting the allocations of the threads that
/// asked for it (the test harness allocates on other threads meanwhile).
struct Counting;

fn count() {
    // `try_with`: the thread-local may be gone while a thread exits.
    let _ = COUNT.try_with(|c| {
        if let Some(n) = c.get() {
            c.set(Some(n + 1));
        }
    });
}

// SAFETY: every method forwards to `System` with the caller's arguments
// unchanged, so `System`'s guarantees hold; the counter is a thread-local
// `Cell` of a `Copy` value, which neither allocates nor re-enters the
// allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: forwarded unchanged (see the impl).
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: forwarded unchanged (see the impl).
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: forwarded unchanged (see the impl).
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded unchanged (see the impl).
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations made by `f` on this thread.
fn allocations(f: impl FnOnce()) -> u64 {
    COUNT.with(|c| c.set(Some(0)));
    f();
    COUNT.with(|c| c.replace(None)).unwrap_or(0)
}

/// Expands `c` and walks all its moves; returns (moves, allocations).
fn walk(c: &G76Cycle) -> (u64, u64) {
    let mut moves = 0_u64;
    let mut x = 0_i64;
    let n = allocations(|| {
        let it = expand_g76(c).unwrap_or_else(|e| panic!("{e}"));
        for m in it {
            moves += 1;
            x ^= m.to.x;
        }
    });
    assert_ne!(x, 1, "keeps the loop");
    (moves, n)
}

/// M68x6 (manuals/gsk988ta-g76.txt, O0013).
fn m68x6() -> G76Cycle {
    cycleref::examples::M68X6
}

#[test]
fn counter_counts() {
    let n = allocations(|| drop(std::hint::black_box(vec![1_u8; 10])));
    assert_eq!(n, 1);
}

#[test]
fn m68x6_does_not_allocate() {
    let (moves, n) = walk(&m68x6());
    assert_eq!(moves, 30);
    assert_eq!(n, 0);
}

#[test]
fn multi_start_does_not_allocate() {
    // Seven starts, D2, lead-in with an I lead, many levels.
    let c = G76Cycle {
        starts: 7,
        infeed: Infeed::LeftRight,
        depth_mode: cycleref::DepthMode::Decreasing,
        first_depth: 300,
        min_cut: 20,
        lead_in: 2000,
        lead: Lead { word: LeadWord::I, mantissa: 4, scale: 0 },
        end: Point::new(60_640, -162_000),
        ..m68x6()
    };
    let (moves, n) = walk(&c);
    assert!(moves > 7 * 40 * 5, "{moves}");
    assert_eq!(n, 0);
}

#[test]
fn linuxcnc_does_not_allocate() {
    // The taper thread of spec/tests/linuxcnc.rs (R1.5: every depth an
    // interval power), and G7 with the tie J0.1 R1.5 K0.4 (an exact power)
    // and a Q that needs the 512-bit tangent nowhere but is irrational.
    let mut c = cycleref::examples::LINUXCNC_TAPER;
    for tie in [false, true] {
        if tie {
            c.x_mode = cycleref::XMode::Diameter;
            c.initial_depth = 1_000;
            c.full_depth = 4_000;
            c.compound_angle = -123_457;
        }
        let mut moves = 0_u64;
        let n = allocations(|| {
            for m in cycleref::expand_linuxcnc(&c).unwrap_or_else(|e| panic!("{e}")) {
                moves += 1;
                std::hint::black_box(m);
            }
        });
        assert!(moves > 40, "{moves}");
        assert_eq!(n, 0);
    }
}

#[test]
fn g78_modes_do_not_allocate() {
    // The G78 infeed modes G76 lacks (centre, left flank, the 980TDi's
    // alternating flanks) and the equal depth steps, on M68x6's thread.
    for (infeed, depth_mode) in [
        (Infeed::Centre, cycleref::DepthMode::Equal),
        (Infeed::LeftFlank, cycleref::DepthMode::Decreasing),
        (Infeed::Alternating, cycleref::DepthMode::Equal),
        (Infeed::Alternating, cycleref::DepthMode::Decreasing),
    ] {
        let c = G76Cycle { infeed, depth_mode, starts: 2, ..m68x6() };
        let (moves, n) = walk(&c);
        assert!(moves >= 2 * 3 * 5, "{infeed:?} {depth_mode:?}: {moves}");
        assert_eq!(n, 0, "{infeed:?} {depth_mode:?}");
    }
}

#[test]
fn g92_does_not_allocate() {
    // O0012's first block (A = X65 Z5, C = X58.7 Z-28, F3 J3 K1) with three
    // starts, a taper and a face thread (988TA P1).
    let c = cycleref::G92Cycle {
        units: cycleref::Units::IS_B_METRIC,
        x_mode: cycleref::XMode::Diameter,
        start: Point::new(65_000, 5_000),
        end: Point::new(58_700, -28_000),
        taper: -1_000,
        lead: Lead { word: LeadWord::F, mantissa: 3, scale: 0 },
        run_out: cycleref::RunOut::Amounts { short: 3_000, long: 1_000 },
        starts: 3,
        start_angle: cycleref::StartAngle::ZERO,
        face: false,
        readings: cycleref::CycleReadings::DEFAULT,
    };
    let face = cycleref::G92Cycle {
        start: Point::new(60_000, 5_000),
        end: Point::new(20_000, 1_000),
        taper: 0,
        face: true,
        ..c
    };
    for c in [c, face] {
        let mut moves = 0_u64;
        let n = allocations(|| {
            for m in cycleref::expand_g92(&c).unwrap_or_else(|e| panic!("{e}")) {
                moves += 1;
                std::hint::black_box(m);
            }
        });
        assert_eq!(moves, 3 * 5);
        assert_eq!(n, 0);
    }
}
