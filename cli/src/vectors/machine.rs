//! The machine a case runs on, and the way its program's words are written.
//!
//! A [`MachineStyle`] is drawn once per draft: profile, increment system, unit (and
//! whether the program selects inch by G20), X mode, FANUC's ways of
//! writing lengths, the pass limit and any parameter overrides. The
//! generators write every word through it ([`MachineStyle::num`], [`MachineStyle::pq`],
//! [`MachineStyle::lead`], [`MachineStyle::q`]), so one template gives programs in every
//! style the profiles accept; [`MachineStyle::settings`] writes the same machine as
//! the case's parameter file and its `machine` object.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use super::{MachineJson, OneLine, ParamJson, ParamsJson, ReadingsJson, Rng};
use cycleref::units::write_fixed;
use cycleref::{IncrementSystem, InputUnit, LeadWord, Units, XMode};
use cycleref_spec::profile::{ParamValue, Profile};
use cycleref_spec::readings::{Readings, TABLE};
use cycleref_spec::ProfileName;

/// A parameter override: an integer, or a length in increments of the
/// program's units (written as a decimal string).
#[derive(Clone, Copy)]
pub(super) enum Param {
    /// An integer parameter.
    Int(i64),
    /// A length, in increments of the program's units.
    Len(i64),
}

/// Everything about the machine, and the style the program is written in.
#[derive(Clone)]
pub(super) struct MachineStyle {
    pub(super) profile: ProfileName,
    pub(super) increment: IncrementSystem,
    /// The unit of the program's values (the machine's, or G20).
    pub(super) unit: InputUnit,
    /// Inch is selected by G20 in the program on a metric machine.
    pub(super) g20: bool,
    pub(super) x: XMode,
    pub(super) calculator_input: bool,
    /// FANUC: lengths written without a decimal point, in increments.
    pub(super) bare: bool,
    pub(super) pass_limit: u32,
    pub(super) params: BTreeMap<&'static str, Param>,
    /// The readings (issue 34): the defaults, unless the case is made
    /// under another value (`super::under_a_reading`).
    pub(super) readings: Readings,
}

impl MachineStyle {
    /// A machine of `profile` with its other settings drawn from `rng`.
    pub(super) fn new(profile: ProfileName, rng: &mut Rng) -> MachineStyle {
        let increment = if rng.chance(35) { IncrementSystem::IsC } else { IncrementSystem::IsB };
        let inch = rng.chance(25);
        let g20 = inch && rng.chance(50);
        let x = if rng.chance(25) { XMode::Radius } else { XMode::Diameter };
        let (calculator_input, bare) = if profile == ProfileName::Fanuc {
            let calc = rng.chance(25);
            (calc, !calc && rng.chance(35))
        } else {
            (false, false)
        };
        let mut params = BTreeMap::new();
        match profile {
            ProfileName::Gsk980 if rng.chance(25) => {
                params.insert("182.7", Param::Int(1));
            }
            ProfileName::Gsk988 if rng.chance(25) => {
                params.insert("3401.6", Param::Int(1));
            }
            _ => {}
        }
        MachineStyle {
            profile,
            increment,
            unit: if inch { InputUnit::Inch } else { InputUnit::Metric },
            g20,
            x,
            calculator_input,
            bare,
            pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
            params,
            readings: Readings::default(),
        }
    }

    /// The program's increment system and unit.
    pub(super) fn units(&self) -> Units {
        Units { system: self.increment, unit: self.unit }
    }

    /// Decimals of one increment.
    pub(super) fn decimals(&self) -> u32 {
        self.units().decimals()
    }

    /// 2 when X words are diameters, 1 when radii.
    pub(super) fn xf(&self) -> i64 {
        self.x.factor()
    }

    /// The profile's data (parameter names and defaults).
    pub(super) fn profile_data(&self) -> Profile {
        Profile::get(self.profile)
    }

    /// `microns` of a millimetre (a 25th of that in inch), in increments.
    pub(super) fn mm(&self, microns: i64) -> i64 {
        let per = self.units().per_unit();
        match self.unit {
            InputUnit::Metric => microns * per / 1000,
            InputUnit::Inch => microns * per / 25_400,
        }
    }

