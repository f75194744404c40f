%bead_start
; G801 [pressure 0.1 kPa]: set the pressure, open the valve, wait for the bead to form
M200=[@P1]
M61
G04 0.2
M17
