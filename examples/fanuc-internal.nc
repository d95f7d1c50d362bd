(seed 004, example 2: FANUC G76, internal thread, lead 3, at IS-B.)
(k = 1.95, dd = 0.4, ddmin = 0.1, allowance 0.1, m 2, r 0.1 lead, a 60.)
O5019;
N10 G99 G21;
N20 M03 S400;
N30 T0303;
N40 G00 X26.0 Z3.0;
N50 G76 P020160 Q100 R0.1;
N60 G76 X36.0 Z-40.0 R0 P1950 Q400 F3.0;
N70 G00 Z200.0;
N80 X100.0;
N90 M30;
