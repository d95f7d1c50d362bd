//! The registry of cycles (`spec/src/cycles/`, the `registry!` table of
//! `spec/src/pipeline.rs`) held to what the crate documentation says adding
//! a cycle touches: each cycle is one module of `spec/src/cycles/`
//! implementing `CycleCall` and one line of the registry, and every item the
//! reader yields for a cycle is found by `Cycle::of`.

use std::collections::BTreeSet;

use cycleref_spec::pipeline::{expand, Cycle, Engine, CYCLE_KINDS};
use cycleref_spec::{read, Machine, ProfileName};

/// The square groove of `examples/gsk980-g75-square.nc`.
const G75: &str = "M03 S800\nG00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8\nG75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011\n";

/// One program per cycle of the registry, each read with its profile.
const PROGRAMS: [(ProfileName, &str, &str); 7] = [
    (
        ProfileName::Gsk988,
        "G76",
        "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.1 R0.05\nG76 X60.64 Z-62 P3.68 Q1.8 F6\n",
    ),
    (
        ProfileName::Gsk980,
        "G78",
        "M3 S300\nG00 X80 Z10\nG78 P000345 Q150 R0.5 J1.5 K2 D2\nG78 X60 Z-60 P3000 Q800 F3\n",
    ),
    (ProfileName::Gsk980, "G32", "M3 S300\nG00 X80 Z10\nG32 Z-20 F2\n"),
    (ProfileName::Gsk980, "G92", "M3 S300\nG0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n"),
    (ProfileName::Gsk980, "G75.1", G75),
    (
        ProfileName::LinuxCnc,
        "G76",
        "G18 G21 G7\nM3 S500\nG0 X22 Z2\nG76 P1.5 Z-20 I-2 J0.3 R1.5 K1.84 Q29.5 H1 E1 L3\n",
    ),
    (ProfileName::LinuxCnc, "G33", "G18 G21 G7\nM3 S500\nG0 X22 Z2\nG33 Z-20 K1.5\n"),
];

#[test]
fn every_cycle_of_the_registry_is_found_by_its_item_and_expands_by_both_engines() {
    let mut kinds = BTreeSet::new();
    for (profile, code, text) in PROGRAMS {
        let program = read(text, &Machine::new(profile)).unwrap_or_else(|e| panic!("{code}: {e}"));
        let cycles: Vec<Cycle<'_, '_>> = program.items.iter().filter_map(Cycle::of).collect();
        assert_eq!(cycles.len(), 1, "{code} on {profile:?}: one cycle");
        let cycle = cycles[0];
        assert_eq!(cycle.code(), code);
        assert!(cycle.index() < CYCLE_KINDS);
        kinds.insert(cycle.index());
        let ours: Vec<_> = expand(cycle, Engine::Impl).unwrap_or_else(|e| panic!("{code}: {e}")).collect();
        let reference: Vec<_> =
            expand(cycle, Engine::Spec).unwrap_or_else(|e| panic!("{code}: {e}")).collect();
        assert!(!ours.is_empty(), "{code}: moves");
        assert_eq!(ours, reference, "{code}: the engine and the reference agree");
        // Every cycle says how it is written, tabulated and reported.
        let _ = (cycle.nc_style(), cycle.pass_table(), cycle.annotations());
        let mut regions = Vec::new();
        cycle.regions(Engine::Impl, &mut regions).unwrap_or_else(|e| panic!("{code}: {e}"));
        assert!(!regions.is_empty(), "{code}: the region it cuts");
        let mut tags = Vec::new();
        cycle.tags(&ours, &mut |t| tags.push(t));
        assert!(!tags.is_empty(), "{code}: its features");
        // And how it is drawn, the same by either engine.
        let panel = cycle.panel(Engine::Impl).unwrap_or_else(|e| panic!("{code}: {e}"));
        assert_eq!(panel, cycle.panel(Engine::Spec).unwrap_or_else(|e| panic!("{code}: {e}")), "{code}");
    }
    assert_eq!(kinds.len(), CYCLE_KINDS, "every line of the registry has a program here");
}

#[test]
fn each_cycle_is_one_module_of_the_cycles_directory() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/cycles");
    let modules: BTreeSet<String> = std::fs::read_dir(&dir)
        .expect("spec/src/cycles")
        .map(|e| e.expect("an entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".rs") && n != "mod.rs")
        .collect();
    assert_eq!(modules.len(), CYCLE_KINDS, "one module per line of the registry: {modules:?}");
    let registry = std::fs::read_to_string(dir.join("mod.rs")).expect("mod.rs");
    for m in &modules {
        let name = m.trim_end_matches(".rs");
        assert!(registry.contains(&format!("mod {name};")), "{name} is declared");
        let text = std::fs::read_to_string(dir.join(m)).expect("a module");
        assert!(text.contains("CycleCall<'a> for "), "{name} implements CycleCall");
    }
}

/// The G76 panel's points A, B, C and D, worked by hand from the 988TA
/// M68x6 program: A = (X80, Z10); C = (X of D + i, Z of A) = (X60.64,
/// Z10); B = X of C + 2·k outwards (diameter X, external) = 60.64 + 2 ×
/// 3.68 = X68.00 at Z10; D = (X60.64, Z-62). In micrometres.
#[test]
fn the_g76_panel_carries_the_manuals_points() {
    use cycleref::Point;
    use cycleref_spec::cycles::{Panel, PassesPanel};
    let (profile, _, text) = PROGRAMS[0];
    let program = read(text, &Machine::new(profile)).expect("reads");
    let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
    let Ok(Panel::Passes(PassesPanel { points, direction, side, starts, .. })) = cycle.panel(Engine::Impl)
    else {
        panic!("G76 is drawn on a panel of its own");
    };
    assert_eq!(
        points,
        [
            Point::new(80_000, 10_000),
            Point::new(68_000, 10_000),
            Point::new(60_640, 10_000),
            Point::new(60_640, -62_000)
        ]
    );
    assert_eq!((direction, side, starts), (-1, 1, 1), "cut towards -Z, external, one start");
}

/// The blocks of a program share a panel by title; the LinuxCNC ones hold
/// X as a diameter (reading R-CHECKLCNC).
#[test]
fn the_single_block_cycles_share_panels_by_title() {
    use cycleref_spec::cycles::Panel;
    let titles: Vec<(&str, bool)> = PROGRAMS
        .iter()
        .filter_map(|(profile, code, text)| {
            let program = read(text, &Machine::new(*profile)).expect("reads");
            let cycle = program.items.iter().find_map(Cycle::of).expect("a cycle");
            match cycle.panel(Engine::Impl).unwrap_or_else(|e| panic!("{code}: {e}")) {
                Panel::Blocks(b) => Some((b.title, b.x_as_diameter)),
                Panel::Passes(_) | Panel::Groove(_) => None,
            }
        })
        .collect();
    assert_eq!(titles, [("G32", false), ("G92", false), ("G76 (LinuxCNC)", true), ("G33", true)]);
}
