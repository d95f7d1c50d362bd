//! `cycleref vectors`: a corpus of conformance vectors.
//!
//! Each case is a program, the machine it runs on (profile, increment
//! system, unit, X mode, calculator-type input, pass limit and every
//! parameter) and what the manual says must happen: the moves of every
//! cycle, exactly as `cycleref expand --format json` prints them, or the
//! alarm (line, stable kind name, message). The schema, the tags and the
//! way a vendor uses the files are documented in `vectors/README.md`.
//!
//! # How a case is made
//!
//! 1. **Seed.** Case `i` draws from a pseudo-random stream that depends
//!    only on `(seed, i)` (`Rng`: splitmix64, no floating point, no hash
//!    maps), so the same count and seed give the same bytes and a larger
//!    count extends a smaller one.
//! 2. **Template.** The template of case `i` depends on `i` alone
//!    (`template`): 3 slots in 5 take the valid templates of `TEMPLATES`
//!    in turn, 2 in 5 the refused ones, and the first 125 cases (the
//!    checked-in corpus) use every template at least once. A template is
//!    one `Template` entry, declared beside its generator in the module of
//!    its cycle (`g76`, `g32`, `g75`, `g92`, `linuxcnc`) or in `refused`: its id, what it must
//!    turn out to be (`Expected`: valid with some features, or refused with
//!    an error kind the compiler checks), its tags and description, and the
//!    generator.
//! 3. **Draft.** The generator writes a `Draft`: the machine
//!    (`machine::MachineStyle`, also the style the words are written in) and the
//!    program's lines, with what the variant it drew adds to the entry.
//! 4. **Evaluation.** The program is read and every cycle expanded by both
//!    the fixed-point engine and the exact reference model (`evaluate`);
//!    a cycle where the two differ is not written: the run fails naming
//!    the case, so the generator is a differential check as well as a
//!    corpus writer. The features a valid program shows are read from its
//!    cycles and moves (each cycle module's `tags`).
//! 5. **Fit.** A draft that is not what its entry expects (a refusal of
//!    another kind, too many moves, a feature missing) is dropped and the
//!    generator drafts again from where the stream is, up to `ATTEMPTS`
//!    times.
//! 6. **Writing.** The case (`make_case`: a typed `CaseJson`, the
//!    `cycleref-vector/1` document, whose expected moves are the cycles of
//!    `expand --format json`) is written by the one JSON serializer in the
//!    corpus's layout of lines ([`crate::json::ser::to_writer_lines`]: a
//!    move, a point, a list of tags, a flat object a line), and
//!    `index.json` lists them all.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use cycleref::{IncrementSystem, InputUnit, Units, XMode};
use cycleref_spec::{read, ErrorKind, Machine, ProfileName, ProgramError};

use crate::json::{ser, CycleJson, OneLine, UnitsJson};
use cycleref_spec::pipeline::{expand, Cycle, Engine};

mod g32;
mod g75;
mod g76;
mod g78;
mod g92;
mod linuxcnc;
mod machine;
mod refused;

use machine::MachineStyle;

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
pub fn run(count: u32, seed: u64, out: &Path) -> Result<String, VectorsError> {
    if out.exists() && !out.is_dir() {
        return Err(VectorsError::NotADirectory { out: out.to_path_buf() });
    }
    std::fs::create_dir_all(out)
        .map_err(|source| VectorsError::CannotCreate { out: out.to_path_buf(), source })?;
    let mut entries = Vec::new();
    let mut tag_counts: BTreeMap<String, u32> = BTreeMap::new();
    let mut files = BTreeSet::new();
    let (mut valid, mut refused) = (0_u32, 0_u32);
    for index in 1..=count {
        let case = make_case(seed, index)?;
        let file = format!("{}.json", case.id);
        std::fs::write(out.join(&file), to_text(&case.json))
            .map_err(|source| VectorsError::CannotWrite { path: out.join(&file), source })?;
        for t in &case.tags {
            *tag_counts.entry(t.clone()).or_default() += 1;
        }
        if case.kind.is_some() {
            refused += 1;
        } else {
            valid += 1;
        }
        entries.push(IndexEntryJson {
            id: case.id,
            file: file.clone(),
            description: case.description,
            expect: if case.kind.is_some() { "error" } else { "moves" },
            kind: case.kind,
            tags: OneLine(case.tags),
        });
        files.insert(file);
    }
    remove_stale(out, &files)?;
    let index = IndexJson { schema: INDEX_SCHEMA, seed, count, tags: OneLine(tag_counts), cases: entries };
    std::fs::write(out.join("index.json"), to_text(&index))
        .map_err(|source| VectorsError::CannotWrite { path: out.join("index.json"), source })?;
    Ok(format!(
        "wrote {count} cases ({valid} with moves, {refused} refused) and index.json to {}\n",
        out.display()
    ))
}

