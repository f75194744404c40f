; expect: 2:9 NC1001 expected an operand
P1 = 2 +
M30
