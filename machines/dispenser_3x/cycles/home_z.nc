%home_z
; G80: Z up to its machine position 0 (the top), in machine coordinates
#MCS ON
G00 Z0
#MCS OFF
M17
