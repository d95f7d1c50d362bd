//! The C types of the interface: plain `#[repr(C)]` structs and integer
//! enums, and their conversions from the engine's model.
//!
//! Input structs ([`CyclerefOptions`], [`CyclerefG76Params`]) carry their
//! enums as plain integers (`uint32_t`) and flags as `uint8_t`: a C caller
//! can put any value there, and a Rust enum or `bool` holding a value
//! outside its range would be undefined behaviour. They are checked on the
//! way in and refused with [`CyclerefStatus::InvalidArgument`]. Output
//! structs use the enums directly: only this crate writes them.

use core::ffi::c_char;

use cycleref::g76::DEFAULT_PASS_LIMIT;
use cycleref::{
    DepthMode, Flank, G76Cycle, G92Cycle, IncrementSystem, Infeed, InputUnit, Lead, LeadWord, Motion, Move,
    PassKind, Point, Role, RunOut, StartAngle, Units, XMode,
};

/// Size of `CyclerefError.message` in bytes, the terminating NUL included.
pub const CYCLEREF_ERROR_MESSAGE_LEN: usize = 512;

/// What a function returned. `CYCLEREF_STATUS_OK` is 0 and every error is
/// negative, so `cycleref_g76_next` can return 1 (a move), 0 (the end) or
/// a negative status.
#[repr(i32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefStatus {
    /// Success.
    Ok = 0,
    /// The move buffer is too small: `*count` holds the number of moves
    /// needed, and the first `capacity` moves were written.
    BufferTooSmall = -1,
    /// The reader refused the program (syntax, a missing or out-of-range
    /// word, an alarm found while reading): the error has its line.
    ProgramError = -2,
    /// The engine refused a cycle (a geometry alarm such as a start point
    /// inside the thread): the error has the line of the cycle's block, or
    /// 0 for `cycleref_g76_new`.
    CycleError = -3,
    /// A null pointer, an enum value out of range, a program that is not
    /// UTF-8 or a parameter file that cannot be applied.
    InvalidArgument = -4,
    /// A panic inside the library was caught (a bug: please report it).
    Panic = -5,
}

/// The control profile a program is read by (`CyclerefOptions::profile`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefProfile {
    /// FANUC-style two-block G76.
    Fanuc = 0,
    /// GSK 980TDi.
    Gsk980 = 1,
    /// GSK 988TA and the extended G76.
    Gsk988 = 2,
    /// LinuxCNC 2.9: its one-block G76 and G33, G7/G8 (IS-C and radius X
    /// by default).
    LinuxCnc = 3,
}

/// The increment system (`CyclerefOptions::increment`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefIncrement {
    /// IS-B, unless the parameter file sets `increment`.
    Default = 0,
    /// IS-B: 0.001 mm / 0.0001 inch (overrides the parameter file).
    IsB = 1,
    /// IS-C: 0.0001 mm / 0.00001 inch (overrides the parameter file).
    IsC = 2,
}

/// Which cycle a move of `cycleref_expand` or `cycleref_cursor_next`
/// belongs to.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefCycle {
    /// A G76 multiple thread-cutting cycle (on the linuxcnc profile,
    /// LinuxCNC's G76).
    G76 = 0,
    /// A G32 thread-cutting block (on the linuxcnc profile, a G33 block).
    G32 = 1,
    /// A G75.1 radial trapezoidal groove cycle.
    G75 = 2,
    /// A G92 thread-cutting cycle block.
    G92 = 3,
    /// A G78 enhanced multiple thread-cutting cycle (the G76 cycle's model).
    G78 = 4,
}

impl CyclerefCycle {
    /// The C name of a cycle's G code ([`cycleref_spec::Cycle::code`]):
    /// LinuxCNC's G76 is a G76 and its G33 a G32. `None` for a code without
    /// one (a cycle added to the registry needs its C name here; a test
    /// holds every registered cycle to it).
    #[must_use]
    pub fn of_code(code: &str) -> Option<CyclerefCycle> {
        Some(match code {
            "G76" => CyclerefCycle::G76,
            "G32" | "G33" => CyclerefCycle::G32,
            "G75.1" => CyclerefCycle::G75,
            "G92" => CyclerefCycle::G92,
            "G78" => CyclerefCycle::G78,
            _ => return None,
        })
    }
}

