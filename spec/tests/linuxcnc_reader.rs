//! The reader's `linuxcnc` profile: LinuxCNC's G76 words, G7/G8, the
//! interpreter's conditions with its own wording, and the readings
//! R-LCNC-WORDS and R-LCNC-G7. Expected values are worked from the words by
//! hand; the interpreter's texts are those of `interp_check.cc` and
//! `interp_convert.cc` (LinuxCNC 2.9), and each refusal below was also
//! refused by `rs274` where the interpreter refuses it (noted).

use cycleref::linuxcnc::LinuxCncG76;
use cycleref::{CycleError, Field, InputUnit, Point, XMode};
use cycleref_spec::reader::Item;
use cycleref_spec::{read, ErrorKind, Machine, ProfileName, ProgramError};

fn machine() -> Machine {
    Machine::new(ProfileName::LinuxCnc)
}

fn cycles(src: &str) -> Vec<LinuxCncG76> {
    let p = read(src, &machine()).unwrap_or_else(|e| panic!("{e}\n{src}"));
    p.items
        .iter()
        .filter_map(|i| match i {
            Item::LinuxCncG76(c) => Some(c.cycle),
            _ => None,
        })
        .collect()
}

fn error(src: &str) -> ProgramError {
    read(src, &machine()).err().unwrap_or_else(|| panic!("expected an error for:\n{src}"))
}

const HEAD: &str = "G18 G21\nM3 S500\nG0 X10 Z1\n";

#[test]
fn words_as_the_interpreter_reads_them() {
    // IS-C mm, radius X (G8 at start): X10 = 100 000 increments.
    let c = cycles(&format!("{HEAD}G76 P1.25 Z-20 I-0.5 J0.1 R1.5 K0.6 Q29.5 H2 E1.2 L3\n"));
    let c = c[0];
    assert_eq!(c.x_mode, XMode::Radius);
    assert_eq!(c.units.unit, InputUnit::Metric);
    assert_eq!((c.start, c.end), (Point::new(100_000, 10_000), Point::new(100_000, -200_000)));
    assert_eq!((c.pitch.mantissa, c.pitch.scale), (125, 2));
    assert_eq!((c.peak_offset, c.initial_depth, c.full_depth), (-5_000, 1_000, 6_000));
    assert_eq!((c.degression, c.compound_angle, c.spring_passes), (15_000, 295_000, 2));
    assert_eq!((c.taper_distance, c.entry_taper, c.exit_taper), (12_000, true, true));
}

