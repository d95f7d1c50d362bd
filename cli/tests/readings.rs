//! Readings per control on the command line (issue 34): `cycleref
//! readings`, `--reading ID=VALUE` on the commands that read a program,
//! `[readings]` in the parameter file (the command line wins), the errors
//! naming the valid ids and values, and the `readings` object of the JSON
//! documents (absent under the defaults).

mod common;

use std::path::Path;

use serde_json::Value;

/// The 980TDi's G92 with J = 8 (radius) longer than the retract X40 - X30
/// = 10 (diameter): clamped to X40 by default (R-RUNOUT `all-profiles`), as
/// written to X46 under `gsk988-only` (spec/tests/readings.rs works both).
const PROGRAM: &str = "M3 S300\nG00 X40 Z5\nG92 X30 Z-20 F2 J8 K2\nM30\n";

fn schema(name: &str) -> jsonschema::Validator {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/schemas").join(name);
    let v: Value = serde_json::from_str(&std::fs::read_to_string(path).expect("schema")).expect("json");
    jsonschema::validator_for(&v).expect("a valid schema")
}

#[test]
fn readings_lists_one_line_per_reading() {
    let all = common::stdout(&["readings"]);
    let ids: Vec<&str> = all.lines().map(|l| l.split('\t').next().unwrap_or("")).collect();
    assert_eq!(
        ids,
        [
            "R-RUNOUT",
            "R-XRUNOUT",
            "R-E980",
            "R-END",
            "R-LONG988",
            "R-HIGHSPEED",
            "R-G78LEFT",
            "R-G78CENTRE",
            "R-LEADIN",
            "R-INFEED",
            "R-LCNC-READER",
            "R-G92Q",
            "R-G75ALLOW",
            "R-G75P",
            "R-NOROUGH",
            "R-DEPTH",
            "R-STARTS",
            "R-G92HS-NOK",
            "R-G92HS-NOJ",
            "R-G92JK988",
            "R-G32RUNOUT",
            "R-CHAMFERANGLE",
            "R-MODAL",
            "R-G32LONG",
            "R-SIDE",
            "R-G75RIDGE",
            "R-G75PECK",
            "R-SPINDLE",
            "R-G75LAYER",
            "R-G75ARC",
            "R-G75CHAMFER",
            "R-G75SLOPE",
            "R-LCNC-G7"
        ]
    );
    assert!(all.starts_with("R-RUNOUT\tall-profiles* | gsk988-only\t[fanuc,gsk980]\t"), "{all}");
    assert!(all.contains("\nR-END\ttravel-i | parallel* | translated\t[fanuc,gsk980,gsk988]\t"), "{all}");
    let gsk988 = common::stdout(&["readings", "--profile", "gsk988"]);
    let ids: Vec<&str> = gsk988.lines().map(|l| l.split('\t').next().unwrap_or("")).collect();
    assert_eq!(
        ids,
        [
            "R-XRUNOUT",
            "R-END",
            "R-LONG988",
            "R-HIGHSPEED",
            "R-G78LEFT",
            "R-G78CENTRE",
            "R-LEADIN",
            "R-INFEED",
            "R-G92Q",
            "R-NOROUGH",
            "R-DEPTH",
            "R-STARTS",
            "R-G92HS-NOK",
            "R-G92HS-NOJ",
            "R-G92JK988",
            "R-G32RUNOUT",
            "R-CHAMFERANGLE",
            "R-MODAL",
            "R-G32LONG",
            "R-SIDE",
            "R-SPINDLE"
        ],
        "{gsk988}"
    );
    assert!(gsk988.contains("R-G92HS-NOK	rapid-retract* | pull-out-to-start	[gsk988]	"), "{gsk988}");
    assert!(gsk988.contains("R-CHAMFERANGLE	from-long-axis* | from-short-axis	[fanuc,gsk988]	"), "{gsk988}");
    assert!(gsk988.contains("R-LONG988\tdisplacement | table*\t[gsk988]\t"), "{gsk988}");
    assert!(gsk988.contains("R-LEADIN\tsame-z* | whole-leads\t[gsk980,gsk988]\t"), "{gsk988}");
    assert!(gsk988.contains("R-INFEED\tright-first* | left-first\t[gsk980,gsk988]\t"), "{gsk988}");
    assert!(gsk988.contains("R-NOROUGH\tnone | one-at-zero*\t[fanuc,gsk980,gsk988]\t"), "{gsk988}");
    assert!(gsk988.contains("R-DEPTH\tprevious-plus-min* | formula\t[gsk980,gsk988]\t"), "{gsk988}");
    assert!(gsk988.contains("R-STARTS\tpass-major* | start-major\t[fanuc,gsk980,gsk988]\t"), "{gsk988}");
}

