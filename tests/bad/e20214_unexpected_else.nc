; expect: 2:1 20214 $ELSE
$ELSE
M30
