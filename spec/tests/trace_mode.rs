//! The reader's plain moves (`Item::Move`) and its trace mode
//! (`LineReader::for_trace`, readings R-CHECKWORDS and
//! R-CHECKPARTIAL): the one reader of programs and traces. Expected values
//! are worked by hand from the words (IS-B mm on gsk980: 1 increment =
//! 0.001 mm, X a diameter; IS-C on linuxcnc: 0.0001 mm).

use cycleref::XMode;
use cycleref_spec::reader::{Item, LineReader, MotionMode, PlainMove};
use cycleref_spec::{read, Machine, ProfileName, ProgramError};

/// The plain moves of `src` as (motion, from, to, x mode).
type Seen = (MotionMode, (Option<i64>, Option<i64>), (Option<i64>, Option<i64>), XMode);

fn moves(src: &str, profile: ProfileName) -> Vec<Seen> {
    let p = read(src, &Machine::new(profile)).unwrap_or_else(|e| panic!("{e}\n{src}"));
    p.items
        .iter()
        .filter_map(|i| match i {
            Item::Move(PlainMove { motion, from, to, x_mode, .. }) => Some((*motion, *from, *to, *x_mode)),
            _ => None,
        })
        .collect()
}

/// The items of a trace read a line at a time, or its first error.
fn trace(lines: &str, profile: ProfileName) -> Result<Vec<String>, ProgramError> {
    let machine = Machine::new(profile);
    let mut reader = LineReader::for_trace(&machine, machine.units());
    let mut out = Vec::new();
    for line in lines.lines() {
        while let Some(item) = reader.next_in(line.as_bytes()) {
            out.push(match item? {
                Item::Source(b) => format!("source {}", b.line),
                Item::Move(m) => format!("move {} {:?}", m.block.line, m.to),
                Item::G32(c) => format!("thread {} {:?} sync {}", c.block.line, c.g32.end, c.g32.sync),
                other => format!("other {}", other.block().line),
            });
        }
    }
    Ok(out)
}

#[test]
fn a_plain_block_is_a_typed_move_from_the_readers_state() {
    let got = moves(
        "G50 X100 Z50\nG00 X80 Z10\nG01 W-5 F0.2\nG02 U10 W-5 I5\nG04 P1000\nZ2\n",
        ProfileName::Gsk980,
    );
    let d = XMode::Diameter;
    assert_eq!(
        got,
        [
            (MotionMode::G00, (Some(100_000), Some(50_000)), (Some(80_000), Some(10_000)), d),
            (MotionMode::G01, (Some(80_000), Some(10_000)), (Some(80_000), Some(5_000)), d),
            (MotionMode::G02, (Some(80_000), Some(5_000)), (Some(90_000), Some(0)), d),
            // G04 is no move; the modal G02 moves the last block.
            (MotionMode::G02, (Some(90_000), Some(0)), (Some(90_000), Some(2_000)), d),
        ]
    );
    // Before both axes are known, an axis is None (R-CHECKPARTIAL).
    let got = moves("G00 X80\nG00 Z10\n", ProfileName::Gsk980);
    assert_eq!(got[0].1, (None, None));
    assert_eq!(got[0].2, (Some(80_000), None));
    assert_eq!(got[1].2, (Some(80_000), Some(10_000)));
}

#[test]
fn linuxcnc_moves_carry_the_x_mode_in_force() {
    // G8: X10 is a radius of 100 000 increments; G7 converts the held
    // position to a diameter (200 000), and X30 is a diameter.
    let got = moves("G18 G21 G8\nG0 X10 Z1\nG7\nG0 X30\n", ProfileName::LinuxCnc);
    assert_eq!(
        got,
        [
            (MotionMode::G00, (None, None), (Some(100_000), Some(10_000)), XMode::Radius),
            (MotionMode::G00, (Some(200_000), Some(10_000)), (Some(300_000), Some(10_000)), XMode::Diameter),
        ]
    );
}

#[test]
fn a_trace_is_read_by_the_program_reader_with_the_trace_rules() {
    // No spindle words are needed; M30 does not end a trace (what follows
    // it moved the tool and is compared); the G32 after a G32 continues
    // the synchronisation.
    let got = trace("G00 X80 Z10\nG32 Z-20 F2\nG32 X84 Z-21\nG00 X90\nM30\nG00 Z10\n", ProfileName::Gsk980)
        .expect("a trace");
    assert_eq!(
        got,
        [
            "move 1 (Some(80000), Some(10000))",
            "thread 2 Point { x: 80000, z: -20000 } sync true",
            "thread 3 Point { x: 84000, z: -21000 } sync false",
            "move 4 (Some(90000), Some(-21000))",
            "source 5",
            "move 6 (Some(90000), Some(10000))",
        ]
    );
    // The program's unit again is fine; another is refused.
    assert!(trace("G21\nG00 X80 Z10\n", ProfileName::Gsk980).is_ok());
    let e = trace("G20\nG00 X80 Z10\n", ProfileName::Gsk980).expect_err("G20");
    assert_eq!((e.line, e.word.as_deref()), (1, Some("G20")));
}

#[test]
fn what_a_trace_may_not_hold_is_refused_by_line_and_word() {
    for (src, line, word, text) in [
        ("G00 X80 Z10\nG92 X58 Z-20 F2\n", 2, "G92", "not canned cycles"),
        ("G00 X80 Z10\nG76 X60 Z-20 P1 Q0.5 F2\n", 2, "G76", "not canned cycles"),
        ("G00 X80 Z10 Y3\n", 1, "Y3", "R-CHECKWORDS"),
        ("G00 X80 Z10 Q3\n", 1, "Q3", "R-CHECKWORDS"),
        ("G00 X80 Z10\nG32 Z-20 F2 J1\n", 2, "J1", "write the run-out as its own block"),
        ("G00 X80 Z10\nG02 X90 Z0 R5\n", 2, "R5", "R-CHECKARC"),
        ("G00 X80 Z10\nM98 P1000\n", 2, "M98", "R-SUBPROGRAM"),
        ("G00 X80 U3 Z10\n", 1, "U3", ""),
        ("G00 U3\n", 1, "U3", "position is not known"),
    ] {
        let e = trace(src, ProfileName::Gsk980).expect_err(src);
        assert_eq!((e.line, e.word.as_deref()), (line, Some(word)), "{src}: {e}");
        assert!(e.to_string().contains(text), "{src}: {e}");
    }
    // The program reader echoes a Y word; the trace mode refuses it.
    assert!(read("G00 X80 Z10 Y3\n", &Machine::new(ProfileName::Gsk980)).is_ok());
    // LinuxCNC: G76 is a cycle; U is an axis of its own; G33 reads K.
    for (src, word) in [("G0 X10 Z1\nG76 P1 Z-5 I-0.5 J0.1 K0.3\n", "G76"), ("G0 X10 Z1 U2\n", "U2")] {
        let e = trace(src, ProfileName::LinuxCnc).expect_err(src);
        assert_eq!(e.word.as_deref(), Some(word), "{src}: {e}");
    }
    let got = trace("G18 G21\nG0 X10 Z1\nG33 Z-5 K1.5\n", ProfileName::LinuxCnc).expect("a G33 trace");
    assert_eq!(got.last().map(String::as_str), Some("thread 3 Point { x: 100000, z: -50000 } sync true"));
}
