; spline_akima_contour: a wave contour through measured points as an Akima spline (the ISG
; default type), followed by the same points as B-spline control points under a shifted #CS.
; Each section is planned as curve pieces with arc-length parametrisation (never chopped into
; lines); the feed changes inside the first section at N100.
%spline_akima_contour
N010 G00 X0 Y20 Z5
N020 G01 Z0 F600
N030 #SLOPE [TYPE=TRAPEZ]
N040 #SPLINE ON
N050 G01 X10 Y28 F3000
N060 X20 Y32
N070 X30 Y28
N080 X40 Y20
N090 X50 Y12
N100 X60 Y8 F1800
N110 X70 Y12
N120 X80 Y20
N130 #SPLINE OFF
N140 G00 Z5
N150 #CS ON [1][0, 40, 0, 0, 0, 0]
N160 G00 X0 Y20
N170 G01 Z0 F600
N180 #SPLINE TYPE BSPLINE
N190 #SPLINE ON
N200 G01 X10 Y28 F3000
N210 X20 Y32
N220 X30 Y28
N230 X40 Y20
N240 X50 Y12
N250 X60 Y8
N260 X70 Y12
N270 X80 Y20
N280 #SPLINE OFF
N290 #CS OFF
N300 G00 Z5
N310 G00 X0 Y0
N320 M30
