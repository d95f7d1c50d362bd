(manuals/gsk980tdi-g76.txt, example O0013, figure 3-96: M68x6 thread.)
(The manual states the least input increment is 0.0001 mm: run with --profile gsk980 --increment is-c.)
(P and Q are in least increments: No.182.7 = 0.)
O0013;
G50 X100 Z50 M3 S300;
G04 X2;                      (dwell 2 s for the spindle speed)
G00 X80 Z10;
G76 P020560 Q1500 R0.1;      (m 2, r 0.5 lead, a 60; min cut 0.15; allowance 0.1)
G76 X60.64 Z-62 P36800 Q18000 F6;  (height 3.68, first depth 1.8)
G00 X100 Z50;
M30;
