//! Errors at the right place, shown safely (issue 30, found 5 and 6): each
//! case failed at 6457e19. Expected lines and words are read off the
//! programs by hand.

mod common;

use common::run;

fn expand(profile: &str, name: &str, text: &[u8], extra: &[&str]) -> (i32, String, usize) {
    let p = common::tmp("errors-in-place", name, "");
    std::fs::write(&p, text).expect("writes");
    let mut args = vec!["expand", "--profile", profile];
    args.extend_from_slice(extra);
    let path = p.to_str().expect("utf-8").to_string();
    args.push(&path);
    let out = run(&args, None);
    (out.status.code().expect("status"), String::from_utf8_lossy(&out.stderr).into_owned(), out.stdout.len())
}

/// The square groove of `examples/gsk980-g75-square.nc`: block 1 at line 2,
/// block 2 at line 3.
fn groove(block1_extra: &str, block2: &str) -> String {
    format!(
        "M03 S800\nG00 X40 Z5\nG75.1 X30 Z0 P2000 Q3000 H-6 D-8{block1_extra}\n{block2}\nG00 X100 Z50\nM30\n"
    )
}

#[test]
fn a_g75_block_1_value_is_reported_at_block_1() {
    let block2 = "G75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011";
    for (extra, words) in
        [(" A0", "A(∠a) (flank angle 1) = 0.0000"), (" B95", "B(∠b) (flank angle 2) = 95.0000")]
    {
        let (code, err, out) = expand("gsk980", "g75.nc", groove(extra, block2).as_bytes(), &[]);
        assert_eq!((code, out), (2, 0), "{err}");
        assert!(err.contains("g75.nc: line 3: ") && err.contains(words), "{extra}: {err}");
    }
    // Q0 of block 1 (the axial step).
    let text = groove("", block2).replace("Q3000", "Q0");
    let (code, err, _) = expand("gsk980", "g75q.nc", text.as_bytes(), &[]);
    assert_eq!(code, 2);
    assert!(err.contains("line 3: Q(Δk) (axial step) = 0.000 is outside its range"), "{err}");
}

#[test]
fn cr_only_line_ends_are_line_ends() {
    let text = b"G50 X100 Z50\rG00 X80 Z10\rG32 Z-20 F2 M03 S500\rG00 X100\rG01 X1 X2\r";
    let (code, err, _) = expand("gsk980", "cr.nc", text, &[]);
    assert_eq!(code, 2);
    assert!(err.contains("cr.nc: line 5, word `X2`: the address appears twice"), "{err}");
}

#[test]
fn control_bytes_are_escaped_and_long_words_cut() {
    let (code, err, _) = expand("gsk980", "nul.nc", b"G50 X100 Z50\nG00 X1 Z1\nG01 X1\x00 Z2\n", &[]);
    assert_eq!(code, 2);
    assert!(err.contains("line 3: cannot read the character `\\u{0}`") && !err.contains('\0'), "{err:?}");
    let word = format!("X1{}.0", "9".repeat(5000));
    let text = format!("G50 X100 Z50\nG00 {word} Z10\nM30\n");
    let (code, err, _) = expand("gsk980", "word.nc", text.as_bytes(), &[]);
    assert_eq!(code, 2);
    // 64 characters of the word and an ellipsis.
    assert!(err.contains(&format!("line 2, word `{}…`", &word[..64])), "{}", &err[..200.min(err.len())]);
    assert!(err.len() < 400, "{} bytes", err.len());
}

#[test]
fn a_line_longer_than_the_limit_is_an_error_naming_it() {
    let text = format!("G50 X100 Z50\nG00 X80 Z10\n({})\nM30\n", "x".repeat(3 << 20));
    let (code, err, out) = expand("gsk980", "long.nc", text.as_bytes(), &[]);
    assert_eq!((code, out), (2, 0));
    assert!(err.contains("long.nc: line 3: ") && err.contains("longer than 1048576 bytes"), "{err}");
}

#[test]
fn a_bad_parameter_is_the_files_error_named_by_its_key() {
    // Issue 30, found 5: `5142 = 9223372036854775807` was reported at the
    // program line that first used it (and not at all when the block gave
    // P(m) itself). Reading R-PARAMS: 5142 (m) is 1..99 on the 988TA.
    let params = common::tmp(
        "errors-in-place",
        "bad.toml",
        "profile = \"gsk988\"\n[parameters]\n5142 = 9223372036854775807\n",
    );
    let params = params.to_str().expect("utf-8").to_string();
    let m68 = b"G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n";
    let (code, err, out) = expand("gsk988", "m68.nc", m68, &["--params", &params]);
    assert_eq!((code, out), (2, 0), "{err}");
    assert!(err.contains("bad.toml: parameter: 5142 = 9223372036854775807 is outside 1..99"), "{err}");
    assert!(!err.contains("line"), "{err}");
}

#[test]
fn a_lead_with_too_many_decimals_says_so() {
    // Issue 30, found 6: F2.1234567 said only "outside the range table".
    let text = b"G50 X100 Z50 M3 S300\nG00 X80 Z10\nG32 Z-20 F2.1234567\n";
    let (code, err, _) = expand("gsk980", "lead.nc", text, &[]);
    assert_eq!(code, 2);
    assert!(
        err.contains("line 3, word `F2.1234567`: the value is outside the range table: F 0.0001..9999 mm, with at most 6 decimals (this lead has 7)"),
        "{err}"
    );
}

/// Seed 004's first FANUC example (`examples/fanuc-external.nc`), run
/// with the 988TA's profile (the default): the 988TA reads G76's words its
/// own way, and the start point then lies inside the thread. The alarm
/// names the profile in force and the profiles that read the program
/// without error (issue 35: "the default profile surprises").
#[test]
fn a_cycle_alarm_names_the_profile_and_the_profiles_that_accept_the_program() {
    let program = b"O5018;\nN10 G99 G21;\nN20 M03 S400;\nN30 T0303;\nN40 G00 X26.0 Z3.0;\n\
                    N460 G76 P020560 Q100 R0.1;\nN60 G76 X21.4 Z-26.0 R0 P1300 Q400 F2.0;\n\
                    N70 G00 X100.0;\nN80 Z200.0;\nN90 M30;\n";
    let (code, err, out) = expand("gsk988", "fanuc-under-gsk988", program, &[]);
    assert_eq!((code, out), (2, 0));
    assert!(err.starts_with("cycleref: error[cycle:start_inside_thread]: "), "{err}");
    assert!(err.contains(": line 7, G76: the start point A lies inside the thread"), "{err}");
    assert!(
        err.trim_end().ends_with(
            "(profile gsk988); the program reads without error with --profile fanuc or --profile gsk980 \
             (the profile decides how the cycle's words are read)"
        ),
        "{err}"
    );
    // And it does: both expand it.
    for profile in ["fanuc", "gsk980"] {
        let (code, err, out) = expand(profile, &format!("fanuc-under-{profile}"), program, &[]);
        assert_eq!(code, 0, "{profile}: {err}");
        assert!(out > 0);
    }
    // A reader error (not a cycle's alarm) names no profile and tries none.
    let (code, err, _) = expand("gsk988", "reader-error", b"G00 X10 N10\n", &[]);
    assert_eq!(code, 2);
    assert!(!err.contains("profile"), "{err}");
}
