//! The G92 thread-cutting cycle (螺纹切削循环), exactly as the manuals
//! define it: one pass per block.
//!
//! Sources: manuals/gsk980tdi-g92.txt ("代码格式", "循环过程" ①-④, notes
//! 1-11, figures 3-88 to 3-91, example O0012), manuals/gsk988ta-g92.txt
//! (normal mode, notes 4-5), seed 000 (parameters 5129-5131). Every reading
//! chosen where the sources are silent carries an id `R-G92…` in
//! `docs/INTERPRETATIONS.md`.
//!
//! | point | definition |
//! |---|---|
//! | A | start point (起点(终点)): the tool position before the block |
//! | B | cut start (切削起点): Z of A; X of C plus R (radius) |
//! | C | cut end (切削终点): X(U) Z(W) of the block |
//!
//! The pass is the pass of the shared pass model ([`crate::pass`]), the
//! same path a G76 pass takes: a G92 block is a G76 pass at the programmed
//! X.

use cycleref::angle::StartAngle;
use cycleref::error::{CycleError, Field};
use cycleref::g92::G92Cycle;
use cycleref::moves::{Flank, Move, Pass, PassKind};
use cycleref::units::{Length, MAX_LENGTH};
use rust_decimal::Decimal;

use crate::exact::{from_increments, to_increments};
use crate::g76::{run_out_amounts, LongAxis};
use crate::pass::{pass_path, PassFrame, PassStream};

/// Expands a G92 block into moves: for each start (reading R-STARTS; the
/// first at Q, the others 360°/L apart), the path of 980TDi "循环过程":
///
/// 1. X from A to the cut start B at rapid ("X 轴从起点快速移动到切削起点");
/// 2. thread from B to the cut end C ("从切削起点螺纹插补到切削终点"), with the
///    run-out K before C and J away from the work ("在距离螺纹切削终点固定长度
///    处 … X 轴沿退刀方向 … 退出", reading R-RUNOUT);
/// 3. X back to the X of A at rapid ("返回到 X 轴绝对坐标与起点相同处");
/// 4. Z back to A at rapid.
///
/// # Errors
///
/// [`G92Cycle::validate`]; [`CycleError::NoInfeed`] when C has the X of A
/// and [`CycleError::TaperBeyondStart`] when B lies beyond A (reading
/// R-G92SIDE); [`CycleError::RunOutTooLong`] (988TA note 4);
/// [`CycleError::RunOutIntoWork`] (reading R-XRUNOUT);
/// [`CycleError::OutOfRange`] for the X of B (reading R-RANGE).
///
/// Twin: `impl/src/engine/g92.rs`, `expand_g92`.
pub fn expand(c: &G92Cycle) -> Result<Vec<Move>, CycleError> {
    Ok(moves(c)?.collect())
}

