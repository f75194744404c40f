; Written in the style of a hand-written shop program: a name plate in vice 2 (G55), the
; border and three engraved bars, the engraving depth in a V.L. variable, a local subroutine
; for one bar, the operator's notes in a STRING, G91 for the bar's relative moves.
%L BAR
G91 G01 Z[V.L.DEPTH - 2] F150
X30 F600
Y1.5
X-30
G90 G00 Z2
M17
%ENGRAVE
#VAR
  V.L.DEPTH : REAL64 = -0.3
  V.L.NOTE : STRING = "plate 100 x 40"
#ENDVAR
G17 G90 G71 G94
G55
T7 M06
S12000 M03
G00 X0 Y0 Z2
G01 Z[V.L.DEPTH] F150
G01 X100 F800
G01 Y40
G01 X0
G01 Y0
G00 Z2
$FOR P1 = 0, 2, 1
  G00 X35 Y[10 + P1 * 8]
  LL BAR
$ENDFOR
V.L.NOTE = "plate done"
M05
G53 G00 Z180
M30
