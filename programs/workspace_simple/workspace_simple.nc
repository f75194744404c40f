; workspace_simple: a laser cut against the conveying direction into the workspace limit,
;   simple hold method (P-AXIS-00555 = 0 on X, machine laser_portal_simple): each block whose
;   contour would pass the hold line pos_limit -190 mm runs at 0.95 x v_conv from its start,
;   so the tool drifts with the belt at 5 % of its velocity and never reaches the line
;   (docs/conveyor.md "Workspace: the hold methods").
%workspace_simple
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X0 Y300 Z0
N60 G01 G91 X-600 F12000
N70 G02 X-300 Y0 I-150 J0
N80 #SYNC OUT
N90 G00 G90 X0 Y0 Z0
N100 M30
