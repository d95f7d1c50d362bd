//! The G75.1 harnesses (`proofs/src/groove.rs`) under `cargo test`: each
//! property exhaustively over a slice of small right-angle grooves and by
//! sampling over the documented ranges. The longer run:
//!
//! ```sh
//! cargo test -p cycleref-proofs --profile proofs --test g75_harnesses -- --ignored
//! ```

use cycleref_proofs::groove::{self, GrooveDomain, GrooveFixedPoint};
use cycleref_proofs::shim::{check_and_print as check, Mode};
use cycleref_proofs::windows::GROOVE_WINDOW;

/// Small right-angle grooves: the Kani window ([`GROOVE_WINDOW`]: with or
/// without layers of 3, allowances 0..=1, pointed tool or widths 1..=2,
/// corner sizes 0..=1 of every kind pattern, every J, both signs of H and
/// D) deeper and wider, depth 1..=8, width 0..=6, pecks 1..=3, steps
/// 1..=3, retract 1, in two unit codes that between them have every unit
/// choice: IS-C inch diameter (3) and IS-B metric radius (4).
const SMALL: GrooveDomain = GrooveDomain {
    depth: (1, 8),
    width: (0, 6),
    peck: (1, 3),
    step: (1, 3),
    retract: (1, 1),
    units: (3, 4),
    ..GROOVE_WINDOW
};

/// Every angle, small enough to expand quickly.
const ANGLES: GrooveDomain = GrooveDomain {
    depth: (1, 4_000),
    width: (0, 4_000),
    peck: (50, 800),
    step: (50, 800),
    retract: (0, 50),
    layer: (0, 2_000),
    allowance_x: (0, 200),
    allowance_z: (0, 200),
    tool_width: (-1, 400),
    corner: (0, 300),
    flank: (1, 900_000),
    slope: (0, 899_999),
    ..GrooveDomain::SQUARE
};

const SAMPLE: Mode = Mode::Sample { runs: 2_000, seed: 0x6737_3531 };

fn small(max_runs: u64) -> Mode {
    Mode::Exhaustive { max_runs }
}

/// The exhaustive slice: the choices that matter for each property, the
/// rest fixed (a wider slice in the ignored run).
const PECKS: GrooveDomain =
    GrooveDomain { corner: (0, 0), corner_kinds: (0, 0), allowance_z: (0, 0), path: (0, 0), ..SMALL };

#[test]
fn pecks_and_steps() {
    check("pecks (exhaustive)", small(200_000), || groove::groove_pecks_and_steps(&PECKS, &GrooveFixedPoint));
    check("pecks (square, sampled)", SAMPLE, || {
        groove::groove_pecks_and_steps(&GrooveDomain::SQUARE_WIDE, &GrooveFixedPoint)
    });
    check("pecks (angles, sampled)", SAMPLE, || groove::groove_pecks_and_steps(&ANGLES, &GrooveFixedPoint));
}

#[test]
fn layers() {
    check("layers (exhaustive)", small(200_000), || groove::groove_layers(&PECKS, &GrooveFixedPoint));
    check("layers (angles, sampled)", SAMPLE, || groove::groove_layers(&ANGLES, &GrooveFixedPoint));
}

/// Corners and allowances matter here; pecking does not.
const REGION: GrooveDomain = GrooveDomain {
    depth: (1, 6),
    width: (0, 5),
    peck: (3, 3),
    step: (1, 2),
    signs: (0, 0),
    path: (0, 0),
    corner_kinds: (0, 3),
    ..SMALL
};

#[test]
fn inside_the_roughing_region() {
    check("inside (exhaustive)", small(700_000), || groove::groove_inside(&REGION, &GrooveFixedPoint));
    check("inside (sampled)", SAMPLE, || {
        groove::groove_inside(&GrooveDomain::SQUARE_WIDE, &GrooveFixedPoint)
    });
}

/// Grooving tools (w ≥ 1), layers, every corner size 0..=3, allowances:
/// the material left by the plunges and the rough contour (J0 and J1), deep
/// enough for ridges and slivers, IS-C inch diameter and IS-B metric radius
/// (442 368 grooves).
const MATERIAL: GrooveDomain = GrooveDomain { units: (3, 4), ..GrooveDomain::MATERIAL };

