//! `cycleref vectors`: the checked-in corpus in `vectors/` is exactly what
//! the generator writes for `--count 125 --seed 1`, it covers every feature
//! and every listed error kind, and every case replays: its program, read
//! again with its machine settings, gives its expectation (the moves through
//! `cycleref expand --format json` with both engines, the error through the
//! library, named here independently of the generator).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use cycleref::CycleError;
use cycleref_spec::reader::{Item, SubprogramError};
use cycleref_spec::{read, ErrorKind, Machine, ProfileName, ProgramError};
use serde_json::Value;

const BIN: &str = env!("CARGO_BIN_EXE_cycleref");
const CORPUS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../vectors");
const REGENERATE: &str = "cargo run -p cycleref-cli -- vectors --count 125 --seed 1 --out vectors";

/// Tags every corpus of 125 cases shows on at least one case with moves.
const FEATURES: &[&str] = &[
    "profile:fanuc",
    "profile:gsk980",
    "profile:gsk988",
    "profile:linuxcnc",
    "increment:is-b",
    "increment:is-c",
    "unit:mm",
    "unit:inch",
    "unit:g20",
    "x:diameter",
    "x:radius",
    "pq:increments",
    "pq:mm",
    "fanuc:bare-increments",
    "fanuc:calculator-input",
    "g76",
    "linuxcnc",
    "g32",
    "thread:external",
    "thread:internal",
    "direction:-z",
    "direction:+z",
    "taper:straight",
    "taper:z-long",
    "taper:x-long",
    "lead:F",
    "lead:I",
    "lead-modal",
    "infeed:D0",
    "infeed:D1",
    "infeed:D2",
    "lead-in",
    "multi-start",
    "run-out:none",
    "run-out:chamfer",
    "run-out:chamfer+k",
    "run-out:chamfer-angle",
    "run-out:amounts",
    "run-out:pull-out",
    "rule:gsk980-note1",
    "rule:gsk980-note2",
    "rule:gsk980-note3",
    "rule:gsk980-note4",
    "rule:jk-one-shot",
    "rule:gsk988-chamfer",
    "rule:gsk988-j-only",
    "rule:gsk988-jk",
    "rule:gsk988-jk-modal",
    "rule:gsk988-k-only",
    "rule:gsk988-k0",
    "rule:gsk988-j0",
    "rule:jk-modal",
    "schedule:one-pass",
    "schedule:min-cut",
    "schedule:exact-k-d",
    "schedule:d-equals-k",
    "finish:none",
    "finish:multiple",
    "block1-modal",
    "params:block1",
    "params:chamfer-5130",
    "p:partial",
    "g32:straight",
    "g32:taper",
    "g32:face",
    "g32:x-long",
    "g32:run-out",
    "g32:pull-out",
    "g32:continuous",
    "g32:q",
    "g32:multi-start",
    "rule:g32-gsk980-jk",
    "rule:g32-gsk980-k-omitted",
    "rule:g32-gsk980-k0",
    "rule:g32-gsk980-j0",
    "rule:g32-gsk988-jk",
    "rule:g32-gsk988-j-only",
    "rule:g32-jk-cancelled",
    "g75",
    "g75:-x",
    "g75:+x",
    "g75:-z",
    "g75:+z",
    "g75:angled",
    "g75:slope",
    "g75:j0",
    "g75:j1",
    "g75:j2",
    "g75:pecking",
    "g75:layers",
    "g75:allowances",
    "g75:tool-width",
    "g75:corners",
    "g75:chamfers",
    "g75:arcs",
    "rule:g75-start-omitted",
    "g92",
    "g92:straight",
    "g92:taper",
    "g92:x-long",
    "g92:long-table",
    "g92:external",
    "g92:internal",
    "g92:run-out",
    "g92:pull-out",
    "g92:chamfer",
    "g92:multi-start",
    "g92:face",
    "rule:g92-face",
    "g92:q",
    "rule:g92-modal",
    "rule:g92-gsk980-jk",
    "rule:g92-gsk980-k0",
    "rule:g92-gsk980-j0",
    "rule:g92-gsk980-no19",
    "rule:g92-gsk988-jk",
    "rule:g92-gsk988-j-only",
    "rule:g92-gsk988-k-only",
    "rule:g92-gsk988-5130",
    "rule:g92-gsk988-high-speed",
    "g78",
    "g78:alternating",
    "g78:equal",
    "rule:g78-p-infeed",
    "rule:g78-gsk988-d",
    "rule:g78-gsk980-m",
    "rule:g78-gsk980-d",
];

