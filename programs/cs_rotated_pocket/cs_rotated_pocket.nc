; cs_rotated_pocket: a rounded rectangular pocket programmed in its own coordinate system,
; placed on the table by a #CS shifted to X100 Y50 Z-2 and turned 25 degrees about Z, then a
; second copy through a chained #CS tilted 10 degrees about X (the arcs then lie in a plane
; that is not XY: ncsim plans them as arcs in the rotated plane, never as lines).
%cs_rotated_pocket
N010 G00 X0 Y0 Z20
N020 #SLOPE [TYPE=TRAPEZ]
N030 #CS ON [1][100, 50, -2, 25, 0, 0]
N040 G00 X10 Y0 Z5
N050 G01 Z0 F600
N060 G01 X50 F3000
N070 G03 X60 Y10 I0 J10
N080 G01 Y30
N090 G03 X50 Y40 I-10 J0
N100 G01 X10
N110 G03 X0 Y30 I0 J-10
N120 G01 Y10
N130 G03 X10 Y0 I10 J0
N140 G00 Z5
N150 #CS ON [2][0, 0, 0, 0, 0, 10]
N160 G00 X10 Y0 Z5
N170 G01 Z0 F600
N180 G01 X50 F3000
N190 G03 X60 Y10 I0 J10
N200 G01 Y30
N210 G03 X50 Y40 I-10 J0
N220 G01 X10
N230 G03 X0 Y30 I0 J-10
N240 G01 Y10
N250 G03 X10 Y0 I10 J0
N260 G00 Z5
N270 #CS OFF ALL
N280 G00 X0 Y0 Z20
N290 M30
