%WAAM_WALL
; Written in the style of a wire-arc additive slicer's writer: a 60 mm wall of 6 layers,
; 1.8 mm each, deposited in alternating directions; the arc is switched by the slicer's own
; cycles named with #FILE NAME (G800 arc on [current A, wire m/min x 10], G801 arc off),
; the wire feed as M value M120=<0.1 m/min>, dwell between layers for cooling.
#FILE NAME [G800="arc_on.cyc" G801="arc_off.cyc"]
G17 G90 G71 G94
G54
G00 X10 Y20 Z30
P1 = 0
$WHILE P1 < 6
  P2 = 2 + P1 * 1.8
  $IF P1 MOD 2 == 0
    G00 X10 Y20 Z[P2 + 5]
    G01 Z[P2] F1200
    G800 [ 140, 85 ]
    G01 X70 F420
  $ELSE
    G00 X70 Y20 Z[P2 + 5]
    G01 Z[P2] F1200
    G800 [ 140, 85 ]
    G01 X10 F420
  $ENDIF
  G801
  G04 8
  P1 = P1 + 1
$ENDWHILE
G00 Z60
M30
