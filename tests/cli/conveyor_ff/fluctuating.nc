; fluctuating: synchro_lag_comoving's co-moving unit (seed 004 4.5 l.757-763) held in PCS1 for
;   4 s on an encoder belt fluctuating +-5 % at 1 Hz, the filters off and the delay time
;   P-AXIS-00626 = the dead time (17455 us): the manual's "right delay time" (l.747), so that
;   synchro_lag shows the delay-time compensation's residual (l.745) and the axes' following
;   error (tests/cli/conveyor_ff_test.sh, docs/conveyor.md "The velocity feed-forward").
N010 G0 G90 X0 Y400 Z0
N020 #MACHINE DATA [AX=S P-AXIS-00620=0 P-AXIS-00626=17455]
N030 S1 [MC_TouchProbe Channel=1]
N040 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
N050 G0 G90 X0 Y450 Z160
N060 G04 4
N070 #SYNC OUT [FEED_CONT=5]
N080 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS400 INTERRUPTIBLE] Z[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
M30
