//! `check` never says AGREE about a toolpath that differs (issue 29): each
//! way in which it did at 6457e19 is a test here that failed there.
//!
//! The expected values are worked by hand:
//!
//! * the verdict survives a closed pipe: a trace of
//!   `examples/gsk988-m68x6.nc` with every lead `F6.0` changed to `F6.1`
//!   differs at every thread move (12 per pass, a report far larger than a
//!   pipe's buffer when repeated over many cycles), and `| head -c 1`
//!   closes the pipe after one byte;
//! * `G00 X80.000 U3 Z10.000` names U and X on one axis: the program
//!   reader's error ("absolute and incremental words for the same axis");
//! * a trace `G32 X80 F2.0` / `G00 Z10` of a program `G00 X80` / `G00 Z10`:
//!   both first moves are made before Z is known; ours is a rapid to X80,
//!   theirs a thread to X80: a "kind of move" (the first block was dropped
//!   from both, and the check said AGREE, 4 = 4 moves);
//! * LinuxCNC's canonical output of `examples/linuxcnc-m20-taper.ngc`
//!   (printed by `rs274 -g`, held in `spec/tests/data/`) with one call
//!   changed at a time: each is an error naming the line.

mod common;

use common::run;
use std::path::PathBuf;
use std::process::{Command, Stdio};

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str, text: &str) -> PathBuf {
    common::tmp("check-verdict", name, text)
}

/// `check` of `program` (a path) against `trace` written to `name`: the exit
/// code and stdout + stderr.
fn check(profile: &str, program: &str, trace: &str, name: &str, extra: &[&str]) -> (i32, String) {
    let t = tmp(name, trace);
    let mut args = vec!["check", "--profile", profile, "--trace", t.to_str().expect("utf-8")];
    args.extend_from_slice(extra);
    args.push(program);
    let out = run(&args, None);
    (
        out.status.code().expect("exit code"),
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr),
    )
}

