//! The typed parameters of one G75.1 radial trapezoidal groove cycle (径向凹槽
//! 切削循环), as the program reader resolves its two blocks (seed 001,
//! manuals/gsk980tdi-g75.1.txt): one home, used by the reference model and
//! the engine alike.
//!
//! The exact definition both engines follow — profile, roughing region,
//! rounding, layers, plunges and every move — is `docs/G75.md`; its readings
//! (`R-G75…`) are listed in `docs/INTERPRETATIONS.md`.

use crate::error::{CycleError, Field};
use crate::readings::G75Readings;
use crate::units::{IncrementSystem, Length, Point, Units, XMode, MAX_LENGTH};

/// J: which paths the cycle runs (走刀路径类型).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PathType {
    /// J0 (the default): roughing only (只走粗加工路径).
    Rough,
    /// J1: roughing, then the finishing contour.
    RoughAndFinish,
    /// J2: the finishing contour only.
    Finish,
}

impl PathType {
    /// True when the cycle roughs (J0, J1).
    #[must_use]
    pub const fn roughs(self) -> bool {
        matches!(self, PathType::Rough | PathType::RoughAndFinish)
    }

    /// True when the cycle runs the finishing contour (J1, J2).
    #[must_use]
    pub const fn finishes(self) -> bool {
        matches!(self, PathType::RoughAndFinish | PathType::Finish)
    }
}

/// A digit of P(a)(b)(d)(e): how a corner is broken.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CornerKind {
    /// 0: a straight chamfer (直线倒角) of equal legs (R-G75CHAMFER).
    Chamfer,
    /// 1: a round (圆弧倒角) tangent to both edges.
    Round,
}

/// One of the four corners A(r1), B(r2), D(r3), E(r4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Corner {
    /// Chamfer width or round radius in radius increments; 0: a sharp
    /// corner (the word was not programmed).
    pub size: i64,
    /// Its P digit.
    pub kind: CornerKind,
}

impl Corner {
    /// A sharp corner.
    pub const SHARP: Corner = Corner { size: 0, kind: CornerKind::Chamfer };
}

/// Index of each corner in [`G75Cycle::corners`].
pub mod corner {
    /// A(r1): the outer corner at the start point S (外底起点处).
    pub const R1: usize = 0;
    /// B(r2): the outer corner at the far end of the opening (外底另一端).
    pub const R2: usize = 1;
    /// D(r3): the bottom corner on the start side (内底靠近起点).
    pub const R3: usize = 2;
    /// E(r4): the bottom corner on the far side (内底远离起点).
    pub const R4: usize = 3;
}

/// 90° in the angle unit (0.0001°).
pub const RIGHT_ANGLE: u32 = 900_000;

/// Largest number of pecks a cycle may have (`docs/G75.md` §9); beyond it
/// the cycle is refused before any move is produced.
pub const MAX_PECKS: u64 = 1_000_000;

/// A G75.1 cycle: both blocks, resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct G75Cycle {
    /// Increment system and unit of every length below.
    pub units: Units,
    /// Diameter or radius X words.
    pub x_mode: XMode,
    /// Where the tool is before the cycle; the cycle ends there (step 10).
    pub from: Point,
    /// X Z of block 1: the groove start point S (梯形槽起点), the corner of
    /// the opening on the start side. Omitted words are the current position.
    pub start: Point,
    /// P(Δi): radial peck in X-word units (a diameter value on a diameter
    /// lathe, so each peck cuts Δi/2 of radius), > 0.
    pub peck: i64,
    /// Q(Δk): axial step between plunges (Z increments), > 0.
    pub step: i64,
    /// H(h): groove depth in X-word units (diameter), signed: the sign is
    /// the radial infeed direction. Not 0.
    pub depth: i64,
    /// D(d): width of the inner bottom (凹槽内底宽度, Z increments, radius
    /// value), signed: the sign is the axial direction (0 counts as +).
    pub width: i64,
    /// A(∠a): flank angle at the start side, between flank and bottom, in
    /// 0.0001° (1..=900 000; default 90°).
    pub flank_a: u32,
    /// B(∠b): flank angle at the far side, 0.0001° (1..=900 000).
    pub flank_b: u32,
    /// L(∠p): slope of the opening against the bottom's extension, 0.0001°
    /// (0..900 000; default 0).
    pub slope: u32,
    /// R(e): retract after each peck (radius increments), ≥ 0.
    pub retract: i64,
    /// V(Δv): largest layer depth in X-word units (diameter); `None`: one
    /// layer, the whole depth (pecking as in G75).
    pub layer: Option<i64>,
    /// U(Δu): finishing allowance on X, X-word units (diameter), ≥ 0.
    pub allowance_x: i64,
    /// W(Δw): finishing allowance on Z, ≥ 0.
    pub allowance_z: i64,
    /// I(r): width of the grooving tool (its magnitude: "输入负值时当成正值处理");
    /// `None`: a pointed tool.
    pub tool_width: Option<i64>,
    /// J0/J1/J2.
    pub path: PathType,
    /// A(r1), B(r2), D(r3), E(r4) with their P digits; index with [`corner`].
    pub corners: [Corner; 4],
    /// The readings of the points the page leaves open (issue 34), as the
    /// program reader resolves them; [`G75Readings::DEFAULT`] for a cycle
    /// built without the reader.
    pub readings: G75Readings,
}

