% 1x10 dots right
( Written in the style of a bioprinter's export: a row of ten dots, 2.5 mm pitch, )
( the machine builder's dot cycle G800 [dwell s, lift mm], pressure as M200=<0.1 kPa> )
N10 G17 G90 G71 G94
N20 G54                       ( the print bed )
N30 G80                       ( Z to its safe height, in machine coordinates )
N40 M200=1200                 ( 120.0 kPa )
N50 G00 X0 Y0
N60 G00 Z0.4
N70 G800 [0.35, 2.0]
N80 G00 X2.5 Z0.4
N90 G800 [0.35, 2.0]
N100 G00 X5 Z0.4
N110 G800 [0.35, 2.0]
N120 G00 X7.5 Z0.4
N130 G800 [0.35, 2.0]
N140 G00 X10 Z0.4
N150 G800 [0.35, 2.0]
N160 G00 X12.5 Z0.4
N170 G800 [0.35, 2.0]
N180 G00 X15 Z0.4
N190 G800 [0.35, 2.0]
N200 G00 X17.5 Z0.4
N210 G800 [0.35, 2.0]
N220 G00 X20 Z0.4
N230 G800 [0.35, 2.0]
N240 G00 X22.5 Z0.4
N250 G800 [0.35, 2.0]
N260 M200=0
N270 G80
N280 M30
