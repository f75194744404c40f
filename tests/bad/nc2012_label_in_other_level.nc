; expect: 6:7 NC2012 [X]
%L SUB
[X]
M17
%main
$GOTO [X]
M30
