//! The reader round trip: a program expanded to nc by
//! `cycleref_cli::output::expand` and read again with the same machine
//! reproduces the expanded toolpath. The toolpath of a text is what the
//! reader makes of it: each cycle (G76, G78, G92, G32, G75.1) expanded by the engine,
//! each plain G00/G01 block a move to its X and Z (G50 sets the position);
//! in the nc output every G76 became plain G00/G32 blocks (each G32 block
//! read back as a one-move G32 thread), so the two toolpaths must agree
//! move by move: the motion (rapid, feed, thread with the same lead per
//! revolution, start angle and synchronisation, arc with the same centre
//! and sense) and the end point. Generated programs (proptest), gsk988 and
//! gsk980, several cycles each.

use cycleref::lead::Ratio;
use cycleref::{Motion, Point, StartAngle};
use cycleref_cli::{output, Format, Job};
use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::reader::{length_word, PlainMove};
use cycleref_spec::{Item, Machine, ProfileName, Reader};
use proptest::prelude::*;

/// A move as the two readings must agree on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Step {
    Rapid(Point),
    Feed(Point),
    /// End, lead per revolution (reduced), start angle, sync.
    Thread(Point, (u128, u128), StartAngle, bool),
    Arc(Point, Point, bool),
}

fn reduced(r: Ratio) -> (u128, u128) {
    let (mut a, mut b) = (r.num, r.den);
    while b != 0 {
        (a, b) = (b, a % b);
    }
    match (r.num.checked_div(a), r.den.checked_div(a)) {
        (Some(n), Some(d)) => (n, d),
        _ => (r.num, r.den),
    }
}

/// The toolpath of `text` read with `machine`, with the source line of
/// each step (for the failure message).
fn toolpath(text: &str, machine: &Machine) -> Result<Vec<(usize, Step)>, String> {
    let mut reader = Reader::new(text.as_bytes(), machine);
    let mut out = Vec::new();
    let mut at: Option<Point> = None;
    let mut rapid = true;
    while let Some(item) = reader.next() {
        let item = item.map_err(|e| e.to_string())?;
        let units = reader.units();
        if let Some(cycle) = Cycle::of(&item) {
            let line = cycle.line();
            for m in expand(cycle, Engine::Impl).map_err(|e| e.to_string())? {
                let step = match m.motion {
                    Motion::Rapid => Step::Rapid(m.to),
                    Motion::Feed => Step::Feed(m.to),
                    Motion::Thread { lead, start_angle, sync } => {
                        Step::Thread(m.to, reduced(lead.increments_per_rev(units)), start_angle, sync)
                    }
                    Motion::Arc { centre, clockwise } => Step::Arc(m.to, centre, clockwise),
                };
                out.push((line, step));
                at = Some(m.to);
            }
            continue;
        }
        let b = match item {
            Item::Source(b) | Item::Move(PlainMove { block: b, .. }) => b,
            _ => continue,
        };
        let mut set_only = false;
        for g in b.all('G') {
            match g.number().integer() {
                Some(0) => rapid = true,
                Some(1) => rapid = false,
                Some(50) => set_only = true,
                _ => {}
            }
        }
        let word = |letter| -> Result<Option<i64>, String> {
            match b.get(letter).map_err(|e| e.to_string())? {
                Some(w) => length_word(machine, units, &b, w).map(Some).map_err(|e| e.to_string()),
                None => Ok(None),
            }
        };
        let (x, z) = (word('X')?, word('Z')?);
        if x.is_none() && z.is_none() {
            continue;
        }
        let prev = at.unwrap_or(Point::new(0, 0));
        let to = Point::new(x.unwrap_or(prev.x), z.unwrap_or(prev.z));
        if !set_only {
            out.push((b.line, if rapid { Step::Rapid(to) } else { Step::Feed(to) }));
        }
        at = Some(to);
    }
    Ok(out)
}

/// The nc expansion of `program` with `profile`.
fn nc(program: &str, profile: ProfileName) -> Result<String, String> {
    let job = Job::new("roundtrip.nc", program.as_bytes().to_vec(), Machine::new(profile), Engine::Impl);
    let mut buf = Vec::new();
    output::expand(&job, Format::Nc, &mut buf).map_err(String::from)?;
    String::from_utf8(buf).map_err(|e| e.to_string())
}

