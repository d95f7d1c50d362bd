//! G76 and G78 of the FANUC-style profiles: block 1's modal values and
//! one-shot words, block 2's cycle, and the run-out rules.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::readings::E980;
use crate::readings::{G92HighSpeedNoJ, G92HighSpeedNoK, HighSpeed, LeadInModal, Readings};
use crate::ProfileName;

/// Modal values of G76 block 1 and, on the 988TA, J and K (reading R-MODAL).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct G76Modal {
    pub(super) finishing_passes: Option<u32>,
    pub(super) chamfer: Option<u32>,
    /// G78's P(r) (G76's infeed D is one-shot).
    pub(super) infeed: Option<Infeed>,
    /// G78's depth mode (980TDi P(m), 988TA D).
    pub(super) depth_mode: Option<DepthMode>,
    pub(super) tool_angle: Option<u32>,
    pub(super) min_cut: Option<i64>,
    pub(super) allowance: Option<i64>,
    pub(super) j: Option<i64>,
    pub(super) k: Option<i64>,
    /// The lead-in E, kept only under reading R-MODAL `modal`.
    pub(super) lead_in: Option<i64>,
}

/// One-shot values of the last block 1 (D, L, E; J, K on the 980TDi).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct G76OneShot {
    /// The cycle whose block 1 set these (a G76 block 1 does not apply to
    /// a G78 block 2, nor the other way).
    pub(super) code: Option<Multipass>,
    pub(super) infeed: Option<Infeed>,
    pub(super) starts: Option<u32>,
    pub(super) lead_in: Option<i64>,
    pub(super) j: Option<i64>,
    pub(super) k: Option<i64>,
    pub(super) line: Option<usize>,
}

