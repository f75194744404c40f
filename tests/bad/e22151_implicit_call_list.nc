; expect: 2:9 22151 invalid character in the parameter list of G80
G80 [12 !]
M30