/// Error kinds every corpus of 125 cases refuses at least once, with the
/// scenario tag of the refusal.
const REFUSALS: &[(&str, &str)] = &[
    ("missing", "refuse:missing-p"),
    ("missing", "refuse:missing-q"),
    ("missing", "refuse:g32-no-end-point"),
    ("cycle:min_cut_exceeds_height", "refuse:min-cut-above-height"),
    ("cycle:allowance_exceeds_height", "refuse:allowance-above-height"),
    ("cycle:run_out_too_long", "refuse:run-out-too-long"),
    ("cycle:run_out_too_long", "refuse:g32-run-out-too-long"),
    ("no_spindle_speed", "refuse:no-spindle-speed"),
    ("cycle:face_thread", "refuse:g76-face-thread"),
    ("out_of_range", "refuse:out-of-range"),
    ("out_of_range", "refuse:g32-zero-lead"),
    ("decimal_point_not_allowed", "refuse:fanuc-decimal-point"),
    ("partial_p", "refuse:partial-p"),
    ("address_not_in_profile", "refuse:address-not-in-profile"),
    ("cycle:too_many_passes", "refuse:too-many-passes"),
    ("cycle:start_inside_thread", "refuse:start-inside-thread"),
    ("cycle:thread_too_short", "refuse:thread-too-short"),
    ("cycle:lead_in_on_x_long_axis", "refuse:lead-in-on-x-long-axis"),
    ("cycle:no_motion", "refuse:g32-no-motion"),
    ("not_in_increments", "refuse:not-in-increments"),
    ("position_unknown", "refuse:position-unknown"),
    ("cycle:out_of_range", "refuse:pass-coordinate-out-of-range"),
    ("unit_change_after_motion", "refuse:unit-change-after-motion"),
    ("missing", "refuse:g75-missing-word"),
    ("missing", "refuse:g75-lone-block"),
    ("cycle:angle_out_of_range", "refuse:g75-angle-out-of-range"),
    ("cycle:slope_not_below_flank", "refuse:g75-slope-not-below-flank"),
    ("cycle:allowance_exceeds_depth", "refuse:g75-allowance-exceeds-depth"),
    ("cycle:corner_too_large", "refuse:g75-corner-too-large"),
    ("cycle:groove_narrower_than_tool", "refuse:g75-groove-narrower-than-tool"),
    ("cycle:ridges_in_layers", "refuse:g75-ridges-in-layers"),
    ("cycle:word_out_of_range", "refuse:g75-word-out-of-range"),
    ("cycle:no_groove_depth", "refuse:g75-no-depth"),
    ("cycle:too_many_pecks", "refuse:g75-too-many-pecks"),
    ("cycle:taper_beyond_start", "refuse:g92-taper-beyond-start"),
    ("cycle:no_infeed", "refuse:g92-no-infeed"),
    ("cycle:run_out_into_work", "refuse:run-out-into-work"),
    ("out_of_range", "refuse:g78-infeed-out-of-range"),
    ("cycle:run_out_too_long", "refuse:g92-run-out-too-long"),
    ("cycle:face_thread", "refuse:g92-face-thread"),
    ("cycle:no_thread_length", "refuse:g92-no-thread-length"),
    ("cycle:steep_face_thread", "refuse:g92-steep-face-thread"),
    ("out_of_range", "refuse:g92-starts-out-of-range"),
    ("out_of_range", "refuse:g92-p-out-of-range"),
    ("out_of_range", "refuse:g78-gsk980-depth-mode"),
    ("out_of_range", "refuse:g78-gsk988-depth-mode"),
    ("cycle:face_thread", "refuse:g78-face-thread"),
    ("missing", "refuse:g78-missing-word"),
];

