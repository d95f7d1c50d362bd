//! Streaming in bounded memory (issue 11): the reader's and the writers'
//! peak live heap bytes do not grow with the number of blocks and cycles.
//!
//! A counting global allocator records, for the thread that asks, the bytes
//! allocated minus the bytes freed and the highest value that difference
//! reaches. Each measurement runs once on a program of `N` G76 cycles and
//! once on the same program with `10 N` cycles; the program's text is built
//! (and, for the writers, put in its [`Job`]) before counting starts, so the
//! text itself, which the design holds once, is not counted.
//!
//! A global allocator needs `unsafe impl GlobalAlloc`: like
//! `proofs/tests/no_alloc.rs`, this test file allows `unsafe` for that alone
//! (the workspace lint is `deny`, every library crate has
//! `#![forbid(unsafe_code)]`).
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use cycleref_cli::{output, plot, Format, Job};
use cycleref_spec::pipeline::{Cycle, Engine};
use cycleref_spec::{Machine, ProfileName, Reader};

/// Live bytes and their peak, for the threads that asked for counting.
#[derive(Clone, Copy)]
struct Live {
    now: i64,
    peak: i64,
}

thread_local! {
    static LIVE: Cell<Option<Live>> = const { Cell::new(None) };
}

fn track(delta: i64) {
    // `try_with`: the thread-local may be gone while a thread exits.
    let _ = LIVE.try_with(|c| {
        if let Some(mut l) = c.get() {
            l.now += delta;
            l.peak = l.peak.max(l.now);
            c.set(Some(l));
        }
    });
}

fn size(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

/// The system allocator, counting live bytes for the threads that asked.
struct Counting;

// SAFETY: every method forwards to `System` with the caller's arguments
// unchanged, so `System`'s guarantees hold; the bookkeeping is a
// thread-local `Cell` of a `Copy` value, which neither allocates nor
// re-enters the allocator. A failed allocation (null) is not counted.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged (see the impl).
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            track(size(layout.size()));
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged (see the impl).
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            track(size(layout.size()));
        }
        p
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded unchanged (see the impl).
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            track(size(new_size) - size(layout.size()));
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        track(-size(layout.size()));
        // SAFETY: forwarded unchanged (see the impl).
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The peak live bytes `f` allocates on this thread above what was live
/// when it started.
fn peak(f: impl FnOnce()) -> i64 {
    LIVE.with(|c| c.set(Some(Live { now: 0, peak: 0 })));
    f();
    LIVE.with(|c| c.replace(None)).map_or(0, |l| l.peak)
}

/// A program of `n` G76 cycles (M68x6 of the 988TA manual, O0013), each
/// followed by a G00 return to the start point.
fn program(n: usize) -> Vec<u8> {
    let mut s = String::from("O0013\nG50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n");
    for i in 0..n {
        // Two ends alternate, so that not every cycle is the same.
        let z = if i % 2 == 0 { "-62" } else { "-40.5" };
        s.push_str(&format!("N{} G76 X60.64 Z{z} P3.680 Q1.800 F6 (cycle {i})\nG00 X80 Z10\n", i + 1));
    }
    s.push_str("M30\n");
    s.into_bytes()
}

const N: usize = 2_000;
/// The JSON writers are slower in a debug build (serde_json unoptimised):
/// fewer cycles, still enough to see a byte per cycle.
const N_JSON: usize = 500;

fn job(n: usize, engine: Engine) -> Job {
    Job::new("bounded.nc", program(n), Machine::new(ProfileName::Gsk988), engine)
}