/// How the tool moves to the end point of a move.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefMotion {
    /// Positioning at rapid traverse (G00).
    Rapid = 0,
    /// Linear feed (G01).
    Feed = 1,
    /// Constant-lead thread cutting synchronised with the spindle (G32).
    Thread = 2,
    /// Clockwise arc (G02) around `centre_x`, `centre_z`.
    ArcCw = 3,
    /// Counter-clockwise arc (G03) around `centre_x`, `centre_z`.
    ArcCcw = 4,
}

/// What a move does within its pass.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefRole {
    /// Rapid from A to the pass start (or to the lead-in start).
    Approach = 0,
    /// Screw-in along the lead-in E.
    LeadIn = 1,
    /// The thread cut.
    Cut = 2,
    /// The run-out at the end of the cut.
    RunOut = 3,
    /// Rapid along X to the X of A.
    Retract = 4,
    /// Rapid along Z back to A (G75.1: back to the start point and to the
    /// point before the cycle).
    Return = 5,
    /// G75.1: a peck (radial feed of at most Δi).
    Peck = 6,
    /// G75.1: the rapid retract e after a peck.
    PeckRetract = 7,
    /// G75.1: the rapid retract to the plunge start.
    PlungeRetract = 8,
    /// G75.1: the axial rapid to the next plunge.
    Step = 9,
    /// G75.1: the rapids to the next layer's start.
    LayerChange = 10,
    /// G75.1: the rough contour.
    RoughContour = 11,
    /// G75.1: the finishing contour.
    FinishContour = 12,
}

/// Rough or finishing pass.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefPassKind {
    /// A rough pass.
    Rough = 0,
    /// A finishing pass.
    Finish = 1,
    /// The one pass of a G92 block (depth and cut 0).
    Single = 2,
}

/// Where in the thread space a pass starts (infeed pattern).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefFlank {
    /// On the right flank line.
    Right = 0,
    /// On the centre line of the final form.
    Centre = 1,
    /// On the left flank line.
    Left = 2,
}

/// Which word programmed a lead.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefLeadWord {
    /// `F`: mm (inch) per revolution.
    F = 0,
    /// `I`: threads per inch.
    I = 1,
    /// `K`: LinuxCNC's pitch (`G33 K`), mm (inch) per revolution along
    /// the move.
    K = 2,
}

/// The infeed mode, the `D` word of the extended G76
/// (`CyclerefG76Params::infeed`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefInfeed {
    /// D0: along the right flank.
    RightFlank = 0,
    /// D1: right flank and centre, alternately.
    RightCentre = 1,
    /// D2: left and right flanks alternately.
    LeftRight = 2,
    /// G78 r = 0: on the centre line.
    Centre = 3,
    /// G78 r = 1: along the left flank.
    LeftFlank = 4,
    /// G78 r = 3 on the 980TDi: one pass a level, right and left flank in
    /// turn.
    Alternating = 5,
}

/// How the rough depths of a G76/G78 cycle grow
/// (`CyclerefG76Params::depth_mode`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefDepthMode {
    /// `round(Δd √n)` with the minimum cut (G76; G78 递减式). Zero, so a
    /// zero-initialised struct is a G76.
    Decreasing = 0,
    /// Equal steps of max(Δd, Δdmin) (G78 等距离).
    Equal = 1,
}

/// The kind of run-out of a G76 cycle (`CyclerefG76Params::run_out_kind`).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CyclerefRunOutKind {
    /// No run-out: the cut ends on the line D-E.
    None = 0,
    /// Run-out by amounts: `run_out_short` (J) and `run_out_long` (K).
    Amounts = 1,
    /// Run-out from the chamfer `run_out_tenths` (r, tenths of the lead)
    /// at `run_out_angle` degrees, with `run_out_long` (K) when
    /// `run_out_has_long` is non-zero.
    Chamfer = 2,
}

