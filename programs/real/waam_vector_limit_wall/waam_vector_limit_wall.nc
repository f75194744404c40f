%WAAM_CORNER_WALL
; Written in the style of a wire-arc additive slicer's writer: an L-shaped wall of 4 layers
; with rounded corners, the travel speed on the arc held to 0.3 m/min by #VECTOR LIMIT while
; the arc is on, the arc switched by the slicer's cycles named with #FILE NAME.
#FILE NAME [G800="arc_on.cyc" G801="arc_off.cyc"]
G17 G90 G71 G94
G54
G00 X20 Y20 Z30
$FOR P1 = 0, 3, 1
  G00 X20 Y20 Z[3 + P1 * 2]
  G01 Z[2 + P1 * 2] F1500
  G800 [ 130, 75 ]
  #VECTOR LIMIT ON [VEL=300]
  G01 X60 F500
  G03 X70 Y30 I0 J10
  G01 Y60
  #VECTOR LIMIT OFF
  G801
  G00 Z[12 + P1 * 2]
  G04 6
$ENDFOR
G00 Z60
M30
