; two_pickers, channel 1 (picker_up): the first of two delta robots along one belt. The line's
;   PLC keeps the measured value of every workpiece that passes this robot's sensor (X 0 of
;   its machine) and hands the oldest one out at each MC_TouchProbe; with it come
;   V.E.LINE_WORKPIECE (which one) and V.E.LINE_TRAVEL (how far it has moved past the
;   sensor, mm). One that has moved more than 120 mm would be met too far downstream: the
;   robot lets it go at once (#SYNC OUT before any motion) and the belt carries it to
;   channel 2. Each one taken is gripped in PCS1, lifted off and set down on the left tray.
;   V.E.LINE_MORE turns 0 when no workpiece can reach this robot any more: the loop ends.
%picker_up
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
N130    G01 X120 Y-160 Z-720 F350000
N140    G01 Z-770 F350000
N150    G01 Z-720 F350000
N160    G01 X-100 Y0 Z-700 F350000
$ENDIF
$ENDWHILE
N165 G01 X-100 Y0 Z-690 F350000
N170 #TRAFO OFF
N180 G01 X0 Y0 Z0 F20000
N190 M30
