; error_while_synchronised: an error while the laser is synchronised keeps the synchronisation
;   (seed 004 §2.3): the belt (300 mm/s) carries the slowly cut sheet out of the conveyor
;   workspace in the conveying direction (X 3000 mm, P-CHAN-00859) at N70: NC9052. The path
;   velocity in PCS1 goes to 0, the machine moves on with the belt and stops before X's soft
;   limit 4000 mm (P-AXIS-00178); the run then ends with NC9052 at N70 and its time, the CSV
;   holding the motion after the error (docs/conveyor.md "Errors while synchronised").
%error_while_synchronised
N10 S1[MC_MoveVelocity Velocity=300000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
N50 G00 G90 X-50 Y100 Z0
N60 G01 G91 X-100 F600
N70 Y300
N80 X100
N90 Y-300
N100 #SYNC OUT
N110 G00 G90 X0 Y0 Z0
N120 M30
