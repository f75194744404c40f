; expect: 2:1 NC1002 not supported: #SIGNAL
#SIGNAL [CH=2 ID=1]
M30
