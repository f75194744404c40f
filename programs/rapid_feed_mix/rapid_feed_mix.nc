; rapid_feed_mix: G00 and G01 mixed as a machining job does: rapid positioning over the part,
;   feed plunges, cuts, rapid retracts; every G00 -> G01 transition stops the path (it behaves
;   like G09, isg-language.md 2.4), G00 runs each axis at most at its rapid velocity.
; portal_3x; four slots at X 40..160 Y 30..90.
%rapid_feed_mix
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z50
N30 $FOR P1 = 0, 3, 1
N40   G00 X[40 + 40 * P1] Y30 Z2        ; rapid over the slot start, all three axes
N50   G01 Z-3 F800                       ; plunge
N60   G01 Y90 F2400                      ; cut the slot
N70   G00 Z2                             ; retract
N80   G00 Y30                            ; rapid back
N90   G01 Z-3 F800
N100  G01 X[50 + 40 * P1] F2400          ; a short side cut
N110  G00 Z20
N120 $ENDFOR
N130 G00 X0 Y0 Z50
N140 M30
