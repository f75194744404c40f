%GALVO_MARK
; Written in the style of a galvo-scanner wrapper for a marking head on a 3-axis portal: the
; portal moves the field, the scanner marks (M values carry the job number and the laser
; settings to the PLC), a dwell per field while the scanner marks.
#TOOL DATA [MARKING_HEAD]
N10 G17 G90 G71 G94
N20 M150=4711              ; job number for the scanner controller
N30 M151=350               ; power in 0.1 %
N40 M152=1200              ; mark speed mm/s
N50 G00 X100 Y100 Z40
N60 M160                   ; start field 1
N70 G04 1.2
N80 G00 X200
N90 M160                   ; start field 2
N100 G04 1.2
N110 G00 Y200
N120 M160 H3=2             ; field 3, pattern 2
N130 G04 0.8
N140 G00 X100
N150 M160 H3=1             ; field 4, pattern 1
N160 G04 0.8
N170 M151=0
N180 G00 X0 Y0 Z50
N190 M30
