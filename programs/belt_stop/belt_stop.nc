; belt_stop: the belt stops and restarts while a sheet is cut: the PLC side stops the CNC-driven
;   belt (MC_MoveVelocity Velocity=0 between two blocks), the cut goes on on the standing sheet,
;   the belt restarts; the machine (X) slows, stands and restarts with it, the contour on the
;   sheet (PCS1) is unchanged (seed 004 §2.3; docs/conveyor.md).
%belt_stop
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X-50 Y100 Z0
N60 G01 G91 X-200 F3000
; the belt stops while Y is cut (500 mm/s^2, 50000 mm/s^3: 0.21 s; the belt's jerk goes into
; X unchanged, so it stays below X's own jerk limit)
N70 S1[MC_MoveVelocity Velocity=0 Acceleration=500 Deceleration=500 Jerk=50000 Direction=1]
N80 Y200
; X is cut back on the standing sheet, then the belt restarts while Y is cut
N90 X200
N100 S1[MC_MoveVelocity Velocity=100000 Acceleration=500 Deceleration=500 Jerk=50000 Direction=1]
N110 Y-200
N120 #SYNC OUT
N130 G00 G90 X0 Y0 Z0
N140 M30
