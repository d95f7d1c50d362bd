//! Both streams made into groups (a run of rapids and the cutting moves
//! after it) and aligned by edit distance, a window of our groups at a time
//! (reading R-CHECKSTREAM), so that a missing or an extra pass is reported
//! as such. `compare_streams` drives the whole comparison.

use std::collections::VecDeque;
use std::io::BufRead;

use cycleref::Units;

use super::compare::{compare, only_kinds};
use super::error::TraceError;
use super::ours::{OurSteps, Regions};
use super::report::Report;
use super::trace::trace_steps;
use super::{Divergence, Group, Kind, Step, TraceFormat};
use crate::job::{Failure, Job};

/// Whose toolpath an error comes from.
pub(super) enum StreamError {
    /// Our program's (its kind kept).
    Ours(Failure),
    /// The trace's.
    Theirs(TraceError),
}

/// The most moves in one group: a pass longer than this (a program of a
/// million G01 blocks is one "pass") is compared in pieces of this size.
const GROUP_MOVES: usize = 4096;

/// The most groups of ours aligned at once: a cycle with more passes is
/// aligned in windows of this many.
const WINDOW_GROUPS: usize = 512;

/// The most cells of an alignment table (beyond, groups are compared in
/// order): 512 groups of ours against 1024 of theirs.
const MAX_CELLS: usize = 1 << 19;

/// Steps made into groups (a run of rapids and the cutting moves after
/// it), each with its owner: the segment of its first cutting move, or of
/// its first rapid.
struct Grouper<I> {
    steps: I,
    /// The group begun by the step that ended the last one, with its
    /// owners so far (rapids', cuts'): the step is put where it belongs
    /// at once, not held aside and moved again.
    next: Option<(Group, Option<u32>, Option<u32>)>,
    /// Steps taken so far.
    count: usize,
    /// Groups given back once compared, emptied, to be filled again: a
    /// group's two vectors are allocated once, not once per pass (most
    /// of `check`'s allocations were these). At most [`SPARE_GROUPS`].
    spare: Vec<Group>,
}

/// The most emptied groups a [`Grouper`] keeps for reuse: a window and
/// the trace's groups read ahead of it, so memory stays that of one
/// window.
const SPARE_GROUPS: usize = 2 * WINDOW_GROUPS + 16;

/// The most moves an emptied group may have room for and still be kept:
/// a pass has a handful; a group grown to thousands (a long run of plain
/// moves, up to [`GROUP_MOVES`]) is dropped, so that reused groups never
/// hold more room than the passes they carry need.
const SPARE_ROOM: usize = 64;

impl<E, I: Iterator<Item = Result<(Step, u32), E>>> Grouper<I> {
    fn new(steps: I) -> Grouper<I> {
        Grouper { steps, next: None, count: 0, spare: Vec::new() }
    }

    /// Takes back a group that was compared, to fill it again.
    fn recycle(&mut self, mut g: Group) {
        if self.spare.len() < SPARE_GROUPS && g.rapids.capacity() + g.cuts.capacity() <= SPARE_ROOM {
            g.rapids.clear();
            g.cuts.clear();
            self.spare.push(g);
        }
    }

    /// An empty group, reused when one is spare.
    fn empty(&mut self) -> Group {
        self.spare.pop().unwrap_or(Group { rapids: Vec::new(), cuts: Vec::new() })
    }

    fn group(&mut self) -> Option<Result<(Group, u32), E>> {
        let (mut g, mut rapid_owner, mut cut_owner) = match self.next.take() {
            Some(begun) => begun,
            None => (self.empty(), None, None),
        };
        loop {
            // The step is looked at where the source returned it, and
            // copied once, into its group.
            let next = self.steps.next();
            let (s, seg) = match &next {
                None if g.len() == 0 => return None,
                None => break,
                Some(Err(_)) => return next.and_then(Result::err).map(Err),
                Some(Ok((s, seg))) => (s, *seg),
            };
            self.count += 1;
            let full = g.cuts.len() >= GROUP_MOVES || g.rapids.len() >= GROUP_MOVES;
            if g.len() > 0 && ((s.kind == Kind::Rapid && !g.cuts.is_empty()) || full) {
                // The step begins the next group.
                let mut begun = self.empty();
                let owners = if s.kind == Kind::Rapid {
                    begun.rapids.push(*s);
                    (Some(seg), None)
                } else {
                    begun.cuts.push(*s);
                    (None, Some(seg))
                };
                self.next = Some((begun, owners.0, owners.1));
                break;
            }
            if s.kind == Kind::Rapid {
                rapid_owner.get_or_insert(seg);
                g.rapids.push(*s);
            } else {
                cut_owner.get_or_insert(seg);
                g.cuts.push(*s);
            }
        }
        Some(Ok((g, cut_owner.or(rapid_owner).unwrap_or(0))))
    }
}

