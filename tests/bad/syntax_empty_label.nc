; expect: 2:2 NC1001 label name
[ ]
M30
