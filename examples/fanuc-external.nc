(seed 004, example 1: FANUC G76, external thread, lead 2, at IS-B.)
(P, Q of G76 without decimal point are in 0.001 mm: k = 1.3, dd = 0.4, ddmin = 0.1.)
O5018;
N10 G99 G21;
N20 M03 S400;
N30 T0303;
N40 G00 X26.0 Z3.0;
N460 G76 P020560 Q100 R0.1;
N60 G76 X21.4 Z-26.0 R0 P1300 Q400 F2.0;
N70 G00 X100.0;
N80 Z200.0;
N90 M30;
