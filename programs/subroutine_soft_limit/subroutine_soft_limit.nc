; subroutine_soft_limit: an error in a global subroutine file names that file.
;   Two 40 x 30 mm parts with corner radius 6 mm, each at the X position the PLC gives in
;   V.E.PART_X (mm), read when the part starts, cut by the global subroutine file
;   part_contour.sub (`L part_contour.sub`). scenario.toml starts with PART_X = 100 (so `ncsim
;   check` passes) and writes 765 while the first part is cut: the subroutine's corner arc (its
;   line 10, N70) ends at X 805, beyond portal_3x's maximum soft position limit X 800 mm
;   (P-AXIS-00178). The run stops before it moves with NC4601 (as `check` would) positioned in
;   part_contour.sub, line 10, not in this file (docs/ipo.md "Blocks of subroutine files").
; portal_3x.
%subroutine_soft_limit
N10 G17 G90 G71 G94
N20 P1 = V.E.PART_X
N30 L part_contour.sub
N40 P1 = V.E.PART_X
N50 L part_contour.sub
N60 M30
