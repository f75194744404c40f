%soft_limit
; a line beyond the X soft limit P-AXIS-00178 = 800 mm of portal_3x: the channel stops the
; axes in the cycle the command would cross it (run-time error NC5502, exit 1)
N10 G01 X1000 F6000
N20 M30
