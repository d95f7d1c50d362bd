//! The range limits, exactly at and one past the boundary, in both engines
//! (cargo-mutants showed the `>` of the coordinate check could become `>=`
//! unnoticed).

use cycleref::lead::{Lead, LeadWord};
use cycleref::units::MAX_LENGTH;
use cycleref::{CycleError, Field, G76Cycle, Infeed, Point, RunOut, Units, XMode};

/// An internal thread (radius X) whose thread start C lies at X = end + i.
fn at_the_edge(taper: i64) -> G76Cycle {
    G76Cycle {
        units: Units::IS_B_METRIC,
        x_mode: XMode::Radius,
        start: Point::new(999_990_000, 10_000),
        end: Point::new(999_999_000, -10_000),
        taper,
        thread_height: 1_000,
        first_depth: 400,
        min_cut: 100,
        finishing_allowance: 50,
        finishing_passes: 1,
        tool_angle: 60,
        infeed: Infeed::RightFlank,
        lead_in: 0,
        starts: 1,
        lead: Lead { word: LeadWord::F, mantissa: 2, scale: 0 },
        run_out: RunOut::None,
        pass_limit: 1_000,
    }
}

#[test]
fn thread_start_exactly_at_the_range_limit_expands() {
    // C = 999 999 000 + 999 = MAX_LENGTH: every point is inside the range.
    let c = at_the_edge(999);
    let ours: Vec<_> = cycleref::expand_g76(&c).expect("inside the range").collect();
    assert_eq!(Ok(ours.clone()), cycleref_spec::g76::expand(&c));
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
