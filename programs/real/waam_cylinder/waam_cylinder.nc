%WAAM_CYLINDER
; Written in the style of a wire-arc additive slicer's writer: a cylinder wall of R 25 mm in
; 5 rings of 2 mm, each ring a full circle with the arc on, the start point moved by 30
; degrees per layer so that the seams do not stack; cycles named by #FILENAME.
#FILENAME [G800="arc_on.cyc" G801="arc_off.cyc"]
G17 G90 G71 G94
G54
G00 X100 Y100 Z40
$FOR P1 = 0, 4, 1
  P2 = P1 * 30
  P3 = 100 + 25 * COS[P2]
  P4 = 100 + 25 * SIN[P2]
  G00 X[P3] Y[P4] Z[4 + P1 * 2]
  G01 Z[2 + P1 * 2] F1200
  G800 [ 120, 70 ]
  G03 X[P3] Y[P4] I[100 - P3] J[100 - P4] F360
  G801
  G00 Z[10 + P1 * 2]
  G04 5
$ENDFOR
G00 Z60
M30
