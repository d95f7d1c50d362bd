//! The one comparison of an engine's expansion with the reference model's:
//! the same alarm, or the same moves in the same order.
//!
//! The differential tests (`proofs/tests/engine_equals_spec.rs`,
//! `proofs/tests/g75_equivalence.rs`) and the test-vector checks compare the
//! fixed-point engine (`cycleref`) with this crate's reference model cycle
//! by cycle. [`compare`] says how two results differ as a typed
//! [`Difference`], whose [`Display`](fmt::Display) names the counts and the
//! first differing move (1-based, both sides), instead of two long vectors;
//! [`assert_same_moves`] panics with it, for tests.
//!
//! ```
//! use cycleref::{CycleError, Motion, Move, Point, Role};
//! use cycleref_spec::differ::{assert_same_moves, compare, Difference};
//!
//! let rapid = |x, z| Move { motion: Motion::Rapid, to: Point::new(x, z), role: Role::Approach, pass: None };
//! let reference = Ok(vec![rapid(10, 0), rapid(10, -50)]);
//!
//! assert_eq!(compare(&Ok(vec![rapid(10, 0), rapid(10, -50)]), &reference), Ok(()));
//! assert_same_moves(&reference.clone(), &reference, "the same cycle");
//!
//! let engine = Ok(vec![rapid(10, 0), rapid(10, -49)]);
//! let difference = compare(&engine, &reference).unwrap_err();
//! assert!(matches!(difference, Difference::Moves { index: 2, engine_count: 2, reference_count: 2, .. }));
//! assert!(difference.to_string().starts_with("2 engine moves against 2 reference moves; first difference at move 2"));
//!
//! let refused = Err(CycleError::StartInsideThread);
//! assert!(matches!(compare(&refused, &reference), Err(Difference::Outcomes { .. })));
//! ```

use std::fmt;

use cycleref::{CycleError, Move};

/// What expanding a cycle gives: all its moves, or its alarm.
pub type Expansion = Result<Vec<Move>, CycleError>;

/// How the engine's expansion of a cycle differs from the reference's.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Difference {
    /// Both expand the cycle, to different moves.
    Moves {
        /// How many moves the engine gives.
        engine_count: usize,
        /// How many moves the reference gives.
        reference_count: usize,
        /// The first move that differs, 1-based (one past the shorter list
        /// when one list is the other's beginning).
        index: usize,
        /// The engine's move there, `None` past its last move (boxed: a
        /// [`Difference`] is an error value, kept small).
        engine: Option<Box<Move>>,
        /// The reference's move there, `None` past its last move.
        reference: Option<Box<Move>>,
    },
    /// At least one refuses the cycle, and the outcomes differ: each side's
    /// move count, or its alarm.
    Outcomes {
        /// The engine's move count or alarm.
        engine: Result<usize, CycleError>,
        /// The reference's move count or alarm.
        reference: Result<usize, CycleError>,
    },
}

/// `Ok(())` when the engine's expansion equals the reference's (the same
/// alarm, or the same moves in the same order), else how they differ.
///
/// # Errors
///
/// The [`Difference`]: the first differing move when both expand, the two
/// outcomes otherwise.
pub fn compare(engine: &Expansion, reference: &Expansion) -> Result<(), Difference> {
    if engine == reference {
        return Ok(());
    }
    match (engine, reference) {
        (Ok(e), Ok(r)) => {
            // They differ, so either a move differs or one list is longer.
            let at = e.iter().zip(r).position(|(a, b)| a != b).unwrap_or(e.len().min(r.len()));
            Err(Difference::Moves {
                engine_count: e.len(),
                reference_count: r.len(),
                index: at + 1,
                engine: e.get(at).copied().map(Box::new),
                reference: r.get(at).copied().map(Box::new),
            })
        }
        (e, r) => Err(Difference::Outcomes {
            engine: e.as_ref().map(Vec::len).map_err(Clone::clone),
            reference: r.as_ref().map(Vec::len).map_err(Clone::clone),
        }),
    }
}

/// Panics, naming `what` (the cycle, a file and line) and the
/// [`Difference`], unless the engine's expansion equals the reference's.
///
/// # Panics
///
/// When [`compare`] finds a difference.
#[track_caller]
pub fn assert_same_moves(engine: &Expansion, reference: &Expansion, what: impl fmt::Display) {
    if let Err(difference) = compare(engine, reference) {
        panic!("{what}: the engine and the reference model differ: {difference}");
    }
}

/// A move, or that there is none at that index.
struct MoveAt<'a>(&'a Option<Box<Move>>);

impl fmt::Display for MoveAt<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Some(m) => write!(f, "{m:?}"),
            None => f.write_str("none (past the last move)"),
        }
    }
}

/// A move count, or an alarm.
struct Outcome<'a>(&'a Result<usize, CycleError>);

impl fmt::Display for Outcome<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Ok(n) => write!(f, "{n} moves"),
            Err(e) => write!(f, "the alarm {e:?} ({e})"),
        }
    }
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Difference::Moves { engine_count, reference_count, index, engine, reference } => write!(
                f,
                "{engine_count} engine moves against {reference_count} reference moves; first difference at \
                 move {index}: engine {}, reference {}",
                MoveAt(engine),
                MoveAt(reference)
            ),
            Difference::Outcomes { engine, reference } => {
                write!(f, "engine {}, reference {}", Outcome(engine), Outcome(reference))
            }
        }
    }
}

impl std::error::Error for Difference {}

#[cfg(test)]
mod tests {
    use super::*;
    use cycleref::{Motion, Point, Role};

    fn feed(z: i64) -> Move {
        Move { motion: Motion::Feed, to: Point::new(0, z), role: Role::Cut, pass: None }
    }

    #[test]
    fn equal_results_compare_equal() {
        assert_eq!(compare(&Ok(vec![feed(1)]), &Ok(vec![feed(1)])), Ok(()));
        let e = Err(CycleError::StartInsideThread);
        assert_eq!(compare(&e, &e), Ok(()));
    }

    #[test]
    fn a_longer_list_differs_one_past_the_shorter() {
        let d = compare(&Ok(vec![feed(1)]), &Ok(vec![feed(1), feed(2)])).unwrap_err();
        assert_eq!(
            d,
            Difference::Moves {
                engine_count: 1,
                reference_count: 2,
                index: 2,
                engine: None,
                reference: Some(Box::new(feed(2)))
            }
        );
        assert!(d.to_string().contains("engine none (past the last move), reference Move"), "{d}");
    }

    #[test]
    fn outcomes_name_counts_and_alarms() {
        let d = compare(&Err(CycleError::StartInsideThread), &Ok(vec![feed(1)])).unwrap_err();
        let text = d.to_string();
        assert!(text.starts_with("engine the alarm StartInsideThread ("), "{text}");
        assert!(text.ends_with("reference 1 moves"), "{text}");
    }

    #[test]
    #[should_panic(expected = "cycle 7: the engine and the reference model differ: 1 engine moves against 1")]
    fn the_assertion_names_what_it_compares() {
        assert_same_moves(&Ok(vec![feed(1)]), &Ok(vec![feed(2)]), "cycle 7");
    }
}
