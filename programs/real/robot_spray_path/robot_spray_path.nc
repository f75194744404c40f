%SPRAY_PANEL
; Written in the style of a robot post-processor for a spray gantry: a raster over a 400 x 300
; panel at constant height with smoothed turns (G261), spray on/off as M values with the flow,
; the pass count and state in V.E. variables for the paint PLC.
V.E.STATE = "spraying"
G17 G90 G71 G94
#CONTOUR MODE [DEV PATH_DEV=2]
G261
G00 X100 Y100 Z120
M150=65
P1 = 0
$WHILE P1 < 6
  G01 X500 Y[100 + P1 * 60] F24000
  G01 X500 Y[130 + P1 * 60]
  G01 X100
  G01 X100 Y[160 + P1 * 60]
  P1 = P1 + 2
  V.E.PASSES = P1
$ENDWHILE
M151
G260
V.E.STATE = "done"
G00 X50 Y50 Z200
M30
