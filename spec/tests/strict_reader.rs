//! The strict reader (issue 12): the findings' exact inputs, each asserting
//! the new behaviour, and a property test of arbitrary bytes through the
//! reader and both engines.

use std::borrow::Cow;

use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::reader::{Item, PlainMove};
use cycleref_spec::{ErrorKind, LineReader, Machine, ProfileName, ProgramError, Reader};
use proptest::prelude::*;

const PROFILES: [ProfileName; 3] = [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988];

/// Every item of `src`, or the first error.
fn read_bytes<'a>(src: &'a [u8], m: &Machine) -> Result<Vec<Item<'a>>, ProgramError> {
    Reader::new(src, m).collect()
}

fn gsk988() -> Machine {
    Machine::new(ProfileName::Gsk988)
}

fn error(src: &[u8], m: &Machine) -> ProgramError {
    match read_bytes(src, m) {
        Ok(_) => panic!("expected an error for {:?}", String::from_utf8_lossy(src)),
        Err(e) => e,
    }
}

/// The M68x6 program of the 988TA manual (O0013) up to its block 1.
const HEAD: &str = "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n";

#[test]
fn letter_o_for_zero_is_a_misplaced_word() {
    // Finding 1: `X6O.64` read as `X6` expanded a wrong thread.
    let src = format!("{HEAD}G76 X6O.64 Z-62 P3.680 Q1.800 F6\n");
    for profile in PROFILES {
        let m = Machine::new(profile);
        let src = if profile == ProfileName::Gsk988 {
            src.clone()
        } else {
            // P and Q in least increments elsewhere; the O is met first anyway.
            src.replace("Q0.150", "Q150")
        };
        let e = error(src.as_bytes(), &m);
        assert_eq!(
            (e.line, e.word.as_deref(), e.kind.name()),
            (4, Some("O.64"), "misplaced"),
            "{profile:?}: {e}"
        );
        let text = e.to_string();
        assert!(text.contains("program number O"), "{text}");
    }
}

#[test]
fn an_o_word_after_a_cycle_is_a_misplaced_word() {
    let e = error(format!("{HEAD}G76 X60.64 Z-62 P3.680 Q1.800 F6 O12\n").as_bytes(), &gsk988());
    assert_eq!((e.line, e.word.as_deref(), e.kind.name()), (4, Some("O12"), "misplaced"), "{e}");
    // Lower case is the same word.
    let e = error(format!("{HEAD}G76 X60.64 Z-62 P3.680 Q1.800 F6 o12\n").as_bytes(), &gsk988());
    assert_eq!((e.line, e.word.as_deref(), e.kind.name()), (4, Some("o12"), "misplaced"), "{e}");
}

#[test]
fn n_only_at_the_start_of_a_block() {
    let m = gsk988();
    // Inside a block: an error naming the word and the rule.
    for (src, line, word) in [
        ("G00 X80 N10 Z10\n", 1, "N10"),
        ("M03 S500\nG00 X80 Z10 N20\n", 2, "N20"),
        ("N10 N20 G00 X80\n", 1, "N20"),
        ("G00 X80; Z10 N30\n", 1, "N30"),
    ] {
        let e = error(src.as_bytes(), &m);
        assert_eq!(
            (e.line, e.word.as_deref(), e.kind.name()),
            (line, Some(word), "misplaced"),
            "{src:?}: {e}"
        );
        assert!(e.to_string().contains("a sequence number N may only start a block"), "{e}");
    }
    // At the start, after an optional `/`, and after a block end: fine.
    for src in
        ["N10 G00 X80\n", "/N10 G00 X80\n", "/ N10 G00 X80\n", "G00 X90; N10 G00 X80\n", "n10 g00 x80\n"]
    {
        let items = read_bytes(src.as_bytes(), &m).unwrap_or_else(|e| panic!("{src:?}: {e}"));
        let Some(Item::Move(PlainMove { block: b, .. })) = items.last() else { panic!("{src:?}: {items:?}") };
        // The N word is not one of the block's words; its text is echoed.
        assert!(!b.has('N'), "{src:?}");
        assert_eq!(b.get('X').expect("one X").map(|w| w.number().integer()), Some(Some(80)), "{src:?}");
    }
}