/// Case `index` (1-based) of the corpus generated from `seed`: the text of
/// its `case-NNNN.json` file, exactly as [`run`] writes it (for library
/// users that take cases one at a time, such as the Python package).
///
/// # Errors
///
/// As [`run`]: the engine and the reference model disagree on the case,
/// or no draft of its template fits.
///
/// ```
/// // Case 2 of every seed is a program that must be refused.
/// let case: serde_json::Value = serde_json::from_str(&cycleref_cli::vectors::case_text(1, 2)?).unwrap();
/// assert_eq!(case["id"], "case-0002");
/// assert!(case["expect"]["error"]["kind"].is_string());
/// # Ok::<(), cycleref_cli::vectors::VectorsError>(())
/// ```
pub fn case_text(seed: u64, index: u32) -> Result<String, VectorsError> {
    Ok(to_text(&make_case(seed, index)?.json))
}

/// Removes `case-NNNN.json` files of an earlier, larger run.
fn remove_stale(out: &Path, keep: &BTreeSet<String>) -> Result<(), VectorsError> {
    let dir =
        std::fs::read_dir(out).map_err(|source| VectorsError::Io { path: out.to_path_buf(), source })?;
    for entry in dir.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let is_case = name
            .strip_prefix("case-")
            .and_then(|n| n.strip_suffix(".json"))
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
        if is_case && !keep.contains(&name) {
            std::fs::remove_file(entry.path())
                .map_err(|source| VectorsError::Io { path: entry.path(), source })?;
        }
    }
    Ok(())
}

// ---- stable names of the error kinds ----

/// The stable name of what is wrong with a program, as written in the
/// `expect.error.kind` field: [`ErrorKind::name`], and for a cycle alarm
/// `cycle:` and [`CycleError::name`](cycleref::CycleError::name).
pub fn kind_name(kind: &ErrorKind) -> String {
    kind.stable_kind()
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

// ---- templates and drafts ----

/// Whether an error is of the kind a template expects: a `matches!` over
/// the reader's [`ErrorKind`], a cycle's alarm being
/// `ErrorKind::Cycle(CycleError::…)`, so that the compiler checks every
/// kind a template names. A kind's stable name ([`kind_name`], the one the
/// corpus writes) is one per variant, so matching the variant is matching
/// the name.
type Refusal = fn(&ErrorKind) -> bool;

/// What every case of a template must turn out to be.
enum Expected {
    /// A valid program of 1 to [`MAX_MOVES`] moves whose computed tags
    /// include these.
    Valid(&'static [&'static str]),
    /// A program refused with an error of this kind.
    Refused(Refusal),
}

/// One template: an entry of [`TEMPLATES`], declared beside its generator.
struct Template {
    /// Names the template in messages (unique).
    id: &'static str,
    /// What its cases must be; a draft that is not is drafted again.
    outcome: Expected,
    /// Tags every case of the template carries: its `template:` or
    /// `refuse:` tag first, then the rules it shows.
    tags: &'static [&'static str],
    /// The description of its cases, unless the draft writes its own
    /// naming the variant it drew.
    description: &'static str,
    /// The generator: one draft from the case's stream.
    generate: fn(&mut Rng) -> Draft,
}

