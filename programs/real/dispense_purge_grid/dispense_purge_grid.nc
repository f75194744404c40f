%dispense_purge_grid
; Written in the style of a dispenser's job file: purge the needle on the calibration plate
; (G55), then a 3 x 3 grid of dots on the bed (G54), with the job state for the operator
; panel in a V.E. string.
V.E.JOB_STATE = "purging"
G17 G90 G71 G94
G55
G805 [ 5.000, 5.000, 0.500 ]      ; purge at X5 Y5, needle 0.5 mm above the plate
G54
V.E.JOB_STATE = "dispensing"
M200=950
P1 = 0
$WHILE P1 < 3
  P2 = 0
  $WHILE P2 < 3
    G00 X[10 + P2 * 4] Y[10 + P1 * 4] Z0.3
    G800 [ 0.25, 1.5 ]
    P2 = P2 + 1
  $ENDWHILE
  P1 = P1 + 1
$ENDWHILE
M200=0
G80
V.E.JOB_STATE = "done"
M30
