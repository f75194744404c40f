; workspace_optimised: a laser cut against the conveying direction into the workspace limit,
;   optimised hold method (P-AXIS-00555 = 1 on X, the laser portal's list): the -X cut runs at
;   its feed until the braking that reaches 0.95 x v_conv at the hold line pos_limit -190 mm;
;   the tool then drifts away at 5 % of the belt; the arc after it is pushed away
;   (docs/conveyor.md "Workspace: the hold methods").
%workspace_optimised
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
