%purge
; G805 [x, y, z]: purge the needle at a position of the active zero point
G00 Z5
G00 X[@P1] Y[@P2]
G01 Z[@P3] F300
M61
G04 1.5
M62
G00 Z5
M17
