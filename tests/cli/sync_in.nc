%sync_in
; #SYNC IN FEED_CONT_AUTO on a static unit: run-time error NC9060 at its line (docs/conveyor.md S-1), exit 1 (run on static_saw)
N10 G00 X0 Y0
N30 #SYNC IN [CONV_VEL 30 FEED_CONT_AUTO]
N40 G01 X10 F600
N50 #SYNC OUT
N60 M30
