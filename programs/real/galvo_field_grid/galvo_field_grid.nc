%GALVO_GRID
; Written in the style of a galvo-scanner wrapper: a 3 x 2 grid of scanner fields of 60 mm,
; each field's pattern number as H value, the field start as M160, the marking time per field
; as a dwell computed from the pattern, the scanner's settings as M values.
#TOOL DATA [GALVO_F160]
G17 G90 G71 G94
M151=420
M152=2500
G00 Z35
$FOR P1 = 0, 1, 1
  $FOR P2 = 0, 2, 1
    G00 X[80 + P2 * 60] Y[80 + P1 * 60]
    H3=[P1 * 3 + P2 + 1]
    M160
    G04 [0.6 + 0.1 * P2]
  $ENDFOR
$ENDFOR
M151=0
G00 X0 Y0 Z50
M30
