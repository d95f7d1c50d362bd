//! One group of ours compared with one of theirs, move by move: the kinds,
//! end points and arc centres (within the tolerance), the leads,
//! synchronisation and start angles (exactly), and rapids, which may be
//! split into an X and a Z move outside the regions the cycles cut
//! (reading R-CHECKSPLIT).

use cycleref::angle::FULL_TURN_MILLIDEGREES;
use cycleref::{Lead, Point, StartAngle, Units};

use super::ours::Regions;
use super::{Divergence, Group, Kind, Step};

/// True when two leads are the same rate (F6 and F6.000; an F and an I of
/// the same value).
fn same_lead(a: Option<Lead>, b: Option<Lead>, units: Units) -> bool {
    match (a, b) {
        // The same word and digits: the same rate, without the products
        // (`u128` products checked for overflow were half of a canonical
        // trace's comparison).
        (Some(a), Some(b)) if a == b => true,
        (Some(a), Some(b)) => {
            let (ra, rb) = (a.increments_per_rev(units), b.increments_per_rev(units));
            ra.num.checked_mul(rb.den) == rb.num.checked_mul(ra.den)
        }
        (None, None) => true,
        _ => false,
    }
}

/// True when a trace's start angle `theirs` is our `ours`: the same angle,
/// or ours rounded to the nearest thousandth of a degree when theirs is a
/// whole number of thousandths and ours is not (reading R-CHECKQ: a `Q`
/// word writes thousandths, and the starts of an L-start thread are
/// 360°/L apart, which for L = 7 is no whole number of them).
fn same_angle(ours: StartAngle, theirs: StartAngle) -> bool {
    ours == theirs
        || (ours.den > 1
            && theirs.den == 1
            && u64::from(theirs.num) == ours.rounded_millidegrees() % FULL_TURN_MILLIDEGREES)
}

/// The two corners of a rapid from `p` to `q` split into an X and a Z move.
fn corners(p: Point, q: Point) -> [Point; 2] {
    [Point::new(q.x, p.z), Point::new(p.x, q.z)]
}

/// Compares a group of ours with a group of theirs; the differences.
pub(super) fn compare(a: &Group, b: &Group, tol: i64, units: Units, regions: Regions<'_>) -> Vec<Divergence> {
    let mut out = Vec::new();
    let tol = i128::from(tol);
    // Equal points first (the usual case), without the wide differences.
    let close = |p: Point, q: Point| {
        p == q
            || (i128::from(p.x) - i128::from(q.x)).abs() <= tol
                && (i128::from(p.z) - i128::from(q.z)).abs() <= tol
    };
    let through = |p: Point, c: Point, q: Point| regions.any(|r| r.crossed_by(p, c) || r.crossed_by(c, q));
    let div = |what, o: &Step, t: &Step| Divergence { what, ours: Some(*o), theirs: Some(*t), moves: 1 };
    // Rapids: their points must be ours. A rapid of ours may be reached
    // through either corner of an X/Z split, and an X/Z split of ours may be
    // made in the other order, as long as the legs stay out of the regions
    // the cycles cut (R-CHECKSPLIT).
    let (ra, rb) = (&a.rapids, &b.rapids);
    let (mut i, mut j) = (0, 0);
    while i < ra.len() {
        let r = &ra[i];
        let Some(t) = rb.get(j) else {
            out.push(Divergence { what: "rapid point", ours: Some(*r), theirs: None, moves: 1 });
            i += 1;
            continue;
        };
        if close(t.to, r.to) {
            i += 1;
            j += 1;
            continue;
        }
        let then = |p: Point| rb.get(j + 1).is_some_and(|u| close(u.to, p));
        // A diagonal of ours, split by theirs.
        if let Some(p) = r.from.filter(|p| p.x != r.to.x && p.z != r.to.z) {
            if let Some(c) = corners(p, r.to).into_iter().find(|&c| close(t.to, c) && then(r.to)) {
                if through(p, c, r.to) {
                    out.push(div("rapid through the work", r, t));
                }
                i += 1;
                j += 2;
                continue;
            }
        }
        // A split of ours (r is the corner of `p` to the next), made in
        // the other order by theirs.
        if let (Some(p), Some(n)) = (r.from, ra.get(i + 1)) {
            let [c0, c1] = corners(p, n.to);
            let other = if r.to == c0 && c0 != p && c0 != n.to {
                Some(c1)
            } else if r.to == c1 && c1 != p && c1 != n.to {
                Some(c0)
            } else {
                None
            };
            if let Some(c) = other.filter(|&c| close(t.to, c) && then(n.to)) {
                if through(p, c, n.to) {
                    out.push(div("rapid through the work", r, t));
                }
                i += 2;
                j += 2;
                continue;
            }
        }
        let crossed = t.from.is_some_and(|p| regions.any(|g| g.crossed_by(p, t.to)));
        out.push(div(if crossed { "rapid through the work" } else { "rapid point" }, r, t));
        i += 1;
        j += 1;
    }
    for t in rb.iter().skip(j) {
        out.push(Divergence { what: "extra rapid", ours: None, theirs: Some(*t), moves: 1 });
    }
    for (i, c) in a.cuts.iter().enumerate() {
        let Some(t) = b.cuts.get(i) else {
            out.push(Divergence { what: "missing move", ours: Some(*c), theirs: None, moves: 1 });
            continue;
        };
        if c.kind != t.kind && !(c.kind.is_arc() && t.kind.is_arc()) {
            out.push(div("kind of move", c, t));
            continue;
        }
        if c.kind != t.kind {
            out.push(div("arc direction", c, t));
        }
        if !close(c.to, t.to) {
            out.push(div("end point", c, t));
        }
        if let (Some(oc), Some(tc)) = (c.centre, t.centre) {
            if !close(oc, tc) {
                out.push(div("arc centre", c, t));
            }
        }
        if c.kind == Kind::Thread {
            if !same_lead(c.lead, t.lead, units) {
                out.push(div("lead", c, t));
            }
            if c.sync != t.sync {
                out.push(div("synchronisation", c, t));
            } else if c.sync && !same_angle(c.angle, t.angle) {
                out.push(div("start angle", c, t));
            }
        }
    }
    for t in b.cuts.iter().skip(a.cuts.len()) {
        out.push(Divergence { what: "extra move", ours: None, theirs: Some(*t), moves: 1 });
    }
    out
}

