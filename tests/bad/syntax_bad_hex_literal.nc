; expect: 2:6 NC1001 hexadecimal
P1 = '16#XYZ'
M30
