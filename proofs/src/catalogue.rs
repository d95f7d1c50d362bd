//! Every Kani harness in one table: its property, window, body, contract,
//! stubs, unwind bound, solver, CI tier and how the shim runs it here.
//!
//! The table is the one home of that information. From it come
//! `proofs/src/kani_proofs.rs` (the `#[kani::proof]` functions, each calling
//! its body in [`crate::bodies`]), the CI matrix in
//! `.github/workflows/kani.yml` (one job per harness) and the table of
//! `proofs/README.md`; `proofs/tests/catalogue.rs` fails when any of them
//! differs from what [`kani_source`], [`workflow`] and
//! [`readme_table`] produce (`CYCLEREF_BLESS=1` rewrites them), and
//! `proofs/tests/kani_windows.rs` runs every body over its window.

use std::fmt::Write as _;

use crate::bodies;

/// Which CI tier runs a harness under Kani.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tier {
    /// A job per harness on every push, required to pass: harnesses whose
    /// windows are small and whose kernels are stubbed by contracts.
    Required,
    /// A job per harness on a schedule (weekly) and by hand, not required:
    /// harnesses that collect moves into a `Vec`, run the interval
    /// kernels unstubbed, or span whole 64-bit ranges, so that CBMC may not
    /// finish within the harness timeout. Compiled only with the proofs
    /// crate's feature `kani-scheduled`.
    Scheduled,
}

/// How `proofs/tests/kani_windows.rs` runs a body here.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Run {
    /// Every input of the window (the shim's exhaustive mode), at most this
    /// many runs; every declared cover must be satisfied.
    Exhaustive(u64),
    /// `samples` uniform draws and `edges` draws at the edges of every
    /// range (`shim::Mode::Edges`: the corners and the values near 0);
    /// every declared cover must be satisfied by one or the other.
    Sampled {
        /// Uniform samples.
        samples: u64,
        /// Draws at the edges.
        edges: u64,
    },
}

/// One Kani harness.
#[derive(Clone, Debug)]
pub struct Harness {
    /// The function's name in `kani_proofs.rs` (Kani's `kani_proofs::NAME`).
    pub name: String,
    /// The property, in one sentence.
    pub property: &'static str,
    /// The window, by the name of its constant or function.
    pub window: String,
    /// The body, run by Kani and by the shim alike.
    pub body: fn(),
    /// The function whose contract the harness proves (`proof_for_contract`).
    pub contract: Option<&'static str>,
    /// The functions replaced by their verified contracts (`stub_verified`).
    pub stubs: &'static [&'static str],
    /// `#[kani::unwind(N)]`.
    pub unwind: u32,
    /// `#[kani::solver(cadical)]`.
    pub cadical: bool,
    /// The CI tier.
    pub tier: Tier,
    /// How the shim runs the body here.
    pub run: Run,
}

/// The engine kernels the G76 harnesses reach, replaced by their contracts.
const G76_STUBS: &[&str] = &[
    "cycleref::engine::arith::round_sqrt",
    "cycleref::engine::arith::round_sqrt_near",
    "cycleref::tan::mul_tan_round",
    "cycleref::engine::arith::round_div",
    "cycleref::engine::arith::saturate_i64",
];

/// The kernels of G32 and G92.
const LINE_STUBS: &[&str] = &["cycleref::engine::arith::round_div", "cycleref::engine::arith::saturate_i64"];

/// The kernels of G75.1.
const GROOVE_STUBS: &[&str] = &[
    "cycleref::engine::arith::floor_div",
    "cycleref::engine::arith::ceil_div",
    "cycleref::engine::arith::saturate_i64",
];

/// The unwind bounds of the G76 harnesses split per infeed mode
/// (`windows::INFEED_MODES`: D0, D1, D2, centre, left flank, alternating),
/// one above the most moves measured over each window by
/// `proofs/tests/unwind.rs`: 78 in D2 (13 passes of 6 moves), 48 in the
/// other modes (8 passes of 6).
const BY_MODE: [u32; 6] = [49, 49, 79, 49, 49, 49];

/// P6's bounds per mode: 80 moves in D2 on either side (engine and the
/// integer restatement), 45 in the other modes.
const EQUIVALENCE_BY_MODE: [u32; 6] = [46, 46, 81, 46, 46, 46];

