//! The program reader: awkward but legal text, modal state, profiles, and
//! every error with its line, word and rule.

use cycleref::{CycleError, G76Cycle, Infeed, Point, RunOut};
use cycleref_spec::profile::{Machine, RunOutRules};
use cycleref_spec::reader::{resolve_run_out, Item};
use cycleref_spec::{read, ErrorKind, ProfileName, ProgramError};

fn gsk988() -> Machine {
    Machine::new(ProfileName::Gsk988)
}

fn cycle(src: &str, m: &Machine) -> G76Cycle {
    let p = read(src, m).unwrap_or_else(|e| panic!("{e}"));
    let c = p.cycles().next().expect("a G76").cycle;
    c
}

fn error(src: &str, m: &Machine) -> ProgramError {
    match read(src, m) {
        Ok(_) => panic!("expected an error for:\n{src}"),
        Err(e) => e,
    }
}

const HEAD: &str = "M03 S500\nG00 X80 Z10\n";

#[test]
fn awkward_but_legal_text() {
    // Lower case, spaces inside words, words out of order, two blocks on one
    // line, full-width block end and comments, %, O and N numbers, blank
    // lines, block delete, explicit plus signs.
    let src = "%\nO0013 (program)\n\n n10 m3 s 300 ; g50 z50 x100\n/G00 Z+10 X 80；（起点）\n\
               g76 r0.1 q0.150 p020560\n   \nN60 F6 Q1.800 P3.680 Z-62 X60.64 g76 (thread)\nM30\n%\n";
    let p = read(src, &gsk988()).unwrap_or_else(|e| panic!("{e}"));
    let c = p.cycles().next().unwrap();
    assert_eq!(c.block.line, 8);
    assert_eq!(c.params_line, Some(6));
    let c = c.cycle;
    assert_eq!(c.start, Point::new(80_000, 10_000));
    assert_eq!(c.end, Point::new(60_640, -62_000));
    assert_eq!((c.thread_height, c.first_depth, c.min_cut, c.finishing_allowance), (3680, 1800, 150, 100));
    assert_eq!((c.finishing_passes, c.tool_angle), (2, 60));
    assert_eq!(c.run_out, RunOut::Chamfer { tenths_of_lead: 5, angle_degrees: 45, long: None });
    // The comment after the block end stays with its block when echoed.
    let texts: Vec<_> = p
        .items
        .iter()
        .filter(|i| matches!(i, Item::Source(_) | Item::Move(_)))
        .map(|i| i.block().text_lossy().into_owned())
        .collect();
    assert!(texts.iter().any(|t| t == "/G00 Z+10 X 80 （起点）"), "{texts:?}");
}

#[test]
fn incremental_end_point_and_taper() {
    // U/W are relative to A; R(i) is signed, radius.
    let c = cycle(&format!("{HEAD}G76 P010060 Q0.1 R0\nG76 U-20 W-70 R-1.5 P2 Q0.5 F2\n"), &gsk988());
    assert_eq!(c.end, Point::new(60_000, -60_000));
    assert_eq!(c.taper, -1500);
}

#[test]
fn modal_block1_values_persist() {
    let src = format!(
        "{HEAD}G76 P030060 Q0.2 R0.05\nG76 X60 Z-30 P2 Q0.5 F2\nG00 X80 Z10\nG76 X61 Z-30 P2 Q0.5 F2\n"
    );
    let p = read(&src, &gsk988()).unwrap();
    let cs: Vec<_> = p.cycles().collect();
    assert_eq!(cs.len(), 2);
    for c in &cs {
        assert_eq!((c.cycle.finishing_passes, c.cycle.min_cut, c.cycle.finishing_allowance), (3, 200, 50));
    }
    assert_eq!(cs[1].cycle.end.x, 61_000);
}

