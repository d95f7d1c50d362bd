//! A stable-Rust property test of `check`'s trace readers and comparison
//! (the nightly fuzz target is `fuzz/fuzz_targets/check_trace.rs`): any
//! bytes, and our own expansion with words spliced in, cut or changed, as
//! an `.nc` and as a `.csv` trace: `check` exits 0, 1 or 2, never panics
//! (101), and every error names the trace's line (or says the trace has no
//! moves). About 600 runs of the command, a few seconds.

use std::path::PathBuf;
use std::process::Command;

use proptest::prelude::*;

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("cycleref-check-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Our expansion of the square groove (G00, G01, G02 with I/K).
fn square() -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_cycleref"))
        .args(["expand", "--profile", "gsk980", &example("gsk980-g75-square.nc")])
        .output()
        .expect("runs");
    String::from_utf8(out.stdout).expect("utf-8")
}

fn run(bytes: &[u8]) {
    let d = dir();
    for name in ["t.nc", "t.csv"] {
        let p = d.join(name);
        std::fs::write(&p, bytes).expect("write");
        let out = Command::new(env!("CARGO_BIN_EXE_cycleref"))
            .args([
                "check",
                "--profile",
                "gsk980",
                "--trace",
                p.to_str().expect("utf-8"),
                &example("gsk980-g75-square.nc"),
            ])
            .output()
            .expect("runs");
        let err = String::from_utf8_lossy(&out.stderr);
        let code = out.status.code();
        assert!(
            matches!(code, Some(0..=2)),
            "{name}: exit {code:?}\n{err}\n{:?}",
            String::from_utf8_lossy(bytes)
        );
        if code == Some(2) {
            assert!(
                err.contains("line ") || err.contains("the trace has no moves"),
                "{name}: an error without a position: {err}"
            );
        }
    }
}

/// Words and pieces of NC blocks and CSV rows.
const PIECES: &[&str] = &[
    "G00",
    "G01",
    "G02",
    "G03",
    "G32",
    "G04",
    "G50",
    "G20",
    "G21",
    "G76",
    "X",
    "Z",
    "U",
    "W",
    "I",
    "K",
    "R",
    "F",
    "Q",
    "P",
    "N10",
    "O1",
    "M30",
    "M98",
    "(",
    ")",
    ";",
    ",",
    "\n",
    " ",
    "-",
    ".",
    "0",
    "9",
    "24.800",
    "-0.400",
    "99999999999999999999",
    "0.0005",
    "arc-cw",
    "arc-ccw",
    "arc",
    "rapid",
    "feed",
    "thread",
    "motion,x,z,i,k\n",
    "motion,x,z,cx,cz,lead,q\n",
    "\u{feff}",
    "\u{ff08}",
    "%",
];

fn mutated() -> impl Strategy<Value = Vec<u8>> {
    let base = square();
    (0..base.len(), 0..base.len(), prop::collection::vec(prop::sample::select(PIECES), 0..6)).prop_map(
        move |(a, b, pieces)| {
            let (a, b) = (a.min(b), a.max(b).min(a + 40));
            let mut s = base.as_bytes()[..a].to_vec();
            for p in pieces {
                s.extend_from_slice(p.as_bytes());
            }
            s.extend_from_slice(&base.as_bytes()[b..]);
            s
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 150, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn any_bytes(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        run(&bytes);
    }

    #[test]
    fn our_expansion_mutated(bytes in mutated()) {
        run(&bytes);
    }
}
