; planes_g18_g19: arcs in the three planes: G17 XY (I, J), G18 ZX (K, I) and G19 YZ (J, K):
;   a half circle in each plane and a helix in G18 along Y, as when milling a rounded edge.
; portal_3x; moves inside X 40..80 Y 40..80 Z -20..10.
%planes_g18_g19
N10 G90 G71 G94
N20 G00 X40 Y40 Z0
N30 G17 G02 X60 Y40 I10 J0 F2400       ; XY half circle over Y50
N40 G18 G02 X80 Z0 I10 K0              ; ZX half circle, centre X70 Z0
N50 G19 G03 Y60 Z0 J10 K0              ; YZ half circle, centre Y50 Z0
N60 G18 G03 X60 Y80 Z0 I-10 K0         ; ZX helix: half circle while Y goes 60 -> 80
N70 G17 G01 X40 Y40 Z0
N80 G00 Z10
N90 M30
