//! The vendor's toolpath as a stream of steps, read as it is taken: an
//! expanded program (`NcTrace`), a CSV (`CsvTrace`) or LinuxCNC's canonical
//! output (`CanonTrace`), every line checked to be UTF-8. Also how a trace
//! is opened, and which format its file's extension names.

use std::collections::VecDeque;
use std::io::BufRead;
use std::path::Path;

use cycleref::units::MAX_LENGTH;
use cycleref::{InputUnit, Lead, LeadWord, Point, StartAngle, Units};
use cycleref_spec::profile::Dialect;
use cycleref_spec::reader::{Item, LineReader};
use cycleref_spec::rs274::{CanonCall, CanonUnits};
use cycleref_spec::Machine;
use rust_decimal::Decimal;

use super::error::TraceError;
use super::fast_nc::{FastNc, Plain};
use super::ours::Follow;
use super::{Context, Kind, Step, TraceFormat};

/// The error of a trace's line `line` whose byte at offset `at` (from 0)
/// is not UTF-8.
fn not_utf8(line: usize, at: usize) -> TraceError {
    TraceError::NotUtf8 { line, byte: at + 1 }
}

/// One line of a trace read from a stream, checked to be UTF-8 (the
/// line end removed); `None` at the end.
fn trace_line<'b>(
    source: &mut dyn BufRead,
    buf: &'b mut Vec<u8>,
    line: usize,
) -> Option<Result<&'b str, TraceError>> {
    buf.clear();
    match source.read_until(b'\n', buf) {
        Ok(0) => return None,
        Ok(_) => {}
        Err(error) => return Some(Err(TraceError::CannotRead { line, error })),
    }
    if buf.last() == Some(&b'\n') {
        buf.pop();
    }
    let text = match std::str::from_utf8(buf) {
        Ok(t) => t,
        Err(e) => return Some(Err(not_utf8(line, e.valid_up_to()))),
    };
    // A byte-order mark may start the first line.
    Some(Ok(if line == 1 { text.strip_prefix('\u{feff}').unwrap_or(text) } else { text }))
}

/// The vendor's toolpath from an expanded program, read in pieces of whole
/// lines (as the program is, `job::next_piece`), a line at a time: the
/// fast path's lines are ASCII, every other line is checked to be UTF-8
/// when it is reached.
pub(super) struct NcTrace<'t, 'm> {
    source: Box<dyn BufRead + 't>,
    /// The current piece (`..piece`) and what was read beyond it.
    buf: Vec<u8>,
    piece: usize,
    /// Where the next line starts in the piece.
    at: usize,
    eof: bool,
    line: usize,
    /// The program reader in its trace mode (reading R-CHECKWORDS): one
    /// reader and one set of rules for programs and traces.
    reader: LineReader<'m>,
    follow: Follow<'m>,
    /// The plain lines our writer writes, read without the reader
    /// (reading R-FASTPATH); it declines every other line to the reader.
    fast: FastNc,
    /// The steps of the current line (a line may hold several blocks).
    ready: VecDeque<Step>,
}

impl<'t, 'm> NcTrace<'t, 'm> {
    pub(super) fn new(
        source: Box<dyn BufRead + 't>,
        machine: &'m Machine,
        units: Units,
        fast: bool,
    ) -> NcTrace<'t, 'm> {
        NcTrace {
            source,
            buf: Vec::new(),
            piece: 0,
            at: 0,
            eof: false,
            line: 0,
            reader: LineReader::for_trace(machine, units),
            follow: Follow::new(machine, units),
            fast: FastNc::new(machine, units, fast),
            ready: VecDeque::new(),
        }
    }

