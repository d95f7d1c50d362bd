//! The files generated from `cycleref_proofs::catalogue` match it:
//! `proofs/src/kani_proofs.rs`, `.github/workflows/kani.yml` and the
//! harness table of `proofs/README.md`. `CYCLEREF_BLESS=1` rewrites them.

use std::path::{Path, PathBuf};

use cycleref_proofs::catalogue::{self, Tier};

fn top() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn bless() -> bool {
    std::env::var_os("CYCLEREF_BLESS").is_some()
}

/// `path` must hold `want`, or, between the markers, the part of it they
/// enclose.
fn generated(path: &str, want: &str, markers: Option<(&str, &str)>) {
    let file = top().join(path);
    let text = std::fs::read_to_string(&file).unwrap_or_default();
    let updated = match markers {
        None => want.to_owned(),
        Some((begin, end)) => {
            let (Some(b), Some(e)) = (text.find(begin), text.find(end)) else {
                panic!("{path}: the markers {begin:?} and {end:?}");
            };
            format!("{}{begin}\n{want}{}", &text[..b], &text[e..])
        }
    };
    if bless() {
        std::fs::write(&file, &updated).expect("write");
    } else {
        assert!(
            text == updated,
            "{path} differs from the catalogue: run CYCLEREF_BLESS=1 cargo test -p cycleref-proofs --test catalogue"
        );
    }
}

#[test]
fn kani_proofs_rs_is_generated_from_the_catalogue() {
    generated("proofs/src/kani_proofs.rs", &catalogue::kani_source(), None);
}

#[test]
fn the_kani_workflow_is_generated_from_the_catalogue() {
    generated(".github/workflows/kani.yml", &catalogue::workflow(), None);
}

#[test]
fn the_readme_table_is_generated_from_the_catalogue() {
    generated(
        "proofs/README.md",
        &catalogue::readme_table(),
        Some(("<!-- BEGIN harness table: generated from src/catalogue.rs -->", "<!-- END harness table -->")),
    );
}

#[test]
fn every_harness_has_one_name_and_one_body() {
    let all = catalogue::harnesses();
    let mut names: Vec<_> = all.iter().map(|h| h.name.as_str()).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), all.len(), "harness names are unique");
    // Every body function written out in bodies.rs is some harness's (the
    // per-infeed ones are generated there by a macro), and each harness
    // calls the body of its own name; that every such body exists is what
    // `.ci/kani-typecheck` compiles.
    for line in include_str!("../src/bodies.rs").lines() {
        if let Some(rest) = line.strip_prefix("pub fn ") {
            let name = rest.split('(').next().unwrap_or_default();
            assert!(names.contains(&name), "bodies::{name} is no harness's body");
        }
    }
    for h in &all {
        let call = format!("fn {}() {{\n    crate::bodies::{}();\n}}", h.name, h.name);
        assert!(catalogue::kani_source().contains(&call), "{}: calls its own body", h.name);
    }
}

#[test]
fn no_required_harness_is_one_its_documentation_expects_not_to_finish() {
    // The harnesses the issue named as not expected to finish, and the ones
    // collecting moves into a Vec, are scheduled, behind the feature.
    for name in [
        "groove_no_panic",
        "lcnc_depth_monotonicity",
        "lcnc_termination",
        "lcnc_spring_passes",
        "lcnc_pass_moves",
    ] {
        assert_eq!(catalogue::harness(name).tier, Tier::Scheduled, "{name}");
    }
    let source = catalogue::kani_source();
    for h in catalogue::harnesses().iter().filter(|h| h.tier == Tier::Scheduled) {
        let gated = "#[cfg(feature = \"kani-scheduled\")]\n#[kani::proof";
        let at = source.find(&format!("fn {}()", h.name)).expect("generated");
        let before = &source[..at];
        let doc_end = before.rfind("///").expect("a doc comment");
        assert!(before[doc_end..].contains(gated), "{} is behind the feature", h.name);
    }
}
