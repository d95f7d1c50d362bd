//! G32: golden tests worked by hand from seed 002's rules, the profiles'
//! rules, and every error.

use cycleref::{CycleError, G32RunOut, Motion, Move, Point, Role, StartAngle};
use cycleref_spec::profile::{G32Rules, Machine};
use cycleref_spec::reader::resolve_g32_run_out;
use cycleref_spec::{read, ErrorKind, ProfileName, ProgramError};

fn example(name: &str) -> String {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every G32 block's moves, as `(G32?, x, z, sync, angle num/den, role)`.
fn moves(src: &str, m: &Machine) -> Vec<Vec<Move>> {
    let p = read(src, m).unwrap_or_else(|e| panic!("{e}"));
    p.threads().map(|c| cycleref_spec::g32::expand(&c.g32).unwrap()).collect()
}

fn error(src: &str, m: &Machine) -> ProgramError {
    read(src, m).err().unwrap_or_else(|| panic!("expected an error:\n{src}"))
}

fn gsk980() -> Machine {
    Machine::new(ProfileName::Gsk980)
}

fn thread(x: i64, z: i64, sync: bool, angle: StartAngle, role: Role, lead: cycleref::Lead) -> Move {
    Move { motion: Motion::Thread { lead, start_angle: angle, sync }, to: Point::new(x, z), role, pass: None }
}

/// F2.0: the reader keeps the value, not its trailing zeros.
const F2: cycleref::Lead = cycleref::Lead { word: cycleref::LeadWord::F, mantissa: 2, scale: 0 };

/// Seed 002's example O0009 at IS-C: two single-block taper passes.
/// Pass 1 from (27.4286, 3) by W-75 to X48.8571: Z is the long axis
/// (75 > (48.8571 - 27.4286) / 2 = 10.71425); no J/K: one thread move to
/// (48.8571, -72), synchronised, at 0°. Pass 2 from (26.4286, 3) (after
/// G00 X55, W75, X26.4286) to (47.4286, -72).
#[test]
fn seed002_taper_example() {
    let mut m = gsk980();
    m.increment = cycleref::IncrementSystem::IsC;
    let got = moves(&example("gsk980-g32-taper.nc"), &m);
    let z = StartAngle::ZERO;
    assert_eq!(
        got,
        vec![
            vec![thread(488_571, -720_000, true, z, Role::Cut, F2)],
            vec![thread(474_286, -720_000, true, z, Role::Cut, F2)],
        ]
    );
}

/// examples/gsk980-g32-runout.nc, worked by hand (IS-B, diameter X):
///
/// 1. From (40, 2) to Z-30, J1.5 K3 Q90000: Z long. The run-out starts K = 3
///    before the end: Z-27, X40 (straight); it ends at Z-30 displaced J =
///    +1.5 (radius) = X43. Q90000 = 90°; the cut synchronises.
/// 2. G00 X50, Z2 cancel J and K; X30.
/// 3. From (30, 2) to (34, -10), Q180000: no run-out; a new synchronised
///    run at 180°.
/// 4. To Z-30 (X34): continuation, no sync, the run's angle 180°.
/// 5. To (38, -40), J1 (K omitted: K = J = 1): continuation. Run-out start
///    Z-39, X = 34 + 4 × (-39 + 30) / (-10) = 37.6; end X = 38 + 2 × 1 = 40.
///    Its Q90000 is ignored (rule 2): still 180°.
#[test]
fn gsk980_run_out_and_continuous_thread() {
    let got = moves(&example("gsk980-g32-runout.nc"), &gsk980());
    let f2 = cycleref::Lead { word: cycleref::LeadWord::F, mantissa: 2, scale: 0 };
    let a90 = StartAngle::from_millidegrees(90_000);
    let a180 = StartAngle::from_millidegrees(180_000);
    assert_eq!(
        got,
        vec![
            vec![
                thread(40_000, -27_000, true, a90, Role::Cut, f2),
                thread(43_000, -30_000, false, a90, Role::RunOut, f2)
            ],
            vec![thread(34_000, -10_000, true, a180, Role::Cut, f2)],
            vec![thread(34_000, -30_000, false, a180, Role::Cut, f2)],
            vec![
                thread(37_600, -39_000, false, a180, Role::Cut, f2),
                thread(40_000, -40_000, false, a180, Role::RunOut, f2)
            ],
        ]
    );
}

/// Face thread (X long, K radius) and a negative J: from (80, 0) to X20 with
/// W0... Z unchanged: X is the long axis; K2 (radius) → the run-out starts
/// at X = 20 + 2 × 2 = 24, Z0; J-1 displaces Z by -1: (20, -1).
#[test]
fn face_thread_with_run_out() {
    let got = moves("M03 S300\nG00 X80 Z0\nG32 X20 F3 J-1 K2\n", &gsk980());
    let f3 = cycleref::Lead { word: cycleref::LeadWord::F, mantissa: 3, scale: 0 };
    let z = StartAngle::ZERO;
    assert_eq!(
        got,
        vec![vec![
            thread(24_000, 0, true, z, Role::Cut, f3),
            thread(20_000, -1_000, false, z, Role::RunOut, f3)
        ]]
    );
}

/// A tapered run-out start rounds to the nearest increment: from (30, 2) to
/// (40.001, -48) with J1 K2: X = 30 + 10.001 × 48 / 50 = 39.60096 → 39.601.
#[test]
fn tapered_run_out_start_rounds_to_nearest() {
    let got = moves("M03 S300\nG00 X30 Z2\nG32 X40.001 Z-48 F2 J1 K2\n", &gsk980());
    assert_eq!(got[0][0].to, Point::new(39_601, -46_000));
    assert_eq!(got[0][1].to, Point::new(42_001, -48_000));
}

/// The 988TA: Q in degrees (Q180.000), K omitted gives a short-axis
/// pull-out only, and a block with a run-out ends the continuous thread.
#[test]
fn gsk988_rules() {
    let m = Machine::new(ProfileName::Gsk988);
    let got = moves("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q180.000 J1\nG32 Z-30 K2\n", &m);
    let f2 = cycleref::Lead { word: cycleref::LeadWord::F, mantissa: 2, scale: 0 };
    let a180 = StartAngle::from_millidegrees(180_000);
    let z = StartAngle::ZERO;
    // Block 1: J1, K omitted: cut to the end, then X + 2 (pull-out).
    // Block 2 starts at (42, -20), synchronises again (block 1 had a
    // run-out), Q 0; J1 K2 (modal J): run-out from Z-28 to (44, -30).
    assert_eq!(
        got,
        vec![
            vec![
                thread(40_000, -20_000, true, a180, Role::Cut, f2),
                thread(42_000, -20_000, false, a180, Role::RunOut, f2)
            ],
            vec![
                thread(42_000, -28_000, true, z, Role::Cut, f2),
                thread(44_000, -30_000, false, z, Role::RunOut, f2)
            ],
        ]
    );
    // Q beyond 360° wraps on the 988TA.
    let got = moves("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q450\n", &m);
    let Motion::Thread { start_angle, .. } = got[0][0].motion else { panic!() };
    assert_eq!(start_angle, StartAngle::from_millidegrees(90_000));
}

#[test]
fn g32_run_out_rules() {
    use G32RunOut::{Amounts, None as NoRunOut};
    let r = G32Rules::Gsk980;
    // Seed 002 rules 2-5.
    assert_eq!(resolve_g32_run_out(r, None, None), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, None, Some(3)), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, Some(-2), None), Amounts { short: -2, long: 2 });
    assert_eq!(resolve_g32_run_out(r, Some(0), None), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, Some(0), Some(0)), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, Some(2), Some(0)), Amounts { short: 2, long: 2 });
    assert_eq!(resolve_g32_run_out(r, Some(0), Some(4)), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, Some(2), Some(4)), Amounts { short: 2, long: 4 });
    let r = G32Rules::Gsk988;
    assert_eq!(resolve_g32_run_out(r, None, Some(3)), NoRunOut);
    assert_eq!(resolve_g32_run_out(r, Some(2), None), Amounts { short: 2, long: 0 });
    assert_eq!(resolve_g32_run_out(G32Rules::NoRunOut, Some(2), Some(3)), NoRunOut);
}