/// Options of `cycleref_expand` and `cycleref_cursor_open`: the machine a
/// program is read with.
///
/// `cycleref_options_default()` gives the defaults of the `cycleref`
/// command: GSK 988TA, IS-B, metric, X as diameter, no parameter file.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct CyclerefOptions {
    /// A `CyclerefProfile`.
    pub profile: u32,
    /// A `CyclerefIncrement`.
    pub increment: u32,
    /// Non-zero: inch input (G20 at program start); zero: metric, unless
    /// the parameter file sets `unit`.
    pub inch: u8,
    /// Non-zero: X words are radii; zero: diameters, unless the parameter
    /// file sets `x`.
    pub radius: u8,
    /// The text of a parameter file (TOML, the keys of the `--params` file
    /// of the `cycleref` command), not necessarily NUL-terminated, or NULL
    /// for none. It is applied on top of the profile's defaults; the
    /// fields `increment`, `inch` and `radius` above override its keys.
    pub params_toml: *const c_char,
    /// Length of `params_toml` in bytes (0 when it is NULL).
    pub params_toml_len: usize,
    /// The readings chosen where the manuals leave a point open (issue
    /// 34; `cycleref readings` lists them): a NUL-terminated UTF-8 string
    /// of `ID=VALUE` pairs separated by commas, e.g.
    /// `"R-RUNOUT=gsk988-only,R-XRUNOUT=towards-start"`, applied after the
    /// parameter file's `[readings]` (so it wins, as `--reading`), or NULL
    /// for none. An unknown id or value is `CYCLEREF_STATUS_INVALID_ARGUMENT`
    /// with a message naming the valid ones. Added at the end of the struct
    /// (0.2.x): code that fills the struct from `cycleref_options_default()`
    /// gets NULL.
    pub readings: *const c_char,
}

impl Default for CyclerefOptions {
    fn default() -> Self {
        CyclerefOptions {
            profile: CyclerefProfile::Gsk988 as u32,
            increment: CyclerefIncrement::Default as u32,
            inch: 0,
            radius: 0,
            params_toml: core::ptr::null(),
            params_toml_len: 0,
            readings: core::ptr::null(),
        }
    }
}

/// One move of a toolpath, in least increments.
///
/// Lengths are exact integers: a coordinate `x` is `x / 10^decimals` mm
/// (inch). The lead, start angle and `sync` are meaningful only when
/// `motion` is `CYCLEREF_MOTION_THREAD` (otherwise they are 0, the angle
/// 0/1); the pass fields only when `has_pass` is non-zero (G76 moves; G32
/// moves have no pass and the fields are 0).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CyclerefMove {
    /// X of the end point, in X-word units (diameter increments unless the
    /// machine has radius X).
    pub x: i64,
    /// Z of the end point, in increments.
    pub z: i64,
    /// Digits of the lead without the decimal point (`F6` is 6, `F1.5` 15).
    pub lead_mantissa: u64,
    /// Thread depth of the pass from B (radius increments).
    pub pass_depth: i64,
    /// Cut of the pass: its depth minus the previous level's (radius
    /// increments).
    pub pass_cut: i64,
    /// The 1-based source line of the block the move came from (G76 and
    /// G75.1 block 2, or the G32 block); 0 for moves of
    /// `cycleref_g76_next`.
    pub line: usize,
    /// Decimals of one increment (IS-B mm 3, IS-B inch 4, IS-C mm 4, IS-C
    /// inch 5).
    pub decimals: u32,
    /// Which cycle the move belongs to.
    pub cycle: CyclerefCycle,
    /// Rapid, feed or thread.
    pub motion: CyclerefMotion,
    /// What the move does.
    pub role: CyclerefRole,
    /// `F` or `I`.
    pub lead_word: CyclerefLeadWord,
    /// Decimals of the programmed lead (`F6` is 0, `F1.5` 1).
    pub lead_scale: u32,
    /// Spindle start angle: `start_angle_num / start_angle_den` thousandths
    /// of a degree, in lowest terms.
    pub start_angle_num: u32,
    /// Denominator of the start angle, at least 1.
    pub start_angle_den: u32,
    /// Rough or finishing.
    pub pass_kind: CyclerefPassKind,
    /// 1-based number of the pass among the passes of its kind.
    pub pass_number: u32,
    /// 1-based thread start of the pass (1..=L).
    pub pass_start: u32,
    /// Position of the pass in the infeed pattern.
    pub pass_flank: CyclerefFlank,
    /// 1 on the move where the control waits for the spindle's
    /// one-revolution signal, else 0.
    pub sync: u8,
    /// 1 when the pass fields are meaningful, 0 when the move has no pass.
    pub has_pass: u8,
    /// X of an arc's centre (absolute, X-word units); 0 for other motions.
    pub centre_x: i64,
    /// Z of an arc's centre (absolute); 0 for other motions.
    pub centre_z: i64,
    /// G75.1: 1-based layer of the move's plunge (also of a layer change);
    /// 0 when the move belongs to no plunge.
    pub plunge_layer: u32,
    /// G75.1: 1-based plunge within its layer; 0 when none.
    pub plunge_number: u32,
}

