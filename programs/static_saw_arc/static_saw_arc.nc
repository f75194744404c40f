; static_saw_arc: the band saw of static_saw (TF5264 4.10) saws an S curve of two arcs into a
;   workpiece on the conveyor: G03 then G02, radius 300 mm, with the belt feed on arcs
;   (docs/conveyor.md "Static processing unit": the X component of the path velocity is the
;   belt's, so the path runs faster where the arc is steeper, 1.155 x the belt at the arcs'
;   outer ends) and C tracking the tangent.
; The arcs do not meet directly: at an inflection the curvature changes sign, and C, which
;   follows the tangent, would have to reverse its velocity within one cycle (a knee of C the
;   planner passes at VELOJUMP's 52 mm/s, where the belt needs 381 mm/s: NC9100, the static
;   unit's dynamic error, 004 l.440, l.621; until session 25 the virtual X moved 25 mm there).
;   004 l.441 asks for a C2 contour, so the last 10 deg of each arc are replaced by a short
;   B-spline whose ends meet the arcs in tangent and curvature (a clamped cubic B-spline starts
;   with the curvature |(P1 - P0) x (P2 - P1)| / (3 |P1 - P0|^3): P1 17 mm along the tangent,
;   P2 a further 17 mm along it and 2.89 mm = 3 x 17^2 / 300 towards the centre; point
;   symmetric about the inflection X-300 Y0, so it meets the G02 arc the same way).
; The belt runs at 85 mm/s (CONV_VEL 5100 mm/min): C follows the tangent, so its acceleration
;   is C'' v^2 with C'' the change of curvature, which jumps at the B-spline's inner knots by
;   0.042 deg/mm^2; within C's jerk budget j T (500 deg/s^2, the C1 rule, docs/planner.md
;   "Corners") that allows a path velocity of 108 mm/s there, and the belt must be handled up
;   to 1.1 x CONV_VEL (NC9100's check). Until session 31 the belt ran at 100 mm/s with
;   CONV_VEL 18000: the step at those knots passed the audit unbounded, at up to 12 x C's jerk.
; source: ncsim library (issue 14, static-saw), after the listing of TF5264 4.10.2.
%
N010 G74 Y1 C1
N020 S1[MC_MoveVelocity Velocity=85000 Acceleration=2000 Deceleration=2000 Jerk=750000 Direction=1]
N030 G0 G90 Y0 C0
N040 S1 [MC_TouchProbe Channel=1]
N050 #SYNC IN [CONVEYOR=S1, CONV_VEL=5100 FEED_CONT=0]
N060 G0 G90 X0 Y0 C30
N070 #CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 180, ROTMODE=1]
N080 F100
(- C pre-positioned tangentially in the catch-up (004 l.443: ROTMODE 1, C = OFFSET - 150 deg); then the S curve )
N090 G03 G90 X-252.606043 Y22.100165 I-150 J-259.807621
(- the inflection as a B-spline that meets both arcs in tangent and curvature: a C2 contour, l.441 )
N092 #SPLINE TYPE BSPLINE
N093 #SPLINE ON
N094 G01 G90 X-268.580818 Y16.285823
N095 G01 G90 X-283.567154 Y7.755769
N096 G01 G90 X-316.432846 Y-7.755769
N097 G01 G90 X-331.419182 Y-16.285823
N098 G01 G90 X-347.393957 Y-22.100165
N099 #SPLINE OFF
N100 G02 G90 X-600 Y0 I-102.606043 J281.907786
N110 #SYNC OUT [FEED_CONT=5]
N120 X[INDP_SYN G0 G90 POS0 INTERRUPTIBLE] Y[INDP_SYN G0 G90 POS0 INTERRUPTIBLE]
N130 #CAXTRACK OFF
N140 M30
