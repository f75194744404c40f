; pick_and_place: a delta robot (kinematic 37) picks every workpiece at the same place on the
;   moving workpiece and places it at the same MCS location, in an endless loop.
; source: TF5264 Conveyor Tracking (seed 004), section 4.9.2 "Programming example", listing
;   "Pick & place".
; repaired: the listing was extracted as one line; blocks and their comments split back into
;   one per line (PDF extraction)
; repaired: program name "%pick and place" -> "%pick_and_place" (underscores lost in
;   extraction, as in "FEED CONT")
%pick_and_place
N010 #KIN ID[37]
N020 G0 G90 X34.9485 Y-18.0290 Z34.0535
N020 #TRAFO ON
(- Start conveyor)
; repaired: "MC MoveVelocity" -> "MC_MoveVelocity" (PDF extraction)
N030 S1[MC_MoveVelocity Velocity=300000 (500000=30m/min) Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
; repaired: "\$WHILE" -> "$WHILE" (markdown escape in the extracted text)
N040 $WHILE [TRUE]
; Waiting position
N050 G01 X-100 Y0 Z-700 F350000
(- Request spindle measured value-)
; repaired: "MC TouchProbe" -> "MC_TouchProbe" (PDF extraction)
N060 S1 [MC_TouchProbe Channel=1]
(- Synchronise with the current workpiece -)
N070 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
(- Grip the workpiece -)
N075 G01 X-50 Y0 Z-700 F350000
N080 G01 X-50 Y0 Z-800 F350000
N090 G01 X-50 Y0 Z-750 F350000
(- Desynchronise and place the workpiece -)
; repaired: "FEED CONT" -> "FEED_CONT" (PDF extraction)
N100 #SYNC OUT [FEED_CONT=5]
(- Move to place location -)
; repaired: "INDP SYN" -> "INDP_SYN", three times (PDF extraction)
N110 X[INDP_SYN G1 G90 POS300 FEED350000 INTERRUPTIBLE] Y[INDP_SYN G1 G90 POS500 FEED350000 INTERRUPTIBLE] Z[INDP_SYN G1 G90 POS-750 FEED350000 INTERRUPTIBLE]
(- Place -)
N120 G01 Z-790 F350000
N130 G01 Z-800 F20000
N140 G01 Z-790 F350000
; repaired: "\$ENDWHILE" -> "$ENDWHILE" (markdown escape in the extracted text)
N150 $ENDWHILE
(-Program ended-)
N160 M30
