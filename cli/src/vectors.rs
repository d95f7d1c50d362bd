//! `cycleref vectors`: a corpus of conformance vectors.
//!
//! Each case is a program, the machine it runs on (profile, increment
//! system, unit, X mode, calculator-type input, pass limit and every
//! parameter) and what the manual says must happen: the moves of every
//! cycle, exactly as `cycleref expand --format json` prints them, or the
//! alarm (line, stable kind name, message). The schema, the tags and the
//! way a vendor uses the files are documented in `vectors/README.md`.
//!
//! The corpus is deterministic: case `i` is drawn from a pseudo-random
//! stream that depends only on `(seed, i)` (splitmix64, no floating point,
//! no hash maps), so the same count and seed give the same bytes and a
//! larger count extends a smaller one. The template of case `i` depends on
//! `i` alone: 3 slots in 5 are valid programs, 2 in 5 programs that must be
//! refused, and the first 90 cases (the checked-in corpus) use every
//! template at least once.
//!
//! Expected results come from the program reader and the fixed-point
//! engine; every cycle is also expanded by the exact reference model and a
//! case where the two differ is not written: the run fails naming the case.
//! The generator is a differential check as well as a corpus writer.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

use cycleref::g75::RIGHT_ANGLE;
use cycleref::units::write_fixed;
use cycleref::{
    CornerKind, CycleError, G32RunOut, IncrementSystem, Infeed, InputUnit, LeadWord, Motion, Move, PassKind,
    PathType, Role, RunOut, Units, XMode,
};
use cycleref_spec::profile::{ParamValue, Profile};
use cycleref_spec::reader::{G32Call, G75Call, G76Call};
use cycleref_spec::{read, ErrorKind, Machine, ProfileName, ProgramError};
use serde_json::{json, Map, Value};

use crate::json::{CycleJson, UnitsJson};
use cycleref_spec::pipeline::{expand, Cycle, Engine};

/// Schema of a case file.
const CASE_SCHEMA: &str = "cycleref-vector/1";
/// Schema of `index.json`.
const INDEX_SCHEMA: &str = "cycleref-vectors-index/1";
/// Largest number of moves a valid case may expect (keeps the corpus small).
const MAX_MOVES: usize = 60;
/// Drafts tried per case before the generator gives up.
const ATTEMPTS: u32 = 400;

/// Writes `count` cases generated from `seed` into `out`, with `index.json`.
/// Case files of an earlier run that are not part of this corpus
/// (`case-NNNN.json` beyond `count`) are removed.
///
/// # Errors
///
/// A message naming the case when the engine and the reference model
/// disagree on it, when no draft of its template fits, or when a file
/// cannot be written.
pub fn run(count: u32, seed: u64, out: &Path) -> Result<String, String> {
    if out.exists() && !out.is_dir() {
        return Err(format!(
            "--out {}: exists and is not a directory (vectors writes a directory of JSON files)",
            out.display()
        ));
    }
    std::fs::create_dir_all(out)
        .map_err(|e| format!("--out {}: cannot create the directory: {e}", out.display()))?;
    let mut entries = Vec::new();
    let mut tag_counts: BTreeMap<String, u32> = BTreeMap::new();
    let mut files = BTreeSet::new();
    let (mut valid, mut refused) = (0_u32, 0_u32);
    for index in 1..=count {
        let case = make_case(seed, index)?;
        let file = format!("{}.json", case.id);
        std::fs::write(out.join(&file), to_text(&case.json))
            .map_err(|e| format!("{}: cannot write: {e}", out.join(&file).display()))?;
        for t in &case.tags {
            *tag_counts.entry(t.clone()).or_default() += 1;
        }
        if case.kind.is_some() {
            refused += 1;
        } else {
            valid += 1;
        }
        entries.push(json!({
            "id": case.id,
            "file": file,
            "description": case.description,
            "expect": if case.kind.is_some() { "error" } else { "moves" },
            "kind": case.kind,
            "tags": case.tags,
        }));
        files.insert(file);
    }
    remove_stale(out, &files)?;
    let index = json!({
        "schema": INDEX_SCHEMA,
        "seed": seed,
        "count": count,
        "tags": tag_counts,
        "cases": entries,
    });
    std::fs::write(out.join("index.json"), to_text(&index))
        .map_err(|e| format!("{}: cannot write: {e}", out.join("index.json").display()))?;
    Ok(format!(
        "wrote {count} cases ({valid} with moves, {refused} refused) and index.json to {}\n",
        out.display()
    ))
}

/// Removes `case-NNNN.json` files of an earlier, larger run.
fn remove_stale(out: &Path, keep: &BTreeSet<String>) -> Result<(), String> {
    let dir = std::fs::read_dir(out).map_err(|e| format!("{}: {e}", out.display()))?;
    for entry in dir.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let is_case = name
            .strip_prefix("case-")
            .and_then(|n| n.strip_suffix(".json"))
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
        if is_case && !keep.contains(&name) {
            std::fs::remove_file(entry.path()).map_err(|e| format!("{}: {e}", entry.path().display()))?;
        }
    }
    Ok(())
}

// ---- stable names of the error kinds ----

/// The stable name of what is wrong with a program, as written in the
/// `expect.error.kind` field: [`ErrorKind::name`], and for a cycle alarm
/// `cycle:` and [`CycleError::name`].
pub fn kind_name(kind: &ErrorKind) -> String {
    match kind {
        ErrorKind::Cycle(e) => format!("cycle:{}", e.name()),
        k => k.name().to_string(),
    }
}

// ---- the pseudo-random stream ----

/// splitmix64's output function.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// splitmix64: tiny, deterministic on every platform.
struct Rng(u64);

impl Rng {
    /// The stream of case `index` under `seed`: it depends on nothing else.
    fn for_case(seed: u64, index: u32) -> Rng {
        Rng(mix(seed ^ 0x6379_636c_6572_6566) ^ mix(u64::from(index).wrapping_mul(0xd1b5_4a32_d192_ed03)))
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        mix(self.0)
    }

    /// A value in `lo..=hi`.
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        let span = (hi - lo).unsigned_abs() + 1;
        lo + i64::try_from(self.next() % span).unwrap_or(0)
    }

    /// True with probability `percent` / 100.
    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }

    /// An index below `n` (`n` > 0).
    fn index(&mut self, n: usize) -> usize {
        let n = u64::try_from(n).unwrap_or(1).max(1);
        usize::try_from(self.next() % n).unwrap_or(0)
    }

    /// One of `items`.
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.index(items.len())]
    }

    fn sign(&mut self) -> i64 {
        if self.chance(50) {
            1
        } else {
            -1
        }
    }
}

// ---- the machine and the way words are written ----

/// A parameter override: an integer, or a length in increments of the
/// program's units (written as a decimal string).
#[derive(Clone, Copy)]
enum Param {
    Int(i64),
    Len(i64),
}

/// Everything about the machine, and the style the program is written in.
#[derive(Clone)]
struct Ctx {
    profile: ProfileName,
    increment: IncrementSystem,
    /// The unit of the program's values (the machine's, or G20).
    unit: InputUnit,
    /// Inch is selected by G20 in the program on a metric machine.
    g20: bool,
    x: XMode,
    calculator_input: bool,
    /// FANUC: lengths written without a decimal point, in increments.
    bare: bool,
    pass_limit: u32,
    params: BTreeMap<&'static str, Param>,
}

impl Ctx {
    fn new(profile: ProfileName, rng: &mut Rng) -> Ctx {
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
        Ctx {
            profile,
            increment,
            unit: if inch { InputUnit::Inch } else { InputUnit::Metric },
            g20,
            x,
            calculator_input,
            bare,
            pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
            params,
        }
    }

    fn units(&self) -> Units {
        Units { system: self.increment, unit: self.unit }
    }

    fn decimals(&self) -> u32 {
        self.units().decimals()
    }

    fn xf(&self) -> i64 {
        self.x.factor()
    }

    fn profile_data(&self) -> Profile {
        Profile::get(self.profile)
    }

    /// `microns` of a millimetre (a 25th of that in inch), in increments.
    fn mm(&self, microns: i64) -> i64 {
        let per = self.units().per_unit();
        match self.unit {
            InputUnit::Metric => microns * per / 1000,
            InputUnit::Inch => microns * per / 25_400,
        }
    }

    /// The value of a length word (X, Z, U, W, R, E, J, K).
    fn num(&self, v: i64) -> String {
        if self.bare {
            return v.to_string();
        }
        let needs_point = self.profile == ProfileName::Fanuc && !self.calculator_input;
        decimal(v, self.decimals(), needs_point)
    }

    /// The state bit of the P/Q unit (182.7 or 3401#6).
    fn pq_bit(&self) -> i64 {
        let key = match self.profile {
            ProfileName::Fanuc => return 0,
            ProfileName::Gsk980 => "182.7",
            ProfileName::Gsk988 => "3401.6",
        };
        match self.params.get(key) {
            Some(Param::Int(v)) => *v,
            _ => 0,
        }
    }

    fn pq_in_increments(&self) -> bool {
        match self.profile {
            ProfileName::Fanuc => true,
            ProfileName::Gsk980 => self.pq_bit() == 0,
            ProfileName::Gsk988 => self.pq_bit() == 1,
        }
    }

    /// The value of P(k), Q(Δd) or Q(Δdmin).
    fn pq(&self, v: i64) -> String {
        if self.pq_in_increments() {
            v.to_string()
        } else {
            decimal(v, self.decimals(), false)
        }
    }

    /// A lead word (`F1.5`, `I16`) and the lead in increments (rounded down).
    fn lead(&self, rng: &mut Rng, word: Option<LeadWord>) -> (String, i64) {
        let word = word.unwrap_or(if rng.chance(20) { LeadWord::I } else { LeadWord::F });
        let text = match (word, self.unit) {
            (LeadWord::F, InputUnit::Metric) => {
                rng.pick(&["1", "1.25", "1.5", "1.75", "2", "2.5", "3", "4", "6"])
            }
            (LeadWord::F, InputUnit::Inch) => rng.pick(&["0.04", "0.05", "0.0625", "0.08", "0.1", "0.125"]),
            (LeadWord::I, _) => rng.pick(&["8", "10", "11.5", "12", "14", "16", "20"]),
        };
        let (int, frac) = text.split_once('.').unwrap_or((text, ""));
        let mantissa: i64 = format!("{int}{frac}").parse().unwrap_or(1);
        let scale = 10_i64.pow(u32::try_from(frac.len()).unwrap_or(0));
        let per = self.units().per_unit();
        let inc = match (word, self.unit) {
            (LeadWord::F, _) => mantissa * per / scale,
            (LeadWord::I, InputUnit::Metric) => 254 * per * scale / (10 * mantissa),
            (LeadWord::I, InputUnit::Inch) => per * scale / mantissa,
        };
        let point = if self.profile == ProfileName::Fanuc && frac.is_empty() { ".0" } else { "" };
        let letter = if word == LeadWord::F { 'F' } else { 'I' };
        (format!("{letter}{text}{point}"), inc)
    }

    /// The Q of G32 for `millidegrees`, in the profile's unit.
    fn q(&self, millidegrees: i64) -> String {
        let degrees = match self.profile {
            ProfileName::Fanuc => false,
            ProfileName::Gsk980 => self.pq_bit() == 1,
            ProfileName::Gsk988 => true,
        };
        if degrees {
            decimal(millidegrees, 3, false)
        } else {
            millidegrees.to_string()
        }
    }

