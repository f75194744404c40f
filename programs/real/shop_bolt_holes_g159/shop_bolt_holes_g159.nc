; Written in the style of a hand-written shop program: the same flange drilled in all four
; vices, the vice chosen by G159 from a counter, the bolt-hole count and radius in V.L.
; variables, a peck cycle as a local subroutine with its depth in P parameters.
%L PECK
P20 = 0
$WHILE P20 > P21
  P20 = P20 - 3
  $IF P20 < P21
    P20 = P21
  $ENDIF
  G01 Z[P20] F180
  G00 Z1
$ENDWHILE
M17
%BOLT_HOLES
#VAR
  V.L.HOLES : UNS16 = 6
  V.L.R : REAL64 = 22.5
#ENDVAR
G17 G90 G71 G94
T5 M06
S3500 M03
P21 = -9
$FOR P1 = 1, 4, 1
  G159=P1
  G00 Z20
  $FOR P2 = 0, V.L.HOLES - 1, 1
    G00 X[30 + V.L.R * COS[P2 * 360 / V.L.HOLES]] Y[30 + V.L.R * SIN[P2 * 360 / V.L.HOLES]] Z1
    LL PECK
  $ENDFOR
  G00 Z20
$ENDFOR
M05
G53 G00 Z180
M30
