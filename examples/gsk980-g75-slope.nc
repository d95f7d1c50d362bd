(A trapezoidal groove on a 10-degree slope L10, flanks 60 and 75 degrees,)
(a 2.5 mm tool, layers V3, rough + finish with rounds at all four corners,)
(P1111. GSK 980TDi profile, IS-B.)
O0011;
M03 S600;
G00 X90 Z12;
G75.1 X80 Z0 P1500 Q2000 H-9 D-6 A60 B75 L10;
G75.1 R0.3 V3 U0.3 W0.1 I2.5 J1 A0.5 B0.5 D0.4 E0.4 P1111;
G00 X120 Z50;
M30;
