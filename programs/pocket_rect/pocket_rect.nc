; pocket_rect: a 50 x 30 mm rectangular pocket with 5 mm corner radius, cleared by concentric
;   offset loops (stepover 4 mm) from the centre outwards, two depths of 2 mm; the loop sizes
;   and depths are parameters, each loop is lines joined by quarter-circle corners.
; portal_3x; pocket centre X100 Y80.
%pocket_rect
N10 G17 G90 G71 G94
N20 P10 = 100                 ; centre X
N30 P11 = 80                  ; centre Y
N40 G00 X[P10] Y[P11] Z2
N50 $FOR P1 = 1, 2, 1
N60   G01 Z[-2 * P1] F400
N70   $FOR P2 = 0, 3, 1
N80     P3 = 9 + 4 * P2         ; half width of the straight part in X
N90     P4 = 1 + 4 * P2         ; half height of the straight part in Y
N100    P5 = 1 + P2             ; corner radius grows 1 mm per loop
N110    G01 X[P10 + P3] Y[P11 - P4 - P5] F2400
N120    G03 X[P10 + P3 + P5] Y[P11 - P4] I0 J[P5]
N130    G01 Y[P11 + P4]
N140    G03 X[P10 + P3] Y[P11 + P4 + P5] I[-P5] J0
N150    G01 X[P10 - P3]
N160    G03 X[P10 - P3 - P5] Y[P11 + P4] I0 J[-P5]
N170    G01 Y[P11 - P4]
N180    G03 X[P10 - P3] Y[P11 - P4 - P5] I[P5] J0
N190    G01 X[P10 + P3]
N200  $ENDFOR
N210  G01 X[P10] Y[P11]
N220 $ENDFOR
N230 G00 Z5
N240 M30
