%GALVO_SERIALS
; Written in the style of a galvo-scanner wrapper that marks serial numbers on a tray of 8
; parts: the portal moves to each part, the serial number goes to the scanner as an M value,
; the text template as H1, the mark time as a dwell; the tray's position as a zero offset
; written by the wrapper into G58.
V.G.NP[5].V.X = 120
V.G.NP[5].V.Y = 90
#TOOL DATA [GALVO_F100]
G17 G90 G71 G94
G58
H1=7
P1 = 50120
$FOR P2 = 0, 7, 1
  G00 X[[P2 MOD 4] * 45] Y[INT[P2 / 4] * 60] Z30
  M170=[P1 + P2]
  M160
  G04 0.45
$ENDFOR
G53 G00 X0 Y0 Z50
M30
