//! Control profiles and the machine configuration, as data.
//!
//! A profile says which addresses a control's G76 has, how `P(m)(r)(a)` may
//! be written, what a value without a decimal point means, which parameters
//! replace omitted words, and which run-out rules apply. The three profiles
//! differ only in this data; the reader and the engines have no per-control
//! code paths beyond looking these fields up.
//!
//! Parameter defaults are not given by the sources; the values chosen here
//! are listed in `docs/INTERPRETATIONS.md` (reading R-PARAM) and can be
//! overridden with a parameter file ([`Machine::apply_toml`]).

use std::collections::BTreeMap;
use std::fmt;
use std::str::FromStr;

use cycleref::{IncrementSystem, Infeed, InputUnit, Units, XMode};
use rust_decimal::Decimal;

/// Which control's manual a program is read by.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ProfileName {
    /// FANUC-style two-block G76 (seed 004).
    Fanuc,
    /// GSK 980TDi (manuals/gsk980tdi-*.txt).
    Gsk980,
    /// GSK 988TA and the extended G76 of seed 000.
    Gsk988,
    /// LinuxCNC 2.9's interpreter: the one-block `G76 P Z I J R K Q H E L`,
    /// G7/G8 (issue 15; readings R-LCNC-* in `docs/INTERPRETATIONS.md`).
    LinuxCnc,
}

impl ProfileName {
    /// Every profile, in the order the command lists them.
    pub const ALL: [ProfileName; 4] =
        [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::LinuxCnc];
}

impl FromStr for ProfileName {
    type Err = ParamsError;
    fn from_str(s: &str) -> Result<Self, ParamsError> {
        match s.to_ascii_lowercase().as_str() {
            "fanuc" => Ok(ProfileName::Fanuc),
            "gsk980" | "gsk980tdi" => Ok(ProfileName::Gsk980),
            "gsk988" | "gsk988ta" => Ok(ProfileName::Gsk988),
            "linuxcnc" => Ok(ProfileName::LinuxCnc),
            _ => Err(ParamsError::UnknownProfile { name: s.to_string() }),
        }
    }
}

impl fmt::Display for ProfileName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ProfileName::Fanuc => "fanuc",
            ProfileName::Gsk980 => "gsk980",
            ProfileName::Gsk988 => "gsk988",
            ProfileName::LinuxCnc => "linuxcnc",
        })
    }
}

/// How `P(m)(r)(a)` of G76 block 1 may be written (reading R-PSPLIT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PSplit {
    /// Last two digits a, next two r, the rest m; the word is omitted only
    /// as a whole, so fewer than five written digits is an error
    /// (manuals/gsk988ta-g76.txt note 4; FANUC).
    WholeOnly,
    /// GSK 980TDi note 4: one or two digits give a, three or four give r and
    /// a, five or more give m, r and a; the missing ones keep their values.
    Partial,
}

/// What a `P(k)`, `Q(Δd)` or `Q(Δdmin)` value means (reading R-PQUNIT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PqUnit {
    /// Least increments; a decimal point is an error (FANUC).
    IncrementsNoPoint,
    /// Least increments; a decimal point is allowed but the value must be a
    /// whole number of increments (GSK with the state parameter selecting
    /// increments, the way Q180.0 of G32 still means 0.18°).
    Increments,
    /// mm (inch).
    Length,
}

/// Run-out rules of a control for G76 (reading R-RUNOUT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunOutRules {
    /// FANUC: no J/K; the chamfer r (or parameter 5130) with angle 5131.
    ChamferOnly,
    /// GSK 980TDi G76 notes 1-4: J/K in block 1, non-modal; J, K omitted:
    /// by r (No.19); J omitted with K != 0: J by r; K omitted or 0 with
    /// J != 0: K = J; J = 0: none. The chamfer angle is 45°.
    Gsk980,
    /// GSK 988TA / seed 000: J/K in block 2, modal; both never programmed:
    /// by r (5130) and angle 5131; otherwise the normal-mode G92 rules
    /// (note 9): J omitted, J = 0 or K = 0 with J given: none; K omitted:
    /// short-axis run-out J only; J and K both non-zero: J and K.
    Gsk988,
    /// GSK 988TA G92 in the high-speed mode (5129 = 1): J, K omitted: by
    /// 5130 and 5131; K omitted (or J or K zero): none (the rapid retract
    /// to the X of A); J omitted: K along the long axis and the short axis
    /// to the X of A; both: J and K (reading R-G92RUNOUT). G76 and G78
    /// take the same rules in that mode (reading R-HIGHSPEED, `g92-rules`).
    Gsk988HighSpeed,
}

