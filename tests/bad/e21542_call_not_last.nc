; expect: 5:8 21542 last
%L SUB
M17
%main
LL SUB G01 X1
M30
