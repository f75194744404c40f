; expect: 2:1 20131 no subroutine
G81 X1
M30