/// G32 run-out rules of a control (reading R-G32RUNOUT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum G32Rules {
    /// FANUC: G32 has no J/K.
    NoRunOut,
    /// GSK 980TDi (seed 002): J signed, K unsigned, both modal, cancelled by
    /// a non-thread motion block; J or J,K omitted: none; K omitted: K = |J|;
    /// J = 0: none; J != 0 with K = 0: K = |J|; J = 0 with K != 0: none.
    Gsk980,
    /// GSK 988TA: J omitted or 0: none; K omitted (J != 0): no long-axis
    /// run-out, J along the short axis (K = 0 is read the same way); a
    /// block with a run-out ends a continuous thread (the next block
    /// synchronises again).
    Gsk988,
}

/// What G32's Q (start angle) means (reading R-G32Q).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QUnit {
    /// Thousandths of a degree, a whole number, 0..=360000 (FANUC: no
    /// decimal point at all; GSK 980TDi No.182.7 = 0: "Q180 或 Q180.0 均认为是
    /// 0.18°").
    Millidegrees {
        /// A decimal point is an error (FANUC).
        no_point: bool,
    },
    /// Degrees, to the increment's decimals; 0..=360 (980TDi No.182.7 = 1)
    /// or any value reduced modulo 360 (988TA: "如果指定了大于 360.000 的值，按去除
    /// 整圈后的值来计算").
    Degrees {
        /// Values beyond 360 are reduced modulo 360 rather than refused.
        wrap: bool,
    },
}

/// Which word set a profile's programs are written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Dialect {
    /// FANUC's and GSK's: the two-block G76, G32, G92, G78, G75.1, U and W
    /// as incremental X and Z, diameter or radius X by setting.
    Fanuc,
    /// LinuxCNC's: the one-block G76 (`P Z I J R K Q H E L`), G7/G8 to
    /// switch diameter and radius X within the program; U and W are axes
    /// of their own, not incremental X and Z; no machine parameters.
    LinuxCnc,
}

/// The data that distinguishes one control from another.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Profile {
    /// The profile's name.
    pub name: ProfileName,
    /// The word set of its programs.
    pub dialect: Dialect,
    /// Addresses allowed in G76 block 1 besides `G`, `N`, `P`, `Q`, `R`.
    pub block1_extra: &'static str,
    /// Addresses allowed in G76 block 2 besides `G`, `N`, `X`, `Z`, `U`,
    /// `W`, `R`, `P`, `Q`, `F`, `I`.
    pub block2_extra: &'static str,
    /// How P(m)(r)(a) splits.
    pub p_split: PSplit,
    /// Smallest finishing pass count m accepted in P(m)(r)(a).
    pub min_finishing_passes: u32,
    /// A length word without a decimal point is in least increments
    /// (FANUC, unless calculator-type input is set); otherwise in mm/inch.
    pub bare_length_is_increments: bool,
    /// Run-out rules.
    pub run_out: RunOutRules,
    /// J/K keep their values across G76 cycles.
    pub jk_modal: bool,
    /// Largest P(k)/Q(Δd) in increments (range tables).
    pub max_depth_increments: i64,
    /// Parameter numbers, in the control's own numbering.
    pub params: ParamNumbers,
    /// G32 run-out rules.
    pub g32_rules: G32Rules,
    /// The control has G75.1, the radial trapezoidal groove cycle (the
    /// GSK 980TDi, seed 001).
    pub g75_1: bool,
    /// Addresses a G92 block accepts besides `G X Z U W R F I M S T`
    /// (reading R-ADDRESS): J K L on the 980TDi, J K L Q P on the 988TA.
    pub g92_extra: &'static str,
    /// Largest L (starts) of G92: 980TDi 1..99, 988TA 1..999.
    pub g92_max_starts: i64,
    /// The control's G78 (the GSK profiles), or `None` (FANUC).
    pub g78: Option<G78Rules>,
}

