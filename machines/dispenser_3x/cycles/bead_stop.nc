%bead_stop
; G802 [retract mm]: close the valve and lift the needle
M62
G91 G01 Z[@P1] F600
G90
M17
