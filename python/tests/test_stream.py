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
