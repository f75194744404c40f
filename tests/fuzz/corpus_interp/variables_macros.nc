%vars
#VAR
  V.L.A[3] : REAL = [1, 2, 3]
  V.L.N : SGN32 = 7
  V.L.S : STRING[20] = "sub.nc"
#ENDVAR
P1 = 3
V.P.X = V.L.A[2] * V.L.N
"M1" = "[V.P.X + 1]"
G01 X["M1"] F100
L V.L.S
#SPLINE ON
G01 X1 Y1
G01 X2 Y3
G01 X4 Y2
#SPLINE OFF
G04 1.5
M30
