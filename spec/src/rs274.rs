//! LinuxCNC's canonical machining calls, as its standalone interpreter
//! prints them (`rs274 -g FILE < /dev/null`): the external ground truth of
//! the `linuxcnc` profile (issue 15).
//!
//! Each output line is `<sequence> N..... <CALL>(<arguments>)`. The calls
//! read here are the motions and the spindle synchronisation:
//!
//! | call | meaning |
//! |---|---|
//! | `STRAIGHT_TRAVERSE(x, y, z, a, b, c)` | rapid to x z |
//! | `STRAIGHT_FEED(x, y, z, a, b, c)` | feed to x z; synchronised while a `START_SPEED_FEED_SYNC` is in force |
//! | `START_SPEED_FEED_SYNC(pitch, velocity_mode)` | synchronise the following feeds: `pitch` per revolution along the path |
//! | `STOP_SPEED_FEED_SYNCH()` | end synchronisation |
//!
//! X is a radius in the program's length unit (`rs274` prints the
//! interpreter's internal radius coordinate with four decimals, also in
//! G7), Z in the same unit; the pitch has six decimals. Every other call
//! is skipped. Values are kept as the exact decimals printed.

use cycleref::{Motion, Move, Units, XMode};
use rust_decimal::Decimal;

/// One motion of `rs274`'s canonical output.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CanonMove {
    /// True for `STRAIGHT_TRAVERSE`, false for `STRAIGHT_FEED`.
    pub rapid: bool,
    /// X as printed: a radius, in the program's unit.
    pub x: Decimal,
    /// Z as printed.
    pub z: Decimal,
    /// The pitch of the synchronisation in force for a feed, as printed.
    pub pitch: Option<Decimal>,
    /// The 1-based line of the output where the call stands.
    pub line: usize,
}

/// Why a canonical output could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CanonError {
    /// The 1-based line of the output.
    pub line: usize,
    /// What was wrong.
    pub message: String,
}

impl std::fmt::Display for CanonError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for CanonError {}

/// Reads the motions of a canonical output, in order.
///
/// # Errors
///
/// A motion or synchronisation call whose arguments are not numbers.
///
/// ```
/// use cycleref_spec::rs274::read;
/// let text = "   11 N..... STRAIGHT_TRAVERSE(14.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)\n\
///             14 N..... START_SPEED_FEED_SYNC(1.500000,0)\n\
///             15 N..... STRAIGHT_FEED(13.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n\
///             16 N..... STOP_SPEED_FEED_SYNCH()\n";
/// let moves = read(text).unwrap();
/// assert_eq!(moves.len(), 2);
/// assert!(moves[0].rapid && moves[0].pitch.is_none());
/// assert_eq!(moves[1].pitch.unwrap().to_string(), "1.500000");
/// assert_eq!(moves[1].z.to_string(), "-20.0000");
/// ```
pub fn read(text: &str) -> Result<Vec<CanonMove>, CanonError> {
    let mut out = Vec::new();
    let mut pitch = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        match call(raw, line)? {
            Some(CanonCall::Motion { rapid, x, z }) => {
                out.push(CanonMove { rapid, x, z, pitch: if rapid { None } else { pitch }, line });
            }
            Some(CanonCall::StartSync { pitch: p }) => pitch = Some(p),
            Some(CanonCall::StopSync) => pitch = None,
            None => {}
        }
    }
    Ok(out)
}

/// One canonical call that [`read`] uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonCall {
    /// `STRAIGHT_TRAVERSE` (rapid) or `STRAIGHT_FEED` to X (a radius) Z.
    Motion {
        /// True for `STRAIGHT_TRAVERSE`.
        rapid: bool,
        /// X as printed.
        x: Decimal,
        /// Z as printed.
        z: Decimal,
    },
    /// `START_SPEED_FEED_SYNC`: the following feeds are synchronised at
    /// `pitch` per revolution along the path.
    StartSync {
        /// The pitch as printed.
        pitch: Decimal,
    },
    /// `STOP_SPEED_FEED_SYNCH`.
    StopSync,
}

