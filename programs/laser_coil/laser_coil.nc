; laser_coil: laser cutting on a coil: four 500 mm sheets travel on the CNC-driven belt
;   (50 mm/s); each is measured by the light barrier, caught up, and cut while it moves (two
;   holes of R30 and a 420 x 300 mm rounded rectangle, on the sheet behind its front edge),
;   then the head returns before the next sheet, so every pass stays inside the workspace
;   (X -200 .. 4000 mm, the soft limits; docs/conveyor.md "Workspace").
%laser_coil
N10 S1[MC_MoveVelocity Velocity=50000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N20 G00 G90 X0 Y0 Z0
$FOR P1 = 1, 4, 1
N30 S1 [MC_TouchProbe Channel=1]
N40 #SYNC IN [CONVEYOR=S1, CONV_VEL=3000 FEED_CONT=0]
; the catch-up: onto the front hole's start point on the moving sheet (PCS1); the cuts run
; from the front edge backwards, so the sheet has travelled far enough before the tool reaches
; its rear part (X stays above the workspace's -200 mm face)
N50 G00 G90 X-140 Y250 Z0
N60 M50
N70 G02 G90 X-140 Y250 I-30 J0 F6000
N80 M51
; the outer contour, 30 mm behind the front edge, with R20 corners
N90 G00 X-30 Y120
N100 M50
N110 G01 X-30 Y380
N120 G03 X-50 Y400 I-20 J0
N130 G01 X-430 Y400
N140 G03 X-450 Y380 I0 J-20
N150 G01 X-450 Y120
N160 G03 X-430 Y100 I20 J0
N170 G01 X-50 Y100
N180 G03 X-30 Y120 I0 J20
N190 M51
; the rear hole
N200 G00 X-360 Y250
N210 M50
N220 G02 X-360 Y250 I-30 J0
N230 M51
N240 #SYNC OUT
N250 G00 G90 X0 Y0 Z0
$ENDFOR
N260 M30
