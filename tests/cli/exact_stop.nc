%exact_stop
; G60 waits until the actual position is inside the exact-stop window P-AXIS-00236
N10 G60 G01 X100 F6000
N20 G01 X200
N30 M30