/// Checks the round trip of `program`; `Ok(false)` when the program itself
/// is refused (the generator's values are not all valid together).
fn round_trip(program: &str, profile: ProfileName) -> Result<bool, String> {
    let machine = Machine::new(profile);
    let Ok(text) = nc(program, profile) else { return Ok(false) };
    let before = toolpath(program, &machine)?;
    let after = toolpath(&text, &machine).map_err(|e| format!("the output does not read: {e}\n{text}"))?;
    for (i, (a, b)) in before.iter().zip(&after).enumerate() {
        if a.1 != b.1 {
            return Err(format!(
                "step {i} differs: program line {} {:?}, output line {} {:?}\n{program}\n---\n{text}",
                a.0, a.1, b.0, b.1
            ));
        }
    }
    if before.len() != after.len() {
        return Err(format!("{} steps, read back {}\n{program}\n---\n{text}", before.len(), after.len()));
    }
    Ok(true)
}

#[test]
fn the_examples_round_trip() {
    for (name, profile) in [
        ("gsk988-m68x6.nc", ProfileName::Gsk988),
        ("seed000-extended.nc", ProfileName::Gsk988),
        ("gsk980-g32-runout.nc", ProfileName::Gsk980),
        ("gsk980-g92-o0012.nc", ProfileName::Gsk980),
        ("gsk980-g78.nc", ProfileName::Gsk980),
        ("gsk988-g78.nc", ProfileName::Gsk988),
    ] {
        let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
        let program = std::fs::read_to_string(path).unwrap();
        assert_eq!(round_trip(&program, profile), Ok(true), "{name}");
    }
}

/// A changed output is caught: one coordinate of one G32 block moved by
/// an increment.
#[test]
fn a_changed_output_is_caught() {
    let program =
        "M03 S500\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 L2\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n";
    let machine = Machine::new(ProfileName::Gsk988);
    let text = nc(program, ProfileName::Gsk988).expect("expands");
    assert!(text.contains(" Q180.000"), "{text}");
    let changed = text.replacen("G32 X64.400 Z-59.000", "G32 X64.400 Z-59.001", 1);
    assert_ne!(changed, text);
    let steps = |t: &str| toolpath(t, &machine).map(|v| v.into_iter().map(|(_, s)| s).collect::<Vec<_>>());
    assert_ne!(steps(program), steps(&changed));
    assert_eq!(steps(program), steps(&text));
}

/// One G76 cycle from A: block 1 then block 2, lengths in mm (P and Q in
/// least increments on the gsk980, whose state parameter says so).
fn g76(profile: ProfileName) -> impl Strategy<Value = String> {
    let pq = move |um: u32| {
        if profile == ProfileName::Gsk980 {
            um.to_string()
        } else {
            format!("{:.3}", f64::from(um) / 1000.0)
        }
    };
    (
        (1_u32..=3, 0_u32..=20, prop::sample::select(vec![0_u32, 29, 55, 60, 80])),
        (50_u32..=400, 0_u32..=100),
        (500_u32..=4000, 200_u32..=2000, 0_i32..=3, -3_i32..=3),
        (1_u32..=4, prop::bool::ANY, prop::bool::ANY, 1_u32..=3),
    )
        .prop_map(move |((m, r, a), (dmin, d), (k, dd, taper_half, _), (lead, internal, plus_z, starts))| {
            // Multi-start threads (L, R-STARTS: Q on the synchronising moves)
            // on the gsk988.
            let l = if profile == ProfileName::Gsk988 && starts > 1 { format!(" L{starts}") } else { String::new() };
            let (x0, z0) = if plus_z { (80, -80) } else { (80, 10) };
            let (x0, x_end) = if internal { (20, 20 + 2 * k / 1000 + 4) } else { (x0, 60) };
            let z_end = if plus_z { -20 } else { -50 };
            let taper = if taper_half == 0 { String::new() } else { format!(" R{}", f64::from(taper_half) * 0.5) };
            format!(
                "G00 X{x0} Z{z0}\nG76 P{m:02}{r:02}{a:02} Q{} R{:.3}{l}\nG76 X{x_end} Z{z_end}{taper} P{} Q{} F{lead}\n",
                pq(dmin),
                f64::from(d) / 1000.0,
                pq(k),
                pq(dd),
            )
        })
}

