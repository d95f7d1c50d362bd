//! Generated part programs for the `pipeline` benchmarks: the criterion
//! group `pipeline` and the `pipeline` binary, which runs the `cycleref`
//! command on programs of 1, 5 and 50 MB.
//!
//! The programs are for the **GSK 980TDi** profile at IS-B (`cycleref
//! --profile gsk980`, the default increment), the profile that reads all
//! three cycles. A program is a header (`O`, `G50`, spindle), then parts
//! of about a dozen lines repeated until the requested size, then `M30`.
//! Part `i` is, in order:
//!
//! * a comment naming the part;
//! * a `G00` to the cycle's start point;
//! * the cycle: for `i % 16 == 15` a G75.1 groove (its two blocks, seed
//!   001's groove at IS-B with `I4 J1`), for `i % 8 == 7` a continuous
//!   G32 thread (three blocks: taper, straight, taper with run-out),
//!   otherwise a G76 M68x6-like thread (block 1 `P020560 Q150 R0.1`, block
//!   2 `X60.64 Z-… P3680 Q…`: the length varies with `i` over 40–70 mm and
//!   the first depth over 1.8, 1.2 and 0.9 mm, 6, 11 or 17 passes);
//! * a `G00 X100 Z50` return;
//! * five to seven `G01`/`G00` blocks (turning moves with varying
//!   coordinates and feeds, some with trailing comments) and, every
//!   third part, a comment-only line.
//!
//! With `cycles: false` the same parts are written without their cycle
//! blocks: a program the reader alone handles (`expand` copies it), used
//! to measure the reader.
//!
//! The text is a pure function of its arguments (no randomness), so every
//! run and every binary reads the same bytes.

use std::fmt::Write as _;

use cycleref_spec::{Machine, ProfileName};

/// The command-line options that select the machine of the programs.
pub const PROFILE_ARGS: [&str; 2] = ["--profile", "gsk980"];

/// The machine of the programs: GSK 980TDi, IS-B, metric, diameters.
#[must_use]
pub fn machine() -> Machine {
    Machine::new(ProfileName::Gsk980)
}

/// A generated program and what it holds.
#[derive(Clone, Debug)]
pub struct Generated {
    /// The program's text.
    pub text: String,
    /// Number of lines (blocks, comments included).
    pub lines: usize,
    /// Number of G76 cycles.
    pub g76: usize,
    /// Number of G32 blocks.
    pub g32: usize,
    /// Number of G75.1 cycles.
    pub g75: usize,
    /// The 1-based line of the last G76 block 2 (for `plot --line`), 0 when
    /// there is none.
    pub last_g76_line: usize,
}

impl Generated {
    /// The number of cycles (G76, G32 blocks, G75.1).
    #[must_use]
    pub fn cycles(&self) -> usize {
        self.g76 + self.g32 + self.g75
    }
}

