; Written in the style of the kernel SDK's cycle samples: a cycle defined as a local
; subroutine of the program and called with LL CYCLE [NAME=...], its parameters read with @P,
; one of them written by the cycle itself; three rows of dots with the machine's pressure.
%L ROW
; LL CYCLE [NAME=ROW @P1=<dots> @P2=<pitch mm> @P3=<y mm>]
@P4 = 0
$WHILE @P4 < @P1
  G00 X[@P4 * @P2] Y[@P3] Z0.4
  G800 [0.25, 1.2]
  @P4 = @P4 + 1
$ENDWHILE
M17
% sdk local cycle rows
N010 G17 G90 G71 G94
N020 G54
N030 M200=1150
N040 LL CYCLE [NAME=ROW @P1=6 @P2=3 @P3=0]
N050 LL CYCLE [NAME=ROW @P1=5 @P2=3.5 @P3=4]
N060 LL CYCLE [NAME=ROW @P1=4 @P2=4 @P3=8]
N070 M200=0
N080 G80
N090 M30
