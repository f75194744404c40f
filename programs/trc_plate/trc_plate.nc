; trc_plate: a CAM-style milling program with tool radius compensation: the outline of an
;   80 x 50 mm plate with 10 mm corner radii and a 20 x 10 mm notch in its top edge, cut
;   outside (climb milling, clockwise, G41) in two depths with a 6 mm end mill (D1, r 3 mm).
;   The contour is the workpiece's, the tool centre runs 3 mm outside it: the plate's arcs
;   grow to 13 mm, the notch's inner corners are the intersections of the offset lines, its
;   outer corners get G25 linear transitions in the first pass and G26 circles in the second.
;   Approach and departure are the indirect selection / deselection blocks (G139).
; portal_3x_tools (tools.lis: D1 r 3 mm); docs/trc.md.
%trc_plate
N10 G17 G90 G71 G94
N20 T1 D1                        ; 6 mm end mill
N30 G00 X5 Y45 Z5
N40 $FOR P1 = 1, 2, 1
N50   $IF P1 == 1
N60     G25                      ; outer corners: linear transitions (the initial state)
N70   $ELSE
N80     G26                      ; outer corners: circles about the corner
N90   $ENDIF
N100  G01 Z[-2.5 * P1] F300
N110  G41 G01 X20 Y45 F1200      ; selection block: onto the contour
N120  Y60
N130  G02 X30 Y70 I10 J0
N140  G01 X50
N150  Y60                        ; the notch
N160  X70
N170  Y70
N180  X90
N190  G02 X100 Y60 I0 J-10
N200  G01 Y30
N210  G02 X90 Y20 I-10 J0
N220  G01 X30
N230  G02 X20 Y30 I0 J10
N240  G01 Y45
N250  G40 G01 X5 Y45             ; deselection block: off the contour
N260 $ENDFOR
N270 G00 Z5
N280 M30
