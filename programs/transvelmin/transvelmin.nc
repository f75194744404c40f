; transvelmin: #TRANSVELMIN (minimum block transition velocity at discontinuous line/circle
;   transitions, isg-language.md 5.6): a polyline with 30-60 degree corners run without it, with
;   #TRANSVELMIN ON [600] (mm/min), and OFF again.
; portal_3x; moves inside X 10..130 Y 10..40.
%transvelmin
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 $FOR P1 = 0, 2, 1
N40   $IF P1 == 1
N50     #TRANSVELMIN ON [600]
N60   $ELSEIF P1 == 2
N70     #TRANSVELMIN OFF
N80   $ENDIF
N90   G01 X30 Y20 F4800
N100  X50 Y10
N110  X70 Y20
N120  X90 Y10
N130  X110 Y25
N140  X130 Y10
N150  G09 X10
N160 $ENDFOR
N170 M30