/// How a profile writes G78, the enhanced multiple thread-cutting cycle
/// (manuals/gsk980tdi-g78.txt, manuals/gsk988ta-g78.txt; readings R-G78P,
/// R-G78INFEED).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct G78Rules {
    /// Addresses of block 1 besides `G P Q R M S T` (980TDi: J K D L E;
    /// 988TA: D L E).
    pub block1_extra: &'static str,
    /// Addresses of block 2 besides `G X Z U W R P Q F I M S T` (988TA: J K).
    pub block2_extra: &'static str,
    /// The infeed mode each value of P(r) selects (980TDi 0-3, 988TA 0-4).
    pub infeeds: &'static [Infeed],
    /// The 980TDi's P(m) is the depth mode (切深选择) and D the finishing
    /// passes; the 988TA's P(m) is the finishing passes and D the depth mode.
    pub m_is_depth_mode: bool,
    /// Largest L.
    pub max_starts: i64,
    /// The infeed mode's parameter when P(r) was never given (No.062, 5144).
    pub infeed_param: &'static str,
    /// The depth mode's parameter (No.061, 5145): 0 equal, 1 decreasing.
    pub depth_mode_param: &'static str,
}

/// The parameter numbers a profile uses for G76.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParamNumbers {
    /// Finishing passes m (5142 / No.57).
    pub finishing_passes: &'static str,
    /// Chamfer r in 0.1 lead (5130 / No.19).
    pub chamfer: &'static str,
    /// Chamfer angle (5131; none on the 980TDi).
    pub chamfer_angle: Option<&'static str>,
    /// Tool angle a (5143 / No.58).
    pub tool_angle: &'static str,
    /// Minimum cut Δdmin (5140 / No.59).
    pub min_cut: &'static str,
    /// Finishing allowance d (5141 / No.60).
    pub finishing_allowance: &'static str,
    /// The P/Q unit state parameter (182.7 / 3401#6; none for FANUC).
    pub pq_unit: Option<&'static str>,
    /// Threading cycle mode (5129 on the 988TA; 1 = high-speed mode).
    pub thread_mode: Option<&'static str>,
}