/// Asserts that the peak measured on `10 n` cycles is within 10 % and
/// 4 KiB of the one on `n` cycles (a cost of even a few bytes per cycle
/// would break it), and that it is small in absolute terms.
fn assert_flat(what: &str, n: usize, small: i64, large: i64) {
    eprintln!("{what}: peak live bytes {small} for {n} cycles, {large} for {} cycles", 10 * n);
    assert!(
        large * 10 <= small * 11 + 4096 * 10,
        "{what}: peak live bytes grow with the program: {small} for {n} cycles, {large} for {} cycles",
        10 * n
    );
    // The output buffer is 64 KiB; one cycle's moves in the reference model
    // a few KiB more.
    assert!(large < 256 * 1024, "{what}: {large} live bytes");
}

#[test]
fn the_counter_sees_live_bytes() {
    let p = peak(|| {
        let a = std::hint::black_box(vec![0_u8; 1000]);
        drop(a);
        let b = std::hint::black_box(vec![0_u8; 300]);
        drop(b);
    });
    assert_eq!(p, 1000);
}

#[test]
fn the_reader_reads_in_constant_memory() {
    let measure = |n: usize| {
        let text = program(n);
        let machine = Machine::new(ProfileName::Gsk988);
        let (mut items, mut cycles) = (0_usize, 0_usize);
        let p = peak(|| {
            for item in Reader::new(&text, &machine) {
                let item = item.unwrap_or_else(|e| panic!("{e}"));
                items += 1;
                cycles += usize::from(Cycle::of(&item).is_some());
            }
        });
        // O, G50, G00, G76 block 1, then a cycle and a G00 per cycle, M30.
        assert_eq!((items, cycles), (4 + 2 * n + 1, n));
        p
    };
    assert_flat("reader", N, measure(N), measure(10 * N));
}

fn writer_peak(n: usize, engine: Engine, write: fn(&Job)) -> i64 {
    let job = job(n, engine);
    peak(|| write(&job))
}

#[test]
fn expand_nc_streams_in_constant_memory() {
    let write: fn(&Job) = |job| output::expand(job, Format::Nc, std::io::sink()).expect("expands");
    for engine in [Engine::Impl, Engine::Spec] {
        let what = format!("expand nc ({engine:?})");
        assert_flat(&what, N, writer_peak(N, engine, write), writer_peak(10 * N, engine, write));
    }
}

#[test]
fn expand_json_streams_in_constant_memory() {
    let write: fn(&Job) = |job| output::expand(job, Format::Json, std::io::sink()).expect("expands");
    let (small, large) =
        (writer_peak(N_JSON, Engine::Impl, write), writer_peak(10 * N_JSON, Engine::Impl, write));
    assert_flat("expand json", N_JSON, small, large);
}

#[test]
fn expand_jsonl_streams_in_constant_memory() {
    let write: fn(&Job) = |job| output::expand(job, Format::Jsonl, std::io::sink()).expect("expands");
    let (small, large) =
        (writer_peak(N_JSON, Engine::Impl, write), writer_peak(10 * N_JSON, Engine::Impl, write));
    assert_flat("expand jsonl", N_JSON, small, large);
}

#[test]
fn passes_streams_in_constant_memory() {
    let write: fn(&Job) = |job| output::passes(job, std::io::sink()).expect("tabulates");
    assert_flat("passes", N, writer_peak(N, Engine::Impl, write), writer_peak(10 * N, Engine::Impl, write));
}

#[test]
fn the_writers_really_write() {
    // The sink measurements above are only worth something if the writers
    // do write the whole program: count what they write for a few cycles.
    let job = job(3, Engine::Impl);
    let mut nc = Vec::new();
    output::expand(&job, Format::Nc, &mut nc).expect("expands");
    let text = String::from_utf8(nc).expect("utf-8");
    // M68x6 to Z-62: 30 moves (manual O0013); to Z-40.5 the same passes.
    assert_eq!(text.matches("(G76 line ").count(), 3, "{text}");
    assert_eq!(text.lines().filter(|l| l.starts_with("G32 ")).count(), 3 * 12, "{text}");
    assert!(text.ends_with("G00 X80 Z10\nM30\n"), "{text}");
}