/// One case as a generator drafts it, before it is checked: the machine,
/// the program, and what the variant drawn adds to its template's entry.
struct Draft {
    ctx: MachineStyle,
    lines: Vec<String>,
    /// The case's description, when the variant drawn has its own.
    description: Option<String>,
    /// Tags of the variant drawn, beside the template's.
    tags: Vec<&'static str>,
    /// Features the variant drawn must show, beside the template's.
    requires: &'static [&'static str],
    /// The kind the variant drawn must be refused with, where the
    /// template's allows several.
    refusal: Option<Refusal>,
}

impl Draft {
    fn new(ctx: MachineStyle, lines: Vec<String>) -> Draft {
        Draft { ctx, lines, description: None, tags: Vec::new(), requires: &[], refusal: None }
    }

    fn described(mut self, description: String) -> Draft {
        self.description = Some(description);
        self
    }

    /// Adds `tag` when `on`.
    fn tag_if(mut self, on: bool, tag: &'static str) -> Draft {
        if on {
            self.tags.push(tag);
        }
        self
    }

    fn requiring(mut self, tags: &'static [&'static str]) -> Draft {
        self.requires = tags;
        self
    }

    fn refused_as(mut self, kind: Refusal) -> Draft {
        self.refusal = Some(kind);
        self
    }
}

// ---- the template schedule ----

/// Every template. The valid ones take the valid slots in this order, the
/// refused ones the refused slots. Case `i`'s template depends on this
/// list: reordering it or adding a template changes the corpus, and the
/// checked-in one is then written again (`vectors/README.md`).
const TEMPLATES: &[&Template] = &[
    &g76::BASIC,
    &g76::D1,
    &g76::D2,
    &g76::LEAD_IN,
    &g76::MULTI_START,
    &g76::RUNOUT_980,
    &g76::RUNOUT_988,
    &g76::CHAMFER,
    &g76::X_LONG,
    &g32::PASSES,
    &g76::ONE_PASS,
    &g76::MIN_CUT,
    &g76::EXACT,
    &g76::D_EQUALS_K,
    &g32::FACE,
    &g76::I_LEAD,
    &g76::PARAMS_MODAL,
    &g32::RUNOUT_980,
    &g76::FANUC_BARE,
    &g76::PARTIAL_P,
    &g32::CONTINUOUS,
    &g76::TAPER,
    &g76::RUNOUT_988_K_ONLY,
    &g32::RUNOUT_988,
    &g76::FANUC_CALC,
    &g75::SEED,
    &g75::SQUARE,
    &g75::CORNERS,
    &g75::SLOPE,
    &g75::INTERNAL,
    &g92::PASSES,
    &g92::RUNOUT_980,
    &g92::RUNOUT_988,
    &g92::MULTI_START,
    &g92::X_LONG,
    &g92::FACE,
    &g78::GSK988,
    &g78::GSK980,
    &linuxcnc::G76,
    &g92::HIGH_SPEED,
    &refused::MISSING_P,
    &refused::MISSING_Q,
    &refused::MIN_CUT,
    &refused::ALLOWANCE,
    &refused::RUN_OUT_LONG,
    &refused::NO_SPINDLE,
    &refused::FACE_THREAD,
    &refused::OUT_OF_RANGE,
    &refused::FANUC_POINT,
    &refused::PARTIAL_P,
    &refused::ADDRESS,
    &refused::G32_NO_END,
    &refused::G32_ZERO_LEAD,
    &refused::TOO_MANY,
    &refused::START_INSIDE,
    &refused::TOO_SHORT,
    &refused::LEAD_IN_X,
    &refused::G32_NO_MOTION,
    &refused::G32_RUN_OUT_LONG,
    &refused::NOT_IN_INCREMENTS,
    &refused::POSITION_UNKNOWN,
    &refused::PASS_OUT_OF_RANGE,
    &refused::UNIT_CHANGE,
    &refused::MISC,
    &refused::G75_MISSING,
    &refused::G75_LONE,
    &refused::G75_ANGLE,
    &refused::G75_SLOPE,
    &refused::G75_ALLOWANCE,
    &refused::G75_CORNER,
    &refused::G75_NARROW,
    &refused::G75_RIDGES,
    &refused::G75_WORD,
    &refused::G75_NO_DEPTH,
    &refused::G75_TOO_MANY_PECKS,
    &g92::TAPER_BEYOND,
    &g92::NO_INFEED,
    &g92::RUN_OUT_INTO_WORK,
    &g78::INFEED_RANGE,
    &linuxcnc::REFUSED,
    &g92::RUN_OUT_LONG,
    &g92::FACE_THREAD,
    &g92::NO_THREAD_LENGTH,
    &g92::STEEP_FACE,
    &g92::STARTS_RANGE,
    &g92::P_RANGE,
    &g78::GSK980_M,
    &g78::GSK988_D,
    &g78::FACE_THREAD,
    &g78::MISSING,
    &g92::LONG_TABLE,
];

