; delta_pick: a delta robot (kinematic 37) picks six parts from a fixed 2 x 3 tray and places
;   them side by side on a fixed place station: no conveyor. Approach, grip and place heights
;   are Cartesian TCP values under #TRAFO ON; the drives start and end at their zero angles by
;   axis moves before #TRAFO ON and after #TRAFO OFF.
; delta_picker (TF5264 geometry, docs/machines.md "Kinematic 37"); TCP X -150..150 mm,
;   Y -100..100 mm, Z -700..-800 mm, the range of the seed's pick & place example.
; The feed F350000 (5.8 m/s) is the seed's: far above what the drives allow, so the drives'
;   own limits (720 deg/s, 20000 deg/s^2) set the pace (docs/planner.md "Kinematics").
%L PICK
; grip at (P31, P32) from the approach height: down, dwell for the vacuum, up
G01 X[P31] Y[P32] Z-720 F350000
G01 Z-790 F60000
G04 0.05
G01 Z-720 F60000
M17

%L PLACE
; place at (P33, P34): down, release, up
G01 X[P33] Y[P34] Z-720 F350000
G01 Z-780 F60000
G04 0.03
G01 Z-720 F60000
M17

%delta_pick
N10 #KIN ID[37]
N20 G90 G01 X0 Y0 Z0 F20000
N30 #TRAFO ON
N40 #SLOPE [TYPE=TRAPEZ]
N50 G01 X0 Y0 Z-720 F350000
N60 P1 = 0
N70 $WHILE P1 < 6
N80   P31 = -150 + 60 * [P1 - 3 * INT[P1 / 3]]
N90   P32 = -60 + 40 * INT[P1 / 3]
N100  LL PICK
N110  P33 = 100 + 10 * P1
N120  P34 = 60
N130  LL PLACE
N140  P1 = P1 + 1
N150 $ENDWHILE
N160 G01 X0 Y0 Z-720 F350000
N170 #TRAFO OFF
N180 G01 X0 Y0 Z0 F20000
N190 M30