    /// The next step: the current line's next, else the first of the
    /// lines after it that move; `None` at the end. A plain line's move
    /// (the fast path's) is returned as it is, never queued, and made a
    /// step by the caller (line `self.line`).
    fn next_step(&mut self) -> Result<Option<Next>, TraceError> {
        loop {
            if let Some(step) = self.ready.pop_front() {
                return Ok(Some(Next::Step(step)));
            }
            if self.at >= self.piece {
                match crate::job::next_piece(&mut *self.source, &mut self.buf, &mut self.piece, &mut self.eof)
                {
                    Ok(false) => return Ok(None),
                    Ok(true) => {}
                    Err(error) => return Err(TraceError::CannotRead { line: self.line + 1, error }),
                }
                self.at = 0;
            }
            let piece = self.buf.get(..self.piece).unwrap_or_default();
            let rest = piece.get(self.at..).unwrap_or_default();
            // A plain line of our writer's (all printable ASCII): taken
            // without the reader, its end found as it is read.
            if let Some((step, advance)) = self.fast.take_at(rest, self.line + 1) {
                self.line += 1;
                self.at += advance;
                match step {
                    Some(plain) => return Ok(Some(Next::Plain(plain))),
                    None => continue,
                }
            }
            // LF, CR LF or a lone CR (reading R-LINEEND), as in a program.
            let (line, advance) = cycleref_spec::lex::split_line(rest);
            let (end, next) = (self.at + line.len(), self.at + advance);
            self.line += 1;
            let mut text = piece.get(self.at..end).unwrap_or_default();
            // The line's own bytes are checked to be UTF-8 when the reader
            // reads it (the lines the fast path takes are ASCII); the lines
            // above it are read as they would be without a bad byte here.
            if let Err(e) = std::str::from_utf8(text) {
                return Err(not_utf8(self.line, e.valid_up_to()));
            }
            self.at = next;
            // A byte-order mark may start the first line.
            if self.line == 1 {
                text = text.strip_prefix("\u{feff}".as_bytes()).unwrap_or(text);
            }
            // A plain line of our writer's: taken without the reader.
            // The reader first reads what the lines taken so left.
            if let Err(error) = self.fast.sync(&mut self.reader, self.line) {
                return Err(TraceError::Program { error, csv_header: false });
            }
            // A CSV header read as a program: say how to read it as a CSV.
            let csv_header =
                || text.contains(&b',') && text.to_ascii_lowercase().windows(6).any(|w| w == b"motion");
            // The line is one piece of the reader's, so that its numbers
            // are the trace's.
            // Each item is lent where the reader returned it (not moved).
            let (follow, fast) = (&mut self.follow, &mut self.fast);
            while let Some(step) = self.reader.next_in_with(text, |item| {
                fast.learn(item);
                match item {
                    Item::Move(m) => {
                        follow.plain(m).map_err(|error| TraceError::Step { error, csv_header: csv_header() })
                    }
                    Item::G32(call) => Ok(Some(follow.thread(call))),
                    Item::Source(_) => Ok(None),
                    // The trace mode refuses every cycle's block; were one
                    // read, it is refused here rather than passed over.
                    other => Err(TraceError::CannedCycle { line: other.block().line }),
                }
            }) {
                let step =
                    step.map_err(|error| TraceError::Program { error, csv_header: csv_header() })??;
                if let Some(step) = step {
                    self.ready.push_back(step);
                }
            }
        }
    }
}

impl Iterator for NcTrace<'_, '_> {
    type Item = Result<(Step, u32), TraceError>;

    fn next(&mut self) -> Option<Self::Item> {
        // A plain line's step is built where it is returned.
        match self.next_step() {
            Ok(Some(Next::Plain(plain))) => Some(Ok((plain.step(self.line), 0))),
            Ok(Some(Next::Step(step))) => Some(Ok((step, 0))),
            Ok(None) => None,
            Err(e) => Some(Err(e)),
        }
    }
}

/// What [`NcTrace::next_step`] found next.
enum Next {
    /// The move of a plain line taken by the fast path (the line just read).
    Plain(Plain),
    /// A step the reader gave.
    Step(Step),
}

/// The columns a CSV trace may have.
pub(super) const CSV_COLUMNS: [&str; 9] = ["motion", "x", "z", "lead", "q", "i", "k", "cx", "cz"];