impl Default for CyclerefMove {
    fn default() -> Self {
        CyclerefMove {
            x: 0,
            z: 0,
            lead_mantissa: 0,
            pass_depth: 0,
            pass_cut: 0,
            line: 0,
            decimals: 0,
            cycle: CyclerefCycle::G76,
            motion: CyclerefMotion::Rapid,
            role: CyclerefRole::Approach,
            lead_word: CyclerefLeadWord::F,
            lead_scale: 0,
            start_angle_num: 0,
            start_angle_den: 1,
            pass_kind: CyclerefPassKind::Rough,
            pass_number: 0,
            pass_start: 0,
            pass_flank: CyclerefFlank::Right,
            sync: 0,
            has_pass: 0,
            centre_x: 0,
            centre_z: 0,
            plunge_layer: 0,
            plunge_number: 0,
        }
    }
}

impl CyclerefMove {
    /// The C form of `m`, a move of a cycle with `decimals` decimals per
    /// increment, from the block on `line` (0 when unknown).
    #[must_use]
    pub fn from_move(m: &Move, decimals: u32, cycle: CyclerefCycle, line: usize) -> CyclerefMove {
        let mut out = CyclerefMove { x: m.to.x, z: m.to.z, line, decimals, cycle, ..CyclerefMove::default() };
        out.role = match m.role {
            Role::Approach => CyclerefRole::Approach,
            Role::LeadIn => CyclerefRole::LeadIn,
            Role::Cut => CyclerefRole::Cut,
            Role::RunOut => CyclerefRole::RunOut,
            Role::Retract => CyclerefRole::Retract,
            Role::Return => CyclerefRole::Return,
            Role::Peck(_) => CyclerefRole::Peck,
            Role::PeckRetract(_) => CyclerefRole::PeckRetract,
            Role::PlungeRetract(_) => CyclerefRole::PlungeRetract,
            Role::Step(_) => CyclerefRole::Step,
            Role::LayerChange(_) => CyclerefRole::LayerChange,
            Role::RoughContour => CyclerefRole::RoughContour,
            Role::FinishContour => CyclerefRole::FinishContour,
        };
        match m.role {
            Role::Peck(p) | Role::PeckRetract(p) | Role::PlungeRetract(p) | Role::Step(p) => {
                out.plunge_layer = p.layer;
                out.plunge_number = p.number;
            }
            Role::LayerChange(l) => out.plunge_layer = l,
            _ => {}
        }
        match m.motion {
            Motion::Rapid => out.motion = CyclerefMotion::Rapid,
            Motion::Feed => out.motion = CyclerefMotion::Feed,
            Motion::Thread { lead, start_angle, sync } => {
                out.motion = CyclerefMotion::Thread;
                out.lead_word = match lead.word {
                    LeadWord::F => CyclerefLeadWord::F,
                    LeadWord::I => CyclerefLeadWord::I,
                    LeadWord::K => CyclerefLeadWord::K,
                };
                out.lead_mantissa = lead.mantissa;
                out.lead_scale = lead.scale;
                out.start_angle_num = start_angle.num;
                out.start_angle_den = start_angle.den;
                out.sync = u8::from(sync);
            }
            Motion::Arc { centre, clockwise } => {
                out.motion = if clockwise { CyclerefMotion::ArcCw } else { CyclerefMotion::ArcCcw };
                out.centre_x = centre.x;
                out.centre_z = centre.z;
            }
        }
        if let Some(p) = m.pass {
            out.has_pass = 1;
            out.pass_kind = match p.kind {
                PassKind::Rough => CyclerefPassKind::Rough,
                PassKind::Finish => CyclerefPassKind::Finish,
                PassKind::Single => CyclerefPassKind::Single,
            };
            out.pass_number = p.number;
            out.pass_start = u32::from(p.start);
            out.pass_depth = p.depth;
            out.pass_cut = p.cut;
            out.pass_flank = match p.flank {
                Flank::Right => CyclerefFlank::Right,
                Flank::Centre => CyclerefFlank::Centre,
                Flank::Left => CyclerefFlank::Left,
            };
        }
        out
    }
}

