//! Subprograms (reading R-SUBPROGRAM): the executed sequence of a program
//! with M98/M99, worked out by hand from the call rules the FANUC and GSK
//! manuals give (M98 P: the last four digits the program, the digits
//! before them the number of runs; M99 returns after the call), and each
//! error with its line, word and kind.

use cycleref_spec::reader::{Item, Reader, SubprogramError};
use cycleref_spec::{ErrorKind, Machine, ProfileName, ProgramError};

fn gsk980() -> Machine {
    Machine::new(ProfileName::Gsk980)
}

/// An item's line and, for a move, its end point (X, Z in increments).
type Run = (usize, Option<i64>, Option<i64>);

/// The line and end point of every item, in the order the reader gives
/// them, or the first error.
fn run(program: &str, machine: &Machine) -> Result<Vec<Run>, ProgramError> {
    let mut out = Vec::new();
    for item in Reader::new(program.as_bytes(), machine) {
        match item? {
            Item::Move(m) => out.push((m.block.line, m.to.0, m.to.1)),
            Item::Source(b) => out.push((b.line, None, None)),
            _ => out.push((0, None, None)),
        }
    }
    Ok(out)
}

fn error(program: &str, machine: &Machine) -> ProgramError {
    run(program, machine).expect_err("the program is refused")
}

/// Two calls from the main program, one with two runs; a nested call.
/// Executed by hand: lines 1, 2, 3, then O1000 (9, then O2000's 13), 5,
/// then O1000 twice, 7 (M30). X is a diameter in IS-B increments.
const NESTED: &str = "G50 X100 Z10
M03 S500
G00 X80 Z5
M98 P1000
G00 X90
M98 P21000
M30
O1000
G00 U-2
M98 P2000
M99
O2000
G00 W-1
M99
";

#[test]
fn calls_run_the_subprogram_in_their_place_repeated_and_nested() {
    // The same call rules on every FANUC and GSK profile (FANUC reads a
    // length without a point in increments: written with points there).
    for (profile, program) in [
        (ProfileName::Gsk980, NESTED.to_string()),
        (ProfileName::Gsk988, NESTED.to_string()),
        (
            ProfileName::Fanuc,
            NESTED
                .replace("X100 Z10", "X100. Z10.")
                .replace("X80 Z5", "X80. Z5.")
                .replace("X90", "X90.")
                .replace("U-2", "U-2.")
                .replace("W-1", "W-1."),
        ),
    ] {
        let got = run(&program, &Machine::new(profile)).unwrap();
        assert_eq!(got, nested_want(), "{profile:?}");
    }
}

fn nested_want() -> Vec<Run> {
    let want = vec![
        (1, None, None), // G50 sets the position: a block echoed, not a move
        (2, None, None),
        (3, Some(80_000), Some(5_000)),
        (9, Some(78_000), Some(5_000)),
        (13, Some(78_000), Some(4_000)),
        (5, Some(90_000), Some(4_000)),
        (9, Some(88_000), Some(4_000)),
        (13, Some(88_000), Some(3_000)),
        (9, Some(86_000), Some(3_000)),
        (13, Some(86_000), Some(2_000)),
        (7, None, None),
    ];
    want
}

#[test]
fn a_program_with_calls_reads_as_the_same_program_written_out() {
    // The program: the thread cut twice, from X80 and from X90.
    let with_calls = "G50 X100 Z10\nM03 S500\nG00 X80 Z5\nM98 P1000\nG00 X90 Z5\nM98 P1000\nM30\nO1000\n\
                      G76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\nM99\n";
    let written_out =
        "G50 X100 Z10\nM03 S500\nG00 X80 Z5\nG76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\n\
                       G00 X90 Z5\nG76 P020560 Q150 R0.1\nG76 X60.64 Z-62 P3680 Q1800 F6\nM30\n";
    let starts = |p: &str| -> Vec<(i64, i64)> {
        Reader::new(p.as_bytes(), &gsk980())
            .filter_map(|i| match i.unwrap() {
                Item::G76(c) => Some((c.cycle.start.x, c.cycle.start.z)),
                _ => None,
            })
            .collect()
    };
    assert_eq!(starts(with_calls), vec![(80_000, 5_000), (90_000, 5_000)]);
    assert_eq!(starts(with_calls), starts(written_out));
}

