//! The command's streaming contract (issue 11), run on the built binary:
//! an error anywhere, even in the last of 100 000 cycles, leaves stdout
//! empty; a closed pipe ends the command quietly with status 0; a full disk
//! is a message and status 2; `--format jsonl` carries the same cycles as
//! `--format json`, then a summary line with the right counts.

mod common;
use common::{run, BIN};
use std::io::{BufRead as _, BufReader};
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A fresh path in the target's scratch directory for this test.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("streaming-tests");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name)
}

const HEAD: &str = "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n";

/// `n` G76 cycles (M68x6, 988TA manual O0013) with a G00 back to the start
/// point after each, and the line of the last cycle's block.
fn cycles(n: usize, last: &str) -> (String, usize) {
    let mut s = String::from(HEAD);
    for _ in 1..n {
        s.push_str("G76 X60.64 Z-62 P3.680 Q1.800 F6\nG00 X80 Z10\n");
    }
    s.push_str(last);
    s.push_str("\nM30\n");
    // Three lines of head, two per cycle before the last, then the last
    // cycle's (its block 2 is its last line).
    (s, 3 + 2 * (n - 1) + 1 + last.matches('\n').count())
}

#[test]
fn the_last_of_100_000_cycles_invalid_writes_nothing() {
    let n = 100_000;
    // Block 2 without P(k).
    let (missing_p, line) = cycles(n, "G76 X60.64 Z-62 Q1.800 F6");
    assert_eq!(line, 200_002);
    // Q(Δdmin) larger than P(k) is an alarm of the cycle (988TA note 6).
    let (q_over_k, q_line) = cycles(n, "G76 P020560 Q1.500 R0.1\nG76 X60.64 Z-62 P1.000 Q0.500 F6");
    assert_eq!(q_line, 200_003);
    let file = scratch("last-invalid.nc");
    std::fs::write(&file, &missing_p).expect("write");
    let file = file.to_str().expect("utf-8 path");
    for format in ["nc", "json", "jsonl"] {
        let out = run(&["expand", "--format", format, file], None);
        assert_eq!(out.status.code(), Some(2), "{format}");
        assert!(out.stdout.is_empty(), "{format}: {} bytes on stdout", out.stdout.len());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(&format!("last-invalid.nc: line {line}: P(k) (thread height) is missing")),
            "{err}"
        );
    }
    let out = run(&["passes", file], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    // The same through standard input, and a cycle alarm rather than a
    // reader error.
    let out = run(&["expand", "-"], Some(q_over_k.as_bytes()));
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.starts_with(&format!(
            "cycleref: error[cycle:min_cut_exceeds_height]: <stdin>: line {q_line}: Q(Δdmin) = 1.500 is larger \
             than the thread height"
        )),
        "{err}"
    );
}

/// Runs `args` on a program of 2 000 cycles (about 1.4 MB of nc output),
/// reads one line of its output and closes the pipe.
fn head_1(args: &[&str]) -> (String, Output) {
    let (program, _) = cycles(2_000, "G76 X60.64 Z-62 P3.680 Q1.800 F6");
    let file = scratch("big.nc");
    std::fs::write(&file, program).expect("write");
    let mut child = Command::new(BIN)
        .args(args)
        .arg(&file)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    let mut first = String::new();
    {
        let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
        stdout.read_line(&mut first).expect("reads a line");
        // The read end closes here.
    }
    let out = child.wait_with_output().expect("waits");
    (first, out)
}

#[test]
fn a_closed_pipe_ends_quietly_with_status_0() {
    for args in [
        &["expand"][..],
        &["expand", "--format", "json"],
        &["expand", "--format", "jsonl"],
        &["expand", "--engine", "spec"],
        &["passes"],
    ] {
        let (first, out) = head_1(args);
        assert!(!first.is_empty(), "{args:?}: no first line");
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(out.stderr.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
    // The output really is larger than a pipe's buffer (64 KiB on Linux):
    // the command was still writing when the pipe closed.
    let out = run(&["expand", scratch("big.nc").to_str().expect("utf-8 path")], None);
    assert!(out.stdout.len() > 1_000_000, "{} bytes", out.stdout.len());
}

#[test]
fn a_full_disk_is_an_error() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("no /dev/full here: skipped");
        return;
    };
    let (big, _) = cycles(2_000, "G76 X60.64 Z-62 P3.680 Q1.800 F6");
    let big_file = scratch("full.nc");
    std::fs::write(&big_file, big).expect("write");
    let big_file = big_file.to_str().expect("utf-8 path").to_string();
    let m68 = example("gsk988-m68x6.nc");
    // Small output (written at the final flush) and large (written on the way).
    for (file, format) in
        [(&m68, "nc"), (&m68, "json"), (&big_file, "nc"), (&big_file, "json"), (&big_file, "jsonl")]
    {
        let out = Command::new(BIN)
            .args(["expand", "--format", format, file])
            .stdin(Stdio::null())
            .stdout(full.try_clone().expect("clone"))
            .stderr(Stdio::piped())
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(2), "{file} {format}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("cycleref: error[output]: cannot write the output: "), "{err}");
        assert!(err.contains("No space left on device"), "{err}");
    }
    let out = Command::new(BIN)
        .args(["passes", &m68])
        .stdout(full.try_clone().expect("clone"))
        .stderr(Stdio::piped())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write the output"));
}

