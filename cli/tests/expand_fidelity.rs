//! The expansion is the program as the control runs it (issue 30): every
//! word of a cycle's blocks is kept (reading R-AUXWORDS), and for every
//! program the reader accepts, the checked-in corpus and every example,
//! `expand(expand(P)) = expand(P)` byte for byte and `check(P, expand(P))`
//! agrees.
//!
//! The expected blocks are worked by hand from the programs: the auxiliary
//! words come, in the block's order, as a block of their own before the
//! cycle's moves, and M30 after them.

use cycleref_cli::{check, output, Format, Job};
use cycleref_spec::pipeline::Engine;
use cycleref_spec::{Machine, ProfileName};
use serde_json::Value;

fn expand(name: &str, text: &[u8], machine: &Machine) -> Result<String, String> {
    let job = Job::new(name, text.to_vec(), machine.clone(), Engine::Impl);
    let mut out = Vec::new();
    output::expand(&job, Format::Nc, &mut out).map_err(String::from)?;
    Ok(String::from_utf8_lossy(&out).into_owned())
}

/// The two properties for one program; `Ok(false)` when the reader refuses
/// it (nothing to hold).
fn holds(name: &str, text: &[u8], machine: &Machine) -> Result<bool, String> {
    let Ok(once) = expand(name, text, machine) else { return Ok(false) };
    let twice = expand(name, once.as_bytes(), machine).map_err(|e| format!("{name}: read back: {e}"))?;
    if twice != once {
        let at = once.lines().zip(twice.lines()).position(|(a, b)| a != b);
        return Err(format!("{name}: expand(expand(P)) differs from expand(P) at line {at:?}"));
    }
    let job = Job::new(name, text.to_vec(), machine.clone(), Engine::Impl);
    let report = check::check_bytes(&job, once.as_bytes(), false, 0).map_err(|e| format!("{name}: {e}"))?;
    if !report.agree() {
        return Err(format!("{name}: check(P, expand(P)) differs:\n{}", report.text()));
    }
    Ok(true)
}

#[test]
fn words_of_cycle_blocks_are_kept_where_the_control_runs_them() {
    let m = Machine::new(ProfileName::Gsk980);
    let p = "G50 X100 Z50\nG00 X80 Z10\nG32 Z-20 F2 M03 S500\nG00 X100\nM30\n";
    let e = expand("g32.nc", p.as_bytes(), &m).expect("expands");
    assert_eq!(e, "G50 X100 Z50\nG00 X80 Z10\nM03 S500\nG32 X80.000 Z-20.000 F2.0\nG00 X100\nM30\n");
    // The 988TA's M68x6 with a tool, coolant and a new speed on its blocks,
    // and the program end on the block after it.
    let m = Machine::new(ProfileName::Gsk988);
    let p = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 T0202 M08\n\
             G76 X60.64 Z-62 P3.680 Q1.800 F6 M09 S600 T0303\nG00 X100 Z50\nM30\n";
    let e = expand("g76.nc", p.as_bytes(), &m).expect("expands");
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(
        &lines[..5],
        [
            "G50 X100 Z50 M3 S300",
            "G00 X80 Z10",
            "T0202 M08",
            "M09 S600 T0303",
            "(G76 line 4: 4 rough + 2 finish passes x 1 start)"
        ]
    );
    // M30 on the cycle block: after its moves (the last is the return to A).
    let p = "G50 X100 Z50\nG00 X80 Z10\nG32 Z-20 F2 M30 M03 S500\n";
    let e = expand("end.nc", p.as_bytes(), &Machine::new(ProfileName::Gsk980)).expect("expands");
    assert_eq!(e, "G50 X100 Z50\nG00 X80 Z10\nM03 S500\nG32 X80.000 Z-20.000 F2.0\nM30\n");
    for (name, text, m) in [
        ("g32.nc", "G50 X100 Z50\nG00 X80 Z10\nG32 Z-20 F2 M03 S500\nG00 X100\nM30\n", ProfileName::Gsk980),
        ("g76.nc", p, ProfileName::Gsk980),
    ] {
        assert!(holds(name, text.as_bytes(), &Machine::new(m)).expect("holds"));
    }
}

