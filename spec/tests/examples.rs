//! `cycleref::examples` are what the reader makes of the programs they
//! come from: a constant cannot drift from its source.

use cycleref::examples::{G75_SEED, M68X6};
use cycleref::IncrementSystem;
use cycleref_spec::{read, Machine, ProfileName};

#[test]
fn m68x6_is_the_manuals_program() {
    // examples/gsk988-m68x6.nc, the manual's O0013 (written out here: the
    // published crate's tests do not see the repository's examples/).
    let text = "O0013;\nG50 X100 Z50 M3 S300;\nG00 X80 Z10;\nG76 P020560 Q0.150 R0.1;\n\
                G76 X60.64 Z-62 P3.680 Q1.800 F6;\nG00 X100 Z50;\nM30;\n";
    let program = read(text, &Machine::new(ProfileName::Gsk988)).unwrap_or_else(|e| panic!("{e}"));
    let cycles: Vec<_> = program.cycles().map(|c| c.cycle).collect();
    assert_eq!(cycles, [M68X6]);
}

#[test]
fn g75_seed_is_the_seeds_program() {
    let mut machine = Machine::new(ProfileName::Gsk980);
    machine.increment = IncrementSystem::IsC;
    let text = "G00 X60 Z30\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\nG75.1 R0.5\n";
    let program = read(text, &machine).unwrap_or_else(|e| panic!("{e}"));
    let grooves: Vec<_> = program.grooves().map(|c| c.cycle).collect();
    assert_eq!(grooves, [G75_SEED]);
}

#[test]
fn linuxcnc_taper_is_its_program() {
    // spec/tests/data/lcnc-taper.ngc, whose rs274 output is checked in
    // beside it (spec/tests/linuxcnc.rs compares every call).
    let text = include_str!("data/lcnc-taper.ngc");
    let program = read(text, &Machine::new(ProfileName::LinuxCnc)).unwrap_or_else(|e| panic!("{e}"));
    let cycles: Vec<_> = program
        .items
        .iter()
        .filter_map(|i| match i {
            cycleref_spec::Item::LinuxCncG76(c) => Some(c.cycle),
            _ => None,
        })
        .collect();
    assert_eq!(cycles, [cycleref::examples::LINUXCNC_TAPER]);
}
