; arm_picker, channel 2 (delta): a delta robot (kinematic 37) 900 mm further down the belt
;   (line.toml sensor_at) takes what the arm let pass: workpieces that came while the arm was
;   busy, and those it let go. A workpiece more than 120 mm past this robot's sensor is let go
;   too and leaves the belt at its end, counted missed. The belt runs at 200 mm/s here
;   (CONV_VEL 12000). It ends when V.E.LINE_MORE says that nothing can reach it any more.
%delta
N10 #KIN ID[37]
N20 G90 G01 X0 Y0 Z0 F20000
N30 #TRAFO ON
N40 G01 X-100 Y0 Z-700 F350000
$WHILE V.E.LINE_MORE == 1
N50   S1 [MC_TouchProbe Channel=1]
N60   #SYNC IN [CONVEYOR=S1, CONV_VEL=12000 FEED_CONT=0]
$IF V.E.LINE_TRAVEL > 120
N70     #SYNC OUT
$ELSE
N80     G01 X-40 Y0 Z-720 F350000
N90     G01 Z-785 F350000
N100    G04 0.04
N110    G01 Z-720 F350000
N120    #SYNC OUT
N130    G01 X60 Y150 Z-720 F350000
N140    G01 Z-770 F350000
N150    G01 Z-720 F350000
N160    G01 X-100 Y0 Z-700 F350000
$ENDIF
$ENDWHILE
N165 G01 X-100 Y0 Z-690 F350000
N170 #TRAFO OFF
N180 G01 X0 Y0 Z0 F20000
N190 M30