/// Compares our toolpath with the trace's, both read as they are taken:
/// our groups are aligned a cycle (at most [`WINDOW_GROUPS`] groups) at a
/// time with the trace's next groups, of which the alignment takes what it
/// matches and leaves the rest for the next window (reading R-CHECKSTREAM).
pub(super) fn compare_streams(
    job: &Job,
    trace: Box<dyn BufRead + '_>,
    format: TraceFormat,
    units: Units,
    tolerance: u64,
    cycles_only: bool,
) -> Result<Report, StreamError> {
    let tol = i64::try_from(tolerance).unwrap_or(i64::MAX);
    let mut ours = Grouper::new(OurSteps::new(job, units, cycles_only).map_err(StreamError::Ours)?);
    let steps = trace_steps(trace, format, &job.machine, units).map_err(StreamError::Theirs)?;
    let mut theirs = Grouper::new(steps);
    let mut report = Report::new(units, tolerance, crate::job::readings_in_force(&job.machine));
    let mut pending: VecDeque<Group> = VecDeque::new();
    let mut lookahead: Option<(Group, u32)> = None;
    // Reused from window to window, as the groups are.
    let mut window = Vec::new();
    // A missing group at the end of a window, held until the next window
    // shows whether the pass it begins is missing whole (see `align`).
    let mut carry: Option<Group> = None;
    loop {
        // Our next window: the groups of one owner.
        let mut owner = None;
        loop {
            let next = match lookahead.take() {
                Some(g) => g,
                None => match ours.group() {
                    None => break,
                    Some(r) => r.map_err(StreamError::Ours)?,
                },
            };
            if owner.is_some_and(|o| o != next.1) || window.len() == WINDOW_GROUPS {
                lookahead = Some(next);
                break;
            }
            owner = Some(next.1);
            window.push(next.0);
        }
        if window.is_empty() {
            break;
        }
        let want = window.len() + window.len().max(16);
        while pending.len() < want {
            match theirs.group() {
                None => break,
                Some(r) => pending.push_back(r.map_err(StreamError::Theirs)?.0),
            }
        }
        let next = lookahead.as_ref().map(|(g, _)| g);
        let regions = Regions(&ours.steps.recent);
        let (divergences, taken) =
            align(&window, pending.make_contiguous(), tol, units, regions, next, &mut carry);
        for g in pending.drain(..taken) {
            theirs.recycle(g);
        }
        for g in window.drain(..) {
            ours.recycle(g);
        }
        report.add(divergences);
    }
    if let Some(g) = carry.take() {
        report.add(vec![missing(&g)]);
    }
    // What the trace has beyond our last move.
    for g in pending.drain(..) {
        report.add(vec![extra(&g)]);
    }
    while let Some(g) = theirs.group() {
        report.add(vec![extra(&g.map_err(StreamError::Theirs)?.0)]);
    }
    if theirs.count == 0 {
        return Err(StreamError::Theirs(TraceError::Empty));
    }
    report.ours_moves = ours.count;
    report.theirs_moves = theirs.count;
    Ok(report)
}

/// One step of the alignment.
#[derive(Clone, Copy)]
enum Op {
    /// Our group i against their group j.
    Pair(usize, usize),
    /// Our groups i.. (p of them) joined against their groups j.. (q).
    Join {
        i: usize,
        p: usize,
        j: usize,
        q: usize,
    },
    Missing(usize),
    Extra(usize),
}

/// The joins tried: one group of ours against two of theirs, two against
/// one, two against two (a rapid written for a cutting move splits a pass
/// or moves a pass boundary; the reverse joins them).
const JOINS: [(usize, usize); 3] = [(1, 2), (2, 1), (2, 2)];

/// Groups joined into one: the later groups' rapids become moves among
/// the cuts.
fn joined(gs: &[Group]) -> Group {
    let mut out = Group { rapids: Vec::new(), cuts: Vec::new() };
    for (n, g) in gs.iter().enumerate() {
        out = if n == 0 { g.clone() } else { out.joined(g) };
    }
    out
}

