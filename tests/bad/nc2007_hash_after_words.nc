; expect: 2:8 NC2007 alone
G01 X1 #FLUSH
M30
