//! The `cycleref` command end to end: both engines print the same output,
//! errors exit with status 2 and print nothing on stdout, JSON parses.

use std::process::{Command, Output};

const EXAMPLES: &[(&str, &[&str])] = &[
    ("gsk988-m68x6.nc", &["--profile", "gsk988"]),
    ("gsk980-m68x6.nc", &["--profile", "gsk980", "--increment", "is-c"]),
    ("seed000-extended.nc", &["--profile", "gsk988"]),
    ("fanuc-external.nc", &["--profile", "fanuc"]),
    ("fanuc-internal.nc", &["--profile", "fanuc"]),
    ("gsk980-g32-taper.nc", &["--profile", "gsk980", "--increment", "is-c"]),
    ("gsk980-g32-runout.nc", &["--profile", "gsk980"]),
];

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn cycleref(args: &[&str], stdin: Option<&str>) -> Output {
    use std::io::Write as _;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_cycleref"));
    cmd.args(args).stdout(std::process::Stdio::piped()).stderr(std::process::Stdio::piped());
    if stdin.is_some() {
        cmd.stdin(std::process::Stdio::piped());
    }
    let mut child = cmd.spawn().expect("runs");
    if let Some(text) = stdin {
        child.stdin.take().unwrap().write_all(text.as_bytes()).unwrap();
    }
    child.wait_with_output().unwrap()
}

#[test]
fn both_engines_print_the_same_expansion() {
    for (name, flags) in EXAMPLES {
        for format in ["nc", "json"] {
            let mut args = vec!["expand", "--format", format];
            args.extend_from_slice(flags);
            let file = example(name);
            args.push(&file);
            let mut spec = args.clone();
            spec.extend_from_slice(&["--engine", "spec"]);
            let mut imp = args.clone();
            imp.extend_from_slice(&["--engine", "impl"]);
            let a = cycleref(&spec, None);
            let b = cycleref(&imp, None);
            assert!(a.status.success(), "{name}: {}", String::from_utf8_lossy(&a.stderr));
            assert_eq!(a.stdout, b.stdout, "{name} {format}: the engines differ");
        }
    }
}

#[test]
fn nc_output_contract() {
    let out = cycleref(&["expand", "--profile", "gsk988", &example("gsk988-m68x6.nc")], None);
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    // Blocks outside the cycle are echoed; the cycle becomes comments and moves.
    assert!(lines.contains(&"G00 X80 Z10 (rapid to the start point A)"), "{text}");
    assert!(lines.contains(&"(G76 line 6: 4 rough + 2 finish passes x 1 start)"));
    assert!(lines.contains(&"(rough 1 start 1 depth 1.800 cut 1.800)"));
    assert!(lines.contains(&"G00 X64.400 Z8.961"));
    assert!(lines.contains(&"G32 X64.400 Z-59.000 F6.0"));
    assert!(lines.contains(&"G32 X70.400 Z-62.000 F6.0"));
    // The G76 blocks themselves are gone.
    assert!(!lines.iter().any(|l| l.starts_with("G76")), "{text}");
}

#[test]
fn multi_start_writes_q_and_restores_the_motion_mode() {
    let program = "M03 S500\nG01 X80 Z10 F0.2\nG76 P010060 Q0.1 R0 L3\nG76 X60 Z-30 P2 Q1 F6\nX90\n";
    let out = cycleref(&["expand", "--profile", "gsk988", "-"], Some(program));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    // Starts at 0, 120 and 240 degrees: Q in degrees on the 988TA (its G32
    // unit), on the synchronising move only.
    assert!(text.contains(" Q120.000\n") && text.contains(" Q240.000\n"), "{text}");
    assert_eq!(text.matches(" Q120.000\n").count(), 5, "{text}");
    // G01 was modal before the cycle: it is restored before `X90`.
    assert!(text.ends_with("G01\nX90\n"), "{text}");
}

#[test]
fn errors_exit_2_with_nothing_on_stdout() {
    let program = "M03 S500\nG00 X80 Z10\nG76 P010060 Q0.1 R0\nG76 X60 Z-30 Q1 F6\n";
    let out = cycleref(&["expand", "--profile", "gsk988", "-"], Some(program));
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("<stdin>: line 4: P(k) (thread height) is missing"), "{err}");
    // A cycle alarm found while expanding, after earlier blocks were read.
    let program = "M03 S500\nG00 X80 Z10\nG76 P010060 Q0.1 R0\nG76 X60 Z-30 P2 Q1 F6 J1 K40\n";
    for engine in ["impl", "spec"] {
        let out = cycleref(&["expand", "--engine", engine, "-"], Some(program));
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains("line 4, G76: the run-out along the long axis (40.000)"), "{err}");
    }
}

#[test]
fn json_parses_and_carries_the_annotations() {
    let out =
        cycleref(&["expand", "--format", "json", "--profile", "gsk988", &example("gsk988-m68x6.nc")], None);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["format"], "cycleref-moves/1");
    let moves = v["cycles"][0]["moves"].as_array().unwrap();
    assert_eq!(moves.len(), 30);
    assert_eq!(moves[0]["motion"], "rapid");
    assert_eq!(moves[0]["x"], "64.400");
    assert_eq!(moves[0]["pass"]["depth"], "1.800");
    assert_eq!(moves[1]["motion"], "thread");
    assert_eq!(moves[1]["sync"], true);
    assert_eq!(moves[2]["role"], "run-out");
}

#[test]
fn g32_blocks_become_plain_thread_moves() {
    let out = cycleref(&["expand", "--profile", "gsk980", &example("gsk980-g32-runout.nc")], None);
    let text = String::from_utf8(out.stdout).unwrap();
    // The run-out is its own G32 block; J and K are gone; Q in 0.001° on the
    // synchronising move only.
    assert!(text.contains("G32 X40.000 Z-27.000 F2.0 Q90000\nG32 X43.000 Z-30.000 F2.0\n"), "{text}");
    assert!(text.contains("G32 X37.600 Z-39.000 F2.0\nG32 X40.000 Z-40.000 F2.0\n"), "{text}");
    assert!(
        text.lines().filter(|l| l.starts_with("G32")).all(|l| !l.contains(" J") && !l.contains(" K")),
        "{text}"
    );
}

#[test]
fn passes_table() {
    let out = cycleref(&["passes", "--profile", "fanuc", &example("fanuc-external.nc")], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("     5  rough     1  right        0.900        0.100         22.200          2.480"),
        "{text}"
    );
}

#[test]
fn passes_table_lists_g32_blocks() {
    let out = cycleref(&["passes", "--profile", "gsk980", &example("gsk980-g32-runout.nc")], None);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("    11    no         34.000        -30.000         37.600        -39.000         40.000        -40.000"), "{text}");
    assert!(text.contains("     9   yes         30.000          2.000         34.000        -10.000              -              -"), "{text}");
}
