%RELIEF
; Written in the style of a hand-written shop program: four relief grooves on a shaft end held
; in vice 4 (G57), the groove data in string macros, the grooves cut by a counted $DO loop,
; a $SWITCH on the groove number for the two deeper ones, the plan as a STRING.
#VAR
  V.P.PLAN : STRING = "4 grooves"
#ENDVAR
"WIDTH" = "3"
"START" = "10"
G17 G90 G71 G94
G57
S4000 M03
G00 X0 Y["START"] Z5
P1 = 0
$DO
  P2 = -1
  $SWITCH P1
    $CASE 1
      P2 = -2
      $BREAK
    $CASE 3
      P2 = -2.5
      $BREAK
    $DEFAULT
      P2 = -1
  $ENDSWITCH
  G00 X0 Y["START" + P1 * 12] Z2
  G01 Z[P2] F200
  G01 X40 F700
  G01 Y["START" + P1 * 12 + "WIDTH"]
  G01 X0
  G00 Z2
  P1 = P1 + 1
$ENDDO P1 < 4
M05
G53 G00 Z180
M30
