//! `cycleref conform --pairs` (issue 35): a batch `check` of programs and
//! their traces. The programs are the repository's examples (so this file
//! runs in the repository, not from the package: `cli/Cargo.toml`
//! excludes it); the traces are `cycleref expand`'s own, one changed by
//! hand, so every verdict below follows from that change.

mod common;

use std::path::{Path, PathBuf};

use common::{conform, run};

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cycleref-conform-pairs-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir
}

fn testcases(junit: &Path) -> usize {
    std::fs::read_to_string(junit).expect("junit").matches("<testcase ").count()
}

#[test]
fn a_batch_check_of_pairs_in_shards() {
    // `conform --pairs`: a list of programs and their traces. The traces
    // are `cycleref expand`'s own (the vendor), one changed by hand: the
    // M68x6 example's rough pass 3 cut 36 increments deeper. Worked out:
    // the unchanged pairs pass, the changed one fails, and nothing else.
    let dir = scratch("pairs");
    let ex = |f: &str| format!("{}/../examples/{f}", env!("CARGO_MANIFEST_DIR"));
    let pairs =
        [("gsk988", "gsk988-m68x6.nc"), ("gsk980", "gsk980-g92-o0012.nc"), ("fanuc", "fanuc-external.nc")];
    let mut list = String::from("# program  trace  profile\n");
    for (i, (profile, file)) in pairs.iter().enumerate() {
        let o = run(&["expand", "--profile", profile, &ex(file)], None);
        assert!(o.status.success(), "{file}: {}", String::from_utf8_lossy(&o.stderr));
        let mut trace = String::from_utf8(o.stdout).expect("utf-8");
        if i == 0 {
            assert!(trace.contains("G32 X61.764 Z-59.000"));
            trace = trace.replacen("G32 X61.764 Z-59.000", "G32 X61.728 Z-59.000", 1);
        }
        std::fs::write(dir.join(format!("trace-{i}.nc")), trace).expect("write");
        // The third pair names no profile: --profile gives it.
        let profile = if i == 2 { "" } else { profile };
        list.push_str(&format!("{}\ttrace-{i}.nc\t{profile}\n", ex(file)).replace("\t\n", "\n"));
    }
    std::fs::write(dir.join("pairs.txt"), &list).expect("write");
    let junit = dir.join("pairs.xml");
    let (code, out, err) = conform(&[
        dir.join("pairs.txt").to_str().expect("utf-8"),
        "--pairs",
        "--profile",
        "fanuc",
        "--jobs",
        "2",
        "--junit",
        junit.to_str().expect("utf-8"),
    ]);
    assert_eq!(code, 1, "{out}{err}");
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2, "{out}");
    assert!(
        lines[0].starts_with("FAIL ") && lines[0].contains("gsk988-m68x6.nc") && lines[0].contains("DIFFER"),
        "{out}"
    );
    assert_eq!(
        lines[1],
        "conform --pairs: 3 cases: 2 passed, 1 failed, 0 refusals expected but not made, 0 refusals not expected, 0 errors"
    );
    assert_eq!(testcases(&junit), 3);
    // Shard 2 of 2 holds the second pair alone, which passes.
    let (code, out, err) =
        conform(&[dir.join("pairs.txt").to_str().expect("utf-8"), "--pairs", "--shard", "2/2"]);
    assert_eq!(code, 0, "{out}{err}");
    assert_eq!(
        out.trim(),
        "conform --pairs: 1 cases (shard 2/2): 1 passed, 0 failed, 0 refusals expected but not made, 0 refusals not \
         expected, 0 errors"
    );
    // A malformed line is an error naming it.
    std::fs::write(dir.join("bad.txt"), "a.nc\n").expect("write");
    let (code, _, err) = conform(&[dir.join("bad.txt").to_str().expect("utf-8"), "--pairs"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("bad.txt: line 1: a pair is two or three fields"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
