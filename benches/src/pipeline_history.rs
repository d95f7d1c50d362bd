//! `benches/pipeline-history.csv`, the rows of the `pipeline` binary: one
//! per program, command and build of a run.
//!
//! Issue 33 added three columns at the end, `ratio_of`, `ratio_wall` and
//! `ratio_cpu`: a row may carry one ratio of two rows of the same run and
//! program, named in `ratio_of` as `A / B` (`expand nc / bytes-out floor`,
//! `rs274 -g / expand`), with the quotient of their median wall and CPU
//! times. The rows written before have twelve fields and read with no
//! ratio; [`upgrade_header`] gives an old file the new header.

/// The header since issue 33.
pub const HEADER: &str = "date,commit,build,size_mb,command,reps,median_s,min_s,median_cpu_s,\
median_rss_mb,max_rss_mb,status,ratio_of,ratio_wall,ratio_cpu";

/// The header of the rows written before issue 33 (its first twelve
/// columns).
pub const OLD_HEADER: &str =
    "date,commit,build,size_mb,command,reps,median_s,min_s,median_cpu_s,median_rss_mb,max_rss_mb,status";

/// A ratio of two rows' medians.
#[derive(Clone, Debug, PartialEq)]
pub struct Ratio {
    /// `A / B`: the commands (with their build when it is not the row's).
    pub of: String,
    /// A's median wall time over B's.
    pub wall: f64,
    /// A's median CPU time over B's.
    pub cpu: f64,
}

/// The medians of a command that finished.
#[derive(Clone, Debug, PartialEq)]
pub struct Times {
    /// Median wall time, seconds.
    pub median_s: f64,
    /// Shortest wall time, seconds.
    pub min_s: f64,
    /// Median user + system time, seconds.
    pub median_cpu_s: f64,
    /// Median peak RSS, MiB.
    pub median_rss_mb: f64,
    /// Largest peak RSS, MiB.
    pub max_rss_mb: f64,
}

/// One row.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// UTC time of the run.
    pub date: String,
    /// The worktree's commit (`-dirty` with changes).
    pub commit: String,
    /// `new`, `baseline`, `floor` (the bytes-out floor) or `peer` (`rs274`).
    pub build: String,
    /// The program's size in MiB (1, 5, 50 for the mixed programs; two
    /// decimals for the LinuxCNC and G75.1 programs).
    pub size_mb: f64,
    /// The command's name (no comma).
    pub command: String,
    /// Runs that finished.
    pub reps: usize,
    /// The medians; `None` when the command did not finish.
    pub times: Option<Times>,
    /// `ok`, `DNF (…)`, `unsupported`, `skipped (…)` (no comma).
    pub status: String,
    /// The ratio this row carries, if any (issue 33).
    pub ratio: Option<Ratio>,
}

/// A number of a CSV field: `None` when empty.
fn num(f: &str) -> Option<Result<f64, ()>> {
    (!f.is_empty()).then(|| f.parse::<f64>().map_err(|_| ()))
}

impl Row {
    /// The row as a CSV line (no line end); commas in text become `;`.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let t = self.times.as_ref().map_or_else(
            || ",,,,".to_string(),
            |t| {
                format!(
                    "{:.4},{:.4},{:.4},{:.1},{:.1}",
                    t.median_s, t.min_s, t.median_cpu_s, t.median_rss_mb, t.max_rss_mb
                )
            },
        );
        let r = self.ratio.as_ref().map_or_else(
            || ",,".to_string(),
            |r| format!("{},{:.3},{:.3}", r.of.replace(',', ";"), r.wall, r.cpu),
        );
        format!(
            "{},{},{},{},{},{},{t},{},{r}",
            self.date,
            self.commit,
            self.build,
            (self.size_mb * 100.0).round() / 100.0,
            self.command.replace(',', ";"),
            self.reps,
            self.status.replace(',', ";")
        )
    }

    /// A row from a CSV line of twelve fields (before issue 33) or fifteen;
    /// `None` for a header, a blank or `#` line, or a malformed line.
    #[must_use]
    pub fn parse(line: &str) -> Option<Row> {
        let line = line.trim_end_matches(['\r', '\n']);
        if line.trim().is_empty() || line.starts_with('#') || line.starts_with("date,") {
            return None;
        }
        let f: Vec<&str> = line.split(',').collect();
        if f.len() != 12 && f.len() != 15 {
            return None;
        }
        let times = match [6, 7, 8, 9, 10].map(|i| num(f[i])) {
            [None, None, None, None, None] => None,
            [Some(Ok(median_s)), Some(Ok(min_s)), Some(Ok(median_cpu_s)), Some(Ok(median_rss_mb)), Some(Ok(max_rss_mb))] => {
                Some(Times { median_s, min_s, median_cpu_s, median_rss_mb, max_rss_mb })
            }
            _ => return None,
        };
        let ratio = match f.get(12..15) {
            None | Some(["", "", ""]) => None,
            Some([of, wall, cpu]) => {
                Some(Ratio { of: (*of).to_string(), wall: wall.parse().ok()?, cpu: cpu.parse().ok()? })
            }
            Some(_) => return None,
        };
        Some(Row {
            date: f[0].to_string(),
            commit: f[1].to_string(),
            build: f[2].to_string(),
            size_mb: f[3].parse().ok()?,
            command: f[4].to_string(),
            reps: f[5].parse().ok()?,
            times,
            status: f[11].to_string(),
            ratio,
        })
    }
}