#[test]
fn parameters_replace_omitted_block1() {
    let mut m = gsk988();
    m.apply_toml(
        "[parameters]\n5142 = 4\n5143 = 55\n5140 = \"0.12\"\n5141 = \"0.05\"\n5130 = 10\n5131 = 30\n",
    )
    .unwrap();
    let c = cycle(&format!("{HEAD}G76 X60 Z-30 P2 Q0.5 F2\n"), &m);
    assert_eq!((c.finishing_passes, c.tool_angle, c.min_cut, c.finishing_allowance), (4, 55, 120, 50));
    assert_eq!(c.run_out, RunOut::Chamfer { tenths_of_lead: 10, angle_degrees: 30, long: None });
}

#[test]
fn parameter_file_errors_name_the_key() {
    let mut m = gsk988();
    assert!(m.apply_toml("[parameters]\n5140 = 0.1\n").unwrap_err().to_string().contains("strings"));
    assert!(m
        .apply_toml("[parameters]\n57 = 1\n")
        .unwrap_err()
        .to_string()
        .contains("not used by the gsk988"));
    assert!(m.apply_toml("colour = 1\n").unwrap_err().to_string().contains("colour"));
    m.apply_toml("profile = \"fanuc\"\nincrement = \"is-c\"\nunit = \"inch\"\nx = \"radius\"\n").unwrap();
    assert_eq!(m.profile.name, ProfileName::Fanuc);
}

#[test]
fn extended_words_d_l_e_apply_once() {
    let src = format!(
        "{HEAD}G76 P010060 Q0.1 R0 D2 L3 E0.5\nG76 X60 Z-30 P2 Q0.5 F2\nG00 X80 Z10\nG76 X60 Z-30 P2 Q0.5 F2\n"
    );
    let p = read(&src, &gsk988()).unwrap();
    let cs: Vec<_> = p.cycles().map(|c| c.cycle).collect();
    assert_eq!((cs[0].infeed, cs[0].starts, cs[0].lead_in), (Infeed::LeftRight, 3, 500));
    assert_eq!((cs[1].infeed, cs[1].starts, cs[1].lead_in), (Infeed::RightFlank, 1, 0));
}

#[test]
fn gsk980_partial_p_and_increment_units() {
    let mut m = Machine::new(ProfileName::Gsk980);
    m.increment = cycleref::IncrementSystem::IsC;
    // "P60": a only; m and r from No.57 and No.19.
    let c = cycle(&format!("{HEAD}G76 P60 Q1500 R0.1\nG76 X60.64 Z-62 P36800 Q18000 F6\n"), &m);
    assert_eq!((c.tool_angle, c.finishing_passes), (60, 1));
    assert_eq!((c.thread_height, c.first_depth, c.min_cut), (36_800, 18_000, 1_500));
    // "P0560": r and a.
    let c = cycle(&format!("{HEAD}G76 P0560\nG76 X60.64 Z-62 P36800 Q18000 F6\n"), &m);
    assert_eq!(c.run_out, RunOut::Chamfer { tenths_of_lead: 5, angle_degrees: 45, long: None });
}

#[test]
fn gsk980_jk_in_block1_are_one_shot() {
    let m = Machine::new(ProfileName::Gsk980);
    let src = format!(
        "{HEAD}G76 P020560 Q150 R0.1 J1 K2\nG76 X60 Z-30 P2000 Q500 F2\nG00 X80 Z10\nG76 X60 Z-30 P2000 Q500 F2\n"
    );
    let p = read(&src, &m).unwrap();
    let cs: Vec<_> = p.cycles().map(|c| c.cycle.run_out).collect();
    assert_eq!(cs[0], RunOut::Amounts { short: 1000, long: 2000 });
    assert_eq!(cs[1], RunOut::Chamfer { tenths_of_lead: 5, angle_degrees: 45, long: None });
}

#[test]
fn gsk988_jk_are_modal() {
    let src = format!("{HEAD}G76 X60 Z-30 P2 Q0.5 F2 J1\nG00 X80 Z10\nG76 X60 Z-30 P2 Q0.5 F2 K3\n");
    let p = read(&src, &gsk988()).unwrap();
    let cs: Vec<_> = p.cycles().map(|c| c.cycle.run_out).collect();
    // K omitted: a short-axis pull-out; then J stays 1 and K = 3 joins it.
    assert_eq!(cs[0], RunOut::Amounts { short: 1000, long: 0 });
    assert_eq!(cs[1], RunOut::Amounts { short: 1000, long: 3000 });
}

