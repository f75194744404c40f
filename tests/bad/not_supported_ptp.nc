; expect: 3:1 NC1002 not supported: #PTP
G01 X1
#PTP ON
M30
