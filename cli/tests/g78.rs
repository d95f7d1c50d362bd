//! G78 through the `cycleref` command, end to end, on
//! examples/gsk980-g78.nc (the passes worked by hand in `spec/tests/g78.rs`,
//! `gsk980_alternating_flanks_with_equal_depths`: equal steps of 0.8 to
//! 2.5, right and left flank in turn, two finishing passes at X60 Z8.964)
//! and examples/gsk988-g78.nc (the 988TA's example with r = 04: G76 D2's
//! passes).

mod common;

use common::{jsonl_cycles, run, stdout};

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch file of this binary's (`common::tmp` under `cycleref-g78-…`).
fn tmp(name: &str, text: &str) -> std::path::PathBuf {
    common::tmp("g78", name, text)
}

/// One pass: the comment, approach, cut to Z-58 (K2), run-out J1.5 (X + 3)
/// at Z-60, retract to X80, return to Z10.
fn pass(comment: &str, x: &str, z: &str, run_out_x: &str) -> String {
    format!(
        "({comment})\nG00 X{x} Z{z}\nG32 X{x} Z-58.000 F3.0\nG32 X{run_out_x} Z-60.000 F3.0\nG00 X80.000 \
         Z-60.000\nG00 X80.000 Z10.000\n"
    )
}

#[test]
fn nc_of_the_980tdi_example_with_both_engines() {
    let want = [
        "(GSK 980TDi G78: equal depth steps of 0.8, flanks in turn, two finishing passes)\nM3 S300\nG00 X80 Z10\n"
            .to_string(),
        "(G78 line 5: 4 rough + 2 finish passes x 1 start)\n".to_string(),
        pass("rough 1 start 1 depth 0.800 cut 0.800", "64.400", "9.669", "67.400"),
        pass("rough 2 start 1 depth 1.600 cut 0.800", "62.800", "8.591", "65.800"),
        pass("rough 3 start 1 depth 2.400 cut 0.800", "61.200", "9.006", "64.200"),
        pass("rough 4 start 1 depth 2.500 cut 0.100", "61.000", "8.964", "64.000"),
        pass("finish 1 start 1 depth 3.000 cut 0.500", "60.000", "8.964", "63.000"),
        pass("finish 2 start 1 depth 3.000 cut 0.000", "60.000", "8.964", "63.000"),
        "G00 X80 Z10\nM30\n".to_string(),
    ]
    .concat();
    let file = example("gsk980-g78.nc");
    for engine in ["impl", "spec"] {
        assert_eq!(stdout(&["expand", "--profile", "gsk980", "--engine", engine, &file]), want, "{engine}");
    }
}

#[test]
fn json_names_the_cycle_and_its_flanks() {
    let got = stdout(&["expand", "--profile", "gsk980", "--format", "json", &example("gsk980-g78.nc")]);
    let v: serde_json::Value = serde_json::from_str(&got).expect("json");
    let c = &v["cycles"][0];
    assert_eq!(
        (c["cycle"].as_str(), c["line"].as_u64(), c["params_line"].as_u64()),
        (Some("G78"), Some(5), Some(4))
    );
    let flanks: Vec<&str> = c["moves"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|m| m["role"] == "approach")
        .map(|m| m["pass"]["flank"].as_str().unwrap())
        .collect();
    assert_eq!(flanks, ["right", "left", "right", "left", "centre", "centre"]);
}

/// The 988TA's example with r = 04 has G76 D2's passes: level 1.8 twice
/// (right Z9.254, left Z8.674), level 2.5 once (Z8.964).
#[test]
fn passes_of_the_988ta_example() {
    let got = stdout(&["passes", "--profile", "gsk988", &example("gsk988-g78.nc")]);
    let rows: Vec<Vec<&str>> = got.lines().skip(2).map(|l| l.split_whitespace().collect()).collect();
    assert_eq!(
        rows[..3],
        [
            ["1", "rough", "1", "right", "1.800", "1.800", "62.400", "9.254"],
            ["2", "rough", "1", "left", "1.800", "1.800", "62.400", "8.674"],
            ["3", "rough", "1", "right", "2.500", "0.700", "61.000", "8.964"],
        ]
    );
    assert!(got.starts_with("G78 at line 10 ("), "{got}");
}

/// A vendor whose second pass starts on the right flank (Z9.337, the
/// right-flank shift 0.663) instead of the left (Z8.591): reported on that
/// pass of the G78.
#[test]
fn check_names_the_g78_pass() {
    let file = example("gsk980-g78.nc");
    let ours = stdout(&["expand", "--profile", "gsk980", &file]);
    let wrong = tmp("wrong.nc", &ours.replace("G00 X62.800 Z8.591", "G00 X62.800 Z9.337"));
    let out = run(&["check", "--profile", "gsk980", "--trace", wrong.to_str().unwrap(), &file], None);
    assert_eq!(out.status.code(), Some(1));
    let report = String::from_utf8(out.stdout).expect("utf-8");
    assert!(report.contains("G78 at line 5, rough pass 2 (start 1, depth 1.600, cut 0.800)"), "{report}");
    assert!(report.contains("difference: X 0 Z 746 increments"), "{report}");
}

#[test]
fn plot_titles_the_g78() {
    let out = tmp("g78.svg", "");
    stdout(&["plot", "--profile", "gsk980", "--output", out.to_str().unwrap(), &example("gsk980-g78.nc")]);
    let svg = std::fs::read_to_string(&out).expect("svg");
    assert!(svg.contains("G78 at line 5"), "{}", &svg[..svg.len().min(1500)]);
}

/// `--format jsonl` on the 980TDi example: one line for the G78 (block 2
/// at line 5, block 1 at line 4), the `json` document's cycle, then the
/// summary: 4 rough and 2 finishing passes of 5 moves = 30 moves.
#[test]
fn jsonl_carries_the_g78() {
    let lines = jsonl_cycles("gsk980", &example("gsk980-g78.nc"), (1, 30));
    assert_eq!(lines.len(), 1);
    assert_eq!(
        (lines[0]["cycle"].as_str(), lines[0]["line"].as_u64(), lines[0]["params_line"].as_u64()),
        (Some("G78"), Some(5), Some(4))
    );
}