/// A program of about `bytes` bytes (at most one part more), with the
/// cycles or without them; see the module's documentation.
#[must_use]
pub fn program(bytes: usize, cycles: bool) -> Generated {
    let mut g = Generated {
        text: String::with_capacity(bytes + 1024),
        lines: 0,
        g76: 0,
        g32: 0,
        g75: 0,
        last_g76_line: 0,
    };
    let line = |g: &mut Generated, s: &str| {
        g.text.push_str(s);
        g.text.push('\n');
        g.lines += 1;
    };
    line(&mut g, "O0100;");
    line(&mut g, "G50 X100 Z50;");
    line(&mut g, "M03 S500;");
    let mut s = String::new();
    let mut i = 0_usize;
    while g.text.len() < bytes {
        line(&mut g, &format!("(part {i})"));
        if i % 16 == 15 {
            line(&mut g, "G00 X60 Z30;");
            if cycles {
                line(&mut g, "G75.1 X50 Z30 P3000 Q5000 H-20 D-10 A45 B30;");
                line(&mut g, "G75.1 R0.5 I4 J1;     (groove)");
                g.g75 += 1;
            }
        } else if i % 8 == 7 {
            line(&mut g, "G00 X30 Z2;");
            if cycles {
                line(&mut g, "G32 X34 Z-10 F2;");
                line(&mut g, "G32 Z-30;");
                line(&mut g, "G32 X38 Z-40 J1;      (thread, run-out)");
                g.g32 += 3;
            }
        } else {
            line(&mut g, "G00 X80 Z10;");
            if cycles {
                let z = 40 + i % 31;
                let q = [1800, 1200, 900][i % 3];
                line(&mut g, "G76 P020560 Q150 R0.1;");
                s.clear();
                let _ = write!(s, "G76 X60.64 Z-{z} P3680 Q{q} F6;");
                line(&mut g, &s);
                g.g76 += 1;
                g.last_g76_line = g.lines;
            }
        }
        line(&mut g, "G00 X100 Z50;");
        for k in 0..5 + i % 3 {
            let x = 20 + (i + k) % 50;
            let z = (i * 7 + k * 3) % 97;
            let frac = (i * 13 + k) % 1000;
            s.clear();
            let _ = match (i + k) % 5 {
                0 => write!(s, "G01 X{x}.{frac:03} Z-{z}.5 F0.2;"),
                1 => write!(s, "G01 X{x}.{frac:03} Z-{z}.25 F0.15; (finish {k})"),
                2 => write!(s, "G00 X{x}.5 Z-{z}.{frac:03};"),
                3 => write!(s, "G01 Z-{z}.{frac:03};"),
                _ => write!(s, "X{x}.{frac:03};"),
            };
            line(&mut g, &s);
        }
        if i % 3 == 0 {
            line(&mut g, "(check the insert)");
        }
        line(&mut g, "G00 X100 Z50;");
        i += 1;
    }
    line(&mut g, "M30;");
    g
}

/// The command-line options of [`linuxcnc_program`].
pub const LINUXCNC_ARGS: [&str; 2] = ["--profile", "linuxcnc"];

/// A LinuxCNC program of `cycles` G76 cycles for the peer benchmark
/// (`pipeline`: `rs274 -g` against `cycleref expand|check --profile
/// linuxcnc`): the cycle of `examples/linuxcnc-m20-taper.ngc` (M20x1.5,
/// entry and exit tapers, diameter mode), each after a `G0 X22 Z2` to its
/// start, with its Z over −20 … −30 mm (41 values) and its thread depth K
/// over 1.84 … 1.92 mm (9 values), so that no two neighbours are alike.
#[must_use]
pub fn linuxcnc_program(cycles: usize) -> String {
    let mut s = String::with_capacity(80 * cycles + 256);
    let _ = writeln!(s, "({cycles} LinuxCNC G76 cycles: examples/linuxcnc-m20-taper.ngc's, Z and K varied)");
    s.push_str("G18 G21 G7\nM3 S500\n");
    for i in 0..cycles {
        let z = 2000 + (i % 41) * 25; // hundredths of a mm
        let k = 184 + i % 9;
        let _ = writeln!(
            s,
            "G0 X22 Z2\nG76 P1.5 Z-{}.{:02} I-2 J0.3 R1.5 K{}.{:02} Q29.5 H1 E1 L3",
            z / 100,
            z % 100,
            k / 100,
            k % 100
        );
    }
    s.push_str("G0 X30 Z5\nM5\nM2\n");
    s
}