impl Profile {
    /// The built-in profile `name`.
    #[must_use]
    pub fn get(name: ProfileName) -> Profile {
        match name {
            ProfileName::Fanuc => Profile {
                name,
                dialect: Dialect::Fanuc,
                block1_extra: "",
                block2_extra: "",
                p_split: PSplit::WholeOnly,
                min_finishing_passes: 1,
                bare_length_is_increments: true,
                run_out: RunOutRules::ChamferOnly,
                jk_modal: false,
                g32_rules: G32Rules::NoRunOut,
                g75_1: false,
                g92_extra: "",
                g92_max_starts: 1,
                g78: None,
                max_depth_increments: 999_999_999,
                params: ParamNumbers {
                    finishing_passes: "5142",
                    chamfer: "5130",
                    chamfer_angle: Some("5131"),
                    tool_angle: "5143",
                    min_cut: "5140",
                    finishing_allowance: "5141",
                    pq_unit: None,
                    thread_mode: None,
                },
            },
            ProfileName::Gsk980 => Profile {
                name,
                dialect: Dialect::Fanuc,
                block1_extra: "JK",
                block2_extra: "",
                p_split: PSplit::Partial,
                min_finishing_passes: 0,
                bare_length_is_increments: false,
                run_out: RunOutRules::Gsk980,
                jk_modal: false,
                g32_rules: G32Rules::Gsk980,
                g75_1: true,
                g92_extra: "JKL",
                g92_max_starts: 99,
                g78: Some(G78Rules {
                    block1_extra: "JKDLE",
                    block2_extra: "",
                    infeeds: &[Infeed::Centre, Infeed::LeftFlank, Infeed::RightFlank, Infeed::Alternating],
                    m_is_depth_mode: true,
                    max_starts: 99,
                    infeed_param: "62",
                    depth_mode_param: "61",
                }),
                max_depth_increments: 99_999_999,
                params: ParamNumbers {
                    finishing_passes: "57",
                    chamfer: "19",
                    chamfer_angle: None,
                    tool_angle: "58",
                    min_cut: "59",
                    finishing_allowance: "60",
                    pq_unit: Some("182.7"),
                    thread_mode: None,
                },
            },
            ProfileName::Gsk988 => Profile {
                name,
                dialect: Dialect::Fanuc,
                block1_extra: "DLE",
                block2_extra: "JK",
                p_split: PSplit::WholeOnly,
                min_finishing_passes: 1,
                bare_length_is_increments: false,
                run_out: RunOutRules::Gsk988,
                jk_modal: true,
                g32_rules: G32Rules::Gsk988,
                g75_1: false,
                g92_extra: "JKLQP",
                g92_max_starts: 999,
                g78: Some(G78Rules {
                    block1_extra: "DLE",
                    block2_extra: "JK",
                    infeeds: &[
                        Infeed::Centre,
                        Infeed::LeftFlank,
                        Infeed::RightFlank,
                        Infeed::RightCentre,
                        Infeed::LeftRight,
                    ],
                    m_is_depth_mode: false,
                    max_starts: 999,
                    infeed_param: "5144",
                    depth_mode_param: "5145",
                }),
                max_depth_increments: 999_999_999,
                params: ParamNumbers {
                    finishing_passes: "5142",
                    chamfer: "5130",
                    chamfer_angle: Some("5131"),
                    tool_angle: "5143",
                    min_cut: "5140",
                    finishing_allowance: "5141",
                    pq_unit: Some("3401.6"),
                    thread_mode: Some("5129"),
                },
            },
            // LinuxCNC has none of the FANUC-style cycles and no machine
            // parameters for G76: the reader refuses those codes on this
            // profile, so the fields below are never read (the G76 of
            // LinuxCNC is read by its own front end).
            ProfileName::LinuxCnc => Profile {
                name,
                dialect: Dialect::LinuxCnc,
                block1_extra: "",
                block2_extra: "",
                p_split: PSplit::WholeOnly,
                min_finishing_passes: 0,
                bare_length_is_increments: false,
                run_out: RunOutRules::ChamferOnly,
                jk_modal: false,
                g32_rules: G32Rules::NoRunOut,
                g75_1: false,
                g92_extra: "",
                g92_max_starts: 1,
                g78: None,
                max_depth_increments: 999_999_999,
                params: ParamNumbers {
                    finishing_passes: "",
                    chamfer: "",
                    chamfer_angle: None,
                    tool_angle: "",
                    min_cut: "",
                    finishing_allowance: "",
                    pq_unit: None,
                    thread_mode: None,
                },
            },
        }
    }

    /// The built-in default of every parameter of this profile, as
    /// (number, value) in the units of [`ParamValue`].
    #[must_use]
    pub fn default_params(&self) -> BTreeMap<String, ParamValue> {
        let p = &self.params;
        let mut m = BTreeMap::new();
        if self.dialect == Dialect::LinuxCnc {
            // No machine parameter changes what LinuxCNC's G76 does.
            return m;
        }
        m.insert(p.finishing_passes.to_string(), ParamValue::Int(1));
        m.insert(p.chamfer.to_string(), ParamValue::Int(0));
        if let Some(n) = p.chamfer_angle {
            m.insert(n.to_string(), ParamValue::Int(0));
        }
        m.insert(p.tool_angle.to_string(), ParamValue::Int(60));
        m.insert(p.min_cut.to_string(), ParamValue::Length(Decimal::ZERO));
        m.insert(p.finishing_allowance.to_string(), ParamValue::Length(Decimal::ZERO));
        if let Some(n) = p.pq_unit {
            m.insert(n.to_string(), ParamValue::Int(0));
        }
        if let Some(n) = p.thread_mode {
            m.insert(n.to_string(), ParamValue::Int(0));
        }
        // Reading R-PARAM: G78 right-flank infeed and decreasing depths by
        // default, so that a G78 with neither P(r) nor the depth mode cuts
        // G76's passes.
        if let Some(g78) = self.g78 {
            m.insert(g78.infeed_param.to_string(), ParamValue::Int(2));
            m.insert(g78.depth_mode_param.to_string(), ParamValue::Int(1));
        }
        m
    }

    /// What G32's Q means under parameter `bit` (182.7 on the 980TDi).
    #[must_use]
    pub fn q_unit(&self, bit: i64) -> QUnit {
        match self.name {
            ProfileName::Fanuc => QUnit::Millidegrees { no_point: true },
            ProfileName::Gsk980 => {
                if bit == 0 {
                    QUnit::Millidegrees { no_point: false }
                } else {
                    QUnit::Degrees { wrap: false }
                }
            }
            ProfileName::Gsk988 => QUnit::Degrees { wrap: true },
            // Never asked: G32 is refused on the linuxcnc profile.
            ProfileName::LinuxCnc => QUnit::Degrees { wrap: false },
        }
    }

