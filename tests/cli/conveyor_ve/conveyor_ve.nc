%conveyor_ve
; the V.E. value of the measured workpiece (its scenario table) is read after #SYNC IN: Y ends at 107
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 X0 Y100 Z0
N60 G01 Y[100 + V.E.PART] F3000
N70 #SYNC OUT
N80 M30
