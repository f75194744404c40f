; expect: 2:13 NC1001 found 'Q5'
N10 G01 X10 Q5
M30
