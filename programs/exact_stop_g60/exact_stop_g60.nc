; exact_stop_g60: exact stops: a square with G60 at two of its corners (non-modal: the path
;   stops and waits for the exact-stop window and settling time P-AXIS-00532 there), then the
;   same square under G360 (exact stop at every block end) and G359 (off again).
; portal_3x; square 30 mm from X20 Y20.
%exact_stop_g60
N10 G17 G90 G71 G94
N20 G00 X20 Y20 Z0
N30 G01 X50 F3000
N40 G60 Y50                     ; exact stop at this corner only
N50 X20
N60 G60 Y20                     ; and at this one
N70 G360                        ; exact stop at every block end
N80 X50
N90 Y50
N100 X20
N110 Y20
N120 G359                       ; off: the next corners are passed without stop
N130 X50
N140 Y50
N150 G00 Z5
N160 M30
