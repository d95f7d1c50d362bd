//! `cycleref plot`: runs the built binary and checks the SVG it writes.

use std::path::PathBuf;
use std::process::{Command, Output};

use svg::node::element::tag::Type;
use svg::parser::Event;

const BIN: &str = env!("CARGO_BIN_EXE_cycleref");
const M68: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk988-m68x6.nc");
const INTERNAL: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/fanuc-internal.nc");

/// A fresh path in the target's scratch directory for this test.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("plot-tests");
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    let _ = std::fs::remove_file(&path);
    path
}

fn plot(profile: &str, input: &str, output: &PathBuf) -> Output {
    Command::new(BIN)
        .args(["plot", "--profile", profile, input, "-o"])
        .arg(output)
        .output()
        .expect("run cycleref")
}

/// The SVG written by a successful `plot`.
fn plot_ok(profile: &str, input: &str, name: &str) -> String {
    let out = scratch(name);
    let run = plot(profile, input, &out);
    assert_eq!(run.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&run.stderr));
    assert!(run.stdout.is_empty(), "plot prints nothing on stdout");
    std::fs::read_to_string(&out).expect("svg written")
}

/// What the checks need from a document: the contents of its `text`
/// elements and the attributes seen, after checking that every tag is
/// closed in order.
struct Parsed {
    texts: Vec<String>,
    dashed: usize,
    paths: usize,
    circles: usize,
}

fn parse(doc: &str) -> Parsed {
    let mut stack: Vec<String> = Vec::new();
    let mut parsed = Parsed { texts: Vec::new(), dashed: 0, paths: 0, circles: 0 };
    for event in svg::read(doc).expect("parser") {
        match event {
            Event::Error(e) => panic!("malformed SVG: {e:?}"),
            Event::Tag(name, kind, attrs) => {
                if kind != Type::End {
                    if attrs.contains_key("stroke-dasharray") {
                        parsed.dashed += 1;
                    }
                    match name {
                        "path" => parsed.paths += 1,
                        "circle" => parsed.circles += 1,
                        _ => {}
                    }
                }
                match kind {
                    Type::Start => stack.push(name.to_string()),
                    Type::End => assert_eq!(stack.pop().as_deref(), Some(name), "unbalanced </{name}>"),
                    Type::Empty => {}
                }
            }
            Event::Text(t) if stack.last().map(String::as_str) == Some("text") => {
                parsed.texts.push(t.trim().to_string());
            }
            _ => {}
        }
    }
    assert!(stack.is_empty(), "unclosed tags: {stack:?}");
    parsed
}