#[test]
fn every_example_reads_back_as_itself_and_agrees() {
    let dir = format!("{}/../examples", env!("CARGO_MANIFEST_DIR"));
    let mut n = 0;
    for entry in std::fs::read_dir(&dir).expect("examples") {
        let path = entry.expect("entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        let profile = match name.split(['-', '.']).next() {
            Some("fanuc") => ProfileName::Fanuc,
            Some("gsk980") => ProfileName::Gsk980,
            Some("linuxcnc") => ProfileName::LinuxCnc,
            _ => ProfileName::Gsk988,
        };
        let mut machine = Machine::new(profile);
        // Written for IS-C, as their comments say (and `cli/tests/expand.rs`
        // runs them).
        if matches!(name.as_str(), "gsk980-g75-seed.nc" | "gsk980-m68x6.nc" | "gsk980-g32-taper.nc") {
            machine.increment = cycleref::IncrementSystem::IsC;
        }
        let text = std::fs::read(&path).expect("reads");
        assert!(holds(&name, &text, &machine).expect("the properties hold"), "{name} is refused");
        n += 1;
    }
    assert_eq!(n, 15, "every example");
}

/// Every case of the checked-in corpus: its file name, program and machine.
fn corpus() -> Vec<(String, Vec<u8>, Machine)> {
    let dir = format!("{}/../vectors", env!("CARGO_MANIFEST_DIR"));
    let mut cases = Vec::new();
    for entry in std::fs::read_dir(&dir).expect("corpus") {
        let path = entry.expect("entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        if !name.starts_with("case-") {
            continue;
        }
        let case: Value =
            serde_json::from_str(&std::fs::read_to_string(&path).expect("reads")).expect("json");
        let profile: ProfileName = case["profile"].as_str().expect("profile").parse().expect("a profile");
        let mut machine = Machine::new(profile);
        machine.apply_toml(case["machine_toml"].as_str().expect("toml")).expect("machine");
        cases.push((name, case["program"].as_str().expect("program").as_bytes().to_vec(), machine));
    }
    cases
}

