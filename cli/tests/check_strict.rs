//! `cycleref check` is strict on everything that shapes the part (issue 12,
//! found 2 and 3): each mutation of our own expansion below is reported,
//! named and located; a split rapid agrees only when it stays out of the
//! region the cycle cuts; the CSV schema carries arcs; empty traces are one
//! error whatever their format.
//!
//! The expected values are worked from the examples' expansions by hand:
//!
//! * `examples/gsk980-g75-square.nc` (GSK 980TDi, IS-B, diameter X): the
//!   finishing contour is, from trace line 49 on, `G00 X30.000 Z0.500`,
//!   `G01 X29.000 Z0.000`, `G01 X24.800 Z0.000` (line 52), the round r3
//!   `G02 X24.000 Z-0.400 I0.000 K-0.400` (line 53: centre X24.800 Z-0.400),
//!   `G01 X24.000 Z-4.700` (line 54), the round r4 `G02 X24.600 Z-5.000
//!   I0.300 K0.000` (line 55: from X24.000 Z-4.700, centre X24.000 + 2 × 0.300
//!   = X24.600, Z-4.700).
//! * `examples/gsk988-m68x6.nc`: A = X80 Z10, D = X60.64 Z-62, k = 3.68, so
//!   the thread's crest is X60.64 + 2 × 3.68 = X68.000; the cut nearest D
//!   starts at Z7.933 (the finishing passes). Rough pass 1 runs out to
//!   X70.400 Z-62 (above the crest); finish pass 2 runs out to X66.640 Z-62
//!   (below it). Our retract is X first (to E = X80 Z-62), then Z (to A).
//! * `examples/gsk980-g32-runout.nc`: the second G32 run synchronises at
//!   Q180000 (program line 9, trace line 10).

mod common;

use common::run;
use std::path::PathBuf;

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch file of this binary's (`common::tmp` under `cycleref-check-strict-…`).
fn tmp(name: &str, text: &str) -> PathBuf {
    common::tmp("check-strict", name, text)
}

