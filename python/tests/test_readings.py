"""Readings per control (issue 34): `readings={"ID": "value"}` as the
command's `--reading ID=VALUE`, winning over the parameter file, and an
unknown id or value a `ValueError` naming the valid ones."""

from __future__ import annotations

from decimal import Decimal

import pytest

import cycleref

# The 980TDi's G92 with J8 (radius) longer than the retract X40 - X30 = 10
# (diameter): clamped to X40 by default (R-RUNOUT all-profiles), as written
# to X30 + 2*8 = X46 under gsk988-only (spec/tests/readings.rs).
PROGRAM = "M3 S300\nG00 X40 Z5\nG92 X30 Z-20 F2 J8 K2\nM30\n"


def run_out_end(**kw):
    (cycle,) = cycleref.expand(PROGRAM, profile="gsk980", **kw)
    (m,) = [m for m in cycle.moves if m.role == "run-out"]
    return (m.x, m.z)


def test_default_and_chosen_reading():
    assert run_out_end() == (Decimal("40.000"), Decimal("-20.000"))
    assert run_out_end(readings={"R-RUNOUT": "gsk988-only"}) == (Decimal("46.000"), Decimal("-20.000"))
    assert run_out_end(readings={}) == run_out_end()


def test_the_keyword_wins_over_the_parameter_file(tmp_path):
    params = tmp_path / "m.toml"
    params.write_text('[readings]\n"R-RUNOUT" = "gsk988-only"\n', encoding="utf-8")
    assert run_out_end(params=params)[0] == Decimal("46.000")
    assert run_out_end(params=params, readings={"R-RUNOUT": "all-profiles"})[0] == Decimal("40.000")


def test_unknown_id_or_value_names_the_valid_ones():
    with pytest.raises(ValueError) as e:
        cycleref.expand(PROGRAM, profile="gsk980", readings={"R-NOPE": "x"})
    assert "R-RUNOUT, R-XRUNOUT, R-E980, R-END, R-LONG988, R-HIGHSPEED, R-G78LEFT, R-G78CENTRE, R-LEADIN, R-INFEED, R-LCNC-READER, R-G92Q, R-G75ALLOW, R-G75P, R-NOROUGH, R-DEPTH, R-STARTS, R-G92HS-NOK, R-G92HS-NOJ, R-G92JK988, R-G32RUNOUT, R-CHAMFERANGLE, R-MODAL, R-G32LONG" in str(e.value)
    with pytest.raises(ValueError) as e:
        cycleref.expand(PROGRAM, profile="gsk980", readings={"R-XRUNOUT": "never"})
    assert "its values are refuse, towards-start" in str(e.value)
