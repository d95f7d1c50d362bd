(manuals/gsk988ta-g76.txt, example O0013: M68x6 thread)
O0013;
G50 X100 Z50 M3 S300;      (set the work coordinates, start the spindle)
G00 X80 Z10;               (rapid to the start point A)
G76 P020560 Q0.150 R0.1;   (2 finishing passes, chamfer 0.5 lead, tool 60 deg, min cut 0.15, allowance 0.1)
G76 X60.64 Z-62 P3.680 Q1.800 F6;  (thread height 3.68, first depth 1.8)
G00 X100 Z50;              (back to the program start)
M30;
