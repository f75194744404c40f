%dot
; G800 [dwell s, lift mm]: one dot at the current position (the machine builder's cycle)
M61                     ; valve open
G04 [@P1]
M62                     ; valve closed
G91 G00 Z[@P2]
G90
M17
