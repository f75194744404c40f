; expect: 2:1 NC1002 not supported: #SIGNAL REMOVE
#SIGNAL REMOVE [ID1]
M30
