%PALLETIZE_3X2
; Written in the style of a robot post-processor for a handling gantry: pick six boxes from
; the conveyor end and place them on a pallet in a 3 x 2 pattern; the cell state for the PLC
; in V.E. strings, the box count in V.E.BOXES, the gripper as M values with the vacuum level.
V.E.CELL = "palletizing"
V.E.BOXES = 0
G17 G90 G71 G94
G00 X50 Y50 Z150
$FOR P1 = 0, 1, 1
  $FOR P2 = 0, 2, 1
    G00 X60 Y420 Z60                   ; above the pick position
    G01 Z22 F4000
    M140=80                            ; vacuum on, 80 %
    G04 0.15
    G01 Z60 F4000
    G00 X[300 + P2 * 120] Y[100 + P1 * 160] Z60
    G01 Z30 F3000
    M141                               ; vacuum off
    G04 0.1
    G01 Z60 F4000
    V.E.BOXES = V.E.BOXES + 1
  $ENDFOR
$ENDFOR
V.E.CELL = "pallet full"
G00 X50 Y50 Z150
M30
