; laser_sheet_mcs: laser cutting of rectangular parts with round corners from a standing sheet
;   (no conveyor: machine coordinates only) on laser_portal's fast X/Y (10 m/s^2): a 2 x 3
;   nest, each part a contour of lines and G02 corner arcs at F12000 with a short pierce dwell.
; laser_portal; parts from X100 Y100 to X660 Y520.
%laser_sheet_mcs
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z20
N30 $FOR P1 = 0, 1, 1
N40   $FOR P2 = 0, 2, 1
N50     P3 = 100 + 200 * P2        ; part corner X
N60     P4 = 100 + 250 * P1        ; part corner Y
N70     G00 X[P3] Y[P4 + 10] Z2
N80     G04 X0.05                  ; pierce
N90     G01 Y[P4 + 140] F12000
N100    G02 X[P3 + 10] Y[P4 + 150] I10 J0
N110    G01 X[P3 + 150]
N120    G02 X[P3 + 160] Y[P4 + 140] I0 J-10
N130    G01 Y[P4 + 10]
N140    G02 X[P3 + 150] Y[P4] I-10 J0
N150    G01 X[P3 + 10]
N160    G02 X[P3] Y[P4 + 10] I0 J10
N170    G00 Z20
N180  $ENDFOR
N190 $ENDFOR
N200 G00 X0 Y0
N210 M30