    /// What P(k), Q(Δd) and Q(Δdmin) mean under parameter `bit` (the value
    /// of 182.7 or 3401#6; ignored by FANUC).
    #[must_use]
    pub fn pq_unit(&self, bit: i64) -> PqUnit {
        match self.name {
            ProfileName::Fanuc => PqUnit::IncrementsNoPoint,
            // 980TDi No.182.7: 0 = least increments (the manual's example
            // P36800 Q18000 at IS-C), 1 = mm/inch.
            ProfileName::Gsk980 => {
                if bit == 0 {
                    PqUnit::Increments
                } else {
                    PqUnit::Length
                }
            }
            // 988TA 3401#6, opposite polarity: 0 = mm/inch (the manual's
            // example P3.680 Q1.800, seed 000's P3 Q1.8), 1 = increments.
            ProfileName::Gsk988 => {
                if bit == 0 {
                    PqUnit::Length
                } else {
                    PqUnit::Increments
                }
            }
            // LinuxCNC's G76 words are lengths.
            ProfileName::LinuxCnc => PqUnit::Length,
        }
    }
}

/// A parameter value: a count/bit, or a length in mm (inch).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamValue {
    /// An integer (counts, angles, bits, chamfer in tenths of a lead).
    Int(i64),
    /// A length in mm (inch), exact.
    Length(Decimal),
}

/// Everything about the machine that a program does not say.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Machine {
    /// The control profile.
    pub profile: Profile,
    /// IS-B or IS-C.
    pub increment: IncrementSystem,
    /// Input unit at program start (G20/G21 may change it before any motion).
    pub unit: InputUnit,
    /// Diameter or radius X.
    pub x_mode: XMode,
    /// FANUC calculator-type decimal point input (parameter 3401#0): a
    /// length without a decimal point is in mm (inch), not increments.
    pub calculator_input: bool,
    /// Largest number of rough passes a G76 may have.
    pub pass_limit: u32,
    /// How deep subprogram calls may nest (reading R-SUBPROGRAM): 1 to
    /// [`MAX_SUBPROGRAM_NESTING`](crate::reader::MAX_SUBPROGRAM_NESTING),
    /// [`DEFAULT_SUBPROGRAM_NESTING`](crate::reader::DEFAULT_SUBPROGRAM_NESTING)
    /// unless the parameter file's `subprogram_nesting` says otherwise.
    pub subprogram_nesting: u8,
    /// The most blocks that may run inside subprograms in one program,
    /// counting every repeat (reading R-SUBPROGRAM: the work of a program
    /// with calls is bounded before anything is written).
    pub subprogram_block_limit: u64,
    /// Parameter values by number (the profile's numbering).
    pub params: BTreeMap<String, ParamValue>,
    /// The readings chosen where the manuals leave a point open (issue
    /// 34): `[readings]` in the parameter file, `--reading` on the command
    /// line; the defaults unless chosen.
    pub readings: crate::readings::Readings,
}

impl Machine {
    /// The machine with the built-in defaults of `profile`: IS-B, metric,
    /// diameter X, no calculator-type input; for `linuxcnc`, IS-C (0.0001
    /// mm, 0.00001 inch: the four decimals `rs274` prints) and radius X
    /// (LinuxCNC starts in G8).
    #[must_use]
    pub fn new(profile: ProfileName) -> Machine {
        let profile = Profile::get(profile);
        let params = profile.default_params();
        let linuxcnc = profile.dialect == Dialect::LinuxCnc;
        Machine {
            profile,
            increment: if linuxcnc { IncrementSystem::IsC } else { IncrementSystem::IsB },
            unit: InputUnit::Metric,
            x_mode: if linuxcnc { XMode::Radius } else { XMode::Diameter },
            calculator_input: false,
            pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
            subprogram_nesting: if linuxcnc {
                crate::reader::LINUXCNC_SUBPROGRAM_NESTING
            } else {
                crate::reader::DEFAULT_SUBPROGRAM_NESTING
            },
            subprogram_block_limit: crate::reader::DEFAULT_SUBPROGRAM_BLOCK_LIMIT,
            params,
            readings: crate::readings::Readings::default(),
        }
    }