/// The vendor's toolpath from a CSV with a header naming its columns
/// (`motion`, `x`, `z`; `lead`, `q`; `i`, `k` or `cx`, `cz` for arcs).
pub(super) struct CsvTrace<'t, 'm> {
    source: Box<dyn BufRead + 't>,
    buf: Vec<u8>,
    line: usize,
    machine: &'m Machine,
    units: Units,
    cols: Vec<String>,
    cm: usize,
    cx: usize,
    cz: usize,
    cl: Option<usize>,
    cq: Option<usize>,
    ci: Option<usize>,
    ck: Option<usize>,
    ccx: Option<usize>,
    ccz: Option<usize>,
    here: Option<Point>,
    in_thread: bool,
}

impl<'t, 'm> CsvTrace<'t, 'm> {
    /// The trace after its header (an empty text has no header and no rows).
    fn new(
        mut source: Box<dyn BufRead + 't>,
        machine: &'m Machine,
        units: Units,
    ) -> Result<CsvTrace<'t, 'm>, TraceError> {
        let mut buf = Vec::new();
        let mut cols = vec!["motion".to_string(), "x".into(), "z".into()];
        let mut h = 0;
        while let Some(l) = trace_line(&mut *source, &mut buf, h + 1) {
            let l = l?;
            if !l.trim().is_empty() {
                cols = Self::columns(h, l)?;
                break;
            }
            h += 1;
        }
        let col = |name: &str| cols.iter().position(|c| c == name);
        let (Some(cm), Some(cx), Some(cz)) = (col("motion"), col("x"), col("z")) else {
            return Err(TraceError::CsvHeaderIncomplete { line: h + 1 });
        };
        let (cl, cq, ci, ck, ccx, ccz) = (col("lead"), col("q"), col("i"), col("k"), col("cx"), col("cz"));
        Ok(CsvTrace {
            source,
            buf,
            line: h + 1,
            machine,
            units,
            cols,
            cm,
            cx,
            cz,
            cl,
            cq,
            ci,
            ck,
            ccx,
            ccz,
            here: None,
            in_thread: false,
        })
    }

    /// The columns the header at line `h` (0-based) names.
    fn columns(h: usize, header: &str) -> Result<Vec<String>, TraceError> {
        let cols: Vec<String> = header.split(',').map(|c| c.trim().to_ascii_lowercase()).collect();
        for (n, c) in cols.iter().enumerate() {
            if !CSV_COLUMNS.contains(&c.as_str()) {
                return Err(TraceError::CsvUnknownColumn { line: h + 1, column: c.clone() });
            }
            if cols[..n].contains(c) {
                return Err(TraceError::CsvColumnTwice { line: h + 1, column: c.clone() });
            }
        }
        Ok(cols)
    }

