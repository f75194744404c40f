; expect: 2:1 NC2015 #IF
#IF 1
G01 X1
M30
