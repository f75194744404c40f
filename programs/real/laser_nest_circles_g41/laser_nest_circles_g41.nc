%NEST_DISCS
; Written in the style of a laser nesting post with the kerf in the control: a row of five
; discs of R 15 mm cut outside the part with G41 (clockwise circles: left of the path is
; outside), lead-in from the disc's left, D2 the stainless kerf, pierce and beam-off cycles.
G17 G90 G71 G94
G54
M110=2600
$FOR P1 = 0, 4, 1
  P2 = 30 + P1 * 40
  G00 X[P2 - 25] Y30 Z10
  G81 [0.5, 2.5]
  G41 D2 G01 X[P2 - 15] Y30 F3000
  G02 X[P2 - 15] Y30 I15 J0
  G40 G01 X[P2 - 25] Y30
  G82
$ENDFOR
M110=0
G53 G00 X0 Y0 Z0
M30