/// The templates of one kind (refused or valid), in schedule order.
fn templates(refused: bool) -> Vec<&'static Template> {
    TEMPLATES.iter().copied().filter(|t| matches!(t.outcome, Expected::Refused(_)) == refused).collect()
}

/// The template of case `index` (1-based): slots 2 and 4 of every 5 are
/// refused programs, the others valid ones; each kind cycles through its
/// templates.
fn template(index: u32) -> &'static Template {
    let s = usize::try_from(index - 1).unwrap_or(0);
    let (group, pos) = (s / 5, s % 5);
    let (pool, n) = match pos {
        1 | 3 => (templates(true), group * 2 + usize::from(pos == 3)),
        _ => (templates(false), group * 3 + pos / 2),
    };
    pool[n % pool.len()]
}

/// How many times case `index`'s (1-based) template came before it in the
/// schedule ([`template`]): 0 for its first case.
fn round(index: u32) -> usize {
    let s = usize::try_from(index - 1).unwrap_or(0);
    let (group, pos) = (s / 5, s % 5);
    match pos {
        1 | 3 => (group * 2 + usize::from(pos == 3)) / templates(true).len(),
        _ => (group * 3 + pos / 2) / templates(false).len(),
    }
}

// ---- checking a draft ----

/// What a program does: the cycles' JSON, or the first error.
struct Evaluated {
    outcome: Result<(Units, Vec<CycleJson>), ProgramError>,
    tags: BTreeSet<String>,
    moves: usize,
    /// Every move of every cycle made, in order (to tell two outcomes
    /// apart: the JSON of the cycles streams once).
    all: Vec<cycleref::Move>,
}

/// Reads and expands a program with both engines.
///
/// # Errors
///
/// A message naming the case when the engine and the reference differ.
fn evaluate(id: &str, machine: &Machine, text: &str) -> Result<Evaluated, VectorsError> {
    let mut tags = BTreeSet::new();
    let program = match read(text, machine) {
        Ok(p) => p,
        Err(e) => return Ok(Evaluated { outcome: Err(e), tags, moves: 0, all: Vec::new() }),
    };
    let mut cycles = Vec::new();
    let mut count = 0;
    let mut all = Vec::new();
    for item in &program.items {
        let Some(cycle) = Cycle::of(item) else { continue };
        let engine = expand(cycle, Engine::Impl).map(Iterator::collect::<Vec<_>>);
        let reference = expand(cycle, Engine::Spec).map(Iterator::collect::<Vec<_>>);
        cycleref_spec::differ::compare(&engine, &reference).map_err(|difference| {
            VectorsError::EnginesDiffer {
                id: id.to_string(),
                code: cycle.code(),
                line: cycle.line(),
                difference: Box::new(difference),
            }
        })?;
        match engine {
            Ok(moves) => {
                cycle.tags(&moves, &mut |t| tag(&mut tags, t));
                count += moves.len();
                all.extend_from_slice(&moves);
                let typed = expand(cycle, Engine::Impl)
                    .map_err(|error| VectorsError::Expansion { id: id.to_string(), error })?;
                cycles.push(CycleJson::new(cycle, typed));
            }
            Err(e) => {
                let error = ProgramError { line: cycle.line(), word: None, kind: ErrorKind::Cycle(e) };
                return Ok(Evaluated { outcome: Err(error), tags, moves: count, all });
            }
        }
    }
    Ok(Evaluated { outcome: Ok((program.units, cycles)), tags, moves: count, all })
}

