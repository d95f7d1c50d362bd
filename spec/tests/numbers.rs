//! The lexer's number shortcuts (`Number::scaled`, `integer`, `exact`,
//! `is_positive`, and the number position a lexed `Word` carries) against
//! their definitions through `rust_decimal`, on generated words: the fast
//! paths of the reader give exactly what the exact value gives.

use cycleref_spec::lex::{Lexer, Word};
use proptest::prelude::*;
use rust_decimal::Decimal;

/// A word's text: a letter, perhaps spaces, a sign, digits with perhaps a
/// point (leading and trailing zeros and long runs of digits included).
fn word_text() -> impl Strategy<Value = String> {
    (
        prop::sample::select(vec!["X", "G", "F", "S", "P"]),
        prop::sample::select(vec!["", " ", "  \t"]),
        prop::sample::select(vec!["", "-", "+"]),
        "0{0,3}[0-9]{0,24}",
        prop::option::of("0{0,3}[0-9]{0,24}0{0,3}"),
    )
        .prop_filter("a number", |(_, _, _, int, frac)| {
            !int.is_empty() || frac.as_ref().is_some_and(|f| !f.is_empty())
        })
        .prop_map(|(l, sp, sign, int, frac)| match frac {
            Some(f) => format!("{l}{sp}{sign}{int}.{f}"),
            None => format!("{l}{sp}{sign}{int}"),
        })
}

/// 10^k as a Decimal, or None beyond its range.
fn pow10(k: u32) -> Option<Decimal> {
    (0..k).try_fold(Decimal::ONE, |p, _| p.checked_mul(Decimal::TEN))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn shortcuts_agree_with_the_exact_value(text in word_text(), scale in 0_u32..8) {
        let block = Lexer::new(text.as_bytes()).next().expect("a block").expect("lexes");
        let lexed = block.words[0];
        // The lexer's precomputed number position gives what a word made
        // from its text alone gives.
        let n = lexed.number();
        let made = Word::new(lexed.letter, &text);
        prop_assert_eq!(n, made.number());
        // ... and the two words are equal: where the number is is no part
        // of a word's value.
        prop_assert_eq!(lexed, made);
        let d = n.decimal();
        // integer: the value when whole and within an i64.
        let whole = d.filter(|d| d.fract().is_zero()).and_then(|d| i64::try_from(d).ok());
        prop_assert_eq!(n.integer(), whole, "integer of {}", text);
        // is_positive: > 0 where a Decimal holds the value.
        prop_assert_eq!(n.is_positive(), d.is_some_and(|d| d > Decimal::ZERO), "is_positive of {}", text);
        // exact(scale): value × 10^scale when whole (checked where a Decimal
        // holds both the value and the product).
        if let Some(p) = d.zip(pow10(scale)).and_then(|(d, p)| d.checked_mul(p)) {
            let expect = if p.fract().is_zero() { i128::try_from(p).ok() } else { None };
            prop_assert_eq!(n.exact(scale), expect, "exact({}) of {}", scale, text);
        }
        // scaled(scale): Some(Some(v)) exactly when v = value × 10^scale is
        // whole; Some(None) when finer.
        match n.scaled(scale) {
            Some(Some(v)) => prop_assert_eq!(Some(i128::from(v)), n.exact(scale), "scaled({}) of {}", scale, text),
            Some(None) => prop_assert_eq!(n.exact(scale), None, "scaled({}) of {}", scale, text),
            None => {}
        }
    }
}