    /// The units at program start.
    #[must_use]
    pub fn units(&self) -> Units {
        Units { system: self.increment, unit: self.unit }
    }

    /// The integer value of parameter `number`.
    #[must_use]
    pub fn int_param(&self, number: &str) -> i64 {
        match self.params.get(number) {
            Some(ParamValue::Int(v)) => *v,
            Some(ParamValue::Length(d)) => d.trunc().try_into().unwrap_or(0),
            None => 0,
        }
    }

    /// The length value of parameter `number` in mm (inch).
    #[must_use]
    pub fn length_param(&self, number: &str) -> Decimal {
        match self.params.get(number) {
            Some(ParamValue::Length(d)) => *d,
            Some(ParamValue::Int(v)) => Decimal::from(*v),
            None => Decimal::ZERO,
        }
    }

    /// Applies a parameter file (TOML). Keys:
    ///
    /// ```toml
    /// profile = "gsk988"        # replaces the profile (and its defaults)
    /// increment = "is-c"        # is-b | is-c
    /// unit = "metric"           # metric | inch
    /// x = "diameter"            # diameter | radius
    /// calculator_input = false  # FANUC 3401#0
    /// pass_limit = 1000000
    /// subprogram_nesting = 4    # 1..10
    /// subprogram_block_limit = 1000000
    /// [parameters]
    /// 5142 = 2                  # integers for counts, angles and bits
    /// 5140 = "0.15"             # lengths as strings, in mm (inch), exact
    /// "3401.6" = 0              # bit parameters as "number.bit"
    /// [readings]                # `cycleref readings` lists them
    /// R-RUNOUT = "gsk988-only"
    /// ```
    ///
    /// # Errors
    ///
    /// [`ParamsError`], naming the key and what was wrong with it.
    pub fn apply_toml(&mut self, text: &str) -> Result<(), ParamsError> {
        self.apply(text, false)
    }

    /// As [`Machine::apply_toml`], but the file's `profile` (still checked
    /// to be a profile's name) does not replace the machine's: a profile
    /// chosen on the command line wins over the file's.
    ///
    /// # Errors
    ///
    /// As [`Machine::apply_toml`].
    pub fn apply_toml_keeping_profile(&mut self, text: &str) -> Result<(), ParamsError> {
        self.apply(text, true)
    }

    fn apply(&mut self, text: &str, keep_profile: bool) -> Result<(), ParamsError> {
        let table: toml::Table = text.parse().map_err(|e: toml::de::Error| ParamsError::toml(text, &e))?;
        let bad = |key: &'static str, expected: &'static str| ParamsError::BadSetting { key, expected };
        if let Some(v) = table.get("profile") {
            let name: ProfileName = v.as_str().ok_or(bad("profile", "a string"))?.parse()?;
            if name != self.profile.name && !keep_profile {
                // The new profile's defaults, then the file's other keys.
                let (pass_limit, nesting, blocks, readings) =
                    (self.pass_limit, self.subprogram_nesting, self.subprogram_block_limit, self.readings);
                *self = Machine::new(name);
                self.readings = readings;
                self.pass_limit = pass_limit;
                self.subprogram_nesting = nesting;
                self.subprogram_block_limit = blocks;
            }
        }
        for (key, value) in &table {
            match key.as_str() {
                "profile" => {}
                "increment" => {
                    self.increment = match value.as_str() {
                        Some("is-b" | "IS-B" | "isb") => IncrementSystem::IsB,
                        Some("is-c" | "IS-C" | "isc") => IncrementSystem::IsC,
                        _ => return Err(bad("increment", "\"is-b\" or \"is-c\"")),
                    }
                }
                "unit" => {
                    self.unit = match value.as_str() {
                        Some("metric" | "mm") => InputUnit::Metric,
                        Some("inch") => InputUnit::Inch,
                        _ => return Err(bad("unit", "\"metric\" or \"inch\"")),
                    }
                }
                "x" => {
                    self.x_mode = match value.as_str() {
                        Some("diameter") => XMode::Diameter,
                        Some("radius") => XMode::Radius,
                        _ => return Err(bad("x", "\"diameter\" or \"radius\"")),
                    }
                }
                "calculator_input" => {
                    self.calculator_input =
                        value.as_bool().ok_or(bad("calculator_input", "true or false"))?;
                }
                "pass_limit" => {
                    let v = value.as_integer().ok_or(bad("pass_limit", "an integer"))?;
                    self.pass_limit = u32::try_from(v)
                        .ok()
                        .filter(|v| *v >= 1)
                        .ok_or(bad("pass_limit", "between 1 and 4294967295"))?;
                }
                "subprogram_nesting" => {
                    let v = value.as_integer().ok_or(bad("subprogram_nesting", "an integer"))?;
                    self.subprogram_nesting = u8::try_from(v)
                        .ok()
                        .filter(|v| (1..=crate::reader::MAX_SUBPROGRAM_NESTING).contains(v))
                        .ok_or(bad("subprogram_nesting", "between 1 and 10"))?;
                }
                "subprogram_block_limit" => {
                    let v = value.as_integer().ok_or(bad("subprogram_block_limit", "an integer"))?;
                    self.subprogram_block_limit = u64::try_from(v)
                        .ok()
                        .filter(|v| *v >= 1)
                        .ok_or(bad("subprogram_block_limit", "at least 1"))?;
                }
                "parameters" => {
                    let t = value.as_table().ok_or(bad("parameters", "a table"))?;
                    for (num, v) in t {
                        self.set_param(num, v)?;
                    }
                }
                "readings" => {
                    let t = value.as_table().ok_or(bad("readings", "a table"))?;
                    for (id, v) in t {
                        let v = v
                            .as_str()
                            .ok_or(bad("readings", "a table of strings (\"R-RUNOUT\" = \"gsk988-only\")"))?;
                        self.readings.set(id, v)?;
                    }
                }
                other => return Err(ParamsError::UnknownKey { key: other.to_string() }),
            }
        }
        Ok(())
    }

