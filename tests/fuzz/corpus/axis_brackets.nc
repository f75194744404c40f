%axis_brackets
N10 S1[MC_MoveVelocity Velocity=300000 (500000=30m/min) Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 S1 [MC_TouchProbe Channel=1 Mode=2 Id=3 WaitSyn]
N30 S[MC_TouchProbe Channel=1]
N40 X[INDP_SYN G1 G90 POS300 FEED350000 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS-750 INTERRUPTIBLE]
N50 Z[INDP_ASYN G91 G01 FEED=100 POS=5 ACC_WEIGHT=50 INCL_OFFSETS]
N60 S1[MC_MoveAbsolute Position=100 Velocity=1000 \
     Acceleration=100]
N70 S1[MC_Stop Deceleration=100]
M30
