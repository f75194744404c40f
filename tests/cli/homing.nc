; G74 (docs/homing.md): X then Y home to P-AXIS-00152 (0 on portal_3x) at P-AXIS-00219
; (default 83.333 mm/s); the path goes on from there.
%homing
N10 G01 X100 Y50 F6000
N20 G74 X1 Y2
N30 G01 X10 F6000
N40 M30
