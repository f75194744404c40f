; expect: 2:16 20998 after #SIGNAL REMOVE the keyword SYN or an open bracket
#SIGNAL REMOVE ID1
M30
