; two_pickers, channel 2 (picker_down): the second delta robot, its sensor 700 mm further
;   down the belt (line.toml sensor_at). It sees only what channel 1 did not take: workpieces
;   that passed channel 1 while it was busy, and those it let go. Its rule is the same (a
;   workpiece more than 120 mm past this robot's sensor is let go, and leaves the belt at
;   its end, counted missed); it sets its parts down on the right tray, nearer to its wait.
;   It ends when V.E.LINE_MORE says that nothing can reach it any more.
%picker_down
N10 #KIN ID[37]
N20 G90 G01 X0 Y0 Z0 F20000
N30 #TRAFO ON
N40 G01 X-100 Y0 Z-700 F350000
$WHILE V.E.LINE_MORE == 1
N50   S1 [MC_TouchProbe Channel=1]
N60   #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
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
