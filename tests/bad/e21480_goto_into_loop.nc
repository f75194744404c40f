; expect: 2:7 21480 into a loop
$GOTO N20
$FOR P1 = 1, 3, 1
N20: G01 X1
$ENDFOR
M30
