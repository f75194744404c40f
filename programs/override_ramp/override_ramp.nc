; override_ramp: a milling contour cut while the PLC changes the path override (scenario.toml):
;   100 % -> 50 % at 1.0 s -> 75 % at 3.0 s -> 100 % at 5.5 s, and 80 % when N120 (file line 19)
;   starts its second pass.
;   A 100 x 60 mm rectangle with corner radius 10 mm, tangent arc lead-in and lead-out, two
;   depths; the override ramps (jerk-limited) on the long lines and through the arcs.
; portal_3x; moves inside X 20..120 Y 20..80.
%override_ramp
N10 G17 G90 G71 G94
N20 G00 X70 Y30 Z5
N30 $FOR P1 = 1, 2, 1
N40   G01 Z[-2 * P1] F600
N50   G03 X70 Y20 I0 J-5 F3000       ; tangent lead-in: half circle onto the contour
N60   G01 X110
N70   G03 X120 Y30 I0 J10              ; corner radius 10
N80   G01 Y70
N90   G03 X110 Y80 I-10 J0
N100  G01 X30
N110  G03 X20 Y70 I0 J-10
N120  G01 Y30
N130  G03 X30 Y20 I10 J0
N140  G01 X70
N150  G03 X70 Y30 I0 J5                ; tangent lead-out
N160 $ENDFOR
N170 G00 Z5
N180 M30
