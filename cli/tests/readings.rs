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
        ["R-RUNOUT", "R-XRUNOUT", "R-E980", "R-HIGHSPEED", "R-LCNC-READER", "R-G92Q", "R-G75ALLOW", "R-G75P"]
    );
    assert!(all.starts_with("R-RUNOUT\tall-profiles* | gsk988-only\t[fanuc,gsk980]\t"), "{all}");
    let gsk988 = common::stdout(&["readings", "--profile", "gsk988"]);
    let gsk988_ids: Vec<&str> = gsk988.lines().map(|l| l.split('\t').next().unwrap_or("")).collect();
    assert_eq!(gsk988_ids, ["R-XRUNOUT", "R-HIGHSPEED", "R-G92Q"], "{gsk988}");
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
        err.contains("unknown reading `R-NOPE`")
            && err.contains(
                "R-RUNOUT, R-XRUNOUT, R-E980, R-HIGHSPEED, R-LCNC-READER, R-G92Q, R-G75ALLOW, R-G75P"
            ),
        "{err}"
    );
    assert!(out.stdout.is_empty());
    let out = common::run(&["passes", "--reading", "R-XRUNOUT=never", p], None);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("its values are refuse, towards-start"), "{err}");
}
