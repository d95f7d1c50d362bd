//! The command line of `pipeline`: its usage and [`Args`], parsed.

use std::path::PathBuf;
use std::time::Duration;

pub(crate) const USAGE: &str =
    "usage: pipeline [--new PATH] [--baseline PATH] [--sizes 1,5,50|none] [--reps 3]
                [--dir DIR] [--timeout SECS] [--mem-limit-mb MB] [--no-append]
                [--peer-cycles 2000] [--rs274 PATH] [--g75-grooves 2000]
       pipeline --floor SHAPE    (the bytes-out floor, to stdout)";

pub(crate) struct Args {
    pub(crate) new: PathBuf,
    pub(crate) baseline: Option<PathBuf>,
    pub(crate) sizes: Vec<usize>,
    pub(crate) reps: usize,
    pub(crate) dir: PathBuf,
    pub(crate) timeout: Duration,
    pub(crate) mem_limit_mb: u64,
    pub(crate) append: bool,
    /// G76 cycles of the LinuxCNC program; 0: no peer benchmark.
    pub(crate) peer_cycles: usize,
    /// LinuxCNC's `rs274`; `None`: the one on `PATH`.
    pub(crate) rs274: Option<PathBuf>,
    /// Grooves of the G75.1-heavy program; 0: none.
    pub(crate) g75_grooves: usize,
}

pub(crate) fn parse() -> Result<Args, String> {
    let mut a = Args {
        new: PathBuf::from("target/release/cycleref"),
        baseline: None,
        sizes: vec![1, 5, 50],
        reps: 3,
        dir: PathBuf::from("target/pipeline"),
        timeout: Duration::from_secs(120),
        mem_limit_mb: 12 * 1024,
        append: true,
        peer_cycles: 2_000,
        rs274: None,
        g75_grooves: 2_000,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{arg} needs a value"));
        match arg.as_str() {
            "--new" => a.new = value()?.into(),
            "--baseline" => a.baseline = Some(value()?.into()),
            "--sizes" => {
                a.sizes = value()?
                    .split(',')
                    .filter(|s| !s.is_empty() && *s != "none")
                    .map(|s| s.trim().parse().map_err(|e| format!("--sizes: {s}: {e}")))
                    .collect::<Result<_, _>>()?;
            }
            "--reps" => a.reps = value()?.parse().map_err(|e| format!("--reps: {e}"))?,
            "--dir" => a.dir = value()?.into(),
            "--timeout" => {
                a.timeout = Duration::from_secs(value()?.parse().map_err(|e| format!("--timeout: {e}"))?);
            }
            "--mem-limit-mb" => {
                a.mem_limit_mb = value()?.parse().map_err(|e| format!("--mem-limit-mb: {e}"))?
            }
            "--no-append" => a.append = false,
            "--peer-cycles" => a.peer_cycles = value()?.parse().map_err(|e| format!("--peer-cycles: {e}"))?,
            "--rs274" => a.rs274 = Some(value()?.into()),
            "--g75-grooves" => a.g75_grooves = value()?.parse().map_err(|e| format!("--g75-grooves: {e}"))?,
            "-h" | "--help" => return Err(String::new()),
            other => return Err(format!("unknown argument `{other}`")),
        }
    }
    if a.reps == 0 {
        return Err("--reps must be at least 1".into());
    }
    Ok(a)
}
