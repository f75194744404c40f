; sync_feed_cont: a laser cut entered on the fly (docs/conveyor.md S-1): three sheets on the
;   CNC-driven belt (0.1 m/s); each catch-up meets its sheet moving at FEED_CONT = 3000 mm/min
;   (50 mm/s relative, reduced as required to what the first edge's corner allows) and the
;   square is cut at F3000 from there without stopping on the sheet.
%sync_feed_cont
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 3, 1
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=3000]
N50 G01 G90 X5 Y100 Z0 F3000
N60 G91 Y40
N70 X40
N80 Y-40
N90 X-40
N100 #SYNC OUT
N110 G00 G90 X0 Y0 Z0
$ENDFOR
N120 M30
