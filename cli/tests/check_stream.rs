//! `check` aligns a cycle at a time (reading R-CHECKSTREAM): a cycle
//! missing from the trace, or a pass too many, is reported where it is and
//! does not shift the comparison of the cycles after it.

use std::process::Command;

const PROGRAM: &str = "M03 S500\nG00 X100 Z50\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\n\
                       G76 X60.64 Z-62 P3.68 Q1.8 F6\nG00 X80 Z10\nG76 X61.64 Z-62 P3.68 Q1.8 F6\n\
                       G00 X80 Z10\nG76 X62.64 Z-62 P3.68 Q1.8 F6\nG00 X100 Z50\nM30\n";

fn dir() -> std::path::PathBuf {
    let d = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("check-stream");
    std::fs::create_dir_all(&d).expect("dir");
    d
}

fn cycleref(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cycleref")).args(args).output().expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The program's file (named for the test: the tests run at once) and its
/// expansion, as lines.
fn expanded(name: &str) -> (String, Vec<String>) {
    let program = dir().join(name);
    std::fs::write(&program, PROGRAM).expect("write");
    let p = program.to_str().expect("utf-8").to_string();
    let (code, out, err) = cycleref(&["expand", "--profile", "gsk988", &p]);
    assert_eq!(code, 0, "{err}");
    (p, out.lines().map(str::to_string).collect())
}

fn check(program: &str, trace: &[String], name: &str) -> (i32, String) {
    let path = dir().join(name);
    std::fs::write(&path, trace.join("\n") + "\n").expect("write");
    let (code, out, err) =
        cycleref(&["check", "--profile", "gsk988", "--trace", path.to_str().expect("utf-8"), program]);
    (code, out + &err)
}

#[test]
fn a_cycle_missing_from_the_trace_is_seven_missing_passes_of_that_cycle_only() {
    let (program, lines) = expanded("missing-cycle-program.nc");
    // The second cycle (block 2 at line 7): its heading comment to the
    // block before the next program block, `G00 X80 Z10` of line 8.
    let start = lines.iter().position(|l| l.starts_with("(G76 line 7:")).expect("cycle 2");
    let end = start + lines[start..].iter().position(|l| l == "G00 X80 Z10").expect("line 8");
    let mut trace = lines.clone();
    trace.drain(start..end);
    let (code, text) = check(&program, &trace, "missing-cycle.nc");
    assert_eq!(code, 1, "{text}");
    // P020560 Q0.1 R0.05 with k 3.68, Δd 1.8: depths 1.8, 2.546 (√2),
    // 3.118 (√3), 3.6 (√4), then 3.63 = k - d: 5 rough passes, and m = 2
    // finishing passes; one group each (the retract and return of a pass
    // begin the next group), so seven groups of cycle 2, none of cycle 3.
    assert!(text.starts_with("DIFFER: 7 divergences"), "{text}");
    assert_eq!(text.matches("G76 at line 7, ").count(), 8, "{text}"); // the first, and all seven
    assert_eq!(text.matches("missing pass").count(), 8, "{text}");
    assert!(text.contains("(tolerance 0 increments; 108 moves of ours, 73 of the trace)"), "{text}");
    assert!(!text.contains("line 9"), "{text}");
    assert!(!text.contains("line 5,"), "{text}");
}

#[test]
fn a_pass_too_many_in_the_first_cycle_is_one_extra_pass() {
    let (program, lines) = expanded("extra-pass-program.nc");
    // Rough pass 2 of the first cycle, written twice.
    let start = lines.iter().position(|l| l.starts_with("(rough 2 start 1")).expect("pass 2");
    let pass: Vec<String> = lines[start + 1..start + 6].to_vec();
    assert!(pass[0].starts_with("G00") && pass[1].starts_with("G32"), "{pass:?}");
    let mut trace = lines.clone();
    for (k, l) in pass.into_iter().enumerate() {
        trace.insert(start + 6 + k, l);
    }
    let (code, text) = check(&program, &trace, "extra-pass.nc");
    assert_eq!(code, 1, "{text}");
    assert!(text.starts_with("DIFFER: 1 divergence "), "{text}");
    assert!(text.contains("extra pass (5 moves we do not make)"), "{text}");
}

#[test]
fn the_trace_may_come_from_standard_input() {
    use std::io::Write as _;
    let (program, lines) = expanded("stdin-program.nc");
    let mut child = Command::new(env!("CARGO_BIN_EXE_cycleref"))
        .args(["check", "--profile", "gsk988", "--trace", "-", &program])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("runs");
    child.stdin.take().expect("stdin").write_all((lines.join("\n") + "\n").as_bytes()).expect("write");
    let out = child.wait_with_output().expect("waits");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    // 3 cycles x 7 passes x 5 moves (approach, cut, run-out, retract,
    // return), G00 X100 Z50 twice and G00 X80 Z10 once (the two between
    // the cycles are no moves: the tool is there already): 108.
    assert!(text.starts_with("AGREE: 108 moves of ours, 108 of the trace"), "{text}");
}
