(A square groove on the GSK 980TDi profile, IS-B: two layers V4, allowances)
(U0.4 W0.2, a 3 mm grooving tool I3, rough + finish J1, a 0.5 chamfer at the)
(start corner A and rounds of 0.4 and 0.3 at the bottom corners D and E,)
(P0011. Worked by hand in proofs/tests/g75_golden.rs.)
O0010;
M03 S800;
G00 X40 Z5;
G75.1 X30 Z0 P2000 Q3000 H-6 D-8;
G75.1 R0.5 V4 U0.4 W0.2 I3 J1 A0.5 D0.4 E0.3 P0011;
G00 X100 Z50;
M30;
