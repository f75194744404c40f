%WAAM_TAPER
; Written in the style of a wire-arc additive slicer's writer: a square tower whose layers step
; inwards by 0.5 mm (a taper), each layer a closed square started and stopped by the slicer's
; cycles (#FILE NAME), the travel speed per layer from a computed feed in m/min on a channel
; whose F unit is mm/min (the writer converts: F = v * 1000).
#FILE NAME [G800="arc_on.cyc" G801="arc_off.cyc"]
G17 G90 G71 G94
G54
G00 X40 Y40 Z40
$FOR P1 = 0, 4, 1
  P2 = 40 + P1 * 0.5
  P3 = 80 - P1 * 0.5
  P4 = 0.4 - P1 * 0.02
  G00 X[P2] Y[P2] Z[4 + P1 * 1.8]
  G01 Z[2 + P1 * 1.8] F1500
  G800 [ 125, 80 ]
  G01 X[P3] F[P4 * 1000]
  G01 Y[P3]
  G01 X[P2]
  G01 Y[P2]
  G801
  G00 Z[12 + P1 * 1.8]
  G04 4
$ENDFOR
G00 Z60
M30
