; Written in the style of a laser nesting post: the same bracket on both pallets (G54, G55),
; a half-size proof piece beside the first one (G56 and #SCALE), the bracket a local subroutine.
%L BRACKET
G00 X0 Y0 Z10
G81 [0.3, 2.5]
G01 X80 F10000
G01 Y20
G03 X60 Y40 I-20 J0
G01 X20
G01 X0 Y20
G01 Y0
G82
M17
%TWO_PALLETS
G17 G90 G71 G94
M110=1800
G54
LL BRACKET
G56
#SCALE ON X0.5 Y0.5
LL BRACKET
#SCALE OFF
G55
LL BRACKET
M110=0
G53 G00 X0 Y0 Z0
M30