    fn param_name(&self, which: fn(&Profile) -> &'static str) -> &'static str {
        which(&self.profile_data())
    }

    /// The machine settings as a parameter file and as a JSON object.
    fn settings(&self) -> (String, Value) {
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
        let mut params = Map::new();
        for (key, default) in self.profile_data().default_params() {
            let value = match (self.params.get(key.as_str()).copied(), default) {
                (Some(Param::Int(v)), _) | (None, ParamValue::Int(v)) => json!(v),
                (Some(Param::Len(v)), _) => json!(decimal(v, self.decimals(), false)),
                (None, ParamValue::Length(d)) => json!(d.to_string()),
            };
            let _ = writeln!(toml, "\"{key}\" = {value}");
            params.insert(key, value);
        }
        let machine = json!({
            "increment": increment,
            "unit": unit,
            "x": x,
            "calculator_input": self.calculator_input,
            "pass_limit": self.pass_limit,
            "parameters": params,
        });
        (toml, machine)
    }
}

/// `v` increments with `decimals` decimals, trailing zeros dropped; a
/// whole value keeps `.0` when `point` is asked for (FANUC: a bare value
/// would be increments).
fn decimal(v: i64, decimals: u32, point: bool) -> String {
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

// ---- drafts ----

/// What a draft must turn out to be.
enum Intent {
    /// A valid program whose computed tags include these.
    Valid(&'static [&'static str]),
    /// A program refused with this kind.
    Refused(&'static str),
}

/// One case before it is checked.
struct Draft {
    ctx: Ctx,
    lines: Vec<String>,
    description: String,
    tags: Vec<String>,
    intent: Intent,
}

impl Draft {
    fn valid(ctx: Ctx, lines: Vec<String>, description: String, tags: &[&str]) -> Draft {
        Draft { ctx, lines, description, tags: owned(tags), intent: Intent::Valid(&[]) }
    }

    fn refused(
        ctx: Ctx,
        lines: Vec<String>,
        description: String,
        tags: &[&str],
        kind: &'static str,
    ) -> Draft {
        Draft { ctx, lines, description, tags: owned(tags), intent: Intent::Refused(kind) }
    }

    fn requiring(mut self, tags: &'static [&'static str]) -> Draft {
        self.intent = Intent::Valid(tags);
        self
    }
}

fn owned(tags: &[&str]) -> Vec<String> {
    tags.iter().map(|t| (*t).to_string()).collect()
}

/// One G76 thread: geometry and schedule, in increments.
#[derive(Clone)]
struct Thread {
    a: (i64, i64),
    d: (i64, i64),
    taper: i64,
    k: i64,
    dd: i64,
    dmin: i64,
    allowance: i64,
    lead: String,
    w: i64,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Taper {
    Straight,
    ZLong,
    XLong,
    Any,
}

/// A random thread, external or internal, cut towards -Z or +Z; `rough`
/// is the range of the rough pass count the first depth aims at.
fn thread(rng: &mut Rng, ctx: &Ctx, taper: Taper, rough: (i64, i64)) -> Thread {
    let xf = ctx.xf();
    let side = rng.sign();
    let dir = if rng.chance(70) { -1 } else { 1 };
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = (lead_inc * rng.range(55, 64) / 100).max(1);
    let allowance = if rng.chance(35) { 0 } else { k * rng.range(2, 8) / 100 };
    let n = rng.range(rough.0, rough.1).max(1);
    let root =
        i64::try_from(cycleref::engine::round_sqrt(u128::try_from(n * 10_000).unwrap_or(1))).unwrap_or(100);
    let dd = ((k - allowance) * 100 / root).max(1);
    let dmin = if rng.chance(40) { 0 } else { (dd * rng.range(5, 20) / 100).min(k) };
    let taper = match taper {
        Taper::Any => rng.pick(&[Taper::Straight, Taper::Straight, Taper::ZLong, Taper::XLong]),
        t => t,
    };
    let (w, i) = match taper {
        Taper::Straight | Taper::Any => (ctx.mm(rng.range(12_000, 40_000)), 0),
        Taper::ZLong => (ctx.mm(rng.range(15_000, 40_000)), rng.sign() * ctx.mm(rng.range(300, 3000))),
        Taper::XLong => {
            let w = ctx.mm(rng.range(4000, 9000));
            let extra = if rng.chance(15) { 0 } else { ctx.mm(rng.range(0, 6000)) };
            (w, rng.sign() * (w + extra))
        }
    };
    let clear = ctx.mm(rng.range(500, 3000));
    let min_root = if side > 0 { i.abs() + ctx.mm(4000) } else { k + i.abs() + clear + ctx.mm(4000) };
    let root = if side > 0 { ctx.mm(rng.range(8000, 35_000)) } else { ctx.mm(rng.range(15_000, 40_000)) };
    let root = root.max(min_root);
    let xd = xf * root;
    let xc = xd + xf * i;
    let xb = xc + side * xf * k;
    let crest_end = xd + side * xf * k;
    let xa = if side > 0 { xb.max(crest_end) + xf * clear } else { xb.min(crest_end) - xf * clear };
    let za = if dir < 0 { ctx.mm(rng.range(1000, 10_000)) } else { -(w + ctx.mm(rng.range(5000, 20_000))) };
    Thread { a: (xa, za), d: (xd, za + dir * w), taper: i, k, dd, dmin, allowance, lead, w }
}

fn tool_angle(rng: &mut Rng) -> i64 {
    rng.pick(&[0, 29, 30, 55, 60, 60, 60, 80])
}

/// P(m)(r)(a) as six digits.
fn pmra(m: i64, r: i64, a: i64) -> String {
    format!("{m:02}{r:02}{a:02}")
}

/// A usual P(m)(r)(a): m 1..2 (0..2 on the 980TDi), r 0..10, a.
fn random_pmra(rng: &mut Rng, ctx: &Ctx) -> String {
    let m = if ctx.profile == ProfileName::Gsk980 && rng.chance(15) { 0 } else { rng.range(1, 2) };
    let r = if rng.chance(40) { 0 } else { rng.range(1, 10) };
    pmra(m, r, tool_angle(rng))
}

/// How a G76 is written.
#[derive(Clone)]
struct G76 {
    block1: bool,
    p: Option<String>,
    extra1: Vec<String>,
    extra2: Vec<String>,
    /// Block 2 words left out: any of `P`, `Q`, `F`, `R`.
    omit: &'static str,
    incremental: bool,
    show_r: bool,
}

impl G76 {
    fn usual(rng: &mut Rng, ctx: &Ctx) -> G76 {
        G76 {
            block1: true,
            p: Some(random_pmra(rng, ctx)),
            extra1: Vec::new(),
            extra2: Vec::new(),
            omit: "",
            incremental: rng.chance(20),
            show_r: rng.chance(30),
        }
    }
}

/// The one or two blocks of a G76.
fn g76_lines(ctx: &Ctx, t: &Thread, g: &G76) -> Vec<String> {
    let mut out = Vec::new();
    if g.block1 {
        let mut s = String::from("G76");
        if let Some(p) = &g.p {
            let _ = write!(s, " P{p}");
        }
        let _ = write!(s, " Q{} R{}", ctx.pq(t.dmin), ctx.num(t.allowance));
        for w in &g.extra1 {
            let _ = write!(s, " {w}");
        }
        out.push(s);
    }
    let mut s = String::from("G76");
    if g.incremental {
        let _ = write!(s, " U{} W{}", ctx.num(t.d.0 - t.a.0), ctx.num(t.d.1 - t.a.1));
    } else {
        let _ = write!(s, " X{} Z{}", ctx.num(t.d.0), ctx.num(t.d.1));
    }
    if (g.show_r || t.taper != 0) && !g.omit.contains('R') {
        let _ = write!(s, " R{}", ctx.num(t.taper));
    }
    if !g.omit.contains('P') {
        let _ = write!(s, " P{}", ctx.pq(t.k));
    }
    if !g.omit.contains('Q') {
        let _ = write!(s, " Q{}", ctx.pq(t.dd));
    }
    if !g.omit.contains('F') {
        let _ = write!(s, " {}", t.lead);
    }
    for w in &g.extra2 {
        let _ = write!(s, " {w}");
    }
    out.push(s);
    out
}

/// Spindle start and positioning at `a`.
fn head(rng: &mut Rng, ctx: &Ctx, a: (i64, i64)) -> Vec<String> {
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

fn any_profile(rng: &mut Rng) -> ProfileName {
    rng.pick(&[ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988])
}

fn gsk(rng: &mut Rng) -> ProfileName {
    rng.pick(&[ProfileName::Gsk980, ProfileName::Gsk988])
}

/// Random run-out words J/K for the profile (none on FANUC): for the
/// 980TDi in block 1, for the 988TA in block 2.
fn random_jk(rng: &mut Rng, ctx: &Ctx, g: &mut G76) {
    let j = ctx.mm(rng.range(300, 2000));
    let k = ctx.mm(rng.range(500, 3000));
    let words = match rng.range(0, 3) {
        0 => vec![],
        1 => vec![format!("J{}", ctx.num(j))],
        _ => vec![format!("J{}", ctx.num(j)), format!("K{}", ctx.num(k))],
    };
    match ctx.profile {
        ProfileName::Fanuc => {}
        ProfileName::Gsk980 => g.extra1.extend(words),
        ProfileName::Gsk988 => g.extra2.extend(words),
    }
}

/// The lines of a one-G76 program.
fn g76_program(rng: &mut Rng, ctx: &Ctx, t: &Thread, g: &G76) -> Vec<String> {
    let mut lines = head(rng, ctx, t.a);
    lines.extend(g76_lines(ctx, t, g));
    lines.push("M30".into());
    lines
}

fn side_text(side: i64) -> &'static str {
    if side > 0 {
        "external"
    } else {
        "internal"
    }
}

// ---- valid templates ----

fn v_basic(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(ctx, lines, "G76 with the profile's usual words".into(), &["template:g76-basic"])
}

fn v_infeed(rng: &mut Rng, mode: i64) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("D{mode}"));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    let (text, tag) = match mode {
        1 => ("G76 infeed D1: right flank and centre alternately", "template:g76-d1"),
        _ => ("G76 infeed D2: left and right flanks alternately, equal amounts", "template:g76-d2"),
    };
    Draft::valid(ctx, lines, text.into(), &[tag])
}

fn v_d1(rng: &mut Rng) -> Draft {
    v_infeed(rng, 1).requiring(&["infeed:D1"])
}

fn v_d2(rng: &mut Rng) -> Draft {
    v_infeed(rng, 2).requiring(&["infeed:D2"])
}

fn v_lead_in(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let taper = if rng.chance(70) { Taper::Straight } else { Taper::ZLong };
    let t = thread(rng, &ctx, taper, (2, 4));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 3000)))));
    if rng.chance(40) {
        g.extra1.push(format!("D{}", rng.range(0, 2)));
    }
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(
        ctx,
        lines,
        "G76 with a lead-in E (screw-in to each pass start)".into(),
        &["template:g76-lead-in"],
    )
    .requiring(&["lead-in"])
}

fn v_multi_start(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::Any, (1, 2));
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(1, rng.range(0, 5), tool_angle(rng)));
    g.extra1.push(format!("L{}", rng.pick(&[2, 3, 3, 4, 7])));
    if rng.chance(30) && t.taper.abs() < t.w {
        g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 2000)))));
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(
        ctx,
        lines,
        "G76 multi-start thread L (starts 360/L degrees apart)".into(),
        &["template:g76-multi-start"],
    )
    .requiring(&["multi-start"])
}

/// A thread with one rough level and one finishing pass, for programs of
/// several cycles.
fn small_thread(rng: &mut Rng, ctx: &Ctx) -> Thread {
    let mut t = thread(rng, ctx, Taper::Straight, (1, 1));
    t.dd = t.k;
    t
}

fn v_runout_980(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let t = small_thread(rng, &ctx);
    let r = rng.range(2, 9);
    let a = tool_angle(rng);
    let j = ctx.mm(rng.range(300, 2000));
    let k = ctx.mm(rng.range(500, 3000));
    let (jt, kt) = (ctx.num(j), ctx.num(k));
    let mut lines = head(rng, &ctx, t.a);
    // Notes 1 (J, K omitted: chamfer by P(r)), 2 (J omitted, K given: J by
    // P(r)), 3 (K omitted: K = J), 4 (J = 0: none), then J and K.
    let variants: [Vec<String>; 5] = [
        vec![],
        vec![format!("K{kt}")],
        vec![format!("J{jt}")],
        vec!["J0".to_string(), format!("K{kt}")],
        vec![format!("J{jt}"), format!("K{kt}")],
    ];
    for words in &variants {
        let g = G76 {
            block1: true,
            p: Some(pmra(1, r, a)),
            extra1: words.clone(),
            extra2: vec![],
            omit: "",
            incremental: false,
            show_r: false,
        };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "GSK 980TDi G76 run-out notes 1-4: five cycles, J/K one-shot in block 1".into(),
        &[
            "template:g76-runout-gsk980",
            "rule:gsk980-note1",
            "rule:gsk980-note2",
            "rule:gsk980-note3",
            "rule:gsk980-note4",
            "rule:jk-one-shot",
        ],
    )
    .requiring(&["run-out:chamfer", "run-out:chamfer+k", "run-out:amounts", "run-out:none"])
}

fn v_runout_988(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let t = small_thread(rng, &ctx);
    let r = rng.range(2, 9);
    let a = tool_angle(rng);
    let (jt, kt) = (ctx.num(ctx.mm(rng.range(300, 2000))), ctx.num(ctx.mm(rng.range(500, 3000))));
    let mut lines = head(rng, &ctx, t.a);
    let steps: [Vec<String>; 5] = [
        vec![],
        vec![format!("J{jt}")],
        vec![format!("K{kt}")],
        vec!["K0".into()],
        vec!["J0".into(), format!("K{kt}")],
    ];
    for (n, words) in steps.iter().enumerate() {
        let g = G76 {
            block1: n == 0,
            p: Some(pmra(1, r, a)),
            extra1: vec![],
            extra2: words.clone(),
            omit: "",
            incremental: false,
            show_r: false,
        };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "GSK 988TA G76 run-out rules, J/K modal in block 2: never programmed (chamfer), J only \
         (pull-out), K added (J and K), K0 (none), J0 (none)"
            .into(),
        &[
            "template:g76-runout-gsk988",
            "rule:gsk988-chamfer",
            "rule:gsk988-j-only",
            "rule:gsk988-jk-modal",
            "rule:gsk988-k0",
            "rule:gsk988-j0",
            "rule:jk-modal",
            "block1-modal",
        ],
    )
    .requiring(&["run-out:chamfer", "run-out:pull-out", "run-out:amounts", "run-out:none"])
}

