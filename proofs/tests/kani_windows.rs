//! Every Kani harness body run here over its exact Kani window
//! (`cycleref_proofs::catalogue`): exhaustively where the catalogue says
//! so, otherwise by uniform samples and by draws at the edges of every range (its
//! corners and the values near 0: `shim::Mode::Edges`); every
//! declared cover must be satisfied, so a cover Kani's
//! `--fail-uncoverable` would find unreachable fails here first.
//!
//! Run by `.ci/run` optimised with overflow checks on:
//!
//! ```sh
//! cargo test -p cycleref-proofs --profile proofs --test kani_windows -- --ignored --nocapture
//! ```
//!
//! `KANI_WINDOWS=name,name` runs only those harnesses. The figures (cases,
//! symbolic words, covers, seconds) are printed as the rows of the table in
//! `proofs/README.md`.

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::Instant;

use cycleref_proofs::catalogue::{self, Harness, Run};
use cycleref_proofs::shim::{self, Mode, Report};

/// What one harness's runs saw.
struct Figures {
    cases: u64,
    pruned: u64,
    symbolic: u64,
    covers: BTreeMap<&'static str, u64>,
    seconds: f64,
}

fn merge(into: &mut Figures, r: &Report) {
    into.cases += r.runs;
    into.pruned += r.pruned;
    into.symbolic = into.symbolic.max(r.symbolic);
    for (m, n) in &r.covers {
        *into.covers.entry(m).or_insert(0) += n;
    }
}

fn run(h: &Harness) -> Figures {
    let start = Instant::now();
    let mut f = Figures { cases: 0, pruned: 0, symbolic: 0, covers: BTreeMap::new(), seconds: 0.0 };
    match h.run {
        Run::Exhaustive(max_runs) => {
            merge(&mut f, &shim::check(&h.name, Mode::Exhaustive { max_runs }, h.body))
        }
        Run::Sampled { samples, edges } => {
            merge(&mut f, &shim::check(&h.name, Mode::Sample { runs: samples, seed: 0x6b61_6e69 }, h.body));
            merge(&mut f, &shim::check(&h.name, Mode::Edges { runs: edges, seed: 0x6564_6765 }, h.body));
        }
    }
    f.seconds = start.elapsed().as_secs_f64();
    f
}

#[test]
#[ignore = "long: run by .ci/run with --profile proofs -- --ignored"]
fn every_harness_body_over_its_kani_window() {
    let only: Option<Vec<String>> =
        std::env::var("KANI_WINDOWS").ok().map(|v| v.split(',').map(str::to_owned).collect());
    let all: Vec<Harness> = catalogue::harnesses()
        .into_iter()
        .filter(|h| only.as_ref().is_none_or(|o| o.contains(&h.name)))
        .collect();
    assert!(!all.is_empty(), "no harness selected");
    let queue = Mutex::new(all.iter().collect::<Vec<_>>());
    let results = Mutex::new(Vec::new());
    let workers = std::thread::available_parallelism().map_or(2, std::num::NonZero::get);
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| loop {
                let Some(h) = queue.lock().expect("queue").pop() else { break };
                let outcome = std::panic::catch_unwind(|| run(h));
                results.lock().expect("results").push((h.name.clone(), outcome.map_err(|_| ())));
            });
        }
    });
    let mut results = results.into_inner().expect("results");
    results.sort_by_key(|(name, _)| all.iter().position(|h| &h.name == name));
    let mut failures = Vec::new();
    println!("| harness | run here | cases | pruned | symbolic words | covers hit | seconds |");
    println!("|---|---|---:|---:|---:|---|---:|");
    for (name, outcome) in &results {
        let h = all.iter().find(|h| &h.name == name).expect("a harness");
        let Ok(f) = outcome else {
            failures.push(format!("{name}: the body failed (its panic is above)"));
            continue;
        };
        let missed: Vec<_> = f.covers.iter().filter(|(_, n)| **n == 0).map(|(m, _)| *m).collect();
        if !missed.is_empty() {
            failures.push(format!("{name}: covers never satisfied over the window: {missed:?}"));
        }
        let how = match h.run {
            Run::Exhaustive(_) => "exhaustive".to_owned(),
            Run::Sampled { samples, edges } => format!("{samples} samples + {edges} at the edges"),
        };
        println!(
            "| `{name}` | {how} | {} | {} | {} | {}/{} | {:.1} |",
            f.cases,
            f.pruned,
            f.symbolic,
            f.covers.len() - missed.len(),
            f.covers.len(),
            f.seconds
        );
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
