%sync
S1[MC_MoveVelocity Velocity=20000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
G0 G90 X0 Y400 Z0
S1 [MC_TouchProbe Channel=1]
#SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
G01 X10 F1000
G02 X20 Y400 R5
#SYNC OUT
M30
