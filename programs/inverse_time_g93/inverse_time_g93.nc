; inverse_time_g93: G93 inverse-time feed (F is the block's machining time in seconds,
;   isg-language.md 2.3) for lines, an arc and a helix, then back to G94 mm/min.
; portal_3x; moves inside X 20..80 Y 20..60.
%inverse_time_g93
N10 G17 G90 G71 G94
N20 G00 X20 Y20 Z0
N30 G93
N40 G01 X80 F1.5                ; 60 mm in 1.5 s
N50 G01 Y60 F0.8                ; 40 mm in 0.8 s
N60 G03 X20 Y60 I-30 J0 F2      ; half circle of radius 30 in 2 s
N70 G02 X20 Y20 Z-5 I0 J-20 F1  ; helical half turn in 1 s
N80 G94
N90 G01 Z0 F600
N100 G01 X50 Y40 F3000
N110 M30
