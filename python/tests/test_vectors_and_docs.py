"""`cycleref.vectors` is the checked-in corpus; the docstrings' examples run."""

from __future__ import annotations

import doctest
import json

import cycleref
from conftest import ROOT


def test_vectors_are_the_checked_in_corpus():
    # vectors/ is `cycleref vectors --count 90 --seed 1` (cli/tests/vectors.rs).
    cases = list(cycleref.vectors(3, 1))
    assert [c["id"] for c in cases] == ["case-0001", "case-0002", "case-0003"]
    for case in cases:
        assert case == json.loads((ROOT / "vectors" / f"{case['id']}.json").read_text())


def test_docstring_examples():
    # The module docstring defines `program`; each function's examples use it.
    program = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n"
    failures, tried = doctest.testmod(
        cycleref, extraglobs={"cycleref": cycleref, "program": program}, optionflags=doctest.ELLIPSIS, report=True
    )
    assert tried > 5
    assert failures == 0