#[test]
fn the_measure_sees_a_program_held_whole() {
    // The control: collecting every item (`read`, which keeps a Vec of the
    // whole program) does grow with the program, and the measure shows it.
    let measure = |n: usize| {
        let text = String::from_utf8(program(n)).expect("utf-8");
        let machine = Machine::new(ProfileName::Gsk988);
        peak(|| {
            let p = cycleref_spec::read(&text, &machine).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(p.cycles().count(), n);
        })
    };
    let (small, large) = (measure(N), measure(10 * N));
    assert!(large > 5 * small, "{small} -> {large}");
}

/// `program(n)` in a file of its own in the temporary directory.
fn program_file(n: usize, tag: &str) -> std::path::PathBuf {
    let path = std::env::temp_dir().join(format!("cycleref-bounded-{}-{tag}-{n}.nc", std::process::id()));
    std::fs::write(&path, program(n)).expect("writes the program");
    path
}

#[test]
fn a_program_in_a_file_is_never_held_whole() {
    // Counting starts before the job exists: a job that held the file's
    // text (about 60 bytes a cycle) would grow by 1 MB from N to 10 N.
    let measure = |n: usize, write: fn(&Job)| {
        let path = program_file(n, "file");
        let p = peak(|| {
            let job = Job::from_file(&path, Machine::new(ProfileName::Gsk988), Engine::Impl)
                .unwrap_or_else(|e| panic!("{}", String::from(e)));
            write(&job);
        });
        std::fs::remove_file(&path).expect("removes the program");
        p
    };
    let nc: fn(&Job) = |job| output::expand(job, Format::Nc, std::io::sink()).expect("expands");
    assert_flat("expand nc from a file", N, measure(N, nc), measure(10 * N, nc));
    let passes: fn(&Job) = |job| output::passes(job, std::io::sink()).expect("tabulates");
    assert_flat("passes from a file", N, measure(N, passes), measure(10 * N, passes));
    // Line 5 is the first cycle (O, G50, G00, G76 block 1 before it).
    let plot: fn(&Job) = |job| {
        let (svg, note) = plot::run(job, &[5], None).unwrap_or_else(|e| panic!("{}", String::from(e)));
        assert!(svg.contains("G76 at line 5") && note.is_none());
    };
    assert_flat("plot --line 5 from a file", N, measure(N, plot), measure(10 * N, plot));
}

#[test]
fn a_file_read_line_by_line_gives_what_the_held_text_gives() {
    let path = program_file(5, "same");
    let from_file = Job::from_file(&path, Machine::new(ProfileName::Gsk988), Engine::Impl)
        .unwrap_or_else(|e| panic!("{}", String::from(e)));
    let (mut a, mut b) = (Vec::new(), Vec::new());
    output::expand(&from_file, Format::Nc, &mut a).expect("expands");
    output::expand(&job(5, Engine::Impl), Format::Nc, &mut b).expect("expands");
    std::fs::remove_file(&path).expect("removes the program");
    assert_eq!(String::from_utf8(a).expect("utf-8"), String::from_utf8(b).expect("utf-8"));
}

#[test]
fn a_file_changed_after_the_start_is_an_error_and_writes_nothing() {
    let path = program_file(3, "changed");
    let job = Job::from_file(&path, Machine::new(ProfileName::Gsk988), Engine::Impl)
        .unwrap_or_else(|e| panic!("{}", String::from(e)));
    // Another length: the change is seen whatever the clock's resolution.
    std::fs::write(&path, program(4)).expect("rewrites the program");
    let mut out = Vec::new();
    let e = output::expand(&job, Format::Nc, &mut out).expect_err("the file changed");
    std::fs::remove_file(&path).expect("removes the program");
    let message = String::from(e);
    assert!(message.contains("the file changed while it was read"), "{message}");
    assert!(out.is_empty());
}

