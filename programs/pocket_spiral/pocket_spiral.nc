; pocket_spiral: a circular pocket of radius 20 mm cleared by a spiral of half circles whose
;   radius grows by 1.5 mm per half turn (each half circle exact: centre moved along X), then
;   one finishing circle at full radius; two depths.
; portal_3x; pocket centre X60 Y60.
%pocket_spiral
N10 G17 G90 G71 G94
N20 G00 X60 Y60 Z2
N30 $FOR P1 = 1, 2, 1
N40   G01 X60 Y60 Z[-1.5 * P1] F300
N50   P2 = 0                          ; x offset of the current point from the centre
N60   P3 = 1.5                        ; radius increment per half turn
N70   P4 = 1                          ; direction: 1 = now at +x side
N80   $WHILE ABS[P2] < 18.5
N90     P5 = [ABS[P2] + P3]           ; next point's distance from the centre
N100    $IF P4 == 1
N110      G03 X[60 - P5] Y60 I[-[P5 + P2] / 2] J0 F2000
N120      P2 = -P5
N130      P4 = 0
N140    $ELSE
N150      G03 X[60 + P5] Y60 I[[P5 - P2] / 2] J0 F2000
N160      P2 = P5
N170      P4 = 1
N180    $ENDIF
N190  $ENDWHILE
N200  G01 X[60 + 20] Y60
N210  G03 X[60 + 20] Y60 I-20 J0        ; finishing circle
N220  G01 X60 Y60
N230 $ENDFOR
N240 G00 Z5
N250 M30
