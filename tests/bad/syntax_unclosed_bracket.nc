; expect: 2:14 NC1001 expected ']'
G01 X[2*[3+4]
M30
