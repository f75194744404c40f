; conveyor_cycle: ncsim's own conveyor program: three workpieces, each measured, synchronised,
;   machined in a rotated coordinate system on the moving workpiece (a rectangle with a
;   rounded corner), desynchronised, and the axes parked with asynchronous independent moves.
; Conveyor 0.1 m/s (MC_MoveVelocity in um/s) = 6 m/min, so CONV_VEL=6 with VEL_RESOLUTION=m/min
;   (TF5264 section 3, #SYNC IN syntax); #CS only between the synchronisation movement and
;   #SYNC OUT (TF5264 section 2, restrictions).
%conveyor_cycle
N010 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 \
        Direction=1]
N020 G0 G90 X0 Y400 Z0
N030 $FOR P1 = 1, 3, 1
N040   S1 [MC_TouchProbe Channel=1]
N050   #SYNC IN [CONVEYOR=S1, CONV_VEL=6 VEL_RESOLUTION=m/min FEED_CONT=0]
N060   G01 X0 Y450 Z20 F20000               ; synchronisation movement
N070   #CS ON [1] [0, 450, 0, 0, 0, 15]
N080   G01 X0 Y0 F10000
N090   G01 X40 Y0
N100   G03 X40 Y40 I0 J20                   ; half circle, centre X40 Y20
N110   G01 X0 Y40
N120   G01 X0 Y0
N130   #CS OFF
N140   #SYNC OUT [FEED_CONT=5]
N150   X[INDP_ASYN G0 G90 POS0] Y[INDP_ASYN G0 G90 POS400]
N160   Z[INDP_SYN G1 G90 POS0 FEED20000]
N170   #WAIT INDP ALL
N180 $ENDFOR
N190 M30
