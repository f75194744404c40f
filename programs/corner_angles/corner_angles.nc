; corner_angles: single corners of 45, 90 and 135 degrees and a reversal at F9000 without a
;   programmed stop: the link velocity is the VELOJUMP step per axis (C0 = 1, A = 3000 mm/s^2,
;   T = 1 ms), the reversal half the step.
; portal_3x; moves inside X 10..170 Y 10..70.
%corner_angles
N10 G17 G90 G71 G94
N20 G00 X10 Y10 Z0
N30 G01 X50 F9000
N40 X[50 + 40 * COS[45]] Y[10 + 40 * SIN[45]]     ; 45 degree turn
N50 G09 G01 X110                                   ; then stop
N60 G01 X150 Y[10 + 40 * SIN[45]]
N70 Y70                                            ; 90 degree turn
N80 G09 X170
N90 G01 X130 Y30
N100 X170 Y70                                      ; reversal (180 degrees)
N110 G09 X170 Y10
N120 G01 X130
N130 X[130 + 40 * COS[45]] Y[10 + 40 * SIN[45]]   ; 135 degree turn
N140 M30