impl State<'_> {
    /// G76 or G78 block 1: `P(m)(r)(a) Q(Δdmin) R(d)` and the profile's
    /// extras (G76: J K on the 980TDi, D L E on the 988TA; G78: J K D L E,
    /// D L E).
    pub(super) fn g76_block1(&mut self, block: &Block<'_>, code: Multipass) -> Result<(), ProgramError> {
        let profile = &self.machine.profile;
        let (name, extra) = match (code, profile.g78) {
            (Multipass::G78, Some(g78)) => ("G78 block 1", g78.block1_extra),
            _ => ("G76 block 1", profile.block1_extra),
        };
        self.check_addresses(block, name, "GPQRMST", extra)?;
        if let Some(p) = block.get('P')? {
            self.split_p(block, p, code)?;
        }
        let min_cut = block.get('Q')?.map(|q| self.pq_length(block, q)).transpose()?;
        let allowance = block.get('R')?.map(|r| self.unsigned_length(block, r)).transpose()?;
        // Reading R-E980: the 980TDi's E is "无符号" with the range
        // "-9999.9999~9999.9999"; `signed` accepts a negative E as its
        // magnitude (as G92 note 10's J and K), `refuse-negative` refuses it.
        let signed_e = profile.name == ProfileName::Gsk980 && self.machine.readings.e980 == E980::Signed;
        let lead_in =
            block
                .get('E')?
                .map(|e| {
                    if signed_e {
                        self.length(block, e).map(i64::abs)
                    } else {
                        self.unsigned_length(block, e)
                    }
                })
                .transpose()?;
        let j = block.get('J')?.map(|j| self.unsigned_length(block, j)).transpose()?;
        let k = block.get('K')?.map(|k| self.unsigned_length(block, k)).transpose()?;
        let modal = &mut self.modal[code as usize];
        if min_cut.is_some() {
            modal.min_cut = min_cut;
        }
        if allowance.is_some() {
            modal.allowance = allowance;
        }
        // Reading R-MODAL `modal`: E persists like Q(Δdmin) and R(d), until
        // another E; `one-shot`: it goes with D and L to the next block 2.
        // (Block 2 takes it from the modal values.)
        if lead_in.is_some() {
            modal.lead_in = lead_in;
        }
        let mut one =
            G76OneShot { code: Some(code), line: Some(block.line), lead_in, j, k, ..G76OneShot::default() };
        if let Some(d) = block.get('D')? {
            match (code, profile.g78) {
                (Multipass::G78, Some(g78)) if g78.m_is_depth_mode => {
                    // 980TDi: D is the finishing passes, 0..99.
                    modal.finishing_passes = Some(Self::count(block, d, 0, 99)?);
                }
                (Multipass::G78, _) => {
                    // 988TA: D is the depth mode, 0 equal, 1 decreasing.
                    modal.depth_mode = Some(depth_mode(Self::count(block, d, 0, 1)?));
                }
                (Multipass::G76, _) => {
                    one.infeed = Some(match Self::count(block, d, 0, 2)? {
                        0 => Infeed::RightFlank,
                        1 => Infeed::RightCentre,
                        _ => Infeed::LeftRight,
                    });
                }
            }
        }
        if let Some(l) = block.get('L')? {
            let max = match (code, profile.g78) {
                (Multipass::G78, Some(g78)) => g78.max_starts,
                _ => 999,
            };
            one.starts = Some(Self::count(block, l, 1, max)?);
        }
        self.one_shot = one;
        Ok(())
    }

    /// Reading R-PSPLIT: last two digits a, next two r, the rest m. For
    /// G78 (reading R-G78P) r is the infeed mode and, on the 980TDi, m the
    /// depth mode.
    pub(super) fn split_p(
        &mut self,
        block: &Block<'_>,
        p: &Word<'_>,
        code: Multipass,
    ) -> Result<(), ProgramError> {
        if p.number().has_point() || p.number().negative {
            return Err(err(
                block,
                Some(p),
                ErrorKind::DecimalPointNotAllowed { rule: "P(m)(r)(a) is a string of digits" },
            ));
        }
        // ASCII digits (the lexer's): their value read as they are, at
        // most 6 of them where it is read (issue 33: a `str` made of them
        // and parsed was a third of the split).
        let digits = p.number().int_bytes();
        let n = digits.len();
        let part = |from: usize, to: usize| -> u32 {
            digits[from..to].iter().fold(0, |v: u32, &b| v.wrapping_mul(10).wrapping_add(u32::from(b - b'0')))
        };
        let whole = self.machine.profile.p_split == PSplit::WholeOnly;
        if whole && n < 5 {
            return Err(err(block, Some(p), ErrorKind::PartialP));
        }
        if n > 6 {
            return Err(err(
                block,
                Some(p),
                ErrorKind::OutOfRange { range: "m 0..99, r 00..99, a 00..99".into() },
            ));
        }
        let a = part(n.saturating_sub(2), n);
        let g78 = self.machine.profile.g78.filter(|_| code == Multipass::G78);
        let min = self.machine.profile.min_finishing_passes;
        let modal = &mut self.modal[code as usize];
        modal.tool_angle = Some(a);
        if n >= 3 {
            let r = part(n.saturating_sub(4), n - 2);
            match g78 {
                Some(g78) => {
                    let mode = g78.infeeds.get(r as usize).copied().ok_or_else(|| {
                        err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange {
                                range: format!("G78 infeed mode r 00..{:02}", g78.infeeds.len() - 1),
                            },
                        )
                    })?;
                    modal.infeed = Some(mode);
                }
                None => modal.chamfer = Some(r),
            }
        }
        if n >= 5 {
            let m = part(0, n - 4);
            match g78 {
                Some(g78) if g78.m_is_depth_mode => {
                    if m > 1 {
                        return Err(err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange {
                                range: "G78 depth mode m 0 (equal) or 1 (decreasing)".into(),
                            },
                        ));
                    }
                    modal.depth_mode = Some(depth_mode(m));
                }
                _ => {
                    if m < min {
                        return Err(err(
                            block,
                            Some(p),
                            ErrorKind::OutOfRange { range: format!("finishing passes m {min:02}..99") },
                        ));
                    }
                    modal.finishing_passes = Some(m);
                }
            }
        }
        Ok(())
    }

    pub(super) fn param_count(&self, number: &str, lo: i64, hi: i64) -> Result<u32, ProgramError> {
        let v = self.machine.int_param(number);
        if (lo..=hi).contains(&v) {
            Ok(u32::try_from(v).unwrap_or(0))
        } else {
            Err(ProgramError {
                line: 0,
                word: None,
                kind: ErrorKind::Parameter(format!("{number} = {v} is outside {lo}..{hi}")),
            })
        }
    }

    pub(super) fn param_length(&self, number: &str) -> Result<i64, ProgramError> {
        let d = self.machine.length_param(number).checked_mul(Decimal::from(self.units.per_unit()));
        match d.map(|d| (i64::try_from(d.trunc()), d.fract().is_zero())) {
            Some((Ok(v), true)) if (0..=MAX_LENGTH).contains(&v) => Ok(v),
            _ => Err(ProgramError {
                line: 0,
                word: None,
                kind: ErrorKind::Parameter(format!(
                    "{number} = {} is not a whole number of least increments in 0..{}",
                    self.machine.length_param(number),
                    MAX_LENGTH
                )),
            }),
        }
    }

    /// G76 or G78 block 2: `X(U) Z(W) R(i) P(k) Q(Δd) F(I)` and the
    /// profile's extras (J K on the 988TA).
    pub(super) fn g76_block2<'a>(
        &mut self,
        block: Block<'a>,
        code: Multipass,
    ) -> Result<G76Call<'a>, ProgramError> {
        let profile = &self.machine.profile;
        let g78 = profile.g78.filter(|_| code == Multipass::G78);
        let (name, block1_extra, block2_extra) = match g78 {
            Some(g78) => ("G78 block 2", g78.block1_extra, g78.block2_extra),
            None => ("G76 block 2", profile.block1_extra, profile.block2_extra),
        };
        self.check_addresses(&block, name, "GXZUWRPQFIMST", block2_extra)?;
        let with_line = |mut e: ProgramError| {
            if e.line == 0 {
                e.line = block.line;
            }
            e
        };
        // Reading R-HIGHSPEED: 5129 switches G76 (seed 000: "螺纹切削循环
        // G92,G76 的模式") and G78 (the 988TA G78 page: "G92，G76，G78 的模
        // 式"); G76 note 9 gives their J/K G92's rules ("存在 J、K 时退尾格式
        // 及相关注意事项同 G92"), so the high-speed mode gives them G92's
        // high-speed rules (`g92-rules`), or the cycle is refused (`refuse`).
        let rules = if self.high_speed() {
            if self.machine.readings.high_speed == HighSpeed::Refuse {
                let n = profile.params.thread_mode.unwrap_or("5129");
                return Err(err(
                    &block,
                    None,
                    ErrorKind::Parameter(format!(
                        "{n} = {} selects the high-speed threading mode, in which a {} is refused \
                         under reading R-HIGHSPEED=refuse; set it to 0 (G92 follows it) or choose \
                         R-HIGHSPEED=g92-rules",
                        self.machine.int_param(n),
                        code.code()
                    )),
                ));
            }
            RunOutRules::Gsk988HighSpeed
        } else {
            profile.run_out
        };
        let (Some(xa), Some(za)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        self.check_spindle(&block)?;
        let Point { x: xd, z: zd } = self.end_point(&block, Point::new(xa, za))?;
        let taper = match block.get('R')? {
            Some(w) => self.length(&block, w)?,
            None => 0,
        };
        let k = self.depth_word(&block, 'P', "P(k) (thread height)", "alarm when P(k) is not given")?;
        let first_depth =
            self.depth_word(&block, 'Q', "Q(Δd) (first depth)", "alarm when Δd is not given")?;
        let lead = self.block_lead(&block)?;
        let mut j = None;
        let mut kk = None;
        if block2_extra.contains('J') {
            if let Some(w) = block.get('J')? {
                j = Some(self.unsigned_length(&block, w)?);
            }
            if let Some(w) = block.get('K')? {
                kk = Some(self.unsigned_length(&block, w)?);
            }
        }
        // Block 1's one-shot values apply to the block 2 of the same cycle.
        let one = std::mem::take(&mut self.one_shot);
        let one = if one.code == Some(code) { one } else { G76OneShot::default() };
        let modal = self.modal[code as usize];
        if block1_extra.contains('J') {
            j = one.j;
            kk = one.k;
        }
        if profile.jk_modal {
            let modal = &mut self.modal[code as usize];
            if j.is_some() {
                modal.j = j;
            }
            if kk.is_some() {
                modal.k = kk;
            }
            j = modal.j;
            kk = modal.k;
        }
        let p = &profile.params;
        let m = match modal.finishing_passes {
            Some(m) => m,
            None => self
                .param_count(p.finishing_passes, i64::from(profile.min_finishing_passes), 99)
                .map_err(with_line)?,
        };
        let a = match modal.tool_angle {
            Some(a) => a,
            None => self.param_count(p.tool_angle, 0, 99).map_err(with_line)?,
        };
        // G78 has no chamfer word (its P(r) is the infeed mode): the
        // parameter's (reading R-G78RUNOUT).
        let r = match modal.chamfer.filter(|_| g78.is_none()) {
            Some(r) => r,
            None => self.param_count(p.chamfer, 0, 99).map_err(with_line)?,
        };
        let angle = match p.chamfer_angle {
            Some(n) => match self.param_count(n, 0, 89).map_err(with_line)? {
                0 => 45,
                v => v,
            },
            None => 45,
        };
        let min_cut = match modal.min_cut {
            Some(v) => v,
            None => self.param_length(p.min_cut).map_err(with_line)?,
        };
        let allowance = match modal.allowance {
            Some(v) => v,
            None => self.param_length(p.finishing_allowance).map_err(with_line)?,
        };
        let run_out = resolve_run_out_under(rules, j, kk, r, angle, &self.machine.readings);
        let (infeed, depth_mode) = match g78 {
            None => (one.infeed.unwrap_or(Infeed::RightFlank), DepthMode::Decreasing),
            Some(g78) => {
                let infeed = match modal.infeed {
                    Some(i) => i,
                    None => {
                        let last = i64::try_from(g78.infeeds.len()).unwrap_or(1) - 1;
                        let v = self.param_count(g78.infeed_param, 0, last).map_err(with_line)?;
                        g78.infeeds.get(v as usize).copied().unwrap_or(Infeed::RightFlank)
                    }
                };
                let depth = match modal.depth_mode {
                    Some(d) => d,
                    None => depth_mode(self.param_count(g78.depth_mode_param, 0, 1).map_err(with_line)?),
                };
                (infeed, depth)
            }
        };
        let restore = self.restore();
        let cycle = G76Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(xa, za),
            end: Point::new(xd, zd),
            taper,
            thread_height: k,
            first_depth,
            min_cut,
            finishing_allowance: allowance,
            finishing_passes: m,
            tool_angle: a,
            infeed,
            depth_mode,
            // Reading R-MODAL (E): the last E of this cycle's block 1 under
            // `modal`, this block 1's under `one-shot`.
            lead_in: if self.machine.readings.lead_in_modal == LeadInModal::Modal {
                modal.lead_in
            } else {
                one.lead_in
            }
            .unwrap_or(0),
            starts: one.starts.unwrap_or(1),
            lead,
            run_out,
            pass_limit: self.machine.pass_limit,
            readings: self.machine.readings.for_cycle(self.machine.profile.name, code == Multipass::G78),
        };
        cycle.validate().map_err(|e| cycle_err(&block, one.line, e))?;
        self.moved = true;
        Ok(G76Call { code, params_line: one.line, block, cycle, restore })
    }
}

