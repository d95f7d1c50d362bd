//! The `linuxcnc` profile through the `cycleref` command, end to end,
//! checked by LinuxCNC itself: the program `cycleref expand --profile
//! linuxcnc` writes (G0 and G33 blocks) must make `rs274` print the same
//! canonical motions as the original program with its G76 (same order,
//! the same rapid or synchronised feed, X and Z within one printed unit,
//! the same pitch). `rs274` missing fails with the command that installs
//! it (`.ci/run` does).

mod common;

use std::process::{Command, Stdio};

use common::run;
use cycleref_spec::rs274::{self, CanonMove};
use rust_decimal::Decimal;

fn example() -> String {
    format!("{}/../examples/linuxcnc-m20-taper.ngc", env!("CARGO_MANIFEST_DIR"))
}

fn stdout(args: &[&str]) -> String {
    let out = run(args, None);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

fn rs274_motions(file: &std::path::Path) -> Vec<CanonMove> {
    let out = Command::new("rs274").arg("-g").arg(file).stdin(Stdio::null()).output().unwrap_or_else(|e| {
        panic!(
            "cannot run `rs274` ({e}): install LinuxCNC's interpreter with `apt-get update && \
                 DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends linuxcnc-uspace`"
        )
    });
    rs274::read(&String::from_utf8_lossy(&out.stdout)).expect("canonical output")
}

#[test]
fn expanded_program_cuts_what_linuxcnc_cuts() {
    let original = rs274_motions(std::path::Path::new(&example()));
    let expanded = stdout(&["expand", "--profile", "linuxcnc", &example()]);
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let file = dir.join("expanded.ngc");
    std::fs::write(&file, &expanded).expect("write");
    let again = rs274_motions(&file);
    // 15 rough passes (J and K are diameters here, the law has the same
    // ratio: 0.3·n^(2/3) < 1.84 ⇔ n < (1.84/0.3)^1.5 = 15.19) and 2 at full
    // depth, of 6 motions each (back, in, angled in, over, angled out,
    // out), the final rapid, and the program's two G0: 105 motions.
    assert_eq!(original.len(), 105, "{original:?}");
    assert_eq!(again.len(), original.len());
    let half = Decimal::new(1, 4);
    for (i, (a, b)) in original.iter().zip(&again).enumerate() {
        assert_eq!(a.rapid, b.rapid, "motion {i}");
        assert!((a.x - b.x).abs() <= half && (a.z - b.z).abs() <= half, "motion {i}: {a:?} against {b:?}");
        match (a.pitch, b.pitch) {
            (None, None) => {}
            (Some(p), Some(q)) => assert!((p - q).abs() <= Decimal::new(1, 6), "motion {i}: {p} against {q}"),
            _ => panic!("motion {i}: {a:?} against {b:?}"),
        }
    }
}

#[test]
fn nc_json_and_passes() {
    let nc = stdout(&["expand", "--profile", "linuxcnc", &example()]);
    // Pass 1 by hand (G7: X in diameter). δ = J = 0.3 (diameter), K = 1.84,
    // |I| = 2, X₀ = 22: back X = 22 + (1.84 − 0.3) = 23.54; the cut X =
    // 22 − (2 + 0.3) = 19.7; the entry taper starts 1.84 above the cut,
    // at 21.54. ζ = (0.3/2)·tan 29.5° = 0.15 × 0.565773… = 0.084866, so the
    // pass starts at Z 2 − 0.0849 = 1.9151 and the angled entry ends E = 1
    // further, at 0.9151. The taper pitch 1.5·√(1² + 0.92²)/1 = 2.038235.
    assert!(nc.contains(
        "(G76 line 6: LinuxCNC threading cycle)\n(pass 1)\nG00 X23.5400 Z1.9151\nG33 X21.5400 Z1.9151 \
         K2.038235\nG33 X19.7000 Z0.9151 K2.038235\n"
    ));
    // The full-depth pass cuts at 22 − (2 + 1.84) = 18.16, runs to E = 1
    // before Z-20 and climbs K = 1.84 back to 20.0 at Z-20 exactly; its
    // "out" is at X₀ + (K − K) = 22; the cycle ends at X22 Z-20.
    assert!(nc
        .contains("G33 X18.1600 Z-19.0000 K1.5\nG33 X20.0000 Z-20.0000 K2.038235\nG00 X22.0000 Z-20.0000\n"));
    let json = stdout(&["expand", "--format", "json", "--profile", "linuxcnc", &example()]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("json");
    assert_eq!(v["cycles"][0]["cycle"], "G76");
    // 17 passes of 6 moves and the final rapid.
    assert_eq!(v["cycles"][0]["moves"].as_array().map(Vec::len), Some(17 * 6 + 1));
    let table = stdout(&["passes", "--profile", "linuxcnc", &example()]);
    // 15 rough passes, then 2 at full depth (H1).
    let rows = table.lines().filter(|l| l.contains(" rough ") || l.contains(" full ")).count();
    assert_eq!(rows, 15 + 2, "{table}");
}

#[test]
fn what_is_not_there_yet_says_so() {
    for cmd in ["plot", "check"] {
        let mut args = vec![cmd, "--profile", "linuxcnc"];
        let e = example();
        args.push(&e);
        if cmd == "check" {
            args.extend(["--trace", &e]);
        } else {
            args.extend(["-o", "/dev/null"]);
        }
        let out = run(&args, None);
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("LinuxCNC's G76") && err.contains("issue 15"), "{cmd}: {err}");
    }
}