fn v_runout_988_k_only(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let t = small_thread(rng, &ctx);
    let (jt, kt) = (ctx.num(ctx.mm(rng.range(300, 2000))), ctx.num(ctx.mm(rng.range(500, 3000))));
    let mut lines = head(rng, &ctx, t.a);
    let p = pmra(1, rng.range(2, 9), tool_angle(rng));
    for (n, words) in
        [vec![format!("K{kt}")], vec![format!("J{jt}"), format!("K{kt}")], vec![]].iter().enumerate()
    {
        let g = G76 {
            block1: n == 0,
            p: Some(p.clone()),
            extra1: vec![],
            extra2: words.clone(),
            omit: "",
            incremental: false,
            show_r: false,
        };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "GSK 988TA G76: K without J (no run-out, although r is set), then J and K, then both modal".into(),
        &["template:g76-runout-gsk988-k", "rule:gsk988-k-only", "rule:gsk988-jk", "rule:jk-modal"],
    )
    .requiring(&["run-out:none", "run-out:amounts"])
}

fn v_chamfer(rng: &mut Rng) -> Draft {
    let profile = rng.pick(&[ProfileName::Fanuc, ProfileName::Gsk988]);
    let mut ctx = Ctx::new(profile, rng);
    ctx.params.insert("5131", Param::Int(rng.pick(&[30, 60, 20])));
    let t = thread(rng, &ctx, Taper::Any, (1, 2));
    // Cycle 1: r from parameter 5130 (no block 1, Δdmin and d from 5140
    // and 5141); cycle 2: r from P(m)(r)(a) of a block 1.
    ctx.params.insert("5130", Param::Int(rng.range(3, 15)));
    ctx.params.insert("5140", Param::Len(t.dmin));
    ctx.params.insert("5141", Param::Len(t.allowance));
    let mut g = G76::usual(rng, &ctx);
    g.block1 = false;
    let mut lines = head(rng, &ctx, t.a);
    lines.extend(g76_lines(&ctx, &t, &g));
    g.block1 = true;
    g.p = Some(pmra(rng.range(1, 2), rng.range(3, 15), tool_angle(rng)));
    lines.extend(g76_lines(&ctx, &t, &g));
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "G76 run-out by the chamfer at the angle of parameter 5131: r from parameter 5130, then from \
         P(m)(r)(a)"
            .into(),
        &["template:g76-chamfer", "params:block1", "params:chamfer-5130"],
    )
    .requiring(&["run-out:chamfer", "run-out:chamfer-angle"])
}

fn v_x_long(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::XLong, (2, 4));
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(rng.range(1, 2), rng.range(0, 3), rng.pick(&[0, 29, 30, 55, 60])));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(ctx, lines, "G76 steep taper, X the long axis (|i| >= |W|)".into(), &["template:g76-x-long"])
        .requiring(&["taper:x-long"])
}

fn v_taper(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let t = thread(rng, &ctx, Taper::ZLong, (2, 5));
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(ctx, lines, "G76 taper thread R(i), Z the long axis".into(), &["template:g76-taper"])
        .requiring(&["taper:z-long"])
}

fn v_one_pass(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 1));
    t.dd = t.k - t.allowance + if rng.chance(40) { 0 } else { rng.range(1, t.k) };
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(
        ctx,
        lines,
        "G76 one-pass schedule: Q(Δd) >= k - d gives a single rough level".into(),
        &["template:g76-one-pass"],
    )
    .requiring(&["schedule:one-pass"])
}

fn v_min_cut(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 1));
    // k - d about 3 Δd and Δdmin about 0.35 Δd: the law's steps fall below
    // Δdmin from the third level on.
    let q = ((t.k - t.allowance) * 10 / rng.range(25, 35)).max(1);
    t.dd = q;
    t.dmin = (q * rng.range(30, 45) / 100).max(1);
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(
        ctx,
        lines,
        "G76 Q(Δdmin) clamping: later rough cuts are Δdmin deep".into(),
        &["template:g76-min-cut"],
    )
    .requiring(&["schedule:min-cut"])
}

fn v_exact(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (2, 4));
    // k - d = round(Δd √n) exactly.
    let n = rng.range(2, 5);
    let q = t.dd;
    let level =
        i64::try_from(cycleref::engine::round_sqrt(u128::try_from(q * q * n).unwrap_or(0))).unwrap_or(q);
    t.k = level + t.allowance;
    t.dmin = 0;
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(ctx, lines, "G76 whose depth law lands exactly on k - d".into(), &["template:g76-exact-k-d"])
        .requiring(&["schedule:exact-k-d"])
}

fn v_d_equals_k(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (1, 2));
    t.allowance = t.k;
    t.dmin = t.dmin.min(t.k);
    let mut g = G76::usual(rng, &ctx);
    g.p = Some(pmra(rng.range(1, 3), rng.range(0, 5), tool_angle(rng)));
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(
        ctx,
        lines,
        "G76 with R(d) = P(k): no rough pass, finishing passes only".into(),
        &["template:g76-d-equals-k"],
    )
    .requiring(&["schedule:d-equals-k"])
}

fn v_i_lead(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let mut t = thread(rng, &ctx, Taper::Any, (2, 4));
    t.lead = ctx.lead(rng, Some(LeadWord::I)).0;
    let mut g = G76::usual(rng, &ctx);
    random_jk(rng, &ctx, &mut g);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::valid(ctx, lines, "G76 with the lead in threads per inch (I)".into(), &["template:g76-i-lead"])
        .requiring(&["lead:I"])
}

/// Cycle 1 from the parameters (no block 1), cycle 2 with a block 1,
/// cycle 3 with the modal values of that block 1 and the modal lead.
fn v_params_modal(rng: &mut Rng) -> Draft {
    let mut ctx = Ctx::new(any_profile(rng), rng);
    let t = small_thread(rng, &ctx);
    let p = ctx.profile_data();
    let names = &p.params;
    ctx.params.insert(names.finishing_passes, Param::Int(rng.range(1, 2)));
    ctx.params.insert(names.tool_angle, Param::Int(tool_angle(rng)));
    ctx.params.insert(names.chamfer, Param::Int(rng.range(0, 8)));
    ctx.params.insert(names.min_cut, Param::Len(t.dmin));
    ctx.params.insert(names.finishing_allowance, Param::Len(t.allowance));
    let mut lines = head(rng, &ctx, t.a);
    let mut g = G76 {
        block1: false,
        p: None,
        extra1: vec![],
        extra2: vec![],
        omit: "",
        incremental: false,
        show_r: false,
    };
    lines.extend(g76_lines(&ctx, &t, &g));
    let mut t2 = t.clone();
    t2.allowance = 0;
    g.block1 = true;
    g.p = Some(pmra(1, rng.range(0, 5), tool_angle(rng)));
    lines.extend(g76_lines(&ctx, &t2, &g));
    g.block1 = false;
    g.omit = "F";
    lines.extend(g76_lines(&ctx, &t2, &g));
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "G76 values from the parameters, then from a block 1 that stays in force; the lead is modal".into(),
        &["template:g76-params-modal", "params:block1", "block1-modal", "lead-modal"],
    )
}

fn v_fanuc_style(rng: &mut Rng, calc: bool) -> Draft {
    let mut ctx = Ctx::new(ProfileName::Fanuc, rng);
    ctx.calculator_input = calc;
    ctx.bare = !calc;
    let t = thread(rng, &ctx, Taper::Any, (2, 5));
    let g = G76::usual(rng, &ctx);
    let lines = g76_program(rng, &ctx, &t, &g);
    let text = if calc {
        "FANUC G76 with calculator-type input: lengths without a decimal point are mm (inch)"
    } else {
        "FANUC G76 with every length in least increments, no decimal point"
    };
    Draft::valid(ctx, lines, text.into(), &["template:fanuc-style"])
}

fn v_fanuc_bare(rng: &mut Rng) -> Draft {
    v_fanuc_style(rng, false)
}

fn v_fanuc_calc(rng: &mut Rng) -> Draft {
    v_fanuc_style(rng, true)
}