/// The stable kind names of `vectors/README.md`, written out again here
/// so that the corpus is checked against the documentation, not against
/// the generator's own function.
///
/// Twin (deliberate): `spec/src/error.rs`, `ErrorKind::name`, and
/// `impl/src/error.rs`, `CycleError::name`.
fn kind(k: &ErrorKind) -> String {
    let cycle = |e: &CycleError| match e {
        CycleError::NoMotion => "no_motion",
        CycleError::OutOfRange { .. } => "out_of_range",
        CycleError::CountOutOfRange { .. } => "count_out_of_range",
        CycleError::ZeroLead => "zero_lead",
        CycleError::LeadOutOfRange => "lead_out_of_range",
        CycleError::MinCutExceedsHeight { .. } => "min_cut_exceeds_height",
        CycleError::AllowanceExceedsHeight { .. } => "allowance_exceeds_height",
        CycleError::FaceThread => "face_thread",
        CycleError::NoInfeed => "no_infeed",
        CycleError::NoThreadLength => "no_thread_length",
        CycleError::SteepFaceThread { .. } => "steep_face_thread",
        CycleError::TaperBeyondStart { .. } => "taper_beyond_start",
        CycleError::RunOutTooLong { .. } => "run_out_too_long",
        CycleError::RunOutIntoWork { .. } => "run_out_into_work",
        CycleError::StartInsideThread => "start_inside_thread",
        CycleError::ThreadTooShort { .. } => "thread_too_short",
        CycleError::LeadInOnXLongAxis => "lead_in_on_x_long_axis",
        CycleError::TooManyPasses { .. } => "too_many_passes",
        CycleError::TooMuchWork { .. } => "too_much_work",
        CycleError::WordOutOfRange { .. } => "word_out_of_range",
        CycleError::AngleOutOfRange { .. } => "angle_out_of_range",
        CycleError::NoGrooveDepth => "no_groove_depth",
        CycleError::SlopeNotBelowFlank { .. } => "slope_not_below_flank",
        CycleError::SlopeNotBelowFlankA { .. } => "slope_not_below_flank_a",
        CycleError::OpeningBelowBottom => "opening_below_bottom",
        CycleError::AllowanceExceedsDepth { .. } => "allowance_exceeds_depth",
        CycleError::CornerTooLarge { .. } => "corner_too_large",
        CycleError::GrooveNarrowerThanTool { .. } => "groove_narrower_than_tool",
        CycleError::RidgesInLayers { .. } => "ridges_in_layers",
        CycleError::TooManyPecks { .. } => "too_many_pecks",
        CycleError::UndecidedRounding => "undecided_rounding",
    };
    match k {
        ErrorKind::Syntax(_) => "syntax".into(),
        ErrorKind::Misplaced { .. } => "misplaced".into(),
        ErrorKind::Encoding { .. } => "encoding".into(),
        ErrorKind::NotInIncrements { .. } => "not_in_increments".into(),
        ErrorKind::DecimalPointNotAllowed { .. } => "decimal_point_not_allowed".into(),
        ErrorKind::Missing { .. } => "missing".into(),
        ErrorKind::OutOfRange { .. } => "out_of_range".into(),
        ErrorKind::AddressNotInProfile { .. } => "address_not_in_profile".into(),
        ErrorKind::Duplicate => "duplicate".into(),
        ErrorKind::PartialP => "partial_p".into(),
        ErrorKind::Unsupported(_) => "unsupported".into(),
        ErrorKind::PositionUnknown => "position_unknown".into(),
        ErrorKind::NoSpindleSpeed => "no_spindle_speed".into(),
        ErrorKind::UnitChangeAfterMotion => "unit_change_after_motion".into(),
        ErrorKind::Parameter(_) => "parameter".into(),
        ErrorKind::Cycle(e) => format!("cycle:{}", cycle(e)),
        ErrorKind::Subprogram(e) => format!(
            "subprogram:{}",
            match e {
                SubprogramError::NotFound { .. } => "not_found",
                SubprogramError::DefinedTwice { .. } => "defined_twice",
                SubprogramError::TooDeep { .. } => "too_deep",
                SubprogramError::ReturnOutsideSubprogram => "return_outside_subprogram",
                SubprogramError::NoReturn { .. } => "no_return",
                SubprogramError::EndInSubprogram { .. } => "end_in_subprogram",
                SubprogramError::MisplacedDefinition { .. } => "misplaced_definition",
                SubprogramError::Unfollowed => "unfollowed",
                SubprogramError::TooManyBlocks { .. } => "too_many_blocks",
                SubprogramError::TextTooLong { .. } => "text_too_long",
                SubprogramError::BadCall(_) => "bad_call",
                SubprogramError::WordBeside { .. } => "word_beside",
            }
        ),
    }
}

