; feed_hold: a milling contour with feed holds by the PLC (scenario.toml): a hold at 2.0 s in the
;   middle of a line, released by a later event at 3.0 s, and a 0.8 s hold when the arc N90 (file
;   line 15) starts. The path brakes on the path (jerk-limited), stands, and resumes where it
;   stopped; the contour is unchanged. A 80 x 50 mm rectangle with corner radius 6 mm.
; portal_3x; moves inside X 20..100 Y 20..70.
%feed_hold
N10 G17 G90 G71 G94
N20 G00 X20 Y20 Z5
N30 G01 Z-1 F600
N40 G01 X94 F2400
N50 G03 X100 Y26 I0 J6
N60 G01 Y64
N70 G03 X94 Y70 I-6 J0
N80 G01 X26
N90 G03 X20 Y64 I0 J-6
N100 G01 Y20
N110 G00 Z5
N120 M30
