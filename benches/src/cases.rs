//! The cycles and the program the benchmarks run, in one place so that the
//! benches, the tests and the `track` binary agree on them.
//!
//! Every case is an external straight thread (X as diameter, IS-B metric)
//! with infeed D0 and no lead-in, which is what [`crate::float`] models.
//! "Passes" counts pass paths, as the throughput of the benches does:
//! `(rough passes + finishing passes) × starts`; each path is an approach,
//! the cut, the run-out, the retract and the return.

use std::fmt::Write as _;

use cycleref::engine::{rough_pass_count, round_sqrt};
use cycleref::g76::{G76Cycle, RunOut};
use cycleref::lead::{Lead, LeadWord};
use cycleref::units::Point;
use cycleref_spec::{Machine, ProfileName};

/// The GSK 988TA manual's M68x6 example (`examples/gsk988-m68x6.nc`).
pub const M68X6_PROGRAM: &str = include_str!("../../examples/gsk988-m68x6.nc");

/// Number of blocks (lines) of [`reader_program`] in the `reader` group.
pub const READER_BLOCKS: usize = 100_000;

/// Rough pass counts of the `flat` group.
pub const FLAT_PASSES: [u64; 5] = [10, 100, 1_000, 10_000, 100_000];

/// The cycle of the M68x6 example, read with the GSK 988TA profile:
/// k 3.68, Δd 1.8, Δdmin 0.15, d 0.1, m 2, a 60°, run-out by the chamfer
/// r = 5 (0.5 lead, 45°), lead F6.
///
/// # Panics
///
/// If the example no longer reads or holds no cycle.
#[must_use]
pub fn m68x6() -> G76Cycle {
    let program = cycleref_spec::read(M68X6_PROGRAM, &Machine::new(ProfileName::Gsk988))
        .unwrap_or_else(|e| panic!("examples/gsk988-m68x6.nc: {e:?}"));
    let call = program.cycles().next().expect("examples/gsk988-m68x6.nc has a G76");
    call.cycle
}

/// Depth of rough level `n` of the schedule without the cap at `k - d`:
/// `D(n) = max(round(Δd √n), D(n-1) + max(Δdmin, 1))`, in increments.
fn uncapped_depth(first_depth: i64, min_cut: i64, n: u64) -> i64 {
    let q = u128::from(first_depth.unsigned_abs());
    let min = min_cut.max(1);
    let mut depth = 0_i64;
    for level in 1..=n {
        let law = i64::try_from(round_sqrt(q * q * u128::from(level))).unwrap_or(i64::MAX);
        depth = law.max(depth + min);
    }
    depth
}