/// A program with each kind of cycle on the 980TDi: two G76 (one with a
/// G01 mode to restore), two G32 blocks and a G75.1 groove.
const MIXED: &str = "M03 S500\nG00 X80 Z10\nG76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\n\
                     G01 X80 Z5 F0.2\nG76 X70 Z-20 P1000 Q500 F2\nG00 X50 Z5\n\
                     G32 Z-30 F2\nG00 X60\nZ5\nG32 X40 Z-20 F2\nG00 X60 Z5\n\
                     G00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\nG75.1 R0.5 I3 J1\nG00 X100 Z50\nM30\n";

fn parse_lines(bytes: &[u8]) -> Vec<serde_json::Value> {
    let text = std::str::from_utf8(bytes).expect("utf-8");
    assert!(text.ends_with('\n'));
    text.lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}"))).collect()
}

#[test]
fn jsonl_is_the_json_cycles_one_per_line_then_a_summary() {
    let mixed = scratch("mixed.nc");
    std::fs::write(&mixed, MIXED).expect("write");
    let mixed = mixed.to_str().expect("utf-8 path").to_string();
    // (file, flags, cycles counted by hand from the program's text).
    let cases = [
        (example("gsk988-m68x6.nc"), vec!["--profile", "gsk988"], 1),
        (example("fanuc-internal.nc"), vec!["--profile", "fanuc"], 1),
        (example("gsk980-g32-runout.nc"), vec!["--profile", "gsk980"], 0),
        (example("gsk980-g75-square.nc"), vec!["--profile", "gsk980"], 1),
        (mixed, vec!["--profile", "gsk980"], 3),
    ];
    for (file, flags, g76_g75) in cases {
        let mut args = vec!["expand"];
        args.extend(&flags);
        args.push(&file);
        let json = run(&[&args[..], &["--format", "json"]].concat(), None);
        assert!(json.status.success(), "{file}: {}", String::from_utf8_lossy(&json.stderr));
        let jsonl = run(&[&args[..], &["--format", "jsonl"]].concat(), None);
        assert!(jsonl.status.success(), "{file}: {}", String::from_utf8_lossy(&jsonl.stderr));
        let doc: serde_json::Value = serde_json::from_slice(&json.stdout).expect("json");
        let mut lines = parse_lines(&jsonl.stdout);
        let summary = lines.pop().expect("a summary line");
        let cycles = doc["cycles"].as_array().expect("cycles");
        assert_eq!(&lines, cycles, "{file}: the jsonl objects are the json document's cycles");
        // Every G32 block is a cycle too.
        let text = std::fs::read_to_string(&file).expect("read");
        let g32 = text.lines().filter(|l| l.trim_start().starts_with("G32")).count();
        let expected_cycles = g76_g75 + g32;
        assert_eq!(lines.len(), expected_cycles, "{file}");
        let moves: usize = cycles.iter().map(|c| c["moves"].as_array().expect("moves").len()).sum();
        let keys: Vec<&str> = summary.as_object().expect("object").keys().map(String::as_str).collect();
        assert_eq!(keys, ["format", "file", "units", "cycles", "moves"], "{file}");
        assert_eq!(summary["format"], "cycleref-moves-jsonl/1");
        assert_eq!(summary["file"], file.as_str());
        assert_eq!(summary["file"], doc["file"]);
        assert_eq!(summary["units"], doc["units"]);
        assert_eq!(summary["cycles"], expected_cycles);
        assert_eq!(summary["moves"], moves);
        if file.ends_with("gsk988-m68x6.nc") {
            // 4 rough + 2 finishing passes of 5 moves (manual O0013).
            assert_eq!(summary["moves"], 30);
        }
    }
}

#[test]
fn jsonl_of_standard_input_and_of_no_cycle() {
    let out = run(&["expand", "--format", "jsonl", "-"], Some(b"G00 X80 Z10\nM30\n"));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(
        String::from_utf8(out.stdout).expect("utf-8"),
        "{\"format\":\"cycleref-moves-jsonl/1\",\"file\":\"<stdin>\",\"units\":{\"unit\":\"mm\",\"decimals\":3},\
         \"cycles\":0,\"moves\":0}\n"
    );
}
