%SLOTS
; Written in the style of a laser CAM post for a perforated panel: 4 x 3 rounded slots on the
; second pallet (G55), each pierced by the builder's cycle, the contour speed limited to
; 6 m/min by #VECTOR LIMIT, the gas pressure and power as M values per slot row.
G17 G90 G71 G94
G55
#VECTOR LIMIT ON [VEL=6000]
M111=80
$FOR P1 = 0, 2, 1
  M110=[1600 + P1 * 100]
  $FOR P2 = 0, 3, 1
    P3 = 40 + P2 * 60
    P4 = 40 + P1 * 50
    G00 X[P3] Y[P4 - 5] Z10
    G81 [0.25, 2.0]
    G01 X[P3 + 20] F8000
    G03 X[P3 + 20] Y[P4 + 5] I0 J5
    G01 X[P3]
    G03 X[P3] Y[P4 - 5] I0 J-5
    G82
  $ENDFOR
$ENDFOR
M110=0
M111=0
#VECTOR LIMIT OFF
G53 G00 X0 Y0 Z0
M30
