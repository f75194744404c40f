; expect: 2:7 20839 after $GOTO
$GOTO 10
M30
