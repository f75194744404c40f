% sample square cycle
; Written in the style of the ISG kernel SDK's samples: channel initialisation, identity and
; orientation settings the simulation reads but does not act on, and a square cut by a cycle
; called with L CYCLE from the program's folder.
#CHANNEL INIT [CONFIG]
#IDENT [SIMULATION]
#ORI MODE [TOOL]
N010 G17 G90 G71 G94
N020 G00 X50 Y50 Z20
N030 L CYCLE [NAME=square.cyc @P1=40 @P2=-2 @P3=1500]
N040 G00 X150 Y50
N050 L CYCLE [NAME=square.cyc @P1=25 @P2=-1]
N060 G00 Z50
N070 M30
