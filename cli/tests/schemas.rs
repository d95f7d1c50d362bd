//! The JSON Schemas of the three documents (`docs/schemas/`) hold for real
//! output: every vector of the corpus, `expand --format json` and every
//! line of `--format jsonl` of every example, and `check --format json`
//! reports that agree and that differ (a rapid, an arc's centre, a thread
//! move's lead, a point of LinuxCNC's G76). A schema that accepted
//! anything would pass these, so each is also shown to refuse a document
//! with one field changed.

mod common;

use std::path::{Path, PathBuf};

use serde_json::Value;

fn top() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn read_json(path: &Path) -> Value {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn schema(name: &str) -> Value {
    read_json(&top().join("docs/schemas").join(name))
}

/// The vector schema with its references to the moves schema made local:
/// the moves schema's definitions copied in (a validator given both files
/// resolves the relative reference the same way).
fn vector_schema() -> Value {
    let moves = schema("cycleref-moves-1.schema.json");
    let text = schema("cycleref-vector-1.schema.json")
        .to_string()
        .replace("cycleref-moves-1.schema.json#/$defs/", "#/$defs/");
    let mut v: Value = serde_json::from_str(&text).expect("json");
    v["$defs"] = moves["$defs"].clone();
    v
}

/// The moves schema's definition `name` as a schema of its own (a jsonl
/// line).
fn moves_def(name: &str) -> Value {
    let mut v = schema("cycleref-moves-1.schema.json");
    let defs = v["$defs"].take();
    serde_json::json!({
        "$schema": v["$schema"],
        "$ref": format!("#/$defs/{name}"),
        "$defs": defs,
    })
}

fn validator(schema: &Value) -> jsonschema::Validator {
    jsonschema::validator_for(schema).expect("a valid schema")
}

fn assert_valid(v: &jsonschema::Validator, doc: &Value, what: &str) {
    let errors: Vec<String> = v.iter_errors(doc).map(|e| format!("{e} at {}", e.instance_path)).collect();
    assert!(errors.is_empty(), "{what}: {errors:#?}");
}

#[test]
fn every_vector_of_the_corpus_is_a_cycleref_vector_1() {
    let v = validator(&vector_schema());
    let mut n = 0;
    let mut errors = 0;
    for entry in std::fs::read_dir(top().join("vectors")).expect("vectors/") {
        let path = entry.expect("entry").path();
        let case = path.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.starts_with("case-"));
        if case && path.extension().is_some_and(|e| e == "json") {
            let doc = read_json(&path);
            assert_valid(&v, &doc, &path.display().to_string());
            n += 1;
            errors += usize::from(doc["expect"].get("error").is_some());
        }
    }
    assert_eq!(n, 125);
    assert!(errors > 0 && errors < n, "both kinds of expectation: {errors} errors of {n}");
    // Refused: an error without its stable kind, a case with both moves
    // and an error, an unknown field.
    let one = read_json(&top().join("vectors/case-0124.json"));
    let mut bad = one.clone();
    bad["expect"]["error"].as_object_mut().expect("error").remove("kind");
    assert!(!v.is_valid(&bad));
    let mut bad = one.clone();
    bad["expect"]["units"] = serde_json::json!({"unit": "mm", "decimals": 3});
    assert!(!v.is_valid(&bad));
    let mut bad = one;
    bad["extra"] = Value::Bool(true);
    assert!(!v.is_valid(&bad));
}

/// Each example with the profile its name says.
fn examples() -> Vec<(String, &'static str)> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(top().join("examples")).expect("examples/") {
        let path = entry.expect("entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_owned();
        let profile = match name.split('-').next().unwrap_or_default() {
            "fanuc" => "fanuc",
            "gsk980" => "gsk980",
            "linuxcnc" => "linuxcnc",
            _ => "gsk988",
        };
        out.push((path.to_str().expect("utf-8").to_owned(), profile));
    }
    out.sort();
    out
}

