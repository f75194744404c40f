; stops_g09_g901: block transitions: G09 (decelerate to 0 at the end of this block only),
;   G900 / G901 / G08 (modal transition modes), and a G00 -> G01 transition that behaves like
;   G09 (isg-language.md 2.4). A staircase of short lines at F4000.
; portal_3x; moves inside X 10..90 Y 10..50.
%stops_g09_g901
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 G01 X20 F4000               ; G00 -> G01: the path stopped before this block
N40 G09 Y20                     ; stop at the end of this block
N50 X30
N60 Y30
N70 G901 X40                    ; decelerate after block end (modal)
N80 Y40
N90 G900 X50                    ; back to the default
N100 Y50
N110 G08 X60                    ; accelerate at block start (initial mode)
N120 G09 Y40
N130 X70 Y30
N140 G00 X80 Y20                ; a rapid between feeds
N150 G01 X90 Y10
N160 G00 Z5
N170 M30