#[test]
fn worked_examples() {
    let word = |t: &'static str| Lexer::new(t.as_bytes()).next().unwrap().unwrap().words[0];
    // G75.1 by its exact value, whatever the zeros.
    assert_eq!(word("G75.1").number().exact(1), Some(751));
    assert_eq!(word("G075.10").number().exact(1), Some(751));
    assert_eq!(word("G75.11").number().exact(1), None);
    assert_eq!(word("G-75.1").number().exact(1), Some(-751));
    // A lead in units of 10^-6.
    assert_eq!(word("F0.0001").number().exact(6), Some(100));
    assert_eq!(word("F9999").number().exact(6), Some(9_999_000_000));
    // Zero in any spelling is not positive; a minus sign is not.
    assert!(!word("S0.000").number().is_positive());
    assert!(!word("S-5").number().is_positive());
    assert!(word("S .5").number().is_positive());
    // 19 nines do not fit an i64 whole... but 18 do.
    assert_eq!(word("P999999999999999999").number().integer(), Some(999_999_999_999_999_999));
    assert_eq!(word("P99999999999999999999").number().integer(), None);
    assert_eq!(word("X-0012.500").number().scaled(3), Some(Some(-12_500)));
    assert_eq!(word("X1.0005").number().scaled(3), Some(None));
    // The shortcut's edge: 18 digits with the decimals are still scaled
    // (19 are left to the exact path, which gives the same value).
    assert_eq!(word("X123456789012345.678").number().scaled(3), Some(Some(123_456_789_012_345_678)));
    assert_eq!(word("X1234567890123456.789").number().scaled(3), None);
    // The one-pass shortcut of scaled: finer digits that are zeros, a
    // point first or last, leading zeros that push it to the long way.
    assert_eq!(word("X1.50000").number().scaled(3), Some(Some(1_500)));
    assert_eq!(word("X1.50001").number().scaled(3), Some(None));
    assert_eq!(word("X.5").number().scaled(3), Some(Some(500)));
    assert_eq!(word("X-5.").number().scaled(3), Some(Some(-5_000)));
    assert_eq!(word("X000000000000001.5").number().scaled(3), Some(Some(1_500)));
    // exact's i64 shortcut has the same edge: 12 digits at scale 6 are 18
    // (the shortcut), 13 are 19 (the i128 loop); both exact.
    assert_eq!(word("F999999999999").number().exact(6), Some(999_999_999_999_000_000));
    assert_eq!(word("F-9999999999999.5").number().exact(6), Some(-9_999_999_999_999_500_000));
    // Longer than 20 characters: decided through the exact value, and zero
    // written long is still not positive.
    assert!(!word("S0.000000000000000000000000").number().is_positive());
    assert!(word("S0.000000000000000000000001").number().is_positive());
    // A word longer than 255 bytes takes the slow path to its number.
    let long = format!("X-{}1.5", "0".repeat(300));
    let w = Lexer::new(long.as_bytes()).next().unwrap().unwrap().words[0];
    assert_eq!(w.number(), Word::new('X', &long).number());
    assert_eq!(w.number().scaled(3), Some(Some(-1_500)));
}

#[test]
fn lexer_edges() {
    use cycleref_spec::lex::lex;
    // A point without digits is no number.
    let e = lex("G01 X. Z1").expect_err("X. has no number");
    assert!(e.to_string().contains("the address `X` without a number"), "{e}");
    assert!(lex("G01 X0. Z.5").is_ok());
    // A comment-only segment after a block end belongs to the block before;
    // a block after it on the same line is read too.
    let blocks = lex("G01 X1 ;(one); G01 X2\nG01 X3").expect("lexes");
    let texts: Vec<String> = blocks.iter().map(|b| b.text_lossy().into_owned()).collect();
    assert_eq!(texts, ["G01 X1 (one)", "G01 X2", "G01 X3"]);
    assert_eq!(blocks.iter().map(|b| b.line).collect::<Vec<_>>(), [1, 1, 2]);
    // A word longer than 255 bytes whose digits start early still reads
    // (its number found again from its text).
    let long = format!("X1{}", "0".repeat(300));
    let w = lex(&long).expect("lexes")[0].words[0];
    assert_eq!(w.number().int_digits().len(), 301);
    assert_eq!(w.number(), Word::new('X', &long).number());
    // Around the byte limit of the number's place: 254, 255 and 256 digits
    // before the point, and as many spaces before the digits.
    for n in [254, 255, 256] {
        for text in [format!("X{}.5", "1".repeat(n)), format!("X{}1.5", " ".repeat(n))] {
            let w = lex(&text).expect("lexes")[0].words[0];
            assert_eq!(w.number(), Word::new('X', &text).number(), "{n}");
            assert!(w.number().has_point(), "{n}");
        }
    }
}

/// A number's `Debug` shows its digits as text (they are kept as bytes).
#[test]
fn a_number_debugs_as_text() {
    let w = Lexer::new(b"X-060.640").next().unwrap().unwrap().words[0];
    assert_eq!(
        format!("{:?}", w.number()),
        r#"Number { negative: true, digits: "060.640", point: Some(3) }"#
    );
}