/// True when the only differences are kinds of move: a rapid written for a
/// cutting move or the reverse, every point in its place.
pub(super) fn only_kinds(d: &[Divergence]) -> bool {
    d.iter().all(|d| d.what == "kind of move")
}

#[cfg(test)]
mod tests {
    use cycleref::{Lead, LeadWord, Point, StartAngle};

    use std::collections::VecDeque;

    use cycleref_spec::cycles::Region;

    use super::*;
    use crate::check::ours::RecentCycle;
    use crate::check::test_steps::{step, MM};

    fn whats(d: &[Divergence]) -> Vec<&'static str> {
        d.iter().map(|d| d.what).collect()
    }

    /// A group of the given rapids and cuts.
    fn group(rapids: Vec<Step>, cuts: Vec<Step>) -> Group {
        Group { rapids, cuts }
    }

    /// A rapid to (x, z) from (fx, fz).
    fn rapid(from: (i64, i64), to: (i64, i64)) -> Step {
        Step { from: Some(Point::new(from.0, from.1)), ..step(Kind::Rapid, to.0, to.1, 1) }
    }

    #[test]
    fn a_diagonal_rapid_split_outside_the_regions_agrees() {
        // Ours: (100, 10) to (90, 0) in one rapid. Theirs: along X to the
        // corner (90, 10), then along Z to (90, 0), or along Z first to the
        // corner (100, 0).
        let (empty, known) = (
            VecDeque::new(),
            VecDeque::from([RecentCycle::Known(
                // A region X 85..95, Z 2..8 (open).
                Region::spanning(&[(85, 2), (95, 8)]).into_iter().collect(),
            )]),
        );
        let none = Regions(&empty);
        let ours = group(vec![rapid((100, 10), (90, 0))], vec![]);
        let x_first = group(vec![rapid((100, 10), (90, 10)), rapid((90, 10), (90, 0))], vec![]);
        let z_first = group(vec![rapid((100, 10), (100, 0)), rapid((100, 0), (90, 0))], vec![]);
        assert!(compare(&ours, &x_first, 0, MM, none).is_empty());
        assert!(compare(&ours, &z_first, 0, MM, none).is_empty());
        // A region X 85..95, Z 2..8 (open): the X-first split's second leg
        // runs down X 90 through it (R-CHECKSPLIT); the Z-first split's legs
        // (X 100, then Z 0) pass it by.
        let cut = Regions(&known);
        assert_eq!(whats(&compare(&ours, &x_first, 0, MM, cut)), ["rapid through the work"]);
        assert!(compare(&ours, &z_first, 0, MM, cut).is_empty());
        // A rapid to another point, and one more rapid than ours.
        let elsewhere = group(vec![rapid((100, 10), (90, 1))], vec![]);
        assert_eq!(whats(&compare(&ours, &elsewhere, 0, MM, none)), ["rapid point"]);
        assert!(compare(&ours, &elsewhere, 1, MM, none).is_empty(), "within a tolerance of 1");
        let more = group(vec![rapid((100, 10), (90, 0)), rapid((90, 0), (95, 0))], vec![]);
        assert_eq!(whats(&compare(&ours, &more, 0, MM, none)), ["extra rapid"]);
    }

    #[test]
    fn leads_are_compared_as_rates() {
        let thread = |lead: Lead| Step { lead: Some(lead), ..step(Kind::Thread, 90, -30, 2) };
        let lead = |word, mantissa, scale| Lead { word, mantissa, scale };
        let ours = group(vec![], vec![thread(lead(LeadWord::F, 254, 2))]);
        // F2.54 = F2.540 = I10 (25.4 mm / 10 threads per inch): the same
        // rate, 2540 increments a turn.
        for same in [lead(LeadWord::F, 2540, 3), lead(LeadWord::I, 10, 0)] {
            assert!(
                compare(&ours, &group(vec![], vec![thread(same)]), 0, MM, Regions(&VecDeque::new()))
                    .is_empty(),
                "{same:?}"
            );
        }
        // F2.5 and I11 (2309.09… increments) are other rates.
        for other in [lead(LeadWord::F, 25, 1), lead(LeadWord::I, 11, 0)] {
            let d = compare(&ours, &group(vec![], vec![thread(other)]), 0, MM, Regions(&VecDeque::new()));
            assert_eq!(whats(&d), ["lead"], "{other:?}");
        }
    }

    #[test]
    fn synchronisation_and_start_angle_are_exact() {
        let ours = group(vec![], vec![step(Kind::Thread, 90, -30, 2)]);
        let unsynchronised = Step { sync: false, ..step(Kind::Thread, 90, -30, 2) };
        let d = compare(&ours, &group(vec![], vec![unsynchronised]), 0, MM, Regions(&VecDeque::new()));
        assert_eq!(whats(&d), ["synchronisation"]);
        // 180° for 0°: a start angle, whatever the tolerance.
        let half_turn = Step { angle: StartAngle { num: 180_000, den: 1 }, ..step(Kind::Thread, 90, -30, 2) };
        let d = compare(&ours, &group(vec![], vec![half_turn]), 1_000, MM, Regions(&VecDeque::new()));
        assert_eq!(whats(&d), ["start angle"]);
    }

    #[test]
    fn kinds_arcs_and_counts_of_moves() {
        // A rapid written for a feed: a kind of move, and nothing else.
        let ours = group(vec![], vec![step(Kind::Feed, 90, -30, 2)]);
        let d = compare(
            &ours,
            &group(vec![], vec![step(Kind::Rapid, 90, -30, 2)]),
            0,
            MM,
            Regions(&VecDeque::new()),
        );
        assert_eq!(whats(&d), ["kind of move"]);
        assert!(only_kinds(&d));
        // An arc the other way round with its centre 2 off: the direction
        // and the centre (beyond a tolerance of 1, not of 2).
        let arc = |kind, cz| Step { centre: Some(Point::new(80, cz)), ..step(kind, 90, -30, 2) };
        let ours = group(vec![], vec![arc(Kind::ArcCw, -20)]);
        let d =
            compare(&ours, &group(vec![], vec![arc(Kind::ArcCcw, -22)]), 1, MM, Regions(&VecDeque::new()));
        assert_eq!(whats(&d), ["arc direction", "arc centre"]);
        assert!(!only_kinds(&d));
        assert_eq!(
            whats(&compare(
                &ours,
                &group(vec![], vec![arc(Kind::ArcCcw, -22)]),
                2,
                MM,
                Regions(&VecDeque::new())
            )),
            ["arc direction"]
        );
        // One move short, and one too many.
        let two = group(vec![], vec![step(Kind::Feed, 90, -30, 2), step(Kind::Feed, 100, -30, 3)]);
        let one = group(vec![], vec![step(Kind::Feed, 90, -30, 2)]);
        assert_eq!(whats(&compare(&two, &one, 0, MM, Regions(&VecDeque::new()))), ["missing move"]);
        assert_eq!(whats(&compare(&one, &two, 0, MM, Regions(&VecDeque::new()))), ["extra move"]);
    }
}
