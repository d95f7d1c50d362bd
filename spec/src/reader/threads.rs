//! G32 and G92: the thread-cutting block and the thread-cutting cycle,
//! their leads, start angles, run-outs and modal values.

#[allow(clippy::wildcard_imports)]
use super::*;
use crate::readings::{G32KZero, G92StartAngle, Readings, G92JK988};

/// The modal values of G92 (reading R-G92MODAL): the cut end, R, J, K, L
/// and P, kept from block to block while G92 is the motion mode (980TDi:
/// "F … J … K … L … 模态参数"; 988TA: "R … 模态值", "P … 模态指令"; FANUC:
/// X(U), Z(W) and R are modal in a canned cycle) and forgotten when
/// another motion G code is programmed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct G92Modal {
    pub(super) end_x: Option<i64>,
    pub(super) end_z: Option<i64>,
    pub(super) taper: Option<i64>,
    pub(super) j: Option<i64>,
    pub(super) k: Option<i64>,
    pub(super) starts: Option<u32>,
    /// P1 (988TA): a face thread.
    pub(super) face: Option<bool>,
    /// The start angle Q (988TA), kept only under reading R-G92Q
    /// `modal`.
    pub(super) start_angle: Option<StartAngle>,
}

impl State<'_> {
    /// The lead of a thread block: its F or I, else the modal one; it
    /// becomes the modal lead.
    pub(super) fn block_lead(&mut self, block: &Block<'_>) -> Result<Lead, ProgramError> {
        let lead = match (block.get('F')?, block.get('I')?) {
            (Some(f), Some(_)) => {
                return Err(err(block, Some(f), ErrorKind::Unsupported("both F and I in one block".into())))
            }
            (Some(w), None) | (None, Some(w)) => self.lead(block, w)?,
            (None, None) => self.lead.ok_or_else(|| {
                err(block, None, ErrorKind::Missing { what: "F(I) (lead)", rule: "a thread needs a lead" })
            })?,
        };
        self.lead = Some(lead);
        Ok(lead)
    }

    /// A G32 block: `X(U) Z(W) F(I) J K Q` (seed 002).
    pub(super) fn g32_block<'a>(&mut self, block: Block<'a>) -> Result<G32Call<'a>, ProgramError> {
        let rules = self.machine.profile.g32_rules;
        let allowed = if rules == G32Rules::NoRunOut { "GXZUWFIQMST" } else { "GXZUWFIJKQMST" };
        self.check_addresses(&block, "G32", allowed, "")?;
        self.check_spindle(&block)?;
        let (Some(x0), Some(z0)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        let Point { x: xe, z: ze } = self.end_point(&block, Point::new(x0, z0))?;
        let lead = self.block_lead(&block)?;
        // J signed, K unsigned (seed 002), both modal.
        if let Some(w) = block.get('J')? {
            self.g32_j = Some(self.length(&block, w)?);
        }
        if let Some(w) = block.get('K')? {
            self.g32_k = Some(self.unsigned_length(&block, w)?);
        }
        let run_out = resolve_g32_run_out_under(rules, self.g32_j, self.g32_k, &self.machine.readings);
        // Q: only the first block of a continuous thread counts (seed 002 rule 2).
        let q = match block.get('Q')? {
            Some(w) => Some(self.start_angle(&block, w)?),
            None => None,
        };
        let (sync, start_angle) = match self.thread_run {
            Some(angle) => (false, angle),
            None => (true, q.unwrap_or(StartAngle::ZERO)),
        };
        let g32 = G32Block {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(x0, z0),
            end: Point::new(xe, ze),
            lead,
            run_out,
            start_angle,
            sync,
            readings: self.machine.readings.for_cycle(self.machine.profile.name, false),
        };
        // The position after the block is where the run-out ends (seed 002,
        // figure 3-82): the reference model says where.
        let moves = crate::g32::expand(&g32).map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        let last = moves.last().map_or(g32.end, |m| m.to);
        self.x = Some(last.x);
        self.z = Some(last.z);
        self.moved = true;
        // 988TA: a run-out in a middle segment makes the thread discontinuous.
        let breaks = rules == G32Rules::Gsk988 && run_out != G32RunOut::None;
        self.thread_run = if breaks { None } else { Some(start_angle) };
        Ok(G32Call { code: "G32", block, g32 })
    }

    /// The motion to restore after a G76 or G75.1 expansion: the mode in
    /// force, unless it is G00 (the expansion's last move) or G92 (every
    /// G92 block is expanded too, so the output never needs the mode back).
    pub(super) fn restore(&self) -> Restore {
        let motion = match self.motion {
            MotionMode::G00 | MotionMode::G92 => None,
            m => Some(m),
        };
        Restore { motion }
    }

    /// A G92 block: `X(U) Z(W) R F(I)` and the profile's extras (980TDi: J
    /// K L; 988TA: J K L Q P), the first of a G92 mode or a repeat
    /// (readings R-G92MODAL, R-G92RUNOUT).
    pub(super) fn g92_block<'a>(&mut self, block: Block<'a>) -> Result<G92Call<'a>, ProgramError> {
        let profile = &self.machine.profile;
        self.check_addresses(&block, "G92", "GXZUWRFIMST", profile.g92_extra)?;
        let with_line = |mut e: ProgramError| {
            if e.line == 0 {
                e.line = block.line;
            }
            e
        };
        let (Some(xa), Some(za)) = (self.x, self.z) else {
            return Err(err(&block, None, ErrorKind::PositionUnknown));
        };
        self.check_spindle(&block)?;
        // The cut end: each axis as programmed (U, W from A), else the
        // previous G92 block's (modal), else A's.
        let (xw, zw, uw, ww) = Self::axis_words(&block)?;
        let xc = self.axis(&block, xw, uw, Some(xa))?.filter(|_| xw.is_some() || uw.is_some());
        let zc = self.axis(&block, zw, ww, Some(za))?.filter(|_| zw.is_some() || ww.is_some());
        let end = Point::new(xc.or(self.g92.end_x).unwrap_or(xa), zc.or(self.g92.end_z).unwrap_or(za));
        let taper = match block.get('R')? {
            Some(w) => self.length(&block, w)?,
            None => self.g92.taper.unwrap_or(0),
        };
        let lead = self.block_lead(&block)?;
        // 980TDi note 10: "J、K输入负值时，按正值处理"; elsewhere J and K are
        // unsigned ("不带方向") and a negative one is refused, but on the
        // 988TA (no range table on its G92 page) under reading R-G92JK988
        // `magnitude`, which takes the 980TDi's note.
        let negative_as_positive = profile.run_out == RunOutRules::Gsk980
            || (profile.run_out == RunOutRules::Gsk988
                && self.machine.readings.g92_jk988 == G92JK988::Magnitude);
        let run_out_word = |w: &Word<'_>| {
            if negative_as_positive {
                self.length(&block, w).map(i64::abs)
            } else {
                self.unsigned_length(&block, w)
            }
        };
        let j = block.get('J')?.map(run_out_word).transpose()?;
        let k = block.get('K')?.map(run_out_word).transpose()?;
        if j.is_some() {
            self.g92.j = j;
        }
        if k.is_some() {
            self.g92.k = k;
        }
        if let Some(w) = block.get('L')? {
            self.g92.starts = Some(Self::count(&block, w, 1, profile.g92_max_starts)?);
        }
        if let Some(w) = block.get('P')? {
            // 988TA: "当 P=0 或省略 P 时，加工轴向螺纹；当 P=1 时，加工端面螺纹" (modal,
            // "螺纹类型，模态指令"; reading R-G92FACE).
            self.g92.face = Some(Self::count(&block, w, 0, 1)? == 1);
        }
        // Reading R-G92Q: the 988TA G92 page says of Q only "螺纹切削开始角度
        // 的位差角。取值单位与范围请参考 G32": `one-shot` takes G32's rule
        // ("非模态，省略时为 0°"), `modal` keeps it as every other G92 word.
        let modal_q = self.machine.readings.g92_q == G92StartAngle::Modal;
        let start_angle = match block.get('Q')? {
            Some(w) => {
                let q = self.start_angle(&block, w)?;
                if modal_q {
                    self.g92.start_angle = Some(q);
                }
                q
            }
            None if modal_q => self.g92.start_angle.unwrap_or(StartAngle::ZERO),
            None => StartAngle::ZERO,
        };
        let p = &profile.params;
        let r = self.param_count(p.chamfer, 0, 99).map_err(with_line)?;
        let angle = match p.chamfer_angle {
            Some(n) => match self.param_count(n, 0, 89).map_err(with_line)? {
                0 => 45,
                v => v,
            },
            None => 45,
        };
        // 988TA: 5129 (THM) = 1 is the high-speed G92 mode, with its own
        // J/K rules (reading R-G92RUNOUT).
        let rules = if self.high_speed() { RunOutRules::Gsk988HighSpeed } else { profile.run_out };
        let run_out = resolve_run_out_under(rules, self.g92.j, self.g92.k, r, angle, &self.machine.readings);
        let cycle = G92Cycle {
            units: self.units,
            x_mode: self.machine.x_mode,
            start: Point::new(xa, za),
            end,
            taper,
            lead,
            run_out,
            starts: self.g92.starts.unwrap_or(1),
            start_angle,
            face: self.g92.face.unwrap_or(false),
            readings: self.machine.readings.for_cycle(profile.name, true),
        };
        cycle.validate().map_err(|e| err(&block, None, ErrorKind::Cycle(e)))?;
        self.g92.end_x = Some(end.x);
        self.g92.end_z = Some(end.z);
        self.g92.taper = Some(taper);
        // The block ends back at A (step ④).
        self.moved = true;
        Ok(G92Call { block, cycle })
    }

    /// G32's Q in the profile's unit (reading R-G32Q).
    pub(super) fn start_angle(&self, block: &Block<'_>, w: &Word<'_>) -> Result<StartAngle, ProgramError> {
        q_word(self.machine, self.units, block, w)
    }
}