    /// The value of a length word (X, Z, U, W, R, E, J, K).
    pub(super) fn num(&self, v: i64) -> String {
        if self.bare {
            return v.to_string();
        }
        let needs_point = self.profile == ProfileName::Fanuc && !self.calculator_input;
        decimal(v, self.decimals(), needs_point)
    }

    /// The state bit of the P/Q unit (182.7 or 3401#6).
    fn pq_bit(&self) -> i64 {
        let key = match self.profile {
            // LinuxCnc: never drawn (the vectors draw FANUC and GSK profiles).
            ProfileName::Fanuc | ProfileName::LinuxCnc => return 0,
            ProfileName::Gsk980 => "182.7",
            ProfileName::Gsk988 => "3401.6",
        };
        match self.params.get(key) {
            Some(Param::Int(v)) => *v,
            _ => 0,
        }
    }

    /// Whether P(k), Q(Δd) and Q(Δdmin) are written in increments.
    pub(super) fn pq_in_increments(&self) -> bool {
        match self.profile {
            ProfileName::Fanuc | ProfileName::LinuxCnc => true,
            ProfileName::Gsk980 => self.pq_bit() == 0,
            ProfileName::Gsk988 => self.pq_bit() == 1,
        }
    }

    /// The value of P(k), Q(Δd) or Q(Δdmin).
    pub(super) fn pq(&self, v: i64) -> String {
        if self.pq_in_increments() {
            v.to_string()
        } else {
            decimal(v, self.decimals(), false)
        }
    }

    /// A lead word (`F1.5`, `I16`) and the lead in increments (rounded down).
    pub(super) fn lead(&self, rng: &mut Rng, word: Option<LeadWord>) -> (String, i64) {
        let word = word.unwrap_or(if rng.chance(20) { LeadWord::I } else { LeadWord::F });
        let text = match (word, self.unit) {
            (LeadWord::F | LeadWord::K, InputUnit::Metric) => {
                rng.pick(&["1", "1.25", "1.5", "1.75", "2", "2.5", "3", "4", "6"])
            }
            (LeadWord::F | LeadWord::K, InputUnit::Inch) => {
                rng.pick(&["0.04", "0.05", "0.0625", "0.08", "0.1", "0.125"])
            }
            (LeadWord::I, _) => rng.pick(&["8", "10", "11.5", "12", "14", "16", "20"]),
        };
        let (int, frac) = text.split_once('.').unwrap_or((text, ""));
        let mantissa: i64 = format!("{int}{frac}").parse().unwrap_or(1);
        let scale = 10_i64.pow(u32::try_from(frac.len()).unwrap_or(0));
        let per = self.units().per_unit();
        let inc = match (word, self.unit) {
            (LeadWord::F | LeadWord::K, _) => mantissa * per / scale,
            (LeadWord::I, InputUnit::Metric) => 254 * per * scale / (10 * mantissa),
            (LeadWord::I, InputUnit::Inch) => per * scale / mantissa,
        };
        let point = if self.profile == ProfileName::Fanuc && frac.is_empty() { ".0" } else { "" };
        let letter = match word {
            LeadWord::F => 'F',
            LeadWord::I => 'I',
            LeadWord::K => 'K',
        };
        (format!("{letter}{text}{point}"), inc)
    }

    /// The Q of G32 for `millidegrees`, in the profile's unit.
    pub(super) fn q(&self, millidegrees: i64) -> String {
        let degrees = match self.profile {
            ProfileName::Fanuc | ProfileName::LinuxCnc => false,
            ProfileName::Gsk980 => self.pq_bit() == 1,
            ProfileName::Gsk988 => true,
        };
        if degrees {
            decimal(millidegrees, 3, false)
        } else {
            millidegrees.to_string()
        }
    }

