//! Any bytes, read with every profile: the reader yields items or an error
//! with a line, never panics; every cycle it accepts is expanded by both
//! engines through the one pipeline, which must give the same moves or the
//! same error.
#![no_main]

use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::{Machine, ProfileName, Reader};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for profile in [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988] {
        let mut machine = Machine::new(profile);
        machine.pass_limit = 2_000;
        for item in Reader::new(data, &machine) {
            let item = match item {
                Ok(item) => item,
                Err(e) => {
                    assert!(e.line >= 1, "an error without a line: {e}");
                    break;
                }
            };
            let Some(cycle) = Cycle::of(&item) else { continue };
            let ours = expand(cycle, Engine::Impl).map(|m| m.take(20_000).collect::<Vec<_>>());
            let reference = expand(cycle, Engine::Spec).map(|m| m.take(20_000).collect::<Vec<_>>());
            assert_eq!(ours, reference, "{:?}", String::from_utf8_lossy(data));
        }
    }
});