/// Largest |H| or |D|, and largest Δv, in increments: 9999.999 at IS-B,
/// 9999.9999 at IS-C (the manual page's range; the seed prints 9999.999 for
/// both, the manual's four decimals for IS-C are taken).
#[must_use]
pub const fn max_size(units: Units) -> i64 {
    match units.system {
        IncrementSystem::IsB => 9_999_999,
        IncrementSystem::IsC => 99_999_999,
    }
}

/// Largest R(e) and corner size: 99.999 (IS-B) / 99.9999 (IS-C).
#[must_use]
pub const fn max_small(units: Units) -> i64 {
    match units.system {
        IncrementSystem::IsB => 99_999,
        IncrementSystem::IsC => 999_999,
    }
}

/// Largest P(Δi) and Q(Δk) in increments (seed 001: 99999999 for both systems).
pub const MAX_PECK: i64 = 99_999_999;

/// Largest |U|, |W|, |I| in increments: 99999.999 (IS-B) / 9999.9999 (IS-C).
pub const MAX_ALLOWANCE: i64 = 99_999_999;

impl G75Cycle {
    fn len(&self, v: i64) -> Length {
        Length::new(v, self.units)
    }

    /// The tool width w in Z increments (0 for a pointed tool).
    #[must_use]
    pub const fn width_of_tool(&self) -> i64 {
        match self.tool_width {
            Some(w) => w,
            None => 0,
        }
    }

    /// Checks the manual's range tables and the alarms that depend only on
    /// the programmed values; the alarms that need the geometry (corners
    /// too large, groove narrower than the tool, `docs/G75.md` §3 and §7)
    /// are the engines' own. Both engines call this first.
    ///
    /// # Errors
    ///
    /// The first violated rule.
    pub fn validate(&self) -> Result<(), CycleError> {
        self.validate_position()?;
        self.validate_words()
    }

    /// [`G75Cycle::validate`]'s first checks: the start point and the
    /// point before the cycle within range. The only ones that depend on
    /// where the groove is: a plan of the same words
    /// ([`crate::engine::g75::G75Plan`]) was validated with them, and needs
    /// only these (issue 33).
    pub(crate) fn validate_position(&self) -> Result<(), CycleError> {
        let c = self;
        for (field, v) in [
            (Field::GrooveStartX, c.start.x),
            (Field::GrooveStartZ, c.start.z),
            (Field::GrooveFromX, c.from.x),
            (Field::GrooveFromZ, c.from.z),
        ] {
            if !(-MAX_LENGTH..=MAX_LENGTH).contains(&v) {
                return Err(CycleError::WordOutOfRange {
                    field,
                    value: c.len(v),
                    rule: "at most 999999999 least increments",
                });
            }
        }
        Ok(())
    }

