//! One group of ours compared with one of theirs, move by move: the kinds,
//! end points and arc centres (within the tolerance), the leads,
//! synchronisation and start angles (exactly), and rapids, which may be
//! split into an X and a Z move outside the regions the cycles cut
//! (reading R-CHECKSPLIT).

use cycleref::{Lead, Point, Units};

use super::ours::Region;
use super::{Divergence, Group, Kind, Step};

/// True when two leads are the same rate (F6 and F6.000; an F and an I of
/// the same value).
fn same_lead(a: Option<Lead>, b: Option<Lead>, units: Units) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => {
            let (ra, rb) = (a.increments_per_rev(units), b.increments_per_rev(units));
            ra.num.checked_mul(rb.den) == rb.num.checked_mul(ra.den)
        }
        (None, None) => true,
        _ => false,
    }
}

/// The two corners of a rapid from `p` to `q` split into an X and a Z move.
fn corners(p: Point, q: Point) -> [Point; 2] {
    [Point::new(q.x, p.z), Point::new(p.x, q.z)]
}

/// Compares a group of ours with a group of theirs; the differences.
pub(super) fn compare(a: &Group, b: &Group, tol: i64, units: Units, regions: &[Region]) -> Vec<Divergence> {
    let mut out = Vec::new();
    let tol = i128::from(tol);
    let close = |p: Point, q: Point| {
        (i128::from(p.x) - i128::from(q.x)).abs() <= tol && (i128::from(p.z) - i128::from(q.z)).abs() <= tol
    };
    let through =
        |p: Point, c: Point, q: Point| regions.iter().any(|r| r.crossed_by(p, c) || r.crossed_by(c, q));
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
        let crossed = t.from.is_some_and(|p| regions.iter().any(|g| g.crossed_by(p, t.to)));
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
            } else if c.sync && c.angle != t.angle {
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