    /// The step of CSV line `n` (1-based), if it moves.
    fn row(&mut self, n: usize, line: &str) -> Result<Option<Step>, TraceError> {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() > self.cols.len() {
            return Err(TraceError::CsvTooManyFields { line: n, fields: f.len(), columns: self.cols.len() });
        }
        let get = |c: Option<usize>| c.and_then(|c| f.get(c).copied()).filter(|s| !s.is_empty());
        let motion = get(Some(self.cm)).unwrap_or("");
        let kind = match motion.to_ascii_lowercase().as_str() {
            "rapid" | "g00" | "g0" => Kind::Rapid,
            "feed" | "g01" | "g1" => Kind::Feed,
            "thread" | "g32" => Kind::Thread,
            "arc-cw" | "g02" | "g2" => Kind::ArcCw,
            "arc-ccw" | "g03" | "g3" => Kind::ArcCcw,
            "arc" => return Err(TraceError::CsvArcDirection { line: n }),
            _ => return Err(TraceError::CsvUnknownMotion { line: n, motion: motion.to_string() }),
        };
        let decimal = |s: &str, column: &'static str| -> Result<Decimal, TraceError> {
            let ok = !s.is_empty()
                && s.trim_start_matches(['-', '+']).chars().all(|c| c.is_ascii_digit() || c == '.')
                && s.trim_start_matches(['-', '+']).chars().any(|c| c.is_ascii_digit());
            let d = if ok { Decimal::from_str_exact(s).ok() } else { None };
            d.ok_or_else(|| TraceError::CsvNotADecimal { line: n, column, value: s.to_string() })
        };
        // A length in increments times `factor`, exact, within the range table.
        let length = |s: Option<&str>, column: &'static str, factor: i64| -> Result<i64, TraceError> {
            let s = s.ok_or(TraceError::CsvMissing { line: n, column })?;
            let out = || TraceError::CsvOutOfRange { line: n, column, value: s.to_string() };
            let v = decimal(s, column)?
                .checked_mul(Decimal::from(self.units.per_unit()))
                .and_then(|v| v.checked_mul(Decimal::from(factor)))
                .ok_or_else(out)?;
            if !v.fract().is_zero() {
                return Err(TraceError::CsvNotInIncrements { line: n, column, value: s.to_string() });
            }
            let v = i64::try_from(v.trunc()).map_err(|_| out())?;
            if v.unsigned_abs() > MAX_LENGTH.unsigned_abs() * factor.unsigned_abs() {
                return Err(out());
            }
            Ok(v)
        };
        let to = Point::new(length(get(Some(self.cx)), "x", 1)?, length(get(Some(self.cz)), "z", 1)?);
        let lead = match get(self.cl) {
            Some(s) if kind == Kind::Thread => {
                Some(parse_lead(s).ok_or_else(|| TraceError::CsvBadLead { line: n, value: s.to_string() })?)
            }
            Some(s) => {
                return Err(TraceError::CsvNotAThread { line: n, column: "lead", value: s.to_string() })
            }
            None if kind == Kind::Thread => return Err(TraceError::CsvThreadWithoutLead { line: n }),
            None => None,
        };
        let angle = match get(self.cq) {
            Some(s) if kind == Kind::Thread => csv_angle(s, n)?,
            Some(s) => return Err(TraceError::CsvNotAThread { line: n, column: "q", value: s.to_string() }),
            None => StartAngle::ZERO,
        };
        let relative = get(self.ci).is_some() || get(self.ck).is_some();
        let absolute = get(self.ccx).is_some() || get(self.ccz).is_some();
        let centre = match (kind.is_arc(), relative, absolute) {
            (false, false, false) => None,
            (false, _, _) => return Err(TraceError::CsvCentreOffArc { line: n }),
            (true, false, false) => return Err(TraceError::CsvArcWithoutCentre { line: n }),
            (true, true, true) => return Err(TraceError::CsvCentreTwice { line: n }),
            (true, true, false) => {
                let Some(p) = self.here else {
                    return Err(TraceError::CsvArcStartUnknown { line: n });
                };
                let di = match get(self.ci) {
                    Some(s) => length(Some(s), "i", self.machine.x_mode.factor())?,
                    None => 0,
                };
                let dk = match get(self.ck) {
                    Some(s) => length(Some(s), "k", 1)?,
                    None => 0,
                };
                Some(Point::new(p.x + di, p.z + dk))
            }
            (true, false, true) => {
                Some(Point::new(length(get(self.ccx), "cx", 1)?, length(get(self.ccz), "cz", 1)?))
            }
        };
        if self.here == Some(to) {
            return Ok(None);
        }
        let from = self.here;
        self.here = Some(to);
        let sync = kind == Kind::Thread && !self.in_thread;
        self.in_thread = kind == Kind::Thread;
        let angle = if sync { angle } else { StartAngle::ZERO };
        Ok(Some(Step { kind, from, to, centre, lead, angle, sync, context: Context::Source { line: n } }))
    }
}

impl Iterator for CsvTrace<'_, '_> {
    type Item = Result<(Step, u32), TraceError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            self.line += 1;
            let mut buf = std::mem::take(&mut self.buf);
            let row = match trace_line(&mut *self.source, &mut buf, self.line)? {
                Err(e) => Err(e),
                Ok(line) if line.trim().is_empty() => Ok(None),
                Ok(line) => self.row(self.line, line),
            };
            self.buf = buf;
            match row {
                Ok(Some(s)) => return Some(Ok((s, 0))),
                Ok(None) => {}
                Err(e) => return Some(Err(e)),
            }
        }
    }
}