/// The moves of [`expand`], made a start at a time (memory of one pass,
/// whatever the number of starts): every alarm is raised before the first
/// move.
///
/// # Errors
///
/// As [`expand`].
pub fn moves(c: &G92Cycle) -> Result<impl Iterator<Item = Move> + Clone + Send + Sync + 'static, CycleError> {
    c.validate()?;
    let u = c.units;
    let len = |v: Decimal| Length::new(to_increments(v, u), u);
    let xf = Decimal::from(c.x_mode.factor());
    let (ax, az) = (from_increments(c.start.x, u), from_increments(c.start.z, u));
    let (cx, cz) = (from_increments(c.end.x, u), from_increments(c.end.z, u));
    let r = from_increments(c.taper, u);
    // In the pass frame (`crate::pass`): (short axis, long axis). A face
    // thread (988TA P1, reading R-G92FACE: "P = 1（端面螺纹）长轴 纵轴，短轴
    // 横轴") has Z as its short axis, radius-like, and X as its long axis, in
    // X words (`lf`).
    let (a, cut_end, sf, lf) =
        if c.face { ((az, ax), (cz, cx), Decimal::ONE, xf) } else { ((ax, az), (cx, cz), xf, Decimal::ONE) };
    // B: "R：切削起点与切削终点 X 轴绝对坐标的差值(半径值)"; on a face thread the
    // short axis is Z ("锥度 R 决定了锥螺纹起点短轴的位置").
    let b = (cut_end.0 + sf * r, a.1);
    // Reading R-G92SIDE: the thread is on the side of A ("根据程序起点位置自动
    // 确定退尾方向"); no short-axis travel (U = 0, W = 0 on a face thread)
    // gives none.
    let u_word = cut_end.0 - a.0;
    if u_word.is_zero() {
        return Err(CycleError::NoInfeed);
    }
    let side: i64 = if u_word < Decimal::ZERO { 1 } else { -1 };
    // "当 R 与 U 的符号不一致时，要求 │R│≤│U/2│": B between A and C (or on A).
    // With the same signs B lies beyond C, away from A, which is allowed.
    if (r > Decimal::ZERO) != (u_word > Decimal::ZERO) && !r.is_zero() && sf * r.abs() > u_word.abs() {
        return Err(CycleError::TaperBeyondStart { taper: len(r), infeed: len(u_word) });
    }
    let w = cut_end.1 - a.1;
    let direction = if w > Decimal::ZERO { 1 } else { -1 };
    // "B 点与 C 点 Z 轴坐标差的绝对值大于 X 轴(半径值)坐标差的绝对值时，Z 轴为长轴；
    // 反之，X 轴为长轴" (reading R-LONG); a face thread's long axis is X.
    // Reading R-LONG988 `table` (988TA "P = 0（轴向螺纹）长轴：横轴"): Z
    // whatever the displacements.
    let long_axis =
        if c.face || w.abs() > r.abs() || c.readings.long_axis_by_table { LongAxis::Z } else { LongAxis::X };
    // K along the long axis, in its units (X words on a face thread).
    let run_out =
        run_out_amounts(c.run_out, c.lead, u, c.readings.chamfer_from_short_axis).map(|(j, k)| (j, k * lf));
    if let Some((_, kk)) = run_out {
        let length = match long_axis {
            LongAxis::Z => w.abs(),
            LongAxis::X => r.abs(),
        };
        // 988TA note 4: a long-axis run-out longer than the thread is an alarm.
        if kk > length {
            return Err(CycleError::RunOutTooLong { run_out: len(kk), length: len(length) });
        }
        // Reading R-XRUNOUT: on an X long axis the run-out runs along Z
        // towards A; the cut line there lies xf·R·J/|W| beyond C's X, on
        // the work's side when R points away from the work (s·R > 0).
        // `towards-start` makes it as written.
        if long_axis == LongAxis::X
            && Decimal::from(side) * r > Decimal::ZERO
            && !c.readings.x_run_out_towards_start
        {
            return Err(CycleError::RunOutIntoWork { taper: len(r) });
        }
    }
    if to_increments(b.0, u).abs() > MAX_LENGTH {
        return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value: len(b.0) });
    }
    // Reading R-RUNOUT `gsk988-only`: J as written, not clamped at the
    // retract, so its end may lie beyond the range (R-RANGE).
    if let (Some((j, _)), false) = (run_out, c.readings.clamp_run_out) {
        let beyond = match long_axis {
            LongAxis::Z => cut_end.0 + Decimal::from(side) * sf * j,
            LongAxis::X => cut_end.1 - Decimal::from(direction) * j,
        };
        if to_increments(beyond, u).abs() > MAX_LENGTH {
            return Err(CycleError::OutOfRange { field: Field::PassCoordinate, value: len(beyond) });
        }
    }
    let frame = PassFrame {
        a,
        transposed: c.face,
        side,
        direction,
        length: w.abs(),
        x_factor: sf,
        long_axis,
        run_out,
        clamp_run_out: c.readings.clamp_run_out,
        // One pass without shift: every R-END value gives this path.
        line: None,
        lead: c.lead,
        units: u,
    };
    let (starts, first_angle) = (c.starts, c.start_angle);
    let mut start = 0_u32;
    Ok(PassStream::new(move |moves: &mut Vec<Move>| {
        if start == starts {
            return false;
        }
        let pass = Pass {
            kind: PassKind::Single,
            number: 1,
            start: u16::try_from(start + 1).expect("L <= 999 (validate)"),
            depth: 0,
            cut: 0,
            flank: Flank::Centre,
        };
        let angle = first_angle.plus(StartAngle::of_start(start, starts));
        pass_path(moves, &frame, b, cut_end, None, pass, angle);
        start += 1;
        true
    }))
}
