%KERF_PARTS
; Written in the style of a laser CAM post that leaves the kerf to the control: a 50 mm square
; plate with a 20 mm round hole, the outline cut counter-clockwise with G42 (kerf
; outside), the hole clockwise with G42 (kerf inside the hole), D1 the kerf
; half width from the tool list, pierce and beam-off by the builder's cycles, sheet G54.
G17 G90 G71 G94
G54
M110=1500
; hole: pierce in its centre, lead-in to the edge, full circle
G00 X25 Y25 Z10
G81 [0.3, 2.0]
G42 D1 G01 X35 Y25 F4000
G02 X35 Y25 I-10 J0
G40 G01 X25 Y25
G82
; outline: pierce outside, lead-in, four sides counter-clockwise
G00 X-5 Y-5 Z10
G81 [0.3, 2.0]
G42 D1 G01 X0 Y0 F8000
G01 X50
G01 Y50
G01 X0
G01 Y0
G40 G01 X-5 Y-5
G82
M110=0
G53 G00 X0 Y0 Z0
M30
