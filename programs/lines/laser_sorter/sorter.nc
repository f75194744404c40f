; laser_sorter, channel 2 (sorter): a gantry downstream of the laser; for each part the laser
;   signals (#WAIT SYN [ID1 CH1]: the path stands until the signal of channel 1 comes), it
;   picks the part (down, 0.2 s grip, up) and drops it on the out-feed, then returns.
%sorter
N10 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 3, 1
N20 #WAIT SYN [ID1 CH1]
N30 G00 X200 Y50
N40 G01 Z-50 F6000
N50 G04 0.2
N60 G01 Z0
N70 G00 X400 Y0
N80 G01 Z-30
N90 G01 Z0
N100 G00 X0 Y0
$ENDFOR
N110 M30