/// Aligns the groups by edit distance (a match costs 0, a substitution 1,
/// a missing or extra group 1, a join of groups that differ only in kinds
/// of move 1) and lists the differences in our order, with the number of
/// their groups taken. When our toolpath goes on with `next`, the
/// alignment may stop before the end of theirs, and the rest belongs to
/// what follows: it stops where the cost plus 1 when their next group is
/// not `next` is least (the fewest groups at equal cost). Without `next`
/// it takes all of `b`.
fn align(
    a: &[Group],
    b: &[Group],
    tol: i64,
    units: Units,
    regions: Regions<'_>,
    next: Option<&Group>,
    carry: &mut Option<Group>,
) -> (Vec<Divergence>, usize) {
    let free_end = next.is_some();
    let (n, m) = (a.len(), b.len());
    let cmp = |x: &Group, y: &Group| compare(x, y, tol, units, regions);
    // Beyond this size the table is too big: compare in order.
    if (n + 1).saturating_mul(m + 1) > MAX_CELLS {
        let mut out: Vec<Divergence> = carry.take().map(|g| missing(&g)).into_iter().collect();
        let end = if free_end { n.min(m) } else { m };
        for i in 0..n.max(end) {
            match (a.get(i), b.get(i).filter(|_| i < end)) {
                (Some(x), Some(y)) => out.extend(cmp(x, y)),
                (Some(x), None) => out.push(missing(x)),
                (None, Some(y)) => out.push(extra(y)),
                (None, None) => {}
            }
        }
        return (out, end);
    }
    // The usual case first: every group of ours met in order, and theirs
    // resumes with our next group (or ends with ours).
    let in_order = n <= m
        && a.iter().zip(b).all(|(x, y)| cmp(x, y).is_empty())
        && match next {
            Some(o) => b.get(n).is_none_or(|t| cmp(o, t).is_empty()),
            None => n == m,
        };
    if in_order {
        return (carry.take().map(|g| missing(&g)).into_iter().collect(), n);
    }
    let w = m + 1;
    let equal: Vec<bool> =
        a.iter().flat_map(|x| b.iter().map(move |y| (x, y))).map(|(x, y)| cmp(x, y).is_empty()).collect();
    let eq = |i: usize, j: usize| equal[i * m + j];
    // A join of our groups i..i+p with their j..j+q, only where the sizes
    // fit (the cheap test first).
    let join = |i: usize, p: usize, j: usize, q: usize| {
        let (x, y) = (&a[i..i + p], &b[j..j + q]);
        x.iter().map(Group::len).sum::<usize>() == y.iter().map(Group::len).sum::<usize>()
            && x[0].rapids.len() == y[0].rapids.len()
            && only_kinds(&cmp(&joined(x), &joined(y)))
    };
    let mut cost = vec![0_u32; (n + 1) * w];
    // The join that reached a cell: 0 none, k + 1 for JOINS[k].
    let mut via = vec![0_u8; (n + 1) * w];
    for i in 0..=n {
        for j in 0..=m {
            let c = if i == 0 || j == 0 {
                u32::try_from(i + j).unwrap_or(u32::MAX / 2)
            } else {
                let sub = cost[(i - 1) * w + j - 1] + u32::from(!eq(i - 1, j - 1));
                let mut c = sub.min(cost[(i - 1) * w + j] + 1).min(cost[i * w + j - 1] + 1);
                for (k, (p, q)) in JOINS.into_iter().enumerate() {
                    if i >= p && j >= q && cost[(i - p) * w + j - q] + 1 < c && join(i - p, p, j - q, q) {
                        via[i * w + j] = u8::try_from(k + 1).unwrap_or(0);
                        c = cost[(i - p) * w + j - q] + 1;
                    }
                }
                c
            };
            cost[i * w + j] = c;
        }
    }
    // Where it ends in theirs: all of it, or (free end) the fewest groups
    // at the least cost.
    let resumes = |j: usize| match (b.get(j), next) {
        (Some(t), Some(o)) => cmp(o, t).is_empty(),
        _ => true,
    };
    let end = if free_end {
        (0..=m).min_by_key(|&j| (cost[n * w + j] + u32::from(!resumes(j)), j)).unwrap_or(m)
    } else {
        m
    };
    // Walk back.
    let (mut i, mut j) = (n, end);
    let mut ops = Vec::new();
    // Walking back, a missing or extra group is preferred over a match of
    // equal cost: when passes repeat (finishing passes), the one reported
    // missing is the last, where a trace that stops early stops, and the
    // one reported extra is the last, the one beyond the manual's count
    // (issue 29: an appended spring pass was named at the first).
    while i > 0 || j > 0 {
        if let Some(&(p, q)) = via[i * w + j].checked_sub(1).and_then(|k| JOINS.get(usize::from(k))) {
            ops.push(Op::Join { i: i - p, p, j: j - q, q });
            i -= p;
            j -= q;
        } else if i > 0 && cost[i * w + j] == cost[(i - 1) * w + j] + 1 {
            ops.push(Op::Missing(i - 1));
            i -= 1;
        } else if j > 0 && cost[i * w + j] == cost[i * w + j - 1] + 1 {
            ops.push(Op::Extra(j - 1));
            j -= 1;
        } else if i > 0
            && j > 0
            && cost[i * w + j] == cost[(i - 1) * w + j - 1] + u32::from(!eq(i - 1, j - 1))
        {
            ops.push(Op::Pair(i - 1, j - 1));
            i -= 1;
            j -= 1;
        } else {
            ops.push(Op::Extra(j - 1));
            j -= 1;
        }
    }
    ops.reverse();
    // A pass is its approach, its cuts and the rapids after them (retract,
    // return), but a group is a run of rapids and the cuts after it: a pass
    // missing from the trace leaves our group i unmatched *and* the rapids
    // that lead our group i + 1 (retract and return of pass i) different
    // from theirs. When the rest of the pair matches once pass i's moves
    // are taken out, the two are one missing pass; likewise an extra pass
    // of theirs (issue 29).
    let mut out = Vec::new();
    let mut k = 0;
    if let Some(g) = carry.take() {
        match ops.first() {
            Some(&Op::Pair(0, y)) if !eq(0, y) && without_pass(&g, &a[0], &b[y], &cmp) => {
                out.push(missing_pass(&g, &a[0]));
                k = 1;
            }
            _ => out.push(missing(&g)),
        }
    }
    while k < ops.len() {
        match (ops[k], ops.get(k + 1).copied()) {
            (Op::Missing(x), Some(Op::Pair(x1, y)))
                if x1 == x + 1 && !eq(x1, y) && without_pass(&a[x], &a[x1], &b[y], &cmp) =>
            {
                out.push(missing_pass(&a[x], &a[x1]));
                k += 2;
                continue;
            }
            (Op::Extra(y), Some(Op::Pair(x, y1)))
                if y1 == y + 1 && !eq(x, y1) && without_pass(&b[y], &b[y1], &a[x], &|t, o| cmp(o, t)) =>
            {
                out.push(extra_pass(&b[y], &b[y1]));
                k += 2;
                continue;
            }
            // Our window's last group, missing, with a next window to come:
            // held, to be judged with that window's first pair.
            (Op::Missing(x), None) if free_end && x + 1 == n => *carry = Some(a[x].clone()),
            (Op::Pair(x, y), _) => out.extend(cmp(&a[x], &b[y])),
            (Op::Join { i, p, j, q }, _) => out.extend(cmp(&joined(&a[i..i + p]), &joined(&b[j..j + q]))),
            (Op::Missing(x), _) => out.push(missing(&a[x])),
            (Op::Extra(y), _) => out.push(extra(&b[y])),
        }
        k += 1;
    }
    (out, end)
}

