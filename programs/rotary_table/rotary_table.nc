; rotary_table: the rotary C axis of static_saw interpolated with the linear axes in machine
;   coordinates: C alone (the path is measured over C, degrees/min), C with X (feed over X),
;   a G00 of X and C together, and C back through zero.
; static_saw; C between -90 and 270 degrees, X 0..200, Y 0..100, Z 0..50.
%rotary_table
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z50 C0
N30 G01 C90 F7200                      ; C alone at 7200 deg/min = 120 deg/s
N40 G01 X100 C180 F3000                ; X and C together: the feed is over X
N50 G00 X200 Y100 C270
N60 G01 Z10 F1200
N70 G01 C-90 F18000                    ; half a turn back through zero
N80 G01 X0 Y0 Z50 C0 F6000
N90 M30
