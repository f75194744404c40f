%cut_off
; G82: beam off, head to 10 mm above the sheet
M09                 ; beam off
G00 Z10
M17
