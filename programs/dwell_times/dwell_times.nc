; dwell_times: dwells between moves in the forms of isg-language.md 2.2 (G04 X<s>, G04 <s>,
;   G04 with a parameter, #TIME <s>): 0.5 s, 0.25 s, 0.0105 s (rounded up to 11 cycles: never
;   shorter than programmed) and 0.1 s; the path stops before each dwell.
; portal_3x; moves along X 10..50.
%dwell_times
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 G01 X20 F3000
N40 G04 X0.5
N50 G01 X30
N60 G04 0.25
N70 P1 = 0.0105
N80 G01 X40
N90 G04 P1
N100 G01 X50
N110 #TIME 0.1
N120 G01 X10
N130 M30
