; contour_arcs: a milling contour of lines and tangent arcs: a 60 x 40 mm rectangle with
;   corner radius 8 mm, cut once around with a tangent arc lead-in and lead-out, at two depths.
; portal_3x; every arc is exact (start and end radius equal), moves inside X 10..90 Y 10..70.
%contour_arcs
N10 G17 G90 G71 G94
N20 G00 X50 Y20 Z5
N30 $FOR P1 = 1, 2, 1
N40   G01 Z[-1.5 * P1] F600
N50   G03 X50 Y12 I0 J-4 F1500       ; tangent lead-in: half circle onto the contour
N60   G01 X72
N70   G03 X80 Y20 I0 J8                ; corner radius 8
N80   G01 Y44
N90   G03 X72 Y52 I-8 J0
N100  G01 X28
N110  G03 X20 Y44 I0 J-8
N120  G01 Y20
N130  G03 X28 Y12 I8 J0
N140  G01 X50
N150  G03 X50 Y20 I0 J4                ; tangent lead-out
N160 $ENDFOR
N170 G00 Z5
N180 M30
