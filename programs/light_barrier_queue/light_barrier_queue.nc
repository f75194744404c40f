; light_barrier_queue: workpieces arrive faster than they are machined: 200 mm parts every
;   250 mm of travel on a 100 mm/s belt (one every 2.5 s) while a part takes about 6 s. With
;   measuring method 3 (P-AXIS-00516 PLC_EXT_LATCH_CONTROL) the PLC keeps every front edge in
;   its queue and each MC_TouchProbe hands out the oldest (seed 004 §4.3; docs/conveyor.md W11,
;   W12): every part is machined, each further downstream than the one before.
%light_barrier_queue
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 6, 1
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X-30 Y100 Z0
N60 G01 G91 X-140 F6000
N70 Y100
N80 X140
N90 Y-100
N100 #SYNC OUT
N110 G00 G90 X0 Y0 Z0
$ENDFOR
N120 M30
