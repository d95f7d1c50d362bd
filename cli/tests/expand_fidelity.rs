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

#[test]
fn every_accepted_case_of_the_corpus_reads_back_as_itself_and_agrees() {
    let dir = format!("{}/../vectors", env!("CARGO_MANIFEST_DIR"));
    let (mut accepted, mut refused) = (0, 0);
    let mut failures = Vec::new();
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
        let program = case["program"].as_str().expect("program");
        match holds(&name, program.as_bytes(), &machine) {
            Ok(true) => accepted += 1,
            Ok(false) => refused += 1,
            Err(e) => failures.push(e),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(accepted >= 60 && refused >= 30, "{accepted} accepted, {refused} refused");
}
