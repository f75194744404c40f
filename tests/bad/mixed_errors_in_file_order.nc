; expect: 6:8 NC1001
; expect: 7:1 20218
; expect: 8:1 NC2009
; expect: 9:1 NC2001
%main
G01 X1 Q
$ENDIF
M1000
$IF 1
M30