fn tag(tags: &mut BTreeSet<String>, t: &str) {
    tags.insert(t.to_string());
}

// ---- a case ----

/// A case ready to write.
struct Case {
    id: String,
    description: String,
    tags: Vec<String>,
    /// The expected error kind, for a refused program.
    kind: Option<String>,
    json: CaseJson,
}

/// Case `index`: drafts of its template until one is what the template's
/// entry expects.
fn make_case(seed: u64, index: u32) -> Result<Case, VectorsError> {
    let id = format!("case-{index:04}");
    let mut rng = Rng::for_case(seed, index);
    let template = template(index);
    for _ in 0..ATTEMPTS {
        let draft = (template.generate)(&mut rng);
        let mut program = draft.lines.join("\n");
        program.push('\n');
        let ev = evaluate(&id, &machine_of(&id, &draft.ctx)?, &program)?;
        let fits = match (&template.outcome, &ev.outcome) {
            (Expected::Valid(required), Ok(_)) => {
                ev.moves > 0
                    && ev.moves <= MAX_MOVES
                    && required.iter().chain(draft.requires).all(|t| ev.tags.contains(*t))
            }
            (Expected::Refused(kind), Err(e)) => kind(&e.kind) && draft.refusal.is_none_or(|k| k(&e.kind)),
            _ => false,
        };
        if !fits {
            continue;
        }
        // Every other round of the schedule is tried under the readings:
        // each template's first case is made under the defaults.
        let (draft, ev) = if round(index) % 2 == 1 {
            under_a_reading(seed, index, &id, draft, &program, ev)?
        } else {
            (draft, ev)
        };
        let (toml, machine_json) = draft.ctx.settings();
        let ctx = &draft.ctx;
        let description = draft.description.unwrap_or_else(|| template.description.to_string());
        let mut tags: BTreeSet<String> =
            template.tags.iter().chain(&draft.tags).map(|t| (*t).to_string()).collect();
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
        // P(k) and Q are G76 words of the FANUC-style profiles only.
        if ctx.profile != ProfileName::LinuxCnc {
            tags.insert(if ctx.pq_in_increments() { "pq:increments" } else { "pq:mm" }.into());
        }
        if ctx.calculator_input {
            tags.insert("fanuc:calculator-input".into());
        }
        if ctx.bare {
            tags.insert("fanuc:bare-increments".into());
        }
        for (id, value) in ctx.readings.non_default(ctx.profile) {
            tags.insert(format!("reading:{id}={value}"));
        }
        let (expect, kind) = match ev.outcome {
            Ok((units, cycles)) => {
                tags.insert("valid".into());
                tags.extend(ev.tags);
                let expect = ExpectJson {
                    units: Some(OneLine(UnitsJson::new(units))),
                    moves: Some(cycles),
                    error: None,
                };
                (expect, None)
            }
            Err(e) => {
                let kind = kind_name(&e.kind);
                tags.insert("refused".into());
                tags.insert(format!("error:{kind}"));
                let message = e.to_string();
                let error = ErrorJson { line: e.line, word: e.word, kind: kind.clone(), message };
                (ExpectJson { units: None, moves: None, error: Some(OneLine(error)) }, Some(kind))
            }
        };
        let tags: Vec<String> = tags.into_iter().collect();
        let json = CaseJson {
            schema: CASE_SCHEMA,
            id: id.clone(),
            seed,
            index,
            description: description.clone(),
            tags: OneLine(tags.clone()),
            profile: ctx.profile.to_string(),
            machine: machine_json,
            machine_toml: toml,
            program,
            expect,
        };
        return Ok(Case { id, description, tags, kind, json });
    }
    Err(VectorsError::NoDraftFits { id, template: template.id, attempts: ATTEMPTS })
}

