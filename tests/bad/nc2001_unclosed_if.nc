; expect: 3:1 NC2001 $IF is not closed
%main
$IF P1 > 1
G01 X1
M30
