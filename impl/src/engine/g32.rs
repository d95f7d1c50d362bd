//! The fixed-point G32 engine: [`cycleref_spec::g32::expand`] in integers.
//!
//! A G32 block gives at most two moves (the cut and the run-out), so they
//! are computed up front into a two-slot array; [`G32Moves`] hands them
//! out. Widths: coordinates and J, K are below 2^31 in magnitude after
//! `validate()`; the only products (a coordinate difference times another,
//! for the run-out start on a taper) are below 2^64 and are formed in
//! `i128`, and the rounded quotient, which lies between the block's two
//! coordinates, is narrowed back to `i64` by the engines' one saturating
//! narrowing (it never saturates).
//!
//! [`cycleref_spec::g32::expand`]: https://docs.rs/cycleref-spec

use core::iter::FusedIterator;

use super::arith::{round_div, saturate_i64};
use crate::error::CycleError;
use crate::g32::{G32Block, G32RunOut};
use crate::moves::{Motion, Move, Role};
use crate::units::{Length, Point};

/// The moves of one G32 block (at most two), made by [`expand_g32`].
#[derive(Clone, Copy, Debug)]
pub struct G32Moves {
    moves: [Option<Move>; 2],
    next: usize,
}

impl Iterator for G32Moves {
    type Item = Move;

    #[inline]
    fn next(&mut self) -> Option<Move> {
        let m = self.moves.get(self.next).copied().flatten();
        if m.is_some() {
            self.next += 1;
        }
        m
    }
}

impl FusedIterator for G32Moves {}

/// Expands one G32 block: the same error or the same moves as the
/// reference model. Twin: `spec/src/g32.rs`, `expand` (the long axis of
/// `long_axis` and the run-out start on the cut line restated in integers).
///
/// # Errors
///
/// [`G32Block::validate`]'s errors, then [`CycleError::RunOutTooLong`].
pub fn expand_g32(b: &G32Block) -> Result<G32Moves, CycleError> {
    b.validate()?;
    let xf = b.x_mode.factor();
    let (s, e) = (b.start, b.end);
    // |coordinates| < 2^30, so differences < 2^31 and products < 2^62.
    let (dx, dz) = (e.x - s.x, e.z - s.z);
    // Long axis (reading R-G32LONG): Z when |dz| > |dx| / xf, i.e. xf|dz| >
    // |dx|, or at the tie under `tie-z`.
    let z_long = xf * dz.abs() > dx.abs() || (b.readings.g32_tie_z && xf * dz.abs() == dx.abs());
    let thread = |sync| Motion::Thread { lead: b.lead, start_angle: b.start_angle, sync };
    let mut out = G32Moves { moves: [None, None], next: 0 };
    let mut at = s;
    let mut count = 0;
    let mut go = |to: Point, role: Role, out: &mut G32Moves| {
        if to != at {
            let sync = b.sync && count == 0;
            if let Some(slot) = out.moves.get_mut(count) {
                *slot = Some(Move { motion: thread(sync), to, role, pass: None });
            }
            count += 1;
            at = to;
        }
    };
    match b.run_out {
        G32RunOut::None => go(e, Role::Cut, &mut out),
        G32RunOut::Amounts { short, long } => {
            let too_long = |length: i64| CycleError::RunOutTooLong {
                run_out: Length::new(long, b.units),
                length: Length::new(length, b.units),
            };
            if z_long {
                if long > dz.abs() {
                    return Err(too_long(dz.abs()));
                }
                let zr = e.z - dz.signum() * long;
                let num =
                    i128::from(s.x) * i128::from(dz) + i128::from(dx) * (i128::from(zr) - i128::from(s.z));
                let xr = saturate_i64(round_div(num, i128::from(dz)));
                go(Point::new(xr, zr), Role::Cut, &mut out);
                go(Point::new(e.x + xf * short, e.z), Role::RunOut, &mut out);
            } else {
                // K is a radius: compare in X-word units.
                if xf * long > dx.abs() {
                    return Err(too_long(dx.abs() / xf));
                }
                let xr = e.x - dx.signum() * xf * long;
                let num =
                    i128::from(s.z) * i128::from(dx) + i128::from(dz) * (i128::from(xr) - i128::from(s.x));
                let zr = saturate_i64(round_div(num, i128::from(dx)));
                go(Point::new(xr, zr), Role::Cut, &mut out);
                go(Point::new(e.x, e.z + short), Role::RunOut, &mut out);
            }
        }
    }
    Ok(out)
}
