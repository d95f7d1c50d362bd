//! The range limits, exactly at and one past the boundary, in both engines
//! (cargo-mutants showed the `>` of the coordinate check could become `>=`
//! unnoticed).

use cycleref::lead::{Lead, LeadWord};
use cycleref::units::MAX_LENGTH;
use cycleref::{CycleError, Field, G76Cycle, Point, Units, XMode};
use cycleref_proofs::harness::PLAIN_CYCLE;
use cycleref_spec::differ::assert_same_moves;

/// An internal thread (radius X) whose thread start C lies at X = end + i.
fn at_the_edge(taper: i64) -> G76Cycle {
    G76Cycle {
        start: Point::new(999_990_000, 10_000),
        end: Point::new(999_999_000, -10_000),
        taper,
        ..PLAIN_CYCLE
    }
}

#[test]
fn thread_start_exactly_at_the_range_limit_expands() {
    // C = 999 999 000 + 999 = MAX_LENGTH: every point is inside the range.
    let c = at_the_edge(999);
    let ours: Vec<_> = cycleref::expand_g76(&c).expect("inside the range").collect();
    assert_same_moves(&Ok(ours.clone()), &cycleref_spec::g76::expand(&c), "the cycle at the range limit");
    assert_eq!(ours.iter().map(|m| m.to.x).max(), Some(MAX_LENGTH));
}

#[test]
fn thread_start_one_past_the_range_limit_is_refused() {
    let c = at_the_edge(1_000);
    let e = cycleref::expand_g76(&c).map(|_| ()).unwrap_err();
    assert!(
        matches!(e, CycleError::OutOfRange { field: Field::PassCoordinate, value } if value.increments == MAX_LENGTH + 1)
    );
    assert_eq!(cycleref_spec::g76::expand(&c).map(|_| ()), Err(e));
}

fn g32(start: Point, end: Point, short: i64, long: i64) -> cycleref::G32Block {
    cycleref::G32Block {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Diameter,
        start,
        end,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: cycleref::G32RunOut::Amounts { short, long },
        start_angle: cycleref::StartAngle::ZERO,
        sync: true,
        readings: cycleref::CycleReadings::DEFAULT,
    }
}

fn both(b: &cycleref::G32Block) -> Result<Vec<cycleref::Move>, CycleError> {
    let ours = cycleref::expand_g32(b).map(Iterator::collect::<Vec<_>>);
    assert_same_moves(&ours, &cycleref_spec::g32::expand(b), format_args!("{b:?}"));
    ours
}

/// A G32 run-out as long as the move is allowed (the whole move is the
/// run-out); one increment longer is the alarm. Z long, and X long with a
/// diameter X, where K is a radius (found by cargo-mutants: `xf * K` could
/// become `xf + K` unnoticed).
#[test]
fn g32_run_out_exactly_the_length_of_the_move() {
    // Z long: |W| = 10.000.
    let moves = both(&g32(Point::new(40_000, 0), Point::new(40_000, -10_000), 1_000, 10_000)).unwrap();
    assert_eq!(moves.len(), 1);
    assert_eq!(moves[0].to, Point::new(42_000, -10_000));
    assert!(matches!(
        both(&g32(Point::new(40_000, 0), Point::new(40_000, -10_000), 1_000, 10_001)),
        Err(CycleError::RunOutTooLong { .. })
    ));
    // X long (a face thread), diameter X: 60.000 on the diameter is 30.000 radius.
    let moves = both(&g32(Point::new(80_000, 0), Point::new(20_000, 0), -1_000, 30_000)).unwrap();
    assert_eq!(moves.len(), 1);
    assert_eq!(moves[0].to, Point::new(20_000, -1_000));
    assert!(matches!(
        both(&g32(Point::new(80_000, 0), Point::new(20_000, 0), -1_000, 30_001)),
        Err(CycleError::RunOutTooLong { .. })
    ));
}

/// §9 (R-G75PECK): more than 10^6 pecks are refused, 10^6 admitted, also
/// when they are 10^6 layers of one peck each, where the layer count
/// alone reaches the limit. The engine bounds the count in closed form
/// (`survivors.rs`, `the_peck_count_refuses_too_many_layers_before_counting_them`);
/// the reference counts the layers one by one, so this case takes it
/// about 20 s. `spec/src/g75/roughing.rs` 266:14 (`count > limit` →
/// `count == limit`, from the reference's whole-file run) refused the
/// 10^6 layers.
#[test]
fn a_million_layers_of_one_peck_are_admitted_by_both() {
    use cycleref::g75::MAX_PECKS;
    use cycleref_proofs::groove::{any_groove, GrooveDomain};
    use cycleref_proofs::shim::{check, Mode};
    let refused = CycleError::TooManyPecks { limit: MAX_PECKS };
    // (depth Y, Δv = 1, Δi = 1): Y layers of one peck and one plunge.
    for (depth, expected) in [(1_000_000, Ok(())), (1_000_001, Err(refused))] {
        let domain = GrooveDomain::layers_only((depth, depth), (1, 1), (1, 1));
        // The domain is one point: its one run makes the cycle.
        let r = check("a million layers", Mode::Exhaustive { max_runs: 1 }, || {
            let c = any_groove(&domain);
            assert_eq!(cycleref::expand_g75(&c).map(|_| ()), expected, "Y {depth}: the engine");
            let g = cycleref_spec::g75::groove(&c);
            let layers = cycleref_spec::g75::rough_layers(&g, 0).map(|layers| layers.len());
            assert_eq!(layers, expected.map(|()| 1_000_000), "Y {depth}: the reference");
        });
        assert_eq!(r.runs, 1);
    }
}
