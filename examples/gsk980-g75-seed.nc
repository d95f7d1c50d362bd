(seed 001 / manuals/gsk980tdi-g75.1.txt, example O0008: trapezoidal groove,)
(depth 20 dia, bottom 10, flank angles 45 and 30 degrees. The manual assumes)
(IS-C, 0.0001 mm: run with --profile gsk980 --increment is-c. It programs no)
(I, so the cycle is a pointed tool's, reading R-G75SEED; add I4 to block 2)
(to have the cycle compensate the 4 mm grooving tool the manual assumes.)
O0008;
G00 X60 Z30 M3 S500;
G75.1 X50 Z30 P30000 Q50000 H-20 D-10 A45 B30;
G75.1 R0.5;
M30;
