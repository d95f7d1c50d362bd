//! `cycleref check` end to end: a trace equal to ours agrees; a wrong pass
//! depth, a missing finishing pass, a flipped run-out and a wrong lead are
//! each caught and named in the manual's terms; what does not matter (a
//! rapid split into X and Z, comments, N numbers, number formatting) is
//! ignored; CSV traces work; errors exit with 2.

mod common;

use common::run;
use std::path::PathBuf;

fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A scratch file of this binary's (`common::tmp` under `cycleref-check-…`).
fn tmp(name: &str, text: &str) -> PathBuf {
    common::tmp("check", name, text)
}

/// Our own expansion of the M68x6 example: the trace a correct vendor makes.
fn good_trace() -> String {
    let out = run(&["expand", "--profile", "gsk988", &example("gsk988-m68x6.nc")], None);
    assert!(out.status.success());
    String::from_utf8(out.stdout).unwrap()
}

fn check(trace: &str, name: &str, extra: &[&str]) -> (i32, String) {
    let p = tmp(name, trace);
    let mut args = vec!["check", "--profile", "gsk988", "--trace", p.to_str().unwrap()];
    args.extend_from_slice(extra);
    let m68 = example("gsk988-m68x6.nc");
    args.push(&m68);
    let out = run(&args, None);
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap() + &String::from_utf8_lossy(&out.stderr),
    )
}

#[test]
fn identical_trace_agrees() {
    let (code, text) = check(&good_trace(), "same.nc", &[]);
    assert_eq!(code, 0, "{text}");
    assert!(text.starts_with("AGREE: 32 moves of ours, 32 of the trace"), "{text}");
}

#[test]
fn what_does_not_matter_is_ignored() {
    // A rapid from A to B1 split into an X move and a Z move, N numbers,
    // comments stripped, numbers written differently, a block that does not move.
    let t = good_trace()
        .replace("(rough 1 start 1 depth 1.800 cut 1.800)\n", "")
        .replace("G00 X64.400 Z8.961\n", "N100 G00 X64.4\nN101 Z8.9610\nG00 X64.4 Z8.961\n")
        .replace("G32 X64.400 Z-59.000 F6.0", "G32 X64.4 Z-59. F6");
    let (code, text) = check(&t, "split.nc", &[]);
    assert_eq!(code, 0, "{text}\n{t}");
}

#[test]
fn wrong_pass_depth_is_named() {
    // Rough pass 3 (depth 3.118) cut at X61.800 instead of X61.764.
    let t = good_trace().replace("X61.764", "X61.800");
    let (code, text) = check(&t, "depth.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("first divergence:\nG76 at line 6, rough pass 3 (start 1, depth 3.118, cut 0.572): Bn"),
        "{text}"
    );
    assert!(text.contains("difference: X 36 Z 0 increments"), "{text}");
    // Within a tolerance of 36 increments it agrees.
    let (code, _) = check(&t, "depth.nc", &["--tolerance", "36"]);
    assert_eq!(code, 0);
}

#[test]
fn missing_finishing_pass_is_named() {
    let good = good_trace();
    let start = good.find("(finish 2 start 1").unwrap();
    let end = start
        + good[start..].find("F6.0\nG00 X80.000 Z-62.000\nG00 X80.000 Z10.000\n").unwrap()
        + "F6.0\nG00 X80.000 Z-62.000\nG00 X80.000 Z10.000\n".len();
    let t = format!("{}{}", &good[..start], &good[end..]);
    let (code, text) = check(&t, "missing.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("G76 at line 6, finish pass 2 (start 1, depth 3.680, cut 0.000): missing pass"),
        "{text}"
    );
    assert!(text.starts_with("DIFFER: 1 divergence"), "{text}");
}

