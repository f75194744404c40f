%BEAD_FRAME
; Written in the style of a dispenser's job file: a glue bead around a 40 x 25 mm frame with
; rounded corners on the bed (G54), started and stopped by the builder's cycles, the bead
; speed changed on the corners, and a second, inner bead.
G17 G90 G71 G94
G54
G80
G00 X5 Y0 Z1
G01 Z0.3 F600
G801 [1400]
G01 X35 F900
G03 X40 Y5 I0 J5 F600
G01 Y20 F900
G03 X35 Y25 I-5 J0 F600
G01 X5 F900
G03 X0 Y20 I0 J-5 F600
G01 Y5 F900
G03 X5 Y0 I5 J0 F600
G802 [1.5]
G00 X10 Y5 Z1
G01 Z0.3 F600
G801 [1200]
G01 X30 F900
G01 Y20
G01 X10
G01 Y5
G802 [1.5]
G80
M30