    /// [`G75Cycle::validate`]'s checks after
    /// [`validate_position`](G75Cycle::validate_position): those of the
    /// words, in its order.
    fn validate_words(&self) -> Result<(), CycleError> {
        let c = self;
        let range = |field: Field, v: i64, lo: i64, hi: i64, rule: &'static str| {
            if v < lo || v > hi {
                return Err(CycleError::WordOutOfRange { field, value: c.len(v), rule });
            }
            Ok(())
        };
        range(Field::Peck, c.peck, 1, MAX_PECK, "0 < Δi <= 99999999 least increments")?;
        range(Field::Step, c.step, 1, MAX_PECK, "0 < Δk <= 99999999 least increments")?;
        let size = max_size(c.units);
        let size_rule = match c.units.system {
            IncrementSystem::IsB => "-9999.999 < value <= 9999.999",
            IncrementSystem::IsC => "-9999.9999 < value <= 9999.9999",
        };
        range(Field::GrooveDepth, c.depth, -size + 1, size, size_rule)?;
        if c.depth == 0 {
            return Err(CycleError::NoGrooveDepth);
        }
        range(Field::BottomWidth, c.width, -size + 1, size, size_rule)?;
        let angle = |field: Field, v: u32, lo: u32, hi: u32| {
            if v < lo || v > hi {
                return Err(CycleError::AngleOutOfRange { field, value: v });
            }
            Ok(())
        };
        angle(Field::FlankA, c.flank_a, 1, RIGHT_ANGLE)?;
        angle(Field::FlankB, c.flank_b, 1, RIGHT_ANGLE)?;
        angle(Field::Slope, c.slope, 0, RIGHT_ANGLE - 1)?;
        let small = max_small(c.units);
        let small_rule = match c.units.system {
            IncrementSystem::IsB => "0 ~ 99.999, unsigned",
            IncrementSystem::IsC => "0 ~ 99.9999, unsigned",
        };
        range(Field::Retract, c.retract, 0, small, small_rule)?;
        if let Some(v) = c.layer {
            let rule = match c.units.system {
                IncrementSystem::IsB => "0 < Δv <= 9999.999",
                IncrementSystem::IsC => "0 < Δv <= 9999.9999",
            };
            range(Field::LayerDepth, v, 1, size, rule)?;
        }
        // R-G75ALLOW: U and W are "无符号" (unsigned): a negative value is
        // refused rather than read as its magnitude (only I has that rule).
        let allowance_rule = "0 <= value <= 99999999 least increments (unsigned)";
        range(Field::AllowanceX, c.allowance_x, 0, MAX_ALLOWANCE, allowance_rule)?;
        range(Field::AllowanceZ, c.allowance_z, 0, MAX_ALLOWANCE, allowance_rule)?;
        if let Some(w) = c.tool_width {
            range(Field::ToolWidth, w, 0, MAX_ALLOWANCE, "0 <= |I| <= 99999999 least increments")?;
        }
        for (field, corner) in
            [Field::CornerR1, Field::CornerR2, Field::CornerR3, Field::CornerR4].into_iter().zip(c.corners)
        {
            range(field, corner.size, 0, small, small_rule)?;
        }
        // L is the slope of the opening (R-G75SLOPE). Rising towards D
        // (default): flank B must be steeper or it never meets the opening.
        // Falling towards D: flank A must be steeper or it never goes down
        // from S into the groove (flank B always meets the opening; that it
        // meets it above the bottom is the engines' check, it needs y3).
        if c.readings.slope_falls_towards_d {
            if c.slope >= c.flank_a {
                return Err(CycleError::SlopeNotBelowFlankA { slope: c.slope, flank_a: c.flank_a });
            }
        } else if c.slope >= c.flank_b {
            return Err(CycleError::SlopeNotBelowFlank { slope: c.slope, flank_b: c.flank_b });
        }
        // Allowances larger than the groove: the roughing bottom must lie
        // below the opening.
        if c.allowance_x >= c.depth.abs() {
            return Err(CycleError::AllowanceExceedsDepth {
                allowance: c.len(c.allowance_x),
                depth: c.len(c.depth.abs()),
            });
        }
        Ok(())
    }

    /// `sx`: +1 when H > 0, −1 when H < 0.
    #[must_use]
    pub const fn radial_sign(&self) -> i64 {
        if self.depth < 0 {
            -1
        } else {
            1
        }
    }

    /// `sz`: +1 when D ≥ 0, −1 when D < 0.
    #[must_use]
    pub const fn axial_sign(&self) -> i64 {
        if self.width < 0 {
            -1
        } else {
            1
        }
    }

    /// Maps a local point (`u` along `sz` from S, `y` along `sx` from S,
    /// `docs/G75.md` §2) to absolute X/Z.
    #[must_use]
    pub const fn to_absolute(&self, u: i64, y: i64) -> Point {
        Point { x: self.start.x + self.radial_sign() * y, z: self.start.z + self.axial_sign() * u }
    }
}
