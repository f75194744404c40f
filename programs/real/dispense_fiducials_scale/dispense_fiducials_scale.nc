; Written in the style of a dispenser's job for a printed board: the same dot pattern at full
; size on the bed (G54) and shrunk to 80 % on a test coupon (G55) with #SCALE; the board's
; fiducial corners as a local subroutine; a job string for the line controller.
%L PATTERN
G00 X0 Y0 Z0.3
G800 [0.2, 1.0]
G00 X30 Y0 Z0.3
G800 [0.2, 1.0]
G00 X30 Y20 Z0.3
G800 [0.2, 1.0]
G00 X0 Y20 Z0.3
G800 [0.2, 1.0]
G00 X15 Y10 Z0.3
G800 [0.4, 1.0]
M17
%FIDUCIALS
V.E.JOB = "fiducials"
G17 G90 G71 G94
M200=1000
G54
LL PATTERN
G55
#SCALE ON X0.8 Y0.8
LL PATTERN
#SCALE OFF
M200=0
G80
M30
