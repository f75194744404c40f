; isg_reference_example: the minimal conformance example, verbatim but for one repair.
; source: /work/shared/reference/isg-language.md section 10 "Minimal conformance examples".
%L SUB1                      ; local sub must precede main
#VAR
  V.L.CNT : UNS32 = 0
#ENDVAR
G91 G01 X10 F1000
M17

%main
#VAR
  V.P.A[3] : REAL = [1.5, 2.5, 3.5]   ; [I] exact array-declaration form not seen
#ENDVAR
N10 G17 G90 G71 G94
N20 G00 X0 Y0 Z10
N30 P1 = 11 MOD 3            ; 2
N40 P2 = 2**P1 + SIN[30]     ; 4.5 (degrees)
N50 $IF P2 >= 4.5
N60   G01 X[P2*10] F1200
N70 $ELSE
N80   G01 X0
N90 $ENDIF
N100 $FOR P3 = 1, 3, 1
N110   LL SUB1
N120 $ENDFOR
; repaired: "N130 G90 G02 X20 Y0 I10 J0" -> "X95": the tool is at X75 Y0 here (X45 + three
;   10 mm incremental moves in SUB1), so the centre is X85 and the end X20 would lie 65 mm from
;   it against a start radius of 10 mm (error NC4201); X95 is the half circle the text means.
N130 G90 G02 X95 Y0 I10 J0   ; I/J relative (G162)
N140 G04 X0.5                ; 0.5 s dwell, alone in block
N150 G61 G01 X30             ; blend at end of this block
N160 X40 Y10
N170 $GOTO [END]
N180 X999                    ; skipped
[END]
N190 M30