#[test]
fn a_file_read_in_pieces_gives_what_the_held_text_gives() {
    // Pieces of whole lines (`job::CHUNK` bytes at a time): lines across
    // piece boundaries, CR LF line ends, a comment line longer than a
    // piece, and a last line without a line end give the same output as
    // the text held whole, and an error the same line.
    let mut text = String::from_utf8(program(3000)).expect("utf-8").replace('\n', "\r\n");
    text.insert_str(0, &format!("({})\r\n", "x".repeat(3 * cycleref_cli::job::CHUNK / 2)));
    // M05 for the program's M30: a line after M30 would not be read
    // (reading R-PROGRAMEND).
    let text = text.trim_end().trim_end_matches("M30").to_string() + "M05";
    assert!(text.len() > 3 * cycleref_cli::job::CHUNK, "{}", text.len());
    let run = |bytes: &str| {
        let path = std::env::temp_dir().join(format!("cycleref-bounded-{}-pieces.nc", std::process::id()));
        std::fs::write(&path, bytes).expect("writes the program");
        let machine = Machine::new(ProfileName::Gsk988);
        let from_file = Job::from_file(&path, machine.clone(), Engine::Impl)
            .unwrap_or_else(|e| panic!("{}", String::from(e)));
        let held = Job::new(&path.display().to_string(), bytes.as_bytes().to_vec(), machine, Engine::Impl);
        let (mut a, mut b) = (Vec::new(), Vec::new());
        let ra = output::expand(&from_file, Format::Nc, &mut a).map_err(String::from);
        let rb = output::expand(&held, Format::Nc, &mut b).map_err(String::from);
        std::fs::remove_file(&path).expect("removes the program");
        assert_eq!(ra, rb);
        assert_eq!(a, b);
        (ra, a)
    };
    let (r, out) = run(&text);
    assert!(r.is_ok() && out.len() > 100_000, "{r:?}");
    // An error on the last line (no line end after it) names that line.
    let lines = text.lines().count();
    let (r, out) = run(&format!("{text}\r\nG01 X1 X2"));
    let e = r.expect_err("a repeated X");
    assert!(e.contains(&format!("line {}", lines + 1)), "{e}");
    assert!(out.is_empty());
}

/// A single M68x6 G76 cycle of `starts` starts (L), as a program file and
/// its expansion as a trace file.
fn multi_start(starts: u32) -> (std::path::PathBuf, std::path::PathBuf) {
    let text = format!(
        "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 L{starts}\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n\
         G00 X100 Z50\nM30\n"
    );
    let dir = std::env::temp_dir();
    let program = dir.join(format!("cycleref-bounded-{}-starts-{starts}.nc", std::process::id()));
    std::fs::write(&program, text).expect("writes the program");
    let job = Job::from_file(&program, Machine::new(ProfileName::Gsk988), Engine::Impl)
        .unwrap_or_else(|e| panic!("{}", String::from(e)));
    let mut nc = Vec::new();
    output::expand(&job, Format::Nc, &mut nc).expect("expands");
    let trace = dir.join(format!("cycleref-bounded-{}-starts-{starts}-trace.nc", std::process::id()));
    std::fs::write(&trace, nc).expect("writes the trace");
    (program, trace)
}

