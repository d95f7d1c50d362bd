(GSK 980TDi G78: equal depth steps of 0.8, flanks in turn, two finishing passes)
M3 S300
G00 X80 Z10
G78 P000345 Q150 R0.5 J1.5 K2 D2
G78 X60 Z-60 P3000 Q800 F3
G00 X80 Z10
M30
