; expect: 5:1 NC2011 N10
; expect: 6:1 NC2011 [A]
N10: G01 X1
[A]
N10: G01 X2
[a]
M30
