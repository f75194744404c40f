%O7007
(Written in the style of a CAM post that enters a round pocket on a helix: a 30 mm bore in)
(vice 2 - G55 -, helical ramp of 3 turns down to 6 mm with G03 and Z, a finishing circle,)
(the centre at X40 Y25, D1 8 mm end mill without compensation - the post's own offsets)
N10 G17 G90 G71 G94
N20 G55
N30 T1 M06
N40 S9500 M03
N50 G00 X51 Y25 Z3
N60 G01 Z0 F300
N70 G03 X51 Y25 Z-2 I-11 J0 F700
N80 G03 X51 Y25 Z-4 I-11 J0
N90 G03 X51 Y25 Z-6 I-11 J0
N100 G03 X51 Y25 I-11 J0 F900
N110 G01 X40 Y25 F900
N120 G00 Z25
N130 M05
N140 G53 G00 Z180
N150 M30