fn v_partial_p(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let t = small_thread(rng, &ctx);
    let mut lines = head(rng, &ctx, t.a);
    let a = tool_angle(rng);
    let r = rng.range(0, 9);
    // P(m)(r)(a) with m = 0 (00..99 on the 980TDi), then "P(a)" and "P(r)(a)" alone.
    let ps = [pmra(0, r, a), format!("{a:02}"), format!("{:02}{:02}", rng.range(0, 9), tool_angle(rng))];
    for p in ps {
        let g = G76 {
            block1: true,
            p: Some(p),
            extra1: vec![],
            extra2: vec![],
            omit: "",
            incremental: false,
            show_r: false,
        };
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    Draft::valid(
        ctx,
        lines,
        "GSK 980TDi P(m)(r)(a) written in part (note 4): m = 0, then a alone, then r and a".into(),
        &["template:gsk980-partial-p", "p:partial"],
    )
    .requiring(&["finish:none"])
}

// ---- G32 templates ----

/// A G32 block.
fn g32(ctx: &Ctx, x: Option<i64>, z: Option<i64>, words: &[String]) -> String {
    let mut s = String::from("G32");
    if let Some(x) = x {
        let _ = write!(s, " X{}", ctx.num(x));
    }
    if let Some(z) = z {
        let _ = write!(s, " Z{}", ctx.num(z));
    }
    for w in words {
        let _ = write!(s, " {w}");
    }
    s
}

/// Radial start, radial end and Z of a G32 thread, and the X retract.
struct Line32 {
    side: i64,
    dir: i64,
    r0: i64,
    z0: i64,
    z1: i64,
    len: i64,
    taper: i64,
    lead: String,
    lead_inc: i64,
}

fn line32(rng: &mut Rng, ctx: &Ctx, taper: bool) -> Line32 {
    let side = rng.sign();
    let dir = if rng.chance(70) { -1 } else { 1 };
    let (lead, lead_inc) = ctx.lead(rng, None);
    let len = ctx.mm(rng.range(15_000, 40_000));
    let r0 = if side > 0 { ctx.mm(rng.range(10_000, 30_000)) } else { ctx.mm(rng.range(20_000, 35_000)) };
    let z0 = if dir < 0 { ctx.mm(rng.range(2000, 5000)) } else { -(len + ctx.mm(rng.range(2000, 5000))) };
    let taper = if taper { rng.sign() * ctx.mm(rng.range(500, 3000)) } else { 0 };
    Line32 { side, dir, r0, z0, z1: z0 + dir * len, len, taper, lead, lead_inc }
}

fn v_g32_passes(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let taper = rng.chance(50);
    let l = line32(rng, &ctx, taper);
    let xf = ctx.xf();
    let k = l.lead_inc * 6 / 10;
    let depths = if rng.chance(50) { vec![k / 2, k] } else { vec![k / 2, k * 4 / 5, k] };
    let crest = l.r0 + l.side * k;
    let clear = ctx.mm(rng.range(2000, 5000));
    let retract =
        xf * (if l.side > 0 { crest + l.taper.max(0) + clear } else { crest + l.taper.min(0) - clear });
    let incremental = rng.chance(40);
    let mut lines = Vec::new();
    for (n, depth) in depths.iter().enumerate() {
        let r = crest - l.side * depth;
        if n == 0 {
            lines.extend(head(rng, &ctx, (xf * r, l.z0)));
        } else {
            lines.push(format!("X{}", ctx.num(xf * r)));
        }
        let lead = if n == 0 { vec![l.lead.clone()] } else { vec![] };
        let x_end = (l.taper != 0).then_some(xf * (r + l.taper));
        if incremental {
            let mut s = String::from("G32");
            if let Some(x) = x_end {
                let _ = write!(s, " X{}", ctx.num(x));
            }
            let _ = write!(s, " W{}", ctx.num(l.z1 - l.z0));
            for w in &lead {
                let _ = write!(s, " {w}");
            }
            lines.push(s);
        } else {
            lines.push(g32(&ctx, x_end, Some(l.z1), &lead));
        }
        lines.push(format!("G00 X{}", ctx.num(retract)));
        if incremental {
            lines.push(format!("W{}", ctx.num(l.z0 - l.z1)));
        } else {
            lines.push(format!("Z{}", ctx.num(l.z0)));
        }
    }
    lines.push("M30".into());
    let what = if taper { "taper" } else { "straight" };
    Draft::valid(
        ctx,
        lines,
        format!("G32 {what} {} thread cut in {} passes, the lead modal", side_text(l.side), depths.len()),
        &["template:g32-passes", "lead-modal"],
    )
    .requiring(if taper { &["g32:taper"] } else { &["g32:straight"] })
}

fn v_g32_face(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let (lead, lead_inc) = ctx.lead(rng, None);
    let outer = ctx.mm(rng.range(30_000, 45_000));
    let inner = ctx.mm(rng.range(6000, 15_000));
    let inward = rng.chance(70);
    let (r0, r1) = if inward { (outer, inner) } else { (inner, outer) };
    let dir = rng.sign();
    let z_face = ctx.mm(rng.range(-2000, 2000));
    let k = lead_inc * 6 / 10;
    let clear = ctx.mm(2000);
    let mut lines = Vec::new();
    let runout = ctx.profile != ProfileName::Fanuc && rng.chance(60);
    for (n, depth) in [k / 2, k].iter().enumerate() {
        let z = z_face + dir * depth;
        if n == 0 {
            lines.extend(head(rng, &ctx, (xf * r0, z)));
        } else {
            lines.push(format!("Z{}", ctx.num(z)));
        }
        let mut words = Vec::new();
        if n == 0 {
            words.push(lead.clone());
        }
        if runout {
            // J along Z (away from the face), K along X (radius).
            words.push(format!("J{}", ctx.num(-dir * ctx.mm(rng.range(300, 1500)))));
            words.push(format!("K{}", ctx.num(ctx.mm(rng.range(500, 2000)))));
        }
        if rng.chance(50) {
            lines.push(g32(&ctx, Some(xf * r1), None, &words));
        } else {
            let mut s = format!("G32 U{} W0", ctx.num(xf * (r1 - r0)));
            for w in &words {
                let _ = write!(s, " {w}");
            }
            lines.push(s);
        }
        lines.push(format!("G00 Z{}", ctx.num(z_face - dir * clear)));
        lines.push(format!("X{}", ctx.num(xf * r0)));
    }
    lines.push("M30".into());
    let what = if inward { "towards the centre" } else { "outwards" };
    let mut tags = vec!["template:g32-face"];
    if runout {
        tags.push("g32:face-run-out");
    }
    Draft::valid(ctx, lines, format!("G32 face thread (X only), cut {what}"), &tags).requiring(&["g32:face"])
}

/// G32 blocks with run-out, one per rule of the profile, each cut from the
/// same start (G00 between them cancels J and K), then one without J/K.
fn g32_runout_program(rng: &mut Rng, ctx: &Ctx, l: &Line32, variants: &[Vec<String>]) -> Vec<String> {
    let xf = ctx.xf();
    let x1 = (l.taper != 0).then_some(xf * (l.r0 + l.taper));
    let clear = ctx.mm(rng.range(3000, 5000));
    let reach = l.taper.abs().max(ctx.mm(2000));
    let retract = xf * (l.r0 + l.side * (reach + clear)).max(ctx.mm(1000));
    let mut lines = head(rng, ctx, (xf * l.r0, l.z0));
    for (n, words) in variants.iter().chain(std::iter::once(&Vec::new())).enumerate() {
        if n > 0 {
            lines.push(format!("X{}", ctx.num(xf * l.r0)));
        }
        let mut words = words.clone();
        if n == 0 {
            words.push(l.lead.clone());
        }
        lines.push(g32(ctx, x1, Some(l.z1), &words));
        lines.push(format!("G00 X{}", ctx.num(retract)));
        lines.push(format!("Z{}", ctx.num(l.z0)));
    }
    lines.push("M30".into());
    lines
}

fn v_g32_runout_980(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let taper = rng.chance(50);
    let l = line32(rng, &ctx, taper);
    let (j, k) = (ctx.mm(rng.range(300, 2000)), ctx.mm(rng.range(500, 3000)));
    let (jt, njt, kt) = (ctx.num(l.side * j), ctx.num(-l.side * j), ctx.num(k));
    let variants = [
        vec![format!("J{jt}"), format!("K{kt}")],
        vec![format!("J{jt}")],
        vec![format!("J{njt}"), "K0".into()],
        vec!["J0".into(), format!("K{kt}")],
    ];
    let lines = g32_runout_program(rng, &ctx, &l, &variants);
    let shape = if taper { "taper" } else { "straight" };
    Draft::valid(
        ctx,
        lines,
        format!(
            "GSK 980TDi G32 {shape} thread, run-out rules of seed 002: J and K, K omitted (K = |J|), \
             J negative with K0 (K = |J|), J0 (none), then J and K cancelled by G00"
        ),
        &[
            "template:g32-run-out-gsk980",
            "rule:g32-gsk980-jk",
            "rule:g32-gsk980-k-omitted",
            "rule:g32-gsk980-k0",
            "rule:g32-gsk980-j0",
            "rule:g32-jk-cancelled",
        ],
    )
    .requiring(&["g32:run-out"])
}

fn v_g32_runout_988(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let mut l = line32(rng, &ctx, false);
    // Steep: the X travel (radius) at least the Z travel; K along X, J along Z.
    l.len = ctx.mm(rng.range(3000, 6000));
    l.z1 = l.z0 + l.dir * l.len;
    l.taper = -l.side * (l.len + if rng.chance(20) { 0 } else { ctx.mm(rng.range(0, 5000)) });
    l.r0 = l.r0.max(l.taper.abs() + ctx.mm(8000));
    let (j, k) = (ctx.mm(rng.range(300, 2000)), ctx.mm(rng.range(500, 2500)));
    let jt = ctx.num(-l.dir * j);
    let variants = [vec![format!("J{jt}"), format!("K{}", ctx.num(k))], vec![format!("J{jt}")]];
    let lines = g32_runout_program(rng, &ctx, &l, &variants);
    Draft::valid(
        ctx,
        lines,
        "GSK 988TA G32 steep taper (X the long axis): J and K, J only (a pull-out along Z), then J and K \
         cancelled by G00"
            .into(),
        &[
            "template:g32-run-out-gsk988",
            "rule:g32-gsk988-jk",
            "rule:g32-gsk988-j-only",
            "rule:g32-jk-cancelled",
        ],
    )
    .requiring(&["g32:run-out", "g32:pull-out", "g32:x-long"])
}

fn v_g32_continuous(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let l = line32(rng, &ctx, false);
    let rise = ctx.mm(rng.range(500, 2000));
    let seg = l.len / 4;
    let (r_in, r_mid) = (l.r0, l.r0 + l.side * rise);
    let z = [l.z0 + l.dir * seg, l.z0 + l.dir * 3 * seg, l.z1];
    let q1 = rng.pick(&[0, 45_000, 90_000, 120_000, 270_000]);
    let wrap = ctx.profile == ProfileName::Gsk988 && rng.chance(40);
    let qtext = |q: i64| {
        if wrap {
            ctx.q(q + 360_000)
        } else {
            ctx.q(q)
        }
    };
    let runout_end = ctx.profile != ProfileName::Fanuc && rng.chance(50);
    let retract = xf * (r_mid + l.side * ctx.mm(4000)).max(ctx.mm(1000));
    let mut lines = head(rng, &ctx, (xf * r_in, l.z0));
    for (start, q) in [q1, (q1 + 180_000) % 360_000].into_iter().enumerate() {
        if start == 1 {
            lines.push(format!("X{}", ctx.num(xf * r_in)));
        }
        let mut first = vec![];
        if start == 0 {
            first.push(l.lead.clone());
        }
        if q != 0 || wrap {
            first.push(format!("Q{}", qtext(q)));
        }
        lines.push(g32(&ctx, Some(xf * r_mid), Some(z[0]), &first));
        let ignored = if rng.chance(40) { vec![format!("Q{}", ctx.q(30_000))] } else { vec![] };
        lines.push(g32(&ctx, None, Some(z[1]), &ignored));
        let last = if runout_end { vec![format!("J{}", ctx.num(l.side * ctx.mm(1000)))] } else { vec![] };
        lines.push(g32(&ctx, Some(xf * r_in), Some(z[2]), &last));
        lines.push(format!("G00 X{}", ctx.num(retract)));
        lines.push(format!("Z{}", ctx.num(l.z0)));
    }
    lines.push("M30".into());
    let mut tags = vec!["template:g32-continuous", "g32:multi-start"];
    if wrap {
        tags.push("g32:q-wrap");
    }
    Draft::valid(
        ctx,
        lines,
        "G32 continuous thread of three blocks (taper in, straight, taper out), cut twice with Q 180 \
         degrees apart"
            .into(),
        &tags,
    )
    .requiring(&["g32:continuous", "g32:q"])
}

// ---- G75.1 grooves (GSK 980TDi only) ----

/// One G75.1 cycle as written, in increments: X, P(Δi), H, V and U in
/// X-word units, R and the corner sizes radius values, the rest along Z.
#[derive(Clone)]
struct Groove {
    /// Where the tool is before the cycle (it returns there).
    from: (i64, i64),
    /// The start point S; a `None` coordinate is left out of block 1 (note
    /// 3: the current position).
    start: (Option<i64>, Option<i64>),
    peck: i64,
    step: i64,
    depth: i64,
    width: i64,
    /// A, B, L as written, in degrees; `None`: left out (90°, 90°, 0°).
    a: Option<String>,
    b: Option<String>,
    l: Option<String>,
    retract: Option<i64>,
    layer: Option<i64>,
    u: Option<i64>,
    w: Option<i64>,
    tool: Option<i64>,
    j: Option<u8>,
    /// A(r1), B(r2), D(r3), E(r4); `None`: left out.
    corners: [Option<i64>; 4],
    /// P(a)(b)(d)(e) of block 2 as written.
    digits: Option<String>,
    /// Block 1 words left out: any of `P`, `Q`, `H`, `D`.
    omit: &'static str,
}

/// A sharp, right-angled groove of radial depth `h_um` and bottom width
/// `d_um` (microns of a radius), towards `sx` on X and `sz` on Z, with a
/// peck and a step that are replaced by the templates; S is on an outer
/// diameter for `sx < 0`, in a bore for `sx > 0`, and the tool stands clear
/// of it.
fn groove(rng: &mut Rng, ctx: &Ctx, sx: i64, sz: i64, h_um: i64, d_um: i64) -> Groove {
    let xf = ctx.xf();
    let r0 = if sx < 0 { rng.range(150, 400) } else { rng.range(120, 300) } * 100;
    let zs = rng.range(-200, 200) * 100;
    let clear = rng.range(10, 50) * 100;
    let from_r = if sx < 0 { r0 + clear } else { r0 - clear };
    let from_z = zs - sz * rng.range(0, 50) * 100;
    Groove {
        from: (xf * ctx.mm(from_r), ctx.mm(from_z)),
        start: (Some(xf * ctx.mm(r0)), Some(ctx.mm(zs))),
        peck: xf * ctx.mm(h_um),
        step: ctx.mm(d_um).max(1),
        depth: sx * xf * ctx.mm(h_um),
        width: sz * ctx.mm(d_um),
        a: None,
        b: None,
        l: None,
        retract: None,
        layer: None,
        u: None,
        w: None,
        tool: None,
        j: None,
        corners: [None; 4],
        digits: None,
        omit: "",
    }
}

/// P(Δi) that cuts `h` radius increments in at most `n` pecks, in X-word
/// units, rounded up to 0.1 mm where the units allow.
fn peck_for(ctx: &Ctx, h: i64, n: i64) -> i64 {
    let grain = ctx.mm(100).max(1);
    let per = (h + n - 1) / n.max(1);
    ctx.xf() * ((per + grain - 1) / grain * grain).max(1)
}

/// `microns` of a radius in increments, at least one.
fn small(ctx: &Ctx, microns: i64) -> i64 {
    ctx.mm(microns).max(1)
}

/// A flank angle in degrees, as written.
fn angle(rng: &mut Rng, choices: &[&str]) -> Option<String> {
    Some(rng.pick(choices).to_string())
}

/// P(a)(b)(d)(e) for `round` (1 for a round, 0 for a chamfer, in the order
/// A B D E), with the leading zeros sometimes left out (reading R-G75P).
fn corner_digits(rng: &mut Rng, round: [bool; 4]) -> String {
    let full: String = round.iter().map(|&r| if r { '1' } else { '0' }).collect();
    if rng.chance(50) {
        let trimmed = full.trim_start_matches('0');
        if trimmed.is_empty() {
            "0".into()
        } else {
            trimmed.into()
        }
    } else {
        full
    }
}

/// The two blocks of a G75.1.
fn g75_lines(ctx: &Ctx, g: &Groove) -> Vec<String> {
    let mut b1 = String::from("G75.1");
    if let Some(x) = g.start.0 {
        let _ = write!(b1, " X{}", ctx.num(x));
    }
    if let Some(z) = g.start.1 {
        let _ = write!(b1, " Z{}", ctx.num(z));
    }
    for (letter, v, pq) in
        [('P', g.peck, true), ('Q', g.step, true), ('H', g.depth, false), ('D', g.width, false)]
    {
        if !g.omit.contains(letter) {
            let _ = write!(b1, " {letter}{}", if pq { ctx.pq(v) } else { ctx.num(v) });
        }
    }
    for (letter, a) in [('A', &g.a), ('B', &g.b), ('L', &g.l)] {
        if let Some(a) = a {
            let _ = write!(b1, " {letter}{a}");
        }
    }
    let mut b2 = String::from("G75.1");
    for (letter, v) in [('R', g.retract), ('V', g.layer), ('U', g.u), ('W', g.w), ('I', g.tool)] {
        if let Some(v) = v {
            let _ = write!(b2, " {letter}{}", ctx.num(v));
        }
    }
    if let Some(j) = g.j {
        let _ = write!(b2, " J{j}");
    }
    for (letter, v) in ['A', 'B', 'D', 'E'].into_iter().zip(g.corners) {
        if let Some(v) = v {
            let _ = write!(b2, " {letter}{}", ctx.num(v));
        }
    }
    if let Some(p) = &g.digits {
        let _ = write!(b2, " P{p}");
    }
    vec![b1, b2]
}

/// The lines of a one-G75.1 program.
fn g75_program(rng: &mut Rng, ctx: &Ctx, g: &Groove) -> Vec<String> {
    let mut lines = head(rng, ctx, g.from);
    lines.extend(g75_lines(ctx, g));
    if rng.chance(30) {
        let away = if g.depth < 0 { 1 } else { -1 };
        lines.push(format!(
            "G00 X{} Z{}",
            ctx.num(g.from.0 + away * ctx.xf() * ctx.mm(5000)),
            ctx.num(g.from.1 + ctx.mm(20_000))
        ));
    }
    lines.push("M30".into());
    lines
}

fn v_g75_seed(rng: &mut Rng) -> Draft {
    let mut ctx = Ctx::new(ProfileName::Gsk980, rng);
    // The seed's example is written for IS-C (P30000 is 3 mm).
    ctx.increment = IncrementSystem::IsC;
    let h_um = rng.range(60, 100) * 100;
    let d_um = rng.range(60, 120) * 100;
    let mut g = groove(rng, &ctx, -1, -1, h_um, d_um);
    g.a = Some("45".into());
    g.b = Some("30".into());
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(3, 6));
    g.step = small(&ctx, rng.range(d_um / 200, d_um / 100) * 100);
    g.retract = Some(small(&ctx, rng.range(2, 10) * 100));
    let with_tool = rng.chance(30);
    if with_tool {
        g.tool = Some(small(&ctx, rng.range(20, 40) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    let what =
        if with_tool { "with the grooving tool's width I" } else { "as written, a pointed tool (R-G75SEED)" };
    Draft::valid(
        ctx,
        lines,
        format!("G75.1 shaped as seed 001's example O0008 (IS-C, A45 B30, pecks with a retract R), {what}"),
        &["template:g75-seed"],
    )
    .requiring(&["g75", "g75:angled", "g75:pecking", "g75:j0", "g75:-x", "g75:-z"])
}

fn v_g75_square(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let xf = ctx.xf();
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let w_um = rng.range(20, 40) * 100;
    let d_um = w_um + rng.range(15, 40) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    let h = ctx.mm(h_um);
    // Two layers: V is 55-75 % of the depth, U at most 10 %.
    g.layer = Some(xf * (h * rng.range(55, 75) / 100).max(1));
    g.u = Some(xf * small(&ctx, rng.range(1, 3) * 100));
    g.w = Some(small(&ctx, rng.range(1, 3) * 100));
    g.tool = Some(small(&ctx, w_um));
    g.step = (ctx.mm(w_um) * rng.range(80, 100) / 100).max(1);
    g.peck = peck_for(&ctx, h, rng.range(1, 2));
    if rng.chance(80) {
        g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    }
    g.j = Some(1);
    if rng.chance(50) {
        g.corners[0] = Some(small(&ctx, rng.range(2, 5) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::valid(
        ctx,
        lines,
        "G75.1 square groove in two layers V, allowances U W, a grooving tool I, rough and finish J1".into(),
        &["template:g75-square"],
    )
    .requiring(&["g75:layers", "g75:allowances", "g75:tool-width", "g75:j1"])
}

fn v_g75_corners(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let with_tool = rng.chance(50);
    let w_um = if with_tool { rng.range(15, 25) * 100 } else { 0 };
    let d_um = w_um + rng.range(25, 45) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    g.a = angle(rng, &["45", "60", "62.5", "70", "75", "80"]);
    g.b = angle(rng, &["45", "60", "75", "80", "90"]);
    // One corner a round and another a chamfer, the other two either or none.
    let round_at = rng.index(4);
    let chamfer_at = (round_at + 1 + rng.index(3)) % 4;
    let mut round = [false; 4];
    for (i, corner) in g.corners.iter_mut().enumerate() {
        let set = i == round_at || i == chamfer_at || rng.chance(50);
        *corner = set.then(|| small(&ctx, rng.range(2, 8) * 100));
        round[i] = i == round_at || (i != chamfer_at && rng.chance(50));
    }
    g.digits = Some(corner_digits(rng, round));
    g.j = Some(1);
    g.tool = with_tool.then(|| small(&ctx, w_um));
    g.step = if with_tool {
        (ctx.mm(w_um) * rng.range(80, 100) / 100).max(1)
    } else {
        small(&ctx, rng.range(15, 30) * 100)
    };
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 2));
    g.retract = Some(small(&ctx, rng.range(2, 5) * 100));
    if rng.chance(40) {
        g.u = Some(ctx.xf() * small(&ctx, rng.range(1, 2) * 100));
        g.w = Some(small(&ctx, rng.range(1, 2) * 100));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::valid(
        ctx,
        lines,
        "G75.1 trapezoidal groove with chamfers and rounds at its corners (P digits), rough and finish J1"
            .into(),
        &["template:g75-corners"],
    )
    .requiring(&["g75:angled", "g75:corners", "g75:arcs", "g75:chamfers", "g75:j1"])
}

fn v_g75_slope(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(30, 60) * 100;
    let with_tool = rng.chance(40);
    let w_um = if with_tool { rng.range(15, 25) * 100 } else { 0 };
    let d_um = w_um + rng.range(25, 50) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    // Every B offered is steeper than every L (R-G75SLOPE: L < B).
    g.l = angle(rng, &["5", "7.5", "10", "15", "20", "30"]);
    if rng.chance(60) {
        g.b = angle(rng, &["45", "60", "75", "90"]);
    }
    if rng.chance(50) {
        g.a = angle(rng, &["60", "75", "90"]);
    }
    let mut round = [false; 4];
    for (i, corner) in g.corners.iter_mut().enumerate() {
        if rng.chance(40) {
            *corner = Some(small(&ctx, rng.range(2, 6) * 100));
            round[i] = rng.chance(50);
        }
    }
    if g.corners.iter().any(Option::is_some) && rng.chance(80) {
        g.digits = Some(corner_digits(rng, round));
    }
    g.tool = with_tool.then(|| small(&ctx, w_um));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 3));
    g.j = Some(2);
    let lines = g75_program(rng, &ctx, &g);
    Draft::valid(
        ctx,
        lines,
        "G75.1 groove whose opening lies on a slope L, finishing contour only (J2)".into(),
        &["template:g75-slope"],
    )
    .requiring(&["g75:slope", "g75:j2"])
}

fn v_g75_internal(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let h_um = rng.range(20, 50) * 100;
    let d_um = rng.range(30, 60) * 100;
    let mut g = groove(rng, &ctx, 1, 1, h_um, d_um);
    // The tool stands at S: block 1 leaves X, Z or both out (note 3).
    let (xs, zs) = (g.start.0.unwrap_or(0), g.start.1.unwrap_or(0));
    match rng.range(0, 3) {
        0 => {
            g.from.0 = xs;
            g.start.0 = None;
        }
        1 => {
            g.from.1 = zs;
            g.start.1 = None;
        }
        _ => {
            g.from = (xs, zs);
            g.start = (None, None);
        }
    }
    if rng.chance(50) {
        g.a = angle(rng, &["60", "75", "90"]);
        g.b = angle(rng, &["60", "75", "90"]);
    }
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(2, 3));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    if rng.chance(50) {
        g.j = Some(0);
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::valid(
        ctx,
        lines,
        "G75.1 internal groove towards +Z from the current position (X/Z of block 1 left out), roughing J0"
            .into(),
        &["template:g75-internal", "rule:g75-start-omitted"],
    )
    .requiring(&["g75:+x", "g75:+z", "g75:j0", "g75:pecking"])
}

// ---- templates of programs that must be refused ----

/// A usual one-G76 draft to break.
fn base(profile: ProfileName, rng: &mut Rng) -> (Ctx, Thread, G76) {
    let ctx = Ctx::new(profile, rng);
    let t = thread(rng, &ctx, Taper::Straight, (1, 3));
    let g = G76::usual(rng, &ctx);
    (ctx, t, g)
}

fn r_missing_p(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(any_profile(rng), rng);
    g.omit = "P";
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(ctx, lines, "G76 block 2 without P(k)".into(), &["refuse:missing-p"], "missing")
}

fn r_missing_q(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(any_profile(rng), rng);
    g.omit = "Q";
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(ctx, lines, "G76 block 2 without Q(Δd)".into(), &["refuse:missing-q"], "missing")
}

fn r_min_cut(rng: &mut Rng) -> Draft {
    let (mut ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.dmin = t.k + ctx.mm(rng.range(1, 500)).max(1);
    let mut tags = vec!["refuse:min-cut-above-height"];
    if rng.chance(30) {
        let name = ctx.param_name(|p| p.params.min_cut);
        ctx.params.insert(name, Param::Len(t.dmin));
        g.block1 = false;
        tags.push("params:block1");
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 with Q(Δdmin) > P(k) (note 6)".into(),
        &tags,
        "cycle:min_cut_exceeds_height",
    )
}

fn r_allowance(rng: &mut Rng) -> Draft {
    let (mut ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.allowance = t.k + ctx.mm(rng.range(1, 500)).max(1);
    t.dmin = t.dmin.min(t.k);
    let mut tags = vec!["refuse:allowance-above-height"];
    if rng.chance(30) {
        let name = ctx.param_name(|p| p.params.finishing_allowance);
        ctx.params.insert(name, Param::Len(t.allowance));
        let min = ctx.param_name(|p| p.params.min_cut);
        ctx.params.insert(min, Param::Len(t.dmin));
        g.block1 = false;
        tags.push("params:block1");
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 with R(d) > P(k) (note 6)".into(),
        &tags,
        "cycle:allowance_exceeds_height",
    )
}

fn r_run_out_long(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, mut t, mut g) = base(profile, rng);
    match profile {
        ProfileName::Fanuc => {
            // The chamfer r × 0.1 × lead beyond a short thread.
            let dir = if t.d.1 < t.a.1 { -1 } else { 1 };
            t.w = ctx.mm(rng.range(3000, 6000));
            t.d.1 = t.a.1 + dir * t.w;
            g.p = Some(pmra(1, rng.range(90, 99), rng.pick(&[0, 29, 30, 55, 60])));
            g.incremental = false;
        }
        ProfileName::Gsk980 => {
            g.extra1 =
                vec![format!("J{}", ctx.num(ctx.mm(1000))), format!("K{}", ctx.num(t.w + ctx.mm(1000)))];
        }
        ProfileName::Gsk988 => {
            g.extra2 =
                vec![format!("J{}", ctx.num(ctx.mm(1000))), format!("K{}", ctx.num(t.w + ctx.mm(1000)))];
        }
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 whose run-out is longer than the thread (note 7)".into(),
        &["refuse:run-out-too-long"],
        "cycle:run_out_too_long",
    )
}

fn r_no_spindle(rng: &mut Rng) -> Draft {
    let (ctx, t, g) = base(any_profile(rng), rng);
    let mut lines = Vec::new();
    if ctx.g20 {
        lines.push("G20".to_string());
    }
    let variant = rng.range(0, 3);
    match variant {
        0 => {}
        1 => {
            lines.push("M03 S500".into());
            lines.push("M05".into());
        }
        2 => {
            lines.push("M03".into());
            lines.push("G50 S2000".into());
        }
        _ => lines.push("S500".into()),
    }
    lines.push(format!("G00 X{} Z{}", ctx.num(t.a.0), ctx.num(t.a.1)));
    let g32_variant = rng.chance(30);
    if g32_variant {
        lines.push(g32(&ctx, None, Some(t.d.1), std::slice::from_ref(&t.lead)));
    } else {
        lines.extend(g76_lines(&ctx, &t, &g));
    }
    lines.push("M30".into());
    let why = ["no S and no M03", "the spindle stopped by M05", "G50 S alone (a clamp)", "no M03"]
        [usize::try_from(variant).unwrap_or(0)];
    let what = if g32_variant { "G32" } else { "G76" };
    Draft::refused(
        ctx,
        lines,
        format!("{what} without a spindle speed: {why} (note 8)"),
        &["refuse:no-spindle-speed"],
        "no_spindle_speed",
    )
}

fn r_face_thread(rng: &mut Rng) -> Draft {
    let (ctx, mut t, mut g) = base(any_profile(rng), rng);
    t.d.1 = t.a.1;
    g.incremental = rng.chance(50);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 face thread: the end point has the Z of the start".into(),
        &["refuse:g76-face-thread"],
        "cycle:face_thread",
    )
}

fn r_out_of_range(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, mut t, mut g) = base(profile, rng);
    let big_f = if ctx.unit == InputUnit::Metric { "F10000" } else { "F10" };
    let mut variants: Vec<(&str, u8)> =
        vec![("P(m)(r)(a) of seven digits", 0), ("lead F beyond the range table", 1), ("P(k) = 0", 2)];
    match profile {
        ProfileName::Gsk988 => {
            variants.extend([
                ("L1000 starts", 3),
                ("infeed D3", 4),
                ("negative J", 5),
                ("m = 0 (01..99)", 6),
            ]);
        }
        ProfileName::Fanuc => variants.push(("m = 0 (01..99)", 6)),
        ProfileName::Gsk980 => variants.push(("negative K in block 1", 7)),
    }
    let (what, v) = rng.pick(&variants);
    match v {
        0 => g.p = Some(format!("1{}", pmra(1, 0, 60))),
        1 => t.lead = big_f.into(),
        2 => t.k = 0,
        3 => g.extra1.push("L1000".into()),
        4 => g.extra1.push("D3".into()),
        5 => g.extra2.push(format!("J-{}", ctx.num(ctx.mm(1000)))),
        6 => g.p = Some(pmra(0, 5, 60)),
        _ => g.extra1.push(format!("K-{}", ctx.num(ctx.mm(1000)))),
    }
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G76 with a value outside its range: {what}"),
        &["refuse:out-of-range"],
        "out_of_range",
    )
}

fn r_fanuc_point(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(ProfileName::Fanuc, rng);
    let variant = rng.range(0, 3);
    let mut lines;
    let what = match variant {
        0 => {
            lines = head(rng, &ctx, t.a);
            let mut b = g76_lines(&ctx, &t, &g);
            let dec = decimal(t.k, ctx.decimals(), true);
            let last = b.pop().unwrap_or_default();
            b.push(last.replacen(&format!(" P{}", t.k), &format!(" P{dec}"), 1));
            lines.extend(b);
            "P(k) with a decimal point"
        }
        1 => {
            lines = head(rng, &ctx, t.a);
            let mut b = g76_lines(&ctx, &t, &g);
            let dec = decimal(t.dmin.max(1), ctx.decimals(), true);
            b[0] = format!("G76 P{} Q{dec} R{}", g.p.clone().unwrap_or_default(), ctx.num(t.allowance));
            lines.extend(b);
            "Q(Δdmin) with a decimal point"
        }
        2 => {
            lines = head(rng, &ctx, t.a);
            g.p = Some(format!("{}.0", pmra(1, 0, 60)));
            lines.extend(g76_lines(&ctx, &t, &g));
            "P(m)(r)(a) with a decimal point"
        }
        _ => {
            lines = head(rng, &ctx, t.a);
            lines.push(g32(&ctx, None, Some(t.d.1), &[t.lead.clone(), "Q180.0".into()]));
            "G32 Q with a decimal point"
        }
    };
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        format!("FANUC: {what} (P/Q in least increments)"),
        &["refuse:fanuc-decimal-point"],
        "decimal_point_not_allowed",
    )
}