/// The machine of a draft, as its parameter file sets it.
fn machine_of(id: &str, ctx: &MachineStyle) -> Result<Machine, VectorsError> {
    let (toml, _) = ctx.settings();
    let mut machine = Machine::new(ctx.profile);
    machine.apply_toml(&toml).map_err(|error| VectorsError::ParamsRefused { id: id.to_string(), error })?;
    Ok(machine)
}

/// A case of an odd [`round`] is made under a reading other than the
/// default (issue 34) where one changes it: each non-default value of every
/// reading of [`TABLE`](cycleref_spec::readings::TABLE) that changes
/// anything on the case's profile is tried in an order drawn from a stream
/// of the case's own (so that the drafts stay those of the default
/// readings), and the first
/// that changes the outcome (other moves, another alarm, moves instead of
/// the alarm or the other way round; valid with at most [`MAX_MOVES`]
/// moves) is taken. Every value tried is a differential test of the two
/// engines under it ([`evaluate`]). A case that no value changes stays
/// under the defaults.
///
/// # Errors
///
/// As [`evaluate`].
fn under_a_reading(
    seed: u64,
    index: u32,
    id: &str,
    draft: Draft,
    program: &str,
    ev: Evaluated,
) -> Result<(Draft, Evaluated), VectorsError> {
    let mut rng = Rng::for_case(seed ^ READINGS_STREAM, index);
    let profile = draft.ctx.profile;
    let mut values: Vec<(&'static str, &'static str)> = cycleref_spec::readings::TABLE
        .iter()
        .filter(|e| e.profiles.contains(&profile))
        .flat_map(|e| {
            let default = e.default_on(profile);
            e.values.iter().filter(move |v| v.name != default).map(move |v| (e.id, v.name))
        })
        .collect();
    // Fisher-Yates, from the readings' own stream.
    for i in (1..values.len()).rev() {
        values.swap(i, rng.index(i + 1));
    }
    for (reading, value) in values {
        let mut ctx = draft.ctx.clone();
        // A value of the table: always accepted.
        if ctx.readings.set(reading, value).is_err() {
            continue;
        }
        let chosen = evaluate(id, &machine_of(id, &ctx)?, program)?;
        let small = chosen.outcome.is_err() || (chosen.moves > 0 && chosen.moves <= MAX_MOVES);
        if small && fingerprint(&chosen) != fingerprint(&ev) {
            return Ok((Draft { ctx, ..draft }, chosen));
        }
    }
    Ok((draft, ev))
}

/// Salt of the readings' stream ([`under_a_reading`]).
const READINGS_STREAM: u64 = 0x7265_6164_696e_6773;

/// What a case expects, to tell whether a reading changes it: the moves,
/// and the alarm if there is one.
fn fingerprint(ev: &Evaluated) -> (&[cycleref::Move], Option<String>) {
    (&ev.all, ev.outcome.as_ref().err().map(ToString::to_string))
}

// ---- the documents ----

/// `cycleref-vector/1`: one case (`vectors/README.md`,
/// `docs/schemas/cycleref-vector-1.schema.json`).
#[derive(serde::Serialize)]
struct CaseJson {
    schema: &'static str,
    id: String,
    seed: u64,
    index: u32,
    description: String,
    tags: OneLine<Vec<String>>,
    profile: String,
    machine: MachineJson,
    machine_toml: String,
    program: String,
    expect: ExpectJson,
}

/// What must happen: the units and the cycles with their moves, or the
/// error.
#[derive(serde::Serialize)]
struct ExpectJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    units: Option<OneLine<UnitsJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    moves: Option<Vec<CycleJson>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<OneLine<ErrorJson>>,
}

/// The expected error: its line, its word (or null), its stable kind and
/// its message.
#[derive(serde::Serialize)]
struct ErrorJson {
    line: usize,
    word: Option<String>,
    kind: String,
    message: String,
}