/// Reading R-RUNOUT: the profile's rules for J, K and r, turned into what
/// the cycle must do, under the default readings
/// ([`resolve_run_out_under`]).
#[must_use]
pub fn resolve_run_out(rules: RunOutRules, j: Option<i64>, k: Option<i64>, r: u32, angle: u32) -> RunOut {
    resolve_run_out_under(rules, j, k, r, angle, &Readings::default())
}

/// [`resolve_run_out`] under `readings`: the 988TA's high-speed rules
/// with K omitted (R-G92HS-NOK) or J omitted (R-G92HS-NOJ).
#[must_use]
pub fn resolve_run_out_under(
    rules: RunOutRules,
    j: Option<i64>,
    k: Option<i64>,
    r: u32,
    angle: u32,
    readings: &Readings,
) -> RunOut {
    let chamfer = |long: Option<i64>| {
        if r == 0 && long.is_none() {
            RunOut::None
        } else {
            RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long }
        }
    };
    match rules {
        RunOutRules::ChamferOnly => chamfer(None),
        RunOutRules::Gsk980 => match (j, k) {
            // Note 1: J and K omitted: by P(r) (or No.19).
            (None, None) => chamfer(None),
            // Note 2: J omitted, K != 0: J by P(r), K as given.
            (None, Some(k)) if k != 0 => {
                if r == 0 {
                    RunOut::None
                } else {
                    RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long: Some(k) }
                }
            }
            (None, Some(_)) => chamfer(None),
            // Note 4: J = 0: none.
            (Some(0), _) => RunOut::None,
            // Note 3: K omitted or K = 0 with J != 0: K = J.
            (Some(j), None | Some(0)) => RunOut::Amounts { short: j, long: j },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
        RunOutRules::Gsk988HighSpeed => match (j, k) {
            // As the normal mode: the chamfer of 5130 and 5131.
            (None, None) => chamfer(None),
            // Reading R-G92HS-NOK `pull-out-to-start`: the "退尾长度 … 固定为
            // 切削终点到起点的短轴轴向距离，与 J 是多少无关" is a thread move,
            // all the way to A's short-axis coordinate (J' clamped there),
            // whatever J is.
            (Some(_), None) if readings.g92_hs_no_k == G92HighSpeedNoK::PullOutToStart => {
                RunOut::Amounts { short: MAX_LENGTH, long: 0 }
            }
            // Reading R-G92HS-NOJ `by-parameter`: the short axis by 5130 and
            // 5131, as the 980TDi G92 note 3 ("省略J时，长轴方向按K退尾，短轴
            // 方向按№.19号参数设定值退尾"); 5130 = 0 gives J = 0, none.
            (None, Some(k)) if k != 0 && readings.g92_hs_no_j == G92HighSpeedNoJ::ByParameter => {
                if r == 0 {
                    RunOut::None
                } else {
                    RunOut::Chamfer { tenths_of_lead: r, angle_degrees: angle, long: Some(k) }
                }
            }
            // "省略 K 时，长轴无退尾，短轴方向的退尾长度，固定为切削终点到起点的短轴轴向
            // 距离，与 J 是多少无关": the rapid retract to the X of A is all
            // there is (step (3)); J = 0 or K = 0 likewise.
            (_, None | Some(0)) | (Some(0), _) => RunOut::None,
            // "省略 J 时，长轴方向按 K 退尾": K along the long axis, the short
            // axis all the way to the X of A (J' is clamped there).
            (None, Some(k)) => RunOut::Amounts { short: MAX_LENGTH, long: k },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
        RunOutRules::Gsk988 => match (j, k) {
            // Seed 000: J and K omitted: by r and 5131, or 5130.
            (None, None) => chamfer(None),
            // G92 normal mode (note 9): J omitted: none.
            (None, Some(_)) | (Some(0), _) | (Some(_), Some(0)) => RunOut::None,
            // K omitted: no long-axis run-out, short axis by J.
            (Some(j), None) => RunOut::Amounts { short: j, long: 0 },
            (Some(j), Some(k)) => RunOut::Amounts { short: j, long: k },
        },
    }
}
