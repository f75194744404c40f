; arm6_pick: a 6-axis articulated robot (kinematic 45) picks workpieces from the moving belt
;   beside it and sets each one down, turned by 90 degrees, on a tray on the other side of its
;   base. ncsim's own program (issue 37).
; arm6_belt (docs/machines.md "Kinematic 45"): joints 1..6 are the axes X, Y, Z, A, B, C; the
;   belt runs along MCS +X 700 mm beside the base (PCS0 at Y 700), its surface at Z 0.
; Before #TRAFO ON the joints are moved to the start pose (joint 5 at 90 deg: the tool points
;   down); under #TRAFO ON X, Y, Z are the TCP and A, B, C the tool orientation (A0 B0: the
;   tool vertical, C its turn about the vertical). Each workpiece: the probe, #SYNC IN, the
;   grip in PCS1 (the workpiece's front edge at X 0, its middle 50 mm behind), #SYNC OUT and
;   the move to the tray in MCS; the part is turned by C90 while it is set down, the tool
;   turned back while it rises. The turn is not in the departure (N150): there the TCP's
;   dynamics are derived from the joints for X, Y, Z only (docs/machines.md "Kinematic 45").
; The feed F120000 (2 m/s) is above what the joints allow in most of the moves: their own v, a,
;   j set the pace (docs/planner.md "Kinematics").
%arm6_pick
N10 #KIN ID[45]
N20 G90 G01 X0 Y0 Z0 A0 B90 C0 F20000
N30 #TRAFO ON
N40 G01 X-100 Y700 Z200 A0 B0 C0 F120000
N50 S1[MC_MoveVelocity Velocity=200000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N60 $WHILE [TRUE]
N70   G01 X-150 Y700 Z200 C0 F120000
N80   S1 [MC_TouchProbe Channel=1]
N90   #SYNC IN [CONVEYOR=S1, CONV_VEL=12000 FEED_CONT=0]
N100  G01 X-50 Y0 Z80 F120000
N110  G01 Z25 F30000
N120  G04 0.05
N130  G01 Z120 F60000
N140  #SYNC OUT
N150  G01 X650 Y-250 Z150 F120000
N160  G01 Z40 C90 F30000
N170  G04 0.03
N180  G01 Z150 C0 F60000
N190 $ENDWHILE
N200 M30
