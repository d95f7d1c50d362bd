//! What the command's tests share: running the built binary.

use std::io::Write as _;
use std::process::{Command, Output, Stdio};

/// The built `cycleref`.
pub const BIN: &str = env!("CARGO_BIN_EXE_cycleref");

/// Runs the command with `args`, `stdin` on its standard input (none: a
/// null device), and collects its output.
pub fn run(args: &[&str], stdin: Option<&[u8]>) -> Output {
    let mut cmd = Command::new(BIN);
    cmd.args(args).stdout(Stdio::piped()).stderr(Stdio::piped());
    cmd.stdin(if stdin.is_some() { Stdio::piped() } else { Stdio::null() });
    let mut child = cmd.spawn().expect("runs");
    if let Some(text) = stdin {
        let mut pipe = child.stdin.take().expect("stdin");
        let text = text.to_vec();
        // A thread: the child may write before it has read everything.
        std::thread::spawn(move || {
            let _ = pipe.write_all(&text);
        });
    }
    child.wait_with_output().expect("waits")
}

/// The standard output of a successful run of the command with `args` (no
/// standard input); a failure panics with its standard error.
#[allow(dead_code, reason = "not every test binary that includes `common` calls it")]
pub fn stdout(args: &[&str]) -> String {
    let out = run(args, None);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Writes `text` to `name` in a scratch directory of this process's own,
/// `cycleref-{tag}-{pid}` under the system's temporary directory, and
/// returns its path.
#[allow(dead_code, reason = "not every test binary that includes `common` calls it")]
pub fn tmp(tag: &str, name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("cycleref-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p
}

/// `expand --profile {profile} --format jsonl` of `file`, held to the
/// `--format json` document of the same run: every line but the last is
/// that document's cycle in order, the last is the summary, whose format is
/// `cycleref-moves-jsonl/1` and whose counts are `counts` (cycles, moves).
/// Returns the cycle lines.
#[allow(dead_code, reason = "not every test binary that includes `common` calls it")]
pub fn jsonl_cycles(profile: &str, file: &str, counts: (u64, u64)) -> Vec<serde_json::Value> {
    let json = stdout(&["expand", "--profile", profile, "--format", "json", file]);
    let doc: serde_json::Value = serde_json::from_str(&json).expect("json");
    let jsonl = stdout(&["expand", "--profile", profile, "--format", "jsonl", file]);
    let mut lines: Vec<serde_json::Value> =
        jsonl.lines().map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}"))).collect();
    let summary = lines.pop().expect("summary");
    assert_eq!(&lines, doc["cycles"].as_array().expect("cycles"));
    assert_eq!(summary["format"], "cycleref-moves-jsonl/1");
    assert_eq!((summary["cycles"].as_u64(), summary["moves"].as_u64()), (Some(counts.0), Some(counts.1)));
    lines
}

/// `cycleref conform ARGS`: its exit code, stdout and stderr.
#[allow(dead_code, reason = "not every test binary that includes `common` calls it")]
pub fn conform(args: &[&str]) -> (i32, String, String) {
    let o = run(&[&["conform"], args].concat(), None);
    (
        o.status.code().expect("exit code"),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}