fn expand(profile: &str, file: &str) -> String {
    let out = run(&["expand", "--profile", profile, &example(file)], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Runs `check` of `file` against `trace` written to `name`: exit code and
/// stdout + stderr.
fn check(profile: &str, file: &str, trace: &str, name: &str, extra: &[&str]) -> (i32, String) {
    let p = tmp(name, trace);
    let program = example(file);
    let mut args = vec!["check", "--profile", profile, "--trace", p.to_str().expect("utf-8")];
    args.extend_from_slice(extra);
    args.push(&program);
    let out = run(&args, None);
    (
        out.status.code().expect("exit code"),
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr),
    )
}

fn square(trace: &str, name: &str, extra: &[&str]) -> (i32, String) {
    check("gsk980", "gsk980-g75-square.nc", trace, name, extra)
}

fn m68(trace: &str, name: &str, extra: &[&str]) -> (i32, String) {
    check("gsk988", "gsk988-m68x6.nc", trace, name, extra)
}

/// `text` with the one occurrence of `from` replaced.
fn replace_one(text: &str, from: &str, to: &str) -> String {
    assert_eq!(text.matches(from).count(), 1, "`{from}` must occur once");
    text.replacen(from, to, 1)
}

const R3: &str = "G02 X24.000 Z-0.400 I0.000 K-0.400";
const R4: &str = "G02 X24.600 Z-5.000 I0.300 K0.000";

#[test]
fn the_square_expansion_agrees_with_itself() {
    let ours = expand("gsk980", "gsk980-g75-square.nc");
    let lines: Vec<&str> = ours.lines().collect();
    assert_eq!(lines[52], R3, "trace line 53");
    assert_eq!(lines[53], "G01 X24.000 Z-4.700", "trace line 54");
    assert_eq!(lines[54], R4, "trace line 55");
    let (code, text) = square(&ours, "same.nc", &[]);
    assert_eq!(code, 0, "{text}");
}

#[test]
fn g02_changed_to_g03_is_an_arc_direction() {
    let t = replace_one(&expand("gsk980", "gsk980-g75-square.nc"), R3, "G03 X24.000 Z-0.400 I0.000 K-0.400");
    let (code, text) = square(&t, "g03.nc", &["--tolerance", "100000"]);
    assert_eq!(code, 1, "{text}");
    assert!(text.starts_with("DIFFER: 1 divergence"), "{text}");
    assert!(
        text.contains(
            "G75.1 at line 9, finish-contour: finishing contour point (arc direction)\n  ours   arc-cw X24.000 \
             Z-0.400\n  theirs arc-ccw X24.000 Z-0.400 (trace line 53)"
        ),
        "{text}"
    );
}

#[test]
fn an_arc_centre_one_increment_off_is_named() {
    // K-0.401: the centre at Z0.000 - 0.401 = Z-0.401, one increment from ours.
    let t = replace_one(&expand("gsk980", "gsk980-g75-square.nc"), R3, "G02 X24.000 Z-0.400 I0.000 K-0.401");
    let (code, text) = square(&t, "centre.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("finishing contour point (arc centre)"), "{text}");
    assert!(text.contains("ours   arc-cw X24.000 Z-0.400 centre X24.800 Z-0.400"), "{text}");
    assert!(text.contains("centre X24.800 Z-0.401 (trace line 53)"), "{text}");
    assert!(text.contains("difference of the centres: X 0 Z -1 increments"), "{text}");
    // The tolerance applies to coordinates, centres included.
    let (code, text) = square(&t, "centre.nc", &["--tolerance", "1"]);
    assert_eq!(code, 0, "{text}");
    // I of a diameter X with one more decimal: half an increment of radius
    // is one increment of X (X24.000 + 2 × 0.3005 = X24.601).
    let t = replace_one(&expand("gsk980", "gsk980-g75-square.nc"), R4, "G02 X24.600 Z-5.000 I0.3005 K0.000");
    let (code, text) = square(&t, "centre-i.nc", &["--format", "json"]);
    assert_eq!(code, 1, "{text}");
    let v: serde_json::Value = serde_json::from_str(&text).expect("json");
    let d = &v["divergences"][0];
    assert_eq!(d["what"], "arc centre");
    assert_eq!(d["ours"]["centre"]["x"], "24.600");
    assert_eq!(d["theirs"]["centre"]["x"], "24.601");
    assert_eq!(d["theirs"]["line"], 55);
    assert_eq!(d["centre_difference_increments"]["x"], 1);
}

#[test]
fn a_finishing_feed_made_a_rapid_is_a_kind_of_move() {
    let t =
        replace_one(&expand("gsk980", "gsk980-g75-square.nc"), "G01 X24.000 Z-4.700", "G00 X24.000 Z-4.700");
    let (code, text) = square(&t, "g00.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(text.starts_with("DIFFER: 1 divergence"), "{text}");
    assert!(
        text.contains(
            "G75.1 at line 9, finish-contour: finishing contour point (kind of move)\n  ours   feed X24.000 \
             Z-4.700\n  theirs rapid X24.000 Z-4.700 (trace line 54)"
        ),
        "{text}"
    );
    // The reverse: a rapid of ours (the retract after the contour) made a feed.
    let t =
        replace_one(&expand("gsk980", "gsk980-g75-square.nc"), "G00 X30.000 Z0.000", "G01 X30.000 Z0.000");
    let (code, text) = square(&t, "g01.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("(kind of move)\n  ours   rapid X30.000 Z0.000\n  theirs feed X30.000 Z0.000"),
        "{text}"
    );
}

#[test]
fn the_issue_square_with_g03_rounds_never_agrees() {
    // Found 2 of issue 12, exactly: both rounds G03, one with a bogus I9 K9
    // and one without a centre.
    let ours = expand("gsk980", "gsk980-g75-square.nc");
    let t = replace_one(&ours, R3, "G03 X24.000 Z-0.400 I9 K9");
    let t = replace_one(&t, R4, "G03 X24.600 Z-5.000");
    let (code, text) = square(&t, "issue.nc", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(!text.contains("AGREE"), "{text}");
    assert!(text.contains("line 55, word `G03`: an arc without a centre"), "{text}");
    // With the second round's centre given, both directions and the bogus
    // centre are named (I9 is 9 mm of radius: X24.800 + 18 = X42.800).
    let t = replace_one(&ours, R3, "G03 X24.000 Z-0.400 I9 K9");
    let t = replace_one(&t, R4, "G03 X24.600 Z-5.000 I0.300 K0.000");
    let (code, text) = square(&t, "issue2.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(text.starts_with("DIFFER: 3 divergences"), "{text}");
    assert!(text.contains("theirs arc-ccw X24.000 Z-0.400 centre X42.800 Z9.000 (trace line 53)"), "{text}");
    assert!(text.contains("theirs arc-ccw X24.600 Z-5.000 (trace line 55)"), "{text}");
}

#[test]
fn an_r_arc_is_refused() {
    let t = replace_one(&expand("gsk980", "gsk980-g75-square.nc"), R3, "G02 X24.000 Z-0.400 R0.4");
    let (code, text) = square(&t, "r.nc", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("line 53, word `R0.4`") && text.contains("centre as I and K"), "{text}");
}

#[test]
fn a_word_that_is_not_of_a_plain_move_is_refused() {
    let ours = expand("gsk980", "gsk980-g75-square.nc");
    for (from, to, word) in [
        ("G01 X24.000 Z-4.700", "G01 X24.000 Z-4.700 R0.5", "R0.5"),
        ("G01 X24.000 Z-4.700", "G01 X24.000 Z-4.700 K1", "K1"),
        ("G01 X24.000 Z-4.700", "G01 X24.000 Z-4.700 Q5", "Q5"),
        ("G01 X24.000 Z-4.700", "G42 G01 X24.000 Z-4.700", "G42"),
        ("G01 X24.000 Z-4.700", "G20 G01 X24.000 Z-4.700", "G20"),
        ("G01 X24.000 Z-4.700", "G01 X24.000 Z-4.700 A3", "A3"),
    ] {
        let t = replace_one(&ours, from, to);
        let (code, text) = square(&t, "word.nc", &[]);
        assert_eq!(code, 2, "{to}: {text}");
        assert!(text.contains(&format!("line 54, word `{word}`")), "{to}: {text}");
    }
}

#[test]
fn a_lead_changed_in_the_last_digit_is_named() {
    let t = replace_one(&good_m68(), "G32 X62.908 Z-59.000 F6.0", "G32 X62.908 Z-59.000 F6.001");
    // Tolerance does not apply to leads.
    let (code, text) = m68(&t, "lead.nc", &["--tolerance", "100000"]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains(
            "G76 at line 6, rough pass 2 (start 1, depth 2.546, cut 0.746): end of cut (run-out start) (lead)\n  \
             ours   X62.908 Z-59.000 F6.0\n  theirs X62.908 Z-59.000 F6.001 (trace line 14)"
        ),
        "{text}"
    );
}

#[test]
fn a_start_angle_changed_is_named() {
    let ours = expand("gsk980", "gsk980-g32-runout.nc");
    let t = replace_one(&ours, "Q180000", "Q180001");
    let (code, text) = check("gsk980", "gsk980-g32-runout.nc", &t, "q.nc", &["--tolerance", "100000"]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains(
            "G32 at line 9: end of cut (run-out start) (start angle)\n  ours   X34.000 Z-10.000 synchronises at \
             180000/1 thousandths of a degree\n  theirs X34.000 Z-10.000 synchronises at 180001/1 thousandths of a \
             degree (trace line 10)"
        ),
        "{text}"
    );
}

fn good_m68() -> String {
    expand("gsk988", "gsk988-m68x6.nc")
}

#[test]
fn a_retract_through_the_thread_is_named_and_one_outside_agrees() {
    let ours = good_m68();
    // Finish pass 2 runs out to X66.640, inside the thread (X60.640 to
    // X68.000): Z first from there drags the tool back through the thread.
    let tail = "G00 X80.000 Z-62.000\nG00 X80.000 Z10.000\nG00 X100 Z50";
    let t = replace_one(&ours, tail, "G00 X66.640 Z10.000\nG00 X80.000 Z10.000\nG00 X100 Z50");
    let (code, text) = m68(&t, "zx.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains(
            "G76 at line 6, finish pass 2 (start 1, depth 3.680, cut 0.000): E (retract end) (rapid through the \
             work)\n  ours   rapid X80.000 Z-62.000\n  theirs rapid X66.640 Z10.000 (trace line 40)"
        ),
        "{text}"
    );
    // Rough pass 1 runs out to X70.400, above the crest: Z first there
    // stays outside the thread, the split in the other order agrees.
    let pass1 = "G32 X70.400 Z-62.000 F6.0\nG00 X80.000 Z-62.000\n";
    let t = replace_one(&ours, pass1, "G32 X70.400 Z-62.000 F6.0\nG00 X70.400 Z10.000\n");
    let (code, text) = m68(&t, "zx1.nc", &[]);
    assert_eq!(code, 0, "{text}");
    // The approach A → B1 split either way stays in front of the thread
    // (Z10 and Z8.961 are beyond the cut start nearest D, Z7.933).
    for split in ["G00 X80.000 Z8.961\nG00 X64.400 Z8.961\n", "G00 X64.400 Z10.000\nG00 X64.400 Z8.961\n"] {
        let t = replace_one(&ours, "G00 X64.400 Z8.961\n", split);
        let (code, text) = m68(&t, "approach.nc", &[]);
        assert_eq!(code, 0, "{split}{text}");
    }
}

#[test]
fn a_csv_trace_carries_arcs() {
    // The square's expansion as CSV rows: G02 rows with i, k or cx, cz.
    let ours = expand("gsk980", "gsk980-g75-square.nc");
    let to_csv = |absolute: bool| {
        let mut csv = String::from(if absolute { "motion,x,z,cx,cz\n" } else { "motion,x,z,i,k\n" });
        let mut at = (String::new(), String::new());
        for line in ours.lines() {
            let w: Vec<&str> = line.split(' ').collect();
            let kind = match w[0] {
                "G00" => "rapid",
                "G01" => "feed",
                "G02" => "arc-cw",
                _ => continue,
            };
            let (x, z) = (w[1][1..].to_string(), w[2][1..].to_string());
            if kind == "arc-cw" {
                let (i, k) = (&w[3][1..], &w[4][1..]);
                if absolute {
                    let d = |s: &str| s.parse::<f64>().expect("number");
                    // Centre = start + (2 I, K), printed with 3 decimals.
                    let cx = format!("{:.3}", d(&at.0) + 2.0 * d(i));
                    let cz = format!("{:.3}", d(&at.1) + d(k));
                    csv.push_str(&format!("G02,{x},{z},{cx},{cz}\n"));
                } else {
                    csv.push_str(&format!("{kind},{x},{z},{i},{k}\n"));
                }
            } else {
                csv.push_str(&format!("{kind},{x},{z},,\n"));
            }
            at = (x, z);
        }
        csv
    };
    for absolute in [false, true] {
        let csv = to_csv(absolute);
        let (code, text) = square(&csv, "square.csv", &[]);
        assert_eq!(code, 0, "{text}\n{csv}");
    }
    let csv = to_csv(false);
    // The direction matters in a CSV too.
    let bad = replace_one(&csv, "arc-cw,24.000,-0.400", "arc-ccw,24.000,-0.400");
    let (code, text) = square(&bad, "ccw.csv", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("(arc direction)"), "{text}");
    // A bare `arc` needs a direction; an arc needs a centre.
    let bare = replace_one(&csv, "arc-cw,24.000,-0.400", "arc,24.000,-0.400");
    let (code, text) = square(&bare, "bare.csv", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("motion `arc` needs a direction: arc-cw (G02) or arc-ccw (G03)"), "{text}");
    let none = replace_one(&csv, "arc-cw,24.000,-0.400,0.000,-0.400", "arc-cw,24.000,-0.400,,");
    let (code, text) = square(&none, "none.csv", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("an arc without a centre"), "{text}");
    // Unknown columns are refused, with the header's line.
    let (code, text) = square("motion,x,z,feedrate\nrapid,1,2,3\n", "col.csv", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("CSV line 1: unknown column `feedrate`"), "{text}");
}

#[test]
fn empty_traces_are_one_error_whatever_their_format() {
    for (name, text) in [
        ("empty.nc", ""),
        ("empty.csv", ""),
        ("comments.nc", "(nothing)\n%\n"),
        ("header.csv", "motion,x,z\n\n"),
        ("still.nc", "G00\nM30\n"),
    ] {
        let (code, out) = m68(text, name, &[]);
        assert_eq!(code, 2, "{name}: {out}");
        assert!(out.contains(&format!("{name}: the trace has no moves")), "{name}: {out}");
    }
}

#[test]
fn a_trace_that_is_not_utf8_names_line_and_byte() {
    let p = tmp("bytes.nc", "");
    std::fs::write(&p, b"G00 X80 Z10\nG00 X6\xff4 Z8\n").expect("write");
    let out = run(&["check", "--trace", p.to_str().expect("utf-8"), &example("gsk988-m68x6.nc")], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 2, byte 7: not UTF-8 text"), "{err}");
}

/// The trace is read in pieces of whole lines (64 KiB): a byte that is not
/// UTF-8 far into the file, after a line longer than a piece, is still
/// named by its own line and byte, and the lines before it are read (a
/// byte-order mark at the start of line 1 is skipped).
#[test]
fn a_trace_read_in_pieces_names_the_line_and_byte_of_a_bad_byte() {
    let p = tmp("pieces.nc", "");
    let mut text = b"\xEF\xBB\xBFG00 X80 Z10\n".to_vec();
    // Line 2: a comment of 100 000 bytes (longer than a piece).
    text.extend_from_slice(b"(");
    text.extend(std::iter::repeat_n(b'c', 100_000));
    text.extend_from_slice(b")\n");
    // Lines 3 to 20 002: 20 000 lines of 12 bytes (about 240 KB).
    for _ in 0..20_000 {
        text.extend_from_slice(b"G00 X80 Z10\n");
    }
    // Line 20 003: the bad byte is the 9th (after "G00 X80 ").
    text.extend_from_slice(b"G00 X80 \xffZ10\n");
    std::fs::write(&p, &text).expect("write");
    let out = run(&["check", "--trace", p.to_str().expect("utf-8"), &example("gsk988-m68x6.nc")], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 20003, byte 9: not UTF-8 text"), "{err}");
}

/// The M68x6 program (gsk988-m68x6.nc) with a second G76 appended whose
/// start X62 lies inside its thread (crest at 60.64 + 2·3.68 = 68.00 >
/// 62): the alarm of line 10, its last line.
const M68_THEN_INSIDE: &str = "O0013;\nG50 X100 Z50 M3 S300;\nG00 X80 Z10;\n\
G76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\nG00 X100 Z50;\n\
G00 X62 Z10;\nG76 P020560 Q0.150 R0.1;\nG00 X62 Z10;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\nM30;\n";

/// `check` runs in one phase (its report is written at the end): the
/// program's last cycle, invalid, is still its error, with exit 2 and
/// nothing on stdout, even when the trace agrees with everything before
/// it, and even when the trace has an error of its own first (the program
/// is then read to its end before the trace's error is given).
#[test]
fn a_program_error_at_the_end_wins_in_the_one_phase_check() {
    let program = tmp("m68-then-inside.nc", M68_THEN_INSIDE);
    let program = program.to_str().expect("utf-8");
    for (name, trace) in [("agrees.nc", good_m68()), ("bad-first-line.nc", "G00 X\u{1}80 Z10\n".to_string())]
    {
        let t = tmp(name, &trace);
        let out =
            run(&["check", "--profile", "gsk988", "--trace", t.to_str().expect("utf-8"), program], None);
        assert_eq!(out.status.code(), Some(2), "{name}");
        assert!(out.stdout.is_empty(), "{name}: {}", String::from_utf8_lossy(&out.stdout));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("line 10, G76: the start point A lies inside the thread"), "{name}: {err}");
    }
}

/// The units of a trace are those the program settles before its first
/// motion (R-UNITS), found without reading the whole program: an inch
/// program (G20 on line 2, G50 on line 3) agrees with its own expansion,
/// whose 4-decimal inch values a metric reading would refuse (X2.4614 is
/// finer than 0.001 mm).
#[test]
fn an_inch_program_is_checked_in_inches() {
    let text = "O0001;\nG20;\nG50 X4 Z2 M3 S300;\nG00 X3 Z0.4;\nG76 P020560 Q0.006 R0.004;\n\
                G76 X2.3874 Z-2.44 P0.0724 Q0.0354 F0.125;\nG00 X4 Z2;\nM30;\n";
    let program = tmp("inch.nc", text);
    let out = run(&["expand", "--profile", "gsk988", program.to_str().expect("utf-8")], None);
    assert!(out.status.success());
    let trace = String::from_utf8(out.stdout).expect("utf-8");
    assert!(trace.contains("G32 X2.4614 Z-2.3775 F0.125"), "{trace}");
    let t = tmp("inch-trace.nc", &trace);
    let out = run(
        &[
            "check",
            "--profile",
            "gsk988",
            "--trace",
            t.to_str().expect("utf-8"),
            program.to_str().expect("utf-8"),
        ],
        None,
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}{}", String::from_utf8_lossy(&out.stderr));
    assert!(text.starts_with("AGREE: 32 moves of ours, 32 of the trace"), "{text}");
}
