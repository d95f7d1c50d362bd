//! Any bytes, read with a profile the first byte chooses, the reader
//! alone (no engine): the
//! reader yields items or an error with a line, never panics, and the
//! line-fed reader (a program file read a line at a time through one
//! reused buffer) gives the same items and the same error as the reader of
//! the whole text.
//!
//! `read_expand` checks the same and then expands every cycle with both
//! engines; the exact reference makes it slow (about 1 000 runs a second).
//! This target spends its runs on the reader only, at tens of thousands a
//! second, so that the reader's corner cases (words, numbers, comments,
//! encodings, modal state across blocks) get the bulk of the executions.
#![no_main]

use cycleref_spec::{LineReader, Machine, ProfileName, Reader};
use libfuzzer_sys::fuzz_target;

/// The profiles, one per run: the input's first byte chooses.
const PROFILES: [ProfileName; 4] = [ProfileName::Fanuc, ProfileName::Gsk980, ProfileName::Gsk988, ProfileName::LinuxCnc];

fuzz_target!(|input: &[u8]| {
    // The first byte chooses the profile (so that a run reads its text
    // once each way, not four times), the rest is the program.
    let Some((&choice, data)) = input.split_first() else { return };
    {
        let machine = Machine::new(PROFILES[usize::from(choice) % PROFILES.len()]);
        let mut whole = Reader::new(data, &machine);
        let mut lines = LineReader::new(&machine);
        let mut buf = Vec::new();
        for line in data.split_inclusive(|&b| b == b'\n') {
            buf.clear();
            buf.extend_from_slice(line);
            while let Some(item) = lines.next_in(&buf) {
                let same = whole.next();
                assert_eq!(same.as_ref(), Some(&item), "{:?}", String::from_utf8_lossy(data));
                if let Err(e) = item {
                    assert!(e.line >= 1, "an error without a line: {e}");
                }
            }
        }
        let last = lines.finish().err();
        if let Some(e) = &last {
            assert!(e.line >= 1, "an error without a line: {e}");
        }
        assert_eq!(whole.next(), last.map(Err), "{:?}", String::from_utf8_lossy(data));
        assert_eq!(whole.next(), None);
    }
});
