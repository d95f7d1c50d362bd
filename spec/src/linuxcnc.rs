//! LinuxCNC's G76 threading cycle, exactly: the reference model of the
//! `linuxcnc` profile.
//!
//! The authority is LinuxCNC's interpreter, `convert_threading_cycle` and
//! `threading_pass` (`src/emc/rs274ngc/interp_convert.cc`, LinuxCNC 2.9;
//! line numbers below are of master 5c41560eb, whose threading code is
//! the installed 2.9.0~pre1's). Where its documentation and its code
//! differ, the code wins (readings `R-LCNC…` in `docs/INTERPRETATIONS.md`).
//!
//! With the drive line X₀ (the X before the block), σ = +1 for an external
//! thread (I < 0) and -1 for an internal one, ξ = 2 in G7 and 1 in G8, and
//! `t = tan Q` (Q negated when the thread runs towards +Z), a pass at depth
//! `δ` below the peak (`δ = J·n^(1/R)` for rough pass n, `δ = K` at full
//! depth) is, in LinuxCNC's own words:
//!
//! | move | to X | to Z |
//! |---|---|---|
//! | "back" (rapid) | `X₀ + σ(K − δ)` | `Z₀ − ζ`, `ζ = (δ/ξ)·t` |
//! | "in" (rapid) | `X₀ − σ(|I| + δ)` | `Z₀ − ζ` |
//! | "over" (synchronised, P) | `X₀ − σ(|I| + δ)` | `Z + (K/ξ)·t − ζ` |
//! | "out" (rapid) | `X₀ + σ(K − δ)` | `Z + (K/ξ)·t − ζ` |
//!
//! (interp_convert.cc l.5657-5701, R-LCNC-PASS). With an entry taper (E >
//! 0, L bit 1) "in" is two synchronised moves at the taper pitch instead:
//! to `X₀ − σ(|I| + δ) + σK` at `Z₀ − ζ`, then to `X₀ − σ(|I| + δ)` at `Z₀ − ζ
//! − E`; with an exit taper (L bit 2) "over" stops at `… + E` and a
//! synchronised move at the taper pitch climbs `σK` back to the pass's end
//! Z. Rough passes run while `δ < K` (l.5776); then 1 + H passes at full
//! depth (l.5784-5790); then one rapid to the block's end point X Z
//! (l.5791). Every coordinate is the exact value rounded to the nearest
//! increment, ties away from zero (R-LCNC-EXACT); comparisons are exact.

use std::cmp::Ordering;

use cycleref::angle::StartAngle;
use cycleref::error::CycleError;
use cycleref::lead::{Lead, MAX_LEAD_SCALE};
use cycleref::linuxcnc::{LinuxCncG76, DEGRESSION_ONE};
use cycleref::moves::{Flank, Motion, Move, Pass, PassKind, Role};
use cycleref::units::{Point, MAX_LENGTH};
use cycleref::Length;
use num_bigint::BigInt;
use num_traits::ToPrimitive;

use crate::pass::PassStream;
use crate::real::Real;

/// `x` rounded to the nearest integer, ties away from zero, decided
/// exactly (`Real::nearest` rounds ties upwards, so a negative value is
/// rounded as its opposite).
///
/// Twin: `impl/src/engine/linuxcnc.rs`, `Values::round_away`.
fn round_away(x: &Real) -> Result<i64, CycleError> {
    let r = if x.sign()? == Ordering::Less { -(-x).nearest()? } else { x.nearest()? };
    r.to_i64().filter(|v| v.unsigned_abs() <= MAX_LENGTH.unsigned_abs()).ok_or(CycleError::OutOfRange {
        field: cycleref::Field::PassCoordinate,
        value: Length { increments: 0, decimals: 0 },
    })
}

