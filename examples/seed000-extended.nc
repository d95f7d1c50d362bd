(seed 000, GSK extended G76, worked example: straight thread with J/K run-out.)
(The seed's snippet programs no spindle speed; M03 S500 is added so that the)
(spindle check of note 8 passes.)
M03 S500
G00 X80 Z10
G76 P020545 Q0.15 R0.5
G76 X60 Z-60 P3 Q1.8 F300 J1.5 K2
G00 X80 Z10
M30