fn expand(profile: &str, program: &str) -> String {
    let out = run(&["expand", "--profile", profile, program], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

#[test]
fn differ_is_exit_1_even_when_the_report_meets_a_closed_pipe() {
    // 100 cycles of M68x6 with the lead wrong everywhere: 100 × 12 thread
    // moves differ, a report of about 150 KB, larger than a pipe's buffer
    // (64 KiB), so the write is still under way when the pipe closes.
    let mut program = String::from("G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n");
    for _ in 0..100 {
        program.push_str("G76 X60.64 Z-62 P3.680 Q1.800 F6\nG00 X80 Z10\n");
    }
    program.push_str("M30\n");
    let p = tmp("pipe.nc", &program);
    let p = p.to_str().expect("utf-8");
    let bad = expand("gsk988", p).replace("F6.0", "F6.1");
    let t = tmp("pipe-trace.nc", &bad);
    let mut child = Command::new(common::BIN)
        .args(["check", "--profile", "gsk988", "--trace", t.to_str().expect("utf-8"), p])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    // Read one byte and close the pipe, as `| head -c 1` does.
    let mut out = child.stdout.take().expect("stdout");
    let mut one = [0_u8; 1];
    std::io::Read::read_exact(&mut out, &mut one).expect("one byte");
    drop(out);
    let status = child.wait_with_output().expect("waits");
    assert_eq!(one[0], b'D', "the report starts with DIFFER");
    assert_eq!(status.status.code(), Some(1), "{}", String::from_utf8_lossy(&status.stderr));
    assert!(status.stderr.is_empty(), "quiet: {}", String::from_utf8_lossy(&status.stderr));
}

#[test]
fn a_full_disk_is_exit_2_with_a_message() {
    if !std::path::Path::new("/dev/full").exists() {
        return;
    }
    let m68 = example("gsk988-m68x6.nc");
    let t = tmp("full-trace.nc", &expand("gsk988", &m68));
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").expect("/dev/full");
    let out = Command::new(common::BIN)
        .args(["check", "--profile", "gsk988", "--trace", t.to_str().expect("utf-8"), &m68])
        .stdout(full)
        .stderr(Stdio::piped())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write the output"));
}

#[test]
fn an_error_message_on_a_full_stderr_keeps_the_status() {
    if !std::path::Path::new("/dev/full").exists() {
        return;
    }
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").expect("/dev/full");
    let out = Command::new(common::BIN)
        .args(["expand", "/nonexistent/missing.nc"])
        .stdout(Stdio::piped())
        .stderr(full)
        .output()
        .expect("runs");
    // Was 101: `eprintln!` panicked on the full device.
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn absolute_and_incremental_words_on_one_axis_are_refused_in_a_trace() {
    let program = tmp("ux.nc", "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM30\n");
    let program = program.to_str().expect("utf-8");
    for (trace, word) in [("G00 X80.000 U3 Z10.000\n", "U3"), ("U3 X80 W5 Z10\n", "U3")] {
        let (code, out) = check("fanuc", program, trace, "ux-trace.nc", &[]);
        assert_eq!(code, 2, "{trace}: {out}");
        assert!(
            out.contains(&format!("line 1, word `{word}`"))
                && out.contains("absolute and incremental words for the same axis"),
            "{trace}: {out}"
        );
    }
}

#[test]
fn a_move_before_the_position_is_known_is_compared_not_dropped() {
    let program = tmp("partial.nc", "G00 X80 M3 S300\nG00 Z10\nG32 Z-20 F2\nG00 X90\nZ10\nM30\n");
    let program = program.to_str().expect("utf-8");
    // The same first move agrees (and the expansion reads back).
    let (code, out) = check("fanuc", program, &expand("fanuc", program), "partial-same.nc", &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("AGREE: 5 moves of ours, 5 of the trace"), "{out}");
    // A rapid where ours is a rapid, but to another Z: the unknown Z of
    // the first move is shown as `?`.
    let trace = "G00 X80\nG00 Z11\nG32 Z-20 F2\nG00 X90\nZ10\n";
    let (code, out) = check("fanuc", program, trace, "partial-z.nc", &[]);
    assert_eq!(code, 1, "{out}");
    // A thread before the position is known has no start: the program
    // reader's own rule refuses it, by line (it was compared on X alone).
    let trace = "G32 X80 F2.0\nG00 Z10\nG32 Z-20 F2\nG00 X90\nZ10\n";
    let (code, out) = check("fanuc", program, trace, "partial-kind.nc", &[]);
    assert_eq!(code, 2, "{out}");
    assert!(out.contains("partial-kind.nc: line 1: the tool position is not known yet"), "{out}");
    // Another X before Z is known.
    let trace = "G00 X81 M3 S300\nG00 Z10\nG32 Z-20 F2\nG00 X90\nZ10\n";
    let (code, out) = check("fanuc", program, trace, "partial-x.nc", &[]);
    assert_eq!(code, 1, "{out}");
    // An incremental move before the position is known is an error.
    let trace = "G00 U3\nG00 X80 Z10\n";
    let (code, out) = check("fanuc", program, trace, "partial-u.nc", &[]);
    assert_eq!(code, 2, "{out}");
    assert!(out.contains("line 1, word `U3`: the tool position is not known yet"), "{out}");
}

/// rs274's canonical output of `examples/linuxcnc-m20-taper.ngc`.
fn m20_canon() -> String {
    std::fs::read_to_string(format!("{}/../spec/tests/data/m20-taper.canon", env!("CARGO_MANIFEST_DIR")))
        .expect("the canonical output")
}

fn check_canon(canon: &str, name: &str) -> (i32, String) {
    let m20 = example("linuxcnc-m20-taper.ngc");
    check("linuxcnc", &m20, canon, name, &["--tolerance", "1"])
}

#[test]
fn the_canonical_output_itself_agrees() {
    let (code, out) = check_canon(&m20_canon(), "m20.canon");
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("AGREE: 104 moves of ours, 104 of the trace"), "{out}");
}

#[test]
fn every_canonical_call_is_read_or_refused() {
    let canon = m20_canon();
    // Each case: a change to rs274's output, and the words of the error.
    let cases: [(&str, &str, &str); 8] = [
        (
            "   10 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)",
            "   10 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)",
            "in CANON_UNITS_INCHES while",
        ),
        ("SET_XY_ROTATION(0.0000)", "SET_XY_ROTATION(30.0000)", "XY rotation of 30.0000 degrees"),
        (
            "STRAIGHT_FEED(9.8500, 0.0000, -18.5644, 0.0000, 0.0000, 0.0000)",
            "STRAIGHT_FEED(9.8500, 5.0000, -18.5644, 0.0000, 0.0000, 0.0000)",
            "moves Y from 0.0000 to 5.0000",
        ),
        (
            "STRAIGHT_FEED(9.8500, 0.0000, -18.5644, 0.0000, 0.0000, 0.0000)",
            "STRAIGHT_FEED(9.8500, 0.0000, -18.5644, 5.0000, 0.0000, 0.0000)",
            "moves A from 0.0000 to 5.0000",
        ),
        ("DISABLE_FEED_OVERRIDE()", "TELEPORT_TOOL()", "the call `TELEPORT_TOOL` is not read"),
        (
            "   16 N..... DISABLE_FEED_OVERRIDE()",
            "DISABLE_FEED_OVERRIDE()",
            "not a line of rs274's canonical output",
        ),
        ("START_SPEED_FEED_SYNC(1.500000,0)", "START_SPEED_FEED_SYNC(1.500000,1)", "velocity mode 1"),
        ("SELECT_PLANE(CANON_PLANE_XZ)", "STRAIGHT_FEED(1, 2)", "2 arguments"),
    ];
    for (from, to, words) in cases {
        assert!(canon.contains(from), "{from}");
        let changed = canon.replacen(from, to, 1);
        let (code, out) = check_canon(&changed, "changed.canon");
        assert_eq!(code, 2, "{to}: {out}");
        assert!(out.contains(words) && out.contains("changed.canon: line "), "{to}: {out}");
    }
}

#[test]
fn calls_that_cannot_move_the_tool_are_skipped() {
    // Each of these, added before the first motion, changes nothing (their
    // list is `rs274::SKIPPED_CALLS`, every one seen in rs274's output).
    let canon = m20_canon();
    for call in [
        "COMMENT(\"x\")",
        "MESSAGE(\" hello\")",
        "DWELL(1.0000)",
        "FLOOD_ON()",
        "MIST_ON()",
        "SELECT_TOOL(1)",
        "CHANGE_TOOL(1)",
        "USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 12.9794, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)",
        "SET_G5X_OFFSET(1, 0.2500, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        "SET_G92_OFFSET(2.5000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.010000)",
        "PROGRAM_STOP()",
    ] {
        let changed = canon.replacen(
            "   13 N..... START_SPINDLE_CLOCKWISE(0)",
            &format!("   13 N..... START_SPINDLE_CLOCKWISE(0)\n   13 N..... {call}"),
            1,
        );
        let (code, out) = check_canon(&changed, "skipped.canon");
        assert_eq!(code, 0, "{call}: {out}");
    }
    // A line numbered by the program's N word is read like N.....
    let numbered = canon.replacen("   14 N..... STRAIGHT_TRAVERSE", "   14 N10    STRAIGHT_TRAVERSE", 1);
    assert_eq!(check_canon(&numbered, "numbered.canon").0, 0);
}

#[test]
fn a_csv_trace_is_read_by_flag_also_from_standard_input() {
    let program = tmp("csv.nc", "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM30\n");
    let program = program.to_str().expect("utf-8");
    let csv = b"motion,x,z\nrapid,80.000,10.000\n";
    let out =
        run(&["check", "--profile", "gsk988", "--trace", "-", "--trace-format", "csv", program], Some(csv));
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    // Named .txt, without the flag: read as a program, and the message says
    // what to pass.
    let t = tmp("csv.txt", std::str::from_utf8(csv).expect("utf-8"));
    let out = run(&["check", "--profile", "gsk988", "--trace", t.to_str().expect("utf-8"), program], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("pass --trace-format csv"));
    let out = run(
        &[
            "check",
            "--profile",
            "gsk988",
            "--trace",
            t.to_str().expect("utf-8"),
            "--trace-format",
            "csv",
            program,
        ],
        None,
    );
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
}

#[test]
fn plot_refuses_a_trace_that_is_not_a_regular_file() {
    let m68 = example("gsk988-m68x6.nc");
    let svg = std::env::temp_dir().join(format!("cycleref-verdict-{}.svg", std::process::id()));
    let out = run(
        &["plot", "--profile", "gsk988", "--trace", "/dev/stdin", "-o", svg.to_str().expect("utf-8"), &m68],
        Some(b"G00 X80 Z10\n"),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("give a regular file"));
}

#[test]
fn a_four_line_program_of_unbounded_work_is_refused_before_a_byte() {
    // Issue 30, found 3: 999 999 rough + 99 finishing passes × 999 starts
    // wrote 3.3 GB in 20 s. The budget (reading R-BUDGET) refuses it before
    // anything is written, whatever the output format.
    let p = tmp(
        "l999.nc",
        "G50 X3000 Z50 M3 S300\nG00 X2200 Z10\nG76 P990000 Q0.001 R0 L999 E1\nG76 X100 Z-62 P999.999 Q0.001 F6\nM30\n",
    );
    let p = p.to_str().expect("utf-8");
    for format in ["nc", "json", "jsonl"] {
        let started = std::time::Instant::now();
        let out = run(&["expand", "--profile", "gsk988", "--format", format, p], None);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        let e = String::from_utf8_lossy(&out.stderr);
        assert!(
            e.contains("line 4") && e.contains("999097902 pass paths") && e.contains("pass limit 1000000"),
            "{e}"
        );
        assert!(started.elapsed() < std::time::Duration::from_secs(10), "{:?}", started.elapsed());
    }
    // M68x6 at 999 starts: 4 rough + 2 finishing passes a start, 5 994
    // pass paths (the heading says so); a parameter file's pass_limit of
    // 5 993 refuses it with that count.
    let m = tmp(
        "m68-l999.nc",
        "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 L999\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n",
    );
    let m = m.to_str().expect("utf-8");
    let params = tmp("limit.toml", "pass_limit = 5993\n");
    let out = run(&["expand", "--profile", "gsk988", "--params", params.to_str().expect("utf-8"), m], None);
    assert_eq!(out.status.code(), Some(2));
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(e.contains("the cycle cuts 5994 pass paths") && e.contains("pass limit 5993"), "{e}");
    let params = tmp("limit.toml", "pass_limit = 5994\n");
    let out = run(&["expand", "--profile", "gsk988", "--params", params.to_str().expect("utf-8"), m], None);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        String::from_utf8_lossy(&out.stdout).contains("(G76 line 4: 4 rough + 2 finish passes x 999 starts)")
    );
}

#[test]
fn cycles_only_compares_the_cycles_moves_and_the_extra_pass_is_the_last() {
    // The expansion of M68x6 (43 lines): 1-4 the program's comment, O, G50
    // and G00 to A; 5-41 the cycle (heading, pass comments, 30 moves); 42
    // the program's G00 X100 Z50; 43 M30.
    let m68 = example("gsk988-m68x6.nc");
    let full = expand("gsk988", &m68);
    let lines: Vec<&str> = full.lines().collect();
    assert_eq!(lines.len(), 43);
    let cycle = lines[4..41].join("\n") + "\n";
    // A log of the cycle alone: AGREE with --cycles-only (30 = 30 moves),
    // DIFFER without (our two G00 blocks are missing from it).
    let (code, out) = check("gsk988", &m68, &cycle, "cycle-only.nc", &["--cycles-only"]);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("AGREE: 30 moves of ours, 30 of the trace"), "{out}");
    let (code, out) = check("gsk988", &m68, &cycle, "cycle-only.nc", &[]);
    assert_eq!(code, 1, "{out}");
    // A wrong pass depth in it is still found.
    let (code, out) =
        check("gsk988", &m68, &cycle.replace("X61.764", "X61.800"), "cycle-bad.nc", &["--cycles-only"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("rough pass 3"), "{out}");
    // A spring pass appended after the last finishing pass (lines 37-41
    // again, at trace lines 42-46): the extra pass named is the appended
    // one, whose cut is trace line 43 (was: 32, the first finishing pass).
    let extra = [&lines[..41], &lines[36..41], &lines[41..]].concat().join("\n") + "\n";
    let (code, out) = check("gsk988", &m68, &extra, "extra.nc", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("DIFFER: 1 divergence"), "{out}");
    assert!(out.contains("trace line 43: extra pass (5 moves we do not make)"), "{out}");
}

#[test]
fn a_g92_pass_missing_or_repeated_is_one_divergence() {
    // O0012's expansion: lines 1-3 the program's O, M3/G0 and G0 to X65
    // Z5; then the four G92 blocks, 6 lines each (heading, approach, cut,
    // run-out, retract, return) at lines 4-9, 10-15, 16-21 and 22-27; then
    // M30. The pass of line 4 starts at X58.7.
    let o12 = example("gsk980-g92-o0012.nc");
    let full = expand("gsk980", &o12);
    let lines: Vec<&str> = full.lines().collect();
    let heads: Vec<usize> =
        lines.iter().enumerate().filter(|(_, l)| l.starts_with("(G92 line")).map(|(i, _)| i).collect();
    assert_eq!(heads, [3, 9, 15, 21], "{full}");
    assert_eq!(lines[4], "G00 X58.700 Z5.000");
    // Without a pass: one divergence, the 5 moves of that pass (approach,
    // cut, run-out, retract, return), named at its cut; no follow-on
    // divergence at the next pass's rapids (was: the retract end compared
    // with the program's G00 X150 Z50).
    for (gone, line, first) in [(0, 4, "X58.700 Z-27.000"), (2, 6, "X57.000 Z-27.000")] {
        let h = heads[gone];
        let trace = [&lines[..h], &lines[h + 6..]].concat().join("\n") + "\n";
        let (code, out) = check("gsk980", &o12, &trace, "g92-missing.nc", &[]);
        assert_eq!(code, 1, "{out}");
        assert!(
            out.starts_with("DIFFER: 1 divergence (tolerance 0 increments; 22 moves of ours, 17 of"),
            "{out}"
        );
        assert!(
            out.contains(&format!("G92 at line {line}, start 1: missing pass (5 moves not in the trace), first: end of cut (run-out start) {first}")),
            "{out}"
        );
    }
    // The pass of line 5 cut twice: one extra pass of 5 moves.
    let h = heads[1];
    let trace = [&lines[..h + 6], &lines[h + 1..]].concat().join("\n") + "\n";
    let (code, out) = check("gsk980", &o12, &trace, "g92-extra.nc", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.starts_with("DIFFER: 1 divergence (tolerance 0 increments; 22 moves of ours, 27 of"),
        "{out}"
    );
    assert!(out.contains("extra pass (5 moves we do not make)"), "{out}");
}

#[test]
fn a_seven_start_thread_agrees_with_its_own_expansion_at_the_q_words_resolution() {
    // L7: the starts are 360°/7 = 51.428571…° apart, which a Q word writes
    // as Q51.429 (thousandths, the nearest). The expansion agrees with its
    // program (it was 36 `start angle` divergences); a Q one thousandth off
    // on start 2 of each of the 6 passes (5 rough + 1 finishing: 6 × 7
    // passes, 211 moves) does not.
    let text = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 L7\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n";
    let program = tmp("seven.nc", text);
    let program = program.to_str().expect("utf-8");
    let nc = expand("gsk988", program);
    assert_eq!(nc.matches(" Q51.429").count(), 6, "{nc}");
    let (code, out) = check("gsk988", program, &nc, "seven-same.nc", &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.starts_with("AGREE: 211 moves of ours, 211 of the trace"), "{out}");
    let (code, out) = check("gsk988", program, &nc.replace(" Q51.429", " Q51.428"), "seven-off.nc", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.starts_with("DIFFER: 6 divergences"), "{out}");
    assert!(out.contains("(start angle)"), "{out}");
    // A whole number of thousandths (L8: 45°) is compared exactly as ever.
    let eight = tmp("eight.nc", &text.replace("L7", "L8"));
    let eight = eight.to_str().expect("utf-8");
    let nc = expand("gsk988", eight);
    let (code, _) = check("gsk988", eight, &nc, "eight-same.nc", &[]);
    assert_eq!(code, 0);
    let (code, out) = check("gsk988", eight, &nc.replace(" Q45.000", " Q45.001"), "eight-off.nc", &[]);
    assert_eq!(code, 1, "{out}");
}
