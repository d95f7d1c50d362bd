"""Errors: `ProgramError` for a block the reader refuses, `CycleError` for a
cycle's alarm, with `line`, `word`, `rule` and the command's message."""

from __future__ import annotations

import subprocess
from decimal import Decimal

import pytest

import cycleref
from conftest import EXAMPLES, cli_binary


def test_a_word_not_in_increments():
    # examples/gsk980-g32-taper.nc is written for IS-C (X27.4286).
    with pytest.raises(cycleref.ProgramError) as e:
        cycleref.expand(EXAMPLES / "gsk980-g32-taper.nc", profile="gsk980")
    assert not isinstance(e.value, cycleref.CycleError)
    assert (e.value.line, e.value.word, e.value.rule) == (7, "X27.4286", "not_in_increments")
    assert "line 7, word `X27.4286`" in str(e.value)


def test_a_missing_spindle_speed():
    with pytest.raises(cycleref.ProgramError) as e:
        cycleref.expand("G00 X80 Z10\nG76 X60.64 Z-62 Q1.800 F6\n")
    assert (e.value.line, e.value.word, e.value.rule) == (2, None, "no_spindle_speed")
    assert str(e.value).startswith("<string>: line 2: ")


def test_a_cycle_alarm_is_a_cycle_error():
    # ffi/src/cursor.rs's test: a G76 whose start A (X62) lies inside the thread.
    program = "G50 X100 Z50 M3 S300;\nG00 X62 Z10;\nG76 P020560 Q0.150 R0.1;\nG76 X60.64 Z-62 P3.680 Q1.800 F6;\n"
    for call in (cycleref.expand, cycleref.iter_moves):
        with pytest.raises(cycleref.CycleError) as e:
            call(program, name="a.nc")
        assert isinstance(e.value, cycleref.ProgramError) and isinstance(e.value, ValueError)
        assert (e.value.line, e.value.word, e.value.rule) == (4, None, "cycle:start_inside_thread")
        assert str(e.value).startswith("a.nc: line 4, G76: the start point A lies inside the thread")


def test_iter_moves_raises_before_the_first_move():
    # An error at the end of a program is raised by the call, before any move.
    program = "M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nG76 X60 Z-60\n"
    with pytest.raises(cycleref.ProgramError) as e:
        cycleref.iter_moves(program)
    assert e.value.line == 5


@pytest.mark.parametrize(
    "name, args",
    [
        ("gsk980-g32-taper.nc", ["--profile", "gsk980"]),
        ("gsk980-m68x6.nc", ["--profile", "gsk980"]),
    ],
)
def test_the_message_is_the_commands(name, args):
    binary = cli_binary()
    if binary is None:
        pytest.skip("the cycleref command is not built (cargo build -p cycleref-cli)")
    path = str(EXAMPLES / name)
    out = subprocess.run([str(binary), "expand", *args, path], capture_output=True, text=True)
    assert out.returncode == 2
    with pytest.raises(cycleref.ProgramError) as e:
        cycleref.expand(EXAMPLES / name, profile="gsk980")
    # The command prints the stable kind (the exception's `rule`) first.
    assert out.stderr == f"cycleref: error[{e.value.rule}]: {e.value}\n"


def test_the_version_is_the_crates():
    # One version across the crates, the package and the C header (issue 35).
    import pathlib
    import re

    cargo = (pathlib.Path(__file__).parents[2] / "Cargo.toml").read_text()
    (version,) = re.findall(r'^\[workspace\.package\]\nversion = "([^"]+)"', cargo, re.M)
    assert cycleref.__version__ == version == "0.2.0"


def test_a_file_that_cannot_be_read_raises_the_oserror_of_its_cause(tmp_path):
    # As open() does: the subclass of the errno, with errno, strerror and
    # filename set (not a bare OSError with only a message).
    missing = tmp_path / "missing.nc"
    calls = (
        lambda: cycleref.expand(missing),
        lambda: cycleref.iter_moves(missing),
        lambda: cycleref.check(missing, missing),
        lambda: cycleref.check(EXAMPLES / "fanuc-external.nc", missing, profile="fanuc"),
        lambda: cycleref.expand("G00 X10 Z10\n", params=missing),
    )
    for call in calls:
        with pytest.raises(FileNotFoundError) as e:
            call()
        assert (e.value.errno, e.value.filename) == (2, str(missing))
        assert e.value.strerror == "No such file or directory"
    with pytest.raises(IsADirectoryError) as e:
        cycleref.expand(tmp_path)
    assert (e.value.errno, e.value.filename) == (21, str(tmp_path))


def test_expand_holds_at_most_a_million_moves():
    # 1354 rough + 1 finishing passes x 250 starts, 4 moves a pass: 1 355 000
    # moves (the command's header and jsonl count say so). expand() refuses
    # it once the move past the limit is reached, having expanded the cycle
    # once; iter_moves() streams it.
    program = (
        "G50 X100 Z50 M3 S300\nG00 X75 Z10\nG76 P010060 Q0.001 R0 L250\n"
        "G76 X60.64 Z-62 P3.68 Q0.1 F6\nM30\n"
    )
    with pytest.raises(cycleref.Error) as e:
        cycleref.expand(program, name="big.nc")
    assert str(e.value).startswith("big.nc: line 4: the expansion exceeds 1000000 moves by this G76")
    assert "use iter_moves()" in str(e.value)
    moves = cycleref.iter_moves(program)
    first = next(moves)
    assert (first.motion, first.x, first.z) == ("rapid", Decimal("67.800"), Decimal("9.942"))


SUBPROGRAMS = (
    "G50 X100 Z50 M3 S300\nG00 X80 Z10\nM98 P1000\nG00 X90\nM98 P1000\nM30\nO1000\n"
    "G76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM99\n"
)


def test_a_subprogram_runs_where_it_is_called():
    # Reading R-SUBPROGRAM (issue 30, found 2): the thread is cut twice,
    # from X80 and from X90, both cycles on line 9 of the file.
    cycles = cycleref.expand(SUBPROGRAMS)
    assert [(c.line, c.moves[-1].x) for c in cycles] == [(9, Decimal("80.000")), (9, Decimal("90.000"))]
    # 4 rough + 2 finishing passes, 5 moves each (approach, cut, run-out,
    # retract, return), in each run.
    assert [len(c.moves) for c in cycles] == [30, 30]


def test_a_call_to_a_missing_subprogram_names_its_line_and_word():
    with pytest.raises(cycleref.ProgramError) as e:
        cycleref.expand(SUBPROGRAMS.replace("M98 P1000\nG00 X90", "M98 P1001\nG00 X90"))
    assert (e.value.line, e.value.word, e.value.rule) == (3, "P1001", "subprogram:not_found")