/// The pitch of LinuxCNC's taper moves, `P · hypot(E, K) / E` with K as a
/// radius (l.5757-5758), rounded to the nearest 10⁻⁶ (the lead's finest
/// scale, and the six decimals `rs274` prints): the feed per revolution
/// along the taper's path, which advances Z by exactly P per revolution
/// (reading R-LCNC-SYNC). Without a taper (E = 0) it is P, as LinuxCNC's
/// `taper_pitch` is.
///
/// Twin: `impl/src/engine/linuxcnc.rs`, `taper_pitch` (in 256-bit
/// integers).
#[must_use]
pub fn taper_pitch(c: &LinuxCncG76) -> Lead {
    if c.taper_distance <= 0 {
        return c.pitch;
    }
    // P = mantissa / 10^scale; E and K/ξ in increments: P·√(ξ²E² + K²)/(ξE).
    let xf = BigInt::from(c.x_mode.factor());
    let e = BigInt::from(c.taper_distance);
    let k = BigInt::from(c.full_depth);
    let s = &xf * &xf * &e * &e + &k * &k;
    let scale = MAX_LEAD_SCALE;
    let a = BigInt::from(c.pitch.mantissa) * BigInt::from(10_u64.pow(scale - c.pitch.scale.min(scale)));
    let b = &xf * &e;
    // round(A·√S / B) = floor((⌊√(4A²S)⌋ + B) / (2B)), ties away from zero.
    let root = (BigInt::from(4) * &a * &a * &s).sqrt();
    let v: BigInt = (root + &b) / (BigInt::from(2) * &b);
    // The word of the pitch (K, as LinuxCNC writes a G33's).
    Lead { word: c.pitch.word, mantissa: v.to_u64().unwrap_or(u64::MAX), scale }
}

/// Expands a LinuxCNC G76 cycle into moves, as the interpreter does
/// (module documentation).
///
/// # Errors
///
/// [`LinuxCncG76::validate`]; [`CycleError::TooManyPasses`] when more than
/// the cycle's `pass_limit` rough passes would be cut;
/// [`CycleError::OutOfRange`] for a pass coordinate beyond the range
/// table; [`CycleError::UndecidedRounding`] (never seen: R-G75TIE decides a
/// value that 512 fraction bits cannot tell from a boundary).
///
/// Twin: `impl/src/engine/linuxcnc.rs`, `expand_linuxcnc` (the passes:
/// `Words::values`, `Points::of`, `LinuxCncMoves::pass_move`).
pub fn expand(c: &LinuxCncG76) -> Result<Vec<Move>, CycleError> {
    Ok(moves(c)?.collect())
}

/// The moves of [`expand`], made a pass at a time (memory of one pass,
/// whatever the number of passes): every pass is computed once to raise
/// any alarm before the first move, then again as it is taken (the
/// reference is a specification: it spends the time, not the memory).
///
/// # Errors
///
/// As [`expand`].
pub fn moves(
    c: &LinuxCncG76,
) -> Result<impl Iterator<Item = Move> + Clone + Send + Sync + 'static, CycleError> {
    c.validate()?;
    let k = Real::int(c.full_depth);
    // Reading R-LIMIT for LinuxCNC: refuse before a move is made when pass
    // limit + 1 would still be shallower than K.
    let limit = u64::from(c.pass_limit);
    if (&depth(c, limit + 1) - &k).sign()? == Ordering::Less {
        return Err(CycleError::TooManyPasses { passes: limit, exact: false, limit: c.pass_limit });
    }
    // l.5775-5781: rough passes while the depth is below K; each is made
    // once here, so that its alarm (a coordinate beyond the range table)
    // comes before the first move.
    let mut buf = Vec::new();
    let mut last_depth = 0_i64;
    let mut n = 1_u64;
    loop {
        let d = depth(c, n);
        if (&d - &k).sign()? != Ordering::Less {
            break;
        }
        buf.clear();
        last_depth =
            pass(c, &mut buf, &d, last_depth, PassKind::Rough, u32::try_from(n).unwrap_or(u32::MAX))?;
        n += 1;
    }
    let rough = n - 1;
    // Reading R-BUDGET: the rough passes and the 1 + H at full depth within
    // the pass limit, before the spring passes are made.
    let pass_paths = u128::from(rough) + u128::try_from(i128::from(c.spring_passes) + 1).unwrap_or(0);
    if pass_paths > u128::from(c.pass_limit) {
        let pass_paths = u64::try_from(pass_paths).unwrap_or(u64::MAX);
        return Err(CycleError::TooMuchWork { pass_paths, limit: c.pass_limit });
    }
    // l.5783-5790: 1 + H passes at full depth (none for H = -1): their
    // values are all the same, made once here.
    if c.spring_passes >= 0 {
        buf.clear();
        pass(c, &mut buf, &k, last_depth, PassKind::Finish, 1)?;
    }
    let c = *c;
    let spring = u64::try_from(i64::from(c.spring_passes) + 1).unwrap_or(0);
    let (mut next, mut last_depth, mut ended) = (1_u64, 0_i64, false);
    Ok(PassStream::new(move |moves: &mut Vec<Move>| {
        if ended {
            return false;
        }
        let made = if next <= rough {
            let number = u32::try_from(next).unwrap_or(u32::MAX);
            pass(&c, moves, &depth(&c, next), last_depth, PassKind::Rough, number)
        } else if next <= rough + spring {
            let number = u32::try_from(next - rough).unwrap_or(u32::MAX);
            pass(&c, moves, &Real::int(c.full_depth), last_depth, PassKind::Finish, number)
        } else {
            // l.5791: to the end point.
            moves.push(Move { motion: Motion::Rapid, to: c.end, role: Role::Return, pass: None });
            ended = true;
            return true;
        };
        // Each pass was made without an error above, from the same exact
        // values: making it again gives the same moves.
        last_depth = made.expect("a pass made once without an alarm is made again without one");
        next += 1;
        true
    }))
}

