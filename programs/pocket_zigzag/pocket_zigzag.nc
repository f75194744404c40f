; pocket_zigzag: a 40 x 24 mm pocket cleared by a zigzag raster (G01, stepover 3 mm) in a
;   $WHILE loop, then a finishing pass around the wall; sharp reversals at every row end.
; portal_3x; pocket from X20 Y20 to X60 Y44.
%pocket_zigzag
N10 G17 G90 G71 G94
N20 G00 X22 Y22 Z2
N30 G01 Z-2 F400
N40 P1 = 22                    ; current row Y
N50 P2 = 1                     ; 1: cut towards +X
N60 $WHILE P1 <= 42
N70   $IF P2 == 1
N80     G01 X58 Y[P1] F2500
N90   $ELSE
N100    G01 X22 Y[P1] F2500
N110  $ENDIF
N120  P1 = P1 + 3
N130  P2 = 1 - P2
N140  $IF P1 <= 42
N150    G01 Y[P1]
N160  $ENDIF
N170 $ENDWHILE
N180 G01 X20 Y20 F1500          ; finishing pass along the wall
N190 X60
N200 Y44
N210 X20
N220 Y20
N230 G00 Z5
N240 M30
