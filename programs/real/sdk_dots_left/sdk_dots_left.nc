% 1x10 dots left
; Written in the style of the kernel SDK's dispensing samples: the same row of ten dots as an
; exporter's "right" variant, written leftwards with incremental moves, the dot cycle called
; with L CYCLE through the builder's file, the pressure as an M value from a P parameter.
#CHANNEL INIT [CONFIG]
N010 G17 G90 G71 G94
N020 G54
N030 P1 = 1180
N040 M200=P1
N050 G00 X22.5 Y10 Z0.4
N060 L CYCLE [NAME=dot.nc @P1=0.3 @P2=2.0]
N070 P2 = 1
N080 $WHILE P2 < 10
N090   G91 G00 X-2.5 Z-2.0
N100   G90
N110   L CYCLE [NAME=dot.nc @P1=0.3 @P2=2.0]
N120   P2 = P2 + 1
N130 $ENDWHILE
N140 M200=0
N150 G80
N160 M30
