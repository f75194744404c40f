; expect: 2:1 NC1002 not supported: #HSC
#HSC ON [BSPLINE]
M30