/// The rows of a `pipeline-history.csv` text, in order.
#[must_use]
pub fn parse_history(text: &str) -> Vec<Row> {
    text.lines().filter_map(Row::parse).collect()
}

/// The text with its header made [`HEADER`] when it is [`OLD_HEADER`];
/// `None` when there is nothing to change.
#[must_use]
pub fn upgrade_header(text: &str) -> Option<String> {
    let rest = text.strip_prefix(OLD_HEADER)?;
    rest.starts_with(['\n', '\r']).then(|| format!("{HEADER}{rest}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const OLD: &str = "2026-11-24T15:38:55Z,f3f1230,baseline,5,check,5,4.1449,3.9496,4.1438,1523.2,1523.3,ok";
    const OLD_DNF: &str = "2026-11-24T15:38:55Z,f3f1230,baseline,5,expand jsonl,0,,,,,,unsupported";

    #[test]
    fn old_rows_read_without_a_ratio() {
        let r = Row::parse(OLD).expect("an old row");
        assert_eq!((r.build.as_str(), r.size_mb, r.command.as_str(), r.reps), ("baseline", 5.0, "check", 5));
        assert_eq!(r.times.as_ref().map(|t| t.median_cpu_s), Some(4.1438));
        assert_eq!(r.ratio, None);
        let d = Row::parse(OLD_DNF).expect("an old row without times");
        assert_eq!((d.times, d.status.as_str()), (None, "unsupported"));
        // Written again, an old row gains three empty columns.
        assert_eq!(r.to_csv(), format!("{OLD},,,"));
        assert_eq!(Row::parse(&r.to_csv()), Some(r));
    }

    #[test]
    fn new_rows_round_trip() {
        let row = Row {
            date: "2026-11-28T10:00:00Z".into(),
            commit: "abc1234-dirty".into(),
            build: "new".into(),
            size_mb: 0.58,
            command: "linuxcnc 2000 G76: expand".into(),
            reps: 3,
            times: Some(Times {
                median_s: 2.5,
                min_s: 2.4,
                median_cpu_s: 2.45,
                median_rss_mb: 4.2,
                max_rss_mb: 4.3,
            }),
            status: "ok".into(),
            ratio: Some(Ratio { of: "rs274 -g / expand".into(), wall: 0.612, cpu: 0.5 }),
        };
        let line = row.to_csv();
        assert_eq!(
            line,
            "2026-11-28T10:00:00Z,abc1234-dirty,new,0.58,linuxcnc 2000 G76: expand,3,2.5000,2.4000,2.4500,4.2,4.3,ok,rs274 -g / expand,0.612,0.500"
        );
        assert_eq!(line.split(',').count(), HEADER.split(',').count());
        assert_eq!(Row::parse(&line), Some(row));
    }

    #[test]
    fn refusals() {
        for bad in [
            "",
            "# a note",
            HEADER,
            OLD_HEADER,
            "2026,c,new,1,expand nc,3,0.1,0.1,0.1,4,4", // eleven fields
            "2026,c,new,1,expand nc,3,0.1,0.1,0.1,4,4,ok,x / y", // thirteen
            "2026,c,new,1,expand nc,3,0.1,,0.1,4,4,ok", // times half there
            "2026,c,new,one,expand nc,3,0.1,0.1,0.1,4,4,ok", // size
            "2026,c,new,1,expand nc,3,0.1,0.1,0.1,4,4,ok,x / y,a,1", // ratio
        ] {
            assert_eq!(Row::parse(bad), None, "{bad}");
        }
    }

    #[test]
    fn the_header_upgrades_once() {
        let old = format!("{OLD_HEADER}\n{OLD}\n");
        let new = upgrade_header(&old).expect("an old header");
        assert_eq!(new, format!("{HEADER}\n{OLD}\n"));
        assert_eq!(upgrade_header(&new), None);
        assert_eq!(upgrade_header(""), None);
        assert!(HEADER.starts_with(OLD_HEADER));
    }

    /// Every row of the committed file reads, old and new.
    #[test]
    fn the_committed_history_reads() {
        let text = include_str!("../pipeline-history.csv");
        assert_eq!(text.lines().next(), Some(HEADER));
        let rows = text.lines().skip(1).filter(|l| !l.trim().is_empty()).count();
        assert!(rows > 400);
        assert_eq!(parse_history(text).len(), rows);
    }
}