#[test]
fn check_and_plot_hold_no_cycle_whole() {
    // Issue 29, found 4: `check` collected a whole G76 into a Vec to find
    // where its cut starts (L999 aborted at 5.9 GB). The peak live bytes of
    // `check` and of `plot` do not grow with the starts:
    // `check` aligns a window of at most 512 passes at a time (reading
    // R-CHECKSTREAM), which a cycle of 1 start (7 passes) does not fill and
    // one of 400 starts (2 800 passes) overflows with its read-ahead of the
    // trace (at most 1 024 groups); from there on the peak is flat:
    // the same for 400 and 800 starts, twice the moves (800: 360°/L is a
    // whole number of thousandths, which the expansion's Q can write exactly).
    let measure = |starts: u32, engine: Engine, what: &str| {
        let (program, trace) = multi_start(starts);
        let p = peak(|| {
            let job = Job::from_file(&program, Machine::new(ProfileName::Gsk988), engine)
                .unwrap_or_else(|e| panic!("{}", String::from(e)));
            match what {
                "check" => {
                    let report = cycleref_cli::check::run(&job, &trace, 0).expect("checks");
                    assert!(report.agree());
                }
                _ => {
                    // Drawn whole: the limit is on moves, not on memory; so
                    // here only the starts' count is streamed past.
                    let e = plot::run(&job, &[99], None).map(|_| ()).map_err(String::from);
                    assert!(e.expect_err("no cycle at line 99").contains("--line 99"));
                }
            }
        });
        std::fs::remove_file(&program).expect("removes the program");
        std::fs::remove_file(&trace).expect("removes the trace");
        p
    };
    // Both engines: the exact-decimal reference (`--engine spec`) makes a
    // G76 a pass and a start at a time too (`spec::pass::PassStream`; it
    // held the cycle's moves, about 3.6 KB a start here).
    for engine in [Engine::Impl, Engine::Spec] {
        let one = measure(1, engine, "check");
        let (small, large) = (measure(400, engine, "check"), measure(800, engine, "check"));
        eprintln!("check ({engine:?}): peak live bytes {one} for 1 start, {small} for 400, {large} for 800");
        assert!(large * 10 <= small * 11 + 40_960, "check ({engine:?}): {small} -> {large}");
        assert!(large < 4 << 20, "check ({engine:?}): {large} live bytes");
    }
    let (small, large) = (measure(1, Engine::Impl, "plot"), measure(800, Engine::Impl, "plot"));
    eprintln!("plot: peak live bytes {small} for 1 start, {large} for 800");
    assert!(large * 10 <= small * 11 + 40_960, "plot: {small} -> {large}");
}

#[test]
fn plot_refuses_a_cycle_too_long_to_draw_before_holding_it() {
    // 999 starts of M68x6: 29 971 moves in check's count; 10 times more
    // with P(m) 99 finishing passes... here a cycle of Q0.001 first depth:
    // passes √n × 0.001 ≥ 3.58 mm deep take n ≈ 12.8 million passes over
    // L2: far beyond MAX_DRAWN_MOVES. Refused, and the peak stays small.
    let text = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.001 R0.1 L40\nG76 X60.64 Z-62 P3.680 Q0.010 F6\nM30\n";
    let job = Job::new("long.nc", text.as_bytes().to_vec(), Machine::new(ProfileName::Gsk988), Engine::Impl);
    let mut message = String::new();
    let p = peak(|| {
        message = plot::run(&job, &[], None).map(|_| ()).map_err(String::from).expect_err("too long");
    });
    assert!(message.contains("plot draws cycles of at most 200000 moves"), "{message}");
    assert!(p < 256 * 1024, "{p} live bytes");
}

/// A writer that changes the program's file when it is first written to
/// (so, during the second phase), by `change`.
struct ChangingWriter {
    out: Vec<u8>,
    change: Option<Box<dyn FnOnce()>>,
}

