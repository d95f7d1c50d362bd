//! Builds `tests/c/expand_example.c` against the static library with the
//! system C compiler, runs it on `examples/gsk988-m68x6.nc` and checks that
//! every check in it passes; does the same with the examples of README.md
//! (the buffer and the cursor), and checks that the header is valid C++.
//!
//! Finding the library: cargo compiles this package's library with all its
//! crate types (`cdylib`, `staticlib`, `rlib`) before it builds the tests,
//! into the directory of the test executable (`target/<profile>/deps`,
//! where `cargo test` leaves `libcycleref_ffi.a` without a hash suffix);
//! `cargo build` copies it one level up, to `target/<profile>`. Both are
//! looked at, the newest wins; if neither has it, the test runs
//! `cargo build -p cycleref-ffi --lib` with the same profile and target
//! directory.
//!
//! The C compiler is `$CC`, or `cc`. Unix only: on other targets the test
//! does nothing.
#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::Command;

const STATIC_LIB: &str = "libcycleref_ffi.a";

/// The system libraries the Rust standard library needs in a static link
/// (`--print native-static-libs`).
fn native_libs() -> &'static [&'static str] {
    if cfg!(target_os = "macos") {
        &["-liconv", "-lSystem", "-lc", "-lm"]
    } else if cfg!(target_os = "linux") {
        &["-lgcc_s", "-lutil", "-lrt", "-lpthread", "-lm", "-ldl", "-lc"]
    } else {
        &["-lpthread", "-lm", "-lc"]
    }
}

fn newest(candidates: &[PathBuf]) -> Option<PathBuf> {
    candidates
        .iter()
        .filter_map(|p| Some((p.metadata().ok()?.modified().ok()?, p.clone())))
        .max_by_key(|(t, _)| *t)
        .map(|(_, p)| p)
}

/// The static library built for this test run.
fn static_lib() -> PathBuf {
    let exe = std::env::current_exe().expect("the test executable's path");
    let deps = exe.parent().expect("the test executable's directory").to_path_buf();
    let profile_dir = deps.parent().expect("the profile directory").to_path_buf();
    let candidates = [deps.join(STATIC_LIB), profile_dir.join(STATIC_LIB)];
    if let Some(lib) = newest(&candidates) {
        return lib;
    }
    // Not there (an unusual layout): build it with the same profile.
    let profile = match profile_dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") | None => "dev".to_string(),
        Some(name) => name.to_string(),
    };
    let target_dir = profile_dir.parent().expect("the target directory");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let status = Command::new(cargo)
        .args(["build", "-p", "cycleref-ffi", "--lib", "--profile", &profile, "--target-dir"])
        .arg(target_dir)
        .status()
        .expect("run cargo build");
    assert!(status.success(), "cargo build -p cycleref-ffi failed");
    newest(&candidates).unwrap_or_else(|| panic!("no {STATIC_LIB} in {}", profile_dir.display()))
}

fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".into())
}

/// Compiles `source` against the static library into `name` (in the
/// tests' temporary directory) and returns the executable's path.
fn build_c(source: &Path, name: &str) -> PathBuf {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = static_lib();
    let exe = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let output = Command::new(compiler())
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-I"])
        .arg(manifest.join("include"))
        .arg(source)
        .arg(&lib)
        .args(native_libs())
        .arg("-o")
        .arg(&exe)
        .output()
        .unwrap_or_else(|e| panic!("cannot run the C compiler `{}`: {e}", compiler()));
    assert!(
        output.status.success(),
        "compiling {} against {} failed:\n{}",
        source.display(),
        lib.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    exe
}

/// Runs `exe` with `args`, asserts success and returns its stdout.
fn run(exe: &Path, args: &[&Path]) -> String {
    let run = Command::new(exe).args(args).output().expect("run the C program");
    let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{} failed ({}):\n{stdout}\n{stderr}", exe.display(), run.status);
    stdout
}

#[test]
fn c_program_expands_the_m68x6_example() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let exe = build_c(&manifest.join("tests/c/expand_example.c"), "cycleref_ffi_expand_example");
    let stdout = run(&exe, &[&manifest.join("../examples/gsk988-m68x6.nc")]);
    assert!(stdout.contains("all checks passed"), "{stdout}");
}

/// The examples of README.md (the buffer and the cursor) compile, run and
/// print what they say.
#[test]
fn readme_examples_run() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(manifest.join("README.md")).expect("read README.md");
    let programs: Vec<_> = readme
        .split("```c\n")
        .skip(1)
        .filter_map(|block| block.split("```").next())
        .filter(|block| block.contains("int main"))
        .collect();
    assert_eq!(programs.len(), 2, "README.md has a C example with main() for the buffer and the cursor");
    assert!(programs[1].contains("cycleref_cursor_next"));
    for (i, code) in programs.into_iter().enumerate() {
        let source = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cycleref_ffi_readme{i}.c"));
        std::fs::write(&source, code).expect("write the README example");
        let stdout = run(&build_c(&source, &format!("cycleref_ffi_readme{i}")), &[]);
        let lines: Vec<_> = stdout.lines().collect();
        assert_eq!(lines.len(), 30, "{stdout}");
        assert_eq!(
            lines[..5],
            [
                "G00 X64400 Z8961",
                "G32 X64400 Z-59000 (sync)",
                "G32 X70400 Z-62000",
                "G00 X80000 Z-62000",
                "G00 X80000 Z10000"
            ]
        );
    }
}

/// The header is also valid C++ (it has `extern "C"` guards and typed
/// enums there). Skipped when there is no C++ compiler.
#[test]
fn header_compiles_as_cpp() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let cxx = std::env::var("CXX").unwrap_or_else(|_| "c++".into());
    let source = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cycleref_header_check.cpp");
    std::fs::write(
        &source,
        "#include \"cycleref.h\"\nint main() { CyclerefMove m{}; return m.motion == CYCLEREF_MOTION_RAPID ? 0 : 1; }\n",
    )
    .expect("write the C++ check");
    let Ok(output) = Command::new(&cxx)
        .args(["-std=c++11", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", "-I"])
        .arg(manifest.join("include"))
        .arg(&source)
        .output()
    else {
        eprintln!("no C++ compiler `{cxx}`: skipped");
        return;
    };
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
}