#[test]
fn run_out_rules_per_profile() {
    use RunOut::{Amounts, Chamfer};
    let ch = |long| Chamfer { tenths_of_lead: 5, angle_degrees: 45, long };
    // FANUC: only the chamfer.
    assert_eq!(resolve_run_out(RunOutRules::ChamferOnly, None, None, 5, 45), ch(None));
    assert_eq!(resolve_run_out(RunOutRules::ChamferOnly, None, None, 0, 45), RunOut::None);
    // 980TDi notes 1-4.
    let r = RunOutRules::Gsk980;
    assert_eq!(resolve_run_out(r, None, None, 5, 45), ch(None)); // note 1
    assert_eq!(resolve_run_out(r, None, Some(2), 5, 45), ch(Some(2))); // note 2
    assert_eq!(resolve_run_out(r, Some(3), None, 5, 45), Amounts { short: 3, long: 3 }); // note 3
    assert_eq!(resolve_run_out(r, Some(3), Some(0), 5, 45), Amounts { short: 3, long: 3 }); // note 3
    assert_eq!(resolve_run_out(r, Some(0), Some(4), 5, 45), RunOut::None); // note 4
    assert_eq!(resolve_run_out(r, Some(3), Some(4), 5, 45), Amounts { short: 3, long: 4 });
    // 988TA: seed 000 and the normal-mode G92 rules.
    let r = RunOutRules::Gsk988;
    assert_eq!(
        resolve_run_out(r, None, None, 5, 30),
        Chamfer { tenths_of_lead: 5, angle_degrees: 30, long: None }
    );
    assert_eq!(resolve_run_out(r, None, Some(2), 5, 45), RunOut::None); // J omitted
    assert_eq!(resolve_run_out(r, Some(0), Some(2), 5, 45), RunOut::None); // J = 0
    assert_eq!(resolve_run_out(r, Some(3), Some(0), 5, 45), RunOut::None); // J != 0, K = 0
    assert_eq!(resolve_run_out(r, Some(3), None, 5, 45), Amounts { short: 3, long: 0 }); // K omitted
    assert_eq!(resolve_run_out(r, Some(3), Some(4), 5, 45), Amounts { short: 3, long: 4 });
}

#[test]
fn fanuc_bare_values_are_increments_unless_calculator_input() {
    let f = Machine::new(ProfileName::Fanuc);
    let c =
        cycle("M03 S500\nG00 X26000 Z3000\nG76 P020560 Q100 R100\nG76 X21400 Z-26000 P1300 Q400 F2.0\n", &f);
    assert_eq!((c.start, c.finishing_allowance), (Point::new(26_000, 3_000), 100));
    let mut calc = f.clone();
    calc.apply_toml("calculator_input = true").unwrap();
    let c = cycle("M03 S500\nG00 X26 Z3\nG76 P020560 Q100 R0.1\nG76 X21.4 Z-26 P1300 Q400 F2.0\n", &calc);
    assert_eq!(c.start, Point::new(26_000, 3_000));
}

#[test]
fn inch_and_is_c() {
    let mut m = gsk988();
    m.increment = cycleref::IncrementSystem::IsC;
    let c = cycle(
        "G20\nM03 S500\nG00 X3.0 Z0.5\nG76 P010060 Q0.001 R0.0005\nG76 X2.5 Z-1.25 P0.05 Q0.02 I16\n",
        &m,
    );
    assert_eq!(c.units.decimals(), 5);
    assert_eq!((c.start, c.thread_height), (Point::new(300_000, 50_000), 5_000));
}

// ---- errors: each names the line, the word and the rule ----

fn kind_of(src: &str, m: &Machine) -> (usize, Option<String>, ErrorKind) {
    let e = error(src, m);
    (e.line, e.word, e.kind)
}

