; expect: 2:2 NC1001 control keyword
$ELSIF P1
M30