fn first_step(g: &Group) -> Option<Step> {
    g.cuts.first().or(g.rapids.last()).copied()
}

/// True when `other` is `next` without the pass that `gone` begins: the
/// rapids of `gone` up to its approach, then the approach of `next`, then
/// the cuts of `next`, compared by `cmp` as equal. The rapids of `next`
/// before its approach are the retract and return of the pass of `gone`.
fn without_pass(
    gone: &Group,
    next: &Group,
    other: &Group,
    cmp: &dyn Fn(&Group, &Group) -> Vec<Divergence>,
) -> bool {
    let (Some((_, lead)), Some(approach)) = (gone.rapids.split_last(), next.rapids.last()) else {
        return false;
    };
    let mut rapids = lead.to_vec();
    let mut approach = *approach;
    approach.from = lead.last().map(|s| s.to).or(gone.rapids.last().and_then(|s| s.from));
    rapids.push(approach);
    let shifted = Group { rapids, cuts: next.cuts.clone() };
    cmp(&shifted, other).is_empty()
}

/// The moves of the pass `gone` begins and `next` ends: its approach, its
/// cuts, and the rapids of `next` before its approach.
fn pass_moves(gone: &Group, next: &Group) -> usize {
    1 + gone.cuts.len() + next.rapids.len().saturating_sub(1)
}

/// A pass of ours missing whole from the trace (see [`without_pass`]).
fn missing_pass(gone: &Group, next: &Group) -> Divergence {
    Divergence { moves: pass_moves(gone, next), ..missing(gone) }
}

/// A pass of theirs that we do not cut (see [`without_pass`]).
fn extra_pass(extra_group: &Group, next: &Group) -> Divergence {
    Divergence { moves: pass_moves(extra_group, next), ..extra(extra_group) }
}

