; laser_sorter, channel 1 (laser): conveyor_squares' three sheets on the CNC-driven belt, each
;   measured, caught up, cut with a 40 mm square while it moves and left again; after each
;   #SYNC OUT the laser tells the sorter (channel 2) that a part is cut: #SIGNAL SYN sends it
;   when the laser has left the part, not when the decoder reads the line (docs/lines.md).
%laser
N10 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 3, 1
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N50 G00 G90 X20 Y100 Z0
N60 G01 G91 X40 F3000
N70 Y40
N80 X-40
N90 Y-40
N100 #SYNC OUT
N110 #SIGNAL SYN [ID1 CH2]
N120 G00 G90 X0 Y0 Z0
$ENDFOR
N130 M30
