; expect: 2:8 NC2007 found 'G01'
#FLUSH G01
M30
