; synchro_lag_static: contour for measuring synchro_lag on a static processing unit; the
;   target points in Y coincide with those of the virtual X axis (synchro_lag in N080).
; source: TF5264 Conveyor Tracking (seed 004), section 4.5, listing "Static processing unit".
;   The listing is a fragment: it starts at N030 and has no header and no program end.
; repaired: the listing was extracted as one line; blocks and their comment lines split back
;   into one per line (PDF extraction)
N030 #CONTOUR MODE [DEV]
N040 G17 G161
; Request measurement from conveyor
N050 S1 [MC_TouchProbe Channel=1]
; Synchronise with conveyor
N060 #SYNC IN [CONVEYOR=S1, CONV_VEL=200 VEL_RESOLUTION=mm/s FEED_CONT=0]
N070 G0 G90 X50 Y0 F100
N070 G01 G90 X25 Y0 F100 G61
N070 G01 G90 X0 Y0 F100 G61
; Linear motion moves in Y in the same way as X moves
N080 G01 X-550 Y-550 G61
; End sequence
N090 #SYNC OUT [FEED_CONT=5]
; repaired: "INDP SYN" -> "INDP_SYN", twice (PDF extraction)
N100 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
; added: program end M30, missing from the fragment
M30
