%L SUBM
G00 Z5
M17
%m
"A" = "[1 + \"B\"]"
"B" = "2 * \"C\""
"C" = "3"
"E" = "SUBM"
G00 X["A"] Y["B"]
LL "E"
M30
