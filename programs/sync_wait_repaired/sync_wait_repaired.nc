; sync_wait_repaired: programs/sync_wait made to run as its manual meant: synchronised with
;   the 300 mm/s belt its own MC_MoveVelocity starts, a 10 s wait on the moving workpiece, X
;   parked at 5 m/min after #SYNC OUT.
; source: TF5264 Conveyor Tracking (seed 004), section 4.5 "Synchronising the workpiece on
;   the linear conveyor", listing "Synchronising the workpiece and waiting time on the linear
;   conveyor". The listing is a fragment without a program header; the header is optional
;   (isg-language.md 1.2) and is left out as in the manual.
N0030 G00 G90 X0 Y0 Z0
(- Start conveyor, only required if CNC controls the conveyor )
; repaired: the N030 block was broken across two lines before "Jerk=750000"; joined back
;   into one block (PDF extraction)
N030 S1[MC_MoveVelocity Velocity=300000 (500000=30m/min) Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N0040 S1 [MC_TouchProbe Channel=1] ;Read measured value
; repaired: "CONV_VEL 30" -> "CONV_VEL 18000": CONV_VEL is in mm/min (004 l.513), and 30 mm/min
;   against the 300 mm/s belt of N030 is 50653 (programs/sync_wait); 18000 mm/min = 300 mm/s as
;   in the pick & place listing
N0050 #SYNC IN [CONV_VEL 18000] ;Select synchronisation
N0060 G0 X0 Y0 ;Position on moving workpiece
N0070 G04 10 ;Waiting time instead of machining
N0130 #SYNC OUT [FEED_CONT=5] ;Select desynchronisation
; repaired: "FEED5" -> "FEED5000": FEED is in mm/min; 5 mm/min parks X (3 m away after the wait
;   on the moving belt) in about ten hours, so the listing's 5 is read as m/min
N0140 X[INDP_SYN G1 POS0 FEED5000 INTERRUPTIBLE] ;Position in the MCS
N0160 M30
