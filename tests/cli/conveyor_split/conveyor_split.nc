%conveyor_split
; the PCS1 velocity split (docs/conveyor.md S-5): F = X's v_max (1000 mm/s) in +X and -X on the
; moving workpiece, belt 300 mm/s: X stays within its v_max (the block runs at 670 mm/s relative)
N10 S1[MC_MoveVelocity Velocity=300000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
N50 G00 X0 Y100 Z0
N60 G01 X600 F60000
N70 G01 X0
N80 #SYNC OUT [FEED_CONT=5]
N90 G00 X0 Y0 Z0
N100 M30