#[test]
fn o_only_alone_at_the_start_of_its_block() {
    let m = gsk988();
    let items = read_bytes(b"O0013 (prog)\nN10 G00 X80 Z10\n", &m).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(items.len(), 2);
    let Item::Source(b) = &items[0] else { panic!("{items:?}") };
    assert_eq!(b.text.as_ref(), b"O0013 (prog)");
    assert!(b.words.is_empty());
    // `O0013;` as the manuals write it, and `%` lines.
    assert!(read_bytes(b"%\nO0013;\nG00 X80 Z10;\n%\n", &m).is_ok());
    // Anything after the program number in its block is an error.
    let e = error(b"O12 G00 X10\n", &m);
    assert_eq!((e.line, e.word.as_deref(), e.kind.name()), (1, Some("O12"), "misplaced"), "{e}");
    assert!(e.to_string().contains("a program number O must stand in a block of its own"), "{e}");
    let e = error(b"M03 S500\nN5 O12\n", &m);
    assert_eq!((e.line, e.word.as_deref(), e.kind.name()), (2, Some("O12"), "misplaced"), "{e}");
}

#[test]
fn a_sixteen_digit_whole_number_gets_the_range_message() {
    // Finding 5: not "not a whole number of least increments".
    for profile in PROFILES {
        let m = Machine::new(profile);
        for word in
            ["X1234567890123456", "X-1234567890123456", "Z1234567890123456.0", "X12345678901234567890123"]
        {
            let e = error(format!("G00 {word}\n").as_bytes(), &m);
            let ErrorKind::OutOfRange { range } = &e.kind else { panic!("{profile:?} {word}: {e}") };
            // IS-B metric: 0.001 mm, the range table's bound is 999999.999.
            assert_eq!(range, "-999999.999..999999.999", "{profile:?} {word}");
            assert_eq!((e.line, e.word.as_deref()), (1, Some(word)));
        }
        // Finer than the increment: the increment's message, whatever the
        // number's size.
        for word in ["X1.0001", "X1234567890123456.0001"] {
            let e = error(format!("G00 {word}\n").as_bytes(), &m);
            assert_eq!(
                e.kind,
                ErrorKind::NotInIncrements { increment: "0.001 mm".into() },
                "{profile:?} {word}: {e}"
            );
        }
    }
    // In a cycle's own words too: P(k) on the 988TA.
    let e = error(format!("{HEAD}G76 X60.64 Z-62 P1234567890123456 Q1.800 F6\n").as_bytes(), &gsk988());
    assert_eq!((e.line, e.kind.name()), (4, "out_of_range"), "{e}");
}

#[test]
fn a_byte_order_mark_is_accepted_and_not_part_of_the_text() {
    let m = gsk988();
    let src = format!("\u{feff}{HEAD}G76 X60.64 Z-62 P3.680 Q1.800 F6\n");
    let items = read_bytes(src.as_bytes(), &m).unwrap_or_else(|e| panic!("{e}"));
    let Item::Source(first) = &items[0] else { panic!("{items:?}") };
    assert_eq!((first.line, first.text.as_ref()), (1, &b"M03 S500"[..]));
    assert_eq!(items.iter().filter_map(Cycle::of).map(|c| c.line()).collect::<Vec<_>>(), [4]);
    // Only at the start of the text: elsewhere it is a character the
    // reader does not know, named visibly.
    let e = error("G00 X80\n\u{feff}G00 Z10\n".as_bytes(), &m);
    assert_eq!((e.line, e.kind.name()), (2, "syntax"), "{e}");
}

#[test]
fn gbk_comments_are_kept_byte_for_byte() {
    let m = Machine::new(ProfileName::Gsk980);
    // 定位 ("positioning") and 螺纹 ("thread") in GBK.
    let src: &[u8] = b"(\xB6\xA8\xCE\xBB)\nM03 S500\nG00 X80 Z10 (\xC2\xDD\xCE\xC6)\nG32 Z-30 F2\n";
    let items = read_bytes(src, &m).unwrap_or_else(|e| panic!("{e}"));
    let texts: Vec<&[u8]> = items
        .iter()
        .filter(|i| matches!(i, Item::Source(_) | Item::Move(_)))
        .map(|i| i.block().text.as_ref())
        .collect();
    assert_eq!(texts, [&b"(\xB6\xA8\xCE\xBB)"[..], b"M03 S500", b"G00 X80 Z10 (\xC2\xDD\xCE\xC6)"]);
    let Item::Move(PlainMove { block: b, .. }) = &items[2] else { panic!() };
    // Borrowed from the source, not re-encoded.
    assert!(matches!(b.text, Cow::Borrowed(_)));
    assert_eq!(b.text_lossy(), "G00 X80 Z10 (\u{FFFD}\u{FFFD}\u{FFFD}\u{FFFD})");
    assert_eq!(items.iter().filter_map(Cycle::of).count(), 1);
}

