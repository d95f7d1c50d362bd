(G32 with run-out, GSK 980TDi rules of seed 002: J signed on the short axis,)
(K on the long axis, both modal; a continuous thread of three blocks.)
M03 S500;
G00 X40 Z2;
G32 Z-30 F2 J1.5 K3 Q90000;   (straight, run-out: J 1.5 out, K 3 before the end)
G00 X50;
Z2;                            (a non-thread motion cancels J and K)
X30;
G32 X34 Z-10 F2 Q180000;       (continuous thread: tapered start ...)
G32 Z-30;                      (... straight middle, Q of block 1 counts ...)
G32 X38 Z-40 J1 Q90000;        (... tapered end with run-out K = J; this Q is ignored)
G00 X50;
Z2;
M30;
