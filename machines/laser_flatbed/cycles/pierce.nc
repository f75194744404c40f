%pierce
; G81 [time s, height mm]: lower to the pierce height, beam on, pierce, down to cutting height
G01 Z[@P2] F3000
M07                 ; beam on
G04 [@P1]
G01 Z1 F3000        ; cutting height 1 mm above the sheet
M17
