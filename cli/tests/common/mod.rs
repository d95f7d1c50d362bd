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
