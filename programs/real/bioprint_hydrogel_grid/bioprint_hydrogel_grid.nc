% hydrogel grid 15x15 2 layers
( Written in the style of a bioprinter's export for a hydrogel grid: meandering strands in X, )
( then in Y, each layer a single bead from the start cycle to the stop cycle, the feed in the )
( exporter's mm/min, the pressure raised for the second layer. )
N10 G17 G90 G71 G94
N20 G54
N30 G80
N40 G00 X0 Y0 Z1.2
N50 G01 Z0.2 F400
N60 G801 [1250]
N70 G01 X15 F600
N80 G01 Y3
N90 G01 X0
N100 G01 Y6
N110 G01 X15
N120 G01 Y9
N130 G01 X0
N140 G01 Y12
N150 G01 X15
N160 G01 Y15
N170 G01 X0
N180 G802 [1.0]
N190 G00 X0 Y0 Z1.5
N200 G01 Z0.45 F400
N210 G801 [1330]
N220 G01 Y15 F600
N230 G01 X3
N240 G01 Y0
N250 G01 X6
N260 G01 Y15
N270 G01 X9
N280 G01 Y0
N290 G01 X12
N300 G01 Y15
N310 G01 X15
N320 G01 Y0
N330 G802 [1.0]
N340 M200=0
N350 G80
N360 M30
