; bolt_circle: drilling a bolt circle of 8 holes with a local subroutine: the hole positions
;   come from SIN/COS of the loop angle in parameters, each hole is a rapid approach, a feed
;   plunge, a 0.2 s dwell at the bottom and a rapid retract.
; portal_3x; circle centre X120 Y90, radius 40.
%L DRILL
; drills at (P20, P21) to depth P22 [mm], dwell P23 [s]
G00 X[P20] Y[P21]
G00 Z2
G01 Z[P22] F600
G04 X[P23]
G00 Z5
M17

%bolt_circle
N10 G17 G90 G71 G94
N20 G00 X120 Y90 Z5
N30 P22 = -6                    ; hole depth
N40 P23 = 0.2                   ; dwell at the bottom [s]
N50 $FOR P1 = 0, 7, 1
N60   P2 = 22.5 + 45 * P1       ; hole angle [deg]
N70   P20 = 120 + 40 * COS[P2]
N80   P21 = 90 + 40 * SIN[P2]
N90   LL DRILL
N100 $ENDFOR
N110 G00 X0 Y0
N120 M30
