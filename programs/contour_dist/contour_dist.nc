; contour_dist: polynomial contouring with #CONTOUR MODE DIST (isg-language.md §5.3,
;   PROG-475180811): the curve starts PRE_DIST before each corner on the incoming block and
;   ends POST_DIST after it on the outgoing one. A 20 mm square's corners with PRE_DIST=2
;   POST_DIST=0.5, 90 and 135 degree corners with the symmetric PRE_DIST=POST_DIST=1, then
;   PRE_DIST=POST_DIST=4 where a 3 mm block caps its side at half of it (1.5 mm) and the
;   other keeps its 4 mm, into and out of a quarter arc; G260 for the last corner, at F6000
;   with the jerk-limited #SLOPE TRAPEZ.
; portal_3x; moves inside X 10..70 Y 10..30.
%contour_dist
N10 G17 G90 G71 G94
N15 #SLOPE [TYPE=TRAPEZ]
N20 G00 X10 Y10 Z0
N30 #CONTOUR MODE [DIST PRE_DIST=2 POST_DIST=0.5]
N40 G261
N50 G01 X30 F6000
N60 Y30
N70 X10
N80 Y14
N90 #CONTOUR MODE [DIST PRE_DIST=1 POST_DIST=1]
N100 X40
N110 Y26
N120 X44 Y30                 ; 135 degree corner
N130 #CONTOUR MODE [DIST PRE_DIST=4 POST_DIST=4]
N140 X47                     ; 3 mm: its sides of the corners capped at 1.5 mm
N150 Y20
N160 G02 X52 Y15 I0 J-5      ; quarter arc, 90 degree corner into it and out of it
N170 G01 X60
N180 G260
N190 Y10
N200 G00 Z5
N210 M30
