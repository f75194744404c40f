; expect: 2:9 20998 after #SIGNAL the keyword SYN or an open bracket
#SIGNAL CH=2 ID=1
M30