    /// The profile's name of a parameter.
    pub(super) fn param_name(&self, which: fn(&Profile) -> &'static str) -> &'static str {
        which(&self.profile_data())
    }

    /// The machine settings as a parameter file and as a JSON object.
    pub(super) fn settings(&self) -> (String, MachineJson) {
        let increment = match self.increment {
            IncrementSystem::IsB => "is-b",
            IncrementSystem::IsC => "is-c",
        };
        let unit = match if self.g20 { InputUnit::Metric } else { self.unit } {
            InputUnit::Metric => "metric",
            InputUnit::Inch => "inch",
        };
        let x = match self.x {
            XMode::Diameter => "diameter",
            XMode::Radius => "radius",
        };
        let mut toml = String::new();
        let _ = writeln!(toml, "profile = \"{}\"", self.profile);
        let _ = writeln!(toml, "increment = \"{increment}\"");
        let _ = writeln!(toml, "unit = \"{unit}\"");
        let _ = writeln!(toml, "x = \"{x}\"");
        let _ = writeln!(toml, "calculator_input = {}", self.calculator_input);
        let _ = writeln!(toml, "pass_limit = {}", self.pass_limit);
        toml.push_str("\n[parameters]\n");
        let mut params = Vec::new();
        for (key, default) in self.profile_data().default_params() {
            let value = match (self.params.get(key.as_str()).copied(), default) {
                (Some(Param::Int(v)), _) | (None, ParamValue::Int(v)) => ParamJson::Int(v),
                (Some(Param::Len(v)), _) => ParamJson::Length(decimal(v, self.decimals(), false)),
                (None, ParamValue::Length(d)) => ParamJson::Length(d.to_string()),
            };
            // A length is a decimal: quoted, it needs no escape.
            let _ = match &value {
                ParamJson::Int(v) => writeln!(toml, "\"{key}\" = {v}"),
                ParamJson::Length(d) => writeln!(toml, "\"{key}\" = \"{d}\""),
            };
            params.push((key, value));
        }
        // Every reading that changes anything on the profile, with its
        // value, in the order `cycleref readings` lists them: the case says
        // what it was made under whatever the defaults of a later version.
        let readings: Vec<(&'static str, &'static str)> = TABLE
            .iter()
            .filter(|e| e.profiles.contains(&self.profile))
            .filter_map(|e| Some((e.id, self.readings.get(e.id)?)))
            .collect();
        if !readings.is_empty() {
            toml.push_str("\n[readings]\n");
            for (id, value) in &readings {
                let _ = writeln!(toml, "\"{id}\" = \"{value}\"");
            }
        }
        let machine = MachineJson {
            increment,
            unit,
            x,
            calculator_input: self.calculator_input,
            pass_limit: self.pass_limit,
            parameters: OneLine(ParamsJson(params)),
            readings: OneLine(ReadingsJson(readings)),
        };
        (toml, machine)
    }
}

/// `v` increments with `decimals` decimals, trailing zeros dropped; a
/// whole value keeps `.0` when `point` is asked for (FANUC: a bare value
/// would be increments).
pub(super) fn decimal(v: i64, decimals: u32, point: bool) -> String {
    let mut s = String::new();
    let _ = write_fixed(&mut s, i128::from(v), decimals);
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            if point {
                s.push('0');
            } else {
                s.pop();
            }
        }
    }
    s
}

/// Spindle start and positioning at `a`.
pub(super) fn head(rng: &mut Rng, ctx: &MachineStyle, a: (i64, i64)) -> Vec<String> {
    let mut l = Vec::new();
    if ctx.g20 {
        l.push("G20".to_string());
    }
    match rng.range(0, 2) {
        0 => l.push("M03 S500".into()),
        1 => l.push(format!(
            "G50 X{} Z{} M3 S300",
            ctx.num(a.0 + ctx.xf() * ctx.mm(20_000)),
            ctx.num(a.1 + ctx.mm(40_000))
        )),
        _ => l.push("G97 S400 M04".into()),
    }
    l.push(format!("G00 X{} Z{}", ctx.num(a.0), ctx.num(a.1)));
    l
}

/// Any of the three profiles.
pub(super) fn any_profile(rng: &mut Rng) -> ProfileName {
    rng.pick(&[ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988])
}

/// One of the two GSK profiles.
pub(super) fn gsk(rng: &mut Rng) -> ProfileName {
    rng.pick(&[ProfileName::Gsk980, ProfileName::Gsk988])
}