/// Reading R-G32RUNOUT: the profile's rules for G32's modal J and K,
/// under the default readings ([`resolve_g32_run_out_under`]).
#[must_use]
pub fn resolve_g32_run_out(rules: G32Rules, j: Option<i64>, k: Option<i64>) -> G32RunOut {
    resolve_g32_run_out_under(rules, j, k, &Readings::default())
}

/// [`resolve_g32_run_out`] under `readings`: the 988TA's K = 0 with J ≠ 0
/// (R-G32RUNOUT `pull-out` or `none`).
#[must_use]
pub fn resolve_g32_run_out_under(
    rules: G32Rules,
    j: Option<i64>,
    k: Option<i64>,
    readings: &Readings,
) -> G32RunOut {
    match (rules, j, k) {
        (G32Rules::NoRunOut, _, _) | (_, None | Some(0), _) => G32RunOut::None,
        // Reading R-G32RUNOUT `none`: the 988TA G92 normal mode's "J≠0，K=0
        // 时，无退尾".
        (G32Rules::Gsk988, Some(_), Some(0)) if readings.g32_k_zero == G32KZero::None => G32RunOut::None,
        // Seed 002: K omitted, or K = 0 with J != 0: K = J.
        (G32Rules::Gsk980, Some(j), None | Some(0)) => G32RunOut::Amounts { short: j, long: j.abs() },
        (G32Rules::Gsk980, Some(j), Some(k)) => G32RunOut::Amounts { short: j, long: k },
        // 988TA: K omitted: no long-axis run-out, J along the short axis.
        (G32Rules::Gsk988, Some(j), None | Some(0)) => G32RunOut::Amounts { short: j, long: 0 },
        (G32Rules::Gsk988, Some(j), Some(k)) => G32RunOut::Amounts { short: j, long: k },
    }
}