/// A G75.1-heavy program for the GSK 980TDi ([`PROFILE_ARGS`]): `grooves`
/// of seed 001's groove at IS-B (the mixed program's, `I4 J1`), each after
/// a `G00` to its start point, the groove and its start shifted in Z by
/// 0 … −9.75 mm (40 values); nothing else between them.
#[must_use]
pub fn g75_program(grooves: usize) -> String {
    let mut s = String::with_capacity(110 * grooves + 64);
    s.push_str("O0200;\nG50 X100 Z50;\nM03 S500;\n");
    for i in 0..grooves {
        let z = 3000 - (i % 40) * 25; // hundredths of a mm
        let (zi, zf) = (z / 100, z % 100);
        let _ = writeln!(
            s,
            "G00 X60 Z{zi}.{zf:02};\nG75.1 X50 Z{zi}.{zf:02} P3000 Q5000 H-20 D-10 A45 B30;\nG75.1 R0.5 I4 J1;"
        );
    }
    s.push_str("G00 X100 Z50;\nM30;\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use cycleref_spec::reader::{Item, Reader};

    #[test]
    fn reads_with_every_cycle() {
        let g = program(20_000, true);
        assert!(g.text.len() >= 20_000 && g.text.len() < 21_000);
        assert!(g.g76 > 0 && g.g32 > 0 && g.g75 > 0);
        let m = machine();
        let (mut g76, mut g32, mut g75) = (0, 0, 0);
        for item in Reader::new(g.text.as_bytes(), &m) {
            match item.expect("the generated program reads") {
                Item::G76(c) => {
                    cycleref::engine::expand_g76(&c.cycle).expect("valid G76");
                    g76 += 1;
                }
                Item::G32(_) => g32 += 1,
                Item::G75(_) => g75 += 1,
                Item::G92(_) => panic!("the generated programs have no G92"),
                Item::LinuxCncG76(_) => panic!("the generated programs have no LinuxCNC G76"),
                Item::Source(_) | Item::Move(_) | Item::G76Params(_) | Item::G75Params(_) => {}
            }
        }
        assert_eq!((g76, g32, g75), (g.g76, g.g32, g.g75));
        assert_eq!(g.text.lines().count(), g.lines);
        assert!(g.text.lines().nth(g.last_g76_line - 1).is_some_and(|l| l.starts_with("G76 X")));
    }

    #[test]
    fn without_cycles_reads_and_is_deterministic() {
        let g = program(10_000, false);
        assert_eq!(g.cycles(), 0);
        let m = machine();
        assert!(Reader::new(g.text.as_bytes(), &m).all(|i| matches!(i, Ok(Item::Source(_) | Item::Move(_)))));
        assert_eq!(program(10_000, false).text, g.text);
    }

    /// Every cycle of a program, read and expanded by the engine; their
    /// count.
    fn cycles_of(text: &str, machine: &Machine) -> usize {
        use cycleref_spec::pipeline::{expand, Cycle, Engine};
        let mut n = 0;
        for item in Reader::new(text.as_bytes(), machine) {
            let item = item.expect("the generated program reads");
            if let Some(c) = Cycle::of(&item) {
                assert!(expand(c, Engine::Impl).expect("a valid cycle").count() > 0);
                n += 1;
            }
        }
        n
    }

    #[test]
    fn linuxcnc_program_reads_and_expands() {
        let text = linuxcnc_program(12);
        assert!(text.contains("G76 P1.5 Z-20.00 I-2 J0.3 R1.5 K1.84 Q29.5 H1 E1 L3"));
        assert!(text.contains("Z-22.00 I-2 J0.3 R1.5 K1.92 "));
        let m = Machine::new(ProfileName::LinuxCnc);
        assert_eq!(cycles_of(&text, &m), 12);
        assert!(Reader::new(text.as_bytes(), &m).all(|i| !matches!(i, Ok(Item::G76(_)))));
        assert_eq!(LINUXCNC_ARGS[1], "linuxcnc");
    }

    #[test]
    fn g75_program_reads_and_expands() {
        let text = g75_program(41);
        let m = machine();
        assert_eq!(cycles_of(&text, &m), 41);
        let g75 = Reader::new(text.as_bytes(), &m).filter(|i| matches!(i, Ok(Item::G75(_)))).count();
        assert_eq!(g75, 41);
        assert!(text.contains("G75.1 X50 Z20.25 P3000"));
    }
}
