; engraving_nc: engraving the letters "NC" 30 mm high: lines for the N, a 270 degree arc for
;   the C, pen-up rapids between strokes, a shallow plunge at reduced feed.
; portal_3x; letters from X20 Y20 to X85 Y50.
%engraving_nc
N10 G17 G90 G71 G94
N20 G00 X20 Y20 Z2
( N )
N30 G01 Z-0.2 F300
N40 G01 Y50 F1800
N50 X45 Y20
N60 Y50
N70 G00 Z2
( C: from the upper right, counter-clockwise around the centre X70 Y35, radius 15 )
N80 G00 X[70 + 15 * COS[45]] Y[35 + 15 * SIN[45]]
N90 G01 Z-0.2 F300
N100 G03 X[70 + 15 * COS[315]] Y[35 + 15 * SIN[315]] I[-15 * COS[45]] J[-15 * SIN[45]] F1800
N110 G00 Z2
N120 G00 X0 Y0 Z10
N130 M30