/// The call of one line of `rs274`'s output (`line` names it in an
/// error), or `None` for a call [`read`] skips or a line that is no call.
///
/// # Errors
///
/// A motion or synchronisation call whose arguments are not numbers.
pub fn call(raw: &str, line: usize) -> Result<Option<CanonCall>, CanonError> {
    let Some(call) = raw.split("N..... ").nth(1) else { return Ok(None) };
    let (name, rest) = call.split_once('(').unwrap_or((call, ""));
    let args = rest.split(')').next().unwrap_or("");
    let numbers = || -> Result<Vec<Decimal>, CanonError> {
        args.split(',')
            .map(|a| {
                a.trim().parse::<Decimal>().map_err(|e| CanonError {
                    line,
                    message: format!("{name}: argument `{}` is not a number ({e})", a.trim()),
                })
            })
            .collect()
    };
    Ok(match name.trim() {
        "STRAIGHT_TRAVERSE" | "STRAIGHT_FEED" => {
            let v = numbers()?;
            if v.len() < 3 {
                return Err(CanonError { line, message: format!("{name}: fewer than three coordinates") });
            }
            Some(CanonCall::Motion { rapid: name.trim() == "STRAIGHT_TRAVERSE", x: v[0], z: v[2] })
        }
        "START_SPEED_FEED_SYNC" | "START_SPEED_FEED_SYNCH" => {
            // Two arguments (pitch, velocity mode), or three with the
            // spindle first (later LinuxCNC versions).
            let v = numbers()?;
            let pitch = match v.len() {
                2 => v[0],
                3 => v[1],
                _ => return Err(CanonError { line, message: format!("{name}: expected 2 or 3 arguments") }),
            };
            Some(CanonCall::StartSync { pitch })
        }
        "STOP_SPEED_FEED_SYNCH" | "STOP_SPEED_FEED_SYNC" => Some(CanonCall::StopSync),
        _ => None,
    })
}

/// Our moves against `rs274`'s motions, call by call: the same kind
/// (rapid, or feed synchronised at a pitch), X as a radius (ours divided by
/// 2 in diameter mode) and Z within one increment of `units` plus half of
/// rs274's printed unit (10⁻⁴), the pitch within 10⁻⁶ (the lead of every
/// synchronised move, reading R-LCNC-SYNC).
///
/// # Errors
///
/// The first difference, named by the move's index and rs274's output
/// line.
pub fn compare(ours: &[Move], canon: &[CanonMove], units: Units, x_mode: XMode) -> Result<(), String> {
    if ours.len() != canon.len() {
        return Err(format!("{} moves against rs274's {}", ours.len(), canon.len()));
    }
    let dec = units.decimals();
    let inc = Decimal::new(1, dec);
    let tol = inc + Decimal::new(5, 5);
    let xf = Decimal::from(x_mode.factor());
    for (i, (m, k)) in ours.iter().zip(canon).enumerate() {
        let x = Decimal::new(m.to.x, dec) / xf;
        let z = Decimal::new(m.to.z, dec);
        if (x - k.x).abs() > tol || (z - k.z).abs() > tol {
            return Err(format!(
                "move {i}: ours X{x} Z{z} (X as a radius), rs274 X{} Z{} (output line {})",
                k.x, k.z, k.line
            ));
        }
        match (m.motion, k.rapid, k.pitch) {
            (Motion::Rapid, true, None) => {}
            (Motion::Thread { lead, .. }, false, Some(p)) => {
                let ours = Decimal::new(i64::try_from(lead.mantissa).unwrap_or(i64::MAX), lead.scale);
                if (ours - p).abs() > Decimal::new(1, 6) {
                    return Err(format!(
                        "move {i}: pitch {ours} against rs274's {p} (output line {})",
                        k.line
                    ));
                }
            }
            _ => return Err(format!("move {i}: {:?} against rs274's {k:?}", m.motion)),
        }
    }
    Ok(())
}