/// The parameters of one G76 cycle, as `cycleref::G76Cycle` has them, for
/// `cycleref_g76_new`.
///
/// Every length is in least increments of the units given by `increment`
/// and `inch`; radius amounts (k, delta-d, delta-d min, d, i, E, J, K) are
/// radius increments whatever `radius` says, while the points A and D carry
/// X in X-word units (diameter increments unless `radius` is non-zero).
/// The values are taken as resolved: the profile rules for omitted words
/// and run-out words that `cycleref_expand` applies are not applied here.
/// The readings are the defaults of every profile (docs/INTERPRETATIONS.md):
/// each pass parallel to C→D until D–E (R-END `parallel`), J clamped at the
/// retract (R-RUNOUT), an X-long run-out into the work refused (R-XRUNOUT),
/// the long axis by the displacements (R-LONG988 is a 988TA G92/G78
/// reading, which a G76 does not take), one rough pass at depth 0 when d =
/// k (R-NOROUGH `one-at-zero`).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct CyclerefG76Params {
    /// X of the start point A (X-word units).
    pub start_x: i64,
    /// Z of the start point A.
    pub start_z: i64,
    /// X(U) of block 2: X of the thread end D (X-word units).
    pub end_x: i64,
    /// Z(W) of block 2: Z of the thread end D.
    pub end_z: i64,
    /// R(i): taper, X of the thread start minus X of D (radius, signed).
    pub taper: i64,
    /// P(k): thread height (radius, > 0).
    pub thread_height: i64,
    /// Q(delta-d): first depth (radius, > 0).
    pub first_depth: i64,
    /// Q(delta-d min): minimum cut (radius).
    pub min_cut: i64,
    /// R(d): finishing allowance (radius).
    pub finishing_allowance: i64,
    /// E: lead-in along X (radius); 0 for none.
    pub lead_in: i64,
    /// Digits of the lead without the decimal point.
    pub lead_mantissa: u64,
    /// J of a `CYCLEREF_RUN_OUT_KIND_AMOUNTS` run-out (radius, unsigned).
    pub run_out_short: i64,
    /// K of an `AMOUNTS` run-out, or of a `CHAMFER` run-out when
    /// `run_out_has_long` is non-zero.
    pub run_out_long: i64,
    /// A `CyclerefIncrement` (`CYCLEREF_INCREMENT_DEFAULT` is IS-B).
    pub increment: u32,
    /// P(m): finishing passes (0..=99).
    pub finishing_passes: u32,
    /// P(a): tool angle in degrees (0..=99).
    pub tool_angle: u32,
    /// A `CyclerefInfeed`.
    pub infeed: u32,
    /// L: number of starts (1..=999).
    pub starts: u32,
    /// A `CyclerefLeadWord`.
    pub lead_word: u32,
    /// Decimals of the lead (`F6` is 0).
    pub lead_scale: u32,
    /// A `CyclerefRunOutKind`.
    pub run_out_kind: u32,
    /// r of a `CHAMFER` run-out: tenths of the lead (0..=99).
    pub run_out_tenths: u32,
    /// Chamfer angle of a `CHAMFER` run-out in degrees (1..=89; the
    /// reader turns a parameter value of 0 into 45).
    pub run_out_angle: u32,
    /// Largest number of rough passes; 0 for the default (1 000 000).
    pub pass_limit: u32,
    /// A `CyclerefDepthMode` (0, decreasing, for G76).
    pub depth_mode: u32,
    /// Non-zero: inch units.
    pub inch: u8,
    /// Non-zero: X words are radii.
    pub radius: u8,
    /// Non-zero: a `CHAMFER` run-out has the K of `run_out_long`.
    pub run_out_has_long: u8,
}