#[test]
fn a_non_utf8_byte_outside_a_comment_names_its_line_and_byte_column() {
    let m = gsk988();
    // `G00 X2` is six bytes: the 0xB6 is the seventh.
    let e = error(b"G00 X10 Z0\nG00 X2\xB60 Z0\n", &m);
    assert_eq!((e.line, e.word.as_deref()), (2, None));
    assert_eq!(e.kind, ErrorKind::Encoding { column: 7, byte: 0xB6 });
    assert_eq!(
        e.to_string(),
        "line 2: byte 0xB6 at byte column 7 is not UTF-8 text (only a comment may hold text in another \
         encoding, such as GBK)"
    );
    // Columns count bytes, a GBK comment's and a UTF-8 character's included:
    // `G00 (` 5, the comment's two bytes 6-7, `) X2` 8-11, then 0xB6 at 12.
    let e = error(b"G00 (\xB6\xA8) X2\xB6\n", &m);
    assert_eq!((e.line, e.kind), (1, ErrorKind::Encoding { column: 12, byte: 0xB6 }));
    // `（` is three bytes: `G00 （a） ` is 4 + 3 + 1 + 3 + 1 = 12 bytes.
    let e = error("G00 （a） \u{0}".as_bytes(), &m);
    assert_eq!((e.line, e.kind.name()), (1, "syntax"), "{e}");
    let e = error("G00 （a） \x7F".as_bytes(), &m);
    assert_eq!(e.line, 1, "{e}");
    let e = error(b"G00 \xE4\xB8 X1\n", &m);
    assert_eq!(e.kind, ErrorKind::Encoding { column: 5, byte: 0xE4 });
    let mut src = "G00 （a） ".as_bytes().to_vec();
    src.push(0xFF);
    let e = error(&src, &m);
    assert_eq!(e.kind, ErrorKind::Encoding { column: 13, byte: 0xFF });
    // A lone continuation byte at the very start of a line.
    let e = error(b"M03 S500\r\n\x80G00\r\n", &m);
    assert_eq!((e.line, e.kind), (2, ErrorKind::Encoding { column: 1, byte: 0x80 }));
}

/// Pieces of programs: enough real words that cycles are reached, and any
/// byte at all.
fn piece() -> impl Strategy<Value = Vec<u8>> {
    const TOKENS: &[&str] = &[
        "M03 S500\n",
        "G00 X80 Z10\n",
        "G76 P020560 Q0.150 R0.1\n",
        "G76 P020560 Q150 R0.1\n",
        "G76 X60.64 Z-62 P3.680 Q1.800 F6\n",
        "G76 X60.64 Z-62 P3680 Q1800 F6\n",
        "G32 Z-30 F2\n",
        "G32 X38 Z-40 J1\n",
        "G75.1 X30 Z0 P2000 Q3000 H-6 D-8\n",
        "G75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011\n",
        "G01 ",
        "G00 ",
        "G20\n",
        "G50 X100 Z50\n",
        "X",
        "Z",
        "U",
        "W",
        "P",
        "Q",
        "R",
        "F",
        "I",
        "J",
        "K",
        "L",
        "E",
        "N",
        "O",
        "-",
        ".",
        "0",
        "1",
        "5",
        "9",
        "60",
        "0.001",
        " ",
        "\n",
        "\r\n",
        ";",
        "(",
        ")",
        "（",
        "）",
        "/",
        "%",
        "\u{feff}",
        "\u{3000}",
        "；",
    ];
    prop_oneof![
        4 => proptest::sample::select(TOKENS).prop_map(|t| t.as_bytes().to_vec()),
        1 => any::<u8>().prop_map(|b| vec![b]),
        1 => proptest::collection::vec(any::<u8>(), 0..6),
    ]
}

fn program() -> impl Strategy<Value = Vec<u8>> {
    proptest::collection::vec(piece(), 0..48).prop_map(|v| v.concat())
}

