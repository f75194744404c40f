%calls_global
P1 = 5
L sub.nc
G01 X[P2] F200
L local.nc
L self.nc
M30
