//! Property tests of the reference model's schedule and geometry over random
//! valid cycles (the proof harnesses in `proofs/` check the engine; these
//! check the reference against the manual's rules directly).

use cycleref::lead::{Lead, LeadWord};
use cycleref::{
    CycleError, DepthMode, G76Cycle, IncrementSystem, Infeed, InputUnit, Motion, Move, PassKind, Point, Role,
    RunOut, Units, XMode,
};
use proptest::prelude::*;

fn cycles() -> impl Strategy<Value = G76Cycle> {
    (
        (any::<bool>(), any::<bool>(), any::<bool>(), any::<bool>(), any::<bool>()),
        (1_i64..=20_000, 1_i64..=30_000, 0_i64..=3_000, 0_u32..=100),
        (0_u32..=99, 0_u32..=4, 0_u8..12, 1_u32..=4),
        (-5_000_i64..=5_000, 1_000_i64..=200_000, 0_i64..=3_000),
        (0_u8..4, 0_i64..=3_000, 0_i64..=3_000, 0_u32..=20, 1_u32..=89),
        (1_u64..=9_999, 0_u32..=3),
    )
        .prop_map(
            |(
                (isc, inch, radius, internal, positive_z),
                (k, dd, dmin, dpct),
                (a, m, infeed, starts),
                (taper, length, clearance),
                (ro, j, kk, r, angle),
                (lead, lead_scale),
            )| {
                let units = Units {
                    system: if isc { IncrementSystem::IsC } else { IncrementSystem::IsB },
                    unit: if inch { InputUnit::Inch } else { InputUnit::Metric },
                };
                let x_mode = if radius { XMode::Radius } else { XMode::Diameter };
                let xf = x_mode.factor();
                let s = if internal { -1 } else { 1 };
                let t = if positive_z { 1 } else { -1 };
                let allowance = (k * i64::from(dpct)) / 100;
                let min_cut = dmin.min(k);
                let end = Point::new(50_000 * xf, -t * 10_000);
                let c_x = end.x + xf * taper;
                let crest = (c_x + s * xf * k).max(end.x + s * xf * k);
                let crest = if s > 0 { crest } else { (c_x + s * xf * k).min(end.x + s * xf * k) };
                let start = Point::new(crest + s * (xf * clearance + 1), end.z - t * length);
                let run_out = match ro {
                    0 => RunOut::None,
                    1 => RunOut::Amounts { short: j, long: kk },
                    2 => RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long: None },
                    _ => RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long: Some(kk) },
                };
                G76Cycle {
                    units,
                    x_mode,
                    start,
                    end,
                    taper,
                    thread_height: k,
                    first_depth: dd,
                    min_cut,
                    finishing_allowance: allowance,
                    finishing_passes: m,
                    tool_angle: a,
                    // G76's D0-D2 and G78's other modes, each with both
                    // depth modes.
                    infeed: match infeed % 6 {
                        0 => Infeed::RightFlank,
                        1 => Infeed::RightCentre,
                        2 => Infeed::LeftRight,
                        3 => Infeed::Centre,
                        4 => Infeed::LeftFlank,
                        _ => Infeed::Alternating,
                    },
                    depth_mode: if infeed < 6 { DepthMode::Decreasing } else { DepthMode::Equal },
                    lead_in: 0,
                    starts,
                    lead: Lead { word: LeadWord::F, mantissa: lead, scale: lead_scale },
                    run_out,
                    pass_limit: 100_000,
                    readings: cycleref::CycleReadings::DEFAULT,
                }
            },
        )
}

