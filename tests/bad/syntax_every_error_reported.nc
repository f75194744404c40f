; expect: 4:8 NC1001
; expect: 5:9 NC1001
; expect: 7:2 NC1001 expected a value
G01 X1 Q
G01 X[1+]
G01 Y1
M
M30
