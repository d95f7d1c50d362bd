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