#[test]
fn reading_on_the_command_line_changes_the_moves_and_is_named() {
    let prog = common::tmp("readings", "g92.nc", PROGRAM);
    let p = prog.to_str().expect("utf-8");
    let default = common::stdout(&["expand", "--profile", "gsk980", p]);
    assert!(default.contains("G32 X40.000 Z-20.000 F2.0"), "{default}");
    assert!(!default.contains("X46"), "{default}");
    let chosen = common::stdout(&["expand", "--profile", "gsk980", "--reading", "R-RUNOUT=gsk988-only", p]);
    assert!(chosen.contains("G32 X46.000 Z-20.000 F2.0\nG00 X40.000 Z-20.000\n"), "{chosen}");
    // The nc output names the reading under the cycle's heading, and only
    // then.
    assert!(
        chosen.contains("(G92 line 3: 1 pass x 1 start)\n(readings: R-RUNOUT=gsk988-only)\n"),
        "{chosen}"
    );
    assert!(!default.contains("readings"), "{default}");

    // The JSON document names the readings only when they differ.
    let v = schema("cycleref-moves-1.schema.json");
    let doc: Value =
        serde_json::from_str(&common::stdout(&["expand", "--profile", "gsk980", "--format", "json", p]))
            .expect("json");
    assert!(doc.get("readings").is_none());
    let doc: Value = serde_json::from_str(&common::stdout(&[
        "expand",
        "--profile",
        "gsk980",
        "--format",
        "json",
        "--reading",
        "R-RUNOUT=gsk988-only",
        p,
    ]))
    .expect("json");
    assert_eq!(doc["readings"], serde_json::json!({"R-RUNOUT": "gsk988-only"}));
    assert!(v.is_valid(&doc));

    // check: the expansion under the reading agrees with itself, and the
    // reports name the reading.
    let trace = common::tmp("readings", "trace.nc", &chosen);
    let t = trace.to_str().expect("utf-8");
    let args = ["check", "--profile", "gsk980", "--reading", "R-RUNOUT=gsk988-only", "--trace", t];
    let text = common::stdout(&[&args[..], &[p]].concat());
    assert!(text.starts_with("AGREE") && text.contains("\nreadings: R-RUNOUT=gsk988-only\n"), "{text}");
    let json: Value =
        serde_json::from_str(&common::stdout(&[&args[..], &["--format", "json", p]].concat())).expect("json");
    assert_eq!(json["readings"], serde_json::json!({"R-RUNOUT": "gsk988-only"}));
    assert!(schema("cycleref-check-1.schema.json").is_valid(&json));
    // Under the defaults the same trace differs, and the report names none.
    let out = common::run(&["check", "--profile", "gsk980", "--trace", t, p], None);
    assert_eq!(out.status.code(), Some(1));
    assert!(!String::from_utf8_lossy(&out.stdout).contains("readings:"));
}

#[test]
fn the_command_line_wins_over_the_parameter_file() {
    let prog = common::tmp("readings-file", "g92.nc", PROGRAM);
    let params = common::tmp("readings-file", "m.toml", "[readings]\n\"R-RUNOUT\" = \"gsk988-only\"\n");
    let (p, f) = (prog.to_str().expect("utf-8"), params.to_str().expect("utf-8"));
    let from_file = common::stdout(&["expand", "--profile", "gsk980", "--params", f, p]);
    assert!(from_file.contains("X46"), "{from_file}");
    let overridden = common::stdout(&[
        "expand",
        "--profile",
        "gsk980",
        "--params",
        f,
        "--reading",
        "R-RUNOUT=all-profiles",
        p,
    ]);
    assert!(!overridden.contains("X46"), "{overridden}");
}

