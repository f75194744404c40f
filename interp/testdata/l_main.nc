%l_main
P1 = 4
V.P.LEN = 3
L sub_move.nc
G00 Y[P2] Z[V.P.LEN]
M30
