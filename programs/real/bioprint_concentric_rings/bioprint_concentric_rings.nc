% rings 3 layers
( Written in the style of a bioprinter export for a well plate insert: three concentric rings )
( per layer, R 2 / 3.5 / 5 mm, three layers 0.25 mm apart, each ring a full circle started by )
( the bead cycle; the pressure drops with the layer as M200 values computed from P parameters )
N10 G17 G90 G71 G94
N20 G54
N30 G80
N40 P10 = 1300
$FOR P1 = 0, 2, 1
  M200=[P10 - P1 * 50]
  $FOR P2 = 0, 2, 1
    P3 = 2 + P2 * 1.5
    G00 X[15 + P3] Y15 Z[0.25 + P1 * 0.25 + 1]
    G01 Z[0.25 + P1 * 0.25] F500
    G801 [P10 - P1 * 50]
    G02 X[15 + P3] Y15 I[-P3] J0 F420
    G802 [1.0]
  $ENDFOR
$ENDFOR
N900 M200=0
N910 G80
N920 M30
