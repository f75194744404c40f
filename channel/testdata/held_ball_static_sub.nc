%held_ball_static_sub
N50 G01 X-200 Y0
N55 M17