fn expand(c: &G76Cycle) -> Option<Vec<Move>> {
    match cycleref_spec::g76::expand(c) {
        Ok(m) => Some(m),
        // Legitimate refusals of generated cycles.
        Err(
            CycleError::RunOutTooLong { .. }
            | CycleError::RunOutIntoWork { .. }
            | CycleError::ThreadTooShort { .. }
            | CycleError::TooManyPasses { .. }
            | CycleError::OutOfRange { .. },
        ) => None,
        Err(e) => panic!("unexpected error {e:?} for {c:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    /// DOMAIN decision 3: rough depths strictly increase, each cut is at least
    /// min(Δdmin, what remains to k - d) and one increment, the last depth is
    /// k - d; then m finishing passes at k cutting d, 0, 0 …
    #[test]
    fn schedule(c in cycles()) {
        let Some(moves) = expand(&c) else { return Ok(()) };
        let passes: Vec<_> = moves.iter().filter(|m| m.role == Role::Approach).filter_map(|m| m.pass).collect();
        let rough: Vec<_> = passes.iter().filter(|p| p.kind == PassKind::Rough && p.start == 1).collect();
        let last = c.thread_height - c.finishing_allowance;
        let min = c.min_cut.max(1);
        let mut levels: Vec<i64> = rough.iter().map(|p| p.depth).collect();
        levels.dedup();
        let mut prev = 0;
        for (n, d) in levels.iter().enumerate() {
            prop_assert!(*d > prev, "level {} not deeper", n + 1);
            prop_assert!(d - prev >= min.min(last - prev), "cut too small at level {}", n + 1);
            prev = *d;
        }
        prop_assert_eq!(levels.last().copied().unwrap_or(0), last);
        if c.first_depth >= last && last > 0 {
            prop_assert_eq!(levels.len(), 1);
        }
        let finish: Vec<_> = passes.iter().filter(|p| p.kind == PassKind::Finish).collect();
        prop_assert_eq!(finish.len(), (c.finishing_passes * c.starts) as usize);
        for p in &finish {
            prop_assert_eq!(p.depth, c.thread_height);
            prop_assert_eq!(p.cut, if p.number == 1 { c.finishing_allowance } else { 0 });
        }
        // Each pass and start exactly once, starts in order within a pass.
        let d2 = c.infeed == Infeed::LeftRight;
        let expected_rough = if d2 { (2 * levels.len()).saturating_sub(1) } else { levels.len() };
        prop_assert_eq!(rough.len(), expected_rough);
    }

    /// Geometry: every pass leaves from A and returns to A, ends its cut on
    /// the end line, its run-out goes away from the work by at most J, the
    /// finishing passes start at the last rough pass's Z, and no pass lies
    /// outside the final form by more than an increment.
    #[test]
    fn geometry(c in cycles()) {
        let Some(moves) = expand(&c) else { return Ok(()) };
        let s = if c.start.x > c.end.x + c.x_mode.factor() * c.taper { 1 } else { -1 };
        let t = (c.end.z - c.start.z).signum();
        let xf = c.x_mode.factor();
        let z_long = (c.end.z - c.start.z).abs() > c.taper.abs();
        let zc = cycleref_spec::tan::mul_tan_round(c.thread_height - c.finishing_allowance, c.tool_angle).unwrap();
        let mut at = c.start;
        let mut last_rough_z = None;
        for m in &moves {
            let p = m.pass.unwrap();
            match m.role {
                Role::Approach => {
                    prop_assert_eq!(at, c.start);
                    let shift = t * (m.to.z - c.start.z);
                    prop_assert!(shift >= 0);
                    // Inside the final V: |shift - zc| <= (k - D) tan(a/2) + 1.
                    let room = cycleref_spec::tan::mul_tan_round(c.thread_height - p.depth, c.tool_angle).unwrap();
                    prop_assert!((shift - zc).abs() <= room + 1, "pass {:?} overcuts: shift {} zc {} room {}", p, shift, zc, room);
                    // X of Bn from the manual's formula.
                    prop_assert_eq!(m.to.x, c.end.x + xf * c.taper + s * xf * (c.thread_height - p.depth));
                    match p.kind {
                        PassKind::Rough => last_rough_z = Some(m.to.z),
                        PassKind::Finish => prop_assert_eq!(m.to.z, last_rough_z.unwrap_or(c.start.z)),
                        PassKind::Single => prop_assert!(false, "a G76 pass is rough or finishing: {:?}", p),
                    }
                }
                Role::Cut => {
                    let synced = matches!(m.motion, Motion::Thread { sync: true, .. });
                    prop_assert!(synced, "the cut synchronises");
                }
                Role::RunOut if z_long => {
                    // Away from the work (outside the cut line's end on D–E,
                    // towards A), never beyond E. On a steep taper the run-out
                    // may still move towards the axis, but less than the thread does.
                    let cut_end_x = c.end.x + s * xf * (c.thread_height - p.depth);
                    prop_assert!(s * (m.to.x - cut_end_x) > 0);
                    prop_assert!(s * (c.start.x - m.to.x) >= 0);
                    prop_assert_eq!(m.to.z, c.end.z);
                }
                Role::RunOut => {
                    // X long: the run-out ends displaced from D along Z towards
                    // the side of A, never beyond A.
                    prop_assert!(t * (c.end.z - m.to.z) > 0);
                    prop_assert!(t * (m.to.z - c.start.z) >= 0);
                }
                Role::Retract => {
                    prop_assert_eq!(m.to.x, c.start.x);
                    prop_assert_eq!(m.to.z, at.z);
                }
                Role::Return => prop_assert_eq!(m.to, c.start),
                Role::LeadIn => {}
                other => prop_assert!(false, "a G76 move with the G75.1 role {:?}", other),
            }
            prop_assert!(m.to != at, "zero-length move");
            at = m.to;
        }
        prop_assert_eq!(at, c.start);
    }
}

/// The generator must mostly produce cycles that expand, or the properties
/// above would pass vacuously.
#[test]
fn generator_is_not_vacuous() {
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;
    let mut runner = TestRunner::deterministic();
    let strategy = cycles();
    let mut ok = 0;
    for _ in 0..500 {
        let c = strategy.new_tree(&mut runner).unwrap().current();
        if expand(&c).is_some() {
            ok += 1;
        }
    }
    assert!(ok > 300, "only {ok} of 500 generated cycles expand");
}
