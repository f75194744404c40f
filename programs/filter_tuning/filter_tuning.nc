; filter_tuning: tuning the conveyor's filters and delay time from an NC program, as seed 004
;   4.2 suggests (l.641: "they can be varied in an NC program using the #MACHINE DATA command
;   and the display signals of the unfiltered and filtered conveyor positions, velocities and
;   accelerations can be acquired"). The belt runs at 300 mm/s. The first workpiece is
;   tracked with the list's filters and delay time (17455 us, the dead time alone), the
;   second with a longer velocity filter and the delay time that also covers the position
;   filter's delay (18955 us: docs/conveyor.md F-5). `ncsim run --detail` shows the display
;   variables and synchro_lag: its static part goes from about -0.45 mm to about 0.
; source: ncsim's own program (docs/conveyor.md F-7). Filters change only while not
;   synchronised (NC9061).
N010 G0 G90 X0 Y400 Z0
; First workpiece: position average 4, velocity FIR 10, delay time 17455 us (the list's)
N020 S1 [MC_TouchProbe Channel=1]
N030 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000]
N040 G0 X0 Y450 Z160
N050 G04 0.5
N060 #SYNC OUT
N070 G0 X0 Y400 Z0
; Filters off for a moment: the display's filtered values are the measured ones
N080 #MACHINE DATA [AX=S P-AXIS-00620=0]
N090 G04 0.2
; Second workpiece: velocity FIR 20 and the delay time + the position filter's delay
N100 #MACHINE DATA [AX=S P-AXIS-00620=1 P-AXIS-00623=20 P-AXIS-00626=18955]
N110 S1 [MC_TouchProbe Channel=1]
N120 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000]
N130 G0 X0 Y450 Z160
N140 G04 0.5
N150 #SYNC OUT
N160 G0 X0 Y400 Z0
M30
