; expect: 3:5 NC1002 not supported: G237
; TRC selection modes other than G138/G139 are refused at their word (docs/trc.md)
G01 G237 G41 X1 F100
M30
