; parametric_ellipse: a contour computed from parameters: an ellipse (semi-axes 50 and 25 mm)
;   approximated by 120 line segments of 3 degrees from SIN/COS in a $FOR loop, cut twice with
;   the second pass rotated by 30 degrees (rotation by hand, in the parameters).
; portal_3x; centre X150 Y100.
%parametric_ellipse
N10 G17 G90 G71 G94
N20 P10 = 150                   ; centre X
N30 P11 = 100                   ; centre Y
N40 P12 = 50                    ; semi-axis a
N50 P13 = 25                    ; semi-axis b
N60 $FOR P1 = 0, 1, 1
N70   P14 = 30 * P1             ; rotation of this pass [deg]
N80   G00 X[P10 + P12 * COS[P14]] Y[P11 + P12 * SIN[P14]] Z2
N90   G01 Z-1 F500
N100  $FOR P2 = 3, 360, 3
N110    P3 = P12 * COS[P2]
N120    P4 = P13 * SIN[P2]
N130    G01 X[P10 + P3 * COS[P14] - P4 * SIN[P14]] Y[P11 + P3 * SIN[P14] + P4 * COS[P14]] F3000
N140  $ENDFOR
N150  G00 Z5
N160 $ENDFOR
N170 M30