#[test]
fn m68_example_is_a_labelled_svg() {
    let doc = plot_ok("gsk988", M68, "m68.svg");
    assert!(doc.starts_with("<svg") || doc.starts_with("<?xml"), "{}", &doc[..40]);
    assert!(doc.ends_with("</svg>\n"));
    assert!(doc.contains(r#"xmlns="http://www.w3.org/2000/svg""#));
    let p = parse(&doc);
    for label in ["A", "B", "C", "D"] {
        assert!(p.texts.iter().any(|t| t == label), "point label {label} missing: {:?}", p.texts);
    }
    for legend in ["rapid (G00)", "rough pass 1, depth 1.800", "finishing passes", "run-out", "lead-in"] {
        assert!(p.texts.iter().any(|t| t.starts_with(legend)), "legend {legend:?} missing: {:?}", p.texts);
    }
    // Title with the file name and the line of the cycle; axis labels.
    assert!(p.texts.iter().any(|t| t.contains("gsk988-m68x6.nc") && t.contains("line 6")), "{:?}", p.texts);
    assert!(p.texts.iter().any(|t| t == "Z (mm)"));
    assert!(p.texts.iter().any(|t| t == "X (diameter, mm)"));
    // Tick labels of both axes.
    assert!(p.texts.iter().any(|t| t == "-60"));
    assert!(p.texts.iter().any(|t| t == "80"));
    // The coordinates of the points, as programmed.
    assert!(p.texts.iter().any(|t| t == "X80.000 Z10.000"));
    assert!(p.texts.iter().any(|t| t == "X60.640 Z-62.000"));
    // Rapids (and their legend swatch) are dashed.
    assert!(p.dashed >= 2, "dashed elements: {}", p.dashed);
    // Rapids, 4 rough passes, the finishing path (both passes coincide), run-outs.
    assert_eq!(p.paths, 1 + 4 + 1 + 1);
    // A, B, C, D on the plot and in the legend.
    assert_eq!(p.circles, 8);
}

#[test]
fn plot_is_deterministic() {
    let first = plot_ok("gsk988", M68, "twice-1.svg");
    let second = plot_ok("gsk988", M68, "twice-2.svg");
    assert_eq!(first.as_bytes(), second.as_bytes());
}

#[test]
fn internal_fanuc_example() {
    let doc = plot_ok("fanuc", INTERNAL, "internal.svg");
    let p = parse(&doc);
    assert!(
        p.texts.iter().any(|t| t.starts_with("internal thread, 15 rough + 2 finishing passes")),
        "{:?}",
        p.texts
    );
    // 15 rough passes: one legend entry for all of them.
    assert!(p.texts.iter().any(|t| t == "rough passes 1\u{2013}15"), "{:?}", p.texts);
    assert!(!p.texts.iter().any(|t| t.starts_with("rough pass 1,")));
    assert!(p.texts.iter().any(|t| t == "lead-in (none)"));
}

#[test]
fn several_cycles_stack_and_mark_lead_in() {
    let input = scratch("two.nc");
    std::fs::write(
        &input,
        "M03 S500\nG00 X80 Z10\nG76 P020545 Q0.15 R0.5 L3 E2\nG76 X60 Z-60 P3 Q1.8 F6 J1.5 K2\n\
         G00 X40 Z-65\nG76 P010060 Q0.05 R0.05\nG76 X30 Z-100 R-2 P1.2 Q0.3 F1.5\nM30\n",
    )
    .expect("write program");
    let doc = plot_ok("gsk988", input.to_str().expect("utf-8 path"), "two.svg");
    let p = parse(&doc);
    assert!(doc.contains(r#"height="1120""#), "two panels of 560 px");
    assert_eq!(p.texts.iter().filter(|t| t.contains("G76 at line")).count(), 2);
    assert!(p.texts.iter().any(|t| t.ends_with("line 4")));
    assert!(p.texts.iter().any(|t| t.ends_with("line 7")));
    assert_eq!(p.texts.iter().filter(|t| *t == "lead-in").count(), 1);
    assert!(p.texts.iter().any(|t| t == "3 starts: their paths coincide"));
}

#[test]
fn error_exits_2_and_writes_nothing() {
    let input = scratch("no-p.nc");
    // Block 2 of G76 without P(k).
    std::fs::write(&input, "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.15 R0.1\nG76 X60.64 Z-62 Q1.8 F6\nM30\n")
        .expect("write program");
    let out = scratch("no-p.svg");
    let run = plot("gsk988", input.to_str().expect("utf-8 path"), &out);
    assert_eq!(run.status.code(), Some(2));
    assert!(run.stdout.is_empty());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("line 4"), "{stderr}");
    assert!(!out.exists(), "no file on error");
}

#[test]
fn no_cycle_is_an_error() {
    let input = scratch("none.nc");
    std::fs::write(&input, "M03 S500\nG00 X80 Z10\nM30\n").expect("write program");
    let out = scratch("none.svg");
    let run = plot("gsk988", input.to_str().expect("utf-8 path"), &out);
    assert_eq!(run.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&run.stderr).contains("no G76 cycle"));
    assert!(!out.exists());
}

#[test]
fn many_moves_stay_small() {
    // About 59 000 moves: 2955 rough passes x 4 starts.
    let input = scratch("big.nc");
    std::fs::write(
        &input,
        "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.001 R0.1 L4\nG76 X60.64 Z-62 P3.68 Q0.05 F6\nM30\n",
    )
    .expect("write program");
    let doc = plot_ok("gsk988", input.to_str().expect("utf-8 path"), "big.svg");
    let p = parse(&doc);
    // Each distinct pass path once: the starts coincide.
    assert!(p.paths < 3000, "paths: {}", p.paths);
    assert!(doc.len() < 1_000_000, "size: {}", doc.len());
}

/// A program with G32 blocks gets a panel of its thread moves and run-outs.
#[test]
fn g32_blocks_are_drawn() {
    let svg = std::env::temp_dir().join(format!("cycleref-g32-{}.svg", std::process::id()));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cycleref"))
        .args(["plot", "--profile", "gsk980"])
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk980-g32-runout.nc"))
        .arg("-o")
        .arg(&svg)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("G32 blocks (lines 5-11)"), "{text}");
    assert_eq!(text.matches("line 11: run-out").count(), 1);
    assert_eq!(text.matches("synchronisation starts").count(), 2);
    let _ = std::fs::remove_file(&svg);
}

/// Our expansion of `example` (with `profile`), with `from` replaced by
/// `to` once, written as a trace in the scratch directory.
fn trace_with(profile: &str, example: &str, from: &str, to: &str, name: &str) -> PathBuf {
    let out = Command::new(BIN).args(["expand", "--profile", profile, example]).output().expect("expands");
    assert!(out.status.success());
    let ours = String::from_utf8(out.stdout).expect("utf-8");
    assert!(ours.contains(from), "{from} not in the expansion");
    let path = scratch(name);
    std::fs::write(&path, ours.replacen(from, to, 1)).expect("writes the trace");
    path
}

fn plot_trace(profile: &str, example: &str, trace: &PathBuf, name: &str) -> (Output, String) {
    let svg = scratch(name);
    let run = Command::new(BIN)
        .args(["plot", "--profile", profile, example, "--trace"])
        .arg(trace)
        .arg("-o")
        .arg(&svg)
        .output()
        .expect("runs");
    (run, std::fs::read_to_string(&svg).unwrap_or_default())
}

#[test]
fn the_first_divergence_is_marked_and_zoomed() {
    // Rough pass 3 of M68x6 ends its cut at X61.764 Z-59 (the golden test
    // of the manual's O0013); the trace ends it 0.036 mm (36 increments)
    // lower.
    let trace = trace_with("gsk988", M68, "G32 X61.764 Z-59.000", "G32 X61.728 Z-59.000", "m68-36.nc");
    let (run, svg) = plot_trace("gsk988", M68, &trace, "m68-36.svg");
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let parsed = parse(&svg);
    let has = |s: &str| parsed.texts.iter().any(|t| t.contains(s));
    // A second panel, zoomed six times the difference each way.
    assert!(has("first divergence, zoomed"), "{:?}", parsed.texts);
    assert!(has("216 increments each way around our point"), "{:?}", parsed.texts);
    // The report's words for it, beside the zoom.
    assert!(has("rough pass 3"), "{:?}", parsed.texts);
    assert!(has("difference: X -36 Z 0 increments"), "{:?}", parsed.texts);
    // The first divergence's large ring: on the cycle's panel and on the
    // zoom; its label "1" on both.
    assert_eq!(svg.matches("r=\"9\"").count(), 2, "{svg}");
    assert_eq!(parsed.texts.iter().filter(|t| t.as_str() == "1").count(), 2);
}

#[test]
fn a_groove_divergence_is_marked_on_its_panel() {
    const SQUARE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk980-g75-square.nc");
    // Layer 1 plunge 2 goes 0.1 mm deeper in the trace.
    let trace = trace_with("gsk980", SQUARE, "G01 X26.000 Z-3.200", "G01 X25.900 Z-3.200", "square-deep.nc");
    let (run, svg) = plot_trace("gsk980", SQUARE, &trace, "square-deep.svg");
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    let parsed = parse(&svg);
    let has = |s: &str| parsed.texts.iter().any(|t| t.contains(s));
    assert!(has("G75.1 at line 9, layer 1 plunge 2"), "{:?}", parsed.texts);
    assert!(has("difference: X -100 Z 0 increments"), "{:?}", parsed.texts);
    assert_eq!(svg.matches("r=\"9\"").count(), 2, "the groove panel and the zoom");
}

#[test]
fn a_trace_on_standard_input_cannot_be_drawn() {
    let out = Command::new(BIN)
        .args(["plot", "--profile", "gsk988", M68, "--trace", "-", "-o"])
        .arg(scratch("stdin.svg"))
        .stdin(std::process::Stdio::null())
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("give it as a file, not `-`"));
}