    fn set_param(&mut self, num: &str, v: &toml::Value) -> Result<(), ParamsError> {
        let known = self.profile.default_params();
        let Some(default) = known.get(num) else {
            let list: Vec<&str> = known.keys().map(String::as_str).collect();
            return Err(ParamsError::UnknownParameter {
                number: num.to_string(),
                profile: self.profile.name,
                known: list.join(", "),
            });
        };
        let bad = |expected: &'static str| ParamsError::BadParameter { number: num.to_string(), expected };
        let value = match (default, v) {
            (ParamValue::Int(_), toml::Value::Integer(i)) => ParamValue::Int(*i),
            (ParamValue::Length(_), toml::Value::String(s)) => ParamValue::Length(
                Decimal::from_str_exact(s)
                    .map_err(|_| ParamsError::NotALength { number: num.to_string(), value: s.clone() })?,
            ),
            (ParamValue::Length(_), toml::Value::Integer(i)) => ParamValue::Length(Decimal::from(*i)),
            (ParamValue::Length(_), toml::Value::Float(_)) => {
                return Err(ParamsError::FloatLength { number: num.to_string() })
            }
            (ParamValue::Int(_), _) => return Err(bad("an integer")),
            (ParamValue::Length(_), _) => return Err(bad("a length string")),
        };
        self.params.insert(num.to_string(), value);
        Ok(())
    }
}

/// Why a parameter file cannot be applied ([`Machine::apply_toml`]), or a
/// profile's name not read. Its `Display` names the key (or parameter) and
/// what it must be.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ParamsError {
    /// The file is not TOML: where the TOML reader stopped (1-based line
    /// and column, in characters) and its message.
    Toml {
        /// The line.
        line: usize,
        /// The column.
        column: usize,
        /// The TOML reader's message (`invalid basic string`).
        message: String,
    },
    /// `profile` names no profile.
    UnknownProfile {
        /// The name given.
        name: String,
    },
    /// A setting (`increment`, `unit`, `x`, `pass_limit`, ...) has a value
    /// it cannot have.
    BadSetting {
        /// The setting.
        key: &'static str,
        /// What it must be.
        expected: &'static str,
    },
    /// A key no setting has.
    UnknownKey {
        /// The key.
        key: String,
    },
    /// A parameter the profile does not use.
    UnknownParameter {
        /// The parameter's number.
        number: String,
        /// The profile.
        profile: ProfileName,
        /// The parameters it knows, comma-separated.
        known: String,
    },
    /// A parameter with a value of the wrong type.
    BadParameter {
        /// The parameter's number.
        number: String,
        /// What it must be.
        expected: &'static str,
    },
    /// A length parameter written as a TOML float, which is not exact.
    FloatLength {
        /// The parameter's number.
        number: String,
    },
    /// A length parameter whose string is not a decimal.
    NotALength {
        /// The parameter's number.
        number: String,
        /// The string.
        value: String,
    },
    /// A reading id that is not selectable (`--reading`, `[readings]`).
    UnknownReading {
        /// The id given.
        id: String,
        /// The selectable ids, comma-separated.
        known: String,
    },
    /// A value the reading does not have.
    BadReading {
        /// The reading's id.
        id: &'static str,
        /// The value given.
        value: String,
        /// Its values, comma-separated.
        valid: String,
    },
    /// A reading choice not written `ID=VALUE`.
    ReadingSyntax {
        /// The text given.
        text: String,
    },
}

