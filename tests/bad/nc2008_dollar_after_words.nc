; expect: 2:8 NC2008 $IF
G01 X1 $IF 1
M30