const SAMPLED: Run = Run::Sampled { samples: 1_000_000, edges: 100_000 };

/// One harness per infeed mode (`windows::INFEED_MODES`).
fn per_infeed(
    out: &mut Vec<Harness>,
    family: &str,
    property: &'static str,
    window: &str,
    bodies: [fn(); 6],
    (unwinds, tier, run): ([u32; 6], Tier, Run),
) {
    for (((code, suffix), body), unwind) in crate::windows::INFEED_MODES.iter().zip(bodies).zip(unwinds) {
        out.push(Harness {
            name: format!("{family}_{suffix}"),
            property,
            window: format!("{window}({code})"),
            body,
            contract: None,
            stubs: G76_STUBS,
            unwind,
            cadical: family == "equivalence",
            tier,
            run,
        });
    }
}

/// Every Kani harness, in the order of `kani_proofs.rs`.
#[must_use]
#[allow(clippy::too_many_lines)]
pub fn harnesses() -> Vec<Harness> {
    use Tier::{Required, Scheduled};
    let mut out = Vec::new();
    per_infeed(
        &mut out,
        "depth_monotonicity",
        "P1: rough depths strictly increase level by level; every cut at least min(Δdmin, what remains), a law cut never grows by more than rounding",
        "depth_window",
        [
            bodies::depth_monotonicity_d0,
            bodies::depth_monotonicity_d1,
            bodies::depth_monotonicity_d2,
            bodies::depth_monotonicity_centre,
            bodies::depth_monotonicity_left_flank,
            bodies::depth_monotonicity_alternating,
        ],
        (BY_MODE, Required, SAMPLED),
    );
    per_infeed(
        &mut out,
        "termination",
        "P2: the rough schedule ends exactly at k − d within the documented number of levels",
        "depth_window",
        [
            bodies::termination_d0,
            bodies::termination_d1,
            bodies::termination_d2,
            bodies::termination_centre,
            bodies::termination_left_flank,
            bodies::termination_alternating,
        ],
        (BY_MODE, Required, SAMPLED),
    );
    out.push(Harness {
        name: "finishing".into(),
        property: "P3: m finishing passes per start at depth k, cutting d then 0, at the last rough Z",
        window: "FINISHING_KANI_WINDOW".into(),
        body: bodies::finishing,
        contract: None,
        stubs: G76_STUBS,
        unwind: 97,
        cadical: false,
        tier: Required,
        run: SAMPLED,
    });
    out.push(Harness {
        name: "run_out_direction".into(),
        property: "P4: every run-out ends away from the work, on the end line (Z long) or the cut's X (X long), never beyond E",
        window: "RUN_OUT_KANI_WINDOW".into(),
        body: bodies::run_out_direction,
        contract: None,
        stubs: G76_STUBS,
        unwind: 79,
        cadical: false,
        tier: Required,
        run: SAMPLED,
    });
    per_infeed(
        &mut out,
        "no_overcut",
        "P5: no pass start lies outside the final thread form by more than one increment",
        "flank_window(G76_WINDOW)",
        [
            bodies::no_overcut_d0,
            bodies::no_overcut_d1,
            bodies::no_overcut_d2,
            bodies::no_overcut_centre,
            bodies::no_overcut_left_flank,
            bodies::no_overcut_alternating,
        ],
        (BY_MODE, Required, SAMPLED),
    );
    per_infeed(
        &mut out,
        "no_rapid_in_thread",
        "No rapid enters the region between the crest and root lines (but the retract after an X-long run-out)",
        "flank_window(NO_RAPID_WINDOW)",
        [
            bodies::no_rapid_in_thread_d0,
            bodies::no_rapid_in_thread_d1,
            bodies::no_rapid_in_thread_d2,
            bodies::no_rapid_in_thread_centre,
            bodies::no_rapid_in_thread_left_flank,
            bodies::no_rapid_in_thread_alternating,
        ],
        (BY_MODE, Required, SAMPLED),
    );
    per_infeed(
        &mut out,
        "equivalence",
        "P6: the engine's moves (or alarm) equal the reference's, restated in integers (crate::g76_exact)",
        "equivalence_window",
        [
            bodies::equivalence_d0,
            bodies::equivalence_d1,
            bodies::equivalence_d2,
            bodies::equivalence_centre,
            bodies::equivalence_left_flank,
            bodies::equivalence_alternating,
        ],
        (EQUIVALENCE_BY_MODE, Scheduled, SAMPLED),
    );
    let mut one = |name: &str,
                   property: &'static str,
                   window: &str,
                   body: fn(),
                   contract: Option<&'static str>,
                   stubs: &'static [&'static str],
                   unwind: u32,
                   cadical: bool,
                   tier: Tier,
                   run: Run| {
        out.push(Harness {
            name: name.into(),
            property,
            window: window.into(),
            body,
            contract,
            stubs,
            unwind,
            cadical,
            tier,
            run,
        });
    };
    one(
        "no_panic",
        "P7: every cycle of the documented ranges, valid or not, gives an alarm or moves in range; no panic, no overflow (first 12 moves)",
        "NO_PANIC_WINDOW",
        bodies::no_panic,
        None,
        G76_STUBS,
        34,
        true,
        Scheduled,
        SAMPLED,
    );
    one(
        "isqrt_rounds",
        "P8: round_sqrt rounds to nearest: (2s − 1)² ≤ 4x < (2s + 1)²",
        "ISQRT_WINDOW",
        bodies::isqrt_rounds,
        Some("cycleref::engine::arith::round_sqrt"),
        &["cycleref::engine::arith::isqrt_floor"],
        7,
        true,
        Required,
        SAMPLED,
    );
    one(
        "round_sqrt_near_contract",
        "The contract of round_sqrt_near: round(√x) whatever the guess, (2s − 1)² ≤ 4x < (2s + 1)²",
        "ISQRT_NEAR_WINDOW",
        bodies::round_sqrt_near_contract,
        Some("cycleref::engine::arith::round_sqrt_near"),
        &["cycleref::engine::arith::round_sqrt"],
        // The loop checks the guess and NEAR_STEPS = 4 corrections: five
        // iterations; Newton's method is round_sqrt's, stubbed.
        6,
        true,
        Required,
        SAMPLED,
    );
    one(
        "isqrt_floor_contract",
        "The contract of isqrt_floor: s² ≤ x < (s + 1)²",
        "ISQRT_WINDOW",
        bodies::isqrt_floor_contract,
        Some("cycleref::engine::arith::isqrt_floor"),
        &[],
        7,
        true,
        Required,
        SAMPLED,
    );
    one(
        "round_div_contract",
        "The contract of round_div: nearest, ties away from zero",
        "ROUND_DIV_WINDOW",
        bodies::round_div_contract,
        Some("cycleref::engine::arith::round_div"),
        &[],
        2,
        true,
        Required,
        SAMPLED,
    );
    one(
        "saturate_i64_contract",
        "The contract of saturate_i64",
        "SATURATE_WINDOW",
        bodies::saturate_i64_contract,
        Some("cycleref::engine::arith::saturate_i64"),
        &[],
        2,
        false,
        Required,
        SAMPLED,
    );
    one(
        "floor_div_contract",
        "The contract of floor_div",
        "DIV_WINDOW",
        bodies::floor_div_contract,
        Some("cycleref::engine::arith::floor_div"),
        &[],
        2,
        true,
        Required,
        SAMPLED,
    );
    one(
        "ceil_div_contract",
        "The contract of ceil_div",
        "DIV_WINDOW",
        bodies::ceil_div_contract,
        Some("cycleref::engine::arith::ceil_div"),
        &[],
        2,
        true,
        Required,
        SAMPLED,
    );
    one(
        "mul_tan_round_contract",
        "The contract of mul_tan_round: round(v·tan(h/2°)) from the table",
        "MUL_TAN_WINDOW",
        bodies::mul_tan_round_contract,
        Some("cycleref::tan::mul_tan_round"),
        &[],
        2,
        true,
        Required,
        SAMPLED,
    );
    one(
        "g32_run_out",
        "G32: the run-out ends J along the short axis from the end and starts K before it; only the first move synchronises",
        "G32_WINDOW",
        bodies::g32_run_out,
        None,
        LINE_STUBS,
        5,
        false,
        Required,
        SAMPLED,
    );
    one(
        "g32_no_rapid",
        "G32: no rapid in a thread block",
        "G32_WINDOW",
        bodies::g32_no_rapid,
        None,
        LINE_STUBS,
        5,
        false,
        Required,
        SAMPLED,
    );
    one(
        "g92_pass",
        "G92: steps 1 to 5 in order, B from the words, the run-out K before C and J away from the work, the starts' angles",
        "G92_WINDOW",
        bodies::g92_pass,
        None,
        LINE_STUBS,
        12,
        false,
        Required,
        SAMPLED,
    );
    one(
        "groove_pecks_and_steps",
        "G75.1: every peck at most Δi, every step at most Δk, retracts by e",
        "GROOVE_WINDOW",
        bodies::groove_pecks_and_steps,
        None,
        GROOVE_STUBS,
        66,
        false,
        Required,
        SAMPLED,
    );
    one(
        "groove_layers",
        "G75.1: layers of at most Δv, in order, the last at the bottom",
        "GROOVE_WINDOW",
        bodies::groove_layers,
        None,
        GROOVE_STUBS,
        66,
        false,
        Required,
        SAMPLED,
    );
    one(
        "groove_inside",
        "G75.1: roughing stays inside the profile less the allowances",
        "GROOVE_WINDOW",
        bodies::groove_inside,
        None,
        GROOVE_STUBS,
        66,
        false,
        Required,
        SAMPLED,
    );
    one(
        "groove_finish_is_profile",
        "G75.1: the finishing contour is the programmed profile",
        "GROOVE_WINDOW",
        bodies::groove_finish_is_profile,
        None,
        GROOVE_STUBS,
        66,
        false,
        Required,
        SAMPLED,
    );
    one(
        "groove_material",
        "G75.1: roughing with a grooving tool leaves no material but the allowances",
        "GROOVE_MATERIAL_WINDOW",
        bodies::groove_material,
        None,
        GROOVE_STUBS,
        128,
        false,
        Required,
        Run::Exhaustive(500_000),
    );
    one(
        "groove_equivalence",
        "G75.1: the engine equals the reference restated in integers for right-angle grooves",
        "GROOVE_EQUIVALENCE_WINDOW",
        bodies::groove_equivalence,
        None,
        GROOVE_STUBS,
        54,
        true,
        Scheduled,
        Run::Exhaustive(900_000),
    );
    one(
        "groove_no_panic",
        "G75.1: every documented groove of at most 1 152 layers, no panic, no overflow (first 8 moves)",
        "GROOVE_NO_PANIC_WINDOW",
        bodies::groove_no_panic,
        None,
        GROOVE_STUBS,
        crate::windows::GROOVE_NO_PANIC_UNWIND,
        true,
        Scheduled,
        SAMPLED,
    );
    one(
        "schedule_step",
        "The depth schedule, one step from any level that satisfies the invariant (an induction over every level)",
        "SCHEDULE_STEP_WINDOW",
        bodies::schedule_step,
        None,
        &["cycleref::engine::arith::round_sqrt"],
        7,
        true,
        Scheduled,
        SAMPLED,
    );
    one(
        "lcnc_depth_monotonicity",
        "LinuxCNC G76: rough depths in order, each shallower than K, rounded depths non-decreasing",
        "LCNC_DEPTH_WINDOW",
        bodies::lcnc_depth_monotonicity,
        None,
        &[],
        256,
        true,
        Scheduled,
        SAMPLED,
    );
    one(
        "lcnc_termination",
        "LinuxCNC G76: refused exactly beyond the pass limit, otherwise N rough passes, 1 + H at K, the return",
        "LCNC_DEPTH_WINDOW",
        bodies::lcnc_termination,
        None,
        &[],
        256,
        false,
        Scheduled,
        SAMPLED,
    );
    one(
        "lcnc_spring_passes",
        "LinuxCNC G76: the passes at full depth, the spring passes repeating the deepest",
        "LCNC_SPRING_WINDOW",
        bodies::lcnc_spring_passes,
        None,
        &[],
        256,
        false,
        Scheduled,
        SAMPLED,
    );
    one(
        "lcnc_pass_moves",
        "LinuxCNC G76: each pass's moves (R-LCNC-PASS), tapers, compound shift, no rapid into the thread",
        "LCNC_PASS_WINDOW",
        bodies::lcnc_pass_moves,
        None,
        &[],
        256,
        false,
        Scheduled,
        SAMPLED,
    );
    out
}