/// A CSV start angle: thousandths of a degree, multiples of 0.1, below 360°.
fn csv_angle(s: &str, n: usize) -> Result<StartAngle, TraceError> {
    let bad = || TraceError::CsvBadStartAngle { line: n, value: s.to_string() };
    if !s.chars().all(|c| c.is_ascii_digit() || c == '.') || !s.chars().any(|c| c.is_ascii_digit()) {
        return Err(bad());
    }
    let d = Decimal::from_str_exact(s).map_err(|_| bad())?;
    let tenths = d.checked_mul(Decimal::from(10)).ok_or_else(bad)?;
    if !tenths.fract().is_zero() || d > Decimal::from(360_000) {
        return Err(bad());
    }
    let t = u32::try_from(tenths.trunc()).map_err(|_| bad())?;
    Ok(if t % 10 == 0 {
        StartAngle::from_millidegrees(u64::from(t / 10))
    } else {
        StartAngle { num: t, den: 10 }
    })
}

fn parse_lead(s: &str) -> Option<Lead> {
    let (word, v) = match s.chars().next()? {
        'F' | 'f' => (LeadWord::F, &s[1..]),
        'I' | 'i' => (LeadWord::I, &s[1..]),
        'K' | 'k' => (LeadWord::K, &s[1..]),
        _ => (LeadWord::F, s),
    };
    let (int, frac) = v.split_once('.').unwrap_or((v, ""));
    let frac = frac.trim_end_matches('0');
    if !int.chars().chain(frac.chars()).all(|c| c.is_ascii_digit()) || int.is_empty() && frac.is_empty() {
        return None;
    }
    let digits = format!("{int}{frac}");
    let digits = digits.trim_start_matches('0');
    let mantissa = if digits.is_empty() { 0 } else { digits.parse().ok()? };
    let lead = Lead { word, mantissa, scale: u32::try_from(frac.len()).ok()? };
    lead.in_range().then_some(lead)
}

/// The format of a trace file, by its extension.
pub(super) fn format_of(trace: &Path) -> TraceFormat {
    match trace.extension() {
        Some(e) if e.eq_ignore_ascii_case("csv") => TraceFormat::Csv,
        Some(e) if e.eq_ignore_ascii_case("canon") => TraceFormat::Rs274,
        _ => TraceFormat::Nc,
    }
}

/// The call of a canonical output's line `line`.
fn call_of(text: &str, line: usize) -> Result<Option<CanonCall>, TraceError> {
    cycleref_spec::rs274::call(text, line).map_err(TraceError::Canon)
}

/// `value × k` when it is a whole number, else `None`: what
/// `value.checked_mul(k)` filtered by a zero `fract()` gives, as an
/// integer. The printed values have a mantissa within 64 bits and `k` is
/// at most 2³², so the product is below 2⁹⁶ and `Decimal`'s product is
/// exact: it is computed in `i128` without `Decimal`'s general
/// multiplication (which was a tenth of `check`'s time on a canonical
/// trace); any other value goes through `Decimal` as before.
#[inline]
fn whole_multiple(value: Decimal, k: i64) -> Option<i128> {
    let (mantissa, scale) = (value.mantissa(), value.scale());
    // The usual case, in `i64` (`i128` division is a library call): the
    // product and the unit within it.
    if let (Ok(m), true) = (i64::try_from(mantissa), scale <= 18) {
        if let Some(product) = m.checked_mul(k) {
            // `rs274` prints four decimals (six for a pitch): a division
            // by a constant is a multiplication.
            let (quotient, remainder) = match scale {
                4 => (product / 10_000, product % 10_000),
                6 => (product / 1_000_000, product % 1_000_000),
                _ => {
                    let unit = 10_i64.pow(scale);
                    (product / unit, product % unit)
                }
            };
            return (remainder == 0).then_some(i128::from(quotient));
        }
    }
    if mantissa.unsigned_abs() <= u128::from(u64::MAX) && scale <= 18 && k.unsigned_abs() <= 1 << 32 {
        let product = mantissa * i128::from(k);
        let unit = 10_i128.pow(scale);
        return (product % unit == 0).then_some(product / unit);
    }
    let product = value.checked_mul(Decimal::from(k)).filter(|s| s.fract().is_zero())?;
    i128::try_from(product).ok()
}

