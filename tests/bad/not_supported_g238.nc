; expect: 3:5 NC1002 not supported: G238
%g238
G01 G238 G41 X1 F100
M30
