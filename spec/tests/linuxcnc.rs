//! The `linuxcnc` reference model against LinuxCNC's own interpreter.
//!
//! `data/lcnc-taper.canon` is what `rs274 -g data/lcnc-taper.ngc <
//! /dev/null` printed (LinuxCNC 2.9.0~pre1, Debian's linuxcnc-uspace); it
//! is the independent oracle of `taper_thread_matches_rs274`. The values
//! in the other tests are worked by hand in their comments.

mod common;

use cycleref::linuxcnc::LinuxCncG76;
use cycleref::{IncrementSystem, InputUnit, Lead, LeadWord, PassKind, Role, Units, XMode};
use cycleref_spec::linuxcnc::{expand, taper_pitch};
use cycleref_spec::real::Real;
use cycleref_spec::rs274;

const MM: Units = Units { system: IncrementSystem::IsC, unit: InputUnit::Metric };

/// `G0 X14 Z2` then `G76 P1.5 Z-20 I-1 J0.2 R1.5 K0.92 Q29.5 H1 E1 L3` in G8
/// (data/lcnc-taper.ngc).
fn taper_cycle() -> LinuxCncG76 {
    cycleref::examples::LINUXCNC_TAPER
}

#[test]
fn taper_thread_matches_rs274() {
    let canon = rs274::read(include_str!("data/lcnc-taper.canon")).unwrap();
    // The first motion is the program's G0 X14 Z2, the last its G0 X20 Z5.
    let cycle = &canon[1..canon.len() - 1];
    let ours = expand(&taper_cycle()).unwrap();
    rs274::compare(&ours, cycle, MM, XMode::Radius).unwrap();
    // 9 rough passes: 0.2·n^(2/3) < 0.92 ⇔ n < 4.6^1.5 = 9.866; then the
    // full-depth pass and one spring pass: 11 passes of 6 moves (back, in,
    // angled in, over, angled out, out), and the return.
    assert_eq!(ours.len(), 11 * 6 + 1);
    let rough = ours.iter().filter(|m| m.pass.is_some_and(|p| p.kind == PassKind::Rough)).count();
    assert_eq!(rough, 9 * 6);
}

#[test]
fn taper_pitch_is_p_times_hypot_over_e() {
    // 1.5·√(1² + 0.92²)/1 = 1.5·1.358823… = 2.0382345… → 2.038235 (rs274
    // prints 2.038235 too).
    assert_eq!(taper_pitch(&taper_cycle()), Lead { word: LeadWord::K, mantissa: 2_038_235, scale: 6 });
}

#[test]
fn straight_thread_by_hand() {
    // G8, X0 = 10, Z0 = 1, Z-10, P1, I-0.5 J0.1 K0.3, R1, Q0, H0, no taper.
    // Depths 0.1·n < 0.3: n = 1, 2 (n = 3 equals K: the loop stops,
    // interp_convert.cc l.5776 `depth < end_depth`); then one pass at K.
    // Pass at δ: back X = 10 + (0.3 − δ), in X = 10 − (0.5 + δ), Z fixed.
    let c = common::STRAIGHT_RADIUS;
    let ours = expand(&c).unwrap();
    let pts: Vec<(i64, i64, Role)> = ours.iter().map(|m| (m.to.x, m.to.z, m.role)).collect();
    let mut expected = Vec::new();
    for (back, cut) in [(102_000, 94_000), (101_000, 93_000), (100_000, 92_000)] {
        expected.push((back, 10_000, Role::Approach));
        expected.push((cut, 10_000, Role::Approach));
        expected.push((cut, -100_000, Role::Cut));
        expected.push((back, -100_000, Role::Retract));
    }
    expected.push((100_000, -100_000, Role::Return));
    assert_eq!(pts, expected);
}

#[test]
fn power_values_from_tables() {
    // ∛4 = 1.58740105196819947475…, ∛100 = 4.64158883361277889241…
    // (published constants; to_decimal truncates), and exact roots.
    assert_eq!(Real::power(2, 2, 3).to_decimal(20).unwrap(), "1.58740105196819947475");
    assert_eq!(Real::power(10, 2, 3).to_decimal(20).unwrap(), "4.64158883361277889241");
    assert!(Real::power(8, 2, 3).is_exact());
    assert_eq!(Real::power(8, 2, 3).to_decimal(3).unwrap(), "4.000");
    assert!(Real::power(9, 1, 2).is_exact());
    assert!(!Real::power(10, 1, 2).is_exact());
}