/// A fresh scratch directory for this test.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("vectors-tests").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn cycleref(args: &[&str]) -> Output {
    Command::new(BIN).args(args).output().expect("run cycleref")
}

fn generate(count: u32, seed: u64, name: &str) -> PathBuf {
    let dir = scratch(name);
    let out = cycleref(&[
        "vectors",
        "--count",
        &count.to_string(),
        "--seed",
        &seed.to_string(),
        "--out",
        dir.to_str().expect("utf-8 path"),
    ]);
    assert!(out.status.success(), "vectors --seed {seed}: {}", String::from_utf8_lossy(&out.stderr));
    dir
}

/// The JSON files of a corpus directory, by name.
fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut m = BTreeMap::new();
    for entry in std::fs::read_dir(dir).expect("corpus dir") {
        let entry = entry.expect("entry");
        let name = entry.file_name().to_string_lossy().into_owned();
        if name.ends_with(".json") {
            m.insert(name, std::fs::read(entry.path()).expect("read"));
        }
    }
    m
}

fn json(bytes: &[u8]) -> Value {
    serde_json::from_slice(bytes).expect("valid JSON")
}

fn cases(dir: &Path) -> Vec<Value> {
    files(dir).iter().filter(|(n, _)| n.starts_with("case-")).map(|(_, b)| json(b)).collect()
}

#[test]
fn checked_in_corpus_is_what_the_generator_writes() {
    let fresh = files(&generate(125, 1, "fresh"));
    let stored = files(Path::new(CORPUS));
    assert_eq!(
        fresh.keys().collect::<Vec<_>>(),
        stored.keys().collect::<Vec<_>>(),
        "vectors/ does not hold the files the generator writes; regenerate with `{REGENERATE}`"
    );
    for (name, bytes) in &fresh {
        assert!(stored[name] == *bytes, "vectors/{name} is stale; regenerate with `{REGENERATE}`");
    }
}

#[test]
fn same_seed_same_bytes_and_a_larger_count_extends_a_smaller_one() {
    let a = files(&generate(12, 7, "small"));
    let b = files(&generate(20, 7, "large"));
    for (name, bytes) in a.iter().filter(|(n, _)| n.starts_with("case-")) {
        assert!(b[name] == *bytes, "{name} changed with the count");
    }
    assert_eq!(b.keys().filter(|n| n.starts_with("case-")).count(), 20);
    let c = files(&generate(12, 8, "other-seed"));
    let differ = a.iter().filter(|(n, bytes)| n.starts_with("case-") && c[*n] != **bytes).count();
    assert!(differ >= 10, "another seed should give other cases ({differ} of 12 differ)");
    // A smaller run into a directory of a larger one leaves no stale case.
    let dir = generate(20, 7, "shrink");
    let out = cycleref(&["vectors", "--count", "5", "--seed", "7", "--out", dir.to_str().unwrap()]);
    assert!(out.status.success());
    assert_eq!(files(&dir).keys().filter(|n| n.starts_with("case-")).count(), 5);
}