/// The machine a case runs on (its `machine` object; the same settings as
/// its parameter file).
#[derive(serde::Serialize)]
pub(super) struct MachineJson {
    pub(super) increment: &'static str,
    pub(super) unit: &'static str,
    pub(super) x: &'static str,
    pub(super) calculator_input: bool,
    pub(super) pass_limit: u32,
    /// Every parameter of the profile, by name in the profile's order.
    pub(super) parameters: OneLine<ParamsJson>,
    /// Every reading that changes anything on the profile (issue 34), by
    /// id in the order of `cycleref readings`, with its value.
    pub(super) readings: OneLine<ReadingsJson>,
}

/// The readings as an object, in the order given.
pub(super) struct ReadingsJson(pub(super) Vec<(&'static str, &'static str)>);

impl serde::Serialize for ReadingsJson {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap as _;
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (key, value) in &self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}

/// The parameters as an object, in the order given.
pub(super) struct ParamsJson(pub(super) Vec<(String, ParamJson)>);

impl serde::Serialize for ParamsJson {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap as _;
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for (key, value) in &self.0 {
            map.serialize_entry(key, value)?;
        }
        map.end()
    }
}

/// A parameter's value: an integer, or a length as a decimal string.
#[derive(serde::Serialize)]
#[serde(untagged)]
pub(super) enum ParamJson {
    /// An integer parameter.
    Int(i64),
    /// A length (`"0.5"`).
    Length(String),
}

/// `index.json` (`cycleref-vectors-index/1`).
#[derive(serde::Serialize)]
struct IndexJson {
    schema: &'static str,
    seed: u64,
    count: u32,
    tags: OneLine<BTreeMap<String, u32>>,
    cases: Vec<IndexEntryJson>,
}

/// A case as `index.json` lists it.
#[derive(serde::Serialize)]
struct IndexEntryJson {
    id: String,
    file: String,
    description: String,
    expect: &'static str,
    kind: Option<String>,
    tags: OneLine<Vec<String>>,
}

/// A document in the corpus's layout: pretty, one move (one point, one
/// list of tags, one flat object) a line — readable, diffable, and a
/// third of the size of full pretty printing.
fn to_text<T: serde::Serialize>(doc: &T) -> String {
    let mut out = Vec::new();
    // Written into memory, of values that always serialize: no error.
    let _ = ser::to_writer_lines(&mut out, doc);
    out.push(b'\n');
    String::from_utf8(out).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn template_ids_are_unique() {
        let ids: BTreeSet<&str> = TEMPLATES.iter().map(|t| t.id).collect();
        assert_eq!(ids.len(), TEMPLATES.len());
    }

    #[test]
    fn the_first_125_cases_use_every_template() {
        let used: BTreeSet<&str> = (1..=125).map(|i| template(i).id).collect();
        let all: BTreeSet<&str> = TEMPLATES.iter().map(|t| t.id).collect();
        assert_eq!(used, all);
    }

    /// Adding a cycle adds its templates (README, "Adding a cycle"): the
    /// valid templates' cases call every cycle of the registry.
    #[test]
    fn the_valid_templates_call_every_cycle_of_the_registry() {
        use cycleref_spec::pipeline::{Cycle, CYCLE_KINDS};
        let mut kinds = BTreeSet::new();
        for (i, t) in templates(false).into_iter().enumerate() {
            let index = u32::try_from(i).expect("few templates") + 1;
            let draft = (t.generate)(&mut Rng::for_case(1, index));
            let (toml, _) = draft.ctx.settings();
            let mut machine = Machine::new(draft.ctx.profile);
            machine.apply_toml(&toml).expect("the template's settings");
            let text = draft.lines.join("\n") + "\n";
            let program = cycleref_spec::read(&text, &machine).unwrap_or_else(|e| panic!("{}: {e}", t.id));
            kinds.extend(program.items.iter().filter_map(Cycle::of).map(Cycle::index));
        }
        assert_eq!(kinds, (0..CYCLE_KINDS).collect::<BTreeSet<_>>());
    }

    #[test]
    fn every_template_carries_its_tag_first() {
        for t in TEMPLATES {
            let prefix = match t.outcome {
                Expected::Valid(_) => "template:",
                Expected::Refused(_) => "refuse:",
            };
            assert!(t.tags.first().is_some_and(|tag| tag.starts_with(prefix)), "{}", t.id);
        }
    }
}

