%sub_bad
P2 = 1
$IF P2 == 2
G01 X[[1]
$ENDIF
M17
