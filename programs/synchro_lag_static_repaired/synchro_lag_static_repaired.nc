; synchro_lag_static_repaired: programs/synchro_lag_static made to run through with the
;   virtual X still: the 45 deg joint at X0 Y0 gets a 30 mm tolerance ball instead of the
;   default 1 mm, and the approach in front of it is three times as long so the ball fits.
; source: TF5264 Conveyor Tracking (seed 004), section 4.5, listing "Static processing unit".
;   The listing is a fragment: it starts at N030 and has no header and no program end.
; repaired: the listing was extracted as one line; blocks and their comment lines split back
;   into one per line (PDF extraction)
; repaired: "[DEV]" -> "[DEV PATH_DEV=30]". As printed (programs/synchro_lag_static) the run
;   ends with NC9100 at the X0 Y0 block: with the belt feed (1.1 x 200 = 220 mm/s in X) Y must
;   go from 0 to 220 mm/s inside the ball. In the 1 mm ball the path crosses about 1.7 mm of X
;   (1 mm before the corner, 0.71 after), i.e. 7.8 ms: a mean Y acceleration of 28000 mm/s^2
;   and, with a triangular acceleration, a jerk of 4 x 220 / 0.0078^2 = 1.5e7 mm/s^3, where
;   Y's list (machines/static_saw_encoder/y.lis) allows 10000 mm/s^2 and 200000 mm/s^3. Even
;   the ideal jerk-limited change takes 2 x sqrt(220 / 200000) = 66 ms, 14.6 mm of X: no ball
;   under 8.6 mm can work. The planner's ball is jerk-bound, its velocity grows as r^(2/3)
;   (33.4 mm/s at 1 mm, 285.4 at 25 mm); 311 mm/s (220 / cos 45) needs r >= 28.5 mm (NC9100 at
;   28 mm, runs from 29 mm). 30 mm: the next round value, 322 mm/s in the ball, 3.6 % margin.
N030 #CONTOUR MODE [DEV PATH_DEV=30]
N040 G17 G161
; Request measurement from conveyor
N050 S1 [MC_TouchProbe Channel=1]
; Synchronise with conveyor
N060 #SYNC IN [CONVEYOR=S1, CONV_VEL=200 VEL_RESOLUTION=mm/s FEED_CONT=0]
; changed: "X50" -> "X150" here and "X25" -> "X75" in the next block: a ball takes at most
;   half of a neighbouring block, so the 30 mm ball needs 60 mm of the block ending at X0 (25 mm
;   as printed); the path, started at rest after the catch-up, is at the belt's velocity 40 ms
;   later, near X146, long before the ball begins at X30
N070 G0 G90 X150 Y0 F100
N070 G01 G90 X75 Y0 F100 G61
N070 G01 G90 X0 Y0 F100 G61
; Linear motion moves in Y in the same way as X moves
N080 G01 X-550 Y-550 G61
; End sequence
N090 #SYNC OUT [FEED_CONT=5]
; repaired: "INDP SYN" -> "INDP_SYN", twice (PDF extraction)
N100 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
; added: program end M30, missing from the fragment
M30
