//! Whether a test that compares with LinuxCNC's `rs274` runs or skips: the
//! one rule, included by `spec/tests/linuxcnc_rs274.rs` and
//! `cli/tests/linuxcnc.rs`.

/// Whether LinuxCNC's interpreter `rs274` can run here. When it cannot, a
/// test that compares with it is skipped with one line on the terminal
/// (written to the standard error handle, which the test harness does not
/// capture), unless `CYCLEREF_REQUIRE_RS274=1` (set by `.ci/run` after it
/// installs it), which makes a missing `rs274` a failure.
pub fn rs274_installed() -> bool {
    use std::io::Write as _;
    use std::process::{Command, Stdio};
    static FOUND: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let found = *FOUND.get_or_init(|| {
        Command::new("rs274")
            .arg("-h")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok()
    });
    let install =
        "apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
                   linuxcnc-uspace";
    if !found {
        assert!(
            std::env::var_os("CYCLEREF_REQUIRE_RS274").is_none_or(|v| v != "1"),
            "CYCLEREF_REQUIRE_RS274=1 and `rs274` cannot be run: install LinuxCNC's interpreter with `{install}`"
        );
        let _ = writeln!(
            std::io::stderr(),
            "skipped: this test compares with LinuxCNC's `rs274`, which is not installed (`{install}`)"
        );
    }
    found
}
