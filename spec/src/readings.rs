//! Readings per control (issue 34): the points of docs/INTERPRETATIONS.md
//! that the sources leave open, each a typed choice with named values, its
//! source and its default per profile.
//!
//! A [`Readings`] value is part of the [`Machine`](crate::profile::Machine)
//! (`[readings]` in the parameter file, `--reading ID=VALUE` on the
//! command line, `readings=` in Python, `readings` in the C options). The
//! program reader resolves it against the profile
//! ([`Readings::for_cycle`]) into the [`CycleReadings`] every threading
//! cycle carries, so the engine and the exact reference take the same
//! value; R-E980 is applied by the reader itself (it only decides whether a
//! word is accepted).
//!
//! Only readings implemented in both engines are listed ([`TABLE`]).

use core::fmt;
use cycleref::CycleReadings;

use crate::profile::{ParamsError, ProfileName};

/// Reading R-RUNOUT: which profiles clamp the short-axis run-out J at the
/// retract distance of a pass without run-out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RunOutClamp {
    /// `all-profiles` (default): 988TA G92 note 5 ("当螺纹短轴方向退尾长度大
    /// 于无退尾时的退刀距离时，系统默认短轴方向退尾长度为无退尾时的退刀距离")
    /// adopted for every profile: the 980TDi and FANUC pages are silent, and
    /// the clamp keeps the run-out between the work and the retract point.
    #[default]
    AllProfiles,
    /// `gsk988-only`: the clamp only where its page says it (gsk988); on
    /// fanuc and gsk980 J is made as written, beyond the X of A (Z long) or
    /// beyond A's Z (X long) when it is longer, and the retract comes back
    /// to A's X.
    Gsk988Only,
}

/// Reading R-XRUNOUT: an X-long run-out whose cut line rises towards A
/// (s·i > 0), along Z towards A, ends inside the material.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum XRunOut {
    /// `refuse` (default): refused with `run_out_into_work`; the retract
    /// after it would cut through the thread (found by the
    /// `no_rapid_in_thread` harness, issue 13).
    #[default]
    Refuse,
    /// `towards-start`: the run-out towards the start point as written
    /// ("根据程序起点位置自动确定退尾方向"; no page calls it an alarm).
    TowardsStart,
}

/// Reading R-E980: a negative lead-in E on the 980TDi's G78, whose page
/// gives E the range "-9999.9999~9999.9999" while calling it "无符号".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum E980 {
    /// `refuse-negative` (default): "无符号" wins; a negative E is
    /// `out_of_range`, as every other unsigned length.
    #[default]
    RefuseNegative,
    /// `signed`: the range wins; a negative E is accepted and, being
    /// without direction ("无符号"), made as its magnitude, as the 980TDi
    /// G92 page does for J and K (note 10: "J、K输入负值时，按正值处理").
    Signed,
}

/// Reading R-HIGHSPEED: a G76 or a G78 on the 988TA when parameter 5129
/// (THM) selects the high-speed threading mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum HighSpeed {
    /// `g92-rules` (default): the run-out words J and K take G92's
    /// high-speed rules (R-G92RUNOUT), as they take G92's normal-mode rules
    /// under 5129 = 0. G76 note 9: "存在 J、K 时退尾格式及相关注意事项同
    /// G92"; 5129 is "螺纹切削循环 G92,G76 的模式" (seed 000, the 988TA G76
    /// page) and "螺纹切削循环 G92，G76，G78 的模式" (the 988TA G78 page).
    #[default]
    G92Rules,
    /// `refuse`: the cycle is refused at its block 2, since no page spells
    /// out a G76 or G78 high-speed pass.
    Refuse,
}

/// Reading R-LCNC-READER: what `;` is in a program of the linuxcnc
/// profile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LcncSemicolon {
    /// `comment` (default): a comment to the end of the line, as LinuxCNC's
    /// interpreter reads it (`rs274 -g` on `G0 X20 Z2 ; approach` makes
    /// `STRAIGHT_TRAVERSE(20.0000, 0.0000, 2.0000, …)`; a `(` after the `;`
    /// is part of the comment). LinuxCNC's behaviour is the authority for
    /// the linuxcnc profile.
    #[default]
    Comment,
    /// `end-of-block`: `;` ends the block, as on the GSK profiles, so the
    /// text after it is read as the next block (a LinuxCNC `; comment` is
    /// then refused).
    EndOfBlock,
}

/// Reading R-G92Q: whether the start angle Q of the 988TA's G92 carries
/// over to the next G92 block.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G92StartAngle {
    /// `one-shot` (default): G32's rule, to which the G92 page refers Q
    /// ("取值单位与范围请参考 G32"; 988TA G32 Q: "非模态，省略时为 0°"): a
    /// G92 block without Q starts at 0°.
    #[default]
    OneShot,
    /// `modal`: Q stays in force until another Q or another motion code,
    /// as every other word of the G92 page ("R … 模态值", J, K "模态指令",
    /// L "模态参数", P "模态指令"); the page states no modality for Q.
    Modal,
}

