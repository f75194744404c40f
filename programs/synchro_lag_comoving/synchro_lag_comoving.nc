; synchro_lag_comoving: on a co-moving processing unit the unit waits after synchronising in
;   X; synchro_lag is read in N090.
; source: TF5264 Conveyor Tracking (seed 004), section 4.5, listing "Co-moving processing
;   unit". The listing is a fragment: no header and no program end.
; repaired: the listing was extracted as one line; blocks and their comment lines split back
;   into one per line (PDF extraction)
; Waiting position
N040 G0 G90 X0 Y400 Z0
; Request spindle measured value
N050 S1 [MC_TouchProbe Channel=1]
; Synchronise with the belt
N060 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
N080 G0 G90 X0 Y450 Z160
N090 G04 2
N100 #SYNC OUT [FEED_CONT=5]
N110 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS400 INTERRUPTIBLE] Z[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
; added: program end M30, missing from the fragment
M30
