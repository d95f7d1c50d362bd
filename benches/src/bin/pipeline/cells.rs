//! The figures: a [`Cell`] (one command on one program by one build: its
//! times, CPU and peak RSS, or why it did not finish), their medians, and
//! an [`Entry`] (a cell as one row of the history, with its ratio).

use cycleref_benches::pipeline_history::{Ratio, Row, Times};

/// The figures of one command on one program by one build.
#[derive(Clone, Debug, Default)]
pub(crate) struct Cell {
    pub(crate) times: Vec<f64>,
    pub(crate) cpu: Vec<f64>,
    pub(crate) rss: Vec<f64>,
    /// Set when the command did not finish or is unsupported.
    pub(crate) status: Option<String>,
}

pub(crate) fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    match s.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => s[n / 2],
        n => (s[n / 2 - 1] + s[n / 2]) / 2.0,
    }
}

pub(crate) fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NAN, f64::max)
}

impl Cell {
    pub(crate) fn done(&self) -> bool {
        self.status.is_none() && !self.times.is_empty()
    }
    pub(crate) fn time(&self) -> String {
        match &self.status {
            Some(s) => s.clone(),
            None => secs(median(&self.times)),
        }
    }
    pub(crate) fn cpu(&self) -> String {
        if self.done() {
            secs(median(&self.cpu))
        } else {
            "–".into()
        }
    }
    pub(crate) fn mem(&self) -> String {
        if self.done() {
            format!("{:.1}", median(&self.rss))
        } else {
            "–".into()
        }
    }
}

fn secs(s: f64) -> String {
    if s < 1.0 {
        format!("{:.0} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

/// One row of the history: a command's cell on a program, with the ratio
/// the row carries.
pub(crate) struct Entry {
    /// The program's size, MiB.
    pub(crate) size_mb: f64,
    /// `new`, `baseline`, `floor`, `peer`.
    pub(crate) build: String,
    pub(crate) command: String,
    pub(crate) cell: Cell,
    pub(crate) ratio: Option<Ratio>,
}

impl Entry {
    pub(crate) fn new(size_mb: f64, build: &str, command: &str, cell: Cell) -> Entry {
        Entry { size_mb, build: build.into(), command: command.into(), cell, ratio: None }
    }

    pub(crate) fn row(&self, date: &str, commit: &str) -> Row {
        let c = &self.cell;
        Row {
            date: date.into(),
            commit: commit.into(),
            build: self.build.clone(),
            size_mb: self.size_mb,
            command: self.command.clone(),
            reps: c.times.len(),
            times: c.done().then(|| Times {
                median_s: median(&c.times),
                min_s: c.times.iter().copied().fold(f64::INFINITY, f64::min),
                median_cpu_s: median(&c.cpu),
                median_rss_mb: median(&c.rss),
                max_rss_mb: max(&c.rss),
            }),
            status: c.status.clone().unwrap_or_else(|| "ok".into()),
            ratio: self.ratio.clone(),
        }
    }
}

/// `a / b` of two cells' medians, named `of`, when both finished.
pub(crate) fn ratio(of: &str, a: &Cell, b: &Cell) -> Option<Ratio> {
    (a.done() && b.done()).then(|| Ratio {
        of: of.into(),
        wall: median(&a.times) / median(&b.times),
        cpu: median(&a.cpu) / median(&b.cpu),
    })
}

pub(crate) fn mib(bytes: usize) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let b = bytes as f64;
    b / 1_048_576.0
}
