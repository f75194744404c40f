; expect: 3:8 20219 alone
$IF 1
$ENDIF G01
M30
