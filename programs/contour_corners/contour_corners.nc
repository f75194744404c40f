; contour_corners: a closed contour of lines and arcs meeting at sharp corners (no tangent
;   transition anywhere): the path stops or slows at each corner by VELOJUMP.
; portal_3x; moves inside X 10..110 Y 10..100.
%contour_corners
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z2
N30 G01 Z-1 F500
N40 G01 X60 F3000
N50 G02 X90 Y40 I30 J0            ; quarter circle, entered at a 90 degree corner
N60 G01 X110 Y60                   ; 45 degree corner after the arc
N70 G01 X80 Y80                    ; 101 degree corner
N80 G03 X40 Y80 I-20 J0            ; half circle over Y100, entered at a corner
N90 G01 X10 Y50                    ; 45 degree corner after the arc
N100 G01 X10 Y10                   ; 45 degree corner
N110 G00 Z5
N120 M30