/// A cycle shaped like M68x6 (A X80 Z10, D Z-62, a 60°, d 0.1, m 2,
/// explicit run-out J 1.0 K 2.0, lead F6) with Δd 0.2 and Δdmin 0.005 and
/// the thread height chosen so that it has exactly `rough` rough passes:
/// `k - d` is the depth of level `rough` of the uncapped schedule. The
/// schedule follows the √n law for about 400 levels, then adds Δdmin.
/// The end X is set so that A stays clear of the thread.
#[must_use]
pub fn passes(rough: u64) -> G76Cycle {
    let first_depth = 200;
    let min_cut = 5;
    let allowance = 100;
    let last = uncapped_depth(first_depth, min_cut, rough);
    let height = last + allowance;
    G76Cycle {
        units: cycleref::Units::IS_B_METRIC,
        x_mode: cycleref::XMode::Diameter,
        start: Point::new(80_000, 10_000),
        // A clear of B by 1 mm on the radius.
        end: Point::new(80_000 - 2 * (height + 1_000), -62_000),
        taper: 0,
        thread_height: height,
        first_depth,
        min_cut,
        finishing_allowance: allowance,
        finishing_passes: 2,
        tool_angle: 60,
        infeed: cycleref::Infeed::RightFlank,
        depth_mode: cycleref::DepthMode::Decreasing,
        lead_in: 0,
        starts: 1,
        lead: Lead { word: LeadWord::F, mantissa: 6, scale: 0 },
        run_out: RunOut::Amounts { short: 1_000, long: 2_000 },
        pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// The `expand/passes_1000` case: [`passes`]`(1000)`.
#[must_use]
pub fn passes_1000() -> G76Cycle {
    passes(1_000)
}

/// An 8-start thread M68x1.5 Ph12 (lead 12 = 8 × 1.5): A X72 Z10, D X66.16
/// Z-40, k 0.92, Δd 0.3, Δdmin 0.05, d 0.05, m 2, a 60°, run-out J 0.5
/// K 1.5, L8.
#[must_use]
pub fn eight_start() -> G76Cycle {
    G76Cycle {
        units: cycleref::Units::IS_B_METRIC,
        x_mode: cycleref::XMode::Diameter,
        start: Point::new(72_000, 10_000),
        end: Point::new(66_160, -40_000),
        taper: 0,
        thread_height: 920,
        first_depth: 300,
        min_cut: 50,
        finishing_allowance: 50,
        finishing_passes: 2,
        tool_angle: 60,
        infeed: cycleref::Infeed::RightFlank,
        depth_mode: cycleref::DepthMode::Decreasing,
        lead_in: 0,
        starts: 8,
        lead: Lead { word: LeadWord::F, mantissa: 12, scale: 0 },
        run_out: RunOut::Amounts { short: 500, long: 1_500 },
        pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// A cycle of the `flat` group with exactly `rough` rough passes, all on
/// the √n law: Δd 1.000 (so every law step is above one increment up to
/// 250 000 levels), Δdmin 0, d 0, one finishing pass, k = round(1000 √n)
/// increments. A X750 Z10, D X100 Z-600 (the largest Z shift,
/// 316.228 × tan 30° = 182.6, stays inside the thread), run-out J 1 K 2.
#[must_use]
pub fn flat(rough: u64) -> G76Cycle {
    let first_depth = 1_000;
    let height = uncapped_depth(first_depth, 0, rough);
    G76Cycle {
        units: cycleref::Units::IS_B_METRIC,
        x_mode: cycleref::XMode::Diameter,
        start: Point::new(750_000, 10_000),
        end: Point::new(100_000, -600_000),
        taper: 0,
        thread_height: height,
        first_depth,
        min_cut: 0,
        finishing_allowance: 0,
        finishing_passes: 1,
        tool_angle: 60,
        infeed: cycleref::Infeed::RightFlank,
        depth_mode: cycleref::DepthMode::Decreasing,
        lead_in: 0,
        starts: 1,
        lead: Lead { word: LeadWord::F, mantissa: 6, scale: 0 },
        run_out: RunOut::Amounts { short: 1_000, long: 2_000 },
        pass_limit: 1_000_000,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

/// Number of pass paths of a cycle: `(rough + finishing) × starts`, with
/// the rough count of [`cycleref::engine::rough_pass_count`].
///
/// # Panics
///
/// If the cycle is refused.
#[must_use]
pub fn pass_paths(c: &G76Cycle) -> u64 {
    let rough = rough_pass_count(c).unwrap_or_else(|e| panic!("cycle refused: {e:?}"));
    (rough + u64::from(c.finishing_passes)) * u64::from(c.starts)
}

/// A program of exactly `blocks` lines for the GSK 988TA reader: a header
/// (`G50`, spindle), then a mix of `G01` and `G00` blocks with and without
/// comments, comment-only lines, and every 100 lines a G76 cycle (a `G00`
/// to its start point and the two G76 blocks of the M68x6 example).
#[must_use]
pub fn reader_program(blocks: usize) -> String {
    let mut s = String::with_capacity(blocks * 32);
    s.push_str("O0001;\nG50 X100 Z50 M3 S300;\n");
    let mut line = 2;
    while line < blocks.saturating_sub(1) {
        let i = line;
        if i % 100 == 0 && line + 3 < blocks {
            s.push_str("G00 X80 Z10;\n");
            s.push_str("G76 P020560 Q0.150 R0.1;\n");
            s.push_str("G76 X60.64 Z-62 P3.680 Q1.800 F6; (M68x6)\n");
            line += 3;
            continue;
        }
        let x = 20 + (i % 50);
        let z = i % 97;
        let frac = i % 1000;
        let _ = match i % 7 {
            0 => writeln!(s, "(pass {i}: facing)"),
            1 | 4 => writeln!(s, "G01 X{x}.{frac:03} Z-{z}.5 F0.2;"),
            2 => writeln!(s, "G01 X{x}.{frac:03} Z-{z}.25 F0.15; (finish {i})"),
            3 | 6 => writeln!(s, "G00 X{x}.5 Z-{z}.{frac:03};"),
            _ => writeln!(s, "G00 X100 Z50; (clear)"),
        };
        line += 1;
    }
    while line < blocks {
        s.push_str(if line + 1 == blocks { "M30;\n" } else { "G00 X100 Z50;\n" });
        line += 1;
    }
    s
}

/// A G75.1 cycle read from `text` with the gsk980 profile at `increment`.
///
/// # Panics
///
/// When the text holds no valid G75.1 (the cases below are fixed).
#[must_use]
pub fn groove(text: &str, increment: cycleref::IncrementSystem) -> cycleref::G75Cycle {
    let mut m = cycleref_spec::Machine::new(cycleref_spec::ProfileName::Gsk980);
    m.increment = increment;
    let program = cycleref_spec::read(text, &m).expect("the case reads");
    let cycle = program.grooves().next().expect("one G75.1").cycle;
    cycle
}

/// Seed 001's example (IS-C): 45° and 30° flanks, 3 plunges of 7 pecks.
#[must_use]
pub fn groove_seed() -> cycleref::G75Cycle {
    groove(
        "G00 X60 Z30 M3 S500\nG75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30\nG75.1 R0.5 I4 J1\n",
        cycleref::IncrementSystem::IsC,
    )
}

/// A groove on a slope with rounds at all four corners and layers: the
/// geometry is all irrational (intervals), the path short.
#[must_use]
pub fn groove_slope() -> cycleref::G75Cycle {
    groove(
        "G00 X90 Z12\nG75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10\n\
         G75.1 R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111\n",
        cycleref::IncrementSystem::IsB,
    )
}

/// A wide groove with many plunges and pecks (about 100 000 moves): the
/// per-move cost of the path.
#[must_use]
pub fn groove_wide() -> cycleref::G75Cycle {
    groove(
        "G00 X210 Z5\nG75.1 X200 Z0 P500 Q300 H-40 D-200 A80 B70\nG75.1 R0.1 V10 I3 J1\n",
        cycleref::IncrementSystem::IsB,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rough_levels(c: &G76Cycle) -> usize {
        cycleref_spec::g76::rough_levels(c).map(|v| v.len()).unwrap_or(0)
    }

    #[test]
    fn m68x6_reads() {
        let c = m68x6();
        assert_eq!(c.thread_height, 3_680);
        assert_eq!(c.first_depth, 1_800);
        assert_eq!(c.starts, 1);
        assert_eq!(pass_paths(&c), rough_pass_count(&c).unwrap() + 2);
    }

    #[test]
    fn passes_1000_has_1000_rough_passes() {
        let c = passes_1000();
        assert_eq!(rough_pass_count(&c), Ok(1_000));
        assert_eq!(rough_levels(&c), 1_000);
        assert_eq!(pass_paths(&c), 1_002);
    }

    #[test]
    fn eight_start_counts() {
        let c = eight_start();
        let rough = rough_pass_count(&c).unwrap();
        assert_eq!(usize::try_from(rough).unwrap(), rough_levels(&c));
        assert_eq!(pass_paths(&c), (rough + 2) * 8);
    }

    #[test]
    fn flat_counts() {
        for n in FLAT_PASSES {
            let c = flat(n);
            assert_eq!(rough_pass_count(&c), Ok(n), "flat({n})");
            assert!(cycleref::expand_g76(&c).is_ok(), "flat({n}) expands");
        }
        // The reference agrees on the small ones (it is slow on the big ones).
        for n in [10, 100, 1_000] {
            assert_eq!(rough_levels(&flat(n)), usize::try_from(n).unwrap());
        }
    }

    #[test]
    fn reader_program_reads() {
        let text = reader_program(1_000);
        assert_eq!(text.lines().count(), 1_000);
        let program = cycleref_spec::read(&text, &Machine::new(ProfileName::Gsk988)).unwrap();
        assert_eq!(program.cycles().count(), 9);
        assert_eq!(reader_program(READER_BLOCKS).lines().count(), READER_BLOCKS);
    }
}
