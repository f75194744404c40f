%l_missing
L no_such_file.nc
M30
