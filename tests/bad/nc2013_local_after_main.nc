; expect: 5:1 NC2013 after the main
%main
G01 X1
M30
%L SUB
M17
