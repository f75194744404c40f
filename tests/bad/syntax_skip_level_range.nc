; expect: 2:2 NC1001 skip level
/11 G01 X1
M30
