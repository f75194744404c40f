; static_saw_fast: programs/static_saw (without its G74) with a belt too fast for the contour: the belt
;   at 750 mm/s (45 m/min) with CONV_VEL 45000 mm/min; the saw's C axis cannot turn fast
;   enough along the spline, so the static unit's "dynamic error" (seed 004 l.621) stops the
;   program before the contour starts: NC9100 at N160, where the spline section is complete
;   and its pieces are prepared (docs/conveyor.md "Static processing unit").
; source: TF5264 Conveyor Tracking (seed 004), section 4.10.2 "Programming example", listing
;   "Machining with static processing unit".
; repaired: the first line of the listing reads "2"; it is the program start "%" misread by
;   the extraction (the other listings start with "%") -> "%" (PDF extraction)
%
(- Home the axes )
; repaired: "N010 G74 Y1 C1" removed: ncsim does not run G74 homing in a program (NC6001, see
;   programs/static_saw); its axes start referenced, at the positions homing would give (0)
; repaired: comment text "convevor" -> "conveyor" (OCR)
(- Start conveyor )
; repaired: "MC MoveVelocity" -> "MC_MoveVelocity" (PDF extraction)
; changed: Velocity=100000 (100 mm/s) -> 750000 (750 mm/s)
N020 S1[MC_MoveVelocity Velocity=750000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N030 G0 G90 Y0 C0
(- Request spindle measured value)
; repaired: "MC TouchProbe" -> "MC_TouchProbe" (PDF extraction)
N040 S1 [MC_TouchProbe Channel=1]
(- Synchronise with conveyor )
; repaired: "FEED CONT" -> "FEED_CONT" (PDF extraction)
; changed: CONV_VEL=18000 -> 45000 (750 mm/s)
N050 #SYNC IN [CONVEYOR=S1, CONV_VEL=45000 FEED_CONT=0]
N060 G0 G90 X0 Y0 C0
(- Activate automatic tracking )
N070 #CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 180, ROTMODE=1]
(- Feed rate is ignored and corresponds to the conveying velocity )
N080 F100
N090 #SPLINE TYPE BSPLINE
N100 #SPLINE ON
(- Start of tangential movement )
N110 G1 G90 X-0 Y0
N120 G1 G90 X-50 Y0
N130 G1 G90 X-200 Y-30
N140 G1 G90 X-350 Y30
N150 G1 G90 X-550 Y0
(- End of tangential movement )
N160 G1 G90 X-600 Y0
N170 #SPLINE OFF
; repaired: "FEED CONT" -> "FEED_CONT" (PDF extraction)
N180 #SYNC OUT [FEED_CONT=5]
; repaired: "INDP SYN" -> "INDP_SYN", twice (PDF extraction)
N190 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
N200 #CAXTRACK OFF
N210 M30
