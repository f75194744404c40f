; laser_repaired: programs/laser made to stay inside its workspace: 20 squares instead of 25
;   and the cut-out 2100 mm long instead of 2600, so Y stays below its 2500 mm soft limit.
; source: TF5264 Conveyor Tracking (seed 004), section 4.8.2 "Programming example", listing
;   "Laser machining on moving sheet / Linear conveyor CNC controlled".
% laser
; Start conveyor
; repaired: "MC MoveVelocity" -> "MC_MoveVelocity" (PDF extraction)
N010 S1[MC_MoveVelocity Velocity=20000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
; Waiting position
N020 G0 G90 X0 Y400 Z0
; Request spindle measured value
; repaired: "MC TouchProbe" -> "MC_TouchProbe" (PDF extraction)
N030 S1 [MC_TouchProbe Channel=1]
; Synchronise
N040 #SYNC IN [CONVEYOR=S1, CONV_VEL=6000 FEED_CONT=0]
N050 G0 G90 X0 Y450 Z160
; repaired: "FOR P2 = 0, 24, 1" -> "$FOR P2 = 0, 24, 1": the "$" was lost in extraction (the
;   German edition of the manual and the closing "$ENDFOR" have it)
; repaired: "0, 24" -> "0, 19": pass P2 = 20 would take Y to 2550 mm at N130, beyond the
;   Y soft limit 2500 mm, the side face of the workspace (NC9053, programs/laser)
$FOR P2 = 0, 19, 1
; Switch on laser
N060 M50
; Plunge
N70 G01 G91 G261 X0 Y0 Z20 F10000
N80 G01 G91 X0 Y-50 Z0
N90 G01 G91 X-50 Y0 Z0
N100 G01 G91 X0 Y50 Z0
N110 G01 G91 X50 Y0 Z0
; Switch off laser
N120 M51
N130 G00 G91 G260 X0 Y100 Z-20
$ENDFOR
; Cut out
N140 G0 G90 X-100 Y350
N150 M50
N160 G01 G91 X150 F100000
; repaired: "Y2600" -> "Y2100" here and at N190: from Y350, 2600 reaches Y2950 > 2500 mm
N170 G01 G91 Y2100
N180 G01 G91 X-150
N190 G01 G91 Y-2100
N200 M51
; repaired: "FEED CONT" -> "FEED_CONT" (PDF extraction)
N210 #SYNC OUT [FEED_CONT=5]
; repaired: N220 was broken across two lines before "POSO"; joined back into one block; "INDP
;   SYN" -> "INDP_SYN" (three times), "POSO" -> "POS0" (letter O for digit 0) and
;   "INTER-RUPTIBLE" -> "INTERRUPTIBLE" (hyphenation) (PDF extraction)
N220 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS400 INTERRUPTIBLE] Z[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
; Program end
N230 M30