/// The harness called `name`.
///
/// # Panics
///
/// When there is none.
#[must_use]
pub fn harness(name: &str) -> Harness {
    harnesses().into_iter().find(|h| h.name == name).unwrap_or_else(|| panic!("no Kani harness {name}"))
}

/// The unwind bound of harness `name`.
///
/// # Panics
///
/// When there is no such harness.
#[must_use]
pub fn unwind(name: &str) -> u32 {
    harness(name).unwind
}

/// Wraps `text` into doc-comment lines of at most 80 columns.
fn doc(out: &mut String, text: &str) {
    let mut line = String::from("///");
    for word in text.split_whitespace() {
        if line.len() + 1 + word.len() > 80 && line.len() > 3 {
            out.push_str(&line);
            out.push('\n');
            line = String::from("///");
        }
        line.push(' ');
        line.push_str(word);
    }
    out.push_str(&line);
    out.push('\n');
}

/// The text of `proofs/src/kani_proofs.rs`.
#[must_use]
pub fn kani_source() -> String {
    let mut s = String::from(
        "//! The Kani harnesses. GENERATED from `proofs/src/catalogue.rs` by\n\
         //! `CYCLEREF_BLESS=1 cargo test -p cycleref-proofs --test catalogue`;\n\
         //! edit the catalogue, not this file.\n\
         //!\n\
         //! Each harness calls its body in `crate::bodies`, which the shim runs\n\
         //! here over the same window (`proofs/tests/kani_windows.rs`). Run one\n\
         //! with `cargo kani -p cycleref-proofs --harness kani_proofs::NAME\n\
         //! --exact`; the scheduled tier needs `--features kani-scheduled`.\n\
         //! Contracts (`-Z function-contracts`): each kernel's `proof_for_contract`\n\
         //! harness proves it over the ranges its callers use, and the cycle\n\
         //! harnesses replace it by that contract (`stub_verified`).\n",
    );
    for h in harnesses() {
        s.push('\n');
        doc(&mut s, &format!("{}. Window: `{}`.", h.property, h.window));
        if h.tier == Tier::Scheduled {
            s.push_str("#[cfg(feature = \"kani-scheduled\")]\n");
        }
        match h.contract {
            Some(c) => {
                let _ = writeln!(s, "#[kani::proof_for_contract({c})]");
            }
            None => s.push_str("#[kani::proof]\n"),
        }
        for stub in h.stubs {
            let _ = writeln!(s, "#[kani::stub_verified({stub})]");
        }
        let _ = writeln!(s, "#[kani::unwind({})]", h.unwind);
        if h.cadical {
            s.push_str("#[kani::solver(cadical)]\n");
        }
        let _ = writeln!(s, "fn {}() {{\n    crate::bodies::{}();\n}}", h.name, h.name);
    }
    s
}

