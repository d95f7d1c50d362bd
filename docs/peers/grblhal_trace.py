#!/usr/bin/env python3
"""Write grblHAL's moves (from grblhal_mc_thread.py) as a plain G00/G32 trace for `cycleref check`:
X as a diameter, three decimals (IS-B), the program's own blocks before and after the cycle."""
import os, sys
DEC = int(os.environ.get("DEC", "3"))
SUF = "" if DEC == 3 else f"-{DEC}d"
sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grblhal_mc_thread import f32, g76_words, mc_thread

def trace(words, lead_word, out):
    t = g76_words(22.0, 2.0, **words)
    lines = ["(grblHAL-style trace, from grblhal_mc_thread.py)", "O0002", "G99 G21", "M03 S500", "G00 X22.0 Z2.0"]
    for m in mc_thread({"x": f32(11.0), "z": f32(2.0)}, t):
        if m[0] == "pass":
            continue
        kind, x, z, _ = m
        if kind == "rapid":
            lines.append(f"G00 X{2*x:.{DEC}f} Z{z:.{DEC}f}")
        else:
            lines.append(f"G32 X{2*x:.{DEC}f} Z{z:.{DEC}f} F{lead_word}")
    lines += ["G00 X100.0", "M30"]
    open(out, "w").write("\n".join(lines) + "\n")

common = dict(P=1.5, Z=-20.0, I=-2.0, J=0.6, R=2.0, K=1.84, Q=30.0, H=1)
trace(common, "1.5", f"trace-grblhal-straight{SUF}.nc")
trace(dict(common, X=-1.0), "1.5004", f"trace-grblhal-taper{SUF}.nc")
