; circle_feeds: full circles (in two halves) of radius 2, 5, 20 and 60 mm at F15000: small
;   circles are limited by the axes' acceleration (centripetal v^2 / r <= a), large ones reach F.
; portal_3x; circles right of X100 Y100.
%circle_feeds
N10 G17 G90 G71 G94
N20 G00 X100 Y100 Z0
N30 G01 X102 F15000
N40 G03 X98 I-2 J0
N50 G03 X102 I2 J0
N60 G09 G01 X105
N70 G03 X95 I-5 J0
N80 G03 X105 I5 J0
N90 G09 G01 X120
N100 G03 X80 I-20 J0
N110 G03 X120 I20 J0
N120 G09 G01 X160
N130 G03 X40 I-60 J0
N140 G03 X160 I60 J0
N150 G09 G01 X100
N160 M30
