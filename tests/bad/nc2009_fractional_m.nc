; expect: 2:5 NC2009 whole numbers
G01 M3.5 X1 F100
M30
