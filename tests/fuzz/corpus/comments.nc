%comments
N10 G01 X1 F100 (a (nested) comment) ; and a line comment
(- decorative -) (* another *)
N20 X2 (unclosed comment runs to the block end
#COMMENT BEGIN
free text G01 X999
#COMMENT END
M30