#[test]
fn blocks_after_the_end_that_no_call_reaches_are_not_read() {
    // O3000 is never called: its bad block is no error.
    let p = "G50 X100 Z10\nM98 P1000\nM30\nO1000\nG00 U-2\nM99\nO3000\nG00 X1 X2\nM99\n";
    let got = run(p, &gsk980()).unwrap();
    assert_eq!(got.iter().map(|r| r.0).collect::<Vec<_>>(), [1, 5, 3]);
}

#[test]
fn a_program_without_calls_reads_as_before() {
    let p = "G50 X100 Z10\nG00 U-2\nM30\nO1000\nG00 X1 X2\n";
    assert_eq!(run(p, &gsk980()).unwrap().len(), 3);
}

fn kind(e: &ProgramError) -> String {
    e.kind.stable_kind()
}

#[test]
fn each_error_names_its_line_word_and_kind() {
    let m = gsk980();
    let cases: &[(&str, usize, Option<&str>, &str)] = &[
        ("G50 X100 Z10\nM98 P1000\nM30\n", 2, Some("P1000"), "subprogram:not_found"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO2000\nM99\n", 2, Some("P1000"), "subprogram:not_found"),
        ("G50 X100 Z10\nM99\nM30\n", 2, Some("M99"), "subprogram:return_outside_subprogram"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nG00 U-2\n", 5, None, "subprogram:no_return"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nG00 U-2\nO2000\nM99\n", 6, None, "subprogram:no_return"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nM30\n", 5, Some("M30"), "subprogram:end_in_subprogram"),
        ("G50 X100 Z10\nG00 X1 M98 P1000\nM30\nO1000\nM99\n", 2, Some("G00"), "subprogram:word_beside"),
        ("G50 X100 Z10\nM98 P1000 L5\nM30\nO1000\nM99\n", 2, Some("L5"), "subprogram:word_beside"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nM99 P20\n", 5, Some("P20"), "subprogram:word_beside"),
        ("G50 X100 Z10\nM98\nM30\n", 2, Some("M98"), "subprogram:bad_call"),
        ("G50 X100 Z10\nM98 P1000.\nM30\nO1000\nM99\n", 2, Some("P1000."), "subprogram:bad_call"),
        ("G50 X100 Z10\nM98 P01000\nM30\nO1000\nM99\n", 2, Some("P01000"), "subprogram:bad_call"),
        ("G50 X100 Z10\nM98 P0\nM30\n", 2, Some("P0"), "subprogram:bad_call"),
        ("G50 X100 Z10\nM98 P123456789\nM30\n", 2, Some("P123456789"), "subprogram:bad_call"),
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nM99\nO1000\nM99\n", 6, None, "subprogram:defined_twice"),
        // Recursion: level 5 is one deeper than the default 4.
        ("G50 X100 Z10\nM98 P1000\nM30\nO1000\nM98 P1000\nM99\n", 5, Some("P1000"), "subprogram:too_deep"),
    ];
    for &(program, line, word, want) in cases {
        let e = error(program, &m);
        assert_eq!((e.line, e.word.as_deref(), kind(&e).as_str()), (line, word, want), "{program:?}: {e}");
    }
}

#[test]
fn the_nesting_depth_is_the_machines() {
    // O1000 -> O2000 -> O3000 -> O4000 -> O5000: five levels.
    let p =
        "G50 X100 Z10\nM98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nM98 P3000\nM99\nO3000\nM98 P4000\nM99\n\
             O4000\nM98 P5000\nM99\nO5000\nG00 U-2\nM99\n";
    let mut m = gsk980();
    let e = error(p, &m);
    assert_eq!((e.line, kind(&e).as_str()), (14, "subprogram:too_deep"));
    assert_eq!(
        e.to_string(),
        "line 14, word `P5000`: this call nests subprograms deeper than 4 levels (the control's limit; \
         `subprogram_nesting` in the parameter file)"
    );
    m.apply_toml("subprogram_nesting = 5").unwrap();
    assert_eq!(run(p, &m).unwrap().iter().map(|r| r.0).collect::<Vec<_>>(), [1, 17, 3]);
    assert!(m.apply_toml("subprogram_nesting = 11").is_err());
}

#[test]
fn the_blocks_run_in_subprograms_are_bounded_before_anything_is_written() {
    // 9999 x 9999 runs of one block: refused at the limit, not run.
    let p = "G50 X100 Z10\nM98 P99991000\nM30\nO1000\nM98 P99992000\nM99\nO2000\nG00 U0\nM99\n";
    let mut m = gsk980();
    m.apply_toml("subprogram_block_limit = 1000").unwrap();
    let e = error(p, &m);
    assert_eq!(kind(&e), "subprogram:too_many_blocks");
    assert!(e.to_string().contains("more than 1000 blocks"), "{e}");
    // The default limit holds too (a million blocks, then the error).
    let e = error(p, &gsk980());
    assert_eq!(kind(&e), "subprogram:too_many_blocks");
    assert!(matches!(e.kind, ErrorKind::Subprogram(SubprogramError::TooManyBlocks { limit: 1_000_000 })));
}

#[test]
fn a_trace_and_the_linuxcnc_dialect_still_refuse_m98() {
    let e = error("G00 X1 Z1\nM98 P1000\nM30\nO1000\nM99\n", &Machine::new(ProfileName::LinuxCnc));
    assert_eq!((e.line, kind(&e).as_str()), (2, "unsupported"));
    assert!(e.to_string().contains("R-SUBPROGRAM"), "{e}");
}

#[test]
fn the_line_fed_reader_without_subprograms_names_the_call() {
    let m = gsk980();
    let mut reader = cycleref_spec::LineReader::new(&m);
    let p = b"G50 X100 Z10\nM98 P1000\nM30\nO1000\nM99\n";
    let mut last = None;
    while let Some(item) = reader.next_in(p) {
        last = Some(item);
    }
    let e = last.unwrap().unwrap_err();
    assert_eq!((e.line, e.word.as_deref(), kind(&e).as_str()), (2, Some("M98"), "unsupported"));
}

/// Subprograms before the main program and after it (reading
/// R-SUBPROGRAM: the main program is the first that does not end with
/// M99). Executed by hand: O0001 from line 9 (its O block echoed), the
/// calls into O1000 (lines 3, then O2000's 7) and O3000 (line 18, after
/// the main program's M30).
const BEFORE_AND_AFTER: &str = "%
O1000
G00 U-2
M98 P2000
M99
O2000 (second level)
G00 W-1
M99
O0001
G50 X100 Z10
M03 S500
G00 X80 Z5
M98 P1000
G00 X90
M98 P3000
M30
O3000
G00 U-4
M99
%
";

#[test]
fn subprograms_before_the_main_program_are_called_not_run() {
    use cycleref_spec::reader::MainStart;
    assert_eq!(MainStart::of_text(BEFORE_AND_AFTER.as_bytes()), MainStart { offset: 63, lines_before: 8 });
    assert!(BEFORE_AND_AFTER[63..].starts_with("O0001\n"));
    let got = run(BEFORE_AND_AFTER, &gsk980()).unwrap();
    let want = vec![
        (9, None, None),
        (10, None, None),
        (11, None, None),
        (12, Some(80_000), Some(5_000)),
        (3, Some(78_000), Some(5_000)),
        (7, Some(78_000), Some(4_000)),
        (14, Some(90_000), Some(4_000)),
        (18, Some(86_000), Some(4_000)),
        (16, None, None),
    ];
    assert_eq!(got, want);
}

#[test]
fn the_main_program_starts_where_the_first_program_without_m99_starts() {
    use cycleref_spec::reader::MainStart;
    fn at(p: &str) -> (usize, &str) {
        let m = MainStart::of_text(p.as_bytes());
        (m.lines_before, &p[m.offset..])
    }
    // No O number: the main program starts after the subprograms' M99.
    let p = "O1000\nG00 U-2\nM99\nG50 X100 Z10\nM98 P1000\nM30\n";
    assert_eq!(at(p), (3, "G50 X100 Z10\nM98 P1000\nM30\n"));
    assert_eq!(run(p, &gsk980()).unwrap().iter().map(|r| r.0).collect::<Vec<_>>(), [4, 2, 6]);
    // A main program first, with or without an O number, subprograms after.
    assert_eq!(at("O0001\nG00 X1\nM98 P1000\nM30\nO1000\nM99\n").0, 0);
    assert_eq!(at("G00 X1\nM98 P1000\nM30\nO1000\nM99\n").0, 0);
    // A first program that runs into the next one without M99 or M30 is
    // the main program.
    assert_eq!(at("O0001\nG00 X1\nO1000\nM99\n").0, 0);
    // Only subprograms: no block runs.
    let p = "O1000\nG00 U-2\nM99\n";
    assert_eq!(at(p), (3, ""));
    assert!(run(p, &gsk980()).unwrap().is_empty());
    // M99 in a comment is no return (the byte search sees it; the reader
    // does not).
    assert_eq!(at("O0001\n(M99)\nG00 X1\nM30\n").0, 0);
}

fn linuxcnc() -> Machine {
    Machine::new(ProfileName::LinuxCnc)
}

/// LinuxCNC's o-word subroutines: each refusal where LinuxCNC 2.9's
/// `rs274` refuses (its message quoted), and the ones not followed here.
#[test]
fn linuxcnc_subroutines_refused_where_rs274_refuses_them() {
    let m = linuxcnc();
    let cases: &[(&str, usize, &str, &str)] = &[
        // rs274: "not in a subroutine definition: 'o100 endsub'".
        (
            "G18 G21 G7\nG0 X10 Z2\no100 endsub\nM2\n",
            3,
            "o100 endsub",
            "subprogram:return_outside_subprogram",
        ),
        // rs274: "Nested subroutine definition".
        (
            "o100 sub\no200 sub\no200 endsub\no100 endsub\nG18\nM2\n",
            2,
            "o200 sub",
            "subprogram:misplaced_definition",
        ),
        // rs274: "EOF in file ... seeking o-word: o<100>".
        ("G18 G21 G7\nG0 X10 Z2\no100 call\nM2\n", 3, "o100 call", "subprogram:not_found"),
        // rs274: "sub: o|100| found in illegal location" (called before
        // its definition, which the path then reaches).
        (
            "G18 G21 G7\nG0 X10 Z2\no100 call\nG0 X20\no100 sub\nG0 X5\no100 endsub\nM2\n",
            5,
            "o100 sub",
            "subprogram:misplaced_definition",
        ),
        // Not followed here: control flow, arguments, return values.
        ("G18\no100 if [1]\nG0 X1\no100 endif\nM2\n", 2, "o100 if", "subprogram:unfollowed"),
        ("G18\no100 call [2]\nM2\no100 sub\no100 endsub\n", 2, "o100 call", "subprogram:word_beside"),
        // A definition the file ends inside.
        ("G18\no100 sub\nG0 X1\n", 2, "o100 sub", "subprogram:no_return"),
    ];
    for &(program, line, word, want) in cases {
        let e = error(program, &m);
        assert_eq!(
            (e.line, e.word.as_deref(), kind(&e).as_str()),
            (line, Some(word), want),
            "{program:?}: {e}"
        );
    }
}

/// `n` subroutines, each calling the next; the last moves.
fn nested(n: usize) -> String {
    let mut p = String::new();
    for i in 1..=n {
        p += &format!("o{i} sub\n");
        p += &if i < n { format!("o{} call\n", i + 1) } else { "G0 X1\n".into() };
        p += &format!("o{i} endsub\n");
    }
    p + "G18 G21 G7\nG0 X10 Z2\no1 call\nM2\n"
}

#[test]
fn linuxcnc_nests_nine_calls_as_rs274_does() {
    // rs274 2.9 runs 9 nested calls and refuses the 10th: "Too many
    // subroutine levels".
    let m = linuxcnc();
    let lines: Vec<usize> = run(&nested(9), &m).unwrap().iter().map(|r| r.0).collect();
    // 27 lines of definitions (o9's G0 X1 on line 26), then G18, G0, the call, M2.
    assert_eq!(lines, [28, 29, 26, 31]);
    let e = error(&nested(10), &m);
    // The 10th call is o9's `o10 call`, line 3 × 9 - 1.
    assert_eq!((e.line, kind(&e).as_str()), (26, "subprogram:too_deep"));
}

#[test]
fn linuxcnc_m2_in_a_subroutine_ends_the_program() {
    // rs274: PROGRAM_END after the subroutine's G0 X1; G0 X30 never runs.
    let p = "o100 sub\nG0 X1\nM2\no100 endsub\nG18 G21 G7\nG0 X10 Z2\no100 call\nG0 X30\nM2\n";
    let lines: Vec<usize> = run(p, &linuxcnc()).unwrap().iter().map(|r| r.0).collect();
    assert_eq!(lines, [5, 6, 2, 3]);
}
