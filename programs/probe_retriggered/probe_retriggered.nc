; probe_retriggered: a program that arms the touch probe for the next sheet too early: it
;   re-arms MC_TouchProbe at the top of the loop while the measurement it armed after #SYNC OUT
;   is still active (no front edge has passed yet): P-ERR-44009 (seed 004 §6.3.1, docs/conveyor.md
;   W13). The first sheet is cut; the golden keeps the error of the second pass.
%probe_retriggered
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 2, 1
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X-50 Y100 Z0
N60 G01 G91 X-100 F3000
N70 Y100
N80 X100
N90 Y-100
N100 #SYNC OUT
; wrong: "arm for the next sheet now" and again at N30
N110 S1 [MC_TouchProbe Channel=1]
N120 G00 G90 X0 Y0 Z0
$ENDFOR
N130 M30
