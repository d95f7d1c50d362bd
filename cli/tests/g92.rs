//! G92 through the `cycleref` command, end to end, on the 980TDi's example
//! O0012 (examples/gsk980-g92-o0012.nc): the `nc` blocks, the `json`
//! moves, the `passes` table, `check` against a vendor's trace and `plot`,
//! with the values worked by hand in `spec/tests/g92.rs` (A = X65 Z5, C at
//! Z-28, J3 K1: the cut to Z-27, the run-out to X + 6 at Z-28, the retract
//! to X65, the return to Z5).

mod common;

use common::{jsonl_cycles, run, stdout};

fn example() -> String {
    format!("{}/../examples/gsk980-g92-o0012.nc", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch file of this binary's (`common::tmp` under `cycleref-g92-…`).
fn tmp(name: &str, text: &str) -> std::path::PathBuf {
    common::tmp("g92", name, text)
}

/// The expected nc of one block: heading, approach, cut, run-out, retract,
/// return.
fn block(line: usize, x: &str, run_out_x: &str) -> String {
    format!(
        "(G92 line {line}: 1 pass x 1 start)\nG00 X{x} Z5.000\nG32 X{x} Z-27.000 F3.0\nG32 X{run_out_x} Z-28.000 \
         F3.0\nG00 X65.000 Z-28.000\nG00 X65.000 Z5.000\n"
    )
}

#[test]
fn nc_of_the_manuals_example_with_both_engines() {
    let want = format!(
        "O0012\nM3 S300 G0 X150 Z50 T0101\nG0 X65 Z5\n{}{}{}{}M30\n",
        block(4, "58.700", "64.700"),
        block(5, "57.700", "63.700"),
        block(6, "57.000", "63.000"),
        block(7, "56.900", "62.900"),
    );
    let file = example();
    for engine in ["impl", "spec"] {
        let got = stdout(&["expand", "--profile", "gsk980", "--engine", engine, &file]);
        assert_eq!(got, want, "engine {engine}");
    }
}

#[test]
fn json_moves_carry_the_single_pass() {
    let file = example();
    let got = stdout(&["expand", "--profile", "gsk980", "--format", "json", &file]);
    let v: serde_json::Value = serde_json::from_str(&got).expect("json");
    let cycles = v["cycles"].as_array().expect("cycles");
    assert_eq!(cycles.len(), 4);
    let c = &cycles[1];
    assert_eq!((c["cycle"].as_str(), c["line"].as_u64()), (Some("G92"), Some(5)));
    assert_eq!((c["start"]["x"].as_str(), c["start"]["z"].as_str()), (Some("65.000"), Some("5.000")));
    let moves = c["moves"].as_array().expect("moves");
    let roles: Vec<&str> = moves.iter().map(|m| m["role"].as_str().unwrap()).collect();
    assert_eq!(roles, ["approach", "cut", "run-out", "retract", "return"]);
    assert_eq!((moves[2]["x"].as_str(), moves[2]["z"].as_str()), (Some("63.700"), Some("-28.000")));
    assert_eq!(moves[1]["sync"].as_bool(), Some(true));
    assert_eq!(moves[2]["sync"].as_bool(), Some(false));
    assert_eq!(moves[1]["pass"]["kind"].as_str(), Some("single"));
}

#[test]
fn passes_table() {
    let got = stdout(&["passes", "--profile", "gsk980", &example()]);
    let rows: Vec<Vec<&str>> = got.lines().skip(2).map(|l| l.split_whitespace().collect()).collect();
    assert_eq!(
        rows[..4],
        [
            ["4", "1", "58.700", "5.000", "58.700", "-27.000", "64.700", "-28.000"],
            ["5", "1", "57.700", "5.000", "57.700", "-27.000", "63.700", "-28.000"],
            ["6", "1", "57.000", "5.000", "57.000", "-27.000", "63.000", "-28.000"],
            ["7", "1", "56.900", "5.000", "56.900", "-27.000", "62.900", "-28.000"],
        ]
    );
    assert!(got.starts_with("G92 blocks ("), "{got}");
}

/// A vendor's trace equal to ours agrees; one whose third pass cuts 0.02
/// (diameter) shallower is reported on that block, its point named in
/// the manual's terms.
#[test]
fn check_a_vendors_trace() {
    let file = example();
    let ours = stdout(&["expand", "--profile", "gsk980", &file]);
    let same = tmp("same.nc", &ours);
    let out = run(&["check", "--profile", "gsk980", "--trace", same.to_str().unwrap(), &file], None);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    let wrong = tmp("wrong.nc", &ours.replace("G32 X57.000 Z-27.000", "G32 X57.020 Z-27.000"));
    let out = run(&["check", "--profile", "gsk980", "--trace", wrong.to_str().unwrap(), &file], None);
    assert_eq!(out.status.code(), Some(1));
    let report = String::from_utf8(out.stdout).expect("utf-8");
    assert!(report.contains("G92 at line 6, start 1: end of cut (run-out start)"), "{report}");
    assert!(report.contains("difference: X 20 Z 0 increments"), "{report}");
}

/// A trace that retracts Z first after its run-out (its Z leg runs at the
/// run-out's X, X63.7, through the crests of the thread between X63.7 and
/// X65) is a rapid through the work, not an agreement (R-CHECKSPLIT).
#[test]
fn check_a_z_first_retract_through_the_crests() {
    let file = example();
    let ours = stdout(&["expand", "--profile", "gsk980", &file]);
    let old = "G32 X63.700 Z-28.000 F3.0\nG00 X65.000 Z-28.000\nG00 X65.000 Z5.000\n";
    assert!(ours.contains(old));
    let z_first = ours.replace(old, "G32 X63.700 Z-28.000 F3.0\nG00 X63.700 Z5.000\nG00 X65.000 Z5.000\n");
    let trace = tmp("z-first.nc", &z_first);
    let out = run(&["check", "--profile", "gsk980", "--trace", trace.to_str().unwrap(), &file], None);
    assert_eq!(out.status.code(), Some(1));
    let report = String::from_utf8(out.stdout).expect("utf-8");
    assert!(report.contains("G92 at line 5, start 1: E (retract end) (rapid through the work)"), "{report}");
}

/// The G92 panel: one blue per block, its rapids dashed, the run-outs
/// green; `--line` picks a G92 block.
#[test]
fn plot_draws_the_g92_blocks() {
    let file = example();
    let plot = |name: &str, extra: &[&str]| {
        let out = tmp(name, "");
        let mut args = vec!["plot", "--profile", "gsk980", "--output", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        args.push(&file);
        stdout(&args);
        std::fs::read_to_string(&out).expect("svg")
    };
    let svg = plot("all.svg", &[]);
    assert!(svg.contains("G92 blocks (lines 4-7)"), "{}", &svg[..svg.len().min(2000)]);
    assert!(svg.contains("4 blocks"));
    assert!(svg.contains("thread (G92), one blue per block"));
    assert!(svg.contains("line 5: run-out"));
    assert!(svg.contains("line 7: approach"));
    let one = plot("one.svg", &["--line", "6"]);
    assert!(one.contains("G92 blocks (lines 6-6)"));
    assert!(!one.contains("line 5: run-out"));
}

/// `--format jsonl`: one line per G92 block, each the `json` document's
/// cycle, then the summary: 4 blocks of 5 moves each (approach, cut,
/// run-out, retract, return) = 20 moves.
#[test]
fn jsonl_carries_the_g92_blocks() {
    let lines = jsonl_cycles("gsk980", &example(), (4, 20));
    let blocks: Vec<(Option<&str>, Option<u64>)> =
        lines.iter().map(|c| (c["cycle"].as_str(), c["line"].as_u64())).collect();
    assert_eq!(
        blocks,
        [(Some("G92"), Some(4)), (Some("G92"), Some(5)), (Some("G92"), Some(6)), (Some("G92"), Some(7))]
    );
}