impl ParamsError {
    /// The error of the TOML reader `e` on `text`, placed.
    fn toml(text: &str, e: &toml::de::Error) -> ParamsError {
        let at = e.span().map_or(0, |span| span.start.min(text.len()));
        let before = text.get(..at).unwrap_or(text);
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        // One line: the reader's message may run over several.
        let message =
            e.message().lines().map(str::trim).filter(|l| !l.is_empty()).collect::<Vec<_>>().join(": ");
        ParamsError::Toml { line, column, message }
    }

    /// The stable kind: `params:toml`, `params:unknown_profile`,
    /// `params:bad_setting`, `params:unknown_key`,
    /// `params:unknown_parameter`, `params:bad_parameter`,
    /// `params:float_length`, `params:not_a_length`,
    /// `params:unknown_reading`, `params:bad_reading`,
    /// `params:reading_syntax`.
    #[must_use]
    pub fn stable_kind(&self) -> &'static str {
        match self {
            ParamsError::Toml { .. } => "params:toml",
            ParamsError::UnknownProfile { .. } => "params:unknown_profile",
            ParamsError::BadSetting { .. } => "params:bad_setting",
            ParamsError::UnknownKey { .. } => "params:unknown_key",
            ParamsError::UnknownParameter { .. } => "params:unknown_parameter",
            ParamsError::BadParameter { .. } => "params:bad_parameter",
            ParamsError::FloatLength { .. } => "params:float_length",
            ParamsError::NotALength { .. } => "params:not_a_length",
            ParamsError::UnknownReading { .. } => "params:unknown_reading",
            ParamsError::BadReading { .. } => "params:bad_reading",
            ParamsError::ReadingSyntax { .. } => "params:reading_syntax",
        }
    }
}

impl fmt::Display for ParamsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamsError::Toml { line, column, message } => {
                write!(f, "parameter file: line {line}, column {column}: not TOML: {message}")
            }
            ParamsError::UnknownProfile { name } => {
                write!(f, "unknown profile `{name}` (expected fanuc, gsk980, gsk988 or linuxcnc)")
            }
            ParamsError::BadSetting { key, expected } => write!(f, "`{key}` must be {expected}"),
            ParamsError::UnknownKey { key } => write!(f, "parameter file: unknown key `{key}`"),
            ParamsError::UnknownParameter { number, profile, known } => {
                write!(f, "parameter {number} is not used by the {profile} profile (it knows {known})")
            }
            ParamsError::BadParameter { number, expected } => {
                write!(f, "parameter {number} must be {expected}")
            }
            ParamsError::FloatLength { number } => {
                write!(
                    f,
                    "parameter {number}: write lengths as strings (\"0.15\") so they stay exact decimals"
                )
            }
            ParamsError::NotALength { number, value } => {
                write!(f, "parameter {number}: `{value}` is not a decimal length")
            }
            ParamsError::UnknownReading { id, known } => {
                write!(f, "unknown reading `{id}` (the selectable readings are {known})")
            }
            ParamsError::BadReading { id, value, valid } => {
                write!(f, "reading {id} has no value `{value}` (its values are {valid})")
            }
            ParamsError::ReadingSyntax { text } => {
                write!(f, "reading `{text}` must be written ID=VALUE (for example R-RUNOUT=gsk988-only)")
            }
        }
    }
}

impl std::error::Error for ParamsError {}