/// Reading R-G75ALLOW: a negative finishing allowance U or W of the
/// 980TDi's G75.1, whose page gives each a signed range while calling it
/// "无符号".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75Allowance {
    /// `refuse-negative` (default): "无符号" wins, a negative U or W is
    /// `out_of_range` (as R-E980's default for the same contradiction).
    #[default]
    RefuseNegative,
    /// `magnitude`: the range "-99999.999~99999.999" wins and the value,
    /// having no direction, is its magnitude, as the same page does for I
    /// ("输入负值时当成正值处理").
    Magnitude,
}

/// Reading R-G75P: which corner each digit of the 980TDi G75.1's
/// P(a)(b)(d)(e) sets when fewer than four digits are written.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum G75PDigits {
    /// `right-aligned` (default): the last digit is e, so leading zeros may
    /// be dropped (P11 = P0011), as a number's value and as the 980TDi's
    /// own P(m)(r)(a) ("地址P输入1位或2位数时取值为a").
    #[default]
    RightAligned,
    /// `left-aligned`: "P 的第一位" is the first digit written (P11 =
    /// P1100); the missing digits are 0 (chamfer).
    LeftAligned,
}

/// The readings chosen for a machine. [`Readings::default`] is the
/// project's reading of every point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Readings {
    /// R-RUNOUT.
    pub run_out: RunOutClamp,
    /// R-XRUNOUT.
    pub x_run_out: XRunOut,
    /// R-E980.
    pub e980: E980,
    /// R-HIGHSPEED.
    pub high_speed: HighSpeed,
    /// R-LCNC-READER.
    pub lcnc_semicolon: LcncSemicolon,
    /// R-G92Q.
    pub g92_q: G92StartAngle,
    /// R-G75ALLOW.
    pub g75_allowance: G75Allowance,
    /// R-G75P.
    pub g75_p: G75PDigits,
}

/// One value of a reading: its name and where it comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadingValue {
    /// The name scripts use (`--reading ID=NAME`).
    pub name: &'static str,
    /// Its source and reason, in one line.
    pub source: &'static str,
}

/// One selectable reading.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ReadingEntry {
    /// The id of docs/INTERPRETATIONS.md.
    pub id: &'static str,
    /// What it decides, in a few words.
    pub point: &'static str,
    /// Its values, the default first.
    pub values: &'static [ReadingValue],
    /// The profiles on which the choice changes anything.
    pub profiles: &'static [ProfileName],
}

impl ReadingEntry {
    /// The default value on `profile` (the same on every profile for the
    /// readings listed today: the first value).
    #[must_use]
    pub fn default_on(&self, _profile: ProfileName) -> &'static str {
        self.values.first().map_or("", |v| v.name)
    }

    fn names(&self) -> String {
        self.values.iter().map(|v| v.name).collect::<Vec<_>>().join(", ")
    }
}

const GSK: &[ProfileName] = &[ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988];

