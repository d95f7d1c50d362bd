"""`cycleref.iter_moves` streams: memory does not grow with the program."""

from __future__ import annotations

import tracemalloc

import cycleref

CYCLE = "G00 X80 Z10\nG76 P020560 Q0.150 R0.1\nG76 X60.64 Z-62 P3.680 Q1.800 F6\n"
CYCLES = 4000  # 30 moves each: 120 000 moves


def rss_kib() -> int:
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    import resource

    return pages * resource.getpagesize() // 1024


def test_iter_moves_holds_one_cycle_at_a_time(tmp_path):
    program = "M3 S300\n" + CYCLE * CYCLES
    path = tmp_path / "big.nc"
    path.write_text(program)
    for source in (path, program):
        it = cycleref.iter_moves(source)
        tracemalloc.start()
        rss_before = rss_kib()
        rss_peak = rss_before
        count = 0
        for m in it:
            count += 1
            if count % 10_000 == 0:
                rss_peak = max(rss_peak, rss_kib())
        _, py_peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        assert count == 30 * CYCLES
        # Holding the moves would take > 100 MB of Python objects (and
        # ~5 MB in the engine); streaming keeps one batch of 1024 moves.
        assert py_peak < 2 * 1024 * 1024, py_peak
        assert rss_peak - rss_before < 16 * 1024, (rss_before, rss_peak)


def test_iter_moves_is_lazy():
    it = cycleref.iter_moves("M3 S300\n" + CYCLE * 3)
    first = next(it)
    assert (first.cycle, first.line, first.motion) == ("G76", 4, "rapid")
    assert sum(1 for _ in it) == 3 * 30 - 1


def test_the_engine_runs_without_the_gil():
    # While the whole program is checked (the first phase of iter_moves, in
    # the engine), another Python thread keeps running.
    import threading
    import time

    program = "M3 S300\n" + CYCLE * 20_000
    state = {"n": 0, "stop": False}

    def spin() -> None:
        while not state["stop"]:
            state["n"] += 1

    t = threading.Thread(target=spin)
    t.start()
    try:
        time.sleep(0.05)
        n0, t0 = state["n"], time.perf_counter()
        time.sleep(0.1)
        rate = (state["n"] - n0) / (time.perf_counter() - t0)  # increments per second, alone
        before = state["n"]
        start = time.perf_counter()
        cycleref.iter_moves(program, engine="spec")
        elapsed = time.perf_counter() - start
        during = state["n"] - before
    finally:
        state["stop"] = True
        t.join()
    # Holding the GIL, the spinning thread would get at most a switch
    # interval (5 ms) or two; released, it runs through the call.
    assert elapsed > 0.1, elapsed
    assert during > rate * 0.05, (during, rate, elapsed)


L999 = (
    "G50 X3000 Z50 M3 S300\nG00 X2200 Z10\n"
    "G76 P990000 Q0.001 R0 L999 E1\nG76 X100 Z-62 P999.999 Q0.001 F6\nM30\n"
)


def test_a_cycle_beyond_the_pass_limit_is_refused_at_once():
    # Issue 30, found 3: 999 999 rough + 99 finishing passes x 999 starts.
    # The budget counts (rough + finishing) x starts before any move.
    import time

    for call in (cycleref.expand, cycleref.iter_moves):
        t = time.monotonic()
        try:
            call(L999)
        except cycleref.CycleError as e:
            # (999 999 + 99) x 999 pass paths.
            assert e.rule == "cycle:too_much_work", e.rule
            assert "999097902 pass paths" in str(e), str(e)
            assert e.line == 4
        else:
            raise AssertionError("refused")
        assert time.monotonic() - t < 5


def test_a_cycle_of_many_starts_is_refused_by_its_pass_paths():
    # M68x6 has 4 rough + 2 finishing passes (the 988TA manual's O0013):
    # 6 pass paths a start; 999 starts are 5 994, within the default limit
    # 1 000 000; a parameter file of pass_limit 5 993 refuses it, with the
    # count, and 5 994 admits it.
    program = "G50 X100 Z50 M3 S300\nG00 X80 Z10\nG76 P020560 Q0.150 R0.1 L999\nG76 X60.64 Z-62 P3.680 Q1.800 F6\nM30\n"
    import tempfile, os

    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write("pass_limit = 5993\n")
    try:
        try:
            cycleref.expand(program, params=f.name)  # a path: params is always a file
        except cycleref.CycleError as e:
            assert e.rule == "cycle:too_much_work", e.rule
            assert "5994 pass paths" in str(e) and "pass limit 5993" in str(e), str(e)
        else:
            raise AssertionError("refused")
        with open(f.name, "w") as g:
            g.write("pass_limit = 5994\n")
        assert len(cycleref.expand(program, params=f.name)) == 1
    finally:
        os.unlink(f.name)


def test_expand_refuses_more_moves_than_it_can_hold_iter_moves_does_not():
    # 40 000 M68x6 cycles of 30 moves: 1 200 000 moves, above expand()'s
    # 1 000 000; refused before any move object is built.
    program = "M3 S300\n" + CYCLE * 40_000
    try:
        cycleref.expand(program)
    except cycleref.Error as e:
        assert "use iter_moves()" in str(e), str(e)
    else:
        raise AssertionError("refused")


def test_iter_moves_raises_once_and_then_stops():
    # A program file changed under the iterator: the moves made before the
    # change is seen come first, then the error once, then nothing.
    import os, tempfile

    with tempfile.NamedTemporaryFile("w", suffix=".nc", delete=False) as f:
        f.write("M3 S300\n" + CYCLE * 200)
    try:
        import pathlib

        it = cycleref.iter_moves(pathlib.Path(f.name))
        next(it)
        with open(f.name, "a") as g:
            g.write(CYCLE)
        raised = 0
        after = 0
        while True:
            try:
                next(it)
                if raised:
                    after += 1
            except StopIteration:
                break
            except cycleref.Error:
                raised += 1
        assert raised == 1 and after == 0, (raised, after)
    finally:
        os.unlink(f.name)