impl CyclerefG76Params {
    /// The C form of `c`.
    #[must_use]
    pub fn from_cycle(c: &G76Cycle) -> CyclerefG76Params {
        let mut p = CyclerefG76Params {
            start_x: c.start.x,
            start_z: c.start.z,
            end_x: c.end.x,
            end_z: c.end.z,
            taper: c.taper,
            thread_height: c.thread_height,
            first_depth: c.first_depth,
            min_cut: c.min_cut,
            finishing_allowance: c.finishing_allowance,
            lead_in: c.lead_in,
            lead_mantissa: c.lead.mantissa,
            increment: match c.units.system {
                IncrementSystem::IsB => CyclerefIncrement::IsB as u32,
                IncrementSystem::IsC => CyclerefIncrement::IsC as u32,
            },
            finishing_passes: c.finishing_passes,
            tool_angle: c.tool_angle,
            infeed: match c.infeed {
                Infeed::RightFlank => CyclerefInfeed::RightFlank as u32,
                Infeed::RightCentre => CyclerefInfeed::RightCentre as u32,
                Infeed::LeftRight => CyclerefInfeed::LeftRight as u32,
                Infeed::Centre => CyclerefInfeed::Centre as u32,
                Infeed::LeftFlank => CyclerefInfeed::LeftFlank as u32,
                Infeed::Alternating => CyclerefInfeed::Alternating as u32,
            },
            depth_mode: match c.depth_mode {
                DepthMode::Decreasing => CyclerefDepthMode::Decreasing as u32,
                DepthMode::Equal => CyclerefDepthMode::Equal as u32,
            },
            starts: c.starts,
            lead_word: match c.lead.word {
                LeadWord::F => CyclerefLeadWord::F as u32,
                LeadWord::I => CyclerefLeadWord::I as u32,
                LeadWord::K => CyclerefLeadWord::K as u32,
            },
            lead_scale: c.lead.scale,
            pass_limit: c.pass_limit,
            inch: u8::from(c.units.unit == InputUnit::Inch),
            radius: u8::from(c.x_mode == XMode::Radius),
            ..CyclerefG76Params::default()
        };
        match c.run_out {
            RunOut::None => p.run_out_kind = CyclerefRunOutKind::None as u32,
            RunOut::Amounts { short, long } => {
                p.run_out_kind = CyclerefRunOutKind::Amounts as u32;
                p.run_out_short = short;
                p.run_out_long = long;
            }
            RunOut::Chamfer { tenths_of_lead, angle_degrees, long } => {
                p.run_out_kind = CyclerefRunOutKind::Chamfer as u32;
                p.run_out_tenths = tenths_of_lead;
                p.run_out_angle = angle_degrees;
                if let Some(k) = long {
                    p.run_out_has_long = 1;
                    p.run_out_long = k;
                }
            }
        }
        p
    }

    /// The cycle these parameters describe.
    ///
    /// # Errors
    ///
    /// A [`FieldError`] naming the field whose enum value is out of range.
    pub fn cycle(&self) -> Result<G76Cycle, FieldError> {
        let bad = |field, value, expected| FieldError { field, value, expected };
        let infeed = match self.infeed {
            0 => Infeed::RightFlank,
            1 => Infeed::RightCentre,
            2 => Infeed::LeftRight,
            3 => Infeed::Centre,
            4 => Infeed::LeftFlank,
            5 => Infeed::Alternating,
            v => return Err(bad("infeed", v, "CyclerefInfeed")),
        };
        let depth_mode = match self.depth_mode {
            0 => DepthMode::Decreasing,
            1 => DepthMode::Equal,
            v => return Err(bad("depth_mode", v, "CyclerefDepthMode")),
        };
        let units = units_of(self.increment, self.inch)?;
        let lead = lead_of(self.lead_word, self.lead_mantissa, self.lead_scale)?;
        let run_out = run_out_of(RunOutFields {
            kind: self.run_out_kind,
            short: self.run_out_short,
            long: self.run_out_long,
            tenths: self.run_out_tenths,
            angle: self.run_out_angle,
            has_long: self.run_out_has_long,
        })?;
        Ok(G76Cycle {
            units,
            x_mode: if self.radius != 0 { XMode::Radius } else { XMode::Diameter },
            start: Point::new(self.start_x, self.start_z),
            end: Point::new(self.end_x, self.end_z),
            taper: self.taper,
            thread_height: self.thread_height,
            first_depth: self.first_depth,
            min_cut: self.min_cut,
            finishing_allowance: self.finishing_allowance,
            finishing_passes: self.finishing_passes,
            tool_angle: self.tool_angle,
            infeed,
            depth_mode,
            lead_in: self.lead_in,
            starts: self.starts,
            lead,
            run_out,
            pass_limit: if self.pass_limit == 0 { DEFAULT_PASS_LIMIT } else { self.pass_limit },
            // R-END `parallel` and R-NOROUGH `one-at-zero`: the defaults on
            // every profile.
            readings: cycleref::CycleReadings {
                pass_end: cycleref::readings::PassEnd::Parallel,
                one_rough_at_zero: true,
                ..cycleref::CycleReadings::DEFAULT
            },
        })
    }
}

