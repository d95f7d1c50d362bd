(PEERS taper: the same thread with R-0.5, radius at the start 0.5 smaller than at the end)
O0002;
G99 G21;
M03 S500;
G00 X22.0 Z2.0;
G76 P010060 Q50 R0;
G76 X18.16 Z-20.0 R-0.5 P920 Q300 F1.5;
G00 X100.0;
M30;