/// Every feature tag on a case with moves, every listed refusal present.
fn assert_covered(dir: &Path) {
    let index = json(&std::fs::read(dir.join("index.json")).expect("index.json"));
    let mut valid_tags = BTreeSet::new();
    let mut refusals = BTreeSet::new();
    let listed = index["cases"].as_array().expect("cases");
    let all = cases(dir);
    assert_eq!(listed.len(), all.len(), "index.json lists every case file");
    for (entry, case) in listed.iter().zip(&all) {
        assert_eq!(entry["id"], case["id"]);
        assert_eq!(entry["tags"], case["tags"]);
        assert_eq!(entry["description"], case["description"]);
        let tags: Vec<&str> = case["tags"].as_array().unwrap().iter().map(|t| t.as_str().unwrap()).collect();
        if let Some(e) = case["expect"].get("error") {
            assert_eq!(entry["expect"], "error");
            assert_eq!(entry["kind"], e["kind"]);
            for t in &tags {
                refusals.insert((e["kind"].as_str().unwrap().to_string(), (*t).to_string()));
            }
        } else {
            assert_eq!(entry["expect"], "moves");
            valid_tags.extend(tags.iter().map(|t| (*t).to_string()));
        }
    }
    for f in FEATURES {
        assert!(valid_tags.contains(*f), "{}: no case with moves shows `{f}`", dir.display());
    }
    for (k, t) in REFUSALS {
        assert!(
            refusals.contains(&((*k).to_string(), (*t).to_string())),
            "{}: no case is refused with `{k}` for `{t}`",
            dir.display()
        );
    }
    let valid = listed.iter().filter(|c| c["expect"] == "moves").count();
    assert!(valid * 2 > listed.len(), "most cases must be valid programs ({valid} of {})", listed.len());
}

#[test]
fn the_corpus_covers_every_feature_and_error_kind() {
    assert_covered(Path::new(CORPUS));
}

#[test]
fn other_seeds_cover_everything_too() {
    // Each template fixes what it covers; the seed only varies the rest.
    for seed in [2, 3] {
        assert_covered(&generate(125, seed, &format!("seed-{seed}")));
    }
}

/// A parameter file from the case's `machine` object (the other form the
/// schema offers).
fn toml_from_json(profile: &str, m: &Value) -> String {
    let mut t = format!("profile = \"{profile}\"\n");
    for key in ["increment", "unit", "x"] {
        t.push_str(&format!("{key} = {}\n", m[key]));
    }
    t.push_str(&format!(
        "calculator_input = {}\npass_limit = {}\n[parameters]\n",
        m["calculator_input"], m["pass_limit"]
    ));
    for (k, v) in m["parameters"].as_object().expect("parameters") {
        t.push_str(&format!("\"{k}\" = {v}\n"));
    }
    t.push_str("[readings]\n");
    for (k, v) in m["readings"].as_object().expect("readings") {
        t.push_str(&format!("\"{k}\" = {v}\n"));
    }
    t
}

fn machine(case: &Value) -> Machine {
    let profile = case["profile"].as_str().unwrap();
    let name: ProfileName = profile.parse().unwrap();
    let mut from_toml = Machine::new(name);
    from_toml.apply_toml(case["machine_toml"].as_str().unwrap()).expect("machine_toml is a parameter file");
    let mut from_json = Machine::new(name);
    from_json.apply_toml(&toml_from_json(profile, &case["machine"])).expect("machine object");
    assert_eq!(from_toml, from_json, "{}: machine and machine_toml disagree", case["id"]);
    from_toml
}

