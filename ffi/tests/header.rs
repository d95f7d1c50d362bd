//! `include/cycleref.h` is what cbindgen generates from the crate today.
//!
//! Set `CYCLEREF_BLESS_HEADER=1` to write the regenerated header instead of
//! comparing (then review and commit it).

use std::path::Path;

#[test]
fn header_is_up_to_date() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("read cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let generated = String::from_utf8(generated).expect("the header is UTF-8");
    let path = dir.join("include/cycleref.h");
    if std::env::var_os("CYCLEREF_BLESS_HEADER").is_some() {
        std::fs::write(&path, &generated).expect("write include/cycleref.h");
        return;
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    if checked_in != generated {
        let first = checked_in
            .lines()
            .zip(generated.lines())
            .position(|(a, b)| a != b)
            .unwrap_or_else(|| checked_in.lines().count().min(generated.lines().count()));
        panic!(
            "ffi/include/cycleref.h is stale (first difference at line {}): regenerate it with \
             `CYCLEREF_BLESS_HEADER=1 cargo test -p cycleref-ffi --test header` and commit it.\n\
             --- generated ---\n{generated}",
            first + 1
        );
    }
}

/// The header's `CYCLEREF_VERSION` is the crate's version (issue 35: one
/// version across the crates, Python and C).
#[test]
fn the_header_names_the_crate_version() {
    let header = include_str!("../include/cycleref.h");
    let want = format!("#define CYCLEREF_VERSION \"{}\"", env!("CARGO_PKG_VERSION"));
    assert!(header.contains(&want), "include/cycleref.h lacks `{want}` (ffi/cbindgen.toml's after_includes)");
}