/// δ_n = J·n^(1/R) = J·n^(10000/R'), R' = R in ten-thousandths.
fn depth(c: &LinuxCncG76, n: u64) -> Real {
    &Real::int(c.initial_depth) * &Real::power(n, DEGRESSION_ONE, c.degression)
}

/// Appends the moves of the pass at depth `d` (`kind` `number`) to `moves`;
/// `last_depth` is the previous pass's depth (radius increments). Returns
/// this pass's depth.
fn pass(
    c: &LinuxCncG76,
    moves: &mut Vec<Move>,
    d: &Real,
    last_depth: i64,
    kind: PassKind,
    number: u32,
) -> Result<i64, CycleError> {
    let xf = Real::int(c.x_mode.factor());
    let sigma: i64 = c.sigma();
    let towards_plus = c.end.z > c.start.z;
    // l.5740-5742: Q in radians, negated for a thread towards +Z.
    let q = if towards_plus { -c.compound_angle } else { c.compound_angle };
    let tan_abs = Real::tan(q.unsigned_abs() * 2);
    let tan = if q < 0 { -tan_abs } else { tan_abs };
    // l.5760: the taper distance changes sign with the direction.
    let taper = if towards_plus { -c.taper_distance } else { c.taper_distance };
    let tapered = c.taper_distance > 0;
    let taper_lead = if tapered { taper_pitch(c) } else { c.pitch };
    let k = Real::int(c.full_depth);
    let i_abs = c.peak_offset.abs();
    let x0 = c.start.x;
    let flank = match q.cmp(&0) {
        Ordering::Equal => Flank::Centre,
        _ if c.compound_angle > 0 => Flank::Right,
        _ => Flank::Left,
    };
    let zeta = &(d / &xf) * &tan;
    let s = Real::int(sigma);
    let x_back = round_away(&(&Real::int(x0) + &(&s * &(&k - d))))?;
    let x_cut = round_away(&(&Real::int(x0 - sigma * i_abs) - &(&s * d)))?;
    let x_rise = x_cut + sigma * c.full_depth;
    let z_start = round_away(&(&Real::int(c.start.z) - &zeta))?;
    let z_end = round_away(&(&(&Real::int(c.end.z) + &(&(&k / &xf) * &tan)) - &zeta))?;
    let d_radius = round_away(&(d / &xf))?;
    let info = Some(Pass { kind, number, start: 1, depth: d_radius, cut: d_radius - last_depth, flank });
    let mut add = |motion, to: Point, role| moves.push(Move { motion, to, role, pass: info });
    let thread = |lead, sync| Motion::Thread { lead, start_angle: StartAngle::ZERO, sync };
    add(Motion::Rapid, Point::new(x_back, z_start), Role::Approach);
    if tapered && c.entry_taper {
        add(thread(taper_lead, true), Point::new(x_rise, z_start), Role::LeadIn);
        add(thread(taper_lead, false), Point::new(x_cut, z_start - taper), Role::LeadIn);
        if !(tapered && c.exit_taper) {
            add(thread(c.pitch, false), Point::new(x_cut, z_end), Role::Cut);
        } else {
            add(thread(c.pitch, false), Point::new(x_cut, z_end + taper), Role::Cut);
            add(thread(taper_lead, false), Point::new(x_rise, z_end), Role::RunOut);
        }
    } else {
        add(Motion::Rapid, Point::new(x_cut, z_start), Role::Approach);
        if tapered && c.exit_taper {
            add(thread(c.pitch, true), Point::new(x_cut, z_end + taper), Role::Cut);
            add(thread(taper_lead, false), Point::new(x_rise, z_end), Role::RunOut);
        } else {
            add(thread(c.pitch, true), Point::new(x_cut, z_end), Role::Cut);
        }
    }
    add(Motion::Rapid, Point::new(x_back, z_end), Role::Retract);
    Ok(d_radius)
}
