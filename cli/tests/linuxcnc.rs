//! The `linuxcnc` profile through the `cycleref` command, end to end,
//! checked by LinuxCNC itself: the program `cycleref expand --profile
//! linuxcnc` writes (G0 and G33 blocks) must make `rs274` print the same
//! canonical motions as the original program with its G76 (same order,
//! the same rapid or synchronised feed, X and Z within one printed unit,
//! the same pitch). `rs274` missing fails with the command that installs
//! it (`.ci/run` does). `check` on this profile reads our expansion, LinuxCNC's
//! canonical output (`.canon`) and a grblHAL-style trace (docs/peers).

mod common;

use std::process::{Command, Stdio};

// The skip rule of the rs274 comparisons, one copy for both crates' tests
// (this file is not packaged: it reads ../examples).
#[path = "../../spec/tests/support/rs274_installed.rs"]
mod rs274_installed;
use rs274_installed::rs274_installed;

use common::{run, stdout};
use cycleref_spec::rs274::{self, CanonMove};
use rust_decimal::Decimal;

fn example() -> String {
    format!("{}/../examples/linuxcnc-m20-taper.ngc", env!("CARGO_MANIFEST_DIR"))
}

/// What `rs274 -g file` prints. Two interpreters at once spoil each
/// other's start (seen as an empty output): the calls take turns, each in
/// a working directory of its own.
fn rs274_output(file: &std::path::Path) -> Vec<u8> {
    static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());
    static CALLS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cycleref-rs274-cli-{}-{call}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    // Across processes two interpreters can still spoil each other's
    // start (two test runs at once): a run that printed nothing is run
    // again, a few times.
    let mut out = Vec::new();
    for attempt in 0..5 {
        if attempt > 0 {
            std::thread::sleep(std::time::Duration::from_millis(200));
        }
        out = Command::new("rs274")
            .arg("-g")
            .arg(file)
            .current_dir(&dir)
            .stdin(Stdio::null())
            .output()
            .unwrap_or_else(|e| {
                panic!(
                    "cannot run `rs274` ({e}): install LinuxCNC's interpreter with `apt-get update && \
                     DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends linuxcnc-uspace`"
                )
            })
            .stdout;
        if !out.is_empty() {
            break;
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    out
}

fn rs274_motions(file: &std::path::Path) -> Vec<CanonMove> {
    rs274::read(&String::from_utf8_lossy(&rs274_output(file))).expect("canonical output")
}

#[test]
fn expanded_program_cuts_what_linuxcnc_cuts() {
    if !rs274_installed() {
        return;
    }
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
fn check_reads_its_own_expansion_and_linuxcnc_canonical_output() {
    if !rs274_installed() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    // Our own expansion (G0/G33 blocks) as a trace: the same toolpath.
    let nc = dir.join("expanded.ngc");
    std::fs::write(&nc, stdout(&["expand", "--profile", "linuxcnc", &example()])).expect("write");
    let out =
        run(&["check", "--profile", "linuxcnc", &example(), "--trace", &nc.display().to_string()], None);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    assert!(text.starts_with("AGREE: 104 moves of ours, 104 of the trace"), "{text}");
    // LinuxCNC's own canonical output (.canon): the same toolpath within
    // one increment (R-LCNC-EXACT: rs274 prints its binary64 radius with
    // four decimals; we round the exact diameter).
    let canon = dir.join("linuxcnc.canon");
    let printed = rs274_output(std::path::Path::new(&example()));
    std::fs::write(&canon, &printed).expect("write");
    let canon = canon.display().to_string();
    let out =
        run(&["check", "--profile", "linuxcnc", "--tolerance", "1", &example(), "--trace", &canon], None);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    // Within 0 increments it differs, and says where: pass 10's X is
    // 22 + (1.84 − 0.3·10^(2/3)) = 22.447523… in diameter, which we round to
    // 22.4475; LinuxCNC prints its radius 11.223761… as 11.2238.
    let out = run(&["check", "--profile", "linuxcnc", &example(), "--trace", &canon], None);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("rough pass 10") && text.contains("X22.4475") && text.contains("X22.4476"),
        "{text}"
    );
    // A canonical trace is LinuxCNC's: refused on another profile.
    let out = run(&["check", "--profile", "gsk988", &example(), "--trace", &canon], None);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn check_names_where_a_grblhal_style_trace_differs() {
    // docs/peers: grblHAL's mc_thread on the same G76 words, transcribed
    // (grblhal-out.txt, "straight"), written as G0/G33 blocks. grblHAL
    // anchors the compound shift at full depth, so its first pass starts
    // at Z 2 + (0.92 − 0.3)·tan 30° = 2.3580 where LinuxCNC starts at
    // 2 − 0.3·tan 30° = 1.8268, and from X22 (the drive line) where
    // LinuxCNC's "back" is at 22 + (1.84 − 0.6) = 23.24.
    let peers = format!("{}/../docs/peers", env!("CARGO_MANIFEST_DIR"));
    let program = format!("{peers}/linuxcnc-straight-g7.ngc");
    let moves = std::fs::read_to_string(format!("{peers}/grblhal-out.txt")).expect("grblhal-out.txt");
    let mut trace = String::from("G7 G18 G21 G90\nM3 S500\nG0 X22 Z2\n");
    for line in moves.lines().skip(1).take_while(|l| !l.starts_with("==")) {
        let words: Vec<&str> = line.split_whitespace().collect();
        let value =
            |key: &str| words.iter().position(|w| *w == key).map(|i| words[i + 1].trim_end_matches(')'));
        let dia = words.iter().position(|w| *w == "(dia").map(|i| words[i + 1].trim_end_matches(')'));
        let z = words.iter().find_map(|w| w.strip_prefix('Z'));
        match (words.first(), dia, z) {
            (Some(&"rapid"), Some(x), Some(z)) => trace.push_str(&format!("G0 X{x} Z{z}\n")),
            (Some(&"sync"), Some(x), Some(z)) => {
                trace.push_str(&format!("G33 X{x} Z{z} K{}\n", value("pitch").expect("pitch")));
            }
            _ => {}
        }
    }
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-grbl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let file = dir.join("grblhal.ngc");
    std::fs::write(&file, &trace).expect("write");
    let out =
        run(&["check", "--profile", "linuxcnc", &program, "--trace", &file.display().to_string()], None);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    let first = text.split("all divergences").next().unwrap_or_default();
    assert!(first.contains("G76 (LinuxCNC) at line 5, rough pass 1"), "{text}");
    assert!(
        first.contains("ours   rapid X23.2400 Z1.8268") && first.contains("theirs rapid X22.0000 Z2.3580"),
        "{text}"
    );
}

#[test]
fn check_names_where_a_grblhal_style_tapered_thread_differs() {
    // docs/peers/trace-grblhal-taper-linuxcnc.ngc: grblHAL's mc_thread with
    // its end tapers, on the example's words (docs/PEERS.md). grblHAL starts
    // pass 1 at Z 2 − 0.15·tan 29.5° + 0.92·tan 29.5° = 2.4356 (the shift
    // anchored at full depth) from X22; LinuxCNC's "back" is X23.54
    // Z1.9151; grblHAL cuts the entry taper at the thread's 1.5 along the
    // move where LinuxCNC runs 1.5·hypot(1, 0.92)/1 = 2.038235.
    let trace = format!("{}/../docs/peers/trace-grblhal-taper-linuxcnc.ngc", env!("CARGO_MANIFEST_DIR"));
    let out = run(&["check", "--profile", "linuxcnc", &example(), "--trace", &trace], None);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    let first = text.split("all divergences").next().unwrap_or_default();
    assert!(first.contains("rough pass 1") && first.contains("ours   rapid X23.5400 Z1.9151"), "{text}");
    assert!(first.contains("theirs rapid X22.0000 Z2.4356"), "{text}");
    // The lead as LinuxCNC writes it: K.
    assert!(text.contains("K2.038235") && text.contains("(lead)"), "{text}");
}

#[test]
fn plot_draws_it_with_a_trace_over_it() {
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let svg = dir.join("m20.svg");
    let out = run(&["plot", "--profile", "linuxcnc", &example(), "-o", &svg.display().to_string()], None);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).expect("svg");
    assert!(text.contains("G76 (LinuxCNC) blocks (lines 6-6)"), "the panel's title");
    assert!(text.contains("exit taper (E, L bit 2)"));
    // 17 passes, each synchronising once (a ring at each).
    assert_eq!(text.matches("synchronisation starts").count(), 17);
    // With the grblHAL-style trace of docs/peers, the first divergence is
    // marked and zoomed.
    let peers = format!("{}/../docs/peers", env!("CARGO_MANIFEST_DIR"));
    let svg = dir.join("grbl.svg");
    let out = run(
        &[
            "plot",
            "--profile",
            "linuxcnc",
            &format!("{peers}/linuxcnc-straight-g7.ngc"),
            "--trace",
            &format!("{peers}/trace-grblhal-straight-linuxcnc.ngc"),
            "-o",
            &svg.display().to_string(),
        ],
        None,
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).expect("svg");
    assert!(
        text.contains("first divergence, zoomed") && text.contains("ours rapid X23.2400 Z1.8268"),
        "zoom"
    );
}

/// The LinuxCNC programs of `examples/` (`*.ngc`).
fn ngc_examples() -> Vec<std::path::PathBuf> {
    let dir = std::path::PathBuf::from(format!("{}/../examples", env!("CARGO_MANIFEST_DIR")));
    let mut out: Vec<_> = std::fs::read_dir(&dir)
        .expect("examples/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "ngc"))
        .collect();
    out.sort();
    out
}

#[test]
fn every_linuxcnc_example_is_what_linuxcnc_cuts() {
    if !rs274_installed() {
        return;
    }
    let examples = ngc_examples();
    assert!(examples.len() >= 2, "{examples:?}");
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-every-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    for (n, example) in examples.iter().enumerate() {
        let name = example.display().to_string();
        // LinuxCNC's canonical output of the example, as a trace: our
        // toolpath (reader, engine, the program's own moves) within one
        // increment, with both engines.
        let canon = dir.join(format!("{n}.canon"));
        std::fs::write(&canon, rs274_output(example)).expect("write");
        let canon = canon.display().to_string();
        // rs274 prints four decimals of the radius: in mm that is our
        // increment (one more for our own rounding); in inch 0.0001 inch is
        // 10 increments of 0.00001, 20 as a diameter (R-CHECKLCNC).
        let inch = std::fs::read_to_string(example).expect("example").contains("G20");
        let tolerance = if inch { "11" } else { "1" };
        for engine in ["impl", "spec"] {
            let out = run(
                &[
                    "check",
                    "--profile",
                    "linuxcnc",
                    "--engine",
                    engine,
                    "--tolerance",
                    tolerance,
                    &name,
                    "--trace",
                    &canon,
                ],
                None,
            );
            let text = String::from_utf8_lossy(&out.stdout);
            assert_eq!(out.status.code(), Some(0), "{name} ({engine}): {text}");
            assert!(text.starts_with("AGREE"), "{name}: {text}");
        }
        // Our expansion, read back by LinuxCNC: the same motions.
        let expanded = dir.join(format!("{n}.ngc"));
        std::fs::write(&expanded, stdout(&["expand", "--profile", "linuxcnc", &name])).expect("write");
        let (a, b) = (rs274_motions(example), rs274_motions(&expanded));
        assert_eq!(a.len(), b.len(), "{name}");
        for (i, (p, q)) in a.iter().zip(&b).enumerate() {
            let close = (p.x - q.x).abs() <= Decimal::new(1, 4) && (p.z - q.z).abs() <= Decimal::new(1, 4);
            assert!(
                close && p.rapid == q.rapid && p.pitch == q.pitch,
                "{name}, motion {i}: {p:?} against {q:?}"
            );
        }
    }
}

/// LinuxCNC's numbered and named subroutines (reading R-SUBPROGRAM), each
/// program checked against `rs274`: `check` of the program against
/// LinuxCNC's own canonical output agrees, and the motions counted by
/// hand. The thread is the example's cycle (105 motions with the
/// program's own G0s; its G76 alone is 17 passes × 6 motions + 1 = 103).
#[test]
fn subroutines_run_as_linuxcnc_runs_them() {
    if !rs274_installed() {
        return;
    }
    let thread = "G76 P1.5 Z-20 I-2 J0.3 R1.5 K1.84 Q29.5 H1 E1 L3";
    let programs: Vec<(&str, String, usize)> = vec![
        // Defined first, called twice from two starts: 2 × 103 + 3 G0.
        (
            "before",
            format!("o100 sub\n{thread}\no100 endsub\nG18 G21 G7\nM3 S500\nG0 X22 Z2\no100 call\nG0 X24 Z2\no100 call\nG0 X30 Z5\nM5\nM2\n"),
            2 * 103 + 3,
        ),
        // Defined after M2 (rs274 seeks forward), named, mixed case.
        (
            "after-named",
            format!("G18 G21 G7\nM3 S500\nG0 X22 Z2\no<Thread> call\nG0 X30 Z5\nM5\nM2\no<thread> sub\n{thread}\no<THREAD> endsub\n"),
            103 + 2,
        ),
        // Nested, with an early return (the G0 X1 after it never runs).
        (
            "nested",
            format!(
                "o1 sub\nG0 X22 Z2\no2 call\no1 endsub\no2 sub\n{thread}\no2 return\nG0 X1\no2 endsub\n\
                 G18 G21 G7\nM3 S500\no0001 call\nG0 X30 Z5\nM5\nM2\n"
            ),
            1 + 103 + 1,
        ),
    ];
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-subs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    for (name, program, motions) in programs {
        let file = dir.join(format!("{name}.ngc"));
        std::fs::write(&file, &program).expect("write");
        let canon = dir.join(format!("{name}.canon"));
        std::fs::write(&canon, rs274_output(&file)).expect("write");
        assert_eq!(rs274_motions(&file).len(), motions, "{name}: rs274's motions");
        let f = file.to_string_lossy();
        let c = canon.to_string_lossy();
        // Within one increment (R-LCNC-EXACT, as the example's check).
        let out = run(&["check", "--profile", "linuxcnc", "--tolerance", "1", &f, "--trace", &c], None);
        let report = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{name}: {report}{}", String::from_utf8_lossy(&out.stderr));
        assert!(report.starts_with("AGREE: "), "{name}: {report}");
        // Our expansion has the motions counted by hand too.
        let nc = stdout(&["expand", "--profile", "linuxcnc", &f]);
        let ours = nc
            .lines()
            .filter(|l| l.starts_with("G0 ") || l.starts_with("G00 ") || l.starts_with("G33 "))
            .count();
        assert_eq!(ours, motions, "{name}: our motions\n{nc}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Reading R-LCNC-READER: LinuxCNC reads `;` as a comment to the end of
/// the line (a `(` or an `M2` after it is part of the comment), and so does
/// the linuxcnc profile by default (`comment`). The program is the
/// subroutine test's thread with `;` comments on its own lines and after
/// blocks: rs274 makes 103 motions of the G76 (17 passes × 6 + 1) and the
/// two G0s, 105; `check` of the program against rs274's canonical output
/// agrees; our expansion has the same 105 motions and keeps the comments
/// as written. Under `end-of-block` the text after `;` is a block of its
/// own and the program is refused (the previous behaviour).
#[test]
fn semicolon_comments_as_linuxcnc_reads_them() {
    if !rs274_installed() {
        return;
    }
    let program = "; a thread, LinuxCNC style\nG18 G21 G7 ; lathe, mm, diameter\nM3 S500\n\
                   G0 X22 Z2 ; approach (no closing paren\n\
                   G76 P1.5 Z-20 I-2 J0.3 R1.5 K1.84 Q29.5 H1 E1 L3 ;M2 is a comment here\n\
                   G0 X30 Z5;\nM5\nM2\n";
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-semi-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let file = dir.join("semi.ngc");
    std::fs::write(&file, program).expect("write");
    let canon = dir.join("semi.canon");
    std::fs::write(&canon, rs274_output(&file)).expect("write");
    assert_eq!(rs274_motions(&file).len(), 103 + 2, "rs274's motions");
    let f = file.to_string_lossy();
    let c = canon.to_string_lossy();
    let out = run(&["check", "--profile", "linuxcnc", "--tolerance", "1", &f, "--trace", &c], None);
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{report}{}", String::from_utf8_lossy(&out.stderr));
    assert!(report.starts_with("AGREE: "), "{report}");
    let nc = stdout(&["expand", "--profile", "linuxcnc", &f]);
    let ours =
        nc.lines().filter(|l| l.starts_with("G0 ") || l.starts_with("G00 ") || l.starts_with("G33 ")).count();
    assert_eq!(ours, 103 + 2, "{nc}");
    assert!(nc.contains("G0 X22 Z2 ; approach (no closing paren\n"), "{nc}");
    // The expansion, comments and all, is a program LinuxCNC cuts the same.
    let expanded = dir.join("expanded.ngc");
    std::fs::write(&expanded, &nc).expect("write");
    assert_eq!(rs274_motions(&expanded).len(), 103 + 2);
    let out = run(&["expand", "--profile", "linuxcnc", "--reading", "R-LCNC-READER=end-of-block", &f], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}

/// R-LCNC-G7 `as-interpreter`: a G7 or G8 that changes the X mode in the
/// G76 block is cut as LinuxCNC cuts it (I, J and K halved once more
/// switching to G7, doubled switching to G8; interp_convert.cc
/// l.2773-2777), `check` agrees with rs274's output, and the expansion
/// keeps the G7/G8 before its moves, so LinuxCNC cuts the expansion the
/// same and it expands to itself. Under the default the block is refused.
#[test]
fn x_mode_switch_in_g76_as_linuxcnc_cuts_it() {
    if !rs274_installed() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("cycleref-lcnc-g7-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    for (name, program, first) in [
        ("to7", "G18 G8 G21\nG0 X10 Z2\nM3 S500\nG7 G76 P1.5 Z-10 I-2 J0.6 K1.84\nM2\n", "G7\n"),
        ("to8", "G18 G7 G21\nG0 X20 Z2\nM3 S500\nG8 G76 P1.5 Z-10 I-1 J0.3 K0.92\nM2\n", "G8\n"),
    ] {
        let file = dir.join(format!("{name}.ngc"));
        std::fs::write(&file, program).expect("write");
        let canon = dir.join(format!("{name}.canon"));
        std::fs::write(&canon, rs274_output(&file)).expect("write");
        let f = file.to_string_lossy();
        let c = canon.to_string_lossy();
        let reading = ["--reading", "R-LCNC-G7=as-interpreter"];
        let out = run(
            &[
                "check",
                "--profile",
                "linuxcnc",
                reading[0],
                reading[1],
                "--tolerance",
                "1",
                &f,
                "--trace",
                &c,
            ],
            None,
        );
        let report = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{report}{}", String::from_utf8_lossy(&out.stderr));
        assert!(report.starts_with("AGREE: 17 moves"), "{report}");
        let nc = stdout(&["expand", "--profile", "linuxcnc", reading[0], reading[1], &f]);
        assert!(nc.contains(&format!("M3 S500\n{first}(G76 line 4")), "{nc}");
        let expanded = dir.join(format!("{name}-expanded.ngc"));
        std::fs::write(&expanded, &nc).expect("write");
        let motions = |p: &std::path::Path| -> Vec<_> {
            rs274_motions(p).into_iter().map(|m| (m.rapid, m.x, m.z, m.pitch)).collect()
        };
        assert_eq!(motions(&expanded), motions(&file), "{name}");
        assert_eq!(stdout(&["expand", "--profile", "linuxcnc", &expanded.to_string_lossy()]), nc);
        let out = run(&["expand", "--profile", "linuxcnc", &f], None);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
    }
    let _ = std::fs::remove_dir_all(&dir);
}
