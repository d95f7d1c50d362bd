//! The command's edges (issue 12 and the plot of issue 11), run on the built
//! binary: flags win over the parameter file, standard input is `<stdin>`
//! everywhere, a BOM and GBK comments in nc output, `vectors --out` onto a
//! file, and `plot`'s cycle limit and `--line`.

mod common;
use common::{run, BIN};
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

const M68: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk988-m68x6.nc");

/// A fresh path in the target's scratch directory for this test.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("edges-tests");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    if path.is_dir() {
        std::fs::remove_dir_all(&path).expect("clean");
    } else {
        let _ = std::fs::remove_file(&path);
    }
    path
}

fn ok(out: &Output) -> String {
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout.clone()).expect("utf-8")
}

fn params(name: &str, text: &str) -> String {
    let p = scratch(name);
    std::fs::write(&p, text).expect("write");
    p.to_str().expect("utf-8 path").to_string()
}

/// The first move of M68x6 (988TA manual, O0013): the first rough pass,
/// depth Δd = 1.8 of k = 3.68 from the end X60.64, flank infeed at half the
/// 60° tool angle from Z10. Diameter: X = 60.64 + 2 (3.68 - 1.8) = 64.4;
/// radius: 60.64 + 3.68 - 1.8 = 62.52; Z = 10 - 1.8 tan 30° = 8.96077.
const FIRST_MOVE_B: &str = "\nG00 X64.400 Z8.961\n";
const FIRST_MOVE_C: &str = "\nG00 X64.4000 Z8.9608\n";
const FIRST_MOVE_RADIUS: &str = "\nG00 X62.520 Z8.961\n";

#[test]
fn profile_flag_wins_over_the_file() {
    // The example is written for the 988TA (Q0.150 with a decimal point);
    // FANUC refuses a decimal point in G76's P and Q.
    let fanuc = params("fanuc.toml", "profile = \"fanuc\"\n");
    let out = run(&["expand", "--params", &fanuc, M68], None);
    assert_eq!(out.status.code(), Some(2), "the file alone selects FANUC");
    assert!(String::from_utf8_lossy(&out.stderr).contains("line 5, word `Q0.150`: no decimal point allowed"));
    let text = ok(&run(&["expand", "--profile", "gsk988", "--params", &fanuc, M68], None));
    assert!(text.contains(FIRST_MOVE_B), "{text}");
    // And the other way round.
    let gsk988 = params("gsk988.toml", "profile = \"gsk988\"\n");
    assert!(run(&["expand", "--params", &gsk988, M68], None).status.success());
    let out = run(&["expand", "--profile", "fanuc", "--params", &gsk988, M68], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no decimal point allowed"));
}

#[test]
fn increment_flag_wins_over_the_file() {
    let is_c = params("is-c.toml", "increment = \"is-c\"\n");
    let is_b = params("is-b.toml", "increment = \"is-b\"\n");
    assert!(ok(&run(&["expand", "--params", &is_c, M68], None)).contains(FIRST_MOVE_C));
    assert!(ok(&run(&["expand", "--increment", "is-b", "--params", &is_c, M68], None)).contains(FIRST_MOVE_B));
    assert!(ok(&run(&["expand", "--params", &is_b, M68], None)).contains(FIRST_MOVE_B));
    assert!(ok(&run(&["expand", "--increment", "is-c", "--params", &is_b, M68], None)).contains(FIRST_MOVE_C));
}

fn units(out: &Output) -> serde_json::Value {
    let doc: serde_json::Value = serde_json::from_str(&ok(out)).expect("json");
    doc["units"].clone()
}

#[test]
fn inch_flag_wins_over_the_file() {
    let metric = params("metric.toml", "unit = \"metric\"\n");
    let inch = params("inch.toml", "unit = \"inch\"\n");
    let mm = serde_json::json!({"unit": "mm", "decimals": 3});
    // IS-B inch: 0.0001 inch.
    let inches = serde_json::json!({"unit": "inch", "decimals": 4});
    assert_eq!(units(&run(&["expand", "--format", "json", "--params", &metric, M68], None)), mm);
    assert_eq!(
        units(&run(&["expand", "--format", "json", "--inch", "--params", &metric, M68], None)),
        inches
    );
    assert_eq!(units(&run(&["expand", "--format", "json", "--params", &inch, M68], None)), inches);
}

#[test]
fn radius_flag_wins_over_the_file() {
    let diameter = params("diameter.toml", "x = \"diameter\"\n");
    let radius = params("radius.toml", "x = \"radius\"\n");
    assert!(ok(&run(&["expand", "--params", &diameter, M68], None)).contains(FIRST_MOVE_B));
    assert!(ok(&run(&["expand", "--radius", "--params", &diameter, M68], None)).contains(FIRST_MOVE_RADIUS));
    assert!(ok(&run(&["expand", "--params", &radius, M68], None)).contains(FIRST_MOVE_RADIUS));
}

#[test]
fn every_flag_wins_over_a_file_that_sets_everything() {
    let file =
        params("all.toml", "profile = \"fanuc\"\nincrement = \"is-b\"\nunit = \"inch\"\nx = \"diameter\"\n");
    let out = run(
        &[
            "expand",
            "--format",
            "json",
            "--profile",
            "gsk988",
            "--increment",
            "is-c",
            "--radius",
            "--params",
            &file,
            M68,
        ],
        None,
    );
    // IS-C inch: 0.00001 inch.
    assert_eq!(units(&out), serde_json::json!({"unit": "inch", "decimals": 5}));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    // Radius X, in the cycle's own words (inch now, the same numbers).
    assert_eq!(doc["cycles"][0]["moves"][0]["x"], "62.52000");
}

#[test]
fn standard_input_is_named_stdin() {
    let program = std::fs::read(M68).expect("read");
    for args in [&["expand", "--format", "json", "-"][..], &["expand", "--format", "json"]] {
        let doc: serde_json::Value = serde_json::from_str(&ok(&run(args, Some(&program)))).expect("json");
        assert_eq!(doc["file"], "<stdin>", "{args:?}");
    }
    let jsonl = ok(&run(&["expand", "--format", "jsonl", "-"], Some(&program)));
    assert!(jsonl.lines().last().expect("summary").contains("\"file\":\"<stdin>\""), "{jsonl}");
    let passes = ok(&run(&["passes", "-"], Some(&program)));
    assert!(passes.starts_with("G76 at line 6 (<stdin>):\n"), "{passes}");
    // In errors.
    let out = run(&["passes", "-"], Some(b"G00 X80 N10\n"));
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr)
        .starts_with("cycleref: error[misplaced]: <stdin>: line 1, word `N10`"));
    // In plot titles (escaped in the SVG).
    let svg = scratch("stdin.svg");
    let out = run(&["plot", "-o", svg.to_str().expect("utf-8 path"), "-"], Some(&program));
    ok(&out);
    let doc = std::fs::read_to_string(&svg).expect("svg");
    assert!(doc.contains("&lt;stdin&gt; \u{2014} G76 at line 6"), "{doc}");
    assert!(!doc.contains("- \u{2014} G76"));
}

