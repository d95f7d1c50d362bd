//! Any bytes, read with every profile (linuxcnc included): the reader yields items or an error
//! with a line, never panics; every cycle it accepts is expanded by both
//! engines through the one pipeline, which must give the same moves or the
//! same error. The same bytes fed to the line-fed reader a line at a time
//! (as a program file is read) give the same items and the same error.
#![no_main]

use cycleref_spec::pipeline::{expand, Cycle, Engine};
use cycleref_spec::{LineReader, Machine, ProfileName, Reader};
use libfuzzer_sys::fuzz_target;

/// `data` read a line at a time through one reused buffer gives what the
/// reader of the whole text gives.
fn same_line_by_line(data: &[u8], machine: &Machine) {
    let mut whole = Reader::new(data, machine);
    let mut lines = LineReader::new(machine);
    let mut buf = Vec::new();
    for line in data.split_inclusive(|&b| b == b'\n') {
        buf.clear();
        buf.extend_from_slice(line);
        while let Some(item) = lines.next_in(&buf) {
            assert_eq!(whole.next().as_ref(), Some(&item), "{:?}", String::from_utf8_lossy(data));
        }
    }
    assert_eq!(whole.next(), lines.finish().err().map(Err), "{:?}", String::from_utf8_lossy(data));
    assert_eq!(whole.next(), None);
}

fuzz_target!(|data: &[u8]| {
    for profile in [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::LinuxCnc] {
        let mut machine = Machine::new(profile);
        machine.pass_limit = 2_000;
        same_line_by_line(data, &machine);
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