/// An input struct's enum field holding a value that is none of its enum's
/// (refused with [`CyclerefStatus::InvalidArgument`]): the field, its
/// value and the enum it must be one of. `Display` is the message the
/// `CyclerefError` carries: `infeed = 9 is not a CyclerefInfeed`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FieldError {
    /// The field (`infeed`, `lead_word`, `run_out_kind`, ...).
    pub field: &'static str,
    /// The value it holds.
    pub value: u32,
    /// The enum its value must be one of (`CyclerefInfeed`).
    pub expected: &'static str,
}

impl FieldError {
    /// The stable kind: `argument:not_an_enum_value`.
    #[must_use]
    pub fn stable_kind(&self) -> &'static str {
        "argument:not_an_enum_value"
    }
}

impl core::fmt::Display for FieldError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{} = {} is not a {}", self.field, self.value, self.expected)
    }
}

impl std::error::Error for FieldError {}

/// The run-out fields of a parameters struct (G76's and G92's).
struct RunOutFields {
    kind: u32,
    short: i64,
    long: i64,
    tenths: u32,
    angle: u32,
    has_long: u8,
}

/// The run-out the fields describe, or an error naming the kind out of range.
fn run_out_of(f: RunOutFields) -> Result<RunOut, FieldError> {
    Ok(match f.kind {
        0 => RunOut::None,
        1 => RunOut::Amounts { short: f.short, long: f.long },
        2 => RunOut::Chamfer {
            tenths_of_lead: f.tenths,
            angle_degrees: f.angle,
            long: (f.has_long != 0).then_some(f.long),
        },
        value => return Err(FieldError { field: "run_out_kind", value, expected: "CyclerefRunOutKind" }),
    })
}

/// The units of an increment field and an inch flag.
fn units_of(increment_field: u32, inch: u8) -> Result<Units, FieldError> {
    let system = increment(increment_field).ok_or(FieldError {
        field: "increment",
        value: increment_field,
        expected: "CyclerefIncrement",
    })?;
    Ok(Units {
        system: system.unwrap_or(IncrementSystem::IsB),
        unit: if inch != 0 { InputUnit::Inch } else { InputUnit::Metric },
    })
}

/// The lead of a lead word field, mantissa and scale.
fn lead_of(word: u32, mantissa: u64, scale: u32) -> Result<Lead, FieldError> {
    let word = match word {
        0 => LeadWord::F,
        1 => LeadWord::I,
        2 => LeadWord::K,
        value => return Err(FieldError { field: "lead_word", value, expected: "CyclerefLeadWord" }),
    };
    Ok(Lead { word, mantissa, scale })
}

/// The parameters of one G92 block (`cycleref_g92_new`), in least
/// increments of the units given, X in X-word units (diameter increments
/// unless `radius` is non-zero), as the reader resolves them: the modal
/// words and the profile's run-out rules that `cycleref_expand` applies
/// are not applied here.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct CyclerefG92Params {
    /// X of the start point A (X-word units).
    pub start_x: i64,
    /// Z of the start point A.
    pub start_z: i64,
    /// X(U): X of the cut end C (X-word units).
    pub end_x: i64,
    /// Z(W): Z of the cut end C.
    pub end_z: i64,
    /// R: the cut start B's short-axis coordinate minus C's (radius,
    /// signed; along Z for a face thread).
    pub taper: i64,
    /// Digits of the lead without the decimal point.
    pub lead_mantissa: u64,
    /// J of a `CYCLEREF_RUN_OUT_KIND_AMOUNTS` run-out (unsigned).
    pub run_out_short: i64,
    /// K of an `AMOUNTS` run-out, or of a `CHAMFER` run-out when
    /// `run_out_has_long` is non-zero.
    pub run_out_long: i64,
    /// A `CyclerefIncrement` (`CYCLEREF_INCREMENT_DEFAULT` is IS-B).
    pub increment: u32,
    /// L: number of starts (1..=999).
    pub starts: u32,
    /// A `CyclerefLeadWord`.
    pub lead_word: u32,
    /// Decimals of the lead (`F3` is 0).
    pub lead_scale: u32,
    /// A `CyclerefRunOutKind`.
    pub run_out_kind: u32,
    /// r of a `CHAMFER` run-out: tenths of the lead (0..=99).
    pub run_out_tenths: u32,
    /// Chamfer angle of a `CHAMFER` run-out in degrees (1..=89).
    pub run_out_angle: u32,
    /// Q: the first start's spindle angle, `start_angle_num /
    /// start_angle_den` thousandths of a degree (a denominator of 0 is 1).
    pub start_angle_num: u32,
    /// See `start_angle_num`.
    pub start_angle_den: u32,
    /// Non-zero: inch units.
    pub inch: u8,
    /// Non-zero: X words are radii.
    pub radius: u8,
    /// Non-zero: a `CHAMFER` run-out has the K of `run_out_long`.
    pub run_out_has_long: u8,
    /// Non-zero: a face thread (988TA P1).
    pub face: u8,
}

