%sync_in
; #SYNC IN FEED_CONT_AUTO: not supported at run time (the manual gives no formula), exit 1 (run on laser_portal)
N10 G00 X0 Y0
N30 #SYNC IN [CONV_VEL 30 FEED_CONT_AUTO]
N40 G01 X10 F600
N50 #SYNC OUT
N60 M30
