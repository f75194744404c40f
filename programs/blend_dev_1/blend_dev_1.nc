; blend_dev_1: polynomial contouring (G261, #CONTOUR MODE DEV PATH_DEV=1): a zigzag of 10 mm and
;   4 mm lines with 90 and 135 degree corners blended inside a tolerance ball of radius 1 mm
;   (shrunk where a block is short), at F6000; the same zigzag is then run once with G260.
; portal_3x; moves inside X 10..110 Y 10..44.
%blend_dev_1
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 #CONTOUR MODE [DEV PATH_DEV=1]
N40 G261
N50 $FOR P1 = 0, 1, 1
N60   $FOR P2 = 0, 4, 1
N70     G01 X[10 + 20 * P2 + 10] Y[10 + 20 * P1] F6000
N80     Y[20 + 20 * P1]
N90     X[10 + 20 * P2 + 14] Y[24 + 20 * P1]      ; 135 degree corner
N100    X[10 + 20 * P2 + 20]
N110    Y[10 + 20 * P1]
N120  $ENDFOR
N130  G260                     ; the second row without blends
N140  G01 X10 Y30
N150 $ENDFOR
N160 G00 Z5
N170 M30