#[test]
fn missing_thread_height_and_first_depth_alarm() {
    let (line, _, kind) = kind_of(&format!("{HEAD}G76 X60 Z-30 Q0.5 F2\n"), &gsk988());
    assert_eq!(line, 3);
    assert!(matches!(kind, ErrorKind::Missing { what, .. } if what.starts_with("P(k)")));
    let (_, _, kind) = kind_of(&format!("{HEAD}G76 X60 Z-30 P2 F2\n"), &gsk988());
    assert!(matches!(kind, ErrorKind::Missing { what, .. } if what.starts_with("Q(Δd)")));
    let msg = error(&format!("{HEAD}G76 X60 Z-30 P2 F2\n"), &gsk988()).to_string();
    assert!(msg.starts_with("line 3: Q(Δd) (first depth) is missing"), "{msg}");
}

#[test]
fn note6_min_cut_or_allowance_above_height() {
    let e = error(&format!("{HEAD}G76 P010060 Q2.5 R0\nG76 X60 Z-30 P2 Q0.5 F2\n"), &gsk988());
    assert!(matches!(e.kind, ErrorKind::Cycle(CycleError::MinCutExceedsHeight { .. })), "{e}");
    assert!(e.to_string().contains("Q(Δdmin) = 2.500 is larger than the thread height P(k) = 2.000"), "{e}");
    let e = error(&format!("{HEAD}G76 P010060 Q0.1 R2.001\nG76 X60 Z-30 P2 Q0.5 F2\n"), &gsk988());
    assert!(matches!(e.kind, ErrorKind::Cycle(CycleError::AllowanceExceedsHeight { .. })), "{e}");
}

#[test]
fn note8_no_spindle_speed() {
    let e = error("G00 X80 Z10\nG76 P010060 Q0.1 R0\nG76 X60 Z-30 P2 Q0.5 F2\n", &gsk988());
    assert_eq!((e.line, e.kind), (3, ErrorKind::NoSpindleSpeed));
    // Stopped spindle.
    let e = error("M03 S300\nM05\nG00 X80 Z10\nG76 X60 Z-30 P2 Q0.5 F2\n", &gsk988());
    assert_eq!(e.kind, ErrorKind::NoSpindleSpeed);
    // G50 S alone is a clamp, not a speed.
    let e = error("M03\nG50 S2000\nG00 X80 Z10\nG76 X60 Z-30 P2 Q0.5 F2\n", &gsk988());
    assert_eq!(e.kind, ErrorKind::NoSpindleSpeed);
}

#[test]
fn face_thread_is_refused() {
    let e = error(&format!("{HEAD}G76 X40 W0 P2 Q0.5 F2\n"), &gsk988());
    assert_eq!(e.kind, ErrorKind::Cycle(CycleError::FaceThread));
    let e = error(&format!("{HEAD}G76 X40 P2 Q0.5 F2\n"), &gsk988());
    assert_eq!(e.kind, ErrorKind::Cycle(CycleError::FaceThread));
}

#[test]
fn values_outside_the_range_tables() {
    let m = gsk988();
    let (_, w, k) = kind_of(&format!("{HEAD}G76 P010060 L1000\nG76 X60 Z-30 P2 Q0.5 F2\n"), &m);
    assert_eq!(w.as_deref(), Some("L1000"));
    assert!(matches!(k, ErrorKind::OutOfRange { .. }));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 P010060 D3\nG76 X60 Z-30 P2 Q0.5 F2\n"), &m);
    assert_eq!(w.as_deref(), Some("D3"));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 P1010060\nG76 X60 Z-30 P2 Q0.5 F2\n"), &m);
    assert_eq!(w.as_deref(), Some("P1010060"));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 P000560\nG76 X60 Z-30 P2 Q0.5 F2\n"), &m);
    assert_eq!(w.as_deref(), Some("P000560")); // m = 0 on the 988TA (01..99)
    let (_, w, _) = kind_of(&format!("{HEAD}G76 X60 Z-30 P2 Q0.5 F10000\n"), &m);
    assert_eq!(w.as_deref(), Some("F10000"));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 X60 Z-30 P2 Q0.5 F0\n"), &m);
    assert_eq!(w.as_deref(), Some("F0"));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 X60 Z-30 P1000000 Q0.5 F2\n"), &m);
    assert_eq!(w.as_deref(), Some("P1000000"));
    let (_, w, _) = kind_of(&format!("{HEAD}G76 X60 Z-30 P2 Q0.5 F2 J-1\n"), &m);
    assert_eq!(w.as_deref(), Some("J-1"));
}

