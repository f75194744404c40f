% sample filename override
; Written in the style of the kernel SDK's samples on implicit calls: G800 runs the machine's
; dot cycle, then #FILE NAME points G800 at this sample's own cycle for a "double dot" and, at
; the end, back to the machine's (an empty name restores the channel parameter).
N010 G17 G90 G71 G94
N020 G54
N030 M200=1100
N040 G00 X5 Y5 Z0.4
N050 G800 [0.3, 1.5]
N060 #FILE NAME [G800="double_dot.cyc"]
N070 G00 X10 Y5 Z0.4
N080 G800 [0.3, 1.5]
N090 G00 X15 Y5 Z0.4
N100 G800 [0.3, 1.5]
N110 #FILE NAME [G800=""]
N120 G00 X20 Y5 Z0.4
N130 G800 [0.3, 1.5]
N140 M200=0
N150 G80
N160 M30
