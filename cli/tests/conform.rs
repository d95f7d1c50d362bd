//! `cycleref conform` (issue 35): a vendor's outcomes run against a corpus
//! of vectors. The "vendor" here is `cycleref expand` itself (a second,
//! independent run of the command per case, through its files), whose
//! outcomes are then changed by hand in known ways: every count and
//! verdict below follows from those changes, not from the code under test.
//!
//! The corpus is `cycleref vectors --count 10 --seed 1` (the first ten
//! cases of the checked-in corpus): of every five cases the 2nd and the
//! 4th must be refused, so cases 2, 4, 7 and 9 are refusals and 1, 3, 5,
//! 6, 8 and 10 valid programs.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use common::{conform, run, BIN};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cycleref-conform-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn corpus(dir: &Path) -> PathBuf {
    let out = dir.join("corpus");
    let o = run(&["vectors", "--count", "10", "--seed", "1", "--out", out.to_str().expect("utf-8")], None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    out
}

/// Each case's outcome from `cycleref expand` run on its program and
/// machine: `case-NNNN.nc`, or `case-NNNN.error` holding its message.
fn outcomes(corpus: &Path, dir: &Path) -> PathBuf {
    let traces = dir.join("traces");
    std::fs::create_dir_all(&traces).expect("traces dir");
    for i in 1..=10 {
        let id = format!("case-{i:04}");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(corpus.join(format!("{id}.json"))).expect("case"))
                .expect("json");
        let program = dir.join(format!("{id}.nc"));
        let params = dir.join(format!("{id}.toml"));
        std::fs::write(&program, v["program"].as_str().expect("program")).expect("write");
        std::fs::write(&params, v["machine_toml"].as_str().expect("machine")).expect("write");
        let o = run(
            &["expand", "--params", params.to_str().expect("utf-8"), program.to_str().expect("utf-8")],
            None,
        );
        if o.status.success() {
            std::fs::write(traces.join(format!("{id}.nc")), o.stdout).expect("write");
        } else {
            std::fs::write(traces.join(format!("{id}.error")), o.stderr).expect("write");
        }
    }
    traces
}

fn testcases(junit: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(junit).expect("junit");
    text.split("<testcase classname=\"cycleref.conform\" name=\"")
        .skip(1)
        .map(|t| t.split('"').next().unwrap_or_default().to_owned())
        .collect()
}

