//! Every error that is not the program's prints the stable kind of its
//! rule (issue 31): `cycleref: error[KIND]: MESSAGE`, exit status 2. The
//! kinds are the README's table (the area, a colon, the rule's name); each
//! case breaks one rule on purpose, and the whole first line is compared.

mod common;

use common::run;

/// The example program the traces are compared with.
fn example(name: &str) -> String {
    format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// The first line of standard error of a run that must fail with status 2
/// and write nothing on standard output.
fn error_line(args: &[&str]) -> String {
    let out = run(args, None);
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?}");
    err.lines().next().unwrap_or_default().to_owned()
}

/// `check` of the example program against a trace file holding `text`.
fn check_trace(name: &str, text: &str) -> (String, String) {
    let trace = common::tmp("error-kinds", name, text);
    let path = trace.to_str().expect("utf-8").to_owned();
    let line = error_line(&["check", "--profile", "gsk988", "--trace", &path, &example("gsk988-m68x6.nc")]);
    (path, line)
}

#[test]
fn a_csv_field_that_is_not_a_decimal() {
    // The rule: a CSV length is a decimal (area trace, rule not_a_decimal).
    let (path, line) = check_trace("bad.csv", "motion,x,z\nrapid,80,1O\n");
    assert_eq!(
        line,
        format!("cycleref: error[trace:not_a_decimal]: {path}: CSV line 2: z `1O` is not a decimal")
    );
}

#[test]
fn a_csv_header_without_its_columns() {
    let (path, line) = check_trace("header.csv", "motion,x\nrapid,80\n");
    assert_eq!(
        line,
        format!(
            "cycleref: error[trace:csv_header_incomplete]: {path}: CSV line 1: the header must name the columns \
             motion, x and z (lead, q, i, k, cx and cz are optional)"
        )
    );
}

#[test]
fn a_trace_without_moves() {
    // Reading R-CHECKEMPTY: area trace, rule empty.
    let (path, line) = check_trace("empty.nc", "");
    assert_eq!(
        line,
        format!("cycleref: error[trace:empty]: {path}: the trace has no moves (reading R-CHECKEMPTY)")
    );
}

#[test]
fn a_missing_trace_file() {
    let line =
        error_line(&["check", "--trace", "/nonexistent/cycleref/trace.nc", &example("gsk988-m68x6.nc")]);
    assert_eq!(
        line,
        "cycleref: error[trace:cannot_open]: /nonexistent/cycleref/trace.nc: No such file or directory (os error 2)"
    );
}

#[test]
fn a_bad_parameter_file() {
    // `spec::profile::ParamsError::BadSetting`: area params, rule bad_setting.
    let params = common::tmp("error-kinds", "bad.toml", "unit = \"furlong\"\n");
    let path = params.to_str().expect("utf-8");
    let line = error_line(&["expand", "--params", path, &example("gsk988-m68x6.nc")]);
    assert_eq!(
        line,
        format!("cycleref: error[params:bad_setting]: {path}: `unit` must be \"metric\" or \"inch\"")
    );
}

#[test]
fn a_bad_shard() {
    // The arguments' error: area usage, rule bad_shard.
    let dir = std::env::temp_dir();
    let dir = dir.to_str().expect("utf-8");
    let line = error_line(&["conform", dir, "--traces", dir, "--shard", "0/2"]);
    assert_eq!(
        line,
        "cycleref: error[usage:bad_shard]: --shard \"0/2\": give I/N with 1 <= I <= N, e.g. 2/4"
    );
}

#[test]
fn an_arc_by_r_in_our_program() {
    // Reading R-CHECKARC, on our side: area check, rule arc_by_r.
    let program =
        common::tmp("error-kinds", "arc-r.nc", "G00 X80 Z10\nG01 Z0 F0.2\nG02 X90 Z-5 R5\nG00 X100\nM30\n");
    let program = program.to_str().expect("utf-8");
    let trace = common::tmp("error-kinds", "arc-r-trace.nc", "G00 X80 Z10\n");
    let line =
        error_line(&["check", "--profile", "gsk988", "--trace", trace.to_str().expect("utf-8"), program]);
    assert_eq!(
        line,
        format!(
            "cycleref: error[check:arc_by_r]: {program}: line 3, word `R5`: an arc is compared by its centre: \
             give I and K (the centre R implies is in general not a point of the increment grid, reading \
             R-CHECKARC)"
        )
    );
}