/// The vendor's toolpath from LinuxCNC's canonical output (reading
/// R-CHECKLCNC): `STRAIGHT_TRAVERSE` is a rapid, `STRAIGHT_FEED` a feed,
/// or a thread move at the pitch of the `START_SPEED_FEED_SYNC` in force,
/// `ARC_FEED` an arc; synchronisation starts at a thread move that follows
/// no thread move (LinuxCNC's planner waits for the index only then). X is
/// printed as a radius: the check holds it as a diameter on this profile.
///
/// Read strictly (reading R-CHECKLCNC-CALLS): every call is read and
/// checked, or one of `rs274::SKIPPED_CALLS`, or an error naming the line
/// and the call. The length unit in force at a motion must be the
/// program's, the XY rotation 0, an arc in the XZ plane, and Y, A, B and C
/// where the first motion has them.
pub(super) struct CanonTrace<'t> {
    source: Box<dyn BufRead + 't>,
    buf: Vec<u8>,
    line: usize,
    units: Units,
    pitch: Option<Lead>,
    in_thread: bool,
    here: Option<Point>,
    /// The unit of `USE_LENGTH_UNITS` in force (rs274 starts in mm).
    length_units: CanonUnits,
    /// `SET_XY_ROTATION` in force.
    rotation: Decimal,
    /// `SELECT_PLANE` in force is XZ.
    plane_xz: bool,
    /// Y, A, B, C of the first motion: every later one keeps them.
    others: Option<[Decimal; 4]>,
}