fn r_partial_p(rng: &mut Rng) -> Draft {
    let (ctx, t, mut g) = base(rng.pick(&[ProfileName::Gsk988, ProfileName::Fanuc]), rng);
    g.p = Some(rng.pick(&["0560", "60", "560", "1060"]).to_string());
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "P(m)(r)(a) written in part where the profile allows it only as a whole".into(),
        &["refuse:partial-p"],
        "partial_p",
    )
}

fn r_address(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (ctx, t, mut g) = base(profile, rng);
    let one = ctx.num(ctx.mm(1000));
    let mut g32_word = None;
    let what = match profile {
        ProfileName::Fanuc => match rng.range(0, 3) {
            0 => {
                g.extra2.push(format!("J{one}"));
                "J in FANUC G76 block 2"
            }
            1 => {
                g.extra1.push("D1".into());
                "D in FANUC G76 block 1"
            }
            2 => {
                g.extra1.push("L2".into());
                "L in FANUC G76 block 1"
            }
            _ => {
                g32_word = Some(format!("J{one}"));
                "J in FANUC G32"
            }
        },
        ProfileName::Gsk980 => match rng.range(0, 2) {
            0 => {
                g.extra1.push(rng.pick(&["D1", "L2"]).into());
                "D or L in 980TDi G76 block 1"
            }
            1 => {
                g.extra1.push(format!("E{one}"));
                "E in 980TDi G76 block 1"
            }
            _ => {
                g.extra2.push(format!("K{one}"));
                "K in 980TDi G76 block 2 (it belongs to block 1)"
            }
        },
        ProfileName::Gsk988 => {
            g.extra1.push(format!("J{one}"));
            "J in 988TA G76 block 1 (it belongs to block 2)"
        }
    };
    let mut lines = head(rng, &ctx, t.a);
    match g32_word {
        Some(w) => lines.push(g32(&ctx, None, Some(t.d.1), &[t.lead.clone(), w])),
        None => lines.extend(g76_lines(&ctx, &t, &g)),
    }
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        format!("an address the profile does not have: {what}"),
        &["refuse:address-not-in-profile"],
        "address_not_in_profile",
    )
}