/// The first error of a program: the reader's, or the first cycle alarm.
fn first_error(text: &str, m: &Machine) -> Option<ProgramError> {
    let program = match read(text, m) {
        Ok(p) => p,
        Err(e) => return Some(e),
    };
    for item in &program.items {
        let (line, engine, reference) = match item {
            Item::G76(c) => (
                c.block.line,
                cycleref::expand_g76(&c.cycle).map(Iterator::count),
                cycleref_spec::g76::expand(&c.cycle).map(|v| v.len()),
            ),
            Item::G32(c) => (
                c.block.line,
                cycleref::expand_g32(&c.g32).map(Iterator::count),
                cycleref_spec::g32::expand(&c.g32).map(|v| v.len()),
            ),
            Item::G75(c) => (
                c.block.line,
                cycleref::expand_g75(&c.cycle).map(Iterator::count),
                cycleref_spec::g75::expand(&c.cycle).map(|v| v.len()),
            ),
            Item::G92(c) => (
                c.block.line,
                cycleref::expand_g92(&c.cycle).map(Iterator::count),
                cycleref_spec::g92::expand(&c.cycle).map(|v| v.len()),
            ),
            Item::LinuxCncG76(c) => (
                c.block.line,
                cycleref::expand_linuxcnc(&c.cycle).map(Iterator::count),
                cycleref_spec::linuxcnc::expand(&c.cycle).map(|v| v.len()),
            ),
            Item::Source(_) | Item::Move(_) | Item::G76Params(_) | Item::G75Params(_) => continue,
        };
        assert_eq!(engine, reference, "line {line}: the engines differ");
        if let Err(e) = engine {
            return Some(ProgramError { line, word: None, kind: ErrorKind::Cycle(e) });
        }
    }
    None
}

#[test]
fn every_case_replays() {
    let dir = scratch("replay");
    let all = cases(Path::new(CORPUS));
    assert_eq!(all.len(), 125);
    for case in &all {
        let id = case["id"].as_str().unwrap();
        assert_eq!(case["schema"], "cycleref-vector/1", "{id}");
        for key in [
            "seed",
            "index",
            "description",
            "tags",
            "profile",
            "machine",
            "machine_toml",
            "program",
            "expect",
        ] {
            assert!(case.get(key).is_some(), "{id}: no `{key}`");
        }
        let m = machine(case);
        let program = case["program"].as_str().unwrap();
        let params = dir.join(format!("{id}.toml"));
        let nc = dir.join(format!("{id}.nc"));
        std::fs::write(&params, case["machine_toml"].as_str().unwrap()).unwrap();
        std::fs::write(&nc, program).unwrap();
        let profile = case["profile"].as_str().unwrap();
        let run = |engine: &str| {
            cycleref(&[
                "expand",
                "--format",
                "json",
                "--engine",
                engine,
                "--profile",
                profile,
                "--params",
                params.to_str().unwrap(),
                nc.to_str().unwrap(),
            ])
        };
        let expect = &case["expect"];
        match expect.get("error") {
            None => {
                assert!(first_error(program, &m).is_none(), "{id}: the program is refused");
                for engine in ["impl", "spec"] {
                    let out = run(engine);
                    assert!(out.status.success(), "{id}: {}", String::from_utf8_lossy(&out.stderr));
                    let got = json(&out.stdout);
                    assert_eq!(got["units"], expect["units"], "{id} ({engine}): units");
                    assert_eq!(got["cycles"], expect["moves"], "{id} ({engine}): moves");
                }
                assert!(!expect["moves"].as_array().unwrap().is_empty(), "{id}: no cycle");
            }
            Some(want) => {
                let e = first_error(program, &m).unwrap_or_else(|| panic!("{id}: the program is accepted"));
                assert_eq!(kind(&e.kind), want["kind"].as_str().unwrap(), "{id}: kind");
                assert_eq!(
                    Some(e.line),
                    want["line"].as_u64().and_then(|l| usize::try_from(l).ok()),
                    "{id}: line"
                );
                assert_eq!(e.word.as_deref(), want["word"].as_str(), "{id}: word");
                assert_eq!(e.to_string(), want["message"].as_str().unwrap(), "{id}: message");
                let out = run("impl");
                assert_eq!(out.status.code(), Some(2), "{id}: exit status");
                assert!(out.stdout.is_empty(), "{id}: output on a refused program");
                let text = e.kind.to_string();
                let stderr = String::from_utf8_lossy(&out.stderr);
                assert!(stderr.contains(&text), "{id}: stderr lacks `{text}`");
                // The command prints the vector's stable kind first, so a
                // script matches the two.
                let head = format!("cycleref: error[{}]: ", want["kind"].as_str().unwrap());
                assert!(stderr.starts_with(&head), "{id}: stderr does not start with `{head}`: {stderr}");
            }
        }
    }
}