#[test]
fn groove_and_thread_panels_have_a_legend_and_a_scale_note() {
    let square =
        plot_ok("gsk980", concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk980-g75-square.nc"), "sq.svg");
    let parsed = parse(&square);
    let has = |s: &str| parsed.texts.iter().any(|t| t.contains(s));
    for s in ["Legend", "rough contour (step 9)", "finishing contour (step 10)", "tool edge, I3.000 wide"] {
        assert!(has(s), "{s}: {:?}", parsed.texts);
    }
    assert!(has("grooving tool I3.000; X and Z to"), "{:?}", parsed.texts);
    let g32 = plot_ok(
        "gsk980",
        concat!(env!("CARGO_MANIFEST_DIR"), "/../examples/gsk980-g32-runout.nc"),
        "g32.svg",
    );
    let parsed = parse(&g32);
    let has = |s: &str| parsed.texts.iter().any(|t| t.contains(s));
    for s in ["Legend", "run-out (J, K)", "spindle synchronises", "4 blocks; X and Z to"] {
        assert!(has(s), "{s}: {:?}", parsed.texts);
    }
}

/// A text element's box: where it is drawn and how wide it may be.
struct TextBox {
    text: String,
    left: f64,
    right: f64,
    top: f64,
    bottom: f64,
}

/// The boxes of every `text` element of `doc`, and the document's width and
/// height. A text's width is taken as 0.62 em a character (DejaVu Sans,
/// the first font the plots name, averages under 0.6 em for these labels:
/// an upper bound), its height 1 em above the baseline and 0.35 em below
/// (more with `dy`); a `rotate(-90 cx cy)` text stands on its side.
fn text_boxes(doc: &str) -> (Vec<TextBox>, f64, f64) {
    let (mut width, mut height) = (0.0, 0.0);
    let mut boxes = Vec::new();
    let mut open: Option<std::collections::HashMap<String, String>> = None;
    let num = |a: &std::collections::HashMap<String, String>, k: &str| -> f64 {
        a.get(k).and_then(|v| v.trim_end_matches("em").parse().ok()).unwrap_or(0.0)
    };
    for event in svg::read(doc).expect("parser") {
        match event {
            Event::Tag("svg", Type::Start, attrs) => {
                width = attrs.get("width").and_then(|v| v.parse().ok()).expect("width");
                height = attrs.get("height").and_then(|v| v.parse().ok()).expect("height");
            }
            Event::Tag("text", Type::Start, attrs) => {
                open = Some(attrs.iter().map(|(k, v)| (k.to_string(), v.to_string())).collect());
            }
            Event::Tag("text", Type::End, _) => open = None,
            Event::Text(t) => {
                let Some(a) = &open else { continue };
                let text = t.trim().to_string();
                let size = num(a, "font-size");
                let w = 0.62 * size * text.chars().count() as f64;
                let (x, y) = (num(a, "x"), num(a, "y") + num(a, "dy") * size);
                let (left, right) = match a.get("text-anchor").map(String::as_str) {
                    Some("middle") => (x - w / 2.0, x + w / 2.0),
                    Some("end") => (x - w, x),
                    _ => (x, x + w),
                };
                let b = if a.get("transform").is_some_and(|t| t.starts_with("rotate(-90")) {
                    // On its side about (x, y): the length runs along y.
                    let (top, bottom) = match a.get("text-anchor").map(String::as_str) {
                        Some("middle") => (y - w / 2.0, y + w / 2.0),
                        Some("end") => (y, y + w),
                        _ => (y - w, y),
                    };
                    TextBox { text, left: x - size, right: x + 0.35 * size, top, bottom }
                } else {
                    TextBox { text, left, right, top: y - size, bottom: y + 0.35 * size }
                };
                boxes.push(b);
            }
            _ => {}
        }
    }
    (boxes, width, height)
}

#[test]
fn no_text_leaves_the_frame_on_any_kind_of_panel() {
    // Issue 35: every kind of panel (G76 external and internal, G78, G92,
    // G32, G75.1 square and slope, LinuxCNC's G76, several cycles, and a
    // trace's divergence with its zoom): every label inside the picture.
    let ex = |f: &str| format!("{}/../examples/{f}", env!("CARGO_MANIFEST_DIR"));
    let mut docs = vec![];
    for (profile, file) in [
        ("gsk988", "gsk988-m68x6.nc"),
        ("gsk980", "gsk980-m68x6.nc"),
        ("fanuc", "fanuc-internal.nc"),
        ("fanuc", "fanuc-external.nc"),
        ("gsk980", "gsk980-g78.nc"),
        ("gsk988", "gsk988-g78.nc"),
        ("gsk980", "gsk980-g92-o0012.nc"),
        ("gsk980", "gsk980-g32-runout.nc"),
        ("gsk980", "gsk980-g75-square.nc"),
        ("gsk980", "gsk980-g75-slope.nc"),
        ("gsk980", "gsk980-g75-seed.nc"),
        ("linuxcnc", "linuxcnc-m20-taper.ngc"),
        ("linuxcnc", "linuxcnc-internal-inch.ngc"),
    ] {
        let out = scratch(&format!("frame-{file}.svg"));
        let run = Command::new(BIN)
            .args(["plot", "--profile", profile, &ex(file), "-o"])
            .arg(&out)
            .output()
            .expect("runs");
        if run.status.success() {
            docs.push((file.to_string(), std::fs::read_to_string(&out).expect("svg")));
        } else {
            // An example written for another increment system (say so in
            // its header) is not a panel kind of its own.
            eprintln!("{file}: {}", String::from_utf8_lossy(&run.stderr));
        }
    }
    let trace = trace_with("gsk988", M68, "G32 X61.764 Z-59.000", "G32 X61.728 Z-59.000", "frame-m68-36.nc");
    let (run, svg) = plot_trace("gsk988", M68, &trace, "frame-m68-36.svg");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    docs.push(("m68 with a divergence".into(), svg));
    assert!(docs.len() >= 10, "{} panels drawn", docs.len());
    let mut outside = Vec::new();
    for (name, doc) in &docs {
        let (boxes, width, height) = text_boxes(doc);
        assert!(!boxes.is_empty(), "{name}: no text");
        for b in boxes {
            if b.left < 0.0 || b.top < 0.0 || b.right > width || b.bottom > height {
                let TextBox { text, left, right, top, bottom } = b;
                outside.push(format!("{name}: `{text}` spans x {left:.0}..{right:.0}, y {top:.0}..{bottom:.0} in {width} x {height}"));
            }
        }
    }
    assert!(outside.is_empty(), "text outside the picture:\n{}", outside.join("\n"));
}

/// The points of the first trace polyline (`stroke="#d6278a"`, a `d` of
/// `M x y L x y …`) in `svg`.
fn trace_points(svg: &str) -> Vec<(f64, f64)> {
    for event in svg::read(svg).expect("parser") {
        if let Event::Tag("path", _, attrs) = event {
            if attrs.get("stroke").map(|v| v.to_string()).as_deref() == Some("#d6278a") {
                let d = attrs.get("d").expect("d").to_string();
                let nums: Vec<f64> = d.split(['M', 'L', ' ']).filter_map(|t| t.parse().ok()).collect();
                return nums.chunks(2).map(|c| (c[0], c[1])).collect();
            }
        }
    }
    Vec::new()
}

/// The Z tick labels of the first panel (the texts on its Z axis, in
/// order, up to the first that does not grow: the next panel's).
fn z_ticks(svg: &str) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for t in svg.split("<text ").filter(|t| t.contains("text-anchor=\"middle\"") && t.contains("y=\"499\"")) {
        let label = t.split('>').nth(1).and_then(|l| l.split('<').next()).map(str::trim).unwrap_or_default();
        let Ok(v) = label.parse::<f64>() else { continue };
        if out.last().is_some_and(|&last| v <= last) {
            break;
        }
        out.push(v);
    }
    out
}

