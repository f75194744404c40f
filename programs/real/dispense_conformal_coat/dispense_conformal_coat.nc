%COAT
; Written in the style of a dispenser's coating job: a board coated in lanes with smoothed
; turns (G261 PATH_DEV 0.5), the valve opened once per lane by the builder's bead cycles, the
; lane count in a V.P. variable, the coating material name as a V.E. string.
#VAR
  V.P.LANES : UNS16 = 5
#ENDVAR
V.E.MATERIAL = "acrylic AR-2"
G17 G90 G71 G94
G54
#CONTOUR MODE [DEV PATH_DEV=0.5]
G261
G00 X2 Y2 Z3
$FOR P1 = 0, V.P.LANES - 1, 1
  G00 X2 Y[2 + P1 * 6] Z3
  G01 Z1.5 F500
  G801 [800]
  G01 X60 F1800
  G01 X60 Y[4 + P1 * 6]
  G01 X2
  G802 [1.5]
$ENDFOR
G260
G80
M30
