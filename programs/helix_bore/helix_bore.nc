; helix_bore: a 20 mm bore by helical interpolation: five turns of G02 with Z descending
;   2 mm per turn, a full finishing circle at depth and a retract to the centre.
; portal_3x; centre X100 Y100, radius 10 (I/J relative to the start, G162).
%helix_bore
N10 G17 G90 G71 G94
N20 G00 X100 Y100 Z2
N30 G01 X110 Y100 Z0 F800
N40 $FOR P1 = 1, 5, 1
N50   G02 X110 Y100 Z[-2 * P1] I-10 J0 F1200   ; one full turn, 2 mm down
N60 $ENDFOR
N70 G02 X110 Y100 I-10 J0                       ; finishing circle at Z-10
N80 G01 X100 Y100
N90 G00 Z5
N100 M30