/// Wider, for sampling (the material grid has depth × width cells).
const MATERIAL_WIDE: GrooveDomain = GrooveDomain {
    depth: (1, 80),
    width: (1, 100),
    peck: (1, 30),
    step: (1, 30),
    layer: (0, 60),
    allowance_x: (0, 20),
    allowance_z: (0, 20),
    tool_width: (1, 30),
    corner: (0, 25),
    ..GrooveDomain::SQUARE_WIDE
};

#[test]
fn material_left_by_roughing() {
    check("material (exhaustive)", small(500_000), || groove::groove_material(&MATERIAL, &GrooveFixedPoint));
    check("material (sampled)", Mode::Sample { runs: 6_000, seed: 0x6d61_7431 }, || {
        groove::groove_material(&MATERIAL_WIDE, &GrooveFixedPoint);
    });
}

/// Corners and tool widths matter; roughing does not (J2 and J1).
const PROFILE: GrooveDomain = GrooveDomain {
    peck: (8, 8),
    step: (3, 3),
    layer: (0, 0),
    path: (1, 2),
    corner: (0, 1),
    signs: (0, 3),
    depth: (6, 7),
    width: (3, 6),
    allowance_x: (0, 0),
    ..SMALL
};

#[test]
fn finishing_contour_is_the_profile() {
    check("profile (exhaustive)", small(800_000), || {
        groove::groove_finish_is_profile(&PROFILE, &GrooveFixedPoint);
    });
    check("profile (sampled)", SAMPLE, || {
        groove::groove_finish_is_profile(&GrooveDomain::SQUARE_WIDE, &GrooveFixedPoint)
    });
}

/// Every documented input, every layer count (the Kani window of
/// `groove_no_panic` has at most 1 152 layers: `proofs/src/windows.rs`).
#[test]
fn no_panic_over_the_documented_ranges() {
    check("no panic (sampled)", Mode::Sample { runs: 20_000, seed: 7 }, || {
        groove::groove_no_panic(&GrooveDomain::FULL, 64, None);
    });
}

/// Beyond the Kani window's 1 152 layers: the most layers a valid groove
/// can have, 10^6 of one peck each (`MAX_PECKS`), the peck count's loop
/// running once per layer, and 10^6 + 1, refused (`TooManyPecks`).
#[test]
fn no_panic_at_the_most_layers() {
    let most = GrooveDomain::layers_only((999_999, 1_000_001), (1, 1), (1, 1));
    let r = check("no panic (most layers)", Mode::Exhaustive { max_runs: 3 }, || {
        groove::groove_no_panic(&most, 64, None);
    });
    assert_eq!(r.runs, 3);
}

/// The long run: wider exhaustive slices, each over the choices its
/// property depends on (each slice below 20 000 000 runs).
#[test]
#[ignore = "long: run with --profile proofs -- --ignored"]
fn long_run() {
    let wide = GrooveDomain { depth: (1, 14), width: (0, 10), peck: (1, 5), step: (1, 4), ..SMALL };
    let pecks = GrooveDomain { corner: (0, 0), corner_kinds: (0, 0), path: (0, 0), ..wide };
    check("pecks (long)", small(20_000_000), || groove::groove_pecks_and_steps(&pecks, &GrooveFixedPoint));
    let inside = GrooveDomain {
        depth: (1, 10),
        peck: (3, 3),
        path: (0, 0),
        corner_kinds: (0, 3),
        signs: (0, 0),
        ..wide
    };
    check("inside (long)", small(20_000_000), || groove::groove_inside(&inside, &GrooveFixedPoint));
    // Corners up to 3 and depths from 5 (the slivers need both), every unit code.
    let material = GrooveDomain { depth: (5, 9), width: (3, 8), units: (0, 7), ..MATERIAL };
    check("material (long)", small(20_000_000), || groove::groove_material(&material, &GrooveFixedPoint));
    let profile =
        GrooveDomain { peck: (8, 8), step: (3, 3), layer: (0, 0), path: (1, 2), allowance_x: (0, 0), ..wide };
    check("profile (long)", small(20_000_000), || {
        groove::groove_finish_is_profile(&profile, &GrooveFixedPoint)
    });
}
