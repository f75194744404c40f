%O4004
(Written in the style of a CAM post for facing: a 120 x 60 mm face in vice 1 - G54 - with a)
(D50 face mill in zigzag passes of 40 mm stepover, two depths, the post's own incremental)
(stepover moves and a final lift to the machine's tool change height with G53)
N10 G17 G90 G71 G94
N20 G54
N30 T20 M06
N40 S2400 M03 M08
N50 G00 X-30 Y0 Z5
N60 G01 Z-0.5 F400
N70 G01 X150 F1500
N80 G91 G01 Y40
N90 G90 G01 X-30
N100 G91 G01 Y40
N110 G90 G01 X150
N120 G00 Z5
N130 G00 X-30 Y0
N140 G01 Z-1.0 F400
N150 G01 X150 F1500
N160 G91 G01 Y40
N170 G90 G01 X-30
N180 G91 G01 Y40
N190 G90 G01 X150
N200 G00 Z5
N210 M09 M05
N220 G53 G00 Z180
N230 M30
