%PICK_PLACE_GANTRY
; Written in the style of a robot post-processor's output for a 3-axis gantry handling cell:
; the state for the cell's PLC in V.E. strings, gripper close / open as M values with the
; grip force, each move a labelled point of the robot program.
V.E.Message = "cell start"
V.E.Station = "feeder"
N10 G17 G90 G71 G94
N20 G00 X50 Y50 Z100            ; P1 home
N30 G00 X120 Y80 Z40            ; P2 above the feeder
N40 G01 Z12 F3000               ; P3 grip position
N50 M130=45                     ; gripper close, 45 N
N60 G04 0.25
N70 G01 Z40 F3000
V.E.Station = "press"
V.E.Message = "part gripped"
N80 G00 X320 Y80 Z40            ; P4 above the press
N90 G01 Z15 F2000               ; P5 place position
N100 M131                       ; gripper open
N110 G04 0.2
N120 G01 Z40 F3000
V.E.Message = "part placed"
N130 G00 X50 Y50 Z100           ; P1 home
V.E.Message = "cell done"
N140 M30