#[test]
fn the_frame_grows_to_hold_a_trace_that_strays_not_one_that_runs_away() {
    // Issue 35. M68x6 spans Z10 to Z-62 (72 mm): a trace whose rough pass 3
    // cuts on to Z-70 strays 8 mm beyond it, and the frame holds all of it
    // (every point of the trace inside the plot area, 90..880 × 72..480);
    // one that cuts to Z-900 runs away, and the frame keeps the scale it
    // has for a trace that does not differ (the same Z ticks), the rest
    // clipped.
    let strays = trace_with("gsk988", M68, "G32 X61.764 Z-59.000", "G32 X61.764 Z-70.000", "m68-strays.nc");
    let (run, svg) = plot_trace("gsk988", M68, &strays, "m68-strays.svg");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let points = trace_points(&svg);
    assert!(points.len() > 20, "{points:?}");
    for (x, y) in &points {
        assert!((90.0..=880.0).contains(x) && (72.0..=480.0).contains(y), "({x}, {y}) outside the plot area");
    }
    let away = trace_with("gsk988", M68, "G32 X61.764 Z-59.000", "G32 X61.764 Z-900.000", "m68-away.nc");
    let (run, svg) = plot_trace("gsk988", M68, &away, "m68-away.svg");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let same = trace_with("gsk988", M68, "G32 X61.764 Z-59.000", "G32 X61.764 Z-59.000", "m68-same.nc");
    let (run, agrees) = plot_trace("gsk988", M68, &same, "m68-same.svg");
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(z_ticks(&agrees).len() >= 5, "{:?}", z_ticks(&agrees));
    assert_eq!(z_ticks(&svg), z_ticks(&agrees));
    assert!(
        trace_points(&svg).iter().any(|(x, _)| *x < 90.0),
        "the run-away point lies beyond the frame, clipped"
    );
}

