; expect: 3:3 NC1001 found '*'
X[1 + \
  * 2]
M30