#[test]
fn fanuc_p_and_q_take_no_decimal_point() {
    let f = Machine::new(ProfileName::Fanuc);
    let e = error("M03 S500\nG00 X26.0 Z3.0\nG76 P020560 Q0.1 R0.1\n", &f);
    assert_eq!(e.word.as_deref(), Some("Q0.1"));
    assert!(matches!(e.kind, ErrorKind::DecimalPointNotAllowed { .. }));
    assert!(e.to_string().contains("least increments"), "{e}");
}

#[test]
fn values_finer_than_the_increment() {
    let e = error("M03 S500\nG00 X80.0001 Z10\n", &gsk988());
    assert_eq!(e.word.as_deref(), Some("X80.0001"));
    assert!(e.to_string().contains("0.001 mm"), "{e}");
    // GSK 980 with P/Q in increments: a fraction of an increment.
    let m = Machine::new(ProfileName::Gsk980);
    let e = error(&format!("{HEAD}G76 X60 Z-30 P2000.5 Q500 F2\n"), &m);
    assert_eq!(e.word.as_deref(), Some("P2000.5"));
}

#[test]
fn p_can_only_be_omitted_as_a_whole() {
    let e = error(&format!("{HEAD}G76 P0560 Q0.1\n"), &gsk988());
    assert_eq!((e.word.as_deref(), e.kind), (Some("P0560"), ErrorKind::PartialP));
}

#[test]
fn addresses_outside_the_profile() {
    let e = error(
        "M03 S500\nG00 X26.0 Z3.0\nG76 X21.4 Z-26.0 P1300 Q400 F2.0 J1\n",
        &Machine::new(ProfileName::Fanuc),
    );
    assert_eq!(e.word.as_deref(), Some("J1"));
    assert!(e.to_string().contains("not part of G76 block 2 on the fanuc profile"), "{e}");
    let e = error(&format!("{HEAD}G76 P020560 D1\n"), &Machine::new(ProfileName::Gsk980));
    assert_eq!(e.word.as_deref(), Some("D1"));
}

#[test]
fn unsupported_codes_and_unknown_positions() {
    let e = error("G71 U1 R0.5\n", &gsk988());
    assert_eq!(e.word.as_deref(), Some("G71"));
    assert!(matches!(e.kind, ErrorKind::Unsupported(_)));
    let e = error("M03 S500\nG00 U10\n", &gsk988());
    assert_eq!(e.kind, ErrorKind::PositionUnknown);
    let e = error("M03 S500\nG76 X60 Z-30 P2 Q0.5 F2\n", &gsk988());
    assert_eq!(e.kind, ErrorKind::PositionUnknown);
    let e = error("G00 X80 Z10\nG20\n", &gsk988());
    assert_eq!((e.line, e.kind), (2, ErrorKind::UnitChangeAfterMotion));
    let e = error("G00 X80 X90\n", &gsk988());
    assert_eq!((e.word.as_deref(), e.kind), (Some("X90"), ErrorKind::Duplicate));
    let e = error("G00 X80 (open comment\n", &gsk988());
    assert!(matches!(e.kind, ErrorKind::Syntax(_)));
    let e = error("G00 X Z1\n", &gsk988());
    assert!(matches!(e.kind, ErrorKind::Syntax(_)));
    assert_eq!(e.word.as_deref(), Some("X"));
}