#[test]
fn a_bom_is_not_echoed_and_gbk_comments_are() {
    let mut program = b"\xEF\xBB\xBF(\xB6\xA8\xCE\xBB)\n".to_vec();
    program.extend_from_slice(b"M03 S500\nG00 X80 Z10 (\xC2\xDD\xCE\xC6)\nG76 P020560 Q0.150 R0.1\n");
    program.extend_from_slice(b"G76 X60.64 Z-62 P3.680 Q1.800 F6 (\xC2\xDD)\nM30 (\xBD\xE1\xCA\xF8)\n");
    let out = run(&["expand", "-"], Some(&program));
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let nc = out.stdout;
    // The BOM is not part of the program's text: the output starts with
    // the first block, the GBK comment byte for byte.
    assert!(nc.starts_with(b"(\xB6\xA8\xCE\xBB)\nM03 S500\nG00 X80 Z10 (\xC2\xDD\xCE\xC6)\n(G76 line 5:"));
    assert!(nc.ends_with(b"\nM30 (\xBD\xE1\xCA\xF8)\n"));
    // The cycle's block (and its comment) is replaced by its moves.
    let text = String::from_utf8_lossy(&nc);
    assert!(!text.lines().any(|l| l.starts_with("G76")), "{text}");
    // A non-UTF-8 byte outside a comment: line and byte column.
    let out = run(&["expand", "-"], Some(b"M03 S500\nG00 X8\xB60 Z10\n"));
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "cycleref: error[encoding]: <stdin>: line 2: byte 0xB6 at byte column 7 is not UTF-8 text (only a \
         comment may hold text in another encoding, such as GBK)\n"
    );
}

#[test]
fn vectors_out_onto_a_file_is_a_clear_error() {
    let file = scratch("not-a-dir");
    std::fs::write(&file, "keep me\n").expect("write");
    let out = run(&["vectors", "--count", "1", "--out", file.to_str().expect("utf-8 path")], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(&format!("--out {}: exists and is not a directory", file.display())), "{err}");
    assert!(!err.contains("os error"), "{err}");
    assert_eq!(std::fs::read_to_string(&file).expect("read"), "keep me\n", "the file is left alone");
    // A directory (new or existing) is fine.
    let dir = scratch("vectors-dir");
    for _ in 0..2 {
        let out = run(&["vectors", "--count", "1", "--out", dir.to_str().expect("utf-8 path")], None);
        assert!(ok(&out).starts_with("wrote 1 cases"));
    }
}

