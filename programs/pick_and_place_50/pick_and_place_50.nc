; pick_and_place_50: seed 004 §4.9.2 "Pick & place" (programs/pick_and_place) repaired so that
;   it runs: 50 workpieces picked from the moving belt in the listing's `$WHILE [TRUE]` loop;
;   the folder's scenario.toml ends the run after the 50th pass of the loop (stop.passes).
; repaired: machine delta_picker_belt: the conveyor workspace's lower Z face -900 mm instead
;   of the listing's -500 mm, which does not hold the working height Z -700 .. -800
; repaired: N100 `#SYNC OUT [FEED_CONT=5]` -> `#SYNC OUT`: the departure ends at rest (5 mm/min
;   is 0.08 mm/s, at rest in all but name; FEED_CONT > 0 on #SYNC OUT is not built yet)
; repaired: N110 `X[INDP_SYN ... POS300] Y[... POS500] Z[... POS-750]` -> `G01 X300 Y500
;   Z-750`: under #TRAFO ON X, Y, Z are the TCP; INDP axis commands would move the drives
;   (POS300 = 300 degrees, beyond their +-180 degree limits)
%pick_and_place_50
N010 #KIN ID[37]
N020 G0 G90 X34.9485 Y-18.0290 Z34.0535
N020 #TRAFO ON
(- Start conveyor)
N030 S1[MC_MoveVelocity Velocity=300000 (500000=30m/min) Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N040 $WHILE [TRUE]
; Waiting position
N050 G01 X-100 Y0 Z-700 F350000
(- Request spindle measured value-)
N060 S1 [MC_TouchProbe Channel=1]
(- Synchronise with the current workpiece -)
N070 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
(- Grip the workpiece -)
N075 G01 X-50 Y0 Z-700 F350000
N080 G01 X-50 Y0 Z-800 F350000
N090 G01 X-50 Y0 Z-750 F350000
(- Desynchronise and place the workpiece -)
N100 #SYNC OUT
(- Move to place location -)
N110 G01 X300 Y500 Z-750 F350000
(- Place -)
N120 G01 Z-790 F350000
N130 G01 Z-800 F20000
N140 G01 Z-790 F350000
N150 $ENDWHILE
(-Program ended-)
N160 M30