#[test]
fn the_expansion_itself_passes_and_each_kind_of_fault_is_named() {
    let dir = scratch("dir");
    let corpus = corpus(&dir);
    let traces = outcomes(&corpus, &dir);
    let refused: Vec<bool> = (1..=10).map(|i| traces.join(format!("case-{i:04}.error")).exists()).collect();
    assert_eq!(refused, [false, true, false, true, false, false, true, false, true, false]);
    let (c, t) = (corpus.to_str().expect("utf-8"), traces.to_str().expect("utf-8"));
    let (code, out, err) = conform(&[c, "--traces", t]);
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(
        out,
        "conform: 10 cases: 10 passed, 0 failed, 0 refusals expected but not made, 0 refusals not expected, 0 errors\n"
    );

    // Four faults: case 1's first rapid X one increment off (a moved
    // point); case 2 (a refusal) answered with a trace; case 3 (valid)
    // refused; case 5 given no outcome.
    let one = traces.join("case-0001.nc");
    let text = std::fs::read_to_string(&one).expect("trace");
    let first_rapid = text.lines().find(|l| l.starts_with("G00 X")).expect("a rapid").to_owned();
    let x: &str = first_rapid.split_whitespace().nth(1).expect("X word");
    let digits = &x[1..];
    let last = digits.chars().last().expect("a digit").to_digit(10).expect("digit");
    let moved = format!("X{}{}", &digits[..digits.len() - 1], (last + 1) % 10);
    assert!(last != 9, "the test moves the last digit up: {x}");
    std::fs::write(&one, text.replacen(&first_rapid, &first_rapid.replacen(x, &moved, 1), 1)).expect("write");
    std::fs::remove_file(traces.join("case-0002.error")).expect("rm");
    std::fs::write(traces.join("case-0002.nc"), "G00 X10 Z10\n").expect("write");
    std::fs::rename(traces.join("case-0003.nc"), traces.join("case-0003.error")).expect("mv");
    std::fs::remove_file(traces.join("case-0005.nc")).expect("rm");
    let junit = dir.join("report.xml");
    let (code, out, err) =
        conform(&[c, "--traces", t, "--jobs", "2", "--junit", junit.to_str().expect("utf-8")]);
    assert_eq!(code, 1, "{out}{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 5, "{out}");
    assert!(lines[0].starts_with("FAIL case-0001: DIFFER: 1 divergence"), "{out}");
    assert!(lines[0].contains("difference: X 1 Z 0 increments"), "{out}");
    assert!(lines[1].starts_with("FAIL case-0002: the program must be refused ("), "{out}");
    assert!(lines[2].starts_with("FAIL case-0003: a valid program was refused: "), "{out}");
    assert!(lines[3].starts_with("ERROR case-0005: no outcome: none of case-0005.nc"), "{out}");
    assert_eq!(
        lines[4],
        "conform: 10 cases: 6 passed, 1 failed, 1 refusal expected but not made, 1 refusal not expected, 1 error"
    );
    let xml = std::fs::read_to_string(&junit).expect("junit");
    assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"), "{xml}");
    assert!(
        xml.contains("<testsuites name=\"cycleref conform\" tests=\"10\" failures=\"3\" errors=\"1\">"),
        "{xml}"
    );
    assert_eq!(testcases(&junit), (1..=10).map(|i| format!("case-{i:04}")).collect::<Vec<_>>());
    for kind in ["differ", "refusal-missing", "refusal-unexpected"] {
        assert_eq!(xml.matches(&format!("<failure type=\"{kind}\"")).count(), 1, "{kind}: {xml}");
    }
    assert_eq!(xml.matches("<error type=\"error\"").count(), 1, "{xml}");
    assert!(xml.trim_end().ends_with("</testsuites>"), "{xml}");
    // Nothing is left beside the report.
    let left: Vec<_> =
        std::fs::read_dir(&dir).expect("dir").filter_map(Result::ok).map(|e| e.file_name()).collect();
    assert!(!left.iter().any(|n| n.to_string_lossy().contains("cycleref-")), "{left:?}");

    // The verdict survives a closed output pipe: status 1, not 0.
    let mut child = Command::new(BIN)
        .args(["conform", c, "--traces", t])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("runs");
    drop(child.stdout.take());
    assert_eq!(child.wait().expect("waits").code(), Some(1));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_command_per_case_in_shards_that_cover_the_corpus_once() {
    let dir = scratch("run");
    let corpus = corpus(&dir);
    let c = corpus.to_str().expect("utf-8");
    let template = format!("'{BIN}' expand --params {{params}} {{program}} > {{trace}}");
    let mut seen = Vec::new();
    for shard in ["1/3", "2/3", "3/3"] {
        let junit = dir.join(format!("shard-{}.xml", &shard[..1]));
        let (code, out, err) =
            conform(&[c, "--run", &template, "--shard", shard, "--junit", junit.to_str().expect("utf-8")]);
        assert_eq!(code, 0, "{shard}: {out}{err}");
        let cases = testcases(&junit);
        // Shard I of 3 holds the cases whose index is I modulo 3.
        let first: usize = shard[..1].parse().expect("digit");
        let expected: Vec<String> = (first..=10).step_by(3).map(|i| format!("case-{i:04}")).collect();
        assert_eq!(cases, expected, "{shard}");
        assert!(
            out.starts_with(&format!(
                "conform: {} cases (shard {shard}): {} passed",
                cases.len(),
                cases.len()
            )),
            "{out}"
        );
        seen.extend(cases);
    }
    seen.sort();
    assert_eq!(seen, (1..=10).map(|i| format!("case-{i:04}")).collect::<Vec<_>>());
    // A command whose trace is wrong fails every valid case; one that
    // refuses everything fails them too, and passes the refusals.
    let (code, out, _) = conform(&[c, "--run", "echo 'G00 X1 Z1' > {trace}"]);
    assert_eq!(code, 1);
    assert!(out.ends_with("conform: 10 cases: 0 passed, 6 failed, 4 refusals expected but not made, 0 refusals not expected, 0 errors\n"), "{out}");
    let (code, out, _) = conform(&[c, "--run", "echo no >&2; exit 3"]);
    assert_eq!(code, 1);
    assert!(out.contains("FAIL case-0001: a valid program was refused: (status 3) no"), "{out}");
    assert!(out.ends_with("conform: 10 cases: 4 passed, 0 failed, 0 refusals expected but not made, 6 refusals not expected, 0 errors\n"), "{out}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_arguments_are_errors() {
    let dir = scratch("args");
    for shard in ["0/2", "3/2", "2", "a/b"] {
        let (code, _, err) = conform(&[dir.to_str().expect("utf-8"), "--traces", ".", "--shard", shard]);
        assert_eq!(code, 2, "{shard}: {err}");
        assert!(err.contains("--shard"), "{err}");
    }
    // An empty directory is no corpus.
    let (code, _, err) = conform(&[dir.to_str().expect("utf-8"), "--traces", "."]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no case-NNNN.json files"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
