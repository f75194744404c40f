%long_line
; one long line at F6000 on portal_3x: 1000 mm / 100 mm/s + 100 / 3000 s of ramps + T (STEP)
N10 G01 X1000 F6000
N20 M30