impl CyclerefG92Params {
    /// The block these parameters describe.
    ///
    /// # Errors
    ///
    /// A [`FieldError`] naming the field whose enum value is out of range.
    pub fn cycle(&self) -> Result<G92Cycle, FieldError> {
        let den = if self.start_angle_den == 0 { 1 } else { self.start_angle_den };
        Ok(G92Cycle {
            units: units_of(self.increment, self.inch)?,
            x_mode: if self.radius != 0 { XMode::Radius } else { XMode::Diameter },
            start: Point::new(self.start_x, self.start_z),
            end: Point::new(self.end_x, self.end_z),
            taper: self.taper,
            lead: lead_of(self.lead_word, self.lead_mantissa, self.lead_scale)?,
            run_out: run_out_of(RunOutFields {
                kind: self.run_out_kind,
                short: self.run_out_short,
                long: self.run_out_long,
                tenths: self.run_out_tenths,
                angle: self.run_out_angle,
                has_long: self.run_out_has_long,
            })?,
            starts: self.starts,
            start_angle: StartAngle::ZERO.plus(StartAngle { num: self.start_angle_num, den }),
            face: self.face != 0,
            readings: cycleref::CycleReadings::DEFAULT,
        })
    }
}

/// A `CyclerefIncrement` value: `Some(None)` for the default, `None` when
/// out of range.
pub(crate) fn increment(v: u32) -> Option<Option<IncrementSystem>> {
    match v {
        0 => Some(None),
        1 => Some(Some(IncrementSystem::IsB)),
        2 => Some(Some(IncrementSystem::IsC)),
        _ => None,
    }
}

/// An error: the status, the line it refers to and a message.
///
/// Functions that take a `CyclerefError *` fill it when they fail (and
/// clear it, status OK, line 0, empty message, when they succeed); it may
/// be NULL when the caller does not want the details.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct CyclerefError {
    /// The status the function returned.
    pub status: CyclerefStatus,
    /// 1-based source line of the offending block, or 0 when the error is
    /// not about a line of the program.
    pub line: usize,
    /// The message in UTF-8, NUL-terminated, truncated to at most
    /// `CYCLEREF_ERROR_MESSAGE_LEN - 1` bytes at a character boundary.
    pub message: [c_char; CYCLEREF_ERROR_MESSAGE_LEN],
}

impl Default for CyclerefError {
    fn default() -> Self {
        CyclerefError { status: CyclerefStatus::Ok, line: 0, message: [0; CYCLEREF_ERROR_MESSAGE_LEN] }
    }
}

impl CyclerefError {
    /// An error with `message` truncated to fit.
    #[must_use]
    pub fn new(status: CyclerefStatus, line: usize, message: &str) -> CyclerefError {
        let mut e = CyclerefError { status, line, ..CyclerefError::default() };
        let text = truncate(message, CYCLEREF_ERROR_MESSAGE_LEN - 1);
        for (dst, &b) in e.message.iter_mut().zip(text.as_bytes()) {
            // The same byte: `c_char` is `i8` on some targets, `u8` on others.
            *dst = c_char::from_ne_bytes([b]);
        }
        e
    }

    /// The message up to its NUL, lossily decoded.
    #[must_use]
    pub fn message(&self) -> String {
        let bytes: Vec<u8> =
            self.message.iter().take_while(|&&c| c != 0).map(|&c| c.to_ne_bytes()[0]).collect();
        String::from_utf8_lossy(&bytes).into_owned()
    }
}

/// The longest prefix of `s` of at most `max` bytes that ends on a
/// character boundary.
#[must_use]
pub(crate) fn truncate(s: &str, max: usize) -> &str {
    if s.len() <= max {
        return s;
    }
    let mut end = max;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    s.get(..end).unwrap_or("")
}
