; expect: 2:2 NC1001 G code number
GX10
M30