/// The text of `.github/workflows/kani.yml`: one job per harness, the
/// required tier on every push and pull request, the scheduled tier weekly
/// and by hand; each job's log is uploaded and its covers checked
/// (`.ci/kani-covers`).
#[must_use]
pub fn workflow() -> String {
    let mut s = String::from(
        "# GENERATED from proofs/src/catalogue.rs by\n\
         # `CYCLEREF_BLESS=1 cargo test -p cycleref-proofs --test catalogue`;\n\
         # edit the catalogue, not this file.\n\
         #\n\
         # One job per Kani harness, each with its own timeout, log artifact\n\
         # and cover check. The required tier runs on every push; the\n\
         # scheduled tier (feature kani-scheduled: harnesses CBMC may not\n\
         # finish in the timeout) weekly and by hand, and is not required.\n\
         name: Kani\n\
         \n\
         on:\n\
         \x20 push:\n\
         \x20 pull_request:\n\
         \x20 schedule:\n\
         \x20   - cron: \"17 3 * * 0\"\n\
         \x20 workflow_dispatch:\n\
         \n\
         env:\n\
         \x20 # Kani 0.65.0 builds with its own toolchain, nightly-2025-08-06\n\
         \x20 # (rustc 1.91.0-nightly), which satisfies the workspace's\n\
         \x20 # rust-version 1.85.\n\
         \x20 KANI_VERSION: 0.65.0\n\
         \n\
         jobs:\n",
    );
    for (tier, job, condition, minutes, timeout, features) in [
        (Tier::Required, "required", None, 45, "30m", ""),
        (
            Tier::Scheduled,
            "scheduled",
            Some("github.event_name == 'schedule' || github.event_name == 'workflow_dispatch'"),
            360,
            "5h",
            " --features kani-scheduled",
        ),
    ] {
        let _ = write!(s, "  {job}:\n    name: kani ${{{{ matrix.harness }}}} ({job})\n");
        if let Some(c) = condition {
            let _ = writeln!(s, "    if: {c}");
        }
        let _ = write!(
            s,
            "    runs-on: ubuntu-latest\n    timeout-minutes: {minutes}\n    strategy:\n      fail-fast: false\n      matrix:\n        harness:\n"
        );
        for h in harnesses().iter().filter(|h| h.tier == tier) {
            let _ = writeln!(s, "          - {}", h.name);
        }
        let _ = write!(
            s,
            "    steps:\n\
             \x20     - uses: actions/checkout@v4\n\
             \x20     - uses: dtolnay/rust-toolchain@stable\n\
             \x20     - uses: actions/cache@v4\n\
             \x20       with:\n\
             \x20         path: |\n\
             \x20           ~/.cargo/bin/kani\n\
             \x20           ~/.cargo/bin/cargo-kani\n\
             \x20           ~/.kani\n\
             \x20           ~/.rustup/toolchains/nightly-2025-08-06-*\n\
             \x20         key: kani-${{{{ env.KANI_VERSION }}}}-${{{{ runner.os }}}}\n\
             \x20     - name: install Kani ${{{{ env.KANI_VERSION }}}}\n\
             \x20       run: |\n\
             \x20         command -v cargo-kani || cargo install --locked kani-verifier --version \"$KANI_VERSION\"\n\
             \x20         cargo kani setup\n\
             \x20     - name: cargo kani --harness ${{{{ matrix.harness }}}}\n\
             \x20       shell: bash\n\
             \x20       run: |\n\
             \x20         set -o pipefail\n\
             \x20         cargo kani -p cycleref-proofs{features} -Z unstable-options --harness-timeout {timeout} \\\n\
             \x20           --harness \"kani_proofs::${{{{ matrix.harness }}}}\" --exact --output-format terse 2>&1 \\\n\
             \x20           | tee \"kani-${{{{ matrix.harness }}}}.log\"\n\
             \x20     - name: every cover satisfied (--fail-uncoverable)\n\
             \x20       if: always()\n\
             \x20       run: .ci/kani-covers \"kani-${{{{ matrix.harness }}}}.log\"\n\
             \x20     - uses: actions/upload-artifact@v4\n\
             \x20       if: always()\n\
             \x20       with:\n\
             \x20         name: kani-${{{{ matrix.harness }}}}\n\
             \x20         path: kani-${{{{ matrix.harness }}}}.log\n"
        );
        if tier == Tier::Required {
            s.push('\n');
        }
    }
    s
}

/// The per-harness table of `proofs/README.md` (without the figures of the
/// runs here, which `proofs/tests/kani_windows.rs` prints).
#[must_use]
pub fn readme_table() -> String {
    let mut s = String::from(
        "| harness | property | window | unwind | stubs (contracts) | tier | Kani |\n|---|---|---|---:|---|---|---|\n",
    );
    for h in harnesses() {
        let stubs = if h.stubs.is_empty() {
            "none".to_owned()
        } else {
            h.stubs
                .iter()
                .map(|p| format!("`{}`", p.rsplit("::").next().unwrap_or(p)))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let property = match h.contract {
            Some(c) => {
                format!("{} (`proof_for_contract` of `{}`)", h.property, c.rsplit("::").next().unwrap_or(c))
            }
            None => h.property.to_owned(),
        };
        let tier = match h.tier {
            Tier::Required => "required",
            Tier::Scheduled => "scheduled",
        };
        let _ = writeln!(
            s,
            "| `{}` | {} | `{}` | {} | {} | {} | not yet run |",
            h.name, property, h.window, h.unwind, stubs, tier
        );
    }
    s
}