/// 5129 = 1 (the 988TA's high-speed threading mode) under reading
/// R-HIGHSPEED=refuse: a G76 or a G78 is refused at its block 2; G92
/// follows it (spec/tests/g92.rs). The default, `g92-rules`, is worked in
/// spec/tests/readings.rs.
#[test]
fn high_speed_mode_refuses_g76_and_g78_under_refuse() {
    let mut m = gsk988();
    m.apply_toml("[parameters]\n5129 = 1\n[readings]\n\"R-HIGHSPEED\" = \"refuse\"\n").unwrap();
    let e = error("M3 S300\nG00 X80 Z10\nG76 P020560 Q0.15 R0.1\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n", &m);
    assert_eq!(e.line, 4);
    assert!(matches!(e.kind, ErrorKind::Parameter(_)), "{e}");
    assert!(e.to_string().contains("5129 = 1") && e.to_string().contains("G76"), "{e}");
    assert!(e.to_string().contains("R-HIGHSPEED=refuse"), "{e}");
    let e = error("M3 S300\nG00 X80 Z10\nG78 X60.64 Z-62 P3.68 Q1.8 F6\n", &m);
    assert_eq!(e.line, 3);
    assert!(e.to_string().contains("G78"), "{e}");
    assert!(read("G00 X1 Z1\n", &m).is_ok());
}

#[test]
fn cycle_alarms_carry_the_block_line() {
    // Note 7: run-out longer than the thread (K = 40 > |W| - shift).
    let src = format!("{HEAD}G76 P010060 Q0.1 R0\nG76 X60 Z-30 P2 Q0.5 F2 J1 K40\n");
    let p = read(&src, &gsk988()).unwrap();
    let c = p.cycles().next().unwrap().clone();
    assert_eq!(c.block.line, 4);
    let e = cycleref_spec::g76::expand(&c.cycle).unwrap_err();
    assert!(matches!(e, CycleError::RunOutTooLong { .. }), "{e}");
    assert!(e.to_string().contains("note 7"), "{e}");
}

/// Found by fuzzing (fuzz/): values with 28 digits overflowed a Decimal
/// when scaled to increments or to ten-thousandths of a degree and
/// panicked; they are errors now.
#[test]
fn huge_values_are_errors_not_panics() {
    let e = error("M03 S500\nG00 X40 Z2\nG32 Z-30 F2 Q9888888888888888888888888888\n", &gsk988());
    assert_eq!(e.word.as_deref(), Some("Q9888888888888888888888888888"));
    let e = error("G00 X9888888888888888888888888.888 Z2\n", &gsk988());
    assert_eq!(e.word.as_deref(), Some("X9888888888888888888888888.888"));
    let mut m = gsk988();
    m.apply_toml("[parameters]\n5140 = \"79228162514264337593543950335\"\n").unwrap();
    let e = error("M03 S500\nG00 X80 Z10\nG76 X60 Z-30 P2 Q0.5 F2\n", &m);
    assert!(matches!(e.kind, ErrorKind::Parameter(_)), "{e}");
}

/// A parameter file that is not TOML is refused with the line and column
/// where the TOML reader stopped, on one line. Worked by hand: line 1 of
/// the first file is `profile = "gsk980` (17 characters), its string never
/// closed: the reader stops at the end of the line, column 18; line 2 of
/// the second is `[readings` (9 characters), a table header never closed:
/// column 10.
#[test]
fn a_parameter_file_that_is_not_toml_is_refused_with_its_place() {
    use cycleref_spec::profile::ParamsError;
    let mut m = Machine::new(ProfileName::Gsk980);
    let e = m.apply_toml("profile = \"gsk980\nx = 3\n").expect_err("not TOML");
    assert!(matches!(e, ParamsError::Toml { line: 1, column: 18, .. }), "{e:?}");
    assert_eq!(e.stable_kind(), "params:toml");
    let e = m.apply_toml("x = 3\n[readings\n").expect_err("not TOML");
    assert!(matches!(e, ParamsError::Toml { line: 2, column: 10, .. }), "{e:?}");
    let shown = e.to_string();
    assert!(shown.starts_with("parameter file: line 2, column 10: not TOML: "), "{shown}");
    assert!(!shown.contains('\n'), "{shown}");
}
