//! G75.1 through the `cycleref` command, end to end: both engines print the
//! same `nc` and `json`; the `nc` blocks, the `json` moves, the `passes`
//! table, the `plot` and `check` of the square example are the values
//! worked by hand in `proofs/tests/g75_golden.rs` (docs/G75.md), mapped to
//! absolute X/Z here.
//!
//! The square example (examples/gsk980-g75-square.nc): S = (X30, Z0), H−6
//! (sx = −1, X = 30 − y/1000), D−8 (sz = −1, Z = −u/1000), diameter
//! programming (f = 2), IS-B. Layers y1 = 4000, y2 = 5600; plunges of
//! layer 1 at u = 200, 3200, 4800 (two pecks of Δi = 2000 each), of layer 2
//! at 600, 3600, 4500 (one peck). Rough contour R0 (200, 0) → K1 (200,
//! 4800) → K2 (600, 5600) → K3 (4500, 5600) → K4 (4800, 5000) → R3 (4800,
//! 0). Finishing: T1s (−500, 0), T1a (0, 1000), T3a (0, 5200), round r3 to
//! T3b (400, 6000) about C3 (400, 5200), bottom to T4b − w (4700, 6000),
//! round r4 to T4c − w (5000, 5400) about C4 − w (4700, 5400), flank B to
//! P3 − w (5000, 0).

mod common;

use common::{run, stdout};
use std::path::PathBuf;

const EXAMPLES: &[(&str, &[&str])] = &[
    ("gsk980-g75-seed.nc", &["--profile", "gsk980", "--increment", "is-c"]),
    ("gsk980-g75-square.nc", &["--profile", "gsk980"]),
    ("gsk980-g75-slope.nc", &["--profile", "gsk980"]),
];

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn square(command: &str, extra: &[&str]) -> String {
    let file = example("gsk980-g75-square.nc");
    let mut args = vec![command, "--profile", "gsk980"];
    args.extend_from_slice(extra);
    args.push(&file);
    stdout(&args)
}

/// A scratch file of this binary's (`common::tmp` under `cycleref-g75-…`).
fn tmp(name: &str, text: &str) -> PathBuf {
    common::tmp("g75", name, text)
}

#[test]
fn both_engines_print_the_same_grooves() {
    for (name, flags) in EXAMPLES {
        for format in ["nc", "json"] {
            let file = example(name);
            let mut args = vec!["expand", "--format", format];
            args.extend_from_slice(flags);
            args.push(&file);
            let spec = stdout(&[args.as_slice(), &["--engine", "spec"]].concat());
            let engine = stdout(&[args.as_slice(), &["--engine", "impl"]].concat());
            assert_eq!(spec, engine, "{name} {format}: the engines differ");
        }
    }
}

#[test]
fn nc_blocks_of_the_square_groove() {
    let text = square("expand", &[]);
    let lines: Vec<&str> = text.lines().collect();
    let at = |line: &str| lines.iter().position(|l| *l == line).unwrap_or_else(|| panic!("{line}\n{text}"));
    // The header comment, then A11 = (200, y_top = 0).
    let header = lines.iter().position(|l| l.starts_with("(G75.1 lines 8-9: J1")).expect("header");
    assert_eq!(lines[header], "(G75.1 lines 8-9: J1 rough + finish, 2 layers, 6 plunges, tool width I3.000)");
    assert_eq!(lines[header + 1], "G00 X30.000 Z-0.200");
    // Layer 1 plunge 1: pecks to y = 2000 and 4000 with a retract of e = 0.5
    // (1.000 of diameter) between, then back to the plunge start.
    let p11 = at("(layer 1 plunge 1)");
    assert_eq!(
        lines[p11 + 1..p11 + 6],
        [
            "G01 X28.000 Z-0.200",
            "G00 X29.000 Z-0.200",
            "G01 X26.000 Z-0.200",
            "G00 X30.000 Z-0.200",
            "G00 X30.000 Z-3.200"
        ]
    );
    // Layer 2 starts at the bottom of layer 1 (y = 4000), at A21 = 600.
    let p21 = at("(layer 2 plunge 1)");
    assert_eq!(lines[p21 - 2..p21], ["G00 X30.000 Z-0.600", "G00 X26.000 Z-0.600"]);
    assert_eq!(lines[p21 + 1], "G01 X24.400 Z-0.600");
    // Step 9, then step 10 with the two rounds as G02 with I (radius) and K.
    let rough = at("(rough contour)");
    assert_eq!(
        lines[rough + 1..rough + 6],
        [
            "G01 X25.200 Z-0.200",
            "G01 X24.400 Z-0.600",
            "G01 X24.400 Z-4.500",
            "G01 X25.000 Z-4.800",
            "G01 X30.000 Z-4.800"
        ]
    );
    let finish = at("(finishing contour)");
    assert_eq!(
        lines[finish + 1..finish + 10],
        [
            "G00 X30.000 Z0.500",
            "G01 X29.000 Z0.000",
            "G01 X24.800 Z0.000",
            "G02 X24.000 Z-0.400 I0.000 K-0.400",
            "G01 X24.000 Z-4.700",
            "G02 X24.600 Z-5.000 I0.300 K0.000",
            "G01 X30.000 Z-5.000",
            "G00 X30.000 Z0.000",
            "G00 X40.000 Z5.000",
        ]
    );
}