#[test]
fn expand_json_of_every_example_is_a_cycleref_moves_1() {
    let v = validator(&schema("cycleref-moves-1.schema.json"));
    let jsonl_cycle = validator(&moves_def("cycle"));
    let jsonl_summary = validator(&moves_def("jsonl_summary"));
    let mut kinds = std::collections::BTreeSet::new();
    let mut expanded = 0;
    for (path, profile) in examples() {
        let out = common::run(&["expand", "--format", "json", "--profile", profile, &path], None);
        // A few examples show an error on purpose (gsk980-g32-taper.nc).
        if out.status.code() == Some(2) {
            continue;
        }
        assert!(out.status.success(), "{path}: {}", String::from_utf8_lossy(&out.stderr));
        expanded += 1;
        let doc: Value = serde_json::from_slice(&out.stdout).expect("json");
        assert_valid(&v, &doc, &path);
        // Each jsonl line: a cycle of the document, then the summary.
        let out = common::run(&["expand", "--format", "jsonl", "--profile", profile, &path], None);
        assert!(out.status.success(), "{path}: {}", String::from_utf8_lossy(&out.stderr));
        let lines: Vec<Value> = String::from_utf8(out.stdout)
            .expect("utf-8")
            .lines()
            .map(|l| serde_json::from_str(l).expect("a json line"))
            .collect();
        let (summary, cycles) = lines.split_last().expect("a summary line");
        assert_eq!(cycles.len(), doc["cycles"].as_array().expect("cycles").len(), "{path}");
        for (n, cycle) in cycles.iter().enumerate() {
            assert_valid(&jsonl_cycle, cycle, &format!("{path}: jsonl line {}", n + 1));
        }
        assert_valid(&jsonl_summary, summary, &format!("{path}: jsonl summary"));
        for c in doc["cycles"].as_array().expect("cycles") {
            kinds.insert(c["cycle"].as_str().expect("code").to_owned());
            for m in c["moves"].as_array().expect("moves") {
                kinds.insert(m["motion"].as_str().expect("motion").to_owned());
            }
        }
    }
    assert!(expanded >= 12, "{expanded} examples expanded");
    // Every cycle code the examples hold, and every kind of motion.
    for k in ["G76", "G78", "G32", "G92", "G75.1", "rapid", "feed", "thread", "arc-cw", "arc-ccw"] {
        assert!(kinds.contains(k), "no example shows {k}: {kinds:?}");
    }
    // Refused: a thread move without its lead, a rapid with a centre.
    let out = common::run(
        &["expand", "--format", "json", "--profile", "gsk980", &example("gsk980-g92-o0012.nc")],
        None,
    );
    let doc: Value = serde_json::from_slice(&out.stdout).expect("json");
    let mut bad = doc.clone();
    bad["cycles"][0]["moves"][1].as_object_mut().expect("a move").remove("lead");
    assert!(!v.is_valid(&bad));
    let mut bad = doc;
    bad["cycles"][0]["moves"][0]["centre"] = serde_json::json!({"x": "1.000", "z": "2.000"});
    assert!(!v.is_valid(&bad));
}

fn example(name: &str) -> String {
    top().join("examples").join(name).to_str().expect("utf-8").to_owned()
}

/// `check --format json` of `program` against its own expansion with
/// `edit` applied to the expansion's text.
fn check_report(profile: &str, program: &str, edit: impl Fn(&str) -> String) -> (i32, Value) {
    let expanded = common::run(&["expand", "--profile", profile, program], None);
    assert!(expanded.status.success());
    let trace =
        common::tmp("schemas", &format!("{}.nc", profile), &edit(&String::from_utf8_lossy(&expanded.stdout)));
    let out = common::run(
        &[
            "check",
            "--format",
            "json",
            "--profile",
            profile,
            "--trace",
            trace.to_str().expect("utf-8"),
            program,
        ],
        None,
    );
    (out.status.code().expect("status"), serde_json::from_slice(&out.stdout).expect("json"))
}

#[test]
fn check_json_is_a_cycleref_check_1() {
    let v = validator(&schema("cycleref-check-1.schema.json"));
    // Agreeing.
    let (code, doc) = check_report("gsk980", &example("gsk980-g92-o0012.nc"), str::to_owned);
    assert_eq!((code, doc["agree"].as_bool()), (0, Some(true)));
    assert_valid(&v, &doc, "an agreeing report");
    // A rapid one increment off.
    let (code, doc) =
        check_report("gsk980", &example("gsk980-g92-o0012.nc"), |t| t.replacen("X58.700", "X58.701", 1));
    assert_eq!((code, doc["agree"].as_bool()), (1, Some(false)));
    assert_valid(&v, &doc, "a rapid off");
    assert_eq!(doc["divergences"][0]["difference_increments"], serde_json::json!({"x": 1, "z": 0}));
    // An arc's centre off (G75.1's finishing contour).
    let (code, doc) = check_report("gsk980", &example("gsk980-g75-square.nc"), |t| {
        t.replacen("I0.300 K0.000", "I0.301 K0.000", 1)
    });
    assert_eq!(code, 1);
    assert_valid(&v, &doc, "an arc off");
    // A thread's lead changed (G76): the pass is the moves document's,
    // flank included.
    let (code, doc) = check_report("gsk988", &example("gsk988-m68x6.nc"), |t| t.replacen("F6", "F5", 1));
    assert_eq!(code, 1);
    assert_valid(&v, &doc, "a lead changed");
    let pass = &doc["divergences"][0]["ours"]["pass"];
    assert_eq!((pass["start"].as_u64(), pass["flank"].as_str()), (Some(1), Some("right")), "{pass}");
    // A point of LinuxCNC's G76 off: its pass has no start.
    let (code, lcnc) = check_report("linuxcnc", &example("linuxcnc-m20-taper.ngc"), |t| {
        t.replacen("X19.7000 Z0.9151", "X19.7010 Z0.9151", 1)
    });
    assert_eq!(code, 1);
    assert_valid(&v, &lcnc, "a LinuxCNC point off");
    let pass = &lcnc["divergences"][0]["ours"]["pass"];
    assert!(pass.get("start").is_none() && pass["flank"].is_string(), "{pass}");
    // Refused: a verdict that is not a boolean, a pass without its flank,
    // an unknown role.
    let mut bad = doc.clone();
    bad["agree"] = Value::String("no".into());
    assert!(!v.is_valid(&bad));
    let mut bad = doc.clone();
    bad["divergences"][0]["ours"]["pass"].as_object_mut().expect("a pass").remove("flank");
    assert!(!v.is_valid(&bad));
    let mut bad = doc;
    bad["divergences"][0]["ours"]["role"] = Value::String("wander".into());
    assert!(!v.is_valid(&bad));
}