fn r_g32_no_end(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let mut lines = head(rng, &ctx, (ctx.xf() * l.r0, l.z0));
    lines.push(format!("G32 {}", l.lead));
    lines.push("M30".into());
    Draft::refused(ctx, lines, "G32 without an end point".into(), &["refuse:g32-no-end-point"], "missing")
}

fn r_g32_zero_lead(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let mut lines = head(rng, &ctx, (ctx.xf() * l.r0, l.z0));
    let zero = rng.pick(&["F0", "F0.0", "I0"]);
    lines.push(g32(&ctx, None, Some(l.z1), &[zero.into()]));
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        format!("G32 with a zero lead {zero}"),
        &["refuse:g32-zero-lead"],
        "out_of_range",
    )
}

fn r_too_many(rng: &mut Rng) -> Draft {
    let mut ctx = Ctx::new(any_profile(rng), rng);
    let limit = rng.range(2, 6);
    ctx.pass_limit = u32::try_from(limit).unwrap_or(2);
    let mut t = thread(rng, &ctx, Taper::Straight, (limit + 3, limit + 12));
    t.dmin = 0;
    let g = G76::usual(rng, &ctx);
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G76 needing more rough passes than the pass limit {limit}"),
        &["refuse:too-many-passes"],
        "cycle:too_many_passes",
    )
}

fn r_start_inside(rng: &mut Rng) -> Draft {
    let (ctx, mut t, g) = base(any_profile(rng), rng);
    let side = if t.a.0 > t.d.0 { 1 } else { -1 };
    t.a.0 = if rng.chance(30) { t.d.0 } else { t.d.0 + side * ctx.xf() * (t.k / 2).max(1) };
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 whose start point lies inside the thread".into(),
        &["refuse:start-inside-thread"],
        "cycle:start_inside_thread",
    )
}

fn r_too_short(rng: &mut Rng) -> Draft {
    let (ctx, mut t, mut g) = base(any_profile(rng), rng);
    let dir = if t.d.1 < t.a.1 { -1 } else { 1 };
    t.w = (t.k / 2).max(1);
    t.d.1 = t.a.1 + dir * t.w;
    g.p = Some(pmra(1, 0, rng.pick(&[60, 80, 90])));
    g.extra1.clear();
    g.extra2.clear();
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 so short that the flank shift of a pass reaches the thread end".into(),
        &["refuse:thread-too-short"],
        "cycle:thread_too_short",
    )
}

fn r_lead_in_x(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(ProfileName::Gsk988, rng);
    let t = thread(rng, &ctx, Taper::XLong, (1, 3));
    let mut g = G76::usual(rng, &ctx);
    g.extra1.push(format!("E{}", ctx.num(ctx.mm(rng.range(300, 2000)))));
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 lead-in E on a steep taper whose long axis is X".into(),
        &["refuse:lead-in-on-x-long-axis"],
        "cycle:lead_in_on_x_long_axis",
    )
}

fn r_g32_no_motion(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let l = line32(rng, &ctx, false);
    let x0 = ctx.xf() * l.r0;
    let mut lines = head(rng, &ctx, (x0, l.z0));
    if rng.chance(50) {
        lines.push(g32(&ctx, Some(x0), Some(l.z0), std::slice::from_ref(&l.lead)));
    } else {
        lines.push(format!("G32 U0 W0 {}", l.lead));
    }
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        "G32 whose end point is the current position".into(),
        &["refuse:g32-no-motion"],
        "cycle:no_motion",
    )
}

fn r_g32_run_out_long(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(gsk(rng), rng);
    let taper = rng.chance(30);
    let l = line32(rng, &ctx, taper);
    let xf = ctx.xf();
    let mut lines = head(rng, &ctx, (xf * l.r0, l.z0));
    let words = vec![
        l.lead.clone(),
        format!("J{}", ctx.num(l.side * ctx.mm(1000))),
        format!("K{}", ctx.num(l.len + ctx.mm(rng.range(1, 3000)))),
    ];
    let x1 = (l.taper != 0).then_some(xf * (l.r0 + l.taper));
    lines.push(g32(&ctx, x1, Some(l.z1), &words));
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        "G32 run-out K longer than the move (988TA G32 note 4)".into(),
        &["refuse:g32-run-out-too-long"],
        "cycle:run_out_too_long",
    )
}

fn r_not_in_increments(rng: &mut Rng) -> Draft {
    let profile = any_profile(rng);
    let (mut ctx, t, g) = base(profile, rng);
    ctx.bare = false;
    let mut lines = head(rng, &ctx, t.a);
    let mut b = g76_lines(&ctx, &t, &g);
    let what = if profile == ProfileName::Gsk980 && ctx.pq_in_increments() && rng.chance(50) {
        let last = b.pop().unwrap_or_default();
        b.push(last.replacen(&format!(" P{}", t.k), &format!(" P{}.5", t.k), 1));
        "P(k) in increments with a fraction"
    } else {
        // One digit finer than the increment on Z of the start.
        let fine = decimal(t.a.1 * 10 + 3, ctx.decimals() + 1, true);
        lines.pop();
        lines.push(format!("G00 X{} Z{fine}", ctx.num(t.a.0)));
        "a coordinate finer than the least increment"
    };
    lines.extend(b);
    lines.push("M30".into());
    Draft::refused(ctx, lines, format!("G76 with {what}"), &["refuse:not-in-increments"], "not_in_increments")
}

fn r_position_unknown(rng: &mut Rng) -> Draft {
    let (ctx, t, g) = base(any_profile(rng), rng);
    let mut lines = Vec::new();
    if ctx.g20 {
        lines.push("G20".to_string());
    }
    lines.push("M03 S500".into());
    let variant = rng.range(0, 2);
    let what = match variant {
        0 => {
            lines.extend(g76_lines(&ctx, &t, &g));
            "G76 before any position is known"
        }
        1 => {
            lines.push(format!("G00 U{} W{}", ctx.num(ctx.mm(10_000)), ctx.num(ctx.mm(-5000))));
            "an incremental move before any position is known"
        }
        _ => {
            lines.push(g32(&ctx, None, Some(t.d.1), std::slice::from_ref(&t.lead)));
            "G32 before any position is known"
        }
    };
    lines.push("M30".into());
    Draft::refused(ctx, lines, what.into(), &["refuse:position-unknown"], "position_unknown")
}

fn r_pass_out_of_range(rng: &mut Rng) -> Draft {
    let ctx = Ctx::new(any_profile(rng), rng);
    let xf = ctx.xf();
    let max = cycleref::units::MAX_LENGTH;
    // Internal steep taper: X of C = X(D) + xf·i lies beyond the range table.
    let xd = rng.range(600_000_000, 900_000_000);
    let i = (max - xd) / xf + rng.range(1, 1_000_000);
    let (lead, lead_inc) = ctx.lead(rng, None);
    let k = (lead_inc * 6 / 10).max(1);
    let za = ctx.mm(rng.range(1000, 5000));
    let t = Thread {
        a: (xf * ctx.mm(rng.range(10_000, 40_000)), za),
        d: (xd, za - ctx.mm(rng.range(5000, 20_000))),
        taper: i,
        k,
        dd: (k / 2).max(1),
        dmin: 0,
        allowance: 0,
        lead,
        w: 0,
    };
    let g = G76 {
        block1: true,
        p: Some(pmra(1, 0, 60)),
        extra1: vec![],
        extra2: vec![],
        omit: "",
        incremental: false,
        show_r: true,
    };
    let lines = g76_program(rng, &ctx, &t, &g);
    Draft::refused(
        ctx,
        lines,
        "G76 taper whose thread start X(D) + i lies outside the range table".into(),
        &["refuse:pass-coordinate-out-of-range"],
        "cycle:out_of_range",
    )
}

fn r_unit_change(rng: &mut Rng) -> Draft {
    let mut ctx = Ctx::new(any_profile(rng), rng);
    ctx.g20 = false;
    let l = line32(rng, &ctx, false);
    let mut lines =
        vec!["M03 S500".to_string(), format!("G00 X{} Z{}", ctx.num(ctx.xf() * l.r0), ctx.num(l.z0))];
    let code = if ctx.unit == InputUnit::Metric { "G20" } else { "G21" };
    lines.push(code.into());
    lines.push(g32(&ctx, None, Some(l.z1), std::slice::from_ref(&l.lead)));
    lines.push("M30".into());
    Draft::refused(
        ctx,
        lines,
        format!("{code} after the first motion"),
        &["refuse:unit-change-after-motion"],
        "unit_change_after_motion",
    )
}

fn r_misc(rng: &mut Rng) -> Draft {
    let variant = rng.range(0, 3);
    let profile = if variant == 3 { ProfileName::Gsk988 } else { any_profile(rng) };
    let (mut ctx, t, g) = base(profile, rng);
    let mut lines = head(rng, &ctx, t.a);
    let (what, kind) = match variant {
        0 => {
            lines.push(format!("G00 X{} (retract", ctx.num(t.a.0)));
            ("a comment that is not closed", "syntax")
        }
        1 => {
            lines.push(format!("G00 X{} X{}", ctx.num(t.a.0), ctx.num(t.a.0 + ctx.mm(1000))));
            ("the same address twice in a block", "duplicate")
        }
        2 => {
            lines.push("G71 U1 R0.5".into());
            ("a G code the reader does not model (G71)", "unsupported")
        }
        _ => {
            ctx.params.insert("5129", Param::Int(1));
            ("parameter 5129 = 1 (high-speed threading mode)", "parameter")
        }
    };
    lines.extend(g76_lines(&ctx, &t, &g));
    lines.push("M30".into());
    Draft::refused(ctx, lines, format!("a program the reader refuses: {what}"), &["refuse:reader"], kind)
}

