%sync_in
; #SYNC IN is not executed by the channel yet: not supported at run time, exit 1 (run on laser_portal)
N10 G00 X0 Y0
N30 #SYNC IN [CONV_VEL 30]
N40 G01 X10 F600
N50 #SYNC OUT
N60 M30
