; thread_mill: thread milling of an M16 x 1.5 internal thread: an arc approach, three full
;   helical turns (G03, climb) rising 1.5 mm per turn, an arc departure; radius 6.75 mm.
; portal_3x; centre X50 Y50, helix in half turns (each an exact half circle).
%thread_mill
N10 G17 G90 G71 G94
N20 G00 X50 Y50 Z-12
N30 G03 X56.75 Y50 Z-12 I3.375 J0 F400        ; half-circle approach onto the thread radius
N40 P1 = -12
N50 $WHILE P1 < -7.5
N60   G03 X43.25 Y50 Z[P1 + 0.75] I-6.75 J0 F600
N70   G03 X56.75 Y50 Z[P1 + 1.5] I6.75 J0
N80   P1 = P1 + 1.5
N90 $ENDWHILE
N100 G03 X50 Y50 I-3.375 J0                    ; half-circle departure to the centre
N110 G00 Z10
N120 M30