/// One G78 cycle: G76's thread with G78's P (the 988TA: m finishing passes,
/// r 0-4, D the depth mode; the 980TDi: m the depth mode, r 0-3, D the
/// finishing passes).
fn g78(profile: ProfileName) -> impl Strategy<Value = String> {
    (g76(profile), 0_u32..=4, 0_u32..=1, 1_u32..=2).prop_map(move |(g76, r, mode, d)| {
        let mut lines: Vec<String> = g76.lines().map(str::to_string).collect();
        // Block 1 is "G76 Pmmrraa …": rewrite its P for G78.
        let rest = lines[1]
            .split_once(' ')
            .map_or("", |(_, r)| r)
            .split_once(' ')
            .map_or("", |(_, r)| r)
            .to_string();
        let a = &lines[1][9..11];
        lines[1] = if profile == ProfileName::Gsk988 {
            format!("G78 P02{r:02}{a} {rest} D{mode}")
        } else {
            format!("G78 P{mode:02}{:02}{a} {rest} D{d}", r % 4)
        };
        lines[2] = lines[2].replacen("G76", "G78", 1);
        lines.join("\n") + "\n"
    })
}

/// A G92 thread cut in two blocks (the second giving only X), with a
/// run-out J K on the GSK profiles, then G00 back (which ends the mode).
fn g92() -> impl Strategy<Value = String> {
    (55_u32..=65, 0_i32..=2, 1_u32..=4, prop::bool::ANY).prop_map(|(x, taper, lead, run_out)| {
        let r = if taper == 0 { String::new() } else { format!(" R-{taper}") };
        let jk = if run_out { " J1 K2" } else { "" };
        format!("G00 X80 Z5\nG92 X{x} Z-30{r} F{lead}{jk}\nX{}\nG00 X90 Z10\n", x - 1)
    })
}

/// A G32 thread from X{x} Z5 with its approach and retract.
fn g32() -> impl Strategy<Value = String> {
    (40_u32..=70, -3_i32..=3, 1_u32..=5).prop_map(|(x, taper, lead)| {
        format!("G00 X{x} Z5\nG32 X{} Z-30 F{lead}\nG00 X90\nG00 Z5\n", i64::from(x) + i64::from(taper))
    })
}

/// Plain moves.
fn plain() -> impl Strategy<Value = String> {
    (60_u32..=90, -40_i32..=10).prop_map(|(x, z)| format!("G01 X{x} Z{z} F0.2\nG00 X90 Z10\n"))
}

fn program(profile: ProfileName) -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![3 => g76(profile), 2 => g78(profile), 2 => g92(), 1 => g32(), 1 => plain()],
        1..4,
    )
    .prop_map(|parts| format!("M03 S500\nG00 X90 Z10\n{}M30\n", parts.concat()))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    #[test]
    fn a_gsk988_program_round_trips(p in program(ProfileName::Gsk988)) {
        let checked = round_trip(&p, ProfileName::Gsk988);
        prop_assert_eq!(checked, Ok(true));
    }

    #[test]
    fn a_gsk980_program_round_trips(p in program(ProfileName::Gsk980)) {
        let checked = round_trip(&p, ProfileName::Gsk980);
        prop_assert_eq!(checked, Ok(true));
    }
}

/// The generator's programs are accepted (a refused program would be
/// skipped by the round trip) and their toolpaths are long.
#[test]
fn the_generated_programs_are_valid() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let (mut steps, mut threads) = (0, 0);
    for profile in [ProfileName::Gsk988, ProfileName::Gsk980] {
        for _ in 0..100 {
            let p = program(profile).new_tree(&mut runner).expect("a program").current();
            if let Err(e) = nc(&p, profile) {
                panic!("refused ({profile:?}): {e}\n{p}");
            }
            let path = toolpath(&p, &Machine::new(profile)).expect("reads");
            steps += path.len();
            threads += path.iter().filter(|(_, s)| matches!(s, Step::Thread(..))).count();
        }
    }
    eprintln!("200 programs: {steps} steps, {threads} thread moves");
    assert!(threads > 1_000, "{threads} thread moves");
}
