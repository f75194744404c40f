%soft_limit
; X800 under a #CS shifted by X200 is MCS X1000, beyond portal_3x's P-AXIS-00178 800 mm: run-time NC5502
N5 #CS ON [1] [200, 0, 0, 0, 0, 0]
N10 G01 X800 F6000
N20 M30
