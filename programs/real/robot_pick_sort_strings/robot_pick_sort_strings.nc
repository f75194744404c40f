%SORTER
; Written in the style of a robot post for a sorting gantry: six parts picked from a fixture,
; each sorted into the good or the reject bin (every third part a reject, as the cell's test; the
; vision result comes as a V.E. value on the real line), the bin named in a V.E. string.
V.E.BIN = "none"
G17 G90 G71 G94
G00 X50 Y50 Z120
$FOR P1 = 0, 5, 1
  G00 X[100 + P1 * 30] Y100 Z40
  G01 Z12 F3000
  M130=35
  G04 0.2
  G01 Z40
  $IF P1 MOD 3 == 2
    V.E.BIN = "reject"
    G00 X450 Y300 Z40
  $ELSE
    V.E.BIN = "good"
    G00 X450 Y150 Z40
  $ENDIF
  G01 Z25 F3000
  M131
  G04 0.15
  G01 Z40
$ENDFOR
V.E.BIN = "none"
G00 X50 Y50 Z120
M30
