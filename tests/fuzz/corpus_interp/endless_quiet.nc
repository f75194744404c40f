%quiet
P1 = 0
$WHILE [TRUE]
  P1 = P1 + 1
$ENDWHILE
M30
