; expect: 2:14 NC1001 closing
"NAME" = "abc
M30
