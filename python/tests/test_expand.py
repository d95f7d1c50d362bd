"""`cycleref.expand` on the shipped examples, against the hand-derived values
of the Rust golden tests (quoted with their file and test)."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest

import cycleref
from conftest import EXAMPLES, example

D = Decimal


def g76_passes(rows, a, cut_end_z, run_end_z):
    """The golden tests' `pass` helper (spec/tests/golden.rs): approach to Bn,
    cut to the run-out start, run-out, retract to E, return to A."""
    out = []
    for x, z, xr in rows:
        out += [
            ("rapid", x, z),
            ("thread", x, cut_end_z),
            ("thread", xr, run_end_z),
            ("rapid", a[0], run_end_z),
            ("rapid", a[0], a[1]),
        ]
    return [(m, D(x), D(z)) for m, x, z in out]


def rendered(cycle):
    return [(m.motion, m.x, m.z) for m in cycle.moves]


def test_gsk988_m68x6_golden(m68x6):
    # spec/tests/golden.rs, gsk988_m68x6: "X of Bn = 60.64 + 2 (3.68 - Dn):
    # 64.400, 62.908, 61.764, 60.840; finishing 60.640 ... Z of Bn = 10 -
    # shift: 8.961, 8.530, 8.200, 7.933 ... The cut ends at Z-59, the
    # run-out at Z-62, X + 6."
    (cycle,) = cycleref.expand(m68x6, profile="gsk988")
    assert (cycle.code, cycle.line, cycle.params_line) == ("G76", 6, 5)
    assert cycle.start == (D("80.000"), D("10.000"))
    assert (cycle.unit, cycle.decimals) == ("mm", 3)
    rows = [
        ("64.400", "8.961", "70.400"),
        ("62.908", "8.530", "68.908"),
        ("61.764", "8.200", "67.764"),
        ("60.840", "7.933", "66.840"),
        ("60.640", "7.933", "66.640"),
        ("60.640", "7.933", "66.640"),
    ]
    assert rendered(cycle) == g76_passes(rows, ("80.000", "10.000"), "-59.000", "-62.000")
    # "4 rough passes with their depths and cuts, then 2 finishing":
    # (Rough, 1, 1800, 1800), (Rough, 2, 2546, 746), (Rough, 3, 3118, 572),
    # (Rough, 4, 3580, 462), (Finish, 1, 3680, 100), (Finish, 2, 3680, 0).
    passes = [(m.pass_.kind, m.pass_.number, m.pass_.depth, m.pass_.cut) for m in cycle.moves if m.role == "approach"]
    assert passes == [
        ("rough", 1, D("1.800"), D("1.800")),
        ("rough", 2, D("2.546"), D("0.746")),
        ("rough", 3, D("3.118"), D("0.572")),
        ("rough", 4, D("3.580"), D("0.462")),
        ("finish", 1, D("3.680"), D("0.100")),
        ("finish", 2, D("3.680"), D("0.000")),
    ]
    # "The lead is 6 on every thread move; the first thread move of each pass synchronises."
    for m in cycle.moves:
        if m.motion == "thread":
            assert m.lead == "F6.0"
            assert m.sync == (m.role == "cut")
            assert m.start_angle_millidegrees == Fraction(0)
        else:
            assert (m.lead, m.sync, m.start_angle_millidegrees) == (None, None, None)


def test_lengths_are_exact_decimals_with_the_increments_decimals(m68x6):
    (cycle,) = cycleref.expand(m68x6)
    m = cycle.moves[0]
    assert type(m.x) is Decimal and str(m.x) == "64.400" and m.x.as_tuple().exponent == -3
    assert str(m.pass_.depth) == "1.800"
    # IS-C: four decimals.
    (c,) = cycleref.expand(example("gsk980-m68x6.nc"), profile="gsk980", increment="is-c")
    assert str(c.moves[0].x) == "64.4000"


def test_gsk980_m68x6_is_c_golden():
    # spec/tests/golden.rs, gsk980_m68x6_is_c: "X of Bn ... 64.4000, 62.9088,
    # 61.7646, 60.8400 ... Z = 8.9608, 8.5303, 8.2000, 7.9331."
    (cycle,) = cycleref.expand(example("gsk980-m68x6.nc"), profile="gsk980", increment="is-c")
    rows = [
        ("64.4000", "8.9608", "70.4000"),
        ("62.9088", "8.5303", "68.9088"),
        ("61.7646", "8.2000", "67.7646"),
        ("60.8400", "7.9331", "66.8400"),
        ("60.6400", "7.9331", "66.6400"),
        ("60.6400", "7.9331", "66.6400"),
    ]
    assert rendered(cycle) == g76_passes(rows, ("80.0000", "10.0000"), "-59.0000", "-62.0000")


def test_seed000_extended_golden():
    # spec/tests/golden.rs, seed000_extended: "X of Bn = 60 + 2 (3 - Dn):
    # 62.4, 61.0, finishing 60 ... Z 9.254, 8.964 ... the cut ends at Z-58
    # and the run-out at Z-60, X + 3."
    (cycle,) = cycleref.expand(example("seed000-extended.nc"), profile="gsk988")
    rows = [
        ("62.400", "9.254", "65.400"),
        ("61.000", "8.964", "64.000"),
        ("60.000", "8.964", "63.000"),
        ("60.000", "8.964", "63.000"),
    ]
    assert rendered(cycle) == g76_passes(rows, ("80.000", "10.000"), "-58.000", "-60.000")


def test_fanuc_external_golden():
    # spec/tests/golden.rs, fanuc_external: "X of Bn = 21.4 + 2 (1.3 - Dn):
    # 23.2, 22.868, 22.614, 22.4, 22.2, 22.0, 21.8, 21.6; finishing 21.4 ...
    # Z = 2.769, 2.673, 2.600, 2.538, 2.480, 2.423, 2.365, 2.307 ... the cut
    # ends at Z-25, the run-out at Z-26, X + 2."
    (cycle,) = cycleref.expand(EXAMPLES / "fanuc-external.nc", profile="fanuc")
    xs = ["23.200", "22.868", "22.614", "22.400", "22.200", "22.000", "21.800", "21.600", "21.400", "21.400"]
    zs = ["2.769", "2.673", "2.600", "2.538", "2.480", "2.423", "2.365", "2.307", "2.307", "2.307"]
    rows = [(x, z, str(D(x) + 2).ljust(6, "0")) for x, z in zip(xs, zs)]
    assert rendered(cycle) == g76_passes(rows, ("26.000", "3.000"), "-25.000", "-26.000")


def test_fanuc_internal_golden():
    # spec/tests/golden.rs, fanuc_internal: 15 rough + 2 finishing passes of
    # 5 moves; "Level 9: ... G00 X34.700 Z2.249"; "Level 15: ... G00 X35.800
    # Z1.932", "G32 X35.200 Z-40.000"; finishing at X36.
    (cycle,) = cycleref.expand(example("fanuc-internal.nc"), profile="fanuc")
    out = rendered(cycle)
    assert len(out) == 17 * 5
    assert out[8 * 5] == ("rapid", D("34.700"), D("2.249"))
    assert out[14 * 5] == ("rapid", D("35.800"), D("1.932"))
    assert out[14 * 5 + 2] == ("thread", D("35.200"), D("-40.000"))
    assert out[15 * 5] == ("rapid", D("36.000"), D("1.932"))


def test_gsk980_g32_runout_golden():
    # spec/tests/golden.rs's sibling spec/tests/g32.rs,
    # gsk980_run_out_and_continuous_thread: block 1 "The run-out starts K = 3
    # before the end: Z-27, X40 (straight); it ends at Z-30 displaced J =
    # +1.5 (radius) = X43. Q90000 = 90°; the cut synchronises." Block 3:
    # "From (30, 2) to (34, -10), Q180000 ... a new synchronised run at 180°."
    cycles = cycleref.expand(example("gsk980-g32-runout.nc"), profile="gsk980")
    assert [c.code for c in cycles] == ["G32"] * 4
    first, third = cycles[0].moves, cycles[1].moves
    assert [(m.x, m.z, m.sync, m.start_angle_millidegrees, m.role, m.lead) for m in first] == [
        (D("40.000"), D("-27.000"), True, Fraction(90000), "cut", "F2.0"),
        (D("43.000"), D("-30.000"), False, Fraction(90000), "run-out", "F2.0"),
    ]
    assert [(m.x, m.z, m.sync, m.start_angle_millidegrees) for m in third] == [
        (D("34.000"), D("-10.000"), True, Fraction(180000)),
    ]
    # Block 5: "Run-out start Z-39, X = 37.6; end X = 38 + 2 × 1 = 40 ... still 180°."
    assert [(m.x, m.z, m.sync, m.start_angle_millidegrees) for m in cycles[3].moves] == [
        (D("37.600"), D("-39.000"), False, Fraction(180000)),
        (D("40.000"), D("-40.000"), False, Fraction(180000)),
    ]


def test_gsk980_g92_o0012_golden():
    # spec/tests/g92.rs, gsk980_example_o0012: "① rapid to B = (x, 5); ②
    # thread to K = 1 before C, Z-27, still at x (straight), then the run-out
    # to Z-28 and J = 3 (radius) outwards, x + 6; ③ rapid to the X of A, X65;
    # ④ rapid to A", for x = 58.7, 57.7, 57, 56.9.
    cycles = cycleref.expand(example("gsk980-g92-o0012.nc"), profile="gsk980")
    assert [(c.code, c.line) for c in cycles] == [("G92", 4), ("G92", 5), ("G92", 6), ("G92", 7)]
    for cycle, x in zip(cycles, ["58.700", "57.700", "57.000", "56.900"]):
        xr = D(x) + 6
        assert rendered(cycle) == [
            ("rapid", D(x), D("5.000")),
            ("thread", D(x), D("-27.000")),
            ("thread", xr, D("-28.000")),
            ("rapid", D("65.000"), D("-28.000")),
            ("rapid", D("65.000"), D("5.000")),
        ]
        assert {(m.pass_.kind, m.pass_.number, m.pass_.depth) for m in cycle.moves} == {("single", 1, D("0.000"))}


def test_gsk980_g78_golden():
    # spec/tests/g78.rs, gsk980_alternating_flanks_with_equal_depths: "levels
    # 0.8 (right, Z 10 - 0.331), 1.6 (left, 2.072 - 0.663 = 1.409: Z 8.591),
    # 2.4 (right, Z 9.006), 2.5 (left, 2.072 - 1.036: Z 8.964)"; X = 60 + 2 (3 -
    # D); two finishing passes at X60 from the last rough Z.
    (cycle,) = cycleref.expand(example("gsk980-g78.nc"), profile="gsk980")
    assert (cycle.code, cycle.line, cycle.params_line) == ("G78", 5, 4)
    starts = [(m.x, m.z, m.pass_.kind, m.pass_.flank) for m in cycle.moves if m.role == "approach"]
    assert starts == [
        (D("64.400"), D("9.669"), "rough", "right"),
        (D("62.800"), D("8.591"), "rough", "left"),
        (D("61.200"), D("9.006"), "rough", "right"),
        (D("61.000"), D("8.964"), "rough", "left"),
        (D("60.000"), D("8.964"), "finish", "centre"),
        (D("60.000"), D("8.964"), "finish", "centre"),
    ]


def test_gsk980_g75_seed_golden():
    # proofs/tests/g75_golden.rs, seed001_as_written: pecks at X47 ... X32,
    # retracts of 0.5 (X48 ... X33), the last peck cut short at X30, plunges
    # at Z20, Z15, Z10; then the rough contour R0 = S, Q1, Q2, R3 = Z-7.3205.
    (cycle,) = cycleref.expand(example("gsk980-g75-seed.nc"), profile="gsk980", increment="is-c")
    assert (cycle.code, cycle.line, cycle.params_line) == ("G75.1", 9, 8)
    assert cycle.from_ == (D("60.0000"), D("30.0000"))
    assert cycle.start == (D("50.0000"), D("30.0000"))

    def plunge(z, n):
        v = []
        for peck, back in [("47", "48"), ("44", "45"), ("41", "42"), ("38", "39"), ("35", "36"), ("32", "33")]:
            v += [("feed", f"{peck}.0000", z, "peck", (1, n)), ("rapid", f"{back}.0000", z, "peck-retract", (1, n))]
        return v + [("feed", "30.0000", z, "peck", (1, n)), ("rapid", "50.0000", z, "plunge-retract", (1, n))]

    expected = [("rapid", "50.0000", "20.0000", "approach", None)]
    expected += plunge("20.0000", 1)
    expected += [("rapid", "50.0000", "15.0000", "step", (1, 2))]
    expected += plunge("15.0000", 2)
    expected += [("rapid", "50.0000", "10.0000", "step", (1, 3))]
    expected += plunge("10.0000", 3)
    expected += [
        ("rapid", "50.0000", "20.0000", "approach", None),
        ("rapid", "50.0000", "30.0000", "rough-contour", None),
        ("feed", "30.0000", "20.0000", "rough-contour", None),
        ("feed", "30.0000", "10.0000", "rough-contour", None),
        ("feed", "50.0000", "-7.3205", "rough-contour", None),
        ("rapid", "50.0000", "20.0000", "rough-contour", None),
        ("rapid", "60.0000", "30.0000", "return", None),
    ]
    got = [
        (m.motion, str(m.x), str(m.z), m.role, (m.plunge.layer, m.plunge.number) if m.plunge else None)
        for m in cycle.moves
    ]
    assert got == expected


def test_g75_arcs_carry_their_centre():
    cycles = cycleref.expand(example("gsk980-g75-square.nc"), profile="gsk980")
    arcs = [m for c in cycles for m in c.moves if m.motion.startswith("arc")]
    assert arcs, "the square example has rounded corners"
    for m in arcs:
        assert isinstance(m.centre[0], Decimal) and isinstance(m.centre[1], Decimal)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.nc")), ids=lambda p: p.name)
def test_every_example_the_same_with_both_engines_and_as_the_json_contract(path):
    profile = "fanuc" if "fanuc" in path.name else ("gsk980" if "gsk980" in path.name else "gsk988")
    increment = "is-c" if path.name in ("gsk980-g75-seed.nc", "gsk980-m68x6.nc") else "is-b"
    try:
        ours = cycleref.expand(path, profile=profile, increment=increment)
    except cycleref.ProgramError as e:
        # examples/gsk980-g32-taper.nc is written for IS-C with one decimal more.
        ours = cycleref.expand(path, profile=profile, increment="is-c")
        increment = "is-c"
        assert e.rule == "not_in_increments"
    ref = cycleref.expand(path, profile=profile, increment=increment, engine="spec")
    assert ours == ref
    streamed = list(cycleref.iter_moves(path, profile=profile, increment=increment))
    assert streamed == [m for c in ours for m in c.moves]


def test_text_bytes_and_path_are_the_same_program(m68x6):
    by_text = cycleref.expand(m68x6)
    assert cycleref.expand(m68x6.encode()) == by_text
    assert cycleref.expand(EXAMPLES / "gsk988-m68x6.nc") == by_text


def test_bad_options_are_value_errors(m68x6):
    with pytest.raises(ValueError, match="profile"):
        cycleref.expand(m68x6, profile="haas")
    with pytest.raises(ValueError, match="increment"):
        cycleref.expand(m68x6, increment="is-a")
    with pytest.raises(TypeError):
        cycleref.expand(42)


def test_linuxcnc_profile():
    # examples/linuxcnc-m20-taper.ngc, worked in cli/tests/linuxcnc.rs: 15
    # rough and 2 full-depth passes of 6 moves, and the closing rapid; IS-C
    # by default on this profile; pass 1's "back" at X 22 + (1.84 - 0.3),
    # Z 2 - 0.15 tan 29.5 deg; its entry taper at the taper pitch
    # 1.5 sqrt(1 + 0.92^2) = 2.038235.
    (cycle,) = cycleref.expand(example("linuxcnc-m20-taper.ngc"), profile="linuxcnc")
    assert (cycle.code, cycle.line, cycle.decimals) == ("G76", 6, 4)
    assert len(cycle.moves) == 17 * 6 + 1
    assert rendered(cycle)[:2] == [("rapid", D("23.5400"), D("1.9151")), ("thread", D("21.5400"), D("1.9151"))]
    # The lead as LinuxCNC writes it (G33 K).
    assert cycle.moves[1].lead == "K2.038235"
    # The reference model gives the same moves.
    (ref,) = cycleref.expand(example("linuxcnc-m20-taper.ngc"), profile="linuxcnc", engine="spec")
    assert rendered(ref) == rendered(cycle)
