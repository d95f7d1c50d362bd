(GSK 988TA G78 example, a straight thread. The page writes P020545, whose)
(r = 05 is outside the range 0 to 4 of P-r: here r = 04, left and right in turn.)
(The page writes F300, a 300 mm lead as written, in the F table 0.0001 to 9999,)
(and cycleref reads it so; here F3, the lead of the pages' other examples, since)
(at S300 a 300 mm lead is 90 m/min along Z. J and K are given: no pass point)
(depends on the lead.)
M3 S300
G00 X80 Z10
G78 P020445 Q0.15 R0.5
G78 X60 Z-60 P3 Q1.8 F3 J1.5 K2
G00 X80 Z10
M30