#[test]
fn g32_errors() {
    let m = gsk980();
    // A missing end point.
    let e = error("M03 S300\nG00 X40 Z2\nG32 F2\n", &m);
    assert!(matches!(e.kind, ErrorKind::Missing { .. }), "{e}");
    assert_eq!(e.line, 3);
    // An end point equal to the position.
    let e = error("M03 S300\nG00 X40 Z2\nG32 X40 Z2 F2\n", &m);
    assert_eq!(e.kind, ErrorKind::Cycle(CycleError::NoMotion));
    // A zero lead.
    let e = error("M03 S300\nG00 X40 Z2\nG32 Z-20 F0\n", &m);
    assert_eq!(e.word.as_deref(), Some("F0"));
    // A run-out longer than the move (988TA G32 note 4).
    let e = error("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 J1 K30\n", &m);
    assert!(matches!(e.kind, ErrorKind::Cycle(CycleError::RunOutTooLong { .. })), "{e}");
    // Q out of range, and Q in 0.001° must be whole.
    let e = error("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q400000\n", &m);
    assert_eq!(e.word.as_deref(), Some("Q400000"));
    let e = error("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q180.5\n", &m);
    assert_eq!(e.word.as_deref(), Some("Q180.5"));
    // No spindle speed.
    let e = error("G00 X40 Z2\nG32 Z-20 F2\n", &m);
    assert_eq!(e.kind, ErrorKind::NoSpindleSpeed);
    // FANUC: no J/K in G32, no decimal point in Q.
    let f = Machine::new(ProfileName::Fanuc);
    let e = error("M03 S300\nG00 X40.0 Z2.0\nG32 Z-20.0 F2.0 J1.0\n", &f);
    assert_eq!(e.word.as_deref(), Some("J1.0"));
    let e = error("M03 S300\nG00 X40.0 Z2.0\nG32 Z-20.0 F2.0 Q180.0\n", &f);
    assert!(matches!(e.kind, ErrorKind::DecimalPointNotAllowed { .. }), "{e}");
}

/// Q180 on the 980TDi (No.182.7 = 0) is 0.18°, as the manual warns.
#[test]
fn q_units_of_the_980() {
    let got = moves("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q180\n", &gsk980());
    let Motion::Thread { start_angle, .. } = got[0][0].motion else { panic!() };
    assert_eq!(start_angle, StartAngle::from_millidegrees(180));
    let mut m = gsk980();
    m.apply_toml("[parameters]\n\"182.7\" = 1\n").unwrap();
    let got = moves("M03 S300\nG00 X40 Z2\nG32 Z-20 F2 Q180\n", &m);
    let Motion::Thread { start_angle, .. } = got[0][0].motion else { panic!() };
    assert_eq!(start_angle, StartAngle::from_millidegrees(180_000));
}