impl CanonTrace<'_> {
    fn new<'t>(source: Box<dyn BufRead + 't>, units: Units) -> CanonTrace<'t> {
        CanonTrace {
            source,
            buf: Vec::new(),
            line: 0,
            units,
            pitch: None,
            in_thread: false,
            here: None,
            length_units: CanonUnits::Mm,
            rotation: Decimal::ZERO,
            plane_xz: true,
            others: None,
        }
    }

    /// A printed length in increments (X doubled: a diameter).
    fn increments(&self, value: Decimal, factor: i64, what: &'static str) -> Result<i64, TraceError> {
        let line = self.line;
        // The errors are built only when raised (`ok_or` built and dropped
        // one for every coordinate).
        let Some(scaled) = whole_multiple(value, self.units.per_unit() * factor) else {
            return Err(TraceError::CanonNotInIncrements { line, what, value });
        };
        match i64::try_from(scaled).ok().filter(|v| v.unsigned_abs() <= MAX_LENGTH.unsigned_abs()) {
            Some(v) => Ok(v),
            None => Err(TraceError::CanonOutOfRange { line, what, value }),
        }
    }

    /// What every motion must meet: the program's unit, no rotation, and
    /// the other axes where they started.
    fn motion_frame(&mut self, call: &'static str, others: [Decimal; 4]) -> Result<(), TraceError> {
        let line = self.line;
        let program = match self.units.unit {
            InputUnit::Metric => CanonUnits::Mm,
            InputUnit::Inch => CanonUnits::Inches,
        };
        if self.length_units != program {
            return Err(TraceError::CanonUnits { line, call, trace: self.length_units, program });
        }
        if !self.rotation.is_zero() {
            return Err(TraceError::CanonRotation { line, call, degrees: self.rotation });
        }
        match self.others {
            None => self.others = Some(others),
            Some(first) if first == others => {}
            Some(first) => {
                let names = ["Y", "A", "B", "C"];
                // `first != others`: some axis differs.
                let i = (0..4).find(|&i| first[i] != others[i]).unwrap_or(0);
                return Err(TraceError::CanonOtherAxis {
                    line,
                    call,
                    axis: names[i],
                    from: first[i],
                    to: others[i],
                });
            }
        }
        Ok(())
    }

    /// The call of line `self.line` (`Some(None)`: an empty line), or
    /// `None` at the end of the trace. A line that is whole in the
    /// source's buffer is read there, where it stands; any other (the
    /// last of a buffer, or after a failed read) is read as
    /// [`trace_line`] reads it, into `self.buf`: the same line either
    /// way, the line end `\n` (a `\r` before it is trimmed by the call's
    /// reading as any space is).
    fn next_call(&mut self) -> Result<Option<Option<CanonCall>>, TraceError> {
        let line = self.line;
        // One look at the buffer: a failed look is read again below,
        // where its error is reported.
        if let Ok(buffer) = self.source.fill_buf() {
            if let Some(end) = memchr::memchr(b'\n', buffer) {
                // `rs274`'s usual lines, read where they lie (the same
                // call as below: `plain_call`'s test).
                if let Some(c) = cycleref_spec::rs274::plain_call(&buffer[..end]) {
                    self.source.consume(end + 1);
                    return Ok(Some(Some(c)));
                }
                let call = match std::str::from_utf8(&buffer[..end]) {
                    // A byte-order mark may start the first line.
                    Ok(t) => {
                        call_of(if line == 1 { t.strip_prefix('\u{feff}').unwrap_or(t) } else { t }, line)
                    }
                    Err(e) => Err(not_utf8(line, e.valid_up_to())),
                };
                self.source.consume(end + 1);
                return call.map(Some);
            }
        }
        // The line is read from a buffer taken for the time of its
        // reading (given back below), so that the call can borrow it.
        let mut buf = std::mem::take(&mut self.buf);
        let call = match trace_line(&mut *self.source, &mut buf, line) {
            None => Ok(None),
            Some(Err(e)) => Err(e),
            Some(Ok(text)) => call_of(text, line).map(Some),
        };
        self.buf = buf;
        call
    }

    fn step(&mut self) -> Result<Option<Step>, TraceError> {
        loop {
            self.line += 1;
            let Some(call) = self.next_call()? else { return Ok(None) };
            let (kind, to, centre) = match call {
                None | Some(CanonCall::Skipped) => continue,
                Some(CanonCall::Units(u)) => {
                    self.length_units = u;
                    continue;
                }
                Some(CanonCall::Rotation(r)) => {
                    self.rotation = r;
                    continue;
                }
                Some(CanonCall::Plane { xz }) => {
                    self.plane_xz = xz;
                    continue;
                }
                Some(CanonCall::StartSync { pitch }) => {
                    let bad = || TraceError::CanonPitch { line: self.line, pitch };
                    let mut mantissa = whole_multiple(pitch, 1_000_000)
                        .and_then(|s| u64::try_from(s).ok())
                        .filter(|m| *m > 0)
                        .ok_or_else(bad)?;
                    let mut scale = 6;
                    while scale > 0 && mantissa % 10 == 0 {
                        mantissa /= 10;
                        scale -= 1;
                    }
                    self.pitch = Some(Lead { word: LeadWord::K, mantissa, scale });
                    continue;
                }
                Some(CanonCall::StopSync) => {
                    self.pitch = None;
                    continue;
                }
                Some(CanonCall::Motion { rapid, x, z, others }) => {
                    self.motion_frame(if rapid { "STRAIGHT_TRAVERSE" } else { "STRAIGHT_FEED" }, others)?;
                    let to = Point::new(self.increments(x, 2, "X")?, self.increments(z, 1, "Z")?);
                    let kind = match (rapid, self.pitch) {
                        (true, _) => Kind::Rapid,
                        (false, None) => Kind::Feed,
                        (false, Some(_)) => Kind::Thread,
                    };
                    (kind, to, None)
                }
                Some(CanonCall::Arc { x, z, cx, cz, rotation, others }) => {
                    self.motion_frame("ARC_FEED", others)?;
                    if !self.plane_xz {
                        return Err(TraceError::CanonArcPlane { line: self.line });
                    }
                    if self.pitch.is_some() {
                        return Err(TraceError::CanonThreadedArc { line: self.line });
                    }
                    let kind = match rotation {
                        -1 => Kind::ArcCw,
                        1 => Kind::ArcCcw,
                        _ => return Err(TraceError::CanonArcTurns { line: self.line, rotation }),
                    };
                    let to = Point::new(self.increments(x, 2, "X")?, self.increments(z, 1, "Z")?);
                    let centre = Point::new(
                        self.increments(cx, 2, "the centre's X")?,
                        self.increments(cz, 1, "the centre's Z")?,
                    );
                    (kind, to, Some(centre))
                }
            };
            let from = self.here.replace(to);
            if from == Some(to) {
                continue;
            }
            let sync = kind == Kind::Thread && !self.in_thread;
            self.in_thread = kind == Kind::Thread;
            let lead = if kind == Kind::Thread { self.pitch } else { None };
            let context = Context::Source { line: self.line };
            return Ok(Some(Step { kind, from, to, centre, lead, angle: StartAngle::ZERO, sync, context }));
        }
    }
}

