%sub_move
G00 X[P1]
P2 = P1 * 2
V.P.LEN = V.P.LEN + 1
M17
