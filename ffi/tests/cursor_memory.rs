//! The cursor's memory does not grow with the program: besides its copy of
//! the text, opening a program of 10 000 cycles and taking every move needs
//! no more live heap than a program of 1 000 (and `cycleref_expand` with a
//! buffer of capacity 0 needs none beyond a constant either).
//!
//! A counting global allocator measures the peak of live heap bytes; this
//! binary has one test, so that no other test allocates meanwhile.
//! `cargo test -p cycleref-ffi --test cursor_memory -- --nocapture` prints
//! the figures.

use std::alloc::{GlobalAlloc, Layout, System};
use std::ptr;
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};

use cycleref_ffi::*;

/// The system allocator, counting live bytes, their peak and the number
/// of allocations.
struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Set on the thread that measures: the test harness allocates on its
    /// own threads meanwhile (capturing output), which must not count.
    static MEASURED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// True on the measuring thread (`try_with`: the thread-local may be gone
/// while a thread exits).
fn measured() -> bool {
    MEASURED.try_with(std::cell::Cell::get).unwrap_or(false)
}

fn grow(n: usize) {
    if !measured() {
        return;
    }
    let live = LIVE.fetch_add(n, Relaxed) + n;
    PEAK.fetch_max(live, Relaxed);
    ALLOCATIONS.fetch_add(1, Relaxed);
}

#[allow(unsafe_code)]
// SAFETY: every call is forwarded to `System` with the same arguments; the
// counters are only arithmetic on the side.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        // SAFETY: the caller's contract, forwarded.
        unsafe { System.dealloc(p, layout) };
        if measured() {
            LIVE.fetch_sub(layout.size(), Relaxed);
        }
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract, forwarded.
        let q = unsafe { System.realloc(p, layout, new_size) };
        if !q.is_null() && measured() {
            LIVE.fetch_sub(layout.size(), Relaxed);
            grow(new_size);
        }
        q
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Starts a measurement: the peak is reset to what is live now.
fn start() -> (usize, usize) {
    let live = LIVE.load(Relaxed);
    PEAK.store(live, Relaxed);
    (live, ALLOCATIONS.load(Relaxed))
}

/// Peak live bytes above the start, and allocations since it.
fn since((live, allocations): (usize, usize)) -> (usize, usize) {
    (PEAK.load(Relaxed) - live, ALLOCATIONS.load(Relaxed) - allocations)
}

/// A GSK 980TDi program (IS-B, mm) of `n` rounds of the three cycles:
/// `3n` cycles, a G76, a G32 and a G75.1 each round.
fn program(n: usize) -> Vec<u8> {
    let mut p = String::from("M03 S600\n");
    for _ in 0..n {
        p.push_str(
            "G00 X80 Z10\nG76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\n\
             G00 X40 Z2\nG32 Z-30 F2 J1.5 K3 Q90000\n\
             G00 X52 Z3\nG75.1 X50 Z0 P4000 Q2000 H-6 D-5\nG75.1 R0.5 I2 J1 D0.5 P0010\n",
        );
    }
    p.push_str("M30\n");
    p.into_bytes()
}

struct Figures {
    text: usize,
    moves: usize,
    /// Peak live bytes of open + every move + close, above the start.
    cursor_peak: usize,
    /// Of that, during `cycleref_cursor_next` only (above what the open
    /// left live).
    next_peak: usize,
    /// Allocations by all the `cycleref_cursor_next` calls.
    next_allocations: usize,
    /// Peak live bytes of `cycleref_expand` with capacity 0.
    expand_peak: usize,
}

#[allow(unsafe_code)]
fn measure(text: &[u8], opts: &CyclerefOptions) -> Figures {
    let mut err = CyclerefError::default();
    let mut m = CyclerefMove::default();
    let mut moves = 0;
    let all = start();
    // SAFETY: valid program, options and outputs; the cursor is used here
    // only and closed once.
    let (next_peak, next_allocations) = unsafe {
        let c = cycleref_cursor_open(text.as_ptr().cast(), text.len(), opts, &mut err);
        assert!(!c.is_null(), "{}", err.message());
        let peak_after_open = PEAK.load(Relaxed);
        let taking = start();
        loop {
            match cycleref_cursor_next(c, &mut m, &mut err) {
                1 => moves += 1,
                0 => break,
                s => panic!("{s}: {}", err.message()),
            }
        }
        let taken = since(taking);
        cycleref_cursor_close(c);
        // Restore the peak of the whole run.
        PEAK.fetch_max(peak_after_open, Relaxed);
        taken
    };
    let (cursor_peak, _) = since(all);
    assert_eq!(LIVE.load(Relaxed), all.0, "the cursor leaks");

    let mut count = 0;
    let expanding = start();
    // SAFETY: valid program, options and outputs; capacity 0 with NULL.
    let s = unsafe {
        cycleref_expand(text.as_ptr().cast(), text.len(), opts, ptr::null_mut(), 0, &mut count, &mut err)
    };
    let (expand_peak, _) = since(expanding);
    assert_eq!((s, count), (CyclerefStatus::BufferTooSmall, moves));
    Figures { text: text.len(), moves, cursor_peak, next_peak, next_allocations, expand_peak }
}

#[test]
fn cursor_memory_does_not_grow_with_the_program() {
    // Rounds of three cycles: about 1 000 and 10 000 cycles.
    // Measured on a thread of its own, counted from its first step, so that
    // every allocation it frees was counted (the harness's threads are not).
    let (small, large) = std::thread::spawn(move || {
        MEASURED.with(|m| m.set(true));
        let opts = CyclerefOptions { profile: CyclerefProfile::Gsk980 as u32, ..cycleref_options_default() };
        let (small_text, large_text) = (program(334), program(3_334));
        // Warm up (anything the first call allocates once and keeps, such
        // as the standard library's buffers).
        measure(&program(1), &opts);
        (measure(&small_text, &opts), measure(&large_text, &opts))
    })
    .join()
    .expect("the measuring thread");
    for (n, f) in [(1_002, &small), (10_002, &large)] {
        println!(
            "{n} cycles: text {} B, {} moves; cursor peak {} B (text copy + {} B), during next {} B with {} \
             allocations ({:.3} per move); cycleref_expand (count only) peak {} B",
            f.text,
            f.moves,
            f.cursor_peak,
            f.cursor_peak.saturating_sub(f.text),
            f.next_peak,
            f.next_allocations,
            f.next_allocations as f64 / f.moves as f64,
            f.expand_peak,
        );
    }
    assert_eq!(large.moves * 334, small.moves * 3_334);
    // The cursor: its copy of the text, plus the same constant.
    assert!(small.cursor_peak >= small.text && large.cursor_peak >= large.text);
    let (small_extra, large_extra) = (small.cursor_peak - small.text, large.cursor_peak - large.text);
    assert_eq!(large_extra, small_extra, "the cursor's memory beyond the text grows with the program");
    assert!(large_extra < 16 * 1024, "{large_extra} B beyond the text");
    // Taking the moves needs no more memory for a longer program, and
    // allocates nothing per move (a G75.1's iterator is boxed: at most one
    // allocation per cycle).
    assert_eq!(large.next_peak, small.next_peak);
    assert!(large.next_allocations <= 10_002, "{} allocations", large.next_allocations);
    // cycleref_expand keeps no copy at all.
    assert_eq!(large.expand_peak, small.expand_peak);
    assert!(large.expand_peak < 16 * 1024, "{} B", large.expand_peak);
}
