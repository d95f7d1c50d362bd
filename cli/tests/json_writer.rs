//! `expand --format json` and `jsonl` (written by `cycleref_cli::json::ser`)
//! are byte for byte what `serde_json` writes for the same typed documents:
//! pretty with `json::Pretty`, compact for each line, for every example
//! program on every machine that reads it, and for a long program.

use std::cell::RefCell;

use cycleref::{IncrementSystem, InputUnit, XMode};
use cycleref_cli::json::{CycleJson, MovesDocument, Pretty, StreamSeq, UnitsJson};
use cycleref_cli::{output, Format, Job};
use cycleref_spec::pipeline::{Cycle, Engine};
use cycleref_spec::{Machine, ProfileName};

/// The cycles of `job` with their moves, each its typed document, read
/// from the program through the library's public reader.
fn cycle_documents(job: &Job) -> Vec<CycleJson> {
    let mut items = job.items().map_err(String::from).expect("reads");
    let mut cycles = Vec::new();
    while let Some(item) = items.next_with(|item| {
        Cycle::of(item).map(|c| CycleJson::new(c, job.expand(c).map_err(String::from).expect("expands")))
    }) {
        if let Some(cycle) = item.expect("reads") {
            cycles.push(cycle);
        }
    }
    cycles
}

/// What serde_json writes for `job`: the json document, the jsonl lines.
fn by_serde_json(job: &Job) -> (Vec<u8>, Vec<u8>) {
    let units = job.validate().map_err(String::from).expect("valid").units;
    let doc = MovesDocument {
        format: "cycleref-moves/1",
        file: &job.name,
        units: UnitsJson::new(units),
        readings: cycleref_cli::job::readings_json(&cycleref_cli::job::readings_in_force(&job.machine)),
        cycles: StreamSeq(RefCell::new(Some(cycle_documents(job).into_iter().map(Ok::<_, String>)))),
    };
    let mut json = Vec::new();
    serde::Serialize::serialize(
        &doc,
        &mut serde_json::Serializer::with_formatter(&mut json, Pretty::default()),
    )
    .expect("serializes");
    json.push(b'\n');
    let mut jsonl = Vec::new();
    let mut moves = 0;
    let cycles = cycle_documents(job);
    let count = cycles.len();
    for (cycle, moves_of) in cycles.into_iter().zip(cycle_move_counts(job)) {
        moves += moves_of;
        serde_json::to_writer(&mut jsonl, &cycle).expect("serializes");
        jsonl.push(b'\n');
    }
    let summary = serde_json::json!({
        "format": "cycleref-moves-jsonl/1",
        "file": job.name,
        "units": UnitsJson::new(units),
        "cycles": count,
        "moves": moves,
    });
    serde_json::to_writer(&mut jsonl, &summary).expect("serializes");
    jsonl.push(b'\n');
    (json, jsonl)
}

/// The number of moves of each cycle of `job`.
fn cycle_move_counts(job: &Job) -> Vec<usize> {
    let mut items = job.items().map_err(String::from).expect("reads");
    let mut counts = Vec::new();
    while let Some(item) = items.next_with(|item| {
        Cycle::of(item).map(|c| job.expand(c).map_err(String::from).expect("expands").count())
    }) {
        counts.extend(item.expect("reads"));
    }
    counts
}

/// What the command writes for `job`: the json document, the jsonl lines.
fn by_command(job: &Job) -> (Vec<u8>, Vec<u8>) {
    let (mut json, mut jsonl) = (Vec::new(), Vec::new());
    output::expand(job, Format::Json, &mut json).map_err(String::from).expect("expands");
    output::expand(job, Format::Jsonl, &mut jsonl).map_err(String::from).expect("expands");
    (json, jsonl)
}

fn assert_same(job: &Job) {
    let (json, jsonl) = by_command(job);
    let (json_ref, jsonl_ref) = by_serde_json(job);
    assert!(json == json_ref, "{}: json differs from serde_json's", job.name);
    assert!(jsonl == jsonl_ref, "{}: jsonl differs from serde_json's", job.name);
}

/// Every profile, each as it comes, at IS-C, in inches and with X as a
/// radius.
fn machines() -> Vec<Machine> {
    let mut machines = Vec::new();
    for profile in [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::LinuxCnc] {
        let machine = Machine::new(profile);
        machines.push(machine.clone());
        machines.push(Machine { increment: IncrementSystem::IsC, ..machine.clone() });
        machines.push(Machine { unit: InputUnit::Inch, ..machine.clone() });
        machines.push(Machine { x_mode: XMode::Radius, ..machine });
    }
    machines
}

#[test]
fn every_example_is_written_as_serde_json_writes_it() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let mut examples: Vec<_> =
        std::fs::read_dir(&dir).expect("examples").map(|e| e.expect("entry").path()).collect();
    examples.sort();
    assert!(examples.len() >= 10, "{examples:?}");
    let mut total = 0;
    for path in examples {
        let source = std::fs::read(&path).expect("reads");
        let mut written = 0;
        for machine in machines() {
            let job = Job::new(&path.display().to_string(), source.clone(), machine, Engine::Impl);
            if job.validate().is_err() {
                continue;
            }
            assert_same(&job);
            written += 1;
        }
        assert!(written > 0, "{}: no machine reads it", path.display());
        total += written;
    }
    // 73 when this was written: the examples did not stop reading.
    assert!(total >= 70, "{total} programs and machines");
}

#[test]
fn a_long_program_is_written_as_serde_json_writes_it() {
    // 300 G76 cycles (M68x6, 988TA manual O0013): over a megabyte of json,
    // so the writer hands its buffer over many times.
    let mut program = String::from("M03 S500\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\n");
    for _ in 0..300 {
        program.push_str("G76 X60.64 Z-62 P3.680 Q1.800 F6\nG00 X80 Z10\n");
    }
    program.push_str("M30\n");
    let job = Job::new(
        "long \"quoted\" \\ name\t.nc",
        program.into_bytes(),
        Machine::new(ProfileName::Gsk988),
        Engine::Impl,
    );
    let (json, _) = by_command(&job);
    assert!(json.len() > 1 << 20, "{} bytes", json.len());
    assert_same(&job);
}
