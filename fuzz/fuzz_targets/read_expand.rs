//! Any text, read with every profile: the reader returns a program or an
//! error, never panics; every cycle it accepts is expanded by both engines,
//! which must give the same moves or the same error.
#![no_main]

use cycleref_spec::{read, Machine, ProfileName};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    for profile in [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988] {
        let mut machine = Machine::new(profile);
        machine.pass_limit = 2_000;
        let Ok(program) = read(text, &machine) else { continue };
        for call in program.cycles() {
            let ours = cycleref::expand_g76(&call.cycle).map(|m| m.take(20_000).collect::<Vec<_>>());
            let reference = cycleref_spec::g76::expand(&call.cycle).map(|mut v| {
                v.truncate(20_000);
                v
            });
            assert_eq!(ours, reference, "{text:?}");
        }
        for call in program.threads() {
            let ours = cycleref::expand_g32(&call.g32).map(Iterator::collect::<Vec<_>>);
            assert_eq!(ours, cycleref_spec::g32::expand(&call.g32), "{text:?}");
        }
    }
});