#[test]
fn flipped_run_out_is_named() {
    // The run-out of rough pass 1 goes into the work: X58.400 instead of X70.400.
    let t = good_trace().replace("G32 X70.400 Z-62.000", "G32 X58.400 Z-62.000");
    let (code, text) = check(&t, "flipped.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("rough pass 1 (start 1, depth 1.800, cut 1.800): run-out end (end point)"),
        "{text}"
    );
    assert!(text.contains("difference: X -12000 Z 0 increments"), "{text}");
}

#[test]
fn wrong_lead_is_named() {
    let good = good_trace();
    let i = good.find("G32 X62.908 Z-59.000 F6.0").unwrap();
    let t =
        format!("{}G32 X62.908 Z-59.000 F5.0{}", &good[..i], &good[i + "G32 X62.908 Z-59.000 F6.0".len()..]);
    let (code, text) = check(&t, "lead.nc", &[]);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("rough pass 2") && text.contains("(lead)") && text.contains("F5.0"), "{text}");
}

#[test]
fn csv_trace_and_json_report() {
    // The same toolpath as CSV rows.
    let mut csv = String::from("motion,x,z,lead,q\nrapid,80.000,10.000,,\n");
    for line in good_trace().lines() {
        let kind = if line.starts_with("G00") {
            "rapid"
        } else if line.starts_with("G32") {
            "thread"
        } else {
            continue;
        };
        let w: Vec<&str> = line.split(' ').collect();
        let lead = if kind == "thread" { w[3] } else { "" };
        csv.push_str(&format!("{kind},{},{},{lead},\n", &w[1][1..], &w[2][1..]));
    }
    let (code, text) = check(&csv, "trace.csv", &[]);
    assert_eq!(code, 0, "{text}\n{csv}");
    // A divergence, as JSON.
    let bad = csv.replacen("thread,64.400,-59.000", "thread,64.400,-58.000", 1);
    let (code, text) = check(&bad, "bad.csv", &["--format", "json"]);
    assert_eq!(code, 1);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["agree"], false);
    let d = &v["divergences"][0];
    assert_eq!(d["what"], "end point");
    assert_eq!(d["ours"]["pass"]["number"], 1);
    assert_eq!(d["ours"]["point"], "end of cut (run-out start)");
    assert_eq!(d["difference_increments"]["z"], 1000);
}

#[test]
fn errors_exit_2() {
    let out = run(&["check", "--trace", "/nonexistent/trace.nc", &example("gsk988-m68x6.nc")], None);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    // A trace with a canned cycle is not a plain toolpath.
    let (code, text) = check("G00 X80 Z10\nG76 X60 Z-30 P2 Q1 F6\n", "cycle.nc", &[]);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("plain G00/G01/G02/G03/G32 blocks"), "{text}");
}

#[test]
fn plot_overlays_a_trace() {
    let t = tmp("overlay.nc", &good_trace().replace("X61.764", "X61.900"));
    let svg = std::env::temp_dir().join(format!("cycleref-overlay-{}.svg", std::process::id()));
    let out = run(
        &[
            "plot",
            "--profile",
            "gsk988",
            &example("gsk988-m68x6.nc"),
            "--trace",
            t.to_str().unwrap(),
            "-o",
            svg.to_str().unwrap(),
        ],
        None,
    );
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("trace: ") && text.contains("#d6278a") && text.contains("clip-path"));
}

#[test]
fn the_motion_mode_after_a_cycle_is_the_one_before_it() {
    // G01 is modal before the G76; the `X90 Z20` after it is a feed move in
    // the program and in our expansion (which restores G01).
    let program = "M03 S500\nG01 X80 Z10 F0.2\nG76 P010060 Q0.1 R0\nG76 X60 Z-30 P2 Q1 F6\nX90 Z20\n";
    let prog = tmp("modal.nc", program);
    let out = run(&["expand", prog.to_str().unwrap()], None);
    let trace = tmp("modal-trace.nc", &String::from_utf8(out.stdout).unwrap());
    let out = run(&["check", "--trace", trace.to_str().unwrap(), prog.to_str().unwrap()], None);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
}