// ---- G75.1 programs that must be refused ----

/// A valid right-angled G75.1 draft to break: A and B left out (90°), a
/// pointed tool, one to three pecks and a few plunges, any J.
fn g75_base(rng: &mut Rng) -> (Ctx, Groove) {
    let ctx = Ctx::new(ProfileName::Gsk980, rng);
    let (sx, sz) = (rng.sign(), rng.sign());
    let h_um = rng.range(20, 60) * 100;
    let d_um = rng.range(30, 80) * 100;
    let mut g = groove(rng, &ctx, sx, sz, h_um, d_um);
    g.peck = peck_for(&ctx, ctx.mm(h_um), rng.range(1, 3));
    g.step = small(&ctx, rng.range(15, 30) * 100);
    if rng.chance(60) {
        g.retract = Some(small(&ctx, rng.range(1, 5) * 100));
    }
    if rng.chance(50) {
        g.j = Some(u8::try_from(rng.range(0, 2)).unwrap_or(0));
    }
    (ctx, g)
}

/// The radial depth of `g` in radius increments, and the bottom width.
fn g75_size(ctx: &Ctx, g: &Groove) -> (i64, i64) {
    (g.depth.abs() / ctx.xf(), g.width.abs())
}

fn r_g75_missing(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (letter, what) = rng.pick(&[("P", "P(Δi)"), ("Q", "Q(Δk)"), ("H", "H(h)"), ("D", "D(d)")]);
    g.omit = letter;
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 block 1 without {what} (note 3: H, D, P and Q cannot be omitted)"),
        &["refuse:g75-missing-word"],
        "missing",
    )
}

fn r_g75_lone(rng: &mut Rng) -> Draft {
    let (ctx, g) = g75_base(rng);
    let mut lines = head(rng, &ctx, g.from);
    let blocks = g75_lines(&ctx, &g);
    let mut block2 = blocks[1].clone();
    if g.retract.is_none() {
        // A block 2 needs one of its own words to be told from a block 1.
        let _ = write!(block2, " R{}", ctx.num(small(&ctx, 500)));
    }
    let what = match rng.range(0, 3) {
        0 => {
            lines.push(blocks[0].clone());
            lines.push(format!("G00 X{} Z{}", ctx.num(g.from.0), ctx.num(g.from.1)));
            lines.push("M30".into());
            "block 1 followed by another block"
        }
        1 => {
            lines.push(blocks[0].clone());
            "block 1 at the end of the program"
        }
        2 => {
            lines.push(block2);
            lines.push("M30".into());
            "block 2 without a block 1"
        }
        _ => {
            lines.push(block2);
            lines.push(blocks[0].clone());
            lines.push("M30".into());
            "block 2 before block 1"
        }
    };
    Draft::refused(
        ctx,
        lines,
        format!("a lone G75.1 block: {what} (note 3: always two blocks)"),
        &["refuse:g75-lone-block"],
        "missing",
    )
}

fn r_g75_angle(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let what = match rng.range(0, 4) {
        0 => {
            g.a = Some("0".into());
            "A0"
        }
        1 => {
            g.a = Some(rng.range(91, 180).to_string());
            "A above 90 degrees"
        }
        2 => {
            g.b = Some("0".into());
            "B0"
        }
        3 => {
            g.b = Some(rng.range(91, 180).to_string());
            "B above 90 degrees"
        }
        _ => {
            g.l = Some(rng.range(90, 120).to_string());
            "L of 90 degrees or more"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 with an angle outside its range: {what} (0 < A, B <= 90, 0 <= L < 90)"),
        &["refuse:g75-angle-out-of-range"],
        "cycle:angle_out_of_range",
    )
}

fn r_g75_slope(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let b = rng.pick(&[15, 20, 30, 45, 60, 75]);
    let l = if rng.chance(30) { b } else { rng.range(b + 1, 89) };
    g.b = Some(b.to_string());
    g.l = Some(l.to_string());
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 whose slope L{l} is not below the flank angle B{b} (R-G75SLOPE)"),
        &["refuse:g75-slope-not-below-flank"],
        "cycle:slope_not_below_flank",
    )
}

fn r_g75_allowance(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let extra = if rng.chance(30) { 0 } else { ctx.xf() * small(&ctx, rng.range(1, 20) * 100) };
    g.u = Some(g.depth.abs() + extra);
    let lines = g75_program(rng, &ctx, &g);
    let what = if extra == 0 { "equal to" } else { "larger than" };
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 whose allowance U is {what} the groove depth H"),
        &["refuse:g75-allowance-exceeds-depth"],
        "cycle:allowance_exceeds_depth",
    )
}

fn r_g75_corner(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (h, d) = g75_size(&ctx, &g);
    // Square flanks: a chamfer or round of size c takes c of each edge.
    let (what, pair, edge) = match rng.range(0, 2) {
        0 => ("A(r1) and D(r3) longer than flank A", [0, 2], h),
        1 => ("D(r3) and E(r4) longer than the bottom", [2, 3], d),
        _ => ("E(r4) and B(r2) longer than flank B", [3, 1], h),
    };
    for i in pair {
        g.corners[i] = Some(edge * rng.range(55, 80) / 100 + 1);
    }
    if rng.chance(50) {
        let round = [rng.chance(50), rng.chance(50), rng.chance(50), rng.chance(50)];
        g.digits = Some(corner_digits(rng, round));
    }
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 with corners {what}"),
        &["refuse:g75-corner-too-large"],
        "cycle:corner_too_large",
    )
}

fn r_g75_narrow(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (_, d) = g75_size(&ctx, &g);
    let what = match rng.range(0, 2) {
        0 => {
            g.tool = Some(d + small(&ctx, rng.range(1, 20) * 100));
            "a tool I wider than the bottom D"
        }
        1 => {
            g.w = Some(d / 2 + small(&ctx, rng.range(1, 10) * 100));
            "an allowance W above half the bottom"
        }
        _ => {
            // The bottom corners fit (d/4 + d/4 <= d) but leave d/2 of it.
            g.corners[2] = Some(d / 4);
            g.corners[3] = Some(d / 4);
            g.tool = Some(d - 2 * (d / 4) + small(&ctx, rng.range(1, 10) * 100));
            "bottom corners D(r3) E(r4) leaving less than the tool's width"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 groove narrower than the tool: {what}"),
        &["refuse:g75-groove-narrower-than-tool"],
        "cycle:groove_narrower_than_tool",
    )
}

fn r_g75_ridges(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let (h, d) = g75_size(&ctx, &g);
    // Two to four layers; a tool (or a pointed one) under half the bottom,
    // so that layer 1 has plunges more than its width apart.
    g.layer = Some(ctx.xf() * (h * rng.range(30, 60) / 100).max(1));
    let tool = if rng.chance(30) { 0 } else { (d * rng.range(20, 40) / 100).max(1) };
    g.tool = (tool > 0).then_some(tool);
    g.step = tool + small(&ctx, rng.range(1, 10) * 100);
    g.j = rng.chance(50).then(|| u8::try_from(rng.range(0, 1)).unwrap_or(0));
    let lines = g75_program(rng, &ctx, &g);
    let what = if tool > 0 { "the tool I" } else { "a pointed tool" };
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 roughed in layers V with a step Q wider than {what} (R-G75RIDGE)"),
        &["refuse:g75-ridges-in-layers"],
        "cycle:ridges_in_layers",
    )
}

fn r_g75_word(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    let units = ctx.units();
    let over = rng.range(1, 1000);
    let what = match rng.range(0, 6) {
        0 => {
            g.retract = Some(cycleref::g75::max_small(units) + over);
            "R(e) above 99.999 (99.9999 at IS-C)"
        }
        1 => {
            g.u = Some(-ctx.xf() * small(&ctx, rng.range(1, 5) * 100));
            "a negative U (unsigned)"
        }
        2 => {
            g.w = Some(-small(&ctx, rng.range(1, 5) * 100));
            "a negative W (unsigned)"
        }
        3 => {
            g.layer = Some(0);
            "V0"
        }
        4 => {
            g.corners[rng.index(4)] = Some(cycleref::g75::max_small(units) + over);
            "a corner size above 99.999 (99.9999 at IS-C)"
        }
        5 => {
            if rng.chance(50) {
                g.peck = 0;
                "P0"
            } else {
                g.step = 0;
                "Q0"
            }
        }
        _ => {
            g.depth = g.depth.signum() * (cycleref::g75::max_size(units) + over);
            "H beyond 9999.999 (9999.9999 at IS-C)"
        }
    };
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        format!("G75.1 with a word outside the manual's range: {what}"),
        &["refuse:g75-word-out-of-range"],
        "cycle:word_out_of_range",
    )
}

fn r_g75_no_depth(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    g.depth = 0;
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(ctx, lines, "G75.1 with H0".into(), &["refuse:g75-no-depth"], "cycle:no_groove_depth")
}

fn r_g75_too_many_pecks(rng: &mut Rng) -> Draft {
    let (ctx, mut g) = g75_base(rng);
    // Pecks of one or two increments into a depth of 2000 or more of them,
    // at a thousand plunges or more: above MAX_PECKS (10^6).
    g.peck = rng.range(1, 2);
    g.step = rng.range(1, 2);
    g.depth = g.depth.signum() * g.peck * rng.range(2000, 4000);
    g.width = g.width.signum() * g.step * rng.range(1000, 2000);
    g.j = rng.chance(50).then(|| u8::try_from(rng.range(0, 1)).unwrap_or(0));
    let lines = g75_program(rng, &ctx, &g);
    Draft::refused(
        ctx,
        lines,
        "G75.1 needing more than a million pecks (P and Q of one or two increments)".into(),
        &["refuse:g75-too-many-pecks"],
        "cycle:too_many_pecks",
    )
}

// ---- the template schedule ----

type Make = fn(&mut Rng) -> Draft;

/// Valid templates, in the order the valid slots use them.
const VALID: &[Make] = &[
    v_basic,
    v_d1,
    v_d2,
    v_lead_in,
    v_multi_start,
    v_runout_980,
    v_runout_988,
    v_chamfer,
    v_x_long,
    v_g32_passes,
    v_one_pass,
    v_min_cut,
    v_exact,
    v_d_equals_k,
    v_g32_face,
    v_i_lead,
    v_params_modal,
    v_g32_runout_980,
    v_fanuc_bare,
    v_partial_p,
    v_g32_continuous,
    v_taper,
    v_runout_988_k_only,
    v_g32_runout_988,
    v_fanuc_calc,
    v_g75_seed,
    v_g75_square,
    v_g75_corners,
    v_g75_slope,
    v_g75_internal,
];

/// Templates of refused programs, in the order the refused slots use them.
const REFUSED: &[Make] = &[
    r_missing_p,
    r_missing_q,
    r_min_cut,
    r_allowance,
    r_run_out_long,
    r_no_spindle,
    r_face_thread,
    r_out_of_range,
    r_fanuc_point,
    r_partial_p,
    r_address,
    r_g32_no_end,
    r_g32_zero_lead,
    r_too_many,
    r_start_inside,
    r_too_short,
    r_lead_in_x,
    r_g32_no_motion,
    r_g32_run_out_long,
    r_not_in_increments,
    r_position_unknown,
    r_pass_out_of_range,
    r_unit_change,
    r_misc,
    r_g75_missing,
    r_g75_lone,
    r_g75_angle,
    r_g75_slope,
    r_g75_allowance,
    r_g75_corner,
    r_g75_narrow,
    r_g75_ridges,
    r_g75_word,
    r_g75_no_depth,
    r_g75_too_many_pecks,
];

/// The template of case `index` (1-based): slots 2 and 4 of every 5 are
/// refused programs, the others valid ones; each kind cycles through its
/// list.
fn template(index: u32) -> Make {
    let s = usize::try_from(index - 1).unwrap_or(0);
    let (group, pos) = (s / 5, s % 5);
    match pos {
        1 | 3 => REFUSED[(group * 2 + usize::from(pos == 3)) % REFUSED.len()],
        _ => VALID[(group * 3 + pos / 2) % VALID.len()],
    }
}

// ---- checking a draft ----

/// What a program does: the cycles' JSON, or the first error.
struct Evaluated {
    outcome: Result<(Units, Vec<Value>), ProgramError>,
    tags: BTreeSet<String>,
    moves: usize,
}

