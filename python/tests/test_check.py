"""`cycleref.check`: a vendor's trace with a wrong pass depth (the README's
example and cli/tests/check.rs), and a trace that agrees."""

from __future__ import annotations

from decimal import Decimal

import pytest

import cycleref
from conftest import EXAMPLES


def nc_trace(program: str) -> str:
    """`cycleref expand`'s nc output, written from the moves: the G76 blocks
    of the program are replaced by their moves (ample for a trace: blocks
    that do not move are ignored by `check`)."""
    (cycle,) = cycleref.expand(program)
    lines = program.splitlines()
    out = []
    for number, line in enumerate(lines, start=1):
        if number == cycle.params_line:
            continue
        if number != cycle.line:
            out.append(line)
            continue
        for m in cycle.moves:
            g = {"rapid": "G00", "thread": "G32"}[m.motion]
            out.append(f"{g} X{m.x} Z{m.z}" + (f" F{m.lead[1:]}" if m.lead else ""))
    return "\n".join(out) + "\n"


def test_a_good_trace_agrees(m68x6):
    report = cycleref.check(m68x6, nc_trace(m68x6))
    assert report.agree and bool(report)
    assert report.divergence_count == 0 and report.divergences == []
    assert report.text.startswith("AGREE: 32 moves of ours, 32 of the trace")


def test_a_wrong_pass_depth_is_the_divergence(m68x6, tmp_path):
    # cli/tests/check.rs: "Rough pass 3 (depth 3.118) cut at X61.800 instead
    # of X61.764" → "difference: X 36 Z 0 increments"; the README's report:
    # "G76 at line 6, rough pass 3 (start 1, depth 3.118, cut 0.572): Bn
    # (pass start, or An before a lead-in) (rapid point)".
    trace = nc_trace(m68x6).replace("X61.764", "X61.800")
    report = cycleref.check(m68x6, trace)
    assert not report.agree
    assert report.divergence_count == 2
    first = report.divergences[0]
    assert first.what == "rapid point"
    assert first.cycle == ("G76", 6)
    assert first.pass_.kind == "rough" and first.pass_.number == 3 and first.pass_.start == 1
    assert (first.pass_.depth, first.pass_.cut) == (Decimal("3.118"), Decimal("0.572"))
    assert first.point == "Bn (pass start, or An before a lead-in)"
    assert (first.ours.motion, first.ours.x, first.ours.z) == ("rapid", Decimal("61.764"), Decimal("8.200"))
    assert (first.theirs.x, first.theirs.z) == (Decimal("61.800"), Decimal("8.200"))
    assert first.difference == (36, 0)
    assert "difference: X 36 Z 0 increments" in report.text
    assert report.json["format"] == "cycleref-check/1"
    # Within a tolerance of 36 increments it agrees (cli/tests/check.rs).
    assert cycleref.check(m68x6, trace, tolerance=36).agree
    # The trace as a file, and the program as a path: the same report.
    p = tmp_path / "theirs.nc"
    p.write_text(trace)
    assert cycleref.check(EXAMPLES / "gsk988-m68x6.nc", p).divergences == report.divergences


def test_a_csv_trace(m68x6):
    (cycle,) = cycleref.expand(m68x6)
    rows = ["motion,x,z,lead", "rapid,80,10,"]
    rows += [f"{m.motion},{m.x},{m.z},{m.lead or ''}" for m in cycle.moves]
    rows += ["rapid,100,50,"]
    assert cycleref.check(m68x6, "\n".join(rows) + "\n", csv=True).agree


def test_a_broken_trace_is_an_error_naming_its_line(m68x6):
    with pytest.raises(cycleref.Error, match="line 2"):
        cycleref.check(m68x6, "G00 X80 Z10\nG76 X60 Z-60\n")