#[test]
fn defaults_and_lenient_values() {
    // R absent and R0.5 are 1 (l.5748); Q absent and Q-1 are 0 (l.5739);
    // E-1 is 0 (l.5755); H absent 0; L2 is the exit taper only; X sets the
    // end X. rs274 cuts these programs (docs/peers/lcnc-probes: r05, hneg).
    let c = cycles(&format!(
        "{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3\nG0 X10 Z1\nG76 P1 Z-5 I-0.5 J0.1 K0.3 R0.5 Q-1 E-1 L2 X12\n"
    ));
    assert_eq!((c[0].degression, c[0].compound_angle, c[0].spring_passes), (10_000, 0, 0));
    assert_eq!((c[1].degression, c[1].compound_angle, c[1].taper_distance), (10_000, 0, 0));
    assert_eq!((c[1].entry_taper, c[1].exit_taper), (false, true));
    assert_eq!(c[1].end, Point::new(120_000, -50_000));
    // H-1: no pass at full depth (read_h refuses only H < -1).
    assert_eq!(cycles(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3 H-1\n"))[0].spring_passes, -1);
}

#[test]
fn g7_and_g8() {
    // G7: X, I, J, K are diameters; the cycle keeps them as written.
    let c = cycles("G18 G21 G7\nM3 S500\nG0 X20 Z1\nG76 P1 Z-5 I-1 J0.2 K0.6\n")[0];
    assert_eq!(c.x_mode, XMode::Diameter);
    assert_eq!((c.start.x, c.peak_offset, c.initial_depth, c.full_depth), (200_000, -10_000, 2_000, 6_000));
    // The position moves with the mode: X10 in G8 is X20 in G7 and back.
    let c = cycles(
        "G18 G21 G8\nM3 S500\nG0 X10 Z1\nG7\nG76 P1 Z-5 I-1 J0.2 K0.6\nG8\nG76 P1 Z-6 I-1 J0.2 K0.6\n",
    );
    assert_eq!((c[0].start.x, c[0].x_mode), (200_000, XMode::Diameter));
    assert_eq!((c[1].start, c[1].x_mode), (Point::new(100_000, -50_000), XMode::Radius));
    // R-LCNC-G7: a mode change on the G76 line is refused (LinuxCNC halves
    // I J K twice there).
    let e = error("G18 G21 G8\nM3 S500\nG0 X10 Z1\nG7 G76 P1 Z-5 I-1 J0.2 K0.6\n");
    assert_eq!(e.line, 4);
    assert!(e.to_string().contains("scales I, J and K twice"), "{e}");
    // The same G7 when already in G7 changes nothing and is read.
    assert_eq!(cycles("G18 G21 G7\nM3 S500\nG0 X20 Z1\nG7 G76 P1 Z-5 I-1 J0.2 K0.6\n").len(), 1);
}

#[test]
fn the_interpreters_refusals_in_its_words() {
    let e = error(&format!("{HEAD}G76 Z-5 I-0.5 J0.1 K0.3\n"));
    assert_eq!(e.line, 4);
    assert!(e.to_string().contains("P word missing with G76"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I-0.5 K0.3\n"));
    assert!(e.to_string().contains("I J or K words missing with G76"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I0 J0.1 K0.3\n"));
    assert!(matches!(e.kind, ErrorKind::Cycle(CycleError::WordOutOfRange { field: Field::PeakOffset, .. })));
    assert!(e.to_string().contains("In G76, I must not be 0"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0 K0.3\n"));
    assert!(e.to_string().contains("In G76, J must be greater than 0"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.3 K0.3\n"));
    assert!(e.to_string().contains("In G76, K must be greater than J"), "{e}");
    let e = error("G18 G21\nG0 X10 Z1\nG76 P1 Z-5 I-0.5 J0.1 K0.3\n");
    assert!(e.to_string().contains("Chosen spindle (0) not turning in G76"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3 H-2\n"));
    assert!(e.to_string().contains("Negative H word used"), "{e}");
    let e = error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3 L-1\n"));
    assert!(e.to_string().contains("Negative L word used"), "{e}");
    // G76 stays the motion mode: an axis-only block runs it again without
    // its words (rs274: "P word missing with G76" at `Z-5`).
    let e = error(&format!("{HEAD}G76 P1 Z-10 I-0.5 J0.1 K0.3\nZ-5\n"));
    assert_eq!(e.line, 5);
    assert!(e.to_string().contains("P word missing with G76"), "{e}");
}

#[test]
fn what_the_profile_does_not_read() {
    // U and W are axes of their own in LinuxCNC, not incremental X and Z.
    let e = error(&format!("{HEAD}G0 U1\n"));
    assert_eq!(e.word.as_deref(), Some("U1"));
    let e = error(&format!("{HEAD}G33.1 Z-5 K1\n"));
    assert!(e.to_string().contains("G33.1"), "{e}");
    let e = error(&format!("{HEAD}G41\nG76 P1 Z-5 I-0.5 J0.1 K0.3\n"));
    assert_eq!((e.line, e.word.as_deref()), (4, Some("G41")));
    assert!(
        e.to_string().contains("Cannot use G76 threading cycle with cutter radius compensation on"),
        "{e}"
    );
    let e = error(&format!("{HEAD}G92 X10 Z1\n"));
    assert!(e.to_string().contains("the linuxcnc profile reads"), "{e}");
    // Q of 90 degrees or more, R above 100, a pitch of 0.
    assert!(error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3 Q90\n")).to_string().contains("-90 < Q < 90"));
    assert!(error(&format!("{HEAD}G76 P1 Z-5 I-0.5 J0.1 K0.3 R101\n")).to_string().contains("R <= 100"));
    assert!(error(&format!("{HEAD}G76 P0 Z-5 I-0.5 J0.1 K0.3\n")).to_string().contains("P > 0"));
}

#[test]
fn g33_blocks() {
    // G33 X Z K: one synchronised move, K per revolution along it (not
    // halved in G7); a G33 after a G33 continues the synchronisation.
    let src = "G18 G21 G7\nM3 S500\nG0 X20 Z1\nG33 X18 Z-5 K1.5\nG33 Z-8 K2\n";
    let p = read(src, &machine()).unwrap();
    let blocks: Vec<_> = p.threads().collect();
    assert_eq!(blocks.len(), 2);
    assert_eq!(blocks[0].code, "G33");
    let g = blocks[0].g32;
    assert_eq!(
        (g.start, g.end, g.x_mode),
        (Point::new(200_000, 10_000), Point::new(180_000, -50_000), XMode::Diameter)
    );
    assert_eq!((g.lead.mantissa, g.lead.scale, g.sync), (15, 1, true));
    // The second G33 follows the first: the synchronisation runs on.
    assert!(!blocks[1].g32.sync);
    assert_eq!(
        (blocks[1].g32.start, blocks[1].g32.end),
        (Point::new(180_000, -50_000), Point::new(180_000, -80_000))
    );
    // The interpreter's refusals (rs274 gives each of these texts).
    let e = error(&format!("{HEAD}G33 Z-5\n"));
    assert!(e.to_string().contains("K word missing with g33/g33.1"), "{e}");
    let e = error(&format!("{HEAD}G33 Z-5 K1 F1\n"));
    assert!(e.to_string().contains("F word used with a g33/g33.1"), "{e}");
    let e = error("G18 G21\nG0 X10 Z1\nG33 Z-5 K1\n");
    assert!(e.to_string().contains("Spindle not turning in G33"), "{e}");
    // Modal: an axis-only block runs G33 again and needs K.
    let e = error(&format!("{HEAD}G33 Z-5 K1\nZ-8\n"));
    assert_eq!(e.line, 5);
    assert!(e.to_string().contains("K word missing"), "{e}");
}

#[test]
fn a_g76_of_no_length_is_refused_at_its_z() {
    // Z is the current Z (written, or omitted): rs274 cuts G33 moves of no
    // length, which our reader refuses as G33 blocks (R-LCNC-G33), so the
    // cycle is refused where its expansion could not be read back.
    for (g76, word) in [("G76 P2 Z1 I-1 J0.5 K1", Some("Z1")), ("G76 P2 I-1 J0.5 K1", None)] {
        let e = error(&format!("{HEAD}{g76}\n"));
        assert_eq!(e.line, 4, "{e}");
        assert_eq!(e.word.as_deref(), word, "{e}");
        assert!(e.to_string().contains("a thread of no length"), "{e}");
    }
    // One increment of Z is a thread.
    assert_eq!(cycles(&format!("{HEAD}G76 P2 Z0.9999 I-1 J0.5 K1\n")).len(), 1);
}
