; expect: 4:1 NC2018 twice
%L SUB
M17
%L SUB
M17
%main
M30
