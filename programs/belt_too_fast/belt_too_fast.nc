; belt_too_fast: the belt speeds up while a sheet is cut: the program was written for 100 mm/s
;   (CONV_VEL=6000 mm/min), the PLC side raises the belt to 150 mm/s between two blocks, and
;   once the filtered belt velocity exceeds 1.10 x CONV_VEL the kernel aborts with 50653
;   (seed 004 l.514; docs/conveyor.md "Errors"). The golden keeps that error.
%belt_too_fast
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X-50 Y100 Z0
N60 G01 G91 X-100 F3000
N70 Y100
; the belt is set faster than CONV_VEL allows
N80 S1[MC_MoveVelocity Velocity=150000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N90 X100
N100 Y-100
N110 #SYNC OUT
N120 G00 G90 X0 Y0 Z0
N130 M30