impl std::io::Write for ChangingWriter {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if let Some(change) = self.change.take() {
            change();
        }
        self.out.extend_from_slice(buf);
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

#[test]
fn a_file_changed_during_the_second_phase_is_an_error() {
    // Issue 30, found 4: a line appended during phase 2 was expanded with
    // exit 0, and an in-place edit of the same length was caught only
    // after 193 MB. Each piece of the second reading is now compared with
    // the first's before a block of it is read (reading R-CHANGED): the
    // output is a prefix of the right one, and the command fails.
    let right = {
        let path = program_file(3000, "during-right");
        let job = Job::from_file(&path, Machine::new(ProfileName::Gsk988), Engine::Impl)
            .unwrap_or_else(|e| panic!("{}", String::from(e)));
        let mut out = Vec::new();
        output::expand(&job, Format::Nc, &mut out).expect("expands");
        std::fs::remove_file(&path).expect("removes the program");
        out
    };
    let appended = |path: std::path::PathBuf| -> Box<dyn FnOnce()> {
        Box::new(move || {
            let mut f = std::fs::OpenOptions::new().append(true).open(&path).expect("opens");
            std::io::Write::write_all(&mut f, b"G76 X60.64 Z-6 P3.680 Q1.800 F6\n").expect("appends");
        })
    };
    let edited = |path: std::path::PathBuf| -> Box<dyn FnOnce()> {
        Box::new(move || {
            // The same length: Z-62 of the last cycle becomes Z-61.
            let mut text = std::fs::read(&path).expect("reads");
            let at = text.windows(4).rposition(|w| w == b"Z-62").expect("a Z-62");
            text[at + 3] = b'1';
            std::fs::write(&path, text).expect("rewrites");
        })
    };
    for (tag, change) in [("append", appended as fn(_) -> _), ("edit", edited)] {
        let path = program_file(3000, tag);
        let job = Job::from_file(&path, Machine::new(ProfileName::Gsk988), Engine::Impl)
            .unwrap_or_else(|e| panic!("{}", String::from(e)));
        let mut w = ChangingWriter { out: Vec::new(), change: Some(change(path.clone())) };
        let e = output::expand(&job, Format::Nc, &mut w).expect_err("the file changed");
        std::fs::remove_file(&path).expect("removes the program");
        let message = String::from(e);
        assert!(message.contains("the file changed while it was read"), "{tag}: {message}");
        assert!(
            w.out.len() < right.len() && right.starts_with(&w.out),
            "{tag}: a prefix of the right output"
        );
    }
}

#[test]
fn cr_lf_and_crlf_are_all_line_ends_across_pieces() {
    // Issue 30, found 5: a file with CR line ends was one line ("every
    // message says line 1"). Reading R-LINEEND: LF, CR LF and a lone CR
    // end a line, also where a piece of the file ends between a CR and its
    // LF. The file read in pieces gives what the held text gives, and what
    // the LF text gives: the same output, the same line in an error.
    // M05 for the program's M30, so that a line after it is read.
    let lf = String::from_utf8(program(3000)).expect("utf-8").replace("M30\n", "M05\n");
    let expanded = |bytes: &[u8], file: bool| -> (Result<(), String>, Vec<u8>) {
        let machine = Machine::new(ProfileName::Gsk988);
        let path = std::env::temp_dir().join(format!("cycleref-bounded-{}-cr.nc", std::process::id()));
        let job = if file {
            std::fs::write(&path, bytes).expect("writes the program");
            Job::from_file(&path, machine, Engine::Impl).unwrap_or_else(|e| panic!("{}", String::from(e)))
        } else {
            Job::new("cr.nc", bytes.to_vec(), machine, Engine::Impl)
        };
        let mut out = Vec::new();
        let r = output::expand(&job, Format::Nc, &mut out).map_err(String::from);
        if file {
            std::fs::remove_file(&path).expect("removes the program");
        }
        (r, out)
    };
    let lines = lf.lines().count();
    for pad in 0..4 {
        // Shift the text by 0 to 3 bytes so that line ends fall on every
        // side of the 64 KiB piece boundary.
        let padded = format!("({})\n{lf}", "x".repeat(pad));
        let (r, want) = expanded(padded.as_bytes(), false);
        assert!(r.is_ok() && want.len() > 100_000);
        for end in ["\r", "\r\n"] {
            let text = padded.replace('\n', end);
            for file in [false, true] {
                let (r, out) = expanded(text.as_bytes(), file);
                assert!(r.is_ok(), "{end:?} pad {pad} file {file}: {r:?}");
                let first_difference =
                    out.split(|&b| b == b'\n').zip(want.split(|&b| b == b'\n')).position(|(a, b)| a != b);
                assert!(
                    out == want,
                    "{end:?} pad {pad} file {file}: output line {first_difference:?} differs"
                );
                // An error on the last line names it.
                let bad = format!("{text}G01 X1 X2{end}");
                let (r, _) = expanded(bad.as_bytes(), file);
                let e = r.expect_err("a repeated X");
                assert!(e.contains(&format!("line {}, word `X2`", lines + 2)), "{end:?} pad {pad}: {e}");
            }
        }
    }
}

#[test]
fn the_reference_makes_a_linuxcnc_g76_a_pass_at_a_time() {
    // LinuxCNC's G76 with H spring passes: 20 and 2 000 passes at full
    // depth (about 4 and 400 KB of moves, were they held). The reference
    // (`--engine spec`) makes them a pass at a time: the same peak.
    let measure = |spring: u32| {
        let text = format!("G18 G21 G8\nM3 S500\nG0 X10 Z1\nG76 P1 Z-10 I-0.5 J0.1 K0.3 H{spring}\nM2\n");
        let machine = Machine::new(ProfileName::LinuxCnc);
        let program = cycleref_spec::read(&text, &machine).expect("reads");
        let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
        let mut count = 0;
        let p = peak(|| {
            count = cycleref_spec::pipeline::expand(cycle, Engine::Spec).expect("expands").count();
        });
        (count, p)
    };
    let ((few, small), (many, large)) = (measure(20), measure(2_000));
    eprintln!("reference, LinuxCNC G76: peak live bytes {small} for {few} moves, {large} for {many}");
    // R1: depths n·J = 0.1, 0.2 below K = 0.3, so 2 rough passes; then
    // 1 + H at full depth; 4 moves a pass, and the return.
    assert_eq!((few, many), ((2 + 21) * 4 + 1, (2 + 2_001) * 4 + 1));
    assert!(large * 10 <= small * 11 + 4_096, "{small} -> {large}");
}

#[test]
fn the_reference_makes_a_g75_1_a_peck_at_a_time() {
    // Issue 29 (R-G75RANGE): the reference (`--engine spec`) held a
    // G75.1's moves to check their range; it now checks them as it makes
    // them, keeps none, and makes them again as they are taken. A groove
    // of a few pecks and one of thousands: the same peak, and the same
    // moves as the engine's (an independent implementation).
    let measure = |depth: u32, width: u32| {
        let text = format!(
            "M03 S800\nG00 X210 Z5\nG75.1 X200 Z0 P2000 Q3000 H-{depth} D-{width}\nG75.1 R0.5 U0.4 W0.2 I3 J1\nM30\n"
        );
        let machine = Machine::new(ProfileName::Gsk980);
        let program = cycleref_spec::read(&text, &machine).expect("reads");
        let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
        let engine: Vec<_> = cycleref_spec::pipeline::expand(cycle, Engine::Impl).expect("expands").collect();
        let mut reference = Vec::new();
        let p = peak(|| {
            let mut moves = cycleref_spec::pipeline::expand(cycle, Engine::Spec).expect("expands");
            // Compared as they come, none kept.
            for (i, m) in engine.iter().enumerate() {
                if moves.next().as_ref() != Some(m) {
                    reference.push(i);
                    break;
                }
            }
            if moves.next().is_some() {
                reference.push(engine.len());
            }
        });
        assert!(reference.is_empty(), "the reference differs from the engine at move {reference:?}");
        (engine.len(), p)
    };
    let ((few, small), (many, large)) = (measure(6, 8), measure(60, 400));
    eprintln!("reference, G75.1: peak live bytes {small} for {few} moves, {large} for {many}");
    assert!(many > 50 * few, "{few} -> {many} moves");
    assert!(large * 10 <= small * 11 + 4_096, "{small} -> {large}");
}
