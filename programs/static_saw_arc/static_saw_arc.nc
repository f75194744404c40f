; static_saw_arc: the band saw of static_saw (TF5264 4.10) saws an S curve of two arcs into a
;   workpiece on the conveyor: G03 then G02, 60 deg each, radius 300 mm, tangent at their
;   joint, with the belt feed on arcs (docs/conveyor.md "Static processing unit": the X
;   component of the path velocity is the belt's, so the path runs faster where the arc is
;   steeper, 1.155 x the belt at the arcs' ends) and C tracking the tangent.
; source: ncsim library (issue 14, static-saw), after the listing of TF5264 4.10.2.
%
N010 G74 Y1 C1
N020 S1[MC_MoveVelocity Velocity=100000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N030 G0 G90 Y0 C0
N040 S1 [MC_TouchProbe Channel=1]
N050 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]
N060 G0 G90 X0 Y0 C30
N070 #CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 180, ROTMODE=1]
N080 F100
(- C pre-positioned tangentially in the catch-up (004 l.443: ROTMODE 1, C = OFFSET - 150 deg); then the S curve )
N090 G03 G90 X-300 Y0 I-150 J-259.807621
N100 G02 G90 X-600 Y0 I-150 J259.807621
N110 #SYNC OUT [FEED_CONT=5]
N120 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
N130 #CAXTRACK OFF
N140 M30
