%a
#VAR
  V.P.T[3][4] : REAL
  V.P.U[2] : UNS08 = [1, 2]
  V.P.N : STRING[10] = "local.nc"
#ENDVAR
$FOR P1 = 0, 2, 1
  $FOR P2 = 0, 3, 1
    V.P.T[P1][P2] = P1 * 4 + P2
  $ENDFOR
$ENDFOR
G01 X[V.P.T[2][3]] Y[SIZEOF[V.P.T]] F[100 * V.P.U[1]]
L V.P.N
#DELETE V.P.T
M30
