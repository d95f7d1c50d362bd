//! Text forms of moves: NC blocks, JSON and the pass table.

use std::fmt;

use cycleref::units::write_fixed;
use cycleref::Point;
use cycleref::{Flank, IncrementSystem, LeadWord, PassKind, Role, StartAngle, Units};
use cycleref_spec::profile::QUnit;

/// `v` increments as a decimal with the increment's number of decimals.
pub fn fixed(v: i64, units: Units) -> String {
    Fixed::new(v, units).to_string()
}

/// A length in increments, displayed as a decimal with the increment's
/// number of decimals (`64.400`), without an allocation.
#[derive(Clone, Copy, Debug)]
pub struct Fixed {
    value: i64,
    decimals: u32,
}

impl Fixed {
    /// `value` increments of `units`.
    #[must_use]
    pub fn new(value: i64, units: Units) -> Fixed {
        Fixed { value, decimals: units.decimals() }
    }
}

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_fixed(f, i128::from(self.value), self.decimals)
    }
}

impl serde::Serialize for Fixed {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// The lead word as programmed (`F6.0`, `F1.5`, `I20.0`), displayed without
/// an allocation.
#[derive(Clone, Copy, Debug)]
pub struct LeadText(pub cycleref::Lead);

impl fmt::Display for LeadText {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let lead = self.0;
        f.write_str(match lead.word {
            LeadWord::F => "F",
            LeadWord::I => "I",
        })?;
        write_fixed(f, i128::from(lead.mantissa), lead.scale)?;
        if lead.scale == 0 {
            // Always with a decimal point: on FANUC a bare value may be read
            // in other units.
            f.write_str(".0")?;
        }
        Ok(())
    }
}

impl serde::Serialize for LeadText {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// The lead word as programmed (`F6.0`, `F1.5`, `I20.0`).
pub fn lead_word(lead: cycleref::Lead) -> String {
    LeadText(lead).to_string()
}

/// The value of a Q word for `angle` in the profile's unit: whole
/// thousandths of a degree, or degrees with the increment system's
/// decimals (3 at IS-B, 4 at IS-C), rounded to nearest where the exact
/// angle has more digits (360°/7).
pub fn q_word(angle: StartAngle, u: Units, q: QUnit) -> String {
    match q {
        QUnit::Millidegrees { .. } => angle.rounded_millidegrees().to_string(),
        QUnit::Degrees { .. } => {
            let decimals: u32 = match u.system {
                IncrementSystem::IsB => 3,
                IncrementSystem::IsC => 4,
            };
            // Units of 10^-decimals degree: num / den millidegrees × 10^(decimals - 3).
            let scale = u64::from(10_u32.pow(decimals - 3));
            let den = u64::from(angle.den);
            let v = (2 * u64::from(angle.num) * scale + den) / (2 * den);
            let mut s = String::new();
            let _ = write_fixed(&mut s, i128::from(v), decimals);
            s
        }
    }
}

/// Name of a pass kind.
pub fn kind_name(k: PassKind) -> &'static str {
    match k {
        PassKind::Rough => "rough",
        PassKind::Finish => "finish",
    }
}

/// Name of a role.
pub fn role_name(r: Role) -> &'static str {
    match r {
        Role::Approach => "approach",
        Role::LeadIn => "lead-in",
        Role::Cut => "cut",
        Role::RunOut => "run-out",
        Role::Retract => "retract",
        Role::Return => "return",
        Role::Peck(_) => "peck",
        Role::PeckRetract(_) => "peck-retract",
        Role::PlungeRetract(_) => "plunge-retract",
        Role::Step(_) => "step",
        Role::LayerChange(_) => "layer-change",
        Role::RoughContour => "rough-contour",
        Role::FinishContour => "finish-contour",
    }
}

/// The plunge a G75.1 move belongs to, if any.
pub fn plunge_of(r: Role) -> Option<cycleref::Plunge> {
    match r {
        Role::Peck(p) | Role::PeckRetract(p) | Role::PlungeRetract(p) | Role::Step(p) => Some(p),
        _ => None,
    }
}

/// An arc's I (X distance from the start to the centre, as a radius) and K
/// (Z distance), as written in the nc format: I may need one more decimal
/// than the increment when X is a diameter and the distance is odd.
pub fn arc_ik(from: Point, centre: Point, x_factor: i64, units: Units) -> (String, String) {
    let dx = centre.x - from.x;
    let i = if dx % x_factor == 0 {
        fixed(dx / x_factor, units)
    } else {
        // Half an increment: print dx * 5 with one more decimal.
        let mut s = String::new();
        let _ = write_fixed(&mut s, i128::from(dx) * 5, units.decimals() + 1);
        s
    };
    (i, fixed(centre.z - from.z, units))
}

/// Name of a flank position.
pub fn flank_name(f: Flank) -> &'static str {
    match f {
        Flank::Right => "right",
        Flank::Centre => "centre",
        Flank::Left => "left",
    }
}
