; grid_subroutines: nested local subroutines and loops: a 3 x 2 grid of pockets, each a
;   square contour (subroutine SQUARE) cut at two depths (subroutine POCKET calls SQUARE),
;   positions from parameters in a $DO loop around a $WHILE loop; the last column is skipped
;   with $CONTINUE; the column pitch comes from a #VAR variable.
; portal_3x; squares of 12 mm side from X20 Y20 to X92 Y68.
%L SQUARE
; a square of side P30 from the current point, incremental, back to the start
G91 G01 X[P30] F2000
Y[P30]
X[-P30]
Y[-P30]
G90
M17

%L POCKET
; two passes of SQUARE at (P31, P32)
G00 X[P31] Y[P32]
G00 Z1
$FOR P33 = 1, 2, 1
  G01 Z[-1 * P33] F500
  LL SQUARE
$ENDFOR
G00 Z5
M17

%grid_subroutines
#VAR
  V.P.PITCH : REAL = 30
#ENDVAR
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z5
N30 P30 = 12
N40 P1 = 0
N50 $DO
N60   P2 = 0
N70   $WHILE P2 < 4
N80     $IF P2 == 3
N90       P2 = P2 + 1
N100      $CONTINUE
N110    $ENDIF
N120    P31 = 20 + V.P.PITCH * P2
N130    P32 = 20 + 36 * P1
N140    LL POCKET
N150    P2 = P2 + 1
N160  $ENDWHILE
N170  P1 = P1 + 1
N180 $ENDDO P1 < 2
N190 G00 X0 Y0
N200 M30
