% two materials 2x5 dots
( Written in the style of a two-printhead bioprinter export: material A from head 1 on the bed )
( (G54), material B from head 2, whose needle offset the export writes into the zero offset )
( G59 before using it; the heads' pressures as M200 (head 1) and M201 (head 2) values. )
N10 G17 G90 G71 G94
N20 V.G.NP[6].V.X = V.G.NP[1].V.X + 32.5
N30 V.G.NP[6].V.Y = V.G.NP[1].V.Y - 0.8
N40 V.G.NP[6].V.Z = V.G.NP[1].V.Z + 0.35
N50 G80
N60 T1
N70 G54
N80 M200=1350
$FOR P1 = 0, 4, 1
  G00 X[P1 * 3] Y0 Z0.4
  G800 [0.3, 1.5]
$ENDFOR
N100 G80
N110 T2
N120 G59
N130 M201=900
$FOR P1 = 0, 4, 1
  G00 X[P1 * 3] Y3 Z0.4
  G800 [0.5, 1.5]
$ENDFOR
N200 M200=0 M201=0
N210 G80
N220 M30
