//! `.ci/kani-covers`, the workflow's stand-in for `--fail-uncoverable`, on
//! logs in the format of `cargo kani --output-format terse` (written by
//! hand in `proofs/tests/kani-logs/`; no Kani run is recorded here): it
//! passes when every harness satisfies every cover, and fails on an
//! unreachable cover and on a harness without a cover summary.

use std::path::Path;
use std::process::Command;

fn covers(log: &str) -> (bool, String) {
    let top = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = Command::new("bash")
        .arg(top.join(".ci/kani-covers"))
        .arg(top.join("proofs/tests/kani-logs").join(log))
        .output()
        .expect("bash runs .ci/kani-covers");
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into_owned())
}

#[test]
fn every_cover_satisfied_passes() {
    assert_eq!(covers("pass.log"), (true, "2 harnesses, every cover satisfied\n".to_owned()));
}

#[test]
fn an_unreachable_cover_fails() {
    let (ok, out) = covers("unreachable.log");
    assert!(!ok);
    assert!(out.starts_with("kani_proofs::g32_run_out: only 3 of 4 covers satisfied"), "{out}");
}

#[test]
fn a_harness_without_a_cover_summary_fails() {
    assert_eq!(covers("no-summary.log"), (false, "kani_proofs::isqrt_rounds: no cover summary\n".to_owned()));
}