#[test]
fn an_unknown_id_or_value_names_the_valid_ones() {
    let prog = common::tmp("readings-err", "g92.nc", PROGRAM);
    let p = prog.to_str().expect("utf-8");
    let out = common::run(&["expand", "--reading", "R-NOPE=x", p], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unknown reading `R-NOPE`") && err.contains("R-RUNOUT, R-XRUNOUT, R-E980, R-END"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    let out = common::run(&["passes", "--reading", "R-XRUNOUT=never", p], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("its values are refuse, towards-start"), "{err}");
}

/// R-END on the command line: a 980TDi G76 taper (spec/tests/readings.rs,
/// `END_TAPER`, works the three by hand): pass 1 ends at X30.765 Z-15
/// (`parallel`, the default), X30.8 Z-15 (`travel-i`), X30.8 Z-15.346
/// (`translated`); the heading names the non-default value.
#[test]
fn pass_end_on_the_command_line() {
    let prog = common::tmp(
        "readings-end",
        "g76.nc",
        "M3 S300\nG00 X40 Z5\nG76 P010060 Q100 R0\nG76 X30 Z-15 R-1 P1000 Q600 F2\nM30\n",
    );
    let p = prog.to_str().expect("utf-8");
    let default = common::stdout(&["expand", "--profile", "gsk980", p]);
    assert!(default.contains("G32 X30.765 Z-15.000 F2.0\n") && !default.contains("readings"), "{default}");
    let travel = common::stdout(&["expand", "--profile", "gsk980", "--reading", "R-END=travel-i", p]);
    assert!(
        travel.contains("(readings: R-END=travel-i)\n") && travel.contains("G32 X30.800 Z-15.000"),
        "{travel}"
    );
    let moved = common::stdout(&["expand", "--profile", "gsk980", "--reading", "R-END=translated", p]);
    assert!(moved.contains("G32 X30.800 Z-15.346 F2.0\n"), "{moved}");
}

/// R-LONG988 `table` (default on gsk988): the steep G92 (|R| = 10 ≥ |W| =
/// 5) has its lead along Z, which a G32 block of its cut (X travel 8, Z
/// travel 4) would read along X: the nc expansion refuses it, naming the
/// reading; the JSON moves are given (the cut to X24 Z-4, worked in
/// spec/tests/readings.rs); under `displacement` it is X long and its
/// run-out into the work is refused (R-XRUNOUT).
#[test]
fn long_axis_table_refuses_plain_blocks() {
    let prog = common::tmp("readings-long", "g92.nc", "M3 S300\nG00 X60 Z0\nG92 X20 Z-5 R10 F2 J2 K1\nM30\n");
    let p = prog.to_str().expect("utf-8");
    let out = common::run(&["expand", "--profile", "gsk988", p], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("error[usage:lead_not_writable]")
            && err.contains("line 3, G92")
            && err.contains("R-LONG988"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    let json = common::stdout(&["expand", "--profile", "gsk988", "--format", "json", p]);
    let doc: Value = serde_json::from_str(&json).expect("json");
    let cut = &doc["cycles"][0]["moves"][1];
    assert_eq!(
        (cut["role"].as_str(), cut["x"].as_str(), cut["z"].as_str()),
        (Some("cut"), Some("24.000"), Some("-4.000"))
    );
    let out = common::run(&["expand", "--profile", "gsk988", "--reading", "R-LONG988=displacement", p], None);
    assert!(String::from_utf8_lossy(&out.stderr).contains("run_out_into_work"));
}

/// R-G92FACE under R-LONG988 `table` (the gsk988 default): the steep P1
/// face thread (Z travel 2.001 above its X travel 2, worked in
/// spec/tests/readings.rs) is made with X long, so the JSON moves and
/// `check` accept it, while the nc expansion refuses it (its G32 block
/// would be read Z long), naming the reading; under `displacement` the
/// cycle itself is refused (steep_face_thread).
#[test]
fn steep_face_thread_under_the_table() {
    let prog = common::tmp("readings-face", "g92.nc", "M3 S300\nG0 X65 Z5\nG92 X61 Z1 R-2.001 F3 P1\nM30\n");
    let p = prog.to_str().expect("utf-8");
    let out = common::run(&["expand", "--profile", "gsk988", p], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("error[usage:lead_not_writable]") && err.contains("line 3, G92"), "{err}");
    let json = common::stdout(&["expand", "--profile", "gsk988", "--format", "json", p]);
    let doc: Value = serde_json::from_str(&json).expect("json");
    let cut = &doc["cycles"][0]["moves"][1];
    assert_eq!(
        (cut["role"].as_str(), cut["x"].as_str(), cut["z"].as_str()),
        (Some("cut"), Some("61.000"), Some("1.000"))
    );
    let out = common::run(&["expand", "--profile", "gsk988", "--reading", "R-LONG988=displacement", p], None);
    assert!(String::from_utf8_lossy(&out.stderr).contains("steep_face_thread"));
}

/// R-G78CENTRE and R-LEADIN on the command line, in the nc output
/// (spec/tests/readings.rs works the same programs by hand): G78 r = 0
/// under B cuts at Z5 (the Z of A), not at zc = 0.462 from it; the lead-in
/// E0.5 under `same-z` starts at X31 on Bn's Z5 and screws in along X
/// only (the default), or under `whole-leads` a lead (F2) back, at Z7.
#[test]
fn g78_centre_and_lead_in_readings_in_the_nc_output() {
    let g78 = "M3 S300\nG00 X40 Z5\nG78 P010060 Q0.1 R0.2\nG78 X30 Z-20 P1 Q0.5 F2\nM30\n";
    let prog = common::tmp("readings-g78", "g78.nc", g78);
    let p = prog.to_str().expect("utf-8");
    let default = common::stdout(&["expand", "--profile", "gsk988", p]);
    assert!(default.contains("G00 X31.000 Z4.538\nG32 X31.000 Z-20.000 F2.0\n"), "{default}");
    let under_b = common::stdout(&["expand", "--profile", "gsk988", "--reading", "R-G78CENTRE=under-b", p]);
    assert!(
        under_b.contains(
            "(readings: R-G78CENTRE=under-b)\n(rough 1 start 1 depth 0.500 cut 0.500)\n\
             G00 X31.000 Z5.000\nG32 X31.000 Z-20.000 F2.0\n"
        ),
        "{under_b}"
    );
    assert!(under_b.contains("(finish 1 start 1 depth 1.000 cut 0.200)\nG00 X30.000 Z5.000\n"), "{under_b}");

    let g76 = "M3 S300\nG00 X40 Z5\nG76 P010000 Q0.1 R0 E0.5\nG76 X30 Z-20 P1 Q1 F2\nM30\n";
    let prog = common::tmp("readings-g78", "g76.nc", g76);
    let p = prog.to_str().expect("utf-8");
    let same_z = common::stdout(&["expand", "--profile", "gsk988", p]);
    assert!(same_z.contains("G00 X31.000 Z5.000\nG32 X30.000 Z5.000 F2.0\nG32 X30.000 Z-20.000"), "{same_z}");
    let whole = common::stdout(&["expand", "--profile", "gsk988", "--reading", "R-LEADIN=whole-leads", p]);
    assert!(whole.contains("G00 X31.000 Z7.000\nG32 X30.000 Z5.000 F2.0\n"), "{whole}");
    // `check` of that expansion under the same reading agrees.
    let trace = common::tmp("readings-g78", "trace.nc", &whole);
    let t = trace.to_str().expect("utf-8");
    let text = common::stdout(&[
        "check",
        "--profile",
        "gsk988",
        "--reading",
        "R-LEADIN=whole-leads",
        "--trace",
        t,
        p,
    ]);
    assert!(text.starts_with("AGREE") && text.contains("\nreadings: R-LEADIN=whole-leads\n"), "{text}");
}

/// R-G75ARC (an output convention): a G75.1 with rounds at the inner
/// bottom's corners D and E (P0011: d = e = 1, R0.5) on the 980TDi, IS-C.
/// Its finishing contour has two arcs; under `front-post` each arc's code
/// is exchanged (G02 ↔ G03), every coordinate, I and K unchanged; `check`
/// of that output agrees under `front-post` and differs under the default,
/// which reads its G02 as clockwise seen with +Z right and +X up.
#[test]
fn arc_codes_front_post() {
    let prog = common::tmp(
        "readings-arc",
        "g75.nc",
        "M3 S300\nG00 X60 Z40\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10\nG75.1 R0.5 I4 J1 D0.5 E0.5 P0011\nM30\n",
    );
    let p = prog.to_str().expect("utf-8");
    let base = ["expand", "--profile", "gsk980", "--increment", "is-c"];
    let rear = common::stdout(&[&base[..], &[p]].concat());
    let front = common::stdout(&[&base[..], &["--reading", "R-G75ARC=front-post", p]].concat());
    let arcs = |text: &str| -> Vec<String> {
        text.lines().filter(|l| l.starts_with("G02") || l.starts_with("G03")).map(str::to_string).collect()
    };
    let (rear_arcs, front_arcs) = (arcs(&rear), arcs(&front));
    assert_eq!(rear_arcs.len(), 2, "{rear}");
    let exchanged: Vec<String> = rear_arcs
        .iter()
        .map(|l| {
            if let Some(rest) = l.strip_prefix("G02") {
                format!("G03{rest}")
            } else {
                format!("G02{}", &l[3..])
            }
        })
        .collect();
    assert_eq!(front_arcs, exchanged);
    // Every other line the same, but the readings' comment.
    let others = |text: &str| -> Vec<String> {
        text.lines()
            .filter(|l| !l.starts_with("G02") && !l.starts_with("G03") && !l.starts_with("(readings:"))
            .map(str::to_string)
            .collect()
    };
    assert_eq!(others(&rear), others(&front));
    let trace = common::tmp("readings-arc", "trace.nc", &front);
    let t = trace.to_str().expect("utf-8");
    let check = ["check", "--profile", "gsk980", "--increment", "is-c", "--trace", t];
    let text = common::stdout(&[&check[..], &["--reading", "R-G75ARC=front-post", p]].concat());
    assert!(text.starts_with("AGREE"), "{text}");
    let out = common::run(&[&check[..], &[p]].concat(), None);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stdout));
}