/// Every selectable reading, in the order `cycleref readings` lists them.
pub const TABLE: &[ReadingEntry] = &[
    ReadingEntry {
        id: "R-RUNOUT",
        point: "the clamp of the short-axis run-out J at the retract (988TA G92 note 5)",
        values: &[
            ReadingValue {
                name: "all-profiles",
                source: "988TA G92 note 5 adopted for every profile; the 980TDi and FANUC pages are silent",
            },
            ReadingValue {
                name: "gsk988-only",
                source: "only the 988TA page says it: J as written on fanuc and gsk980",
            },
        ],
        profiles: &[ProfileName::Fanuc, ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-XRUNOUT",
        point: "an X-long run-out towards A when s*i > 0 (into the work)",
        values: &[
            ReadingValue {
                name: "refuse",
                source: "run_out_into_work: the retract after it would cut the thread",
            },
            ReadingValue {
                name: "towards-start",
                source: "\"根据程序起点位置自动确定退尾方向\" as written; no page calls it an alarm",
            },
        ],
        profiles: GSK,
    },
    ReadingEntry {
        id: "R-E980",
        point: "a negative lead-in E on the 980TDi's G78",
        values: &[
            ReadingValue { name: "refuse-negative", source: "980TDi G78: E \"无符号\" (unsigned)" },
            ReadingValue {
                name: "signed",
                source: "980TDi G78: E \"-9999.9999~9999.9999\"; made as |E| like G92 note 10's J and K",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-HIGHSPEED",
        point: "G76 and G78 under 5129 = 1 (the 988TA's high-speed threading mode)",
        values: &[
            ReadingValue {
                name: "g92-rules",
                source: "988TA G76 note 9 \"存在 J、K 时退尾格式及相关注意事项同 G92\"; 5129 \"G92，G76，G78 的模式\": G92's high-speed J/K rules",
            },
            ReadingValue {
                name: "refuse",
                source: "no page spells out a high-speed G76 or G78 pass: refused at block 2",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-LCNC-READER",
        point: "`;` in a linuxcnc program",
        values: &[
            ReadingValue {
                name: "comment",
                source: "LinuxCNC's interpreter: `;` starts a comment to the end of the line (rs274 -g)",
            },
            ReadingValue {
                name: "end-of-block",
                source: "`;` ends the block, as on the GSK profiles: a `; comment` is refused",
            },
        ],
        profiles: &[ProfileName::LinuxCnc],
    },
    ReadingEntry {
        id: "R-G92Q",
        point: "whether the 988TA G92's start angle Q carries over to the next G92 block",
        values: &[
            ReadingValue {
                name: "one-shot",
                source: "988TA G92 Q \"取值单位与范围请参考 G32\"; G32 Q \"非模态，省略时为 0°\"",
            },
            ReadingValue {
                name: "modal",
                source: "every other 988TA G92 word is modal (R, J, K, L, P); the page states none for Q",
            },
        ],
        profiles: &[ProfileName::Gsk988],
    },
    ReadingEntry {
        id: "R-G75ALLOW",
        point: "a negative finishing allowance U or W of the 980TDi's G75.1",
        values: &[
            ReadingValue { name: "refuse-negative", source: "980TDi G75.1: U, W \"无符号\" (unsigned)" },
            ReadingValue {
                name: "magnitude",
                source: "980TDi G75.1: U, W \"-99999.999~99999.999\"; made as |U|, |W| like I (\"输入负值时当成正值处理\")",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
    ReadingEntry {
        id: "R-G75P",
        point: "the corners of a G75.1 P(a)(b)(d)(e) written with fewer than four digits",
        values: &[
            ReadingValue {
                name: "right-aligned",
                source: "P is a number: the last digit is e, leading zeros dropped (as the 980TDi's P(m)(r)(a))",
            },
            ReadingValue {
                name: "left-aligned",
                source: "\"P 的第一位\" is the first digit written: P11 sets a and b",
            },
        ],
        profiles: &[ProfileName::Gsk980],
    },
];

impl Readings {
    /// The value of reading `id`, by name.
    #[must_use]
    pub fn get(&self, id: &str) -> Option<&'static str> {
        let v = match id {
            "R-RUNOUT" => match self.run_out {
                RunOutClamp::AllProfiles => "all-profiles",
                RunOutClamp::Gsk988Only => "gsk988-only",
            },
            "R-XRUNOUT" => match self.x_run_out {
                XRunOut::Refuse => "refuse",
                XRunOut::TowardsStart => "towards-start",
            },
            "R-E980" => match self.e980 {
                E980::RefuseNegative => "refuse-negative",
                E980::Signed => "signed",
            },
            "R-HIGHSPEED" => match self.high_speed {
                HighSpeed::G92Rules => "g92-rules",
                HighSpeed::Refuse => "refuse",
            },
            "R-LCNC-READER" => match self.lcnc_semicolon {
                LcncSemicolon::Comment => "comment",
                LcncSemicolon::EndOfBlock => "end-of-block",
            },
            "R-G92Q" => match self.g92_q {
                G92StartAngle::OneShot => "one-shot",
                G92StartAngle::Modal => "modal",
            },
            "R-G75ALLOW" => match self.g75_allowance {
                G75Allowance::RefuseNegative => "refuse-negative",
                G75Allowance::Magnitude => "magnitude",
            },
            "R-G75P" => match self.g75_p {
                G75PDigits::RightAligned => "right-aligned",
                G75PDigits::LeftAligned => "left-aligned",
            },
            _ => return None,
        };
        Some(v)
    }

    /// Sets reading `id` to the value named `value`.
    ///
    /// # Errors
    ///
    /// [`ParamsError::UnknownReading`] naming the ids, or
    /// [`ParamsError::BadReading`] naming the reading's values.
    pub fn set(&mut self, id: &str, value: &str) -> Result<(), ParamsError> {
        let Some(entry) = TABLE.iter().find(|e| e.id == id) else {
            return Err(ParamsError::UnknownReading { id: id.to_string(), known: known_ids() });
        };
        let bad = || ParamsError::BadReading { id: entry.id, value: value.to_string(), valid: entry.names() };
        match (entry.id, value) {
            ("R-RUNOUT", "all-profiles") => self.run_out = RunOutClamp::AllProfiles,
            ("R-RUNOUT", "gsk988-only") => self.run_out = RunOutClamp::Gsk988Only,
            ("R-XRUNOUT", "refuse") => self.x_run_out = XRunOut::Refuse,
            ("R-XRUNOUT", "towards-start") => self.x_run_out = XRunOut::TowardsStart,
            ("R-E980", "refuse-negative") => self.e980 = E980::RefuseNegative,
            ("R-E980", "signed") => self.e980 = E980::Signed,
            ("R-HIGHSPEED", "g92-rules") => self.high_speed = HighSpeed::G92Rules,
            ("R-HIGHSPEED", "refuse") => self.high_speed = HighSpeed::Refuse,
            ("R-LCNC-READER", "comment") => self.lcnc_semicolon = LcncSemicolon::Comment,
            ("R-LCNC-READER", "end-of-block") => self.lcnc_semicolon = LcncSemicolon::EndOfBlock,
            ("R-G92Q", "one-shot") => self.g92_q = G92StartAngle::OneShot,
            ("R-G92Q", "modal") => self.g92_q = G92StartAngle::Modal,
            ("R-G75ALLOW", "refuse-negative") => self.g75_allowance = G75Allowance::RefuseNegative,
            ("R-G75ALLOW", "magnitude") => self.g75_allowance = G75Allowance::Magnitude,
            ("R-G75P", "right-aligned") => self.g75_p = G75PDigits::RightAligned,
            ("R-G75P", "left-aligned") => self.g75_p = G75PDigits::LeftAligned,
            _ => return Err(bad()),
        }
        Ok(())
    }

    /// Applies `ID=VALUE` pairs separated by commas (the C options field;
    /// blanks around each pair are ignored, an empty text sets nothing).
    ///
    /// # Errors
    ///
    /// [`ParamsError::ReadingSyntax`] for a pair without `=`, else as
    /// [`Readings::set`].
    pub fn apply_list(&mut self, text: &str) -> Result<(), ParamsError> {
        for pair in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
            self.apply_pair(pair)?;
        }
        Ok(())
    }

    /// Applies one `ID=VALUE` (`--reading`).
    ///
    /// # Errors
    ///
    /// As [`Readings::apply_list`].
    pub fn apply_pair(&mut self, pair: &str) -> Result<(), ParamsError> {
        let Some((id, value)) = pair.split_once('=') else {
            return Err(ParamsError::ReadingSyntax { text: pair.to_string() });
        };
        self.set(id.trim(), value.trim())
    }

    /// The readings whose value differs from the default on `profile`, as
    /// `(id, value)` in [`TABLE`]'s order: what the `check` report and the
    /// JSON documents name.
    #[must_use]
    pub fn non_default(&self, profile: ProfileName) -> Vec<(&'static str, &'static str)> {
        TABLE
            .iter()
            .filter_map(|e| {
                let v = self.get(e.id)?;
                (v != e.default_on(profile)).then_some((e.id, v))
            })
            .collect()
    }

    /// True when `;` starts a comment to the end of the line in a program
    /// of a LinuxCNC dialect (`lcnc`), reading R-LCNC-READER `comment`.
    #[must_use]
    pub fn semicolon_comments(&self, lcnc: bool) -> bool {
        lcnc && self.lcnc_semicolon == LcncSemicolon::Comment
    }

    /// What a threading cycle of `profile` does under these readings.
    #[must_use]
    pub fn for_cycle(&self, profile: ProfileName) -> CycleReadings {
        CycleReadings {
            clamp_run_out: self.run_out == RunOutClamp::AllProfiles || profile == ProfileName::Gsk988,
            x_run_out_towards_start: self.x_run_out == XRunOut::TowardsStart,
        }
    }
}

fn known_ids() -> String {
    TABLE.iter().map(|e| e.id).collect::<Vec<_>>().join(", ")
}

/// `cycleref readings`: one line per reading of [`TABLE`], its id, its
/// values with the default on `profile` marked `*` (every profile's when
/// `None`), the profiles it changes anything on, and each value's source.
pub struct Listing {
    /// The profile whose defaults are marked.
    pub profile: Option<ProfileName>,
}

impl fmt::Display for Listing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for e in TABLE {
            if let Some(p) = self.profile {
                if !e.profiles.contains(&p) {
                    continue;
                }
            }
            let default = e.default_on(self.profile.unwrap_or(ProfileName::Gsk988));
            let values: Vec<String> = e
                .values
                .iter()
                .map(|v| if v.name == default { format!("{}*", v.name) } else { v.name.to_string() })
                .collect();
            let profiles: Vec<String> = e.profiles.iter().map(ToString::to_string).collect();
            let sources: Vec<String> = e.values.iter().map(|v| format!("{}: {}", v.name, v.source)).collect();
            writeln!(
                f,
                "{}\t{}\t[{}]\t{}",
                e.id,
                values.join(" | "),
                profiles.join(","),
                sources.join("; ")
            )?;
        }
        Ok(())
    }
}
