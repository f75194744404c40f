; line_late: a channel that arms its probe only after a 2 s dwell. The workpiece's front edge
;   reaches the sensor after 100 mm of belt travel; at the hand-over (t = 2 s) it has travelled
;   v x 2 s - 100 mm past it. More than 200 mm and the program lets it go (missed at the belt's
;   end): so the line runs clean up to v = 150 mm/s and misses the workpiece above, by
;   construction (line sweep's test, tests/cli/production_line_test.sh).
%late
N10 G04 2
N20 S[MC_TouchProbe Channel=1]
N30 #SYNC IN [CONVEYOR=S, CONV_VEL=6000 FEED_CONT=0]
$IF V.E.LINE_TRAVEL > 200
N40 #SYNC OUT
$ELSE
N50 G01 G90 X20 Y100 Z0 F3000
N60 #SYNC OUT
$ENDIF
N70 M30
