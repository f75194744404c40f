; arm_picker, channel 1 (arm): a 6-axis articulated robot (kinematic 45, machines/arm6_belt)
;   beside the belt. The line's PLC keeps the measured value of every workpiece that passes
;   the arm's sensor (X 0 of its machine) and hands the oldest one out at each MC_TouchProbe,
;   with V.E.LINE_TRAVEL (how far it has moved past the sensor, mm). One that has moved more
;   than 250 mm would be met too far downstream: the arm lets it go (#SYNC OUT before any
;   motion) and the belt carries it to its end, counted missed. Each one taken is gripped in
;   PCS1 with the tool vertical (A0 B0), lifted, and set down on the tray on the other side,
;   turned by 90 degrees while it goes down (C90; not in the departure N130, as in
;   programs/arm6_pick). V.E.LINE_MORE turns 0 when no workpiece can reach the arm any more:
;   the loop ends, the arm moves up off the belt and the joints return to their start pose.
%arm
N10 #KIN ID[45]
N20 G90 G01 X0 Y0 Z0 A0 B90 C0 F20000
N30 #TRAFO ON
N40 G01 X-150 Y700 Z200 A0 B0 C0 F120000
$WHILE V.E.LINE_MORE == 1
N50   S1 [MC_TouchProbe Channel=1]
N60   #SYNC IN [CONVEYOR=S1, CONV_VEL=12000 FEED_CONT=0]
$IF V.E.LINE_TRAVEL > 250
N70     #SYNC OUT
$ELSE
N80     G01 X-50 Y0 Z80 F120000
N90     G01 Z25 F30000
N100    G04 0.05
N110    G01 Z120 F60000
N120    #SYNC OUT
N130    G01 X650 Y-250 Z150 F120000
N140    G01 Z40 C90 F30000
N150    G04 0.03
N160    G01 Z150 C0 F60000
N170    G01 X-150 Y700 Z200 C0 F120000
$ENDIF
$ENDWHILE
N175 G01 X-150 Y700 Z250 F120000
N180 #TRAFO OFF
N190 G01 X0 Y0 Z0 A0 B90 C0 F20000
N200 M30
