%long_line
; one long line at F6000 on portal_3x: 700 mm / 100 mm/s + 100 / 3000 s of ramps + T (STEP)
; (inside the X soft limits -1 .. 800 mm, which the channel monitors every cycle)
N10 G01 X700 F6000
N20 M30
