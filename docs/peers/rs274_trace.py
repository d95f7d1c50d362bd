#!/usr/bin/env python3
"""Turn `rs274 -g` canonical output (X as a radius, 4 decimals) into a plain G00/G32 trace for
`cycleref check` (X as a diameter, 3 decimals). Only the moves after the first STRAIGHT_TRAVERSE
(the program's G0 X22 Z2) are kept; START_SPEED_FEED_SYNC(p, ...) gives the lead of the next feeds."""
import os, re, sys
DEC = int(os.environ.get("DEC", "3"))
src, out, head = sys.argv[1], sys.argv[2], sys.argv[3:]
lines = ["(LinuxCNC trace, from rs274 -g)"] + head
lead = None
for raw in open(src):
    m = re.search(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|START_SPEED_FEED_SYNC)\(([^)]*)\)", raw)
    if not m:
        continue
    args = [float(a) for a in m.group(2).split(",")]
    if m.group(1) == "START_SPEED_FEED_SYNC":
        lead = args[0]
        continue
    x, z = 2 * args[0], args[2]
    g = "G00" if m.group(1) == "STRAIGHT_TRAVERSE" else "G32"
    lines.append(f"{g} X{x:.{DEC}f} Z{z:.{DEC}f}" + (f" F{lead:g}" if g == "G32" else ""))
lines += ["G00 X100.0", "M30"]
open(out, "w").write("\n".join(lines) + "\n")
