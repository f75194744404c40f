%LASER_PARTS
; Written in the style of a laser CAM post: two parts on the first sheet (G54), each pierced
; by the builder's cycle G81 [time s, height mm] and cut at the laser power of M110=<W>,
; smoothed by #HSC within 0.05 mm and held to 9 m/min on the contour by #VECTOR LIMIT.
N10 G17 G90 G71 G94
N20 G54
N30 #VECTOR LIMIT ON [VEL=9000]
N40 M110=2200
; --- part 1: 60 x 40 plate with rounded corners
N50 G00 X0 Y5 Z10
N60 G81 [0.4, 3.0]
N70 #HSC ON [PATH_DEV=0.05]
N80 G01 Y35 F12000
N90 G02 X5 Y40 I5 J0
N100 G01 X55
N110 G02 X60 Y35 I0 J-5
N120 G01 Y5
N130 G02 X55 Y0 I-5 J0
N140 G01 X5
N150 G02 X0 Y5 I0 J5
N160 #HSC OFF
N170 G82
; --- part 2: a disc of R 20
N180 G00 X100 Y20 Z10
N190 G81 [0.4, 3.0]
N200 G02 X100 Y20 I20 J0 F6000
N210 G82
N220 M110=0
N230 #VECTOR LIMIT OFF
N240 G53 G00 X0 Y0 Z0
N250 M30
