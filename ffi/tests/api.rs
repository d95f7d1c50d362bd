//! The C interface called from Rust through the `rlib`: its moves are the
//! engine's, its errors carry the right status, line and message.

use core::ffi::{c_char, CStr};
use core::ptr;

use cycleref_ffi::*;
use cycleref_spec::{read, Machine, ProfileName};

fn example(name: &str) -> String {
    let path = format!("{}/../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn options(profile: CyclerefProfile) -> CyclerefOptions {
    CyclerefOptions { profile: profile as u32, ..cycleref_options_default() }
}

/// `cycleref_expand` with a buffer of `capacity`: the status, the moves
/// written and the error.
#[allow(unsafe_code)]
fn expand_with(
    program: &[u8],
    opts: &CyclerefOptions,
    capacity: usize,
) -> (CyclerefStatus, usize, Vec<CyclerefMove>, CyclerefError) {
    let mut moves = vec![CyclerefMove::default(); capacity];
    let mut count = usize::MAX;
    let mut err = CyclerefError::default();
    // SAFETY: every pointer is valid for the call: the program slice, the
    // options, a buffer of `capacity` moves, `count` and `err`.
    let status = unsafe {
        cycleref_expand(
            program.as_ptr().cast(),
            program.len(),
            opts,
            if capacity == 0 { ptr::null_mut() } else { moves.as_mut_ptr() },
            capacity,
            &mut count,
            &mut err,
        )
    };
    moves.truncate(count.min(capacity));
    (status, count, moves, err)
}

fn expand(program: &str, opts: &CyclerefOptions) -> Result<Vec<CyclerefMove>, String> {
    let (status, n, _, err) = expand_with(program.as_bytes(), opts, 0);
    if status != CyclerefStatus::BufferTooSmall && status != CyclerefStatus::Ok {
        return Err(err.message());
    }
    let (status, count, moves, err) = expand_with(program.as_bytes(), opts, n);
    assert_eq!(status, CyclerefStatus::Ok, "{}", err.message());
    assert_eq!(err.status, CyclerefStatus::Ok);
    assert_eq!((err.line, err.message()), (0, String::new()));
    assert_eq!(count, n);
    Ok(moves)
}

/// Every move of every cycle of `program`, straight from the engine.
fn engine_moves(program: &str, machine: &Machine) -> Vec<CyclerefMove> {
    let p = read(program, machine).expect("reads");
    let mut out = Vec::new();
    for item in &p.items {
        match item {
            cycleref_spec::Item::G76(c) => out.extend(cycleref::expand_g76(&c.cycle).unwrap().map(|m| {
                CyclerefMove::from_move(&m, c.cycle.units.decimals(), CyclerefCycle::G76, c.block.line)
            })),
            cycleref_spec::Item::G32(c) => out.extend(cycleref::expand_g32(&c.g32).unwrap().map(|m| {
                CyclerefMove::from_move(&m, c.g32.units.decimals(), CyclerefCycle::G32, c.block.line)
            })),
            _ => {}
        }
    }
    out
}

#[test]
fn m68x6_equals_the_engine() {
    let text = example("gsk988-m68x6.nc");
    let moves = expand(&text, &options(CyclerefProfile::Gsk988)).unwrap();
    assert_eq!(moves.len(), 30);
    assert_eq!(moves, engine_moves(&text, &Machine::new(ProfileName::Gsk988)));
    let m = moves[1];
    assert_eq!(
        (m.motion, m.role, m.x, m.z, m.sync),
        (CyclerefMotion::Thread, CyclerefRole::Cut, 64_400, -59_000, 1)
    );
    assert_eq!((m.lead_word, m.lead_mantissa, m.lead_scale), (CyclerefLeadWord::F, 6, 0));
    assert!(moves.iter().all(|m| m.line == 6 && m.has_pass == 1 && m.decimals == 3));
}

#[test]
fn every_example_equals_the_engine() {
    use cycleref::IncrementSystem::{IsB, IsC};
    for (name, profile, p, system) in [
        ("fanuc-external.nc", CyclerefProfile::Fanuc, ProfileName::Fanuc, IsB),
        ("fanuc-internal.nc", CyclerefProfile::Fanuc, ProfileName::Fanuc, IsB),
        // Written for IS-C, as their comments say.
        ("gsk980-m68x6.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsC),
        ("gsk980-g32-runout.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsB),
        ("gsk980-g32-taper.nc", CyclerefProfile::Gsk980, ProfileName::Gsk980, IsC),
        ("seed000-extended.nc", CyclerefProfile::Gsk988, ProfileName::Gsk988, IsB),
    ] {
        let text = example(name);
        let mut o = options(profile);
        o.increment = if system == IsC { CyclerefIncrement::IsC } else { CyclerefIncrement::IsB } as u32;
        let got = expand(&text, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!got.is_empty(), "{name}");
        let mut m = Machine::new(p);
        m.increment = system;
        assert_eq!(got, engine_moves(&text, &m), "{name}");
    }
}

#[test]
fn g32_moves_have_no_pass() {
    let text = example("gsk980-g32-runout.nc");
    let moves = expand(&text, &options(CyclerefProfile::Gsk980)).unwrap();
    // Worked out in spec/tests/g32.rs: cut and run-out, then three blocks
    // of a continuous thread, the last with a run-out.
    let got: Vec<_> = moves.iter().map(|m| (m.line, m.role, m.x, m.z, m.sync, m.start_angle_num)).collect();
    assert_eq!(
        got,
        vec![
            (5, CyclerefRole::Cut, 40_000, -27_000, 1, 90_000),
            (5, CyclerefRole::RunOut, 43_000, -30_000, 0, 90_000),
            (9, CyclerefRole::Cut, 34_000, -10_000, 1, 180_000),
            (10, CyclerefRole::Cut, 34_000, -30_000, 0, 180_000),
            (11, CyclerefRole::Cut, 37_600, -39_000, 0, 180_000),
            (11, CyclerefRole::RunOut, 40_000, -40_000, 0, 180_000),
        ]
    );
    for m in &moves {
        assert_eq!(
            (m.cycle, m.motion, m.has_pass, m.pass_number, m.pass_depth),
            (CyclerefCycle::G32, CyclerefMotion::Thread, 0, 0, 0)
        );
    }
}

#[test]
fn options_reach_the_machine() {
    let text = example("gsk988-m68x6.nc");
    let mut o = options(CyclerefProfile::Gsk988);
    o.increment = CyclerefIncrement::IsC as u32;
    let moves = expand(&text, &o).unwrap();
    assert_eq!((moves[0].decimals, moves[0].x), (4, 644_000));
    // Inch: the same words in 0.0001 inch.
    o.increment = CyclerefIncrement::IsB as u32;
    o.inch = 1;
    let moves = expand(&text, &o).unwrap();
    assert_eq!((moves[0].decimals, moves[0].x), (4, 644_000));
    // Radius X: X words are radii.
    let mut r = options(CyclerefProfile::Gsk988);
    r.radius = 1;
    let mut m = Machine::new(ProfileName::Gsk988);
    m.x_mode = cycleref::XMode::Radius;
    assert_eq!(expand(&text, &r).unwrap(), engine_moves(&text, &m));
    // The parameter file, and the fields overriding it.
    let toml = "increment = \"is-c\"\n[parameters]\n5142 = 3\n";
    let mut t = options(CyclerefProfile::Gsk988);
    t.params_toml = toml.as_ptr().cast::<c_char>();
    t.params_toml_len = toml.len();
    let mut m = Machine::new(ProfileName::Gsk988);
    m.apply_toml(toml).unwrap();
    assert_eq!(expand(&text, &t).unwrap(), engine_moves(&text, &m));
    t.increment = CyclerefIncrement::IsB as u32;
    assert_eq!(expand(&text, &t).unwrap()[0].decimals, 3);
}

#[test]
fn buffer_too_small_reports_the_count_and_fills_the_buffer() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let all = expand(&text, &o).unwrap();
    for capacity in [0, 1, 29] {
        let (status, count, moves, err) = expand_with(text.as_bytes(), &o, capacity);
        assert_eq!(
            (status, count, err.status),
            (CyclerefStatus::BufferTooSmall, 30, CyclerefStatus::BufferTooSmall)
        );
        assert_eq!(moves, all[..capacity]);
        assert!(err.message().contains("30 moves"), "{}", err.message());
    }
    let (status, count, moves, _) = expand_with(text.as_bytes(), &o, 100);
    assert_eq!((status, count), (CyclerefStatus::Ok, 30));
    assert_eq!(moves, all);
}

#[test]
fn program_and_cycle_errors() {
    let o = options(CyclerefProfile::Gsk988);
    let missing_p =
        "G50 X100 Z50 M3 S300;\nG00 X80 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 Q1.800 F6;\n";
    let (status, count, _, err) = expand_with(missing_p.as_bytes(), &o, 10);
    assert_eq!(
        (status, count, err.status, err.line),
        (CyclerefStatus::ProgramError, 0, CyclerefStatus::ProgramError, 4)
    );
    assert!(err.message().contains("P(k)"), "{}", err.message());
    // Accepted by the reader, refused by the engine: A between the crest
    // and the root of the thread.
    let inside =
        "G50 X100 Z50 M3 S300;\nG00 X62 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\n";
    let (status, count, _, err) = expand_with(inside.as_bytes(), &o, 10);
    assert_eq!((status, count, err.line), (CyclerefStatus::CycleError, 0, 4));
    assert!(err.message().starts_with("line 4, G76: the start point A"), "{}", err.message());
}

#[test]
#[allow(unsafe_code)]
fn invalid_arguments() {
    let text = example("gsk988-m68x6.nc");
    let o = options(CyclerefProfile::Gsk988);
    let (status, _, _, err) = expand_with(b"G00 X\xff;", &o, 0);
    assert_eq!(status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("not UTF-8"), "{}", err.message());
    let mut bad = o;
    bad.increment = 9;
    assert_eq!(expand_with(text.as_bytes(), &bad, 0).0, CyclerefStatus::InvalidArgument);
    let mut bad = o;
    bad.params_toml_len = 3;
    let (status, _, _, err) = expand_with(text.as_bytes(), &bad, 0);
    assert_eq!(status, CyclerefStatus::InvalidArgument);
    assert!(err.message().contains("params_toml"), "{}", err.message());
    let mut count = 7;
    let mut err = CyclerefError::default();
    // SAFETY: NULL where the function must refuse it; the other pointers
    // are valid.
    unsafe {
        let p = text.as_ptr().cast::<c_char>();
        assert_eq!(
            cycleref_expand(ptr::null(), 0, &o, ptr::null_mut(), 0, &mut count, &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!((count, err.line), (0, 0));
        assert!(err.message().contains("program is NULL"));
        assert_eq!(
            cycleref_expand(p, text.len(), ptr::null(), ptr::null_mut(), 0, &mut count, ptr::null_mut()),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!(
            cycleref_expand(p, text.len(), &o, ptr::null_mut(), 0, ptr::null_mut(), &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert_eq!(
            cycleref_expand(p, text.len(), &o, ptr::null_mut(), 1, &mut count, &mut err),
            CyclerefStatus::InvalidArgument
        );
        assert!(err.message().contains("moves"), "{}", err.message());
    }
}

#[test]
#[allow(unsafe_code)]
fn the_step_api_yields_the_cycle() {
    let text = example("gsk988-m68x6.nc");
    let program = read(&text, &Machine::new(ProfileName::Gsk988)).unwrap();
    let cycle = program.cycles().next().unwrap().cycle;
    let params = CyclerefG76Params::from_cycle(&cycle);
    // The parameters tests/c/expand_example.c writes by hand.
    let by_hand = CyclerefG76Params {
        increment: CyclerefIncrement::IsB as u32,
        start_x: 80_000,
        start_z: 10_000,
        end_x: 60_640,
        end_z: -62_000,
        thread_height: 3_680,
        first_depth: 1_800,
        min_cut: 150,
        finishing_allowance: 100,
        finishing_passes: 2,
        tool_angle: 60,
        infeed: CyclerefInfeed::RightFlank as u32,
        starts: 1,
        lead_word: CyclerefLeadWord::F as u32,
        lead_mantissa: 6,
        run_out_kind: CyclerefRunOutKind::Chamfer as u32,
        run_out_tenths: 5,
        run_out_angle: 45,
        pass_limit: cycleref::g76::DEFAULT_PASS_LIMIT,
        ..CyclerefG76Params::default()
    };
    assert_eq!(params, by_hand);
    assert_eq!(params.cycle(), Ok(cycle));
    assert_eq!(CyclerefG76Params { pass_limit: 0, ..by_hand }.cycle(), Ok(cycle));

    let mut err = CyclerefError::default();
    // SAFETY: valid params and error; the handle is used, then freed once.
    unsafe {
        let h = cycleref_g76_new(&params, &mut err);
        assert!(!h.is_null());
        assert_eq!(err.status, CyclerefStatus::Ok);
        let mut stepped = Vec::new();
        let mut m = CyclerefMove::default();
        while cycleref_g76_next(h, &mut m) == 1 {
            stepped.push(m);
        }
        assert_eq!(cycleref_g76_next(h, &mut m), 0);
        cycleref_g76_free(h);
        let expanded: Vec<_> = expand(&text, &options(CyclerefProfile::Gsk988))
            .unwrap()
            .into_iter()
            .map(|m| CyclerefMove { line: 0, ..m })
            .collect();
        assert_eq!(stepped, expanded);

        // Every kind of run-out and infeed round-trips.
        for run_out in [
            cycleref::RunOut::None,
            cycleref::RunOut::Amounts { short: 1_500, long: 2_000 },
            cycleref::RunOut::Chamfer { tenths_of_lead: 10, angle_degrees: 30, long: Some(2_500) },
        ] {
            for infeed in
                [cycleref::Infeed::RightFlank, cycleref::Infeed::RightCentre, cycleref::Infeed::LeftRight]
            {
                let c = cycleref::G76Cycle { run_out, infeed, ..cycle };
                assert_eq!(CyclerefG76Params::from_cycle(&c).cycle(), Ok(c));
            }
        }

        let inside = CyclerefG76Params { start_x: 62_000, ..params };
        assert!(cycleref_g76_new(&inside, &mut err).is_null());
        assert_eq!((err.status, err.line), (CyclerefStatus::CycleError, 0));
        for bad in [
            CyclerefG76Params { run_out_kind: 3, ..params },
            CyclerefG76Params { lead_word: 2, ..params },
            CyclerefG76Params { increment: 3, ..params },
            CyclerefG76Params { infeed: 3, ..params },
        ] {
            assert!(cycleref_g76_new(&bad, &mut err).is_null());
            assert_eq!(err.status, CyclerefStatus::InvalidArgument);
        }
        assert!(cycleref_g76_new(ptr::null(), ptr::null_mut()).is_null());
        assert_eq!(cycleref_g76_next(ptr::null_mut(), &mut m), CyclerefStatus::InvalidArgument as i32);
        cycleref_g76_free(ptr::null_mut());
    }
}

#[test]
#[allow(unsafe_code)]
fn static_strings() {
    // SAFETY: both functions return static NUL-terminated strings.
    unsafe {
        assert_eq!(CStr::from_ptr(cycleref_version()).to_str(), Ok(env!("CARGO_PKG_VERSION")));
        assert_eq!(CStr::from_ptr(cycleref_status_name(-1)).to_str(), Ok("CYCLEREF_STATUS_BUFFER_TOO_SMALL"));
        assert_eq!(CStr::from_ptr(cycleref_status_name(0)).to_str(), Ok("CYCLEREF_STATUS_OK"));
        assert_eq!(CStr::from_ptr(cycleref_status_name(42)).to_str(), Ok("unknown status"));
    }
    for s in [
        CyclerefStatus::Ok,
        CyclerefStatus::BufferTooSmall,
        CyclerefStatus::ProgramError,
        CyclerefStatus::CycleError,
        CyclerefStatus::InvalidArgument,
        CyclerefStatus::Panic,
    ] {
        // SAFETY: as above.
        let name = unsafe { CStr::from_ptr(cycleref_status_name(s as i32)) };
        assert_eq!(name.to_str().unwrap(), format!("CYCLEREF_STATUS_{}", screaming(&format!("{s:?}"))));
    }
}

fn screaming(camel: &str) -> String {
    let mut out = String::new();
    for (i, c) in camel.chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(c.to_ascii_uppercase());
    }
    out
}
