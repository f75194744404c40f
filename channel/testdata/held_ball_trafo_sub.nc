%held_ball_trafo_sub
N10 G01 X-150 Y50 Z-850
N20 M17
