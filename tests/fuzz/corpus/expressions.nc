%expressions
N10 P1 = 11 MOD 3
N20 P2 = 2**P1 + SIN[30] - COS[60] * TAN[45] / 2
N30 P3 = [P1 > 1] && [P2 <= 10] || NOT [P1 == 0] XOR [P2 != 3]
N40 P4 = [P1 & 7] | [3 ^ 1] + INV[0]
N50 P5 = SQRT[16] + SQR[2] + ABS[-1] + INT[2.7] + ROUND[2.5] + FRACT[1.5]
N60 P6 = '16#FA1B' + '0x0ED2' + 'H1869f' + PI + TRUE - FALSE
N70 P7 = ATAN2[1, 1] + ASIN[1] + ACOS[0] + EXP[1] + LN[1] + DEXP[2] + LOG[10]
N80 X[-2*P1] Y[[P2+P3]*[P4-1]]
N90 P8 += 1
N100 P8 /= 2
N110 P100[5][2] = PP10 + 1
M30
