; expect: 2:20 NC1001 value after the keyword
#SYNC IN [CONV_VEL=]
M30