impl Iterator for CanonTrace<'_> {
    type Item = Result<(Step, u32), TraceError>;

    fn next(&mut self) -> Option<Self::Item> {
        self.step().transpose().map(|r| r.map(|s| (s, 0)))
    }
}

/// The trace's name and a buffered reader of it (`-`: standard input), to
/// be read as `format`: an nc trace is read in pieces of whole lines
/// (`job::next_piece`, [`CHUNK`] bytes a read), straight into the piece
/// (no buffer of its own between, whose copy was 1.5 % of a `check`);
/// the others a line at a time, through a buffer.
///
/// [`CHUNK`]: crate::job::CHUNK
pub(super) fn open_trace(
    trace: &Path,
    format: TraceFormat,
) -> Result<(String, Box<dyn BufRead>), TraceError> {
    if trace == Path::new("-") {
        return Ok((crate::job::STDIN_NAME.to_string(), Box::new(std::io::stdin().lock())));
    }
    let file = std::fs::File::open(trace)
        .map_err(|error| TraceError::CannotOpen { path: trace.display().to_string(), error })?;
    let room = if format == TraceFormat::Nc { 0 } else { 1 << 16 };
    Ok((trace.display().to_string(), Box::new(std::io::BufReader::with_capacity(room, file))))
}

/// Steps with their segments, read as they are taken: one of the three
/// readers, by value (not boxed), so that a step is built where the
/// comparison takes it instead of returned through a call it cannot see
/// into and copied. One is made per comparison and stays where it is made,
/// so its size is no cost (the readers are not boxed for it).
#[allow(clippy::large_enum_variant)]
pub(super) enum TraceSteps<'t, 'm> {
    Nc(NcTrace<'t, 'm>),
    Csv(CsvTrace<'t, 'm>),
    Canon(CanonTrace<'t>),
}

impl Iterator for TraceSteps<'_, '_> {
    type Item = Result<(Step, u32), TraceError>;

    #[inline(always)]
    fn next(&mut self) -> Option<Self::Item> {
        match self {
            TraceSteps::Nc(t) => t.next(),
            TraceSteps::Csv(t) => t.next(),
            TraceSteps::Canon(t) => t.next(),
        }
    }
}

/// The vendor's steps, read as they are taken from `source`: an expanded
/// program, a CSV, or LinuxCNC's canonical trace (`rs274`). The text must be UTF-8 (a byte-order mark is
/// skipped).
pub(super) fn trace_steps<'t, 'm: 't>(
    source: Box<dyn BufRead + 't>,
    format: TraceFormat,
    machine: &'m Machine,
    units: Units,
) -> Result<TraceSteps<'t, 'm>, TraceError> {
    Ok(if format == TraceFormat::Rs274 {
        if machine.profile.dialect != Dialect::LinuxCnc {
            return Err(TraceError::CanonProfile);
        }
        TraceSteps::Canon(CanonTrace::new(source, units))
    } else if format == TraceFormat::Csv {
        TraceSteps::Csv(CsvTrace::new(source, machine, units)?)
    } else {
        TraceSteps::Nc(NcTrace::new(source, machine, units, true))
    })
}
