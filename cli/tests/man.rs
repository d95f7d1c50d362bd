//! The manual pages in `cli/man/` are what `cycleref man` prints today, and
//! `cycleref completions` writes a script for every shell clap knows that
//! names every subcommand. A change to an option's help text fails here
//! until the pages are regenerated:
//!
//! ```text
//! cargo build -p cycleref-cli
//! for s in "" expand passes check vectors conform plot completions man readings; do
//!   target/debug/cycleref man $s > cli/man/cycleref${s:+-$s}.1
//! done
//! ```

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_cycleref");
const SUBCOMMANDS: [&str; 9] =
    ["expand", "passes", "check", "vectors", "conform", "plot", "completions", "man", "readings"];

fn stdout(args: &[&str]) -> String {
    let out = Command::new(BIN).args(args).output().expect("runs");
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

#[test]
fn the_checked_in_manual_pages_are_current() {
    let dir = format!("{}/man", env!("CARGO_MANIFEST_DIR"));
    let pages = std::iter::once(None).chain(SUBCOMMANDS.iter().map(|&s| Some(s)));
    for sub in pages {
        let (file, args) = match sub {
            None => ("cycleref.1".to_string(), vec!["man"]),
            Some(s) => (format!("cycleref-{s}.1"), vec!["man", s]),
        };
        let checked_in = std::fs::read_to_string(format!("{dir}/{file}")).unwrap_or_default();
        assert_eq!(
            stdout(&args),
            checked_in,
            "cli/man/{file} is stale: regenerate it (see this test's docs)"
        );
    }
    // The main page lists every subcommand's page.
    let main = stdout(&["man"]);
    for s in SUBCOMMANDS {
        assert!(main.contains(&format!("cycleref\\-{s}(1)")), "{s} missing from the main page");
    }
}

#[test]
fn an_unknown_subcommand_has_no_page() {
    let out = Command::new(BIN).args(["man", "expnad"]).output().expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no subcommand `expnad`"));
    assert!(out.stdout.is_empty());
}

#[test]
fn completions_name_every_subcommand() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let script = stdout(&["completions", shell]);
        for s in SUBCOMMANDS {
            assert!(script.contains(s), "{shell}: {s} missing");
        }
        assert!(script.contains("trace") && script.contains("profile"), "{shell}: options missing");
    }
}
