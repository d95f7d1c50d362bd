(PEERS straight: M20x1.5 external, fanuc profile; P Q without decimal point are 0.001 mm)
O0001;
G99 G21;
M03 S500;
G00 X22.0 Z2.0;
G76 P010060 Q50 R0;
G76 X18.16 Z-20.0 R0 P920 Q300 F1.5;
G00 X100.0;
M30;
