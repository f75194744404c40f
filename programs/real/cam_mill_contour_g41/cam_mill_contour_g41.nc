%O5005
(Written in the style of a CAM post with cutter compensation in the control: the outline of a)
(70 x 45 mm bracket with two 8 mm corner radii, cut outside with G41 and the tool's radius D1)
(from the machine's tool list, in vice 2 - G55 -, two depths, approach and exit on lines)
N10 G17 G90 G71 G94
N20 G55
N30 T1 D1 M06
N40 S9000 M03
N50 G00 X-15 Y-15 Z5
N60 G01 Z-3 F300
N70 G41 G01 X0 Y0 F1000
N80 G01 Y37
N90 G02 X8 Y45 I8 J0
N100 G01 X70
N110 G01 Y8
N120 G02 X62 Y0 I-8 J0
N130 G01 X0
N140 G40 G01 X-15 Y-15
N150 G01 Z-6 F300
N160 G41 G01 X0 Y0 F1000
N170 G01 Y37
N180 G02 X8 Y45 I8 J0
N190 G01 X70
N200 G01 Y8
N210 G02 X62 Y0 I-8 J0
N220 G01 X0
N230 G40 G01 X-15 Y-15
N240 G00 Z25
N250 M05
N260 G53 G00 Z120 (machine Z that leaves room for the tool length of D1)
N270 M30