#[test]
fn json_moves_of_the_square_groove() {
    let text = square("expand", &["--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&text).expect("json");
    let cycle = &v["cycles"][0];
    assert_eq!(cycle["cycle"], "G75.1");
    assert_eq!(cycle["line"], 9);
    let moves = cycle["moves"].as_array().expect("moves");
    let arcs: Vec<&serde_json::Value> =
        moves.iter().filter(|m| m["motion"].as_str().is_some_and(|s| s.starts_with("arc"))).collect();
    assert_eq!(arcs.len(), 2);
    // r3 about C3 = (400, 5200): X 30 − 5.2, Z −0.4; r4 about C4 − w.
    assert_eq!(arcs[0]["motion"], "arc-cw");
    assert_eq!(arcs[0]["centre"]["x"], "24.800");
    assert_eq!(arcs[0]["centre"]["z"], "-0.400");
    assert_eq!(arcs[0]["role"], "finish-contour");
    assert_eq!(arcs[1]["centre"]["x"], "24.600");
    assert_eq!(arcs[1]["centre"]["z"], "-4.700");
    // The pecks carry their plunge: 3 × 2 in layer 1, 3 × 1 in layer 2.
    let pecks: Vec<(u64, u64)> = moves
        .iter()
        .filter(|m| m["role"] == "peck")
        .map(|m| (m["plunge"]["layer"].as_u64().unwrap(), m["plunge"]["number"].as_u64().unwrap()))
        .collect();
    assert_eq!(pecks, [(1, 1), (1, 1), (1, 2), (1, 2), (1, 3), (1, 3), (2, 1), (2, 2), (2, 3)]);
    assert!(moves.iter().any(|m| m["role"] == "layer-change" && m["plunge"]["layer"] == 2));
    // The path returns to the point before the cycle.
    let last = moves.last().expect("a move");
    assert_eq!((last["x"].as_str(), last["z"].as_str()), (Some("40.000"), Some("5.000")));
}

#[test]
fn passes_lists_layers_and_plunges() {
    let text = square("passes", &[]);
    // The table's rows: those that start with a layer number.
    let rows: Vec<Vec<&str>> = text
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>())
        .filter(|r| r.len() == 6 && r[0].parse::<u32>().is_ok())
        .collect();
    let expected = [
        ["1", "1", "-0.200", "30.000", "26.000", "2"],
        ["1", "2", "-3.200", "30.000", "26.000", "2"],
        ["1", "3", "-4.800", "30.000", "26.000", "2"],
        ["2", "1", "-0.600", "26.000", "24.400", "1"],
        ["2", "2", "-3.600", "26.000", "24.400", "1"],
        ["2", "3", "-4.500", "26.000", "24.400", "1"],
    ];
    assert_eq!(rows, expected, "{text}");
    assert!(text.contains("rough contour (step 9): 5 cutting moves"), "{text}");
    assert!(text.contains("finishing contour (step 10): 6 cutting moves"), "{text}");
}

#[test]
fn plot_draws_the_groove_and_the_tool() {
    let out = tmp("square.svg", "");
    let file = example("gsk980-g75-square.nc");
    let o = run(&["plot", "--profile", "gsk980", &file, "-o", out.to_str().expect("utf-8")], None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(&out).expect("svg");
    assert!(svg.starts_with("<svg") || svg.contains("<svg"), "not an SVG");
    assert!(svg.contains("G75.1 at lines 8-9"), "the panel's title");
    assert!(svg.contains("grooving tool I3.000"), "the tool's width is named");
    assert!(
        svg.matches("<path").count() + svg.matches("<line").count() + svg.matches("<polyline").count() > 20
    );
}

#[test]
fn check_names_a_wrong_plunge() {
    let ours = square("expand", &[]);
    let file = example("gsk980-g75-square.nc");
    let run = |trace: &str, name: &str| {
        let p = tmp(name, trace);
        let o = run(&["check", "--profile", "gsk980", "--trace", p.to_str().expect("utf-8"), &file], None);
        (o.status.code().expect("exit code"), String::from_utf8_lossy(&o.stdout).into_owned())
    };
    let (code, text) = run(&ours, "same.nc");
    assert_eq!(code, 0, "{text}");
    assert!(text.starts_with("AGREE"), "{text}");
    // Layer 2 plunge 2 cut 0.1 mm (100 increments of diameter) too deep.
    let wrong = ours.replacen("G01 X24.400 Z-3.600", "G01 X24.300 Z-3.600", 1);
    assert_ne!(wrong, ours);
    let (code, text) = run(&wrong, "deep.nc");
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("G75.1 at line 9, layer 2 plunge 2"), "{text}");
    assert!(text.contains("difference: X 100 Z 0 increments") || text.contains("X -100"), "{text}");
}
