; language_tour: ncsim's own program touring the ISG language broadly: local subroutines
;   (%L, LL, M17/M29), #VAR declarations with arrays and a continued initialiser, string
;   macros, hex literals, expressions (precedence, functions, comparisons, logic, bit
;   operations, compound assignment), every control-flow family, arcs with relative and
;   absolute centres, #CS, polynomial contouring, dwell, $GOTO and a skip block.
; Every move stays inside X 0..80, Y 0..45, Z -2.5..10 (portal_3x); arcs are geometrically
;   exact. Values in the comments are what the interpreter must compute.
%L SQUARE
#VAR
  V.L.SIDE : REAL = 10
#ENDVAR
G91 G01 X[V.L.SIDE] F[P10]
Y[V.L.SIDE]
X[-V.L.SIDE]
Y[-V.L.SIDE]
G90
M17

%L CIRCLES
; two full circles of radius 5 from (P21, P22), each in two halves
$FOR P20 = 1, 2, 1
  G02 X[P21 + 10] Y[P22] I5 J0
  G02 X[P21] Y[P22] I-5 J0
$ENDFOR
M29

%language_tour
#VAR
  V.P.COUNT : UNS32 = 0
  V.P.TABLE[4] : REAL = [0.5, 1.5, \
                         2.5, 3.5]
  V.P.LABEL : STRING[16] = "tour"
#ENDVAR
N10 G17 G90 G71 G94
#COMMENT BEGIN
A block comment: these lines are not NC blocks.
G01 X999 is not executed.
#COMMENT END
N20 "DEPTH" = "-2.5"
N30 "CLEAR" = "[\"DEPTH\" + 12.5]"        ; a macro using a macro: 10
N40 P10 = 1200
N50 P11 = '16#10' + '0x0F' + 'H1'          ; 16 + 15 + 1 = 32
N60 G00 X0 Y0 Z["CLEAR"]                    ; Z10
N70 G01 Z["DEPTH"] F[P10]                   ; Z-2.5
N80 LL SQUARE                               ; a 10 mm square, back at X0 Y0
N90 P21 = 20
N100 P22 = 10
N110 G01 X[P21] Y[P22]
N120 LL CIRCLES                             ; back at X20 Y10
( expressions )
N130 P1 = 11 MOD 3                          ; 2
N140 P2 = 2**P1 + SIN[30] * COS[60] - ABS[-1]   ; 4 + 0.25 - 1 = 3.25
N150 P3 = SQRT[16] + INT[2.7] + ROUND[2.5] + FRACT[1.25] + FLOOR[-1.5] + CEIL[1.2]
N160 P4 = ATAN[1] + ACOS[0] - ASIN[1]       ; 45 (degrees)
N170 P5 = [P1 > 1] && [P2 <= 10] || NOT [P3 == 0]   ; 1
N180 P6 = [P11 & 7] | [3 ^ 1]               ; 0 | 2 = 2
N190 P7 = EXP[0] + LN[1] + DEXP[1] + LOG[100] + PI - PI   ; 13
N200 V.P.COUNT += 1
N210 V.P.TABLE[2] *= 2                      ; 5
N220 P100[1] = P1 * 2                       ; 4
N230 G01 X V.P.TABLE[2] Y P100[1]           ; X5 Y4
( control flow )
N240 $IF P5 == 1
N250   G01 X30 Y20
N260 $ELSEIF P6 > 4
N270   G01 X30 Y25
N280 $ELSE
N290   G01 X30 Y30
N300 $ENDIF
N310 $SWITCH P1
N320 $CASE 1
N330   P8 = 10
N340   $BREAK
N350 $CASE 1 + 1
N360   P8 = 20
N370   $BREAK
N380 $DEFAULT
N390   P8 = 0
N400 $ENDSWITCH
N410 P9 = 0
N420 $WHILE P9 < 3
N430   P9 = P9 + 1
N440   $IF P9 == 2
N450     $CONTINUE
N460   $ENDIF
N470   G01 X[30 + P9 * 5] Y20
N480 $ENDWHILE                              ; at X45 Y20
N490 $DO
N500   P9 -= 1
N510 $ENDDO P9 > 0
N520 $REPEAT
N530   P9 += 2
N540   $IF P9 > 100
N550     $BREAK
N560   $ENDIF
N570 $UNTIL P9 >= 6
( arcs )
N580 G02 X55 Y20 I5 J0                      ; centre X50 Y20, radius 5
N590 G03 X65 Y20 I5 J0                      ; centre X60 Y20, radius 5
N600 G161 G02 X75 Y20 I70 J20               ; absolute centre X70 Y20, radius 5
N610 G162
( coordinate systems )
N620 #CS ON [1] [10, 5, 0, 0, 0, 30]
N630 G01 X10 Y0
N640 #CS OFF
N650 #CS DEF [2] [0, 0, 5]
N660 #CS ON [2]
N670 G01 X20 Y20
N680 #CS OFF ALL
( polynomial contouring, dwell, jumps )
N690 #CONTOUR MODE [DEV PATH_DEV 0.1]
N700 G261
N710 G01 X40 Y20
N720 G01 X40 Y40
N730 G260
N740 #FLUSH
N750 G04 0.5
N760 #TIME 0.2
N770 $GOTO N790
N780 G01 X999                               ; jumped over
N790: G00 Z10
/ N800 G01 X5                               ; skipped when skip level 1 is active
N810 #MSG ["tour done"]
N820 M30