/// The items (or the error that ends them) of `data` fed to a
/// [`LineReader`] a line at a time through one reused buffer, as `Debug`
/// text: a file read line by line must read as the same text in memory.
fn line_by_line(data: &[u8], machine: &Machine) -> Vec<String> {
    let mut reader = LineReader::new(machine);
    let mut shown = Vec::new();
    let mut buf = Vec::new();
    for line in data.split_inclusive(|&b| b == b'\n') {
        buf.clear();
        buf.extend_from_slice(line);
        while let Some(item) = reader.next_in(&buf) {
            shown.push(format!("{item:?}"));
        }
    }
    if let Err(e) = reader.finish() {
        shown.push(format!("{:?}", Err::<Item<'_>, _>(e)));
    }
    shown
}

/// Reads `data` with every profile and expands every cycle with both
/// engines: no panic, errors on a line of the text, the engines agree.
fn run_all(data: &[u8]) -> Result<(), TestCaseError> {
    // LF, CR LF and a lone CR each end a line (reading R-LINEEND).
    let lone_cr = data.windows(2).filter(|w| w[0] == b'\r' && w[1] != b'\n').count()
        + usize::from(data.last() == Some(&b'\r'));
    let lines = data.iter().filter(|&&b| b == b'\n').count() + lone_cr + 1;
    for profile in PROFILES {
        let mut machine = Machine::new(profile);
        machine.pass_limit = 2_000;
        let whole: Vec<String> = Reader::new(data, &machine).map(|i| format!("{i:?}")).collect();
        prop_assert_eq!(&whole, &line_by_line(data, &machine), "{:?}", String::from_utf8_lossy(data));
        for item in Reader::new(data, &machine) {
            let item = match item {
                Ok(item) => item,
                Err(e) => {
                    prop_assert!(
                        e.line >= 1 && e.line <= lines,
                        "{profile:?}: line {} of {lines}: {e}",
                        e.line
                    );
                    // The message renders and starts with its position.
                    let shown = e.to_string();
                    prop_assert!(shown.starts_with(&format!("line {}", e.line)), "{shown}");
                    break;
                }
            };
            let Some(cycle) = Cycle::of(&item) else { continue };
            prop_assert!(cycle.line() >= 1 && cycle.line() <= lines);
            let ours = expand(cycle, Engine::Impl).map(|m| m.take(5_000).collect::<Vec<_>>());
            let reference = expand(cycle, Engine::Spec).map(|m| m.take(5_000).collect::<Vec<_>>());
            prop_assert_eq!(ours, reference, "{:?} {:?}", profile, String::from_utf8_lossy(data));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3_000, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_bytes_never_panic_and_the_engines_agree(data in program()) {
        run_all(&data)?;
    }

    #[test]
    fn arbitrary_bytes_after_a_valid_head(tail in program()) {
        let mut data = format!("{HEAD}G76 X60.64 Z-62 P3.680 Q1.800 F6\n").into_bytes();
        data.extend_from_slice(&tail);
        run_all(&data)?;
    }
}

#[test]
fn the_property_reaches_cycles() {
    // The generator is worth something only if programs with cycles that
    // both engines expand come out of it: the examples of each profile do.
    let m68 = format!("{HEAD}G76 X60.64 Z-62 P3.680 Q1.800 F6\n");
    let gsk980 = "M03 S500\nG00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\n\
                  G75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011\nG00 X40 Z2\nG32 Z-30 F2\nG32 X38 Z-40 J1\n";
    for (src, profile, cycles) in [(m68.as_str(), ProfileName::Gsk988, 1), (gsk980, ProfileName::Gsk980, 3)] {
        let m = Machine::new(profile);
        let items = read_bytes(src.as_bytes(), &m).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(items.iter().filter_map(Cycle::of).count(), cycles);
        run_all(src.as_bytes()).expect("agree");
    }
}

#[test]
fn percent_alone_on_its_line_and_slash_only_first() {
    let m = Machine::new(ProfileName::Gsk988);
    // Accepted: `%` lines (with a comment), `/` before the first word.
    for ok in ["%\nG00 X80 Z10\n%\n", "% (start)\nG00 X80 Z10\n", "/G00 X80 Z10\n", " / N10 G00 X80\n"] {
        assert!(read_bytes(ok.as_bytes(), &m).is_ok(), "{ok:?}");
    }
    // Refused, naming the mark and the rule (R-SEQNUM).
    for (bad, line, word) in [
        ("G00 X10 % Z5\n", 1, "%"),
        ("G00 X80 Z10\n% G00 X10\n", 2, "G00"),
        ("G00 X10 / Z5\n", 1, "/"),
        ("G00 X80 Z10; %\n", 1, "%"),
    ] {
        let e = error(bad.as_bytes(), &m);
        assert_eq!(
            (e.line, e.word.as_deref(), e.kind.name()),
            (line, Some(word), "misplaced"),
            "{bad:?}: {e}"
        );
    }
    assert!(error(b"G00 X10 % Z5\n", &m).to_string().contains("on a line of its own"));
    assert!(error(b"G00 X10 / Z5\n", &m).to_string().contains("block delete `/` may only start a block"));
}

/// R-ADDRESS: a word a cycle block does not define is refused, naming the
/// word, the block and the profile; the block's own words, the profile's
/// extras and M, S, T are accepted. The table is the one of
/// docs/INTERPRETATIONS.md (from the cycle formats of the seeds).
#[test]
fn each_cycle_block_accepts_exactly_its_addresses() {
    let fanuc = Machine::new(ProfileName::Fanuc);
    let gsk980 = Machine::new(ProfileName::Gsk980);
    let m988 = gsk988();
    let g76 = |block1: &str, block2: &str| format!("M03 S500\nG00 X80 Z10\n{block1}\n{block2}\n");
    let g75 = |block1: &str, block2: &str| format!("M03 S500\nG00 X40 Z5\n{block1}\n{block2}\n");
    let g32 = |block: &str| format!("M03 S500\nG00 X40 Z2\n{block}\n");
    let b1 = "G76 P020560 Q0.1 R0.05";
    let b2 = "G76 X60.64 Z-62 P3.68 Q1.8 F6";
    let b1_fanuc = "G76 P020560 Q100 R50";
    // GSK 980TDi: P(k) and Q in least increments (its state parameter).
    let (b1_980, b2_980) = ("G76 P020560 Q100 R0.05", "G76 X60.64 Z-62 P3680 Q1800 F6");
    let b2_fanuc = "G76 X60640 Z-62000 P3680 Q1800 F6";
    let g75_1 = "G75.1 X30 Z0 P2000 Q3000 H-6 D-8";
    let g75_2 = "G75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011";
    let refused: [(String, &Machine, &str, &str); 8] = [
        (g76(&format!("{b1} Y1"), b2), &m988, "Y1", "G76 block 1"),
        (g76(b1, &format!("{b2} H1")), &m988, "H1", "G76 block 2"),
        (g76(&format!("{b1_fanuc} L2"), b2_fanuc), &fanuc, "L2", "G76 block 1"),
        (g76(b1_fanuc, &format!("{b2_fanuc} J1")), &fanuc, "J1", "G76 block 2"),
        (g76(&format!("{b1_980} D1"), b2_980), &gsk980, "D1", "G76 block 1"),
        (g32("G32 Z-30 F2 J1"), &fanuc, "J1", "G32"),
        (g75(&format!("{g75_1} K1"), g75_2), &gsk980, "K1", "G75.1 block 1"),
        (g75(g75_1, &format!("{g75_2} Q1")), &gsk980, "Q1", "G75.1 block 2"),
    ];
    for (src, m, word, block) in &refused {
        let e = error(src.as_bytes(), m);
        assert_eq!(e.word.as_deref(), Some(*word), "{src}");
        match &e.kind {
            ErrorKind::AddressNotInProfile { cycle, .. } => assert_eq!(cycle, block, "{src}"),
            other => panic!("{src}: {other:?}"),
        }
    }
    let accepted: [(String, &Machine); 6] = [
        (g76(&format!("{b1} L2 E1 D1 M08"), &format!("{b2} J1 K1 S500 T0101")), &m988),
        (g76(&format!("{b1_980} J1 K1"), b2_980), &gsk980),
        (g76(&format!("{b1_fanuc} T0202"), &format!("{b2_fanuc} M08")), &fanuc),
        (g32("G32 Z-30 F2 J1 K1 Q90 S400"), &gsk980),
        (g32("G32 Z-30 F2 Q90 M08"), &fanuc),
        (g75(&format!("{g75_1} M08"), &format!("{g75_2} S300 T0303")), &gsk980),
    ];
    for (src, m) in &accepted {
        read_bytes(src.as_bytes(), m).unwrap_or_else(|e| panic!("{src}: {e}"));
    }
}