/// Why the corpus cannot be made or written.
#[derive(Debug)]
#[non_exhaustive]
pub enum VectorsError {
    /// `--out` names something that is not a directory.
    NotADirectory {
        /// The path given.
        out: PathBuf,
    },
    /// The output directory cannot be made.
    CannotCreate {
        /// The path given.
        out: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file cannot be written.
    CannotWrite {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The output directory cannot be listed, or an earlier case removed.
    Io {
        /// The directory or file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The engine and the reference model differ on a case's cycle: a
    /// defect of this project, never a valid corpus.
    EnginesDiffer {
        /// The case.
        id: String,
        /// The cycle's G code.
        code: &'static str,
        /// Its line.
        line: usize,
        /// How they differ.
        difference: Box<cycleref_spec::differ::Difference>,
    },
    /// A cycle that expanded once did not the second time (not expected).
    Expansion {
        /// The case.
        id: String,
        /// The alarm.
        error: cycleref::CycleError,
    },
    /// The parameter file a template generated is refused (a defect of the
    /// template).
    ParamsRefused {
        /// The case.
        id: String,
        /// Why.
        error: cycleref_spec::profile::ParamsError,
    },
    /// No draft of a case's template was what the template expects.
    NoDraftFits {
        /// The case.
        id: String,
        /// The template.
        template: &'static str,
        /// The drafts tried.
        attempts: u32,
    },
}

impl VectorsError {
    /// The stable kind: `vectors:not_a_directory`, `vectors:cannot_create`,
    /// `vectors:cannot_write`, `vectors:io`, `vectors:engines_differ`,
    /// `vectors:expansion`, `vectors:params_refused`,
    /// `vectors:no_draft_fits`.
    #[must_use]
    pub fn stable_kind(&self) -> &'static str {
        match self {
            VectorsError::NotADirectory { .. } => "vectors:not_a_directory",
            VectorsError::CannotCreate { .. } => "vectors:cannot_create",
            VectorsError::CannotWrite { .. } => "vectors:cannot_write",
            VectorsError::Io { .. } => "vectors:io",
            VectorsError::EnginesDiffer { .. } => "vectors:engines_differ",
            VectorsError::Expansion { .. } => "vectors:expansion",
            VectorsError::ParamsRefused { .. } => "vectors:params_refused",
            VectorsError::NoDraftFits { .. } => "vectors:no_draft_fits",
        }
    }
}

impl std::fmt::Display for VectorsError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            VectorsError::NotADirectory { out } => write!(
                f,
                "--out {}: exists and is not a directory (vectors writes a directory of JSON files)",
                out.display()
            ),
            VectorsError::CannotCreate { out, source } => {
                write!(f, "--out {}: cannot create the directory: {source}", out.display())
            }
            VectorsError::CannotWrite { path, source } => {
                write!(f, "{}: cannot write: {source}", path.display())
            }
            VectorsError::Io { path, source } => write!(f, "{}: {source}", path.display()),
            VectorsError::EnginesDiffer { id, code, line, difference } => {
                write!(
                    f,
                    "{id}: {code} at line {line}: the engine and the reference model differ: {difference}"
                )
            }
            VectorsError::Expansion { id, error } => write!(f, "{id}: {error}"),
            VectorsError::ParamsRefused { id, error } => {
                write!(f, "{id}: the generated parameter file is refused: {error}")
            }
            VectorsError::NoDraftFits { id, template, attempts } => {
                write!(f, "{id}: no draft of its template ({template}) fitted in {attempts} attempts")
            }
        }
    }
}

impl std::error::Error for VectorsError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            VectorsError::CannotCreate { source, .. }
            | VectorsError::CannotWrite { source, .. }
            | VectorsError::Io { source, .. } => Some(source),
            VectorsError::ParamsRefused { error, .. } => Some(error),
            VectorsError::Expansion { error, .. } => Some(error),
            _ => None,
        }
    }
}