fn missing(g: &Group) -> Divergence {
    Divergence { what: "missing pass", ours: first_step(g), theirs: None, moves: g.len() }
}

fn extra(g: &Group) -> Divergence {
    Divergence { what: "extra pass", ours: None, theirs: first_step(g), moves: g.len() }
}

#[cfg(test)]
mod tests {
    use cycleref::Point;

    use super::*;
    use crate::check::test_steps::{pass, step, MM};

    fn whats(d: &[Divergence]) -> Vec<&'static str> {
        d.iter().map(|d| d.what).collect()
    }

    #[test]
    fn equal_groups_agree_and_take_as_many() {
        let ours = [pass(100), pass(90), pass(80)];
        let theirs = [pass(100), pass(90), pass(80), pass(70)];
        // Our next group is theirs after the three: they agree, three taken.
        let (d, taken) = align(&ours, &theirs, 0, MM, Regions(&VecDeque::new()), Some(&pass(70)), &mut None);
        assert_eq!((whats(&d), taken), (vec![], 3));
        // Without a next group, all of theirs is taken: one extra pass.
        let (d, taken) = align(&ours, &theirs, 0, MM, Regions(&VecDeque::new()), None, &mut None);
        assert_eq!((whats(&d), taken), (vec!["extra pass"], 4));
    }

    #[test]
    fn a_missing_pass_is_one_divergence_not_a_shift() {
        let ours = [pass(100), pass(90), pass(80), pass(70)];
        let theirs = [pass(100), pass(80), pass(70)];
        let (d, taken) = align(&ours, &theirs, 0, MM, Regions(&VecDeque::new()), None, &mut None);
        assert_eq!((whats(&d), taken), (vec!["missing pass"], 3));
        assert_eq!(d[0].ours.map(|s| s.to), Some(Point::new(90, -30)));
    }

    #[test]
    fn a_window_stops_where_the_trace_resumes_with_our_next_group() {
        // Our window's last pass is missing from the trace, which goes on
        // with our next window's first pass: the window takes two groups and
        // reports the missing pass, instead of pairing it with the next
        // window's pass (a substitution, then an extra pass later). The
        // missing pass is held until the next window, whose first pair
        // shows whether it is missing whole; it is reported there.
        let ours = [pass(100), pass(90), pass(80)];
        let next = pass(500);
        let theirs = [pass(100), pass(90), pass(500), pass(490)];
        let mut carry = None;
        let (d, taken) = align(&ours, &theirs, 0, MM, Regions(&VecDeque::new()), Some(&next), &mut carry);
        assert_eq!((whats(&d), taken), (vec![], 2));
        assert_eq!(carry.as_ref().and_then(|g| g.cuts.first()).map(|s| s.to), Some(Point::new(80, -30)));
        let (d, taken) =
            align(&[next, pass(490)], &theirs[2..], 0, MM, Regions(&VecDeque::new()), None, &mut carry);
        assert_eq!((whats(&d), taken), (vec!["missing pass"], 2));
        assert!(carry.is_none());
    }

    #[test]
    fn a_changed_end_point_is_named_within_the_tolerance() {
        let ours = [pass(100)];
        let mut moved = pass(100);
        moved.cuts[0].to = Point::new(100, -31);
        let (d, _) =
            align(&ours, std::slice::from_ref(&moved), 0, MM, Regions(&VecDeque::new()), None, &mut None);
        assert_eq!(whats(&d), vec!["end point"]);
        let (d, _) =
            align(&ours, std::slice::from_ref(&moved), 1, MM, Regions(&VecDeque::new()), None, &mut None);
        assert!(d.is_empty());
    }

    #[test]
    fn long_runs_are_grouped_in_pieces() {
        // One rapid and GROUP_MOVES + 5 feeds: two groups, the second of 5.
        let steps = std::iter::once(Ok::<_, TraceError>((step(Kind::Rapid, 0, 0, 1), 0))).chain(
            (1..=GROUP_MOVES + 5).map(|i| Ok((step(Kind::Feed, 0, -i64::try_from(i).unwrap_or(0), 2), 0))),
        );
        let mut g = Grouper::new(steps);
        let first = g.group().and_then(Result::ok).map(|(g, _)| (g.rapids.len(), g.cuts.len()));
        let second = g.group().and_then(Result::ok).map(|(g, _)| (g.rapids.len(), g.cuts.len()));
        assert_eq!((first, second), (Some((1, GROUP_MOVES)), Some((0, 5))));
        assert!(g.group().is_none());
        assert_eq!(g.count, GROUP_MOVES + 6);
    }
}
