; soft_limit_stop: a contour that would leave the soft limits. Two 40 x 30 mm parts with
;   corner radius 6 mm, each at the X position the PLC gives in V.E.PART_X (mm), read when the
;   part starts (a V.E. barrier: the path stops before it, docs/scenario.md). scenario.toml
;   starts with PART_X = 100, so `ncsim check` (which reads [ve]) passes; while the first part
;   is cut the PLC writes PART_X = 765: the second part's right side would reach X 805, beyond
;   portal_3x's maximum soft position limit X 800 mm (P-AXIS-00178, x.lis). N60 ends inside it
;   (X 799); the corner arc N70 would leave it on its way to X 805: its target is refused at
;   decode before it moves (NC4601 at line 18, as `check` reports such a target; the manual's
;   P-AXIS-00554 ERROR), so the run ends at X 799; the axis never gets beyond the limit.
; portal_3x; the first part at X 100..140, Y 20..50.
%soft_limit_stop
N10 G17 G90 G71 G94
N20 $FOR P2 = 1, 2, 1
N30   P1 = V.E.PART_X
N40   G00 X[P1 + 6] Y20 Z5
N50   G01 Z-1 F600
N60   G01 X[P1 + 34] F3000
N70   G03 X[P1 + 40] Y26 I0 J6           ; the corner: crosses X 800 for PART_X = 765
N80   G01 Y44
N90   G03 X[P1 + 34] Y50 I-6 J0
N100  G01 X[P1 + 6]
N110  G03 X[P1] Y44 I0 J-6
N120  G01 Y26
N130  G03 X[P1 + 6] Y20 I6 J0
N140  G00 Z5
N150 $ENDFOR
N160 M30
