; expect: 2:12 NC1001 expected ','
$FOR P1 = 1
$ENDFOR
M30
