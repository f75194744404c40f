; override_above_100: a milling contour cut while the operator turns the path override above
;   100 % (scenario.toml): 100 % -> 150 % at 0.8 s -> 300 % at 2.5 s -> 100 % at 4.5 s.
;   The machine portal_3x_override has the third override type, "Reduced [0 .. >100 %]"
;   (000 §7.5.6, NCSIM-CHAN-630 REDUCED_ABOVE_100): above 100 % the cruise rises up to the axes'
;   G00 velocity (500 mm/s) and on the arcs up to the axes' acceleration, while the joints and
;   stops keep their 100 % velocities (docs/decisions.md "Override and feed hold").
;   A 160 x 80 mm rectangle with corner radius 10 mm, cut twice at F3000 (50 mm/s).
; portal_3x_override; moves inside X 20..180 Y 20..100.
%override_above_100
N10 G17 G90 G71 G94
N20 G00 X30 Y20 Z5
N30 G01 Z-1 F600
N40 $FOR P1 = 1, 2, 1
N50   G01 X170 F3000
N60   G03 X180 Y30 I0 J10              ; corner radius 10
N70   G01 Y90
N80   G03 X170 Y100 I-10 J0
N90   G01 X30
N100  G03 X20 Y90 I0 J-10
N110  G01 Y30
N120  G03 X30 Y20 I10 J0
N130 $ENDFOR
N140 G00 Z5
N150 M30