#[test]
fn every_accepted_case_of_the_corpus_reads_back_as_itself_and_agrees() {
    let (mut accepted, mut refused) = (0, 0);
    let mut failures = Vec::new();
    for (name, program, machine) in corpus() {
        match holds(&name, &program, &machine) {
            Ok(true) => accepted += 1,
            Ok(false) => refused += 1,
            Err(e) => failures.push(e),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(accepted >= 60 && refused >= 30, "{accepted} accepted, {refused} refused");
}

/// Every way of changing one move of `nc` (an expansion), each a new text:
/// a coordinate's or a lead's last digit changed (one increment for the
/// expansion's numbers), the kind of a move changed, an arc's direction
/// flipped, a move deleted, a move repeated after the next one (the tool
/// goes back), and a word the trace reader does not model added.
fn mutations(nc: &str) -> Vec<(String, String)> {
    let lines: Vec<&str> = nc.lines().collect();
    // A line that moves: a motion G code, or a modal block of X, Z, U or W.
    let is_move = |l: &str| {
        !l.starts_with('(')
            && l.split(' ').any(|w| w.starts_with(['X', 'Z', 'U', 'W']))
            && !l.split(' ').any(|w| matches!(w, "G50" | "G04" | "G4"))
    };
    let moves: Vec<usize> = (0..lines.len()).filter(|&i| is_move(lines[i])).collect();
    let with = |i: usize, new: Option<String>, extra: Option<(usize, String)>| -> String {
        let mut out = String::new();
        for (j, l) in lines.iter().enumerate() {
            if j == i {
                if let Some(n) = &new {
                    out.push_str(n);
                    out.push('\n');
                }
            } else {
                out.push_str(l);
                out.push('\n');
            }
            if let Some((k, t)) = &extra {
                if *k == j {
                    out.push_str(t);
                    out.push('\n');
                }
            }
        }
        out
    };
    // The last digit of the number after `letter` changed by one.
    let nudge = |line: &str, letter: char| -> Option<String> {
        let at = line.find(&format!(" {letter}"))? + 2;
        let end = line[at..].find(' ').map_or(line.len(), |e| at + e);
        let last = line[..end].char_indices().rev().find(|(_, c)| c.is_ascii_digit())?.0;
        let d = line.as_bytes()[last];
        let new = if d == b'9' { b'8' } else { d + 1 };
        Some(format!("{}{}{}", &line[..last], char::from(new), &line[last + 1..]))
    };
    let mut out = Vec::new();
    // A sample of the moves: the first 6 and every 7th.
    for (n, &i) in moves.iter().enumerate().filter(|(n, _)| *n < 6 || n % 7 == 0) {
        let l = lines[i];
        let point = |l: &str| -> Vec<Option<f64>> {
            ['X', 'Z']
                .iter()
                .map(|c| {
                    let at = l.find(&format!(" {c}"))? + 2;
                    let end = l[at..].find(' ').map_or(l.len(), |e| at + e);
                    l[at..end].parse::<f64>().ok()
                })
                .collect()
        };
        // A move of no length (LinuxCNC's G76 ends with one): its kind and
        // its presence do not shape the toolpath.
        let zero = n > 0 && point(lines[moves[n - 1]]) == point(l) && point(l).iter().all(Option::is_some);
        for letter in ['X', 'Z', 'I', 'K'] {
            if let Some(m) = nudge(l, letter) {
                out.push((format!("line {} {letter}±1: {m}", i + 1), with(i, Some(m), None)));
            }
        }
        if l.starts_with("G32 ") {
            if let Some(m) = nudge(l, 'F') {
                out.push((format!("line {} lead: {m}", i + 1), with(i, Some(m), None)));
            }
            out.push((format!("line {} kind", i + 1), with(i, Some(l.replacen("G32 ", "G01 ", 1)), None)));
        }
        if l.starts_with("G00 ") && !zero {
            out.push((format!("line {} kind", i + 1), with(i, Some(l.replacen("G00 ", "G01 ", 1)), None)));
        }
        for (a, b) in [("G02 ", "G03 "), ("G03 ", "G02 ")] {
            if l.starts_with(a) {
                out.push((format!("line {} arc", i + 1), with(i, Some(l.replacen(a, b, 1)), None)));
            }
        }
        // Deleted, unless the next move goes to the same point (then the
        // toolpath is the same: the next one makes the move).
        if !zero && moves.get(n + 1).is_none_or(|&next| point(lines[next]) != point(l)) {
            out.push((format!("line {} deleted", i + 1), with(i, None, None)));
        }
        out.push((format!("line {} A1 added", i + 1), with(i, Some(format!("{l} A1")), None)));
        // Repeated after the next move, when that one goes elsewhere.
        // Only between moves to whole points (X and Z absolute), so the
        // detour is a move; and not to a corner of the next diagonal rapid,
        // which R-CHECKSPLIT lets a trace split (the same toolpath).
        let whole = |l: &str| point(l).iter().all(Option::is_some);
        if let Some(&next) = moves.get(n + 1).filter(|&&k| whole(l) && whole(lines[k])) {
            let (p, q) = (point(l), point(lines[next]));
            let after = moves.get(n + 2).map(|&k| point(lines[k]));
            let corner = after
                .as_ref()
                .is_some_and(|r| (p[0] == r[0] && p[1] == q[1]) || (p[0] == q[0] && p[1] == r[1]));
            if p != q && after != Some(p.clone()) && !corner {
                out.push((
                    format!("line {} repeated after line {}", i + 1, next + 1),
                    with(usize::MAX, None, Some((next, l.to_string()))),
                ));
            }
        }
    }
    out
}

#[test]
fn no_single_change_of_a_move_agrees() {
    // Issue 29: for the corpus's accepted programs, every
    // change of one move of the expansion is a DIFFER or an error, never
    // AGREE (tolerance 0).
    let programs = corpus();
    let (mut tried, mut programs_tried) = (0, 0);
    for (name, text, machine) in &programs {
        let Ok(nc) = expand(name, text, machine) else { continue };
        programs_tried += 1;
        let job = Job::new(name, text.clone(), machine.clone(), Engine::Impl);
        for (what, trace) in mutations(&nc) {
            tried += 1;
            if let Ok(report) = check::check_bytes(&job, trace.as_bytes(), false, 0) {
                assert!(!report.agree(), "{name}: {what}: check says AGREE");
            }
        }
    }
    eprintln!("{tried} single changes of {programs_tried} programs' expansions: none agrees");
    assert!(programs_tried >= 60 && tried >= 3000, "{programs_tried} programs, {tried} changes");
}

#[test]
fn the_program_ends_at_m30_and_subprograms_run_where_they_are_called() {
    // Issue 30, found 2. Reading R-PROGRAMEND: blocks after M02/M30 are
    // not run, so not expanded, not echoed and not read (an error there is
    // no error). Reading R-SUBPROGRAM: a call is replaced by the
    // subprogram's blocks (the call was echoed and the subprogram expanded
    // once, in its place after M30).
    let m = Machine::new(ProfileName::Gsk988);
    let p = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM30\nO1000\nG76 P020560 Q0.150 R0.1\n\
             G76 X60.64 Z-62 P3.680 Q1.800 F6\nG01 X1 X2\nM99\n";
    assert_eq!(
        expand("end.nc", p.as_bytes(), &m).expect("expands"),
        "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM30\n"
    );
    // M30 on a cycle's block: the cycle runs, then the program ends.
    let p = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG32 Z-20 F2 M30\nG00 X1 X2\n";
    assert_eq!(
        expand("g32-end.nc", p.as_bytes(), &Machine::new(ProfileName::Gsk980)).expect("expands"),
        "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG32 X80.000 Z-20.000 F2.0\nM30\n"
    );
    // The program: the control cuts the thread twice, from X80 and
    // from X90; its expansion is that of the program written out by hand
    // (but for the header comments, which name the cycle's line in the
    // file: line 9 both times with the call).
    let with_calls = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM98 P1000\nG00 X90\nM98 P1000\nM30\nO1000\n\
                      G76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM99\n";
    let written_out = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n\
                       G76 X60.64 Z-62 P3.680 Q1.800 F6\nG00 X90\nG76 P020560 Q0.150 R0.1\n\
                       G76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n";
    let ours = expand("sub.nc", with_calls.as_bytes(), &m).expect("expands");
    let theirs = expand("inline.nc", written_out.as_bytes(), &m).expect("expands");
    let headers =
        |s: &str| s.lines().filter(|l| l.starts_with("(G76 line")).map(str::to_string).collect::<Vec<_>>();
    let body = |s: &str| s.lines().filter(|l| !l.starts_with("(G76 line")).collect::<Vec<_>>().join("\n");
    assert_eq!(body(&ours), body(&theirs));
    assert_eq!(
        headers(&ours),
        [
            "(G76 line 9: 4 rough + 2 finish passes x 1 start)",
            "(G76 line 9: 4 rough + 2 finish passes x 1 start)"
        ]
    );
    assert_eq!(ours.matches("G00 X90.000 Z10.000").count(), 6, "{ours}");
    // The expansion reads back as itself (no call is left in it), and a
    // check of the program against it agrees.
    assert_eq!(expand("again.nc", ours.as_bytes(), &m).expect("expands"), ours);
    let job = Job::new("sub.nc", with_calls.as_bytes().to_vec(), m.clone(), Engine::Impl);
    assert!(check::check_bytes(&job, ours.as_bytes(), false, 0).expect("checks").agree());
    // From a file (read a piece at a time, the subprograms read again from
    // its start) as from memory.
    let from_file = |program: &str, profile: &str| -> String {
        let path =
            std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("subprograms-{profile}.nc"));
        std::fs::write(&path, program).expect("write");
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_cycleref"))
            .args(["expand", "--profile", profile])
            .arg(&path)
            .output()
            .expect("runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    assert_eq!(from_file(with_calls, "gsk988"), ours);
    // Subprograms before the main program (called, not run as it) and
    // after it, from a file (the main program's start found by a second
    // reading, the file read from there) and from memory: the executed
    // blocks, echoed, worked out by hand.
    let before_and_after = "%\nO1000\nG00 U-2\nM98 P2000\nM99\nO2000\nG00 W-1\nM99\nO0001\nG50 X100 Z10\n\
                            M03 S500\nG00 X80 Z5\nM98 P1000\nG00 X90\nM98 P3000\nM30\nO3000\nG00 U-4\nM99\n%\n";
    let want = "O0001\nG50 X100 Z10\nM03 S500\nG00 X80 Z5\nG00 U-2\nG00 W-1\nG00 X90\nG00 U-4\nM30\n";
    let gsk980 = Machine::new(ProfileName::Gsk980);
    assert_eq!(expand("before.nc", before_and_after.as_bytes(), &gsk980).expect("expands"), want);
    assert_eq!(from_file(before_and_after, "gsk980"), want);
    // LinuxCNC's M2 ends the program too.
    let p = "G18 G21 G7\nM3 S500\nG0 X22 Z2\nM2\nG0 X1 X2\n";
    assert_eq!(
        expand("m2.ngc", p.as_bytes(), &Machine::new(ProfileName::LinuxCnc)).expect("expands"),
        "G18 G21 G7\nM3 S500\nG0 X22 Z2\nM2\n"
    );
}