/// `n` G76 cycles; cycle `i` (from 0) has its block 2 at line 4 + 2 i.
fn many_cycles(n: usize) -> String {
    let mut s = String::from("M03 S500\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n");
    for _ in 0..n {
        s.push_str("G76 X60.64 Z-62 P3.680 Q1.800 F6\nG00 X80 Z10\n");
    }
    s
}

fn plot(name: &str, program: &str, extra: &[&str]) -> (Output, PathBuf) {
    let input = scratch(&format!("{name}.nc"));
    std::fs::write(&input, program).expect("write");
    let svg = scratch(&format!("{name}.svg"));
    let mut args = vec!["plot", "-o", svg.to_str().expect("utf-8 path")];
    args.extend_from_slice(extra);
    args.push(input.to_str().expect("utf-8 path"));
    (run(&args, None), svg)
}

fn panels(svg: &PathBuf) -> Vec<usize> {
    let doc = std::fs::read_to_string(svg).expect("svg");
    doc.match_indices("G76 at line ")
        .map(|(i, m)| {
            let rest = &doc[i + m.len()..];
            rest[..rest.find(|c: char| !c.is_ascii_digit()).expect("end")].parse().expect("a line")
        })
        .collect()
}

#[test]
fn plot_draws_at_most_24_cycles_and_says_so() {
    let (out, svg) = plot("thirty", &many_cycles(30), &[]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let lines = panels(&svg);
    assert_eq!(lines, (0..24).map(|i| 4 + 2 * i).collect::<Vec<_>>());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("thirty.nc: drew 24 of 30 cycles (at most 24 without --line)"), "{err}");
    assert!(err.contains("--line N"), "{err}");
    // 24 panels of 560 px.
    assert!(std::fs::read_to_string(&svg).expect("svg").contains(&format!("height=\"{}\"", 24 * 560)));
    // Exactly 24: no note.
    let (out, svg) = plot("twenty-four", &many_cycles(24), &[]);
    assert!(out.status.success());
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(panels(&svg).len(), 24);
}

#[test]
fn plot_line_picks_cycles() {
    let program = many_cycles(30);
    // The 28th cycle, beyond the first 24.
    let (out, svg) = plot("one", &program, &["--line", "58"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(panels(&svg), [58]);
    assert!(std::fs::read_to_string(&svg).expect("svg").contains("height=\"560\""));
    let (out, svg) = plot("two", &program, &["--line", "62", "--line", "4"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(panels(&svg), [4, 62]);
    // G76 block 1 (line 3) picks the cycle of the block 2 read with it
    // (`params_line`), line 4 (issue 30: it said there was no G76 there).
    let (out, svg) = plot("block1", &program, &["--line", "3"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert_eq!(panels(&svg), [4]);
    // A line without a cycle: G00 (line 5), past the end.
    for line in ["5", "1000"] {
        let (out, svg) = plot("none", &program, &["--line", line]);
        assert_eq!(out.status.code(), Some(2), "--line {line}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(&format!("--line {line}: no G76, G32, G92 or G75.1 block at that line")),
            "{err}"
        );
        assert!(!svg.exists(), "no file on error");
    }
}

#[test]
fn a_start_inside_the_thread_only_at_this_increment_names_the_other() {
    // The 980TDi manual's M68x6 program gives P(k) and Q(Δd) in least
    // increments for IS-C (P36800 = 3.68 mm); read at IS-B they are 36.8
    // and 18 mm, and A (X80) lies inside a thread 73.6 mm deep.
    let gsk980 = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk980-m68x6.nc");
    let out = run(&["expand", "--profile", "gsk980", gsk980], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("the start point A lies inside the thread"), "{err}");
    assert!(err.contains("was it written for --increment is-c?"), "{err}");
    // A start inside the thread at every increment system gets no hint.
    let inside = b"M03 S500\nG00 X62 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n";
    let out = run(&["expand", "--profile", "gsk988", "-"], Some(inside));
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("the start point A lies inside the thread"), "{err}");
    assert!(!err.contains("--increment"), "{err}");
}

#[test]
fn no_program_and_standard_input_a_terminal_is_a_usage_error() {
    // `script` gives the command a terminal for standard input.
    if Command::new("script").arg("--version").output().is_err() {
        eprintln!("no `script` here: skipped");
        return;
    }
    let out = Command::new("script")
        .args(["-qec", &format!("{BIN} expand"), "/dev/null"])
        .stdin(Stdio::null())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stdout));
    assert!(String::from_utf8_lossy(&out.stdout).contains("no program: give a FILE"));
}
