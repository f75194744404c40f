%soft_limit
; Under a #CS turned 90 deg about Z the arc's ends are inside portal_3x's soft limits (MCS X 750),
; its bulge is not (MCS X 811.8 > P-AXIS-00178 800 mm): check and time judge targets only under a
; turned #CS, so the channel's monitor stops it at run time: NC5502
N5 #CS ON [1] [0, 300, 0, 90, 0, 0]
N10 G01 X-100 Y-750 F6000
N20 G03 X100 Y-750 I100 J50
N30 M30
