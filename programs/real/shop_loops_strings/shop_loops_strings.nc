%SHOP_PLATE
; Written in the style of a hand-written shop program: a plate of 3 x 4 holes drilled with a
; peck loop, the hole pattern's pitch in a string macro, the operator's messages in V.L.
; strings, the hole count in a V.P. variable.
#VAR
  V.L.NOTE : STRING[40] = "set up plate 1"
  V.P.HOLES : UNS32 = 0
#ENDVAR
"PITCH" = "15"
#MSG ["drilling 12 holes"]
G17 G90 G71 G94
G00 X20 Y20 Z20
$FOR P1 = 0, 2, 1
  $FOR P2 = 0, 3, 1
    G00 X[20 + P2 * "PITCH"] Y[20 + P1 * "PITCH"] Z2
    P3 = 0
    $REPEAT
      P3 = P3 - 2
      G01 Z[P3] F200
      G00 Z2
    $UNTIL P3 <= -6
    V.P.HOLES = V.P.HOLES + 1
  $ENDFOR
$ENDFOR
V.L.NOTE = "plate done"
G00 Z50
M30
