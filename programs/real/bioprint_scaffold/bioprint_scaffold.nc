% scaffold 20x20 4 layers
( Written in the style of a bioprinter's export: a lattice scaffold of 4 layers, 0.3 mm each, )
( strands alternating in X and Y, beads started and stopped by the builder's cycles )
( G801 [pressure 0.1 kPa] and G802 [retract mm]. )
#VAR
  V.P.LAYER : REAL64
  V.P.Z : REAL64
  V.P.K : REAL64
#ENDVAR
N10 G17 G90 G71 G94
N20 G54
N30 G80
N40 G00 X0 Y0
$FOR V.P.LAYER = 0, 3, 1
  V.P.Z = 0.25 + V.P.LAYER * 0.3
  $FOR V.P.K = 0, 4, 1
    $IF V.P.LAYER MOD 2 == 0
      G00 X0 Y[V.P.K * 5] Z[V.P.Z + 1]
      G01 Z[V.P.Z] F600
      G801 [1150]
      G01 X20 F480
      G802 [1.0]
    $ELSE
      G00 X[V.P.K * 5] Y0 Z[V.P.Z + 1]
      G01 Z[V.P.Z] F600
      G801 [1150]
      G01 Y20 F480
      G802 [1.0]
    $ENDIF
  $ENDFOR
$ENDFOR
N900 M200=0
N910 G80
N920 M30