/// Reads and expands a program with both engines.
///
/// # Errors
///
/// A message naming the case when the engine and the reference differ.
fn evaluate(id: &str, machine: &Machine, text: &str) -> Result<Evaluated, String> {
    let mut tags = BTreeSet::new();
    let program = match read(text, machine) {
        Ok(p) => p,
        Err(e) => return Ok(Evaluated { outcome: Err(e), tags, moves: 0 }),
    };
    let mut cycles = Vec::new();
    let mut count = 0;
    for item in &program.items {
        let Some(cycle) = Cycle::of(item) else { continue };
        let engine = expand(cycle, Engine::Impl).map(Iterator::collect::<Vec<_>>);
        let reference = expand(cycle, Engine::Spec).map(Iterator::collect::<Vec<_>>);
        same(id, cycle.code(), cycle.line(), &engine, &reference)?;
        match engine {
            Ok(moves) => {
                match cycle {
                    Cycle::G76(call) => g76_tags(call, &moves, &mut tags),
                    Cycle::G32(call) => g32_tags(call, &moves, &mut tags),
                    Cycle::G75(call) => g75_tags(call, &moves, &mut tags),
                }
                count += moves.len();
                let typed = expand(cycle, Engine::Impl).map_err(|e| format!("{id}: {e}"))?;
                cycles.push(serde_json::to_value(CycleJson::new(cycle, typed)).map_err(|e| e.to_string())?);
            }
            Err(e) => {
                let error = ProgramError { line: cycle.line(), word: None, kind: ErrorKind::Cycle(e) };
                return Ok(Evaluated { outcome: Err(error), tags, moves: count });
            }
        }
    }
    Ok(Evaluated { outcome: Ok((program.units, cycles)), tags, moves: count })
}

/// The differential check: the engine must equal the reference.
fn same(
    id: &str,
    cycle: &str,
    line: usize,
    engine: &Result<Vec<Move>, CycleError>,
    reference: &Result<Vec<Move>, CycleError>,
) -> Result<(), String> {
    if engine == reference {
        return Ok(());
    }
    let detail = match (engine, reference) {
        (Ok(a), Ok(b)) => {
            let i = a.iter().zip(b).position(|(x, y)| x != y).unwrap_or(a.len().min(b.len()));
            format!(
                "{} moves against {}; first difference at move {}: engine {:?}, reference {:?}",
                a.len(),
                b.len(),
                i + 1,
                a.get(i),
                b.get(i)
            )
        }
        (a, b) => format!(
            "engine {:?}, reference {:?}",
            a.as_ref().map(Vec::len).map_err(|e| e.to_string()),
            b.as_ref().map(Vec::len).map_err(|e| e.to_string())
        ),
    };
    Err(format!("{id}: {cycle} at line {line}: the engine and the reference model differ: {detail}"))
}

fn units_json(u: Units) -> Value {
    serde_json::to_value(UnitsJson::new(u)).unwrap_or(Value::Null)
}

fn tag(tags: &mut BTreeSet<String>, t: &str) {
    tags.insert(t.to_string());
}

/// The features a valid G76 shows, read from the cycle and its moves.
fn g76_tags(call: &G76Call, moves: &[Move], tags: &mut BTreeSet<String>) {
    let c = &call.cycle;
    tag(tags, "g76");
    let xc = c.end.x + c.x_mode.factor() * c.taper;
    tag(tags, if c.start.x > xc { "thread:external" } else { "thread:internal" });
    tag(tags, if c.end.z < c.start.z { "direction:-z" } else { "direction:+z" });
    let w = (c.end.z - c.start.z).abs();
    tag(
        tags,
        if c.taper == 0 {
            "taper:straight"
        } else if w > c.taper.abs() {
            "taper:z-long"
        } else {
            "taper:x-long"
        },
    );
    tag(tags, if c.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
    tag(
        tags,
        match c.infeed {
            Infeed::RightFlank => "infeed:D0",
            Infeed::RightCentre => "infeed:D1",
            Infeed::LeftRight => "infeed:D2",
        },
    );
    if c.lead_in > 0 {
        tag(tags, "lead-in");
    }
    if c.starts > 1 {
        tag(tags, "multi-start");
    }
    match c.run_out {
        RunOut::None => tag(tags, "run-out:none"),
        RunOut::Amounts { long: 0, .. } => tag(tags, "run-out:pull-out"),
        RunOut::Amounts { .. } => tag(tags, "run-out:amounts"),
        RunOut::Chamfer { long, angle_degrees, .. } => {
            tag(tags, if long.is_some() { "run-out:chamfer+k" } else { "run-out:chamfer" });
            if angle_degrees != 45 {
                tag(tags, "run-out:chamfer-angle");
            }
        }
    }
    match c.finishing_passes {
        0 => tag(tags, "finish:none"),
        1 => {}
        _ => tag(tags, "finish:multiple"),
    }
    // The rough levels of start 1, in order (D2 cuts two passes per level).
    let mut levels: Vec<i64> = Vec::new();
    for m in moves.iter().filter(|m| m.role == Role::Approach) {
        if let Some(p) = m.pass.filter(|p| p.kind == PassKind::Rough && p.start == 1) {
            if levels.last() != Some(&p.depth) {
                levels.push(p.depth);
            }
        }
    }
    let target = c.thread_height - c.finishing_allowance;
    if target == 0 {
        tag(tags, "schedule:d-equals-k");
    }
    if levels.len() == 1 {
        tag(tags, "schedule:one-pass");
    }
    let q = u128::try_from(c.first_depth).unwrap_or(0);
    let law = |n: usize| {
        i64::try_from(cycleref::engine::round_sqrt(q * q * u128::try_from(n).unwrap_or(0)))
            .unwrap_or(i64::MAX)
    };
    let step = c.min_cut.max(1);
    for n in 2..=levels.len() {
        let clamp = levels[n - 2] + step;
        if c.min_cut > 0 && law(n) < clamp && clamp < target {
            tag(tags, "schedule:min-cut");
        }
    }
    if !levels.is_empty() && law(levels.len()) == target {
        tag(tags, "schedule:exact-k-d");
    }
}

/// The features a valid G32 block shows.
fn g32_tags(call: &G32Call, moves: &[Move], tags: &mut BTreeSet<String>) {
    let b = &call.g32;
    tag(tags, "g32");
    let (dx, dz) = (b.end.x - b.start.x, b.end.z - b.start.z);
    tag(
        tags,
        if dx == 0 {
            "g32:straight"
        } else if dz == 0 {
            "g32:face"
        } else {
            "g32:taper"
        },
    );
    if dx != 0 && dz != 0 && dz.abs() * b.x_mode.factor() <= dx.abs() {
        tag(tags, "g32:x-long");
    }
    tag(tags, if b.lead.word == LeadWord::F { "lead:F" } else { "lead:I" });
    match b.run_out {
        G32RunOut::None => {}
        G32RunOut::Amounts { long: 0, .. } => tag(tags, "g32:pull-out"),
        G32RunOut::Amounts { .. } => tag(tags, "g32:run-out"),
    }
    if !b.sync {
        tag(tags, "g32:continuous");
    }
    if b.sync && !b.start_angle.is_zero() && !moves.is_empty() {
        tag(tags, "g32:q");
    }
}

/// The features a valid G75.1 shows, read from the cycle and its moves.
fn g75_tags(call: &G75Call, moves: &[Move], tags: &mut BTreeSet<String>) {
    let c = &call.cycle;
    tag(tags, "g75");
    tag(tags, if c.depth < 0 { "g75:-x" } else { "g75:+x" });
    tag(tags, if c.width < 0 { "g75:-z" } else { "g75:+z" });
    if c.flank_a != RIGHT_ANGLE || c.flank_b != RIGHT_ANGLE {
        tag(tags, "g75:angled");
    }
    if c.slope > 0 {
        tag(tags, "g75:slope");
    }
    tag(
        tags,
        match c.path {
            PathType::Rough => "g75:j0",
            PathType::RoughAndFinish => "g75:j1",
            PathType::Finish => "g75:j2",
        },
    );
    if c.allowance_x > 0 || c.allowance_z > 0 {
        tag(tags, "g75:allowances");
    }
    if c.tool_width.is_some_and(|w| w > 0) {
        tag(tags, "g75:tool-width");
    }
    if moves.iter().any(|m| matches!(m.role, Role::LayerChange(_))) {
        tag(tags, "g75:layers");
    }
    if moves.iter().any(|m| matches!(m.role, Role::PeckRetract(_))) {
        tag(tags, "g75:pecking");
    }
    if c.corners.iter().any(|k| k.size > 0) {
        tag(tags, "g75:corners");
    }
    if c.path.finishes() && c.corners.iter().any(|k| k.size > 0 && k.kind == CornerKind::Chamfer) {
        tag(tags, "g75:chamfers");
    }
    if moves.iter().any(|m| matches!(m.motion, Motion::Arc { .. })) {
        tag(tags, "g75:arcs");
    }
}

// ---- a case ----

/// A case ready to write.
struct Case {
    id: String,
    description: String,
    tags: Vec<String>,
    /// The expected error kind, for a refused program.
    kind: Option<String>,
    json: Value,
}

fn make_case(seed: u64, index: u32) -> Result<Case, String> {
    let id = format!("case-{index:04}");
    let mut rng = Rng::for_case(seed, index);
    let make = template(index);
    for _ in 0..ATTEMPTS {
        let draft = make(&mut rng);
        let (toml, machine_json) = draft.ctx.settings();
        let mut machine = Machine::new(draft.ctx.profile);
        machine
            .apply_toml(&toml)
            .map_err(|e| format!("{id}: the generated parameter file is refused: {e}"))?;
        let mut program = draft.lines.join("\n");
        program.push('\n');
        let ev = evaluate(&id, &machine, &program)?;
        let fits = match (&draft.intent, &ev.outcome) {
            (Intent::Valid(required), Ok(_)) => {
                ev.moves > 0 && ev.moves <= MAX_MOVES && required.iter().all(|t| ev.tags.contains(*t))
            }
            (Intent::Refused(kind), Err(e)) => kind_name(&e.kind) == *kind,
            _ => false,
        };
        if !fits {
            continue;
        }
        let ctx = &draft.ctx;
        let mut tags: BTreeSet<String> = draft.tags.iter().cloned().collect();
        tags.insert(format!("profile:{}", ctx.profile));
        tags.insert(
            match ctx.increment {
                IncrementSystem::IsB => "increment:is-b",
                IncrementSystem::IsC => "increment:is-c",
            }
            .into(),
        );
        tags.insert(if ctx.unit == InputUnit::Metric { "unit:mm" } else { "unit:inch" }.into());
        if ctx.g20 {
            tags.insert("unit:g20".into());
        }
        tags.insert(if ctx.x == XMode::Diameter { "x:diameter" } else { "x:radius" }.into());
        tags.insert(if ctx.pq_in_increments() { "pq:increments" } else { "pq:mm" }.into());
        if ctx.calculator_input {
            tags.insert("fanuc:calculator-input".into());
        }
        if ctx.bare {
            tags.insert("fanuc:bare-increments".into());
        }
        let (expect, kind) = match ev.outcome {
            Ok((units, cycles)) => {
                tags.insert("valid".into());
                tags.extend(ev.tags);
                (json!({"units": units_json(units), "moves": cycles}), None)
            }
            Err(e) => {
                let kind = kind_name(&e.kind);
                tags.insert("refused".into());
                tags.insert(format!("error:{kind}"));
                let error = json!({"line": e.line, "word": e.word, "kind": kind, "message": e.to_string()});
                (json!({ "error": error }), Some(kind))
            }
        };
        let tags: Vec<String> = tags.into_iter().collect();
        let json = json!({
            "schema": CASE_SCHEMA,
            "id": id,
            "seed": seed,
            "index": index,
            "description": draft.description,
            "tags": tags,
            "profile": ctx.profile.to_string(),
            "machine": machine_json,
            "machine_toml": toml,
            "program": program,
            "expect": expect,
        });
        return Ok(Case { id, description: draft.description, tags, kind, json });
    }
    Err(format!("{id}: no draft of its template fitted in {ATTEMPTS} attempts"))
}

// ---- JSON text ----

/// Pretty JSON with one move (and one list of scalars, one flat object) per
/// line: readable, diffable, and a third of the size of full pretty printing.
fn to_text(v: &Value) -> String {
    let mut s = String::new();
    write_value(v, 0, &mut s);
    s.push('\n');
    s
}

fn scalar(v: &Value) -> bool {
    !v.is_object() && !v.is_array()
}

fn write_value(v: &Value, indent: usize, out: &mut String) {
    let compact = match v {
        Value::Object(m) => m.contains_key("motion") || m.values().all(scalar),
        Value::Array(a) => a.iter().all(scalar),
        _ => true,
    };
    if compact {
        out.push_str(&serde_json::to_string(v).unwrap_or_default());
        return;
    }
    let pad = " ".repeat(indent + 2);
    match v {
        Value::Object(m) => {
            out.push_str("{\n");
            for (n, (key, val)) in m.iter().enumerate() {
                out.push_str(&pad);
                out.push_str(&serde_json::to_string(key).unwrap_or_default());
                out.push_str(": ");
                write_value(val, indent + 2, out);
                out.push_str(if n + 1 < m.len() { ",\n" } else { "\n" });
            }
            out.push_str(&" ".repeat(indent));
            out.push('}');
        }
        Value::Array(a) => {
            out.push_str("[\n");
            for (n, val) in a.iter().enumerate() {
                out.push_str(&pad);
                write_value(val, indent + 2, out);
                out.push_str(if n + 1 < a.len() { ",\n" } else { "\n" });
            }
            out.push_str(&" ".repeat(indent));
            out.push(']');
        }
        _ => {}
    }
}
