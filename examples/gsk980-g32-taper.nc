(seed 002 / manuals/gsk980tdi-g32.txt, example O0009: taper thread, lead 2,)
(cut in two passes with G32. The manual prints 4 decimals: run with)
(--profile gsk980 --increment is-c. The seed programs no spindle speed;)
(M03 S300 is added so that the spindle check passes.)
O0009;
M03 S300;
G00 X27.4286 Z3;          (first infeed 1 mm)
G32 X48.8571 W-75 F2.0;   (taper thread, first pass)
G00 X55;                  (retract)
W75;                      (back along Z)
X26.4286;                 (second infeed 0.5 mm)
G32 X47.4286 W-75 F2.0;   (taper thread, second pass)
G00 X55;
W75;
M30;