/// The legend names the readings in force that differ from the defaults
/// (issue 34), as the nc output's `(readings: …)` comment does, on every
/// kind of panel, inside the picture even with every reading changed; under
/// the defaults it names none.
#[test]
fn the_legend_names_the_readings_not_the_defaults() {
    let ex = |f: &str| format!("{}/../examples/{f}", env!("CARGO_MANIFEST_DIR"));
    let every: Vec<String> = ["R-RUNOUT=gsk988-only", "R-XRUNOUT=towards-start", "R-E980=signed"]
        .into_iter()
        .chain(["R-G78LEFT=mirror-b", "R-G78CENTRE=under-b", "R-LEADIN=whole-leads"])
        .map(String::from)
        .collect();
    for (profile, file) in [
        ("gsk988", "gsk988-m68x6.nc"),
        ("gsk988", "gsk988-g78.nc"),
        ("gsk980", "gsk980-g78.nc"),
        ("gsk980", "gsk980-g92-o0012.nc"),
        ("gsk980", "gsk980-g75-square.nc"),
    ] {
        let out = scratch(&format!("readings-{file}.svg"));
        let mut cmd = Command::new(BIN);
        cmd.args(["plot", "--profile", profile, &ex(file), "-o"]).arg(&out);
        for r in &every {
            cmd.args(["--reading", r]);
        }
        let run = cmd.output().expect("runs");
        assert!(run.status.success(), "{file}: {}", String::from_utf8_lossy(&run.stderr));
        let doc = std::fs::read_to_string(&out).expect("svg");
        let (boxes, width, height) = text_boxes(&doc);
        assert!(
            boxes.iter().any(|b| b.text == "readings (not the defaults):"),
            "{file}: {:?}",
            boxes.iter().map(|b| &b.text).collect::<Vec<_>>()
        );
        let named: String = boxes.iter().map(|b| b.text.as_str()).collect::<Vec<_>>().join(" ");
        for r in &every {
            assert!(named.contains(r.as_str()), "{file}: {r} not named: {named}");
        }
        for b in boxes {
            assert!(
                b.left >= 0.0 && b.top >= 0.0 && b.right <= width && b.bottom <= height,
                "{file}: `{}` outside the picture",
                b.text
            );
        }
        let default = plot_ok(profile, &ex(file), &format!("d-{file}.svg"));
        assert!(!default.contains("readings (not the defaults)"), "{file}");
    }
}
