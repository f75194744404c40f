%O6006
(Written in the style of a CAM post with compensation in the control: a 60 x 16 mm closed)
(slot with round ends, finished clockwise - conventional - with G42 and D3 - 10 mm end mill -)
(in vice 1 - G54 -, plunged at the slot centre line, two depths)
N10 G17 G90 G71 G94
N20 G54
N30 T3 D3 M06
N40 S7000 M03
N50 G00 X30 Y0 Z5
N60 G01 Z-2 F250
N70 G42 G01 X30 Y8 F900
N80 G01 X52
N90 G02 X52 Y-8 I0 J-8
N100 G01 X8
N110 G02 X8 Y8 I0 J8
N120 G01 X30
N130 G40 G01 X30 Y0
N140 G01 Z-4 F250
N150 G42 G01 X30 Y8 F900
N160 G01 X52
N170 G02 X52 Y-8 I0 J-8
N180 G01 X8
N190 G02 X8 Y8 I0 J8
N200 G01 X30
N210 G40 G01 X30 Y0
N220 G00 Z25
N230 M05
N240 G53 G00 Z120 (machine Z that leaves room for the tool length of D3)
N250 M30
