; end_feed_e: the non-modal end feed E (feed at the block end, with G94; isg-language.md 2.1):
;   long lines whose velocity falls from F to E before a corner, E above F (taken as F), and
;   the same lines without E for comparison.
; portal_3x; moves inside X 10..210 Y 10..60.
%end_feed_e
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 G01 X110 F9000 E1200        ; decelerate to 1200 mm/min at the corner
N40 G01 Y60 E600
N50 G01 X210 F9000
N60 G01 Y10 E12000              ; E above F: E = F
N70 G01 X110
N80 G01 Y60
N90 G01 X10
N100 M30
