; expect: 2:1 NC1002 not supported: G41
G41 X1
M30
